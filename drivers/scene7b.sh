#!/usr/bin/env bash
# drivers/scene7b.sh [--quick | --full] [-o OUTDIR]: the hyperelastic ring of thesis ch. 7.4.2
# (scene 7b, ../shared/SCENES.md) with the methods and parameters of Tables 7.4 and 7.5, in one
# load step as the thesis ran it, and the same runs in 14 load steps beside them; then its report.
#
#   default: N = 128 256       (about 1 min on 2 cores)
#   --quick: N = 128           (about 15 s)
#   --full:  N = 128 256 512   (about 5 min: the projection method at c = 1e2 in 14 load steps
#                               needs ~100 Newton iterations per load step)
#
# Per N the bulk stages (sig-mesh, sig-material, sig-contact, sig-assemble) run once into
# OUTDIR/N<N>/base/; each method and parameter then gets OUTDIR/N<N>/<method>[_<value>]/ with
# symlinks to the base DS files, its own deck (datafiles/scene7b/ring.dat with N, method and
# parameter replaced: one load step, the deck's reading of the thesis), the case.b of sig-solve
# and the summary.json + contact.csv of sig-post; the same runs in the labelled variant
# LOADSTEPS n=14 go to OUTDIR/loadsteps14/N<N>/<method>[_<value>]/ (the robust path a user would
# take for a harder crush: what load stepping costs and buys). The runs of Figs 7.13-7.16 (pdas
# and projection at 1e4, alm) also get ring.pvd with one ring_NNNN.vtu per load step, and run
# once more from rest (LOADSTEPS start=rest, OUTDIR/rest/N<N>/<run>/) beside the deck's start,
# the small-strain solution: what the first iterate costs and buys.
#
#   pdas        gamma in 1 10 1e2 1e3 1e4 1e5 1e6   (Table 7.5, and gamma = 1)
#   projection  c     in 1 10 1e2 1e3 1e4 1e5 1e6   (Table 7.4, and c = 1)
#   alm         r = 1e3                             (the ALM column of Table 7.4; the thesis does
#                                                    not print its r)
# Every run is bounded by the deck's maxit (Newton iterations per load step, 200): a run that
# does not converge within it stops at that step as "Nv", the later steps are not attempted.
# The rings next to the largest N (N - 8, - 4, - 2, + 2, + 4, + 8, with its layers) get PDAS
# gamma = 1e4, projection c = 1e4 and 1e5 and ALM in one step (OUTDIR/neighbours/N<n>/): how far
# a count moves with the number of nodes around the ring alone.
# When /usr/bin/python3 imports getfem, postproc/getfem_ring.py solves the one-step crush on the
# same mesh per N (OUTDIR/N<N>/getfem.json: its Newton iterations and reaction beside ours).
# The accuracy of each run is measured against OUTDIR/reference: PDAS gamma = 1e4 in one load
# step on the next finer ring, N = 2 x (largest N) (512 by default, 256 quick, 1024 full), whose
# Gamma3 nodes include those of every coarser ring (the grid is halved exactly): error of the
# vertical reaction on AB and of the final pressure at the shared nodes, charted against the
# solve time.
# Then postproc/scene7b_report.py OUTDIR writes OUTDIR/report.md, its PNG charts and
# OUTDIR/scene.json (the scene index entry; OUTDIR/command.txt says how the runs were made).
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/scene7b.sh [--quick | --full] [-o OUTDIR]
  --quick     N = 128 instead of 128 256
  --full      N = 128 256 512
  -o OUTDIR   results folder (default out/scene7b)
  -h, --help  this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/scene7b.sh${*:+ $*}"
out=$root/out/scene7b
sizes=(128 256)
while [ $# -gt 0 ]; do
  case $1 in
    --quick) sizes=(128) ;;
    --full) sizes=(128 256 512) ;;
    -o) [ $# -ge 2 ] || die "-o needs a folder"; out=$2; shift ;;
    -h | --help) usage; exit 0 ;;
    *) usage >&2; exit 2 ;;
  esac
  shift
done
template=$root/datafiles/scene7b/ring.dat
[ -r "$template" ] || die "cannot read $template"
require_stages mesh material contact assemble solve post
require_charts

# deck TEMPLATE OUTPUT N METHOD FIELD VALUE VTK STEPS [START]: the template with MESH N= and the
# SOLVER card's method and parameter replaced (any r=, gamma=, c= of the template dropped),
# OUTPUT vtk=VTK, LOADSTEPS n=STEPS (and start=START if given); MESH layers=$mesh_layers when
# that is set (the neighbouring meshes keep the largest N's layers).
mesh_layers=
deck() {
  deck_variant "$1" "$2" --set "MESH.N=$3" --drop SOLVER.gamma --drop SOLVER.c --drop SOLVER.r \
    --set "SOLVER.method=$4" --set "SOLVER.$5=$6" --set "OUTPUT.vtk=$7" --set "LOADSTEPS.n=$8" \
    ${9:+--set "LOADSTEPS.start=$9"} ${mesh_layers:+--set "MESH.layers=$mesh_layers"}
}

declare -A field=([pdas]=gamma [projection]=c [alm]=r)
declare -A values=([pdas]="1 10 1e2 1e3 1e4 1e5 1e6" [projection]="1 10 1e2 1e3 1e4 1e5 1e6" [alm]="1e3")
steps=$(deck_value "$template" LOADSTEPS n) || die "$template: no LOADSTEPS n="
variant_steps=14
[ "$steps" != "$variant_steps" ] || die "$template: LOADSTEPS n=$steps is already the variant's"
getfem=0
if /usr/bin/python3 -c 'import getfem' 2>/dev/null; then getfem=1; fi
rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd)
{
  provenance
  echo "sizes: ${sizes[*]}"
  echo "load steps: $steps (variant $variant_steps in loadsteps$variant_steps/)"
} >"$out/command.txt"
start=$SECONDS

# run ROOT BASE N METHOD VALUE STEPS [START] [VTK]: one solve (deck, sig-solve, sig-post) of
# the ring at N in ROOT/N<N>/<method>[_<value>]/, on the DS files of BASE; VTK output for the
# figure runs (alm and 1e4) unless VTK says no.
run() {
  local root_dir=$1 base_dir=$2 n=$3 method=$4 value=$5 nsteps=$6 first=${7:-} vtk=${8:-} dir ds
  if [ "$method" = alm ]; then dir=$root_dir/N$n/alm; else dir=$root_dir/N$n/${method}_$value; fi
  mkdir -p "$dir"
  for ds in nopo mili cont tae; do ln -s "$base_dir/case.$ds" "$dir/case.$ds"; done
  if [ -z "$vtk" ]; then
    vtk=no
    if [ "$method" = alm ] || [ "$value" = 1e4 ]; then vtk=yes; fi
  fi
  deck "$template" "$dir/ring.dat" "$n" "$method" "${field[$method]}" "$value" "$vtk" "$nsteps" \
    "$first"
  "$bin/sig-solve" "$dir/ring.dat" -o "$dir" >"$dir/solve.log" 2>&1 ||
    die "sig-solve failed for N = $n $method $value, $nsteps load steps (see $dir/solve.log)"
  "$bin/sig-post" "$dir/ring.dat" -o "$dir" >"$dir/post.log" 2>&1 ||
    die "sig-post failed for N = $n $method $value, $nsteps load steps (see $dir/post.log)"
  echo "N=$n $method ${field[$method]}=$value: $(grep -o '[0-9/]* load steps.*' "$dir/solve.log" | sed 's/, solve.*//')"
  progress_step "${dir#"$out"/}"
}

# base DIR N: the bulk stages of the ring at N into DIR.
base() {
  local stage
  mkdir -p "$1"
  deck "$template" "$1/ring.dat" "$2" pdas gamma 1e3 no "$steps"
  for stage in mesh material contact assemble; do
    "$bin/sig-$stage" "$1/ring.dat" -o "$1" >"$1/$stage.log" 2>&1 ||
      die "sig-$stage failed at N = $2 (see $1/$stage.log)"
  done
  progress_step "${1#"$out"/}"
}

# sweep ROOT N STEPS BASE [START]: every method and parameter at N in STEPS load steps, into
# ROOT/N<N>/; with START (rest), only the three runs of Figs 7.13-7.16 from that first iterate.
sweep() {
  local root_dir=$1 n=$2 nsteps=$3 base_dir=$4 first=${5:-} method value
  for method in pdas alm projection; do
    local chosen=${values[$method]}
    if [ -n "$first" ] && [ "$method" != alm ]; then chosen=1e4; fi
    for value in $chosen; do
      run "$root_dir" "$base_dir" "$n" "$method" "$value" "$nsteps" "$first"
    done
  done
}

# Runs: per mesh a base, 15 runs in one step, 15 in the variant, 3 from rest, GetFEM; the
# neighbours of the largest N; then the reference.
neighbour_offsets=(-8 -4 -2 2 4 8)
neighbour_runs=("pdas 1e4" "projection 1e4" "projection 1e5" "alm 1e3")
progress_begin $((35 * ${#sizes[@]} + ${#neighbour_offsets[@]} * (1 + ${#neighbour_runs[@]}) + 1))
for n in "${sizes[@]}"; do
  base "$out/N$n/base" "$n"
  sweep "$out" "$n" "$steps" "$out/N$n/base"
  sweep "$out/loadsteps$variant_steps" "$n" "$variant_steps" "$out/N$n/base"
  sweep "$out/rest" "$n" "$steps" "$out/N$n/base" rest
  if [ $getfem -eq 1 ]; then
    /usr/bin/python3 "$root/postproc/getfem_ring.py" --deck "$out/N$n/base/ring.dat" --repeat 1 \
      --json "$out/N$n/getfem.json" >"$out/N$n/getfem.log" 2>&1 ||
      die "postproc/getfem_ring.py failed at N = $n (see $out/N$n/getfem.log)"
    tail -1 "$out/N$n/getfem.log"
  else
    echo "scene7b.sh: /usr/bin/python3 cannot import getfem: no GetFEM comparison at N = $n"
  fi
  progress_step "N$n/getfem"
done

# The count's spread: the figure runs and projection c = 1e5 in one step on the rings next to the
# largest N, into OUTDIR/neighbours/N<n>/. A count of a Newton whose active set crosses a wide arc
# is one sample; these say how far it moves with the number of nodes around the ring alone (the
# layers through the thickness are the largest N's: the generator's default, 3 N / 64 + 1, would
# change them too).
n_top=${sizes[${#sizes[@]} - 1]}
mesh_layers=$((3 * n_top / 64 + 1))
for offset in "${neighbour_offsets[@]}"; do
  n=$((n_top + offset))
  base "$out/neighbours/N$n/base" "$n"
  for spec in "${neighbour_runs[@]}"; do
    read -r method value <<<"$spec"
    run "$out/neighbours" "$out/neighbours/N$n/base" "$n" "$method" "$value" "$steps" "" no
  done
done
mesh_layers=

# The reference for the accuracy: PDAS on the ring with twice the largest N.
n_ref=$((2 * sizes[${#sizes[@]} - 1]))
reference=$out/reference
mkdir -p "$reference"
deck "$template" "$reference/ring.dat" "$n_ref" pdas gamma 1e4 no "$steps"
for stage in mesh material contact assemble solve post; do
  "$bin/sig-$stage" "$reference/ring.dat" -o "$reference" >"$reference/$stage.log" 2>&1 ||
    die "sig-$stage failed for the reference N = $n_ref (see $reference/$stage.log)"
done
echo "reference N=$n_ref pdas gamma=1e4: $(grep -o '[0-9/]* load steps.*' "$reference/solve.log" | sed 's/, solve.*//')"
progress_step reference
record_seconds $start
"$python" "$root/postproc/scene7b_report.py" "$out"
