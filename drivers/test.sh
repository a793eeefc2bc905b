#!/usr/bin/env bash
# drivers/test.sh: the set-up of run.sh, then the test suite (ctest: the pipeline, report and
# layering tests in build/; a build/ of setup.sh has no unit tests), then the unit tests under
# AddressSanitizer + UBSan in build-asan/, then the readers' fuzz targets for 30 s each from a
# fixed seed, one per core. With clang and libFuzzer (setup.sh installs them) build-asan/ is one
# clang build holding both the sanitizer unit tests and the fuzz targets (-DSIG_FUZZ=ON): the
# libraries are compiled once for both, and clang compiles the sanitizers faster than gcc. Without
# them it is a gcc build and fuzzing is skipped.
set -euo pipefail
source "$(dirname "$0")/lib/environment.sh"
help_from_header "$@"
source "$(dirname "$0")/setup.sh"
cd "$SIG_ROOT"
jobs=$(nproc 2>/dev/null || echo 2)
ctest --test-dir "$SIG_BUILD" -j "$jobs" --output-on-failure

asan=$SIG_ROOT/build-asan
fuzz=0
if command -v clang++ > /dev/null &&
  ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a > /dev/null 2>&1; then
  fuzz=1
fi
if [ ! -f "$asan/CMakeCache.txt" ]; then
  # -O1 -g1: the optimisation level the sanitizers recommend, with line-level stacks.
  compiler=()
  [ $fuzz -eq 0 ] || compiler=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DSIG_FUZZ=ON)
  cmake -S "$SIG_ROOT" -B "$asan" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -g1" \
    -DSIG_SANITIZE=ON -DSIG_UNIT_TESTS_ONLY=ON "${compiler[@]}"
fi
cmake --build "$asan" -j "$jobs"
# Leak detection stays on; OpenMPI's own leaks (MPI_Init of a MUMPS solver) are suppressed by
# the libraries they come from (tests/lsan-openmpi.supp).
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS=suppressions=$SIG_ROOT/tests/lsan-openmpi.supp \
  ctest --test-dir "$asan" -j "$jobs" -L unit --output-on-failure

# Fuzzing (tests/fuzz/README.md), in the same build: ASan + UBSan everywhere, libFuzzer's
# coverage on the readers' libraries.
if [ $fuzz -eq 0 ]; then
  echo "test.sh: clang or libFuzzer (libclang-rt-14-dev) absent: fuzzing skipped"
elif ! grep -q '^SIG_FUZZ:BOOL=ON' "$asan/CMakeCache.txt"; then
  echo "test.sh: $asan was configured without the fuzz targets (an older gcc build):" \
    "remove it for one clang build of both; fuzzing skipped"
else
  tests/fuzz/run.sh --build "$asan" --time "${SIG_FUZZ_SECONDS:-30}" --at-once "$jobs"
fi
