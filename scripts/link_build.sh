#!/usr/bin/env bash
# Makes this checkout's build reachable the way the docs use it (scripts/setup.sh runs it;
# rerun it after moving the checkout):
#  - `essaim` on PATH: a link to build/essaim in BIN_DIR (default /usr/local/bin as root,
#    else ~/.local/bin);
#  - `import essaim` in .venv: a .pth file puts build/python (the module) on its path.
# Usage: scripts/link_build.sh [BIN_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
target="$PWD/build/essaim"
if [ ! -x "$target" ]; then
  echo "essaim setup: $target is not built (bash scripts/setup.sh builds it)" >&2
  exit 1
fi
if [ $# -gt 0 ]; then
  bin_dir=$1
elif [ "$(id -u)" -eq 0 ]; then
  bin_dir=/usr/local/bin
else
  bin_dir="$HOME/.local/bin"
fi
mkdir -p "$bin_dir"
link="$bin_dir/essaim"
if [ -e "$link" ] && [ ! -L "$link" ]; then
  # Someone installed essaim there another way: theirs stays.
  echo "essaim setup: $link is a file, not a link: left as it is; this build is $target" >&2
else
  ln -sfn "$target" "$link"
  echo "essaim setup: $link -> $target"
fi
case ":$PATH:" in
  *":$bin_dir:"*) ;;
  *) echo "essaim setup: $bin_dir is not on PATH; add it (in ~/.bashrc: export PATH=\"$bin_dir:\$PATH\")," \
          "or run build/essaim" ;;
esac
found=$(command -v essaim || true)
if [ -n "$found" ] && [ "$(readlink -f "$found")" != "$(readlink -f "$target")" ]; then
  echo "essaim setup: note: \`essaim\` in this shell is $found, which comes before $bin_dir on PATH"
fi

if [ -x .venv/bin/python3 ]; then
  site=$(.venv/bin/python3 -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
  echo "$PWD/build/python" > "$site/essaim-build.pth"
fi
