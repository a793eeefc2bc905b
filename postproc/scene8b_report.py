#!/usr/bin/python3
"""Scene 8b report: the hyperelastic ring impact with friction (thesis ch. 8.5) beside the
thesis's statements.

    postproc/scene8b_report.py OUTDIR

OUTDIR is what drivers/scene8b.sh wrote: command.txt, and one folder per run (impact/<method>,
friction/<method>_<law>, r/specific-penalty_r<r>, sweep/<method>_n<n>_r<r>, fig86) holding
ring.dat (its deck), run.txt (method, friction law, placement, r), energy.csv and case.hist
(sig-march), march.log and wall.txt (the stage's wall-clock seconds). Writes OUTDIR/report.md,
OUTDIR/runs.csv, OUTDIR/scene.json (the scene index entry) and the PNGs the report shows. The
thesis's values come from the 8b rows of postproc/thesis_values.csv. Every number in the report is
read from those files or computed from them here (with the report library postproc/sigreport).
"""
import argparse
import csv
import math
from pathlib import Path

from sigreport import charts
from sigreport.ds import sig_dump_json
from sigreport import (Checks, MapCell, MapPanel, Point, Series, Table, load_thesis, main_guard,
                       markdown_table, pyplot, read_command, read_ds, speed_accuracy_chart,
                       stability_map, write_scene_json)

plt = pyplot()

LABEL = {
    "signorini": "Signorini at t_n",
    "emm": "EMM (Signorini, equivalent mass)",
    "specific-penalty": "specific penalty (8.32)",
    "two-step": "two-step [13], persistency on the midpoint velocity (C15)",
    "two-step-increment": "two-step [13], persistency on the increment",
    "ipm": "IPM (8.30)-(8.31)",
    "ipm-emm": "IPM + EMM",
    "ipm-emm-midpoint": "IPM + EMM, midpoint stress (not Gonzalez's)",
}
MARKER = {"signorini": "o", "emm": "v", "specific-penalty": "D", "two-step": "^",
          "two-step-increment": "<", "ipm": "P", "ipm-emm": "*", "ipm-emm-midpoint": "x"}
FIG87 = ("specific-penalty", "emm", "two-step", "ipm-emm")  # the thesis's four
GAIN = 0.1          # stability: E_end > E0 (1 + 0.1 %) frictionless is a gain
DISSIPATES = 1.0    # frictionless loss beyond 1 % flagged
BALANCE_TOL = 1e-8  # E + interface - friction work - wall work constant, relative to E0
SIGN_TOL = 1e-9     # a step's friction or wall work above this x E0 is a gain


def fmt(x, spec=".3g"):
    return "n/a" if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, spec)


# ---------------------------------------------------------------------------------------------
# Reading the files


def read_run(folder):
    """One run: method, friction, placement, r, k, T, the energy rows, wall time and HIST
    scalars, and its measures; None if it did not march."""
    energy = folder / "energy.csv"
    if not energy.is_file():
        return None
    with energy.open() as f:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    if not rows:
        return None
    method, friction, placement, r = (folder / "run.txt").read_text().split()
    hist = {}
    if (folder / "case.hist").is_file():
        ds = read_ds(folder / "case.hist", arrays=["converged", "failure", "time_march", "k", "T"])
        hist = {n: v if isinstance(v, str) else v[0] for n, v in ds.values.items()}
    wall = folder / "wall.txt"
    run = {"folder": folder, "name": folder.name, "method": method, "friction": friction,
           "placement": placement, "r": float(r), "rows": rows, "hist": hist,
           "k": hist.get("k", math.nan), "T": hist.get("T", math.nan),
           "wall": float(wall.read_text()) if wall.is_file() else math.nan}
    run.update(measures(run))
    return run


def measures(run):
    rows = run["rows"]
    e = [r["total"] for r in rows]
    e0 = e[0]
    active = [int(r["active_nodes"]) for r in rows]
    contact = [i for i, a in enumerate(active) if a > 0]
    first = contact[0] if contact else None
    balance = [r["total"] + r["interface"] - r["friction_work"] - r["wall_work"] for r in rows]
    steps_planned = round(run["T"] / run["k"]) if run["k"] == run["k"] else len(rows) - 1
    converged = int(run["hist"].get("converged", 1)) != 0 and len(rows) == steps_planned + 1
    before = rows[:first] if first is not None else rows
    d_friction = [b["friction_work"] - a["friction_work"] for a, b in zip(rows, rows[1:])]
    d_wall = [b["wall_work"] - a["wall_work"] for a, b in zip(rows, rows[1:])]
    in_contact = [rows[i]["newton_iterations"] for i in contact]
    return {
        "converged": converged,
        "failure": run["hist"].get("failure", ""),
        "e0": e0,
        "change": 100 * (e[-1] - e0) / e0,
        "balance_drift": max(abs(b - balance[0]) for b in balance) / e0,
        "penetration": max(r["max_penetration"] for r in rows),
        "impact_time": rows[first]["time"] if first is not None else math.nan,
        "impact_step": first,
        "free_drift": max(abs(r["total"] - e0) for r in before) / e0,
        "free_iterations": int(sum(r["newton_iterations"] for r in before)),
        "free_steps": len(before) - 1,
        "friction_work": rows[-1]["friction_work"],
        "wall_work": rows[-1]["wall_work"],
        "worst_friction_step": max(d_friction, default=0.0) / e0,
        "worst_wall_step": max(d_wall, default=0.0) / e0,
        "max_active": max(active),
        "newton": int(sum(r["newton_iterations"] for r in rows)),
        "contact_steps": len(contact),
        "newton_per_contact_step": sum(in_contact) / len(in_contact) if in_contact else math.nan,
        "steps": len(rows) - 1,
    }


def read_group(out, group):
    folder = out / group
    if not folder.is_dir():
        return {}
    return {r["name"]: r for f in sorted(folder.iterdir()) if f.is_dir() and (r := read_run(f))}


# ---------------------------------------------------------------------------------------------
# Charts


def window_of(runs, before=0.05, after=1.0):
    impacts = [r["impact_time"] for r in runs if not math.isnan(r["impact_time"])]
    if not impacts:
        return (-math.inf, math.inf)
    return (min(impacts) - before, min(impacts) + after)


def energy_chart(out, runs, title, png, window, key="total", label_of=None):
    charts.energy_chart(out / png, [
        (label_of(run) if label_of else LABEL.get(run["method"], run["method"]),
         MARKER.get(run["method"], "."), [r["time"] for r in run["rows"]],
         [r[key] / run["e0"] for r in run["rows"]]) for run in runs], title, window, markersize=2)


def balance_chart(out, run, png, window):
    """The energy balance per step split into its terms, each over E0: kinetic, strain,
    interface (stored by the foundation), and the work dissipated by friction and by the wall;
    their sum (E + interface - friction work - wall work) is constant."""
    rows = [r for r in run["rows"] if window[0] <= r["time"] <= window[1]]
    t = [r["time"] for r in rows]
    e0 = run["e0"]
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    ax.plot(t, [r["kinetic"] / e0 for r in rows], label="kinetic 1/2 v.M v")
    ax.plot(t, [r["elastic"] / e0 for r in rows], label="strain sum W(C)")
    ax.plot(t, [r["interface"] / e0 for r in rows], label="interface (r/2) sum w [q]_+^2")
    ax.plot(t, [-r["friction_work"] / e0 for r in rows], label="dissipated by friction")
    ax.plot(t, [-r["wall_work"] / e0 for r in rows], label="dissipated by the wall")
    ax.plot(t, [(r["total"] + r["interface"] - r["friction_work"] - r["wall_work"]) / e0
                for r in rows], "k--", label="sum (constant)")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("energy / E0")
    ax.set_title(f"Energy balance per step: {LABEL.get(run['method'])}, {run['friction']}")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / png, dpi=110)
    plt.close(fig)


def positions_chart(out, folder, png):
    """Fig 8.6: the deformed ring's outline at successive kept states (case.hist u on case.nopo's
    boundary edges), before, during and after the impact."""
    mesh = sig_dump_json(folder / "case.nopo", values=True)  # a NOPO, not a DS
    hist = read_ds(folder / "case.hist", arrays=["u", "output_time"])
    xy = mesh["coordinates"]
    edges = mesh["edges"]  # (a, b, ref) triples, 1-based nodes
    u = hist.array("u")
    times = hist["output_time"]
    energy = folder / "energy.csv"
    with energy.open() as f:
        rows = list(csv.DictReader(f))
    first = next((float(r["time"]) for r in rows if int(r["active_nodes"]) > 0), times[0])
    wanted = [first - 0.2, first, first + 0.1, first + 0.2, first + 0.35, first + 0.5, times[-1]]
    picks = sorted({min(range(len(times)), key=lambda i: abs(times[i] - w)) for w in wanted})
    fig, ax = plt.subplots(figsize=(8, 4))
    for n, i in enumerate(picks):
        color = plt.cm.viridis(n / max(1, len(picks) - 1))
        for e in range(0, len(edges), 3):
            a, b = edges[e] - 1, edges[e + 1] - 1
            pa = (xy[2 * a] + u[i][2 * a], xy[2 * a + 1] + u[i][2 * a + 1])
            pb = (xy[2 * b] + u[i][2 * b], xy[2 * b + 1] + u[i][2 * b + 1])
            ax.plot((pa[0], pb[0]), (pa[1], pb[1]), color=color, linewidth=0.8,
                    label=f"t = {times[i]:.3f} s" if e == 0 else None)
    ax.axhline(0.0, color="k", linewidth=1.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x1 (m)")
    ax.set_ylabel("x2 (m)")
    ax.set_title("Fig 8.6: the ring before, during and after the impact (IPM + EMM, mu1)")
    ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(out / png, dpi=110)
    plt.close(fig)


# ---------------------------------------------------------------------------------------------
# Tables


def run_table(runs, caption, thesis_of=lambda run: ""):
    table = Table(["run", "dE / E0 (%)", "balance drift / E0", "max penetration (m)",
                   "friction work (J/m)", "wall work (J/m)", "contact steps",
                   "Newton its per contact step", "wall (s)", "thesis"], caption=caption)
    for run in runs:
        status = "" if run["converged"] else f" **Nv** ({run['failure']})"
        table.add(f"{LABEL.get(run['method'], run['method'])}, {run['friction']}{status}",
                  f"{run['change']:+.4f}", f"{run['balance_drift']:.1e}",
                  f"{run['penetration']:.4g}", f"{run['friction_work']:.4g}",
                  f"{run['wall_work']:.4g}", run["contact_steps"],
                  fmt(run["newton_per_contact_step"], ".2f"), fmt(run["wall"]), thesis_of(run))
    return table


def stability_status(run):
    if not run["converged"]:
        return "Nv"
    flags = []
    if run["change"] > GAIN:
        flags.append("gain")
    if run["change"] < -DISSIPATES:
        flags.append("dissipates")
    return "+".join(flags) or "ok"


# ---------------------------------------------------------------------------------------------
# The report


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", type=Path)
    out = parser.parse_args().outdir
    info = read_command(out)
    thesis = load_thesis().scene("8b")
    penetration_row = thesis.row("penetration_error", "specific penalty/two-step [13]")
    thesis_sp, thesis_ts = (float(v) for v in penetration_row.value.split("/"))

    impact = read_group(out, "impact")
    friction = read_group(out, "friction")
    r_runs = read_group(out, "r")
    sweep = list(read_group(out, "sweep").values())
    fig86 = read_run(out / "fig86") if (out / "fig86").is_dir() else None
    quick = info.get("quick", "0") == "1"

    window = window_of(list(impact.values()) + list(friction.values()))
    charts = {}
    energy_chart(out, [impact[m] for m in FIG87 if m in impact],
                 "Fig 8.7: frictionless energy near the impact", "fig8_7.png", window)
    energy_chart(out, [r for m, r in impact.items() if m not in FIG87],
                 "Frictionless, the other strategies", "fig8_7_others.png", window)
    energy_chart(out, list(friction.values()), "Fig 8.8: energy near the impact with friction "
                 "(mu0 = 0.2)", "fig8_8.png", window,
                 label_of=lambda r: f"{LABEL.get(r['method'])}, {r['friction']}")
    charts.update(fig8_7="fig8_7.png", fig8_7_others="fig8_7_others.png", fig8_8="fig8_8.png")
    balance_run = friction.get("ipm-emm_mu2") or next(iter(friction.values()), None)
    if balance_run:
        balance_chart(out, balance_run, "balance.png", window)
        charts["balance"] = "balance.png"
    if fig86 and (out / "fig86" / "case.hist").is_file():
        positions_chart(out, out / "fig86", "fig8_6.png")
        charts["fig8_6"] = "fig8_6.png"

    # Speed against accuracy and the stability map over the sweep (the window, frictionless).
    ns = sorted({round(1 / r["k"]) for r in sweep})
    rs = sorted({r["r"] for r in sweep})
    methods = [m for m in LABEL if any(r["method"] == m for r in sweep)]
    if sweep:
        series = []
        for method in methods:
            for rr in rs:
                runs = sorted((r for r in sweep if r["method"] == method and r["r"] == rr),
                              key=lambda r: r["k"], reverse=True)
                if not runs or (rr != rs[-1] and method not in ("specific-penalty", "ipm",
                                                                "ipm-emm")):
                    continue
                label = LABEL[method] + (f", r = {rr:g}" if method in ("specific-penalty", "ipm",
                                                                        "ipm-emm") else "")
                series.append(Series(label, [
                    Point(r["wall"] / r["T"], max(abs(r["change"]), 1e-6) if r["converged"]
                          else None, f"k=1/{round(1 / r['k'])}") for r in runs],
                    marker=MARKER[method], hollow=rr != rs[-1], markersize=5))
        speed_accuracy_chart(out / "speed_accuracy.png", series,
                             xlabel="wall time per simulated second (s)",
                             ylabel="|energy change| / E0 across the impact (%)",
                             title="Speed against accuracy, frictionless (labels: k)",
                             figsize=(7.5, 4.5), dpi=110, legend_fontsize=6, label_fontsize=6)
        cells, row_names = [], []
        for method in methods:
            for rr in (rs if method in ("specific-penalty", "ipm", "ipm-emm") else [rs[-1]]):
                row = []
                for n in ns:
                    run = next((r for r in sweep if r["method"] == method and r["r"] == rr
                                and round(1 / r["k"]) == n), None)
                    if run is None:
                        row.append(MapCell("no run", "missing"))
                        continue
                    status = stability_status(run)
                    # A run that stopped: the step it stopped at and what it had lost by then.
                    text = (f"Nv at step {run['steps'] + 1}\n{run['change']:+.2f}% before"
                            if status == "Nv" else
                            f"{run['change']:+.2f}%\npen {run['penetration']:.2g}\n{status}")
                    row.append(MapCell(text, status))
                cells.append(row)
                row_names.append(method + (f" r={rr:g}" if method in ("specific-penalty", "ipm",
                                                                     "ipm-emm") else ""))
        stability_map(out / "stability.png", [MapPanel(
            "Stability: energy change, penetration (m), status per strategy, r and k",
            row_names, [f"k = 1/{n}" for n in ns], cells)], fontsize=6)
        charts.update(speed_accuracy="speed_accuracy.png", stability="stability.png")

    with (out / "runs.csv").open("w") as f:
        f.write("group,run,method,friction,placement,r,k,energy_change_percent,balance_drift,"
                "max_penetration,friction_work,wall_work,contact_steps,newton,converged,"
                "wall_seconds\n")
        for group, runs in (("impact", impact.values()), ("friction", friction.values()),
                            ("r", r_runs.values()), ("sweep", sweep),
                            ("fig86", [fig86] if fig86 else [])):
            for run in runs:
                f.write(f"{group},{run['name']},{run['method']},{run['friction']},"
                        f"{run['placement']},{run['r']:g},{run['k']:.9g},{run['change']:.9g},"
                        f"{run['balance_drift']:.3g},{run['penetration']:.9g},"
                        f"{run['friction_work']:.9g},{run['wall_work']:.9g},"
                        f"{run['contact_steps']},{run['newton']},{int(run['converged'])},"
                        f"{run['wall']}\n")

    # Checks: the "what it must show" that the runs can hold.
    checks = Checks()
    all_runs = list(impact.values()) + list(friction.values()) + list(r_runs.values()) + sweep + \
        ([fig86] if fig86 else [])
    done = [r for r in all_runs if r["converged"]]
    checks.add("every impact and friction run converges at every step",
               all(r["converged"] for r in list(impact.values()) + list(friction.values())),
               ours=", ".join(f"{r['name']}: {r['failure']}" for r in
                              list(impact.values()) + list(friction.values())
                              if not r["converged"]) or "all")
    gonzalez = [r for r in done if not r["method"].endswith("-midpoint")]
    worst = max((r["balance_drift"] for r in gonzalez), default=math.nan)
    checks.add(f"balance E + interface - friction work - wall work constant to {BALANCE_TOL:g} E0 "
               "(Prop. 8.1 with Gonzalez's stress; every converged run of it)",
               not math.isnan(worst) and worst <= BALANCE_TOL, ours=f"worst {worst:.2e}")
    thesis_runs = [r for r in list(impact.values()) + list(friction.values())
                   if r["placement"] == "thesis" and r["impact_step"]]
    if thesis_runs:
        drift = max(r["free_drift"] for r in thesis_runs)
        its = sum(r["free_iterations"] for r in thesis_runs)
        # Rounding: v = (2 / k)(u_n - u_{n-1}) - v_{n-1} differences positions up to 90 m apart.
        checks.add("free flight (steps before the first contact, t < 9 s) exact: energy constant "
                   "to rounding (1e-11 E0), no Newton iteration", drift <= 1e-11 and its == 0,
                   ours=f"{thesis_runs[0]['free_steps']} steps, drift {drift:.1e} E0, "
                        f"{its} iterations, first contact at t = "
                        f"{fmt(thesis_runs[0]['impact_time'], '.4f')} s")
    sp = impact.get("specific-penalty")
    if sp:
        checks.add("specific penalty conserves E + interface energy (3.53): no wall work",
                   abs(sp["wall_work"]) <= BALANCE_TOL * sp["e0"] and sp["balance_drift"] <=
                   BALANCE_TOL, ours=f"wall work {sp['wall_work']:.2e} J/m, balance drift "
                                     f"{sp['balance_drift']:.1e}")
    ipms = [r for r in all_runs if r["method"].startswith("ipm") and r["converged"]]
    if ipms:
        g = 0.002
        deepest = max(r["penetration"] for r in ipms)
        checks.add("IPM keeps the penetration <= g = 0.002 m at every step (every IPM run)",
                   deepest <= g * (1 + 1e-8), ours=f"max {deepest:.6g} m over {len(ipms)} runs")
    signed = [r for r in done if r["friction"] != "none" or r["method"].startswith("ipm")]
    if signed:
        wf = max(r["worst_friction_step"] for r in signed)
        ww = max(r["worst_wall_step"] for r in signed if r["method"] != "two-step")
        checks.add("friction and the wall only dissipate: every step's friction work and (but "
                   "two-step's) wall work <= 0", wf <= SIGN_TOL and ww <= SIGN_TOL,
                   ours=f"largest step gain: friction {wf:.1e} E0, wall {ww:.1e} E0")
    ipm_emm = impact.get("ipm-emm")
    two = impact.get("two-step")
    if sp and ipm_emm and two:
        ratio_sp = sp["penetration"] / ipm_emm["penetration"]
        ratio_ts = two["penetration"] / ipm_emm["penetration"]
        checks.add("thesis: IPM's penetration 30-35x smaller than the specific penalty's and "
                   "two-step's (l.16020)", 30 / 1.5 <= min(ratio_sp, ratio_ts) and
                   max(ratio_sp, ratio_ts) <= 35 * 1.5,
                   ours=f"{ratio_sp:.1f}x and {ratio_ts:.1f}x")
        checks.add(f"r = 1e9 Pa/m reading (C13): specific penalty's penetration within a factor 3 "
                   f"of the thesis's {thesis_sp} m",
                   thesis_sp / 3 <= sp["penetration"] <= 3 * thesis_sp,
                   ours=f"{sp['penetration']:.4g} m")
    mu1, mu2 = friction.get("ipm-emm_mu1"), friction.get("ipm-emm_mu2")
    if mu1 and mu2:
        checks.add("thesis: mu2 dissipates much more than mu1 (Fig 8.8): friction work of mu2 "
                   "at least 1.5x mu1's", mu2["friction_work"] <= 1.5 * mu1["friction_work"],
                   ours=f"{-mu2['friction_work']:.4g} against {-mu1['friction_work']:.4g} J/m "
                        f"({mu2['friction_work'] / mu1['friction_work']:.2f}x)")
    mid = impact.get("ipm-emm-midpoint")
    if mid and ipm_emm:
        checks.add("Gonzalez's stress against the midpoint stress: the balance holds with "
                   "Gonzalez's only", ipm_emm["balance_drift"] <= BALANCE_TOL <
                   mid["balance_drift"], ours=f"{ipm_emm['balance_drift']:.1e} against "
                                              f"{mid['balance_drift']:.1e}")

    # The report text.
    title = "Scene 8b: hyperelastic ring impact with friction (thesis ch. 8.5, Figs 8.6-8.8)"
    any_run = next(iter(impact.values()), None)

    def thesis_penetration(run):
        if run["method"] == "specific-penalty":
            return f"penetration {thesis_sp} m (p.234)"
        if run["method"] == "two-step":
            return f"penetration {thesis_ts} m (p.234)"
        if run["method"] == "ipm-emm":
            return "penetration 30-35x smaller, <= g = 0.002 m"
        if run["method"] == "emm":
            return "dissipates more than IPM + EMM"
        return ""

    key_table = run_table([impact[m] for m in LABEL if m in impact],
                          "Frictionless: the energy across the impact per strategy (Fig 8.7), "
                          "ours with the thesis's statements beside", thesis_penetration)
    md = [f"# {title}", "",
          f"Command: `{info.get('command', '?')}` ({info.get('date', '?')}, "
          f"{info.get('host', '?')}, revision {info.get('revision', '?')}); then "
          f"`postproc/scene8b_report.py {out}`." + (" **Quick variant**: the impact window "
                                                     "only, fewer runs." if quick else ""), "",
          "## What it models and why", "",
          "A ring 9 <= |x - (100, 100)| <= 10 (m) of the thesis's Ciarlet-Geymonat material "
          "(c1 = 0.5 MPa, c2 = 0.005 MPa, a = 0.35 MPa, rho = 1000) thrown at (10, -10) m/s onto "
          "the rigid half plane x2 <= 0, no gravity: large deformation (total Lagrangian P1), "
          "since the impact pressure rho c_p V ~ 0.6 MPa is of the order of the moduli and the "
          "ring flattens; plane strain (choice C13, as scene 7b). The implicit midpoint rule with "
          "Gonzalez's algorithmic stress (3.41) conserves the discrete energy (8.33) exactly "
          "without contact, so every change across the impact is the contact's and the "
          "friction's. Mesh: 128 x 13 nodes (1664, the thesis's), Gamma3 = the whole outer "
          "circle (128 multiplier nodes). Data as printed: T = 10 s, k = 1/300, first contact "
          "at t = 9 s (C17); r = 1e9 Pa/m (C13: the printed \"1000 Pa\" read as 1000 MPa/m), "
          "g = 0.002 m, mu0 = 0.2; contact and friction at t_n at the current position "
          "(datafiles/scene8b/ring.dat says why for each choice).", ""]
    if any_run:
        md += [f"Impact runs: placement `{any_run['placement']}`, E0 = {any_run['e0']:.7g} J/m "
               f"(the thesis's 128-gon ring: 5.9666e6), first contact at t = "
               f"{fmt(any_run['impact_time'], '.4f')} s.", ""]
    if "fig8_6" in charts:
        md += ["## Fig 8.6: the ring before, during and after the impact", "",
               "![Fig 8.6](fig8_6.png)", "",
               "`fig86/ring.pvd` holds a state every 10 steps (IPM + EMM, mu1) for ParaView: "
               "point data displacement (*Warp By Vector*), velocity, contact_pressure.", ""]
    md += ["## Fig 8.7: frictionless energy near the impact", "", "![Fig 8.7](fig8_7.png)", "",
           "![the other strategies](fig8_7_others.png)", "",
           "dE / E0 = (E_end - E0) / E0 at the end of the run; the balance drift is the largest "
           "change of E + interface - friction work - wall work (exact with Gonzalez's stress, "
           "to the Newton tolerance); penetration is the largest q_n over the run; wall = "
           "sig-march's wall-clock time.", ""]
    md += key_table.lines()
    if sp and ipm_emm and two:
        md += ["", f"Penetrations: specific penalty {sp['penetration']:.4g} m (thesis "
               f"{thesis_sp} m), two-step {two['penetration']:.4g} m (thesis {thesis_ts} m), "
               f"IPM + EMM {ipm_emm['penetration']:.4g} m: ratios "
               f"{sp['penetration'] / ipm_emm['penetration']:.1f}x and "
               f"{two['penetration'] / ipm_emm['penetration']:.1f}x (thesis: 30 to 35x).", ""]
    md += ["## Fig 8.8: with friction", "", "![Fig 8.8](fig8_8.png)", ""]
    md += run_table(list(friction.values()), "With friction, mu0 = 0.2").lines()
    if balance_run:
        md += ["", "## The energy balance per step", "", "![balance](balance.png)", "",
               f"{LABEL.get(balance_run['method'])} with {balance_run['friction']}: the terms of "
               "(8.34) per step, E_n - E_{n-1} = -sum N (q_n - q_{n-1}) - sum T slip, the normal "
               "work split into the change of the foundation's stored energy and the wall's "
               "work. Per run, `energy.csv` has every step's kinetic, elastic (strain), "
               "interface, friction_work, wall_work, normal_force and tangential_force.", ""]
    if r_runs:
        md += ["## C13: the specific penalty's penetration against r", ""]
        ordered = sorted(r_runs.values(), key=lambda r: r["r"])
        g = 0.002
        rows = [[f"{r['r']:g}", f"{r['penetration']:.4g}", f"{r['penetration'] / g:.1f}x",
                 f"{r['change']:+.4f}", fmt(r["newton_per_contact_step"], ".2f"),
                 "yes" if r["converged"] else "Nv"] for r in ordered]
        md += [markdown_table(["r (Pa/m)", "max penetration (m)", "against IPM's g",
                               "dE / E0 (%)", "Newton its per contact step", "converged"],
                              rows), ""]
        # The r whose penetration is the thesis's, by log-log interpolation between the runs
        # that bracket it.
        bracket = [(a, b) for a, b in zip(ordered, ordered[1:])
                   if (a["penetration"] - thesis_sp) * (b["penetration"] - thesis_sp) <= 0]
        if bracket:
            a, b = bracket[0]
            slope = math.log(b["penetration"] / a["penetration"]) / math.log(b["r"] / a["r"])
            r_thesis = a["r"] * (thesis_sp / a["penetration"]) ** (1 / slope)
            md += [f"The thesis's {thesis_sp} m is the penetration of r = {r_thesis:.2g} Pa/m "
                   f"here (log-log interpolation, penetration ~ r^{slope:.2f}); at that r IPM's "
                   f"g = {g} m is {thesis_sp / g:.0f}x smaller, the thesis's \"30 to 35 times\" "
                   f"({thesis_sp}/{g} and {thesis_ts}/{g} are {thesis_sp / g:.0f} and "
                   f"{thesis_ts / g:.0f}). The deck's r = 1e9 Pa/m (C13: \"1000\" in the moduli's "
                   "unit per metre, MPa/m) penetrates far less.", ""]
        else:
            md += [f"The thesis's {thesis_sp} m lies outside the r of these runs.", ""]
    if sweep:
        md += ["## Speed against accuracy and stability", "",
               f"The window: the same ring 5 cm above the foundation, T = "
               f"{fmt(sweep[0]['T'])} s, frictionless, k = " +
               ", ".join(f"1/{n}" for n in ns) + ", r = " + ", ".join(f"{x:g}" for x in rs) +
               " for the penalty-type strategies.", "",
               "![speed against accuracy](speed_accuracy.png)", "", "![stability](stability.png)",
               "", f"Status: Nv = a step's Newton failed (the march stops there); gain = the "
               f"energy grew by more than {GAIN:g} %; dissipates = it fell by more than "
               f"{DISSIPATES:g} %; ok otherwise.", ""]
        rows = [[r["name"], f"{r['change']:+.4f}", f"{r['penetration']:.3g}",
                 fmt(r["newton_per_contact_step"], ".2f"), fmt(r["wall"] / r["T"]),
                 stability_status(r) + (f" ({r['failure']})" if not r["converged"] else "")]
                for r in sorted(sweep, key=lambda r: (r["method"], r["r"], r["k"]))]
        md += [markdown_table(["run", "dE / E0 (%)", "max penetration (m)",
                               "Newton its per contact step", "wall s per simulated s",
                               "status"], rows), ""]
    md += ["## Checks (issue 14, \"what it must show\")", ""]
    md += checks.table(("name", "ours", "result"),
                       header=("requirement", "measured", "result")).lines()
    md += ["", "Thesis values from `postproc/thesis_values.csv`; `runs.csv` has every run's "
           "numbers, each run's `energy.csv` every step.", ""]
    (out / "report.md").write_text("\n".join(md))
    write_scene_json(out, "8b", title, info, checks, key_table=key_table, charts=charts)
    print(out / "report.md")


if __name__ == "__main__":
    main_guard(main)
