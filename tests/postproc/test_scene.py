"""sigreport.scene on the canned result tree: command.txt, summary.json, CSV columns, solve
seconds, and the scene index entry scene.json of PROTOCOL.md section 6."""
import json

import pytest

from sigreport import (Checks, ReportError, Table, find_pvd, read_command, read_csv_columns,
                       read_summary, solve_seconds, write_scene_json)


def test_reads_the_canned_runs(scene):
    info = read_command(scene, required=("command", "meshes"))
    assert info["command"] == "drivers/scene7a.sh --quick -o tests/postproc/data/scene"
    assert info["date"] == "2026-12-02T05:50:00Z"  # only the first ':' splits
    with pytest.raises(ReportError, match="no 'sizes:' line"):
        read_command(scene, required=("sizes",))
    pdas = read_summary(scene / "N16/pdas_1e2", required=("converged", "times"))
    nv = read_summary(scene / "N16/projection_1")
    assert pdas["converged"] and not nv["converged"] and nv["iterations"] == 3
    with pytest.raises(ReportError, match="no key 'hertz_missing'"):
        read_summary(scene / "N16/pdas_1e2", required=("hertz_missing",))
    times = pdas["times"]
    # A solve time is every phase of sig-solve, not sig-assemble's `assemble`.
    assert solve_seconds(pdas) == pytest.approx(sum(v for k, v in times.items() if k != "assemble"))
    assert solve_seconds(pdas, ("solve",)) == times["solve"]
    c = read_csv_columns(scene / "N16/pdas_1e2/contact.csv")
    assert len(c["x1"]) == 17 and c["x1"].dtype.kind == "f"
    assert set(c["status"]) <= {"contact", "free"} and c["friction_status"].dtype.kind == "U"
    # The nodal forces balance the load 2 R f = 32 of the half disc (sum of multipliers).
    assert c["multiplier"].sum() == pytest.approx(32, rel=1e-6)
    assert find_pvd(scene) == ["N16/pdas_1e2/hertz.pvd", "N16/projection_1/hertz.pvd"]


def test_scene_json_is_the_protocol_entry(scene):
    (scene / "report.md").write_text("# report\n")
    (scene / "speed_accuracy.png").write_bytes(b"\x89PNG")
    checks = Checks()
    checks.add("pdas converges", True, detail="3 iterations")
    checks.add("projection c = 1 converges", False, detail="Nv")
    checks.add("slope", None, detail="one mesh")
    table = Table(["N", "pdas"], [[16, "3 (7)"]], caption="iterations, ours (thesis)")
    path = write_scene_json(scene, "7a", "Scene 7a", read_command(scene), checks,
                            key_table=table, charts={"speed_accuracy": "speed_accuracy.png"})
    entry = json.loads(path.read_text())
    assert list(entry) == ["scene", "title", "report", "command", "seconds", "checks",
                           "key_table", "charts", "pvd"]
    assert entry["scene"] == "7a" and entry["report"] == "report.md"
    assert entry["command"].startswith("drivers/scene7a.sh") and entry["seconds"] == 1.5
    assert entry["checks"][1] == {"name": "projection c = 1 converges", "pass": False,
                                  "detail": "Nv"}
    assert entry["checks"][2]["pass"] is None
    assert entry["key_table"] == {"caption": "iterations, ours (thesis)", "header": ["N", "pdas"],
                                  "rows": [["16", "3 (7)"]]}
    assert entry["charts"] == {"speed_accuracy": "speed_accuracy.png"}
    assert entry["pvd"] == ["N16/pdas_1e2/hertz.pvd", "N16/projection_1/hertz.pvd"]


def test_scene_json_refuses_paths_it_did_not_write(scene):
    (scene / "report.md").write_text("# report\n")
    with pytest.raises(ReportError, match="'stability.png', which is not a file"):
        write_scene_json(scene, "7a", "t", "cmd", charts={"stability": "stability.png"})
    with pytest.raises(ReportError, match="which is not a file"):
        write_scene_json(scene, "7a", "t", "cmd", pvd=[str(scene / "N16/pdas_1e2/hertz.pvd")])
    with pytest.raises(ReportError, match="a check is"):
        write_scene_json(scene, "7a", "t", "cmd", checks=[{"name": "x", "pass": "yes",
                                                          "detail": ""}])
    assert not (scene / "scene.json").exists()


def test_scene_json_keeps_errata_and_studies(scene):
    (scene / "report.md").write_text("# report\n")
    checks = Checks()
    checks.add("two-step penetration 0.071 m", False, ours="0.0184 m",
               erratum="closed form k v / 2 = 0.0167 m")
    checks.add("IPM + EMM loses 0.1 %", False, ours="0.46 %", study="k and mesh table")
    entry = json.loads(write_scene_json(scene, "8b", "t", "cmd", checks, pvd=[]).read_text())
    assert entry["checks"] == [
        {"name": "two-step penetration 0.071 m", "pass": False, "detail": "ours 0.0184 m",
         "erratum": "closed form k v / 2 = 0.0167 m"},
        {"name": "IPM + EMM loses 0.1 %", "pass": False, "detail": "ours 0.46 %",
         "study": "k and mesh table"}]
    # An erratum of a passing check, an empty reference, or an unknown key is refused.
    for bad in ({"name": "x", "pass": True, "detail": "", "erratum": "closed form: 1"},
                {"name": "x", "pass": False, "detail": "", "erratum": ""},
                {"name": "x", "pass": False, "detail": "", "erratum": "a", "study": "b"},
                {"name": "x", "pass": False, "detail": "", "why": "a"}):
        with pytest.raises(ReportError, match="a check is"):
            write_scene_json(scene, "8b", "t", "cmd", checks=[bad], pvd=[])
