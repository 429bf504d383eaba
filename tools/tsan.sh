#!/usr/bin/env bash
# ThreadSanitizer check of the parallel stages (docs/robustness.md): clang with
# -fsanitize=thread in build-tsan/, then multi-threaded runs that exercise each stage the
# threads split: act (from 256 robots), media (from 64 RAB devices), sense + control, the
# shared ray grid, and gripper/turret joints. Any report fails the script.
#   tools/tsan.sh            (not part of CI: the build takes ~5 CPU-minutes)
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
CC=clang CXX=clang++ cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" \
  -DCMAKE_C_FLAGS=-fsanitize=thread -DCMAKE_CXX_FLAGS=-fsanitize=thread -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread > /dev/null
cmake --build build-tsan -j2 --target essaim
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1}
status=0
for run in "arenas/foraging.argos 300 2" "arenas/clustering.argos 300 3" "bench/rab_1000.argos 15 2" \
           "bench/avoidance_1000.argos 15 2"; do
  set -- $run
  name=$(basename "$1" .argos)
  if build-tsan/essaim run "$1" --ticks "$2" --threads "$3" --record -o "$out/$name" > "$out/$name.log" 2>&1; then
    echo "tsan: $1 ($2 ticks, $3 threads): clean"
  else
    echo "tsan: $1 ($2 ticks, $3 threads): FAILED"; grep -A30 "WARNING: ThreadSanitizer" "$out/$name.log" | head -60 || tail -20 "$out/$name.log"
    status=1
  fi
done
exit $status
