#!/usr/bin/env bash
# drivers/scene3d_cattaneo.sh [--quick] [-o OUTDIR]: Cattaneo-Mindlin on the Hertz half ball
# (issue 26, "Cattaneo-Mindlin"; datafiles/scene3d/cattaneo_mindlin.dat): the ball's clamped top
# pressed and sheared, Coulomb friction on the rigid flat, PDAS; then its report beside Cattaneo
# and Mindlin's stick radius.
#
#   full:    nu = 0.45 on the meshes (h, grading) = (0.16, 0.3) (0.08, 0.2) (0.04, 0.1)
#            (0.03, 0.075); nu = 0.3 and 0.4 on (0.04, 0.1) (the nu trend)
#   --quick: nu = 0.45 on (0.16, 0.3) (0.08, 0.2); nu = 0.3 and 0.4 on (0.08, 0.2)
#
# Per mesh sig-mesh runs once into OUTDIR/mesh_<h>/; each run OUTDIR/h<h>_nu<nu>/ links its
# case.nopo and runs sig-material, sig-contact, sig-assemble, sig-solve and sig-post on the deck
# with that mesh and nu. Then postproc/cattaneo3d_report.py OUTDIR writes OUTDIR/report.md, its
# PNGs, summary.json and scene.json.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

template=$root/datafiles/scene3d/cattaneo_mindlin.dat
# Runs: "h grading nu"; the ladder at the deck's nu = 0.45, the trend (nu = 0.3, 0.4 and 0.45) on
# one mesh; the last run is the ladder's finest mesh (the only one with vtk output).
quick_runs=("0.16 0.3 0.45" "0.08 0.2 0.3" "0.08 0.2 0.4" "0.08 0.2 0.45")
full_runs=("0.16 0.3 0.45" "0.08 0.2 0.45" "0.04 0.1 0.3" "0.04 0.1 0.4" "0.04 0.1 0.45"
  "0.03 0.075 0.45")

usage() {
  cat <<EOF
usage: drivers/scene3d_cattaneo.sh [--quick] [-o OUTDIR]
Cattaneo-Mindlin on the Hertz half ball (datafiles/scene3d/cattaneo_mindlin.dat), then its report.
  --quick     the two coarsest meshes only (about 10 s)
  -o OUTDIR   results folder (default out/scene3d_cattaneo)
  -h, --help  this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/scene3d_cattaneo.sh${*:+ $*}"
parse_quick_out out/scene3d_cattaneo "$@"

require_half_ball_scene

if [ $quick -eq 1 ]; then
  runs=("${quick_runs[@]}")
else
  runs=("${full_runs[@]}")
fi

mkdir -p "$out"
out=$(cd "$out" && pwd)
failed=()
listed=()
for run in "${runs[@]}"; do
  read -r h grading nu <<<"$run"
  listed+=("h${h}_nu$nu $h $grading $nu")
done
{
  provenance
  echo "runs: $(printf '%s;' "${listed[@]}" | sed 's/;$//')"
} >"$out/command.txt"
cp "$template" "$out/cattaneo_mindlin.template.dat"

rm -rf "$out"/mesh_* "$out"/h[0-9]*
progress_begin ${#runs[@]}
start=$SECONDS
for run in "${runs[@]}"; do
  read -r h grading nu <<<"$run"
  t0=$SECONDS
  mesh=$out/mesh_$h
  if [ ! -d "$mesh" ]; then
    mkdir -p "$mesh"
    deck_variant "$template" "$mesh/cattaneo_mindlin.dat" --set MESH.h="$h" \
      --set MESH.grading="$grading"
    build_base "$mesh/cattaneo_mindlin.dat" "$mesh" "the mesh of h = $h, grading = $grading" mesh
  fi
  dir=$out/h${h}_nu$nu
  mkdir -p "$dir"
  link_ds "../mesh_$h" "$dir" nopo
  deck_variant "$mesh/cattaneo_mindlin.dat" "$dir/cattaneo_mindlin.dat" --set MATERIAL.nu="$nu"
  # vtk on the ladder's finest mesh only (the last run).
  [ "$run" = "${runs[-1]}" ] ||
    deck_variant "$dir/cattaneo_mindlin.dat" "$dir/cattaneo_mindlin.dat" --set OUTPUT.vtk=no
  for stage in material contact assemble solve post; do
    if [ $stage = solve ]; then
      run_timed solve "$dir/cattaneo_mindlin.dat" "$dir" || { failed+=("$dir"); break; }
    else
      run_stage $stage "$dir/cattaneo_mindlin.dat" "$dir" || { failed+=("$dir"); break; }
    fi
  done
  progress_step "h = $h, nu = $nu ($((SECONDS - t0)) s)"
done
echo "scene3d_cattaneo.sh: all runs done in $((SECONDS - start)) s"
record_seconds $start

"$python" "$root/postproc/cattaneo3d_report.py" "$out"
if [ ${#failed[@]} -gt 0 ]; then
  die "${#failed[@]} run(s) failed: ${failed[*]}"
fi
