#!/usr/bin/env bash
# Pipeline test, scene 6 check 2 of ALGORITHMS.md 3.6: the rail (2 x 0.1, both ends clamped, at
# 256 x 16 cells) on bilateral Winkler springs (CONTACT law=compliance-bilateral), frictionless,
# under the moving load's Gaussian held at x0 = 1, static (sig-solve), against the semi-analytic
# infinite strip of postproc/winkler_strip.py: the peak bottom and top deflections and the peak
# spring pressure within 1 % at psi = 10, 50 and 200 (the clamped ends 1 m away and the mesh
# account for 0.2-0.4 %).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
python=${PYTHON:-/usr/bin/python3}
"$python" -c 'import numpy' 2>/dev/null || { echo "scene6_winkler: skipped, no numpy"; exit 77; }
source "$root/drivers/lib/deck.sh"
die() { echo "scene6_winkler: $*" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SIG_BIN=$bin
failures=0
for psi in 10 50 200; do
  deck=$work/winkler_$psi.dat
  deck_variant "$root/datafiles/scene6/winkler.dat" "$deck" --set MESH.ny=16 --set MOVINGLOAD.psi=$psi
  "$root/drivers/chain.sh" "$deck" -o "$work/psi$psi" > "$work/psi$psi.log" 2>&1 ||
    { cat "$work/psi$psi.log" >&2; die "the chain failed at psi = $psi"; }
  if ! PYTHONPATH=$root/postproc "$python" "$root/postproc/winkler_strip.py" \
      --compare "$deck" "$work/psi$psi" --tolerance 0.01 > "$work/compare$psi.json"; then
    echo "FAIL: psi = $psi beyond 1 % of the strip:"; cat "$work/compare$psi.json"
    failures=$((failures + 1))
  fi
  "$python" -c "
import json
r = json.load(open('$work/compare$psi.json'))
print('psi = $psi: ' + ', '.join('%s %.5f (strip %.5f, %+.2f %%)' % (q, v['ours'], v['strip'], 100 * v['relative']) for q, v in r.items()))"
done
[ "$failures" -eq 0 ] || exit 1
echo "scene6_winkler: the rail within 1 % of the Winkler strip at psi = 10, 50, 200"
