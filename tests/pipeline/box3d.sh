#!/usr/bin/env bash
# Requirement (issue 26, first slice): a 3D deck runs through the chain. datafiles/scene3d/box.dat,
# a 1 x 1 x 2 m steel block under its own weight clamped at its base, meshed with tetrahedra by
# gmsh: sig-mesh, sig-material, sig-assemble, sig-solve and sig-post run; the base does not move,
# every node goes down, the top goes down by about the bar's rho g L^2 / (2 E) (less: the clamped
# base holds the lateral bulge back), the block stays symmetric about its vertical mid-planes (to
# the mesh's asymmetry), and the .vtu holds tetrahedra with a 3-component displacement, a
# 6-component stress and von Mises. A deck that holds the base along x3 only leaves the block
# free to slide and turn, and is refused.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_command gmsh "the box generator meshes through gmsh"

deck=$root/datafiles/scene3d/box.dat
out=$work/box
"$root/drivers/chain.sh" "$deck" -o "$out" >"$work/chain.log" 2>&1 ||
  { tail -20 "$work/chain.log"; die "drivers/chain.sh $deck failed"; }

checks=$((checks + 1))
"$python" - "$out" "$bin" <<'PY' || fail "the solution of box.dat"
import json, subprocess, sys
out, bindir = sys.argv[1], sys.argv[2]
def dump(path, *options):
    return json.loads(subprocess.run([f"{bindir}/sig-dump", "--json", *options, path],
                                     capture_output=True, text=True, check=True).stdout)
mesh = dump(f"{out}/case.nopo", "--values")
u = {a["name"]: a["values"] for a in dump(f"{out}/case.b", "--values=u")["arrays"]
     if "values" in a}["u"]
x = mesh["coordinates"]
n = len(x) // 3
problems = []
if mesh.get("dim") != 3 or len(u) != 3 * n:
    problems.append(f"dim {mesh.get('dim')}, {len(u)} displacements for {n} nodes")
rho_g, E, L = 77008.5, 210e9, 2.0
bar = rho_g * L * L / (2 * E)
top = [i for i in range(n) if abs(x[3 * i + 2] - L) < 1e-12]
base = [i for i in range(n) if x[3 * i + 2] == 0]
if max(abs(u[3 * i + c]) for i in base for c in range(3)) != 0:
    problems.append("the clamped base moved")
if max(u[3 * i + 2] for i in range(n)) > 1e-6 * bar:
    problems.append(f"a node moves up by {max(u[3 * i + 2] for i in range(n))}")
drop = -min(u[3 * i + 2] for i in top)
if not 0.6 * bar < drop < bar:
    problems.append(f"the top goes down by {drop}, the bar's {bar}")
# The lateral displacements of the block average out (symmetry about x1 = 0.5 and x2 = 0.5).
for c in (0, 1):
    mean = sum(u[3 * i + c] for i in range(n)) / n
    if abs(mean) > 0.05 * bar:
        problems.append(f"mean u{c + 1} = {mean}: the block leans")
for p in problems:
    print(p)
print(f"box3d: {n} nodes, top drop {drop:.4g} m, bar {bar:.4g} m")
sys.exit(1 if problems else 0)
PY

# The ParaView file: its XML header names each array and its components (the cells' type,
# VTK_TETRA, is read back by VTK in tests/post/test_vtk_3d.cpp).
checks=$((checks + 1))
vtu=$out/box_0000.vtu
if [ ! -f "$vtu" ]; then
  fail "no $vtu"
else
  header=$(head -c 20000 "$vtu" | tr -d '\000' | sed -n '/<UnstructuredGrid>/,/<AppendedData/p')
  for field in 'Name="displacement" NumberOfComponents="3"' 'Name="stress" NumberOfComponents="6"' \
    'Name="von_mises"'; do
    grep -aqF -- "$field" <<<"$header" || fail "the .vtu lacks $field"
  done
fi

# Held along x3 only, the block may slide and turn: refused, naming the motion.
sed 's/^DIRICHLET ref=1 ux=0 uy=0 uz=0$/DIRICHLET ref=1 uz=0/' "$deck" >"$work/sliding.dat"
"$root/drivers/chain.sh" "$work/sliding.dat" -o "$work/sliding" >"$work/sliding.log" 2>&1 &&
  fail "a block held along x3 only was solved" || true
checks=$((checks + 1))
grep -q "free to move" "$work/sliding.log" || fail "the sliding block's refusal: $(grep -m1 error "$work/sliding.log")"

finish "the 3D box runs through the chain"
