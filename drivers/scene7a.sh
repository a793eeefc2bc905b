#!/usr/bin/env bash
# drivers/scene7a.sh [--quick] [-o OUTDIR]: the Hertz half disc of thesis ch. 7.4.1 (scene 7a,
# ../shared/SCENES.md) with every method and parameter of Tables 7.1-7.3, then its report.
#
#   full:    N = 128 256 512; error-vs-h study (Fig 7.10) at N = 64 128 256 512
#   --quick: N = 128 256;     error-vs-h study at N = 64 128 256 512 (PDAS only)
#
# Per N the bulk stages (sig-mesh, sig-material, sig-contact, sig-assemble) run once into
# OUTDIR/N<N>/base/; each method and parameter then gets OUTDIR/N<N>/<method>_<value>/ holding
# symlinks to the base DS files, its own deck (the template with N, method and parameter
# replaced) and what sig-solve and sig-post write there (case.b, summary.json, contact.csv, .pvd).
# sig-solve only reads case.tae and case.cont, so a variant costs one factorization and the
# contact iterations, not a new mesh.
#
# Methods and parameters (the thesis's values where it has them):
#   pdas        gamma in 1 10 1e2 1e3 1e4           (Table 7.2)
#   projection  c     in 1 10 1e2 1e3 1e4           (Table 7.1)
#   alm         r     in 1 10 1e2 1e3 1e4           (r = 1e2 is the ALM column of Tables 7.1/7.2)
#   penalty     r     in 1e2 1e3 1e4 1e5 1e6        (its error falls as 1/r: a speed/accuracy set)
# The error-vs-h study runs PDAS gamma = 1e2 twice: on the deck's graded mesh (OUTDIR/N<N>/,
# adding N = 64) and on the thesis's uniform mesh (MESH grading=0, OUTDIR/error/N<N>/). Only the
# uniform mesh refines everywhere with N (the graded one refines Gamma3 but keeps its interior
# growth law), so only it is an h-refinement in the sense of Fig 7.10.
# The Hertz half disc adapted (issue 29), OUTDIR/adapted/: drivers/adapt.sh from the uniform
# N = 16 (PDAS gamma = 1e2, Dörfler theta 0.5; 9 steps, 8 with --quick) against the overkill
# overkill2/, the last adapted mesh refined uniformly twice (finer everywhere than every adapted
# mesh: they nest); the uniform meshes of the error study against the uniform N = 512, finer
# everywhere than each of them (error/N<N>/pdas_1e2/error.json, sig-error's norm of V), with the
# references' own estimates (case.est): adapted meshes no worse per dof (the report's check).
# Then postproc/scene7a_report.py OUTDIR writes OUTDIR/report.md, its PNGs and OUTDIR/scene.json.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"
source "$(dirname "${BASH_SOURCE[0]}")/lib/adapted.sh"

usage() {
  cat <<EOF
usage: drivers/scene7a.sh [--quick] [-o OUTDIR]
  --quick     N = 128 256 instead of 128 256 512 (the error study keeps 64 ... 512)
  -o OUTDIR   results folder (default out/scene7a)
  -h, --help  this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/scene7a.sh${*:+ $*}"
template=$root/datafiles/scene7a/hertz.dat
parse_quick_out out/scene7a "$@"

require_stages mesh material contact assemble solve post error estimate refine adapt
require_decks "$template"
require_charts

# The error study keeps its N = 512 reference in the quick variant too: against a reference
# only twice finer, the reference's own error biases the slope (1.56 measured with 256).
if [ $quick -eq 1 ]; then
  meshes=(128 256)
  error_meshes=(64 128 256 512)
  adapt_steps=8
else
  meshes=(128 256 512)
  error_meshes=(64 128 256 512)
  adapt_steps=9
fi
sweep=(1 10 1e2 1e3 1e4)
penalty_sweep=(1e2 1e3 1e4 1e5 1e6)

mkdir -p "$out"
out=$(cd "$out" && pwd)

source "$root/drivers/lib/hertz_deck.sh"

# write_deck DECK N GRADING [METHOD VALUE]: the Hertz template for mesh N.
write_deck() {
  hertz_deck "$template" "$@"
}

# A variant whose stage fails (a crash, not a non-convergence: that is a result, "Nv") is listed
# here; the other runs and the report go on, and the script exits 1 at the end.
failed=()

# base FOLDER N GRADING: mesh, materials, contact elements and the assembled system of mesh N
# in FOLDER/N<N>/base.
base() {
  local n=$2 grading=$3 dir=$1/N$2/base
  rm -rf "$dir"
  mkdir -p "$dir"
  write_deck "$dir/hertz.dat" "$n" "$grading"
  build_base "$dir/hertz.dat" "$dir" "the base case of N = $n"
  progress_step "${dir#"$out"/}"
}

# variant FOLDER N GRADING METHOD VALUE: sig-solve and sig-post in FOLDER/N<N>/<method>_<value>/
# on the base DS files.
variant() {
  local n=$2 grading=$3 method=$4 value=$5
  local dir=$1/N$n/${method}_$value
  rm -rf "$dir"
  mkdir -p "$dir"
  link_ds ../base "$dir" nopo mili cont tae
  write_deck "$dir/hertz.dat" "$n" "$grading" "$method" "$value"
  run_stage solve "$dir/hertz.dat" "$dir" && run_stage post "$dir/hertz.dat" "$dir" ||
    failed+=("$dir")
  progress_step "${dir#"$out"/}"
}

{
  provenance
  echo "meshes: ${meshes[*]}"
  echo "error_meshes: ${error_meshes[*]}"
  echo "adapt_steps: $adapt_steps"
} >"$out/command.txt"
cp "$template" "$out/hertz.template.dat"

rm -rf "$out"/N[0-9]* "$out/error" "$out/adapted"
# Runs: per mesh a base and 20 variants; per mesh of the error study a uniform base and variant,
# and the graded pair where the sweep lacks that mesh.
runs=$((21 * ${#meshes[@]} + 2 * ${#error_meshes[@]} + 3)) # + the adapted loop, 2 overkills
for n in "${error_meshes[@]}"; do
  [[ " ${meshes[*]} " == *" $n "* ]] || runs=$((runs + 2))
done
progress_begin $runs
start=$SECONDS
for n in "${meshes[@]}"; do
  t0=$SECONDS
  base "$out" "$n" ""
  for value in "${sweep[@]}"; do
    variant "$out" "$n" "" pdas "$value"
    variant "$out" "$n" "" projection "$value"
    variant "$out" "$n" "" alm "$value"
  done
  for value in "${penalty_sweep[@]}"; do
    variant "$out" "$n" "" penalty "$value"
  done
  echo "scene7a.sh: N = $n done ($((SECONDS - t0)) s)"
done
# The error-vs-h study: the graded meshes the sweep lacks, then the uniform ones.
for n in "${error_meshes[@]}"; do
  t0=$SECONDS
  if [ ! -d "$out/N$n/base" ]; then
    base "$out" "$n" ""
    variant "$out" "$n" "" pdas 1e2
  fi
  base "$out/error" "$n" 0
  variant "$out/error" "$n" 0 pdas 1e2
  echo "scene7a.sh: N = $n (error study) done ($((SECONDS - t0)) s)"
done

# The adapted study: the loop from the uniform N = 16, its overkill, the errors of both series in
# the norm of V, each against a reference finer everywhere than the meshes it judges.
adapted=$out/adapted
mkdir -p "$adapted"
write_deck "$adapted/hertz.template.dat" 16 0 pdas 1e2
deck_variant "$adapted/hertz.template.dat" "$adapted/hertz.dat" --set OUTPUT.vtk=no
adapted_study "$adapted" "$adapted/hertz.dat" "$adapt_steps"
finest=${error_meshes[-1]}
run_stage estimate "$out/error/N$finest/pdas_1e2/hertz.dat" "$out/error/N$finest/pdas_1e2" ||
  failed+=("$out/error/N$finest/pdas_1e2 (sig-estimate)")
for n in "${error_meshes[@]::${#error_meshes[@]}-1}"; do
  error_json "error/N$n/pdas_1e2" "error/N$finest/pdas_1e2"
done
echo "scene7a.sh: all runs done in $((SECONDS - start)) s"
record_seconds $start

"$python" "$root/postproc/scene7a_report.py" "$out"
if [ ${#failed[@]} -gt 0 ]; then
  die "${#failed[@]} run(s) failed: ${failed[*]}"
fi
