#!/usr/bin/env bash
# Requirement (issues 23 and 26): Dirichlet conditions on contact nodes are honoured in the node's
# frame in 3D too. The oedometer of oedometer.sh in a box: a unit cube of gmsh's tetrahedra on the
# foundation x3 <= 0, rollers ux = 0 on its faces x1 = 0, 1 and uy = 0 on its faces x2 = 0, 1
# (those cards hold the base's edge nodes, contact nodes whose held axis is one tangent of their
# frame: the other keeps its friction law; the base's corners have both held), a pressure q on the
# top. P1 holds the confined state exactly: u1 = u2 = 0, u3 = u3(0) - q x3 / (lambda + 2 mu),
# u3(0) = -q / cn on a compliance, -g beyond a compliance-unilateral layer's wall, 0 on a
# Signorini wall; each base node carries the normal pressure q and no shear along its free
# tangents (a held one carries its roller's reaction). Each law with pdas
# and alm: displacements to 1e-10 of their scale, pressures to 1e-10 of q, edges and corners
# included; an oblique roller (a DIRICHLET card on an axis that is not one of the node's
# tangents) is refused naming the node.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_command gmsh "the cube is meshed by gmsh"

E=200
nu=0.3
q=2
# The cube with one physical surface per pair of faces: 1 the base, 2 the top, 3 the faces x1 =
# 0, 1, 4 the faces x2 = 0, 1.
cat >"$work/cube.geo" <<'EOF'
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Volume(1) = {1};
Physical Surface(1) = {5};
Physical Surface(2) = {6};
Physical Surface(3) = {1, 2};
Physical Surface(4) = {3, 4};
Mesh.CharacteristicLengthMax = 0.34;
Mesh.MshFileVersion = 4.1;
EOF
gmsh -3 "$work/cube.geo" -o "$work/cube.msh" >"$work/gmsh.log" 2>&1 || die "gmsh failed: $(tail -2 "$work/gmsh.log")"

deck() { # deck FILE CONTACT_FIELDS FRICTION_CARD METHOD
  cat >"$1" <<EOF
TITLE oedometer in 3D, rollers on the contact edges
MESH file=$work/cube.msh
MATERIAL law=hooke E=$E nu=$nu
DIRICHLET ref=3 ux=0
DIRICHLET ref=4 uy=0
PRESSURE ref=2 p=$q
CONTACT ref=1 obstacle=plane point=0,0,0 normal=0,0,1 $2
$3
SOLVER method=$4 gamma=100 r=100 eps=1e-12
OUTPUT vtk=no
EOF
}

check() { # check DIR BOTTOM_U3 STATUS
  "$python" - "$1" "$2" "$3" "$bin" "$E" "$nu" "$q" <<'PY'
import csv, json, subprocess, sys
out, bottom, status, bindir = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
E, nu, q = map(float, sys.argv[5:8])
lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
dump = lambda f: json.loads(subprocess.run([f"{bindir}/sig-dump", "--json", "--values", f],
                                           capture_output=True, text=True, check=True).stdout)
u = {a["name"]: a["values"] for a in dump(f"{out}/case.b")["arrays"] if "values" in a}["u"]
xyz = dump(f"{out}/case.nopo")["coordinates"]
scale = abs(bottom) + q / (lam + 2 * mu)
worst = max(max(abs(u[3 * i]), abs(u[3 * i + 1]),
                abs(u[3 * i + 2] - (bottom - q * xyz[3 * i + 2] / (lam + 2 * mu))))
            for i in range(len(xyz) // 3))
problems = []
if worst > 1e-10 * scale:
    problems.append(f"displacement off the exact state by {worst / scale:.2e} of its scale")
rows = list(csv.DictReader(open(f"{out}/contact.csv")))
edges = 0
for row in rows:
    x, y = float(row["x1"]), float(row["x2"])
    edges += x in (0.0, 1.0) or y in (0.0, 1.0)
    if abs(float(row["pressure"]) - q) > 1e-10 * q:
        problems.append(f"node at ({x}, {y}): pressure {row['pressure']}, exact {q}")
    if row["normal_status"] != status:
        problems.append(f"node at ({x}, {y}): status {row['normal_status']}, expected {status}")
    # A held component's force is its roller's reaction (the confinement, lambda / (lambda +
    # 2 mu) q on the side faces): only the free components carry no shear.
    free = [k for k, held in ((1, x in (0.0, 1.0)), (2, y in (0.0, 1.0))) if not held]
    shear = max([abs(float(row[f"tangential_force_{k}"])) for k in free] + [0.0])
    if shear > 1e-10 * q or row["friction_status"] not in ("S=", "-"):
        problems.append(f"node at ({x}, {y}): shear {shear}, status {row['friction_status']}")
if edges < 8:
    problems.append(f"only {edges} base nodes on the rollers' faces: the case needs them")
print("\n".join(problems) or f"{len(rows)} base nodes, {edges} on the rollers' faces")
sys.exit(1 if problems else 0)
PY
}

cn=10
declare -A cases=(
  [compliance]="law=compliance cn=$cn|$("$python" -c "print(-$q / $cn)")|CN"
  [wall]="law=compliance-unilateral cn=$cn g=0.05|-0.05|CU"
  [coulomb]="law=signorini|0|CU"
)
for name in "${!cases[@]}"; do
  IFS='|' read -r fields bottom status <<<"${cases[$name]}"
  friction=""
  [ "$name" = coulomb ] && friction="FRICTION ref=1 law=coulomb mu=0.3"
  for method in pdas alm; do
    checks=$((checks + 1))
    dir=$work/$name-$method
    deck "$dir.dat" "$fields" "$friction" "$method"
    if ! SIG_BIN=$bin "$root/drivers/chain.sh" "$dir.dat" -o "$dir" >"$dir.log" 2>&1; then
      fail "$name $method: the chain failed: $(grep -m1 -i error "$dir.log")"
    elif ! grep -q "converged in" "$dir.log"; then
      fail "$name $method: Nv: $(grep -m1 'sig-solve:' "$dir.log")"
    else
      check "$dir" "$bottom" "$status" || fail "$name $method: not the exact oedometer state"
    fi
  done
done

# A roller along an axis that is not one of a base node's tangents: the plane tilted about x1,
# so ux is t1 but uy mixes the normal and t2.
checks=$((checks + 1))
dir=$work/oblique
deck "$dir.dat" "law=signorini" "" pdas
sed -i 's/normal=0,0,1/normal=0,0.6,0.8/; s/point=0,0,0/point=0,0,-1/' "$dir.dat"
SIG_BIN=$bin "$root/drivers/chain.sh" "$dir.dat" -o "$dir" >"$dir.log" 2>&1 &&
  fail "an oblique roller on a contact node was accepted"
grep -q "oblique.dat:5: field 'uy': holds u2 of contact node [0-9]* (mesh node [0-9]*), which is neither the obstacle's normal" "$dir.log" ||
  fail "the oblique roller's refusal: $(grep -m1 -i error "$dir.log")"
finish "the oedometer in 3D: rollers on the contact edges honoured in the nodes' frames"
