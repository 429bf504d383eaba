"""SIERRA imports engine plugins as `engine.<name>`; its own `engine` package (ARGoS, ROS)
is a regular package, so this one extends its path over every `engine/` folder on
sys.path: `engine.essaim` (here) and `engine.argos` (SIERRA's) both import."""
import pkgutil

__path__ = pkgutil.extend_path(__path__, __name__)  # noqa: F821 (set by the import system)
