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
#  - case.hist records per step the loop's counts, the loop converged in every step.
# Run from the repository root with SIG_BIN set (ctest does both); exit 77 (skipped) when
# matplotlib or numpy are missing.
set -euo pipefail

source "$(dirname "$0")/lib/common.sh"
require_python matplotlib numpy
quick_driver scene6

SIG_BIN=$bin PYTHONPATH=$root/postproc:$PYTHONPATH "$python" - "$work/scene6" <<'PYEOF'
import sys
from pathlib import Path

from pipeline_checks import check, check_scene_index, finish
from sigreport import read_ds

out = Path(sys.argv[1])
scene = check_scene_index(out, "6", 8)
names = {c["name"] for c in scene["checks"]}
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
