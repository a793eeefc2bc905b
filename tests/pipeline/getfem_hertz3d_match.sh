#!/usr/bin/env bash
# Requirement (issue 26, "Against GetFEM 3D"): on the same tetrahedral mesh of the half ball,
# with the same load and the same holds, on the plane x3 = 0 and on a cylinder of axis x1 under
# it, our frictionless 3D contact solve and GetFEM 5.4's nodal contact brick give the same
# discrete solution: every contact node's normal nodal force to 1e-6 of the largest (5e-4 on the
# cylinder: GetFEM's normal is a finite difference, below), the same nodes in contact (but those within 1e-8 of the largest force of the
# threshold), both stopped at a residual of 1e-10. The holds: the flat top's nodes held in x and
# y (our DIRICHLET ref=2 ux=0 uy=0; GetFEM's --clamp-top), the tilts and the vertical translation
# held by the contact alone; the load: the pressure p on the top. Ours starts from rest, GetFEM
# from its rigid shift (the solution is unique). Skips without GetFEM (python3-getfem).
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_command gmsh "the half ball is meshed by gmsh"
/usr/bin/python3 -c 'import getfem' 2>/dev/null || skip "/usr/bin/python3 cannot import getfem"

geo=$root/meshes/half_ball.geo
mesh=$work/half_ball.msh
gmsh "$geo" -3 -format msh22 -setnumber R 8 -setnumber h 0.08 -setnumber grading 0.2 -o "$mesh" \
  >"$work/gmsh.log" 2>&1 || die "gmsh failed: $(tail -3 "$work/gmsh.log")"
p=0.0696302876

# match NAME TOLERANCE GETFEM_OPTION... -- CONTACT_OBSTACLE: our chain and GetFEM on the mesh with
# the obstacle given to each side, the nodal forces equal to TOLERANCE of the largest.
match() {
  local name=$1 tolerance=$2 getfem_options=() obstacle
  shift 2
  while [ "$1" != -- ]; do getfem_options+=("$1"); shift; done
  obstacle=$2
  /usr/bin/python3 "$root/postproc/getfem_hertz3d.py" --msh "$mesh" --clamp-top --pressure $p \
    --eps 1e-10 --repeat 1 "${getfem_options[@]}" --json "$work/getfem_$name.json" \
    >"$work/getfem_$name.log" 2>&1 ||
    die "postproc/getfem_hertz3d.py $name failed: $(tail -3 "$work/getfem_$name.log")"
  cat >"$work/ball_$name.dat" <<DECK
# The half ball of postproc/getfem_hertz3d.py (R = 8, E = 150, nu = 0.3, GPa-m), its top held in
# x and y and pressed by p, on the $name, frictionless.
TITLE half ball against GetFEM
MESH file=$mesh
MATERIAL law=hooke E=150 nu=0.3
DIRICHLET ref=2 ux=0 uy=0
TRACTION ref=2 f=0,0,-$p
CONTACT ref=3 $obstacle law=signorini exclude=2
SOLVER method=pdas eps=1e-10
OUTPUT vtk=no
DECK
  "$root/drivers/chain.sh" "$work/ball_$name.dat" -o "$work/ours_$name" >"$work/ours_$name.log" 2>&1 ||
    { tail -20 "$work/ours_$name.log"; die "drivers/chain.sh failed on the $name"; }

  checks=$((checks + 1))
  "$python" - "$work/ours_$name/contact.csv" "$work/getfem_$name.json" "$name" "$tolerance" <<'PY' || fail "ours against GetFEM on the $name"
import csv, sys
from pipeline_checks import getfem_nodes_against
pairs, problems, theirs, largest = getfem_nodes_against(csv.DictReader(open(sys.argv[1])),
                                                        sys.argv[2])
worst, statuses = 0.0, 0
matched = len(pairs)
for r, n in pairs:
    N = float(r["multiplier"])
    worst = max(worst, abs(N - n["normal_force"]))
    threshold = 1e-9 * largest
    near = abs(n["normal_force"] - threshold) < 1e-8 * largest
    if not near and (r["status"] == "contact") != (n["normal_force"] > threshold):
        statuses += 1
if matched < len(theirs) - sum(1 for k in theirs if abs(k[2] - 8) < 1e-9):
    problems.append(f"{matched} of GetFEM's {len(theirs)} nodes matched")
if worst > float(sys.argv[4]) * largest:
    problems.append(f"normal nodal forces differ by {worst:.3g} ({worst / largest:.2g} of the largest)")
if statuses:
    problems.append(f"{statuses} nodes differ in status")
for p in problems:
    print(p)
contacts = sum(1 for r, n in pairs if r["status"] == "contact")
print(f"on the {sys.argv[3]}, against GetFEM: {matched} nodes, {contacts} in contact, forces within "
      f"{worst / largest:.2g} of the largest ({largest:.4g}), {statuses} statuses differ")
sys.exit(1 if problems else 0)
PY
}

match plane 1e-6 -- "obstacle=plane point=0,0,0 normal=0,0,1"
# A rigid cylinder of the ball's radius across under it (a wheel on a rail, turned over): an
# elliptic contact, the normals no longer parallel. GetFEM's normal is a forward difference of the
# distance with a step of 1e-3 of the element's radius, wrong by about step / (2 radius of the
# cylinder), ours exact: the forces then differ by 1.5e-4 of the largest here, by 2.7e-4, 6.7e-5
# and 1.8e-5 with radii 2, 32 and 128 (falling with the curvature; the statuses are the same).
match cylinder 5e-4 --cylinder 8 -- "obstacle=cylinder centre=0,0,-8 axis=1,0,0 radius=8"
finish "the frictionless 3D solve is GetFEM's on the same mesh, on a plane and on a cylinder"
