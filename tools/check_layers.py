#!/usr/bin/env python3
"""Layers include only downward: every `#include "<folder>/..."` in src/ must name a layer
below the including file's own (or the same one). Exit 1 naming each upward include.

The order is the one README.md's Architecture section draws and src/CMakeLists.txt links.
lua/host sits beside the simulation layers, not above them: it sees only core.
argos (C++ loop functions, the ARGoS API) sits beside lua/loop, on the same floor: neither
sees the other, and only sim above them sees both.
A header named *_impl.h is private to its folder (model/xml_loader_impl.h: the loader's class):
only files in that folder include it.
"""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
# Each layer and the layers it may include (itself included).
BELOW = {
    "core": {"core"},
    "spatial": {"core", "spatial"},
    "model": {"core", "spatial", "model"},
    "physics": {"core", "spatial", "model", "physics"},
    "devices": {"core", "spatial", "model", "physics", "devices"},
    "lua/host": {"core", "lua/host"},
}
BELOW["lua/debug"] = BELOW["lua/host"] | {"lua/debug"}
BELOW["lua/robot"] = BELOW["devices"] | BELOW["lua/host"] | {"lua/robot"}
BELOW["lua/loop"] = BELOW["lua/robot"] | {"lua/loop"}
BELOW["argos"] = BELOW["lua/robot"] | {"argos"}
BELOW["sim"] = BELOW["lua/loop"] | BELOW["argos"] | {"sim"}
BELOW["output"] = BELOW["sim"] | {"output"}
BELOW["serve"] = BELOW["output"] | {"serve"}
BELOW["render"] = BELOW["output"] | {"render"}
BELOW["python"] = BELOW["render"] | {"python"}
BELOW["debug"] = BELOW["serve"] | BELOW["lua/debug"] | {"debug"}
BELOW["app"] = BELOW["debug"] | BELOW["render"] | {"app"}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def layer_of(relative: str) -> str | None:
    """The layer a path under src/ belongs to ("lua/host/x.h" -> "lua/host")."""
    parts = relative.split("/")
    if parts[0] == "lua" and len(parts) > 2:
        return "lua/" + parts[1]
    return parts[0] if parts[0] in BELOW else None


def main() -> int:
    src = ROOT / "src"
    upward = []
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".cpp", ".h"):
            continue
        own = layer_of(str(path.relative_to(src)))
        if own is None:
            upward.append(f"{path.relative_to(ROOT)}: not in any known layer")
            continue
        for target in INCLUDE.findall(path.read_text(encoding="utf-8")):
            if "/" not in target:
                continue  # a file beside it, or a generated one
            other = layer_of(target)
            if target.endswith("_impl.h") and Path(target).parent != path.parent.relative_to(src):
                upward.append(f"{path.relative_to(ROOT)}: includes {target}, private to src/{Path(target).parent}")
                continue
            if other is not None and other not in BELOW[own]:
                upward.append(f"{path.relative_to(ROOT)}: {own} includes {target} ({other} is above it)")
    if upward:
        print(f"check_layers: {len(upward)} include(s) against the layer order or a private header:", file=sys.stderr)
        for line in upward:
            print("  " + line, file=sys.stderr)
        return 1
    print(f"check_layers: every include in src/ goes downward ({len(BELOW)} layers)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
