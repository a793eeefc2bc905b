#!/usr/bin/env bash
# Requirement (issue 14, scene 8b): the scene's driver and report on a small variant
# (drivers/scene8b.sh --quick with SIG_SCENE8B_SMALL=1: a 64 x 7 ring landing at (10, -10) m/s,
# 0.1 s of impact, IPM + EMM with mu1 and mu2, the specific penalty, two-step, EMM, Signorini):
# every run converges, the energy balance E + interface - friction work - wall work holds to 1e-8
# E0 at every step (Gonzalez's stress), the specific penalty does no wall work (3.53), IPM keeps
# the penetration <= g, friction and the wall only dissipate, mu2 dissipates more than mu1, and
# the report writes report.md, scene.json and the .pvd of the impact.
set -euo pipefail
export SIG_BIN=${SIG_BIN:?SIG_BIN is not set}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

SIG_SCENE8B_SMALL=1 drivers/scene8b.sh --quick -o "$work/out" >"$work/driver.log" 2>&1 ||
  { tail -n 30 "$work/driver.log"; echo "FAIL: drivers/scene8b.sh"; exit 1; }

/usr/bin/python3 - "$work/out" <<'PY'
import json, sys
from pathlib import Path
out = Path(sys.argv[1])
entry = json.loads((out / "scene.json").read_text())
checks = {c["name"]: c for c in entry["checks"]}
ok = True
def need(prefix):
    global ok
    found = [c for name, c in checks.items() if name.startswith(prefix)]
    if not found:
        print(f"FAIL: no check '{prefix}...'")
        ok = False
        return
    c = found[0]
    print(f"{'PASS' if c['pass'] else 'FAIL'}: {c['name']}: {c['detail']}")
    ok = ok and c["pass"] is True
need("every impact and friction run converges")
need("balance E + interface")
need("specific penalty conserves E + interface")
need("IPM keeps the penetration")
need("friction and the wall only dissipate")
# mu2 >= mu1 over (0, g): more friction work (the report's 1.5x is for the scene's 0.5 s).
import csv
runs = {r["run"]: r for r in csv.DictReader((out / "runs.csv").open())}
w1, w2 = float(runs["ipm-emm_mu1"]["friction_work"]), float(runs["ipm-emm_mu2"]["friction_work"])
print(f"{'PASS' if w2 < w1 < 0 else 'FAIL'}: friction work mu2 {w2:.4g} < mu1 {w1:.4g} < 0 J/m")
ok = ok and w2 < w1 < 0
for name in ("report.md", "fig8_6.png", "fig8_7.png", "fig8_8.png", "balance.png"):
    if not (out / name).is_file():
        print(f"FAIL: no {name}")
        ok = False
if not entry["pvd"]:
    print("FAIL: no .pvd in scene.json")
    ok = False
sys.exit(0 if ok else 1)
PY
echo "scene8b_small: the driver, the report and its checks on the small ring"
