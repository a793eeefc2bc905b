#!/usr/bin/env bash
# drivers/scene4.sh [--quick] [-o OUTDIR]: scene 4 (issue 11), the ball pressed on a foundation
# with normal compliance, a rigid wall at depth g and nonmonotone friction, solved by the
# convexification loop (datafiles/scene4/ball.dat), and the square of the error study
# (datafiles/scene4/square.dat); then postproc/scene4_report.py writes OUTDIR/report.md, its PNGs
# and OUTDIR/scene.json.
#
# Meshes of the ball (each OUTDIR/mesh_<M>/base: sig-mesh, sig-material, sig-contact,
# sig-assemble of the deck; the runs link its DS files); N boundary segments, N/4 on Gamma3:
#   C  N = 256 (64 contact elements), graded arcs, grading 0.1
#   M  N = 512 (128 contact elements, the thesis's), graded arcs, grading 0.1
#   G  N = 512, uniform arcs, grading 0.03: the deck's
#   T  N = 512, uniform arcs, grading 0.011: the thesis's size (21068 dofs)
#   R  N = 1024, uniform arcs, grading 0.008 (64658 dofs): the reference of the speed-accuracy
#      chart (--quick: T is the reference)
# Runs (OUTDIR/<figure>/<name>/: the deck variant, its DS files, summary.json, contact.csv and,
# for the figures, the .pvd):
#   fig42/<M>         a = 2, b = 0.02, alpha = 1, g = 0.5 (the deck) on every mesh; the other
#                     figures on G
#   fig43/a2, a0.002  a = b = 2, a = b = 0.002
#   fig44/g0, g10     g = 0 and g = 10 (a = 2, b = 0.002); signorini: frictionless Signorini
#                     (the limit g = 0 must equal it); compliance_g10: law=compliance (no wall)
#   fig45/alpha1, alpha100 (a = 1, b = 0.5) on T (--quick: G), and fig45/counts/<...>: the outer
#                     count against the tolerance (1e-3 ... 1e-7), the start (rest, slipped) and
#                     the relaxation (1, 0.5)
#   fig46/rho<rho>    the perturbed data (l.7739-7743) rho = 20, 10, 2, 1e-2: f0 = (0, -rho),
#                     f2 = (-(4 + rho), 0), cn = 10 + rho
#   fig47/n<n>        the square with n segments per side, n = 2 ... 256 against 512 (--quick:
#                     2 ... 64 against 128), Gamma1 clamped (the deck); fig47/rollers/n<n> the
#                     same with rollers on Gamma1 (u1 = 0 only), a solution without the clamped
#                     corners' singularity
#   fig47/adapted     the clamped square adapted (issue 29): drivers/adapt.sh from n = 8
#                     (Dörfler theta 0.5, 9 steps, 162 ... ~15k dofs; --quick: 5 steps), each
#                     step<k>/ against the overkill reference overkill2/, the last adapted mesh
#                     refined uniformly twice (sig-refine --theta 1; overkill1/ once), finer
#                     everywhere than every adapted mesh; the uniform reference n512 (n128)
#                     gets its own estimate (case.est) and every uniform run its error against
#                     overkill2 beside its own (error_overkill.json); fig47/adapted/uniform:
#                     the finest uniform mesh judged (n = 256; 64) again by drivers/chain.sh,
#                     timed as the adaptive steps are (chain_wall.txt)
#   map/<M>/alpha<alpha>_a<a>_b<b>  the stability map of the loop: alpha in 1 10 100 300 1000,
#                     (a, b) in (2, 1.9) (2, 1) (2, 0.02) (5, 0.02) on C, M (and G, T); a run that is
#                     Nv or cycles again with relaxation 0.5 (..._relaxed)
#   methods/<case>/<method>_<value>  the inner methods and their parameter on G, for the Fig 4.2
#                     case and for alpha = 100, b = 1; penalty with full steps (its default) and
#                     with the line search (_search)
#   speed/<M>/<method>_<value>  the Fig 4.2 case by each method on C, M, G (and T), its error
#                     ||u - u_ref||_V against the reference (sig-error, error.json)
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3). Times are sig-solve
# phases: run it on a quiet machine for times worth quoting.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"
source "$(dirname "${BASH_SOURCE[0]}")/lib/adapted.sh"

usage() {
  cat <<EOF
usage: drivers/scene4.sh [--quick] [-o OUTDIR]
  --quick     the map on M for alpha = 1, 100, 1000, the inner methods on the Fig 4.2
              case, Fig 4.5 on G (eps = 1e-3, 1e-5, 1e-7), T the reference, Fig 4.7 up to
              n = 64 against 128 and 5 adaptive steps (about a minute)
  -o OUTDIR   results folder (default out/scene4)
  -h, --help  this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/scene4.sh${*:+ $*}"
template=$root/datafiles/scene4/ball.dat
square=$root/datafiles/scene4/square.dat
parse_quick_out out/scene4 "$@"

require_stages mesh material contact assemble solve post error estimate refine adapt dump
require_decks "$template" "$square"
require_charts

alphas=(1 10 100 300 1000)
pairs=(2:1.9 2:1 2:0.02 5:0.02) # a:b
tolerances=(1e-3 1e-4 1e-5 1e-6 1e-7)
method_cases=(fig42 hard)
if [ $quick -eq 1 ]; then
  alphas=(1 100 1000)
  tolerances=(1e-3 1e-5 1e-7)
  method_cases=(fig42)
  meshes=(C M G)
  map_meshes=(M)
  key_mesh=G
  reference=T
  squares=(2 4 8 16 32 64)
  square_reference=128
  adapt_steps=5
else
  meshes=(C M G T)
  map_meshes=(C M G T)
  key_mesh=T
  reference=R
  squares=(2 4 8 16 32 64 128 256)
  square_reference=512
  adapt_steps=9
fi

mkdir -p "$out"
out=$(cd "$out" && pwd)
failed=()

# mesh_edits M: the MESH card of mesh M.
mesh_edits() {
  case $1 in
    C) echo "--set MESH.N=256 --set MESH.grading=0.1 --set MESH.arcs=graded" ;;
    M) echo "--set MESH.grading=0.1 --set MESH.arcs=graded" ;;
    G) echo "" ;;
    T) echo "--set MESH.grading=0.011" ;;
    R) echo "--set MESH.N=1024 --set MESH.grading=0.008" ;;
    *) die "unknown mesh $1" ;;
  esac
}

# base M: the mesh, materials, contact elements and system of the deck on mesh M.
base() {
  local dir=$out/mesh_$1/base
  rm -rf "$dir"
  mkdir -p "$dir"
  # shellcheck disable=SC2046
  deck_variant "$template" "$dir/ball.dat" $(mesh_edits "$1")
  build_base "$dir/ball.dat" "$dir" "mesh $1"
  progress_step "mesh $1"
}

# run NAME BASE_DECK_DIR EDIT...: the variant of BASE_DECK_DIR's deck with the edits in
# OUTDIR/NAME: the DS files of the base where the variant keeps their cards, sig-contact and
# sig-assemble where it changes them, then sig-solve and sig-post.
run() {
  local name=$1 base_dir=$2
  shift 2
  local dir=$out/$name deck base_deck
  base_deck=$(ls "$base_dir"/*.dat)
  deck=$dir/$(basename "$base_deck")
  rm -rf "$dir"
  mkdir -p "$dir"
  deck_variant "$base_deck" "$deck" "$@"
  variant_ds "$base_deck" "$dir" "$deck" || { failed+=("$dir"); progress_step "$name"; return 0; }
  run_stage solve "$deck" "$dir" && run_stage post "$deck" "$dir" || failed+=("$dir")
  progress_step "$name"
}

# The runs, counted for the progress lines.
declare -A methods=([pdas]="1 2e2 1e4 1e6" [alm]="1 2e2 1e4 1e6" [projection]="1 1e-2 1e-4 1e-6"
  [penalty]="1e2 1e4 1e6 1e8")
all_meshes=("${meshes[@]}" "$reference")
runs=${#all_meshes[@]}                                    # bases
runs=$((runs + ${#all_meshes[@]} + 2 + 4))                # fig42, fig43, fig44
runs=$((runs + 2 + 2 * ${#tolerances[@]} * 2 + 2))       # fig45
runs=$((runs + 4 + 4 * (${#squares[@]} + 1)))             # fig46, fig47 (base + run, 2 BCs)
runs=$((runs + 4))                                        # fig47/adapted: loop, 2 overkills, n
runs=$((runs + ${#map_meshes[@]} * ${#alphas[@]} * ${#pairs[@]})) # map
runs=$((runs + ${#method_cases[@]} * (16 + 4)))          # methods
runs=$((runs + ${#meshes[@]} * 5))                        # speed
progress_begin $runs

{
  provenance
  echo "meshes: ${meshes[*]}"
  echo "map_meshes: ${map_meshes[*]}"
  echo "key_mesh: $key_mesh"
  echo "reference: $reference"
  echo "squares: ${squares[*]}"
  echo "square_reference: $square_reference"
  echo "adapt_steps: $adapt_steps"
} >"$out/command.txt"
cp "$template" "$out/ball.template.dat"
cp "$square" "$out/square.template.dat"
rm -rf "$out"/mesh_* "$out"/fig4[2-7] "$out"/map "$out"/methods "$out"/speed

start=$SECONDS
for m in "${all_meshes[@]}"; do
  base "$m"
done

# Fig 4.2 on every mesh and the reference.
for m in "${all_meshes[@]}"; do
  run "fig42/$m" "$out/mesh_$m/base"
done
G=$out/mesh_G/base
key=$out/mesh_$key_mesh/base

# Fig 4.3: constant mu.
run fig43/a2 "$G" --set FRICTION.a=2 --set FRICTION.b=2
run fig43/a0.002 "$G" --set FRICTION.a=0.002 --set FRICTION.b=0.002

# Fig 4.4: the limits g = 0 (Signorini, frictionless: mu p(0) = 0) and g = 10 (no wall reached).
run fig44/g0 "$G" --set CONTACT.g=0 --set FRICTION.b=0.002
run fig44/g10 "$G" --set CONTACT.g=10 --set FRICTION.b=0.002
run fig44/signorini "$G" --set CONTACT.law=signorini --drop CONTACT.cn --set CONTACT.g=0 \
  --drop-card FRICTION --drop-card CONVEXIFICATION
run fig44/compliance_g10 "$G" --set CONTACT.law=compliance --drop CONTACT.g --set FRICTION.b=0.002

# Fig 4.5: alpha = 1 and 100 with a = 1, b = 0.5, and how the outer count moves.
for alpha in 1 100; do
  run "fig45/alpha$alpha" "$key" --set FRICTION.a=1 --set FRICTION.b=0.5 \
    --set "FRICTION.alpha=$alpha"
  for start_from in rest slipped; do
    for eps in "${tolerances[@]}"; do
      run "fig45/counts/alpha${alpha}_${start_from}_eps$eps" "$key" --set FRICTION.a=1 \
        --set FRICTION.b=0.5 --set "FRICTION.alpha=$alpha" --set "CONVEXIFICATION.eps=$eps" \
        --set "CONVEXIFICATION.start=$start_from" --set OUTPUT.vtk=no
    done
  done
  run "fig45/counts/alpha${alpha}_rest_eps1e-5_relaxed" "$key" --set FRICTION.a=1 \
    --set FRICTION.b=0.5 --set "FRICTION.alpha=$alpha" --set CONVEXIFICATION.relaxation=0.5 \
    --set OUTPUT.vtk=no
done

# Fig 4.6: the perturbed data, and ||u_rho - u||_V against the Fig 4.2 solution (same mesh).
for rho in 20 10 2 0.01; do
  run "fig46/rho$rho" "$G" --add-card "BODYFORCE f=0,-$rho" \
    --set "TRACTION.f=-$("$python" -c "print(f'{4 + $rho:g}')"),0" \
    --set "CONTACT.cn=$("$python" -c "print(f'{10 + $rho:g}')")"
  error_json "fig46/rho$rho" fig42/G
done

# Fig 4.7: nested squares against the finest, Gamma1 clamped (the deck) and on rollers.
for bc in clamped rollers; do
  folder=fig47
  edits=(--set OUTPUT.vtk=no)
  if [ $bc = rollers ]; then
    folder=fig47/rollers
    edits+=(--drop DIRICHLET.uy)
  fi
  for n in "${squares[@]}" "$square_reference"; do
    dir=$out/$folder/base_n$n
    mkdir -p "$dir"
    deck_variant "$square" "$dir/square.dat" --set "MESH.nx=$n" "${edits[@]}"
    build_base "$dir/square.dat" "$dir" "the square n = $n ($bc)"
    progress_step "$folder/base_n$n"
    run "$folder/n$n" "$dir"
  done
  for n in "${squares[@]}"; do
    error_json "$folder/n$n" "$folder/n$square_reference"
  done
done

# Fig 4.7 adapted (issue 29): the clamped square from n = 8, solve -> estimate -> mark -> refine
# (drivers/adapt.sh, Dörfler theta 0.5), against the overkill reference: the last adapted mesh
# refined uniformly twice, finer everywhere than every adapted mesh (the adapted meshes nest: each
# refines the one before). The uniform reference gets its own estimate, and every uniform run its
# error against the overkill beside its own against n = $square_reference.
adapted=$out/fig47/adapted
mkdir -p "$adapted"
deck_variant "$square" "$adapted/square.dat" --set MESH.nx=8 --set OUTPUT.vtk=no
"$root/drivers/adapt.sh" "$adapted/square.dat" -o "$adapted" --steps "$adapt_steps" --theta 0.5 \
  >"$adapted/adapt.log" 2>&1 || { tail -20 "$adapted/adapt.log" >&2; die "adapt.sh failed"; }
progress_step "fig47/adapted ($adapt_steps steps)"
overkill_references "$adapted" "$adapt_steps" "$adapted/square.dat" "$adapted/square.dat"
# The finest uniform mesh judged, by the same chain as the adaptive steps, for its wall clock.
finest=${squares[-1]}
timed_chain "$out/fig47/base_n$finest/square.dat" "$adapted/uniform"
progress_step "fig47/adapted/uniform (n = $finest by chain.sh)"
adapted_errors fig47/adapted "$adapt_steps" fig47/n "fig47/n$square_reference" square.dat \
  "${squares[@]}"

# The stability map of the loop: alpha x (a - b) x mesh; Nv or cycling runs again relaxed.
for m in "${map_meshes[@]}"; do
  for alpha in "${alphas[@]}"; do
    for pair in "${pairs[@]}"; do
      a=${pair%%:*}
      b=${pair#*:}
      name=map/$m/alpha${alpha}_a${a}_b$b
      law=(--set "FRICTION.alpha=$alpha" --set "FRICTION.a=$a" --set "FRICTION.b=$b")
      run "$name" "$out/mesh_$m/base" "${law[@]}" --set OUTPUT.vtk=no
      if ! grep -q '"converged": true' "$out/$name/summary.json" 2>/dev/null ||
        ! grep -q '"cycle": 0' "$out/$name/summary.json" 2>/dev/null; then
        run "${name}_relaxed" "$out/mesh_$m/base" "${law[@]}" \
          --set CONVEXIFICATION.relaxation=0.5 --set OUTPUT.vtk=no
      fi
    done
  done
done

# The inner methods and their parameter, on G.
for case in "${method_cases[@]}"; do
  edits=()
  [ $case = fig42 ] || edits=(--set FRICTION.alpha=100 --set FRICTION.b=1)
  for method in pdas alm projection penalty; do
    for value in ${methods[$method]}; do
      solver=(--drop SOLVER.gamma --set "SOLVER.method=$method"
        --set "SOLVER.$(parameter_of "$method")=$value" --set OUTPUT.vtk=no)
      run "methods/$case/${method}_$value" "$G" "${edits[@]}" "${solver[@]}"
      if [ $method = penalty ]; then
        run "methods/$case/${method}_${value}_search" "$G" "${edits[@]}" "${solver[@]}" \
          --set SOLVER.search=yes
      fi
      # The Fig 4.2 case's parameter sweep is a series of the speed-accuracy chart.
      if [ $case = fig42 ]; then
        for name in "${method}_$value" "${method}_${value}_search"; do
          [ ! -f "$out/methods/$case/$name/summary.json" ] ||
            ! grep -q '"converged": true' "$out/methods/$case/$name/summary.json" ||
            error_json "methods/$case/$name" "fig42/$reference"
        done
      fi
    done
  done
done

# Speed against accuracy: each method at its default parameter (penalty with the search, and a
# softer penalty) on each mesh, against the reference.
for m in "${meshes[@]}"; do
  for variant in pdas:2e2 alm:2e2 projection:1 penalty:1e6 penalty:1e4; do
    method=${variant%%:*}
    value=${variant#*:}
    name=speed/$m/${method}_$value
    extra=()
    [ $method != penalty ] || extra=(--set SOLVER.search=yes)
    run "$name" "$out/mesh_$m/base" --drop SOLVER.gamma --set "SOLVER.method=$method" \
      --set "SOLVER.$(parameter_of "$method")=$value" --set OUTPUT.vtk=no "${extra[@]}"
    error_json "$name" "fig42/$reference"
  done
done
echo "scene4.sh: all runs done in $((SECONDS - start)) s"
record_seconds $start

"$python" "$root/postproc/scene4_report.py" "$out"
if [ ${#failed[@]} -gt 0 ]; then
  die "${#failed[@]} run(s) failed: ${failed[*]}"
fi
