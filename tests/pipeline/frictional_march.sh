#!/usr/bin/env bash
# Requirement (issue 23): a frictional deck marches with a linear body. sig-march refused
# FRICTION with a Hooke body ("friction in time marching needs a hyperelastic body"); now the
# linear march condenses the slips too. The free disc of datafiles/dynamics/free_disc.dat thrown
# obliquely at (2, -10) m/s onto the plane x2 = 14, its bottom quarter in contact, Coulomb
# mu = 0.3, over 0.2 s of k = 0.01 s:
#  - the deck runs (exit 0, every step converged) with each of its friction laws in turn, and
#    Coulomb's with every strategy (signorini, compliance, specific-penalty, two-step, ipm), and
#    energy.csv keeps the balance E + interface - friction work - wall work = E0 to 1e-9 E0 with
#    a friction work that never grows and ends negative;
#  - case.hist has the kept tangential pressures and sig-post shows them;
#  - FRICTION law=coulomb mu=0 gives the frictionless march's energies (to 1e-12 of E0): the
#    slips among the unknowns change nothing without a bound;
#  - law=nonmonotone, whose convexification only the marches in velocity run, is refused naming
#    the FRICTION card's field law.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"

# deck NAME STRATEGY FRICTION_CARD: the free disc, 0.02 m above the plane x2 = 14.
deck() {
  mkdir -p "$work/$1"
  sed -E -e "s|^INITIAL .*|INITIAL v=2,-10|" \
    -e "s|^TIME .*|TIME scheme=midpoint T=0.2 k=0.01 output_every=5 mass=consistent|" \
    -e "s|^OUTPUT .*|OUTPUT vtk=yes|" datafiles/dynamics/free_disc.dat >"$work/$1/disc.dat"
  printf 'CONTACT ref=3 obstacle=plane point=0,13.98 normal=0,1 %s\n%s\n' "$2" "$3" \
    >>"$work/$1/disc.dat"
}
# run NAME: the chain of the deck; its log on failure.
run() {
  drivers/chain.sh "$work/$1/disc.dat" -o "$work/$1" >"$work/$1/chain.log" 2>&1 ||
    { tail -n 20 "$work/$1/chain.log"; fail "$1 did not run"; }
}

deck coulomb "strategy=signorini" "FRICTION ref=3 law=coulomb mu=0.3"
# Coulomb with every other strategy of the linear march.
deck coulomb_compliance "strategy=compliance r=1e5" "FRICTION ref=3 law=coulomb mu=0.3"
deck coulomb_penalty "strategy=specific-penalty r=1e5" "FRICTION ref=3 law=coulomb mu=0.3"
deck coulomb_two_step "strategy=two-step r=1e5" "FRICTION ref=3 law=coulomb mu=0.3"
deck coulomb_ipm "strategy=ipm r=1e5 g=0.002" "FRICTION ref=3 law=coulomb mu=0.3"
deck tresca "strategy=specific-penalty r=1e5" "FRICTION ref=3 law=tresca threshold=20"
deck mu2 "strategy=ipm r=1e5 g=0.002" "FRICTION ref=3 law=mu2 mu=0.3"
deck frictionless "strategy=signorini" ""
deck zero "strategy=signorini" "FRICTION ref=3 law=coulomb mu=0"
strategies="coulomb coulomb_compliance coulomb_penalty coulomb_two_step coulomb_ipm"
for name in $strategies tresca mu2 frictionless zero; do run $name; done

python3 - "$work" $strategies <<'PY' || failures=$((failures + 1))
import csv, sys
work = sys.argv[1]
def rows(name):
    return list(csv.DictReader(open(f"{work}/{name}/energy.csv")))
ok = True
for name in sys.argv[2:] + ["tresca", "mu2"]:
    r = rows(name)
    e0 = float(r[0]["total"])
    balance = max(abs(float(x["total"]) + float(x["interface"]) - float(x["friction_work"])
                      - float(x["wall_work"]) - e0) for x in r) / e0
    work_ = [float(x["friction_work"]) for x in r]
    grew = max(b - a for a, b in zip(work_, work_[1:]))
    contact = sum(int(x["active_nodes"]) > 0 for x in r)
    print(f"{name}: {len(r) - 1} steps, {contact} in contact, balance error / E0 = {balance:.2e}, "
          f"friction work {work_[-1]:.6g} J/m (E0 {e0:.6g}), largest rise {grew:.2e}")
    if len(r) != 21 or contact < 3:
        print(f"FAIL {name}: 20 steps with contact expected"); ok = False
    if balance > 1e-9 or grew > 1e-12 * e0 or not work_[-1] < 0:
        print(f"FAIL {name}: balance or friction work"); ok = False
a, b = rows("frictionless"), rows("zero")
e0 = float(a[0]["total"])
diff = max(abs(float(x[c]) - float(y[c])) for x, y in zip(a, b)
           for c in ("total", "kinetic", "elastic", "wall_work"))
print(f"coulomb mu=0 against frictionless: max energy difference / E0 = {diff / e0:.2e}")
if len(a) != len(b) or diff > 1e-12 * e0:
    print("FAIL: mu = 0 is not the frictionless march"); ok = False
sys.exit(0 if ok else 1)
PY

tangential=$("$bin/sig-dump" --json "$work/coulomb/case.hist" | grep -o '"tangential_pressure"' || true)
[ -n "$tangential" ] || fail "case.hist has no tangential_pressure"
grep -aq 'Name="tangential_pressure"' "$work/coulomb/disc_0004.vtu" ||
  fail "the .vtu has no tangential_pressure"

deck nonmonotone "strategy=signorini" "FRICTION ref=3 law=nonmonotone a=0.4 b=0.2 alpha=10"
if drivers/chain.sh "$work/nonmonotone/disc.dat" -o "$work/nonmonotone" \
  >"$work/nonmonotone/chain.log" 2>&1; then
  fail "law=nonmonotone marched with the midpoint rule"
elif ! grep -q "disc.dat:$(grep -n '^FRICTION' "$work/nonmonotone/disc.dat" | cut -d: -f1): field 'law'.*convexification" \
  "$work/nonmonotone/chain.log"; then
  tail -n 5 "$work/nonmonotone/chain.log"
  fail "law=nonmonotone refused without naming FRICTION law"
fi

[ $failures -eq 0 ] && echo "frictional_march: a frictional linear march runs and balances"
exit $((failures > 0))
