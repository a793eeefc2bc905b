"""Two DS files of one march (case.hist) or solve (case.b) hold the same answers: every array of
the reference in the other, its integers (steps, statuses, Newton and outer counts) identical, its
reals within `tolerance` of the array's largest magnitude; the wall times, the processes (ranks)
and the provenance (paths) may differ. Through sig-dump --json --values.

    same_history.py SIG_BIN REFERENCE OTHER [TOLERANCE]   prints each array's worst difference
"""
import json
import subprocess
import sys

# Arrays that say how or where the run went, not what it found. MUMPS's `ordering` is compared:
# one process and the ranks give it the same order (METIS's, gathered on the host, on 3D rows).
SKIPPED = ("ranks", "provenance", "date")


def arrays(bin_dir, path):
    out = subprocess.run([f"{bin_dir}/sig-dump", "--json", "--values", path],
                         capture_output=True, text=True, check=True).stdout
    return {a["name"]: a for a in json.loads(out)["arrays"]}


def differences(bin_dir, reference, other, tolerance=1e-8):
    """[(name, relative worst difference or None for identical integers/text, ok)]."""
    ref, oth = arrays(bin_dir, reference), arrays(bin_dir, other)
    rows = []
    for name, a in ref.items():
        if name in SKIPPED or name.startswith("time_") or name.startswith("step_seconds"):
            continue
        b = oth.get(name)
        if b is None or b.get("shape") != a.get("shape"):
            rows.append((name, None, False))
            continue
        x, y = a.get("values"), b.get("values")
        if a["type"] != "float64":
            rows.append((name, None, x == y))
            continue
        scale = max((abs(v) for v in x), default=0.0)
        worst = max((abs(u - v) for u, v in zip(x, y)), default=0.0)
        relative = worst / scale if scale > 0 else worst
        rows.append((name, relative, relative <= tolerance))
    return rows


if __name__ == "__main__":
    bin_dir, reference, other = sys.argv[1:4]
    tolerance = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-8
    bad = 0
    for name, relative, ok in differences(bin_dir, reference, other, tolerance):
        what = "identical" if relative is None else f"{relative:.1e} of its largest value"
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {what if ok or relative is not None else 'differs'}")
        bad += not ok
    sys.exit(1 if bad else 0)
