"""ARGoS's include graph (docs/loop-functions.md, "Which ARGoS versions' projects build"): a
project that includes one of essaim's ARGoS headers gets every type ARGoS's header of the same
path brings in, through whatever it includes, as far as essaim provides those headers. Each
header is compiled alone in a translation unit that uses the types of all of them, with the
flags pkg-config gives a project (argos3_simulator)."""
import os
import shutil
import subprocess

import pytest

from argos_projects import ROOT, need_essaim, sdk

INCLUDE = ROOT / "src" / "argos" / "include" / "argos3"

# For each header, the provided headers that ARGoS's header of the same path reaches through
# its #includes at ilpincy/argos3 421bd763 (by file name, without .h), also those it reaches
# through headers essaim does not provide (a plugin factory, ray3.h, physics_engine.h...).
ARGOS_REACHES = {
    "core/control_interface/ci_controller.h": "argos_configuration argos_exception datatypes",
    "core/simulator/entity/composable_entity.h": (
        "ci_controller controllable_entity embodied_entity entity medium space argos_configuration "
        "argos_exception any datatypes argos_log angles general quaternion range vector2 vector3 "
        "string_utilities"),
    "core/simulator/entity/controllable_entity.h": (
        "ci_controller entity argos_configuration argos_exception datatypes argos_log angles general "
        "range vector2 vector3 string_utilities"),
    "core/simulator/entity/embodied_entity.h": (
        "entity argos_configuration argos_exception datatypes argos_log angles general quaternion range "
        "vector2 vector3 string_utilities"),
    "core/simulator/entity/entity.h": "argos_configuration argos_exception datatypes argos_log",
    "core/simulator/entity/floor_entity.h": (
        "entity argos_configuration argos_exception color datatypes argos_log angles general range "
        "vector2 vector3 string_utilities"),
    "core/simulator/entity/positional_entity.h": (
        "entity argos_configuration argos_exception datatypes argos_log angles general quaternion range "
        "vector2 vector3 string_utilities"),
    "core/simulator/loop_functions.h": (
        "ci_controller controllable_entity embodied_entity entity medium simulator space "
        "argos_configuration argos_exception any color datatypes argos_log angles general quaternion "
        "range rng vector2 vector3 string_utilities"),
    "core/simulator/medium/medium.h": "argos_configuration argos_exception datatypes",
    "core/simulator/simulator.h": (
        "medium argos_configuration argos_exception datatypes argos_log angles general range rng vector2 "
        "string_utilities"),
    "core/simulator/space/space.h": (
        "ci_controller controllable_entity embodied_entity entity medium argos_configuration "
        "argos_exception any datatypes argos_log angles general quaternion range vector2 vector3 "
        "string_utilities"),
    "core/utility/configuration/argos_configuration.h": "argos_exception datatypes",
    "core/utility/configuration/argos_exception.h": "",
    "core/utility/datatypes/any.h": "argos_exception",
    "core/utility/datatypes/color.h": "argos_exception datatypes string_utilities",
    "core/utility/datatypes/datatypes.h": "",
    "core/utility/logging/argos_log.h": "datatypes",
    "core/utility/math/angles.h": "argos_exception datatypes general range string_utilities",
    "core/utility/math/general.h": "datatypes",
    "core/utility/math/quaternion.h": "argos_exception datatypes angles general range vector2 vector3 string_utilities",
    "core/utility/math/range.h": "argos_exception datatypes string_utilities",
    "core/utility/math/rng.h": "argos_exception datatypes angles general range string_utilities",
    "core/utility/math/vector2.h": "argos_exception datatypes angles general range string_utilities",
    "core/utility/math/vector3.h": "argos_exception datatypes angles general range vector2 string_utilities",
    "core/utility/string_utilities.h": "argos_exception datatypes",
    "core/wrappers/lua/lua_controller.h": (
        "ci_controller argos_configuration argos_exception datatypes angles general range rng "
        "string_utilities"),
    "plugins/robots/foot-bot/simulator/footbot_entity.h": (
        "ci_controller composable_entity controllable_entity embodied_entity entity medium space "
        "argos_configuration argos_exception any datatypes argos_log angles general quaternion range "
        "vector2 vector3 string_utilities"),
    "plugins/simulator/entities/box_entity.h": (
        "ci_controller composable_entity controllable_entity embodied_entity entity positional_entity "
        "medium space argos_configuration argos_exception any color datatypes argos_log angles general "
        "quaternion range vector2 vector3 string_utilities led_entity led_equipped_entity"),
    "plugins/simulator/entities/cylinder_entity.h": (
        "ci_controller composable_entity controllable_entity embodied_entity entity positional_entity "
        "medium space argos_configuration argos_exception any color datatypes argos_log angles general "
        "quaternion range vector2 vector3 string_utilities led_entity led_equipped_entity"),
    "plugins/simulator/entities/led_entity.h": (
        "entity positional_entity argos_configuration argos_exception color datatypes argos_log angles "
        "general quaternion range vector2 vector3 string_utilities"),
    "plugins/simulator/entities/led_equipped_entity.h": (
        "ci_controller composable_entity controllable_entity embodied_entity entity positional_entity "
        "medium space argos_configuration argos_exception any color datatypes argos_log angles general "
        "quaternion range vector2 vector3 string_utilities led_entity"),
    "plugins/simulator/entities/light_entity.h": (
        "ci_controller composable_entity controllable_entity embodied_entity entity positional_entity "
        "medium space argos_configuration argos_exception any color datatypes argos_log angles general "
        "quaternion range vector2 vector3 string_utilities led_entity led_equipped_entity"),
    "plugins/simulator/media/led_medium.h": (
        "entity positional_entity medium argos_configuration argos_exception color datatypes argos_log "
        "angles general quaternion range vector2 vector3 string_utilities led_entity"),
}

# What each header declares, used as a project would: a complete type, a constant, a call.
USES = {
    "ci_controller": "(void)sizeof(argos::CCI_Controller);",
    "composable_entity": "(void)sizeof(argos::CComposableEntity);",
    "controllable_entity": "(void)sizeof(argos::CControllableEntity);",
    "embodied_entity": "(void)sizeof(argos::CEmbodiedEntity); (void)sizeof(argos::SAnchor);",
    "entity": "(void)sizeof(argos::CEntity);",
    "floor_entity": "(void)sizeof(argos::CFloorEntity);",
    "positional_entity": "(void)sizeof(argos::CPositionalEntity);",
    "loop_functions": "(void)sizeof(argos::CLoopFunctions);",
    "medium": "(void)sizeof(argos::CMedium);",
    "simulator": "(void)sizeof(argos::CSimulator);",
    "space": "(void)sizeof(argos::CSpace::TMapPerType);",
    "argos_configuration": "(void)sizeof(argos::TConfigurationNode);",
    "argos_exception": "(void)argos::CARGoSException(\"x\").what();",
    "any": "(void)sizeof(argos::CAny);",
    "color": "(void)argos::CColor::GRAY50.GetRed();",
    "datatypes": "argos::UInt32 u = 0; argos::Real r = u; (void)r;",
    "argos_log": "argos::LOG << \"x\";",
    "angles": "(void)argos::CRadians::TWO_PI.GetValue();",
    "general": "(void)argos::Abs(-1.0);",
    "quaternion": "(void)sizeof(argos::CQuaternion);",
    "range": "(void)argos::CRange<argos::Real>(0, 1).GetMax();",
    "rng": "argos::CRandom::CRNG* rng = nullptr; (void)(rng ? rng->Uniform(argos::CRange<argos::Real>(0, 1)) : 0);",
    "vector2": "(void)argos::CVector2(1, 2).Length();",
    "vector3": "(void)argos::CVector3(1, 2, 3).Length();",
    "string_utilities": "(void)argos::ToString(1);",
    "lua_controller": "(void)sizeof(argos::CLuaController); lua_State* L = nullptr; (void)L;",
    "footbot_entity": "(void)sizeof(argos::CFootBotEntity);",
    "box_entity": "(void)sizeof(argos::CBoxEntity);",
    "cylinder_entity": "(void)sizeof(argos::CCylinderEntity);",
    "led_entity": "(void)sizeof(argos::CLEDEntity);",
    "led_equipped_entity": "(void)sizeof(argos::CLEDEquippedEntity);",
    "light_entity": "(void)sizeof(argos::CLightEntity);",
    "led_medium": "(void)sizeof(argos::CLEDMedium);",
}


def provided():
    return sorted(str(p.relative_to(INCLUDE)) for p in INCLUDE.rglob("*.h"))


def test_every_provided_header_is_in_the_table():
    assert provided() == sorted(ARGOS_REACHES)
    assert sorted(p.split("/")[-1][:-2] for p in provided()) == sorted(USES)


@pytest.fixture(scope="module")
def cflags():
    env = dict(os.environ, PKG_CONFIG_PATH=str(sdk() / "lib" / "pkgconfig"))
    done = subprocess.run(["pkg-config", "--cflags", "argos3_simulator"], env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout.split()


@need_essaim
@pytest.mark.parametrize("header", sorted(ARGOS_REACHES))
def test_a_header_alone_gives_what_argos_header_gives(header, cflags, tmp_path):
    names = [header.split("/")[-1][:-2], *ARGOS_REACHES[header].split()]
    body = "\n".join(f"  {{ {USES[name]} }}  // {name}" for name in names)
    source = tmp_path / "alone.cpp"
    source.write_text(f"#include <argos3/{header}>\n\nvoid UseAll() {{\n{body}\n}}\n")
    compiler = os.environ.get("CXX") or shutil.which("c++")
    done = subprocess.run([compiler, "-std=c++17", "-fsyntax-only", *cflags, str(source)], capture_output=True,
                          text=True)
    assert done.returncode == 0, f"{header} alone:\n{source.read_text()}\n{done.stderr}"
