#!/usr/bin/env bash
# The main job's build holds no test: scripts/run.sh asks scripts/setup.sh for the program only
# (--program, target impulse2d), setup.sh configures that build with the tests off, and in such
# any configuration the impulse2d target depends on no test and no GoogleTest (CMake's target
# graph says).
# Usage: tests/check_run_builds_no_test.sh <source dir> <scratch dir>
set -uo pipefail
source_dir="$1"
scratch="$2"
failures=0
fail() {
  echo "check_run_builds_no_test: $*" >&2
  failures=$((failures + 1))
}

grep -q '^scripts/setup.sh --program build impulse2d$' "$source_dir/scripts/run.sh" ||
  fail "scripts/run.sh does not call 'scripts/setup.sh --program build impulse2d'"
grep -q 'program_only" -eq 1 ]; then' "$source_dir/scripts/setup.sh" &&
  grep -q '^  tests=OFF$' "$source_dir/scripts/setup.sh" ||
  fail "scripts/setup.sh --program no longer configures with the tests off"

rm -rf "$scratch"
mkdir -p "$scratch"
# The target graph of a full configuration (tests on): what the impulse2d target depends on.
if ! cmake -S "$source_dir" -B "$scratch/build" -DCMAKE_BUILD_TYPE=Release \
     -DIMPULSE2D_BUILD_TESTS=ON --graphviz="$scratch/graph/targets.dot" >"$scratch/log" 2>&1; then
  fail "configuring failed: $(tail -5 "$scratch/log")"
elif [ ! -f "$scratch/graph/targets.dot.impulse2d" ]; then
  fail "no dependency graph of the impulse2d target"
else
  needed=$(sed -n 's/.*label = "\([^"\\]*\).*/\1/p' "$scratch/graph/targets.dot.impulse2d" | sort -u)
  echo "$needed" | grep -qx impulse2d_core || fail "the graph does not show impulse2d_core: $needed"
  tests=$(echo "$needed" | grep -E '^test_|gtest|GTest' || true)
  [ -n "$tests" ] && fail "the impulse2d target depends on tests: $tests"
fi
rm -rf "$scratch"

if [ "$failures" -gt 0 ]; then exit 1; fi
echo "check_run_builds_no_test: the main job builds the program and no test"
