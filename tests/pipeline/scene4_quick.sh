#!/usr/bin/env bash
# Pipeline test, scene 4 (issue 11): drivers/scene4.sh --quick (the ball with compliance, wall and
# nonmonotone friction through the convexification loop; the square of Fig 4.7) and its report,
# then the requirements on the results:
#  - every check of the report passes (Fig 4.2's status pattern on every mesh, Fig 4.4's limits
#    equal to the Signorini and pure compliance solves, Fig 4.6's difference falling with rho,
#    Fig 4.7's rate 1 +- 0.15 on the square with rollers on Gamma1, ...); Fig 4.7's uniform rate
#    with Gamma1 clamped is shown, not checked: the corner singularity holds it at 0.6-0.9;
#  - Fig 4.7 adapted (issue 29), 5 steps of drivers/adapt.sh from n = 8 against the overkill (the
#    last adapted mesh refined uniformly twice): the error falls with the dofs at slope
#    0.5 +- 0.075 over steps 2-4, the effectivity is in [0.3, 3] on every mesh, both estimates
#    of the references are below the errors they correct; the quick ladder's finest uniform mesh
#    (n = 64) is too coarse for the fifth of the dofs and half the time (the full driver checks
#    them), so those two checks may fail here;
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
import json, sys
from pathlib import Path

from pipeline_checks import check, check_scene_index, finish

out = Path(sys.argv[1])
# The quick ladder's finest uniform mesh is n = 64: the claims against it (a fifth of its dofs,
# half its time) need the full ladder.
against_finest = lambda c: "Fig 4.7 adapted" in c["name"] and (
    "a fifth" in c["name"] or "half" in c["name"])
scene = check_scene_index(out, "4", 13, allowed=against_finest)
adapted = json.loads((out / "fig47_adapted.json").read_text())
rate = adapted["uniform_rate_h"]
check(0.6 <= rate <= 0.9, f"Fig 4.7, Gamma1 clamped, uniform: rate {rate:.3f} in [0.6, 0.9], the "
      "corner singularity's (shown, not a report check)")
slope = adapted["adapted_slope"]
check(abs(slope - 0.5) <= 0.075, f"Fig 4.7 adapted: slope {slope:.3f} against dofs in 0.5 +- 0.075 "
      f"over steps {adapted['fit_steps']}")
check(len(adapted["steps"]) == 5 and all(0.3 <= e <= 3 for e in adapted["effectivity"]),
      f"Fig 4.7 adapted: 5 steps, effectivities {[round(e, 2) for e in adapted['effectivity']]} "
      "in [0.3, 3]")
errors = [s["error"] for s in adapted["steps"]]
check(all(a > b for a, b in zip(errors, errors[1:])) and
      adapted["overkill_estimate"] < errors[-1] and adapted["overkill1_error"] < errors[-1],
      f"Fig 4.7 adapted: errors {errors} fall, the overkill's own estimate "
      f"{adapted['overkill_estimate']:.3g} and the once-refined's distance "
      f"{adapted['overkill1_error']:.3g} below the last")
check(all(s["solve_s"] > 0 and s["estimate_s"] > 0 and s["wall_s"] > 0 for s in adapted["steps"])
      and all(s["refine_s"] > 0 for s in adapted["steps"][:-1]),
      "Fig 4.7 adapted: every step's stage times recorded")
check(any(c["name"].startswith("Fig 4.7 adapted") and "a fifth" in c["name"]
          for c in scene["checks"]), "Fig 4.7 adapted: the fifth of the dofs is a report check")
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
