#!/usr/bin/python3
"""The hyperelastic crush of issue 28 (datafiles/scene3d/crush.dat) solved by GetFEM 5.4, the
peer of drivers/scene3d_crush.sh.

    /usr/bin/python3 postproc/getfem_crush3d.py --deck DATAFILE [--steps S] [--eps EPS]
                                                [--json FILE]

Same problem as the deck, read from it:
  - the SAME mesh: the deck's MESH file= (msh 2.2, meshes/hollow_ball.geo: physical volume 1,
    surfaces 2 the flat top, 3 the outer sphere, 4 the cavity), P1 tetrahedra, IM_TETRAHEDRON(2)
    (exact for the P1 loads; the law is constant per tetrahedron, as ours with one point);
  - the law: GetFEM's finite-strain elasticity brick with 'Ciarlet Geymonat', params
    [lambda; mu; a'] = [4 (a + c2); 2 (c1 + c2); c1] from the deck's c1, c2, a. GetFEM's W is
    a' i1 + (mu/2 - a') i2 + (lambda/4 - mu/2 + a') i3 - (lambda/2 + mu) ln(i3) / 2 + const
    (getfem_nonlinear_elasticity.cc), with these params c1 I1 + c2 I2 + a I3 - (c1 + 2 c2 + a)
    ln I3 + const: the thesis's W (1.63), ours (modules/material/ciarlet_geymonat.hpp). The script
    checks it: GetFEM's W at three homogeneous deformations (its potential integrated over the
    mesh under u = G X, over the volume) minus ours is one constant to 1e-12;
  - Dirichlet data: the top (region 2) held at s (ux, uy, uz) of the deck's DIRICHLET ref=2,
    s = k / S, k = 1 .. S (the deck's LOADSTEPS n=S, or --steps), each step from the previous
    solution, the first from rest, by add_Dirichlet_condition_with_multipliers (a P1 multiplier
    on the top's faces: the nodal values exactly, the imposed field being in the space);
  - the obstacle: the deck's plane x3 >= point3 (CONTACT obstacle=plane normal=0,0,1 only),
    frictionless nodal contact on the outer sphere's nodes (ours excludes the top's rim, exclude=2;
    those nodes are held and far from the plane: their multipliers stay 0),
    add_nodal_contact_with_rigid_obstacle_brick version 2, r = the small-strain Young modulus.
Newton: md.solve with its default line search, max_res = eps x the reaction's scale (the
small-strain stiffness mu times the imposed displacement times the body's size, GetFEM's residual
being absolute), lsolver 'auto' (MUMPS). Per load step: the vertical reaction on the top (the
internal force of the same law, GWFL, summed over the top's x3 dofs), the sum of the contact
forces (they balance it), GetFEM's Newton iterations and the nodes in contact. Prints a summary;
--json writes it. Exit 1 when a step does not converge.
"""
import argparse
import sys
import time
from pathlib import Path

import numpy as np

from getfem_common import deck_cards, getfem_version, import_gmsh, parse_timed_args, print_summary

try:
    import getfem as gf
except ImportError:
    sys.exit("getfem_crush3d.py: error: cannot import getfem (Debian: python3-getfem; use /usr/bin/python3)")

VOLUME, TOP, OUTER = 1, 2, 3  # physical groups of meshes/hollow_ball.geo


def fail(message):
    sys.exit(f"getfem_crush3d.py: error: {message}")


def read_deck(path):
    """The MESH file, MATERIAL, DIRICHLET ref=2, CONTACT plane, LOADSTEPS and SOLVER fields."""
    cards = deck_cards(path)
    try:
        material, dirichlet, contact = cards["MATERIAL"], cards["DIRICHLET"], cards["CONTACT"]
        if material.get("law") != "ciarlet-geymonat":
            fail(f"{path}: needs MATERIAL law=ciarlet-geymonat, got law={material.get('law')}")
        if dirichlet.get("ref") != str(TOP) or contact.get("ref") != str(OUTER):
            fail(f"{path}: needs DIRICHLET ref={TOP} and CONTACT ref={OUTER} (hollow_ball.geo's groups)")
        normal = [float(v) for v in contact.get("normal", "").split(",")]
        if contact.get("obstacle") != "plane" or normal[:2] != [0.0, 0.0] or not normal[2] > 0:
            fail(f"{path}: needs CONTACT obstacle=plane normal=0,0,1 (the x3 floor)")
        mesh = Path(cards["MESH"]["file"])
        return {"mesh": mesh if mesh.is_absolute() else Path(path).parent / mesh,
                "c1": float(material["c1"]), "c2": float(material["c2"]), "a": float(material["a"]),
                "u_top": [float(dirichlet.get(k, 0)) for k in ("ux", "uy", "uz")],
                "floor": float(contact["point"].split(",")[2]),
                "steps": int(cards.get("LOADSTEPS", {}).get("n", 1)),
                "eps": float(cards.get("SOLVER", {}).get("eps", 1e-5))}
    except (KeyError, ValueError, IndexError) as e:
        fail(f"{path}: cannot read the MESH file, MATERIAL, DIRICHLET, CONTACT and LOADSTEPS fields ({e})")


def thesis_energy(G, c1, c2, a):
    """W (1.63) of F = I + G: c1 (I1 - 3) + c2 (I2 - 3) + a (I3 - 1) - (c1 + 2 c2 + a) ln I3."""
    F = np.eye(3) + G
    C = F.T @ F
    I1, I3 = np.trace(C), np.linalg.det(C)
    I2 = 0.5 * (I1 * I1 - np.trace(C @ C))
    return c1 * (I1 - 3) + c2 * (I2 - 3) + a * (I3 - 1) - (c1 + 2 * c2 + a) * np.log(I3)


def check_same_law(md, mfu, mim, d):
    """GetFEM's W minus ours at three homogeneous deformations u = G X: one constant (the
    parameter map is right), else fail. Returns the largest spread."""
    rng = np.random.default_rng(28)
    X = mfu.basic_dof_nodes()[:, 0::3]
    volume = gf.asm_generic(mim, 0, "1", -1, md)
    shifts = []
    for _ in range(3):
        G = 0.3 * rng.standard_normal((3, 3))
        u = np.zeros(mfu.nbdof())
        for k in range(3):
            u[k::3] = (G @ X)[k]
        md.set_variable("u", u)
        theirs = gf.asm_generic(mim, 0, "Ciarlet_Geymonat_potential(Grad_u, params)", -1, md) / volume
        shifts.append(theirs - thesis_energy(G, d["c1"], d["c2"], d["a"]))
    spread = max(shifts) - min(shifts)
    if spread > 1e-12 * max(1.0, abs(shifts[0])):
        fail(f"GetFEM's 'Ciarlet Geymonat' W minus the thesis's is not constant ({shifts}): "
             "the parameter map is wrong")
    md.set_variable("u", np.zeros(mfu.nbdof()))
    return spread


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--deck", type=Path, required=True, help="the crush datafile")
    parser.add_argument("--steps", type=int, help="load steps (default: the deck's LOADSTEPS n=)")
    parser.add_argument("--eps", type=float, help="relative residual (default: the deck's eps)")
    parser.add_argument("--json", type=Path, help="write the summary here")
    parser.set_defaults(repeat=1)
    args = parse_timed_args(parser, fail)
    d = read_deck(args.deck)
    steps = args.steps if args.steps is not None else d["steps"]
    eps = args.eps if args.eps is not None else d["eps"]
    if steps < 1:
        fail(f"--steps must be >= 1, got {steps}")
    try:
        m = import_gmsh(d["mesh"], (VOLUME, TOP, OUTER))
    except RuntimeError as e:
        fail(str(e))

    mfu = gf.MeshFem(m, 3)
    mfu.set_classical_fem(1)
    mim = gf.MeshIm(m, gf.Integ("IM_TETRAHEDRON(2)"))
    lam, mu = 4 * (d["a"] + d["c2"]), 2 * (d["c1"] + d["c2"])
    young = mu * (3 * lam + 2 * mu) / (lam + mu)
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("params", [lam, mu, d["c1"]])
    law_spread = check_same_law(md, mfu, mim, d)
    md.add_finite_strain_elasticity_brick(mim, "Ciarlet Geymonat", "u", "params")
    md.add_initialized_data("DirichletData", [0.0, 0.0, 0.0])
    md.add_Dirichlet_condition_with_multipliers(mim, "u", mfu, TOP, "DirichletData")
    contact_dofs = np.sort(mfu.basic_dof_on_region(OUTER))
    nbc = len(contact_dofs) // 3
    md.add_variable("lambda_n", nbc)
    md.add_initialized_data("r", [young])
    md.add_nodal_contact_with_rigid_obstacle_brick(mim, "u", "lambda_n", "r", OUTER,
                                                   f"z - {d['floor']!r}", 2)
    top_z = np.sort(mfu.basic_dof_on_region(TOP))[2::3]
    points = mfu.basic_dof_nodes()[:, 0::3]
    size = float(np.ptp(points, axis=1).max())
    scale = mu * max(abs(v) for v in d["u_top"]) * size  # a force: the residual is absolute
    force = "((Id(meshdim)+Grad_u)*Ciarlet_Geymonat_PK2(Grad_u,params)):Grad_Test_u"
    start, width = (int(v) for v in np.atleast_1d(md.interval_of_variable("u")))

    rows, converged, seconds = [], True, 0.0
    for k in range(1, steps + 1):
        s = k / steps
        md.set_variable("DirichletData", [s * v for v in d["u_top"]])
        t0 = time.perf_counter()
        result = np.atleast_1d(md.solve("max_res", eps * scale, "max_iter", 200, "lsolver", "auto"))
        seconds += time.perf_counter() - t0
        iterations = int(result[0])
        ok = iterations < 200 and (len(result) < 2 or bool(result[1]))
        internal = np.asarray(gf.asm_generic(mim, 1, force, -1, md)).ravel()[start:start + width]
        contact = -np.asarray(md.variable("lambda_n")).ravel()  # the plane pushes: N >= 0
        rows.append({"step": k, "load": s, "newton_iterations": iterations, "converged": ok,
                     "reaction_z": float(internal[top_z].sum()),
                     "contact_force_sum": float(contact.sum()),
                     "contact_nodes": int((contact > 1e-9 * max(contact.max(), 1e-300)).sum())})
        if not ok:
            converged = False
            break
        if abs(rows[-1]["reaction_z"] + rows[-1]["contact_force_sum"]) > 1e-6 * abs(rows[-1]["reaction_z"]):
            fail(f"step {k}: the reaction on the top {rows[-1]['reaction_z']:.9g} does not balance the "
                 f"contact forces {rows[-1]['contact_force_sum']:.9g}: the GWFL force is not the brick's law")
    summary = {
        "getfem_version": getfem_version(),
        "description": (f"{d['mesh'].name} ({m.nbpts()} points, {m.nbcvs()} tetrahedra), P1, 'Ciarlet "
                        f"Geymonat' params [{lam:g}; {mu:g}; {d['c1']:g}], top held at s "
                        f"({', '.join(f'{v:g}' for v in d['u_top'])}) in {steps} load steps, nodal "
                        f"contact brick version 2 with x3 >= {d['floor']:g}, r = E = {young:.4g}, "
                        f"max_res {eps * scale:.3g} (eps {eps:g} x {scale:.3g}), lsolver auto"),
        "law_check_spread": law_spread,
        "dofs": int(mfu.nbdof()), "contact_candidates": nbc, "steps": rows, "converged": converged,
        "newton_iterations": int(sum(r["newton_iterations"] for r in rows)),
        "solve_seconds": [seconds], "solve_seconds_median": seconds,
    }
    print_summary(summary, f"GetFEM {summary['getfem_version']}: {summary['dofs']} dofs, {steps} load "
                  f"steps, Newton per step {[r['newton_iterations'] for r in rows]}, {{solve}}, "
                  f"reaction_z per step {[round(r['reaction_z'], 9) for r in rows]}"
                  f"{'' if converged else ', NOT converged'}", args.json)
    if not converged:
        fail(f"load step {len(rows)} did not converge in {rows[-1]['newton_iterations']} iterations")


if __name__ == "__main__":
    main()
