#!/usr/bin/env bash
# Requirement (issue 28, "the viscoelastic marches in 3D"): the quasistatic Kelvin-Voigt march with
# memory and its normal law in velocity runs on a 3D body through the code path of the 2D one, and
# both give the same solution where P1 holds it exactly in either dimension: a column on a damped
# foundation under a ramped pressure, in uniaxial stress (nu = 0, eta1 = 0: no lateral stress, so
# the sides stay free and the top is held laterally only). Then u = (0, ..., u(x_d, t)) is affine
# in height at every step (the stress is uniform, sigma_dd = -t), the foundation sees one velocity
# everywhere (RNI while it is below g, CUV on the bound after), and the 2D strip (plane strain, a
# rectangle of triangles) and the 3D box (gmsh's tetrahedra) march the same scalar problem.
# Checked at every kept time: the 3D displacement against the 2D one at the same height and the
# 3D foundation force per unit width against the 2D one per unit length, to 1e-10, the lateral
# displacements zero, both statuses met. (About 1 s: two chains of five stages.)
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_command gmsh "the box generator meshes through gmsh"

common='MATERIAL law=kelvin-voigt E=100 nu=0 eta1=0 eta2=0.5
MEMORY E=20 nu=0 beta=2
TIME scheme=quasistatic T=1 k=0.0625 output_every=4
SOLVER linear=cholmod method=pdas gamma=100 eps=1e-12 maxit=100
OUTPUT vtk=no'
cat >"$work/column2d.dat" <<DECK
TITLE a Kelvin-Voigt column with memory on a damped foundation, 2D (plane strain)
# Units: GPa, m, s.
MESH generator=rectangle lx=1 ly=1 nx=2 ny=4
$common
DIRICHLET ref=2 ux=0
TRACTION ref=2 f=0,-1 ramp=1
CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=damped-unilateral cn=10 g=0.047
DECK
cat >"$work/column3d.dat" <<DECK
TITLE the same column in 3D: a box of tetrahedra, its base on the foundation
# Units: GPa, m, s.
MESH generator=box lx=1 ly=0.5 lz=1 h=0.5
$common
DIRICHLET ref=2 ux=0 uy=0
TRACTION ref=2 f=0,0,-1 ramp=1
CONTACT ref=1 obstacle=plane point=0,0,0 normal=0,0,1 law=damped-unilateral cn=10 g=0.047
DECK
for d in 2 3; do
  "$root/drivers/chain.sh" "$work/column${d}d.dat" -o "$work/$d" >"$work/chain$d.log" 2>&1 ||
    { tail -20 "$work/chain$d.log"; die "drivers/chain.sh column${d}d.dat failed"; }
done

checks=$((checks + 1))
"$python" - "$work" "$bin" <<'PY' || fail "the 3D column against the 2D one"
import json, subprocess, sys
work, bindir = sys.argv[1], sys.argv[2]
def dump(path):
    return json.loads(subprocess.run([f"{bindir}/sig-dump", "--json", "--values", path],
                                     capture_output=True, text=True, check=True).stdout)
def case(d):
    x = dump(f"{work}/{d}/case.nopo")["coordinates"]
    hist = {a["name"]: a for a in dump(f"{work}/{d}/case.hist")["arrays"] if "values" in a}
    return [x[i:i + d] for i in range(0, len(x), d)], hist
def rows(a):
    width = a["shape"][-1]
    return [a["values"][i:i + width] for i in range(0, len(a["values"]), width)]
(x2, h2), (x3, h3) = case(2), case(3)
problems = []
for name in ("converged", "output_time"):
    if h2[name]["values"] != h3[name]["values"]:
        problems.append(f"{name}: 2D {h2[name]['values']}, 3D {h3[name]['values']}")
# The 2D state is affine in height: u2 = a + b x2, read off its bottom and top left corners.
bottom = next(i for i, p in enumerate(x2) if p == [0.0, 0.0])
top = next(i for i, p in enumerate(x2) if p == [0.0, 1.0])
u2, u3 = rows(h2["u"]), rows(h3["u"])
scale = max(abs(v) for u in u2 for v in u)
worst = 0.0
for a2, a3 in zip(u2, u3):
    a, b = a2[2 * bottom + 1], a2[2 * top + 1] - a2[2 * bottom + 1]
    for i, p in enumerate(x2):
        worst = max(worst, abs(a2[2 * i]), abs(a2[2 * i + 1] - (a + b * p[1])))
    for i, p in enumerate(x3):
        worst = max(worst, abs(a3[3 * i]), abs(a3[3 * i + 1]), abs(a3[3 * i + 2] - (a + b * p[2])))
if len(u2) != 5 or len(u3) != 5 or not scale > 0 or worst > 1e-10 * scale:
    problems.append(f"displacements off the 2D column's by {worst:.3e} (scale {scale:.3e}, "
                    f"{len(u2)} and {len(u3)} kept states)")
# The foundation: force per unit length (2D) and per unit width (3D, ly = 0.5) at every step.
f2 = [sum(r) for r in rows(h2["force_n"])]
f3 = [sum(r) / 0.5 for r in rows(h3["force_n"])]
force = max(abs(v) for v in f2)
gap = max(abs(a - b) for a, b in zip(f2, f3))
if len(f2) != 17 or len(f3) != 17 or not force > 0 or gap > 1e-10 * force:
    problems.append(f"foundation forces off by {gap:.3e} of {force:.3e} ({len(f2)} steps)")
for d, h in ((2, h2), (3, h3)):
    statuses = [set(r) for r in rows(h["normal_status"])[1:]]
    if any(len(s) != 1 for s in statuses):
        problems.append(f"{d}D: the foundation's nodes differ in status")
    if not {1, 2} <= set.union(*statuses):
        problems.append(f"{d}D: statuses {set.union(*statuses)}, expected RNI (1) and CUV (2)")
print(f"3D against 2D: displacements {worst / scale:.2e} of {scale:.4g}, "
      f"forces {gap / force:.2e} of {force:.4g}")
if problems:
    print("\n".join(problems))
    sys.exit(1)
PY

finish "the 3D Kelvin-Voigt column marches as the 2D one"
