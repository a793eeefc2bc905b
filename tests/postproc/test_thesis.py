"""sigreport.thesis: one schema, one file, lookup by (scene, item, key)."""
import pytest
from conftest import DATA

from sigreport import THESIS_CSV, ReportError, ThesisValues, load_thesis


def test_lookup_and_list_rows():
    t = ThesisValues.load(DATA / "thesis_small.csv")
    assert t.get("7a", "hertz_p0") == "14.49" and t.number("7a", "hertz_p0") == 14.49
    assert t.row("7a", "hertz_p0").unit == "GPa" and t.row("7a", "hertz_p0").where == "(7.38) computed"
    # A list row stands for one entry per part, and for itself.
    assert t.get("7b", "iterations_pdas", "N=128;gamma=1e2") == "13"
    assert t.get("7b", "iterations_pdas", "N=128;gamma=1e3") == "Nv"
    assert t.number("7b", "iterations_pdas", "N=128;gamma=1e3") is None  # Nv is not a number
    assert t.get("7b", "cpu_alm", "N=256") == "43" and t.row("7b", "cpu_alm", "N=256").unit == "s"
    assert t.get("7b", "cpu_alm", "N=128/256/512") == "1/43/160"
    # Keys that only look like lists are left whole.
    assert t.get("7a", "contact_nodes_by_iteration", "N=256;iterations 1/3/5/8") == "1/51/35/29"
    assert t.get("5", "reference_dofs", "h=k=1/256") == "784768"
    assert t.get("5", "reference_dofs", "h=k=1") is None
    assert t.keys("7b", "cpu_alm") == ["N=128/256/512", "N=128", "N=256", "N=512"]
    assert t.scene("7b").get("cpu_alm", "N=512") == "160"
    assert t.get("7a", "absent", default="—") == "—"
    with pytest.raises(ReportError, match="no thesis value scene=7a item=absent"):
        t.require("7a", "absent")


def test_schema_errors_name_the_line(tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("# scene,item,key,value,unit,where\n7a,hertz_p0,,14.49,GPa\n")
    with pytest.raises(ReportError, match=r"bad.csv:2: 5 columns, the schema has 6"):
        ThesisValues.load(path)


def test_the_project_file_holds_every_scene_in_the_schema():
    t = load_thesis()
    assert t.path == THESIS_CSV
    assert {r.scene for r in t.rows()} >= {"4", "5", "6", "7a", "7b", "8a", "8b"}
    assert t.get("7a", "iterations_projection", "N=256;c=1e4") == "8"
    assert t.get("7b", "iterations_pdas", "N=256;gamma=1e5") == "15"
    assert t.number("4", "convexification_iterations", "alpha=100;a=1;b=0.5") == 68
    assert t.row("8a", "penetration_error", "specific penalty").unit == "m"
