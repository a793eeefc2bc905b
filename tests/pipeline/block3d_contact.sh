#!/usr/bin/env bash
# Requirement (issue 26, 3D contact): datafiles/scene3d/block_on_plane.dat, a block of P1
# tetrahedra pressed by a uniform pressure p on a rigid plane, frictionless, nu = 0, its top held
# in x1 and x2 only: the contact alone holds the translation along x3 and the two tilts. The
# exact solution is uniaxial, and P1 reproduces it (a patch test of the 3D contact path: frames,
# condensation onto the contact normals, tributary areas): every base node in contact, its
# pressure (nodal force over tributary area) p, the nodal forces summing to p times the base's
# area, the base on the plane, the top lowered by p lz / E; contact.csv has x3 and u3, the .vtu
# the contact pressure and status. The same
# deck with every method; a deck with a 2D obstacle, a 2D body's plane= or a sphere in 2D words is
# refused naming the field. And the same block in
# large deformation (Saint Venant-Kirchhoff, lambda = 0), uniaxial again (issue 28).
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_command gmsh "the box generator meshes through gmsh"

deck=$root/datafiles/scene3d/block_on_plane.dat
for method in pdas alm penalty projection; do
  out=$work/$method
  # penalty's foundation stiffness r, per unit area, 1e5 times the block's E / lz: the default's
  # 100 is the thesis's GPa-m scale, and this deck is in Pa
  solver="method=$method"
  [ "$method" = penalty ] && solver="method=penalty r=2.1e16"
  sed "s/^SOLVER method=pdas$/SOLVER $solver/" "$deck" >"$work/$method.dat"
  "$root/drivers/chain.sh" "$work/$method.dat" -o "$out" >"$work/$method.log" 2>&1 ||
    { tail -20 "$work/$method.log"; die "drivers/chain.sh ($method) failed"; }
  checks=$((checks + 1))
  "$python" - "$out" "$bin" "$method" <<'PY' || fail "the solution of block_on_plane.dat ($method)"
import csv, json, subprocess, sys
out, bindir, method = sys.argv[1], sys.argv[2], sys.argv[3]
rows = list(csv.DictReader(open(f"{out}/contact.csv")))
p, E, lz = 1e6, 210e9, 1.0
# penalty's wall is a spring: the body sinks by p / r = 1e-5 of the top's drop, uniformly
exact = 2e-5 if method == "penalty" else 1e-9
problems = []
if not rows or any(c not in rows[0] for c in ("x3", "u3", "slip_1", "tangential_force_3")):
    problems.append("contact.csv lacks a 3D column (x3, u3, slip_1..3, tangential_force_1..3)")
if any(r["converged"] != "1" for r in rows):
    problems.append("not converged")
if any(r["status"] != "contact" for r in rows):
    problems.append(f"{sum(r['status'] != 'contact' for r in rows)} base nodes not in contact")
worst = max(abs(float(r["pressure"]) / p - 1) for r in rows)
if worst > exact:
    problems.append(f"a base node's pressure is off by {worst:.3g} of p")
force = sum(float(r["multiplier"]) for r in rows)
if abs(force / p - 1) > 1e-9:
    problems.append(f"the nodal forces sum to {force}, p x area = {p}")
mesh = json.loads(subprocess.run([f"{bindir}/sig-dump", "--json", "--values", f"{out}/case.nopo"],
                                 capture_output=True, text=True, check=True).stdout)
u = {a["name"]: a["values"] for a in json.loads(subprocess.run(
    [f"{bindir}/sig-dump", "--json", "--values=u", f"{out}/case.b"], capture_output=True,
    text=True, check=True).stdout)["arrays"] if "values" in a}["u"]
x = mesh["coordinates"]
n = len(x) // 3
drop = p * lz / E
for i in range(n):
    expected = -drop * x[3 * i + 2] / lz
    if abs(u[3 * i + 2] - expected) > exact * drop + 1e-9 * drop:
        problems.append(f"node {i + 1}: u3 {u[3 * i + 2]:.6g}, exact {expected:.6g}")
        break
    if max(abs(u[3 * i]), abs(u[3 * i + 1])) > 1e-9 * drop:
        problems.append(f"node {i + 1} moves sideways")
        break
for q in problems:
    print(q)
print(f"block3d ({method}): {len(rows)} contact nodes, pressure off by {worst:.2g}, force sum "
      f"{force:.10g}")
sys.exit(1 if problems else 0)
PY
done

# ParaView: the .vtu of the pdas run has tetrahedra's stress and the contact fields at the nodes.
checks=$((checks + 1))
vtu=$work/pdas/pdas_0000.vtu
if [ ! -f "$vtu" ]; then
  fail "no $vtu"
else
  header=$(head -c 20000 "$vtu" | tr -d '\000' | sed -n '/<UnstructuredGrid>/,/<AppendedData/p')
  for field in 'Name="displacement" NumberOfComponents="3"' 'Name="contact_pressure"' \
    'Name="contact_status"' 'Name="stress" NumberOfComponents="6"'; do
    grep -aqF -- "$field" <<<"$header" || fail "the .vtu lacks $field"
  done
fi

# In large deformation (issue 28): the same block of Saint Venant-Kirchhoff with nu = 0 (lambda =
# 0) under a nominal pressure p = 2e10 Pa (a tenth of E) in two load steps. With lambda = 0 the
# uniaxial stretch keeps S11 = S22 = 0 exactly, so the exact solution is uniaxial again:
# mu s (s^2 - 1) = -p (P33 = s S33, S33 = mu (s^2 - 1)) for the stretch s = 0.886, u3 = (s - 1)
# x3 at every node, and every base node's nominal pressure p (PDAS, Newton eps = 1e-12; measured
# 3e-15 and 1e-15).
sed -e 's/^MATERIAL.*/MATERIAL law=svk E=210e9 nu=0/' \
  -e 's/PRESSURE ref=2 p=1e6/PRESSURE ref=2 p=2e10/' -e 's/^SOLVER method=pdas$/SOLVER method=pdas eps=1e-12/' -e 's/^OUTPUT.*/OUTPUT vtk=no/' \
  "$deck" >"$work/svk.dat"
echo "LOADSTEPS n=2" >>"$work/svk.dat"
checks=$((checks + 1))
if ! "$root/drivers/chain.sh" "$work/svk.dat" -o "$work/svk" >"$work/svk.log" 2>&1; then
  tail -20 "$work/svk.log"
  fail "drivers/chain.sh (svk, large deformation) failed"
else
  "$python" - "$work/svk" "$bin" <<'PY' || fail "the large-deformation block (svk)"
import csv, json, subprocess, sys
out, bindir = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(f"{out}/contact.csv")))
p, mu = 2e10, 105e9
s = 0.9
for _ in range(50):
    s -= (mu * s * (s * s - 1) + p) / (mu * (3 * s * s - 1))
def dump(path, *extra):
    return json.loads(subprocess.run([f"{bindir}/sig-dump", "--json", *extra, path],
                                     capture_output=True, text=True, check=True).stdout)
x = dump(f"{out}/case.nopo", "--values")["coordinates"]
u = [a for a in dump(f"{out}/case.b", "--values=u")["arrays"] if a["name"] == "u"][0]["values"]
n = len(x) // 3
problems = []
if any(r["converged"] != "1" or r["status"] != "contact" for r in rows):
    problems.append("a base node not converged or not in contact")
pressure = max(abs(float(r["pressure"]) / p - 1) for r in rows)
stretch = max(abs(u[3 * i + 2] - (s - 1) * x[3 * i + 2]) for i in range(n)) / (1 - s)
side = max(max(abs(u[3 * i]), abs(u[3 * i + 1])) for i in range(n)) / (1 - s)
for value, what in ((pressure, "nominal pressure"), (stretch, "u3 = (s - 1) x3"),
                    (side, "no sideways motion")):
    if value > 1e-10:
        problems.append(f"{what}: off by {value:.3g}")
for q in problems:
    print(q)
print(f"block3d (svk, s = {s:.6f}): pressure off by {pressure:.2g}, u3 by {stretch:.2g}")
sys.exit(1 if problems else 0)
PY
fi

# Decks in the wrong dimension's words, refused naming the field.
refused() { # NAME SED-EXPRESSION FIELD
  sed "$2" "$deck" >"$work/$1.dat"
  checks=$((checks + 1))
  if "$root/drivers/chain.sh" "$work/$1.dat" -o "$work/$1" >"$work/$1.log" 2>&1; then
    fail "$1 was solved"
  elif ! grep -q "$3" "$work/$1.log"; then
    fail "$1: the refusal does not name $3: $(grep -m1 -i error "$work/$1.log")"
  fi
}
refused two_components 's/point=0,0,0 normal=0,0,1/point=0,0 normal=0,1/' "field 'point'"
refused disc 's/obstacle=plane point=0,0,0 normal=0,0,1/obstacle=disc centre=0,0,-1 radius=1/' \
  "field 'obstacle'"
refused plane_strain 's/^MATERIAL .*/& plane=strain/' "field 'plane'"
finish "a block pressed on a rigid plane in 3D: the patch test with every method"
