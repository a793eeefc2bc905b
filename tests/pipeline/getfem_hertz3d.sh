#!/usr/bin/env bash
# Pipeline test, the GetFEM side of the 3D Hertz ball (issue 26, postproc/getfem_hertz3d.py) on the
# coarse mesh of meshes/half_ball.geo (h = 0.08, grading 0.2: 3672 dofs; R = 8, E = 150,
# nu = 0.3, P = 14, so Hertz's a = 0.799 = R / 10, p0 = 10.48), in a few seconds:
#  - frictionless, and Coulomb mu = 0.3 with the Cattaneo-Mindlin step Q = 2.1 = mu P / 2: every
#    Newton solve converges;
#  - against Hertz on this mesh: the contact radius (largest radius of a node in contact) within
#    15 % of a (measured -5.0 %: the radius of the last node in contact undershoots a by up to a
#    mesh size, 0.08 + 0.2 a = 0.24 = 30 % of a at worst), the axis node's pressure within 25 % of
#    p0 (measured +14 % frictionless, +10 % with friction: the nodal pressures of this mesh scatter
#    by +-10 % between neighbours), and the mean pressure within a / 2 (nodal forces over tributary
#    areas) within 8 % of Hertz's frictionless (measured +3.0 %; +1.2 % and +0.05 % on finer
#    meshes), 12 % with friction (measured +7.0 %: the stuck centre sharpens the pressure; +6.2 %
#    on the 29k-dof mesh, datafiles/scene3d/GETFEM.md);
#  - the solution is an equilibrium: the contact forces sum to (0, 0, P) (to (-Q, 0, P) in the
#    tangential step) to 1e-8 P; the top-face constraints that remove the rigid motions carry
#    nothing under the axisymmetric normal load (zero by symmetry: a moment below 1e-2 P R,
#    measured 5e-4 P R, the mesh's asymmetry), and in the tangential step their tilt rows carry
#    the moment Q R of the tangential load within 5 % (measured +0.5 %);
#  - Coulomb's cone holds at every node (|T| <= mu N + 1e-6 max N: Newton stops at max_res 1e-8,
#    not at an exact projection; measured 3e-11 here, 2e-8 at nu = 0.45), and after the tangential step
#    some nodes stick and some slip, the node on the axis sticks, the separating stick radius
#    (getfem_hertz3d.py) lies inside the contact zone, and the largest radius of a sticking node is
#    within two mesh sizes of Cattaneo-Mindlin's c (the issue's tolerance; measured +5.6 %, 0.04
#    against 2 h(c) = 0.41). Cattaneo-Mindlin's c is no sharper reference here: nu = 0.3 on a
#    rigid flat couples normal and tangential (the separating radius is 0.32, c = 0.63).
# Skips (exit 77) without gmsh or GetFEM (/usr/bin/python3 -c 'import getfem'). Needs no build.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
python=/usr/bin/python3 # Debian's interpreter: python3-getfem is built for it
require_command gmsh
require_python getfem numpy # Debian: python3-getfem

mesh=(--h 0.08 --grading 0.2)
"$python" "$root/postproc/getfem_hertz3d.py" "${mesh[@]}" --repeat 1 --json "$work/mu0.json" ||
  [ -s "$work/mu0.json" ] || die "getfem_hertz3d.py (frictionless) failed"
"$python" "$root/postproc/getfem_hertz3d.py" "${mesh[@]}" --mu 0.3 --tangential 2.1 --repeat 1 \
  --json "$work/mu03.json" || [ -s "$work/mu03.json" ] || die "getfem_hertz3d.py (mu 0.3, Q 2.1) failed"

"$python" - "$work" <<'EOF'
import json, math, sys
from pathlib import Path
import numpy as np
from pipeline_checks import check, finish

work = Path(sys.argv[1])
H, GRADING = 0.08, 0.2
for name in ("mu0", "mu03"):
    s = json.loads((work / f"{name}.json").read_text())
    P, mu, Q = s["P"], s["mu"], s["Q"]
    for step in s["steps"]:
        where = f"mu {mu:g}, {step['step']} step"
        h = step["hertz"]
        check(step["converged"], f"{where}: Newton converged ({step['newton_iterations']})")
        check(abs(h["a_rel_error"]) <= 0.15, f"{where}: contact radius {step['contact_radius']:.4f} "
              f"within 15 % of a = {h['a']:.4f} ({100 * h['a_rel_error']:+.1f} %)")
        check(abs(h["p_axis_rel_error"]) <= 0.25, f"{where}: axis pressure {step['p_axis']:.3f} "
              f"within 25 % of p0 = {h['p0']:.3f} ({100 * h['p_axis_rel_error']:+.1f} %)")
        bound = 0.08 if mu == 0 else 0.12
        check(abs(h["p_mean_centre_rel_error"]) <= bound, f"{where}: mean pressure within a/2 "
              f"{step['p_mean_centre']:.3f} within {100 * bound:g} % of Hertz's {h['p_mean_centre']:.3f} "
              f"({100 * h['p_mean_centre_rel_error']:+.1f} %)")
        nodes = step["nodes"]
        N = np.array([n["normal_force"] for n in nodes])
        T = np.array([n["tangential_force"] for n in nodes]).T
        load = np.array([-(Q or 0.0) if step["step"] == "tangential" else 0.0, 0.0, P])
        total = np.array([T[0].sum(), T[1].sum(), N.sum()])
        check(np.abs(total - load).max() <= 1e-8 * P,
              f"{where}: contact forces sum to {np.round(total, 10).tolist()} (load {load.tolist()})")
        # A reaction lambda of a top-face row is a traction lambda (mean rows), lambda x or lambda y
        # (tilts) or lambda (-y, x) (twist): its force or moment is at most |lambda| pi R^4 / 2.
        R = s["R"]
        reaction = dict(zip(s["constraints"], step["rigid_reactions"]))
        if step["step"] == "normal":
            worst = max(abs(r) for r in reaction.values()) * math.pi * R**4 / 2
            check(worst <= 1e-2 * P * R, f"{where}: top-face constraints carry a moment or force "
                  f"<= {worst:.3g}, at most 1e-2 P R = {1e-2 * P * R:.3g} (zero by symmetry)")
        else:
            moment = abs(reaction["tilt_x"]) * math.pi * R**4 / 4
            check(abs(moment - Q * R) <= 0.05 * Q * R, f"{where}: the tilt rows carry the moment "
                  f"{moment:.4g} of the tangential load, Q R = {Q * R:.4g} (within 5 %)")
        if mu > 0:
            excess = (np.linalg.norm(T, axis=0) - mu * N).max()
            check(excess <= 1e-6 * N.max(), f"{where}: max |T| - mu N = {excess:.2e}, at most 1e-6 max N (cone)")
        if step["step"] == "tangential":
            check(step["stick_nodes"] > 0 and step["slip_nodes"] > 0,
                  f"{where}: {step['stick_nodes']} nodes stick, {step['slip_nodes']} slip")
            axis = min(nodes, key=lambda n: np.hypot(n["x"], n["y"]))
            check(axis["status"] == "stick", f"{where}: the node on the axis sticks ({axis['status']})")
            check(0 < step["stick_radius_separating"] < step["contact_radius"],
                  f"{where}: the separating stick radius {step['stick_radius_separating']:.4f} lies inside "
                  f"the contact radius {step['contact_radius']:.4f}")
            c = h["c"]
            check(abs(step["stick_radius"] - c) <= 2 * (H + GRADING * c),
                  f"{where}: stick radius {step['stick_radius']:.4f} within two mesh sizes "
                  f"({2 * (H + GRADING * c):.3f}) of c = {c:.4f}")
finish("getfem_hertz3d")
print("getfem_hertz3d: all checks passed")
EOF
