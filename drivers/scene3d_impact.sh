#!/usr/bin/env bash
# drivers/scene3d_impact.sh [--quick] [--friction] [-o OUTDIR]: the ball impact in 3D (issue 28,
# "Ball impact"; datafiles/scene3d/ball_impact.dat): scene 8a's ball and speed on the rigid plane
# with every contact strategy of scene 8a, on a ladder of half-ball meshes graded towards the
# pole, then its report beside Hertz's impact time.
#
# --friction: the oblique frictional impact instead (datafiles/scene3d/oblique_impact.dat: the
# same ball at (3, 4, -10) m/s, Coulomb mu = 0.3) with the same strategies and ladder, no 2D
# runs; its report (postproc/scene3d_friction_report.py, OUTDIR/report.md and runs.csv) gives per
# run the balance of scene 8b, max |E + interface - friction work - wall work - E0| / E0 (to
# 1e-9 at the Newton eps 1e-10, the deck's), the friction work and its largest rise over a step
# (<= 0: dissipative), E(T) / E0 and the Newton iterations. Default OUTDIR
# out/scene3d_friction.
#
#   full:    meshes (h, grading) = (0.25, 0.3) (0.14, 0.2) (0.1, 0.15) (0.07, 0.1)
#   --quick: mesh (0.25, 0.3) only
#
# Per mesh the bulk stages sig-mesh, sig-material, sig-assemble run once into OUTDIR/m<k>/base;
# each strategy gets OUTDIR/m<k>/<method>/ with symlinks to those DS files, its own deck (CONTACT
# and TIME mass= set), its own sig-contact and sig-march (energy.csv, march.log, wall.txt).
# Methods (scene 8a's, drivers/scene8a.sh): signorini (consistent mass), compliance and
# specific-penalty (r = 1e12 Pa/m), emm (Signorini + EMM), two-step (persistency on the midpoint
# velocity), two-step-increment, ipm, ipm-emm (g = 5e-4 m). OUTDIR/2d/<method>: scene 8a's 2D ball
# (datafiles/scene8a/ball.dat) with each strategy at the same k, T and gap, the losses the 3D ones
# are compared with. Then postproc/scene3d_impact_report.py
# OUTDIR writes OUTDIR/report.md, OUTDIR/runs.csv and OUTDIR/energy.png, speed_energy.png.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3), SIG_GMSH.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/scene3d_impact.sh [--quick] [--friction] [-o OUTDIR]
  --quick     the coarsest mesh only (about a minute)
  --friction  the oblique impact with Coulomb friction (datafiles/scene3d/oblique_impact.dat)
  -o OUTDIR   results folder (default out/scene3d_impact, with --friction out/scene3d_friction)
  -h, --help  this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3),
SIG_GMSH (default gmsh: the half ball's mesher).
EOF
}

invocation="drivers/scene3d_impact.sh${*:+ $*}"
out=
quick=0
friction=0
parse_options -o=out --quick:quick=1 --friction:friction=1 -- "$@"
if [ $friction -eq 1 ]; then
  template=$root/datafiles/scene3d/oblique_impact.dat
  out=${out:-out/scene3d_friction}
else
  template=$root/datafiles/scene3d/ball_impact.dat
  out=${out:-out/scene3d_impact}
fi

require_stages mesh material contact assemble march
require_decks "$template"
require_charts
command -v "${SIG_GMSH:-gmsh}" >/dev/null || die "gmsh is needed to mesh the half ball"

if [ $quick -eq 1 ]; then
  meshes=("0.25 0.3")
else
  meshes=("0.25 0.3" "0.14 0.2" "0.1 0.15" "0.07 0.1")
fi
source "$root/drivers/lib/impact3d.sh"
methods=("${impact3d_methods[@]}")

# The plane of the template (only its strategy fields change per method).
point=$(deck_value "$template" CONTACT point) || die "no CONTACT point= in $template"

mkdir -p "$out"
out=$(cd "$out" && pwd)
failed=()
ladder_begin ball_impact
start=$SECONDS
k=0
for mesh in "${meshes[@]}"; do
  ladder_mesh "$mesh" ball_impact
  build_base "$base/ball_impact.dat" "$base" "the mesh of h = $h, grading = $grading" \
    mesh material assemble
  echo "$h $grading" >"$base/mesh.txt"
  progress_step "m$k/base (h = $h, grading = $grading)"
  for method in "${methods[@]}"; do
    dir=$out/m$k/$method
    mkdir -p "$dir"
    link_ds ../base "$dir" nopo mili tae
    f=${impact3d_fields[$method]}
    contact="CONTACT ref=3 obstacle=plane point=$point normal=0,0,1 ${f%|*}"
    deck_variant "$base/ball_impact.dat" "$dir/ball_impact.dat" --replace-card CONTACT "$contact" \
      --set TIME.mass="${f#*|}"
    { run_stage contact "$dir/ball_impact.dat" "$dir" &&
      run_timed march "$dir/ball_impact.dat" "$dir"; } || failed+=("$dir")
    progress_step "m$k/$method"
  done
  echo "scene3d_impact.sh: mesh $k (h = $h, grading = $grading) done ($((SECONDS - t0)) s)"
done
if [ $friction -eq 1 ]; then
  echo "scene3d_impact.sh: all runs done in $((SECONDS - start)) s"
  record_seconds $start
  "$python" "$root/postproc/scene3d_friction_report.py" "$out"
  [ ${#failed[@]} -eq 0 ] || die "${#failed[@]} run(s) failed: ${failed[*]}"
  exit 0
fi
# Scene 8a's 2D ball (datafiles/scene8a/ball.dat, its 128-node circle) with the same strategies,
# k, T and gap below its lowest point (x2 = 15): the losses the 3D ones are compared with.
deck2d=$root/datafiles/scene8a/ball.dat
k3=$(deck_value "$template" TIME k)
T3=$(deck_value "$template" TIME T)
y2d=$("$python" -c "print(repr(15 + float('${point##*,}')))")
base=$out/2d/base
rm -rf "$out/2d"
mkdir -p "$base"
deck_variant "$deck2d" "$base/ball.dat" --set MESH.file="$root/datafiles/scene8a/ball.msh" \
  --set TIME.k="$k3" --set TIME.T="$T3" --set TIME.output_every=50 --set OUTPUT.vtk=no
build_base "$base/ball.dat" "$base" "scene 8a's 2D ball" mesh material assemble
for method in "${methods[@]}"; do
  dir=$out/2d/$method
  mkdir -p "$dir"
  link_ds ../base "$dir" nopo mili tae
  f=${impact3d_fields[$method]}
  deck_variant "$base/ball.dat" "$dir/ball.dat" --set TIME.mass="${f#*|}" --replace-card CONTACT \
    "CONTACT ref=3 obstacle=plane point=0,$y2d normal=0,1 ${f%|*}"
  { run_stage contact "$dir/ball.dat" "$dir" && run_timed march "$dir/ball.dat" "$dir"; } ||
    failed+=("$dir")
done
progress_step "2d (scene 8a's ball, ${#methods[@]} strategies)"
echo "scene3d_impact.sh: all runs done in $((SECONDS - start)) s"
record_seconds $start

"$python" "$root/postproc/scene3d_impact_report.py" "$out"
if [ ${#failed[@]} -gt 0 ]; then
  die "${#failed[@]} run(s) failed: ${failed[*]}"
fi
