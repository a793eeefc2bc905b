#!/usr/bin/env bash
# Pipeline test, scene 6 (issue 13): drivers/scene6.sh --quick (the rail under the moving load with
# the slip-rate friction's convexification in every step of the dynamic backward Euler, at
# h = 1/32; Fig 6.5 for h = k = 1/2 ... 1/16 against 1/32; a small stability map) and its report,
# then the requirements on the results:
#  - every check of the report passes or is marked not run (the quick Fig 6.5 slope): the
#    Winkler strip within 1 % at psi = 10, 50, 200, the quasi-static limit (the frictionless
#    march equal to the static solves at t = 0.2 ... 0.8), the loads following c t, the small
#    viscosity invisible, the loop converged in every step, one factorization per march;
#  - scene.json (PROTOCOL.md 6) names files that exist;
#  - the figure run's .pvd is a time series whose .vtu carry velocity, contact pressure and the
#    statuses as point data;
#  - case.hist records per step the loop's counts, the loop converged in every step;
#  - the adapted study (issue 29) is checked by the report (no worse per dof than the scene's
#    uniform meshes, effectivities in [0.3, 3], passing above), its adapt.csv has 4 steps of
#    growing dofs, and the last adapted mesh carries contact nodes on every quarter of the rail
#    (marked on the worst time of each place, not the last time, when the load is at the end).
# Run from the repository root with SIG_BIN set (ctest does both); exit 77 (skipped) when
# matplotlib or numpy are missing.
set -euo pipefail

source "$(dirname "$0")/lib/common.sh"
require_python matplotlib numpy
quick_driver scene6

SIG_BIN=$bin PYTHONPATH=$root/postproc:$PYTHONPATH "$python" - "$work/scene6" <<'PYEOF'
import csv
import sys
from pathlib import Path

from pipeline_checks import check, check_scene_index, finish
from sigreport import read_ds

out = Path(sys.argv[1])
scene = check_scene_index(out, "6", 11)
names = {c["name"] for c in scene["checks"]}
check(any(n.startswith("adapted meshes no worse per dof") for n in names),
      "the report checks the adapted meshes per dof")
check(sum(n.startswith("adapted study: effectivity") for n in names) == 2,
      "the report checks the effectivities (max over t and at t = T)")
rows = list(csv.DictReader((out / "adapted" / "adapt.csv").open()))
dofs = [int(r["dofs"]) for r in rows]
check(len(rows) == 4 and all(a < b for a, b in zip(dofs, dofs[1:])),
      f"adapted/adapt.csv: 4 steps of growing dofs ({dofs})")


def contact_per_quarter(step):
    """The contact nodes of adapted/step<step> on each quarter of the rail."""
    import numpy as np
    from sigreport import Mesh
    folder = out / "adapted" / f"step{step}"
    x = Mesh.read(folder / "case.nopo").xy[:, 0]
    nodes = np.asarray(read_ds(folder / "case.cont", arrays=["node"])["node"]) - 1
    return np.histogram(x[nodes], bins=[0, 0.5, 1, 1.5, 2])[0]


first, last = contact_per_quarter(0), contact_per_quarter(3)
check(all(last >= 2 * first),
      f"the adapted meshes refine Gamma3 along the whole rail: contact nodes per quarter "
      f"{list(first)} at step 0, {list(last)} at step 3 (at least twice as many on each)")
for needed in ("Winkler strip at psi = 10 within 1 %", "Winkler strip at psi = 200 within 1 %"):
    check(needed in names, f"the report checks '{needed}'")
check(any(n.startswith("quasi-static limit") for n in names), "the report checks the quasi-static limit")
pvd = out / "figs" / "friction" / "rail.pvd"
check(pvd.is_file() and pvd.read_text().count("<DataSet") >= 50,
      "figs/friction/rail.pvd is a time series (every other step)")
vtu = out / "figs" / "friction" / "rail_0010.vtu"
text = vtu.read_text(errors="replace") if vtu.is_file() else ""
for field in ("velocity", "contact_pressure", "normal_status", "friction_status"):
    check(f'Name="{field}"' in text, f"{vtu.name} has the point data {field}")
hist = read_ds(out / "figs" / "friction" / "case.hist",
               arrays=["outer_iterations", "outer_converged", "total", "steps"])
check(len(hist["outer_iterations"]) == hist.scalar("steps") + 1 and
      min(hist["outer_iterations"][1:]) >= 1 and all(hist["outer_converged"][1:]),
      f"figs/friction: the loop ran and converged in every step (at most "
      f"{max(hist['outer_iterations'])} convex solves)")
finish("scene6_quick")
PYEOF
echo "scene6_quick: the quick scene and its report pass"
