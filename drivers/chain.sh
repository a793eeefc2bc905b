#!/usr/bin/env bash
# drivers/chain.sh DATAFILE [-o OUTDIR] [--time-limit SECONDS] [--all] [--np P]: run a datafile's chain
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
#
# --np P runs sig-assemble, and sig-solve (a small-strain contact deck with linear=mumps) or
# sig-march (a linear body's march, midpoint, newmark, backward-euler or quasistatic, with
# linear=mumps; not mass=emm), as P ranks
# under mpirun: each rank assembles the rows of its part of K into its part case.tae.r<rank> and
# reads them back (README "Distributed solve"); the other stages run as one process. A case
# assembled on another number of ranks (or by one process, for --np P >= 2, and the other way
# round) is assembled again, and the stages after it run. As root it sets OpenMPI's
# allow-run-as-root variables; --oversubscribe lets P exceed the cores (one BLAS thread per rank;
# mpirun_ranks, lib/environment.sh).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/environment.sh"
help_from_header "$@"
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
if [ $# -lt 1 ]; then
  echo "usage: drivers/chain.sh DATAFILE [-o OUTDIR] [--time-limit SECONDS] [--all] [--np P]" >&2
  exit 2
fi
deck=$1
shift
[ -r "$deck" ] || { echo "chain.sh: cannot read datafile $deck" >&2; exit 2; }
[ -x "$bin/sig-mesh" ] || { echo "chain.sh: no executables in $bin (run drivers/run.sh)" >&2; exit 2; }
options=()
all=0
np=0
name=$(basename "$deck")
outdir=out/${name%.*}
while [ $# -gt 0 ]; do
  case $1 in
    --all) all=1 ;;
    --np)
      [[ ${2:-} =~ ^[1-9][0-9]*$ ]] || { echo "chain.sh: --np needs a number of ranks >= 1" >&2; exit 2; }
      np=$2
      shift
      ;;
    -o) [ $# -ge 2 ] && outdir=$2; options+=("$1" "${2:-}"); shift ;;
    *) options+=("$1") ;;
  esac
  shift
done

# stage NAME: one stage of the chain, sig-solve or sig-march under mpirun with --np.
stage() {
  if { [ "$1" = solve ] || [ "$1" = march ] || { [ "$1" = assemble ] && [ "$np" -gt 1 ]; }; } &&
    [ "$np" -gt 0 ]; then
    mpirun_ranks "$np" "$bin/sig-$1" "$deck" "${options[@]}"
  else
    "$bin/sig-$1" "$deck" "${options[@]}"
  fi
}

# A deck sig-dump cannot read is the stages' to refuse, in their words: every stage runs, sig-mesh
# first; then the stages' own parser says which stages the deck calls for (sig-dump --chain: a
# CONTACT card adds sig-contact, a TIME card makes the case dynamic, sig-march replacing
# sig-solve), so that the chain sees the cards the stages see, whatever the line ends.
if [ "$all" -eq 1 ] || ! stale=$("$bin/sig-dump" --stale "$deck" "$outdir" 2>/dev/null); then
  "$bin/sig-mesh" "$deck" "${options[@]}"
  for stage in $("$bin/sig-dump" --chain "$deck"); do
    [ "$stage" = mesh ] || stage "$stage"
  done
  exit 0
fi
# The parts of the case's TAE (sig-assemble removes those its index does not name): P of them
# for --np P >= 2, none else.
parts=$(find "$outdir" -maxdepth 1 -name 'case.tae.r[0-9]*' 2> /dev/null | wc -l || true)
[ "$np" -gt 1 ] && wanted=$np || wanted=0
rerun=0 # a stage ran that the staleness above did not foresee: every later stage runs too
for stage in $("$bin/sig-dump" --chain "$deck"); do
  why=$(grep -m1 "^$stage: " <<<"$stale" || true)
  if [ -z "$why" ] && [ "$stage" = assemble ] && [ "$parts" -ne "$wanted" ]; then
    why="$stage: case.tae has $parts parts (one per rank of its assembly), this run wants $wanted"
    rerun=1
  elif [ -z "$why" ] && [ "$rerun" -eq 1 ]; then
    why="$stage: sig-assemble ran again"
  fi
  if [ -z "$why" ]; then
    echo "chain.sh: sig-$stage is up to date"
    continue
  fi
  echo "chain.sh: running sig-$stage: ${why#"$stage: "}"
  stage "$stage"
done
