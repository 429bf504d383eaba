"""Where C++ loop-function libraries and essaim's ARGoS API reach (docs/loop-functions.md, "C++
loop functions", "Libraries"): every library name ARGoS installs links to essaim's API, whose
soname is essaim's own, so an ARGoS on LD_LIBRARY_PATH is never loaded; one experiment's
libraries see each other's symbols, a later experiment's never do; a label is looked up among
the experiment's libraries (the last one's when several register it), and registered twice in
one of them is refused."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

from argos_projects import ESSAIM, HERE, build_project, need_essaim, skip_without_python_module
from argos_projects import run as run_essaim

pytestmark = need_essaim

SONAME = "libessaim_argos_api.so.1"
ARGOS_NAMES = ["argos3core_simulator"] + [f"argos3plugin_simulator_{p}" for p in (
    "block", "builderbot", "drone", "dynamics2d", "dynamics3d", "dynamics3d_floor", "dynamics3d_gravity",
    "dynamics3d_magnetism", "dynamics3d_srocs", "entities", "epuck", "eyebot", "footbot", "genericrobot", "media",
    "pipuck", "pointmass3d", "prototype", "qtopengl", "spiri")]
MARKER = "A LIBRARY OF ARGOS ITSELF WAS LOADED"


@pytest.fixture(scope="module")
def stand_in(tmp_path_factory):
    """A folder of libraries named as ARGoS's, each ending the process (exit 86) when loaded."""
    folder = tmp_path_factory.mktemp("argos_lib")
    source = folder / "stand_in.c"
    source.write_text('#include <stdio.h>\n#include <unistd.h>\n'
                      f'__attribute__((constructor)) static void loaded(void) {{ fputs("{MARKER}\\n", stderr); '
                      '_exit(86); }\n')
    for name in ARGOS_NAMES:
        done = subprocess.run(["cc", "-shared", "-fPIC", "-o", str(folder / f"lib{name}.so"), str(source)],
                              capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
    return folder


@pytest.fixture(scope="module")
def scope(tmp_path_factory, stand_in):
    """The scope project built with ARGoS's stand-ins on LD_LIBRARY_PATH (TWIN_WORD "first")."""
    return build_project(HERE / "scope_project", tmp_path_factory.mktemp("first"),
                         env={"LD_LIBRARY_PATH": str(stand_in)})


@pytest.fixture(scope="module")
def second(tmp_path_factory):
    """The same project built with TWIN_WORD "second": the same class under the same label."""
    return build_project(HERE / "scope_project", tmp_path_factory.mktemp("second"), cmake_args=["-DTWIN_WORD=second"])


def run(argos: Path, *args, cwd: Path, env=None):
    """essaim run, with the twin.txt of an earlier run removed."""
    (cwd / "twin.txt").unlink(missing_ok=True)
    return run_essaim(argos, *args, cwd=cwd, env=env)


def twin(out: Path) -> str:
    """The twin.txt the run's loop functions wrote, in its working folder <out>/files."""
    return (out / "files" / "twin.txt").read_text()


def needed(library: Path):
    dynamic = subprocess.run(["readelf", "-d", str(library)], capture_output=True, text=True).stdout
    return [line.split("[", 1)[1].rstrip("]") for line in dynamic.splitlines() if "(NEEDED)" in line]


def test_every_argos_library_name_links_to_essaims_soname(scope):
    for name in ARGOS_NAMES:  # each a link to essaim's library, which the linker records
        assert os.path.realpath(Path(ESSAIM).resolve().parent / "argos3-sdk" / "lib" / f"lib{name}.so").endswith(SONAME)
    libraries = needed(scope / "build" / "libtwin_loop_functions.so")
    assert SONAME in libraries and not [n for n in libraries if "argos3" in n]
    assert not [n for n in needed(Path(ESSAIM)) if "argos3" in n]


def test_an_argos_on_ld_library_path_is_never_loaded(scope, stand_in, tmp_path):
    env = {"LD_LIBRARY_PATH": str(stand_in)}
    done = run(scope / "scope.argos", "--out", str(tmp_path / "out"), cwd=scope, env=env)
    assert done.returncode == 0, done.stderr
    assert MARKER not in done.stderr and twin(tmp_path / "out") == "first\n"
    ldd = subprocess.run(["ldd", str(scope / "build" / "libtwin_loop_functions.so")], capture_output=True, text=True,
                         env=dict(os.environ, **env)).stdout
    assert SONAME in ldd and "libargos3" not in ldd and str(stand_in) not in ldd


def test_a_library_linked_against_argos_itself_is_refused_unloaded(scope, stand_in, tmp_path):
    """Linked against ARGoS's library (here its stand-in), it would load ARGoS: refused first."""
    source = tmp_path / "built_against_argos.c"
    source.write_text("int built_against_argos(void) { return 1; }\n")
    library = scope / "build" / "libbuilt_against_argos.so"
    subprocess.run(["cc", "-shared", "-fPIC", "-o", str(library), str(source), f"-L{stand_in}",
                    "-Wl,--no-as-needed", "-largos3core_simulator", f"-Wl,-rpath,{stand_in}"], check=True)
    argos = scope / "built_against_argos.argos"
    argos.write_text((scope / "scope.argos").read_text().replace("libtwin_loop_functions", "libbuilt_against_argos"))
    done = run(argos, "--out", str(tmp_path / "out"), cwd=scope)
    assert done.returncode == 2, done.stderr
    assert MARKER not in done.stderr and "<loop_functions>" in done.stderr
    assert "was built against ARGoS itself or an older essaim (it needs libargos3core_simulator.so)" in done.stderr


def test_a_label_registered_twice_in_one_library_is_refused(scope, tmp_path):
    argos = scope / "twice.argos"
    argos.write_text((scope / "scope.argos").read_text().replace("libtwin_loop_functions", "libtwice_loop_functions"))
    done = run(argos, "--out", str(tmp_path / "out"), cwd=scope)
    assert done.returncode == 2, done.stderr
    assert "twice.argos:" in done.stderr and "<loop_functions>" in done.stderr
    assert "label 'twin_loop_functions' is registered twice in " in done.stderr


def test_a_label_is_looked_up_in_the_library_named_only(scope, tmp_path):
    """The library named needs the one that registers the label: not found, and said so."""
    argos = scope / "thin.argos"
    argos.write_text((scope / "scope.argos").read_text().replace("libtwin_loop_functions", "libthin_loop_functions"))
    done = run(argos, "--out", str(tmp_path / "out"), cwd=scope)
    assert done.returncode == 2, done.stderr
    assert "no loop functions registered as 'twin_loop_functions'" in done.stderr
    assert f"{(scope / 'build' / 'libtwin_loop_functions.so').resolve()} registers it" in done.stderr


def helper_experiment(scope):
    argos = scope / "helper.argos"
    text = (scope / "scope.argos").read_text().replace('library="build/libtwin_loop_functions.so" ', "")
    argos.write_text(text.replace('"twin_loop_functions"', '"needs_helper_loop_functions"'))
    return argos


def test_a_library_uses_what_another_library_of_the_experiment_defines(scope, tmp_path):
    """Label alone: ARGOS_PLUGIN_PATH's libraries are loaded together, as ARGoS loads them."""
    argos = helper_experiment(scope)
    plugin_path = f"{scope / 'build' / 'libtwin_helper.so'}:{scope / 'build' / 'libneeds_helper_loop_functions.so'}"
    done = run(argos, "--out", str(tmp_path / "a"), cwd=scope, env={"ARGOS_PLUGIN_PATH": plugin_path})
    assert done.returncode == 0, done.stderr
    assert twin(tmp_path / "a") == "helped\n"
    # Named alone, the library lacks its helper's function.
    done = run(argos, "--out", str(tmp_path / "b"), cwd=scope,
               env={"ARGOS_PLUGIN_PATH": str(scope / "build" / "libneeds_helper_loop_functions.so")})
    assert done.returncode == 2 and "undefined symbol: TwinHelperWord" in done.stderr


def label_alone(scope):
    argos = scope / "by_label.argos"
    argos.write_text((scope / "scope.argos").read_text().replace('library="build/libtwin_loop_functions.so" ', ""))
    return argos


def test_a_label_is_looked_up_in_the_experiments_libraries_only(scope, second, tmp_path):
    """Label alone, ARGOS_PLUGIN_PATH naming the second build: its class, not the first's."""
    plugin_path = str(second / "build" / "libtwin_loop_functions.so")
    done = run(label_alone(scope), "--out", str(tmp_path / "out"), cwd=scope, env={"ARGOS_PLUGIN_PATH": plugin_path})
    assert done.returncode == 0, done.stderr
    assert twin(tmp_path / "out") == "second\n"


@pytest.mark.parametrize("order, word", [(["twin", "rival"], "rival"), (["rival", "twin"], "first")])
def test_a_label_two_libraries_register_is_the_last_ones(scope, tmp_path, order, word):
    """Label alone, as ARGoS's factory keeps the last registration: ARGOS_PLUGIN_PATH's order."""
    plugin_path = ":".join(str(scope / "build" / f"lib{name}_loop_functions.so") for name in order)
    done = run(label_alone(scope), "--out", str(tmp_path / "out"), cwd=scope, env={"ARGOS_PLUGIN_PATH": plugin_path})
    assert done.returncode == 0, done.stderr
    assert twin(tmp_path / "out") == word + "\n"


def test_experiments_in_one_process_each_get_their_own_class(scope, second, tmp_path):
    """Two projects' libraries define the same class under the same label; one Python process
    runs the first, the second, then the first again (both libraries loaded by then)."""
    module = Path(ESSAIM).resolve().parent / "python"
    skip_without_python_module()
    script = (
        "import os, sys, essaim\n"
        "for folder in sys.argv[1:]:\n"
        "    os.chdir(folder)\n"
        "    if os.path.exists('twin.txt'): os.remove('twin.txt')\n"
        "    s = essaim.Simulation('scope.argos', seed=1)\n"
        "    s.run(); s.finish()\n"
        "    print(open('twin.txt').read().strip())\n")
    done = subprocess.run([sys.executable, "-c", script, str(scope), str(second), str(scope)], capture_output=True,
                          text=True, timeout=300, env=dict(os.environ, PYTHONPATH=str(module)))
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["first", "second", "first"]
