#!/usr/bin/env bash
# drivers/chain.sh DATAFILE [-o OUTDIR] [--time-limit SECONDS] [--all]: run a datafile's chain
# of stages, MODULEF style (-o and --time-limit go to every stage):
# sig-mesh -> sig-material -> sig-contact (if the deck has a CONTACT card) -> sig-assemble ->
# sig-solve -> sig-post, or sig-march -> sig-post for a dynamic deck (TIME card). Each stage
# reads what the earlier ones wrote to OUTDIR (default out/<datafile stem>/). Uses $SIG_BIN, or
# build/bin.
#
# Like make, it runs only the stages that are stale: a stage whose files in OUTDIR exist and
# were made from the deck's present card values and from the present files of the stages before
# it is skipped ("up to date"). The stages' files record what they were made from
# (core/provenance.hpp) and `sig-dump --stale` compares that with the deck (core/stale.hpp): no
# hashing here. --all runs every stage.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/environment.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
if [ $# -lt 1 ]; then
  echo "usage: drivers/chain.sh DATAFILE [-o OUTDIR] [--time-limit SECONDS] [--all]" >&2
  exit 2
fi
deck=$1
shift
[ -r "$deck" ] || { echo "chain.sh: cannot read datafile $deck" >&2; exit 2; }
[ -x "$bin/sig-mesh" ] || { echo "chain.sh: no executables in $bin (run drivers/run.sh)" >&2; exit 2; }
options=()
all=0
name=$(basename "$deck")
outdir=out/${name%.*}
while [ $# -gt 0 ]; do
  case $1 in
    --all) all=1 ;;
    -o) [ $# -ge 2 ] && outdir=$2; options+=("$1" "${2:-}"); shift ;;
    *) options+=("$1") ;;
  esac
  shift
done

# A deck sig-dump cannot read is the stages' to refuse, in their words: every stage runs, sig-mesh
# first; then the stages' own parser says which stages the deck calls for (sig-dump --chain: a
# CONTACT card adds sig-contact, a TIME card makes the case dynamic, sig-march replacing
# sig-solve), so that the chain sees the cards the stages see, whatever the line ends.
if [ "$all" -eq 1 ] || ! stale=$("$bin/sig-dump" --stale "$deck" "$outdir" 2>/dev/null); then
  "$bin/sig-mesh" "$deck" "${options[@]}"
  for stage in $("$bin/sig-dump" --chain "$deck"); do
    [ "$stage" = mesh ] || "$bin/sig-$stage" "$deck" "${options[@]}"
  done
  exit 0
fi
for stage in $("$bin/sig-dump" --chain "$deck"); do
  why=$(grep -m1 "^$stage: " <<<"$stale" || true)
  if [ -z "$why" ]; then
    echo "chain.sh: sig-$stage is up to date"
    continue
  fi
  echo "chain.sh: running sig-$stage: ${why#"$stage: "}"
  "$bin/sig-$stage" "$deck" "${options[@]}"
done
