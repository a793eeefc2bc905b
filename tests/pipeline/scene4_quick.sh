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

source "$(dirname "$0")/lib/common.sh"
require_stages mesh material contact assemble solve post error dump
require_command gmsh
require_python matplotlib numpy
quick_driver scene4

"$python" - "$work/scene4" <<'EOF'
import json, re, sys
from pathlib import Path

from pipeline_checks import check, check_scene_index, finish

out = Path(sys.argv[1])
clamped = lambda c: "Gamma1 clamped" in c["name"]
scene = check_scene_index(out, "4", 12, allowed=clamped)
for check_ in filter(clamped, scene["checks"]):
    # The rate of the clamped square is the corner singularity's, below 1 (the report explains
    # it): measured, not a pass.
    rate = float(re.search(r"ours ([0-9.]+)", check_["detail"]).group(1))
    check(0.6 <= rate <= 0.9, f"Fig 4.7, Gamma1 clamped: rate {rate} in [0.6, 0.9], the "
          "corner singularity's")
check(any("rollers" in c["name"] and c["pass"] is True for c in scene["checks"]),
      "Fig 4.7, Gamma1 on rollers: rate 1 +- 0.15")
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
finish("scene4_quick")
print("scene4_quick: all checks passed")
EOF
