#!/usr/bin/env bash
# The sanitizer build (docs/robustness.md): clang with ASan + UBSan (no recovery: any report
# fails its test) and libFuzzer coverage, in build-asan/; the whole ctest suite under it,
# then a short fuzz pass of every target on the same build.
#   tools/sanitize.sh [FUZZ_SECONDS_PER_TARGET=12]      (0: no fuzz pass)
# Needs the packages scripts/setup.sh installs (and its .venv), plus clang: installed here
# when missing.
set -euo pipefail
cd "$(dirname "$0")/.."
fuzz_seconds=${1:-12}

missing=()
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

python=()  # the project's venv when there is one (else CMake's own choice, or the cached one)
[ -x .venv/bin/python3 ] && python=(-DESSAIM_PYTHON="$PWD/.venv/bin/python3")
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
start=$SECONDS
CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DESSAIM_SANITIZE=ON -DESSAIM_FUZZ=ON "${python[@]}" "${launcher[@]}" > /dev/null
cmake --build build-asan -j2
echo "sanitize: built in $((SECONDS - start)) s"
start=$SECONDS
# halt_on_error: the first report ends the process, so the test fails; leaks too.
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1} UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/lsan.supp}  # third-party leaks only
ctest --test-dir build-asan --output-on-failure -j2
echo "sanitize: suite in $((SECONDS - start)) s"
if ((fuzz_seconds > 0)); then
  # A fixed seed: the same mutations every time, so this pass does not turn red by chance.
  FUZZ_BUILD=build-asan FUZZ_SEED=${FUZZ_SEED:-1} tools/fuzz.sh "$fuzz_seconds"
fi
