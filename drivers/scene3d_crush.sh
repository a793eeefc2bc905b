#!/usr/bin/env bash
# drivers/scene3d_crush.sh [--quick] [--steps S] [--no-getfem] [-o OUTDIR]: the hyperelastic crush
# (issue 28): the hollow Ciarlet-Geymonat ball of datafiles/scene3d/crush.dat pressed on the plane
# in one load step and in S (default 5), with every method of sig-solve's large-deformation solve
# (pdas, alm, projection and penalty, the SOLVER defaults but penalty's r = 1e4), against GetFEM
# 5.4 on the same mesh (postproc/getfem_crush3d.py: its finite-strain brick with 'Ciarlet
# Geymonat', nodal contact, the same Dirichlet data and load steps), then
# postproc/scene3d_crush_report.py: OUTDIR/report.md (reaction ours / GetFEM / relative
# difference, per load step, and the Newton iterations per method and load step) and
# OUTDIR/summary.json.
#
#   full:    the deck's mesh (crush.msh, 1095 dofs) and a finer one of meshes/hollow_ball.geo
#            (h = 0.06, grading 0.15, cap 0.12), gmsh
#   --quick: the deck's mesh only (the pipeline test, tests/pipeline/crush3d.sh)
#   --no-getfem: no GetFEM (also when /usr/bin/python3 cannot import getfem)
#
# OUTDIR/<mesh>/base holds the DS files of sig-mesh, sig-material, sig-contact and sig-assemble;
# OUTDIR/<mesh>/steps<S>/<method>/ a run (deck, case.b, solve.log, wall.txt) and
# OUTDIR/<mesh>/steps<S>/getfem.json GetFEM's.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3), SIG_GMSH.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<USAGE
usage: drivers/scene3d_crush.sh [--quick] [--steps S] [--no-getfem] [-o OUTDIR]
  --quick       the deck's mesh only (about 17 s)
  --steps S     the several-step runs' load steps (default 5; the one-step runs always)
  --no-getfem   skip the GetFEM comparison
  -o OUTDIR     results folder (default out/scene3d_crush)
  -h, --help    this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3),
SIG_GMSH (default gmsh: the finer mesh's mesher).
USAGE
}

invocation="drivers/scene3d_crush.sh${*:+ $*}"
template=$root/datafiles/scene3d/crush.dat
out=out/scene3d_crush
quick=0
several=5
getfem=1
parse_options -o=out --quick:quick=1 --steps=several --no-getfem:getfem=0 -- "$@"
require_positive --steps "$several"
[ "$several" -ge 2 ] || die "--steps must be >= 2 (the one-step runs are always made), got $several"
require_stages mesh material contact assemble solve dump
require_decks "$template"
if [ $getfem -eq 1 ] && ! /usr/bin/python3 -c 'import getfem' 2>/dev/null; then
  echo "scene3d_crush.sh: /usr/bin/python3 cannot import getfem: no GetFEM comparison"
  getfem=0
fi

methods=(pdas alm projection penalty)
mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -rf "$out"/coarse "$out"/fine
provenance >"$out/command.txt"
echo "getfem: $getfem" >>"$out/command.txt"
start=$SECONDS

# mesh_file NAME: the msh of mesh NAME (coarse: the deck's; fine: meshed here by gmsh).
mesh_file() {
  if [ "$1" = coarse ]; then
    echo "$root/datafiles/scene3d/crush.msh"
    return
  fi
  command -v "${SIG_GMSH:-gmsh}" >/dev/null || die "gmsh is needed to mesh the finer hollow ball"
  "${SIG_GMSH:-gmsh}" "$root/meshes/hollow_ball.geo" -3 -format msh22 -setnumber h 0.06 \
    -setnumber grading 0.15 -setnumber cap 0.12 -o "$out/fine/hollow_ball.msh" \
    >"$out/fine/gmsh.log" 2>&1 || die "gmsh failed (see $out/fine/gmsh.log)"
  echo "$out/fine/hollow_ball.msh"
}

meshes=(coarse)
[ $quick -eq 1 ] || meshes+=(fine)
failed=()
for mesh in "${meshes[@]}"; do
  base=$out/$mesh/base
  mkdir -p "$base"
  msh=$(mesh_file "$mesh") || exit 1
  deck_variant "$template" "$base/crush.dat" --set "MESH.file=$msh"
  build_base "$base/crush.dat" "$base" "the $mesh hollow ball"
  for steps in 1 "$several"; do
    for method in "${methods[@]}"; do
      dir=$out/$mesh/steps$steps/$method
      mkdir -p "$dir"
      edits=(--set "SOLVER.method=$method" --set "LOADSTEPS.n=$steps")
      [ "$method" = penalty ] && edits+=(--set SOLVER.r=1e4)
      deck_variant "$base/crush.dat" "$dir/crush.dat" "${edits[@]}"
      variant_ds "$base/crush.dat" "$dir" "$dir/crush.dat" && run_timed solve "$dir/crush.dat" "$dir" ||
        failed+=("$dir")
      grep -h '^sig-solve:' "$dir/solve.log" || true
    done
    if [ $getfem -eq 1 ]; then
      /usr/bin/python3 "$root/postproc/getfem_crush3d.py" --deck "$base/crush.dat" --steps "$steps" \
        --json "$out/$mesh/steps$steps/getfem.json" || failed+=("$out/$mesh/steps$steps (GetFEM)")
    fi
  done
done
echo "scene3d_crush.sh: all runs done in $((SECONDS - start)) s"
record_seconds $start

"$python" "$root/postproc/scene3d_crush_report.py" "$out" || failed+=("the report's checks")
if [ ${#failed[@]} -gt 0 ]; then
  die "${#failed[@]} failed: ${failed[*]}"
fi
