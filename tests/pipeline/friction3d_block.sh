#!/usr/bin/env bash
# Requirement (issue 26, friction in 3D): datafiles/scene3d/block_friction.dat, a block of P1
# tetrahedra pressed by p on a rigid plane and pulled by a tangential traction q along the oblique
# direction (0.6, 0.8), held by contact and friction alone, nu = 0 so that the pressure does not
# spread it:
#  - Coulomb mu = 0.5 (q / p = 0.1), every method: every base node sticks, the nodal tangential
#    forces (global axes, contact.csv) sum to q x area along (0.6, 0.8), the normal ones to
#    p x area;
#  - Coulomb mu = 0.12 (pdas, alm) and Tresca s = 1.1 q: some nodes slip, each with |T| = s (mu N,
#    or s times its area) along its slip, the others without slip, the sums as above; Tresca
#    s = 3 q: every node sticks;
#  - Tresca s = 0.9 q: the load exceeds what friction holds, the solve reports the drift;
#  - a friction law not done in 3D (nonmonotone) is refused naming the field.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_command gmsh "the box generator meshes through gmsh"

deck=$root/datafiles/scene3d/block_friction.dat
run() { # NAME SED-EXPRESSION: the deck edited, solved in $work/NAME
  sed "$2" "$deck" >"$work/$1.dat"
  "$root/drivers/chain.sh" "$work/$1.dat" -o "$work/$1" >"$work/$1.log" 2>&1
}
solved() { # NAME LAW BOUND STICK(all|some) [STICKING-SLIP: the largest slip of a sticking node]
  checks=$((checks + 1))
  "$python" - "$work/$1/contact.csv" "$2" "$3" "$4" "${5:-1e-15}" <<'PY' || fail "the solution of $1"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
law, bound, stick, held = sys.argv[2], float(sys.argv[3]), sys.argv[4], float(sys.argv[5])
p, q, area = 1e6, 1e5, 1.0
problems = []
if any(r["converged"] != "1" for r in rows):
    problems.append("not converged")
T = [sum(float(r[f"tangential_force_{k}"]) for r in rows) for k in (1, 2, 3)]
N = sum(float(r["multiplier"]) for r in rows)
if math.dist(T, (0.6 * q * area, 0.8 * q * area, 0.0)) > 1e-9 * q * area:
    problems.append(f"the tangential forces sum to {T}, not q x area along (0.6, 0.8)")
if abs(N / (p * area) - 1) > 1e-9:
    problems.append(f"the normal forces sum to {N}, not p x area")
slipping = 0
for r in rows:
    t = [float(r[f"tangential_force_{k}"]) for k in (1, 2, 3)]
    s = [float(r[f"slip_{k}"]) for k in (1, 2, 3)]
    tn, sn = math.hypot(*t), math.hypot(*s)
    force = float(r["multiplier"])
    limit = bound * force if law == "coulomb" else bound * force / float(r["pressure"])
    if r["friction_status"] == "S=":
        if sn > held:
            problems.append(f"node {r['node']} sticks with a slip {sn}")
    elif r["friction_status"] == "S+":
        slipping += 1
        if abs(tn - limit) > 1e-7 * limit:
            problems.append(f"node {r['node']} slips with |T| = {tn}, its bound {limit}")
        if 1 - sum(a * b for a, b in zip(t, s)) / (tn * sn) > 1e-9:
            problems.append(f"node {r['node']}: its force is not along its slip")
    else:
        problems.append(f"node {r['node']}: status {r['friction_status']}")
if stick == "all" and slipping:
    problems.append(f"{slipping} nodes slip, none should")
if stick == "some" and not 0 < slipping < len(rows):
    problems.append(f"{slipping} of {len(rows)} nodes slip: the case needs both")
for x in problems:
    print(x)
print(f"{sys.argv[1].split('/')[-2]}: {slipping} of {len(rows)} nodes slip, T sum {T}")
sys.exit(1 if problems else 0)
PY
}

for method in pdas alm projection penalty; do
  solver="method=$method"
  [ "$method" = penalty ] && solver="method=penalty r=2.1e16" # 1e5 E / lz per unit area
  run "coulomb_$method" "s/^SOLVER method=pdas$/SOLVER $solver/" || fail "coulomb ($method) failed"
  # penalty's sticking springs give way by T / (r w), 1e-11 m here (the block moves 1e-6 m)
  solved "coulomb_$method" coulomb 0.5 all "$([ "$method" = penalty ] && echo 1e-10 || echo 1e-15)"
done
for method in pdas alm; do
  run "partial_$method" "s/mu=0.5/mu=0.12/; s/^SOLVER method=pdas$/SOLVER method=$method/" ||
    fail "coulomb mu=0.12 ($method) failed"
  solved "partial_$method" coulomb 0.12 some
done
run tresca_stick 's/law=coulomb mu=0.5/law=tresca threshold=3e5/' || fail "tresca s=3q failed"
solved tresca_stick tresca 3e5 all
run tresca_partial 's/law=coulomb mu=0.5/law=tresca threshold=1.1e5/' || fail "tresca s=1.1q failed"
solved tresca_partial tresca 1.1e5 some

checks=$((checks + 1))
run tresca_drift 's/law=coulomb mu=0.5/law=tresca threshold=0.9e5/' || true
grep -q "did not converge: drift" "$work/tresca_drift.log" ||
  fail "Tresca below the load: no drift reported ($(grep -m1 -i 'warn\|error' "$work/tresca_drift.log"))"

checks=$((checks + 1))
if run nonmonotone 's/law=coulomb mu=0.5/law=nonmonotone a=0.5 b=0.2 alpha=2000/'; then
  fail "law=nonmonotone was solved in 3D"
elif ! grep -q "field 'law': law=nonmonotone in 3D is not implemented" "$work/nonmonotone.log"; then
  fail "the refusal of nonmonotone in 3D: $(grep -m1 -i error "$work/nonmonotone.log")"
fi
finish "a block pulled on a rigid plane in 3D with Coulomb and Tresca friction"
