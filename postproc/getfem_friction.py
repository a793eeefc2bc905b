#!/usr/bin/python3
"""Static frictional contact of the half disc solved by GetFEM 5.4, the peer of
tests/pipeline/friction_getfem.sh (and a benchmark peer like getfem_hertz.py).

    /usr/bin/python3 postproc/getfem_friction.py [--deck DATAFILE] [--n N] [--grading G]
        [--law coulomb|tresca] [--mu MU] [--threshold S] [--eps EPS] [--version V]
        [--brick obstacle|basic] [--repeat K] [--json FILE] [--workdir DIR] [--nopo case.nopo]

The problem (fields read from the deck when given: MESH R N grading, MATERIAL E nu, TRACTION f,
CONTACT point normal, FRICTION law mu threshold, SOLVER eps, INITIAL u; the defaults are the issue's
deck): the half disc x1^2 + (x2 - R)^2 <= R^2, x2 <= R meshed by gmsh from meshes/half_disc.geo (the
script sig-mesh's half-disc generator runs: N uniform segments on the arc Gamma3, the same grading,
then the arc nodes moved to their exact polar positions as sig-mesh does; --nopo checks that GetFEM
has sig-mesh's nodes to 1e-12), P1 plane strain (GetFEM's 2D isotropic linearized
elasticity with the 3D Lame coefficients), traction f on the top edge, NO Dirichlet condition, and
contact with friction on Gamma3 against the rigid half plane behind `point` with outward `normal`
(default x2 <= 0). The body is held by contact and friction alone, so the first tangent is
singular from u = 0; every solve starts from the deck's INITIAL u (default the rigid shift
u = (0, -h^2/R), h = pi R / N, as in getfem_hertz.py and ../shared/PEERS.md).

GetFEM's nodal contact with friction (getfem_contact_and_friction_nodal.cc):
  - coulomb, --brick obstacle (default): add_nodal_contact_with_rigid_obstacle_brick(mim, 'u',
    'lambda_n', 'lambda_t', 'r', 'friction_coeff', GAMMA3, signed distance, version). GetFEM
    builds BN (rows -n at the node's dofs), BT (the tangent of Gram-Schmidt on e1, here +-(n2, -n1)),
    the gap (the signed distance at the node) and alpha_i = M_ii / l (M the boundary mass matrix, l
    the largest side of the bounding box), and solves Alart-Curnier's equations in the nodal forces
    lambda_n, lambda_t: lambda_n = min(0, lambda_n - r alpha (BN u - gap)), lambda_t = projection of
    lambda_t - r alpha BT u on the ball of radius -mu lambda_n;
  - coulomb, --brick basic: the same problem through add_basic_contact_brick with BN, BT, gap and
    alpha built here as the obstacle brick builds them (a check of that construction);
  - tresca: GetFEM's Coulomb_friction_brick has a Tresca version (radius = threshold on every node
    whatever its normal state: the classical Tresca model, as ours), but GetFEM 5.4 reaches it only
    from C++ (add_basic_contact_brick(..., Tresca_version, dataname_threshold, ...)); neither the
    rigid-obstacle brick nor the Python interface of the basic brick takes a threshold. So the
    Tresca case is built from GetFEM's basic brick on an explicit model: the variable U = (u, z),
    z one extra unknown per contact node, the stiffness K and load F of the elastic model above
    (assembled once by GetFEM, add_explicit_matrix / add_explicit_rhs), a frictionless basic brick
    for Signorini (BN, gap, alpha as above), and a basic brick with Coulomb friction whose normal
    rows act on z alone (z_i <= 0, friction coefficient 1) with the constant force c_i = threshold
    x w_i pushing z_i on its bound: its normal multiplier is -c_i from the first iterate (started
    there), so the friction ball has radius c_i on every node: the Tresca bound on the nodal force,
    w_i the nodal weight of sig-contact (half the chords to the neighbours along the arc).
Augmentation r = E (GetFEM's advice; --r), augmentation version 2 (symmetric Alart-Curnier except
for the contact-friction coupling) by default; --version 1 (unsymmetric) reaches the same solution;
version 3 diverges on this problem (Coulomb, N = 64: |u| ~ 1e13).

Conversion to our nodal forces (contact.csv): GetFEM's multipliers are nodal forces (no weight),
the force of the foundation on the body is BN^T lambda_n + BT^T lambda_t = -lambda_n n + lambda_t ut,
ours is N n - T t with t = (n2, -n1), so N = -lambda_n and T = -(ut . t) lambda_t; slip = t . u.
GetFEM's statuses are derived from its solution: in contact (CU) when N > 1e-9 max N, else free;
friction (Coulomb: contact nodes only, else '-'; Tresca: every node) S= when |slip| <= 1e-9 R, else
S+ / S- by the sign of the slip.

Newton stops at max_res = eps relative to the external load (GetFEM's criterion, as
getfem_hertz.py: GetFEM divides the l1 norm of its residual by the l1 norm of the source terms; on
the explicit model of the basic bricks, where it does not, max_res is eps times that norm), linear
solver 'auto' (sequential MUMPS here). At N = 512 (97k dofs, uniform) the Coulomb residual stalls
near 1e-10 of the load, so eps = 1e-10 there makes GetFEM's Newton counts erratic (10, 72, 8 and 9,
21, 10 in two runs of three solves from the same start; 7, 7, 7 at eps = 1e-8): time with --eps
1e-8. One untimed solve first (GetFEM assembles its linear bricks once and keeps them), then K
timed solves of md.solve, each from the same start; only md.solve is timed. Prints a summary;
--json writes it with the nodal forces and statuses in boundary order (increasing x1, the order of
sig-contact's case.cont).
"""
import argparse
import math
import statistics
import sys
import tempfile
from pathlib import Path

import numpy as np

from getfem_common import (deck_cards, explicit_model, getfem_version, import_half_disc,
                           nopo_coordinates, parse_timed_args, plane_strain_elasticity,
                           print_summary, snap_arc, timed_solves, tributary_lengths)

try:
    import getfem as gf
except ImportError:
    sys.exit("getfem_friction.py: error: cannot import getfem (Debian: python3-getfem; use /usr/bin/python3)")

ROOT = Path(__file__).resolve().parent.parent
GEO = ROOT / "meshes" / "half_disc.geo"
TOP, GAMMA3 = 2, 3  # physical curves of half_disc.geo: top edge, lower half circle
# The deck (tests/pipeline/friction_getfem.sh writes it).
DEFAULTS = {"R": 8.0, "N": 64, "grading": 0.1, "E": 150.0, "nu": 0.3, "f": (0.4, -2.0),
            "point": (0.0, 0.0), "normal": (0.0, 1.0), "law": "coulomb", "mu": 0.4,
            "threshold": 1.0, "eps": 1e-10, "start": None}
FORCE_TOL, SLIP_TOL = 1e-9, 1e-9  # status tolerances: x max N, x R


def fail(message):
    sys.exit(f"getfem_friction.py: error: {message}")


def pair(text):
    values = tuple(float(v) for v in text.split(","))
    if len(values) != 2:
        raise ValueError(f"'{text}' is not a pair x,y")
    return values


def read_deck(path):
    """The fields of DEFAULTS a deck gives (MESH half-disc, MATERIAL hooke plane strain, TRACTION
    ref=2, CONTACT plane signorini, FRICTION, SOLVER eps, INITIAL u)."""
    d = dict(DEFAULTS)
    if path is None:
        return d
    cards = deck_cards(path)
    try:
        mesh, material = cards["MESH"], cards["MATERIAL"]
        if mesh.get("generator") != "half-disc":
            fail(f"{path}: needs MESH generator=half-disc")
        if material.get("plane", "strain") != "strain":
            fail(f"{path}: this comparison is plane strain, the deck says plane={material['plane']}")
        contact = cards["CONTACT"]
        if contact.get("obstacle", "plane") != "plane" or contact.get("law", "signorini") != "signorini" \
                or float(contact.get("gap", 0)) != 0:
            fail(f"{path}: needs CONTACT obstacle=plane law=signorini without gap=")
        if cards["TRACTION"].get("ref") != str(TOP) or contact.get("ref") != str(GAMMA3):
            fail(f"{path}: needs TRACTION ref={TOP} and CONTACT ref={GAMMA3}")
        d.update(R=float(mesh["r"]), N=int(mesh["n"]), grading=float(mesh.get("grading", 0)),
                 E=float(material["e"]), nu=float(material["nu"]), f=pair(cards["TRACTION"]["f"]),
                 point=pair(contact.get("point", "0,0")), normal=pair(contact["normal"]))
        friction = cards.get("FRICTION", {})
        if friction:
            d["law"] = friction.get("law", "coulomb")
            d["mu"] = float(friction.get("mu", d["mu"]))
            d["threshold"] = float(friction.get("threshold", d["threshold"]))
        d["eps"] = float(cards.get("SOLVER", {}).get("eps", d["eps"]))
        if "u" in cards.get("INITIAL", {}):
            d["start"] = pair(cards["INITIAL"]["u"])
    except (KeyError, ValueError) as e:
        fail(f"{path}: cannot read the MESH, MATERIAL, TRACTION, CONTACT, FRICTION cards ({e})")
    return d


def getfem_tangent(un):
    """The tangent GetFEM's rigid-obstacle brick takes for the unit normal un (2D): Gram-Schmidt
    on e1, or on e2 when e1 is within 1e-3 of un (orthonormal_basis_to_unit_vec)."""
    for e in (np.array([1.0, 0.0]), np.array([0.0, 1.0])):
        v = e - (e @ un) * un
        if np.linalg.norm(v) >= 1e-3:
            return v / np.linalg.norm(v)
    raise AssertionError("no tangent")


def signed_distance(point, n):
    """The obstacle as GetFEM's muparser expression in x, y: n . (x - point)."""
    terms = []
    for c, var, p in ((n[0], "x", point[0]), (n[1], "y", point[1])):
        if c != 0:
            arg = var if p == 0 else f"({var} - ({p!r}))"
            terms.append(arg if c == 1 else f"{c!r} * {arg}")
    return " + ".join(terms)


def check_mesh(m, nopo):
    """GetFEM's mesh has sig-mesh's nodes: same count, each node within 1e-12 of one of ours."""
    from scipy.spatial import cKDTree

    ours = nopo_coordinates(nopo)
    theirs = np.asarray(m.pts()).T
    if len(ours) != len(theirs):
        fail(f"GetFEM's mesh has {len(theirs)} nodes, {nopo} has {len(ours)}")
    dist, index = cKDTree(ours).query(theirs)
    if len(set(index.tolist())) != len(ours) or dist.max() > 1e-12:
        fail(f"GetFEM's nodes are not {nopo}'s: max distance {dist.max():.3g}")
    return {"nopo": str(nopo), "nodes": len(ours), "max_distance": float(dist.max())}


class Problem:
    """The GetFEM model of the frictional half disc and what the comparison reads off it."""


def build_problem(d, r=None, version=2, brick="obstacle", workdir=None, nopo=None, start=None):
    """GetFEM's model of the deck's problem d (read_deck) with augmentation r (default E),
    augmentation `version` and `brick` (obstacle | basic); its unknowns start at `start`, a
    uniform displacement (default: the deck's INITIAL u, else the rigid shift (0, -h^2/R)).
    Returns a Problem: md, unknowns (name -> start values), displacement() and the
    multipliers read as our nodal forces (forces()), the contact nodes' geometry (X, xdof, ydof,
    order, weights, n, t, gap), the elastic K and F, and max_res for a relative eps."""
    R, E, nu, N, law = d["R"], d["E"], d["nu"], d["N"], d["law"]
    h = math.pi * R / N
    start_shift = start if start is not None else (d["start"] or (0.0, -h * h / R))
    r = r if r is not None else E
    basic = law == "tresca" or brick == "basic"

    # 1. The mesh: gmsh on half_disc.geo, imported by GetFEM.
    with tempfile.TemporaryDirectory() as tmp:
        workdir = workdir or Path(tmp)
        workdir.mkdir(parents=True, exist_ok=True)
        try:
            m, msh = import_half_disc(GEO, workdir, R, N, d["grading"], (TOP, GAMMA3))
        except RuntimeError as e:
            fail(str(e))
    # sig-mesh puts the arc nodes at their exact polar positions; so do we.
    points = np.array(m.pts())
    arc = [int(i) for i in np.atleast_1d(m.pid_in_regions([GAMMA3]))]
    try:
        snap_arc(points, arc, (0.0, R), R, -math.pi, N, math.pi / N)
    except ValueError as e:
        fail(f"{msh.name}: {e}")
    m.set_pts(points)
    mesh_check = check_mesh(m, nopo) if nopo else None

    # 2. P1 plane-strain elasticity with the traction on the top edge.
    elastic, mfu, mim = plane_strain_elasticity(m, E, nu, d["f"], TOP)
    nbdof = mfu.nbdof()
    elastic.assembly("build_all")  # K and F of the elastic model alone, at u = 0
    K, F = elastic.tangent_matrix(), np.asarray(elastic.rhs()).ravel()

    # 3. The contact nodes (dof order, as GetFEM's multipliers), their geometry and weights.
    dofs = np.sort(np.asarray(mfu.basic_dof_on_region(GAMMA3)).ravel())
    xdof, ydof = dofs[0::2], dofs[1::2]
    nbc = len(xdof)
    if nbc != N + 1 or not np.all(ydof == xdof + 1):
        fail(f"{nbc} contact nodes on Gamma3 (N + 1 = {N + 1} expected) or dofs not paired per node")
    X = np.asarray(mfu.basic_dof_nodes())[:, xdof]
    order = np.argsort(X[0])  # boundary order of case.cont: x1 increases along the lower arc
    weights = np.empty(nbc)
    weights[order] = tributary_lengths(X[:, order])
    n = np.array(d["normal"]) / np.linalg.norm(d["normal"])
    t = np.array([n[1], -n[0]])
    gap = n @ (X - np.array(d["point"])[:, None])

    start = np.zeros(nbdof)
    start[0::2], start[1::2] = start_shift
    md = elastic
    if basic:
        # Explicit model U = (u, z): K and F of the elastic model.
        extra = nbc if law == "tresca" else 0
        size = nbdof + extra
        md = explicit_model(K, size)
        force = np.zeros(size)
        force[:nbdof] = F
        # alpha_i = M_ii / l as the rigid-obstacle brick computes it (homogenizes r only).
        M = gf.asm_mass_matrix(mim, mfu, mfu, GAMMA3)
        pmin, pmax = np.min(m.pts(), axis=1), np.max(m.pts(), axis=1)
        alpha = np.array([M[int(i), int(i)] for i in xdof]) / np.max(pmax - pmin)
        md.add_initialized_data("alpha", alpha)
        md.add_initialized_data("gap", gap)
        md.add_initialized_data("r", [r])
        BN = gf.Spmat("empty", nbc, size)
        BT = gf.Spmat("empty", nbc, size)
        for j in range(nbc):
            BN[j, int(xdof[j])], BN[j, int(ydof[j])] = -n[0], -n[1]
            BT[j, int(xdof[j])], BT[j, int(ydof[j])] = t[0], t[1]
        md.add_variable("lambda_n", nbc)
        md.add_variable("lambda_t", nbc)
        if law == "coulomb":
            md.add_initialized_data("friction_coeff", [d["mu"]])
            md.add_basic_contact_brick("U", "lambda_n", "lambda_t", "r", BN, BT, "friction_coeff",
                                       "gap", "alpha", version)
        else:
            bound = d["threshold"] * weights  # Tresca: |T_i| <= threshold w_i
            md.add_basic_contact_brick("U", "lambda_n", "r", BN, "gap", "alpha", version)
            BZ = gf.Spmat("empty", nbc, size)
            for j in range(nbc):
                BZ[j, nbdof + j] = 1.0
            force[nbdof:] = bound
            md.add_variable("lambda_z", nbc)
            md.add_initialized_data("one", [1.0])
            md.add_initialized_data("zero", [0.0])
            md.add_basic_contact_brick("U", "lambda_z", "lambda_t", "r", BZ, BT, "one", "zero",
                                       "alpha", version)
        md.add_explicit_rhs("U", force)
        tangent_sign = 1.0  # BT rows are t
        u_start = np.concatenate([start, np.zeros(extra)])
        displacement = lambda: np.asarray(md.variable("U")).ravel()[:nbdof]
        unknowns = {"U": u_start, "lambda_n": np.zeros(nbc), "lambda_t": np.zeros(nbc)}
        if law == "tresca":
            unknowns["lambda_z"] = -bound
    else:
        md.add_variable("lambda_n", nbc)
        md.add_variable("lambda_t", nbc)
        md.add_initialized_data("r", [r])
        md.add_initialized_data("friction_coeff", [d["mu"]])
        md.add_nodal_contact_with_rigid_obstacle_brick(mim, "u", "lambda_n", "lambda_t", "r", "friction_coeff",
                                                       GAMMA3, signed_distance(d["point"], n), version)
        tangent_sign = float(getfem_tangent(-n) @ t)
        displacement = lambda: np.asarray(md.variable("u")).ravel()
        unknowns = {"u": start, "lambda_n": np.zeros(nbc), "lambda_t": np.zeros(nbc)}

    p = Problem()
    p.__dict__.update(md=md, unknowns=unknowns, displacement=displacement, mfu=mfu, m=m, N=N,
                      R=R, E=E, r=r, law=law, basic=basic, X=X, xdof=xdof, ydof=ydof, nbc=nbc,
                      order=order, weights=weights, n=n, t=t, gap=gap, start_shift=start_shift,
                      tangent_sign=tangent_sign, nbdof=nbdof, mesh_check=mesh_check,
                      elastic=elastic)
    p.K, p.F = K, F

    def forces():
        """Our nodal forces (N, T) of GetFEM's multipliers, in GetFEM's contact-node order."""
        ln = np.asarray(md.variable("lambda_n")).ravel()
        lt = np.asarray(md.variable("lambda_t")).ravel()
        return -ln + 0.0, -tangent_sign * lt + 0.0
    p.forces = forces
    # GetFEM divides its residual by an approximation of the external load, the l1 norm of the
    # source terms (max_res is then relative), but counts no explicit rhs: on the explicit model
    # the residual is absolute, so max_res is scaled by the l1 norm of the same traction load.
    p.max_res_scale = float(np.abs(p.F).sum()) if basic else 1.0
    return p


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--deck", type=Path, help="datafile giving the problem (default: the issue's deck)")
    parser.add_argument("--n", type=int, help="segments on the arc (default: the deck's, 64)")
    parser.add_argument("--grading", type=float, help="mesh size growth away from the arc (default: the deck's)")
    parser.add_argument("--law", choices=("coulomb", "tresca"), help="friction law (default: the deck's)")
    parser.add_argument("--mu", type=float, help="Coulomb friction coefficient (default: the deck's)")
    parser.add_argument("--threshold", type=float, help="Tresca bound on |tangential pressure| (default: the deck's)")
    parser.add_argument("--eps", type=float, help="GetFEM's max_res, relative to the load (default: the deck's eps)")
    parser.add_argument("--r", type=float, help="augmentation parameter (default E)")
    parser.add_argument("--version", type=int, default=2, choices=(1, 2, 3),
                        help="augmentation version of the brick (default 2)")
    parser.add_argument("--brick", choices=("obstacle", "basic"), default="obstacle",
                        help="Coulomb through the rigid-obstacle brick (default) or the basic brick")
    parser.add_argument("--maxit", type=int, default=100, help="Newton iterations (default 100)")
    parser.add_argument("--repeat", type=int, default=3, help="timed solves (default 3)")
    parser.add_argument("--json", type=Path, help="write the summary here")
    parser.add_argument("--workdir", type=Path, help="folder for the gmsh mesh (default: temporary)")
    parser.add_argument("--nopo", type=Path, help="sig-mesh's case.nopo: check GetFEM has its nodes")
    parser.add_argument("--noisy", action="store_true", help="print GetFEM's Newton iterations")
    args = parse_timed_args(parser, fail)
    d = read_deck(args.deck)
    for key in ("law", "mu", "threshold", "eps", "grading"):
        if getattr(args, key) is not None:
            d[key] = getattr(args, key)
    if args.n is not None:
        d["N"] = args.n
    if d["N"] < 4 or d["N"] % 2:
        fail(f"N must be even and >= 4, got {d['N']}")
    if d["law"] not in ("coulomb", "tresca"):
        fail(f"FRICTION law={d['law']}: coulomb or tresca")
    R, N, law = d["R"], d["N"], d["law"]
    p = build_problem(d, args.r, args.version, args.brick, args.workdir, args.nopo)
    md, unknowns, displacement, r = p.md, p.unknowns, p.displacement, p.r
    basic, X, xdof, ydof, order, weights = p.basic, p.X, p.xdof, p.ydof, p.order, p.weights
    n, t, gap, start_shift, tangent_sign = p.n, p.t, p.gap, p.start_shift, p.tangent_sign
    nbdof, nbc, mesh_check = p.nbdof, p.nbc, p.mesh_check
    max_res = d["eps"] * p.max_res_scale
    options = ["max_res", max_res, "max_iter", args.maxit, "lsolver", "auto"] + (["noisy"] if args.noisy else [])

    times, iterations, converged = timed_solves(md, unknowns, options, args.repeat)
    converged = converged and all(i < args.maxit for i in iterations)

    # 4. Our nodal forces, slips and statuses, in boundary order.
    u = displacement()
    ln = np.asarray(md.variable("lambda_n")).ravel()
    lt = np.asarray(md.variable("lambda_t")).ravel()
    normal_force = -ln + 0.0  # + 0.0: no negative zeros in the output
    tangential_force = -tangent_sign * lt + 0.0
    u1, u2 = u[xdof], u[ydof]
    slip = t[0] * u1 + t[1] * u2
    force_tol = FORCE_TOL * max(normal_force.max(), 0.0)
    slip_tol = SLIP_TOL * R
    contact = normal_force > force_tol
    friction = np.where(np.abs(slip) <= slip_tol, "S=", np.where(slip > 0, "S+", "S-"))
    if law == "coulomb":
        friction = np.where(contact, friction, "-")
    load = np.array(d["f"]) * 2 * R  # the top edge has length 2R
    resultant = (normal_force[:, None] * n - tangential_force[:, None] * t).sum(axis=0)
    nodes = [{"x1": float(X[0, i]), "x2": float(X[1, i]), "u1": float(u1[i]), "u2": float(u2[i]),
              "gap": float(gap[i] + n[0] * u1[i] + n[1] * u2[i]), "weight": float(weights[i]),
              "normal_force": float(normal_force[i]), "tangential_force": float(tangential_force[i]),
              "slip": float(slip[i]), "status": "contact" if contact[i] else "free",
              "normal_status": "CU" if contact[i] else "free", "friction_status": str(friction[i])}
             for i in order]
    law_text = (f"Coulomb mu = {d['mu']:g}" if law == "coulomb" else f"Tresca threshold {d['threshold']:g}")
    brick_text = ("add_nodal_contact_with_rigid_obstacle_brick" if not basic else
                  "add_basic_contact_brick (BN, BT, gap, alpha built as the obstacle brick)" if law == "coulomb" else
                  "add_basic_contact_brick x 2 on an explicit model: Signorini + Coulomb friction "
                  "(coefficient 1) with a fixed normal force threshold x w_i on extra unknowns")
    summary = {
        "getfem_version": getfem_version(),
        "description": (f"gmsh half disc N = {N}, grading {d['grading']:g}, P1 plane strain, no Dirichlet, "
                        f"{law_text}: {brick_text}, version {args.version}, r = {r:g}, max_res {d['eps']:g}, "
                        f"lsolver auto, start u = ({start_shift[0]:g}, {start_shift[1]:g})"),
        "law": law, "mu": d["mu"] if law == "coulomb" else None,
        "threshold": d["threshold"] if law == "tresca" else None,
        "n": N, "grading": d["grading"], "dofs": int(nbdof),
        "model_unknowns": int(md.nbdof()),  # u (or U), the multipliers, Tresca's z and lambda_z
        "contact_nodes": nbc, "newton_iterations": iterations, "converged": converged,
        "solve_seconds": times, "solve_seconds_median": statistics.median(times),
        "active_nodes": int(contact.sum()),
        "stick_nodes": int(np.sum(friction == "S=")),
        "slip_nodes": int(np.sum((friction == "S+") | (friction == "S-"))),
        "load": load.tolist(), "resultant": resultant.tolist(),
        "equilibrium_error": float(np.linalg.norm(resultant + load) / np.linalg.norm(load)),
        "status_tolerances": {"normal_force": force_tol, "slip": slip_tol},
        "mesh_check": mesh_check,
        "nodes": nodes,
    }
    print_summary(summary, f"GetFEM {summary['getfem_version']}, {law_text}, N = {N}: {nbdof} "
                  f"dofs, Newton {iterations}{'' if converged else ' (NOT converged)'}, {{solve}}, "
                  f"{summary['active_nodes']} in contact (friction {summary['stick_nodes']} S=, "
                  f"{summary['slip_nodes']} S+/S-), resultant ({resultant[0]:.6f}, "
                  f"{resultant[1]:.6f}) against load ({load[0]:g}, {load[1]:g})", args.json)
    if not converged:
        sys.exit(1)


if __name__ == "__main__":
    main()
