#!/usr/bin/python3
"""Scene 8a report: the elastic ball impact (thesis ch. 8.5) beside the thesis's numbers.

    postproc/scene8a_report.py OUTDIR

OUTDIR is what drivers/scene8a.sh wrote: command.txt, impact.txt (mesh, foundation height, T,
k of the impact runs), and one folder per run (impact/<method>, fig85/<run>,
sweep/<method>_k<k>, readings/<reading>, study/<mesh>/<method>_k<k>) holding ball.dat (its
deck), method.txt, energy.csv and case.hist (sig-march), march.log and wall.txt (the stage's
wall-clock seconds), and bar/<run> (bar.dat, energy.csv: the closed-form check). Writes
OUTDIR/report.md, OUTDIR/methods.csv, OUTDIR/sweep.csv, OUTDIR/study.csv, OUTDIR/scene.json (the
scene index entry) and the PNGs the report shows. The thesis's values come from the 8a rows of
postproc/thesis_values.csv. Every number in the report is read from those files or computed
from them here (with the report library postproc/sigreport: decks, case.hist through sig-dump,
thesis values, checks, charts).
"""
import argparse
import math
import re
from pathlib import Path

from sigreport import (Checks, Deck, MapCell, MapPanel, Series, Table, energy_chart, load_thesis,
                       main_guard, markdown_table, read_command, speed_accuracy_chart,
                       stability_map, write_report)
from sigreport import fmt_spec as fmt
from sigreport.impact import (Bar, energy_curves, energy_measures, hist_scalars, impact_window,
                              read_energy_rows, speed_point, stability_status, wall_seconds)

METHODS = ("signorini", "compliance", "specific-penalty", "emm", "two-step", "two-step-increment",
           "ipm", "ipm-emm")
CLASSICAL = ("signorini", "compliance", "specific-penalty", "emm", "two-step",
             "two-step-increment")  # Fig 8.3
IPM_VARIANTS = ("specific-penalty", "ipm", "ipm-emm")                           # Fig 8.4
LABEL = {
    "signorini": "classical scheme, Signorini (g = 0)",
    "compliance": "classical scheme, normal compliance",
    "specific-penalty": "specific penalty (3.51)",
    "specific-penalty-emm": "specific penalty + EMM",
    "emm": "EMM (Signorini, equivalent mass)",
    "two-step": "two-step [13], persistency on the midpoint velocity (C15)",
    "two-step-increment": "two-step [13], persistency on the increment",
    "ipm": "IPM (8.30)-(8.32)",
    "ipm-emm": "IPM + EMM",
}
MARKER = {"signorini": "o", "compliance": "s", "specific-penalty": "D", "emm": "v",
          "two-step": "^", "two-step-increment": "<", "ipm": "P", "ipm-emm": "*",
          "specific-penalty-emm": "x"}
GAP_RUN = re.compile(r"^g[0-9.eE+-]+$")  # a Fig 8.5 run of IPM + EMM with its gap g
DECK_R, DECK_G = 1e12, 5e-4  # the deck's reading of r and g (ball.dat)
R_PENETRATION = "4.6e11"     # r of the specific penalty's 0.0034 m (drivers/scene8a.sh)
STUDY_METHODS = ("signorini", "emm", "ipm-emm")
BAR_RUNS = ("signorini-emm", "ipm-emm", "signorini-consistent", "ipm-consistent",
            "mid-step-k5e-6", "mid-step-k2.5e-6")
BAR_LABEL = {
    "signorini-emm": "Signorini + EMM",
    "ipm-emm": "IPM + EMM (r = 1e14 Pa/m, g = 1e-4 m: the wall not reached)",
    "signorini-consistent": "Signorini, consistent mass",
    "ipm-consistent": "IPM, consistent mass (r = 1e14, g = 1e-4)",
    "mid-step-k5e-6": "Signorini + EMM, the end arriving mid-step, k = 5e-6",
    "mid-step-k2.5e-6": "Signorini + EMM, the end arriving mid-step, k = 2.5e-6",
}
# The "must show" (issue 5), as numbers.
CONSERVING_TOL = 1.0   # two-step and specific penalty: |dE| / E0 within 1 %
KV2_TOL = 0.5          # two-step (C15): penetration within 50 % of the thesis's 0.0051 m
# Signorini "dissipating visibly": it loses more than the thesis's IPM + EMM, whose 0.1 % the
# thesis counts as conserving "almost all" the energy, and more than the conserving methods.
VISIBLE_LOSS = 0.1
THESIS_LOSS_FACTOR = 2.0  # IPM + EMM: the thesis's 0.1 % loss, within a factor 2 either way
STRONGLY = 0.5         # EMM "strongly" reduces Signorini's loss: removes at least half of it
R_READING = 3.0        # the r = 1e12 Pa/m reading: penetration within a factor 3 of 0.0034 m
GAIN = 0.1             # stability: E_end > E0 (1 + 0.1 %) is an energy gain
STATUS_TEXT = (
    f"Status: Nv = a step's Newton failed (the march stops there, the failure is "
    f"quoted); gain = the energy grew by more than {GAIN:g} %; dissipates = it fell by "
    f"more than {VISIBLE_LOSS:g} %; chatter = the ball left and touched the foundation "
    "again (contact episodes > 1) or the active count went up and down more than "
    "once; ok otherwise. The issue asks k = 1e-2 ... 1e-4; the coarser k = 1e-1 and "
    "3e-2 are there to find where the strategies fail.")


def label_of(name):
    """The legend and table name of a run: its method's, or IPM + EMM with its gap."""
    return f"IPM + EMM, g = {float(name[1:]):g} m" if GAP_RUN.match(name) else LABEL.get(name, name)


# ---------------------------------------------------------------------------------------------
# Reading the files


def read_run(folder, name=None):
    """One run: its deck, energy rows, wall time, HIST scalars and measures; None if it did not
    march. `name`: its name in the report (default: its method)."""
    rows = read_energy_rows(folder)
    if rows is None:
        return None
    deck = Deck.read(folder / "ball.dat")
    method = (folder / "method.txt").read_text().strip()
    run = {
        "folder": folder,
        "method": method,
        "name": name or method,
        "rows": rows,
        "k": deck.number("TIME", "k"),
        "T": deck.number("TIME", "T"),
        "gap": deck.number("CONTACT", "gap", math.nan),
        "r": deck.number("CONTACT", "r", math.nan),
        "plane": deck.value("MATERIAL", "plane", "stress"),
        "foundation": deck.numbers("CONTACT", "point")[1],
        "radius": 10.0,
        "wall": wall_seconds(folder),
        "hist": hist_scalars(folder / "case.hist", ["converged", "failure", "time_march"]),
    }
    run.update(energy_measures(run))
    run.update(contact_episodes(run))
    return run


def contact_episodes(run):
    """The ball's contact history: the energy excursion during contact, the separation time,
    the episodes of contact (maximal runs of steps with active nodes; more than one is a rebound,
    chatter of the whole ball) and the reversals of the active count beyond rise-then-fall
    (chatter of the contact zone)."""
    rows, active, contact = run["rows"], run["active"], run["contact"]
    e0 = run["e0"]
    episodes = sum(1 for i, a in enumerate(active) if a > 0 and (i == 0 or active[i - 1] == 0))
    diffs = [b - a for a, b in zip(active, active[1:]) if b != a]
    reversals = sum(1 for a, b in zip(diffs, diffs[1:]) if (a > 0) != (b > 0))
    last = contact[-1] if contact else None
    separated = last is not None and last < len(rows) - 1
    return {
        "separation_time": rows[last + 1]["time"] if separated else math.nan,
        "excursion": 100 * max(abs(r["total"] - e0) for r in rows) / e0,
        "episodes": episodes,
        "reversals": max(0, reversals - 1),
        "time_march": run["hist"].get("time_march", math.nan),
    }


def status(run):
    """A run's behaviour in the stability map (sigreport.impact.stability_status)."""
    return stability_status(run, gain=GAIN, loss=VISIBLE_LOSS,
                            chatter=run["episodes"] > 1 or run["reversals"] > 0)


def read_runs(out):
    """The impact runs {method: run}, Fig 8.5's {name: run} and the sweep's runs."""
    impact = {m: r for m in METHODS if (r := read_run(out / "impact" / m))}
    fig85 = {}
    if (out / "fig85").is_dir():
        for folder in sorted((out / "fig85").iterdir()):
            run = read_run(folder, folder.name if folder.name.startswith("g") else None)
            if run:
                fig85[run["name"]] = run
    sweep = [r for f in sorted((out / "sweep").glob("*_k*")) if (r := read_run(f))] \
        if (out / "sweep").is_dir() else []
    return impact, fig85, sweep


def read_bar(out):
    """The bar runs {name: measures against the closed form} and the Bar; ({}, None) without
    them."""
    deck = out / "bar" / "base" / "bar.dat"
    if not deck.is_file():
        return {}, None
    bar = Bar.of_deck(Deck.read(deck))
    runs = {}
    for name in BAR_RUNS:
        rows = read_energy_rows(out / "bar" / name)
        if rows:
            runs[name] = bar.measures(rows)
    return runs, bar


def read_readings(out):
    """The readings of the thesis's data {name: run} (readings/<name>)."""
    folder = out / "readings"
    if not folder.is_dir():
        return {}
    return {f.name: run for f in sorted(folder.iterdir()) if (run := read_run(f, f.name))}


class Study:
    """The loss against k and the mesh: every run of Signorini, EMM and IPM + EMM that lands on
    a time level with the deck's r and g, by (mesh, method, k): study/<mesh>/ (--study), the
    sweep (deck mesh) and the impact runs and readings/deck (the impact mesh, k = 1e-3)."""

    def __init__(self, out, impact, sweep, readings, impact_mesh):
        self.cells = {}
        self.meshes = []
        for run in sweep:
            self._add("deck", run)
        for run in impact.values():
            self._add(impact_mesh, run)
        if "deck" in readings:
            self._add(impact_mesh, readings["deck"])
        if (out / "study").is_dir():
            for folder in sorted((out / "study").iterdir()):
                for run_dir in sorted(folder.iterdir()):
                    if (run := read_run(run_dir)):
                        self._add(folder.name, run)
        self.meshes = [m for m in ("deck", "thesis", "fine") if any(c[0] == m for c in self.cells)]
        self.ks = sorted({c[2] for c in self.cells}, reverse=True)
        self.nodes = {m: mesh_nodes(out, m) for m in self.meshes}

    def _add(self, mesh, run):
        # Only what the deck reads: its r and g, the ball landing on a time level.
        deck_r = math.isnan(run["r"]) or run["r"] == DECK_R
        deck_g = math.isnan(run["gap"]) or run["gap"] == DECK_G
        if run["method"] in STUDY_METHODS and run["converged"] and deck_r and deck_g \
                and run["plane"] == "stress" and landing_on_level(run):
            self.cells.setdefault((mesh, run["method"], run["k"]), run)

    def get(self, mesh, method, k):
        return self.cells.get((mesh, method, k))

    def rows(self):
        """Every cell for study.csv."""
        return [(m, method, k, run) for (m, method, k), run in sorted(self.cells.items())]


def landing_on_level(run):
    """The ball's lowest point (x2 = 15 at rest) reaches the foundation on a time level."""
    steps = (15.0 - run["foundation"]) / (10.0 * run["k"])
    return abs(steps - round(steps)) < 1e-6


def mesh_nodes(out, mesh):
    """The node count sig-mesh reported for OUTDIR/<mesh>/base ("?" if absent)."""
    log = out / mesh / "base" / "mesh.log"
    words = log.read_text().split() if log.is_file() else []
    return next((words[i - 1] for i, w in enumerate(words) if w.startswith("nodes")), "?")


# ---------------------------------------------------------------------------------------------
# Charts and files


def energy_figure(out, runs, names, title, png, window):
    energy_chart(out / png, energy_curves([runs[n] for n in names if n in runs],
                                          lambda r: label_of(r["name"]),
                                          lambda r: MARKER.get(r["method"], ".")), title, window)


def speed_chart(out, sweep):
    """Each strategy a series, each k a point: wall time per simulated second against the energy
    change across the impact; a march that stopped (Nv) on the top edge."""
    series = []
    for method in METHODS:
        runs = sorted((r for r in sweep if r["method"] == method and not math.isnan(r["wall"])),
                      key=lambda r: -r["k"])
        if runs:
            series.append(Series(LABEL[method], [speed_point(r, f"{r['k']:g}") for r in runs],
                                 marker=MARKER[method], hollow=False, markersize=5))
    speed_accuracy_chart(out / "speed_accuracy.png", series,
                         xlabel="wall time per simulated second (s/s)",
                         ylabel="|energy change| / E0 across the impact (%)",
                         title="Speed against accuracy (labels: k; changes below 1e-6 % at 1e-6)",
                         figsize=(7.5, 4.5), dpi=110, legend_fontsize=7, label_fontsize=6)


def sweep_run(sweep, method, k):
    return next((r for r in sweep if r["method"] == method and r["k"] == k), None)


def stability_chart(out, sweep, ks):
    cells = []
    for method in METHODS:
        row = []
        for k in ks:
            run = sweep_run(sweep, method, k)
            state = status(run) if run else "missing"
            text = state if state in ("Nv", "missing") else f"{run['change']:+.2f}%\n{state}"
            row.append(MapCell(text, state))
        cells.append(row)
    panel = MapPanel("Stability: energy change and behaviour per strategy and k", list(METHODS),
                     [f"k = {k:g}" for k in ks], cells, xlabel="time step k (s)",
                     ylabel="strategy (-)")
    stability_map(out / "stability.png", [panel], fontsize=7)


def draw_charts(out, impact, fig85, names85, sweep, ks):
    window = impact_window(impact.values(), before=0.01, after=0.03)
    energy_figure(out, impact, CLASSICAL, "Fig 8.3: energy across the impact, classical methods",
                  "fig8_3.png", window)
    energy_figure(out, impact, IPM_VARIANTS, "Fig 8.4: IPM variants", "fig8_4.png", window)
    energy_figure(out, fig85, names85 + ["specific-penalty-emm"],
                  "Fig 8.5: IPM + EMM against the allowed penetration g", "fig8_5.png", window)
    charts = {"fig8_3": "fig8_3.png", "fig8_4": "fig8_4.png", "fig8_5": "fig8_5.png"}
    if sweep:
        speed_chart(out, sweep)
        stability_chart(out, sweep, ks)
        charts.update(speed_accuracy="speed_accuracy.png", stability="stability.png")
    return charts


def write_csvs(out, impact, fig85, sweep):
    """methods.csv (the impact and Fig 8.5 runs) and sweep.csv."""
    with (out / "methods.csv").open("w") as f:
        f.write("method,energy_change_percent,max_excursion_percent,max_penetration,"
                "max_active,newton_iterations,steps,converged,wall_seconds\n")
        for name, run in list(impact.items()) + list(fig85.items()):
            f.write(f"{name},{run['change']:.9g},{run['excursion']:.9g},{run['penetration']:.9g},"
                    f"{run['max_active']},{run['newton']},{run['steps']},{int(run['converged'])},"
                    f"{run['wall']}\n")
    with (out / "sweep.csv").open("w") as f:
        f.write("method,k,energy_change_percent,max_penetration,episodes,reversals,converged,"
                "status,wall_seconds,wall_per_simulated_second\n")
        for run in sweep:
            f.write(f"{run['method']},{run['k']:g},{run['change']:.9g},{run['penetration']:.9g},"
                    f"{run['episodes']},{run['reversals']},{int(run['converged'])},"
                    f"{status(run)},{run['wall']},{run['wall'] / run['T']:.6g}\n")


def write_study_csv(out, study):
    """study.csv: every run of the loss against k and the mesh."""
    with (out / "study.csv").open("w") as f:
        f.write("mesh,nodes,method,k,energy_change_percent,max_penetration\n")
        for mesh, method, k, run in study.rows():
            f.write(f"{mesh},{study.nodes[mesh]},{method},{k:g},{run['change']:.9g},"
                    f"{run['penetration']:.9g}\n")


# ---------------------------------------------------------------------------------------------
# The report


def checks(runs, thesis, found):
    """The thesis's claims and our requirements as Checks (name: the requirement, ours: what was
    measured, and for a claim not reproduced the study beside it: `found` is what the runs hold,
    Found); a missing run is a FAIL (the driver makes every one)."""
    out = Checks()

    def row(text, measured, ok, study=None, erratum=None):
        ok = bool(ok)
        out.add(text, ok, ours=measured, study=None if ok else study,
                erratum=None if ok else erratum)

    def change(run):
        return f"{fmt(run['change'], '+.3f')} %" if run else "no run"

    # Two-step: the thesis has it both conserve the energy (Fig 8.3) and penetrate 0.0051 m; each
    # reading of its persistency (C15) gives one of the two, checked on each.
    two_step_study = (
        "each reading of [13]'s persistency holds one of the thesis's two claims: on the "
        f"increment the energy is kept ({change(runs.get('two-step-increment'))}) with no "
        "penetration, on the midpoint velocity (C15) the penetration is the thesis's (k v / 2) "
        f"and {change(runs.get('two-step'))} is lost; no reading gives both, and no published "
        "result of [13] on this ball was found to decide")
    for name in ("two-step", "two-step-increment", "specific-penalty"):
        run = runs.get(name)
        ok = run is not None and run["converged"] and abs(run["change"]) <= CONSERVING_TOL
        row(f"{name}: energy conserved across the impact within {CONSERVING_TOL:g} % (Fig 8.3)",
            change(run), ok, study=two_step_study)
    run = runs.get("two-step")
    reference = float(thesis.get("penetration_error", "two-step [13]", "0.0051"))
    ok = run is not None and abs(run["penetration"] - reference) <= KV2_TOL * reference
    row(f"two-step (C15, the midpoint velocity): penetration within {100 * KV2_TOL:g} % of the "
        f"thesis's {reference:g} m (k v / 2 = 0.005 m)",
        f"{fmt(run['penetration'])} m" if run else "no run", ok, study=two_step_study)
    run = runs.get("signorini")
    conserving = [abs(runs[m]["change"]) for m in ("two-step-increment", "specific-penalty")
                  if m in runs]
    ok = (run is not None and run["converged"] and run["change"] <= -VISIBLE_LOSS and
          -run["change"] > max(conserving, default=0.0))
    row(f"signorini dissipates visibly (loses > {VISIBLE_LOSS:g} %, the thesis's IPM + EMM "
        "dissipation, and more than two-step on the increment and specific penalty)",
        change(run), ok)
    run = runs.get("ipm-emm")
    ipm_emm = thesis.row("ipm_emm", "dissipation/penetration")
    loss, depth = (float(x) for x in (ipm_emm.value.split("/") if ipm_emm else ("0.1", "0.005")))
    ok = run is not None and run["converged"] and run["penetration"] <= run["gap"] * (1 + 1e-9)
    row(f"ipm-emm: penetration <= g = {fmt(DECK_G)} m, the thesis's {depth:g} % of R (p.230)",
        f"{fmt(run['penetration'])} m" if run else "no run", ok)
    ok = (run is not None and run["converged"] and
          loss / THESIS_LOSS_FACTOR <= -run["change"] <= loss * THESIS_LOSS_FACTOR)
    row(f"ipm-emm: dissipates the thesis's {loss:g} % (p.230), within a factor "
        f"{THESIS_LOSS_FACTOR:g}", change(run), ok, study=found.ipm_emm_study(loss))
    run, signorini = runs.get("emm"), runs.get("signorini")
    share = removed_share(run, signorini)
    ok = share is not None and run["converged"] and share >= STRONGLY
    row(f"emm (ALGORITHMS.md 4.3 D: the Gamma3 nodes' inertia removed, mass, centre and moments "
        f"kept) 'strongly' reduces signorini's dissipation (Fig 8.3): removes at least "
        f"{100 * STRONGLY:g} % of it",
        f"{change(run)} against {change(signorini)}: {percent(share)} % of the loss "
        "removed" if share is not None else "no run", ok, study=found.emm_study())
    run = runs.get("specific-penalty")
    reference = float(thesis.get("penetration_error", "specific penalty", "0.0034"))
    ok = (run is not None and reference / R_READING <= run["penetration"] <= reference * R_READING)
    row(f"r = 1e12 Pa/m reading: specific penalty's penetration within a factor {R_READING:g} of "
        f"the thesis's {reference:g} m", f"{fmt(run['penetration'])} m" if run else "no run", ok)
    found.bar_checks(out)
    return out


def removed_share(emm, signorini):
    """The share of Signorini's loss EMM removes (None without both runs or a loss)."""
    if not (emm and signorini and signorini["change"] < 0):
        return None
    return 1 - emm["change"] / signorini["change"]


class Found:
    """What settles the thesis's energy claims, or could not: the bar against its closed form,
    the readings of the thesis's data at its k, and the loss against k and the mesh."""

    def __init__(self, out, impact, sweep, impact_mesh):
        self.bar, self.bar_model = read_bar(out)
        self.readings = read_readings(out)
        self.study = Study(out, impact, sweep, self.readings, impact_mesh)
        self.impact_mesh = impact_mesh
        self.has_study = (out / "study").is_dir()

    # The readings: (label, run) of IPM + EMM at k = 1e-3, the deck's reading first.
    def reading_rows(self):
        named = [("deck", "the deck: r = 1e12 Pa/m (\"1000\" in GPa/m), landing on a time level, "
                  "plane stress")]
        named += [(f"r{r}", f"r = {r} Pa/m ({why})") for r, why in (
            ("1e3", "as printed, \"r = 1000 Pa\""), ("1e9", "\"1000\" in MPa/m"),
            (R_PENETRATION, "where the specific penalty penetrates the thesis's 0.0034 m"))]
        named += [(f"phase{p}", f"the ball landing {p} of a step later (the start height read "
                   f"{10 * 1e-3 * float(p):g} m higher)") for p in ("0.25", "0.5", "0.75")]
        named += [("strain", "plane strain (the thesis says plane stress)")]
        return [(label, self.readings[name]) for name, label in named if name in self.readings]

    def ipm_emm_study(self, loss):
        """The study beside the check of IPM + EMM's 0.1 %."""
        near = [label for label, run in self.reading_rows() if close_to(run["change"], loss)]
        readings = "; ".join(f"{label}: {run['change']:+.3f} %"
                             for label, run in self.reading_rows())
        ks = [f"k = {k:g}: {run['change']:+.3f} %" for k in self.study.ks
              if (run := self.study.get(self.impact_mesh, "ipm-emm", k))]
        return (f"at the thesis's k = 1e-3 on the {self.impact_mesh} mesh, {readings or 'no run'}"
                f": {'; '.join(near) + ' within' if near else 'no reading within'} a factor "
                f"{THESIS_LOSS_FACTOR:g} of {loss:g} %. Against k ({self.impact_mesh} mesh): "
                f"{', '.join(ks) or 'no run'} (the study table). No published value of this ball "
                "was found (Khenous, Laborde and Renard 2008, the mass redistribution method, is "
                "not in the documentation searched)")

    def emm_study(self):
        """The study beside the check of EMM's "strongly"."""
        shares = [(m, k, share) for m in self.study.meshes for k in self.study.ks
                  if (share := removed_share(self.study.get(m, "emm", k),
                                             self.study.get(m, "signorini", k))) is not None]
        ball = (f"on the ball EMM removes {percent(min(s for *_, s in shares))} to "
                f"{percent(max(s for *_, s in shares))} % of Signorini's loss over "
                f"{len(shares)} pairs of mesh and k (the study table)" if shares
                else "no pair of runs of the ball")
        bar = self.bar
        if {"signorini-emm", "signorini-consistent", "mid-step-k5e-6", "mid-step-k2.5e-6"} \
                <= set(bar):
            bar_text = (
                f"; the bar (closed form: no loss) keeps its energy with EMM to "
                f"{abs(bar['signorini-emm']['energy_change']):.0e} where the consistent mass "
                f"loses {-100 * bar['signorini-consistent']['energy_change']:.3f} %, when its "
                f"end lands on a time level; landing mid-step it loses "
                f"{-100 * bar['mid-step-k5e-6']['energy_change']:.3f} % at k = 5e-6 and "
                f"{-100 * bar['mid-step-k2.5e-6']['energy_change']:.4f} % at 2.5e-6 (order "
                "k^2). EMM removes the loss of the contact nodes' inertia (the bar's, of order "
                "h / L whatever k); the ball's loss falls with k like the mid-step bar's (the "
                "table), the work of the wall on nodes landing between time levels, which EMM "
                "does not remove (our reading)")
        else:
            bar_text = ""
        return (ball + bar_text + ". No published result of EMM on this ball was found "
                "(Khenous, Laborde and Renard 2008 is not in the documentation searched)")

    def bar_checks(self, out):
        """The bar against its closed form: our check of EMM and the march, not a thesis claim."""
        bar = self.bar
        if not bar:
            out.add("bar (closed form): runs", None, detail="no bar runs")
            return
        emm = [bar[n] for n in ("signorini-emm", "ipm-emm") if n in bar]
        worst = max(abs(m["energy_change"]) for m in emm) if emm else math.nan
        out.add("bar (closed form, datafiles/scene8a/bar.dat): Signorini + EMM and IPM + EMM "
                "keep the energy 1/2 m v^2 to 1e-6", len(emm) == 2 and worst <= 1e-6,
                ours=f"worst {worst:.1e}")
        off = max(abs(m["contact_steps"] - m["closed_form_steps"]) for m in bar.values())
        out.add("bar: contact lasts 2 L / c to one time step (every bar run)", off <= 1,
                ours=f"worst {off:g} step(s) off")
        impulse = max(abs(m["impulse_ratio"] - 1) for m in bar.values())
        out.add("bar: the wall's impulse is 2 m v to 1 % (every bar run)", impulse <= 0.01,
                ours=f"worst {100 * impulse:.2f} %")

    def section_bar(self):
        if not self.bar:
            return []
        b = self.bar_model
        table = Table(["run", "dE / E0", "contact steps (2 L / c)", "impulse / 2 m v",
                       "max penetration (m)"])
        for name, m in self.bar.items():
            table.add(BAR_LABEL.get(name, name), f"{m['energy_change']:+.2e}",
                      f"{m['contact_steps']} ({m['closed_form_steps']:g})",
                      f"{m['impulse_ratio']:.4f}", f"{m['penetration']:.2g}")
        return ["## The closed form: a bar striking a wall", "",
                f"`datafiles/scene8a/bar.dat`: a strip of the ball's material with nu = 0 (then "
                f"exactly a 1D bar in the continuum), L = {b.length:g} m, {b.width:g} m wide, "
                f"h = 0.1 m, thrown at {b.v:g} m/s onto a wall: contact for 2 L / c = "
                f"{b.contact_time:g} s (c = {b.c:g} m/s), impulse 2 m v = {b.impulse:g} N s/m, "
                "no energy lost. k = 5e-6 (c k / h = 0.5); the end lands on a time level but in "
                "the mid-step runs. The P1 strip moves sideways by about 2e-3 of its axial "
                "displacement (tests/pipeline/impact_bar.sh): the consistent mass of a row is "
                "not proportional to its share of the stiffness.", ""] + table.lines() + [
                "", "The energy is the body's (8.33): IPM's compliance holds some during contact "
                "and gives it back. EMM removes the loss of the contact row's mass (the "
                "consistent mass's loss, of order h / L, whatever k), but a node landing between "
                "two time levels is stopped at t_n by a force that works over the part of the "
                "step before the landing: a loss of order k^2 per node.", ""]

    def section_study(self):
        study = self.study
        if not study.cells:
            return []
        md = ["## The loss against k and the mesh", "",
              "IPM + EMM, EMM and Signorini with the deck's r = 1e12 Pa/m and g = 5e-4 m, the "
              "ball landing on a time level (the window: foundation 0.5 m below, T = 0.1 s; the "
              "sweep's deck runs, T = 0.3, and the impact runs on the impact mesh, T = 2, "
              "included). The thesis: 0.1 % for IPM + EMM at k = 1e-3 on 7820 nodes (p.230), "
              "marked **thesis**; a loss within a factor 2 of it is marked *near 0.1 %*. "
              + ("" if self.has_study else
                 "`drivers/scene8a.sh --study` fills the other cells (the thesis and a finer "
                 "mesh, k = 1e-3 ... 5e-5)."), ""]
        header = ["k (s)"] + [f"{m} ({study.nodes[m]} nodes)" for m in study.meshes]
        rows, shares = [], []
        for k in study.ks:
            row, share_row = [f"{k:g}" + (" **thesis**" if k == 1e-3 else "")], [f"{k:g}"]
            for mesh in study.meshes:
                run = study.get(mesh, "ipm-emm", k)
                cell = "—" if run is None else f"{run['change']:+.4f} %" + (
                    " *near 0.1 %*" if close_to(run["change"], 0.1) else "")
                row.append(cell)
                emm, sig = study.get(mesh, "emm", k), study.get(mesh, "signorini", k)
                share = removed_share(emm, sig)
                share_row.append("—" if share is None else
                                 f"{emm['change']:+.4f} / {sig['change']:+.4f} %: "
                                 f"{percent(share)} %")
            rows.append(row)
            shares.append(share_row)
        md += ["IPM + EMM, dE / E0 across the impact:", "", markdown_table(header, rows), "",
               "EMM against Signorini: dE / E0 of EMM / of Signorini, and the share of "
               "Signorini's loss EMM removes (the thesis: \"strongly\"):", "",
               markdown_table(header, shares), ""]
        return md

    def section_readings(self):
        rows = self.reading_rows()
        if not rows:
            return []
        table = Table(["reading of the thesis's data", "IPM + EMM dE / E0 (%)",
                       "max penetration (m)", "near 0.1 %"])
        for label, run in rows:
            table.add(label, f"{run['change']:+.4f}", f"{run['penetration']:.3g}",
                      "yes" if close_to(run["change"], 0.1) else "no")
        sp = self.readings.get(f"specific-penalty_r{R_PENETRATION}")
        note = (f" At r = {R_PENETRATION} Pa/m the specific penalty penetrates "
                f"{sp['penetration']:.4g} m (the thesis: 0.0034 m)." if sp else "")
        return ["## Does the thesis's 0.1 % appear at any reading of its data?", "",
                f"IPM + EMM at the thesis's k = 1e-3 on the {self.impact_mesh} mesh, g = 5e-4 m, "
                "the window (T = 0.1 s), each row one reading the deck does not take." + note, ""
                ] + table.lines() + [""]


def percent(share):
    """A share in whole percent, without a negative zero."""
    text = f"{100 * share:.0f}"
    return "0" if text == "-0" else text


def close_to(change, loss):
    """A loss (dE in %, negative) within a factor THESIS_LOSS_FACTOR of `loss` (%)."""
    return loss / THESIS_LOSS_FACTOR <= -change <= loss * THESIS_LOSS_FACTOR


def thesis_beside(name, thesis):
    if name == "specific-penalty":
        v = thesis.row("penetration_error", "specific penalty")
        return f"penetration {v.value} {v.unit} ({v.where})" if v else ""
    if name in ("two-step", "two-step-increment"):
        v = thesis.row("penetration_error", "two-step [13]")
        return f"penetration {v.value} {v.unit} ({v.where})" if v else ""
    if name == "ipm-emm":
        v = thesis.row("ipm_emm", "dissipation/penetration")
        if v:
            d, p = v.value.split("/")
            return f"dissipation {d} %, penetration {p} % of R ({v.where})"
    return {"signorini": "dissipates (Fig 8.3)", "compliance": "dissipates (Fig 8.3)",
            "emm": "reduces the dissipation, not to zero (Fig 8.3)",
            "ipm": "conserves better, fluctuates (Fig 8.4)"}.get(name, "")


def method_table(runs, names, thesis, with_thesis=True, caption=""):
    table = Table(["method", "dE across impact (%)", "max abs(E - E0) (%)", "max penetration (m)",
                   "(% of R)", "max active", "Newton its", "steps", "wall (s)", "thesis"],
                  caption=caption)
    for name in names:
        run = runs.get(name)
        if run is None:
            table.add(name, "no run", *[""] * 8)
            continue
        nv = "" if run["converged"] else " **Nv**"
        table.add(f"{label_of(name)}{nv}", f"{run['change']:+.4f}",
                  f"{run['excursion']:.4f}", f"{run['penetration']:.3g}",
                  f"{100 * run['penetration'] / run['radius']:.3g}", run["max_active"],
                  run["newton"], run["steps"], fmt(run["wall"]),
                  thesis_beside(name, thesis) if with_thesis else "")
    return table


def section_head(out, title, info, impact):
    impact_info = (out / "impact.txt").read_text().split() if (out / "impact.txt").is_file() \
        else ["?", "?", "?", "?"]
    any_run = next(iter(impact.values()), None)
    return [
        f"# {title}",
        "",
        f"Command: `{info.get('command', '?')}` ({info.get('date', '?')}, "
        f"{info.get('host', '?')}, revision {info.get('revision', '?')}); then "
        f"`postproc/scene8a_report.py {out}`.",
        "",
        "## What it models and why",
        "",
        "A linear elastic ball (R = 10 m, rho = 1000 kg/m^3, E = 1e11 Pa, nu = 0.35) thrown at "
        "10 m/s on a rigid foundation, frictionless, no gravity: the cross-section of a ball in "
        "2D plane stress (the thesis's \"contraintes planes\"), small strain (the impact strain is "
        "of the order v0 / c = 10 / 1e4 = 1e-3, c = sqrt(E / rho); the motion is a rigid "
        "translation, exact in linear kinematics, plus vibrations). What is measured is the "
        "discrete energy (8.33) E = 1/2 v.Mv + 1/2 u.Ku of the implicit midpoint rule across "
        "the impact: without contact it is conserved exactly, so every change comes from the "
        "contact strategy. Gamma3 is the whole circle with the thesis's 128 contact nodes; "
        "r = 1e12 Pa/m (the thesis's \"r = 1000\" read in GPa/m, ch. 7's convention: read in "
        "Pa it would let the ball sink metres); g = 5e-4 m (0.005 % of R); the ball starts 15 m "
        "above the foundation so that it lands at t = 1.5 s as in Fig 8.3 "
        "(datafiles/scene8a/ball.dat says why for each choice).",
        "",
        f"Impact runs: mesh `{impact_info[0]}` ({mesh_nodes(out, impact_info[0])} nodes; the "
        f"thesis: 7820 nodes, 128 multiplier nodes), foundation at x2 = "
        f"{impact_info[1]}, T = {impact_info[2]} s, k = {impact_info[3]} s. "
        + (f"E0 = {any_run['e0']:.6g} J/m; first contact at t = {fmt(any_run['impact_time'])} s."
           if any_run else ""),
        ""]


ENERGY_TEXT = (
    "dE across impact = (E_end - E0) / E0 with E_end after the ball has left the foundation; "
    "max abs(E - E0) includes the fluctuations during contact; penetration is the largest "
    "u_n - gap over the run; wall = sig-march's wall-clock time. E is the body's energy (8.33) "
    "only: during contact the penalty-type strategies (compliance, specific penalty, IPM) "
    "store energy in the foundation, (r / 2) sum w [u_n]_+^2 for the specific penalty "
    "(3.53), which E does not count; hence their dips during contact.")


def section_energy(impact, fig85, names85, thesis):
    """The energy section and its table of the impact runs (the scene's key table)."""
    key_table = method_table(impact, METHODS, thesis, caption="Energy across the impact per "
                             "strategy, ours with the thesis's statements beside")
    md = ["## Energy across the impact", "", "![Fig 8.3](fig8_3.png)", "",
          "![Fig 8.4](fig8_4.png)", "", "![Fig 8.5](fig8_5.png)", "", ENERGY_TEXT, ""]
    md += key_table.lines()
    md += ["", "Fig 8.5 runs (IPM + EMM against g, and the specific penalty with EMM):", ""]
    md += method_table(fig85, names85 + ["specific-penalty-emm"], thesis, with_thesis=False).lines()
    md += ["", "The thesis (p.230): with g = 0.001 IPM + EMM gives the result of the specific "
           "penalty with EMM, every node staying in compliance without reaching g. Ours:", ""]
    reference = fig85.get("specific-penalty-emm")
    for n in names85:
        run = fig85[n]
        reached = run["penetration"] >= run["gap"] * (1 - 1e-9)
        same = (f"; dE differs from specific penalty + EMM by "
                f"{abs(run['change'] - reference['change']):.3g} %" if reference else "")
        md.append(f"- g = {run['gap']:g} m: the bound is {'reached' if reached else 'not reached'}"
                  f" (max penetration {run['penetration']:.3g} m){same}.")
    return md, key_table


def sweep_cell(run):
    state = status(run)
    return (f"{run['change']:+.3f} %, pen {run['penetration']:.2g} m, "
            f"{run['episodes']} ep., {run['reversals']} rev., "
            f"{fmt(run['wall'] / run['T'], '.3g')} s/s: **{state}**"
            + (f" ({run['failure']})" if state == "Nv" and run["failure"] else ""))


def section_sweep(sweep, ks):
    if not sweep:
        return []
    rows = [[method] + [sweep_cell(run) if (run := sweep_run(sweep, method, k)) else "no run"
                        for k in ks] for method in METHODS]
    return ["## Speed against accuracy and stability over the time step", "",
            "The window: the foundation 0.5 m below the ball (impact at t = 0.05 s), T = "
            f"{fmt(sweep[0]['T'])} s, deck mesh, every strategy for k = "
            + ", ".join(f"{k:g}" for k in ks) + ".", "",
            "![speed against accuracy](speed_accuracy.png)", "",
            "![stability](stability.png)", "", STATUS_TEXT, "",
            markdown_table(["method"] + [f"k = {k:g}" for k in ks], rows), ""]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", type=Path)
    out = parser.parse_args().outdir
    info = read_command(out)
    thesis = load_thesis().scene("8a")
    impact, fig85, sweep = read_runs(out)
    ks = sorted({r["k"] for r in sweep}, reverse=True)
    names85 = sorted((n for n in fig85 if n.startswith("g")), key=lambda n: float(n[1:]))
    charts = draw_charts(out, impact, fig85, names85, sweep, ks)
    write_csvs(out, impact, fig85, sweep)
    title = "Scene 8a: elastic ball impact (thesis ch. 8.5, Figs 8.3-8.5)"
    energy, key_table = section_energy(impact, fig85, names85, thesis)
    impact_mesh = ((out / "impact.txt").read_text().split() or ["deck"])[0] \
        if (out / "impact.txt").is_file() else "deck"
    found = Found(out, impact, sweep, impact_mesh)
    write_study_csv(out, found.study)
    results = checks(impact, thesis, found)
    md = section_head(out, title, info, impact) + energy
    md += found.section_readings() + found.section_study() + found.section_bar()
    md += results.claims_section("## Checks (issues 5, 14 and 30)", "",
                                 "Thesis values from `postproc/thesis_values.csv`.")
    md += section_sweep(sweep, ks)
    md += ["Files: `methods.csv`, `sweep.csv`; per run `energy.csv` (every step) and `case.hist`. "
           "Fig 8.2 (positions and contact forces before, during and after the impact) is for "
           "ParaView: `fig82/ipm-emm/ball.pvd` holds every step of IPM + EMM across the impact "
           "(point data displacement, velocity, contact_pressure; *Warp By Vector*).", ""]
    print(write_report(out, "\n".join(md), "8a", title, info, results, key_table=key_table,
                       charts=charts))


if __name__ == "__main__":
    main_guard(main)
