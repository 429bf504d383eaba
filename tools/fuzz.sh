#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz, clang, ASan + UBSan) and runs each for a fixed
# time (docs/robustness.md).
#   tools/fuzz.sh [SECONDS_PER_TARGET=60] [TARGET...]     targets: argos recording png lua_bindings
# FUZZ_BUILD=DIR picks the build folder (default build-fuzz; CI reuses its sanitizer build),
# FUZZ_SEED=N the random seed.
# Findings (crash-*, timeout-*, oom-*, leak-*) land in DIR/findings/<target>/; inputs that
# raised coverage are kept in DIR/corpus/<target>/ (the committed seeds in tests/fuzz/corpus/
# stay untouched). Exits 1 when any target found something.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
((${#targets[@]})) || targets=(argos recording png lua_bindings)
build=${FUZZ_BUILD:-build-fuzz}
# FUZZ_SEED=N repeats the same mutations (CI: a pass that is green here stays green there,
# it only runs further or less far); 0, the default, lets libFuzzer pick.
seed=${FUZZ_SEED:-0}

if [ ! -f "$build/build.ninja" ]; then
  launcher=()
  if command -v ccache > /dev/null; then
    launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  fi
  CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DESSAIM_FUZZ=ON \
    "${launcher[@]}" > /dev/null
fi
cmake --build "$build" -j2 --target "${targets[@]/#/fuzz_}"

status=0
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/findings/$t"
  log="$build/fuzz_$t.log"
  # -timeout: an input running over 10 s is a hang; -rss_limit_mb: over 2 GiB a blow-up.
  if ! "$build/fuzz_$t" "$build/corpus/$t" "tests/fuzz/corpus/$t" -max_total_time="$seconds" \
      -seed="$seed" -timeout=10 -rss_limit_mb=2048 -max_len=16384 -artifact_prefix="$build/findings/$t/" \
      -print_final_stats=1 > "$log" 2>&1; then
    status=1
    echo "fuzz_$t: FOUND A PROBLEM ($log, $build/findings/$t/):"
    grep -E "ERROR|runtime error|SUMMARY|Test unit written" "$log" | head -5 || true
  fi
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  # libFuzzer stops at its first finding: then fewer seconds than asked were run.
  done_line=$(grep -o 'Done [0-9]* runs in [0-9]* second' "$log" | grep -o 'in [0-9]*' | grep -o '[0-9]*' || true)
  echo "fuzz_$t: $execs executions in ${done_line:-less than $seconds (stopped at a finding)} s, coverage $cov edges"
done
exit $status
