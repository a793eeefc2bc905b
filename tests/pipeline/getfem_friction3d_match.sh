#!/usr/bin/env bash
# Requirement (issue 26, "Against GetFEM 3D", with friction): on the same tetrahedral mesh of the
# half ball (R = 8, E = 150, nu = 0.3, 3672 dofs), with the same holds and the same Coulomb law
# (mu = 0.3), our 3D frictional contact solve (pdas and alm) and GetFEM 5.4's nodal
# contact brick with friction give the same discrete solution: every contact node's normal and
# tangential nodal forces to 1e-6 of the largest normal force, the same statuses (free, stick,
# slip; nodes within 1e-8 of the stick/slip threshold exempt), both stopped at 1e-10 (ours:
# relative increment and residual; GetFEM: max_res relative to its source terms).
# The holds: the flat top clamped and moved by (0.02, 0, -0.07) (our DIRICHLET ref=2 ux=0.02 uy=0
# uz=-0.07; postproc/getfem_hertz3d.py --clamp-top --top-shift 0.02 --top-drop 0.07): the top
# dragged sideways and down, so that the contact (78 nodes) sticks at its centre (27) and slips at
# its rim (51); a shift alone would roll the ball about its contact. The pressure p on the top
# (on held dofs: it goes into the reactions) is on both sides. Ours starts from rest, GetFEM
# from its rigid shift u_z = -a^2 / (4 R) (the discrete solution does not depend on it).
# Conventions (datafiles/scene3d/GETFEM.md): GetFEM's multipliers are nodal forces, ours too
# (contact.csv's multiplier and tangential_force_1..3); GetFEM's lambda_t is the force of the
# plane on the body, ours the force of the body on the plane (along the slip): compared with
# opposite signs. GetFEM's status (its solution has none): slip where the slip |u_t| / its largest
# exceeds the cone's margin (mu N - |T|) / max N, stick otherwise; the threshold is where both
# vanish, so a node with their sum below 1e-8 is exempt.
# Tresca (threshold 1 per unit area: 387 nodes stick, 102 slip, free nodes included, Tresca's bound
# holding every node): GetFEM's Python bricks take no threshold, so postproc/getfem_hertz3d.py
# --threshold builds it from the basic brick on an explicit model (its docstring); the same
# checks, every node's status judged by its bound S w (w its tributary area), not by mu N.
# Skips without GetFEM (python3-getfem) or gmsh.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_command gmsh "the half ball is meshed by gmsh"
/usr/bin/python3 -c 'import getfem' 2>/dev/null || skip "/usr/bin/python3 cannot import getfem"
require_stages mesh material contact assemble solve post

mesh=$work/half_ball.msh
gmsh "$root/meshes/half_ball.geo" -3 -format msh22 -setnumber R 8 -setnumber h 0.08 \
  -setnumber grading 0.2 -o "$mesh" >"$work/gmsh.log" 2>&1 || die "gmsh failed: $(tail -3 "$work/gmsh.log")"
p=0.0696302876
mu=0.3

threshold=1

for law in coulomb tresca; do
  if [ $law = coulomb ]; then
    friction="law=coulomb mu=$mu" option=(--mu $mu) bound=$mu
  else
    friction="law=tresca threshold=$threshold" option=(--threshold $threshold) bound=$threshold
  fi
  /usr/bin/python3 "$root/postproc/getfem_hertz3d.py" --msh "$mesh" --clamp-top --top-shift 0.02 \
    --top-drop 0.07 --pressure $p "${option[@]}" --eps 1e-10 --repeat 1 --json "$work/getfem_$law.json" \
    >"$work/getfem_$law.log" 2>&1 || die "postproc/getfem_hertz3d.py ($law) failed: $(tail -3 "$work/getfem_$law.log")"

  for method in pdas alm; do
    cat >"$work/${method}_$law.dat" <<DECK
# The half ball of postproc/getfem_hertz3d.py (R = 8, E = 150, nu = 0.3, GPa-m), its top clamped
# and moved by (0.02, 0, -0.07), on the plane x3 = 0 with friction $friction.
TITLE half ball against GetFEM, $law
MESH file=$mesh
MATERIAL law=hooke E=150 nu=0.3
DIRICHLET ref=2 ux=0.02 uy=0 uz=-0.07
TRACTION ref=2 f=0,0,-$p
CONTACT ref=3 obstacle=plane point=0,0,0 normal=0,0,1 law=signorini exclude=2
FRICTION ref=3 $friction
SOLVER method=$method eps=1e-10
OUTPUT vtk=no
DECK
    "$root/drivers/chain.sh" "$work/${method}_$law.dat" -o "$work/${method}_$law" >"$work/${method}_$law.log" 2>&1 ||
      { tail -20 "$work/${method}_$law.log"; die "drivers/chain.sh ($method, $law) failed"; }

    checks=$((checks + 1))
    "$python" - "$work/${method}_$law/contact.csv" "$work/getfem_$law.json" $bound "$method" $law <<'PY' || fail "ours ($method, $law) against GetFEM"
import csv, math, sys
from pipeline_checks import getfem_nodes_against
bound, method, law = float(sys.argv[3]), sys.argv[4], sys.argv[5]
tresca = law == "tresca"  # bound: Coulomb's mu, or Tresca's threshold per unit area
pairs, problems, theirs, largest = getfem_nodes_against(csv.DictReader(open(sys.argv[1])),
                                                        sys.argv[2])
in_contact = [n for n in theirs.values() if n["normal_force"] > 1e-9 * largest]
held = list(theirs.values()) if tresca else in_contact  # the nodes friction holds
slip_scale = max(math.hypot(*n["u"][:2]) for n in held)
worst_n, worst_t, differ, exempt, counts = 0.0, 0.0, 0, 0, {}
matched = len(pairs)
for r, n in pairs:
    N, T = n["normal_force"], n["tangential_force"]
    worst_n = max(worst_n, abs(float(r["multiplier"]) - N))
    worst_t = max(worst_t, math.dist([float(r[f"tangential_force_{k}"]) for k in (1, 2, 3)], [-t for t in T]))
    contact = N > 1e-9 * largest
    margin = ((bound * n["area"] if tresca else bound * N) - math.hypot(*T)) / largest
    slip = math.hypot(*n["u"][:2]) / slip_scale
    status = "-" if not (contact or tresca) else ("S+" if slip > margin else "S=")
    near = (not tresca and abs(N - 1e-9 * largest) < 1e-8 * largest) or \
        ((contact or tresca) and margin + slip < 1e-8)
    counts[status] = counts.get(status, 0) + 1
    mine = r["friction_status"] if (r["status"] == "contact" or tresca) else "-"
    if mine != status:
        if near:
            exempt += 1
        else:
            differ += 1
            problems.append(f"node {r['node']}: ours {mine}, GetFEM {status} (margin {margin:.3g}, slip {slip:.3g})")
rim = sum(1 for k in theirs if abs(k[2] - 8) < 1e-9)  # on the top: exclude=2
if matched < len(theirs) - rim:
    problems.append(f"{matched} of GetFEM's {len(theirs) - rim} nodes matched")
if exempt > 2:
    problems.append(f"{exempt} nodes exempt as near the stick/slip threshold (at most 2 expected)")
if counts.get("S=", 0) == 0 or counts.get("S+", 0) == 0:
    problems.append(f"the case needs both stick and slip: {counts}")
for name, worst in (("normal", worst_n), ("tangential", worst_t)):
    if worst > 1e-6 * largest:
        problems.append(f"{name} nodal forces differ by {worst:.3g} ({worst / largest:.2g} of the largest)")
for p in problems:
    print(p)
print(f"{method} against GetFEM ({law} {bound:g}): {matched} nodes (free {counts.get('-', 0)}, stick "
      f"{counts.get('S=', 0)}, slip {counts.get('S+', 0)}), normal forces within {worst_n / largest:.2g}, "
      f"tangential within {worst_t / largest:.2g} of the largest ({largest:.4g}), {differ} statuses "
      f"differ, {exempt} exempt")
sys.exit(1 if problems else 0)
PY
  done
done
finish "the frictional 3D solve (Coulomb and Tresca) is GetFEM's on the same mesh"
