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
