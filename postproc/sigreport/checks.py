"""Checks, collected once per report: the report's checks section and the `checks` of the scene
index entry (scene.json) come from the same list.

    checks = Checks()
    checks.add("contact nodes, N = 256", within(30, 29, abs=1), ours=30, target=29,
               tolerance="+-1")
    checks.add("slope", None, detail="fewer than two meshes")   # None: not run
    checks.add("two-step penetration 0.071 m (p.234)", False, ours="0.0184 m",
               erratum="closed form k v / 2 = 0.0167 m")        # the thesis's claim is wrong
    checks.add("IPM + EMM loses 0.1 %", False, ours="0.46 %",
               study="no reading of k, r, g gives 0.1 % (study table)")  # FAIL, studied
    checks.passed, checks.failed, checks.errata, checks.not_run     # counts
    checks.table().markdown()    # | check | ours | target | tolerance | result |
    checks.table(("name", "ours", "result", "basis"))   # basis: the erratum's reference or the
                                                        # FAIL's study
    checks.as_json()             # [{"name": ..., "pass": true | false | null, "detail": ...}]

Outcomes: PASS; FAIL; `erratum`, a thesis claim our runs do not reproduce and an independent
reference (a closed form, a published result, GetFEM) contradicts too, the reference named with
the number it gives; `not run` (its run is missing). Without an independent reference a claim not
reproduced stays a FAIL, with the study that could not settle it beside it. In JSON an erratum is
`"pass": false` (the claim fails) with `"erratum": "<reference and its number>"`, which the index
counts apart from the FAILs; a FAIL's study is `"study": "..."`. A FAIL is reported as measured,
never tuned away.
"""
from .table import Table

ERRATUM = "erratum"


class Check:
    """One check: name, passed (True, False, None = not run), detail, the cells ours, target,
    tolerance its table row shows, and for a failed claim its erratum (the independent reference
    and the number it gives) or its study."""

    def __init__(self, name, passed, detail="", ours=None, target=None, tolerance=None,
                 erratum=None, study=None):
        self.name = name
        self.passed = None if passed is None else bool(passed)
        self.detail, self.ours, self.target, self.tolerance = detail, ours, target, tolerance
        if erratum and study:
            raise ValueError(f"check '{name}': an erratum or a study, not both")
        if erratum and self.passed is not False:
            # An erratum names why a claim we do not reproduce is wrong; a claim that passes or
            # was not run has none.
            raise ValueError(f"check '{name}': an erratum needs a failed claim (passed={passed})")
        self.erratum = erratum or None
        self.study = study or None

    @property
    def is_erratum(self):
        return self.erratum is not None

    @property
    def result(self):
        """"PASS", "FAIL", "erratum" or "not run"."""
        if self.passed is None:
            return "not run"
        if self.passed:
            return "PASS"
        return ERRATUM if self.is_erratum else "FAIL"

    @property
    def basis(self):
        """What settles a claim not reproduced: "reference: ..." for an erratum, "study: ..."
        for a studied FAIL; None otherwise."""
        if self.is_erratum:
            return f"reference: {self.erratum}"
        return f"study: {self.study}" if self.study else None

    def cell(self, column, missing="—"):
        value = getattr(self, column)
        return missing if value is None else value

    def as_json(self):
        detail = self.detail
        if not detail:
            detail = ", ".join(f"{k} {v}" for k, v in (("ours", self.ours), ("target", self.target),
                                                        ("tolerance", self.tolerance))
                               if v is not None)
        entry = {"name": str(self.name), "pass": self.passed, "detail": str(detail)}
        if self.is_erratum:
            entry["erratum"] = str(self.erratum)
        elif self.study:
            entry["study"] = str(self.study)
        return entry


class Checks:
    """An ordered list of Check."""

    def __init__(self):
        self.items = []

    def add(self, name, passed, detail="", ours=None, target=None, tolerance=None, erratum=None,
            study=None):
        check = Check(name, passed, detail, ours, target, tolerance, erratum, study)
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
        """FAILs only: an erratum is counted apart."""
        return sum(c.passed is False and not c.is_erratum for c in self.items)

    @property
    def errata(self):
        return sum(c.is_erratum for c in self.items)

    @property
    def not_run(self):
        return sum(c.passed is None for c in self.items)

    @property
    def ok(self):
        """No FAIL, and at least one check settled (a PASS or an erratum)."""
        return self.failed == 0 and self.passed + self.errata > 0

    def summary(self):
        """"12 PASS, 1 FAIL" (", 2 erratum" and ", 2 not run" when there are some)."""
        text = f"{self.passed} PASS"
        if self.errata:
            text += f", {self.errata} {ERRATUM}"
        text += f", {self.failed} FAIL"
        return text + (f", {self.not_run} not run" if self.not_run else "")

    def table(self, columns=("name", "ours", "target", "tolerance", "result"), header=None,
              missing="—"):
        """A Table with one row per check; `columns` are Check attributes (name, ours, target,
        tolerance, detail, result, basis)."""
        names = {"name": "check", "basis": "reference (erratum) or study (FAIL)"}
        header = header or [names.get(c, c) for c in columns]
        return Table(header, [[c.cell(col, missing) for col in columns] for c in self.items])

    def claims_section(self, heading, preface, sources):
        """The Markdown lines of a report's section on the thesis's claims: `heading`, `preface`
        (may be empty) and the rule that sorts a claim not reproduced into erratum or FAIL, one
        row per claim with what settles it, then the summary and `sources` (where the values
        come from)."""
        rule = ("A claim not reproduced is an *erratum* when an independent reference (a closed "
                "form, a published result, GetFEM) contradicts it too, and a FAIL with the study "
                "beside it otherwise.")
        lines = [heading, "", (preface + " " if preface else "") + rule, ""]
        lines += self.table(("name", "ours", "result", "basis"),
                            header=("requirement", "measured", "result",
                                    "reference (erratum) or study (FAIL)")).lines()
        return lines + ["", f"{self.summary()}. {sources}", ""]

    def as_json(self):
        return [c.as_json() for c in self.items]
