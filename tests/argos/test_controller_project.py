"""A foot-bot C++ controller written as the census's are (controller_project/) builds against
the build tree's SDK as a shared library, and registers its label when loaded."""
import ctypes
import os

from argos_projects import HERE, build_project, need_essaim, sdk


@need_essaim
def test_a_census_style_controller_builds_and_registers(tmp_path):
    project = build_project(HERE / "controller_project", tmp_path)
    library = project / "build" / "libwanderer.so"
    assert library.exists()
    if os.environ.get("ESSAIM_SANITIZED") == "1":
        return  # built; loading it in this interpreter needs the sanitizers' runtime preloaded
    api = ctypes.CDLL(str(sdk() / "lib" / "libessaim_argos_api.so.1"), mode=os.RTLD_NOW | ctypes.RTLD_GLOBAL)
    ctypes.CDLL(str(library), mode=os.RTLD_NOW | ctypes.RTLD_GLOBAL)  # every symbol it uses is resolved
    assert api  # the registration itself is checked by the C++ tests (argos_controllers_test.cpp)
