#!/usr/bin/python3
"""Scene 7b report (hyperelastic ring, thesis ch. 7.4.2): reads every run under OUT
(OUT/N<n>/<method>[_<value>]/case.b through sig-dump, + contact.csv of sig-post, written by
drivers/scene7b.sh)
and writes OUT/report.md with its charts:

- Tables 7.4 / 7.5 ("ours (thesis)"; our count is the total of Newton iterations over the load
  steps, "Nv" where a run did not converge, then the load step that failed), Table 7.6 (times),
  the dof counts;
- Fig 7.13 (fig7_13_pressure.png): contact pressure along Gamma3 at the final load step for
  PDAS, projection (gamma = c = 1e4, the thesis's value in Figs 7.14-7.16) and ALM, and the
  check that they agree within 1 % (PASS / FAIL lines);
- Figs 7.14-7.16 (fig7_14_16_ek.png): E_k = ||x(k+1) - x(k)|| of the same three runs;
- the stability map (stability_map.png): method x parameter x N -> total iterations or Nv, with
  the solve time of each run beside its count;
- the speed against accuracy chart (speed_accuracy.png): every run's solve time against its
  errors relative to OUT/reference (PDAS on the next finer ring);
- per run: iterations per load step, support reactions and their moment (a moment that is not
  ~0 relative to Ry times the radius means the ring swayed off the symmetric branch: "sway",
  also in the tables and the map), time, and the deviation of its final pressure from PDAS's.

Usage: scene7b_report.py OUT. Also writes OUT/scene.json (the scene index entry). Built on the
report library postproc/sigreport (DS files through sig-dump, thesis values, cells, charts,
checks); the module also offers pressure_deviation(p, reference) and accuracy(ds, reference),
used by tests/pipeline/scene7b_small.sh.
"""
import csv
import functools
import math
import sys
from pathlib import Path

from sigreport import (Checks, Deck, MapCell, MapPanel, Point, ReportError, Series, Table,
                       load_thesis, main_guard, markdown_table, ours_thesis, pyplot, read_command,
                       read_ds, run_cell, speed_accuracy_chart, stability_map, write_scene_json)

PARAMETERS = ["1", "10", "1e2", "1e3", "1e4", "1e5", "1e6"]
FIGURE_VALUE = "1e4"  # c = gamma of Figs 7.14-7.16 and Table 7.6
TOLERANCE = 0.01      # "the three methods reach the same final state": pressures within 1 %
R_OUT = 10.0          # outer radius: the lever arm that makes the reaction moment relative
SWAY = 1e-6           # |M| / (|Ry| R_OUT) above this: the state left the symmetric branch
MISSING = "-"         # this report's text for a value or run that is absent


def scalar(ds, name):
    return ds[name][0]


def final_pressure(ds):
    """Contact pressure (multiplier / weight) of the last stored load step, or None."""
    p = ds.get("step_pressure", [])
    m = len(ds.get("multiplier", []))
    if not p or not m:
        return None
    return p[-m:]


def pressure_deviation(p, reference):
    """max_i |p_i - reference_i| / max_i |reference_i| (the Fig 7.13 check)."""
    scale = max(abs(x) for x in reference)
    return max(abs(x - y) for x, y in zip(p, reference)) / scale


def parameter_key(value):
    """1000.0 -> '1e3' as the thesis tables write it; 1 -> '1', 10 -> '10'."""
    v = float(value)
    if v in (1, 10):
        return str(int(v))
    return f"1e{round(math.log10(v))}"


class Runs:
    """The runs under OUT: (N, method, parameter key or '') -> case.b (a sigreport Ds; its
    folder is ds.path.parent)."""

    def __init__(self, out):
        self.runs = {}
        for b in sorted(out.glob("N*/*/case.b")):
            n = int(b.parent.parent.name[1:])
            method, _, value = b.parent.name.partition("_")
            ds = read_ds(b)
            self.runs[(n, method, parameter_key(value) if value else "")] = ds
        self.sizes = sorted({k[0] for k in self.runs})

    def get(self, n, method, p=""):
        if method == "alm":
            return next((d for (nn, m, _), d in self.runs.items() if nn == n and m == "alm"), None)
        return self.runs.get((n, method, p))

    def figure_runs(self, n):
        """The three runs of Figs 7.13-7.16 at N = n: label -> ds (missing ones left out)."""
        runs = {f"PDAS gamma = {FIGURE_VALUE}": self.get(n, "pdas", FIGURE_VALUE),
                f"projection c = {FIGURE_VALUE}": self.get(n, "projection", FIGURE_VALUE),
                "ALM": self.get(n, "alm")}
        return {k: v for k, v in runs.items() if v is not None}


def sway(ds):
    """|M| / (|Ry| R_OUT): the moment of the support reactions relative to Ry's lever arm, zero
    on the symmetric branch (the horizontal reaction is zero by equilibrium against a
    frictionless plane, sway or not)."""
    ry = scalar(ds, "reaction_y")
    return abs(scalar(ds, "reaction_moment")) / (abs(ry) * R_OUT) if ry else 0.0


def swayed(ds):
    return scalar(ds, "converged") and sway(ds) > SWAY


def iterations_cell(ds, with_time=False):
    if ds is None:
        return MISSING
    converged = bool(scalar(ds, "converged"))
    text = run_cell(converged, scalar(ds, "iterations"), sway=swayed(ds),
                    detail=f"step {len(ds['step_iterations'])}")
    return text + (f", {scalar(ds, 'time_solve'):.2f} s" if with_time else "")


def current_abscissa(ds):
    """x1 + u1 of the contact nodes at the final state (contact.csv of sig-post), or None."""
    path = ds.path.parent / "contact.csv"
    if not path.exists():
        return None
    with open(path) as f:
        return [float(r["x1"]) + float(r["u1"]) for r in csv.DictReader(f)]


def what_it_models():
    return ["## What this scene models and why", "",
            "A ring 9 <= |x - (0,10)| <= 10 of the thesis's Ciarlet-Geymonat material (c1 = 0.5, "
            "c2 = 0.005, a = 0.35 MPa) is pushed down by (0, -14) on its top arc AB against the "
            "rigid foundation x2 <= 0, in 14 equal load steps, without friction. 2D plane strain "
            "(F33 = 1; the thesis says plane stress, but its 2D C = F^T F is the plane-strain "
            "one). Finite strain (total Lagrangian P1), because the ring is crushed by 14 of its "
            "20 units of height: a small-strain model would be meaningless there, and the gap and "
            "normal of each Gamma3 node are taken at its current position. The mesh is "
            "structured, N nodes around and 3N/64 + 1 through the thickness (the thesis's dof "
            "counts), and exactly mirror-symmetric about x1 = 0: a mesh symmetric only to 1e-8 "
            "lets the ring sway sideways. Even on this mesh a method can leave the symmetric "
            "branch (round-off grows where that branch is unstable): the moment of the support "
            "reactions shows it (the horizontal reaction cannot: it is zero by equilibrium on a "
            "frictionless plane), and such runs are marked sway. The "
            "question is the thesis's: do the active-set methods (PDAS, iterative projection) "
            "reach the augmented Lagrangian's solution as fast in large deformation, and how does "
            "the projection method's c decide between convergence and Nv.", ""]


def iteration_tables(runs, thesis):
    """The lines of Tables 7.4 and 7.5, and Table 7.4 (the scene index's key table)."""
    lines, tables = [], []
    for title, method, name, item in (
            ("Table 7.4: iterative projection vs c", "projection", "c", "iterations_projection"),
            ("Table 7.5: primal-dual active set vs gamma", "pdas", "gamma", "iterations_pdas")):
        table = Table(["N"] + [f"{name} = {p}" for p in PARAMETERS]
                      + (["ALM"] if method == "projection" else []),
                      caption=f"{title}: total Newton iterations over the load steps, "
                      "ours (thesis)")
        for n in runs.sizes:
            row = [str(n)]
            for p in PARAMETERS:
                row.append(ours_thesis(iterations_cell(runs.get(n, method, p)),
                                       thesis.get(item, f"N={n};{name}={p}"), missing=MISSING))
            if method == "projection":
                row.append(ours_thesis(iterations_cell(runs.get(n, "alm")),
                                       thesis.get("iterations_alm", f"N={n}"), missing=MISSING))
            table.add(*row)
        lines += [f"## {title}", "", table.markdown(), ""]
        tables.append(table)
    return lines, tables[0]


def time_table(runs, thesis):
    lines = [f"## Table 7.6: solve time at c = gamma = {FIGURE_VALUE}", "",
             "Ours: wall seconds of sig-solve's nonlinear solve (case.b time_solve; this machine, "
             "one core) with the Newton iterations beside it; thesis: CPU seconds.", ""]
    rows = []
    for n in runs.sizes:
        row = [str(n)]
        for method, p in (("projection", FIGURE_VALUE), ("pdas", FIGURE_VALUE), ("alm", "")):
            row.append(ours_thesis(iterations_cell(runs.get(n, method, p), True),
                                   thesis.get(f"cpu_{method}", f"N={n}"), unit="s",
                                   missing=MISSING))
        rows.append(row)
    return lines + [markdown_table(["N", "projection", "PDAS", "ALM"], rows), ""]


def dof_table(runs, thesis):
    rows = []
    for n in runs.sizes:
        row = [str(n)]
        for method, p, item in (("pdas", FIGURE_VALUE, "dofs_active_set"), ("alm", "", "dofs_alm")):
            ds = runs.get(n, method, p)
            row.append(ours_thesis(scalar(ds, "dofs") if ds else None,
                                   thesis.get(item, f"N={n}", "?"), missing=MISSING))
        rows.append(row)
    return ["## Unknowns", "", markdown_table(["N", "active set / projection", "ALM"], rows), ""]


def pressure_section(runs, plt, out, checks):
    lines = ["## Fig 7.13: contact pressure on Gamma3 at the final load step", "",
             "Nominal pressure (nodal contact force / reference tributary length) against the "
             "current abscissa x1 + u1 of each Gamma3 node, after load step 14. Check: the three "
             "methods reach the same final state, max_i |p_i - p_PDAS,i| / max_i p_PDAS,i <= 1 %.",
             "", "![pressure](fig7_13_pressure.png)", ""]
    fig, axes = plt.subplots(1, len(runs.sizes), figsize=(5.5 * len(runs.sizes), 4), squeeze=False)
    for ax, n in zip(axes[0], runs.sizes):
        figure_runs = runs.figure_runs(n)
        reference = runs.get(n, "pdas", FIGURE_VALUE)
        p_ref = final_pressure(reference) if reference and scalar(reference, "converged") else None
        for (label, ds), style in zip(figure_runs.items(), ("-", "--", ":")):
            p = final_pressure(ds)
            if not scalar(ds, "converged") or p is None:
                lines.append(f"- N = {n}, {label}: not compared (Nv)")
                if ds is not reference:
                    checks.add(f"Fig 7.13: N = {n}, {label}: final pressure within 1 % of PDAS's",
                               None, detail="not compared (Nv)")
                continue
            x = current_abscissa(ds) or list(range(len(p)))
            ax.plot(x, p, style, marker=".", markersize=3, label=label)
            if p_ref is None or ds is reference:
                continue
            d = pressure_deviation(p, p_ref)
            detail = (f"max pressure difference {100 * d:.2g} % of the maximum {max(p_ref):.4g} "
                      f"(tolerance 1 %)")
            check = checks.add(f"Fig 7.13: N = {n}, {label}: final pressure within 1 % of PDAS's",
                               d <= TOLERANCE, detail=detail)
            lines.append(f"- {check.result}: N = {n}, {label} vs PDAS: {detail}")
        ax.set_title(f"N = {n}")
        ax.set_xlabel("x1 + u1 (current abscissa)")
        ax.set_ylabel("contact pressure (MPa)")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "fig7_13_pressure.png", dpi=110)
    plt.close(fig)
    return lines + [""]


def last_step_history(ds):
    """E_k of the last load step of a converged run: (step, [E_1, E_2, ...])."""
    step = max(ds["history_step"])
    return step, [e for s, e in zip(ds["history_step"], ds["history_step_norm"]) if s == step]


def ek_section(runs, plt, out):
    from matplotlib.ticker import MaxNLocator
    lines = [f"## Figs 7.14-7.16: E_k = ||x(k+1) - x(k)|| (c = gamma = {FIGURE_VALUE})", "",
             "The thesis plots E_k against the iteration index for N = 128, 256, 512 without "
             "saying which load step (its Tables 7.4/7.5 give 8 to 19 iterations per run, fewer "
             "than 14 load steps of at least one iteration each: it does not say how it counts "
             "them). We plot the last load step (14, the most deformed state) and say so; "
             "x = (u, lambda) for ALM, u otherwise.", "",
             "![E_k](fig7_14_16_ek.png)", "",
             "| N | run | load step | iterations | E_k |", "|---|---|---|---|---|"]
    fig, axes = plt.subplots(1, len(runs.sizes), figsize=(5 * len(runs.sizes), 4), squeeze=False)
    for ax, n in zip(axes[0], runs.sizes):
        for (label, ds), marker in zip(runs.figure_runs(n).items(), ("o", "s", "^")):
            if not scalar(ds, "converged"):
                continue
            step, ek = last_step_history(ds)
            ax.semilogy(range(1, len(ek) + 1), [max(e, 1e-300) for e in ek], marker=marker,
                        label=label)
            lines.append(f"| {n} | {label} | {step} | {len(ek)} | "
                         + " ".join(f"{e:.1e}" for e in ek) + " |")
        ax.set_title(f"N = {n}, load step 14")
        ax.xaxis.set_major_locator(MaxNLocator(integer=True))
        ax.set_xlabel("iteration index k")
        ax.set_ylabel("E_k")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(out / "fig7_14_16_ek.png", dpi=110)
    plt.close(fig)
    return lines + [""]


def stability_section(runs, out, maxit):
    lines = ["## Stability map: method x parameter x N", "",
             "Total Newton iterations over the 14 load steps, and the solve time of the run; "
             f"Nv (step k) = load step k did not converge within maxit = {maxit} iterations, the "
             "later steps were not attempted (so every run is bounded); sway = converged, but "
             "to a state off the symmetric branch (|M| / (|Ry| R) > "
             f"{SWAY:g}, see the run table): the ring rolled to one side, a different solution of "
             "the nonlinear problem, not the one of the tables. ALM runs at r = 1e3 only.", "",
             "![stability](stability_map.png)", "",
             "| method | N | " + " | ".join(PARAMETERS) + " |",
             "|---|---" + "|---" * len(PARAMETERS) + "|"]
    for method, name in (("projection", "c"), ("pdas", "gamma")):
        for n in runs.sizes:
            cells = [iterations_cell(runs.get(n, method, p), True) for p in PARAMETERS]
            lines.append(f"| {method} ({name}) | {n} | " + " | ".join(cells) + " |")
    for n in runs.sizes:
        lines.append(f"| alm (r = 1e3) | {n} | " + " | ".join(
            iterations_cell(runs.get(n, "alm"), True) if p == "1e3" else "" for p in PARAMETERS)
            + " |")
    lines.append("")

    panels = []
    for method, name, values in (("projection", "c", PARAMETERS), ("pdas", "gamma", PARAMETERS),
                                 ("alm", "r", ["1e3"])):
        cells = []
        for n in runs.sizes:
            row = []
            for p in values:
                ds = runs.get(n, method, p)
                if ds is None:
                    row.append(MapCell(MISSING, "missing"))
                elif not scalar(ds, "converged"):
                    row.append(MapCell("Nv", "Nv"))
                else:
                    its = scalar(ds, "iterations")
                    row.append(MapCell(str(its) + ("\nsway" if swayed(ds) else ""),
                                       "sway" if swayed(ds) else "ok", its))
            cells.append(row)
        panels.append(MapPanel(f"{method}: total iterations", [f"N = {n}" for n in runs.sizes],
                               values, cells, xlabel=name))
    stability_map(out / "stability_map.png", panels, value_label="log10(total iterations)",
                  title="Ring: Newton iterations over the 14 load steps (red Nv, framed: sway)")
    return lines


def run_table(runs):
    lines = ["## Per run: iterations per load step, reactions, time, final pressure", "",
             "Reaction: force of the supports on the ring at AB after the last attempted step "
             "(sum of f_int over the imposed dofs). Rx is zero by equilibrium (the foundation is "
             "a frictionless plane, its forces are vertical), so it cannot show a sway; M, the "
             "moment of the reactions about the origin at the current positions, can: it is zero "
             "on the symmetric branch and balances an off-centre contact zone otherwise. "
             f"|M| / (|Ry| R), R = {R_OUT:g}, above {SWAY:g} is marked sway. "
             f"dp: max pressure difference to PDAS gamma = {FIGURE_VALUE} at the final step, "
             "relative to its maximum.", "",
             "| N | run | per-step iterations | Rx | Ry | M / (Ry R) | solve s | dp | failure |",
             "|---|---|---|---|---|---|---|---|---|"]
    order = sorted(runs.runs.items(), key=lambda kv: (kv[0][0], kv[0][1],
                                                      float(kv[0][2] or 0)))
    for (n, method, value), ds in order:
        steps = " ".join(f"{i}" + ("" if c else "Nv")
                         for i, c in zip(ds["step_iterations"], ds["step_converged"]))
        rx, ry = scalar(ds, "reaction_x"), scalar(ds, "reaction_y")
        ratio = f"{sway(ds):.1e}" + (" **sway**" if swayed(ds) else "")
        reference = runs.get(n, "pdas", FIGURE_VALUE)
        dp = "-"
        if scalar(ds, "converged") and reference and scalar(reference, "converged"):
            p, p_ref = final_pressure(ds), final_pressure(reference)
            if p and p_ref:
                dp = f"{pressure_deviation(p, p_ref):.1e}"
        run = method + (f" {value}" if value else "")
        failure = ds.get("failure", "").replace("|", "/")
        lines.append(f"| {n} | {run} | {steps} | {rx:.4g} | {ry:.4g} | {ratio} | "
                     f"{scalar(ds, 'time_solve'):.2f} | {dp} | {failure} |")
    return lines + [""]


@functools.lru_cache(maxsize=None)
def _pressures_at(path):
    with open(path) as f:
        return {(round(float(r["x1"]), 9), round(float(r["x2"]), 9)): float(r["pressure"])
                for r in csv.DictReader(f)}


def contact_pressures(ds):
    """{(x1, x2) of the reference node, rounded: final pressure} from contact.csv (read once per
    file: the reference's serves every run)."""
    return _pressures_at(ds.path.parent / "contact.csv")


def accuracy(ds, reference):
    """(reaction error, pressure error) of a converged run against the reference run: the
    relative error of the vertical reaction on AB, and max |p - p_ref| / max p_ref over the
    Gamma3 nodes the two rings share; None for an Nv run."""
    if not scalar(ds, "converged"):
        return None
    ry, ry_ref = scalar(ds, "reaction_y"), scalar(reference, "reaction_y")
    p, p_ref = contact_pressures(ds), contact_pressures(reference)
    shared = [x for x in p if x in p_ref]
    if len(shared) < len(p):
        raise ReportError(f"{ds.path.parent}: {len(p) - len(shared)} Gamma3 nodes are not "
                          f"nodes of the reference ring {reference.path.parent}")
    scale = max(p_ref.values())
    return abs(ry - ry_ref) / abs(ry_ref), max(abs(p[x] - p_ref[x]) for x in shared) / scale


def speed_accuracy_section(runs, reference, out):
    n_ref = Deck.read(reference.path.parent / "ring.dat").value("MESH", "N")
    lines = ["## Speed against accuracy", "",
             f"Every run is a point: its solve time against its error, measured against the "
             f"reference run PDAS gamma = {FIGURE_VALUE} on the next finer ring "
             f"(N = {n_ref}, {scalar(reference, 'dofs')} dofs, reference/), whose Gamma3 nodes "
             f"include those of the coarser rings. Error: of the vertical reaction on AB (the "
             f"chart), and the largest final-pressure difference at the shared Gamma3 nodes "
             f"relative to the reference's maximum pressure (a pointwise measure, dominated by the "
             f"edges of the contact zone). A run that does not converge has no "
             f"error: it is drawn on the top edge as Nv. The error is the mesh's (at a given N "
             f"every converged method gives the same state within the tolerance, but for a run "
             f"marked sway, which found another equilibrium); the methods differ in time.", "",
             "![speed against accuracy](speed_accuracy.png)", ""]
    marker = {"pdas": "o", "projection": "s", "alm": "^"}
    colors = dict(zip(runs.sizes, ("tab:blue", "tab:orange", "tab:green", "tab:red")))
    order = sorted(runs.runs.items(), key=lambda kv: (kv[0][0], kv[0][1], float(kv[0][2] or 0)))
    series, rows = {}, []
    for (n, method, value), ds in order:
        a = accuracy(ds, reference)
        t = scalar(ds, "time_solve")
        run = method + (f" {value}" if value else "")
        if (n, method) not in series:
            series[(n, method)] = Series(f"{method}, N = {n}", [], color=colors[n],
                                         marker=marker[method], line="", hollow=False,
                                         markersize=6)
        series[(n, method)].points.append(Point(t, a[0] if a else None,
                                                "sway" if swayed(ds) else ""))
        run += " (sway)" if swayed(ds) else ""
        rows.append([n, run, f"{t:.2f}", f"{a[0]:.2e}" if a else "Nv",
                     f"{a[1]:.2e}" if a else "Nv"])
    speed_accuracy_chart(out / "speed_accuracy.png", list(series.values()),
                         xlabel="solve time (s)",
                         ylabel="error of the vertical reaction vs the reference ring",
                         title="Ring: speed against accuracy", figsize=(7.5, 5), dpi=110,
                         legend_fontsize=7)
    return lines + [markdown_table(["N", "run", "solve s", "reaction error", "pressure error"],
                                   rows), ""]


def deck_field(runs, card, field):
    """A field of the runs' decks ('?' if none has it)."""
    for ds in runs.runs.values():
        deck = ds.path.parent / "ring.dat"
        if deck.exists() and (value := Deck.read(deck).value(card, field)) is not None:
            return value
    return "?"


def main():
    if len(sys.argv) != 2:
        raise ReportError("usage: scene7b_report.py OUT")
    plt = pyplot()
    out = Path(sys.argv[1])
    info = read_command(out, required=("command",))
    runs = Runs(out)
    if not runs.runs:
        raise ReportError(f"no N*/*/case.b under {out}")
    thesis = load_thesis().scene("7b")
    checks = Checks()
    maxit = deck_field(runs, "SOLVER", "maxit")
    reference_b = out / "reference" / "case.b"
    reference = read_ds(reference_b) if reference_b.exists() else None
    title = "Scene 7b: hyperelastic ring pressed on a rigid foundation"
    lines = [f"# {title}", "",
             "Cells are ours (thesis). Our count is the total of Newton iterations over the 14 "
             "load steps; 'Nv' = not converged (the load step that failed). Deck: "
             "datafiles/scene7b/ring.dat (plane strain, 14 load steps to u = (0,-14) on AB, "
             f"eps = 1e-5, maxit = {maxit} per load step, linear solver "
             f"{deck_field(runs, 'SOLVER', 'linear')}). The deformed ring of the "
             f"figure runs is in N<n>/<run>/ring.pvd, one state per load step (ParaView).", ""]
    lines += what_it_models()
    table_lines, key_table = iteration_tables(runs, thesis)
    lines += table_lines
    lines += time_table(runs, thesis)
    lines += dof_table(runs, thesis)
    lines += pressure_section(runs, plt, out, checks)
    lines += ek_section(runs, plt, out)
    lines += stability_section(runs, out, maxit)
    charts = {"stability": "stability_map.png", "fig7_13": "fig7_13_pressure.png",
              "fig7_14_16": "fig7_14_16_ek.png"}
    if reference and scalar(reference, "converged"):
        lines += speed_accuracy_section(runs, reference, out)
        charts["speed_accuracy"] = "speed_accuracy.png"
    else:
        lines += ["## Speed against accuracy", "",
                  "No converged reference run in reference/ (drivers/scene7b.sh makes it): no "
                  "errors to chart.", ""]
    lines += run_table(runs)
    (out / "report.md").write_text("\n".join(lines))
    write_scene_json(out, "7b", title, info, checks, key_table=key_table, charts=charts)
    print(f"scene7b_report: wrote {out / 'report.md'} ({len(runs.runs)} runs)")


if __name__ == "__main__":
    main_guard(main)
