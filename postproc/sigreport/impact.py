"""The impact scenes (8a, 8b): a run folder of sig-march with energy.csv (sig-post, every
step), case.hist and wall.txt (the stage's wall-clock seconds), the measures both reports take
of it, and the status of a run in their stability maps.

    rows = read_energy_rows(folder)          # [{column: float}] per time level; None: no march
    hist = hist_scalars(folder / "case.hist", ["converged", "failure", "time_march"])
    run = {"rows": rows, "hist": hist, "k": k, "T": T, "wall": wall_seconds(folder)}
    run.update(energy_measures(run))         # converged, e0, change (%), penetration, ...
    impact_window(runs, before=0.01, after=0.03)  # times around the first impact of any run
    energy_curves(runs, label_of, marker_of)      # the curves of charts.energy_chart
    speed_point(run, "k=1e-2")               # wall time per simulated second, |dE| / E0 (%)
    stability_status(run, gain=0.1, loss=1.0)     # "Nv", "ok" or "gain", "dissipates", ...
    bar = Bar.of_deck(Deck.read("bar.dat"))   # the closed form of a bar striking a wall
    bar.measures(rows)                        # its run against it: energy, contact time, impulse
"""
import csv
import math
from pathlib import Path

from .charts import Point
from .ds import read_ds

# A change of energy below this (in %) is drawn at it on the log axis of the speed chart.
SMALLEST_CHANGE = 1e-6


def read_energy_rows(folder):
    """energy.csv of a run as a list of {column: float}; None when the run did not march (no
    file, or no row)."""
    path = Path(folder) / "energy.csv"
    if not path.is_file():
        return None
    with path.open() as f:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    return rows or None


def hist_scalars(path, arrays):
    """One value of each of `arrays` of a case.hist (a text array whole), {} when the march
    wrote no case.hist."""
    if not Path(path).is_file():
        return {}
    ds = read_ds(path, arrays=arrays)
    return {name: v if isinstance(v, str) else v[0] for name, v in ds.values.items()}


def wall_seconds(folder):
    """The stage's wall-clock seconds (wall.txt), nan when absent."""
    path = Path(folder) / "wall.txt"
    return float(path.read_text()) if path.is_file() else math.nan


def energy_measures(run):
    """What both impact reports measure of a run (a dict with rows, hist, k, T): converged (the
    march says so and made every planned step), failure, e0, change (the energy change across
    the run, % of E0), penetration, impact_step and impact_time (the first step with an active
    node), max_active, newton (iterations), steps."""
    rows = run["rows"]
    e0 = rows[0]["total"]
    active = [int(r["active_nodes"]) for r in rows]
    contact = [i for i, a in enumerate(active) if a > 0]
    first = contact[0] if contact else None
    finite = not (math.isnan(run["k"]) or math.isnan(run["T"]))
    planned = round(run["T"] / run["k"]) if finite else len(rows) - 1
    return {
        "converged": int(run["hist"].get("converged", 1)) != 0 and len(rows) == planned + 1,
        "failure": run["hist"].get("failure", ""),
        "e0": e0,
        "change": 100 * (rows[-1]["total"] - e0) / e0,
        "penetration": max(r["max_penetration"] for r in rows),
        "impact_step": first,
        "impact_time": rows[first]["time"] if first is not None else math.nan,
        "contact": contact,
        "active": active,
        "max_active": max(active),
        "newton": int(sum(r["newton_iterations"] for r in rows)),
        "steps": len(rows) - 1,
    }


def impact_window(runs, before, after):
    """(t0 - before, t0 + after) about the first impact t0 of the runs; everything when none
    touched."""
    impacts = [r["impact_time"] for r in runs if not math.isnan(r["impact_time"])]
    if not impacts:
        return (-math.inf, math.inf)
    return (min(impacts) - before, min(impacts) + after)


def energy_curves(runs, label_of, marker_of, key="total"):
    """(label, marker, times, key / E0) of each run, for charts.energy_chart."""
    return [(label_of(run), marker_of(run), [r["time"] for r in run["rows"]],
             [r[key] / run["e0"] for r in run["rows"]]) for run in runs]


def speed_point(run, text):
    """A run on the speed chart: wall time per simulated second against |dE| / E0 (%), at
    SMALLEST_CHANGE when below it; on the Nv line (y None) when it stopped."""
    y = max(abs(run["change"]), SMALLEST_CHANGE) if run["converged"] else None
    return Point(run["wall"] / run["T"], y, text)


def stability_status(run, gain, loss, chatter=False):
    """A run's cell in a stability map: "Nv" when it stopped, else the failures seen joined by
    '+' ("gain": the energy grew by more than `gain` % of E0; "dissipates": it fell by more than
    `loss` %; "chatter" when `chatter`), or "ok"."""
    if not run["converged"]:
        return "Nv"
    flags = []
    if run["change"] > gain:
        flags.append("gain")
    if run["change"] < -loss:
        flags.append("dissipates")
    if chatter:
        flags.append("chatter")
    return "+".join(flags) or "ok"


class Bar:
    """The closed form of a bar of length L, density rho, modulus E (nu = 0: E' = E in plane
    stress and strain), cross-section `width` (per metre of thickness), thrown at speed v along
    its axis onto a rigid wall: contact lasts 2 L / c (c = sqrt(E / rho)), the wall's impulse is
    2 m v (m = rho L width), the bar leaves at +v with all its energy 1/2 m v^2."""

    def __init__(self, length, width, rho, E, v):
        self.length, self.width, self.rho, self.E, self.v = length, width, rho, E, v
        self.c = math.sqrt(E / rho)
        self.mass = rho * length * width
        self.contact_time = 2 * length / self.c
        self.impulse = 2 * self.mass * v
        self.energy = 0.5 * self.mass * v * v

    @classmethod
    def of_deck(cls, deck):
        """The bar of a deck (MESH generator=rectangle along x2, lx the width, ly the length;
        MATERIAL E, rho; INITIAL v along x2)."""
        return cls(deck.number("MESH", "ly"), deck.number("MESH", "lx"),
                   deck.number("MATERIAL", "rho"), deck.number("MATERIAL", "E"),
                   math.hypot(*deck.numbers("INITIAL", "v")))

    def measures(self, rows):
        """A run (energy.csv rows) against the closed form: energy change (relative), contact
        steps (steps with an active node) and their time against 2 L / c (in steps), the wall's
        impulse k sum N (each step's momentum balance M (v_n - v_{n-1}) = k (N_n - K u_{n-1/2}),
        1^T K = 0) over 2 m v."""
        k = rows[1]["time"] - rows[0]["time"]
        active = [r for r in rows if r["active_nodes"] > 0]
        return {
            "k": k,
            "energy_change": (rows[-1]["total"] - rows[0]["total"]) / rows[0]["total"],
            "energy_excursion": max(abs(r["total"] - rows[0]["total"]) for r in rows)
            / rows[0]["total"],
            "contact_steps": len(active),
            "closed_form_steps": self.contact_time / k,
            "contact_time": len(active) * k,
            "impulse_ratio": k * sum(r["normal_force"] for r in rows) / self.impulse,
            "e0_ratio": rows[0]["total"] / self.energy,
            "penetration": max(r["max_penetration"] for r in rows),
            "left": rows[-1]["active_nodes"] == 0,
        }
