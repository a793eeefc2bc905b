#!/usr/bin/python3
"""The Hertz half ball (issue 26) solved by GetFEM 5.4: normal contact, with or without Coulomb
friction, and Cattaneo-Mindlin's tangential step; the GetFEM side of the 3D comparisons.

    /usr/bin/python3 postproc/getfem_hertz3d.py [--msh FILE | --h H --grading G] [--R R] [--E E]
        [--nu NU] [--P P | --pressure p] [--clamp-top [--top-shift DX] [--top-drop DZ]] [--cylinder RC]
        [--mu MU | --threshold S] [--tangential Q] [--eps EPS]
        [--version V] [--repeat K] [--json FILE] [--workdir DIR]

What is solved:
  - the body: the lower half of the ball of centre (0, 0, R) and radius R, its flat face on top at
    z = R, touching the plane z = 0 at the origin, meshed by gmsh from meshes/half_ball.geo
    (tetrahedra graded towards the origin: size h + grading * distance, capped at R / 4; --msh
    takes a mesh of that script instead, msh 2.2 with its physical groups 1 volume, 2 top face,
    3 curved face);
  - P1 isotropic linearized elasticity in 3D (E, nu; R = 8, E = 150, nu = 0.3 by default: scene
    7a's data), IM_TETRAHEDRON(2);
  - the load: a uniform pressure P / |top| on the top face (|top| the meshed face's area: total force P, default 14: Hertz's
    a / R = 0.0998); --pressure p: the pressure p instead, of total P = p |top|. The half ball is not a half-space: Hertz's formulas assume the load is
    applied at infinity of a half-space, here it is applied at height R = 10 a, so the measured
    a and p0 carry a finite-body error besides the mesh error (for the half disc of scene 7a the
    same effect is -0.74 % on p0, ../shared/PEERS.md);
  - contact: GetFEM's nodal contact with the rigid obstacle z >= 0 (signed distance 'z') on every
    node of the curved face, add_nodal_contact_with_rigid_obstacle_brick, augmentation r = E
    (GetFEM's advice), version 2 (symmetric Alart-Curnier except for the contact-friction
    coupling) by default; frictionless by default, Coulomb with --mu MU (the brick's lambda_t,
    two tangential nodal forces per node along GetFEM's tangents e_x, e_y);
  - Tresca with --threshold S (with --clamp-top): GetFEM 5.4's nodal and basic contact bricks
    take a friction coefficient only from Python (the C++ basic brick's Tresca version is not in
    the interface), so the Tresca case is built as postproc/getfem_friction.py builds it in 2D,
    from GetFEM's basic brick on an explicit model: the variable U = (u, z), z one extra unknown
    per contact node; the stiffness K and load F of the elastic model (assembled once by GetFEM,
    add_explicit_matrix / add_explicit_rhs); the clamp as constraints on U; a frictionless basic
    brick for the plane (BN = -e_z rows, gap = z, alpha = M_ii / l as the obstacle brick computes
    it); and a basic brick with Coulomb friction (coefficient 1) whose normal rows act on z alone
    (z_i <= 0) with the constant force c_i = S w_i pushing z_i on its bound, its tangential rows
    BT = e_x, e_y of the node's u: its normal multiplier is -c_i from the first iterate (started
    there), so the friction ball has radius c_i on every node, in contact or not (the classical
    Tresca model, as ours; w_i the node's tributary area, sig-contact's weight); the nodes of the
    clamped top's rim are left out (our decks' CONTACT exclude=2: a clamped node held to stick
    would repeat the clamp, and GetFEM's tangent is then singular);
  - rigid motions: the contact holds z and, with friction, x, y and the twist about z; what it
    does not hold is removed by weak constraints on the top face (add_constraint_with_multipliers,
    one row each, the integral over the top face Gamma_2):
      twist  int (x u_y - y u_x) = 0  and tilt  int x u_z = int y u_z = 0   (every run),
      mean translation  int u_x = int u_y = 0                               (frictionless only).
    Under the axisymmetric normal load their reactions vanish up to the mesh's asymmetry (the
    JSON lists them): they remove the kernel without over-constraining. Friction must carry the
    tangential load Q, so with friction the translations are left to it. The tilt rows carry the
    moment Q R of the tangential load about the contact (a weak clamp of the top face against
    rotation, as a test machine's crosshead): without them the moment would tilt the ball and
    shift the contact patch by Q R / P, more than a, which is not Cattaneo-Mindlin's problem;
    --clamp-top replaces these rows by u_x = u_y = 0 at every node of the top face (nodal
    Dirichlet rows through multipliers, exact), the holds of our decks' DIRICHLET ref=2 ux=0 uy=0:
    the tilts and the vertical translation are then held by the contact alone; with friction the
    clamp carries the tangential reaction, and --top-shift DX prescribes u_x = DX there instead
    (DIRICHLET ref=2 ux=DX uy=0); a shift alone rolls the ball about its contact (the tilts are
    free), so --top-drop DZ also prescribes u_z = -DZ there (DIRICHLET ref=2 ux=DX uy=0 uz=-DZ: the
    top clamped and moved, the load then a displacement; the pressure, on held dofs, goes into the
    reactions), the top dragged sideways and down so that the contact sticks at its centre and
    slips at its rim;
  - the start: the rigid shift u = (0, 0, -a_H^2 / (4 R)) (a_H Hertz's radius), which pushes the
    nodes within a_H / sqrt(2) of the axis into the plane: from u = 0 one node touches and the
    first tangent is singular (as in getfem_hertz.py);
  - Newton: GetFEM's md.solve with its default line search, max_res = eps (relative to the l1
    norm of the source terms, GetFEM's criterion), lsolver 'auto' (sequential MUMPS here);
  - --tangential Q (needs --mu): after the normal step, a second load step adds a uniform
    tangential traction (Q / |top|, 0, 0) on the top face (total Q < mu P), solved from the
    first step's solution. GetFEM's nodal friction is the static Coulomb law on the total
    tangential displacement (the brick has no previous-step displacement), so the second step is
    the static problem under the full load started from the first step, not an incremental slip
    law; nodes stuck in step 1 have zero tangential displacement, so where they stay stuck the
    two agree.

Measured: the contact radius (largest radial distance of a node with N > 1e-9 max N), the peak
pressure (the normal nodal force of the node on the axis divided by its tributary area: one third
of the area of each curved-face triangle around it, the integral of its P1 hat function on the
surface), the mean pressure within a / 2 of the axis (the sum of the nodal forces over the sum of
the tributary areas of the nodes there, beside Hertz's mean p0 (8 / 3) (1 - (3 / 4)^(3 / 2)): less
noisy than one node), the approach (-u_z at the top centre), per contact node its normal force N = -lambda_n
and tangential force vector (force of the plane on the body), and with --tangential the statuses
stick / slip (slip where |T| >= mu N - 1e-6 mu max N, among nodes in contact), the stick radius
beside c = a (1 - Q / (mu P))^(1/3) measured two ways: the largest radial distance of a sticking
node, and the separating radius (the radius with the fewest sticking nodes outside and slipping
nodes inside it; the statuses are mixed over a band of the coarse meshes, see separating_radius). Beside them
Hertz's values on a rigid plane: E* = E / (1 - nu^2), a = (3 P R / (4 E*))^(1/3),
p0 = 3 P / (2 pi a^2), approach a^2 / R, with relative errors. Cattaneo-Mindlin's c holds for
Dundurs' beta = 0; a rigid flat with nu != 0.5 has beta != 0 (normal-tangential coupling), so c
is a reference, not an exact solution of this problem.

One untimed solve first (GetFEM assembles its linear bricks once), then K timed solves from the
same start (each step); only md.solve is timed; the median of the K is reported. Prints a
summary; --json writes it with the nodal forces. Exit 1 when a Newton solve does not converge.
"""
import argparse
import math
import statistics
import sys
import tempfile
from pathlib import Path

import numpy as np

from hertz3d_report import hertz  # Hertz's a, p0 and approach, as our report takes them
from getfem_common import (explicit_model, getfem_version, gmsh_mesh, import_gmsh,
                           isotropic_elasticity, parse_timed_args, print_summary, timed_solves,
                           tributary_areas)

try:
    import getfem as gf
except ImportError:
    sys.exit("getfem_hertz3d.py: error: cannot import getfem (Debian: python3-getfem; use /usr/bin/python3)")

ROOT = Path(__file__).resolve().parent.parent
GEO = ROOT / "meshes" / "half_ball.geo"
VOLUME, TOP, CURVED = 1, 2, 3  # physical groups of half_ball.geo
CONTACT_TOL = 1e-9  # in contact when N > CONTACT_TOL max N
SLIP_TOL = 1e-6     # slipping when |T| >= mu N - SLIP_TOL mu max N


def fail(message):
    sys.exit(f"getfem_hertz3d.py: error: {message}")


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--msh", type=Path, help="a mesh of meshes/half_ball.geo (msh 2.2) instead of meshing")
    parser.add_argument("--h", type=float, default=0.08, help="mesh size at the origin (default 0.08)")
    parser.add_argument("--grading", type=float, default=0.2, help="mesh size growth with distance (default 0.2)")
    parser.add_argument("--R", type=float, default=8.0, help="radius (default 8)")
    parser.add_argument("--E", type=float, default=150.0, help="Young's modulus (default 150)")
    parser.add_argument("--nu", type=float, default=0.3, help="Poisson's ratio (default 0.3)")
    parser.add_argument("--P", type=float, default=14.0, help="total normal load (default 14)")
    parser.add_argument("--pressure", type=float, metavar="p",
                        help="the top face's pressure p instead of P / |top| (then P = p |top|)")
    parser.add_argument("--clamp-top", action="store_true",
                        help="u_x = u_y = 0 at the top face's nodes instead of the weak rigid-motion rows")
    parser.add_argument("--top-shift", type=float, default=0.0, metavar="DX",
                        help="with --clamp-top: u_x = DX at the top face's nodes (default 0)")
    parser.add_argument("--top-drop", type=float, metavar="DZ",
                        help="with --clamp-top: also u_z = -DZ at the top face's nodes")
    parser.add_argument("--cylinder", type=float, metavar="RC",
                        help="the obstacle is the rigid cylinder of radius RC and axis x through (0, 0, -RC), "
                             "touching z = 0 along the x axis, instead of the plane (frictionless only)")
    parser.add_argument("--mu", type=float, default=0.0, help="Coulomb coefficient (default 0: frictionless)")
    parser.add_argument("--threshold", type=float, metavar="S",
                        help="Tresca friction of bound S per unit area instead of Coulomb (needs --clamp-top)")
    parser.add_argument("--tangential", type=float, metavar="Q", help="second step: tangential load Q < mu P")
    parser.add_argument("--eps", type=float, default=1e-8, help="GetFEM's max_res (default 1e-8)")
    parser.add_argument("--version", type=int, default=2, choices=(1, 2), help="augmentation version (default 2)")
    parser.add_argument("--maxit", type=int, default=100, help="Newton iterations (default 100)")
    parser.add_argument("--repeat", type=int, default=3, help="timed solves (default 3)")
    parser.add_argument("--json", type=Path, help="write the summary here")
    parser.add_argument("--workdir", type=Path, help="folder for the gmsh mesh (default: temporary)")
    args = parse_timed_args(parser, fail)
    if args.mu < 0 or args.P <= 0 or args.R <= 0 or args.E <= 0 or not 0 <= args.nu < 0.5:
        fail("need mu >= 0, P > 0, R > 0, E > 0, 0 <= nu < 0.5")
    if args.pressure is not None and not args.pressure > 0:
        fail(f"--pressure p needs p > 0, got {args.pressure:g}")
    if (args.top_shift != 0 or args.top_drop is not None) and not args.clamp_top:
        fail("--top-shift and --top-drop need --clamp-top")
    if args.clamp_top and args.tangential is not None:
        fail("--tangential needs the weak rigid-motion rows, not --clamp-top (the clamp would carry Q)")
    if args.threshold is not None and (not args.threshold > 0 or args.mu != 0 or not args.clamp_top
                                       or args.tangential is not None or args.cylinder is not None):
        fail("--threshold S needs S > 0 and --clamp-top, without --mu, --tangential or --cylinder")
    if args.cylinder is not None and (args.cylinder <= 0 or args.mu != 0):
        fail("--cylinder RC needs RC > 0 and no friction")
    if args.tangential is not None and not 0 < args.tangential < args.mu * args.P:
        fail(f"--tangential Q needs 0 < Q < mu P = {args.mu * args.P:g} (set --mu)")
    return args


def load_mesh(args):
    """GetFEM's mesh of --msh, or of half_ball.geo meshed with --h, --grading, --R."""
    with tempfile.TemporaryDirectory() as tmp:
        workdir = args.workdir or Path(tmp)
        workdir.mkdir(parents=True, exist_ok=True)
        try:
            msh = args.msh or gmsh_mesh(GEO, workdir / f"half_ball_h{args.h:g}_g{args.grading:g}.msh",
                                        3, {"R": args.R, "h": args.h, "grading": args.grading})
            return import_gmsh(msh, (VOLUME, TOP, CURVED)), str(args.msh or f"half_ball.geo h {args.h:g} grading {args.grading:g}")
        except RuntimeError as e:
            fail(f"{e} (GetFEM 5.4 renumbers the regions of msh 4.1: mesh with -format msh22)")


def top_area(mim):
    """The area of the meshed top face: a polygon inscribed in the circle of radius R (pi R^2 less
    0.7 % with the 25 rim segments of the cap R / 4)."""
    return float(gf.asm_generic(mim, 0, "1", TOP))


def add_loads(md, mim, pressure):
    """The uniform pressure on the top face (data "pressure") and a tangential traction (data
    "shear", zero until the second step)."""
    md.add_initialized_data("pressure", [0.0, 0.0, -pressure])
    md.add_source_term_brick(mim, "u", "pressure", TOP)
    md.add_initialized_data("shear", [0.0, 0.0, 0.0])
    md.add_source_term_brick(mim, "u", "shear", TOP)


RIGID_ROWS = {"twist": "(X(1) * Test_u(2) - X(2) * Test_u(1))", "tilt_x": "X(1) * Test_u(3)",
              "tilt_y": "X(2) * Test_u(3)", "mean_x": "Test_u(1)", "mean_y": "Test_u(2)"}


def add_rigid_constraints(md, mim, mfu, names):
    """One weak constraint int_top row . u = 0 per name of RIGID_ROWS, through the multiplier
    variable "rigid" (its values are the reactions)."""
    nbdof = mfu.nbdof()
    B = gf.Spmat("empty", len(names), nbdof)
    for k, name in enumerate(names):
        row = np.asarray(gf.asm_generic(mim, 1, RIGID_ROWS[name], TOP, "u", 1, mfu, np.zeros(nbdof)))
        for j in np.nonzero(row)[0]:
            B[k, int(j)] = row[j]
    md.add_variable("rigid", len(names))
    md.add_constraint_with_multipliers("u", "rigid", B, np.zeros(len(names)))


def clamp_top(md, mfu, shift, drop, variable="u", size=None):
    """u_x = shift, u_y = 0 (and u_z = -drop unless drop is None) at every node of the top face:
    one row per dof of `variable` (of `size` unknowns, the field's dofs first; default the field
    u) through the multiplier variable "clamp" (its values are the nodal reactions). Returns the
    number of rows."""
    dofs = np.sort(mfu.basic_dof_on_region(TOP))
    value = (shift, 0.0, None if drop is None else -drop)  # x, y, z per node
    held = [(int(d), value[k % 3]) for k, d in enumerate(dofs) if value[k % 3] is not None]
    B = gf.Spmat("empty", len(held), size or mfu.nbdof())
    for row, (dof, _) in enumerate(held):
        B[row, dof] = 1.0
    md.add_variable("clamp", len(held))
    md.add_constraint_with_multipliers(variable, "clamp", B, np.array([v for _, v in held]))
    return len(held)


def contact_nodes(mfu, mim):
    """The curved face's nodes: their x dofs (the order of GetFEM's lambda_n), coordinates 3 x n and
    tributary areas."""
    xdofs = np.sort(mfu.basic_dof_on_region(CURVED))[0::3]
    xyz = mfu.basic_dof_nodes()[:, xdofs]
    where, weights = tributary_areas(mim, CURVED)
    if where.shape != xyz.shape or np.abs(where - xyz).max() > 1e-12:
        fail("the scalar P1 nodes of the curved face are not in the order of the vector field's")
    return xdofs, xyz, weights


def add_contact(md, mim, nbc, E, mu, version, cylinder=None):
    """GetFEM's nodal contact brick with the plane z >= 0 on the curved face (with Coulomb friction
    when mu > 0), or, frictionless, with the cylinder of radius `cylinder` under it, of axis x
    (its signed distance). Returns the names of its multipliers."""
    md.add_variable("lambda_n", nbc)
    md.add_initialized_data("r", [E])
    if mu == 0:
        obstacle = "z" if cylinder is None else \
            f"sqrt(y*y + (z + {cylinder!r})*(z + {cylinder!r})) - {cylinder!r}"
        md.add_nodal_contact_with_rigid_obstacle_brick(mim, "u", "lambda_n", "r", CURVED, obstacle, version)
        return ["lambda_n"]
    md.add_variable("lambda_t", 2 * nbc)
    md.add_initialized_data("friction_coeff", [mu])
    md.add_nodal_contact_with_rigid_obstacle_brick(mim, "u", "lambda_n", "lambda_t", "r", "friction_coeff",
                                                   CURVED, "z", version)
    return ["lambda_n", "lambda_t"]


def tresca_model(mfu, mim, pressure, args, nodes, start_shift):
    """The explicit model of the module docstring (Tresca): returns (md, names, start)."""
    base, _, _ = isotropic_elasticity(mim.linked_mesh(), args.E, args.nu, "IM_TETRAHEDRON(2)")
    add_loads(base, mim, pressure)
    base.assembly("build_all")  # K and F of the elastic model alone, at u = 0
    K, F = base.tangent_matrix(), np.asarray(base.rhs()).ravel()
    xdofs, xyz, weights = nodes
    nbdof, nbc = mfu.nbdof(), len(xdofs)
    size = nbdof + nbc
    md = explicit_model(K, size)
    held = clamp_top(md, mfu, args.top_shift, args.top_drop, "U", size)
    M = gf.asm_mass_matrix(mim, mfu, mfu, CURVED)
    pts = mim.linked_mesh().pts()
    alpha = np.array([M[int(i) + 2, int(i) + 2] for i in xdofs]) / np.max(np.max(pts, axis=1) - np.min(pts, axis=1))
    md.add_initialized_data("alpha", alpha)
    md.add_initialized_data("gap", xyz[2])
    md.add_initialized_data("r", [args.E])
    BN = gf.Spmat("empty", nbc, size)
    BT = gf.Spmat("empty", 2 * nbc, size)
    BZ = gf.Spmat("empty", nbc, size)
    for j, x in enumerate(int(i) for i in xdofs):
        BN[j, x + 2] = -1.0
        BT[2 * j, x], BT[2 * j + 1, x + 1] = 1.0, 1.0
        BZ[j, nbdof + j] = 1.0
    md.add_variable("lambda_n", nbc)
    md.add_basic_contact_brick("U", "lambda_n", "r", BN, "gap", "alpha", args.version)
    md.add_variable("lambda_z", nbc)
    md.add_variable("lambda_t", 2 * nbc)
    md.add_initialized_data("one", [1.0])
    md.add_initialized_data("zero", [0.0])
    md.add_basic_contact_brick("U", "lambda_z", "lambda_t", "r", BZ, BT, "one", "zero", "alpha",
                               args.version)
    bound = args.threshold * weights  # |T_i| <= S w_i
    md.add_explicit_rhs("U", np.concatenate([F, bound]))
    start = {"U": np.zeros(size), "clamp": np.zeros(held), "lambda_n": np.zeros(nbc),
             "lambda_z": -bound, "lambda_t": np.zeros(2 * nbc)}
    start["U"][2:nbdof:3] = start_shift
    return md, ["U", "clamp", "lambda_n", "lambda_z", "lambda_t"], start


def nodal_forces(md, nbc, frictional):
    """N (normal force pressing, >= 0) and the tangential force vectors T (3 x n) of the plane on
    the body: -lambda_n and lambda_t along GetFEM's tangents e_x, e_y (Gram-Schmidt on e1, e2
    against the normal e_z)."""
    N = -np.asarray(md.variable("lambda_n")).ravel() + 0.0
    T = np.zeros((3, nbc))
    if frictional:
        lt = np.asarray(md.variable("lambda_t")).ravel().reshape(nbc, 2)
        T[:2] = lt.T + 0.0
    return N, T


def state(md, names):
    return {name: np.array(md.variable(name)) for name in names}


def run_step(md, start, args, label):
    """Timed solves of one load step from `start`; fail unless all converge."""
    options = ["max_res", args.eps, "max_iter", args.maxit, "lsolver", "auto"]
    seconds, iterations, converged = timed_solves(md, start, options, args.repeat)
    converged = converged and all(i < args.maxit for i in iterations)
    return {"step": label, "newton_iterations": iterations, "converged": converged,
            "solve_seconds": seconds, "solve_seconds_median": statistics.median(seconds)}


def contact_measures(N, T, xyz, weights, mu, a_hertz, bound=None):
    """Contact radius, peak pressure (node on the axis), the mean pressure within a_hertz / 2,
    statuses and stick radius; with `bound` (Tresca's per node) the statuses by it."""
    r = np.hypot(xyz[0], xyz[1])
    centre = r < a_hertz / 2
    contact = N > CONTACT_TOL * N.max()
    axis = int(np.argmin(r + xyz[2]))
    m = {"contact_nodes": int(contact.sum()), "contact_radius": float(r[contact].max()),
         "first_free_radius": float(r[~contact & (r > r[contact].max())].min()),
         "axis_node_radius": float(r[axis]), "p_axis": float(N[axis] / weights[axis]),
         "p_max_nodal": float((N / weights).max()),
         "p_mean_centre": float(N[centre].sum() / weights[centre].sum()),
         "resultant": [float(T[0].sum()), float(T[1].sum()), float(N.sum())]}
    status = np.where(contact, "contact", "free").astype(object)
    if mu > 0 or bound is not None:
        limit = mu * N if bound is None else bound
        slipping = contact & (np.linalg.norm(T, axis=0) >= limit - SLIP_TOL * limit.max())
        status[contact & ~slipping] = "stick"
        status[slipping] = "slip"
        stick = status == "stick"
        m["stick_nodes"], m["slip_nodes"] = int(stick.sum()), int(slipping.sum())
        m["stick_radius"] = float(r[stick].max()) if stick.any() else 0.0
        m["stick_radius_separating"], m["misclassified"] = separating_radius(r[contact], stick[contact])
        m["inner_slip_radius"] = float(r[slipping].min()) if slipping.any() else None
    return m, status


def separating_radius(r, stick):
    """The radius c that best separates sticking nodes (inside) from slipping ones (outside): the
    fewest nodes on the wrong side (slip at r < c or stick at r >= c); c is midway between two
    consecutive radii, the smallest such. Returns (c, that number of nodes). The statuses of a
    nodal solution on an unstructured mesh are mixed near the boundary, where the largest radius
    of a sticking node follows one outlier."""
    order = np.argsort(r)
    rs, st = r[order], stick[order]
    # wrong[k]: c between rs[k-1] and rs[k]: slips among the first k, sticks among the rest.
    wrong = np.concatenate(([0], np.cumsum(~st))) + np.concatenate((np.cumsum(st[::-1])[::-1], [0]))
    k = int(np.argmin(wrong))
    edges = np.concatenate(([0.0], (rs[:-1] + rs[1:]) / 2, [rs[-1]]))
    return float(edges[k]), int(wrong[k])


def rel(ours, ref):
    return float((ours - ref) / ref)


def compare(m, H, P, Q, mu):
    """Hertz's (and Cattaneo-Mindlin's) values beside ours with relative errors."""
    out = {"a": H["a"], "a_rel_error": rel(m["contact_radius"], H["a"]),
           "p0": H["p0"], "p_axis_rel_error": rel(m["p_axis"], H["p0"]),
           "p_mean_centre": H["p_mean_centre"], "p_mean_centre_rel_error": rel(m["p_mean_centre"], H["p_mean_centre"]),
           "approach": H["approach"], "approach_rel_error": rel(m["approach"], H["approach"]),
           "E_star": H["E_star"]}
    if Q is not None:
        c = H["a"] * (1 - Q / (mu * P)) ** (1 / 3)
        out.update({"c": c, "stick_radius_rel_error": rel(m["stick_radius"], c),
                    "stick_radius_separating_rel_error": rel(m["stick_radius_separating"], c),
                    "c_with_measured_a": m["contact_radius"] * (1 - Q / (mu * P)) ** (1 / 3)})
    return out


def node_table(N, T, xyz, weights, status, m, u):
    """Per contact node: GetFEM point id, coordinates, tributary area, N, T, displacement (3 x n),
    status."""
    ids = np.atleast_1d(m.pid_from_coords(xyz, 1e-10)).astype(int)
    return [{"id": int(ids[i]), "x": float(xyz[0, i]), "y": float(xyz[1, i]), "z": float(xyz[2, i]),
             "area": float(weights[i]), "normal_force": float(N[i]),
             "tangential_force": [float(T[0, i]), float(T[1, i]), float(T[2, i])],
             "u": [float(u[0, i]), float(u[1, i]), float(u[2, i])],
             "status": str(status[i])} for i in range(len(N))]


def measure(md, mfu, mesh, nodes, args, H, Q):
    """Everything measured on the current solution of md."""
    xdofs, xyz, weights = nodes
    tresca = args.threshold is not None
    N, T = nodal_forces(md, len(xdofs), args.mu > 0 or tresca)
    bound = args.threshold * weights if tresca else None
    m, status = contact_measures(N, T, xyz, weights, args.mu, H["a"], bound)
    u = np.asarray(md.variable("U" if tresca else "u")).ravel()[:mfu.nbdof()]
    at_centre = np.nonzero(np.linalg.norm(mfu.basic_dof_nodes() - np.array([[0], [0], [args.R]]), axis=0)
                           < 1e-9 * args.R)[0]
    if len(at_centre) != 3:
        fail(f"found {len(at_centre)} dofs at the top centre (0, 0, {args.R:g}), expected 3")
    m["approach"] = float(-u[np.sort(at_centre)[2]])  # qdim 3: the third dof of a node is u_z
    m["rigid_reactions"] = ([] if args.clamp_top else
                            [float(v) for v in np.atleast_1d(md.variable("rigid"))])
    m["hertz"] = compare(m, H, args.P, Q, args.mu)
    m["nodes"] = node_table(N, T, xyz, weights, status, mesh,
                            np.stack([u[xdofs + k] for k in range(3)]))
    return m


def main():
    args = parse_args()
    H = hertz(args.P, args.R, args.E, args.nu)
    mesh, mesh_text = load_mesh(args)
    md, mfu, mim = isotropic_elasticity(mesh, args.E, args.nu, "IM_TETRAHEDRON(2)")
    if args.pressure is None:
        pressure = args.P / top_area(mim)  # the meshed area: the total is P
    else:
        pressure, args.P = args.pressure, args.pressure * top_area(mim)
        H = hertz(args.P, args.R, args.E, args.nu)
    add_loads(md, mim, pressure)
    if args.threshold is not None:
        # The curved face's nodes off the clamped top (our decks' CONTACT exclude=2): Tresca's
        # bound holds every node, and a clamped node held to stick would repeat the clamp.
        xdofs, xyz, weights = contact_nodes(mfu, mim)
        top = set(int(d) for d in np.asarray(mfu.basic_dof_on_region(TOP)).ravel())
        keep = np.array([int(d) not in top for d in xdofs])
        nodes = (xdofs[keep], xyz[:, keep], weights[keep])
        md, names, start = tresca_model(mfu, mim, pressure, args, nodes, -H["a"] ** 2 / (4 * args.R))
        rows = []
    elif args.clamp_top:
        rows = []
        clamp_top(md, mfu, args.top_shift, args.top_drop)
        holds = ["clamp"]
    else:
        rows = ["twist", "tilt_x", "tilt_y"] + (["mean_x", "mean_y"] if args.mu == 0 else [])
        add_rigid_constraints(md, mim, mfu, rows)
        holds = ["rigid"]
    if args.threshold is None:
        nodes = contact_nodes(mfu, mim)
        multipliers = add_contact(md, mim, len(nodes[0]), args.E, args.mu, args.version, args.cylinder)
        names = ["u"] + holds + multipliers
        start = {name: np.zeros_like(np.atleast_1d(md.variable(name)), dtype=float) for name in names}
        start["u"][2::3] = -H["a"] ** 2 / (4 * args.R)

    steps = [run_step(md, start, args, "normal")]
    results = [measure(md, mfu, mesh, nodes, args, H, None)]
    if args.tangential is not None:
        after_normal = state(md, names)
        md.set_variable("shear", [args.tangential / top_area(mim), 0.0, 0.0])
        steps.append(run_step(md, after_normal, args, "tangential"))
        results.append(measure(md, mfu, mesh, nodes, args, H, args.tangential))
    summary = {
        "getfem_version": getfem_version(),
        "description": (f"half ball R = {args.R:g} ({mesh_text}), P1 tetrahedra, E = {args.E:g}, "
                        f"nu = {args.nu:g}, pressure {pressure:.10g} on the top face, total P = {args.P:g}, "
                        f"nodal contact brick with "
                        + ("z >= 0" if args.cylinder is None else f"the cylinder of radius {args.cylinder:g} and axis x under z = 0")
                        + f" version {args.version}, r = E, mu = {args.mu:g}, "
                        + ("" if args.threshold is None else f"Tresca S = {args.threshold:g} (explicit model, basic bricks), ")
                        + f"max_res {args.eps:g}, lsolver auto, start u_z = -a^2/(4R), "
                        + (f"top face's nodes held at u_x = {args.top_shift:g}, u_y = 0"
                           + ("" if args.top_drop is None else f", u_z = {-args.top_drop:g}") if args.clamp_top
                           else f"top-face constraints {rows}")),
        "pressure": pressure, "clamp_top": args.clamp_top, "top_shift": args.top_shift, "top_drop": args.top_drop,
        "R": args.R, "E": args.E, "nu": args.nu, "P": args.P, "mu": args.mu, "threshold": args.threshold,
        "Q": args.tangential,
        "mesh": mesh_text, "dofs": int(mfu.nbdof()), "points": int(mesh.nbpts()),
        "tetrahedra": int(mesh.nbcvs()), "contact_candidates": len(nodes[0]),
        "constraints": rows, "converged": all(s["converged"] for s in steps),
        "newton_iterations": steps[0]["newton_iterations"],
        "solve_seconds": steps[0]["solve_seconds"],
        "solve_seconds_median": steps[0]["solve_seconds_median"],
        "steps": [dict(s, **r) for s, r in zip(steps, results)],
    }
    print_summary(summary, summary_line(summary), args.json)
    if not summary["converged"]:
        fail("a Newton solve did not converge: " +
             ", ".join(f"{s['step']} {s['newton_iterations']}" for s in steps))


def summary_line(s):
    lines = [f"GetFEM {s['getfem_version']}, {s['mesh']}: {s['dofs']} dofs, mu = {s['mu']:g}, {{solve}}"]
    for step in s["steps"]:
        h = step["hertz"]
        line = (f"  {step['step']}: Newton {step['newton_iterations']}, median {step['solve_seconds_median']:.3f} s, "
                f"{step['contact_nodes']} in contact, a = {step['contact_radius']:.4f} "
                f"({100 * h['a_rel_error']:+.1f} % vs {h['a']:.4f}), p_axis = {step['p_axis']:.3f} "
                f"({100 * h['p_axis_rel_error']:+.1f} % vs p0 {h['p0']:.3f}), mean p within a/2 {step['p_mean_centre']:.3f} "
                f"({100 * h['p_mean_centre_rel_error']:+.1f} %), approach {step['approach']:.5f} "
                f"({100 * h['approach_rel_error']:+.1f} %), resultant {', '.join(f'{v:.5g}' for v in step['resultant'])}")
        if "c" in h:
            line += (f"\n    stick {step['stick_nodes']} slip {step['slip_nodes']}, c = {h['c']:.4f}: largest stick "
                     f"radius {step['stick_radius']:.4f} ({100 * h['stick_radius_rel_error']:+.1f} %), separating "
                     f"radius {step['stick_radius_separating']:.4f} "
                     f"({100 * h['stick_radius_separating_rel_error']:+.1f} %, {step['misclassified']} nodes on the wrong side)")
        lines.append(line)
    return "\n".join(lines)


if __name__ == "__main__":
    main()
