#!/usr/bin/env bash
# Requirement (issue 28, "Performance"): a linear contact march takes its free-flight steps
# without forming their contact problem (integrator/elastodynamic_march.hpp: the free step is the
# step when the strategy's first laws give no force at its end), and that changes nothing. On the
# coarse half ball of datafiles/scene3d/ball_impact.dat ((h, grading) = (0.25, 0.3), 1338 dofs,
# 200 steps through the impact and the flight off the plane), each march by default and with
# SOLVER free_flight=no (the contact problem formed at every step):
#  - every array of case.hist the same to 1e-10 of its largest value (the same decision on the
#    same numbers: measured identical in one process; 2.4e-12 as 2 ranks, where two runs of one
#    deck differ by 1.4e-12), its integers (Newton counts, statuses) identical;
#  - the steps taken in free flight (case.hist's free_flight) exactly those where the march with
#    free_flight=no found the free step to be the step (0 Newton iterations), none with
#    free_flight=no, and some before the impact and after the take-off;
# for the compliance (a law with a force from the first penetration) and IPM + EMM (its gap g;
# mass=emm: the step matrix's mass the EMM one, free or not) in one process, and IPM (consistent
# mass) as 2 ranks under mpirun (MUMPS's condensation) when mpirun is there. (The helper's run
# also checked Signorini and two-step: identical.)
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
source "$(dirname "$0")/lib/half_ball.sh"
source "$root/drivers/lib/deck.sh"
require_stages mesh material contact assemble march dump
require_command gmsh "the half ball is meshed by gmsh"
export OPENBLAS_NUM_THREADS=1

half_ball_base "$root/datafiles/scene3d/ball_impact.dat" 0.25 0.3
plane="CONTACT ref=3 obstacle=plane point=0,0,-0.00525 normal=0,0,1"

# same NAME: the march NAME (default) against NAME-condensed (free_flight=no).
same() {
  checks=$((checks + 1))
  "$python" - "$bin" "$work/$1/case.hist" "$work/$1-condensed/case.hist" "$1" <<'PY' ||
import sys
from same_history import arrays, differences
bin_dir, free, condensed, name = sys.argv[1:5]
bad = [(a, r) for a, r, ok in differences(bin_dir, condensed, free, 1e-10)
       if not ok and a != "free_flight"]
worst = max((r for a, r, ok in differences(bin_dir, condensed, free, 1e-10)
             if r is not None and a != "free_flight"), default=0.0)
f = arrays(bin_dir, free)
c = arrays(bin_dir, condensed)
taken = [int(x) for x in f["free_flight"]["values"]]
expected = [0] + [int(n == 0) for n in c["newton_iterations"]["values"][1:]]
active = c["active_nodes"]["values"]
first = next(s for s, a in enumerate(active) if a > 0)
last = max(s for s, a in enumerate(active) if a > 0)
print(f"{name}: {sum(taken)} of {len(taken) - 1} steps in free flight "
      f"({sum(taken[:first])} before the impact, {sum(taken[last + 1:])} after the take-off), "
      f"the worst array {worst:.1e} of its largest value")
ok = not bad and taken == expected and sum(c["free_flight"]["values"]) == 0
ok = ok and sum(taken[:first]) > 0 and sum(taken[last + 1:]) > 0
if bad:
    print("arrays differing:", bad)
if taken != expected:
    print("free steps", [s for s, t in enumerate(taken) if t],
          "expected", [s for s, t in enumerate(expected) if t])
sys.exit(0 if ok else 1)
PY
    fail "$1: free flight against the condensed march"
}

for spec in "compliance|strategy=compliance r=1e12|consistent" "ipm-emm|strategy=ipm r=1e12 g=5e-4|emm"; do
  IFS='|' read -r name fields mass <<<"$spec"
  run "$name" "$plane $fields" "$mass"
  run "$name-condensed" "$plane $fields" "$mass" 's|^SOLVER .*|& free_flight=no|'
  same "$name"
done

# Under mpirun: IPM as 2 ranks (MUMPS; mass=emm marches in one process), by default and with
# free_flight=no.
if command -v mpirun >/dev/null; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1
  for name in mpi mpi-condensed; do
    flag=yes
    [ "$name" = mpi ] || flag=no
    mkdir -p "$work/$name"
    deck_variant "$base/ball.dat" "$work/$name/ball.dat" --set CONTACT.strategy=ipm \
      --set SOLVER.linear=mumps --set SOLVER.free_flight=$flag --set TIME.mass=consistent
    "$root/drivers/chain.sh" "$work/$name/ball.dat" -o "$work/$name" --np 2 >"$work/$name.log" 2>&1 ||
      { tail -20 "$work/$name.log"; die "$name: the chain with --np 2 failed"; }
  done
  same mpi
fi
finish "free-flight steps without their contact problem: the condensed march's history, the same steps free"
