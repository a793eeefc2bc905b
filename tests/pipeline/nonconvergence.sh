#!/usr/bin/env bash
# Requirement: non-convergence is a result, not a crash. A contact method stopped by its
# iteration limit exits 0, and case.b / summary.json record converged = false, the iterations
# done, the reason and the residual history (the tables print "Nv").
set -euo pipefail
bin=${SIG_BIN:?SIG_BIN is not set}
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
die() {
  echo "nonconvergence: $*" >&2
  exit 1
}
source drivers/lib/hertz_deck.sh

# The projection method with a small c needs a dozen iterations on this mesh: allow 3.
hertz_deck datafiles/scene7a/hertz.dat "$work/nv.dat" 64 "" projection 1
sed -i -E '/^[[:space:]]*SOLVER[[:space:]]/ s/maxit=[^[:space:]]+/maxit=3/' "$work/nv.dat"
grep -q "maxit=3" "$work/nv.dat" || die "could not set maxit"
for stage in mesh material contact assemble solve post; do
  run_stage "$stage" "$work/nv.dat" "$work" || die "sig-$stage failed on a non-converging case"
done
grep -q "NOT converged (Nv)" "$work/solve.log" || die "sig-solve did not announce Nv: $(cat "$work/solve.log")"
/usr/bin/python3 - "$work/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
assert s["converged"] is False, s["converged"]
assert s["iterations"] == 3 and len(s["residual_history"]) == 3, s["iterations"]
assert s["failure"] == "iteration-limit", s["failure"]
assert "iteration limit" in s["failure_detail"], s["failure_detail"]
print(f"nonconvergence: projection c = 1, maxit = 3: converged {s['converged']}, "
      f"{s['iterations']} iterations, residuals {[f'{r:.2e}' for r in s['residual_history']]}")
PY
