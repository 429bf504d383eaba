#!/bin/bash
# essaim against ARGoS 3 on this machine, 1 000 foot-bots, one thread, no visualization:
# the diffusion arena with a trivial Lua controller (bench/minimal.lua) and with the C++
# avoidance controller (bench/avoidance_cpp/, built here against ARGoS's own headers).
#
#   bench/argos_side_by_side/run.sh ARGOS_PREFIX [ESSAIM_BUILD_DIR] [REPEAT]
#
# ARGOS_PREFIX: an ARGoS 3 install (bin/argos3, include/argos3, lib/argos3). ESSAIM_BUILD_DIR:
# default build. REPEAT (default 3): runs per measurement, the least CPU time is kept.
# ARGOS_SOURCE (optional, environment): ARGoS's git checkout, to print its version.
#
# Both simulators are timed the same way: CPU seconds (user + system, /usr/bin/time) of a
# 200-tick run less those of a 20-tick run, over 1 000 robots x 180 ticks, so that start-up,
# loading and placement cancel. essaim's own `essaim bench` line (wall time, after set-up)
# is printed beside. Not run by ctest: ARGoS is no dependency of essaim.
set -euo pipefail

ARGOS=$(realpath "${1:?usage: run.sh ARGOS_PREFIX [ESSAIM_BUILD_DIR] [REPEAT]}")
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
BUILD=$(realpath "${2:-$ROOT/build}")
REPEAT=${3:-3}
WORK=$(mktemp -d /tmp/argos-side-by-side.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
export ARGOS ROOT BUILD WORK

# The C++ controller, compiled against ARGoS's installed headers and libraries (and Lua's,
# which ARGoS's sensor interface includes).
g++ -O3 -DNDEBUG -std=c++17 -shared -fPIC -o "$WORK/libbench_avoidance_argos.so" "$ROOT/bench/avoidance_cpp/avoidance.cpp" \
  -I"$ARGOS/include" $(pkg-config --cflags lua5.4 2>/dev/null || echo -I/usr/include/lua5.4) \
  -L"$ARGOS/lib/argos3" -Wl,-rpath,"$ARGOS/lib/argos3" -largos3core_simulator \
  -largos3plugin_simulator_footbot -largos3plugin_simulator_genericrobot

# experiment NAME LENGTH_SECONDS: the filled-in ARGoS file's path.
experiment() {
  local out="$WORK/$1-$2.argos"
  sed -e "s|@LENGTH@|$2|" -e "s|@SCRIPT@|$ROOT/bench/minimal.lua|" \
    -e "s|@LIBRARY@|$WORK/libbench_avoidance_argos|" "$HERE/$1.argos.in" >"$out"
  echo "$out"
}

# cpu_seconds FUNCTION ARGS...: the least user + system CPU seconds of REPEAT runs of the
# function, each in a child bash that /usr/bin/time counts whole.
cpu_seconds() {
  local best=""
  for _ in $(seq "$REPEAT"); do
    /usr/bin/time -f "%U %S" -o "$WORK/time" bash -c "$(declare -f "$1"); cd '$WORK' && $*" >"$WORK/out" 2>&1 || {
      cat "$WORK/out" >&2
      return 1
    }
    local t
    t=$(awk '{print $1 + $2}' "$WORK/time")
    if [ -z "$best" ] || awk -v a="$t" -v b="$best" 'BEGIN{exit !(a < b)}'; then best=$t; fi
  done
  echo "$best"
}

# per_step SHORT LONG: µs per robot-step from the two CPU times (1 000 robots, 180 ticks).
per_step() { awk -v s="$1" -v l="$2" 'BEGIN{printf "%.2f", (l - s) * 1e6 / (1000 * 180)}'; }

# Each simulator with its own library paths: essaim's bench controller links the ARGoS
# library names that essaim's own API library stands for, which ARGoS's must not shadow.
argos_run() {
  env LD_LIBRARY_PATH="$ARGOS/lib/argos3" ARGOS_PLUGIN_PATH="$ARGOS/lib/argos3" "$ARGOS/bin/argos3" -z -c "$1"
}
essaim_run() {
  env -u LD_LIBRARY_PATH ARGOS_PLUGIN_PATH="$BUILD/bench" "$BUILD/essaim" run "$ROOT/bench/$1" -q --threads 1 \
    --ticks "$2" -o "$WORK/essaim-out"
}

echo "# $(date -u +%FT%TZ) on $(hostname); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
lscpu | grep -E "^(Model name|CPU\(s\)|L1d|L2|L3)" | sed 's/^/# /'
echo "# essaim $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?') ($BUILD), ARGoS at $ARGOS${ARGOS_SOURCE:+ ($(git -C "$ARGOS_SOURCE" describe --tags 2>/dev/null))}"
printf "%-20s %12s %12s %8s\n" scenario "ARGoS us/r-s" "essaim us/r-s" "ratio"
for pair in "diffusion-minimal diffusion_1000" "avoidance-cpp-1000 avoidance_cpp_1000"; do
  set -- $pair
  a_short=$(cpu_seconds argos_run "$(experiment "$2" 2)")
  a_long=$(cpu_seconds argos_run "$(experiment "$2" 20)")
  e_short=$(cpu_seconds essaim_run "$2.argos" 20)
  e_long=$(cpu_seconds essaim_run "$2.argos" 200)
  a=$(per_step "$a_short" "$a_long")
  e=$(per_step "$e_short" "$e_long")
  printf "%-20s %12s %12s %8s\n" "$1" "$a" "$e" "$(awk -v a="$a" -v e="$e" 'BEGIN{printf "%.1f", a / e}')"
done
echo "# essaim bench, same build (wall us per robot-step after set-up):"
ARGOS_PLUGIN_PATH="$BUILD/bench" "$BUILD/essaim" bench --only diffusion-minimal,avoidance-cpp-1000 --ticks 200 --dir "$ROOT/bench" |
  sed 's/^/# /'
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"
