#!/usr/bin/env bash
# Requirement: a stage killed half-way leaves no partial DS behind. DS files are written to a
# temporary file and renamed, so whenever the kill lands, case.tae is either the complete file of
# the previous run or the complete new one (they differ only in the recorded assembly time): it
# always has the full size and reads back with valid CRCs.
set -euo pipefail
bin=${SIG_BIN:?SIG_BIN is not set}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
deck=$work/big.dat
sed -e 's/N=256/N=256/' -e 's/grading=0.1/grading=0/' datafiles/scene7a/hertz.dat > "$deck"
for stage in mesh material contact assemble; do "$bin/sig-$stage" "$deck" -o "$work/out" > /dev/null; done
reference=$(stat -c %s "$work/out/case.tae")

# Run sig-assemble again and kill it with SIGKILL at several moments of its run.
for delay in 0.02 0.05 0.1 0.15 0.2 0.3 0.4 0.6; do
  "$bin/sig-assemble" "$deck" -o "$work/out" > /dev/null 2>&1 &
  pid=$!
  sleep "$delay"
  kill -9 "$pid" 2> /dev/null || true
  wait "$pid" 2> /dev/null || true
  now=$(stat -c %s "$work/out/case.tae")
  if [ "$now" != "$reference" ]; then
    echo "FAIL: case.tae has $now bytes instead of $reference after a kill at ${delay}s" >&2
    exit 1
  fi
  "$bin/sig-dump" "$work/out/case.tae" > /dev/null || { echo "FAIL: case.tae unreadable after a kill at ${delay}s" >&2; exit 1; }
done
# Leftover temporaries never carry the DS name.
ls -a "$work/out" | grep -q '^case\.tae$'
echo "killed_stage: case.tae intact after 8 kills"
