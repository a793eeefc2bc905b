#!/usr/bin/python3
"""Cattaneo-Mindlin report (issue 26): the Hertz half ball sheared after its normal load, beside
Cattaneo and Mindlin's stick radius c = a (1 - Q / (mu P))^(1/3).

    postproc/cattaneo3d_report.py OUTDIR

OUTDIR is what drivers/scene3d_cattaneo.sh wrote: command.txt, cattaneo_mindlin.template.dat and
per run <name>/ (its deck cattaneo_mindlin.dat, the DS files, summary.json, contact.csv). Writes
OUTDIR/report.md, stick_slip.png, traction.png, OUTDIR/summary.json (every number of the report)
and OUTDIR/scene.json.

The functions `measure` (the stick/slip measures of one run's contact.csv) and `top_reaction`
(the clamp's force, from the displacement and the P1 stiffness) also serve the pipeline test
tests/pipeline/cattaneo_mindlin_quick.sh (postproc/ on PYTHONPATH).

Conventions of contact.csv (3D): `multiplier` N >= 0 is the normal force on the ball (+x3),
`tangential_force_1..3` the tangential force in global axes, reported as the force the ball
exerts on the flat (the top is dragged along +x1, the sum is +Q e1); `friction_status` S= stick,
S+ slip. Ours per run: P = sum N, Q = |sum T|, a the largest radius of a node in contact, the
stick radius c the radius that best separates the stick nodes from the slip nodes (fewest nodes
on the wrong side, the middle of the best interval), with the largest stick node and the smallest
slip node radius beside it (the ragged edge of an unstructured mesh), the centroid of the stick
nodes, the largest | |T| - mu N | / (mu N) of the slip nodes.
"""
import argparse
import math
from pathlib import Path

import numpy as np

from hertz3d_report import hertz, radius
from sigreport import (Checks, Deck, ReportError, Table, finish_report, main_guard, pyplot,
                       read_command, read_csv_columns, read_ds, read_summary, save_figure,
                       solve_seconds)
from sigreport.ds import sig_dump_json

FORCE_TOL = 1e-8    # the contact forces against the clamp's reaction, relative to P
CONE_TOL = 1e-6     # |T| = mu N on every slip node, relative
MESH_SIZES = 2      # the stick radius within this many mesh sizes of Cattaneo-Mindlin's


def dundurs_beta(nu):
    """Dundurs' beta of an elastic body (nu) on a rigid flat: (1 - 2 nu) / (2 (1 - nu))."""
    return (1 - 2 * nu) / (2 * (1 - nu))


def cattaneo_radius(a, ratio):
    """Cattaneo-Mindlin's stick radius for Q / (mu P) = ratio < 1."""
    return a * (1 - ratio) ** (1 / 3)


def cattaneo_traction(r, a, c, mu, p0):
    """Cattaneo-Mindlin's tangential traction along the load: mu p0 sqrt(1 - r^2 / a^2), less
    mu p0 (c / a) sqrt(1 - r^2 / c^2) within c."""
    outer = mu * p0 * np.sqrt(np.clip(1 - (r / a) ** 2, 0, None))
    inner = mu * p0 * (c / a) * np.sqrt(np.clip(1 - (r / c) ** 2, 0, None))
    return outer - inner


def mesh_size(mesh, r):
    """The graded mesh's size at distance r from the pole (meshes/half_ball.geo, cap ignored)."""
    h, grading = mesh
    return h + grading * r


def separating_radius(r_stick, r_slip):
    """The radius that leaves the fewest stick nodes outside and slip nodes inside; of the best
    interval between two node radii, its middle."""
    radii = np.unique(np.concatenate([r_stick, r_slip]))
    cuts = np.concatenate([[0.0], (radii[1:] + radii[:-1]) / 2, [radii[-1] + 1e-12]])
    wrong = np.array([(r_stick > c).sum() + (r_slip < c).sum() for c in cuts])
    best = np.nonzero(wrong == wrong.min())[0]
    return float((cuts[best[0]] + cuts[best[-1]]) / 2), int(wrong.min())


def measure(csv_path, mu):
    """The measures of one run (module docstring) from its contact.csv."""
    c = read_csv_columns(csv_path, text_columns=("status", "friction_status", "normal_status"))
    x, y = c["x1"], c["x2"]
    r = np.hypot(x, y)
    N, p = c["multiplier"], c["pressure"]
    T = np.stack([c[f"tangential_force_{k}"] for k in (1, 2, 3)], axis=1)
    contact = c["status"] == "contact"
    stick = contact & (c["friction_status"] == "S=")
    slip = contact & (c["friction_status"] == "S+")
    if not contact.any() or not stick.any() or not slip.any():
        raise ReportError(f"{csv_path}: {contact.sum()} nodes in contact, {stick.sum()} stick, "
                          f"{slip.sum()} slip: not a partial slip")
    P, Qv = float(N.sum()), T.sum(axis=0)
    Q = float(np.linalg.norm(Qv))
    ratio = Q / (mu * P)
    a = float(r[contact].max())
    c_fit, wrong = separating_radius(r[stick], r[slip])
    Tn = np.linalg.norm(T, axis=1)
    cone = np.abs(Tn[slip] - mu * N[slip]) / (mu * N[slip])
    area = np.where(contact, N / np.where(p > 0, p, 1), np.nan)
    return {"P": P, "Q": Q, "Q_vector": Qv.tolist(), "ratio": ratio, "a": a, "c": c_fit,
            "c_misplaced": wrong, "c_stick_max": float(r[stick].max()),
            "c_slip_min": float(r[slip].min()), "c_cm": cattaneo_radius(a, ratio),
            "stick_centre": [float(x[stick].mean()), float(y[stick].mean())],
            "stick_nodes": int(stick.sum()), "slip_nodes": int(slip.sum()),
            "contact_nodes": int(contact.sum()), "cone_error": float(cone.max()),
            "stick_cone_max": float((Tn[stick] / (mu * N[stick])).max()),
            "converged": bool((c["converged"] == 1).all()),
            # arrays for the charts (dropped from summary.json)
            "x": x, "y": y, "r": r, "theta": np.arctan2(y, x), "stick": stick, "slip": slip,
            "contact": contact, "q1": np.where(contact, T[:, 0] / area, np.nan),
            "T1": T[:, 0], "area": area, "p": p}


def top_reaction(nopo, case_b, E, nu, ref=2):
    """The force of the clamp of boundary reference `ref` on the ball: the P1 internal forces
    K u summed over that reference's nodes (Hooke, tetrahedra of case.nopo, u of case.b), and the
    largest |K u| at the nodes neither clamped nor in contact over the largest at the top (the
    residual of equilibrium there)."""
    mesh = sig_dump_json(nopo, values=True)
    X = np.asarray(mesh["coordinates"], dtype=float).reshape(-1, 3)
    tets = np.asarray(mesh["tetrahedron_nodes"], dtype=int).reshape(-1, 4) - 1
    faces = np.asarray(mesh["faces"], dtype=int).reshape(-1, 4)
    u = np.asarray(read_ds(case_b, arrays=["u"])["u"], dtype=float).reshape(-1, 3)
    lam, G = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    J = np.stack([X[tets[:, k]] - X[tets[:, 0]] for k in (1, 2, 3)], axis=2)  # columns: edges
    inv = np.linalg.inv(J)                                          # rows: grad lambda_1..3
    grads = np.concatenate([-inv.sum(axis=1, keepdims=True), inv], axis=1)  # (m, 4, 3)
    volume = np.abs(np.linalg.det(J)) / 6
    grad_u = np.einsum("mai,maj->mij", u[tets], grads)
    eps = (grad_u + grad_u.transpose(0, 2, 1)) / 2
    sigma = 2 * G * eps + lam * np.trace(eps, axis1=1, axis2=2)[:, None, None] * np.eye(3)
    f_el = volume[:, None, None] * np.einsum("mij,maj->mai", sigma, grads)
    f = np.zeros_like(X)
    np.add.at(f, tets, f_el)
    top = np.unique(faces[faces[:, 3] == ref, :3] - 1)
    return f[top].sum(axis=0), f, top


class Run:
    """One run of the driver: its folder, mesh (h, grading), nu, the measures."""

    def __init__(self, out, name, mesh, nu, mu, R, E):
        self.name, self.mesh, self.nu = name, mesh, nu
        folder = out / name
        s = read_summary(folder, required=("converged", "dofs"))
        self.converged, self.dofs = bool(s["converged"]), int(s["dofs"])
        self.iterations, self.seconds = int(s.get("iterations", 0)), solve_seconds(s)
        if not self.converged:
            self.m = None
            return
        self.m = measure(folder / "contact.csv", mu)
        reaction, f, top = top_reaction(folder / "case.nopo", folder / "case.b", E, nu)
        # contact.csv's tangential force is the ball's on the flat, its normal one the flat's on
        # the ball: the flat's force on the ball is (-T, N); clamp + flat = 0.
        flat = np.array(self.m["Q_vector"]) * np.array([-1, -1, 0]) + [0, 0, self.m["P"]]
        self.m["equilibrium"] = float(np.linalg.norm(reaction + flat) / self.m["P"])
        self.m["reaction"] = reaction.tolist()
        self.m["hertz"] = hertz(self.m["P"], R, E, nu)


def stick_slip_chart(path, run, mu):
    """The contact nodes in the plane x3 = 0 coloured by status, circles a, c (ours) and c_CM."""
    m = run.m
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(5.8, 5.4))
    free = ~m["contact"] & (m["r"] < 1.3 * m["a"])
    ax.plot(m["x"][free], m["y"][free], ".", color="0.7", markersize=3, label="free")
    ax.plot(m["x"][m["stick"]], m["y"][m["stick"]], "o", color="C0", markersize=3.5, label="stick")
    ax.plot(m["x"][m["slip"]], m["y"][m["slip"]], "s", color="C3", markersize=3.5,
            fillstyle="none", label="slip")
    t = np.linspace(0, 2 * math.pi, 200)
    for radius_, style, label in ((m["a"], "k-", f"a = {m['a']:.3f} (last node in contact)"),
                                  (m["c_cm"], "k--", f"c CM = {m['c_cm']:.3f}"),
                                  (m["c"], "C0:", f"c ours = {m['c']:.3f}")):
        ax.plot(radius_ * np.cos(t), radius_ * np.sin(t), style, lw=1, label=label)
    ax.set_aspect("equal")
    lim = 1.3 * m["a"]
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_xlabel("x1, the direction of the load (m)")
    ax.set_ylabel("x2 (m)")
    ax.set_title(f"Stick and slip, nu = {run.nu:g}, h = {run.mesh[0]:g}, Q/(mu P) = {m['ratio']:.3f}",
                 fontsize=9)
    ax.legend(fontsize=7, loc="upper right")
    return save_figure(fig, path)


def ring_means(m, width):
    """q1 of rings of the given width about the pole: the sum of the nodal forces T1 over the sum
    of the tributary areas of the nodes in contact in each ring (less noisy than one node)."""
    edges = np.arange(0, m["a"] + width, width)
    centres, means = [], []
    area = m["area"]
    for lo, hi in zip(edges[:-1], edges[1:]):
        ring = m["contact"] & (m["r"] >= lo) & (m["r"] < hi)
        if ring.any():
            centres.append(float(m["r"][ring].mean()))
            means.append(float(m["T1"][ring].sum() / area[ring].sum()))
    return np.array(centres), np.array(means)


def traction_chart(path, run, mu):
    """q1 = T1 / tributary area of the nodes within 10 degrees of the x1 axis, and its ring
    means, against CM's with Hertz's a and p0 of our P (the discrete a, the last node in contact,
    undershoots a by up to a mesh size) and c = a (1 - Q / (mu P))^(1/3)."""
    m = run.m
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    a, p0 = m["hertz"]["a"], m["hertz"]["p0"]
    rr = np.linspace(0, a, 300)
    ax.plot(rr, cattaneo_traction(rr, a, cattaneo_radius(a, m["ratio"]), mu, p0), "k-", lw=1,
            label="Cattaneo-Mindlin (Hertz's a, p0 of our P)")
    ax.plot(rr, mu * p0 * np.sqrt(1 - (rr / a) ** 2), "k:", lw=1, label="mu p (Hertz)")
    picked = {"r": m["r"], "theta": m["theta"], "p": m["q1"]}
    for mask, label, marker, color in ((m["stick"], "ours, stick node", "o", "C0"),
                                       (m["slip"], "ours, slip node", "s", "C3")):
        r, q = radius({**picked, "r": np.where(mask, m["r"], np.nan)}, 0)
        ax.plot(r, q, linestyle="none", marker=marker, color=color, markersize=4,
                fillstyle="none", label=label)
    rc, qc = ring_means(m, mesh_size(run.mesh, m["c_cm"]) / 2)
    ax.plot(rc, qc, "C2^-", markersize=4, lw=1, label="ours, mean over rings")
    ax.set_xlim(0, 1.2 * a)
    ax.set_xlabel("r, nodes within 10 degrees of the x1 axis (m)")
    ax.set_ylabel("tangential traction q1 (GPa)")
    ax.set_title(f"Tangential traction along the load, nu = {run.nu:g}, h = {run.mesh[0]:g}",
                 fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    return save_figure(fig, path)


def parse_runs(info):
    """command.txt's `runs:` line: name h grading nu, separated by ';'."""
    runs = []
    for item in info["runs"].split(";"):
        name, h, grading, nu = item.split()
        runs.append((name, (float(h), float(grading)), float(nu)))
    return runs


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path)
    out = parser.parse_args().out.resolve()
    info = read_command(out, required=("command", "runs"))
    deck = Deck.read(out / "cattaneo_mindlin.template.dat")
    R, E = deck.number("MESH", "R"), deck.number("MATERIAL", "E")
    mu = deck.number("FRICTION", "mu")
    runs = [Run(out, name, mesh, nu, mu, R, E) for name, mesh, nu in parse_runs(info)]
    nu_deck = deck.number("MATERIAL", "nu")
    ladder = sorted((r for r in runs if r.nu == nu_deck), key=lambda r: -r.mesh[0])
    others = {r.mesh for r in runs if r.nu != nu_deck}
    if len(others) != 1:
        raise ReportError(f"{out}: the runs of nu other than {nu_deck:g} are on {len(others)} meshes, "
                          "the trend wants one")
    trend = sorted((r for r in runs if r.mesh in others), key=lambda r: r.nu)
    checks = Checks()
    bad = [r.name for r in runs if not r.converged]
    checks.add("every run converges", not bad, detail="all converge" if not bad else ", ".join(bad))
    done = [r for r in runs if r.converged]
    worst = max(r.m["equilibrium"] for r in done)
    checks.add("contact forces = the clamp's reaction (K u at the top) on every run",
               worst <= FORCE_TOL, ours=f"{worst:.2g} of P", tolerance=f"{FORCE_TOL:g}")
    cone = max(r.m["cone_error"] for r in done)
    checks.add("|T| = mu N on every slip node", cone <= CONE_TOL, ours=f"{cone:.2g}",
               tolerance=f"{CONE_TOL:g}")
    fine = ladder[-1]
    fm = fine.m
    size = mesh_size(fine.mesh, fm["c_cm"])
    checks.add(f"stick radius within {MESH_SIZES} mesh sizes of CM's (nu = {fine.nu:g}, finest mesh)",
               abs(fm["c"] - fm["c_cm"]) <= MESH_SIZES * size,
               ours=f"{fm['c']:.4f}", target=f"{fm['c_cm']:.4f}",
               tolerance=f"{MESH_SIZES} x {size:.3f}")

    title = "Cattaneo-Mindlin: the Hertz half ball sheared (3D)"
    lines = [f"# {title}", "",
             f"Produced by `{info['command']}` on {info.get('date', '?')} ({info.get('host', '?')}, "
             f"revision {info.get('revision', '?')}), its runs in {info.get('seconds', '?')} s; this "
             f"report by `postproc/cattaneo3d_report.py {out}`. Deck: "
             f"`datafiles/scene3d/cattaneo_mindlin.dat` (copy: `cattaneo_mindlin.template.dat`); "
             f"each run's deck is `<run>/cattaneo_mindlin.dat`.", "",
             f"Checks: {checks.summary()}.", "", checks.table().markdown(), "",
             "## The problem", "",
             f"The half ball of the Hertz scene (R = {R:g}, E = {E:g}), Coulomb friction mu = {mu:g} on "
             f"the rigid flat x3 = 0, its flat top clamped and moved by (d_t, 0, -d_n) = "
             f"({deck.value('DIRICHLET', 'ux')}, 0, {deck.value('DIRICHLET', 'uz')}): P and Q "
             f"are the sums of the contact forces (checked against the clamp's reaction K u). One "
             f"static solve under the total displacement: the slip is measured from the reference "
             f"(no load history: sig-solve's LOADSTEPS steps only the finite-strain solve and "
             f"proportionally, sig-march is 2D). Cattaneo-Mindlin: c = a (1 - Q / (mu P))^(1/3) "
             f"with our a (the last node in contact) and our Q / (mu P); q(r) = mu p0 sqrt(1 - r^2/a^2) "
             f"- mu p0 (c/a) sqrt(1 - r^2/c^2) within c, p0 = 3 P / (2 pi a^2).", ""]

    def row(r):
        m = r.m
        if m is None:
            return [r.name, f"{r.mesh[0]:g}, {r.mesh[1]:g}", f"{r.nu:g}", r.dofs, "Nv"] + ["—"] * 8
        return [r.name, f"{r.mesh[0]:g}, {r.mesh[1]:g}", f"{r.nu:g}", r.dofs, r.iterations,
                f"{m['P']:.3f}", f"{m['ratio']:.3f}", f"{m['a']:.4f} ({m['hertz']['a']:.4f})",
                f"{m['c']:.4f} [{m['c_slip_min']:.3f}, {m['c_stick_max']:.3f}]", f"{m['c_cm']:.4f}",
                f"{(m['c'] - m['c_cm']) / mesh_size(r.mesh, m['c_cm']):+.2f}",
                f"{m['stick_centre'][0]:+.3f}, {m['stick_centre'][1]:+.3f}", f"{r.seconds:.2f}"]

    header = ["run", "h, grading", "nu", "dofs", "iterations", "P", "Q/(mu P)", "a (Hertz's of P)",
              "c ours [first slip, last stick]", "c CM", "(c - c CM) / mesh size",
              "stick centroid", "solve s"]
    key_table = Table(header, [row(r) for r in ladder],
                      caption="The mesh ladder: ours against Cattaneo-Mindlin")
    lines += ["## Stick radius on the mesh ladder", "", key_table.markdown(), "",
              "c ours is the radius that best separates the stick nodes from the slip nodes; on an "
              "unstructured surface the edge is ragged: the bracket gives the smallest radius of a "
              "slip node and the largest of a stick node. The mesh size is h + grading x c CM "
              "(meshes/half_ball.geo).", ""]
    stick_slip_chart(out / "stick_slip.png", fine, mu)
    traction_chart(out / "traction.png", fine, mu)
    lines += ["## Stick/slip map and traction profile (finest mesh)", "",
              "![stick and slip](stick_slip.png)", "", "![traction along x1](traction.png)", "",
              "The nodal traction is the nodal tangential force over the node's tributary area: "
              "in the stick zone the nodal values scatter far more than the pressures of the Hertz "
              "report (a stuck node's tangential force is whatever its neighbours' leave, "
              "unbounded by mu N); the ring means (the forces over the areas of the contact nodes "
              "in rings half a mesh size wide) are the comparable quantity. CM's curve uses "
              "Hertz's a and p0 of our P: the last node in contact undershoots a by up to a mesh "
              "size.", ""]
    rows = []
    for r in trend:
        if r.m is None:
            rows.append([f"{r.nu:g}", f"{dundurs_beta(r.nu):.4f}", "Nv"] + ["—"] * 4)
            continue
        m = r.m
        rows.append([f"{r.nu:g}", f"{dundurs_beta(r.nu):.4f}", f"{m['ratio']:.3f}",
                     f"{m['c'] / m['a']:.3f}", f"{m['c_cm'] / m['a']:.3f}",
                     f"{m['c'] / m['c_cm'] - 1:+.1%}",
                     f"{m['stick_centre'][0] / m['a']:+.3f}"])
    trend_table = Table(["nu", "Dundurs beta", "Q/(mu P)", "c/a ours", "c/a CM", "c / c CM - 1",
                         "stick centroid x1 / a"], rows,
                        caption=f"nu trend on the mesh (h, grading) = "
                                f"({trend[0].mesh[0]:g}, {trend[0].mesh[1]:g})" if trend else "")
    low = trend[0]
    if low.m is not None:
        stick_slip_chart(out / "stick_slip_low_nu.png", low, mu)
    lines += ["## How far a rigid flat with nu < 0.5 follows Cattaneo-Mindlin", "",
              trend_table.markdown(), "",
              f"![stick and slip at nu = {low.nu:g}](stick_slip_low_nu.png)" if low.m else "", "",
              "Cattaneo and Mindlin's solution assumes that the normal load makes no tangential "
              "traction: true when Dundurs' beta = 0, for a rigid flat beta = (1 - 2 nu) / "
              "(2 (1 - nu)), zero only at nu = 1/2. With nu < 1/2 the pressure draws the surface of "
              "the ball towards the axis, the flat holds it back, and friction carries an outward "
              "radial traction on the ball that is no part of CM's. Our static solve under the "
              "total displacement (no history) adds it to the shear's (along -x1 on the ball): "
              "they add on the trailing side (x1 < 0), which slips first, and cancel on the "
              "leading one, so the stick zone shrinks and moves towards +x1 (the centroid "
              "column), the more so the larger beta. A load history (the normal load first, its "
              "radial traction and Spence's partial slip set before the shear) is another problem, "
              "not solved here; CM's analysis holds exactly only at beta = 0. P1 tetrahedra lock "
              "as nu tends to 1/2, so nu = 0.45 "
              "(beta = 0.09) is the closest we go; its stick radius is the one checked against CM "
              "above.", ""]

    summary = {"R": R, "E": E, "mu": mu,
               "runs": [{"name": r.name, "mesh": list(r.mesh), "nu": r.nu, "dofs": r.dofs,
                         "converged": r.converged, "iterations": r.iterations,
                         "seconds": r.seconds, "dundurs_beta": dundurs_beta(r.nu),
                         **({k: v for k, v in r.m.items() if not isinstance(v, np.ndarray)}
                            if r.m else {})} for r in runs]}
    return finish_report(out, "\n".join(lines) + "\n", "3d_cattaneo", title, info, checks, summary,
                         key_table=key_table,
                         charts={"stick_slip": "stick_slip.png", "traction": "traction.png",
                                 "stick_slip_low_nu": "stick_slip_low_nu.png"})


if __name__ == "__main__":
    main_guard(main)
