#!/usr/bin/python3
"""Gonzalez in 3D report (issue 28): the free spinning hyperelastic ball marched with Gonzalez's
algorithmic stress and with the plain midpoint stress.

    postproc/scene3d_spin_report.py OUTDIR

OUTDIR is what drivers/scene3d_spin.sh wrote: base/ (case.nopo, case.tae: the mesh and the
mass) and per stress <stress>/ (case.hist with every state kept, wall.txt). Writes
OUTDIR/report.md and OUTDIR/summary.json, and prints one line per run.

Per run and kept state n: the discrete energy E_n (case.hist 'total': 1/2 v.Mv + the strain
energy) and the angular momentum about the origin L_n = sum_a x_a x (M v)_a, with x = X + u the
current nodal positions, v the nodal velocities and M the mass of case.tae (the consistent mass:
(M v)_a is node a's momentum). The measures: max_n |E_n - E_0| / E_0 and
max_n |L_n - L_0| / |L_0|.
"""
import json
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from sigreport.ds import read_ds, sig_dump_json  # noqa: E402

STRESSES = ("gonzalez", "midpoint")


def mass_matrix(tae):
    """The mass of case.tae as a dense matrix (its CSR pattern is K's, 1-based)."""
    n = int(tae["ndof"][0])
    rowptr = np.array(tae["K_rowptr"]) - 1
    col = np.array(tae["K_col"]) - 1
    values = np.array(tae["M_val"])
    M = np.zeros((n, n))
    for i in range(n):
        M[i, col[rowptr[i]:rowptr[i + 1]]] = values[rowptr[i]:rowptr[i + 1]]
    return M


def angular_momenta(X, M, u, v):
    """L_n = sum_a x_a x (M v_n)_a for every kept state n (rows of u and v)."""
    x = X[None, :, :] + u.reshape(u.shape[0], -1, 3)
    p = (v @ M).reshape(v.shape[0], -1, 3)  # M is symmetric
    return np.cross(x, p).sum(axis=1)


def run_measures(folder, X, M):
    hist = read_ds(folder / "case.hist", ["total", "elastic", "u", "v", "newton_iterations",
                                          "converged"])
    E = np.array(hist["total"])
    L = angular_momenta(X, M, hist.array("u"), hist.array("v"))
    iterations = np.array(hist["newton_iterations"][1:])
    wall = (folder / "wall.txt").read_text().strip() if (folder / "wall.txt").is_file() else "?"
    return {
        "steps": len(E) - 1,
        "converged": bool(hist["converged"][0]),
        "E0": float(E[0]),
        "energy_drift": float(np.max(np.abs(E - E[0])) / E[0]),
        "energy_end": float((E[-1] - E[0]) / E[0]),
        "elastic_fraction": float(np.max(hist["elastic"]) / E[0]),
        "L0": [float(c) for c in L[0]],
        "momentum_drift": float(np.max(np.linalg.norm(L - L[0], axis=1)) /
                                np.linalg.norm(L[0])),
        "newton_mean": float(iterations.mean()) if len(iterations) else 0.0,
        "newton_max": int(iterations.max()) if len(iterations) else 0,
        "wall_seconds": wall,
    }


def main():
    out = Path(sys.argv[1])
    base = out / "base"
    mesh = sig_dump_json(base / "case.nopo", values=True)
    X = np.array(mesh["coordinates"], dtype=float).reshape(-1, 3)
    M = mass_matrix(read_ds(base / "case.tae", ["ndof", "K_rowptr", "K_col", "M_val"]))
    runs = {s: run_measures(out / s, X, M) for s in STRESSES if (out / s / "case.hist").is_file()}
    lines = ["# Gonzalez in 3D: a free spinning hyperelastic ball", "",
             f"{X.shape[0]} nodes, tetrahedra P1; "
             "datafiles/scene3d/spinning_ball.dat, drivers/scene3d_spin.sh.", "",
             "| stress | steps | max abs(E - E0) / E0 | (E_end - E0) / E0 | "
             "max abs(L - L0) / abs(L0) | max strain energy / E0 | Newton (mean, max) | wall s |",
             "|---|---|---|---|---|---|---|---|"]
    for stress, r in runs.items():
        lines.append(f"| {stress} | {r['steps']} | {r['energy_drift']:.3e} | "
                     f"{r['energy_end']:.3e} | {r['momentum_drift']:.3e} | "
                     f"{r['elastic_fraction']:.3g} | "
                     f"{r['newton_mean']:.2f}, {r['newton_max']} | {r['wall_seconds']} |")
        print(f"{stress}: {r['steps']} steps, E0 = {r['E0']:.12g}, max |E - E0|/E0 = "
              f"{r['energy_drift']:.3e}, max |L - L0|/|L0| = {r['momentum_drift']:.3e}, max strain "
              f"energy / E0 = {r['elastic_fraction']:.3g}, "
              f"L0 = ({r['L0'][0]:.6g}, {r['L0'][1]:.6g}, {r['L0'][2]:.6g}), Newton "
              f"{r['newton_mean']:.2f} mean {r['newton_max']} max")
    lines += ["", "E: case.hist 'total' (1/2 v.Mv + strain energy); L = sum_a x_a x (M v)_a "
              "about the origin, x = X + u, M the consistent mass of case.tae.", ""]
    (out / "report.md").write_text("\n".join(lines))
    (out / "summary.json").write_text(json.dumps({"nodes": int(X.shape[0]), "runs": runs},
                                                 indent=2) + "\n")


if __name__ == "__main__":
    main()
