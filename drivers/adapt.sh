#!/usr/bin/env bash
# drivers/adapt.sh DATAFILE [-o OUTDIR] [--steps K] [--dofs N] [--theta T] [--reference DIR]:
# the adaptive loop on a static deck or a march (issue 29), solve -> estimate -> mark -> refine:
#   step 0 runs the deck's chain (drivers/chain.sh) into OUTDIR/step0, then sig-estimate;
#   step k > 0 runs OUTDIR/step<k>.dat, the deck with its MESH card replaced by
#   `MESH file=step<k-1>/refined.nopo`, the mesh sig-refine made from step k-1's indicators
#   (Dörfler's marking with theta T, default 0.5; longest-edge bisection keeping references
#   and sub-domains, new nodes on the first deck's arcs).
# It stops after K steps (default 4) or at the first step with N dofs or more (default: no
# budget). OUTDIR (default out/<stem>-adapt) gets adapt.csv: step, dofs, estimate (sig-estimate's
# eta, in the norm of V) and, with --reference DIR (a chain's output on a finer mesh), error
# (sig-error's absolute error against it) and effectivity (estimate / error); then the loop's
# cost per step: estimate_s and refine_s, the stages' own times (sig-estimate's indicators,
# case.est `seconds`; sig-refine's marking and bisection, from its log; 0 at the last step, which
# is not refined), wall_s, the wall clock of the step's chain and sig-estimate processes, and
# refine_wall_s, sig-refine's (sig-error's measure left out of both). The solve's own time is
# the step's summary.json `times`.
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

# The values of the scalar arrays NAME,NAME... of a DS, space-separated, from sig-dump's JSON.
ds_values() {
  "$bin/sig-dump" --json --values="$2" "$1" | python3 -c 'import json, sys
arrays = {a["name"]: a for a in json.load(sys.stdin)["arrays"]}
print(" ".join(str(arrays[name]["values"][0]) for name in sys.argv[1].split(",")))' "$2"
}

# The seconds since START_US (microseconds of $EPOCHREALTIME without its point), to the us.
seconds_since() {
  local us=$((${EPOCHREALTIME/./} - $1))
  printf '%d.%06d' $((us / 1000000)) $((us % 1000000))
}

csv=$outdir/adapt.csv
echo "step,dofs,estimate,error,effectivity,estimate_s,refine_s,wall_s,refine_wall_s" >"$csv"
for ((k = 0; k < steps; k++)); do
  dir=$outdir/step$k
  step_deck=$deck_path
  if [ "$k" -gt 0 ]; then
    # The deck with the refined mesh: its MESH card replaced, every other card as it was.
    step_deck=$outdir/step$k.dat
    awk -v mesh="MESH file=step$((k - 1))/refined.nopo" \
      'toupper($1) == "MESH" { print mesh; next } { print }' "$deck_path" >"$step_deck"
  fi
  mkdir -p "$dir"
  t0=${EPOCHREALTIME/./}
  "$root/drivers/chain.sh" "$step_deck" -o "$dir" >"$dir/chain.log" 2>&1 ||
    { cat "$dir/chain.log" >&2; echo "adapt.sh: step $k: the chain failed" >&2; exit 1; }
  "$bin/sig-estimate" "$step_deck" -o "$dir" >"$dir/estimate.log" 2>&1 ||
    { cat "$dir/estimate.log" >&2; echo "adapt.sh: step $k: sig-estimate failed" >&2; exit 1; }
  wall=$(seconds_since "$t0")
  read -r estimate step_dofs estimate_s < <(ds_values "$dir/case.est" estimate,dofs,seconds)
  [ -n "$estimate_s" ] || { echo "adapt.sh: step $k: cannot read $dir/case.est" >&2; exit 1; }
  error= effectivity=
  if [ -n "$reference" ]; then
    error=$("$bin/sig-error" --json "$dir" "$reference" |
      python3 -c 'import json, sys; print(json.load(sys.stdin)["error"])')
    effectivity=$(python3 -c "print($estimate / $error if $error > 0 else '')")
  fi
  echo "adapt.sh: step $k: $step_dofs dofs, estimate $estimate${error:+, error $error, effectivity $effectivity}"
  refine_s=0 refine_wall=0
  last=0
  [ "$k" -lt $((steps - 1)) ] || last=1
  if [ $last -eq 0 ] && [ "$dofs" -gt 0 ] && [ "$step_dofs" -ge "$dofs" ]; then
    echo "adapt.sh: $step_dofs dofs reach the budget of $dofs: stopped"
    last=1
  fi
  if [ $last -eq 0 ]; then
    t0=${EPOCHREALTIME/./}
    "$bin/sig-refine" "$step_deck" -o "$dir" --theta "$theta" --shape "$deck_path" \
      >"$dir/refine.log" 2>&1 ||
      { cat "$dir/refine.log" >&2; echo "adapt.sh: step $k: sig-refine failed" >&2; exit 1; }
    refine_wall=$(seconds_since "$t0")
    refine_s=$(sed -n 's/.*; mark and refine \([0-9.e+-]*\) s$/\1/p' "$dir/refine.log")
    [ -n "$refine_s" ] || { echo "adapt.sh: step $k: no time in $dir/refine.log" >&2; exit 1; }
  fi
  echo "$k,$step_dofs,$estimate,$error,$effectivity,$estimate_s,$refine_s,$wall,$refine_wall" >>"$csv"
  [ $last -eq 0 ] || break
done
echo "$csv"
