#!/usr/bin/env bash
# Requirement (issue 23): against GetFEM 5.4's nodal Alart-Curnier Newton on the same mesh, from
# the same start and judged by one residual (postproc/getfem_newton_counts.py: the nodal
# equilibrium and complementarity residual below 1e-10 of the load, computed the same way for
# both), static Coulomb on the half disc with no Dirichlet condition (the frictional Hertz deck at
# N = 64, started from the rigid shift (0, -h^2 / R) that puts its three lowest nodes in contact):
# at GetFEM's r = E, r / 10 and 10 r, from that shift and from rest, PDAS and ALM converge in at
# most GetFEM's count + 2 (or, where GetFEM does not converge within 30 iterations, they do), and
# their nodal forces agree with GetFEM's to 1e-8 of the largest where both converge.
# Skips (exit 77) without GetFEM (/usr/bin/python3 -c 'import getfem') or gmsh.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
python=/usr/bin/python3
command -v gmsh >/dev/null || { echo "newton_getfem: skipped, no gmsh"; exit 77; }
"$python" -c 'import getfem, numpy, scipy' 2>/dev/null ||
  { echo "newton_getfem: skipped, $python cannot import getfem (Debian: python3-getfem)"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
shift_u2=$("$python" -c "import math; h = math.pi * 8 / 64; print(repr(-h * h / 8))")
sed -e 's/N=256/N=64/' -e "s/^INITIAL .*/INITIAL u=0,$shift_u2/" \
  "$root/datafiles/friction/hertz_coulomb.dat" >"$work/deck.dat"
failed=0
for r in 15 150 1500; do
  for start in deck rest; do
    for method in pdas alm; do
      json=$work/$r-$start-$method.json
      SIG_BIN=$bin "$python" "$root/postproc/getfem_newton_counts.py" --deck "$work/deck.dat" \
        --r-getfem "$r" --start "$start" --method "$method" --max 30 --json "$json" | tail -1
      "$python" - "$json" <<'PY' || failed=1
import json, sys
s = json.load(open(sys.argv[1]))
where = f"{s['method']} r_getfem {s['r_getfem']:g} start {s['start']}"
if s["ours"] is None:
    sys.exit(f"FAIL {where}: ours did not reach the residual")
if s["getfem"] is not None:
    if s["ours"] > s["getfem"] + 2:
        sys.exit(f"FAIL {where}: {s['ours']} iterations against GetFEM's {s['getfem']} + 2")
    if s["force_difference"] > 1e-8:
        sys.exit(f"FAIL {where}: forces differ by {s['force_difference']:.2e} of their maximum")
PY
    done
  done
done
exit $failed
