#!/usr/bin/env bash
# Installs what is missing on Debian 12, makes the Python venv, builds essaim.
# Idempotent: rerunning only rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(build-essential cmake ninja-build pkg-config
          libbox2d-dev liblua5.4-dev lua5.4 libtinyxml2-dev libeigen3-dev libpng-dev libcairo2-dev
          libgtest-dev googletest libcli11-dev nlohmann-json3-dev python3 python3-venv python3-pip python3-dev
          pybind11-dev libcpp-httplib-dev chromium clang-format-14 ffmpeg
          libtomlplusplus-dev lua-check)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "essaim setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

if [ ! -x .venv/bin/python3 ]; then
  python3 -m venv .venv
fi
.venv/bin/python3 -m pip install -q --disable-pip-version-check -r scripts/requirements.txt

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DESSAIM_PYTHON="$PWD/.venv/bin/python3" > /dev/null
cmake --build build
# `essaim` on PATH (a link in /usr/local/bin as root, else ~/.local/bin) and `import essaim`
# in the venv.
bash scripts/link_build.sh
echo "essaim setup: built build/essaim (also \`essaim\` on PATH) and the Python module (.venv/bin/python -c 'import essaim')"
