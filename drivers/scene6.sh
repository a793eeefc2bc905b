#!/usr/bin/env bash
# drivers/scene6.sh [--quick] [-o OUTDIR]: the viscoelastodynamic rail of thesis ch. 6.4 (scene 6,
# ../shared/SCENES.md, ../shared/ALGORITHMS.md 3, datafiles/scene6/rail.dat): a clamped strip with
# inertia on a compliant foundation under a moving Gaussian load, friction of the slip rate by the
# convexification loop in every step of the dynamic backward Euler; then its report
# (postproc/scene6_report.py: Figs 6.2-6.5, the checks, speed against accuracy, the stability map).
#
# Runs (each a folder of OUTDIR with its deck, the DS files of its chain and the stages' logs):
#   winkler/psi<psi>      ALGORITHMS.md 3.6 check 2: static, bilateral springs, load at x0 = 1,
#                         against postproc/winkler_strip.py (psi = 10, 50, 200)
#   figs/friction         the deck: h = 1/64, k = 0.01, friction; every other state for ParaView
#                         (Figs 6.2, 6.3, the statuses per node)
#   figs/frictionless     the same without friction (Fig 6.3 beside it; the quasi-static check)
#   figs/psi10, psi200    frictionless, psi = 10 and 200 (Fig 6.4, t = 0.5)
#   quasistatic/t<t>      static solves with the load held at x0 = 2 t, frictionless (ALGORITHMS.md
#                         3.6 check 1: the dynamic rail must equal them)
#   viscosity/kv          figs/friction with a small Kelvin-Voigt viscosity (the thesis neglects it)
#   convergence/n<N>      h = k = 1/N with friction, N = 2 ... 128, and the reference N = 256
#                         (Fig 6.5 by sig-error); pdas, and alm for speed against accuracy
#   stability/n<n>_k<K>_a<alpha>   the map: mesh x k x alpha -> outer and Newton counts per step, Nv
#   adapted/              issue 29, adapted against uniform meshes, every one at the deck's
#                         k = 0.01 with states kept every 0.05 s and its estimate (case.est):
#                         drivers/adapt.sh from the 16 x 2 rail (Dörfler theta 0.5; 6 steps, 4
#                         with --quick), one mesh for the whole march (a triangle's indicator is
#                         its largest over the kept times: the load and the contact zone sweep
#                         the rail); overkill1/2, the last adapted mesh refined uniformly once and
#                         twice (finer everywhere than every adapted mesh: they nest);
#                         uniform/n<N>, the scene's N x N meshes (N = 8 ... 128 against 256;
#                         --quick 8 ... 32 against 64); start/x<m>, the start mesh refined
#                         uniformly, 16m x 2m (m = 1 ... 8 against 16; --quick 1 ... 4 against 8)
# --quick: figures at h = 1/32, N = 2 ... 16 against N = 32, a smaller map and adapted study.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"
source "$(dirname "${BASH_SOURCE[0]}")/lib/adapted.sh"

usage() {
  cat <<EOF
usage: drivers/scene6.sh [--quick] [-o OUTDIR]
  --quick     figures at h = 1/32, Fig 6.5 for h = k = 1/2 ... 1/16 against 1/32, a smaller map,
              4 adapted steps
  -o OUTDIR   results folder (default out/scene6)
  -h, --help  this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/scene6.sh${*:+ $*}"
template=$root/datafiles/scene6/rail.dat
winkler_template=$root/datafiles/scene6/winkler.dat
parse_quick_out out/scene6 "$@"
require_stages mesh material contact assemble solve march post error estimate refine adapt
[ -r "$template" ] || die "cannot read the deck $template"
require_charts

if [ $quick -eq 1 ]; then
  figure_n=32
  convergence_n=(2 4 8 16)
  reference_n=32
  alm_n=(4 8 16)
  winkler_ny=16
  stability_n=(16 32)
  stability_k=(8 32)
  stability_alpha=(20 2000)
  adapt_steps=4
  adapt_uniform_n=(8 16 32)
  adapt_uniform_reference=64
  adapt_start_m=(1 2 4)
  adapt_start_reference=8
else
  figure_n=64
  convergence_n=(2 4 8 16 32 64 128)
  reference_n=256
  alm_n=(4 8 16 32 64)
  winkler_ny=32
  stability_n=(16 64 128)
  stability_k=(8 32 128 512)
  stability_alpha=(2 20 200 2000 20000)
  adapt_steps=6
  adapt_uniform_n=(8 16 32 64 128)
  adapt_uniform_reference=256
  adapt_start_m=(1 2 4 8)
  adapt_start_reference=16
fi
# [choice] the adapted study's start mesh: 16 x 2 cells of 0.125 x 0.05 m, two rows through the
# thickness, edges of about the load's standard deviation (0.1 m). Not the scene's 16 x 16 (cells
# of aspect 20): bisection only refines, so its 16 rows, more than the bending needs, would stay
# in every adapted mesh (measured from 16 x 16: 1.1-1.2 times the uniform error per dof).
adapt_nx=16 adapt_ny=2
quasistatic_t=(0.2 0.4 0.6 0.8)
# [choice] the viscosity of the labelled variant: eta1 = 0.001, eta2 = 0.002 GPa s: viscous stresses
# of eta / (E tau) ~ 4e-4 of the elastic ones at the load's time scale tau = 0.05 s.
viscosity="eta1=0.001 eta2=0.002"

mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -rf "$out/winkler" "$out/figs" "$out/quasistatic" "$out/viscosity" "$out/convergence" \
  "$out/stability" "$out/adapted"
{
  provenance
  echo "quick: $quick"
  echo "figure_n: $figure_n"
  echo "convergence_n: ${convergence_n[*]}"
  echo "reference_n: $reference_n"
  echo "alm_n: ${alm_n[*]}"
  echo "winkler_ny: $winkler_ny"
  echo "stability: n ${stability_n[*]}; k 1/${stability_k[*]}; alpha ${stability_alpha[*]}"
  echo "viscosity: $viscosity"
  echo "adapt_steps: $adapt_steps"
  echo "adapt_start: $adapt_nx $adapt_ny"
  echo "adapt_uniform_n: ${adapt_uniform_n[*]}"
  echo "adapt_uniform_reference: $adapt_uniform_reference"
  echo "adapt_start_m: ${adapt_start_m[*]}"
  echo "adapt_start_reference: $adapt_start_reference"
} >"$out/command.txt"
cp "$template" "$out/rail.template.dat"

# A run whose stage fails (a crash: a Newton or convexification failure is a result, "Nv") is
# listed here; the other runs and the report go on, and the script exits 1 at the end.
failed=()

# run DIR TEMPLATE EDIT...: the deck TEMPLATE with the edits (deck_variant) in DIR/rail.dat, and
# its chain of stages in DIR (sig-march for a deck with a TIME card, else sig-solve), each stage's
# output in DIR/<stage>.log.
run() {
  local dir=$1 deck_template=$2 stage solve=solve
  shift 2
  rm -rf "$dir"
  mkdir -p "$dir"
  deck_variant "$deck_template" "$dir/rail.dat" "$@"
  deck_has "$dir/rail.dat" TIME && solve=march
  for stage in mesh material contact assemble "$solve" post; do
    run_stage "$stage" "$dir/rail.dat" "$dir" || { failed+=("$dir"); break; }
  done
  progress_step "${dir#"$out"/}"
}

# march_edits N K EVERY VTK: the mesh, step and output of a march.
march_edits() {
  echo --set MESH.nx=$1 --set MESH.ny=$1 --set TIME.k=$2 --set TIME.output_every=$3 \
    --set OUTPUT.vtk=$4
}
frictionless=(--drop-card FRICTION --drop-card CONVEXIFICATION)
inverse() { "$python" -c "print(repr(1 / $1))"; }

runs=$((3 + 4 + ${#quasistatic_t[@]} + 1 + ${#convergence_n[@]} + 1 + ${#alm_n[@]} +
  ${#stability_n[@]} * ${#stability_k[@]} * ${#stability_alpha[@]} +
  3 + ${#adapt_uniform_n[@]} + 1 + ${#adapt_start_m[@]} + 1)) # the loop, 2 overkills, 2 ladders
progress_begin $runs
start=$SECONDS

# 1. The Winkler strip (static, bilateral springs).
for psi in 10 50 200; do
  run "$out/winkler/psi$psi" "$winkler_template" --set MESH.ny=$winkler_ny \
    --set MOVINGLOAD.psi=$psi
done

# 2. The figures: h = 1/figure_n, k = 0.01 (t = 0.2 ... 0.8 and 0.5 are steps).
run "$out/figs/friction" "$template" $(march_edits $figure_n 0.01 2 yes)
run "$out/figs/frictionless" "$template" $(march_edits $figure_n 0.01 10 no) "${frictionless[@]}"
for psi in 10 200; do
  run "$out/figs/psi$psi" "$template" $(march_edits $figure_n 0.01 50 yes) "${frictionless[@]}" \
    --set MOVINGLOAD.psi=$psi
done

# 3. The quasi-static limit: static solves with the load held where it is at t.
for t in "${quasistatic_t[@]}"; do
  run "$out/quasistatic/t$t" "$template" --set MESH.nx=$figure_n --set MESH.ny=$figure_n \
    --drop-card TIME "${frictionless[@]}" --set MOVINGLOAD.c=0 \
    --set MOVINGLOAD.x0="$("$python" -c "print(2 * $t)")" --set OUTPUT.vtk=no
done

# 4. A small viscosity, which the thesis neglects.
run "$out/viscosity/kv" "$template" $(march_edits $figure_n 0.01 10 no) \
  --replace-card MATERIAL "MATERIAL law=kelvin-voigt E=100 nu=0.3 $viscosity plane=strain rho=1e-6"

# 5. Fig 6.5: h = k = 1/N against N = reference_n; states kept at multiples of 1/16 (or every
#    step below N = 16), so that the maximum over the coarse time levels is taken at shared times.
every() { [ "$1" -ge 16 ] && echo $(($1 / 16)) || echo 1; }
for n in "${convergence_n[@]}" "$reference_n"; do
  run "$out/convergence/n$n" "$template" $(march_edits "$n" "$(inverse "$n")" "$(every "$n")" no) \
    --set SOLVER.linear=mumps
done
for n in "${alm_n[@]}"; do
  run "$out/convergence/alm_n$n" "$template" $(march_edits "$n" "$(inverse "$n")" "$(every "$n")" no) \
    --set SOLVER.linear=mumps --set SOLVER.method=alm
done
for dir in "$out"/convergence/*; do
  [ "$dir" = "$out/convergence/n$reference_n" ] && continue
  [ -e "$dir/case.hist" ] || continue
  "$bin/sig-error" --json "$dir" "$out/convergence/n$reference_n" >"$dir/error.json" \
    2>"$dir/error.log" || failed+=("$dir (sig-error)")
done

# 6. The stability map of the loop: mesh x k x alpha. SOLVER maxit=50 a step (sig-march's default
#    in the midpoint marches; the marches in velocity take sig-solve's 100): at k = 1/512 the
#    deck's budget, 512 steps x 100 x CONVEXIFICATION maxit 200 = 1.024e7 Newton iterations, is
#    above the 1e7 a run may take and sig-march refuses it. The map's convex solves take about
#    two Newton iterations each (at most 377 in a step of 185 convex solves: n = 16, k = 1/128,
#    alpha = 2); a step that would need 50 in one is Nv on the map, shown, never silent.
for n in "${stability_n[@]}"; do
  for kk in "${stability_k[@]}"; do
    for alpha in "${stability_alpha[@]}"; do
      run "$out/stability/n${n}_k${kk}_a$alpha" "$template" \
        $(march_edits "$n" "$(inverse "$kk")" "$kk" no) --set FRICTION.alpha=$alpha \
        --set SOLVER.maxit=50
    done
  done
done

# 7. Adapted against uniform meshes (issue 29). Every mesh at the deck's k = 0.01, the references
#    too: the errors are the space errors of one time discretization, what the estimator
#    estimates (Fig 6.5 refines h and k together). States kept every 0.05 s (the load
#    moves 0.1 m, one standard deviation, between two), so that the indicators' maximum over the
#    kept times sees the load at every place, and sig-error's maximum over t is Fig 6.5's measure.
adapted=$out/adapted
mkdir -p "$adapted"
deck_variant "$template" "$adapted/rail.dat" --set MESH.nx=$adapt_nx --set MESH.ny=$adapt_ny \
  --set TIME.output_every=5 --set OUTPUT.vtk=no
adapted_study "$adapted" "$adapted/rail.dat" "$adapt_steps"

# estimated_run NAME NX NY: the adapted study's deck on the uniform NX x NY mesh in adapted/NAME,
# marched and estimated.
estimated_run() {
  local dir=$adapted/$1
  run "$dir" "$adapted/rail.dat" --set MESH.nx=$2 --set MESH.ny=$3
  [ ! -e "$dir/case.hist" ] || run_stage estimate "$dir/rail.dat" "$dir" ||
    failed+=("$dir (sig-estimate)")
}
for n in "${adapt_uniform_n[@]}" "$adapt_uniform_reference"; do
  estimated_run "uniform/n$n" "$n" "$n"
done
for m in "${adapt_start_m[@]}" "$adapt_start_reference"; do
  estimated_run "start/x$m" $((adapt_nx * m)) $((adapt_ny * m))
done
for n in "${adapt_uniform_n[@]}"; do
  error_json "adapted/uniform/n$n" "adapted/uniform/n$adapt_uniform_reference"
done
for m in "${adapt_start_m[@]}"; do
  error_json "adapted/start/x$m" "adapted/start/x$adapt_start_reference"
done
echo "scene6.sh: all runs done in $((SECONDS - start)) s"
record_seconds $start

"$python" "$root/postproc/scene6_report.py" "$out"
if [ ${#failed[@]} -gt 0 ]; then
  die "${#failed[@]} run(s) failed: ${failed[*]}"
fi
