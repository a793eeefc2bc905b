#!/usr/bin/env bash
# drivers/scene5.sh [--quick] [-o OUTDIR]: scene 5 (issue 12), the quasistatic Kelvin-Voigt strip
# on a damped foundation with a velocity bound and Coulomb friction in velocity (thesis ch. 5.5,
# Figs 5.2-5.12), marched by sig-march scheme=quasistatic; then postproc/scene5_report.py writes
# OUTDIR/report.md, its PNGs and OUTDIR/scene.json.
#
# Two loads, every figure with both (ALGORITHMS.md 2.5 item 1):
#   P  the printed data, f2 = (0, -10 t)        datafiles/scene5/strip.dat
#   R  the labelled variant f2 = (0, -t)        datafiles/scene5/strip_rescaled.dat
# Meshes (each OUTDIR/mesh_<M>/base: sig-mesh, sig-material, sig-contact, sig-assemble; the runs
# link its DS files): 64 (the thesis's union-jack 64 x 12, 3354 dofs as the thesis counts them)
# and the nested family n<N> (N x N/4 union-jack cells, h = 1/N) of the error study.
# Runs (OUTDIR/<figure>/<load>/<name>/: the deck variant, case.hist, steps.csv; .pvd where noted):
#   fig52/<L>            the deck (g = 0.01, cn = 10, mu = 0.2), every step kept, .pvd
#   fig53/<L>/c<c>       g = 0.05, mu = 0, cn = 10 (Fig 5.4's run, .pvd) and 20: profiles, t-series
#   fig55/<L>/g<g>       cn = 10, mu = 0, g = 0.001 0.01 0.05 0.1 (Figs 5.5, 5.6)
#   fig57/<L>/c<c>       g = 0.05, mu = 0, cn = 0.01 5 8 12 15 20 (Figs 5.7, 5.8)
#   fig59/<L>/mu<mu>     g = 0.05, cn = 10, mu = 0 ... 1 (Fig 5.9; mu = 0.6 is Fig 5.10, .pvd)
#   fig511/<L>/rho<rho>  h = k = 1/16: mu + rho, f0 = (rho, rho), f2 + (rho, rho), against
#                        rho0 (the unperturbed run): ||u_rho - u||_V at t = 1 (sig-error)
#   fig512/n<N>          the printed data, h = k = 1/N against the reference n256 (--quick:
#                        n64), errors at t = 0.25, 0.5, 0.75, 1 (sig-error)
#   fig512/time/k<K>     h = 1/64, k = 1/16, 1/64 against 1/256: the time error alone
#   fig512/elastic/n<N>  the clamped strip alone (Hooke, the load of t = 1, no contact, sig-solve)
#                        on the same meshes: the rate the geometry allows
#   fig512/rollers/n<N>  the labelled variant with rollers on Gamma1 (u1 = 0 only, no clamped
#                        corner) against its own reference; for the march, the elastic strip and
#                        the rollers also the error on [1, 4] x [0, 1], away from the corners
#                        (error_interior.json)
#   fig512/adapted       the printed data adapted (issue 29, full run only): drivers/adapt.sh
#                        from the 8 x 2 union-jack mesh (Dörfler theta 0.5, 10 steps), one mesh
#                        for the whole march (indicators: the largest over t = 0.25 ... 1), the
#                        scene's k = 1/64 on every step; each step<k>/ against overkill2/, the
#                        last adapted mesh refined uniformly twice and marched with k = 1/256
#                        (finer everywhere, in space and time, than every adapted run); the
#                        uniform reference n256 gets its own estimate (case.est), every uniform
#                        run its error against overkill2 (error_overkill.json); uniform/: the
#                        finest uniform mesh judged (n128) again by drivers/chain.sh, timed as
#                        the adaptive steps are (chain_wall.txt)
#   speed/<method>_<value>/n<N>  alm r = 100, projection c = 1 and c = 0.01 on the nested meshes
#                        against the same reference (pdas gamma = 100: fig512)
#   map/k<K>_c<c>_g<g>   the stability map: k x cn x g -> Newton iterations per step, Nv
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3). March times are
# sig-march's: run it on a quiet machine for times worth quoting.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"
source "$(dirname "${BASH_SOURCE[0]}")/lib/adapted.sh"

usage() {
  cat <<EOF
usage: drivers/scene5.sh [--quick] [-o OUTDIR]
  --quick     fewer variants per figure, Fig 5.12 up to h = 1/32 against 1/64 and not
              adapted, a smaller map (under a minute)
  -o OUTDIR   results folder (default out/scene5)
  -h, --help  this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/scene5.sh${*:+ $*}"
template=$root/datafiles/scene5/strip.dat
rescaled=$root/datafiles/scene5/strip_rescaled.dat
parse_quick_out out/scene5 "$@"

require_stages mesh material contact assemble march post error estimate refine adapt dump
require_decks "$template" "$rescaled"
require_charts

if [ $quick -eq 1 ]; then
  g_series=(0.001 0.01 0.05 0.1)
  c_series=(0.01 10 20)
  mu_series=(0 0.6 1)
  rhos=(0.1 0.001 1e-06)
  nested=(4 8 16 32)
  reference=64
  speed_meshes=(8 16 32)
  map_k=(16 64)
  map_c=(1 10 100)
  map_g=(0.01 0.1)
  adapt_steps=0
else
  g_series=(0.001 0.01 0.05 0.1)
  c_series=(0.01 5 8 12 15 20)
  mu_series=(0 0.2 0.4 0.6 0.8 1)
  rhos=(0.1 0.01 0.001 0.0001 1e-05 1e-06)
  nested=(4 8 16 32 64 128)
  reference=256
  speed_meshes=(16 32 64 128)
  map_k=(16 64 256)
  map_c=(0.01 1 10 100)
  map_g=(0.001 0.01 0.1)
  adapt_steps=10
fi

mkdir -p "$out"
out=$(cd "$out" && pwd)
failed=()

# base M EDIT...: the mesh, materials, contact elements and system of the printed deck on mesh M.
base() {
  local name=$1 dir=$out/mesh_$1/base
  shift
  rm -rf "$dir"
  mkdir -p "$dir"
  deck_variant "$template" "$dir/strip.dat" "$@"
  build_base "$dir/strip.dat" "$dir" "mesh $name"
  progress_step "mesh $name"
}

# run NAME TEMPLATE MESH EDIT...: the variant of TEMPLATE on mesh MESH (its MESH and TIME cards:
# h = k) with the edits in OUTDIR/NAME: the DS files of the mesh's base where the variant keeps
# their cards, sig-contact and sig-assemble where it changes them, then sig-march, and sig-post
# when it writes VTK.
run() {
  local name=$1 deck_template=$2 base_dir=$out/mesh_$3/base
  shift 3
  local dir=$out/$name deck=$out/$name/strip.dat base_deck=$base_dir/strip.dat
  rm -rf "$dir"
  mkdir -p "$dir"
  deck_variant "$deck_template" "$deck" --replace-card MESH "$(deck_cards "$base_deck" MESH)" \
    --replace-card TIME "$(deck_cards "$base_deck" TIME)" "$@"
  variant_ds "$base_deck" "$dir" "$deck" || { failed+=("$dir"); progress_step "$name"; return 0; }
  if run_stage march "$deck" "$dir"; then
    if [ "$(deck_value "$deck" OUTPUT vtk || echo yes)" != no ]; then
      run_stage post "$deck" "$dir" || failed+=("$dir")
    fi
  else
    failed+=("$dir")
  fi
  progress_step "$name"
}

# window_error_json RUN REFERENCE WINDOW: $out/RUN/error_interior.json, sig-error's error on the
# sub-domain WINDOW (X0,X1,Y0,Y1) only.
window_error_json() {
  "$bin/sig-error" --json --window "$3" "$out/$1" "$out/$2" >"$out/$1/error_interior.json" ||
    { failed+=("$out/$1 (sig-error --window)"); rm -f "$out/$1/error_interior.json"; }
}
interior=1,4,0,1

# The two loads' templates, by label.
declare -A load_deck=([P]=$template [R]=$rescaled)
frictionless=(--replace-card FRICTION "FRICTION ref=3 law=none")
novtk=(--set OUTPUT.vtk=no)

runs=$((1 + ${#nested[@]} + 1))                                        # bases
runs=$((runs + 2 * (1 + 2 + ${#g_series[@]} + ${#c_series[@]} + ${#mu_series[@]}))) # figs 5.2-5.10
runs=$((runs + 2 * (1 + ${#rhos[@]}) + 3 * (${#nested[@]} + 1) + 3))   # figs 5.11, 5.12
runs=$((runs + 3 * ${#speed_meshes[@]} + ${#map_k[@]} * ${#map_c[@]} * ${#map_g[@]}))
[ "$adapt_steps" -eq 0 ] || runs=$((runs + 4))                        # fig512/adapted
progress_begin $runs

{
  provenance
  echo "rescaled: $rescaled"
  echo "g_series: ${g_series[*]}"
  echo "c_series: ${c_series[*]}"
  echo "mu_series: ${mu_series[*]}"
  echo "rhos: ${rhos[*]}"
  echo "nested: ${nested[*]}"
  echo "reference: $reference"
  echo "speed_meshes: ${speed_meshes[*]}"
  echo "map_k: ${map_k[*]}"
  echo "map_c: ${map_c[*]}"
  echo "map_g: ${map_g[*]}"
  echo "adapt_steps: $adapt_steps"
} >"$out/command.txt"
cp "$template" "$out/strip.template.dat"
cp "$rescaled" "$out/strip_rescaled.template.dat"
rm -rf "$out"/mesh_* "$out"/fig5* "$out"/speed "$out"/map

start=$SECONDS
# The meshes: the thesis's 64 x 12, and the nested N x N/4 of the error study.
base 64
for n in "${nested[@]}" "$reference"; do
  base "n$n" --set "MESH.nx=$n" --set "MESH.ny=$((n / 4))" \
    --set "TIME.k=$("$python" -c "print(1 / $n)")" --set "TIME.output_every=$((n / 4))"
done

for L in P R; do
  deck=${load_deck[$L]}
  # Fig 5.2: the deck itself.
  run "fig52/$L" "$deck" 64
  # Figs 5.3, 5.4: g = 0.05, frictionless, cn = 10 and 20 (the time series of profiles).
  for c in 10 20; do
    vtk=("${novtk[@]}")
    [ $c != 10 ] || vtk=()
    run "fig53/$L/c$c" "$deck" 64 --set CONTACT.g=0.05 --set "CONTACT.cn=$c" "${frictionless[@]}" \
      "${vtk[@]}"
  done
  # Figs 5.5, 5.6: t = 1, cn = 10, frictionless, g varies.
  for g in "${g_series[@]}"; do
    run "fig55/$L/g$g" "$deck" 64 --set "CONTACT.g=$g" "${frictionless[@]}" "${novtk[@]}"
  done
  # Figs 5.7, 5.8: t = 1, g = 0.05, frictionless, cn varies.
  for c in "${c_series[@]}"; do
    run "fig57/$L/c$c" "$deck" 64 --set CONTACT.g=0.05 --set "CONTACT.cn=$c" \
      "${frictionless[@]}" "${novtk[@]}"
  done
  # Figs 5.9, 5.10: t = 1, g = 0.05, cn = 10, mu varies (mu = 0: no friction law).
  for mu in "${mu_series[@]}"; do
    vtk=("${novtk[@]}")
    [ "$mu" != 0.6 ] || vtk=()
    if [ "$mu" = 0 ]; then
      run "fig59/$L/mu$mu" "$deck" 64 --set CONTACT.g=0.05 "${frictionless[@]}" "${vtk[@]}"
    else
      run "fig59/$L/mu$mu" "$deck" 64 --set CONTACT.g=0.05 --set "FRICTION.mu=$mu" "${vtk[@]}"
    fi
  done
  # Fig 5.11: h = k = 1/16, the perturbed data against the unperturbed run.
  run "fig511/$L/rho0" "$deck" n16 "${novtk[@]}"
  for rho in "${rhos[@]}"; do
    mu=$("$python" -c "print(0.2 + $rho)")
    run "fig511/$L/rho$rho" "$deck" n16 --set "FRICTION.mu=$mu" --add-card "BODYFORCE f=$rho,$rho" \
      --add-card "TRACTION ref=2 f=$rho,$rho" "${novtk[@]}"
    error_json "fig511/$L/rho$rho" "fig511/$L/rho0"
  done
done

# Fig 5.12: the printed data on the nested meshes against the reference.
for n in "$reference" "${nested[@]}"; do
  run "fig512/n$n" "$template" "n$n" "${novtk[@]}"
done
for n in "${nested[@]}"; do
  error_json "fig512/n$n" "fig512/n$reference"
done
# The time error alone: h = 1/64, k = 1/16 and 1/64 against k = 1/256.
for k in 256 16 64; do
  run "fig512/time/k$k" "$template" n64 --set "TIME.k=$("$python" -c "print(1 / $k)")" \
    --set "TIME.output_every=$((k / 4))" "${novtk[@]}"
done
for k in 16 64; do
  error_json "fig512/time/k$k" "fig512/time/k256"
done
# The same meshes without contact or time: the clamped elastic strip under the load of t = 1.
for n in "$reference" "${nested[@]}"; do
  dir=$out/fig512/elastic/n$n
  mkdir -p "$dir"
  deck_variant "$out/mesh_n$n/base/strip.dat" "$dir/strip.dat" --drop-card CONTACT \
    --drop-card FRICTION --drop-card TIME --replace-card MATERIAL "MATERIAL E=100 nu=0.3" \
    --replace-card TRACTION "TRACTION ref=2 f=0,-10" --replace-card SOLVER "SOLVER linear=cholmod" \
    --set OUTPUT.vtk=no
  link_ds "$out/mesh_n$n/base" "$dir" nopo
  for stage in material assemble solve; do
    run_stage $stage "$dir/strip.dat" "$dir" || { failed+=("$dir"); break; }
  done
  progress_step "fig512/elastic/n$n"
done
for n in "${nested[@]}"; do
  error_json "fig512/elastic/n$n" "fig512/elastic/n$reference"
done
# Away from the corners: the same errors on the sub-domain [1, 4] x [0, 1] (sig-error --window,
# error_interior.json), the march's and the clamped elastic strip's. And the labelled variant
# with rollers on Gamma1 (u1 = 0 only: no clamped corner; the foundation alone holds the
# vertical motion, so the step matrix is condensed with its interior factorized apart).
for n in "${nested[@]}"; do
  window_error_json "fig512/n$n" "fig512/n$reference" "$interior"
  window_error_json "fig512/elastic/n$n" "fig512/elastic/n$reference" "$interior"
done
for n in "$reference" "${nested[@]}"; do
  run "fig512/rollers/n$n" "$template" "n$n" --drop-card DIRICHLET \
    --add-card "DIRICHLET ref=1 ux=0" --add-card "DIRICHLET ref=4 ux=0" "${novtk[@]}"
done
for n in "${nested[@]}"; do
  error_json "fig512/rollers/n$n" "fig512/rollers/n$reference"
  window_error_json "fig512/rollers/n$n" "fig512/rollers/n$reference" "$interior"
done

# Fig 5.12 adapted (issue 29, full run only): the printed data from the 8 x 2 union-jack mesh,
# solve -> estimate -> mark -> refine (drivers/adapt.sh, Dörfler theta 0.5): one mesh for the whole
# march, marked on each triangle's largest indicator over the kept times t = 0.25 ... 1, the
# scene's k = 1/64 on every step (the time error at h = 1/64 is 1.3e-4 against E_hk = 9.4e-3).
# Against the overkill reference: the last adapted mesh refined uniformly twice, marched with
# k = 1/256, finer everywhere in space and time than every adapted run. The uniform reference
# gets its own estimate, every uniform run its error against the overkill beside its own.
if [ "$adapt_steps" -gt 0 ]; then
  adapted=$out/fig512/adapted
  mkdir -p "$adapted"
  deck_variant "$template" "$adapted/strip.dat" --set MESH.nx=8 --set MESH.ny=2 \
    --set TIME.output_every=16 --set OUTPUT.vtk=no
  deck_variant "$adapted/strip.dat" "$adapted/overkill.template.dat" \
    --set "TIME.k=$("$python" -c "print(1 / 256)")" --set TIME.output_every=64
  "$root/drivers/adapt.sh" "$adapted/strip.dat" -o "$adapted" --steps "$adapt_steps" \
    --theta 0.5 >"$adapted/adapt.log" 2>&1 ||
    { tail -20 "$adapted/adapt.log" >&2; die "adapt.sh failed"; }
  progress_step "fig512/adapted ($adapt_steps steps)"
  overkill_references "$adapted" "$adapt_steps" "$adapted/strip.dat" \
    "$adapted/overkill.template.dat"
  # The finest uniform mesh judged, by the same chain as the adaptive steps, for its wall clock.
  finest=${nested[-1]}
  deck_variant "$out/mesh_n$finest/base/strip.dat" "$adapted/uniform.dat" --set OUTPUT.vtk=no
  timed_chain "$adapted/uniform.dat" "$adapted/uniform"
  progress_step "fig512/adapted/uniform (n$finest by chain.sh)"
  adapted_errors fig512/adapted "$adapt_steps" fig512/n "fig512/n$reference" strip.dat \
    "${nested[@]}"
fi

# Speed against accuracy: the other contact methods on the nested meshes (pdas: fig512).
for n in "${speed_meshes[@]}"; do
  for variant in alm:100 projection:1 projection:0.01; do
    method=${variant%%:*}
    value=${variant#*:}
    name=speed/${method}_$value/n$n
    run "$name" "$template" "n$n" --drop SOLVER.gamma --set "SOLVER.method=$method" \
      --set "SOLVER.$(parameter_of "$method")=$value" "${novtk[@]}"
    error_json "$name" "fig512/n$reference"
  done
done

# The stability map: k x cn x g on the 64 x 12 mesh, the printed load with friction.
for k in "${map_k[@]}"; do
  for c in "${map_c[@]}"; do
    for g in "${map_g[@]}"; do
      run "map/k${k}_c${c}_g$g" "$template" 64 --set "TIME.k=$("$python" -c "print(1 / $k)")" \
        --set TIME.output_every=$k --set "CONTACT.cn=$c" --set "CONTACT.g=$g" "${novtk[@]}"
    done
  done
done
echo "scene5.sh: all runs done in $((SECONDS - start)) s"
record_seconds $start

"$python" "$root/postproc/scene5_report.py" "$out"
if [ ${#failed[@]} -gt 0 ]; then
  die "${#failed[@]} run(s) failed: ${failed[*]}"
fi
