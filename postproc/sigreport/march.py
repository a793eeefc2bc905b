"""A march of sig-march (scenes 5 and 6): its folder's deck, case.hist through sig-dump and
error.json of sig-error; the scene reports derive their run classes from it.

    run = March(out / "fig52" / "P", "strip.dat", arrays=["converged", "k", ...])
    run.k, run.converged, run.failure, run.p       # step, converged, failure text, contact nodes
    run.rows("force_n")[n]                        # a per-contact-node array at step n
    run.step(0.5), run.steps_done()               # the step of a time; steps marched
    run.u(n)                                      # the displacement kept at step n (output_every)
    run.seconds()                                 # sig-march's setup and march
    run.error()                                   # error.json as a dict, None when absent
    read_error(folder, "error_interior.json")     # the same for any folder and file
"""
import json
from pathlib import Path

from .deck import read_deck
from .ds import read_ds
from .errors import ReportError


def read_error(folder, name="error.json"):
    """An error file of sig-error (error, relative, max_error, ...) as a dict; None when the
    run wrote none."""
    path = Path(folder) / name
    return json.loads(path.read_text()) if path.is_file() else None


class March:
    """One run folder of a march: `deck` (its datafile deck_name), `ds` (case.hist with
    `arrays`, a list or a function of the deck giving it), k, converged, failure, p (contact
    nodes) and weight (their nodal weights)."""

    def __init__(self, folder, deck_name, arrays):
        self.dir = Path(folder)
        hist = self.dir / "case.hist"
        if not hist.is_file():
            raise ReportError(f"{hist} is missing: the run failed (see its march.log)")
        self.deck = read_deck(self.dir / deck_name)
        self.ds = read_ds(hist, arrays=arrays(self.deck) if callable(arrays) else arrays)
        self.k = self.ds.scalar("k")
        self.converged = bool(self.ds.scalar("converged"))
        self.failure = self.ds.get("failure", "")
        self.p = len(self.ds["contact_node"])
        self.weight = self.ds.array("weight")
        self._states = None

    def rows(self, name):
        """A per-contact-node array of case.hist, one row per time level."""
        return self.ds.array(name).reshape(-1, self.p)

    def step(self, t):
        """The step of the time level nearest to t."""
        return int(round(t / self.k))

    def steps_done(self):
        return len(self.ds["newton_iterations"]) - 1

    def states(self):
        """The kept displacements (one row per kept state) and the steps they were kept at."""
        if self._states is None:
            ds = read_ds(self.dir / "case.hist", arrays=["u", "output_step"])
            self._states = (ds.array("u").reshape(len(ds["output_step"]), -1),
                            list(ds["output_step"]))
        return self._states

    def u(self, n):
        states, kept = self.states()
        if n not in kept:
            raise ReportError(f"{self.dir}: step {n} is not a kept state (output_every)")
        return states[kept.index(n)]

    def seconds(self):
        """sig-march's setup (frames, factorization, Schur complement, dense Cholesky) and march."""
        return self.ds.scalar("time_factorize") + self.ds.scalar("time_march")

    def error(self):
        return read_error(self.dir)
