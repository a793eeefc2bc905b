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

root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
python=${PYTHON:-/usr/bin/python3}
"$python" -c 'import matplotlib, numpy' 2>/dev/null ||
  { echo "scene6_quick: skipped, no matplotlib/numpy"; exit 77; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
SIG_BIN=$bin "$root/drivers/scene6.sh" --quick -o "$work/scene6" >"$work/driver.log" 2>&1 ||
  { tail -40 "$work/driver.log"; echo "scene6_quick: drivers/scene6.sh --quick failed" >&2; exit 1; }

SIG_BIN=$bin PYTHONPATH=$root/postproc "$python" - "$work/scene6" <<'PYEOF'
import json, sys
from pathlib import Path

from sigreport import read_ds

out = Path(sys.argv[1])
failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


scene = json.loads((out / "scene.json").read_text())
check(scene["scene"] == "6", "scene.json is scene 6")
for c in scene["checks"]:
    check(c["pass"] is not False, f"report check: {c['name']} ({c['detail']})")
check(sum(c["pass"] is True for c in scene["checks"]) >= 8, "at least 8 checks evaluated and passed")
names = {c["name"] for c in scene["checks"]}
for needed in ("Winkler strip at psi = 10 within 1 %", "Winkler strip at psi = 200 within 1 %"):
    check(needed in names, f"the report checks '{needed}'")
check(any(n.startswith("quasi-static limit") for n in names), "the report checks the quasi-static limit")
for name in [scene["report"]] + list(scene["charts"].values()) + scene["pvd"]:
    check((out / name).is_file(), f"scene.json names {name}, which exists")
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
sys.exit(1 if failures else 0)
PYEOF
echo "scene6_quick: the quick scene and its report pass"
