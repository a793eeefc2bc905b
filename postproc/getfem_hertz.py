#!/usr/bin/python3
"""The Hertz half disc of scene 7a solved by GetFEM 5.4, the peer of drivers/bench-hertz.sh.

    /usr/bin/python3 postproc/getfem_hertz.py [--deck DATAFILE] [--n N] [--grading G] [--eps EPS]
                                             [--repeat K] [--json FILE] [--workdir DIR]

Same problem as datafiles/scene7a/hertz.dat (R, E, nu, f, grading, eps read from it) (../shared/SCENES.md "Scene 7a", ../shared/PEERS.md):
the half disc x1^2 + (x2 - R)^2 <= R^2, x2 <= R meshed by gmsh from meshes/half_disc.geo (the
script sig-mesh runs: N uniform segments on the arc, the same grading), P1 plane strain
(isotropic linearized elasticity in 2D), traction (0, -f) on the top edge, u1 = 0 at the top
centre through add_constraint_with_multipliers (gmsh points are not imported as regions), and
frictionless nodal contact with the rigid foundation x2 >= 0:
add_nodal_contact_with_rigid_obstacle_brick version 2 (symmetric Alart-Curnier), r = E as
GetFEM advises. Newton stops at max_res = eps relative to the external load (GetFEM's criterion,
our eps = 1e-5), linear solver 'auto' (sequential MUMPS here).

From u = 0 the first tangent is singular (one node touches; the half disc may turn about its
top centre), so every solve starts from the rigid shift u = (0, -h^2/R), h = pi R / N, which
pushes the three lowest nodes into the foundation; this makes the Newton counts reproducible.
One untimed solve comes first (GetFEM assembles its linear bricks once and keeps them; our
stiffness is assembled by sig-assemble, outside the times we compare); then K timed solves,
each from the same start. Only md.solve is timed. Prints a summary; --json writes it.
"""
import argparse
import math
import statistics
import sys
import tempfile
from pathlib import Path

import numpy as np

from getfem_common import (deck_cards, getfem_version, import_half_disc, parse_timed_args,
                           plane_strain_elasticity, print_summary, timed_solves,
                           tributary_lengths)

try:
    import getfem as gf
except ImportError:
    sys.exit("getfem_hertz.py: error: cannot import getfem (Debian: python3-getfem; use /usr/bin/python3)")

ROOT = Path(__file__).resolve().parent.parent
GEO = ROOT / "meshes" / "half_disc.geo"
DECK = ROOT / "datafiles" / "scene7a" / "hertz.dat"
TOP, GAMMA3 = 2, 3  # physical curves of half_disc.geo: top edge, lower half circle


def fail(message):
    sys.exit(f"getfem_hertz.py: error: {message}")


def read_deck(path):
    """R, grading (MESH), E, nu (MATERIAL), f = |f| (TRACTION), eps (SOLVER) of a scene 7a deck."""
    cards = deck_cards(path)
    try:
        return {"R": float(cards["MESH"]["r"]), "grading": float(cards["MESH"].get("grading", 0)),
                "E": float(cards["MATERIAL"]["e"]), "nu": float(cards["MATERIAL"]["nu"]),
                "f": math.hypot(*(float(v) for v in cards["TRACTION"]["f"].split(","))),
                "eps": float(cards.get("SOLVER", {}).get("eps", 1e-5))}
    except (KeyError, ValueError) as e:
        fail(f"{path}: cannot read R, E, nu, f from the MESH, MATERIAL, TRACTION cards ({e})")



def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=512, help="segments on the arc (default 512)")
    parser.add_argument("--deck", type=Path, default=DECK,
                        help="scene 7a datafile giving R, E, nu, f, grading, eps (default: the template)")
    parser.add_argument("--grading", type=float, help="mesh size growth away from the arc (default: the deck's)")
    parser.add_argument("--repeat", type=int, default=3, help="timed solves (default 3)")
    parser.add_argument("--eps", type=float, help="relative residual (default: the deck's eps)")
    parser.add_argument("--json", type=Path, help="write the summary here")
    parser.add_argument("--workdir", type=Path, help="folder for the gmsh mesh (default: temporary)")
    args = parse_timed_args(parser, fail)
    if args.n < 4 or args.n % 2:
        fail(f"--n must be even and >= 4, got {args.n}")
    deck = read_deck(args.deck)
    R, f, E, nu = deck["R"], deck["f"], deck["E"], deck["nu"]
    if args.grading is None:
        args.grading = deck["grading"]
    if args.eps is None:
        args.eps = deck["eps"]
    h = math.pi * R / args.n

    with tempfile.TemporaryDirectory() as tmp:
        workdir = args.workdir or Path(tmp)
        workdir.mkdir(parents=True, exist_ok=True)
        try:
            m, _ = import_half_disc(GEO, workdir, R, args.n, args.grading, (TOP, GAMMA3))
        except RuntimeError as e:
            fail(str(e))

    md, mfu, mim = plane_strain_elasticity(m, E, nu, (0.0, -f), TOP)
    nbdof = mfu.nbdof()

    # u1 = 0 at the top centre (0, R): a one-row constraint on the x dof of that node.
    nodes = mfu.basic_dof_nodes()
    at_centre = np.nonzero((np.abs(nodes[0]) < 1e-9 * R) & (np.abs(nodes[1] - R) < 1e-9 * R))[0]
    if len(at_centre) != 2:
        fail(f"found {len(at_centre)} dofs at the top centre (0, {R}), expected 2")
    B = gf.Spmat("empty", 1, nbdof)
    B[0, int(at_centre.min())] = 1.0  # qdim 2: the first dof of a node is u1
    md.add_variable("mult_u1", 1)
    md.add_constraint_with_multipliers("u", "mult_u1", B, [0.0])

    # Nodal contact with the foundation x2 >= 0 (signed distance 'y').
    contact_dofs = np.sort(mfu.basic_dof_on_region(GAMMA3))
    contact_x = contact_dofs[0::2]  # one per node, increasing: the order of lambda_n
    nbc = len(contact_x)
    if nbc != args.n + 1:
        fail(f"{nbc} contact nodes on Gamma3, expected N + 1 = {args.n + 1}")
    md.add_variable("lambda_n", nbc)
    md.add_initialized_data("r", [E])
    md.add_nodal_contact_with_rigid_obstacle_brick(mim, "u", "lambda_n", "r", GAMMA3, "y", 2)

    start = np.zeros(nbdof)
    start[1::2] = -h * h / R

    unknowns = {"u": start, "lambda_n": np.zeros(nbc), "mult_u1": np.zeros(1)}
    times, iterations, _ = timed_solves(md, unknowns, ["max_res", args.eps, "max_iter", 100, "lsolver", "auto"],
                                        args.repeat)

    # Pressure = nodal force / tributary length, nodes ordered by angle along the arc.
    lam = np.asarray(md.variable("lambda_n")).ravel()
    force = -lam  # GetFEM's nodal contact multiplier is negative in compression
    if force.sum() <= 0:
        fail(f"GetFEM's contact multipliers sum to {lam.sum():g}: expected a compressive (negative) sum")
    xy = nodes[:, contact_x]
    order = np.argsort(np.arctan2(xy[1] - R, xy[0]))
    weights = np.empty(nbc)
    weights[order] = tributary_lengths(xy[:, order])
    pressure = force / weights
    b = 2 * math.sqrt(2 * R**2 * f * (1 - nu**2) / (E * math.pi))
    p0 = 4 * R * f / (math.pi * b)
    active = int(np.sum(force > 1e-9 * force.max()))
    summary = {
        "getfem_version": getfem_version(),
        "description": (f"gmsh half disc N = {args.n}, grading {args.grading:g}, P1, nodal contact "
                        f"brick version 2 (symmetric), r = E = {E:g}, max_res {args.eps:g}, "
                        f"lsolver auto, start u = (0, -h^2/R)"),
        "n": args.n,
        "grading": args.grading,
        "dofs": int(nbdof),
        "contact_nodes": nbc,
        "newton_iterations": iterations,
        "solve_seconds": times,
        "solve_seconds_median": statistics.median(times),
        "active_nodes": active,
        "resultant": float(force.sum()),
        "load": 2 * R * f,
        "p_max": float(pressure.max()),
        "p0": p0,
        "p_max_rel_error": float((pressure.max() - p0) / p0),
    }
    print_summary(summary, f"GetFEM {summary['getfem_version']}, N = {args.n}: {nbdof} dofs, "
                  f"Newton {iterations}, {{solve}}, {active} active nodes, resultant "
                  f"{summary['resultant']:.4f} (load {2 * R * f:g}), p_max {summary['p_max']:.4f} "
                  f"({100 * summary['p_max_rel_error']:+.2f} % vs p0 = {p0:.4f})", args.json)


if __name__ == "__main__":
    main()
