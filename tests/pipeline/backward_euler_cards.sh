#!/usr/bin/env bash
# Requirement (issue 13): a backward-Euler deck (sig-march TIME scheme=backward-euler) that asks
# for what the dynamic march does not model is refused with file, line and field and a non-zero
# exit, before anything is factorized; the good deck marches.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
good=$work/good.dat
sed -e 's/nx=64 ny=64/nx=8 ny=2/' -e 's/^OUTPUT .*/OUTPUT vtk=no/' \
  "$root/datafiles/scene6/rail.dat" > "$good"
"$root/drivers/chain.sh" "$good" -o "$work/out" > "$work/good.log" 2>&1 ||
  { cat "$work/good.log"; die "the good deck"; }

# expect DECK_LINE_EDIT EXPECTED_TEXT...: sig-march on the edited deck must fail with every text.
expect() {
  sed -e "$1" "$good" > "$work/bad.dat"
  refused "$1" march "$work/bad.dat" "$work/out" "${@:2}"
}

expect 's/of=slip-rate/of=slip/'                       "bad.dat:" "'of'" "slip rate"
expect 's/law=compliance cn=10 c3=1e8/law=damped cn=10/' "bad.dat:" "'law'" "velocity"
expect 's/exclude=1/exclude=1 strategy=compliance/'    "bad.dat:" "'strategy'"
expect 's/output_every=10/output_every=10 mass=emm/'   "bad.dat:" "'mass'" "emm"
expect '$a MEMORY E=1 nu=0.3 beta=2'                   "bad.dat:" "MEMORY" "quasistatic"
expect 's/CONVEXIFICATION eps=1e-5/CONVEXIFICATION eps=1e-5 start=sideways/' "bad.dat:" "'start'"
# A body without density has no mass: the TAE of the deck without rho.
sed -e 's/ rho=1e-6//' "$good" > "$work/massless.dat"
status=0
message=$("$root/drivers/chain.sh" "$work/massless.dat" -o "$work/massless" 2>&1) || status=$?
if [ "$status" -eq 0 ] || ! grep -q "massless.dat.*'rho'.*mass" <<< "$message"; then
  fail "a massless body: exit $status: $message"
fi
[ "$failures" -eq 0 ] || exit 1
echo "backward_euler_cards: 7 bad decks refused with file, line and field; the good one marched"
