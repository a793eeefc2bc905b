"""sigreport.cells, .table, .checks: the "ours (thesis)" cells, markdown tables, PASS/FAIL."""
import math

import pytest

from sigreport import (Checks, Table, fmt, markdown_table, ours_thesis, pct, run_cell,
                       tolerance_text, within)


def test_cells():
    assert run_cell(True, 59) == "59" and run_cell(True, 208, sway=True) == "208 sway"
    assert run_cell(False, 200, detail="step 12") == "Nv (step 12)" and run_cell(False, 3) == "Nv"
    assert run_cell(None, 3) == "—" and run_cell(None, 3, missing="-") == "-"
    assert ours_thesis("59", "12") == "59 (12)" and ours_thesis(None, "12") == "— (12)"
    assert ours_thesis("Nv", None, missing="-") == "Nv (-)"
    assert ours_thesis("1.52", "89", unit="s") == "1.52 (89 s)"
    assert fmt(0.0123449) == "0.01234" and fmt(None) == "—" and fmt(math.nan) == "—"
    assert fmt(2.0, 3) == "2" and pct(-0.0123) == "-1.23 %" and pct(None) == "—"


def test_tolerances():
    assert within(30, 29, abs=1) and not within(31, 29, abs=1)
    assert within(14.3, 14.49, rel=0.02) and not within(14.1, 14.49, rel=0.02)
    assert within(1.09, 1.0, abs=0.05, rel=0.05) and not within(1.11, 1.0, abs=0.05, rel=0.05)
    assert within(None, 1, abs=1) is None and within(math.nan, 1, abs=1) is None
    assert tolerance_text(abs=1) == "+-1" and tolerance_text(rel=0.02) == "2 %"


def test_markdown_table_and_key_table():
    t = Table(["N", "c = 1"], [[128, "12 (11)"]], caption="Table 7.1")
    t.add(256, "Nv (11)")
    assert t.markdown() == "| N | c = 1 |\n|---|---|\n| 128 | 12 (11) |\n| 256 | Nv (11) |"
    assert markdown_table(["a"], []) == "| a |\n|---|"
    assert t.as_json() == {"caption": "Table 7.1", "header": ["N", "c = 1"],
                           "rows": [["128", "12 (11)"], ["256", "Nv (11)"]]}


def test_checks_collected_once():
    checks = Checks()
    checks.add("contact nodes", within(30, 29, abs=1), ours=30, target=29, tolerance="+-1")
    checks.add("p_max", within(15.0, 14.49, rel=0.02), ours="15.0", target="14.49",
               tolerance="2 %")
    checks.add("slope", None, detail="fewer than two meshes")
    assert (checks.passed, checks.failed, checks.not_run) == (1, 1, 1)
    assert checks.summary() == "1 PASS, 1 FAIL, 1 not run" and not checks.ok
    assert checks.table().markdown().split("\n") == [
        "| check | ours | target | tolerance | result |", "|---|---|---|---|---|",
        "| contact nodes | 30 | 29 | +-1 | PASS |", "| p_max | 15.0 | 14.49 | 2 % | FAIL |",
        "| slope | — | — | — | not run |"]
    assert checks.table(("name", "detail", "result"), header=("requirement", "why", "result")) \
        .markdown().split("\n")[-1] == "| slope | fewer than two meshes | not run |"
    assert checks.as_json() == [
        {"name": "contact nodes", "pass": True, "detail": "ours 30, target 29, tolerance +-1"},
        {"name": "p_max", "pass": False, "detail": "ours 15.0, target 14.49, tolerance 2 %"},
        {"name": "slope", "pass": None, "detail": "fewer than two meshes"}]


def test_erratum_is_an_outcome_apart():
    """A thesis claim we do not reproduce and an independent reference contradicts is an
    erratum, named with the reference and its number; without a reference it stays a FAIL, with
    its study beside it."""
    checks = Checks()
    checks.add("free flight exact", True, ours="1e-13")
    checks.add("two-step penetration 0.071 m", False, ours="0.0184 m",
               erratum="closed form k v / 2 = 0.0167 m")
    checks.add("IPM + EMM loses 0.1 %", False, ours="0.46 %",
               study="no reading of k, r, g gives it")
    assert (checks.passed, checks.failed, checks.errata, checks.not_run) == (1, 1, 1, 0)
    assert checks.summary() == "1 PASS, 1 erratum, 1 FAIL" and not checks.ok
    assert [c.result for c in checks] == ["PASS", "erratum", "FAIL"]
    assert checks.table(("name", "result", "basis")).markdown().split("\n") == [
        "| check | result | reference (erratum) or study (FAIL) |", "|---|---|---|",
        "| free flight exact | PASS | — |",
        "| two-step penetration 0.071 m | erratum | reference: closed form k v / 2 = 0.0167 m |",
        "| IPM + EMM loses 0.1 % | FAIL | study: no reading of k, r, g gives it |"]
    assert checks.as_json()[1:] == [
        {"name": "two-step penetration 0.071 m", "pass": False, "detail": "ours 0.0184 m",
         "erratum": "closed form k v / 2 = 0.0167 m"},
        {"name": "IPM + EMM loses 0.1 %", "pass": False, "detail": "ours 0.46 %",
         "study": "no reading of k, r, g gives it"}]
    # Errata and passes settle a scene; a FAIL does not.
    settled = Checks()
    settled.add("a", True)
    settled.add("b", False, erratum="GetFEM: 1.23")
    assert settled.ok and settled.summary() == "1 PASS, 1 erratum, 0 FAIL"


def test_erratum_needs_a_failed_claim():
    with pytest.raises(ValueError, match="needs a failed claim"):
        Checks().add("passes", True, erratum="closed form: 2")
    with pytest.raises(ValueError, match="needs a failed claim"):
        Checks().add("not run", None, erratum="closed form: 2")
    with pytest.raises(ValueError, match="not both"):
        Checks().add("both", False, erratum="closed form: 2", study="a table")
