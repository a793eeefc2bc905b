#!/usr/bin/env bash
# Requirement (issue 25): no stale DS used silently. Every file of a case records the values of
# the deck's cards it was made from (core/provenance.hpp). On two small decks (the frictional
# Hertz half disc at N = 32, and a vibrating block marched in time), each card in turn is
# changed and a stage downstream of the first stage that reads the card is run alone: it
# refuses, naming the file, the card, the old and new values with the deck's line, and the
# stage to rerun, leaving the case as it was. drivers/chain.sh then runs exactly the stale
# stages (the first that reads the card and those after it, read from its output) and gives
# the new result: case.b (case.hist) equal to a fresh chain's of the edited deck, and other than
# before. A comment, spacing, other case, reordered cards and a default spelt out are no change:
# chain.sh runs nothing and the stages accept the case. A case.cont, case.mili or case.nopo made
# from another deck and copied in is refused, and chain.sh reruns what it makes stale.
set -euo pipefail
source tests/pipeline/lib/distrust.sh
stages_checked=0

sed -e 's/N=256/N=32/' datafiles/friction/hertz_coulomb.dat > "$work/hertz.dat"
cp tests/pipeline/data/vibrating_block.dat "$work/block.dat"
chain "$work/hertz.dat" "$work/hertz" || exit 1
chain "$work/block.dat" "$work/block" || exit 1

# The displacements a case's solve (case.b) or march (case.hist) ended with.
result() {
  local file=$1/case.b
  [ -f "$file" ] || file=$1/case.hist
  "$bin/sig-dump" --json --values=u "$file" |
    python3 -c 'import json, sys
arrays = {a["name"]: a for a in json.load(sys.stdin)["arrays"]}
print(" ".join(repr(x) for x in arrays["u"]["values"]))'
}

# ran LOG: the stages chain.sh ran, from its output ("chain.sh: running sig-X: why").
ran() {
  sed -n 's/^chain\.sh: running sig-\([a-z]*\): .*/\1/p' "$1" | tr '\n' ' ' | sed 's/ $//'
}

# rechain DECK DIR EXPECTED WHAT: chain.sh on the case must run exactly EXPECTED (stage names,
# space-separated; empty: none) and say the others are up to date.
rechain() {
  local deck=$1 dir=$2 expected=$3 what=$4 got
  drivers/chain.sh "$deck" -o "$dir" >"$dir.log" 2>&1 || { fail "$what: chain.sh failed: $(tail -3 "$dir.log")"; return 1; }
  got=$(ran "$dir.log")
  stages_checked=$((stages_checked + 1))
  [ "$got" = "$expected" ] || fail "$what: chain.sh ran '$got', not '$expected': $(grep '^chain.sh' "$dir.log")"
  for stage in $("$bin/sig-dump" --chain "$deck"); do
    [[ " $expected " == *" $stage "* ]] && continue
    grep -q "^chain.sh: sig-$stage is up to date$" "$dir.log" || fail "$what: chain.sh did not say sig-$stage is up to date"
  done
}

# change CASE N WHAT CARD FROM TO ALONE FIRST EXPECTED OLD NEW [SAME]: edit CARD of CASE's deck
# (FROM -> TO on its line), run sig-ALONE alone: refused with "was made with OLD, but
# DECK:LINE now says NEW" and "rerun sig-FIRST"; then chain.sh runs EXPECTED and gives a fresh
# chain's result of the edited deck, other than before (unless SAME: a new start of one solve).
change() {
  local case=$1 n=$2 what=$3 card=$4 from=$5 to=$6 alone=$7 first=$8 expected=$9
  local old_text=${10} new_text=${11} same=${12:-}
  local dir=$work/$case$n deck=$work/$case$n.dat line old new
  cp -r "$work/$case" "$dir"
  sed -e "/^$card /s/$from/$to/" "$work/$case.dat" > "$deck"
  ! cmp -s "$deck" "$work/$case.dat" || { fail "$what: '$from' is not in the $card card"; return; }
  line=$(grep -n "^$card " "$deck" | head -1 | cut -d: -f1)
  expect_refusal "$what, sig-$alone alone" "$alone" "$deck" "$dir" \
    "was made with $old_text, but $deck:$line now says $new_text:" \
    "rerun sig-$first and the stages after it"
  rechain "$deck" "$dir" "$expected" "$what" || return
  chain "$deck" "$dir.fresh" || return
  old=$(result "$work/$case") new=$(result "$dir")
  [ "$new" = "$(result "$dir.fresh")" ] || fail "$what: the rerun stale stages did not give a fresh chain's result"
  [ -n "$same" ] || [ "$new" != "$old" ] || fail "$what: the result did not change"
}

# The static deck: each card of every stage of its chain.
change hertz 1 "a finer mesh" MESH "N=32" "N=40" solve mesh \
  "mesh material contact assemble solve post" "MESH N=32" "MESH N=40"
change hertz 2 "a new E" MATERIAL "E=150" "E=210" solve material \
  "material assemble solve post" "MATERIAL E=150" "MATERIAL E=210"
change hertz 3 "a scaled load" TRACTION "f=0.4,-2" "f=0.6,-3" solve assemble \
  "assemble solve post" "TRACTION ref=2 f=0.4,-2" "TRACTION ref=2 f=0.6,-3"
change hertz 4 "a moved obstacle" CONTACT "point=0,0" "point=0,-0.01" solve contact \
  "contact solve post" "CONTACT point=0,0" "CONTACT point=0,-0.01"
change hertz 5 "another mu" FRICTION "mu=0.4" "mu=0.05" solve contact \
  "contact solve post" "FRICTION mu=0.4" "FRICTION mu=0.05"
# (PDAS and ALM reach the same displacements: the new result is case.b's method.)
change hertz 6 "another method" SOLVER "method=pdas" "method=alm" post solve \
  "solve post" "SOLVER method=pdas" "SOLVER method=alm" same
"$bin/sig-dump" "$work/hertz6/case.b" | grep -q '^  method .*"alm"$' ||
  fail "another method: case.b was not solved by alm: $("$bin/sig-dump" "$work/hertz6/case.b" | grep '^  method')"
change hertz 7 "another start" INITIAL "u=0,-0.0012" "u=0,-0.002" post solve \
  "solve post" "INITIAL u=0,-0.0012" "INITIAL u=0,-0.002" same
# The dynamic deck: the march's cards.
change block 1 "a new density" MATERIAL "rho=1" "rho=2" march material \
  "material assemble march post" "MATERIAL rho=1" "MATERIAL rho=2"
change block 2 "a moved support" DIRICHLET "uy=0" "uy=-0.001" march assemble \
  "assemble march post" "DIRICHLET ref=1 uy=0" "DIRICHLET ref=1 uy=-0.001"
change block 3 "another time step" TIME "k=0.01" "k=0.02" post march \
  "march post" "TIME k=0.01" "TIME k=0.02"
change block 4 "another initial velocity" INITIAL "v=0,-0.1" "v=0,-0.2" post march \
  "march post" "INITIAL v=0,-0.1" "INITIAL v=0,-0.2"

# A card added, and sig-post's own cards: the stages that read them, nothing upstream.
cp -r "$work/hertz" "$work/added"
sed -e '/^TRACTION /a DIRICHLET ref=1 ux=0' "$work/hertz.dat" > "$work/added.dat"
line=$(grep -n '^DIRICHLET ' "$work/added.dat" | cut -d: -f1)
expect_refusal "a DIRICHLET card added, sig-solve alone" solve "$work/added.dat" "$work/added" \
  "was made without a DIRICHLET card, but $work/added.dat:$line now has DIRICHLET ref=1 ux=0" \
  "rerun sig-assemble"
rechain "$work/added.dat" "$work/added" "assemble solve post" "a DIRICHLET card added"
cp -r "$work/hertz" "$work/output"
sed -e 's/^OUTPUT vtk=yes/OUTPUT vtk=yes name=hertz2/' "$work/hertz.dat" > "$work/output.dat"
rechain "$work/output.dat" "$work/output" "post" "OUTPUT name= changed"
[ -f "$work/output/hertz2.pvd" ] || fail "OUTPUT name=hertz2: sig-post did not write hertz2.pvd"
cp -r "$work/hertz" "$work/title"
sed -e 's/^TITLE .*/TITLE Another name/' "$work/hertz.dat" > "$work/title.dat"
rechain "$work/title.dat" "$work/title" "post" "TITLE changed (a name in sig-post's files only)"
grep -q '"title": "Another name"' "$work/title/summary.json" || fail "TITLE: summary.json has the old title"

# The same values in other words: nothing is stale, and a stage run alone accepts the case.
cp -r "$work/hertz" "$work/same"
{
  echo "# the frictional Hertz deck, rewritten"
  grep '^FRICTION' "$work/hertz.dat" | tr 'A-Z' 'a-z' | sed 's/mu=0.4/mu=4e-1   bound=normal # Coulomb/'
  grep -v '^FRICTION\|^MATERIAL\|^#' "$work/hertz.dat" | tac
  echo "MATERIAL   nu=0.30 E=1.5e2 law=HOOKE plane=strain thickness=1 # the same law"
} > "$work/same.dat"
rechain "$work/same.dat" "$work/same" "" "comments, spacing, case, order and defaults"
for stage in solve post; do
  "$bin/sig-$stage" "$work/same.dat" -o "$work/same" > "$work/same.$stage.log" 2>&1 ||
    fail "the same values in other words: sig-$stage refused: $(tail -2 "$work/same.$stage.log")"
done

# Files made from another deck and copied in (hertz5: mu = 0.05, hertz2: E = 210, hertz1: N = 40).
copied() { # copied WHAT FILE FROM ALONE FRAGMENT EXPECTED
  local dir=$work/copied_$2
  cp -r "$work/hertz" "$dir"
  cp "$work/$3/case.$2" "$dir/"
  [ "$2" != nopo ] || cp "$work/$3/case.nopo.prov" "$dir/"
  expect_refusal "$1, sig-$4 alone" "$4" "$work/hertz.dat" "$dir" "$5"
  rechain "$work/hertz.dat" "$dir" "$6" "$1" || return
  [ "$(result "$dir")" = "$(result "$work/hertz")" ] || fail "$1: chain.sh did not restore the deck's result"
}
copied "another deck's case.cont" cont hertz5 solve "case.cont was made with FRICTION mu=0.05" \
  "contact solve post"
copied "another deck's case.mili" mili hertz2 assemble "case.mili was made with MATERIAL E=210" \
  "material assemble solve post"
copied "another deck's case.nopo" nopo hertz1 material "case.nopo was made with MESH N=40" \
  "mesh material contact assemble solve post"
# A case.nopo copied in without its record is not the mesh the record describes.
cp -r "$work/hertz" "$work/bare"
cp "$work/hertz1/case.nopo" "$work/bare/"
expect_refusal "a case.nopo copied in alone, sig-contact alone" contact "$work/hertz.dat" \
  "$work/bare" "bare/case.nopo is not the NOPO that" "rerun sig-mesh"

finish "$checks refusals naming the card, $stages_checked chain.sh runs with exactly the stale stages"
