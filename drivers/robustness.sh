#!/usr/bin/env bash
# drivers/robustness.sh [--quick] [-o OUTDIR]: the robustness map of the contact Newton (issue 23,
# postproc/robustness_map.py): every method on the Hertz deck (scene 7a), the frictional Hertz deck
# with Coulomb and Tresca, scene 4's ball and square, scene 7b's ring in one and in 14 load steps,
# and in 3D the Hertz half ball, frictionless and sheared with Coulomb's cone (the Cattaneo-Mindlin
# deck), the method's parameter over 1e-2 .. 1e4 times its natural scale (r, gamma: E / h; c: h / E)
# in half decades, two meshes each, from rest and from the scene's start; per point the Newton
# iterations or the failure's name. Then OUTDIR/report.md with one map per deck, the checks (ALM and
# PDAS converge at every point of the Signorini, Tresca and Coulomb decks, 2D and 3D) and the
# theory's reason where a method or a law leaves what it covers.
#
#   full:    about 1350 solves
#   --quick: the Hertz, Coulomb and Tresca decks, the ring and the 3D Coulomb ball, one mesh and
#            one start each, pdas, alm and projection at 1e-2, 1, 1e2, 1e4 (the CI's variant)
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"
usage() {
  cat <<USAGE
usage: drivers/robustness.sh [--quick] [-o OUTDIR]
  --quick     the CI's map (5 decks, 3 methods, 4 parameters) instead of the full one
  -o OUTDIR   results folder (default out/robustness)
  -h, --help  this message
USAGE
}
invocation="drivers/robustness.sh${*:+ $*}"
parse_quick_out out/robustness "$@"
require_stages mesh material contact assemble solve
require_charts
template="the decks of postproc/robustness_map.py"
rm -rf "$out"
mkdir -p "$out"
provenance >"$out/command.txt"
flags=()
[ "$quick" -eq 1 ] && flags+=(--quick)
start=$SECONDS
"$python" "$root/postproc/robustness_map.py" run "$out" "${flags[@]}" > "$out/runs.log"
echo "robustness: $(grep -c . "$out/runs.log") solves in $((SECONDS - start)) s"
record_seconds "$start"
"$python" "$root/postproc/robustness_map.py" report "$out"
