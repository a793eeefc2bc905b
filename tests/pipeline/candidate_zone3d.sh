#!/usr/bin/env bash
# Requirement (issue 26: "condense only the candidates that can touch, re-factorize when the zone
# outgrows them"): SOLVER candidate_gap= condenses only the contact nodes of small initial gap. On
# a coarse half ball pressed on a rigid plane, frictionless, the solve with a zone the contact
# outgrows widens it and starts again (said in the log), and ends at the solution of the solve
# that condenses every node: the same statuses, nodal forces to 1e-9 of the largest, the
# displacement to 1e-9 of the largest; a zone that holds the contact at once takes one solve.
# candidate_gap= is refused, naming the field, in a large-deformation deck and with a law that
# acts on nodes apart from the obstacle (there the nodes outside the zone would lose their force).
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_command gmsh "the half ball generator meshes through gmsh"

cat >"$work/all.dat" <<'DECK'
# A coarse half ball (R = 8, E = 150, nu = 0.3, GPa-m) pressed on the plane x3 = 0 by a traction
# of 3 on its flat top, held there in x1 and x2: a contact radius of about 3.
TITLE half ball, every contact node condensed
MESH generator=half_ball r=8 h=1
MATERIAL law=hooke E=150 nu=0.3
DIRICHLET ref=2 ux=0 uy=0
TRACTION ref=2 f=0,0,-3
CONTACT ref=3 obstacle=plane point=0,0,0 normal=0,0,1 law=signorini exclude=2
SOLVER method=pdas
OUTPUT vtk=no
DECK
sed 's/^SOLVER method=pdas$/SOLVER method=pdas candidate_gap=0.001/' "$work/all.dat" >"$work/small.dat"
sed 's/^SOLVER method=pdas$/SOLVER method=pdas candidate_gap=2/' "$work/all.dat" >"$work/wide.dat"
for case in all small wide; do
  "$root/drivers/chain.sh" "$work/$case.dat" -o "$work/$case" >"$work/$case.log" 2>&1 ||
    { tail -20 "$work/$case.log"; die "drivers/chain.sh $case.dat failed"; }
done
checks=$((checks + 1))
grep -q "the zone widens and the solve restarts" "$work/small.log" ||
  fail "the small zone did not widen: $(grep -m1 'contact zone' "$work/small.log")"
checks=$((checks + 1))
grep -q "condensed, 1 solve," "$work/wide.log" ||
  fail "the wide zone took more than one solve: $(grep 'contact zone' "$work/wide.log")"

for case in small wide; do
  checks=$((checks + 1))
  "$python" - "$work/all" "$work/$case" "$bin" <<'PY' || fail "the $case zone's solution"
import csv, json, subprocess, sys
whole, part, bindir = sys.argv[1], sys.argv[2], sys.argv[3]
def rows(d):
    return {r["node"]: r for r in csv.DictReader(open(f"{d}/contact.csv"))}
def u(d):
    out = subprocess.run([f"{bindir}/sig-dump", "--json", "--values=u", f"{d}/case.b"],
                         capture_output=True, text=True, check=True).stdout
    return {a["name"]: a["values"] for a in json.loads(out)["arrays"] if "values" in a}["u"]
a, b = rows(whole), rows(part)
problems = []
if a.keys() != b.keys():
    problems.append("different contact nodes")
active = sum(r["status"] == "contact" for r in a.values())
if any(a[k]["status"] != b[k]["status"] for k in a):
    problems.append("statuses differ")
largest = max(float(r["multiplier"]) for r in a.values())
force = max(abs(float(a[k]["multiplier"]) - float(b[k]["multiplier"])) for k in a)
if force > 1e-9 * largest:
    problems.append(f"nodal forces differ by {force:.3g} of {largest:.3g}")
ua, ub = u(whole), u(part)
reach = max(abs(x) for x in ua)
gap = max(abs(x - y) for x, y in zip(ua, ub))
if gap > 1e-9 * reach:
    problems.append(f"displacements differ by {gap:.3g} of {reach:.3g}")
if any(r["converged"] != "1" for r in b.values()):
    problems.append("not converged")
for p in problems:
    print(p)
print(f"{part}: {active} nodes in contact, forces within {force / largest:.2g}, u within "
      f"{gap / reach:.2g}")
sys.exit(1 if problems else 0)
PY
done

# Where it has no meaning, refused naming the field: a large-deformation solve, and laws that act
# on nodes apart from the obstacle (Tresca's threshold, the bilateral springs), on the 2D half disc.
half_disc() { # NAME MATERIAL-LINE CONTACT-EXTRA FRICTION-LINE
  cat >"$work/$1.dat" <<DECK
TITLE half disc, candidate_gap= with $1
MESH generator=half-disc R=8 N=16
$2
DIRICHLET ref=1 ux=0
TRACTION ref=2 f=0,-2
CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 $3
$4
SOLVER method=pdas candidate_gap=0.01
OUTPUT vtk=no
DECK
  checks=$((checks + 1))
  if "$root/drivers/chain.sh" "$work/$1.dat" -o "$work/$1" >"$work/$1.log" 2>&1; then
    fail "candidate_gap= with $1 was accepted"
  elif ! grep -q "field 'candidate_gap'" "$work/$1.log"; then
    fail "the refusal of candidate_gap= with $1: $(grep -m1 -i error "$work/$1.log")"
  fi
}
half_disc svk "MATERIAL law=svk E=150 nu=0.3 plane=strain" "law=signorini" ""
half_disc tresca "MATERIAL law=hooke E=150 nu=0.3 plane=strain" "law=signorini" \
  "FRICTION ref=3 law=tresca threshold=1"
half_disc bilateral "MATERIAL law=hooke E=150 nu=0.3 plane=strain" \
  "law=compliance-bilateral cn=100" ""
finish "SOLVER candidate_gap= condenses a zone that widens until it holds the contact"
