#!/usr/bin/env bash
# tests/fuzz/run.sh [--build DIR] [--time SECONDS] [--jobs N] [--at-once K] [TARGET...]: run the
# readers' libFuzzer targets (tests/fuzz/README.md; DIR default build-asan, drivers/test.sh's
# clang build with -DSIG_FUZZ=ON) from their committed seed corpus, each for
# SECONDS (default 30) with a fixed seed, under ASan + UBSan, with at most 1 GB per allocation and
# 2 GB in all; K targets side by side (default 1), each with N fuzzing processes. Every input a target found new is kept in a scratch corpus (out/fuzz/<target>/corpus),
# never in tests/; an input that fails is saved as out/fuzz/<target>/crash-*, replayed to show
# the error, and the script exits 1: add it to tests/fuzz/corpus/<target>/ once fixed.
# Prints the executions per target. drivers/test.sh runs one target per core; a developer's
# longer run is e.g. `tests/fuzz/run.sh --time 3600 --jobs 2`.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$root/build-asan
seconds=30
jobs=1
at_once=1
targets=()
while [ $# -gt 0 ]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --time) seconds=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --at-once) at_once=$2; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(datafile gmsh freefem nopo ds)
build=$(cd "$build" 2>/dev/null && pwd) || { echo "fuzz: no build folder $build" >&2; exit 2; }
out=$root/out/fuzz
for target in "${targets[@]}"; do
  binary=$build/tests/fuzz/fuzz_$target
  [ -x "$binary" ] || { echo "fuzz: no $binary (configure with clang and -DSIG_FUZZ=ON)" >&2; exit 2; }
done

# One target's run; prints its line and returns 1 when it found a failing input.
fuzz_target() {
  local target=$1 binary=$build/tests/fuzz/fuzz_$1
  local dir=$out/$target
  mkdir -p "$dir/corpus"
  cp -n "$root/tests/fuzz/corpus/$target/"* "$dir/corpus/" 2>/dev/null || true
  log=$dir/fuzz.log
  status=0
  # -close_fd_mask=2: the readers' warnings (a reoriented triangle ...) would flood the log;
  # a failing input is replayed below with its message.
  parallel=()
  [ "$jobs" -le 1 ] || parallel=(-jobs="$jobs" -workers="$jobs")
  (cd "$dir" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$binary" -seed=1 -max_total_time="$seconds" "${parallel[@]}" \
    -rss_limit_mb=2048 -malloc_limit_mb=1024 -timeout=10 -max_len=65536 -close_fd_mask=2 \
    -artifact_prefix="$dir/" "$dir/corpus" > "$log" 2>&1) || status=$?
  runs=$({ grep -ho 'Done [0-9]* runs' "$log" "$dir"/fuzz-*.log 2>/dev/null || true; } |
    awk '{s += $2} END {print s + 0}')
  crashes=$(ls "$dir"/crash-* "$dir"/oom-* "$dir"/timeout-* "$dir"/leak-* 2>/dev/null || true)
  if [ "$status" -ne 0 ] || [ -n "$crashes" ]; then
    echo "fuzz $target: FAILED after $runs executions in ${seconds} s; inputs: ${crashes:-none (see $log)}"
    for input in $crashes; do
      "$build/tests/fuzz/fuzz_$target" "$input" 2>&1 | grep -E 'ERROR|error|SUMMARY|terminate|what' | head -5 || true
    done
    return 1
  fi
  echo "fuzz $target: $runs executions in ${seconds} s, no failure"
}

# K targets at a time, each one's lines printed whole when it ends.
failed=0
pending=("${targets[@]}")
while [ ${#pending[@]} -gt 0 ]; do
  batch=("${pending[@]:0:$at_once}")
  pending=("${pending[@]:$at_once}")
  pids=()
  for target in "${batch[@]}"; do
    mkdir -p "$out/$target"
    fuzz_target "$target" > "$out/$target/result.txt" 2>&1 &
    pids+=($!)
  done
  for i in "${!pids[@]}"; do
    wait "${pids[$i]}" || failed=1
    cat "$out/${batch[$i]}/result.txt"
  done
done
exit $failed
