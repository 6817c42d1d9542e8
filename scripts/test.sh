#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite with ctest; then (in CI, or
# with FULL=1) the same suite built by Clang under AddressSanitizer + UndefinedBehavior-
# Sanitizer (which also checks that Clang reproduces GCC's pinned state hashes), and a
# 60-second fuzz smoke of each libFuzzer target.
# Usage: scripts/test.sh [build-dir]     (default build dir: build)
#        FULL=1 scripts/test.sh          (also the sanitizer suite and the fuzz smoke locally)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${1:-build}"
scripts/setup.sh "$build_dir"
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)"

# CI means CI for any value but empty, false, 0, no or off (as the golden harness reads it).
ci_value=$(printf '%s' "${CI:-}" | tr '[:upper:]' '[:lower:]')
case "$ci_value" in
  ""|false|0|no|off) in_ci=0 ;;
  *) in_ci=1 ;;
esac
if [ "$in_ci" = "1" ] || [ "${FULL:-}" = "1" ]; then
  export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitizer_suppressions.txt:print_suppressions=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  sanitized="${build_dir}-asan"
  echo "test: Clang + AddressSanitizer + UndefinedBehaviorSanitizer build in $sanitized"
  CC=clang CXX=clang++ cmake -S . -B "$sanitized" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only" -DCMAKE_C_FLAGS_RELEASE="-O1 -gline-tables-only" \
    -DIMPULSE2D_SANITIZE=ON -DIMPULSE2D_FUZZ=ON >/dev/null
  cmake --build "$sanitized" -j "$(nproc)"
  ctest --test-dir "$sanitized" --output-on-failure -j "$(nproc)"
  scripts/fuzz.sh "${FUZZ_SECONDS:-60}" "$sanitized"
fi
