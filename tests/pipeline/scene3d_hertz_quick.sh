#!/usr/bin/env bash
# Requirement (issue 26, "Hertz ball"): drivers/scene3d_hertz.sh --quick runs the Hertz half ball
# (datafiles/scene3d/hertz_ball.dat) with PDAS, ALM, projection and penalty on two graded meshes
# and its report checks the results beside Hertz's: every run converges; on the (0.08, 0.2) mesh
# (3672 dofs) the contact radius within 15 % of a (measured -5.0 %: the last node in contact
# undershoots a by up to a mesh size), the axis node's pressure within 25 % of p0 (+14.2 %: one
# node's pressure scatters by +-10 % there) and the mean pressure within a/2 within 8 % (+3.1 %),
# the numbers of GetFEM's nodal brick on the same mesh (datafiles/scene3d/GETFEM.md); the contact
# forces sum to P = 14 to 1e-8; ALM and projection give PDAS's nodal forces to 1e-6 of the
# largest, penalty r = 1e6 to 1e-2. Here: the report exists, says no FAIL, its scene.json lists
# those checks as PASS, and the two a / p0 checks of the full run as not run.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_stages mesh material contact assemble solve post dump
require_command gmsh "the half ball is meshed by gmsh"
require_python numpy matplotlib

SIG_BIN=$bin "$root/drivers/scene3d_hertz.sh" --quick -o "$work/out" >"$work/driver.log" 2>&1 ||
  { tail -20 "$work/driver.log"; die "drivers/scene3d_hertz.sh --quick failed"; }
checks=$((checks + 1))
[ -s "$work/out/report.md" ] || fail "no report.md"

checks=$((checks + 1))
"$python" - "$work/out" <<'PY' || fail "the report's checks"
import json, sys
from pathlib import Path
from pipeline_checks import check, finish

out = Path(sys.argv[1])
scene = json.loads((out / "scene.json").read_text())
results = {c["name"]: c["pass"] for c in scene["checks"]}
for c in scene["checks"]:
    print(f"{c['pass']}: {c['name']}: {c['detail']}")
check(all(v is not False for v in results.values()), "no check of the report fails")
check(sum(v is True for v in results.values()) == 8, "eight checks pass")
check(sum(v is None for v in results.values()) == 2, "the full run's two checks are not run")
summary = json.loads((out / "summary.json").read_text())
runs = {(tuple(r["mesh"]), r["method"]): r for r in summary["runs"]}
coarse = runs[((0.08, 0.2), "pdas")]
check(coarse["dofs"] == 3672, f"the (0.08, 0.2) mesh has GetFEM's 3672 dofs ({coarse['dofs']})")
check(abs(coarse["p_axis"] - 11.965) < 0.02 * 11.965,
      f"its axis pressure {coarse['p_axis']:.3f} is GetFEM's 11.965 to 2 % (GETFEM.md)")
for name in ("speed_accuracy.png", "profile.png", "convergence.png"):
    check((out / name).is_file(), f"{name} written")
finish("scene3d_hertz_quick")
PY
finish "the Hertz ball's quick run and its checks"
