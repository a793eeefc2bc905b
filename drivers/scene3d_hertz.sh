#!/usr/bin/env bash
# drivers/scene3d_hertz.sh [--quick] [-o OUTDIR]: the Hertz half ball (issue 26, "Hertz ball"; the
# 3D scene 7a, datafiles/scene3d/hertz_ball.dat) with the four contact methods on a ladder of
# meshes graded towards the contact, then its report beside Hertz's analytic values.
#
#   full:    meshes (h, grading) = (0.16, 0.3) (0.08, 0.2) (0.04, 0.1) (0.03, 0.075) (0.02, 0.05)
#   --quick: meshes (h, grading) = (0.16, 0.3) (0.08, 0.2)
#
# Per mesh the bulk stages run once into OUTDIR/m<k>/base/: sig-mesh, then the pressure of the
# deck is set to P / |top| of that mesh (its flat top is a polygon inscribed in the circle, 0.7 %
# smaller at the cap R / 4), so that every mesh carries the total P = 14 of Hertz's a = R / 10;
# then sig-material, sig-contact and sig-assemble. Each method then gets OUTDIR/m<k>/<method>/
# with symlinks to the base DS files, its own deck and what sig-solve and sig-post write there:
#   pdas gamma = 1e2, alm r = 1e2, projection c = 1e2 (the exact methods, their defaults) and
#   penalty r = 1e6 (its pressures differ from the exact ones by O(k / r)),
# all with the deck's SOLVER candidate_gap=0.08. Then postproc/hertz3d_report.py OUTDIR writes
# OUTDIR/report.md, its PNGs and OUTDIR/scene.json.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/scene3d_hertz.sh [--quick] [-o OUTDIR]
  --quick     the two coarsest meshes only (a few seconds)
  -o OUTDIR   results folder (default out/scene3d_hertz)
  -h, --help  this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/scene3d_hertz.sh${*:+ $*}"
template=$root/datafiles/scene3d/hertz_ball.dat
parse_quick_out out/scene3d_hertz "$@"

require_half_ball_scene

# The ladder: (h at the pole, grading), each mesh about 3x the dofs of the one before.
if [ $quick -eq 1 ]; then
  meshes=("0.16 0.3" "0.08 0.2")
else
  meshes=("0.16 0.3" "0.08 0.2" "0.04 0.1" "0.03 0.075" "0.02 0.05")
fi
methods=(pdas alm projection penalty)
declare -A value=([pdas]=1e2 [alm]=1e2 [projection]=1e2 [penalty]=1e6)
P=14

mkdir -p "$out"
out=$(cd "$out" && pwd)
failed=()

# top_pressure NOPO: P / |top|, |top| the area of the boundary triangles of reference 2.
top_pressure() {
  "$bin/sig-dump" --json --values "$1" | "$python" -c "
import json, sys
import numpy as np
dump = json.load(sys.stdin)
x = np.asarray(dump['coordinates'], dtype=float).reshape(-1, 3)
faces = np.asarray(dump['faces'], dtype=int).reshape(-1, 4)  # nodes from 1, reference
top = faces[faces[:, 3] == 2, :3] - 1
area = 0.5 * np.linalg.norm(np.cross(x[top[:, 1]] - x[top[:, 0]], x[top[:, 2]] - x[top[:, 0]]), axis=1).sum()
print(repr($P / area))"
}

ladder_begin hertz_ball "P: $P"
start=$SECONDS
k=0
for mesh in "${meshes[@]}"; do
  ladder_mesh "$mesh" hertz_ball --set OUTPUT.vtk=no
  build_base "$base/hertz_ball.dat" "$base" "the mesh of h = $h, grading = $grading" mesh
  pressure=$(top_pressure "$base/case.nopo") || die "cannot measure the top face of $base/case.nopo"
  deck_variant "$base/hertz_ball.dat" "$base/hertz_ball.dat" --set PRESSURE.p="$pressure"
  build_base "$base/hertz_ball.dat" "$base" "the base case of h = $h" material contact assemble
  progress_step "m$k/base (h = $h, grading = $grading)"
  for method in "${methods[@]}"; do
    dir=$out/m$k/$method
    mkdir -p "$dir"
    link_ds ../base "$dir" nopo mili cont tae
    deck_variant "$base/hertz_ball.dat" "$dir/hertz_ball.dat" --set SOLVER.method="$method" \
      --set "SOLVER.$(parameter_of "$method")=${value[$method]}"
    # vtk on the finest mesh's PDAS run only: the .vtu of the others adds time, not insight.
    [ "$k" -ne ${#meshes[@]} ] || [ "$method" != pdas ] ||
      deck_variant "$dir/hertz_ball.dat" "$dir/hertz_ball.dat" --set OUTPUT.vtk=yes
    run_timed solve "$dir/hertz_ball.dat" "$dir" && run_stage post "$dir/hertz_ball.dat" "$dir" ||
      failed+=("$dir")
    progress_step "m$k/$method"
  done
  echo "scene3d_hertz.sh: mesh $k (h = $h, grading = $grading) done ($((SECONDS - t0)) s)"
done
echo "scene3d_hertz.sh: all runs done in $((SECONDS - start)) s"
record_seconds $start

"$python" "$root/postproc/hertz3d_report.py" "$out"
if [ ${#failed[@]} -gt 0 ]; then
  die "${#failed[@]} run(s) failed: ${failed[*]}"
fi
