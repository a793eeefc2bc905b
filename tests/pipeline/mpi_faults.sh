#!/usr/bin/env bash
# Pipeline test (issue 27, "Faults"): sig-solve and sig-assemble under mpirun fail whole and
# leave nothing half done.
#  - a mesh with fewer cells than ranks (the square of two triangles as 3 ranks) is refused by
#    every rank with a message that names the largest usable count; non-zero exit, no case.b;
#  - rank 0 killed (SIGKILL) while it writes case.b (SIG_STOP_WRITING stops it there, as in
#    killed_stage.sh), the other rank having done its part: mpirun ends non-zero, no case.b, no
#    rank left running;
#  - sig-assemble as 3 ranks of the two triangles refused the same way, nothing written; rank 1
#    of a distributed assembly killed while it writes its part case.tae.r1: mpirun ends
#    non-zero, no part renamed into place (rank 0's waits for it), case.tae unchanged.
# Run from the repository root with SIG_BIN set (ctest does both).
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
command -v mpirun > /dev/null || die "no mpirun: drivers/setup.sh installs mpi-default-bin"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1

# 1. Fewer cells than ranks.
deck=$work/tiny.dat
cat > "$deck" <<'EOF'
TITLE two triangles on a compliant foundation
MESH generator=square lx=1 nx=1
MATERIAL law=hooke E=200 nu=0.3 plane=strain
DIRICHLET ref=1 ux=0 uy=0
TRACTION ref=2 f=0,-8
CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=compliance-unilateral cn=10 g=0.05
SOLVER method=pdas gamma=200 eps=1e-8 maxit=200 linear=mumps
OUTPUT vtk=no
EOF
tiny=$work/tiny
drivers/chain.sh "$deck" -o "$tiny" > "$work/tiny_chain.log" 2>&1 ||
  { cat "$work/tiny_chain.log"; die "the two-triangle chain failed in one process"; }
# refused_on_tiny STAGE: sig-STAGE as 3 ranks on the two triangles ends non-zero with the
# message naming the ranks the mesh allows.
refused_on_tiny() {
  status=0
  mpirun --oversubscribe -np 3 "$bin/sig-$1" "$deck" -o "$tiny" > "$work/tiny.log" 2>&1 ||
    status=$?
  [ $status -ne 0 ] || fail "sig-$1 as 3 ranks on 2 triangles exited 0"
  grep -q "cannot be shared by 3 ranks: run mpirun with at most 2 ranks" "$work/tiny.log" ||
    { cat "$work/tiny.log"; fail "sig-$1: no message naming the ranks a 2-triangle mesh allows"; }
  echo "mpi_faults: sig-$1 as 3 ranks on 2 triangles refused (exit $status)"
}
rm -f "$tiny/case.b"
refused_on_tiny solve
[ ! -e "$tiny/case.b" ] || fail "a refused distributed solve wrote case.b"
# sig-assemble too, before it writes a part or the index.
before=$(cksum < "$tiny/case.tae")
refused_on_tiny assemble
[ "$(cksum < "$tiny/case.tae")" = "$before" ] && [ -z "$(ls "$tiny" | grep 'case.tae.r')" ] ||
  fail "a refused distributed assembly changed case.tae or wrote a part: $(ls "$tiny")"

# kill_in_write STAGE FILE: runs sig-STAGE as 2 ranks of mpirun on the Hertz case, the rank that
# writes FILE stopped in its write (SIG_STOP_WRITING) and killed (SIGKILL): mpirun must end
# non-zero and take the other rank with it. Sets $host (the killed rank's pid) and $status.
kill_in_write() {
  local stage=$1 file=$2 job ranks pid
  SIG_STOP_WRITING=$file mpirun --oversubscribe -np 2 "$bin/sig-$stage" "$hertz" -o "$out" \
    > "$work/killed.log" 2>&1 &
  job=$!
  host=""
  for _ in $(seq 600); do # up to 60 s on a loaded machine
    for pid in $(pgrep -P "$job" -x "sig-$stage" || true); do
      [ "$(awk '{print $3}' "/proc/$pid/stat" 2> /dev/null)" = T ] && host=$pid
    done
    [ -n "$host" ] || ! kill -0 "$job" 2> /dev/null && break
    sleep 0.1
  done
  [ -n "$host" ] || { cat "$work/killed.log"; die "no rank stopped in the write of $file"; }
  ranks=$(pgrep -P "$job" -x "sig-$stage" | tr '\n' ' ')
  kill -9 "$host"
  status=0
  wait "$job" || status=$?
  [ $status -ne 0 ] || fail "mpirun exited 0 with the rank writing $file killed"
  # mpirun's teardown signals the other rank as it exits: give the process a moment to go.
  for pid in $ranks; do
    for _ in $(seq 50); do
      kill -0 "$pid" 2> /dev/null && [ "$(awk '{print $3}' "/proc/$pid/stat" 2> /dev/null)" != Z ] ||
        break
      sleep 0.1
    done
    ! kill -0 "$pid" 2> /dev/null || [ "$(awk '{print $3}' "/proc/$pid/stat" 2> /dev/null)" = Z ] ||
      fail "rank process $pid still running 5 s after the job ended"
  done
}

# 2. Rank 0 killed in the write of case.b.
hertz=$work/hertz.dat
sed -e 's/N=256/N=32/' datafiles/scene7a/hertz.dat > "$hertz"
out=$work/hertz
drivers/chain.sh "$hertz" -o "$out" > "$work/hertz_chain.log" 2>&1 ||
  { cat "$work/hertz_chain.log"; die "the Hertz chain failed in one process"; }
rm -f "$out/case.b"
kill_in_write solve case.b
[ ! -e "$out/case.b" ] || fail "case.b written though rank 0 was killed in its write"
echo "mpi_faults: rank 0 (pid $host) killed in the write of case.b: mpirun exit $status," \
  "no case.b, ranks gone"

# 3. Rank 1 killed in the write of its part of a distributed assembly (rank 0's part whole,
# waiting for it): no part renamed into place, the case's TAE as it was.
before=$(cksum < "$out/case.tae")
kill_in_write assemble case.tae.r1
[ "$(cksum < "$out/case.tae")" = "$before" ] || fail "case.tae changed by a killed assembly"
[ -z "$(ls "$out" | grep 'case.tae.r')" ] ||
  fail "a killed assembly left parts in place: $(ls "$out" | grep 'case.tae.r' | tr '\n' ' ')"
echo "mpi_faults: rank 1 (pid $host) killed in the write of case.tae.r1: mpirun exit $status," \
  "no part in place, case.tae unchanged"
[ $failures -eq 0 ] || exit 1
