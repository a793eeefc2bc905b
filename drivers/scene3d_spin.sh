#!/usr/bin/env bash
# drivers/scene3d_spin.sh [--quick] [--k K] [-o OUTDIR]: Gonzalez in 3D (issue 28): the free
# spinning hyperelastic ball of datafiles/scene3d/spinning_ball.dat marched with Gonzalez's
# algorithmic stress and with the plain midpoint stress, then postproc/scene3d_spin_report.py:
# the energy and the angular momentum of every kept state against the first (OUTDIR/report.md,
# OUTDIR/summary.json).
#
#   full:    the deck's 1000 steps of k = 1e-3 s
#   --quick: its first 50 steps (the pipeline test, tests/pipeline/spin3d.sh)
#   --k K:   1000 steps (--quick: 50) of k = K instead (the README's larger steps)
#
# OUTDIR/base holds the DS files of sig-mesh, sig-material and sig-assemble; OUTDIR/<stress>/ a
# run (its deck, case.hist, energy.csv, march.log, wall.txt).
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3), SIG_GMSH.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<USAGE
usage: drivers/scene3d_spin.sh [--quick] [--k K] [-o OUTDIR]
  --quick     the first 50 steps (a few seconds)
  --k K       the time step (default the deck's, 1e-3 s); 1000 steps (--quick: 50) of it
  -o OUTDIR   results folder (default out/scene3d_spin)
  -h, --help  this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3),
SIG_GMSH (default gmsh: the ball's mesher).
USAGE
}

invocation="drivers/scene3d_spin.sh${*:+ $*}"
template=$root/datafiles/scene3d/spinning_ball.dat
out=out/scene3d_spin
quick=0
step=
parse_options -o=out --quick:quick=1 --k=step -- "$@"

require_stages mesh material assemble march dump
require_decks "$template"
command -v "${SIG_GMSH:-gmsh}" >/dev/null || die "gmsh is needed to mesh the ball"

mkdir -p "$out/base"
out=$(cd "$out" && pwd)
echo "$invocation" >"$out/command.txt"
start=$SECONDS
base=$out/base
steps=1000
[ $quick -eq 1 ] && steps=50
[ -n "$step" ] || step=$(deck_value "$template" TIME k) || die "no TIME k= in $template"
T=$("$python" -c "print(repr($steps * float('$step')))") || die "--k must be a number, got '$step'"
deck_variant "$template" "$base/spinning_ball.dat" --set TIME.k="$step" --set TIME.T="$T"
build_base "$base/spinning_ball.dat" "$base" "the ball" mesh material assemble
failed=()
for stress in gonzalez midpoint; do
  dir=$out/$stress
  rm -rf "$dir"
  mkdir -p "$dir"
  link_ds ../base "$dir" nopo mili tae
  deck_variant "$base/spinning_ball.dat" "$dir/spinning_ball.dat" --set TIME.stress=$stress
  run_timed march "$dir/spinning_ball.dat" "$dir" || failed+=("$dir")
done
echo "scene3d_spin.sh: all runs done in $((SECONDS - start)) s"
record_seconds $start

"$python" "$root/postproc/scene3d_spin_report.py" "$out"
if [ ${#failed[@]} -gt 0 ]; then
  die "${#failed[@]} run(s) failed: ${failed[*]}"
fi
