#!/usr/bin/env bash
# Pipeline test (issue 27, "Same answers"): sig-march under mpirun. Scene 6's rail
# (datafiles/scene6/rail.dat: backward Euler in velocity, compliance contact, slip-rate friction
# by the convexification loop in every step) on a coarse mesh (16 x 16 cells, 15 steps of
# k = 0.02), marched in one process and as 2 ranks (oversubscribed, one BLAS thread each; each
# rank holds the rows of its METIS part of the step matrix, MUMPS factorizes them together with
# the contact unknowns its Schur complement): every array of case.hist within 1e-8 of its largest
# value, the statuses and the Newton and outer counts identical, case.hist records 2 ranks.
# Refused under mpirun, by card and field, and nothing written: a step matrix for CHOLMOD
# (SOLVER linear=), a march of one process (TIME scheme=midpoint). About 5 s.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
source "$root/drivers/lib/deck.sh"
require_command mpirun "drivers/setup.sh installs mpi-default-bin"
require_stages mesh material contact assemble march dump
# A waiting rank yields its core: ctest's other tests share the 2 cores (drivers/lib/environment.sh).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
export OMPI_MCA_mpi_yield_when_idle=1

# 1. One process.
deck=$work/rail.dat
deck_variant "$root/datafiles/scene6/rail.dat" "$deck" --set MESH.nx=16 --set MESH.ny=16 \
  --set TIME.T=0.3 --set TIME.k=0.02 --set TIME.output_every=5 --set SOLVER.linear=mumps \
  --set OUTPUT.vtk=no
one=$work/one
"$root/drivers/chain.sh" "$deck" -o "$one" > "$work/one.log" 2>&1 ||
  { cat "$work/one.log"; die "the rail's chain failed in one process"; }

# 2. Two ranks on the same DS files.
two=$work/two
mkdir -p "$two"
cp "$deck" "$one"/case.nopo* "$one"/case.mili* "$one"/case.cont* "$one"/case.tae* "$two"/
mpirun --oversubscribe -np 2 "$bin/sig-march" "$deck" -o "$two" > "$work/two.log" 2>&1 ||
  { cat "$work/two.log"; die "mpirun -np 2 sig-march failed"; }
checks=$((checks + 1))
grep -q "(mumps, ordering amd, 2 ranks" "$work/two.log" ||
  fail "the log line does not name MUMPS's ordering and 2 ranks: $(tail -3 "$work/two.log")"
checks=$((checks + 1))
"$python" "$root/tests/pipeline/lib/same_history.py" "$bin" "$one/case.hist" "$two/case.hist" \
  1e-8 > "$work/same.txt" || fail "2 ranks differ from one process: $(grep FAIL "$work/same.txt")"
worst=$(grep -v identical "$work/same.txt" | sort -g -k3 | tail -1 | sed "s/^ok *//")
echo "$test_name: 2 ranks against one process: $(grep -c identical "$work/same.txt") arrays" \
  "identical, the worst $worst"
checks=$((checks + 1))
"$bin/sig-dump" --json --values "$two/case.hist" | "$python" -c '
import json, sys
a = {x["name"]: x.get("values") for x in json.load(sys.stdin)["arrays"]}
sys.exit(0 if a["ranks"] == [2] and a["converged"] == [1] else 1)' ||
  fail "case.hist of 2 ranks does not record ranks = 2 and converged = 1"

# 3. Refused under mpirun, before any file is written.
refused_ranks() {
  local what=$1 variant=$2 text status=0
  shift 2
  checks=$((checks + 1))
  rm -f "$two/case.hist"
  mpirun --oversubscribe -np 2 "$bin/sig-march" "$variant" -o "$two" > "$work/refused.log" 2>&1 ||
    status=$?
  [ "$status" -ne 0 ] || fail "$what: mpirun -np 2 sig-march exited 0"
  for text in "$@"; do
    grep -qF -- "$text" "$work/refused.log" ||
      fail "$what: the message lacks '$text': $(cat "$work/refused.log")"
  done
  [ ! -e "$two/case.hist" ] || fail "$what: a refused march wrote case.hist"
}
cholmod=$two/cholmod.dat
deck_variant "$deck" "$cholmod" --set SOLVER.linear=cholmod
refused_ranks "linear=cholmod" "$cholmod" "field 'linear'" "set SOLVER linear=mumps"
midpoint=$two/midpoint.dat
deck_variant "$deck" "$midpoint" --set TIME.scheme=midpoint --drop-card FRICTION \
  --drop-card CONVEXIFICATION
refused_ranks "scheme=midpoint" "$midpoint" "field 'scheme'" "marches in one process"
finish "the rail's march as 2 ranks gives one process's answers; two decks refused under mpirun"
