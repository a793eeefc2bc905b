#!/usr/bin/env bash
# Requirement: bad input gets a clear message naming file, line and field, and a non-zero exit;
# nothing already written is damaged.
set -euo pipefail
source tests/pipeline/lib/common.sh
good=$work/good.dat
sed -e 's/N=256/N=32/' datafiles/scene7a/hertz.dat > "$good"
drivers/chain.sh "$good" -o "$work/out" > /dev/null 2>&1
before=$(cd "$work/out" && sha256sum case.* | sha256sum)

# expect STAGE DECK_LINE_EDIT EXPECTED_TEXT...: apply a sed edit to the good deck, run the
# stage, require a non-zero exit and every expected text in its message (field names are
# case-insensitive in datafiles, so is the match).
expect() {
  local stage=$1 edit=$2
  shift 2
  sed -e "$edit" "$good" > "$work/bad.dat"
  refused "$stage, $edit" "$stage" "$work/bad.dat" "$work/out" "$@"
}

expect mesh      's/^MESH/MESSH/'                         "bad.dat:" "unknown card" "MESSH"
expect mesh      's/ N=32/ N=33/'                         "bad.dat:" "'N'"
expect material  's/nu=0.3/nu=0.5/'                       "bad.dat:" "'nu'" "0.5"
expect material  's/plane=strain/plane=strain thickness=-1/' "bad.dat:" "'thickness'"
expect material  's/E=150/E=abc/'                         "bad.dat:" "'E'" "abc"
expect contact   's/^CONTACT ref=3/CONTACT ref=7/'        "bad.dat:" "'ref'"
expect contact   's/normal=0,1/normal=0,0/'               "bad.dat:" "'normal'"
expect assemble  's/^TRACTION ref=2/TRACTION ref=9/'      "bad.dat:" "'ref'"
expect solve     's/method=pdas/method=newton/'           "bad.dat:" "'method'" "newton"
expect solve     's/eps=1e-5/eps=-1/'                     "bad.dat:" "'eps'"
expect solve     's/^SOLVER /SOLVER colour=red /'         "bad.dat:" "'colour'"
# Contact and friction laws (issue 10): ranges and fields the law does not read, on their line.
expect contact   's/law=signorini gap=0/law=compliance cn=0/'  "bad.dat:" "'cn'" "> 0"
expect contact   's/law=signorini gap=0/law=compliance/'       "bad.dat:" "'cn'"
expect contact   's/law=signorini gap=0/law=compliance-unilateral cn=10 g=-1/' "bad.dat:" "'g'" ">= 0"
expect contact   's/law=signorini gap=0/law=signorini cn=10/'  "bad.dat:" "'cn'" "not a parameter"
expect contact   's/law=signorini gap=0/law=tresca/'           "bad.dat:" "'law'" "tresca"
expect contact   '$a FRICTION ref=3 law=coulomb mu=-0.2'      "bad.dat:" "'mu'" ">= 0"
expect contact   '$a FRICTION ref=3 law=tresca threshold=-1'  "bad.dat:" "'threshold'" ">= 0"
expect contact   '$a FRICTION ref=2 law=coulomb mu=0.2'       "bad.dat:" "'ref'" "no CONTACT card"
expect contact   '/^CONTACT/d; $a FRICTION ref=3 law=coulomb mu=0.2' "bad.dat:" "'ref'" "CONTACT"
expect solve     '$a INITIAL u=0,-1 v=1,0'                    "bad.dat:" "'v'" "static"
expect contact   's/law=signorini gap=0/law=compliance-unilateral cn=10/' "bad.dat:" "'g'" "depth"
# The nonmonotone law (1.39) of scene 4: alpha >= 0, b <= a, a given.
nm='s/law=signorini gap=0/law=compliance-unilateral cn=10 g=0.5/; $a FRICTION ref=3 law=nonmonotone'
expect contact   "$nm a=2 b=0.02 alpha=-1"                     "bad.dat:" "'alpha'" ">= 0"
expect contact   "$nm a=1 b=2 alpha=1"                         "bad.dat:" "'b'" "<= a"
expect contact   "$nm b=0.02 alpha=1"                          "bad.dat:" "'a'" "missing"
expect solve     "$nm a=1 b=0.5 alpha=1 of=slip-rate"          "bad.dat:" "'of'" "slip rate"
expect solve     "$nm a=1 b=0.5 alpha=1\nCONVEXIFICATION relaxation=2" "bad.dat:" "'relaxation'" "(0, 1]"
expect solve     '$a CONVEXIFICATION eps=1e-5'                 "bad.dat:" "CONVEXIFICATION" "nonmonotone"
# The laws in velocity belong to the quasistatic march (issue 12), not to a static solve.
expect solve     's/law=signorini gap=0/law=damped cn=10/'    "bad.dat:" "'law'" "velocity"
expect solve     's/^TRACTION ref=2 .*/& ramp=1/'             "bad.dat:" "'ramp'" "no time"
expect material  's/^MATERIAL .*/MATERIAL law=kelvin-voigt E=150 nu=0.3 eta1=-1/' "bad.dat:" "'eta1'" ">= 0"
expect material  '$a MEMORY E=1 nu=0.3 beta=1'                 "bad.dat:" "'region'" "kelvin-voigt"
# Scene 6 (issue 13): the moving load's psi > 0, the truncation c3 > 0, and friction of the slip
# rate only in a march in time, each on its line (the appended card is the deck's last).
last=$(($(grep -c '' "$good") + 1)) contact_line=$(grep -n '^CONTACT' "$good" | cut -d: -f1)
expect assemble  '$a MOVINGLOAD ref=2 F=10 psi=0 c=2'        "bad.dat:$last:" "'psi'" "> 0"
expect assemble  '$a MOVINGLOAD ref=2 F=10 psi=-50 c=2'      "bad.dat:$last:" "'psi'" "> 0"
expect contact   's/law=signorini gap=0/law=compliance cn=10 c3=0/' "bad.dat:$contact_line:" "'c3'" "> 0"
expect solve     "$nm a=1 b=0.5 alpha=2000 of=slip-rate"       "bad.dat:$last:" "'of'" "march in time"

# Friction in large deformation is refused on the FRICTION card, before any solve.
hyper=$work/hyper.dat
sed -e 's/^MATERIAL .*/MATERIAL law=ciarlet-geymonat c1=0.5 c2=0.005 a=0.35 plane=strain/' \
  -e '$a FRICTION ref=3 law=coulomb mu=0.2' "$good" > "$hyper"
status=0
message=$(drivers/chain.sh "$hyper" -o "$work/hyper" 2>&1) || status=$?
if [ "$status" -eq 0 ] || ! grep -q "hyper.dat:.*'law'.*large deformation" <<< "$message"; then
  fail "friction in large deformation: exit $status: $message"
fi
[ ! -e "$work/hyper/case.b" ] || fail "friction in large deformation wrote case.b"

# A truncated and a corrupted DS are refused with the file and array named.
cp "$work/out/case.tae" "$work/keep.tae"
head -c 5000 "$work/keep.tae" > "$work/out/case.tae"
message=$("$bin/sig-solve" "$good" -o "$work/out" 2>&1) && fail "truncated TAE accepted"
grep -q "case.tae" <<< "$message" && grep -q "truncated" <<< "$message" || fail "truncated TAE message: $message"
cp "$work/keep.tae" "$work/out/case.tae"
size=$(stat -c %s "$work/out/case.tae")
printf '\xff' | dd of="$work/out/case.tae" bs=1 seek=$((size / 2)) conv=notrunc status=none
message=$("$bin/sig-solve" "$good" -o "$work/out" 2>&1) && fail "corrupted TAE accepted"
grep -q "CRC" <<< "$message" && grep -q "array '" <<< "$message" || fail "corrupted TAE message: $message"
cp "$work/keep.tae" "$work/out/case.tae"

# Command-line values of the error and benchmark tools: a refusal naming the option and the value.
expect_option() {
  local what=$1 expected=$2 status=0 message
  shift 2
  message=$("$@" 2>&1) || status=$?
  if [ "$status" -eq 0 ] || ! grep -qF -- "$expected" <<< "$message"; then
    fail "$what: exit $status: $message"
  fi
}
for window in 1,2,3,4, 1,2,3 1,2,x,4 2,1,3,4; do
  expect_option "--window $window" "--window $window" \
    "$bin/sig-error" --window "$window" "$work/out" "$work/out"
done
for repeat in abc 2x 0; do
  expect_option "--repeat $repeat" "--repeat: '$repeat'" \
    "$bin/sig-bench-quasistatic" "$good" -o "$work/out" --repeat "$repeat"
done

# Nothing the good run wrote was touched by the failed ones.
after=$(cd "$work/out" && sha256sum case.* | sha256sum)
[ "$before" = "$after" ] || fail "a failed stage changed a DS file"

[ "$failures" -eq 0 ] || exit 1
echo "bad_input: 25 bad inputs and 7 bad option values refused with file, line and field; DS files intact"
