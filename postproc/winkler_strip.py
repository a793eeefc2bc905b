#!/usr/bin/env python3
"""Semi-analytic solution of ALGORITHMS.md 3.6 check 2: an infinite plane-strain strip
0 <= y <= l on bilateral Winkler springs (bottom: sigma22 = cn u2, sigma12 = 0, the springs pull
too), loaded on top by the Gaussian traction (0, -F exp(-psi x^2)) (top: sigma12 = 0,
sigma22 = -g), solved exactly by a cosine/sine transform in x.

With u1 = int_0^inf a(k, y) sin(kx) dk and u2 = int_0^inf b(k, y) cos(kx) dk, Navier's equations
become per wavenumber k the 4 x 4 linear ODE z' = A(k) z in z = (a, b, a', b'):
    mu a'' = (lambda + 2 mu) k^2 a + (lambda + mu) k b'
    (lambda + 2 mu) b'' = mu k^2 b - (lambda + mu) k a'
with sigma12 = mu (a' - k b) sin(kx) and sigma22 = (lambda k a + (lambda + 2 mu) b') cos(kx), and
the load's transform g_hat(k) = (F / pi) sqrt(pi / psi) exp(-k^2 / (4 psi)). The top state is
exp(A l) times the bottom one (the matrix exponential by scaling and squaring: A is defective,
its roots +-k are double), and the four boundary conditions fix the bottom state. The integral
over k is Gauss-Legendre (400 points: 10 digits) on [0, k_max], k_max where g_hat has fallen
by e^-40.

numpy only (CI has no scipy). Prints JSON: the peak bottom and top deflections, the peak spring
pressure cn d, its integral (= F sqrt(pi / psi)) and where the springs go into tension.

    winkler_strip.py --psi 50 [--E 100 --nu 0.3 --l 0.1 --cn 10 --F 10] [--profile FILE.csv]

With --compare DECK RUN_DIR it compares a finished static run of a rail deck (MESH
generator=rectangle, CONTACT law=compliance-bilateral, MOVINGLOAD at x0 on a node; the data are
read from the deck) with the strip: the deflections of the bottom and top nodes at x0 (contact.csv
and case.b's u, the rectangle's nodes numbered row by row from (0, 0)) and the spring pressure
there; prints JSON and exits 1 if one differs by more than --tolerance (relative, default 0.01).
"""
import argparse
import json
import math
import sys

import numpy as np


def expm(M):
    """exp(M) by scaling and squaring with a Taylor series (M small and dense)."""
    norm = np.abs(M).sum(axis=1).max()
    s = max(0, int(math.ceil(math.log2(norm / 0.25))) if norm > 0.25 else 0)
    X = M / 2.0**s
    E = np.eye(M.shape[0])
    term = np.eye(M.shape[0])
    for n in range(1, 20):
        term = term @ X / n
        E = E + term
    for _ in range(s):
        E = E @ E
    return E


def bottom_and_top(k, E, nu, l, cn, F, psi):
    """b(k, 0) and b(k, l): the vertical displacement amplitudes at the bottom and the top."""
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    A = np.zeros((4, 4))
    A[0, 2] = A[1, 3] = 1.0
    A[2, 0] = (lam + 2 * mu) * k * k / mu
    A[2, 3] = (lam + mu) * k / mu
    A[3, 1] = mu * k * k / (lam + 2 * mu)
    A[3, 2] = -(lam + mu) * k / (lam + 2 * mu)
    P = expm(A * l)
    shear = np.array([0.0, -k, 1.0, 0.0])           # a' - k b
    normal = np.array([lam * k, 0.0, 0.0, lam + 2 * mu])  # sigma22 amplitude
    g_hat = F / math.pi * math.sqrt(math.pi / psi) * math.exp(-k * k / (4 * psi))
    rows = np.array([shear, normal - np.array([0.0, cn, 0.0, 0.0]), shear @ P, normal @ P])
    z0 = np.linalg.solve(rows, np.array([0.0, 0.0, 0.0, -g_hat]))
    return z0[1], (P @ z0)[1]


def solve(E=100.0, nu=0.3, l=0.1, cn=10.0, F=10.0, psi=50.0, points=400):
    k_max = math.sqrt(160.0 * psi)  # g_hat(k_max) = g_hat(0) e^-40
    nodes, weights = np.polynomial.legendre.leggauss(points)
    k = 0.5 * k_max * (nodes + 1)
    w = 0.5 * k_max * weights
    amplitudes = np.array([bottom_and_top(kk, E, nu, l, cn, F, psi) for kk in k])
    return k, w, amplitudes


def deflection(k, w, amplitude, x):
    """-u2 at abscissae x (from the load's centre): the deflection, positive downwards."""
    return -np.cos(np.outer(x, k)) @ (w * amplitude)


def compare(deck_path, run_dir):
    """The FE run against the strip: {quantity: {"ours", "strip", "relative"}}."""
    from pathlib import Path

    from sigreport import ReportError, read_csv_columns, read_deck, read_ds

    deck = read_deck(deck_path)
    if deck.value("MESH", "generator") != "rectangle":
        raise ReportError(f"{deck_path}: the comparison needs MESH generator=rectangle")
    if deck.value("CONTACT", "law") != "compliance-bilateral":
        raise ReportError(f"{deck_path}: the strip's springs are CONTACT law=compliance-bilateral")
    nx, ny = int(deck.number("MESH", "nx")), int(deck.number("MESH", "ny"))
    lx = deck.number("MESH", "lx")
    E, nu = deck.number("MATERIAL", "E"), deck.number("MATERIAL", "nu")
    cn = deck.number("CONTACT", "cn")
    F, psi = deck.number("MOVINGLOAD", "F"), deck.number("MOVINGLOAD", "psi")
    x0 = deck.number("MOVINGLOAD", "x0", 0.0)
    column = round(x0 / lx * nx)
    if abs(column * lx / nx - x0) > 1e-9 * lx:
        raise ReportError(f"{deck_path}: the load's centre x0 = {x0} is on no node column")
    run_dir = Path(run_dir)
    rows = read_csv_columns(run_dir / "contact.csv", text_columns=("status", "normal_status",
                                                                   "friction_status"))
    at = [i for i, x in enumerate(rows["x1"]) if abs(x - x0) <= 1e-9 * lx]
    if len(at) != 1:
        raise ReportError(f"{run_dir}/contact.csv: no single contact node at x1 = {x0}")
    i = at[0]
    if int(rows["node"][i]) != column + 1:
        raise ReportError(f"{run_dir}/contact.csv: node {rows['node'][i]} at x1 = {x0}, not the "
                          f"rectangle's node {column + 1}: its numbering is not row by row")
    u = read_ds(run_dir / "case.b", arrays=["u"])["u"]
    top = ny * (nx + 1) + column
    k, w, amp = solve(E, nu, deck.number("MESH", "ly"), cn, F, psi)
    strip = {
        "bottom_deflection": float(deflection(k, w, amp[:, 0], [0.0])[0]),
        "top_deflection": float(deflection(k, w, amp[:, 1], [0.0])[0]),
    }
    strip["peak_pressure"] = cn * strip["bottom_deflection"]
    ours = {
        "bottom_deflection": -rows["u2"][i],
        "top_deflection": -u[2 * top + 1],
        "peak_pressure": rows["pressure"][i],
    }
    return {q: {"ours": ours[q], "strip": strip[q], "relative": ours[q] / strip[q] - 1}
            for q in strip}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--E", type=float, default=100.0)
    parser.add_argument("--nu", type=float, default=0.3)
    parser.add_argument("--l", type=float, default=0.1)
    parser.add_argument("--cn", type=float, default=10.0)
    parser.add_argument("--F", type=float, default=10.0)
    parser.add_argument("--psi", type=float)
    parser.add_argument("--profile", help="write x, bottom and top deflection to this CSV")
    parser.add_argument("--compare", nargs=2, metavar=("DECK", "RUN_DIR"))
    parser.add_argument("--tolerance", type=float, default=0.01)
    a = parser.parse_args(argv)
    if a.compare:
        result = compare(*a.compare)
        json.dump(result, sys.stdout, indent=1)
        print()
        return 0 if all(abs(r["relative"]) <= a.tolerance for r in result.values()) else 1
    if a.psi is None:
        parser.error("give --psi (or --compare DECK RUN_DIR)")
    k, w, amp = solve(a.E, a.nu, a.l, a.cn, a.F, a.psi)
    x = np.linspace(0.0, 2.0, 4001)
    bottom = deflection(k, w, amp[:, 0], x)
    top = deflection(k, w, amp[:, 1], x)
    tension = x[np.argmax(bottom < 0)] if np.any(bottom < 0) else float("nan")
    # int p dx = cn int d dx over the whole line = cn pi (-b(0, 0)), the k = 0 limit.
    b0, _ = bottom_and_top(1e-9, a.E, a.nu, a.l, a.cn, a.F, a.psi)
    result = {
        "psi": a.psi,
        "peak_bottom_deflection": float(bottom[0]),
        "peak_top_deflection": float(top[0]),
        "peak_pressure": float(a.cn * bottom[0]),
        "pressure_integral": float(-a.cn * math.pi * b0),
        "load_integral": a.F * math.sqrt(math.pi / a.psi),
        "tension_beyond": float(tension),
    }
    if a.profile:
        with open(a.profile, "w") as out:
            out.write("x,bottom_deflection,top_deflection\n")
            for row in zip(x, bottom, top):
                out.write("%.6f,%.10g,%.10g\n" % row)
    json.dump(result, sys.stdout, indent=1)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
