#!/usr/bin/env bash
# Requirement (issue 16): the deck's smaller traps. Output names are plain file names (OUTPUT
# name=../../x/pwn wrote outside the output folder, an empty name= hidden files); an empty value
# is an error naming its field (it used to swallow the next field); a non-UTF-8 TITLE gives valid
# JSON, and says so; a byte order mark and CR-only line ends read; errors name 'R' and 'N' as the
# schema spells them; a body nothing holds is refused naming the free motion; an unused SOLVER
# field of a TIME deck is said to be unused; a failed write to stdout is an error. Each refusal:
# exit status, message with file, line and field, and no file of the case changed.
set -euo pipefail
source tests/pipeline/lib/distrust.sh

static_deck "$work/block.dat"
chain "$work/block.dat" "$work/out"
bad() { # bad NAME SED-EDIT: a copy of the good deck, edited
  sed -e "$2" "$work/block.dat" > "$work/$1.dat"
}

bad escape 's|^OUTPUT vtk=yes|OUTPUT vtk=yes name=../../x/pwn|'
expect_refusal "OUTPUT name=../../x/pwn" post "$work/escape.dat" "$work/out" \
  "escape.dat:7: field 'name'" "not a plain file name"
[ ! -e "$work/x" ] && [ ! -e "$work/x/pwn.pvd" ] || fail "name=../../x/pwn wrote outside the output folder"
bad hidden 's|^OUTPUT vtk=yes|OUTPUT vtk=yes name=.hidden|'
expect_refusal "OUTPUT name=.hidden" post "$work/hidden.dat" "$work/out" \
  "hidden.dat:7: field 'name'" "not a plain file name"
bad swallow 's|^OUTPUT vtk=yes|OUTPUT name= vtk=yes|'
expect_refusal "OUTPUT name= vtk=yes" post "$work/swallow.dat" "$work/out" \
  "swallow.dat:7: field 'name': empty value ('vtk=yes' is the next field)"
bad young 's|E=200 nu=0.3|E= nu=0.3|'
expect_refusal "MATERIAL E= nu=0.3" material "$work/young.dat" "$work/out" \
  "young.dat:3: field 'E': empty value ('nu=0.3' is the next field)"
bad radius 's|^MESH .*|MESH generator=half-disc R=-1 N=16|'
expect_refusal "MESH R=-1 named 'R'" mesh "$work/radius.dat" "$work/out" \
  "radius.dat:2: field 'R': must be > 0, got -1"
bad count 's|^MESH .*|MESH generator=half-disc R=1 N=15|'
expect_refusal "MESH N=15 named 'N'" mesh "$work/count.dat" "$work/out" \
  "count.dat:2: field 'N': must be even"
bad free '/^DIRICHLET/d'
for stage in mesh material assemble; do
  "$bin/sig-$stage" "$work/free.dat" -o "$work/free" > /dev/null 2>&1 || fail "sig-$stage failed on free.dat"
done
expect_refusal "a body nothing holds" solve "$work/free.dat" "$work/free" \
  "free.dat: the body is free to move: nothing holds the translation along x1, the translation along x2 and the rotation about"

# A failed write to the standard output is an error, not exit 0.
checks=$((checks + 1))
status=0
message=$("$bin/sig-dump" "$work/out/case.tae" 2>&1 > /dev/full) || status=$?
if [ "$status" -eq 0 ] || ! grep -q "cannot write to the standard output" <<< "$message"; then
  fail "sig-dump > /dev/full: exit $status: $message"
else
  echo "ok ($test_name): sig-dump > /dev/full: $message"
fi

# Decks as editors save them: a byte order mark, CR-only line ends. The chain runs.
checks=$((checks + 1))
printf '\xef\xbb\xbf' | cat - "$work/block.dat" > "$work/bom.dat"
tr '\n' '\r' < "$work/block.dat" > "$work/cr.dat"
for deck in bom cr; do
  drivers/chain.sh "$work/$deck.dat" -o "$work/$deck" > "$work/$deck.log" 2>&1 ||
    fail "$deck.dat refused: $(tail -2 "$work/$deck.log")"
done
cmp -s <("$bin/sig-dump" "$work/bom/case.b" | grep '^  u ') <("$bin/sig-dump" "$work/cr/case.b" | grep '^  u ') ||
  fail "the BOM and CR decks give different solutions"
echo "ok ($test_name): a deck with a byte order mark and one with CR-only line ends run"

# A Latin-1 TITLE: summary.json stays valid UTF-8 (the bad byte replaced), with a warning.
checks=$((checks + 1))
sed -e 's|^TITLE .*|TITLE caf\xe9 \xe0 Paris|' "$work/block.dat" > "$work/latin.dat"
drivers/chain.sh "$work/latin.dat" -o "$work/latin" > "$work/latin.log" 2>&1 || fail "the Latin-1 deck failed"
grep -q "latin.dat:1: TITLE is not valid UTF-8: 2 bad byte(s) replaced by U+FFFD" "$work/latin.log" ||
  fail "no warning for the Latin-1 TITLE: $(grep -i title "$work/latin.log" | head -2)"
python3 -c "import json,sys; t = json.loads(open(sys.argv[1], 'rb').read().decode('utf-8'))['title']; assert t == 'caf\ufffd \ufffd Paris', t" \
  "$work/latin/summary.json" || fail "summary.json of a Latin-1 TITLE is not valid UTF-8 JSON"
echo "ok ($test_name): a Latin-1 TITLE gives valid UTF-8 JSON, with a warning"

# SOLVER c= (projection's parameter) in a TIME deck is not used: sig-march says so.
checks=$((checks + 1))
dynamic_deck "$work/disc.dat"
sed -i -e 's|^SOLVER linear=cholmod|SOLVER linear=cholmod c=100|' "$work/disc.dat"
drivers/chain.sh "$work/disc.dat" -o "$work/disc" > "$work/disc.log" 2>&1 || fail "the dynamic deck failed"
grep -q "disc.dat:6: SOLVER c=100 is not used by sig-march" "$work/disc.log" ||
  fail "SOLVER c= of a TIME deck passed silently"
echo "ok ($test_name): SOLVER c= in a TIME deck: $(grep -m1 'c=100' "$work/disc.log")"
distrust_finish
