#!/usr/bin/env bash
# drivers/bench-impact3d.sh [--quick] [--repeat N] [--mesh "H GRADING"] [-o OUTDIR]: the speed
# target of issue 28 for the 3D ball impact, "the 3D impact march per step within 1.5x a
# contact-free step (as measured in 2D)": drivers/bench-ball.sh's measure (scene 8a) on
# datafiles/scene3d/ball_impact.dat.
#
# Cases, each a sig-march of the deck on one half-ball mesh (default (h, grading) = (0.07, 0.1),
# scene3d_impact.sh's finest, 19167 dofs; --quick (0.25, 0.3), 1338 dofs):
#   no-contact  the same march without the CONTACT card (the ball flies through the plane, the
#               consistent mass): every step one solve with the factorized step matrix, the
#               contact-free step of the comparison;
#   <strategy>  every strategy of drivers/scene3d_impact.sh (signorini, compliance,
#               specific-penalty, emm, two-step, two-step-increment, ipm, ipm-emm).
# Per run: the wall time of sig-march (reading the DS files, factorizing, marching, writing
# case.hist) and, from case.hist's step_seconds and energy.csv's active nodes, the mean time of its
# steps in contact and of its steps in free flight. Ratios, each dividing two times of this one
# script run: the march per step against the contact-free march per step (bench-ball.sh's ratio,
# the 2D measure), and a step in contact against a contact-free step (the mean step of the
# no-contact run), the stricter one. Median of N runs (default 5), round robin (run i of every case
# before run i + 1 of any), so that a burst of load on the shared machine falls on all cases alike.
# Nothing is asserted: OUTDIR/report.md (default out/bench-impact3d) marks each ratio against 1.5;
# OUTDIR/bench.csv has every run. The load average is recorded: quote numbers of a quiet machine,
# or label them loaded.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3), SIG_GMSH.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/bench-impact3d.sh [--quick] [--repeat N] [--mesh "H GRADING"] [-o OUTDIR]
  --quick            the coarse mesh (0.25, 0.3) instead of (0.07, 0.1)
  --repeat N         runs per case, the median is reported (default 5)
  --mesh "H GRADING" the half ball's mesh size at the pole and its grading
  -o OUTDIR          results folder (default out/bench-impact3d)
Environment: SIG_BIN, PYTHON, SIG_GMSH (default gmsh: the half ball's mesher).
EOF
}

invocation="drivers/bench-impact3d.sh${*:+ $*}"
out=out/bench-impact3d
repeat=5
mesh="0.07 0.1"
parse_options --quick:mesh="0.25 0.3" --repeat=repeat --mesh=mesh -o=out -- "$@"
require_positive --repeat "$repeat"
read -r h grading extra <<<"$mesh"
[ -n "$grading" ] && [ -z "${extra:-}" ] || die "--mesh takes \"H GRADING\", got '$mesh'"
require_stages mesh material contact assemble march dump
template=$root/datafiles/scene3d/ball_impact.dat
require_decks "$template"
command -v "${SIG_GMSH:-gmsh}" >/dev/null || die "gmsh is needed to mesh the half ball"
mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -rf "$out/base" "$out/runs"
mkdir -p "$out/base" "$out/runs"

deck_variant "$template" "$out/base/ball_impact.dat" --set MESH.h="$h" --set MESH.grading="$grading"
build_base "$out/base/ball_impact.dat" "$out/base" "the half ball (h = $h, grading = $grading)" \
  mesh material assemble
point=$(deck_value "$template" CONTACT point) || die "no CONTACT point= in $template"

# case -> "CONTACT fields|mass": drivers/scene3d_impact.sh's strategies; no-contact has none.
source "$root/drivers/lib/impact3d.sh"
declare -A fields=([no-contact]="|consistent")
for name in "${impact3d_methods[@]}"; do fields[$name]=${impact3d_fields[$name]}; done
cases=(no-contact "${impact3d_methods[@]}")
for name in "${cases[@]}"; do
  dir=$out/runs/$name
  mkdir -p "$dir"
  link_ds ../../base "$dir" nopo mili tae
  f=${fields[$name]}
  if [ -n "${f%|*}" ]; then
    deck_variant "$out/base/ball_impact.dat" "$dir/ball_impact.dat" --set TIME.mass="${f#*|}" \
      --replace-card CONTACT "CONTACT ref=3 obstacle=plane point=$point normal=0,0,1 ${f%|*}"
    run_stage contact "$dir/ball_impact.dat" "$dir" || die "sig-contact failed: $name"
  else
    deck_variant "$out/base/ball_impact.dat" "$dir/ball_impact.dat" --set TIME.mass="${f#*|}" \
      --drop-card CONTACT --drop-card SOLVER
  fi
done

bench_provenance >"$out/command.txt"
echo "mesh: h = $h, grading = $grading" >>"$out/command.txt"
echo "case,run,wall_seconds,steps,contact_steps,contact_step_seconds,free_step_seconds,load" \
  >"$out/bench.csv"
for ((i = 1; i <= repeat; i++)); do
  for name in "${cases[@]}"; do
    dir=$out/runs/$name
    t0=$(date +%s.%N)
    "$bin/sig-march" "$dir/ball_impact.dat" -o "$dir" >"$dir/march.log" 2>&1 ||
      die "sig-march failed: $name (see $dir/march.log)"
    t1=$(date +%s.%N)
    load=$(cut -d' ' -f1 /proc/loadavg)
    echo "$name,$i,$("$python" "$root/postproc/bench_impact3d.py" row "$dir" "$t0" "$t1"),$load" \
      >>"$out/bench.csv"
  done
  echo "bench-impact3d.sh: round $i of $repeat done (load $(cut -d' ' -f1-3 /proc/loadavg))"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$out/command.txt"

"$python" "$root/postproc/bench_impact3d.py" report "$out"
