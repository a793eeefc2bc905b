#!/usr/bin/env bash
# Requirement (issue 28, "Gonzalez in 3D"): the hyperelastic march runs on a 3D mesh, Gonzalez's
# algorithmic stress conserves the energy of a free body in 3D, and the 3D hyperelastic march
# takes frictionless contact with a plane. drivers/scene3d_spin.sh --quick: the free
# Ciarlet-Geymonat ball of datafiles/scene3d/spinning_ball.dat (93 nodes, spinning at
# omega = (3, 4, 12) rad/s, no Dirichlet condition), 50 steps of k = 1e-3 s with each stress at
# Newton eps = 1e-10; checked on its summary.json (postproc/scene3d_spin_report.py, E from
# case.hist, L = sum_a x_a x (M v)_a from the kept states and case.tae's mass):
#  - both runs converge at every step, and the strain energy is not negligible (the ball swells:
#    the step is nonlinear);
#  - Gonzalez's stress keeps the energy to 1e-10 relative (measured 9e-15), the midpoint stress
#    does not (drift above 1e-6; measured 7e-5);
#  - both keep the angular momentum to 1e-10 relative (measured 5e-15 and 3e-15).
# Then the same ball dropped at 5 m/s on the plane x3 = -1.01 (60 steps of k = 1e-3: it lands at
# step 2 and is still squashed at the end), Gonzalez's stress, checked on energy.csv:
#  - the specific penalty (r = 1e8 Pa/m) keeps E + interface energy to 1e-10 of E0 (its identity
#    (3.53) with Gonzalez's; measured 1e-14), and the ball penetrates (the contact is active);
#  - IPM + EMM (g = 5 mm) never penetrates beyond g (1 + 1e-8), Signorini beyond 1e-9 m, and both
#    keep E - contact work (the wall's and the foundation's) to 1e-10 of E0.
# The 1000-step run and its numbers: datafiles/scene3d/README.md. About 4 s (loaded machine).
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_stages mesh material assemble march dump
require_command gmsh "the ball is meshed by gmsh"
require_python numpy

SIG_BIN=$bin "$root/drivers/scene3d_spin.sh" --quick -o "$work/out" >"$work/driver.log" 2>&1 ||
  { tail -n 30 "$work/driver.log"; die "drivers/scene3d_spin.sh --quick failed"; }
grep -E "^(gonzalez|midpoint):" "$work/driver.log" || true

"$python" - "$work/out" <<'PY'
import json, sys
from pathlib import Path
from pipeline_checks import check, finish
out = Path(sys.argv[1])
runs = json.loads((out / "summary.json").read_text())["runs"]
g, m = runs["gonzalez"], runs["midpoint"]
for name, r in runs.items():
    check(r["converged"] and r["steps"] == 50, f"{name}: {r['steps']} steps, converged "
          f"{r['converged']}")
    check(r["elastic_fraction"] > 1e-3,
          f"{name}: the strain energy reaches {r['elastic_fraction']:.3g} E0 > 1e-3 E0")
    check(r["momentum_drift"] < 1e-10,
          f"{name}: max |L - L0| / |L0| = {r['momentum_drift']:.3g} < 1e-10")
check(g["energy_drift"] < 1e-10, f"gonzalez: max |E - E0| / E0 = {g['energy_drift']:.3g} < 1e-10")
check(m["energy_drift"] > 1e-6,
      f"midpoint: max |E - E0| / E0 = {m['energy_drift']:.3g} > 1e-6 (it drifts)")
finish("spin3d")
PY

# The drop: the driver's ball (its mesh, laws and mass linked), a CONTACT card per strategy.
source "$root/drivers/lib/deck.sh"
base=$work/out/base
for run in "specific-penalty r=1e8|consistent" "ipm r=1e8 g=0.005|emm" "signorini|consistent"; do
  fields=${run%|*}
  dir=$work/drop/${fields%% *}
  mkdir -p "$dir"
  for ds in nopo mili tae; do ln -s "$base/case.$ds" "$dir/case.$ds"; done
  deck_variant "$base/spinning_ball.dat" "$dir/drop.dat" --replace-card INITIAL "INITIAL v=0,0,-5" \
    --add-card "CONTACT ref=3 obstacle=plane point=0,0,-1.01 normal=0,0,1 strategy=$fields" \
    --set TIME.T=0.06 --set TIME.output_every=10 --set TIME.mass="${run#*|}"
  for stage in contact march; do
    "$bin/sig-$stage" "$dir/drop.dat" -o "$dir" >"$dir/$stage.log" 2>&1 ||
      { tail -n 20 "$dir/$stage.log"; die "sig-$stage failed on the drop (${fields%% *})"; }
  done
  grep "^sig-march:" "$dir/march.log" || true
done
"$python" - "$work/drop" <<'PY'
import csv, sys
from pathlib import Path
from pipeline_checks import check, finish
drop = Path(sys.argv[1])
def rows(name):
    return list(csv.DictReader((drop / name / "energy.csv").open()))
for name, bound in (("specific-penalty", None), ("ipm", 0.005), ("signorini", 0.0)):
    r = rows(name)
    E0 = float(r[0]["total"])
    check(len(r) == 61, f"{name}: {len(r) - 1} of 60 steps")
    penetration = max(float(x["max_penetration"]) for x in r)
    active = max(int(x["active_nodes"]) for x in r)
    check(active > 0, f"{name}: the ball touches the plane ({active} nodes at most)")
    if bound is None:
        drift = max(abs(float(x["total"]) + float(x["interface"]) - E0) for x in r) / E0
        check(drift < 1e-10, f"{name}: max |E + interface - E0| / E0 = {drift:.3g} < 1e-10")
        check(penetration > 1e-3, f"{name}: penetrates {penetration:.3g} m (a compliant law)")
    else:
        check(penetration <= bound * (1 + 1e-8) + 1e-9,
              f"{name}: largest penetration {penetration:.3g} m <= {bound} m")
        drift = max(abs(float(x["total"]) - float(x["contact_work"]) - E0) for x in r) / E0
        check(drift < 1e-10, f"{name}: max |E - contact work - E0| / E0 = {drift:.3g} < 1e-10")
finish("spin3d (drop)")
PY
