#!/usr/bin/env bash
# Requirement (issue 23): a body held by friction alone converges from rest, with no INITIAL card
# (a 2 x 1 block under the traction (0.2, -1), Coulomb mu = 0.3), with pdas, alm and projection,
# on a rigid plane and on a compliant foundation;
# the same block pushed beyond its friction bound (traction (0.5, -1): Q = 1 > mu P = 0.6) has no
# equilibrium, and every output a user opens says so: sig-solve's Nv line, case.b's
# failure_reason, summary.json's failure "drift" with its size, contact.csv's converged column
# (0 on every row), the .vtu's field data converged = 0 (in 3D, where no step shows the drift,
# the failure says every node slips at its bound); a CONTACT card whose obstacle faces
# Gamma3 from inside the body is warned about.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"

block() { # block FILE TRACTION METHOD [CONTACT_OVERRIDE [FRICTION_OVERRIDE]]
  cat >"$1" <<EOF
TITLE block held by friction alone
# Units: GPa and m. No Dirichlet condition and no INITIAL card.
MESH generator=rectangle lx=2 ly=1 nx=16 ny=8
MATERIAL law=hooke E=100 nu=0.3 plane=strain
TRACTION ref=2 f=$2
${4:-CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=signorini}
${5:-FRICTION ref=3 law=coulomb mu=0.3}
SOLVER method=$3 gamma=100 r=100 c=0.01 eps=1e-10 maxit=100
OUTPUT vtk=yes
EOF
}

# The same block on a compliant foundation (compliance, and a compliant layer over a wall):
# at rest every node is at q_n = 0, the compliance's kink, where Coulomb's bound mu cn [q_n]_+ is
# 0 but rises with a press (the cone's apex, held on its stick side). On the layer, friction of
# the penetration (8.3) with asperities of depth g: the block sinks q_n = p / cn = 0.005 = g / 4,
# where mu1 mu=1 gives 0.25 and mu2 mu=0.25 gives 0.44, both above Q / P = 0.2; at rest their
# coefficient is 0, but a press raises the bound (mu1's to second order), so the apex sticks too.
compliance="CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=compliance cn=200"
layer="CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=compliance-unilateral cn=200 g=0.02"
mu1="FRICTION ref=3 law=mu1 mu=1"
mu2="FRICTION ref=3 law=mu2 mu=0.25"
for variant in "pdas" "alm" "projection" "pdas|$compliance" "alm|$compliance" "pdas|$layer" \
  "pdas|$layer|$mu1" "alm|$layer|$mu2"; do
  IFS='|' read -r method contact friction <<<"$variant"
  dir=$work/held_${method}_${#contact}_${#friction}
  block "$dir.dat" 0.2,-1 "$method" "$contact" "$friction"
  SIG_BIN=$bin drivers/chain.sh "$dir.dat" -o "$dir" >"$dir.log" 2>&1 || { tail -5 "$dir.log"; die "$method: the chain failed"; }
  grep -q "converged in" "$dir.log" || { grep sig-solve "$dir.log"; die "$method: the block held by friction did not converge from rest"; }
  /usr/bin/python3 - "$dir/contact.csv" "${friction:-law=coulomb}" <<'PY' || die "$method: not an equilibrium of the block"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
law = sys.argv[2].split("law=")[1].split()[0]
def mu(r):  # (8.3) at the node's penetration, the asperities of depth g = 0.02
    crushed = min(max(-float(r["gap"]), 0.0) / 0.02, 1.0)
    return {"coulomb": 0.3, "mu1": crushed, "mu2": 0.25 * (2 - crushed)}[law]
N = sum(float(r["multiplier"]) for r in rows)
T = sum(float(r["tangential_multiplier"]) for r in rows)
assert abs(N - 2.0) < 1e-8 and abs(T - 0.4) < 1e-8, (N, T)  # P = 2 x 1, Q = 2 x 0.2
assert all(r["converged"] == "1" for r in rows)
assert all(abs(float(r["tangential_multiplier"])) <= mu(r) * float(r["multiplier"]) + 1e-12 for r in rows)
PY
  echo "robust_newton: $method${contact:+ (${contact#*law=}${friction:+, ${friction#*law=}})}: the block held by friction converges from rest ($(grep -o 'converged in [0-9]* iterations' "$dir.log"))"
done

dir=$work/slides
block "$dir.dat" 0.5,-1 pdas
SIG_BIN=$bin drivers/chain.sh "$dir.dat" -o "$dir" >"$dir.log" 2>&1 || { tail -5 "$dir.log"; die "sliding block: the chain failed"; }
grep -q "sig-solve: Nv, drift:" "$dir.log" || { grep sig-solve "$dir.log"; die "sliding block: sig-solve did not name the drift"; }
"$bin/sig-dump" "$dir/case.b" | grep -q 'failure_reason.*"drift"' || die "sliding block: case.b has no failure_reason drift"
/usr/bin/python3 - "$dir" <<'PY' || die "sliding block: an output does not say Nv"
import csv, json, sys
from pathlib import Path
out = Path(sys.argv[1])
s = json.loads((out / "summary.json").read_text())
assert s["converged"] is False and s["failure"] == "drift" and s["drift"] > 0, s
assert all(r["converged"] == "0" for r in csv.DictReader(open(out / "contact.csv")))
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(str(next(out.glob("*_0000.vtu"))))
reader.Update()
assert reader.GetOutput().GetFieldData().GetArray("converged").GetValue(0) == 0
PY
echo "robust_newton: the block beyond its friction bound is a drift in every output"

# The 3D pulled block under mu1 (datafiles/scene3d/block_friction.dat on a compliant layer):
# mu = 0.09 gives mu1 = 0.09 q_n / g = 0.045 at the block's penetration q_n = p / cn = 1e-6 = g / 2,
# below Q / P = 1e5 / 1e6 = 0.1 (and mu1 <= 0.09 at any depth): no equilibrium. Each
# step is held by the slip directions' curvature, so no unheld step shows the drift; the failure
# says that every node slips at its bound and what that means.
dir=$work/slides3d
sed -e 's/law=signorini/law=compliance-unilateral cn=1e12 g=2e-6/' -e 's/law=coulomb mu=0.5/law=mu1 mu=0.09/' \
  datafiles/scene3d/block_friction.dat >"$dir.dat"
grep -q "law=mu1 mu=0.09" "$dir.dat" && grep -q "compliance-unilateral cn=1e12 g=2e-6" "$dir.dat" || die "the 3D variant of block_friction.dat was not made (its cards changed?)"
SIG_BIN=$bin drivers/chain.sh "$dir.dat" -o "$dir" >"$dir.log" 2>&1 || true
grep -q "sig-solve: Nv, .*every node with a friction bound slips at it.*no equilibrium" "$dir.log" ||
  { grep sig-solve "$dir.log"; die "3D block beyond its friction bound: the failure does not say every node slips"; }
echo "robust_newton: the 3D block beyond its friction bound fails naming the slip at every node"

# Penalty's stiff tangential springs on the Tresca half disc (datafiles/friction/hertz_coulomb.dat
# with Tresca's threshold 1, N = 64, from rest; r = 38201 = 100 E / h, the robustness map's point):
# once every node slips, the unheld step that reverses the slip crosses each node's stick window
# |q_t| <= s / r (1e-5 of the step) between the step's geometric samples; found at the slip's
# closest approach to 0, the body is held there and the solve converges, where it was called a
# drift (an equilibrium exists: Q = 6.4 < the bound, 1 on each of Gamma3's 25 units of length).
dir=$work/stiff_penalty
sed -e 's/N=256/N=64/' -e 's/law=coulomb mu=0.4/law=tresca threshold=1/' -e '/^INITIAL/d' \
  -e 's/^SOLVER method=pdas gamma=100/SOLVER method=penalty r=38201/' datafiles/friction/hertz_coulomb.dat >"$dir.dat"
grep -q "law=tresca threshold=1" "$dir.dat" && grep -q "method=penalty r=38201" "$dir.dat" &&
  grep -q "N=64" "$dir.dat" && ! grep -q "^INITIAL" "$dir.dat" ||
  die "the Tresca variant of hertz_coulomb.dat was not made (its cards changed?)"
SIG_BIN=$bin drivers/chain.sh "$dir.dat" -o "$dir" >"$dir.log" 2>&1 || true
grep -q "sig-solve: penalty .* converged in" "$dir.log" ||
  { grep sig-solve "$dir.log"; die "stiff penalty on the Tresca half disc: not converged"; }
echo "robust_newton: penalty r = 100 E / h on the Tresca half disc converges from rest ($(grep -o 'converged in [0-9]* iterations' "$dir.log"))"

dir=$work/facing
block "$dir.dat" 0.2,-1 pdas "CONTACT ref=3 obstacle=plane point=0,2 normal=0,-1 law=signorini"
"$bin/sig-mesh" "$dir.dat" -o "$dir" >/dev/null
"$bin/sig-contact" "$dir.dat" -o "$dir" >"$dir.log" 2>&1 || true
grep -q "contact nodes face the obstacle from inside the body" "$dir.log" || { cat "$dir.log"; die "no warning for an obstacle facing Gamma3 from inside"; }
echo "robust_newton: an obstacle facing Gamma3 from inside the body is warned about"
