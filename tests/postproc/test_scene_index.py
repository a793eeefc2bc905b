"""postproc/scene_index.py: a thesis claim that an independent reference contradicts (an
erratum) is counted apart from the FAILs in the index pages and does not fail its scene; a FAIL
beside it still does, and the detail shows the erratum's reference and the FAIL's study."""
import json

import scene_index


def write_scene(out, name, checks):
    folder = out / name
    folder.mkdir(parents=True)
    (folder / "report.md").write_text(f"# {name}\n")
    entry = {"scene": name, "title": f"Scene {name}", "report": "report.md",
             "command": f"drivers/{name}.sh", "seconds": 2.0, "checks": checks,
             "key_table": None, "charts": {}, "pvd": []}
    (folder / "scene.json").write_text(json.dumps(entry))
    scene = scene_index.Scene(name)
    scene_index.load(out, scene)
    return scene


PASS = {"name": "balance", "pass": True, "detail": "1e-13"}
ERRATUM = {"name": "two-step 0.071 m", "pass": False, "detail": "ours 0.0184 m",
           "erratum": "closed form k v / 2 = 0.0167 m"}
STUDIED = {"name": "IPM + EMM 0.1 %", "pass": False, "detail": "ours 0.46 %",
           "study": "no reading of k, r, g"}


def test_erratum_counted_apart(tmp_path):
    settled = write_scene(tmp_path, "8b", [PASS, ERRATUM])
    assert settled.counts() == (1, 0, 1, 0)
    assert settled.ok and settled.verdict() == "PASS: 1/2 checks pass, 1 erratum"
    failing = write_scene(tmp_path, "8a", [PASS, ERRATUM, STUDIED])
    assert failing.counts() == (1, 1, 1, 0)
    assert not failing.ok and failing.verdict() == "FAIL: 1/3 checks pass, 1 erratum, 1 FAIL"
    # A scene of errata only is settled too; one of no settled check is not.
    assert write_scene(tmp_path, "x", [ERRATUM]).ok
    assert not write_scene(tmp_path, "y", [{"name": "s", "pass": None, "detail": ""}]).ok


def test_pages_name_the_reference_and_the_study(tmp_path):
    scenes = [write_scene(tmp_path, "8b", [PASS, ERRATUM]),
              write_scene(tmp_path, "8a", [PASS, STUDIED])]
    md = scene_index.markdown(tmp_path, scenes, "stamp")
    assert "1 of 2 scenes pass all their checks (1 erratum of the thesis: claims an" in md
    assert "| two-step 0.071 m | erratum | ours 0.0184 m; reference: closed form k v / 2 = " \
           "0.0167 m |" in md
    assert "| IPM + EMM 0.1 % | FAIL | ours 0.46 %; study: no reading of k, r, g |" in md
    page = scene_index.page(tmp_path, scenes, "stamp")
    assert '<span class="erratum">erratum</span>' in page
    assert '<span class="fail">FAIL</span>' in page and ".erratum {" in page
