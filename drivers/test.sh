#!/usr/bin/env bash
# drivers/test.sh: the set-up of run.sh, then the whole test suite (ctest), then the unit tests
# again under AddressSanitizer + UBSan in build-asan/.
set -euo pipefail
source "$(dirname "$0")/setup.sh"
cd "$SIG_ROOT"
jobs=$(nproc 2>/dev/null || echo 2)
ctest --test-dir "$SIG_BUILD" -j "$jobs" --output-on-failure

asan=$SIG_ROOT/build-asan
if [ ! -f "$asan/CMakeCache.txt" ]; then
  # -O1 -g1: the optimisation level the sanitizers recommend, with line-level stacks.
  cmake -S "$SIG_ROOT" -B "$asan" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -g1" -DSIG_SANITIZE=ON \
    -DSIG_UNIT_TESTS_ONLY=ON
fi
cmake --build "$asan" -j "$jobs"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir "$asan" -j "$jobs" -L unit --output-on-failure
