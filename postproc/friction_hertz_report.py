#!/usr/bin/python3
"""Frictional Hertz report: the half disc pressed and pushed sideways, held by Coulomb friction.

    postproc/friction_hertz_report.py OUTDIR

OUTDIR is what drivers/friction_hertz.sh wrote: command.txt, N<N>/<run>/ with hertz.dat (the
run's deck), summary.json and contact.csv (sig-post). Writes OUTDIR/report.md, its PNGs and
OUTDIR/scene.json (the scene index entry). Every number is read from those files or computed here
from the deck's data: the Hertz pressure (7.38) and Cattaneo and Mindlin's stick zone
c = b sqrt(1 - Q / (mu P)). Built on the report library postproc/sigreport.
"""
import argparse
import csv
import math
from pathlib import Path

import numpy as np

from sigreport import (Checks, Deck, Point, ReportError, Series, Table, fmt, main_guard, pyplot,
                       read_command, read_summary, run_cell, save_figure, solve_seconds,
                       speed_accuracy_chart, write_report)

plt = pyplot()

METHODS = ("pdas", "alm", "projection", "penalty")
# The runs that stand for each method (drivers/friction_hertz.sh): parameters that converge on a
# body held sideways by friction alone; the sweep shows where the others fail.
DEFAULT = {"pdas": "1e2", "alm": "1e2", "projection": "1", "penalty": "1e2"}
PARAMETER = {"pdas": "gamma", "alm": "r", "projection": "c", "penalty": "r"}
LABEL = {"pdas": "PDAS", "alm": "ALM", "projection": "projection", "penalty": "penalty"}
COLOR = {"pdas": "C0", "alm": "C2", "projection": "C1", "penalty": "C3"}
MARKER = {"pdas": "o", "alm": "^", "projection": "s", "penalty": "D"}
# Checks: forces of the exact methods agree to this share of their maximum (issue 10's GetFEM
# tolerance), the equilibrium and the Coulomb cone hold to AGREE of the loads.
AGREE = 1e-6
CONE = 1e-6


# ---------------------------------------------------------------------------------------------
# Reading the files


def read_scene_command(out):
    info = read_command(out, required=("command", "meshes", "reference", "sweep_n"))
    info["meshes"] = [int(n) for n in info["meshes"].split()]
    info["reference"] = int(info["reference"])
    info["sweep_n"] = int(info["sweep_n"])
    return info


class Data:
    """The deck's loads and material, the Hertz pressure and Cattaneo and Mindlin's traction."""

    def __init__(self, path):
        deck = Deck.read(path)
        self.R = deck.number("MESH", "R")
        self.q, minus_p = deck.numbers("TRACTION", "f")
        self.p = -minus_p
        self.E = deck.number("MATERIAL", "E")
        self.nu = deck.number("MATERIAL", "nu")
        self.mu = deck.number("FRICTION", "mu")
        self.P, self.Q = 2 * self.R * self.p, 2 * self.R * self.q  # per unit thickness
        self.b = 2 * math.sqrt(2 * self.R**2 * self.p * (1 - self.nu**2) / (self.E * math.pi))
        self.p0 = 4 * self.R * self.p / (math.pi * self.b)
        self.ratio = self.Q / (self.mu * self.P)
        self.c = self.b * math.sqrt(1 - self.ratio)

    def pressure(self, x):
        x = np.asarray(x, dtype=float)
        return self.p0 * np.sqrt(np.clip(1 - (x / self.b)**2, 0, None))

    def cattaneo(self, x):
        """mu p - the stick zone's correction mu p0 (c / b) sqrt(1 - x^2 / c^2)."""
        x = np.asarray(x, dtype=float)
        return self.mu * (self.pressure(x)
                          - self.p0 * self.c / self.b * np.sqrt(np.clip(1 - (x / self.c)**2, 0, None)))


def read_contact(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise ReportError(f"{path} has no rows")
    columns = ("x1", "multiplier", "pressure", "tangential_multiplier", "tangential_pressure",
               "slip")
    try:
        c = {k: np.array([float(r[k]) for r in rows]) for k in columns}
        c["normal_status"] = np.array([r["normal_status"] for r in rows])
        c["friction_status"] = np.array([r["friction_status"] for r in rows])
    except (KeyError, ValueError) as e:
        raise ReportError(f"{path}: {e}")
    return c


def collect_runs(out, meshes):
    runs = {}
    for n in meshes:
        for d in sorted((out / f"N{n}").glob("*")):
            if d.name == "base" or not (d / "summary.json").is_file():
                continue
            s = read_summary(d, required=("converged", "iterations", "times"))
            run = {"n": n, "name": d.name, "dir": d, "summary": s, "converged": s["converged"],
                   "iterations": s["iterations"], "contact": read_contact(d / "contact.csv"),
                   "seconds": solve_seconds(s)}
            method, _, value = d.name.partition("_")
            run["method"], run["value"] = method, value
            runs[(n, d.name)] = run
    return runs


# ---------------------------------------------------------------------------------------------
# What a run shows


def zones(c):
    """Contact and stick zones: (first x1, last x1) of the nodes in contact and of S= nodes."""
    contact = c["normal_status"] != "free"
    stick = c["friction_status"] == "S="
    span = (lambda m: (c["x1"][m].min(), c["x1"][m].max()) if m.any() else (math.nan, math.nan))
    return span(contact), span(stick)


def checks_of(run, data):
    """Equilibrium of the loads, the Coulomb cone and the stick / slip conditions, relative to P."""
    c = run["contact"]
    N, T, slip = c["multiplier"], c["tangential_multiplier"], c["slip"]
    status = c["friction_status"]
    scale = data.P
    cone = np.max(np.abs(T) - data.mu * N) / scale
    slipping = (status == "S+") | (status == "S-")
    sliding_force = np.max(np.abs(np.abs(T[slipping]) - data.mu * N[slipping])) / scale if slipping.any() else 0
    wrong_way = int(np.sum(slipping & (np.sign(T) != np.sign(slip))))
    stuck_slip = np.max(np.abs(slip[status == "S="])) if (status == "S=").any() else 0.0
    return {"normal": abs(N.sum() - data.P) / scale, "tangential": abs(T.sum() - data.Q) / scale,
            "cone": cone, "sliding": sliding_force, "wrong_way": wrong_way, "stuck_slip": stuck_slip}


def shared_error(run, reference):
    """Max differences of the normal and tangential pressures at the Gamma3 nodes the run shares
    with the reference (the reference's arc refines the run's), relative to the reference's max."""
    a, r = run["contact"], reference["contact"]
    index = {round(x, 9): k for k, x in enumerate(r["x1"])}
    pairs = [(k, index[round(x, 9)]) for k, x in enumerate(a["x1"]) if round(x, 9) in index]
    if not pairs:
        return math.nan, math.nan
    i, j = (np.array(v) for v in zip(*pairs))
    en = np.max(np.abs(a["pressure"][i] - r["pressure"][j])) / np.max(np.abs(r["pressure"]))
    et = np.max(np.abs(a["tangential_pressure"][i] - r["tangential_pressure"][j])) / np.max(
        np.abs(r["tangential_pressure"]))
    return en, et


def table(header, rows):
    return Table(header, rows).lines()


def iterations_cell(run):
    return run_cell(run["converged"], run["iterations"], detail=run["iterations"])


# ---------------------------------------------------------------------------------------------
# Sections


def section_model(data):
    return [
        "## What is modelled, and why",
        "",
        f"A linear elastic half disc (R = {data.R:g}, E = {data.E:g} GPa, nu = {data.nu:g}), 2D "
        f"plane strain and small strain as scene 7a (a long cylinder, strains below 1e-2), on the "
        f"rigid foundation x2 <= 0. The top edge carries the traction (q, -p) = ({data.q:g}, "
        f"{-data.p:g}) GPa: P = 2Rp = {data.P:g} and Q = 2Rq = {data.Q:g} per unit thickness, "
        f"Q / (mu P) = {data.ratio:.3g} with Coulomb's mu = {data.mu:g}. No Dirichlet condition: "
        f"contact holds the body vertically and friction holds it sideways. The mesh is fine only "
        f"along Gamma3, the lower arc, where contact happens (graded inside, as scene 7a). Each run "
        f"starts from the rigid shift (0, -h^2/R), h = pi R / N, which puts the three lowest nodes "
        f"in contact; the run from u = 0 is below, under stability.",
        "",
        f"Hertz (7.38) for the normal load alone: half-width b = {data.b:.4f}, p0 = {data.p0:.4f}. "
        f"Cattaneo and Mindlin (normal load first, then Q): a central stick zone of half-width "
        f"c = b sqrt(1 - Q / (mu P)) = {data.c:.4f} and slip towards +x1 on both sides, where the "
        f"traction is mu p.",
        "",
    ]


def section_runs(runs, info):
    lines = ["## Every method and mesh", "",
             "Forces are nodal (pressure x tributary length); the zones are the first and last "
             "node of each status. Time: every sig-solve phase but assembly (summary.json `times`).",
             ""]
    rows = []
    for n in info["meshes"] + [info["reference"]]:
        for method in METHODS:
            run = runs.get((n, f"{method}_{DEFAULT[method]}"))
            if run is None:
                continue
            (c0, c1), (s0, s1) = zones(run["contact"])
            counts = run["summary"]["friction_status_counts"]
            rows.append([n, LABEL[method], f"{PARAMETER[method]} = {DEFAULT[method]}",
                         iterations_cell(run), f"{run['seconds']:.3f}",
                         f"[{fmt(c0, 3)}, {fmt(c1, 3)}]", f"[{fmt(s0, 3)}, {fmt(s1, 3)}]",
                         counts["S="], counts["S+"], counts["S-"]])
    lines += table(["N", "method", "parameter", "iterations", "time s", "contact zone",
                    "stick zone", "S=", "S+", "S-"], rows)
    return lines + [""]


def section_zones(runs, data, info, out):
    """Ours beside Hertz and Cattaneo-Mindlin, and the plot of the tractions."""
    n = info["meshes"][-1]
    run = runs[(n, "pdas_1e2")]
    c = run["contact"]
    (c0, c1), (s0, s1) = zones(c)
    a, centre = (c1 - c0) / 2, (c1 + c0) / 2
    stick_half, stick_centre = (s1 - s0) / 2, (s1 + s0) / 2
    lines = [
        f"## Stick and slip zones against Cattaneo and Mindlin (PDAS, N = {n})", "",
        f"![tractions](tractions_N{n}.png)", "",
    ]
    zones_table = Table(["quantity", "ours", "analytic", "ours / analytic"], [
        ["contact half-width a (nodes)", fmt(a), f"b = {fmt(data.b)}", fmt(a / data.b, 3)],
        ["contact centre", fmt(centre), "0", "—"],
        ["stick half-width (nodes)", fmt(stick_half), f"c = {fmt(data.c)}",
         fmt(stick_half / data.c, 3)],
        ["stick / contact half-width", fmt(stick_half / a, 3),
         f"sqrt(1 - Q/(mu P)) = {fmt(data.c / data.b, 3)}", "—"],
        ["stick zone centre", fmt(stick_centre), "0", "—"],
        ["max pressure", fmt(np.max(c["pressure"])), f"p0 = {fmt(data.p0)}",
         fmt(np.max(c["pressure"]) / data.p0, 3)],
    ], caption=f"Stick and slip zones against Cattaneo and Mindlin (PDAS, N = {n})")
    lines += zones_table.lines()
    lines += [
        "",
        "How far the half disc can follow Cattaneo and Mindlin: their result is for two elastic "
        "half-spaces of the same material, loaded normally first and then tangentially, with the "
        "tangential load applied at the contact. Three things differ here, each visible above:",
        f"- the moment Q R = {data.Q * data.R:g} of the traction on the top edge is balanced by "
        f"the contact forces, so the contact zone moves towards +x1 (centre {fmt(centre, 3)}) and "
        f"the pressure leans; the analytic curves in the plot are drawn about our contact centre "
        f"for their shape only;",
        "- an elastic body on a rigid plane couples the normal and tangential problems (Dundurs' "
        f"beta = (1 - 2 nu) / (2 (1 - nu)) = {(1 - 2 * data.nu) / (2 * (1 - data.nu)):.3g}, 0 for "
        "identical materials): the normal load alone makes the contact edges slip inwards;",
        "- the problem is static and solved in one step from the reference configuration (the "
        "slip is the whole tangential displacement), not along the normal-then-tangential path "
        "of the analysis.",
        "So the stick zone is expected inside the contact zone, shifted with it, with slip S+ "
        "at both edges, but not at the analytic ratio c / b.",
        "",
    ]
    # The plot: pressure and tangential traction, statuses, analytic shapes about our centre.
    x = c["x1"]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(x, c["pressure"], "k.-", lw=0.8, label="normal pressure (ours)")
    ax.plot(x, data.mu * c["pressure"], "k:", lw=0.8, label="mu x pressure (slip bound)")
    ax.plot(x, c["tangential_pressure"], "C0.-", lw=0.8, label="tangential traction (ours)")
    for status, mark, color in (("S=", "s", "C2"), ("S+", ">", "C3"), ("S-", "<", "C1")):
        m = c["friction_status"] == status
        ax.plot(x[m], c["tangential_pressure"][m], mark, color=color, ms=5, ls="none",
                label=f"{status} nodes")
    xa = np.linspace(-data.b, data.b, 400)
    ax.plot(xa + centre, data.pressure(xa), "k--", lw=0.6, alpha=0.6, label="Hertz, about our centre")
    ax.plot(xa + centre, data.cattaneo(xa), "C0--", lw=0.6, alpha=0.6,
            label="Cattaneo-Mindlin, about our centre")
    ax.set_xlim(c0 - 2 * data.b / 3, c1 + 2 * data.b / 3)
    ax.set_xlabel("x1 (m)")
    ax.set_ylabel("traction (GPa)")
    ax.set_title(f"Frictional Hertz, PDAS, N = {n}")
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    save_figure(fig, out / f"tractions_N{n}.png", dpi=120)
    return lines, zones_table


def section_agreement(runs, data, info, checks):
    lines = ["## The methods agree, and the laws hold", "",
             "Forces of each method against PDAS on the same mesh (max difference / max force), "
             "statuses compared node by node; the equilibrium of the loads (sum N = P, sum T = Q) "
             "and the Coulomb cone (|T| <= mu N, |T| = mu N and T along the slip on slipping "
             "nodes, no slip on sticking ones), relative to P.", ""]
    rows, ok = [], True
    for n in info["meshes"]:
        ref = runs.get((n, "pdas_1e2"))
        for method in METHODS:
            run = runs.get((n, f"{method}_{DEFAULT[method]}"))
            if run is None or ref is None:
                continue
            ch = checks_of(run, data)
            exact = method != "penalty"
            if run["converged"]:
                dn = np.max(np.abs(run["contact"]["multiplier"] - ref["contact"]["multiplier"])) / np.max(
                    ref["contact"]["multiplier"])
                dt = np.max(np.abs(run["contact"]["tangential_multiplier"]
                                   - ref["contact"]["tangential_multiplier"])) / np.max(
                    np.abs(ref["contact"]["tangential_multiplier"]))
                same = bool(np.all(run["contact"]["friction_status"] == ref["contact"]["friction_status"])
                            and np.all(run["contact"]["normal_status"] == ref["contact"]["normal_status"]))
                good = ch["normal"] < CONE and ch["tangential"] < CONE and ch["cone"] < CONE and \
                    ch["wrong_way"] == 0
                if exact:
                    good = good and dn < AGREE and dt < AGREE and same and ch["sliding"] < CONE
                ok = ok and good
                verdict = "PASS" if good else "FAIL"
            else:
                dn = dt = math.nan
                same = None
                verdict = "Nv"
            what = ("agrees with PDAS; equilibrium and the Coulomb cone hold" if exact else
                    "equilibrium and the Coulomb cone hold")
            checks.add(f"N = {n}, {LABEL[method]}: {what}", None if verdict == "Nv" else good,
                       detail=f"forces vs PDAS {fmt(dn, 2)} / {fmt(dt, 2)}, statuses equal "
                              f"{same}, sum N - P {fmt(ch['normal'], 2)}, sum T - Q "
                              f"{fmt(ch['tangential'], 2)}, max |T| - mu N {fmt(ch['cone'], 2)}"
                       if verdict != "Nv" else "Nv")
            rows.append([n, LABEL[method], fmt(dn, 2), fmt(dt, 2), "—" if same is None else same,
                         fmt(ch["normal"], 2), fmt(ch["tangential"], 2), fmt(ch["cone"], 2),
                         fmt(ch["sliding"], 2), ch["wrong_way"], fmt(ch["stuck_slip"], 2), verdict])
    lines += table(["N", "method", "N vs PDAS", "T vs PDAS", "statuses = PDAS", "sum N - P",
                    "sum T - Q", "max |T| - mu N", "slip: ||T| - mu N|", "T against slip",
                    "max slip of S=", "check"], rows)
    lines += ["", "Penalty regularizes the laws (its wall and stick are springs of stiffness r): it "
              "is checked for equilibrium and the cone only, not against the exact methods.", ""]
    return lines, ok


def section_stability(runs, info):
    n = info["sweep_n"]
    lines = [f"## Stability: where the methods fail (N = {n})", "",
             "Newton iterations for each method and parameter with a line search (`SOLVER "
             "search=yes`: alpha = 1, 1/2, ... the first step length that lowers the residual, "
             "else the one of least residual, while the residual is above 1e3 eps) and with full "
             "Newton steps, as the thesis's methods (`search=no`). By default (`search=auto`) "
             "a frictional solve searches with alm, pdas and projection, not with penalty. Nv: "
             "no convergence within maxit.", ""]
    rows = []
    for method in METHODS:
        values = sorted({r["name"].split("_")[1] for r in runs.values() if r["n"] == n and
                         r["method"] == method and r["name"].endswith("_full")}, key=float)
        for value in values:
            cells = [LABEL[method], f"{PARAMETER[method]} = {value}"]
            for mode in ("search", "full"):
                run = runs.get((n, f"{method}_{value}_{mode}"))
                cells += [iterations_cell(run), f"{run['seconds']:.3f}"] if run else ["—", "—"]
            rows.append(cells)
    lines += table(["method", "parameter", "iterations (search=yes)", "time s",
                    "iterations (search=no)", "time s"], rows)
    zero = runs.get((n, "pdas_1e2_from_zero"))
    if zero:
        lines += ["", f"From u = 0 instead of the rigid shift (PDAS gamma = 1e2): "
                  f"{iterations_cell(zero)}; {zero['summary']['failure'] or 'converged'}. A single "
                  f"node touches at u = 0: it sticks (the apex of the Coulomb cone on an active "
                  f"wall belongs to stick), the rotation it does not hold is an unheld step, cut "
                  f"where the next node touches (solver/contact_newton.hpp)."]
    lines += ["", "With full steps (search=no), where a stick test t + gamma q_t (or r q_t, q_t / c) "
              "sees a large slip — a large parameter, a coarse mesh, projection's held-back normals "
              "— the nodes of the contact zone slip one after the other; once none sticks, a body "
              "held sideways by friction alone has no tangential stiffness in the step, drifts by "
              "the tangential load over the proximal term, and the iteration cycles (Nv). The "
              "globalized steps (search=auto) cut such an unheld step where a node first sticks, and "
              "shorten the steps that raise the residual over ten times the recent ones. Bodies held "
              "by a Dirichlet condition do not have this mode.", ""]
    return lines


def section_tresca(runs, info):
    n = info["sweep_n"]
    run = runs.get((n, "tresca_pdas_1e2"))
    if not run:
        return []
    c = run["contact"]
    threshold = Deck.read(run["dir"] / "hertz.dat").number("FRICTION", "threshold")
    slipping = (c["friction_status"] == "S+") | (c["friction_status"] == "S-")
    bound = np.max(np.abs(np.abs(c["tangential_pressure"][slipping]) - threshold)) if slipping.any() else 0
    counts = run["summary"]["friction_status_counts"]
    return [f"## Tresca (N = {n}, threshold {threshold:g} GPa)", "",
            f"PDAS gamma = 1e2: {iterations_cell(run)}, S= {counts['S=']}, S+ {counts['S+']}, "
            f"S- {counts['S-']} nodes. Tresca bounds the traction on every node of Gamma3, in "
            f"contact or not (the classical model): free nodes stick or slip too. On slipping nodes "
            f"| |t| - threshold | <= {bound:.2g} GPa.", ""]


def section_speed_accuracy(runs, info, out):
    ref = runs.get((info["reference"], "pdas_1e2"))
    lines = ["## Speed against accuracy", "",
             f"Each method and mesh a point (and the parameter sweep at N = {info['sweep_n']}): "
             f"time of sig-solve's phases against the error of the tangential traction at the "
             f"Gamma3 nodes shared with the reference (PDAS, N = {info['reference']}); Nv on the "
             f"top edge.", "", "![speed vs accuracy](speed_accuracy.png)", ""]
    rows = []
    series = {m: Series(LABEL[m], [], color=COLOR[m], marker=MARKER[m], line="", hollow=False,
                        markersize=6) for m in METHODS}
    for run in sorted(runs.values(), key=lambda r: (r["n"], r["name"])):
        if run["n"] == info["reference"] or run["name"] in ("pdas_1e2_from_zero", "tresca_pdas_1e2") \
                or run["name"].endswith(("_full", "_search")):
            continue
        en, et = shared_error(run, ref) if (ref and run["converged"]) else (math.nan, math.nan)
        rows.append([run["n"], LABEL[run["method"]], f"{PARAMETER[run['method']]} = {run['value']}",
                     iterations_cell(run), f"{run['seconds']:.3f}", fmt(en, 3), fmt(et, 3)])
        label = (f"N={run['n']}" if run["value"] == DEFAULT[run["method"]] else
                 f"{PARAMETER[run['method']]}={run['value']}")
        series[run["method"]].points.append(
            Point(run["seconds"], et if run["converged"] else None, label))
    speed_accuracy_chart(out / "speed_accuracy.png", [s for s in series.values() if s.points],
                         xlabel="sig-solve time (s)",
                         ylabel="tangential traction error, max over max (-)",
                         title="Frictional Hertz: speed against accuracy", figsize=(6.5, 4.5),
                         legend_fontsize=7, label_fontsize=6)
    lines += table(["N", "method", "parameter", "iterations", "time s", "pressure error",
                    "tangential error"], rows)
    return lines + [""]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path)
    out = parser.parse_args().out.resolve()
    info = read_scene_command(out)
    data = Data(out / "hertz.template.dat")
    runs = collect_runs(out, info["meshes"] + [info["reference"]])
    for key in [(n, "pdas_1e2") for n in info["meshes"] + [info["reference"]]]:
        if key not in runs:
            raise ReportError(f"no run {key[1]} at N = {key[0]} in {out}")
    checks = Checks()
    pdas_converged = all(runs[(n, "pdas_1e2")]["converged"] for n in info["meshes"])
    checks.add("PDAS gamma = 1e2 converges on every mesh", pdas_converged,
               detail=", ".join(f"N = {n}: {iterations_cell(runs[(n, 'pdas_1e2')])}"
                                for n in info["meshes"]))
    agreement, ok = section_agreement(runs, data, info, checks)
    passed = ok and pdas_converged
    title = "Frictional Hertz: a half disc held by Coulomb friction"
    lines = [f"# {title}", "",
             f"Produced by `{info['command']}` on {info.get('date', '?')} ({info.get('host', '?')}, "
             f"revision {info.get('revision', '?')}); this report by "
             f"`postproc/friction_hertz_report.py {out}`. Deck: `datafiles/friction/hertz_coulomb.dat` "
             f"(copy: `hertz.template.dat`); each run's deck is `N<N>/<run>/hertz.dat`.", "",
             f"Checks: {'PASS' if passed else 'FAIL'} (PDAS converges on every "
             f"mesh; the exact methods agree to {AGREE:g}; equilibrium and the cone hold).", ""]
    lines += section_model(data)
    lines += section_runs(runs, info)
    zones, key_table = section_zones(runs, data, info, out)
    lines += zones
    lines += agreement
    lines += section_speed_accuracy(runs, info, out)
    lines += section_stability(runs, info)
    lines += section_tresca(runs, info)
    n = info["meshes"][-1]
    write_report(out, "\n".join(lines) + "\n", "friction_hertz", title, info, checks,
                 key_table=key_table, charts={"speed_accuracy": "speed_accuracy.png",
                                              "tractions": f"tractions_N{n}.png"})
    print(f"{out / 'report.md'}: checks {'PASS' if passed else 'FAIL'}")
    return 0 if passed else 1


if __name__ == "__main__":
    main_guard(main)
