#!/usr/bin/env bash
# Requirement (issue 26, 3D contact with normals off the axes): the patch test of
# block_on_plane.dat turned so that the obstacle's normal is n = (1, 2, 2) / 3, none of the axes
# nor in a plane of two: a unit cube of P1 tetrahedra (4 x 4 x 4 cubes, six tetrahedra each),
# rotated so that its base lies on the plane x . n = 0, nu = 0, its top pushed by delta along -n
# (DIRICHLET with all three components), frictionless. The exact solution is uniaxial along n:
# u(x) = -delta (x . n) / L n, every base node in contact with the pressure E delta / L, no
# tangential motion. It checks the contact frames (t1, t2, -n) built from a normal off the axes,
# their rotation of the three dofs and the condensation onto the normals, with every method.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"

"$python" - "$work/tilted.msh" <<'PY'
# The rotated cube, gmsh 2.2: physical 1 the base, 2 the top, 4 the volume.
import itertools, sys
n, L = 4, 1.0
e1, e2, normal = (2 / 3, -2 / 3, 1 / 3), (2 / 3, 1 / 3, -2 / 3), (1 / 3, 2 / 3, 2 / 3)
index, points = {}, []
for k, j, i in itertools.product(range(n + 1), repeat=3):
    index[i, j, k] = len(points) + 1
    points.append(tuple((i * e1[c] + j * e2[c] + k * normal[c]) * L / n for c in range(3)))
def volume(t):
    p = [points[v - 1] for v in t]
    u = [[p[m][c] - p[0][c] for c in range(3)] for m in (1, 2, 3)]
    return (u[0][0] * (u[1][1] * u[2][2] - u[1][2] * u[2][1])
            - u[0][1] * (u[1][0] * u[2][2] - u[1][2] * u[2][0])
            + u[0][2] * (u[1][0] * u[2][1] - u[1][1] * u[2][0]))
tets = []
for i, j, k in itertools.product(range(n), repeat=3):
    for order in itertools.permutations(range(3)):  # Kuhn's six tetrahedra of a cube
        corner, path = [i, j, k], [index[i, j, k]]
        for axis in order:
            corner[axis] += 1
            path.append(index[tuple(corner)])
        tets.append(path if volume(path) > 0 else [path[0], path[2], path[1], path[3]])
faces = {}
for t in tets:
    for f in ((t[0], t[1], t[2]), (t[0], t[1], t[3]), (t[0], t[2], t[3]), (t[1], t[2], t[3])):
        faces.setdefault(tuple(sorted(f)), []).append(f)
layer = {v: key[2] for key, v in index.items()}
triangles = []
for key, found in faces.items():
    layers = {layer[v] for v in key}
    if len(found) == 1 and layers in ({0}, {n}):
        triangles.append((1 if layers == {0} else 2, found[0]))
with open(sys.argv[1], "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(points))
    for m, p in enumerate(points):
        f.write("%d %.17g %.17g %.17g\n" % (m + 1, *p))
    f.write("$EndNodes\n$Elements\n%d\n" % (len(triangles) + len(tets)))
    for m, (ref, t) in enumerate(triangles):
        f.write("%d 2 2 %d %d %d %d %d\n" % (m + 1, ref, ref, *t))
    for m, t in enumerate(tets):
        f.write("%d 4 2 4 4 %d %d %d %d\n" % (len(triangles) + m + 1, *t))
    f.write("$EndElements\n")
PY

for method in pdas alm projection penalty; do
  solver="method=$method"
  # penalty's wall is a spring of stiffness r per unit area: 1e5 times E / L, as block3d_contact
  [ "$method" = penalty ] && solver="method=penalty r=2.1e16"
  cat >"$work/$method.dat" <<DECK
TITLE a block on a plane of normal (1, 2, 2) / 3
MESH file=$work/tilted.msh
MATERIAL law=hooke E=210e9 nu=0
DIRICHLET ref=2 ux=-3.3333333333333333e-06 uy=-6.6666666666666667e-06 uz=-6.6666666666666667e-06
CONTACT ref=1 obstacle=plane point=0,0,0 normal=0.3333333333333333,0.6666666666666667,0.6666666666666667 law=signorini
SOLVER $solver
OUTPUT vtk=no
DECK
  "$root/drivers/chain.sh" "$work/$method.dat" -o "$work/$method" >"$work/$method.log" 2>&1 ||
    { tail -20 "$work/$method.log"; die "drivers/chain.sh ($method) failed"; }
  checks=$((checks + 1))
  "$python" - "$work/$method" "$bin" "$method" <<'PY' || fail "the tilted block ($method)"
import csv, json, subprocess, sys
out, bindir, method = sys.argv[1], sys.argv[2], sys.argv[3]
E, L, delta = 210e9, 1.0, 1e-5
n = (1 / 3, 2 / 3, 2 / 3)
p = E * delta / L
# penalty's wall is a spring: the base sinks by p / r = 1e-5 of delta along -n
tolerance = 2e-5 if method == "penalty" else 1e-9
rows = list(csv.DictReader(open(f"{out}/contact.csv")))
problems = []
if len(rows) != 25:
    problems.append(f"{len(rows)} contact nodes, the base has 25")
if any(r["converged"] != "1" or r["status"] != "contact" for r in rows):
    problems.append("a base node not converged or not in contact")
worst = max(abs(float(r["pressure"]) / p - 1) for r in rows)
if worst > tolerance:
    problems.append(f"a base node's pressure is off by {worst:.3g} of E delta / L")
force = sum(float(r["multiplier"]) for r in rows)
if abs(force / p - 1) > max(tolerance, 1e-9):
    problems.append(f"the nodal forces sum to {force}, p x area = {p}")
dump = lambda *a: json.loads(subprocess.run([f"{bindir}/sig-dump", "--json", *a],
                                            capture_output=True, text=True, check=True).stdout)
x = dump("--values", f"{out}/case.nopo")["coordinates"]
u = {a["name"]: a["values"] for a in dump("--values=u", f"{out}/case.b")["arrays"]
     if "values" in a}["u"]
for i in range(len(x) // 3):
    s = sum(x[3 * i + c] * n[c] for c in range(3))
    exact = [-delta * s / L * n[c] for c in range(3)]
    # penalty: the whole block shifted by the wall spring's sink, uniform
    off = max(abs(u[3 * i + c] - exact[c]) for c in range(3))
    if off > tolerance * delta + 1e-9 * delta:
        problems.append(f"node {i + 1}: u {u[3 * i:3 * i + 3]}, exact {exact}")
        break
for q in problems:
    print(q)
print(f"tilted block ({method}): pressure off by {worst:.2g}, force sum / (p area) - 1 = "
      f"{force / p - 1:.2g}")
sys.exit(1 if problems else 0)
PY
done
finish "a block on a plane whose normal is off the axes: the 3D patch test with every method"
