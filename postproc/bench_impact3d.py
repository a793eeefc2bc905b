#!/usr/bin/python3
"""The measures and the report of drivers/bench-impact3d.sh (the 3D ball impact's time per step
against a contact-free step, issue 28).

    bench_impact3d.py row RUNDIR T0 T1   one CSV row's measures of the march just run in RUNDIR
                                         (T0, T1: its start and end, date +%s.%N)
    bench_impact3d.py report OUTDIR      OUTDIR/report.md from OUTDIR/bench.csv

row prints "wall_seconds,steps,contact_steps,contact_step_seconds,free_step_seconds": the march's
wall time, its steps (energy.csv, the initial state left out), those with a node in contact
(energy.csv active_nodes > 0), and the mean of case.hist's step_seconds (each step's own time in
sig-march) over the steps in contact and over the others (nan when there are none).
"""
import csv
import math
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from sigreport.ds import read_ds  # noqa: E402

TARGET = 1.5  # issue 28: a step of the 3D impact march within 1.5x a contact-free step


def mean(values):
    return sum(values) / len(values) if values else math.nan


def row(folder, t0, t1):
    rows = list(csv.DictReader(open(folder / "energy.csv")))[1:]
    seconds = read_ds(folder / "case.hist", ["step_seconds"])["step_seconds"][1:]
    if len(seconds) != len(rows):
        sys.exit(f"bench_impact3d.py: {folder}: {len(seconds)} step times, {len(rows)} steps")
    touch = [int(r["active_nodes"]) > 0 for r in rows]
    contact = [s for s, t in zip(seconds, touch) if t]
    free = [s for s, t in zip(seconds, touch) if not t]
    print(f"{t1 - t0:.3f},{len(rows)},{len(contact)},{mean(contact):.6g},{mean(free):.6g}")


def report(out):
    rows = list(csv.DictReader(open(out / "bench.csv")))
    info = dict(l.split(": ", 1) for l in (out / "command.txt").read_text().splitlines())
    cases = list(dict.fromkeys(r["case"] for r in rows))

    def median(name, key):
        return statistics.median(float(r[key]) for r in rows if r["case"] == name)

    def runs(name, key):
        return " ".join(f"{float(r[key]):.2f}" for r in rows if r["case"] == name)

    steps = {c: int(next(r["steps"] for r in rows if r["case"] == c)) for c in cases}
    free_march = median("no-contact", "wall_seconds") / steps["no-contact"]
    free_step = median("no-contact", "free_step_seconds")
    loads = [float(r["load"]) for r in rows]
    repeat = max(int(r["run"]) for r in rows)

    def mark(ratio):
        return f"{ratio:.2f} ({'meets' if ratio <= TARGET else 'above'} {TARGET:g})"

    md = ["# Benchmark: the 3D ball impact's step against a contact-free step", "",
          f"Command: `{info['command']}` ({info['date']}, {info['host']}; {info['load after']} "
          f"after; revision {info['revision']}). datafiles/scene3d/ball_impact.dat on the half ball "
          f"({info['mesh']}), {steps['no-contact']} steps of k = 1e-4 s; median of {repeat} runs per "
          f"case, round robin; load average at the runs' ends {min(loads):.2f} to {max(loads):.2f}"
          f" ({'loaded' if max(loads) > 1.0 else 'quiet'} machine). The contact-free march (the "
          f"CONTACT card dropped: one solve with the factorized step matrix a step): "
          f"{1e3 * free_march:.2f} ms per step of its wall time, {1e3 * free_step:.2f} ms per step "
          "of its own step times (case.hist step_seconds).", "",
          "| case | wall (s) | runs (s) | steps in contact | march per step (ms) | march / "
          "contact-free march | step in contact (ms) | step in contact / contact-free step | "
          "free step in the run (ms) |", "|---|---|---|---|---|---|---|---|---|"]
    for c in cases:
        wall = median(c, "wall_seconds")
        contact = median(c, "contact_step_seconds")
        md.append(f"| {c} | {wall:.2f} | {runs(c, 'wall_seconds')} | "
                  f"{next(r['contact_steps'] for r in rows if r['case'] == c)} | "
                  f"{1e3 * wall / steps[c]:.2f} | {mark(wall / steps[c] / free_march)} | "
                  + ("—" if math.isnan(contact) else f"{1e3 * contact:.2f}") + " | "
                  + ("—" if math.isnan(contact) else mark(contact / free_step)) + " | "
                  f"{1e3 * median(c, 'free_step_seconds'):.2f} |")
    md += ["", "March / contact-free march is drivers/bench-ball.sh's ratio (2D, scene 8a): the "
           "whole march's wall time per step, flight and contact together, against the contact-free "
           "march's. Step in contact / contact-free step is the stricter: the mean own time of the "
           "steps with a node on the plane against the mean step of the contact-free march. Each "
           "ratio divides two medians of this one script run.", ""]
    (out / "report.md").write_text("\n".join(md))
    print("\n".join(md))


def main():
    if len(sys.argv) == 5 and sys.argv[1] == "row":
        row(Path(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]))
    elif len(sys.argv) == 3 and sys.argv[1] == "report":
        report(Path(sys.argv[2]))
    else:
        sys.exit(__doc__.split("\n\n")[1])


if __name__ == "__main__":
    main()
