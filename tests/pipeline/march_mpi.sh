#!/usr/bin/env bash
# Pipeline test (issue 27, "Same answers"): sig-march under mpirun. Scene 6's rail
# (datafiles/scene6/rail.dat: backward Euler in velocity, compliance contact, slip-rate friction
# by the convexification loop in every step) on a coarse mesh (16 x 16 cells, 15 steps of
# k = 0.02), marched in one process and as 2 ranks (oversubscribed, one BLAS thread each; each
# rank holds the rows of its METIS part of the step matrix, MUMPS factorizes them together with
# the contact unknowns its Schur complement): every array of case.hist within 1e-8 of its largest
# value, the statuses and the Newton and outer counts identical, case.hist records 2 ranks.
# The same march on a distributed assembly (mpirun -np 2 sig-assemble: a part per rank) within
# 1e-10 of that on the whole TAE; a part of another run and a job of another size than the
# parts' refused, naming the file. Refused under mpirun, by card and field, and nothing written:
# a step matrix for CHOLMOD (SOLVER linear=), a midpoint march with the EMM (TIME mass=).
# About 8 s.
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

# 2b. Distributed assembly (mpirun -np 2 sig-assemble): each rank writes the rows of its part to
# case.tae.r<rank>, rank 0 the index case.tae; the march reads the parts and gives the answers
# of the march on the whole TAE to 1e-10. Its rows are the whole assembly's bit for bit (the unit
# test TaeParts.EachRankReadsOfItsPartWhatTheWholeTaeGives), and on a quiet machine the two
# marches agree in every bit; under ctest's load MUMPS over 2 ranks is not repeatable run to run
# (on these bit-identical inputs the two marches once differed by 9.9e-12 of the largest kinetic
# energy).
dist=$work/dist
mkdir -p "$dist"
cp "$one"/case.nopo* "$one"/case.mili* "$one"/case.cont* "$dist"/
for out in "$dist" "$work/other"; do
  mkdir -p "$out"
  cp -n "$one"/case.nopo* "$one"/case.mili* "$one"/case.cont* "$out"/
  mpirun --oversubscribe -np 2 "$bin/sig-assemble" "$deck" -o "$out" > "$work/assemble.log" 2>&1 ||
    { cat "$work/assemble.log"; die "mpirun -np 2 sig-assemble failed"; }
done
checks=$((checks + 1))
[ -s "$dist/case.tae.r0" ] && [ -s "$dist/case.tae.r1" ] && grep -q "parts 2" "$work/assemble.log" ||
  fail "mpirun -np 2 sig-assemble wrote no parts case.tae.r0, r1: $(ls "$dist")"
mpirun --oversubscribe -np 2 "$bin/sig-march" "$deck" -o "$dist" > "$work/dist.log" 2>&1 ||
  { cat "$work/dist.log"; die "mpirun -np 2 sig-march on the parts failed"; }
checks=$((checks + 1))
"$python" "$root/tests/pipeline/lib/same_history.py" "$bin" "$two/case.hist" "$dist/case.hist" \
  1e-10 > "$work/same_dist.txt" ||
  fail "the parts' march differs from the whole TAE's: $(grep FAIL "$work/same_dist.txt")"
echo "$test_name: the parts of 2 ranks against the whole TAE as 2 ranks:" \
  "$(grep -c identical "$work/same_dist.txt") arrays identical," \
  "the worst $(grep -v identical "$work/same_dist.txt" | sort -g -k3 | tail -1 | sed "s/^ok *//")"
# sig-post says in the march's summary.json how it ran.
checks=$((checks + 1))
"$bin/sig-post" "$deck" -o "$dist" > "$work/post.log" 2>&1 || { cat "$work/post.log"; die "sig-post failed"; }
"$python" -c '
import json, sys
s = json.load(open(sys.argv[1]))
sys.exit(0 if s["ranks"] == 2 and s["ordering"] == "amd" and s["scheme"] == "backward-euler" else 1)' \
  "$dist/summary.json" || fail "the march's summary.json lacks ranks 2: $(cat "$dist/summary.json")"
# A part of another run (the same deck assembled again), a job of another size: refused, the
# file named, no case.hist.
refused_parts() {
  local what=$1 np=$2 text=$3 status=0
  checks=$((checks + 1))
  rm -f "$dist/case.hist"
  mpirun --oversubscribe -np "$np" "$bin/sig-march" "$deck" -o "$dist" > "$work/refused.log" 2>&1 ||
    status=$?
  [ "$status" -ne 0 ] || fail "$what: mpirun -np $np sig-march exited 0"
  grep -qF -- "$text" "$work/refused.log" ||
    fail "$what: the message lacks '$text': $(cat "$work/refused.log")"
  [ ! -e "$dist/case.hist" ] || fail "$what: a refused march wrote case.hist"
}
cp "$work/other/case.tae.r1" "$dist/case.tae.r1"
refused_parts "a part of another run" 2 "$dist/case.tae.r1: the part of rank 1 of 2 of the assembly"
refused_parts "3 ranks on 2 parts" 3 "$dist/case.tae: the index of an assembly on 2 ranks, and this job has 3"

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
# The midpoint march takes mpirun (tests/pipeline/march_mpi3d.sh), but not the Equivalent Mass
# Matrix (built from the whole mass) nor a hyperelastic body (its Newton matrix assembled from the
# whole state).
midpoint=$two/midpoint.dat
deck_variant "$deck" "$midpoint" --set TIME.scheme=midpoint --set TIME.mass=emm \
  --drop-card FRICTION --drop-card CONVEXIFICATION
refused_ranks "mass=emm" "$midpoint" "field 'mass'" "mass=emm marches in one process"
finish "the rail's march as 2 ranks gives one process's answers, on the whole TAE and on its parts; a foreign part, another job size and two decks refused under mpirun"
