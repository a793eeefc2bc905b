#!/usr/bin/python3
"""Newton iteration counts of GetFEM and of our stages on the frictional half disc, each iterate
judged by ONE residual computed here the same way for both (issue 23's comparison).

    /usr/bin/python3 postproc/getfem_newton_counts.py --deck DATAFILE [--method pdas|alm]
        [--r-getfem R] [--start rest|deck] [--tol 1e-10] [--max 60] [--version 1|2]
        [--bin DIR] [--json FILE]

The problem is getfem_friction.py's (half disc, no Dirichlet condition, Coulomb friction), from
the deck's INITIAL u (--start deck) or from u = 0 (--start rest), on the same mesh (gmsh's
half_disc.geo for GetFEM, sig-mesh's half-disc generator for us: the same nodes, checked).

The measure of an iterate (u, N, T), N, T our nodal normal and tangential forces (contact.csv's
multiplier and tangential_multiplier), all in forces:
    equilibrium   K u - F - sum_i (N_i n - T_i t) at the contact nodes' dofs, K and F GetFEM's
                  assembled plane-strain stiffness and traction load
    contact       N_i - [N_i + k q_i]_+ with q_i = -(gap_i + n . u_i) the penetration
    friction      T_i - proj_[-mu N_i+, mu N_i+](T_i + k t . u_i)
with k = E (a node's stiffness per unit thickness, the natural scale of issue 23) and the whole
vector's norm divided by ||F||. Its zeros are the solutions whatever k > 0. The last iterates'
nodal forces are compared too: max over nodes of |ours - GetFEM's| over GetFEM's largest force
(force_difference), meaningful when both converged.

Counts: GetFEM's k-th iterate is its state after md.solve with max_iter = k (its Newton is
deterministic from the same start), ours the state sig-solve writes with SOLVER maxit = k; the
count is the first k whose measure is <= tol. Augmentations: GetFEM's r acts on nodal forces
through alpha_i = M_ii / l (getfem_friction.py), ours on pressures, so the same law needs
r_ours = r_getfem alpha_i / w_i = r_getfem 2 / (3 l) (P1: M_ii = 2 w_i / 3).
"""
import argparse
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from getfem_common import nopo_coordinates  # noqa: E402
from getfem_friction import build_problem, read_deck  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent


def fail(message):
    sys.exit(f"getfem_newton_counts.py: error: {message}")


def measure(p, mu, u, N, T):
    """The relative residual of the module docstring; u on GetFEM's dofs, N and T per contact
    node in GetFEM's contact-node order."""
    force = np.zeros_like(u)
    force[p.xdof] = N * p.n[0] - T * p.t[0]
    force[p.ydof] = N * p.n[1] - T * p.t[1]
    equilibrium = np.asarray(p.K.mult(u)).ravel() - p.F - force
    k = p.E
    q = -(p.gap + p.n[0] * u[p.xdof] + p.n[1] * u[p.ydof])
    slip = p.t[0] * u[p.xdof] + p.t[1] * u[p.ydof]
    contact = N - np.maximum(N + k * q, 0.0)
    bound = mu * np.maximum(N, 0.0)
    friction = T - np.clip(T + k * slip, -bound, bound)
    total = math.sqrt(equilibrium @ equilibrium + contact @ contact + friction @ friction)
    return total / np.linalg.norm(p.F)


def getfem_iterates(p, start, kmax, version_options):
    """GetFEM's iterates 1 .. kmax from `start` (name -> values)."""
    for k in range(1, kmax + 1):
        for name, value in start.items():
            p.md.set_variable(name, value)
        p.md.solve("max_res", 1e-30, "max_iter", k, "lsolver", "auto", *version_options)
        N, T = p.forces()
        yield k, p.displacement().copy(), N, T


class Ours:
    """Our stages on the deck: the chain once, then sig-solve with maxit = k."""

    def __init__(self, deck_text, workdir, bindir, p):
        self.work, self.bin, self.text = workdir, bindir, deck_text
        self.deck = workdir / "deck.dat"
        self.deck.write_text(deck_text)
        for stage in ("mesh", "material", "contact", "assemble"):
            self.run(stage)
        ours = nopo_coordinates(workdir / "case.nopo")
        theirs = np.asarray(p.m.pts()).T
        from scipy.spatial import cKDTree
        dist, self.node_of = cKDTree(ours).query(theirs)  # GetFEM point -> our node
        if dist.max() > 1e-9:
            fail(f"the meshes differ: a GetFEM node is {dist.max():.3g} from ours")
        # GetFEM's dof -> our dof: GetFEM's basic dof nodes are its mesh points
        dof_nodes = np.asarray(p.mfu.basic_dof_nodes()).T[0::2]
        dist, node = cKDTree(ours).query(dof_nodes)
        self.our_dof = np.empty(p.nbdof, dtype=int)
        self.our_dof[0::2], self.our_dof[1::2] = 2 * node, 2 * node + 1
        self.contact_xy = p.X.T

    def run(self, stage, check=True):
        done = subprocess.run([str(self.bin / f"sig-{stage}"), str(self.deck), "-o", str(self.work)],
                              capture_output=True, text=True)
        if check and done.returncode != 0:
            fail(f"sig-{stage} failed: {done.stderr.strip()}")
        return done

    def iterate(self, k):
        """(u on GetFEM's dofs, N, T in GetFEM's contact order) after k iterations."""
        lines = [l for l in self.text.splitlines() if not l.upper().startswith("SOLVER")]
        solver = [l for l in self.text.splitlines() if l.upper().startswith("SOLVER")][0]
        solver = " ".join(w for w in solver.split() if not w.lower().startswith(("maxit=", "eps=")))
        self.deck.write_text("\n".join(lines + [f"{solver} maxit={k} eps=1e-14"]) + "\n")
        self.run("solve", check=False)
        self.run("post")
        u = dump_values(self.bin, self.work / "case.b", "u")
        rows = np.genfromtxt(self.work / "contact.csv", delimiter=",", names=True)
        from scipy.spatial import cKDTree
        _, row = cKDTree(np.c_[rows["x1"], rows["x2"]]).query(self.contact_xy)
        return u[self.our_dof], rows["multiplier"][row], rows["tangential_multiplier"][row]


def dump_values(bindir, path, name):
    out = subprocess.run([str(bindir / "sig-dump"), "--json", f"--values={name}", str(path)],
                         capture_output=True, text=True, check=True).stdout
    for a in json.loads(out)["arrays"]:
        if a["name"] == name:
            return np.asarray(a["values"], dtype=float)
    fail(f"{path} has no array {name}")


def first_below(values, tol):
    for k, v in values:
        if v <= tol:
            return k
    return None


def main():
    import getfem as gf
    gf.util_trace_level(0)
    gf.util_warning_level(0)
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--deck", type=Path, required=True)
    parser.add_argument("--method", default="pdas", choices=("pdas", "alm"))
    parser.add_argument("--r-getfem", type=float, help="GetFEM's augmentation (default E)")
    parser.add_argument("--start", default="deck", choices=("deck", "rest"))
    parser.add_argument("--tol", type=float, default=1e-10)
    parser.add_argument("--max", type=int, default=60, help="iterations tried on each side")
    parser.add_argument("--version", type=int, default=1, choices=(1, 2))
    parser.add_argument("--bin", type=Path, default=ROOT / "build" / "bin")
    parser.add_argument("--json", type=Path)
    args = parser.parse_args()
    d = read_deck(args.deck)
    if d["law"] != "coulomb":
        fail("the comparison is Coulomb's")
    start = (0.0, 0.0) if args.start == "rest" else None
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        p = build_problem(d, args.r_getfem, args.version, "obstacle", work / "gmsh", start=start)
        pts = np.asarray(p.m.pts())
        l = float(np.max(pts.max(axis=1) - pts.min(axis=1)))
        r_ours = p.r * 2.0 / (3.0 * l)
        text = args.deck.read_text().splitlines()
        key = "gamma" if args.method == "pdas" else "r"
        text = [l for l in text if not l.upper().startswith(("SOLVER", "INITIAL"))]
        text.append(f"SOLVER method={args.method} {key}={r_ours!r} linear=mumps")
        if args.start == "deck":
            text.append(f"INITIAL u={p.start_shift[0]!r},{p.start_shift[1]!r}")
        ours = Ours("\n".join(text) + "\n", work, args.bin, p)

        theirs, their_forces = [], None
        for k, u, N, T in getfem_iterates(p, p.unknowns, args.max, []):
            theirs.append((k, measure(p, d["mu"], u, N, T)))
            their_forces = (N, T)
            if theirs[-1][1] <= args.tol:
                break
        mine, my_forces = [], None
        for k in range(1, args.max + 1):
            u, N, T = ours.iterate(k)
            mine.append((k, measure(p, d["mu"], u, N, T)))
            my_forces = (N, T)
            if mine[-1][1] <= args.tol:
                break
    scale = max(np.abs(their_forces[0]).max(), np.abs(their_forces[1]).max())
    force_difference = max(np.abs(my_forces[0] - their_forces[0]).max(),
                           np.abs(my_forces[1] - their_forces[1]).max()) / scale
    summary = {"deck": str(args.deck), "method": args.method, "start": args.start,
               "r_getfem": p.r, "r_ours": r_ours, "tol": args.tol,
               "getfem": first_below(theirs, args.tol), "ours": first_below(mine, args.tol),
               "getfem_history": [v for _, v in theirs], "our_history": [v for _, v in mine],
               "force_difference": float(force_difference)}
    print(f"{args.method} r_getfem {p.r:g} (ours {r_ours:.6g}), start {args.start}: GetFEM "
          f"{summary['getfem']} iterations, ours {summary['ours']} (residual <= {args.tol:g}); "
          f"forces differ by {force_difference:.1e} of their maximum")
    if args.json:
        args.json.write_text(json.dumps(summary, indent=1) + "\n")


if __name__ == "__main__":
    main()
