#!/usr/bin/env bash
# Pipeline test, scene 4 (issue 11): drivers/scene4.sh --quick (the ball with compliance, wall and
# nonmonotone friction through the convexification loop; the square of Fig 4.7) and its report,
# then the requirements on the results:
#  - every check of the report passes (Fig 4.2's status pattern on every mesh, Fig 4.4's limits
#    equal to the Signorini and pure compliance solves, Fig 4.6's difference falling with rho,
#    Fig 4.7's rate 1 +- 0.15 on the square with rollers on Gamma1, ...), but Fig 4.7's rate with
#    Gamma1 clamped, which the corner singularity holds at 0.6-0.9 (the report says why);
#  - scene.json (PROTOCOL.md 6) names files that exist, with the Fig 4.5 table as its key table;
#  - the figure runs have a .pvd whose .vtu carries the statuses as point data;
#  - every run's summary.json records the loop (outer count, inner counts per convex solve).
# Run from the repository root with SIG_BIN set (ctest does both); exit 77 (skipped) when the
# executables, gmsh or matplotlib are missing.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
python=${PYTHON:-/usr/bin/python3}
for stage in mesh material contact assemble solve post error dump; do
  [ -x "$bin/sig-$stage" ] || { echo "scene4_quick: skipped, no $bin/sig-$stage"; exit 77; }
done
command -v gmsh >/dev/null || { echo "scene4_quick: skipped, no gmsh"; exit 77; }
"$python" -c 'import matplotlib, numpy' 2>/dev/null ||
  { echo "scene4_quick: skipped, no matplotlib/numpy"; exit 77; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
SIG_BIN=$bin "$root/drivers/scene4.sh" --quick -o "$work/scene4" >"$work/driver.log" 2>&1 ||
  { tail -40 "$work/driver.log"; echo "scene4_quick: drivers/scene4.sh --quick failed" >&2; exit 1; }

"$python" - "$work/scene4" <<'EOF'
import json, re, sys
from pathlib import Path

out = Path(sys.argv[1])
failures = []

def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)

scene = json.loads((out / "scene.json").read_text())
check(scene["scene"] == "4", "scene.json is scene 4")
for check_ in scene["checks"]:
    if "Gamma1 clamped" in check_["name"]:
        # The rate of the clamped square is the corner singularity's, below 1 (the report
        # explains it): measured, not a pass.
        rate = float(re.search(r"ours ([0-9.]+)", check_["detail"]).group(1))
        check(0.6 <= rate <= 0.9, f"Fig 4.7, Gamma1 clamped: rate {rate} in [0.6, 0.9], the "
              "corner singularity's")
        continue
    check(check_["pass"] is not False, f"report check: {check_['name']} ({check_['detail']})")
check(any("rollers" in c["name"] and c["pass"] is True for c in scene["checks"]),
      "Fig 4.7, Gamma1 on rollers: rate 1 +- 0.15")
check(sum(c["pass"] is True for c in scene["checks"]) >= 12, "at least 12 checks evaluated and passed")
for name in [scene["report"]] + list(scene["charts"].values()) + scene["pvd"]:
    check((out / name).is_file(), f"scene.json names {name}, which exists")
check("Fig 4.5" in scene["key_table"]["caption"] and len(scene["key_table"]["rows"]) == 2,
      "the key table is Fig 4.5's, alpha = 1 and 100")
vtu = out / "fig42" / "G" / "ball_0000.vtu"
text = vtu.read_text(errors="replace") if vtu.is_file() else ""
for field in ("normal_status", "friction_status", "contact_pressure"):
    check(f'Name="{field}"' in text, f"{vtu.name} has the point data {field}")
summary = json.loads((out / "fig42" / "G" / "summary.json").read_text())
loop = summary.get("convexification", {})
check(loop.get("converged") is True and loop.get("outer_iterations", 0) >= 2,
      f"fig42/G: the loop converged in {loop.get('outer_iterations')} outer iterations")
check(len(loop.get("inner_iterations", [])) == loop.get("outer_iterations") and
      sum(loop.get("inner_iterations", [])) == summary["iterations"],
      "fig42/G: one inner count per convex solve, summing to the iterations")
if failures:
    sys.exit(f"scene4_quick: {len(failures)} check(s) failed")
print("scene4_quick: all checks passed")
EOF
