#!/usr/bin/env bash
# drivers/test.sh: the set-up of run.sh, then the test suite (ctest: the pipeline, report and
# layering tests in build/; a build/ of setup.sh has no unit tests), then the unit tests under
# AddressSanitizer + UBSan in build-asan/, then the readers' fuzz targets for 30 s each from a
# fixed seed in build-fuzz/, one per core (clang and libFuzzer; skipped when clang is absent).
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
# Leak detection stays on; OpenMPI's own leaks (MPI_Init of a MUMPS solver) are suppressed by
# the libraries they come from (tests/lsan-openmpi.supp).
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS=suppressions=$SIG_ROOT/tests/lsan-openmpi.supp \
  ctest --test-dir "$asan" -j "$jobs" -L unit --output-on-failure

# Fuzzing (tests/fuzz/README.md): libFuzzer needs clang, with every library instrumented, so a
# build of its own; only the reader libraries and the five targets are built.
fuzz=$SIG_ROOT/build-fuzz
if command -v clang++ > /dev/null &&
  ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a > /dev/null 2>&1; then
  if [ ! -f "$fuzz/CMakeCache.txt" ]; then
    CC=clang CXX=clang++ cmake -S "$SIG_ROOT" -B "$fuzz" -DCMAKE_BUILD_TYPE=None \
      -DCMAKE_CXX_FLAGS="-O1" -DSIG_FUZZ=ON -DSIG_UNIT_TESTS_ONLY=ON
  fi
  cmake --build "$fuzz" -j "$jobs" --target fuzz_datafile fuzz_gmsh fuzz_freefem fuzz_nopo fuzz_ds
  tests/fuzz/run.sh --build "$fuzz" --time "${SIG_FUZZ_SECONDS:-30}" --at-once "$jobs"
else
  echo "test.sh: clang or libFuzzer (libclang-rt-14-dev) absent: fuzzing skipped"
fi
