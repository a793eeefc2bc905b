#!/usr/bin/env bash
# drivers/adapt.sh DATAFILE [-o OUTDIR] [--steps K] [--dofs N] [--theta T] [--reference DIR]:
# the adaptive loop on a static deck or a march (issue 29), solve -> estimate -> mark -> refine:
#   step 0 runs the deck's chain (drivers/chain.sh) into OUTDIR/step0, then sig-estimate;
#   step k > 0 runs OUTDIR/step<k>.dat, the deck with its MESH card replaced by
#   `MESH file=step<k-1>/refined.nopo`, the mesh sig-refine made from step k-1's indicators
#   (Dörfler's marking with theta T, default 0.5; longest-edge bisection keeping references
#   and sub-domains, new nodes on the first deck's arcs).
# It stops after K steps (default 4) or at the first step with N dofs or more (default: no
# budget). The loop runs in one process, sig-adapt: each step's stages (the chain's mesh ... post,
# sig-estimate, sig-refine) are called there and write their DS files as the chain does, synced
# once a step; a process a stage cost each step 0.1-0.3 s of start-ups, file syncs, an MPI
# singleton and the driver's queries, more than the stages' work on the small meshes.
# OUTDIR (default out/<stem>-adapt) gets adapt.csv: step, dofs, estimate (sig-estimate's eta, in
# the norm of V) and, with --reference DIR (a chain's output on a finer mesh), error (sig-error's
# absolute error against it, measured after the loop) and effectivity (estimate / error); then
# the loop's cost per step: estimate_s and refine_s, the stages' own times (sig-estimate's
# indicators, case.est `seconds`; sig-refine's marking and bisection, from its log; 0 at the last
# step, which is not refined), wall_s, the wall clock of the step's chain and estimate,
# refine_wall_s, sig-refine's, and elapsed_s, the loop's wall clock from this script's call of
# sig-adapt (its process's start counted) to the end of the step's estimate. The solve's own
# time is the step's summary.json `times`.
# A march (TIME card) gets one mesh adapted to the whole march: sig-estimate estimates every kept
# state (step 0, every output_every-th step, the last), a triangle's indicator is its largest
# eta_T over them (the worst time of each place), the estimate and the error are those of the
# last kept time (sig-error's `error`). Why not re-meshing with a transfer of the state: the
# marches' singularities sit where the geometry puts them (scene 5's clamped corners, at every
# time), a march in velocity factorizes its step matrix once for all its steps, and a transfer
# of u, w and the memory between meshes would add its own error at every re-meshing (not
# implemented: this loop adapts one mesh). The time step is the deck's TIME card on every step:
# the loop adapts the space mesh only (tie k to the finest h in the deck if the time error
# matters). The reference of --reference is then a march that keeps the last time too.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/environment.sh"
help_from_header "$@"
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
usage="usage: drivers/adapt.sh DATAFILE [-o OUTDIR] [--steps K] [--dofs N] [--theta T] [--reference DIR]"
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
deck=$1
shift
[ -r "$deck" ] || { echo "adapt.sh: cannot read datafile $deck" >&2; exit 2; }
name=$(basename "$deck")
stem=${name%.*}
outdir=out/$stem-adapt steps=4 dofs=0 theta=0.5 reference=
while [ $# -gt 0 ]; do
  [ $# -ge 2 ] || { echo "adapt.sh: $1 needs a value; $usage" >&2; exit 2; }
  case $1 in
    -o) outdir=$2 ;;
    --steps) steps=$2 ;;
    --dofs) dofs=$2 ;;
    --theta) theta=$2 ;;
    --reference) reference=$2 ;;
    *) echo "adapt.sh: unknown option $1; $usage" >&2; exit 2 ;;
  esac
  shift 2
done
[[ $steps =~ ^[1-9][0-9]*$ ]] || { echo "adapt.sh: --steps $steps is not a count >= 1" >&2; exit 2; }
[[ $dofs =~ ^[0-9]+$ ]] || { echo "adapt.sh: --dofs $dofs is not a count" >&2; exit 2; }
# A march (TIME card) leaves case.hist, a static solve case.b: the reference must be the same.
solution=case.b
if grep -qi '^[[:space:]]*TIME[[:space:]]' "$deck"; then
  solution=case.hist
fi
if [ -n "$reference" ] && [ ! -f "$reference/case.nopo" ]; then
  echo "adapt.sh: --reference $reference holds no case.nopo (run its chain first)" >&2
  exit 2
fi
if [ -n "$reference" ] && [ ! -f "$reference/$solution" ]; then
  echo "adapt.sh: --reference $reference holds no $solution: $deck is a" \
    "$([ $solution = case.hist ] && echo march || echo static deck), its reference must be one" >&2
  exit 2
fi
mkdir -p "$outdir"
deck_path=$(cd "$(dirname "$deck")" && pwd)/$name

# The loop, in one process (sig-adapt: every stage's main called there, each writing its DS
# files into step<k>/ as the chain does; files synced once a step). Its wall clock starts here,
# so that its process's start counts (elapsed_s).
t0=${EPOCHREALTIME/./}
"$bin/sig-adapt" "$deck_path" -o "$outdir" --steps "$steps" --dofs "$dofs" --theta "$theta" \
  --clock-start "$t0" | sed 's/^sig-adapt: /adapt.sh: /' ||
  { echo "adapt.sh: the loop failed (sig-adapt)" >&2; exit 1; }

# adapt.csv: sig-adapt's loop.csv with, given a reference, sig-error's error of each step and
# the effectivity (measured after the loop: not part of its cost).
csv=$outdir/adapt.csv
echo "step,dofs,estimate,error,effectivity,estimate_s,refine_s,wall_s,refine_wall_s,elapsed_s" >"$csv"
while IFS=, read -r k step_dofs estimate times; do
  error= effectivity=
  if [ -n "$reference" ]; then
    error=$("$bin/sig-error" --json "$outdir/step$k" "$reference" |
      sed -n 's/^ *"error": *\([^,]*\),*$/\1/p')
    [ -n "$error" ] || { echo "adapt.sh: step $k: no error from sig-error" >&2; exit 1; }
    effectivity=$(awk -v e="$estimate" -v r="$error" 'BEGIN { if (r > 0) printf "%.17g", e / r }')
    echo "adapt.sh: step $k: error $error, effectivity $effectivity"
  fi
  echo "$k,$step_dofs,$estimate,$error,$effectivity,$times" >>"$csv"
done < <(tail -n +2 "$outdir/loop.csv")
echo "$csv"
