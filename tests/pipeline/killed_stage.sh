#!/usr/bin/env bash
# Requirement: a stage killed half-way leaves no partial file behind and damages nothing, and the
# temporaries it leaves do not pile up. Every atomic write (DS, text, VTK) goes to a hidden
# temporary renamed over its target at the end. Each stage here is stopped at a point known to be
# mid-write (SIG_STOP_WRITING: the process stops itself with the temporary of that file half
# written, core/ds.hpp stop_point_for_tests), killed with SIGKILL there, and then:
#  - the temporary it was writing is there (the kill did land mid-write),
#  - every file of the case is byte for byte what it was, and still reads (sig-dump),
#  - the next stage to start (the next one killed, and sig-solve at the end) removes the
#    temporary of the killed one and says so; no temporary of any name is left.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
deck=$work/hertz.dat
sed -e 's/N=256/N=64/' datafiles/scene7a/hertz.dat > "$deck"
out=$work/out
drivers/chain.sh "$deck" -o "$out" > /dev/null 2>&1 || die "the chain failed"
sums() { (cd "$out" && sha256sum case.* contact.csv hertz.pvd hertz_0000.vtu summary.json); }
before=$(sums)

# kill_mid_write STAGE FILE: run the stage until it stops inside the write of FILE, kill it.
# The temporary left by the previous kill must be gone by then: the stage removed it.
previous=""
kill_mid_write() {
  local stage=$1 file=$2
  SIG_STOP_WRITING=$file "$bin/sig-$stage" "$deck" -o "$out" > /dev/null 2>&1 &
  local pid=$! state=""
  for _ in $(seq 600); do # up to 60 s on a loaded machine
    state=$(awk '{print $3}' "/proc/$pid/stat" 2>/dev/null || echo gone)
    [ "$state" = T ] || [ "$state" = gone ] && break
    sleep 0.1
  done
  [ "$state" = T ] || die "sig-$stage did not stop in the write of $file (state $state)"
  [ -z "$previous" ] || [ ! -e "$previous" ] || die "sig-$stage did not remove $previous"
  local temporary=$out/.$file.tmp.$pid
  [ -s "$temporary" ] || die "sig-$stage stopped, but $temporary is not there half written"
  kill -9 "$pid"
  wait "$pid" 2> /dev/null || true
  [ -e "$temporary" ] || die "the temporary of the killed sig-$stage vanished by itself"
  [ "$(sums)" = "$before" ] || die "sig-$stage killed mid-write of $file changed the case's files"
  echo "killed_stage: sig-$stage killed mid-write of $file: $(basename "$temporary") left, $(stat -c %s "$temporary") bytes; the case's files intact${previous:+; the previous temporary removed}"
  previous=$temporary
}
kill_mid_write assemble case.tae
kill_mid_write post contact.csv
kill_mid_write post hertz_0000.vtu
for ds in nopo mili cont tae b; do
  "$bin/sig-dump" "$out/case.$ds" > /dev/null || die "case.$ds does not read after the kills"
done

# The next stage removes the last temporary, whichever stage wrote it.
message=$("$bin/sig-solve" "$deck" -o "$out" 2>&1) || die "sig-solve failed after the kills: $message"
grep -qF "removed $previous, left by a stage that was killed" <<< "$message" ||
  die "sig-solve did not remove $previous: $message"
left=$(find "$out" -name '.*.tmp.*')
[ -z "$left" ] || die "temporaries left: $left"
echo "killed_stage: 3 kills mid-write, the case intact, each temporary removed by the next stage"
