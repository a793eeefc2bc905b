#!/usr/bin/env bash
# Requirement (issue 26, "Cattaneo-Mindlin"): datafiles/scene3d/cattaneo_mindlin.dat, the Hertz
# half ball (nu = 0.45) clamped at its top, pressed and sheared by (d_t, 0, -d_n) on a rigid flat
# with Coulomb friction mu = 0.3, on the coarse graded mesh (h, grading) = (0.08, 0.2) (3672
# dofs), one static PDAS solve; from contact.csv and the displacement:
#  - the contact forces sum to the load (P, Q) the clamp applies, its reaction computed apart
#    (the P1 internal forces K u summed over the top's nodes), to 1e-8 of P; Q / (mu P) in
#    [0.3, 0.7] (partial slip);
#  - every slip node has |T| = mu N to 1e-6, its force along its slip; every stick node has no
#    slip and |T| < mu N;
#  - the stick nodes form a disc about the pole: their centroid within one mesh size of the
#    pole, none beyond c_CM + 2 mesh sizes, the stick radius c (the radius that best separates
#    stick and slip nodes) within two mesh sizes of Cattaneo-Mindlin's a (1 - Q / (mu P))^(1/3)
#    with a the measured contact radius (mesh size h + grading x c_CM, meshes/half_ball.geo).
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_stages mesh material contact assemble solve post dump
require_command gmsh "the half ball is meshed by gmsh"
require_python numpy

deck=$work/cattaneo_mindlin.dat
sed 's/h=0.04 grading=0.1/h=0.08 grading=0.2/; s/vtk=yes/vtk=no/' \
  "$root/datafiles/scene3d/cattaneo_mindlin.dat" >"$deck"
grep -q "h=0.08 grading=0.2" "$deck" || die "the deck's MESH card is not h=0.04 grading=0.1"
SIG_BIN=$bin "$root/drivers/chain.sh" "$deck" -o "$work/run" >"$work/chain.log" 2>&1 ||
  { tail -20 "$work/chain.log"; die "drivers/chain.sh on cattaneo_mindlin.dat failed"; }

checks=$((checks + 1))
SIG_BIN=$bin PYTHONPATH=$root/postproc:$PYTHONPATH "$python" - "$work/run" <<'PY' || fail "the solution's checks"
import math, sys
from pathlib import Path
import numpy as np
from cattaneo3d_report import measure, mesh_size, top_reaction
from pipeline_checks import check, finish

run, mu, E, nu, mesh = Path(sys.argv[1]), 0.3, 150.0, 0.45, (0.08, 0.2)
m = measure(run / "contact.csv", mu)
check(m["converged"], "the solve converged")
reaction, f, top = top_reaction(run / "case.nopo", run / "case.b", E, nu)
flat = np.array([-m["Q_vector"][0], -m["Q_vector"][1], m["P"]])  # the flat's force on the ball
gap = np.linalg.norm(reaction + flat) / m["P"]
check(gap <= 1e-8, f"contact forces = the clamp's load (P, Q) = ({m['P']:.4f}, {m['Q']:.4f}): "
      f"{gap:.2g} of P")
check(abs(m["Q_vector"][1]) <= 1e-2 * m["Q"], f"Q along x1 (Q2 / Q = {m['Q_vector'][1] / m['Q']:.2g})")
check(0.3 <= m["ratio"] <= 0.7, f"Q / (mu P) = {m['ratio']:.3f} in [0.3, 0.7]")
check(m["cone_error"] <= 1e-6, f"|T| = mu N on the {m['slip_nodes']} slip nodes "
      f"(largest gap {m['cone_error']:.2g})")
check(m["stick_cone_max"] < 1, f"|T| < mu N on the {m['stick_nodes']} stick nodes "
      f"(largest {m['stick_cone_max']:.4f} mu N)")

import csv
rows = {int(r["node"]): r for r in csv.DictReader(open(run / "contact.csv"))}
worst_dir, worst_stuck = 0.0, 0.0
for r in rows.values():
    s = np.array([float(r[f"slip_{k}"]) for k in (1, 2, 3)])
    t = np.array([float(r[f"tangential_force_{k}"]) for k in (1, 2, 3)])
    if r["status"] == "contact" and r["friction_status"] == "S+":
        worst_dir = max(worst_dir, 1 - t @ s / (np.linalg.norm(t) * np.linalg.norm(s)))
    elif r["status"] == "contact":
        worst_stuck = max(worst_stuck, np.linalg.norm(s))
check(worst_dir <= 1e-9, f"each slip node's force along its slip (1 - cos: {worst_dir:.2g})")
check(worst_stuck <= 1e-12, f"no stick node slips (largest slip {worst_stuck:.2g} m)")

size = mesh_size(mesh, m["c_cm"])
centre = math.hypot(*m["stick_centre"])
check(centre <= size, f"the stick nodes' centroid {centre:.4f} from the pole, within a mesh "
      f"size {size:.3f}")
check(m["c_stick_max"] <= m["c_cm"] + 2 * size,
      f"no stick node beyond c_CM + 2 mesh sizes (the last at {m['c_stick_max']:.4f})")
check(abs(m["c"] - m["c_cm"]) <= 2 * size,
      f"stick radius {m['c']:.4f} within 2 mesh sizes ({2 * size:.3f}) of Cattaneo-Mindlin's "
      f"{m['c_cm']:.4f} (a = {m['a']:.4f}, Q / (mu P) = {m['ratio']:.3f})")
print(f"P {m['P']:.6f} Q {m['Q']:.6f} a {m['a']:.4f} c {m['c']:.4f} [{m['c_slip_min']:.4f}, "
      f"{m['c_stick_max']:.4f}] c_CM {m['c_cm']:.4f}; {m['stick_nodes']} stick, "
      f"{m['slip_nodes']} slip of {m['contact_nodes']} in contact")
finish("cattaneo_mindlin_quick")
PY
finish "Cattaneo-Mindlin on the Hertz half ball (coarse mesh)"
