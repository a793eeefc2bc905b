#!/usr/bin/python3
"""Numeric comparison of two runs of a scene driver (a report before and after a change).

    /usr/bin/python3 postproc/compare_reports.py OLD_DIR NEW_DIR [--rtol 1e-9] [--skip REGEX]

Every markdown table of OLD_DIR/report.md and every .csv file under OLD_DIR is matched with its
namesake in NEW_DIR (tables by their order, csv columns by name: a column the new run adds is
new output and left out, one it drops is reported); cell by cell, integers must be
equal and reals agree to rtol relative (an absolute floor of rtol times the column's largest
magnitude, so that a round-off around zero is not a change). Columns whose header names a time
(seconds, "(s)", "ms", "speed", "time", "x one factorization") are measurements, not results,
and are skipped, as is every column matching --skip and every table whose caption (the line
above it) names a time. Prints one line per cell that moved and a
summary; exit 1 if any moved, 2 if the two runs do not have the same tables.
"""
import argparse
import csv
import math
import re
import sys
from pathlib import Path

TIMED = re.compile(r"(^|\s)s$|second|\(s\)|\bms\b|speed|time|factori[sz]ation|wall|\bs/|per s\b",
                   re.IGNORECASE)
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def markdown_tables(path):
    """The tables of a markdown file: (header cells, rows of cells, caption), in order; the
    caption is the last paragraph line above the table."""
    tables, header, rows, caption, last = [], None, [], "", ""
    for line in path.read_text().splitlines() + [""]:
        if line.startswith("|"):
            # Cells split at unescaped pipes (a norm in a header is written \|\|u\|\|).
            inner = line.strip()[1:].removesuffix("|")
            cells = [c.strip().replace("\\|", "|") for c in re.split(r"(?<!\\)\|", inner)]
            if header is None:
                header, caption = cells, last
            elif not all(re.fullmatch(r":?-+:?", c) for c in cells if c):
                rows.append(cells)
        else:
            if header is not None:
                tables.append((header, rows, caption))
                header, rows = None, []
            if line.strip():
                last = line
    return tables


def csv_table(path):
    with path.open(newline="") as f:
        lines = list(csv.reader(f))
    return (lines[0], lines[1:], "") if lines else ([], [], "")


def common_columns(old, new):
    """The two tables restricted to the columns both have (a column added by the change, such
    as contact.csv's `converged`, is new output, not a moved result), and the names dropped."""
    (head_old, rows_old, caption), (head_new, rows_new, _) = old, new
    names = [h for h in head_old if h in head_new]
    pick = lambda head, rows: [[r[head.index(h)] if head.index(h) < len(r) else "" for h in names]
                               for r in rows]
    dropped = [h for h in head_old if h not in head_new]
    return (names, pick(head_old, rows_old), caption), (names, pick(head_new, rows_new), ""), dropped


def numbers(cell):
    return [float(x) for x in NUMBER.findall(cell)]


def compare_table(where, old, new, rtol, skip):
    """Moved cells of one table, as printable lines."""
    (head_old, rows_old, caption), (head_new, rows_new, _) = old, new
    if TIMED.search(caption):  # a table of timings
        return []
    if head_old != head_new or len(rows_old) != len(rows_new):
        return [f"{where}: the table's header or row count changed "
                f"({len(rows_old)} rows -> {len(rows_new)})"]
    moved = []
    for col, name in enumerate(head_old):
        if TIMED.search(name) or (skip and re.search(skip, name)):
            continue
        column = [numbers(r[col]) if col < len(r) else [] for r in rows_old]
        scale = max((abs(v) for vs in column for v in vs if math.isfinite(v)), default=0.0)
        for i, (a, b) in enumerate(zip(rows_old, rows_new)):
            ca, cb = (a[col] if col < len(a) else ""), (b[col] if col < len(b) else "")
            na, nb = numbers(ca), numbers(cb)
            same = len(na) == len(nb) and all(
                x == y or abs(x - y) <= rtol * max(abs(x), abs(y), scale) for x, y in zip(na, nb))
            if not na and not nb:
                same = ca == cb
            if not same:
                moved.append(f"{where} row {i + 1} ({a[0]}) column '{name}': {ca} -> {cb}")
    return moved


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("old", type=Path)
    p.add_argument("new", type=Path)
    p.add_argument("--rtol", type=float, default=1e-9)
    p.add_argument("--skip", default="", help="regex of column headers to leave out")
    a = p.parse_args()
    moved, compared = [], 0
    for old_file in sorted(a.old.rglob("*")):
        rel = old_file.relative_to(a.old)
        new_file = a.new / rel
        if old_file.name == "report.md":
            old_tables = markdown_tables(old_file)
        elif old_file.suffix == ".csv":
            old_tables = [csv_table(old_file)]
        else:
            continue
        if not new_file.exists():
            print(f"{rel}: missing in {a.new}")
            return 2
        new_tables = markdown_tables(new_file) if old_file.name == "report.md" else [csv_table(new_file)]
        if len(old_tables) != len(new_tables):
            print(f"{rel}: {len(old_tables)} tables -> {len(new_tables)}")
            return 2
        for k, (o, n) in enumerate(zip(old_tables, new_tables)):
            compared += 1
            if old_file.suffix == ".csv":
                o, n, dropped = common_columns(o, n)
                moved += [f"{rel}: column '{h}' dropped" for h in dropped]
            moved += compare_table(f"{rel} table {k + 1}", o, n, a.rtol, a.skip)
    for line in moved:
        print(line)
    print(f"compare_reports: {compared} tables, {len(moved)} cells moved (rtol {a.rtol:g})")
    return 1 if moved else 0


if __name__ == "__main__":
    sys.exit(main())
