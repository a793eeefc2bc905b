#!/usr/bin/env bash
# drivers/friction_hertz.sh [--quick] [-o OUTDIR]: the frictional Hertz half disc (issue 10,
# datafiles/friction/hertz_coulomb.dat): pressed and pushed sideways, held by contact and Coulomb
# friction alone; every method, the stick and slip zones against Cattaneo and Mindlin, then the
# report.
#
#   full:    N = 128 256 512, reference N = 1024
#   --quick: N = 128 256,     reference N = 512
#
# Runs (each in OUTDIR/N<N>/<variant>/ on the base DS files of OUTDIR/N<N>/base/, as scene7a.sh):
#   pdas_1e2, alm_1e2, projection_1, penalty_1e2    every N (the parameters that converge on this
#                                                  body held by friction alone: the sweep shows
#                                                  where the others fail)
#   a parameter sweep at N = 256: pdas gamma, alm r in 1 1e2 1e4, projection c in 1e2 1 1e-2
#   1e-4, penalty r in 1e1 1e2 1e3 1e4 1e6; each with the default line search (SOLVER
#   search=auto, <method>_<value>), with a line search (search=yes, <method>_<value>_search) and
#   with full Newton steps (search=no, <method>_<value>_full)
#   pdas_1e2_from_zero at N = 256: the Newton from u = 0 instead of the rigid shift (a single
#                                   node touches: the same solution, the count beside)
#   tresca_pdas_1e2 at N = 256:     the Tresca law with threshold 1 GPa instead of Coulomb
# Every run starts from the rigid shift u = (0, -h^2 / R), h = pi R / N (the INITIAL card).
# Then postproc/friction_hertz_report.py OUTDIR writes OUTDIR/report.md, its PNGs and
# OUTDIR/scene.json.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/friction_hertz.sh [--quick] [-o OUTDIR]
  --quick     N = 128 256, reference 512 (instead of 128 256 512, reference 1024)
  -o OUTDIR   results folder (default out/friction_hertz)
  -h, --help  this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/friction_hertz.sh${*:+ $*}"
template=$root/datafiles/friction/hertz_coulomb.dat
parse_quick_out out/friction_hertz "$@"

require_stages mesh material contact assemble solve post
require_decks "$template"
require_charts

if [ $quick -eq 1 ]; then
  meshes=(128 256)
  reference=512
else
  meshes=(128 256 512)
  reference=1024
fi
sweep_n=256
declare -A sweep=([pdas]="1 1e2 1e4" [alm]="1 1e2 1e4" [projection]="1e2 1 1e-2 1e-4"
  [penalty]="1e1 1e2 1e3 1e4 1e6")
declare -A default=([pdas]=1e2 [alm]=1e2 [projection]=1 [penalty]=1e2)

mkdir -p "$out"
out=$(cd "$out" && pwd)
source "$root/drivers/lib/hertz_deck.sh"

deck_value "$template" INITIAL u >/dev/null || die "$template: no INITIAL u= card (the rigid start shift)"

# write_deck DECK N [METHOD VALUE [EDIT...]]: the template for mesh N with its rigid shift, the
# method and parameter (hertz_deck), and further deck edits (deck_variant's --set, --drop, ...).
write_deck() {
  local deck=$1 n=$2 method=${3:-} value=${4:-}
  hertz_deck "$template" "$deck" "$n" "" "$method" "$value"
  [ $# -le 4 ] || deck_variant "$deck" "$deck" "${@:5}"
}

failed=()

# base N: mesh, materials, contact elements and the assembled system in OUTDIR/N<N>/base.
base() {
  local n=$1 dir=$out/N$1/base
  rm -rf "$dir"
  mkdir -p "$dir"
  write_deck "$dir/hertz.dat" "$n"
  build_base "$dir/hertz.dat" "$dir" "the base case of N = $n"
  progress_step "${dir#"$out"/}"
}

# variant N NAME METHOD VALUE [EDIT...]: sig-solve and sig-post in OUTDIR/N<N>/NAME/ on the base
# DS files (with edits of the FRICTION card, its own case.cont).
variant() {
  local n=$1 name=$2 dir=$out/N$1/$2
  rm -rf "$dir"
  mkdir -p "$dir"
  link_ds ../base "$dir" nopo mili cont tae
  write_deck "$dir/hertz.dat" "$n" "${@:3}"
  if ! cmp -s <(grep -iE '^[[:space:]]*(contact|friction)' "$dir/hertz.dat") \
    <(grep -iE '^[[:space:]]*(contact|friction)' "$out/N$n/base/hertz.dat"); then
    rm "$dir/case.cont"
    run_stage contact "$dir/hertz.dat" "$dir" || failed+=("$dir")
  fi
  run_stage solve "$dir/hertz.dat" "$dir" && run_stage post "$dir/hertz.dat" "$dir" ||
    failed+=("$dir")
  progress_step "${dir#"$out"/}"
}

{
  provenance
  echo "meshes: ${meshes[*]}"
  echo "reference: $reference"
  echo "sweep_n: $sweep_n"
} >"$out/command.txt"
cp "$template" "$out/hertz.template.dat"

rm -rf "$out"/N[0-9]*
# Runs: per mesh a base and the 4 methods, the reference's base and pdas, and at N = sweep_n
# each swept value with and without the search, the run from zero and Tresca.
runs=$((5 * ${#meshes[@]} + 2 + 2))
for method in "${!sweep[@]}"; do
  for value in ${sweep[$method]}; do
    runs=$((runs + 2))
  done
done
progress_begin $runs
start=$SECONDS
for n in "${meshes[@]}" "$reference"; do
  t0=$SECONDS
  base "$n"
  if [ "$n" = "$reference" ]; then
    variant "$n" pdas_1e2 pdas 1e2
  else
    for method in pdas alm projection penalty; do
      variant "$n" "${method}_${default[$method]}" "$method" "${default[$method]}"
    done
  fi
  if [ "$n" = "$sweep_n" ]; then
    for method in pdas alm projection penalty; do
      # search=auto is search=yes with friction, but for penalty (contact_newton.cpp,
      # newton_options): the sweep's plain runs are links to those, not solved again.
      same_as_auto=search
      [ "$method" != penalty ] || same_as_auto=full
      for value in ${sweep[$method]}; do
        variant "$n" "${method}_${value}_search" "$method" "$value" --set SOLVER.search=yes
        variant "$n" "${method}_${value}_full" "$method" "$value" --set SOLVER.search=no
        [ "$value" = "${default[$method]}" ] ||
          ln -s "${method}_${value}_$same_as_auto" "$out/N$n/${method}_$value"
      done
    done
    variant "$n" pdas_1e2_from_zero pdas 1e2 --drop-card INITIAL
    variant "$n" tresca_pdas_1e2 pdas 1e2 --set FRICTION.law=tresca --drop FRICTION.mu \
      --set FRICTION.threshold=1
  fi
  echo "friction_hertz.sh: N = $n done ($((SECONDS - t0)) s)"
done
echo "friction_hertz.sh: all runs done in $((SECONDS - start)) s"
record_seconds $start

"$python" "$root/postproc/friction_hertz_report.py" "$out"
if [ ${#failed[@]} -gt 0 ]; then
  die "${#failed[@]} run(s) failed: ${failed[*]}"
fi
