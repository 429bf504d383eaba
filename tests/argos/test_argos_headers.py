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
    "core/control_interface/ci_actuator.h": "argos_configuration argos_exception datatypes",
    "core/control_interface/ci_controller.h": "argos_configuration argos_exception ci_actuator ci_sensor datatypes",
    "core/control_interface/ci_sensor.h": "argos_configuration argos_exception datatypes",
    "core/simulator/actuator.h": "argos_exception",
    "core/simulator/entity/composable_entity.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller ci_sensor "
        "controllable_entity datatypes embodied_entity entity general medium physics_engine "
        "quaternion range space string_utilities vector2 vector3"),
    "core/simulator/entity/controllable_entity.h": (
        "angles argos_configuration argos_exception argos_log ci_actuator ci_controller ci_sensor "
        "datatypes entity general range string_utilities vector2 vector3"),
    "core/simulator/entity/embodied_entity.h": (
        "angles argos_configuration argos_exception argos_log datatypes entity general physics_engine "
        "quaternion range string_utilities vector2 vector3"),
    "core/simulator/entity/entity.h": "argos_configuration argos_exception argos_log datatypes",
    "core/simulator/entity/floor_entity.h": (
        "angles argos_configuration argos_exception argos_log color datatypes entity general range "
        "string_utilities vector2 vector3"),
    "core/simulator/entity/positional_entity.h": (
        "angles argos_configuration argos_exception argos_log datatypes entity general quaternion "
        "range string_utilities vector2 vector3"),
    "core/simulator/loop_functions.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller ci_sensor "
        "color controllable_entity datatypes embodied_entity entity general medium physics_engine "
        "quaternion range rng simulator space string_utilities vector2 vector3"),
    "core/simulator/medium/medium.h": "argos_configuration argos_exception datatypes",
    "core/simulator/physics_engine/physics_engine.h": (
        "angles argos_configuration argos_exception argos_log datatypes general range "
        "string_utilities vector2"),
    "core/simulator/sensor.h": "argos_exception",
    "core/simulator/simulator.h": (
        "angles argos_configuration argos_exception argos_log datatypes general medium physics_engine "
        "range rng string_utilities vector2"),
    "core/simulator/space/space.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller ci_sensor "
        "controllable_entity datatypes embodied_entity entity general medium physics_engine "
        "quaternion range string_utilities vector2 vector3"),
    "core/utility/configuration/argos_configuration.h": "argos_exception datatypes",
    "core/utility/configuration/argos_exception.h": "",
    "core/utility/datatypes/any.h": "argos_exception",
    "core/utility/datatypes/byte_array.h": "argos_exception datatypes",
    "core/utility/datatypes/color.h": "argos_exception datatypes string_utilities",
    "core/utility/datatypes/datatypes.h": "",
    "core/utility/logging/argos_log.h": "datatypes",
    "core/utility/math/angles.h": "argos_exception datatypes general range string_utilities",
    "core/utility/math/general.h": "datatypes",
    "core/utility/math/quaternion.h": (
        "angles argos_exception datatypes general range string_utilities vector2 vector3"),
    "core/utility/math/range.h": "argos_exception datatypes string_utilities",
    "core/utility/math/rng.h": "angles argos_exception datatypes general range string_utilities",
    "core/utility/math/vector2.h": "angles argos_exception datatypes general range string_utilities",
    "core/utility/math/vector3.h": "angles argos_exception datatypes general range string_utilities vector2",
    "core/utility/string_utilities.h": "argos_exception datatypes",
    "core/wrappers/lua/lua_controller.h": (
        "angles argos_configuration argos_exception ci_actuator ci_controller ci_sensor datatypes "
        "general range rng string_utilities"),
    "plugins/robots/foot-bot/control_interface/ci_footbot_base_ground_sensor.h": (
        "angles argos_configuration argos_exception ci_sensor datatypes general range "
        "string_utilities vector2"),
    "plugins/robots/foot-bot/control_interface/ci_footbot_distance_scanner_actuator.h": (
        "angles argos_configuration argos_exception ci_actuator datatypes general range "
        "string_utilities"),
    "plugins/robots/foot-bot/control_interface/ci_footbot_distance_scanner_sensor.h": (
        "angles argos_configuration argos_exception ci_sensor datatypes general range "
        "string_utilities"),
    "plugins/robots/foot-bot/control_interface/ci_footbot_gripper_actuator.h": (
        "angles argos_configuration argos_exception ci_actuator datatypes general range "
        "string_utilities"),
    "plugins/robots/foot-bot/control_interface/ci_footbot_light_sensor.h": (
        "angles argos_configuration argos_exception ci_sensor datatypes general range "
        "string_utilities"),
    "plugins/robots/foot-bot/control_interface/ci_footbot_motor_ground_sensor.h": (
        "angles argos_configuration argos_exception ci_sensor datatypes general range "
        "string_utilities vector2"),
    "plugins/robots/foot-bot/control_interface/ci_footbot_proximity_sensor.h": (
        "angles argos_configuration argos_exception ci_sensor datatypes general range "
        "string_utilities"),
    "plugins/robots/foot-bot/control_interface/ci_footbot_turret_actuator.h": (
        "angles argos_configuration argos_exception ci_actuator datatypes general range "
        "string_utilities"),
    "plugins/robots/foot-bot/control_interface/ci_footbot_turret_encoder_sensor.h": (
        "angles argos_configuration argos_exception ci_sensor datatypes general range "
        "string_utilities vector2"),
    "plugins/robots/foot-bot/simulator/footbot_base_ground_rotzonly_sensor.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller "
        "ci_footbot_base_ground_sensor ci_sensor controllable_entity datatypes embodied_entity entity "
        "general medium physics_engine quaternion range rng sensor space string_utilities vector2 "
        "vector3"),
    "plugins/robots/foot-bot/simulator/footbot_distance_scanner_default_actuator.h": (
        "actuator angles any argos_configuration argos_exception argos_log ci_actuator ci_controller "
        "ci_footbot_distance_scanner_actuator ci_sensor composable_entity controllable_entity "
        "datatypes embodied_entity entity footbot_entity general medium physics_engine quaternion "
        "range space string_utilities vector2 vector3"),
    "plugins/robots/foot-bot/simulator/footbot_distance_scanner_rotzonly_sensor.h": (
        "angles argos_configuration argos_exception argos_log ci_footbot_distance_scanner_sensor "
        "ci_sensor datatypes embodied_entity entity general physics_engine quaternion range rng "
        "sensor string_utilities vector2 vector3"),
    "plugins/robots/foot-bot/simulator/footbot_entity.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller ci_sensor "
        "composable_entity controllable_entity datatypes embodied_entity entity general medium "
        "physics_engine quaternion range space string_utilities vector2 vector3"),
    "plugins/robots/foot-bot/simulator/footbot_gripper_default_actuator.h": (
        "actuator angles argos_configuration argos_exception argos_log ci_actuator "
        "ci_footbot_gripper_actuator datatypes entity general quaternion range string_utilities "
        "vector2 vector3"),
    "plugins/robots/foot-bot/simulator/footbot_light_rotzonly_sensor.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller "
        "ci_footbot_light_sensor ci_sensor controllable_entity datatypes embodied_entity entity "
        "general medium physics_engine quaternion range rng sensor space string_utilities vector2 "
        "vector3"),
    "plugins/robots/foot-bot/simulator/footbot_motor_ground_rotzonly_sensor.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller "
        "ci_footbot_motor_ground_sensor ci_sensor controllable_entity datatypes embodied_entity "
        "entity general medium physics_engine quaternion range rng sensor space string_utilities "
        "vector2 vector3"),
    "plugins/robots/foot-bot/simulator/footbot_proximity_default_sensor.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller "
        "ci_footbot_proximity_sensor ci_sensor controllable_entity datatypes embodied_entity entity "
        "general medium physics_engine quaternion range rng sensor space string_utilities vector2 "
        "vector3"),
    "plugins/robots/foot-bot/simulator/footbot_turret_default_actuator.h": (
        "actuator angles any argos_configuration argos_exception argos_log ci_actuator ci_controller "
        "ci_footbot_turret_actuator ci_sensor composable_entity controllable_entity datatypes "
        "embodied_entity entity footbot_entity general medium physics_engine quaternion range space "
        "string_utilities vector2 vector3"),
    "plugins/robots/foot-bot/simulator/footbot_turret_encoder_default_sensor.h": (
        "angles argos_configuration argos_exception argos_log ci_footbot_turret_encoder_sensor "
        "ci_sensor datatypes entity general range sensor string_utilities vector2 vector3"),
    "plugins/robots/generic/control_interface/ci_battery_sensor.h": (
        "argos_configuration argos_exception ci_sensor datatypes"),
    "plugins/robots/generic/control_interface/ci_colored_blob_omnidirectional_camera_sensor.h": (
        "angles argos_configuration argos_exception argos_log ci_sensor color datatypes general range "
        "string_utilities"),
    "plugins/robots/generic/control_interface/ci_differential_steering_actuator.h": (
        "argos_configuration argos_exception ci_actuator datatypes"),
    "plugins/robots/generic/control_interface/ci_differential_steering_sensor.h": (
        "argos_configuration argos_exception ci_sensor datatypes"),
    "plugins/robots/generic/control_interface/ci_leds_actuator.h": (
        "argos_configuration argos_exception ci_actuator color datatypes string_utilities"),
    "plugins/robots/generic/control_interface/ci_positioning_sensor.h": (
        "angles argos_configuration argos_exception ci_sensor datatypes general quaternion range "
        "string_utilities vector2 vector3"),
    "plugins/robots/generic/control_interface/ci_range_and_bearing_actuator.h": (
        "argos_configuration argos_exception byte_array ci_actuator datatypes"),
    "plugins/robots/generic/control_interface/ci_range_and_bearing_sensor.h": (
        "angles argos_configuration argos_exception byte_array ci_sensor datatypes general quaternion "
        "range string_utilities vector2 vector3"),
    "plugins/robots/generic/simulator/battery_default_sensor.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_battery_sensor "
        "ci_controller ci_sensor controllable_entity datatypes embodied_entity entity general medium "
        "physics_engine quaternion range rng sensor space string_utilities vector2 vector3"),
    "plugins/robots/generic/simulator/colored_blob_omnidirectional_camera_rotzonly_sensor.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator "
        "ci_colored_blob_omnidirectional_camera_sensor ci_controller ci_sensor color "
        "controllable_entity datatypes embodied_entity entity general medium physics_engine "
        "quaternion range rng sensor space string_utilities vector2 vector3"),
    "plugins/robots/generic/simulator/differential_steering_default_actuator.h": (
        "actuator angles any argos_configuration argos_exception argos_log ci_actuator ci_controller "
        "ci_differential_steering_actuator ci_sensor composable_entity controllable_entity datatypes "
        "embodied_entity entity general medium physics_engine quaternion range rng space "
        "string_utilities vector2 vector3"),
    "plugins/robots/generic/simulator/differential_steering_default_sensor.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller "
        "ci_differential_steering_sensor ci_sensor controllable_entity datatypes embodied_entity "
        "entity general medium physics_engine quaternion range rng sensor space string_utilities "
        "vector2 vector3"),
    "plugins/robots/generic/simulator/leds_default_actuator.h": (
        "actuator angles any argos_configuration argos_exception argos_log ci_actuator ci_controller "
        "ci_leds_actuator ci_sensor color composable_entity controllable_entity datatypes "
        "embodied_entity entity general led_entity led_equipped_entity medium physics_engine "
        "positional_entity quaternion range space string_utilities vector2 vector3"),
    "plugins/robots/generic/simulator/positioning_default_sensor.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller "
        "ci_positioning_sensor ci_sensor controllable_entity datatypes embodied_entity entity general "
        "medium physics_engine quaternion range rng sensor space string_utilities vector2 vector3"),
    "plugins/robots/generic/simulator/range_and_bearing_default_actuator.h": (
        "actuator angles argos_configuration argos_exception argos_log byte_array ci_actuator "
        "ci_range_and_bearing_actuator datatypes entity general positional_entity quaternion range "
        "string_utilities vector2 vector3"),
    "plugins/robots/generic/simulator/range_and_bearing_medium_sensor.h": (
        "angles any argos_configuration argos_exception argos_log byte_array ci_actuator "
        "ci_controller ci_range_and_bearing_sensor ci_sensor controllable_entity datatypes "
        "embodied_entity entity general medium physics_engine quaternion range rng sensor space "
        "string_utilities vector2 vector3"),
    "plugins/simulator/entities/box_entity.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller ci_sensor "
        "color composable_entity controllable_entity datatypes embodied_entity entity general "
        "led_entity led_equipped_entity medium physics_engine positional_entity quaternion range "
        "space string_utilities vector2 vector3"),
    "plugins/simulator/entities/cylinder_entity.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller ci_sensor "
        "color composable_entity controllable_entity datatypes embodied_entity entity general "
        "led_entity led_equipped_entity medium physics_engine positional_entity quaternion range "
        "space string_utilities vector2 vector3"),
    "plugins/simulator/entities/led_entity.h": (
        "angles argos_configuration argos_exception argos_log color datatypes entity general "
        "positional_entity quaternion range string_utilities vector2 vector3"),
    "plugins/simulator/entities/led_equipped_entity.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller ci_sensor "
        "color composable_entity controllable_entity datatypes embodied_entity entity general "
        "led_entity medium physics_engine positional_entity quaternion range space string_utilities "
        "vector2 vector3"),
    "plugins/simulator/entities/light_entity.h": (
        "angles any argos_configuration argos_exception argos_log ci_actuator ci_controller ci_sensor "
        "color composable_entity controllable_entity datatypes embodied_entity entity general "
        "led_entity led_equipped_entity medium physics_engine positional_entity quaternion range "
        "space string_utilities vector2 vector3"),
    "plugins/simulator/media/led_medium.h": (
        "angles argos_configuration argos_exception argos_log color datatypes entity general "
        "led_entity medium positional_entity quaternion range string_utilities vector2 vector3"),
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
    "physics_engine": "(void)argos::CPhysicsEngine::GetSimulationClockTick;",
    "ci_sensor": "(void)sizeof(argos::CCI_Sensor::TMap);",
    "ci_actuator": "(void)sizeof(argos::CCI_Actuator::TMap);",
    "sensor": "(void)sizeof(argos::CSimulatedSensor);",
    "actuator": "(void)sizeof(argos::CSimulatedActuator);",
    "byte_array": "(void)argos::CByteArray(2).Size();",
    "ci_footbot_base_ground_sensor": "(void)sizeof(argos::CCI_FootBotBaseGroundSensor::SReading);",
    "ci_footbot_distance_scanner_actuator": "(void)sizeof(argos::CCI_FootBotDistanceScannerActuator);",
    "ci_footbot_distance_scanner_sensor": "(void)sizeof(argos::CCI_FootBotDistanceScannerSensor::TReadingsMap);",
    "ci_footbot_gripper_actuator": "(void)argos::CCI_FootBotGripperActuator::LOCKED_POSITIVE;",
    "ci_footbot_light_sensor": "(void)sizeof(argos::CCI_FootBotLightSensor::TReadings);",
    "ci_footbot_motor_ground_sensor": "(void)sizeof(argos::CCI_FootBotMotorGroundSensor::SReading);",
    "ci_footbot_proximity_sensor": "(void)sizeof(argos::CCI_FootBotProximitySensor::TReadings);",
    "ci_footbot_turret_actuator": "(void)argos::CCI_FootBotTurretActuator::MODE_SPEED_CONTROL;",
    "ci_footbot_turret_encoder_sensor": "(void)sizeof(argos::CCI_FootBotTurretEncoderSensor);",
    "ci_battery_sensor": "(void)argos::CCI_BatterySensor::SReading().TimeLeft;",
    "ci_colored_blob_omnidirectional_camera_sensor": (
        "(void)argos::CCI_ColoredBlobOmnidirectionalCameraSensor::SReadings().Counter;"),
    "ci_differential_steering_actuator": "(void)sizeof(argos::CCI_DifferentialSteeringActuator);",
    "ci_differential_steering_sensor": "(void)argos::CCI_DifferentialSteeringSensor::SReading().WheelAxisLength;",
    "ci_leds_actuator": "(void)sizeof(argos::CCI_LEDsActuator::TSettings);",
    "ci_positioning_sensor": "(void)sizeof(argos::CCI_PositioningSensor::SReading);",
    "ci_range_and_bearing_actuator": "(void)sizeof(argos::CCI_RangeAndBearingActuator);",
    "ci_range_and_bearing_sensor": "(void)argos::CCI_RangeAndBearingSensor::SPacket().Data.Size();",
    "footbot_base_ground_rotzonly_sensor": "(void)sizeof(argos::CFootBotBaseGroundRotZOnlySensor);",
    "footbot_distance_scanner_default_actuator": "(void)sizeof(argos::CFootBotDistanceScannerDefaultActuator);",
    "footbot_distance_scanner_rotzonly_sensor": "(void)sizeof(argos::CFootBotDistanceScannerRotZOnlySensor);",
    "footbot_gripper_default_actuator": "(void)sizeof(argos::CFootBotGripperDefaultActuator);",
    "footbot_light_rotzonly_sensor": "(void)sizeof(argos::CFootBotLightRotZOnlySensor);",
    "footbot_motor_ground_rotzonly_sensor": "(void)sizeof(argos::CFootBotMotorGroundRotZOnlySensor);",
    "footbot_proximity_default_sensor": "(void)sizeof(argos::CFootBotProximityDefaultSensor);",
    "footbot_turret_default_actuator": "(void)sizeof(argos::CFootBotTurretDefaultActuator);",
    "footbot_turret_encoder_default_sensor": "(void)sizeof(argos::CFootBotTurretEncoderDefaultSensor);",
    "battery_default_sensor": "(void)sizeof(argos::CBatteryDefaultSensor);",
    "colored_blob_omnidirectional_camera_rotzonly_sensor": (
        "(void)sizeof(argos::CColoredBlobOmnidirectionalCameraRotZOnlySensor);"),
    "differential_steering_default_actuator": "(void)sizeof(argos::CDifferentialSteeringDefaultActuator);",
    "differential_steering_default_sensor": "(void)sizeof(argos::CDifferentialSteeringDefaultSensor);",
    "leds_default_actuator": "(void)sizeof(argos::CLEDsDefaultActuator);",
    "positioning_default_sensor": "(void)sizeof(argos::CPositioningDefaultSensor);",
    "range_and_bearing_default_actuator": "(void)sizeof(argos::CRangeAndBearingDefaultActuator);",
    "range_and_bearing_medium_sensor": "(void)sizeof(argos::CRangeAndBearingMediumSensor);",
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
