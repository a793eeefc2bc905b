#!/usr/bin/env bash
# Requirement (issue 29): drivers/adapt.sh runs solve -> estimate -> mark -> refine on a static
# deck or a march, a folder per step with the chain's output and adapt.csv (step, dofs,
# estimate, error, effectivity). On the frictional block (datafiles/first/block.dat at nx = 8,
# Coulomb friction on Gamma3) for 3 steps against the deck at nx = 128 (finer everywhere than
# every adapted mesh: two refinements of nx = 8 make cells of 1/16 at the finest, the reference
# has 1/64):
#  - the dofs grow, the estimate and the error fall at every step, effectivity in [0.3, 3];
#  - every step's mesh keeps the references 1-4 and the bounding box of the first;
#  - --dofs stops the loop at the first step past the budget;
#  - sig-refine refuses a theta outside (0, 1] and a stale case.est;
#  - the loop runs in one process (sig-adapt) and writes what the chain writes: step 1's DS
#    files are those of drivers/chain.sh on step1.dat, times and dates left out; its wall clock
#    elapsed_s grows from step to step.
# On the Hertz half disc of scene 7a (N = 32, 2 steps): the refined arc's nodes lie on the
# circle of radius R (the generator's, not the chords'), the estimate falls, Gamma3 and the
# Dirichlet node survive. On a small march (scene 5's strip), one mesh for the whole march:
# refined where the indicator, the largest over the kept states, is.
set -euo pipefail
source tests/pipeline/lib/common.sh
require_stages mesh material contact assemble solve post estimate refine adapt error dump

sed -e 's/nx=16 ny=8/nx=8 ny=4/' datafiles/first/block.dat >"$work/block.dat"
sed -e 's/nx=16 ny=8/nx=128 ny=64/' datafiles/first/block.dat >"$work/reference.dat"
SIG_BIN=$bin drivers/chain.sh "$work/reference.dat" -o "$work/reference" >"$work/ref.log" 2>&1 ||
  { tail -20 "$work/ref.log"; die "the reference chain failed"; }
SIG_BIN=$bin drivers/adapt.sh "$work/block.dat" -o "$work/block" --steps 3 \
  --reference "$work/reference" >"$work/adapt.log" 2>&1 ||
  { tail -30 "$work/adapt.log"; die "adapt.sh failed on the block"; }
cat "$work/adapt.log"

checks=$((checks + 1))
"$python" - "$work/block/adapt.csv" <<'PY' || fail "adapt.csv of the block (above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
bad = []
if [r["step"] for r in rows] != ["0", "1", "2"]:
    bad.append(f"steps {[r['step'] for r in rows]}, not 0, 1, 2")
for a, b in zip(rows, rows[1:]):
    for key, grows in (("dofs", True), ("estimate", False), ("error", False)):
        if (float(b[key]) > float(a[key])) != grows:
            bad.append(f"step {b['step']}: {key} {a[key]} -> {b[key]}")
for r in rows:
    if not 0.3 <= float(r["effectivity"]) <= 3:
        bad.append(f"step {r['step']}: effectivity {r['effectivity']}")
for b in bad:
    print("FAIL:", b)
sys.exit(1 if bad else 0)
PY

# The references and the domain of every step's mesh: those of the first.
shape() { "$bin/sig-dump" "$1" | grep -E '^  (references|bounding box)' | sed -e 's/([^)]*)//g'; }
first=$(shape "$work/block/step0/case.nopo")
for k in 1 2; do
  checks=$((checks + 1))
  [ "$(shape "$work/block/step$k/case.nopo")" = "$first" ] ||
    fail "step $k: the mesh has $(shape "$work/block/step$k/case.nopo"), not $first"
  grep -q "^MESH file=step$((k - 1))/refined.nopo$" "$work/block/step$k.dat" ||
    fail "step $k: its deck does not read the refined mesh"
done

# One process, the chain's files: step 1 again by drivers/chain.sh, a process a stage.
SIG_BIN=$bin drivers/chain.sh "$work/block/step1.dat" -o "$work/chain1" >"$work/chain1.log" 2>&1 ||
  { tail -20 "$work/chain1.log"; die "chain.sh failed on step1.dat"; }
# sig-dump --json of a DS without its date and its arrays of times and provenance.
untimed() {
  "$bin/sig-dump" --json "$1" | "$python" -c 'import json, sys
d = json.load(sys.stdin)
d.pop("date", None)
d["arrays"] = [a for a in d["arrays"] if not any(w in a["name"] for w in
               ("time", "seconds", "wall", "provenance"))]
print(json.dumps(d, sort_keys=True))'
}
for ds in nopo mili cont tae b post; do
  checks=$((checks + 1))
  [ "$(untimed "$work/block/step1/case.$ds")" = "$(untimed "$work/chain1/case.$ds")" ] ||
    fail "step 1's case.$ds (sig-adapt) is not chain.sh's"
done
checks=$((checks + 1))
"$python" - "$work/block/adapt.csv" <<'PY' || fail "elapsed_s of the block's loop"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
elapsed = [float(r["elapsed_s"]) for r in rows]
walls = [float(r["wall_s"]) for r in rows]
bad = [f"step {k}: elapsed_s {e} below the step's wall_s {w}" for k, (e, w) in
       enumerate(zip(elapsed, walls)) if e < w]
bad += [f"elapsed_s {a} -> {b}" for a, b in zip(elapsed, elapsed[1:]) if not b > a]
print("\n".join("FAIL: " + b for b in bad))
sys.exit(1 if bad else 0)
PY

# A budget of 200 dofs: steps 0, 1, 2 have 90, 138, 260 dofs; the loop stops after step 2.
checks=$((checks + 1))
SIG_BIN=$bin drivers/adapt.sh "$work/block.dat" -o "$work/budget" --steps 5 --dofs 200 \
  >"$work/budget.log" 2>&1 || { cat "$work/budget.log"; die "adapt.sh --dofs failed"; }
[ "$(wc -l <"$work/budget/adapt.csv")" -eq 4 ] && grep -q "260 dofs reach the budget" "$work/budget.log" ||
  fail "--dofs 200 did not stop after step 2: $(cat "$work/budget/adapt.csv")"

# The Hertz half disc: the arc stays on the circle.
sed -e 's/N=256 grading=0.1/N=32/' datafiles/scene7a/hertz.dat >"$work/hertz.dat"
SIG_BIN=$bin drivers/adapt.sh "$work/hertz.dat" -o "$work/hertz" --steps 2 >"$work/hertz.log" 2>&1 ||
  { tail -30 "$work/hertz.log"; die "adapt.sh failed on the Hertz half disc"; }
cat "$work/hertz.log"
checks=$((checks + 2))
"$python" - "$work/hertz" <<'PY' || fail "the Hertz half disc's loop (above)"
import csv, math, sys
work = sys.argv[1]
rows = list(csv.DictReader(open(f"{work}/adapt.csv")))
bad = []
if not float(rows[1]["estimate"]) < float(rows[0]["estimate"]):
    bad.append(f"estimate {rows[0]['estimate']} -> {rows[1]['estimate']}")
contact = list(csv.DictReader(open(f"{work}/step1/contact.csv")))
before = list(csv.DictReader(open(f"{work}/step0/contact.csv")))
if not len(contact) > len(before):
    bad.append(f"Gamma3 has {len(contact)} nodes after refinement, {len(before)} before")
worst = max(abs(math.hypot(float(r["x1"]), float(r["x2"]) - 8) - 8) for r in contact)
print(f"Gamma3: {len(before)} -> {len(contact)} nodes, largest |distance to the centre - R| {worst:.2e}")
if worst > 1e-12 * 8:
    bad.append(f"a Gamma3 node {worst} off the circle")
for b in bad:
    print("FAIL:", b)
sys.exit(1 if bad else 0)
PY
shape_h=$(shape "$work/hertz/step0/case.nopo")
[ "$(shape "$work/hertz/step1/case.nopo" | grep references)" = "$(grep references <<<"$shape_h")" ] ||
  fail "the half disc's references changed: $(shape "$work/hertz/step1/case.nopo")"

# sig-refine's bad input: a theta outside (0, 1], indicators of a stale estimate.
checks=$((checks + 1))
message=$("$bin/sig-refine" "$work/block.dat" -o "$work/block/step0" --theta 2 2>&1) &&
  fail "sig-refine --theta 2 exited 0"
grep -qF -- "--theta 2: expected a number in (0, 1]" <<<"$message" || fail "--theta 2: $message"
sed -e 's/f=0.2,-1/f=0.2,-1.5/' "$work/block.dat" >"$work/stale.dat"
refused "a stale case.est" refine "$work/stale.dat" "$work/block/step0" "is stale" "TRACTION"

# A march (scene 5's strip at 8 x 2, k = 1/8, the states of t = 0, 0.25 ... 1 kept): one mesh for
# the whole march, 2 steps. case.est holds eta of each kept state and the last one as the
# estimate; step 1 cuts step 0's triangle of the largest indicator (the largest over the kept
# states), and the triangles it cuts carry larger indicators than those it keeps; a static
# solve's folder as the march's reference is refused.
sed -e 's/nx=64 ny=12/nx=8 ny=2/' -e 's/k=0.015625 output_every=1/k=0.125 output_every=2/' \
  -e 's/^OUTPUT .*/OUTPUT name=strip vtk=no/' datafiles/scene5/strip.dat >"$work/march.dat"
SIG_BIN=$bin drivers/adapt.sh "$work/march.dat" -o "$work/march" --steps 2 \
  >"$work/march.log" 2>&1 ||
  { tail -30 "$work/march.log"; die "adapt.sh failed on the march"; }
cat "$work/march.log"
checks=$((checks + 2))
SIG_BIN=$bin PYTHONPATH=postproc "$python" - "$work/march" <<'PY' || fail "the march's loop (above)"
import csv, sys
import numpy as np
from sigreport import Mesh, read_ds
work = sys.argv[1]
bad = []
rows = list(csv.DictReader(open(f"{work}/adapt.csv")))
if len(rows) != 2 or not int(rows[1]["dofs"]) > int(rows[0]["dofs"]):
    bad.append(f"adapt.csv: {rows}")
est = read_ds(f"{work}/step0/case.est", arrays=["indicator", "times", "estimates", "estimate",
                                                  "estimate_max"])
times, estimates = list(est.array("times")), list(est.array("estimates"))
if times != [0, 0.25, 0.5, 0.75, 1] or est.scalar("estimate") != estimates[-1] or \
        est.scalar("estimate_max") != max(estimates) or not estimates[-1] > estimates[1] > 0:
    bad.append(f"case.est: times {times}, estimates {estimates}, estimate {est.scalar('estimate')}")
eta = est.array("indicator")
coarse, fine = Mesh.read(f"{work}/step0/case.nopo"), Mesh.read(f"{work}/step1/case.nopo")


def areas(mesh):
    p = mesh.xy[mesh.tri]
    d1, d2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    return 0.5 * np.abs(d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0])


# A coarse triangle is cut when the fine triangles whose centroids lie in it are smaller.
fine_centroids, fine_areas = fine.xy[fine.tri].mean(axis=1), areas(fine)
cut = []
for t, (tri, area) in enumerate(zip(coarse.xy[coarse.tri], areas(coarse))):
    a, b, c = tri
    m = np.array([b - a, c - a]).T
    lam = np.linalg.solve(m, (fine_centroids - a).T).T
    inside = (lam >= -1e-12).all(axis=1) & (lam.sum(axis=1) <= 1 + 1e-12)
    cut.append(bool(fine_areas[inside].max() < area * (1 - 1e-9)))
cut = np.array(cut)
print(f"step 1 cuts {cut.sum()} of {len(cut)} triangles; mean indicator cut "
      f"{eta[cut].mean():.3e}, kept {eta[~cut].mean():.3e}")
if not cut[int(np.argmax(eta))]:
    bad.append("the triangle of the largest indicator is not cut")
if not (cut.any() and (~cut).any() and eta[cut].mean() > 2 * eta[~cut].mean()):
    bad.append("the cut triangles do not carry the larger indicators")
for b in bad:
    print("FAIL:", b)
sys.exit(1 if bad else 0)
PY
checks=$((checks + 1))
status=0
SIG_BIN=$bin drivers/adapt.sh "$work/march.dat" -o "$work/march_ref" --reference "$work/reference" \
  >"$work/march_ref.log" 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "holds no case.hist" "$work/march_ref.log" ||
  fail "a static reference for a march: exit $status, $(cat "$work/march_ref.log")"
finish "the block's, the half disc's and a march's adaptive loops, the budget: $checks checks"
