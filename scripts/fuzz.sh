#!/usr/bin/env bash
# Runs each libFuzzer target for a given time on its seed corpus (tests/fuzz/corpus/<name>)
# plus a scratch corpus, in a Clang build with ASan + UBSan + fuzzer coverage. A crashing
# input is saved as tests/fuzz/regressions/<target>-<hash>; keep it there (it is replayed by
# this script on every run) and fix the bug. FUZZ_SEED (default 1) fixes the mutation
# sequence so a CI smoke run is reproducible; set another to explore further.
# Usage: scripts/fuzz.sh [seconds-per-target] [build-dir]   (defaults: 60, build-asan)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
build_dir="${2:-build-asan}"
export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitizer_suppressions.txt:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
if [ ! -x "$build_dir/tests/fuzz/fuzz_restore_snapshot" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only" -DCMAKE_C_FLAGS_RELEASE="-O1 -gline-tables-only" \
    -DIMPULSE2D_SANITIZE=ON -DIMPULSE2D_FUZZ=ON >/dev/null
  cmake --build "$build_dir" -j "$(nproc)" --target fuzz_scene_loader fuzz_narrow_phase fuzz_restore_snapshot
fi
status=0
for target in fuzz_scene_loader fuzz_narrow_phase fuzz_restore_snapshot; do
  name="${target#fuzz_}"
  binary="$build_dir/tests/fuzz/$target"
  # Earlier crashes first: each must now pass.
  for regression in tests/fuzz/regressions/"$target"-*; do
    [ -e "$regression" ] || continue
    "$binary" "$regression" >/dev/null 2>&1 || { echo "fuzz: $regression crashes again"; status=1; }
  done
  scratch="$build_dir/fuzz_corpus/$name"
  mkdir -p "$scratch"
  log="$build_dir/fuzz_$name.log"
  if "$binary" "$scratch" "tests/fuzz/corpus/$name" -max_total_time="$seconds" -max_len=8192 \
      -seed="${FUZZ_SEED:-1}" -timeout=10 -rss_limit_mb=2048 -artifact_prefix="tests/fuzz/regressions/$target-" \
      -print_final_stats=1 >"$log" 2>&1; then
    executions=$(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}')
    echo "fuzz: $target: ${executions:-?} executions in ${seconds} s, no crash"
  else
    echo "fuzz: $target FAILED (log: $log; the input is in tests/fuzz/regressions/)"
    tail -30 "$log"
    status=1
  fi
done
exit $status
