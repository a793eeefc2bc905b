#!/usr/bin/python3
"""The report of drivers/bench-mpi.sh (issue 27, "Scale"): OUTDIR/bench.md.

    bench_mpi_report.py OUTDIR

Reads OUTDIR/command.txt (provenance, deck, size, load averages), OUTDIR/stages.tsv (the base
stages' seconds and peak memory) and either OUTDIR/runs.tsv (the timed sig-solve runs under
mpirun and their summary.json) or OUTDIR/analysis.tsv (MUMPS's analysis alone, the line of
SIG_MUMPS_ANALYSIS: modules/solver/src/mumps_solver.cpp).

The model of P processes (a model from the np = 1 run's statistics, not a measurement), with F
the elimination's flops (RINFOG(3)), r = F / (factorize - analysis) the flop rate of one core,
L the largest front (INFOG(11)), t_a the analysis (on the host, sequential), t_c the phases after
the factorization (the contact Newton on the dense complement, which every rank runs whole), m
the contact unknowns and B = 10 GB/s a network's bandwidth:

    T(P) = t_a + (F - W) / (P r) + W / (min(P, L / 256) r) + t_c + log2(P) 8 m^2 / B,

W = min(L^3 / 3, F) the largest front's dense elimination, which MUMPS splits by blocks of rows
(a type-2 front: some hundred rows a process), so over at most about L / 256 processes; the rest
of the tree is taken to divide perfectly. T(1) / (t_a + t_c + W / (L / 256 r)) bounds the speed-up.
"""
import csv
import json
import math
import statistics
import sys
from pathlib import Path

BLOCK_ROWS = 256    # rows of a type-2 front a process takes, at least (the model's grain)
BANDWIDTH = 10e9    # bytes per second of the network (the complement's broadcast)
MODEL_RANKS = (16, 32, 64, 128, 256)
# INFOG(7); 1 is the order given in PERM_IN, ours METIS's nested dissection (mumps_solver.cpp).
ORDERINGS = {0: "amd", 1: "metis", 2: "amf", 3: "scotch", 4: "pord", 5: "metis", 6: "qamd"}


def read_info(out):
    return dict(line.split(": ", 1) for line in (out / "command.txt").read_text().splitlines()
                if ": " in line)


def stages_text(out):
    with open(out / "stages.tsv") as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    return ("Base stages (once): " + ", ".join(
        f"sig-{r['stage']} {float(r['seconds']):.1f} s ({int(r['peak_rss_kb']) / 2**20:.2f} GB)"
        for r in rows) + " (seconds, peak resident memory; sig-mesh's include gmsh's mesh "
        "generation).")


def header(info, title):
    return [f"# The distributed solve: {title}", "",
            f"Produced by `{info['command']}` on {info['date']} ({info['host']}, revision "
            f"{info['revision']}). Load average before the timed part {info['load_start']}, "
            f"after it {info['load_end']}."]


def title_of(info):
    deck = "the 3D Hertz half ball" if info["deck"] == "ball" else "scene 7a's 2D Hertz"
    return f"{deck}, {info['size']}"


def analysis_report(out, info):
    with open(out / "analysis.tsv") as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    rate = float(info["rate"]) if info.get("rate") else None
    lines = header(info, title_of(info) + ", MUMPS's analysis alone") + [
        "", stages_text(out), "",
        "MUMPS's estimates of the factorization (sig-solve with SIG_MUMPS_ANALYSIS: the "
        "analysis, then the stage stops); the predicted factorization at np = 1 is the analysis "
        "and RINFOG(1) at the rate given (--rate):", "",
        "| ranks | unknowns | contact unknowns (Schur) | ordering | analysis s | flops RINFOG(1) | "
        "factor entries INFOG(20) | factors GB | largest front INFOG(5) | tree nodes INFOG(6) | "
        "MB max / total INFOG(16) / INFOG(17) | predicted factorization s |",
        "|" + "---|" * 12]
    for a in rows:
        flops, entries = float(a["flops"]), float(a["entries"])
        predicted = (f"{float(a['seconds']) + flops / rate:.0f} (at {rate:.3g} flop/s)"
                     if rate and a["ranks"] == "1" else "-")
        lines.append(f"| {a['ranks']} | {a['n']} | {a['schur']} | "
                     f"{ORDERINGS.get(int(a['ordering']), 'other')} | {float(a['seconds']):.2f} | "
                     f"{flops:.3e} | {entries:.3e} | {8 * entries / 1e9:.1f} | "
                     f"{a['largest_front']} | {a['tree_nodes']} | {a['mb_max']} / {a['mb_total']} | "
                     f"{predicted} |")
    return lines


def model(m1, times):
    """T(P) of the module docstring from the np = 1 statistics and median times."""
    F, L, m = m1["flops"], m1["largest_front"], m1["schur_size"]
    r = F / max(times["factorize"] - times["analysis"], 1e-9)
    t_a = times["analysis"]
    t_c = times["phases"] - times["factorize"]
    W = min(L ** 3 / 3, F)
    front_ranks = max(1.0, L / BLOCK_ROWS)

    def T(P):
        return (t_a + (F - W) / (P * r) + W / (min(P, front_ranks) * r) + t_c +
                math.log2(P) * 8 * m * m / BANDWIDTH)
    bound = T(1) / (t_a + t_c + W / (front_ranks * r))
    return r, W, front_ranks, t_a, t_c, T, bound


def runs_report(out, info):
    runs = {}
    with open(out / "runs.tsv") as f:
        for row in csv.DictReader(f, delimiter="\t"):
            s = json.loads(Path(row["summary"]).read_text())
            t = {p: float(v) for p, v in s["times"].items() if p != "assemble"}
            runs.setdefault(int(row["ranks"]), []).append({
                "wall": float(row["wall_s"]), "phases": sum(t.values()), "times": t,
                "analysis": s["mumps"]["analysis_seconds"],
                "rss": [int(v) for v in row["peak_rss_kb"].split(",")], "summary": s})
    ranks = sorted(runs)
    for p, rs in runs.items():
        assert all(r["summary"]["ranks"] == p for r in rs), f"summary.json says another ranks than {p}"
        assert all(r["summary"]["converged"] for r in rs), f"np = {p}: a run did not converge"
    first = runs[ranks[0]][0]["summary"]
    phases = list(runs[ranks[0]][0]["times"])
    med = {p: {"wall": statistics.median(r["wall"] for r in rs),
               "phases": statistics.median(r["phases"] for r in rs),
               "analysis": statistics.median(r["analysis"] for r in rs),
               **{ph: statistics.median(r["times"][ph] for r in rs) for ph in phases},
               "rss": [statistics.median(r["rss"][i] for r in rs) for i in range(p)]}
           for p, rs in runs.items()}

    def eff(p, key):
        return med[1][key] / (p * med[p][key]) if med[p][key] > 0 else float("nan")

    K = len(runs[1])
    lines = header(info, title_of(info)) + [
        "", f"{first['dofs']} dofs, {first['mumps']['schur_size']:.0f} contact unknowns "
        f"(MUMPS's Schur complement), MUMPS ordering {first['ordering']}, PDAS "
        f"{first['iterations']} iterations. Medians of {K} run{'s' if K > 1 else ''} per rank "
        f"count, taken round robin. {stages_text(out)}", "",
        "**Read these times as a shared 2-core machine's** (the load averages above): with 2 "
        "cores np = 2 cannot show a speed-up beyond 2 (more ranks than cores are oversubscribed "
        "and only slower). MUMPS's statistics (flops, factor entries, memory) do not depend on "
        "the load.", "",
        "## Times (medians, seconds)", "",
        "Phases: summary.json `times` without sig-assemble's `assemble`; factorize = MUMPS's "
        "analysis + partial factorization, the Schur complement included (analysis: of it, "
        "MUMPS's analysis, on the host); solve = the contact Newton on the dense complement "
        "(every rank) and the expansion. Wall: the mpirun job (MPI's start, reading case.tae, "
        "writing case.b included). Efficiency: T_1 / (P T_P). Peak RSS: /usr/bin/time's maximum "
        "resident set of each rank, rank 0 first.", "",
        "| ranks | " + " | ".join(phases) + " | analysis | phases | wall | efficiency (phases) | "
        "efficiency (factorize) | peak RSS per rank (GB) |",
        "|" + "---|" * (len(phases) + 7)]
    for p in ranks:
        m = med[p]
        lines.append(f"| {p} | " + " | ".join(f"{m[ph]:.2f}" for ph in phases) +
                     f" | {m['analysis']:.2f} | {m['phases']:.2f} | {m['wall']:.2f} | "
                     f"{eff(p, 'phases'):.2f} | {eff(p, 'factorize'):.2f} | " +
                     ", ".join(f"{v / 2**20:.2f}" for v in m["rss"]) + " |")

    lines += ["", "## MUMPS's statistics (first run of each rank count)", "",
              "Totals: RINFOG(3) flops of the elimination (RINFOG(1) the analysis's estimate), "
              "INFOG(29) factor entries, INFOG(9) the reals allocated for the factors, INFOG(11) "
              "the largest front, INFOG(21) / INFOG(22) the MB the factorization used on the "
              "largest rank / on all. Per rank (rank 0, the host, holding the Schur complement, "
              "first): RINFO(3) flops, INFO(27) factor entries, INFO(22) MB, INFO(23) pivots "
              "eliminated.", "",
              "| ranks | flops | estimate | factor entries | factor space | largest front | "
              "MB max / total | flops per rank | entries per rank | MB per rank | "
              "pivots per rank |",
              "|" + "---|" * 11]
    for p in ranks:
        s = runs[p][0]["summary"]["mumps"]

        def share(key, fmt):
            return ", ".join(fmt(v) for v in s[key])
        lines.append(f"| {p} | {s['flops']:.3e} | {s['flops_estimate']:.3e} | "
                     f"{s['factor_entries']:.3e} | {s.get('factor_space', float('nan')):.3e} | "
                     f"{s['largest_front']:.0f} | "
                     f"{s['memory_max_mb']:.0f} / {s['memory_total_mb']:.0f} | "
                     f"{share('rank_flops', lambda v: f'{v:.2e}')} | "
                     f"{share('rank_entries', lambda v: f'{v:.2e}')} | "
                     f"{share('rank_memory_mb', lambda v: f'{v:.0f}')} | "
                     f"{share('rank_pivots', lambda v: f'{v:.0f}')} |")
    m1 = runs[1][0]["summary"]["mumps"]
    lines += ["", f"Dense contact block: the Schur complement is {m1['schur_size']:.0f}^2 "
              f"doubles = {8 * m1['schur_size'] ** 2 / 2 ** 20:.0f} MB on every rank "
              f"(broadcast), and each PDAS iteration factorizes its active part densely on every "
              f"rank."]

    r, W, front_ranks, t_a, t_c, T, bound = model(m1, med[1])
    nodes = m1.get("tree_nodes", 0)
    fronts = (f"the tree's {nodes:.0f} fronts (INFOG(6); {m1['flops'] / nodes:.2g} flops a front on "
              f"average)" if nodes else "the tree's fronts")
    lines += ["", "## A model of 16 to 256 processes (from the np = 1 statistics: a model, not a "
              "measurement)", "",
              f"r = {r:.3g} flop/s of one core (RINFOG(3) over the factorization less the "
              f"analysis), F = {m1['flops']:.3g} flops, the largest front L = "
              f"{m1['largest_front']:.0f} of {fronts}: its dense elimination W = min(L^3/3, F) = {W:.3g} "
              f"flops ({W / m1['flops']:.0%} of F) splits over at most L / {BLOCK_ROWS} = "
              f"{front_ranks:.0f} processes; t_a = {t_a:.2f} s of analysis on the host, t_c = "
              f"{t_c:.2f} s after the factorization (the contact Newton every rank runs whole); "
              f"the complement's broadcast at {BANDWIDTH / 1e9:.0f} GB/s. T(P) = t_a + (F - W) / "
              f"(P r) + W / (min(P, L / {BLOCK_ROWS}) r) + t_c + log2(P) 8 m^2 / B "
              f"(postproc/bench_mpi_report.py). Speed-up bound T(1) / (t_a + t_c + W / "
              f"(L / {BLOCK_ROWS} r)) = {bound:.1f}.", "",
              "| P | T(P) s | speed-up T(1) / T(P) | efficiency | factor entries per process | "
              "measured phases s (efficiency) |",
              "|---|---|---|---|---|---|"]
    for P in sorted(set(ranks) | set(MODEL_RANKS)):
        measured = f"{med[P]['phases']:.3g} ({eff(P, 'phases'):.2f})" if P in med else "-"
        lines.append(f"| {P} | {T(P):.3g} | {T(1) / T(P):.1f} | {T(1) / (P * T(P)):.2f} | "
                     f"{m1['factor_entries'] / P:.2e} | {measured} |")
    lines += ["", "Raw runs: `runs.tsv` (ranks, run, wall s, peak RSS per rank KB, summary.json)."]
    return lines


def main():
    out = Path(sys.argv[1])
    info = read_info(out)
    lines = (analysis_report if (out / "analysis.tsv").exists() else runs_report)(out, info)
    text = "\n".join(lines) + "\n"
    (out / "bench.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
