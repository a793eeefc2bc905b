#!/usr/bin/env bash
# Requirement (issue 24): the card reference datafiles/CARDS.md is generated from the card schema
# (modules/core/src/cards.cpp) and the table of ranges (core/src/ranges.cpp) by
# `sig-dump --cards-markdown`, never edited by hand: this test regenerates it and fails, with the
# difference and the command that regenerates it, while the committed file differs. It also
# requires the fields the hand-written card table once lacked (SOLVER search=, CONTACT exclude=,
# the damped laws) and every card of `sig-dump --cards` to be in it.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
regenerate="build/bin/sig-dump --cards-markdown > datafiles/CARDS.md"

"$bin/sig-dump" --cards-markdown >"$work/CARDS.md"
if ! diff -u "$root/datafiles/CARDS.md" "$work/CARDS.md" >"$work/diff"; then
  head -n 40 "$work/diff"
  echo "FAIL: datafiles/CARDS.md is not what the card schema gives (above: committed -> fresh)."
  echo "      Regenerate it from the repository's root with: $regenerate"
  exit 1
fi

failures=0
# The words of the reference on one line: wrapping may break a phrase anywhere.
tr -s ' \n' '  ' <"$work/CARDS.md" >"$work/flat"
for expected in '## SOLVER' '- `search` (default `auto`)' '## CONTACT' '- `exclude`:' \
  'damped (1.25)' 'damped-unilateral (1.28)'; do
  grep -qF -- "$expected" "$work/flat" ||
    { echo "FAIL: CARDS.md lacks '$expected'"; failures=$((failures + 1)); }
done
# Every card of `sig-dump --cards` (its index: two spaces, the keyword, two spaces) has a section.
for card in $("$bin/sig-dump" --cards | sed -n 's/^  \([A-Z][A-Z]*\)  .*/\1/p'); do
  grep -qx "## $card" "$work/CARDS.md" ||
    { echo "FAIL: CARDS.md has no section for $card"; failures=$((failures + 1)); }
done
[ $failures -eq 0 ] || exit 1
echo "cards_reference: datafiles/CARDS.md is the schema's ($(grep -c '^## [A-Z]' "$work/CARDS.md") cards)"
