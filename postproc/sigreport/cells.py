"""Table cells: numbers, "ours (thesis)", runs that did not converge (Nv) or swayed, missing
values, and tolerance checks. Each function takes `missing`, the text of an absent value (the
default "—"; a report that always wrote "-" passes missing="-").

    fmt(0.0123449)                         # "0.01234"      fmt(None) -> "—"
    fmt_spec(0.0123449, "+.3f")            # "+0.012"       fmt_spec(nan) -> "n/a"
    pct(-0.0123)                           # "-1.23 %"
    run_cell(True, 59)                     # "59"
    run_cell(True, 208, sway=True)         # "208 sway"
    run_cell(False, 200, detail="step 12") # "Nv (step 12)"
    ours_thesis("59", "12")                # "59 (12)"      ours_thesis(None, "12") -> "— (12)"
    ours_thesis("1.52", "89", unit="s")    # "1.52 (89 s)"
    within(30, 29, abs=1)                  # True: |30 - 29| <= 1
    within(14.3, 14.49, rel=0.02)          # True: |14.3 - 14.49| <= 0.02 |14.49|
"""
import math

MISSING = "—"


def is_missing(x):
    return x is None or (isinstance(x, float) and math.isnan(x))


def fmt(x, digits=4, missing=MISSING):
    """`digits` significant digits (format 'g'), or `missing`."""
    return missing if is_missing(x) else f"{x:.{digits}g}"


def fmt_spec(x, spec=".3g", missing="n/a"):
    """x in a format spec ("+.3f", ".2f", ...), or `missing`."""
    return missing if is_missing(x) else format(x, spec)


def pct(x, missing=MISSING):
    """A ratio as a signed percentage with two decimals: -0.0123 -> "-1.23 %"."""
    return missing if is_missing(x) else f"{100 * x:+.2f} %"


def run_cell(converged, value, sway=False, detail=None, missing=MISSING):
    """The cell of one run: its value (an iteration count, a time) if it converged, "Nv" if it did
    not (with the detail in parentheses: the failing step, its iteration count), the value and
    "sway" when it converged to a state off the expected branch; `missing` when there is no run
    (converged None)."""
    if converged is None:
        return missing
    if not converged:
        return "Nv" + (f" ({detail})" if detail not in (None, "") else "")
    return str(value) + (" sway" if sway else "")


def ours_thesis(ours, thesis, unit="", missing=MISSING):
    """"ours (thesis)": either side `missing` when None; the unit after the thesis's value."""
    ours = missing if is_missing(ours) else str(ours)
    thesis = missing if is_missing(thesis) else str(thesis)
    return f"{ours} ({thesis}{' ' + unit if unit else ''})"


def within(ours, target, rel=None, abs=None):
    """|ours - target| <= abs + rel |target| (either tolerance may be left out); None when either
    value is missing (a check not run, not a failure)."""
    if is_missing(ours) or is_missing(target):
        return None
    if rel is None and abs is None:
        raise ValueError("within: give rel=, abs= or both")
    bound = (abs or 0.0) + (rel or 0.0) * math.fabs(target)
    return math.fabs(ours - target) <= bound


def tolerance_text(rel=None, abs=None):
    """"+-1", "2 %", "+-1 + 2 %": how a tolerance of `within` is shown in a checks table."""
    parts = []
    if abs is not None:
        parts.append(f"+-{abs:g}")
    if rel is not None:
        parts.append(f"{100 * rel:g} %")
    return " + ".join(parts)
