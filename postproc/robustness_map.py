#!/usr/bin/python3
"""The robustness map of the contact Newton (issue 23): every method on decks that are not tuned
for it, its parameter over 1e-2 .. 1e4 times the natural scale in half decades, two meshes, from
rest and from the scene's start; per point the iterations or the failure's name.

    /usr/bin/python3 postproc/robustness_map.py run OUT [--quick]    the runs (sig-* in $SIG_BIN)
    /usr/bin/python3 postproc/robustness_map.py report OUT           OUT/report.md, maps, scene.json

Natural scales (what a parameter is measured against): r and gamma, pressure per length, E / h
with E Young's modulus (for Ciarlet-Geymonat's law its small-strain modulus) and h the mesh size
of the contact boundary from the median nodal weight w (in 2D h = w, half a node's two Gamma3
edges; in 3D w is an area and h = sqrt(w)); c, length per pressure, h / E. A point's parameter
is factor x its natural scale.

The decks (datafiles/, each as it ships but for the SOLVER card and the start):
  hertz            scene 7a's half disc, frictionless Signorini (the deck's search=no dropped)
  coulomb          the frictional Hertz deck, Coulomb mu = 0.4, no Dirichlet condition
  tresca           the same with FRICTION law=tresca threshold=1
  ball, square     scene 4's decks: compliance with a wall, non-monotone friction, convexification
  ring             scene 7b's Ciarlet-Geymonat ring in one load step
  ring14           the same in LOADSTEPS n=14
  hertz3d          the 3D Hertz half ball (datafiles/scene3d/hertz_ball.dat), frictionless
  coulomb3d        its Cattaneo-Mindlin shear (cattaneo_mindlin.dat), Coulomb mu = 0.3 with the
                   cone: both on coarse half balls (pole size h = 0.25 and 0.15, grading 0.3),
                   without candidate_gap (every Gamma3 node a contact node), from rest
Starts: rest (no INITIAL card; the ring's LOADSTEPS start=rest) and the scene's own where it has
one (the frictional decks' rigid shift (0, -h^2 / R), the ring's small-strain start).
Each point is one sig-solve on the bulk stages of its deck, mesh and start, with the deck's eps
and maxit; its result is read from case.b (converged, iterations, failure_reason).
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from sigreport import (Checks, Deck, MapCell, MapPanel, ReportError, Table, main_guard,  # noqa: E402
                       read_ds, stability_map, write_report)

ROOT = Path(__file__).resolve().parent.parent
BIN = Path(os.environ.get("SIG_BIN", ROOT / "build" / "bin"))
FACTORS = [10 ** (e / 2) for e in range(-4, 9)]  # 1e-2 .. 1e4, half decades
QUICK_FACTORS = [1e-2, 1.0, 1e2, 1e4]
METHODS = {"pdas": "gamma", "alm": "r", "projection": "c", "penalty": "r"}
SHORT = {"cycling": "cyc", "stagnation": "stag", "divergence": "div", "drift": "drift",
         "iteration-limit": "lim", "singular-step": "sing"}


class DeckSpec:
    """A deck of the map: its template, the meshes (the MESH field and its values) and starts."""

    def __init__(self, name, template, mesh_field, meshes, starts, edit=None, quick_mesh=None,
                 law="", methods=tuple(METHODS), dim=2):
        self.name, self.template, self.mesh_field = name, ROOT / template, mesh_field
        self.dim = dim
        self.meshes, self.starts, self.edit = meshes, starts, edit
        self.quick_mesh, self.law, self.methods = quick_mesh, law, methods

    def deck(self, mesh, start):
        d = Deck.read(self.template)
        d.set("MESH", **{self.mesh_field: str(mesh)})
        d.drop("SOLVER", "search")
        if self.edit:
            self.edit(d)
        if start == "rest":
            d.remove_cards("INITIAL")
            if d.has("LOADSTEPS"):
                d.set("LOADSTEPS", start="rest")
        elif d.has("FRICTION") and d.value("MESH", "generator") == "half-disc":
            radius = d.number("MESH", "R")
            h = math.pi * radius / mesh
            d.remove_cards("INITIAL")
            d.add_card(f"INITIAL u=0,{-h * h / radius!r}")
        return d


def coarse_half_ball(d):
    d.set("MESH", grading="0.3")
    d.drop("SOLVER", "candidate_gap")


def tresca(d):
    d.set("FRICTION", law="tresca", threshold="1")
    d.drop("FRICTION", "mu")


def fourteen_steps(d):
    d.set("LOADSTEPS", n="14")


DECKS = [
    DeckSpec("hertz", "datafiles/scene7a/hertz.dat", "N", [64, 128], ["rest"], quick_mesh=64,
             law="Signorini"),
    DeckSpec("coulomb", "datafiles/friction/hertz_coulomb.dat", "N", [64, 128], ["rest", "scene"],
             quick_mesh=64, law="Coulomb mu = 0.4"),
    DeckSpec("tresca", "datafiles/friction/hertz_coulomb.dat", "N", [64, 128], ["rest", "scene"],
             edit=tresca, quick_mesh=64, law="Tresca threshold 1"),
    DeckSpec("ball", "datafiles/scene4/ball.dat", "N", [256, 512], ["rest"],
             law="compliance + wall, non-monotone friction"),
    DeckSpec("square", "datafiles/scene4/square.dat", "nx", [16, 32], ["rest"],
             law="compliance + wall, non-monotone friction"),
    DeckSpec("ring", "datafiles/scene7b/ring.dat", "N", [64, 128], ["rest", "scene"],
             quick_mesh=64, law="Signorini, Ciarlet-Geymonat, one load step"),
    DeckSpec("ring14", "datafiles/scene7b/ring.dat", "N", [64, 128], ["rest", "scene"],
             edit=fourteen_steps, law="Signorini, Ciarlet-Geymonat, 14 load steps"),
    DeckSpec("hertz3d", "datafiles/scene3d/hertz_ball.dat", "h", [0.25, 0.15], ["rest"],
             edit=coarse_half_ball, quick_mesh=0.25, law="Signorini, 3D", dim=3),
    DeckSpec("coulomb3d", "datafiles/scene3d/cattaneo_mindlin.dat", "h", [0.25, 0.15], ["rest"],
             edit=coarse_half_ball, quick_mesh=0.25, law="Coulomb mu = 0.3, 3D (the cone)", dim=3),
]
QUICK = {"hertz": ("rest",), "coulomb": ("rest",), "tresca": ("scene",), "ring": ("scene",),
         "coulomb3d": ("rest",)}
QUICK_METHODS = ("pdas", "alm", "projection")


def stage(name, deck, folder):
    done = subprocess.run([str(BIN / f"sig-{name}"), str(deck), "-o", str(folder)],
                          capture_output=True, text=True)
    if done.returncode != 0:
        raise ReportError(f"sig-{name} {deck}: {done.stderr.strip()[-400:]}")
    return done


def young_modulus(deck):
    """E of the (first) MATERIAL card; Ciarlet-Geymonat's small-strain modulus from c1, c2, a
    (lambda = 4 (a + c2), mu = 2 (c1 + c2), ../shared/PEERS.md)."""
    if deck.value("MATERIAL", "law") == "ciarlet-geymonat":
        c1, c2, a = (deck.number("MATERIAL", f) for f in ("c1", "c2", "a"))
        lam, mu = 4 * (a + c2), 2 * (c1 + c2)
        return mu * (3 * lam + 2 * mu) / (lam + mu)
    return deck.number("MATERIAL", "E")


def natural_scale(deck, base, dim):
    """E / h (pressure per length), h from the median nodal weight w of case.cont: w in 2D (a
    length), sqrt(w) in 3D (an area)."""
    weights = sorted(read_ds(base / "case.cont", ["weight"])["weight"])
    return young_modulus(deck) / weights[len(weights) // 2] ** (1 / (dim - 1))


def run_point(base, folder, deck, method, value):
    """One sig-solve of `deck` with SOLVER method=value on the DS files of `base`."""
    folder.mkdir(parents=True, exist_ok=True)
    for name in ("case.nopo", "case.mili", "case.cont", "case.tae"):
        target = folder / name
        if not target.exists():
            target.symlink_to(base / name)
    deck.set("SOLVER", method=method, **{METHODS[method]: f"{value:.6g}"})
    deck.write(folder / "deck.dat")
    start = time.perf_counter()
    stage("solve", folder / "deck.dat", folder)
    seconds = time.perf_counter() - start
    b = read_ds(folder / "case.b", ["converged", "iterations", "failure_reason"])
    converged = bool(b["converged"][0])
    return {"converged": converged, "iterations": int(b["iterations"][0]),
            "failure": "" if converged else b.get("failure_reason", "iteration-limit"),
            "seconds": seconds}


def run(out, quick):
    out.mkdir(parents=True, exist_ok=True)
    points = []
    factors = QUICK_FACTORS if quick else FACTORS
    for spec in DECKS:
        if quick and spec.name not in QUICK:
            continue
        meshes = [spec.quick_mesh] if quick else spec.meshes
        starts = QUICK[spec.name] if quick else spec.starts
        methods = QUICK_METHODS if quick else spec.methods
        for mesh in meshes:
            for start in starts:
                base = out / spec.name / f"m{mesh}_{start}" / "base"
                base.mkdir(parents=True, exist_ok=True)
                deck = spec.deck(mesh, start)
                deck.write(base / "deck.dat")
                for name in ("mesh", "material", "contact", "assemble"):
                    stage(name, base / "deck.dat", base)
                scale = natural_scale(deck, base, spec.dim)
                for method in methods:
                    for factor in factors:
                        value = factor / scale if method == "projection" else factor * scale
                        folder = base.parent / f"{method}_{factor:.3g}"
                        result = run_point(base, folder, spec.deck(mesh, start), method, value)
                        points.append({"deck": spec.name, "law": spec.law, "mesh": mesh,
                                       "mesh_field": spec.mesh_field,
                                       "start": start, "method": method, "factor": factor,
                                       "parameter": value, "natural": scale, **result})
                        outcome = result["iterations"] if result["converged"] else result["failure"]
                        print(f"{spec.name} {mesh_label(points[-1])} {start} {method} "
                              f"x{factor:.3g}: {outcome}", flush=True)
    (out / "map.json").write_text(json.dumps({"quick": quick, "points": points}, indent=1) + "\n")


# --- The report -----------------------------------------------------------------------------


def mesh_label(p):
    """A point's mesh as its MESH field and value: N128, h0.25."""
    return f"{p.get('mesh_field', 'N')}{p['mesh']}"


def factor_label(f):
    e = round(2 * math.log10(f)) / 2
    return f"1e{e:g}" if e == int(e) else f"1e{e:g}"


def panels_of(points, deck):
    mine = [p for p in points if p["deck"] == deck]
    rows = sorted({(p["method"], p["mesh"], p["start"]) for p in mine},
                  key=lambda r: (list(METHODS).index(r[0]), r[1], r[2]))
    factors = sorted({p["factor"] for p in mine})
    at = {(p["method"], p["mesh"], p["start"], p["factor"]): p for p in mine}
    cells = []
    for row in rows:
        line = []
        for f in factors:
            p = at.get(row + (f,))
            if p is None:
                line.append(MapCell("", "missing"))
            elif p["converged"]:
                line.append(MapCell(str(p["iterations"]), "ok", p["iterations"]))
            else:
                line.append(MapCell(SHORT.get(p["failure"], p["failure"]), "Nv"))
        cells.append(line)
    label = {(p["method"], p["mesh"], p["start"]): mesh_label(p) for p in mine}
    return MapPanel(deck, [f"{r[0]} {label[r]} {r[2]}" for r in rows],
                    [factor_label(f) for f in factors],
                    cells, xlabel="parameter / natural scale (-)", ylabel="method, mesh, start (-)")


# The theory's reason for the failures the map shows where a method or a law leaves what it
# covers (the report's last section).
THEORY = """\
- **Projection with a small c** (c = factor x h / E): its inactive nodes follow the Robin law
  q_n(k+1) = q_n(k) + c lambda(k+1) (7.22), a relaxed fixed point. A node of stiffness k (force
  per length, the natural scale's k ~ E / h times its weight) moves by 1 / (1 + c k) of the
  distance to its fixed point per iteration: the contraction is rho = 1 / (1 + c k), about
  1 / (1 + factor), and the iterations to reduce the error by eps are ln(1/eps) / ln(1/rho):
  at factor 1e-2, rho = 0.990 and about 2300 iterations for eps = 1e-10, beyond maxit. The
  thesis's Nv for c <= 10 on the ring (Table 7.1) is the same contraction.
- **Penalty**: its r is a model parameter (the penetration is p / r), not an algorithm's; at a
  large r the piecewise-linear springs are stiff: a node sticks only while |q_t| <= s / r, a
  window a step crosses in a fraction of order s / (r |dq_t|) of its length, and the path between
  spring states grows long (the map names where it stops), at a small r the body sinks into
  the foundation by p / r.
- **Non-monotone friction (scene 4's ball and square)**: mu(|u_t|) falls with the slip, the
  problem is not monotone and the convexification loop (4.110)-(4.112) converges only where
  the fixed point contracts (ALGORITHMS.md 1.3: p0 m_mu + mu0 L_p < alpha0); a failure there is
  the loop's, with the inner Newton's reason when an inner solve fails.
- **Coulomb friction** is not monotone either: existence holds for mu small enough against the
  bulk's normal-tangential coupling, uniqueness for smaller mu still; the scenes' mu (0.4 on
  the half disc) are in the range the map covers."""


def checks_of(points):
    checks = Checks()
    exact = ("hertz", "coulomb", "tresca", "ring", "ring14", "hertz3d", "coulomb3d")
    for deck in exact:
        mine = [p for p in points if p["deck"] == deck and p["method"] in ("pdas", "alm")]
        if not mine:
            continue
        failed = [p for p in mine if not p["converged"]]
        where = ", ".join(f"{p['method']} {mesh_label(p)} {p['start']} x{p['factor']:.3g}: "
                          f"{p['failure']}" for p in failed[:6])
        checks.add(f"{deck}: ALM and PDAS converge at every point", not failed,
                   ours=f"{len(mine) - len(failed)} of {len(mine)}" + (f" ({where})" if failed else ""),
                   target=f"{len(mine)} of {len(mine)}")
    return checks


def summary_table(points):
    rows = []
    decks = list(dict.fromkeys(p["deck"] for p in points))
    for deck in decks:
        for method in METHODS:
            mine = [p for p in points if p["deck"] == deck and p["method"] == method]
            if not mine:
                continue
            ok = [p["iterations"] for p in mine if p["converged"]]
            reasons = sorted({p["failure"] for p in mine if not p["converged"]})
            rows.append([deck, method, f"{len(ok)} / {len(mine)}",
                         f"{min(ok)} .. {max(ok)}" if ok else "—",
                         f"{sorted(ok)[len(ok) // 2]}" if ok else "—", ", ".join(reasons) or "—"])
    return Table(["deck", "method", "converged", "iterations", "median", "failures"], rows)


def report(out):
    data = json.loads((out / "map.json").read_text())
    points = data["points"]
    decks = list(dict.fromkeys(p["deck"] for p in points))
    charts = {}
    for deck in decks:
        charts[deck] = stability_map(out / f"map_{deck}.png", [panels_of(points, deck)],
                                     value_label="Newton iterations (iterations)",
                                     title=f"{deck}: iterations, or the failure's name",
                                     cell_size=(0.62, 0.42), fontsize=7).name
    checks = checks_of(points)
    laws = {p["deck"]: p["law"] for p in points}
    lines = ["# Robustness map of the contact Newton", "",
             f"{'Quick' if data['quick'] else 'Full'} map: {len(points)} solves "
             f"({sum(p['seconds'] for p in points):.0f} s of sig-solve). Each cell is one "
             "sig-solve: its Newton iterations, or the reason it stopped (cyc cycling, stag "
             "stagnation, div divergence, drift, lim iteration limit, sing a singular step). "
             "Columns: the method's parameter over its natural scale (r, gamma: E / h; c: h / E).",
             "", "## Per deck and method", "", summary_table(points).markdown(), ""]
    for deck in decks:
        lines += [f"## {deck} ({laws[deck]})", "", f"![{deck}]({charts[deck]})", ""]
    lines += ["## Checks", "", checks.table().markdown(), "",
              "## Where the theory does not cover a method or a law", "", THEORY, ""]
    command = (out / "command.txt").read_text().strip() if (out / "command.txt").exists() else ""
    write_report(out, "\n".join(lines) + "\n", "robustness", "Robustness map of the contact Newton",
                 command, checks, charts={k: v for k, v in charts.items()})
    print(f"{out / 'report.md'}: {len(points)} points, checks {checks.passed} PASS, "
          f"{checks.failed} FAIL")
    return 0 if checks.failed == 0 else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("what", choices=("run", "report"))
    parser.add_argument("out", type=Path)
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    if args.what == "run":
        run(args.out, args.quick)
        return 0
    return report(args.out)


if __name__ == "__main__":
    main_guard(main)
