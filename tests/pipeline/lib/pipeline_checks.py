"""The checks of a pipeline test's Python part (tests/pipeline/lib/common.sh puts this folder on
PYTHONPATH): each printed as an ok or FAIL line, the failures kept for the exit status."""
import sys

failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


def finish(name):
    """Exit 1 naming how many checks failed, or return."""
    if failures:
        sys.exit(f"{name}: {len(failures)} check(s) failed")


def check_scene_index(out, scene, at_least, allowed=lambda check_: False):
    """A scene's out/<scene>/scene.json: its number, no report check failed (unless `allowed`
    says the check is measured elsewhere), at least `at_least` passed, every file it names
    written. Returns the parsed index."""
    import json

    index = json.loads((out / "scene.json").read_text())
    check(index["scene"] == scene, f"scene.json is scene {scene}")
    for c in index["checks"]:
        if not allowed(c):
            check(c["pass"] is not False, f"report check: {c['name']} ({c['detail']})")
    check(sum(c["pass"] is True for c in index["checks"]) >= at_least,
          f"at least {at_least} checks evaluated and passed")
    for name in [index["report"]] + list(index["charts"].values()) + index["pvd"]:
        check((out / name).is_file(), f"scene.json names {name}, which exists")
    return index


def getfem_nodes_against(ours, getfem_json):
    """Our contact.csv rows (csv.DictReader rows) beside the nodes of postproc/getfem_hertz3d.py's
    JSON table, paired by their coordinates (to 1e-9): (pairs [(row, node)], problems, GetFEM's
    table by coordinates, its largest normal force). A problem: GetFEM or ours not converged, one
    of our nodes not in GetFEM's table."""
    import json
    g = json.load(open(getfem_json))
    if not g["converged"]:
        sys.exit("GetFEM did not converge")
    key = lambda x, y, z: (round(x, 9), round(y, 9), round(z, 9))
    step = g["steps"][0]
    theirs = {key(n["x"], n["y"], n["z"]): n for n in step.get("nodes", g.get("nodes", []))}
    largest = max(n["normal_force"] for n in theirs.values())
    pairs, problems = [], []
    for r in ours:
        if r["converged"] != "1":
            problems.append("ours did not converge")
            break
        n = theirs.get(key(float(r["x1"]), float(r["x2"]), float(r["x3"])))
        if n is None:
            problems.append(f"node {r['node']} ({r['x1']}, {r['x2']}, {r['x3']}) not in GetFEM's "
                            "table")
            continue
        pairs.append((r, n))
    return pairs, problems, theirs, largest
