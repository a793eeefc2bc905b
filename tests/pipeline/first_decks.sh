#!/usr/bin/env bash
# Requirement (issue 24): the README's "Your first deck" runs as written, so that the front door
# cannot drift from the code. In README.md,
#  - each block after `<!-- first-deck PATH -->` is the file PATH (datafiles/first/block.dat,
#    disc.dat) byte for byte, and both decks are shown;
#  - each block after `<!-- first-run -->` (drivers/chain.sh DECK) runs, as a user would type it,
#    from a folder laid out as the repository (drivers/ and datafiles/ linked, out/ its own);
#  - each block after `<!-- first-check -->` (the Python check of the block's force balance and
#    Coulomb cone, of the disc's energy balance) runs there and passes: they assert themselves.
# A section without its three blocks, or a check that prints nothing, fails the test too.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
export SIG_BIN=${SIG_BIN:-$root/build/bin}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The marked blocks of the README, in order: work/blocks/NN-KIND (first line: the marker's
# argument for a deck), and the count of each kind.
python3 - "$root/README.md" "$work/blocks" <<'PY'
import re, sys
from pathlib import Path
text = Path(sys.argv[1]).read_text()
out = Path(sys.argv[2])
out.mkdir()
pattern = re.compile(r"<!-- (first-deck|first-run|first-check)( [^ ]+)? -->\n```[a-z]*\n(.*?)```\n",
                     re.S)
blocks = pattern.findall(text)
markers = len(re.findall(r"<!-- first-(deck|run|check)", text))
if markers != len(blocks):
    sys.exit(f"README.md: {markers} first-deck markers, {len(blocks)} of them before a fenced block")
kinds = [kind for kind, _, _ in blocks]
if kinds != ["first-deck", "first-run", "first-check"] * 2:
    sys.exit(f"README.md: the first decks' blocks are {kinds}, not deck, run, check twice")
for n, (kind, argument, body) in enumerate(blocks):
    (out / f"{n:02d}-{kind}").write_text((argument.strip() + "\n" if argument else "") + body)
print(f"README.md: {len(blocks)} marked blocks")
PY

mkdir "$work/user"
ln -s "$root/drivers" "$work/user/drivers"
ln -s "$root/datafiles" "$work/user/datafiles"
failures=0
decks=()
for block in "$work"/blocks/*; do
  case $block in
    *-first-deck)
      path=$(head -n 1 "$block")
      decks+=("$path")
      if ! tail -n +2 "$block" | cmp -s - "$root/$path"; then
        echo "FAIL: the deck shown before $path in README.md is not the file:"
        tail -n +2 "$block" | diff - "$root/$path" | head -n 20 || true
        failures=$((failures + 1))
      fi
      ;;
    *-first-run)
      echo "README command: $(cat "$block")"
      if ! (cd "$work/user" && bash -euo pipefail "$block") >"$work/run.log" 2>&1; then
        tail -n 20 "$work/run.log"
        echo "FAIL: the README's command failed: $(cat "$block")"
        failures=$((failures + 1))
      fi
      ;;
    *-first-check)
      if (cd "$work/user" && python3 "$block") >"$work/check.log" 2>&1 && [ -s "$work/check.log" ]; then
        sed 's/^/  /' "$work/check.log"
      else
        sed 's/^/  /' "$work/check.log"
        echo "FAIL: the README's Python check after ${decks[-1]} failed"
        failures=$((failures + 1))
      fi
      ;;
  esac
done
[ "${decks[*]}" = "datafiles/first/block.dat datafiles/first/disc.dat" ] ||
  { echo "FAIL: the README shows ${decks[*]}, not the block and the disc"; failures=$((failures + 1)); }

[ $failures -eq 0 ] || exit 1
echo "first_decks: the README's decks are the files; its commands and checks run as written"
