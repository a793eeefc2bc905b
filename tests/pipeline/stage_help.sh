#!/usr/bin/env bash
# Pipeline test (issue 17): every stage teaches its cards.
#  - every bin/sig-* answers --help (exit 0: usage, what it reads and writes, its cards with their
#    fields) and --version (exit 0: "sig-x (Signorini) VERSION, revision REV", REV the git
#    revision in a git checkout); a bad command line exits 1 with the usage;
#  - every card a stage looks up is in its --help: the stages of two small chains run here (a
#    static and a dynamic deck) and, when the whole suite ran before this test (ctest runs it
#    last: it is the cleanup of the fixture card_trace), the stages of every pipeline test, all
#    record the cards they looked up in $SIG_CARD_TRACE;
#  - sig-dump --cards lists every card of the schema and --cards CARD prints its fields with
#    their defaults.
# Run from the repository root with SIG_BIN set (ctest does both); exit 77 (skipped) when the
# executables are missing.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
[ -x "$bin/sig-dump" ] || { echo "stage_help: skipped, no $bin/sig-dump"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# 1. --help and --version of every stage.
stages=()
for exe in "$bin"/sig-*; do
  [ -x "$exe" ] || continue
  name=$(basename "$exe")
  stages+=("$name")
  if ! "$exe" --help >"$work/$name.help" 2>"$work/$name.err"; then
    fail "$name --help exits non-zero: $(cat "$work/$name.err")"
    continue
  fi
  head -1 "$work/$name.help" | grep -q "^usage: $name " || fail "$name --help: no usage line"
  grep -q '^Options:' "$work/$name.help" || fail "$name --help: no options"
  version=$("$exe" --version) || fail "$name --version exits non-zero"
  [[ $version =~ ^$name\ \(Signorini\)\ [0-9]+\.[0-9]+,\ revision\ [^\ ]+$ ]] ||
    fail "$name --version prints '$version'"
  if git -C "$root" rev-parse --git-dir >/dev/null 2>&1; then
    head=$(git -C "$root" rev-parse --short=12 HEAD)
    # A build of an older commit of the same tree is fine; an unknown revision is not.
    [[ $version != *"revision unknown" ]] || fail "$name --version: revision unknown in a git tree"
    echo "$name: $version (HEAD $head)"
  fi
  status=0
  "$exe" --no-such-option >/dev/null 2>"$work/$name.bad" || status=$?
  [ "$status" -eq 1 ] && grep -q "usage: $name" "$work/$name.bad" ||
    fail "$name --no-such-option: exit $status, message '$(cat "$work/$name.bad")'"
done
echo "stage_help: ${#stages[@]} executables: ${stages[*]}"
[ ${#stages[@]} -ge 9 ] || fail "only ${#stages[@]} executables in $bin"

# 2. Every card a stage looked up is in its --help (a card heading "KEYWORD:" or
#    "KEYWORD (repeatable):").
trace=$work/trace.txt
for deck in datafiles/cantilever.dat tests/pipeline/data/vibrating_block.dat; do
  SIG_CARD_TRACE=$trace SIG_BIN=$bin bash "$root/drivers/chain.sh" "$root/$deck" \
    -o "$work/$(basename "$deck" .dat)" >"$work/chain.log" 2>&1 || {
    cat "$work/chain.log"
    fail "the chain of $deck failed"
  }
done
[ -s "$trace" ] || fail "the chains recorded no card in SIG_CARD_TRACE"
suite_trace=${SIG_BUILD:-$root/build}/card_trace.txt
[ -s "$suite_trace" ] && cat "$suite_trace" >>"$trace"
checked=0
while read -r stage keyword; do
  checked=$((checked + 1))
  help=$work/$stage.help
  [ -f "$help" ] || "$bin/$stage" --help >"$help" 2>/dev/null || true
  grep -qE "^$keyword( \(repeatable\))?: " "$help" ||
    fail "$stage looks up card $keyword, which its --help does not list"
done < <(sort -u "$trace")
echo "stage_help: $checked (stage, card) pairs looked up, each in the stage's --help"

# 3. sig-dump --cards: the index has every card, each card its fields and defaults.
"$bin/sig-dump" --cards >"$work/cards.txt" || fail "sig-dump --cards exits non-zero"
cards=$(tail -n +2 "$work/cards.txt" | awk '/^  [A-Z]/ {print $1}')
for card in TITLE MESH MATERIAL DIRICHLET TRACTION CONTACT FRICTION SOLVER TIME INITIAL OUTPUT; do
  grep -qx "$card" <<<"$cards" || fail "sig-dump --cards does not list $card"
done
for card in $cards; do
  "$bin/sig-dump" --cards "$card" >"$work/card.txt" || fail "sig-dump --cards $card exits non-zero"
  grep -qE "^$card( \(repeatable\))?: " "$work/card.txt" || fail "sig-dump --cards $card: no heading"
done
"$bin/sig-dump" --cards material | grep -qE '^ +thickness +.*\[default: 1\]' ||
  fail "sig-dump --cards material: no 'thickness ... [default: 1]'"
status=0
"$bin/sig-dump" --cards NOSUCHCARD >/dev/null 2>"$work/err.txt" || status=$?
[ "$status" -eq 1 ] && grep -q "no card NOSUCHCARD" "$work/err.txt" ||
  fail "sig-dump --cards NOSUCHCARD: exit $status"

if [ "$failures" -gt 0 ]; then
  echo "stage_help: $failures failure(s)"
  exit 1
fi
echo "stage_help: ok"
