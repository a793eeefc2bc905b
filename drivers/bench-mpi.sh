#!/usr/bin/env bash
# drivers/bench-mpi.sh [-o OUTDIR] [--deck ball|hertz] [--h H] [--n N] [--grading G] [--repeat K]
#                      [--ranks LIST] [--analysis-only] [--rate FLOPS]: the distributed solve at
# scale (issue 27, "Scale"): sig-solve under mpirun at np = 1 and 2 on the 3D Hertz ball (or the
# 2D Hertz), MUMPS's statistics and, from them, a model of 16 to 256 processes.
#
# The deck: --deck ball (default) is the 3D Hertz half ball, datafiles/scene3d/hertz_ball.dat
# (PDAS, the candidates of initial gap <= 0.08 condensed: MUMPS's Schur complement) at mesh size H
# at the pole (default 0.04) growing by G per unit distance from it (default 0.02), with SOLVER
# linear=mumps and no VTK; --deck hertz is scene 7a's 2D Hertz, datafiles/scene7a/hertz.dat (PDAS
# gamma = 1e2, linear=mumps) at MESH N (default 2048) and grading G (default 0, the thesis's
# uniform mesh: 1.55M dofs). sig-mesh to sig-assemble run once (each stage's seconds and peak
# memory recorded: sig-mesh's include gmsh's mesh generation); then K rounds (default 3), each
# sig-solve as 1, then 2 ranks (--ranks, comma separated, 1 first) under mpirun (mpirun_ranks,
# lib/environment.sh), round robin so that load bursts on the shared machine fall on every rank
# count alike, and sig-post for summary.json. Per run: the solve's phases (summary.json `times`
# without sig-assemble's `assemble`: factorize = MUMPS's analysis and partial factorization with
# the Schur complement, frames, schur, solve = the contact Newton and the expansion), the wall
# time of the mpirun job, the peak resident memory of every rank (/usr/bin/time -f %M around each
# rank) and MUMPS's statistics (summary.json `mumps`: INFOG, RINFOG and every rank's INFO,
# RINFO). Medians over the K rounds; the parallel efficiency T_1 / (P T_P) of each phase; the load
# average before and after the timed runs; a model of 16 to 256 processes from the np = 1 runs'
# statistics and times (bench.md states it: a model, not a measurement).
#
# --analysis-only: after sig-assemble, MUMPS's analysis alone at each rank count (sig-solve with
# SIG_MUMPS_ANALYSIS, modules/solver/src/mumps_solver.cpp): its estimates of the factorization
# (RINFOG(1) flops, INFOG(20) factor entries, INFOG(5) the largest front, INFOG(16) / INFOG(17)
# the MB of the largest rank / of all: whether np = 2 fits where np = 1 does) and, with
# --rate FLOPS (the elimination's flops per second at np = 1, from the bench.md of a full run on a
# smaller mesh), the predicted np = 1 factorization seconds: a problem's size chosen before it
# runs.
#
# Writes OUTDIR/bench.md (default out/bench-mpi), the raw table OUTDIR/runs.tsv (or
# OUTDIR/analysis.tsv) and the base stages' OUTDIR/stages.tsv.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/bench-mpi.sh [-o OUTDIR] [--deck ball|hertz] [--h H] [--n N] [--grading G]
                            [--repeat K] [--ranks LIST] [--analysis-only] [--rate FLOPS]
  --deck D         ball (default): the 3D Hertz half ball; hertz: scene 7a's 2D Hertz
  --h H            ball: mesh size at the pole (default 0.04)
  --n N            hertz: boundary segments on Gamma3 (default 2048)
  --grading G      ball: growth of the mesh size per unit distance from the pole (default
                   0.02); hertz: MESH grading (default 0, the thesis's uniform mesh)
  --repeat K       rounds, medians reported (default 3)
  --ranks LIST     the numbers of ranks, comma separated, 1 first (default 1,2)
  --analysis-only  MUMPS's analysis alone at each rank count: its estimates, no factorization
  --rate FLOPS     with --analysis-only: the elimination's flops per second at np = 1, for the
                   predicted factorization seconds
  -o OUTDIR        results folder (default out/bench-mpi)
  -h, --help       this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/bench-mpi.sh${*:+ $*}"
out=out/bench-mpi
deck=ball
h=0.04
n=2048
grading=
repeat=3
ranks=1,2
analysis_only=0
rate=
parse_options --deck=deck --h=h --n=n --grading=grading --repeat=repeat --ranks=ranks \
  --rate=rate --analysis-only:analysis_only=1 -o=out -- "$@"
number='^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$'
case $deck in
  ball)
    template=$root/datafiles/scene3d/hertz_ball.dat
    grading=${grading:-0.02}
    [[ $h =~ $number ]] && "$python" -c "import sys; sys.exit(not $h > 0)" ||
      die "--h must be a positive number, got '$h'"
    ;;
  hertz)
    template=$root/datafiles/scene7a/hertz.dat
    grading=${grading:-0}
    [[ $n =~ ^[0-9]+$ ]] && [ "$n" -ge 4 ] && [ $((n % 2)) -eq 0 ] ||
      die "--n must be an even integer >= 4, got '$n'"
    ;;
  *) die "--deck must be ball or hertz, got '$deck'" ;;
esac
[[ $grading =~ $number ]] || die "--grading must be a number >= 0, got '$grading'"
[ -z "$rate" ] || [[ $rate =~ $number ]] || die "--rate must be a positive number, got '$rate'"
require_positive --repeat "$repeat"
[[ $ranks =~ ^1(,[1-9][0-9]*)*$ ]] ||
  die "--ranks must be numbers of ranks, comma separated, 1 first, got '$ranks'"
IFS=, read -r -a rank_counts <<<"$ranks"
require_stages mesh material contact assemble solve post
command -v mpirun >/dev/null || die "no mpirun (OpenMPI, drivers/setup.sh)"
[ -x /usr/bin/time ] || die "no /usr/bin/time for the peak memory (apt-get install time)"
[ "$deck" = hertz ] || command -v gmsh >/dev/null || die "gmsh is needed to mesh the half ball"
require_decks "$template"

mkdir -p "$out"
out=$(cd "$out" && pwd)
source "$root/drivers/lib/hertz_deck.sh"
base=$out/base
rm -rf "$base" "$out"/np* "$out/runs.tsv" "$out/analysis.tsv" "$out/stages.tsv" "$out/bench.md"
mkdir -p "$base"
case=$base/case.dat
if [ "$deck" = ball ]; then
  deck_variant "$template" "$case" --set MESH.h="$h" --set MESH.grading="$grading" \
    --set SOLVER.linear=mumps --set OUTPUT.vtk=no
  size="h = $h, grading $grading"
else
  hertz_deck "$template" "$case" "$n" "$grading"
  deck_variant "$case" "$case" --set OUTPUT.vtk=no
  size="N = $n, grading $grading"
fi

# seconds T0 T1: the seconds between two `date +%s%N`, to the millisecond.
seconds() {
  awk -v ns=$(($2 - $1)) 'BEGIN { printf "%.3f", ns / 1e9 }'
}

echo "bench-mpi.sh: $deck, $size: sig-mesh to sig-assemble once, in $base"
printf 'stage\tseconds\tpeak_rss_kb\n' >"$out/stages.tsv"
for stage in mesh material contact assemble; do
  t0=$(date +%s%N)
  /usr/bin/time -f %M -o "$base/$stage.rss" "$bin/sig-$stage" "$case" -o "$base" \
    >"$base/$stage.log" 2>&1 ||
    { cat "$base/$stage.log" >&2; die "sig-$stage failed (log: $base/$stage.log)"; }
  t1=$(date +%s%N)
  printf '%s\t%s\t%s\n' "$stage" "$(seconds "$t0" "$t1")" "$(tail -n1 "$base/$stage.rss")" \
    >>"$out/stages.tsv"
done
load_start=$(cut -d' ' -f1-3 /proc/loadavg)

if [ "$analysis_only" -eq 1 ]; then
  printf 'ranks\tn\tschur\tordering\tseconds\tflops\tentries\tlargest_front\ttree_nodes\tmb_max\tmb_total\n' \
    >"$out/analysis.tsv"
  for np in "${rank_counts[@]}"; do
    echo "bench-mpi.sh: MUMPS's analysis alone at np = $np (load average" \
      "$(cut -d' ' -f1-3 /proc/loadavg))"
    rm -f "$base/analysis.$np.tsv"
    SIG_MUMPS_ANALYSIS=$base/analysis.$np.tsv mpirun_ranks "$np" "$bin/sig-solve" "$case" \
      -o "$base" >"$base/analysis.$np.log" 2>&1 ||
      { cat "$base/analysis.$np.log" >&2; die "the analysis failed (log: $base/analysis.$np.log)"; }
    [ "$(wc -l <"$base/analysis.$np.tsv")" -eq 1 ] ||
      die "sig-solve ran no MUMPS analysis, or more than one (log: $base/analysis.$np.log)"
    printf '%s\t%s\n' "$np" "$(cat "$base/analysis.$np.tsv")" >>"$out/analysis.tsv"
  done
else
  for np in "${rank_counts[@]}"; do
    mkdir -p "$out/np$np"
    link_ds ../base "$out/np$np" nopo mili cont tae
    cp "$case" "$out/np$np/case.dat"
  done

  # The peak resident memory of each rank (KB), in PREFIX.<rank>: /usr/bin/time around the rank.
  # shellcheck disable=SC2016 # expanded by the rank's shell
  per_rank_time='exec /usr/bin/time -f %M -o "$0.$OMPI_COMM_WORLD_RANK" "$@"'

  printf 'ranks\trun\twall_s\tpeak_rss_kb\tsummary\n' >"$out/runs.tsv"
  for k in $(seq 1 "$repeat"); do
    for np in "${rank_counts[@]}"; do
      dir=$out/np$np
      echo "bench-mpi.sh: round $k of $repeat, np = $np: starts at $(date -u +%H:%M:%S)" \
        "(load average $(cut -d' ' -f1-3 /proc/loadavg))"
      t0=$(date +%s%N)
      if ! mpirun_ranks "$np" bash -c "$per_rank_time" "$dir/rss.$k" "$bin/sig-solve" \
        "$dir/case.dat" -o "$dir" >"$dir/solve.$k.log" 2>&1; then
        cat "$dir/solve.$k.log" >&2
        die "sig-solve failed at np = $np (log: $dir/solve.$k.log)"
      fi
      t1=$(date +%s%N)
      run_stage post "$dir/case.dat" "$dir" || die "sig-post failed at np = $np"
      cp "$dir/summary.json" "$dir/summary.$k.json"
      rss=$(for r in $(seq 0 $((np - 1))); do tail -n1 "$dir/rss.$k.$r"; done | paste -sd,)
      wall=$(seconds "$t0" "$t1")
      printf '%s\t%s\t%s\t%s\t%s\n' "$np" "$k" "$wall" "$rss" "$dir/summary.$k.json" \
        >>"$out/runs.tsv"
      echo "bench-mpi.sh: round $k of $repeat, np = $np: mpirun $wall s, peak RSS per rank" \
        "$rss KB"
    done
  done
fi
{
  bench_provenance
  echo "deck: $deck"
  echo "size: $size"
  echo "rate: $rate"
  echo "load_start: $load_start"
  echo "load_end: $(cut -d' ' -f1-3 /proc/loadavg)"
} >"$out/command.txt"

"$python" "$root/postproc/bench_mpi_report.py" "$out"
