#!/usr/bin/python3
"""Scene 7b report (hyperelastic ring, thesis Tables 7.4 and 7.5): reads the case.b of every run
under OUT (OUT/N<n>/<method>[_<value>]/case.b, written by drivers/scene7b.sh) and writes
OUT/report.md with "ours (thesis)" cells, thesis values from postproc/thesis_values_7b.csv.

An iteration count is the total over the load steps (the thesis's tables give one number per
run); "Nv" where a run did not converge (then the load step that failed is named). Also the
dof counts, the per-step iterations and the support reactions (a horizontal reaction that is
not ~0 relative to the vertical one means the ring swayed off the symmetric branch).

Usage: scene7b_report.py OUT. The module also offers read_ds(path) -> {name: value} for
the DS container (core/ds.hpp layout), used by tests/pipeline/scene7b_small.sh.
"""
import csv
import struct
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def read_ds(path):
    """Arrays of a DS file as {name: list | str}; format of modules/core/include/core/ds.hpp."""
    data = Path(path).read_bytes()
    if data[:8] != b"SIGDS\0\0\0" or data[-4:] != b"ENDS":
        raise SystemExit(f"{path}: not a whole DS file")
    _version, count = struct.unpack_from("<II", data, 8)
    pos = 16 + 128 + 4
    arrays = {}
    for _ in range(count):
        name = data[pos:pos + 24].split(b"\0", 1)[0].decode()
        kind, rank = struct.unpack_from("<II", data, pos + 24)
        pos += 32 + 8 * rank
        (size,) = struct.unpack_from("<Q", data, pos)
        pos += 8
        payload = data[pos:pos + size]
        pos += size + 4
        if kind == 1:
            arrays[name] = list(struct.unpack(f"<{size // 8}q", payload))
        elif kind == 2:
            arrays[name] = list(struct.unpack(f"<{size // 8}d", payload))
        else:
            arrays[name] = payload.decode()
    return arrays


def scalar(ds, name):
    return ds[name][0]


def thesis_values():
    """(item, key) -> value text."""
    values = {}
    with open(HERE / "thesis_values_7b.csv") as f:
        for row in csv.reader(line for line in f if not line.startswith("#")):
            scene, item, key, value = row[:4]
            if "/" in key and "=" in key:  # "N=128;gamma=10/1e2/..." -> one entry per value
                head, _, tail = key.rpartition("=")
                for k, v in zip(tail.split("/"), value.split("/")):
                    values[(item, f"{head}={k}")] = v
            elif key.startswith("N=") and "/" in key:  # "N=128/256/512"
                for n, v in zip(key[2:].split("/"), value.split("/")):
                    values[(item, f"N={n}")] = v
            else:
                values[(item, key)] = value
    return values


def parameter_key(value):
    """1000.0 -> '1e3' as the thesis tables write it; 10 -> '10'."""
    v = float(value)
    if v == 10:
        return "10"
    exponent = round(__import__("math").log10(v))
    return f"1e{exponent}"


def main():
    if len(sys.argv) != 2:
        raise SystemExit("usage: scene7b_report.py OUT")
    out = Path(sys.argv[1])
    thesis = thesis_values()
    runs = {}  # (N, method, parameter) -> ds
    for b in sorted(out.glob("N*/*/case.b")):
        n = int(b.parent.parent.name[1:])
        method, _, value = b.parent.name.partition("_")
        runs[(n, method, value)] = read_ds(b)
    if not runs:
        raise SystemExit(f"scene7b_report: no N*/*/case.b under {out}")
    sizes = sorted({k[0] for k in runs})

    def cell(ds):
        if ds is None:
            return "-"
        total = scalar(ds, "iterations")
        if scalar(ds, "converged"):
            return str(total)
        return f"Nv (step {len(ds['step_iterations'])})"

    lines = ["# Scene 7b: hyperelastic ring pressed on a rigid foundation", "",
             "Cells are ours (thesis). Our count is the total of Newton iterations over the load "
             "steps; 'Nv' = not converged (the load step that failed). Deck: "
             "datafiles/scene7b/ring.dat (plane strain, 14 load steps to u = (0,-14) on AB, "
             "eps = 1e-5, maxit = 200 per step, UMFPACK).", ""]
    parameters = ["10", "1e2", "1e3", "1e4", "1e5", "1e6"]
    for title, method, name, item in (
            ("Table 7.4: iterative projection vs c", "projection", "c", "iterations_projection"),
            ("Table 7.5: primal-dual active set vs gamma", "pdas", "gamma", "iterations_pdas")):
        lines += [f"## {title}", "", "| N | " + " | ".join(f"{name} = {p}" for p in parameters)
                  + (" | ALM |" if method == "projection" else " |"),
                  "|---" * (len(parameters) + 1 + (method == "projection")) + "|"]
        for n in sizes:
            row = [str(n)]
            for p in parameters:
                ds = next((d for (nn, m, v), d in runs.items()
                           if nn == n and m == method and v and parameter_key(v) == p), None)
                row.append(f"{cell(ds)} ({thesis.get((item, f'N={n};{name}={p}'), '?')})")
            if method == "projection":
                ds = next((d for (nn, m, _), d in runs.items() if nn == n and m == "alm"), None)
                row.append(f"{cell(ds)} ({thesis.get(('iterations_alm', f'N={n}'), '?')})")
            lines.append("| " + " | ".join(row) + " |")
        lines.append("")

    lines += ["## Unknowns", "", "| N | active set / projection | ALM |", "|---|---|---|"]
    for n in sizes:
        row = [str(n)]
        for method, item in (("pdas", "dofs_active_set"), ("alm", "dofs_alm")):
            ds = next((d for (nn, m, _), d in runs.items() if nn == n and m == method), None)
            row.append(f"{scalar(ds, 'dofs') if ds else '-'} ({thesis.get((item, f'N={n}'), '?')})")
        lines.append("| " + " | ".join(row) + " |")
    lines.append("")

    lines += ["## Per-step iterations, reactions, solve time", "",
              "Reaction: force of the supports on the ring at AB after the last attempted step "
              "(sum of f_int over the imposed dofs); |Rx / Ry| ~ 1e-12 or below means no sway.",
              "", "| N | run | per-step iterations | Rx | Ry | Rx / Ry | solve s | failure |",
              "|---|---|---|---|---|---|---|---|"]
    for (n, method, value), ds in sorted(runs.items(), key=lambda kv: (kv[0][0], kv[0][1],
                                                                        float(kv[0][2] or 0))):
        steps = " ".join(f"{i}" + ("" if c else "Nv")
                         for i, c in zip(ds["step_iterations"], ds["step_converged"]))
        rx, ry = scalar(ds, "reaction_x"), scalar(ds, "reaction_y")
        ratio = f"{abs(rx / ry):.1e}" if ry else "-"
        run = method + (f" {value}" if value else "")
        failure = ds.get("failure", "").replace("|", "/")
        lines.append(f"| {n} | {run} | {steps} | {rx:.4g} | {ry:.4g} | {ratio} | "
                     f"{scalar(ds, 'time_solve'):.2f} | {failure} |")
    lines.append("")
    (out / "report.md").write_text("\n".join(lines))
    print(f"scene7b_report: wrote {out / 'report.md'} ({len(runs)} runs)")


if __name__ == "__main__":
    main()
