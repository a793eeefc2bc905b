"""A scene's folder: the driver's command.txt, the runs' summary.json and CSV files, the solve
time of a run, and the scene index entry out/<scene>/scene.json that every scene report writes
(`drivers/run.sh --all` builds out/index.html from these files):

    {"scene": "7a", "title": "...", "report": "report.md", "command": "drivers/scene7a.sh --quick",
     "seconds": 12.3,
     "checks": [{"name": "...", "pass": true, "detail": "..."},
                {"name": "...", "pass": false, "detail": "...", "erratum": "<reference>: <number>"},
                {"name": "...", "pass": false, "detail": "...", "study": "..."}],
     "key_table": {"caption": "...", "header": ["...", ...], "rows": [["ours (thesis)", ...], ...]},
     "charts": {"speed_accuracy": "speed_accuracy.png", "stability": "stability.png", ...},
     "pvd": ["N256/pdas_1e2/hertz.pvd", ...]}

Paths are relative to out/<scene>/. `seconds` is the driver's wall time for its runs (the
`seconds:` line scene drivers append to command.txt; null when absent); `pass` is null for a check
that was not run; a failed thesis claim carries its "erratum" (an independent reference contradicts
the thesis: the index counts it apart from the FAILs) or its "study" (sigreport.checks).

    info = read_command(out, required=("command", "meshes"))   # {"command": ..., "seconds": "53"}
    summary = read_summary(run_dir)                             # summary.json of sig-post
    solve_seconds(summary)                                      # every sig-solve phase but assembly
    table = read_csv_columns(run_dir / "contact.csv")           # {column: numpy array}
    write_scene_json(out, "7a", "Hertz half disc", info, checks, key_table=table_71,
                     charts={"speed_accuracy": "speed_vs_accuracy.png"})
    write_report(out, text, "7a", "Hertz half disc", info, checks, ...)  # report.md, then the same
"""
import json
from pathlib import Path

from .errors import ReportError
from .files import write_text_atomically

# summary.json `times` merges the phases of every stage run in the folder; these belong to
# stages before sig-solve (BAR.md: a solve time is all of the stage's phases but assembly).
EARLIER_STAGE_PHASES = ("assemble",)


def read_command(out, required=()):
    """command.txt of a scene driver (`key: value` lines, drivers/lib/scene.sh `provenance`) as a
    dict; ReportError when it or a required key is missing."""
    path = Path(out) / "command.txt"
    if not path.is_file():
        raise ReportError(f"{path} is missing: run the scene's driver first")
    info = {}
    for line in path.read_text().splitlines():
        key, sep, value = line.partition(":")
        if sep:
            info[key.strip()] = value.strip()
    for key in required:
        if key not in info:
            raise ReportError(f"{path}: no '{key}:' line")
    return info


def read_summary(folder, required=()):
    """summary.json of a run folder (sig-post); ReportError naming the file when it is missing,
    unreadable or lacks a required key."""
    path = Path(folder) / "summary.json"
    try:
        summary = json.loads(path.read_text())
    except OSError as e:
        raise ReportError(f"{path}: cannot read ({e.strerror})") from None
    except json.JSONDecodeError as e:
        raise ReportError(f"{path}: not JSON ({e})") from None
    for key in required:
        if key not in summary:
            raise ReportError(f"{path}: no key '{key}'")
    return summary


def solve_seconds(summary, phases=None):
    """Seconds of the given phases of summary.json `times`; by default every phase but those of
    earlier stages (sig-solve's factorize, schur, frames, solve, ...)."""
    times = summary.get("times", {})
    if phases is None:
        phases = [p for p in times if p not in EARLIER_STAGE_PHASES]
    return sum(float(times.get(p, 0.0)) for p in phases)


def read_csv_columns(path, text_columns=()):
    """A CSV file with a header as {column: numpy array}: float arrays, except `text_columns` and
    columns whose values are not all numbers (string arrays). ReportError for a missing or empty
    file."""
    import csv

    import numpy as np
    path = Path(path)
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            rows = list(reader)
            header = reader.fieldnames or []
    except OSError as e:
        raise ReportError(f"{path}: cannot read ({e.strerror})") from None
    if not rows:
        raise ReportError(f"{path}: no rows")
    columns = {}
    for name in header:
        values = [r[name] for r in rows]
        if name not in text_columns:
            try:
                columns[name] = np.array([float(v) for v in values])
                continue
            except (TypeError, ValueError):
                pass
        columns[name] = np.array(values)
    return columns


def find_pvd(out):
    """Every .pvd under `out`, relative to it, sorted."""
    out = Path(out)
    return sorted(str(p.relative_to(out)) for p in out.rglob("*.pvd"))


def _seconds(value):
    if value is None or value == "":
        return None
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ReportError(f"scene.json: seconds '{value}' is not a number") from None


def valid_check(check):
    """A check entry of scene.json: {name, pass, detail}, and for a failed claim either
    "erratum" (the independent reference that contradicts the thesis, with its number) or
    "study" (what was tried); sigreport.checks writes them."""
    if not isinstance(check, dict) or not {"name", "pass", "detail"} <= set(check):
        return False
    extra = set(check) - {"name", "pass", "detail"}
    if check["pass"] not in (True, False, None) or extra not in (set(), {"erratum"}, {"study"}):
        return False
    return not extra or (check["pass"] is False and bool(check[extra.pop()]))


def write_scene_json(out, scene, title, command, checks=(), key_table=None, charts=None,
                     pvd=None, seconds=None, report="report.md"):
    """Write out/<scene>/scene.json (the module docstring's format) and return its path.

    `command`: the driver's command line, or the dict of read_command (its `command` and
    `seconds`); `checks`: a Checks (or a list of {"name", "pass", "detail"}); `key_table`: a
    Table (or its as_json()), the scene's main "ours (thesis)" table; `charts`: {name: PNG path
    relative to out}; `pvd`: paths relative to out (default: every .pvd under out). Every path
    must exist: a report pointing at a file it did not write is a bug."""
    out = Path(out)
    if isinstance(command, dict):
        seconds = command.get("seconds") if seconds is None else seconds
        command = command.get("command", "")
    charts = dict(charts or {})
    pvd = find_pvd(out) if pvd is None else list(pvd)
    for name in [report] + list(charts.values()) + pvd:
        if Path(name).is_absolute() or not (out / name).is_file():
            raise ReportError(f"{out}: scene.json would point at '{name}', which is not a file "
                              f"under {out}")
    entry = {
        "scene": str(scene),
        "title": str(title),
        "report": str(report),
        "command": str(command),
        "seconds": _seconds(seconds),
        "checks": checks.as_json() if hasattr(checks, "as_json") else list(checks),
        "key_table": key_table.as_json() if hasattr(key_table, "as_json") else key_table,
        "charts": {str(k): str(v) for k, v in charts.items()},
        "pvd": [str(p) for p in pvd],
    }
    for check in entry["checks"]:
        if not valid_check(check):
            raise ReportError(f"scene.json: a check is {{name, pass: true|false|null, detail}}, "
                              f"with an erratum (pass false) or a study (pass false), got {check}")
    return write_text_atomically(out / "scene.json",
                                 json.dumps(entry, indent=1, ensure_ascii=False) + "\n")


def write_report(out, text, scene, title, command, checks=(), key_table=None, charts=None,
                 pvd=None):
    """Write OUT/report.md (the text as given) and the scene index entry pointing at it
    (write_scene_json's arguments); return report.md's path."""
    path = write_text_atomically(Path(out) / "report.md", text)
    write_scene_json(out, scene, title, command, checks, key_table=key_table, charts=charts,
                     pvd=pvd)
    return path


def finish_report(out, text, scene, title, command, checks, summary, key_table=None, charts=None):
    """The end of a scene report: OUT/summary.json (`summary` and the checks), report.md and
    scene.json (write_report), the checks printed one a line; returns the exit status, 0 when
    no check fails."""
    summary = {**summary, "checks": checks.as_json()}
    write_text_atomically(Path(out) / "summary.json",
                          json.dumps(summary, indent=1, default=str) + "\n")
    path = write_report(out, text, scene, title, command, checks, key_table=key_table,
                        charts=charts)
    print(f"{path}: {checks.summary()}")
    for c in checks:
        print(f"{c.result}: {c.name}: {c.ours if c.ours is not None else c.detail}")
    return 0 if checks.ok else 1
