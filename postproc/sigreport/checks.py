"""PASS/FAIL checks, collected once per report: the report's checks section and the `checks` of
the scene index entry (scene.json) come from the same list.

    checks = Checks()
    checks.add("contact nodes, N = 256", within(30, 29, abs=1), ours=30, target=29,
               tolerance="+-1")
    checks.add("slope", None, detail="fewer than two meshes")   # None: not run
    checks.passed, checks.failed, checks.not_run                # counts
    checks.table().markdown()    # | check | ours | target | tolerance | result |
    checks.table(("name", "ours", "result"), header=("requirement", "measured", "result"))
    checks.as_json()             # [{"name": ..., "pass": true | false | null, "detail": ...}]

`pass` is null for a check that could not be evaluated (its run is missing): neither a PASS nor a
FAIL. A FAIL is reported as measured, never tuned away.
"""
from .table import Table


class Check:
    """One check: name, passed (True, False, None = not run), detail, and the cells ours,
    target, tolerance its table row shows."""

    def __init__(self, name, passed, detail="", ours=None, target=None, tolerance=None):
        self.name = name
        self.passed = None if passed is None else bool(passed)
        self.detail, self.ours, self.target, self.tolerance = detail, ours, target, tolerance

    @property
    def result(self):
        """"PASS", "FAIL" or "not run"."""
        return "not run" if self.passed is None else "PASS" if self.passed else "FAIL"

    def cell(self, column, missing="—"):
        value = getattr(self, column)
        return missing if value is None else value

    def as_json(self):
        detail = self.detail
        if not detail:
            detail = ", ".join(f"{k} {v}" for k, v in (("ours", self.ours), ("target", self.target),
                                                        ("tolerance", self.tolerance))
                               if v is not None)
        return {"name": str(self.name), "pass": self.passed, "detail": str(detail)}


class Checks:
    """An ordered list of Check."""

    def __init__(self):
        self.items = []

    def add(self, name, passed, detail="", ours=None, target=None, tolerance=None):
        check = Check(name, passed, detail, ours, target, tolerance)
        self.items.append(check)
        return check

    def __iter__(self):
        return iter(self.items)

    def __len__(self):
        return len(self.items)

    @property
    def passed(self):
        return sum(c.passed is True for c in self.items)

    @property
    def failed(self):
        return sum(c.passed is False for c in self.items)

    @property
    def not_run(self):
        return sum(c.passed is None for c in self.items)

    @property
    def ok(self):
        """Every check evaluated passed (and at least one was evaluated)."""
        return self.failed == 0 and self.passed > 0

    def summary(self):
        """"12 PASS, 1 FAIL" (", 2 not run" when some were not)."""
        text = f"{self.passed} PASS, {self.failed} FAIL"
        return text + (f", {self.not_run} not run" if self.not_run else "")

    def table(self, columns=("name", "ours", "target", "tolerance", "result"), header=None,
              missing="—"):
        """A Table with one row per check; `columns` are Check attributes (name, ours, target,
        tolerance, detail, result)."""
        header = header or ["check" if c == "name" else c for c in columns]
        return Table(header, [[c.cell(col, missing) for col in columns] for c in self.items])

    def as_json(self):
        return [c.as_json() for c in self.items]
