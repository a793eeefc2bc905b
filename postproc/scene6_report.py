#!/usr/bin/env python3
"""Scene 6 report: postproc/scene6_report.py OUTDIR (after drivers/scene6.sh).

Reads the runs of drivers/scene6.sh (case.hist and case.b through sig-dump, the meshes' NOPO,
error.json of sig-error, the Winkler strip of winkler_strip.py) and writes OUTDIR/report.md, its
charts (PNG) and OUTDIR/scene.json:
  - Fig 6.2 (deformed rail and contact forces at t = 0.2, 0.4, 0.6, 0.8), Fig 6.3 (the normal
    pressure along Gamma3 at those times, beside the frictionless march and the static solves),
    Fig 6.4 (psi = 10 vs 200, frictionless, t = 0.5), the statuses per node in space and time;
  - Fig 6.5 (||u - u_hk||_V against h = k against the reference run, at t = T and the maximum
    over the shared time levels, with the slope), the thesis's reference beside ours;
  - the checks of ALGORITHMS.md 3.6 (the Winkler strip, the quasi-static limit), the viscosity
    the thesis neglects, one factorization per march, the convexification per step;
  - speed against accuracy and the stability map of the loop (mesh x k x alpha);
  - the meshes adapted to the whole march against uniform ones, all at k = 0.01 (issue 29):
    errors against overkill references, effectivities, the ratio at equal dofs.
"""
import functools
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from sigreport import (Checks, MapCell, MapPanel, March, Mesh, Point, ReportError,  # noqa: E402
                       Series, Table, find_pvd, fmt, load_thesis, loglog_slope, main_guard,
                       pyplot, read_command, read_deck, read_ds, save_figure,
                       speed_accuracy_chart, stability_map, within, write_report)
from sigreport.adapted import (EFFECTIVITY_RANGE, adapted_figure, corrected,  # noqa: E402
                               per_dof_ratios, read_adapt_csv)
from sigreport.march import read_error  # noqa: E402
from sigreport.table import markdown_table  # noqa: E402
import winkler_strip  # noqa: E402

HIST_ARRAYS = ["converged", "failure", "k", "T", "steps", "time_march", "time_factorize",
               "sparse_factorizations", "dense_factorizations", "newton_iterations",
               "step_converged", "contact_node", "weight", "force_n", "force_t", "velocity_t",
               "normal_status", "friction_status", "output_step", "ndof", "kinetic", "elastic",
               "interface", "compliance_energy", "total", "step_seconds", "step_seconds_contact",
               "step_seconds_right_side"]
LOOP_ARRAYS = ["outer_iterations", "outer_converged", "status_cycle"]
FREE, CN = 0, 1
NONE, STICK, SLIP_PLUS, SLIP_MINUS = 0, 1, 2, 3
FIGURE_TIMES = (0.2, 0.4, 0.6, 0.8)
WINKLER_TOLERANCE = 0.01
QUASISTATIC_TOLERANCE = 0.01
SLOPE, SLOPE_TOLERANCE = 1.0, 0.15
# Fig 6.5's slope is fitted where the mesh resolves the load: edges 2h <= 0.0625 m, at least 1.6
# edges per standard deviation 1 / sqrt(2 psi) = 0.1 m of the Gaussian (h <= 1/32); the coarser
# points are shown with their local slopes.
RESOLVED_N = 32
PSI_64 = (10, 200)  # Fig 6.4's two load widths


class Rail(March):
    """A march of the driver: its deck rail.dat, case.hist (sig-dump, with the convexification
    loop's arrays when the deck has friction), its mesh and error.json."""

    def __init__(self, folder):
        super().__init__(folder, "rail.dat", lambda deck: HIST_ARRAYS + (
            LOOP_ARRAYS if deck.has("FRICTION") else []))
        self.loop = self.deck.has("FRICTION")
        self._mesh = None

    @property
    def mesh(self):
        if self._mesh is None:
            self._mesh = Mesh.read(self.dir / "case.nopo")
        return self._mesh

    def x(self):
        """x1 of the contact nodes."""
        return self.mesh.xy[[n - 1 for n in self.ds["contact_node"]], 0]

    def pressure(self, n):
        return self.rows("force_n")[n] / self.weight

    def energies(self):
        """Per step: 1/2 w.M w, 1/2 u.K u, the foundation's energy and their total. (A case.hist
        written before the one layout of stages/history_io.hpp has the foundation's energy as
        compliance_energy and a total that holds it.)"""
        kinetic, elastic = self.ds.array("kinetic"), self.ds.array("elastic")
        if "interface" in self.ds:
            stored = self.ds.array("interface")
            total = self.ds.array("total") + stored
        else:
            stored, total = self.ds.array("compliance_energy"), self.ds.array("total")
        return {"kinetic": kinetic, "elastic": elastic, "foundation": stored, "total": total}

    def traction(self, n):
        return self.rows("force_t")[n] / self.weight

    def outer(self):
        return self.ds.array("outer_iterations")[1:] if self.loop else None

    def cycles(self):
        return int(sum(1 for c in self.ds["status_cycle"][1:] if c > 0)) if self.loop else 0

    def counts(self, n):
        normal, friction = self.rows("normal_status")[n], self.rows("friction_status")[n]
        return {"free": int((normal == FREE).sum()), "CN": int((normal == CN).sum()),
                "S=": int((friction == STICK).sum()), "S+": int((friction == SLIP_PLUS).sum()),
                "S-": int((friction == SLIP_MINUS).sum())}


class Scene:
    """OUT of drivers/scene6.sh: command.txt, the marches (each read once), the checks and
    charts the sections add."""

    def __init__(self, out):
        self.out = Path(out)
        self.info = read_command(out, required=("command", "quick", "figure_n", "reference_n"))
        self.quick = self.info["quick"] == "1"
        self.figure_n = int(self.info["figure_n"])
        self.reference_n = int(self.info["reference_n"])
        self.thesis = load_thesis().scene("6")
        self.checks, self.charts = Checks(), {}

    @functools.cache
    def march(self, name):
        return Rail(self.out / name)

    @property
    def friction(self):
        return self.march("figs/friction")

    @property
    def frictionless(self):
        return self.march("figs/frictionless")

    @property
    def reference(self):
        return self.march(f"convergence/n{self.reference_n}")

    def fig64(self):
        return [self.march(f"figs/psi{psi}") for psi in PSI_64]

    def shown(self):
        """The steps of the figures' times that the friction march reached."""
        friction = self.friction
        return [n for n in (friction.step(t) for t in FIGURE_TIMES) if n <= friction.steps_done()]

    def thesis_reference(self):
        """The thesis's "dofs/CPU s" of its reference run (None when absent)."""
        return self.thesis.get("reference", "h=k=1/256 dofs/cpu")


def section(title):
    return ["", f"## {title}", ""]


# --- Figures -----------------------------------------------------------------------------------

def draw_rail(ax, run, n, title, force_scale, bottom):
    """The deformed rail at step n (amplification 1), its contact forces on the body per unit
    length ((-T, N) / w at the deformed bottom nodes) and the foundation's surface, down to
    x2 = bottom."""
    import numpy as np
    from matplotlib.collections import LineCollection
    xy = run.mesh.xy + run.u(n).reshape(-1, 2)
    ax.tripcolor(xy[:, 0], xy[:, 1], run.mesh.tri, facecolors=np.zeros(len(run.mesh.tri)),
                 cmap="Greys", vmin=-1, vmax=4, edgecolors="none")
    ax.add_collection(LineCollection([xy[list(e)] for e in run.mesh.boundary()], colors="0.2",
                                     linewidths=0.8))
    ax.axhline(0, color="k", lw=0.6, ls=":")
    nodes = [c - 1 for c in run.ds["contact_node"]]
    p, t = run.pressure(n), run.traction(n)
    on = p > 1e-12 * max(1.0, float(np.max(np.abs(p))))
    every = max(1, len(nodes) // 64)  # at most 64 arrows
    on[np.arange(len(on)) % every != 0] = False
    ax.quiver(xy[nodes, 0][on], xy[nodes, 1][on], -t[on], p[on], angles="xy", scale_units="xy",
              scale=force_scale / 0.25, width=0.003, color="C3")
    ax.set_xlim(-0.05, 2.05)
    ax.set_ylim(bottom, 0.3)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=8)
    ax.set_xlabel("x1 (m)", fontsize=8)
    ax.set_ylabel("x2 (m)", fontsize=8)


def rail_figure(path, panels, suptitle):
    """Two panels a row, one per (run, step, title): the deformed rails on one force scale."""
    import numpy as np
    scale = max(float(np.max(np.hypot(r.pressure(n), r.traction(n)))) for r, n, _ in panels)
    # One vertical range for every panel, the deepest deflection in view (psi = 10 sinks 0.78 m).
    bottom = min(-0.75, min(float(np.min(r.mesh.xy[:, 1] + r.u(n).reshape(-1, 2)[:, 1]))
                            for r, n, _ in panels) - 0.05)
    rows = (len(panels) + 1) // 2
    fig, axes = pyplot().subplots(rows, 2, figsize=(11, 3.0 * rows + 0.5), squeeze=False)
    for ax, (run, n, title) in zip(axes.flat, panels):
        draw_rail(ax, run, n, title, scale, bottom)
    for ax in list(axes.flat)[len(panels):]:
        ax.axis("off")
    fig.suptitle(suptitle + f" (arrows: contact force per unit length, {fmt(scale, 3)} GPa = "
                 "0.25 m)", fontsize=8)
    fig.tight_layout()
    return save_figure(fig, path).name


def plot_figure(path, figsize, xlabel, ylabel, title, draw, title_size=8, legend=None,
                grid=True):
    """One axes: draw(ax) plots on it; the labels, title, legend (legend() keywords, fontsize
    7) and grid, and the PNG's name."""
    fig, ax = pyplot().subplots(figsize=figsize)
    draw(ax)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=title_size)
    ax.legend(fontsize=7, **(legend or {}))
    if grid:
        ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    return save_figure(fig, path).name


def pressure_figure(path, curves, title):
    """p(x) along Gamma3: curves = [(x, p, label, style)]."""
    def draw(ax):
        for x, p, label, style in curves:
            ax.plot(x, p, style, label=label, lw=1.2, ms=3)
    return plot_figure(path, (7.5, 3.4), "x1 (m)", "normal pressure p(u_nu) (GPa)", title, draw,
                       title_size=9, legend={"ncol": 2})


def status_figure(path, run):
    """Every contact node's status at every step: x1 against t, colour by (normal, friction)."""
    import numpy as np
    from matplotlib.colors import ListedColormap
    normal, friction = run.rows("normal_status")[1:], run.rows("friction_status")[1:]
    code = np.where(normal == FREE, 0, 1 + np.where(friction == STICK, 0,
                                                      np.where(friction == SLIP_PLUS, 1, 2)))
    order = np.argsort(run.x())
    names = ["free", "CN/S=", "CN/S+", "CN/S-"]
    colours = ["#eeeeee", "#2c7bb6", "#d7191c", "#fdae61"]

    def draw(ax):
        t_end = run.k * code.shape[0]
        ax.imshow(code[:, order].T, origin="lower", aspect="auto", interpolation="nearest",
                  cmap=ListedColormap(colours), vmin=-0.5, vmax=3.5,
                  extent=[0.5 * run.k, t_end + 0.5 * run.k, run.x()[order][0],
                          run.x()[order][-1]])
        ax.plot([0, 1], [0, 2], "k--", lw=0.8, label="load centre x = c t")
        for name, colour in zip(names, colours):
            ax.plot([], [], "s", color=colour, label=name)
    return plot_figure(path, (7.5, 3.6), "t (s)", "x1 of the contact node (m)",
                       "Statuses per node and step (figs/friction): normal free / CN, friction "
                       "S= / S+ / S-", draw, legend={"loc": "upper left", "ncol": 5}, grid=False)


def loop_figure(path, runs):
    """Convexification outer iterations and Newton iterations per step."""
    fig, axes = pyplot().subplots(1, 2, figsize=(9, 3.2))
    for run, label in runs:
        t = [run.k * (i + 1) for i in range(run.steps_done())]
        axes[0].plot(t, run.outer(), lw=0.9, label=label)
        axes[1].plot(t, run.ds["newton_iterations"][1:], lw=0.9, label=label)
    axes[0].set_ylabel("convexification loop (iterations)")
    axes[1].set_ylabel("Newton, all convex solves (iterations)")
    for ax in axes:
        ax.set_xlabel("t (s)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Per time step: the loop's count and its inner Newton iterations", fontsize=9)
    fig.tight_layout()
    return save_figure(fig, path).name


def energy_figure(path, run):
    def draw(ax):
        t = [run.k * i for i in range(run.steps_done() + 1)]
        for name, values in run.energies().items():
            ax.plot(t, values, label=name, lw=1.0)
        ax.set_yscale("symlog", linthresh=1e-6)
    return plot_figure(path, (7.5, 3.0), "t (s)", "energy per m of thickness (GJ/m)",
                       "Energies of the march (figs/friction): 1/2 w.M w, 1/2 u.K u, the "
                       "foundation's, total", draw)


def convergence_figure(path, rows, fit_n, reference_n):
    def draw(ax):
        h = [1 / n for n, _, _ in rows]
        ax.loglog(h, [e for _, e, _ in rows], "o-", label="||u - u_hk||_V at t = T")
        ax.loglog(h, [m for _, _, m in rows], "s-", label="max over the shared time levels")
        fit = [(1 / n, m) for n, _, m in rows if n >= fit_n]
        if len(fit) >= 2:
            s = loglog_slope([a for a, _ in fit], [b for _, b in fit])
            h0, e0 = fit[-1]
            ax.loglog([fit[0][0], h0], [e0 * (fit[0][0] / h0) ** s, e0], "k--", lw=0.8,
                      label=f"fit h <= 1/{fit_n}: slope {s:.2f}")
            ax.loglog([fit[0][0], h0], [0.5 * e0 * (fit[0][0] / h0), 0.5 * e0], "k:", lw=0.8,
                      label="slope 1")
    return plot_figure(path, (6.0, 4.2), "mesh size h (m)", "||eps(u_ref - P u_hk)||_L2 (m)",
                       f"Fig 6.5: error against h, time step k = h, reference h = k = "
                       f"1/{reference_n}", draw, title_size=9)



# --- Sections ----------------------------------------------------------------------------------

def section_head(scene):
    info = scene.info
    quick = " (quick)" if scene.quick else ""
    return [f"# Scene 6: viscoelastodynamic rail under a moving load{quick}",
            "",
            f"Command: `{info['command']}` ({info.get('seconds', '?')} s of runs); report: "
            "`postproc/scene6_report.py`. Thesis ch. 6.4 (l.12411-12660), SCENES.md \"Scene 6\", "
            "ALGORITHMS.md 3.",
            "",
            "**What is modelled and why.** A rail, the strip (0, 2) x (0, 0.1) m, clamped at both "
            "ends, in 2D plane strain and small strain (the thesis's model, ALGORITHMS.md C2), with "
            "inertia (rho = 1000 kg/m^3, i.e. 1e-6 GPa s^2/m^2 in the deck's GPa and m: 1000 with "
            "GPa would inflate the inertia 1e9 times), E = 100 GPa, nu = 0.3, on a compliant "
            "foundation p = min(cn [u_nu]+, c3), cn = 10 GPa/m, c3 = 1e8 (never reached), with "
            "the nonmonotone friction of the slip rate mu(r) = (a - b) exp(-alpha r) + b, a = 1, "
            "b = 0.5, alpha = 2000 s/m, under the Gaussian load (0, -F exp(-psi (x - c t)^2)), "
            "F = 10 GPa, psi = 50 m^-2 (printed m^-1), c = 2 m/s, T = 1 s. Marched by backward "
            "Euler in velocity (6.63)-(6.66), the step matrix M/k + k K factorized and condensed "
            "onto Gamma3 once, the convexification loop in every step (mu frozen at the previous "
            "iterate's slip rate, from the previous step's: ALGORITHMS.md 3.3, C12). "
            "**Viscosity:** none (C = 0), as the thesis (l.12475); the variant below with a "
            "small Kelvin-Voigt viscosity changes nothing visible. **Mesh:** \"Gamma divided into "
            "1/h parts\" on every side (l.12621): 1/h x 1/h cells of 2h x 0.1h, aspect ratio 20, "
            "two triangles each, what the thesis's 132610 dofs at h = 1/256 imply (2 x 257^2 "
            "displacement dofs + 2 x 256 multipliers). The moving load is integrated on each "
            "edge by 3-point Gauss on pieces of at most 1/(2 sqrt(psi)) (C11).",
            "",
            f"Figures at h = 1/{scene.figure_n}, k = 0.01 (so that t = 0.2 ... 0.8 and 0.5 are steps; "
            "the thesis gives neither h nor k for them). Every choice is a comment in "
            "`datafiles/scene6/rail.dat`."]


def section_winkler(scene):
    out = scene.out
    strip_table = Table(["psi (m^-2)", "bottom deflection (m)", "top deflection (m)",
                         "peak pressure (GPa)", "largest difference"],
                        caption="The rail, static, on bilateral springs (CONTACT "
                                "law=compliance-bilateral), load held at x0 = 1: ours (the "
                                "semi-analytic infinite strip of postproc/winkler_strip.py)")
    for psi in (10, 50, 200):
        run = out / "winkler" / f"psi{psi}"
        r = winkler_strip.compare(run / "rail.dat", run)
        worst = max(abs(v["relative"]) for v in r.values())
        strip_table.add(psi, *[f"{fmt(r[q]['ours'], 5)} ({fmt(r[q]['strip'], 5)})"
                               for q in ("bottom_deflection", "top_deflection", "peak_pressure")],
                        f"{100 * worst:.2f} %")
        scene.checks.add(f"Winkler strip at psi = {psi} within 1 %", worst <= WINKLER_TOLERANCE,
                         ours=f"{100 * worst:.2f} %", target="0", tolerance="1 %",
                         detail="bottom and top deflections and the spring pressure under the load")
    ny = read_deck(out / "winkler" / "psi50" / "rail.dat").number("MESH", "ny")
    return section("Check: the bilateral Winkler strip (ALGORITHMS.md 3.6 check 2)") + [
        strip_table.markdown(), "",
        f"Mesh 256 x {int(ny)} cells. The strip is infinite and its springs pull; the rail is "
        "clamped 1 m from the load: the difference left is that and the mesh. ALGORITHMS.md's "
        "[check] table gives 0.78062 / 0.46364 / 0.25306 m at the bottom, as our "
        "Fourier solution (`postproc/winkler_strip.py --psi 50`)."]


def peak_follows_load(friction, shown):
    """Whether the pressure peak is within 0.15 m of the load centre c t at every shown step."""
    return all(abs(float(friction.x()[int(friction.pressure(n).argmax())]) - 2 * n * friction.k)
               <= 0.15 for n in shown)


def status_counts(friction, shown):
    counts = Table(["t (s)", "free", "CN", "S=", "S+", "S-", "pressure peak at x1 (m)",
                    "load centre c t (m)", "convexification iterations"],
                   caption="Statuses of the 1/h - 1 contact nodes (figs/friction)")
    for n in shown:
        c = friction.counts(n)
        x_peak = float(friction.x()[int(friction.pressure(n).argmax())])
        counts.add(f"{n * friction.k:g}", c["free"], c["CN"], c["S="], c["S+"], c["S-"],
                   fmt(x_peak, 3), fmt(2 * n * friction.k, 3), int(friction.outer()[n - 1]))
    return counts


def section_figs62_63(scene):
    friction, frictionless, out = scene.friction, scene.frictionless, scene.out
    shown = scene.shown()
    lines = section("Figs 6.2 and 6.3: the rail and the normal force at t = 0.2, 0.4, 0.6, 0.8")
    if not friction.converged:
        lines.append(f"**The march stopped (Nv):** {friction.failure}")
    scene.charts["fig62"] = rail_figure(
        out / "fig62_rail.png", [(friction, n, f"t = {n * friction.k:g} s") for n in shown],
        "Fig 6.2: deformed rail (x 1) and contact forces on Gamma3, friction")
    curves = []
    for i, n in enumerate(shown):
        curves.append((friction.x(), friction.pressure(n), f"t = {n * friction.k:g} friction",
                       f"C{i}-"))
        if n <= frictionless.steps_done():
            curves.append((frictionless.x(), frictionless.pressure(n), "frictionless", f"C{i}--"))
    scene.charts["fig63"] = pressure_figure(out / "fig63_pressure.png", curves,
                                            "Fig 6.3: normal pressure along Gamma3 (solid: "
                                            "friction, dashed: frictionless)")
    scene.checks.add("the contact forces follow the load (Fig 6.2: the pressure peak within "
                     "0.15 m of x = c t at t = 0.2 ... 0.8)",
                     peak_follows_load(friction, shown) and len(shown) == len(FIGURE_TIMES),
                     detail="significant forces only under the moving mass, left to right")
    scene.charts["statuses"] = status_figure(out / "statuses.png", friction)
    return lines + [
        f"![Fig 6.2]({scene.charts['fig62']})", "", f"![Fig 6.3]({scene.charts['fig63']})", "",
        status_counts(friction, shown).markdown(), "",
        f"![statuses]({scene.charts['statuses']})", "",
        "The ParaView time series `figs/friction/rail.pvd` (every other step) carries the "
        "displacement, the velocity, the contact pressure, the tangential pressure and the "
        "statuses (normal_status 0 free / 1 CN, friction_status 1 S= / 2 S+ / 3 S-) as point "
        "data: `paraview out/scene6/figs/friction/rail.pvd`, Warp By Vector."]


def section_fig64(scene):
    fig64 = scene.fig64()
    n05 = fig64[0].step(0.5)
    scene.charts["fig64"] = rail_figure(scene.out / "fig64_psi.png",
                                        [(r, n05, f"psi = {psi}, t = 0.5 s")
                                         for r, psi in zip(fig64, PSI_64)],
                                        "Fig 6.4: deformed rail and contact forces")
    scene.charts["fig64_pressure"] = pressure_figure(
        scene.out / "fig64_pressure.png",
        [(r.x(), r.pressure(n05), f"psi = {psi}", f"C{i}-")
         for i, (r, psi) in enumerate(zip(fig64, PSI_64))],
        "Fig 6.4: normal pressure along Gamma3 at t = 0.5 (frictionless)")
    return section("Fig 6.4: psi = 10 and psi = 200, frictionless, t = 0.5") + [
        f"![Fig 6.4]({scene.charts['fig64']})", "",
        f"![Fig 6.4 pressure]({scene.charts['fig64_pressure']})", "",
        "A larger psi is a shorter mass: a narrower, shorter bell (the thesis's reading)."]


def section_quasistatic(scene):
    frictionless = scene.frictionless
    qs = Table(["t (s)", "||u_dyn - u_static||_V / ||u_static||_V", "max |p_dyn - p_static| / "
                "max p_static", "static solve iterations"],
               caption="The frictionless march against static solves with the load held at "
                       "x0 = c t (same mesh)")
    worst_qs = 0.0
    for t in FIGURE_TIMES:
        ds = read_ds(scene.out / "quasistatic" / f"t{t}" / "case.b",
                     arrays=["u", "multiplier", "iterations", "converged"])
        n = frictionless.step(t)
        u_dyn, u_static = frictionless.u(n), ds.array("u")
        rel = frictionless.mesh.strain_norm(u_dyn - u_static) / \
            frictionless.mesh.strain_norm(u_static)
        p_static = ds.array("multiplier") / frictionless.weight
        rel_p = float(abs(frictionless.pressure(n) - p_static).max() / p_static.max())
        worst_qs = max(worst_qs, rel, rel_p)
        qs.add(t, f"{rel:.2e}", f"{rel_p:.2e}", int(ds.scalar("iterations")))
    scene.checks.add("quasi-static limit: the frictionless march equals the static solves at "
                     "t = 0.2 ... 0.8 (well under 1 %)", worst_qs <= QUASISTATIC_TOLERANCE,
                     ours=f"{100 * worst_qs:.1e} %", target="0", tolerance="1 %")
    return section("Check: the quasi-static limit (ALGORITHMS.md 3.6 check 1)") + [
        qs.markdown(), "",
        "The rail's first vibration (foundation mode sqrt(cn / (rho l)) = 1e4 rad/s, waves at "
        "~1e4 m/s) is far faster than the load (0.1 m at 2 m/s: 0.05 s): at every t the "
        "dynamic rail is the static one to O((omega tau)^-2), and backward Euler damps the "
        "start-up transient."]


def section_viscosity(scene):
    kv, friction = scene.march("viscosity/kv"), scene.friction
    visc = read_deck(kv.dir / "rail.dat").card("MATERIAL").fields
    worst_v = 0.0
    for n in kv.states()[1][1:]:
        if n in friction.states()[1]:
            diff = kv.mesh.strain_norm(kv.u(n) - friction.u(n)) / kv.mesh.strain_norm(friction.u(n))
            worst_v = max(worst_v, diff)
    scene.checks.add("a small viscosity changes nothing visible (< 1 % in ||.||_V)",
                     worst_v <= 0.01, ours=f"{100 * worst_v:.3f} %", tolerance="1 %")
    return section("The viscosity the thesis neglects") + [
        f"A Kelvin-Voigt viscosity eta1 = {visc.get('eta1')}, eta2 = {visc.get('eta2')} GPa s "
        "(MATERIAL law=kelvin-voigt; C in the step matrix M/k + C + k K) changes the "
        f"displacement by at most {100 * worst_v:.3f} % in ||.||_V over the kept states "
        "(every 0.1 s): nothing visible at the figures' scale."]


def convergence_runs(scene, prefix="n"):
    """The marches convergence/<prefix><n> but the reference, by n: [(n, Rail)]."""
    folders = [(int(p.name[len(prefix):]), p)
               for p in (scene.out / "convergence").glob(f"{prefix}*")
               if p.name[len(prefix):].isdigit()]
    return [(n, scene.march(f"convergence/{p.name}")) for n, p in sorted(folders)
            if n != scene.reference_n]


def fig65_rows(scene):
    """Fig 6.5's table, and its rows (n, error at T, max over t) of the converged runs."""
    reference_n = scene.reference_n
    rows, table = [], Table(["h = k", "dofs", "||u - u_hk||_V at T", "max over t",
                             "local slope (max)", "relative at T", "march (s)",
                             "convexification per step (mean / max)"],
                            caption=f"Against h = k = 1/{reference_n}, the reference")
    for n, run in convergence_runs(scene):
        e = run.error()
        if e is None or not run.converged:
            table.add(f"1/{n}", run.ds.scalar("ndof"), "Nv", "Nv", "", "", fmt(run.seconds(), 3),
                      "")
            continue
        local = loglog_slope([1 / rows[-1][0], 1 / n], [rows[-1][2], e["max_error"]]) \
            if rows else None
        rows.append((n, e["error"], e["max_error"]))
        outer = run.outer()
        table.add(f"1/{n}", run.ds.scalar("ndof"), fmt(e["error"], 4), fmt(e["max_error"], 4),
                  fmt(local, 3), fmt(e["relative"], 3), fmt(run.seconds(), 3),
                  f"{outer.mean():.1f} / {int(outer.max())}")
    return table, rows


def fit_slopes(rows):
    """The slopes of the maximum over t and of the error at T on the resolved meshes."""
    fit = [(1 / n, m) for n, _, m in rows if n >= RESOLVED_N]
    if len(fit) < 2:
        return None, None
    return (loglog_slope([a for a, _ in fit], [b for _, b in fit]),
            loglog_slope([1 / n for n, _, _ in rows if n >= RESOLVED_N],
                         [e for n, e, _ in rows if n >= RESOLVED_N]))


def fig65_check(scene, fit_slope):
    if scene.quick:
        coarsest = max(n for n, _ in convergence_runs(scene))
        scene.checks.add("Fig 6.5 slope 1 +- 0.15", None,
                         detail=f"quick: h = k >= 1/{coarsest} against 1/{scene.reference_n}, "
                                f"slope {fmt(fit_slope, 3)} (indicative only)")
    else:
        scene.checks.add(f"Fig 6.5 slope 1 +- 0.15 (max over t, h <= 1/{RESOLVED_N})",
                         fit_slope is not None and within(fit_slope, SLOPE, abs=SLOPE_TOLERANCE),
                         ours=fmt(fit_slope, 3), target="1", tolerance="0.15")


def section_fig65(scene):
    reference, reference_n = scene.reference, scene.reference_n
    table, rows = fig65_rows(scene)
    fit_slope, fit_slope_T = fit_slopes(rows)
    scene.charts["fig65"] = convergence_figure(scene.out / "fig65_error.png", rows, RESOLVED_N,
                                               reference_n)
    fig65_check(scene, fit_slope)
    return section("Fig 6.5: the error against h = k") + [
        table.markdown(), "", f"![Fig 6.5]({scene.charts['fig65']})", "",
        f"The reference h = k = 1/{reference_n}: {int(reference.ds.scalar('ndof'))} displacement "
        f"dofs ({reference.p} contact nodes; the thesis counts 132610 = 2 x 257^2 + 2 x 256 with "
        f"its multiplier nodes), its march {fmt(reference.seconds(), 3)} s here (setup "
        f"{fmt(reference.ds.scalar('time_factorize'), 3)} s, "
        f"{int(reference.ds.scalar('sparse_factorizations'))} sparse factorization); "
        f"the thesis: {scene.thesis_reference()} (dofs / CPU s).",
        "",
        f"Slope of the maximum over t, fitted on h <= 1/{RESOLVED_N} (where the edges, 2h <= "
        "0.0625 m, resolve the Gaussian of standard deviation 0.1 m): "
        f"{fmt(fit_slope, 3)}; of the error at t = T: {fmt(fit_slope_T, 3)}. The coarser "
        "points cannot carry the load's shape (at most a few edges under the mass): their "
        "local slopes rise from about 0 towards 1 and they are shown, not fitted. A reference "
        "only twice finer than the finest run makes that run's error look smaller (against "
        "the exact solution e(h) - e(h/2) is e(h) / 2 at slope 1), which steepens the last "
        "local slope. The error is taken at the shared time levels of each run and the "
        "reference (multiples of 1/16, or every step of the coarser runs): ALGORITHMS.md 0.6; "
        "the maximum over t is Theorem 6.7's measure (l.11758)."]


def section_loop(scene):
    friction, reference = scene.friction, scene.reference
    scene.charts["loop"] = loop_figure(scene.out / "loop_counts.png",
                                       [(friction, f"h = 1/{scene.figure_n}, k = 0.01"),
                                        (reference, f"h = k = 1/{scene.reference_n}")])
    outer = friction.outer()
    converged = all(friction.ds["outer_converged"][1:])
    scene.checks.add("the convexification loop converges in every step (figs/friction)",
                     friction.converged and converged, ours=f"{int(outer.max())} at most",
                     detail="mu frozen at the previous iterate's slip rate, eps = 1e-5")
    scene.charts["energy"] = energy_figure(scene.out / "energy.png", friction)
    marches = [friction, scene.frictionless, scene.march("viscosity/kv"), reference] + \
        scene.fig64()
    scene.checks.add("one sparse factorization for each march",
                     all(int(r.ds.scalar("sparse_factorizations")) == 1 for r in marches),
                     detail="M/k + k K factorized and condensed onto Gamma3 once")
    return section("The convexification loop per time step") + [
        f"![loop]({scene.charts['loop']})", "",
        f"figs/friction: {int(outer.sum())} convex solves in {friction.steps_done()} steps "
        f"(mean {outer.mean():.2f}, at most {int(outer.max())}), "
        f"{int(sum(friction.ds['newton_iterations']))} Newton iterations; every step's loop "
        f"{'converged' if converged else 'did NOT converge'} "
        f"(eps = 1e-5 on the contact nodes' velocities and the tractions, at most 200); "
        f"status cycles: {friction.cycles()}.", "", f"![energy]({scene.charts['energy']})"]


def section_speed(scene):
    series = []
    for label, prefix, colour in (("pdas", "n", "C0"), ("alm", "alm_n", "C1")):
        points = []
        for n, run in convergence_runs(scene, prefix):
            e = run.error()
            points.append(Point(run.seconds(), e["max_error"] if e and run.converged else None,
                                f"1/{n}"))
        if points:
            series.append(Series(f"{label}, h = k", points, color=colour))
    scene.charts["speed_accuracy"] = speed_accuracy_chart(
        scene.out / "speed_accuracy.png", series, xlabel="sig-march setup + march (s)",
        ylabel="max over t of ||u - u_hk||_V (m)",
        title="Scene 6: speed against accuracy").name
    return section("Speed against accuracy") + [
        f"![speed against accuracy]({scene.charts['speed_accuracy']})", "",
        "Each point a run of Fig 6.5 (h = k, friction), labelled by h; the time is sig-march's "
        "setup (frames, one sparse factorization with the Schur complement onto Gamma3, the "
        "dense Cholesky) and its march, every step included."]


def stability_cell(scene, m, a, kk, stab, failures):
    """A cell of the stability map, its row of the table and its failure."""
    folder = scene.out / "stability" / f"n{m}_k{kk}_a{a:g}"
    if not (folder / "case.hist").is_file():
        return MapCell("missing", "missing")
    run = scene.march(folder.relative_to(scene.out).as_posix())
    o, cyc = run.outer(), run.cycles()
    status = "ok" if run.converged else "Nv"
    if cyc:
        status = "chatter" if run.converged else "Nv+chatter"
    text = f"{o.mean():.1f}/{int(o.max())}" if run.converged else f"Nv @{run.steps_done()}"
    stab.add(f"{m} x {m}", f"1/{kk}", f"{a:g}", f"{run.steps_done()}/{kk}",
             f"{o.mean():.2f} / {int(o.max())}", int(max(run.ds["newton_iterations"][1:])), cyc,
             "converged" if run.converged else f"Nv: {run.failure[:80]}")
    if not run.converged:
        failures.append(f"{m} x {m}, k = 1/{kk}, alpha = {a:g}")
    return MapCell(text, status, float(o.max()))


STABILITY_WHY = (
    "The fixed point converged in every step of every run of the map, alpha = 2000 "
    "included: with slip rates of the order of 1 m/s under the moving load, "
    "alpha r >> 1 at the slipping nodes (mu = b, the flat tail of (6.90)) and the "
    "sticking nodes sit at mu = a; the contraction is slowest where alpha r ~ 1, "
    "i.e. for small alpha (2 to 200 s/m), which needs the most convex solves per "
    "step. Stick-slip cycles are detected (status_cycle) and reported as such; none "
    "was met. The small-slope condition (4.20) in the slip rate, p0 m_mu + mu0 L_p < "
    "alpha0, bounds alpha (a - b) exp(-alpha r) at the nodes' actual slip rates, not "
    "at r = 0.")


def section_stability(scene):
    panels, stab = [], Table(["mesh", "k", "alpha", "steps", "convex solves per step (mean / max)",
                              "Newton per step (max)", "status cycles", "result"],
                             caption="Every run of the map")
    names = [p.name.split("_") for p in (scene.out / "stability").iterdir()]
    meshes = sorted({int(n[0][1:]) for n in names})
    ks = sorted({int(n[1][1:]) for n in names})
    alphas = sorted({float(n[2][1:]) for n in names})
    failures = []
    for m in meshes:
        cells = [[stability_cell(scene, m, a, kk, stab, failures) for kk in ks] for a in alphas]
        panels.append(MapPanel(f"mesh {m} x {m}", [f"{a:g}" for a in alphas],
                               [f"1/{kk}" for kk in ks], cells, xlabel="time step k (s)",
                               ylabel="alpha (s/m)"))
    scene.charts["stability"] = stability_map(
        scene.out / "stability.png", panels, value_label="max convex solves per step (iterations)",
        title="Convexification per step (mean/max): where the fixed point contracts").name
    return section("Stability of the convexification loop: mesh x k x alpha") + [
        f"![stability]({scene.charts['stability']})", "", stab.markdown(), "",
        ("The fixed point fails (Nv) at: " + "; ".join(failures) + ".") if failures
        else STABILITY_WHY]


def section_beside_thesis(scene):
    """What the thesis prints (counts and slopes) and draws, beside ours."""
    friction, reference, reference_n = scene.friction, scene.reference, scene.reference_n
    shown, fig64 = scene.shown(), scene.fig64()
    n05 = fig64[0].step(0.5)
    fit_slope, fit_slope_T = fit_slopes(fig65_rows(scene)[1])
    peaks = [float(friction.pressure(n).max()) for n in shown]
    spans = []
    for n in shown:
        on = friction.x()[friction.pressure(n) > 0]
        spans.append(f"[{on.min():.2f}, {on.max():.2f}]" if len(on) else "none")
    bell = [(float(r.pressure(n05).max()), float(sum(r.weight[r.pressure(n05) > 0])))
            for r in fig64]
    side = Table(["item", "thesis", "ours"])
    side.add("Fig 6.2: contact forces", "significant only under the mass, moving left to right "
             "(drawn)", "contact zone " + ", ".join(f"t = {n * friction.k:g}: {z}"
                                                    for n, z in zip(shown, spans)) + " m")
    side.add("Fig 6.3: normal force on Gamma3", "four bell-shaped curves following the mass "
             "(drawn, no values)", "bells peaking at " + ", ".join(fmt(v, 3) for v in peaks) +
             (" GPa, the peak within 0.15 m of c t" if peak_follows_load(friction, shown) else
              " GPa, the peak NOT within 0.15 m of c t at every time"))
    side.add("Fig 6.4: psi = 10 against 200", "larger psi: a narrower, shorter mass (drawn)",
             f"peak {fmt(bell[0][0], 3)} against {fmt(bell[1][0], 3)} GPa, contact length "
             f"{fmt(bell[0][1], 3)} against {fmt(bell[1][1], 3)} m")
    side.add("Fig 6.5: slope of ||u - u_hk||_V", "1", f"{fmt(fit_slope, 3)} (max over t, "
             f"h <= 1/{RESOLVED_N}); {fmt(fit_slope_T, 3)} at t = T")
    thesis_dofs, thesis_cpu = (scene.thesis_reference() or "?/?").split("/")
    side.add(f"reference h = k = 1/{reference_n}: dofs", f"{thesis_dofs} (2 x 257^2 + 2 x 256)",
             f"{int(reference.ds.scalar('ndof'))} displacement dofs + {reference.p} contact nodes")
    side.add(f"reference h = k = 1/{reference_n}: time", f"{thesis_cpu} s CPU",
             f"{fmt(reference.seconds(), 3)} s wall (this run, shared machine; "
             "drivers/bench-scene6.sh measures it quiet)")
    return section("The thesis beside ours") + [
        side.markdown(), "",
        "The thesis prints no error value, force or status count for scene 6: beside its "
        "slope and its reference run there are only its drawings, against which ours are "
        "read (the same shapes; its mesh and step for Figs 6.2-6.4 are not stated)."]


def study_mesh(folder, judged=True):
    """A mesh of the adapted study: dofs, eta at t = T (estimate_T) and its maximum over the kept
    times (estimate; case.est) and, when `judged`, sig-error's error at t = T (error_T) and its
    maximum over the shared times (error; error.json against the mesh's reference)."""
    path = folder / "case.est"
    if not path.is_file():
        raise ReportError(f"{path}: missing (sig-estimate)")
    est = read_ds(path, arrays=["dofs", "estimate", "estimate_max", "estimates", "times"])
    mesh = {"dofs": int(est.scalar("dofs")), "estimate_T": est.scalar("estimate"),
            "estimate": est.scalar("estimate_max"), "estimates": est["estimates"],
            "times": est["times"]}
    if judged:
        e = read_error(folder)
        if e is None:
            raise ReportError(f"{folder}/error.json: missing (sig-error)")
        mesh.update({"error": e["max_error"], "error_T": e["error"],
                     "effectivity": mesh["estimate"] / e["max_error"],
                     "effectivity_T": mesh["estimate_T"] / e["error"]})
    return mesh


def gamma3_per_quarter(folder):
    """The Gamma3 (x2 = 0) nodes of a mesh on each quarter of the rail."""
    import numpy as np
    xy = Mesh.read(folder / "case.nopo").xy
    return np.histogram(xy[np.abs(xy[:, 1]) < 1e-12, 0], bins=[0, 0.5, 1, 1.5, 2 + 1e-9])[0]


def section_adapted(scene):
    """Issue 29: the meshes adapted to the whole march against the scene's uniform N x N meshes
    (checked: no worse per dof) and against the start mesh refined uniformly (shown), all at
    k = 0.01; the effectivities of every mesh of the study (checked)."""
    folder, info = scene.out / "adapted", scene.info
    title = section("Adapted meshes against uniform ones (issue 29)")
    if not (folder / "adapt.csv").is_file():
        return title + ["Not run (no adapted/adapt.csv: an output of drivers/scene6.sh before "
                        "the adapted study)."]
    steps = read_adapt_csv(folder)
    for s in steps:
        s.update(study_mesh(folder / f"step{s['step']}"))
    overkill = study_mesh(folder / "overkill2", judged=False)
    overkill1 = read_error(folder / "overkill1") or {}
    u_ref, m_ref = info["adapt_uniform_reference"], info["adapt_start_reference"]
    nx, ny = (int(v) for v in info["adapt_start"].split())
    uniform = [dict(study_mesh(folder / f"uniform/n{n}"), name=f"{n} x {n}")
               for n in info["adapt_uniform_n"].split()]
    start = [dict(study_mesh(folder / f"start/x{m}"), name=f"{nx * int(m)} x {ny * int(m)}")
             for m in info["adapt_start_m"].split()]
    uniform_ref = study_mesh(folder / f"uniform/n{u_ref}", judged=False)
    start_ref = study_mesh(folder / f"start/x{m_ref}", judged=False)
    m_ref_name = f"{nx * int(m_ref)} x {ny * int(m_ref)}"

    ratios = per_dof_ratios(steps, uniform, overkill["estimate"], uniform_ref["estimate"])
    start_ratios = dict((s["step"], r) for s, r in
                        per_dof_ratios(steps, start, overkill["estimate"], start_ref["estimate"]))
    worst = max(ratios, key=lambda c: c[1]) if ratios else None
    scene.checks.add(
        "adapted meshes no worse per dof than the scene's uniform N x N meshes (issue 29): each "
        "adapted mesh within their dofs, its error (max over t, against the overkill, + its "
        f"estimate) at most theirs at its dofs (against {u_ref} x {u_ref}, + its estimate; "
        "log-log interpolated)", None if worst is None else worst[1] <= 1.0,
        ours="no adapted mesh within the uniform dofs" if worst is None else
        f"largest ratio {worst[1]:.2f} (step {worst[0]['step']}, {worst[0]['dofs']} dofs) over "
        f"steps {', '.join(str(s['step']) for s, _ in ratios)}", target="<= 1")
    judged = steps + uniform + start
    for key, when in (("effectivity", "maxima over the kept times"), ("effectivity_T", "t = T")):
        values = [m[key] for m in judged]
        scene.checks.add(
            f"adapted study: effectivity (estimate / error, {when}) in [0.3, 3] on every mesh "
            f"(the {len(steps)} adapted, the {len(uniform) + len(start)} uniform)",
            all(EFFECTIVITY_RANGE[0] <= v <= EFFECTIVITY_RANGE[1] for v in values),
            ours=f"{min(values):.2f} ... {max(values):.2f}", target="[0.3, 3]")

    slope = loglog_slope([s["dofs"] for s in steps[1:]], [s["error"] for s in steps[1:]])
    uniform_slope = loglog_slope([u["dofs"] for u in uniform], [u["error"] for u in uniform])
    scene.charts["adapted"] = adapted_figure(
        scene.out / "rail_adapted.png", steps, uniform, overkill["estimate"],
        uniform_ref["estimate"], f"{u_ref} x {u_ref}", -slope,
        "The rail, k = 0.01: max over t of the error, uniform and adapted meshes",
        others=[(f"uniform {nx}m x {ny}m (the start mesh refined), against {m_ref_name}",
                 start)])
    rows = [[s["step"], s["dofs"], fmt(s["estimate"], 3), fmt(s["error"], 3),
             fmt(corrected(s["error"], overkill["estimate"]), 3), f"{s['effectivity']:.2f}",
             next((f"{r:.2f}" for c, r in ratios if c is s), ""),
             f"{start_ratios[s['step']]:.2f}" if s["step"] in start_ratios else "",
             fmt(s["estimate_T"], 3), fmt(s["error_T"], 3), f"{s['effectivity_T']:.2f}"]
            for s in steps]
    urows = [[family, u["name"], u["dofs"], fmt(u["estimate"], 3), fmt(u["error"], 3),
              fmt(corrected(u["error"], ref["estimate"]), 3), f"{u['effectivity']:.2f}",
              fmt(u["estimate_T"], 3), fmt(u["error_T"], 3), f"{u['effectivity_T']:.2f}"]
             for family, ladder, ref in (("scene's", uniform, uniform_ref),
                                         ("start refined", start, start_ref))
             for u in ladder]
    last = steps[-1]
    peak = max(range(len(last["estimates"])), key=lambda i: last["estimates"][i])
    quarters = gamma3_per_quarter(folder / f"step{last['step']}")
    start_text = ", ".join(f"{r:.2f}" for _, r in sorted(start_ratios.items()))
    return title + [
        f"`drivers/adapt.sh` from the {nx} x {ny} rail (cells {2 / nx:g} x {0.1 / ny:g} m; "
        f"Zienkiewicz-Zhu indicators, Dörfler theta 0.5, conforming bisection), "
        f"{len(steps)} steps, `adapted/`. *One mesh for the whole march*: the load and the "
        "contact zone under it sweep the rail (the pressure's bell follows c t, Fig 6.3), so a "
        "marking at the last kept time alone would refine the right end, where the load is at "
        "t = T; sig-estimate's indicator of a triangle is its largest eta_T over the kept times "
        "t = 0, 0.05, ..., 1, and the meshes refine along the whole rail (the last one has "
        f"{', '.join(str(q) for q in quarters)} Gamma3 nodes on the rail's four quarters; its "
        f"eta peaks at t = {last['times'][peak]:g}, "
        f"{last['estimates'][peak] / last['estimate_T']:.1f} times its value at t = T). *Time step*: the deck's k = 0.01 on every mesh, the "
        "references too, so the errors are the space errors of one time discretization, what "
        "the estimator estimates (Fig 6.5 above refines h and k together). *Error*: "
        "sig-error's norm of V, ||eps(u_ref - P u_h)||_L2, its maximum over the shared kept "
        "times (Fig 6.5's measure), against sig-estimate's estimate_max (the maximum of eta "
        "over the kept times); the values at t = T beside. *References*, each finer everywhere "
        "than every mesh it judges: the adapted meshes against the overkill (the last adapted "
        f"mesh refined uniformly twice, {overkill['dofs']} dofs, its own estimate "
        f"{fmt(overkill['estimate'], 3)}; the once-refined one differs from it by "
        f"{fmt(overkill1.get('max_error'), 3)}), the scene's uniform N x N meshes against "
        f"{u_ref} x {u_ref} ({uniform_ref['dofs']} dofs, estimate "
        f"{fmt(uniform_ref['estimate'], 3)}), the start mesh refined uniformly against "
        f"{m_ref_name} ({start_ref['dofs']} dofs, estimate {fmt(start_ref['estimate'], 3)}); "
        "\"+ its estimate\" adds the reference's own estimate in quadrature, as the ratios do.",
        "",
        markdown_table(["step", "dofs", "estimate", "error vs overkill", "+ its estimate",
                        "effectivity", "/ scene's uniform at these dofs",
                        "/ start refined at these dofs", "estimate at T", "error at T",
                        "effectivity at T"], rows),
        "",
        markdown_table(["uniform", "cells", "dofs", "estimate", "error vs its reference",
                        "+ its estimate", "effectivity", "estimate at T", "error at T",
                        "effectivity at T"], urows),
        "",
        f"![rail adapted]({scene.charts['adapted']})",
        "",
        f"Slopes against dofs (max over t): adapted {-slope:.3f} (steps 1-{last['step']}), the "
        f"scene's uniform meshes {-uniform_slope:.3f}. Against the start mesh refined "
        f"uniformly the ratios are {start_text or 'not computed (no step within its dofs)'} "
        "(shown, not checked): the load visits every place, so the meshes adapted to the whole "
        "march are nearly uniform along the rail, and what they gain over the scene's meshes "
        "is the cells' shape (the scene's 2h x 0.1h cells put N rows through the thickness, "
        "more than the bending needs), not where the cells sit."]


def key_table(scene):
    """The scene index's key table: Fig 6.5's errors."""
    key = Table(["h = k", "max over t of ||u - u_hk||_V", "march (s)"],
                caption=f"Fig 6.5 against h = k = 1/{scene.reference_n} (thesis: no values "
                        f"printed; its reference run {scene.thesis_reference()})")
    for n, e, m in fig65_rows(scene)[1]:
        key.add(f"1/{n}", fmt(m, 4), fmt(scene.march(f"convergence/n{n}").seconds(), 3))
    return key


def main():
    if len(sys.argv) != 2:
        raise ReportError("usage: scene6_report.py OUT")
    scene = Scene(sys.argv[1])
    md = section_head(scene) + section_winkler(scene) + section_figs62_63(scene) + \
        section_fig64(scene) + section_quasistatic(scene) + section_viscosity(scene) + \
        section_fig65(scene) + section_loop(scene) + section_speed(scene) + \
        section_stability(scene) + section_adapted(scene) + section_beside_thesis(scene)
    checks = scene.checks
    md += section("Checks") + [checks.table().markdown(), "", checks.summary()]
    write_report(scene.out, "\n".join(md) + "\n", "6", "Scene 6: viscoelastodynamic rail under a "
                 "moving load", scene.info, checks, key_table=key_table(scene), charts=scene.charts,
                 pvd=find_pvd(scene.out))
    print(f"scene6_report: {scene.out / 'report.md'} ({checks.summary()})")
    return 0 if checks.ok else 1


if __name__ == "__main__":
    main_guard(main)
