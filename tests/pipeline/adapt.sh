#!/usr/bin/env bash
# Requirement (issue 29): drivers/adapt.sh runs solve -> estimate -> mark -> refine on a static
# deck, a folder per step with the chain's output and adapt.csv (step, dofs, estimate, error,
# effectivity). On the frictional block (datafiles/first/block.dat at nx = 8, Coulomb friction
# on Gamma3) for 3 steps against the deck at nx = 128 (finer everywhere than every adapted mesh:
# two refinements of nx = 8 make cells of 1/16 at the finest, the reference has 1/64):
#  - the dofs grow, the estimate and the error fall at every step, effectivity in [0.3, 3];
#  - every step's mesh keeps the references 1-4 and the bounding box of the first;
#  - --dofs stops the loop at the first step past the budget;
#  - sig-refine refuses a theta outside (0, 1] and a stale case.est.
# On the Hertz half disc of scene 7a (N = 32, 2 steps): the refined arc's nodes lie on the
# circle of radius R (the generator's, not the chords'), the estimate falls, Gamma3 and the
# Dirichlet node survive. A march (TIME card) is refused.
set -euo pipefail
source tests/pipeline/lib/common.sh
require_stages mesh material contact assemble solve post estimate refine error dump

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

cp "$work/block.dat" "$work/march.dat"
echo "TIME scheme=midpoint T=1 k=0.1" >>"$work/march.dat"
checks=$((checks + 1))
status=0
SIG_BIN=$bin drivers/adapt.sh "$work/march.dat" -o "$work/march" >"$work/march.log" 2>&1 || status=$?
[ "$status" -ne 0 ] && grep -q "static decks only" "$work/march.log" ||
  fail "a march: exit $status, $(cat "$work/march.log")"
finish "the block's and the half disc's adaptive loops, the budget, a march refused: $checks checks"
