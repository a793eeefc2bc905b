#!/usr/bin/python3
"""The hyperelastic ring of scene 7b solved by GetFEM 5.4, the peer of drivers/bench-ring.sh.

    /usr/bin/python3 postproc/getfem_ring.py [--deck DATAFILE] [--n N] [--eps EPS]
                                            [--repeat K] [--lsearch NAME] [--start rest|small-strain]
                                            [--json FILE]

Same problem as datafiles/scene7b/ring.dat (../shared/SCENES.md "Scene 7b", ../shared/PEERS.md),
radii, N, AB and Gamma3 bounds, c1, c2, a, the imposed displacement and LOADSTEPS read from the
deck; the SAME mesh as sig-mesh's ring generator (modules/mesh/src/generators_structured.cpp),
rebuilt here node for node (angles, radii, the on_grid rounding that makes it exactly
mirror-symmetric, the mirrored diagonals), P1 triangles:
  - GetFEM's finite-strain elasticity brick with its 'Ciarlet Geymonat' law, params
    [lambda; mu; a'] = [4 (a + c2); 2 (c1 + c2); c1]: the thesis's W up to a constant; in 2D
    GetFEM uses plane strain, as our deck does;
  - AB (outer-circle nodes with x2 >= gamma1_above) held at s (0, -14), s = k / steps,
    k = 1 .. steps, each step starting from the previous one, by add_Dirichlet_condition_with_
    multipliers (with add_Dirichlet_condition_with_simplification and contact version 2, GetFEM's
    Newton cut the Dirichlet step of load step 1 down to 1/8 and did not converge in 200
    iterations);
  - frictionless nodal contact with the foundation x2 >= 0 on Gamma3 (outer-circle nodes with
    x2 <= gamma3_below): add_nodal_contact_with_rigid_obstacle_brick version 2 (symmetric
    Alart-Curnier), r = the small-strain Young modulus, as GetFEM advises.
Newton stops at max_res = eps x 1e-2, GetFEM's absolute residual: 1e-2 is the force scale of the
ring (the final vertical reaction is 0.02-0.03), so eps plays the role of our relative eps.
Linear solver 'auto' (sequential MUMPS here). --lsearch NAME passes GetFEM's line search
(default: its Newton_with_step_control; simplest, basic, systematic: its classical Newton with
that search): GetFEM's own count depends on it (modules/solver/NEWTON.md, the ring's counts). The vertical reaction on AB is the sum over the AB
y-dofs of the internal force, assembled in GWFL from the same law, and is checked against the
sum of the contact forces (global equilibrium). K timed solves of all the load steps, each from
u = 0 (only md.solve is timed). --start small-strain starts the first load step where ours does
with LOADSTEPS start=small-strain (stages/small_strain_start.hpp): at the solution of the same
contact problem with GetFEM's isotropic linearized elasticity brick (plane strain, the law's
lambda and mu, its tangent at rest) under the first step's Dirichlet data, u and lambda_n kept;
its Newton iterations are counted apart (start_iterations), as ours are. Ours shortens that start
where it would invert a triangle; the rings here take it whole (start_fraction 1), and this
script does not shorten it; the start's solve is not timed. Prints a summary; --json writes it.
"""
import argparse
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from getfem_common import deck_cards, getfem_version, parse_timed_args, print_summary

try:
    import getfem as gf
except ImportError:
    sys.exit("getfem_ring.py: error: cannot import getfem (Debian: python3-getfem; use /usr/bin/python3)")

ROOT = Path(__file__).resolve().parent.parent
DECK = ROOT / "datafiles" / "scene7b" / "ring.dat"
AB, GAMMA3 = 1, 3  # GetFEM regions (face sets) built below


def fail(message):
    sys.exit(f"getfem_ring.py: error: {message}")


def read_deck(path):
    """The MESH (ring generator), MATERIAL, DIRICHLET, LOADSTEPS and SOLVER fields used here."""
    cards = deck_cards(path)
    try:
        mesh, material = cards["MESH"], cards["MATERIAL"]
        if mesh.get("generator") != "ring" or material.get("law") != "ciarlet-geymonat":
            fail(f"{path}: needs MESH generator=ring and MATERIAL law=ciarlet-geymonat")
        if material.get("plane", "strain") != "strain":
            fail(f"{path}: GetFEM's 2D finite-strain laws are plane strain, the deck says plane={material['plane']}")
        # centre= (center= its old spelling), 0,0 when absent as in the card schema.
        center = [float(v) for v in mesh.get("centre", mesh.get("center", "0,0")).split(",")]
        return {"center": center, "r_in": float(mesh["r_in"]), "r_out": float(mesh["r_out"]),
                "N": int(mesh["n"]), "gamma1_above": float(mesh["gamma1_above"]),
                "gamma3_below": float(mesh["gamma3_below"]),
                "c1": float(material["c1"]), "c2": float(material["c2"]), "a": float(material["a"]),
                "ux": float(cards["DIRICHLET"].get("ux", 0)), "uy": float(cards["DIRICHLET"]["uy"]),
                "steps": int(cards.get("LOADSTEPS", {}).get("n", 1)),
                "eps": float(cards.get("SOLVER", {}).get("eps", 1e-5))}
    except (KeyError, ValueError) as e:
        fail(f"{path}: cannot read the ring, material, DIRICHLET and LOADSTEPS fields ({e})")



def on_grid(value, magnitude):
    """sig-mesh's rounding to a multiple of 2^(ilogb(magnitude) + 1 - 52) (exact mirror images)."""
    q = math.ldexp(1.0, math.frexp(magnitude)[1] - 1 + 1 - 52)
    return round(value / q) * q  # round half to even, as std::nearbyint


def ring_mesh(d):
    """Nodes (2 x n) and triangles (3 x t) of sig-mesh's ring generator (same order)."""
    N, r_in, r_out = d["N"], d["r_in"], d["r_out"]
    layers = max(2, 3 * N // 64 + 1)
    magnitude = abs(d["center"][0]) + r_out
    cx, cy = on_grid(d["center"][0], magnitude), d["center"][1]
    nodes = np.zeros((2, N * layers))
    for j in range(layers):
        r = r_in + (r_out - r_in) * j / (layers - 1)
        for k in range(N // 2 + 1):
            angle = -math.pi / 2 + 2 * math.pi * k / N
            dx = 0.0 if k in (0, N // 2) else on_grid(r * math.cos(angle), magnitude)
            y = cy - r if k == 0 else cy + r if k == N // 2 else cy + r * math.sin(angle)
            nodes[:, j * N + k] = (cx + dx, y)
            nodes[:, j * N + (N - k) % N] = (cx - dx, y)
    triangles = []
    node = lambda k, j: j * N + k % N
    for j in range(layers - 1):
        for k in range(N):
            a, b, c, e = node(k, j), node(k + 1, j), node(k + 1, j + 1), node(k, j + 1)
            triangles += [(a, c, b), (a, e, c)] if k < N // 2 else [(a, e, b), (b, e, c)]
    outer = [node(k, layers - 1) for k in range(N)]
    return nodes, np.array(triangles).T, outer, layers


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--deck", type=Path, default=DECK, help="scene 7b datafile (default: the template)")
    parser.add_argument("--n", type=int, help="nodes around (default: the deck's MESH N=)")
    parser.add_argument("--repeat", type=int, default=3, help="timed solves (default 3)")
    parser.add_argument("--eps", type=float, help="relative residual (default: the deck's eps)")
    parser.add_argument("--lsearch", default="default",
                        choices=["default", "simplest", "basic", "systematic"],
                        help="GetFEM's Newton line search (default: its step control)")
    parser.add_argument("--start", choices=["rest", "small-strain"], default="rest",
                        help="first iterate of the first load step (default rest)")
    parser.add_argument("--json", type=Path, help="write the summary here")
    args = parse_timed_args(parser, fail)
    d = read_deck(args.deck)
    if args.n is not None:
        d["N"] = args.n
    if d["N"] < 4 or d["N"] % 2:
        fail(f"N must be even and >= 4, got {d['N']}")
    eps = args.eps if args.eps is not None else d["eps"]

    nodes, triangles, outer, layers = ring_mesh(d)
    m = gf.Mesh("empty", 2)
    pids = np.asarray(m.add_point(nodes)).ravel()
    if len(set(pids.tolist())) != nodes.shape[1]:
        fail("GetFEM merged some nodes of the ring")
    m.add_convex(gf.GeoTrans("GT_PK(2,1)"), nodes[:, triangles.T.ravel()].reshape(
        2, -1, 3).transpose(0, 2, 1))
    tol = 1e-9 * d["r_out"]
    ab_nodes = [p for p in outer if nodes[1, p] >= d["gamma1_above"] - tol]
    contact_nodes = [p for p in outer if nodes[1, p] <= d["gamma3_below"] + tol]
    m.set_region(AB, m.faces_from_pid(pids[ab_nodes]))
    m.set_region(GAMMA3, m.faces_from_pid(pids[contact_nodes]))

    mfu = gf.MeshFem(m, 2)
    mfu.set_classical_fem(1)
    mim = gf.MeshIm(m, gf.Integ("IM_TRIANGLE(2)"))
    c1, c2, a = d["c1"], d["c2"], d["a"]
    lam, mu = 4 * (a + c2), 2 * (c1 + c2)
    young = mu * (3 * lam + 2 * mu) / (lam + mu)

    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("params", [lam, mu, c1])
    hyperelastic = md.add_finite_strain_elasticity_brick(mim, "Ciarlet Geymonat", "u", "params")
    md.add_initialized_data("DirichletData", [0.0, 0.0])
    md.add_Dirichlet_condition_with_multipliers(mim, "u", mfu, AB, "DirichletData")
    contact_dofs = np.sort(mfu.basic_dof_on_region(GAMMA3))
    nbc = len(contact_dofs) // 2
    if nbc != len(contact_nodes):
        fail(f"{nbc} contact nodes in GetFEM's region, {len(contact_nodes)} expected")
    md.add_variable("lambda_n", nbc)
    md.add_initialized_data("r", [young])
    md.add_nodal_contact_with_rigid_obstacle_brick(mim, "u", "lambda_n", "r", GAMMA3, "y", 2)
    ab_dofs = np.sort(mfu.basic_dof_on_region(AB))
    if len(ab_dofs) != 2 * len(ab_nodes):
        fail(f"{len(ab_dofs)} dofs on AB, {2 * len(ab_nodes)} expected")

    linear = None
    if args.start == "small-strain":
        md.add_initialized_data("lambda", [lam])
        md.add_initialized_data("mu", [mu])
        linear = md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")
        md.disable_bricks(linear)

    def small_strain_start(s):
        """GetFEM's count for the linear contact problem under the first step's data, u and
        lambda_n left at its solution."""
        md.disable_bricks(hyperelastic)
        md.enable_bricks(linear)
        md.set_variable("DirichletData", [s * d["ux"], s * d["uy"]])
        result = np.atleast_1d(md.solve("max_res", eps * 1e-2, "max_iter", 200, "lsolver", "auto",
                                        "lsearch", args.lsearch))
        md.disable_bricks(linear)
        md.enable_bricks(hyperelastic)
        if len(result) > 1 and not result[1]:
            fail("GetFEM's small-strain start did not converge")
        return int(result[0])

    def solve():
        md.set_variable("u", np.zeros(mfu.nbdof()))
        md.set_variable("lambda_n", np.zeros(nbc))
        per_step, seconds, converged = [], 0.0, True
        start_iterations = small_strain_start(1 / d["steps"]) if linear is not None else 0
        for k in range(1, d["steps"] + 1):
            s = k / d["steps"]
            md.set_variable("DirichletData", [s * d["ux"], s * d["uy"]])
            t0 = time.perf_counter()
            result = np.atleast_1d(md.solve("max_res", eps * 1e-2, "max_iter", 200, "lsolver", "auto",
                                             "lsearch", args.lsearch))
            seconds += time.perf_counter() - t0
            per_step.append(int(result[0]))
            if len(result) > 1 and not result[1]:
                converged = False
                break
        return seconds, per_step, converged, start_iterations

    runs = [solve() for _ in range(args.repeat)]
    seconds, per_step, converged, start_iterations = runs[-1]

    # Reaction on AB: the internal force of the same law (GWFL) summed over the AB y-dofs.
    force = gf.asm_generic(mim, 1, "((Id(meshdim)+Grad_u)*Plane_Strain_Ciarlet_Geymonat_PK2(Grad_u,params)):Grad_Test_u",
                           -1, md)
    start, size = (int(v) for v in np.atleast_1d(md.interval_of_variable("u")))
    force = np.asarray(force).ravel()[start:start + size]  # the vector holds every variable
    reaction = [float(force[ab_dofs[0::2]].sum()), float(force[ab_dofs[1::2]].sum())]
    contact_force = -np.asarray(md.variable("lambda_n")).ravel()  # negative in compression
    if converged and abs(reaction[1] + contact_force.sum()) > 1e-6 * abs(reaction[1]):
        fail(f"reaction on AB {reaction[1]:.9g} does not balance the contact forces "
             f"{contact_force.sum():.9g}: the GWFL force is not the brick's law")
    summary = {
        "getfem_version": getfem_version(),
        "description": (f"sig-mesh's ring N = {d['N']} ({layers} layers) rebuilt node for node, P1, "
                        f"'Ciarlet Geymonat' params [{lam:g}; {mu:g}; {c1:g}] (plane strain), "
                        f"{d['steps']} load steps, nodal contact brick version 2, r = E = {young:.4g}, "
                        f"max_res {eps * 1e-2:g}, lsolver auto, lsearch {args.lsearch}"),
        "n": d["N"],
        "dofs": int(mfu.nbdof()),
        "contact_nodes": nbc,
        "ab_nodes": len(ab_nodes),
        "lsearch": args.lsearch,
        "start": args.start,
        "start_iterations": start_iterations,
        "converged": bool(converged),
        "newton_per_step": per_step,
        "newton_iterations": int(sum(per_step)),
        "solve_seconds": [r[0] for r in runs],
        "solve_seconds_median": statistics.median(r[0] for r in runs),
        "reaction_x": reaction[0],
        "reaction_y": reaction[1],
        "contact_force_sum": float(contact_force.sum()),
    }
    print_summary(summary, f"GetFEM {summary['getfem_version']}, N = {d['N']}: {summary['dofs']} "
                  f"dofs, Newton {summary['newton_iterations']} (per step {per_step}), {{solve}}, "
                  f"reaction ({reaction[0]:.4g}, {reaction[1]:.6g}), contact forces sum "
                  f"{summary['contact_force_sum']:.6g}{'' if converged else ', NOT converged'}",
                  args.json)


if __name__ == "__main__":
    main()
