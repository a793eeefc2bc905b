#!/usr/bin/env bash
# Requirement (issue 23): the CI's robustness map (drivers/robustness.sh --quick) runs, every one
# of its checks passes (ALM and PDAS converge at every point of the Signorini and Coulomb decks,
# from 1e-2 to 1e4 times the parameter's natural scale), and every point that does not converge
# carries a named failure, never a bare Nv.
set -euo pipefail
bin=${SIG_BIN:?SIG_BIN is not set}
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() {
  echo "robustness_quick: $*" >&2
  exit 1
}

SIG_BIN=$bin "$root/drivers/robustness.sh" --quick -o "$work/map" > "$work/log" 2>&1 ||
  fail "drivers/robustness.sh --quick failed: $(tail -5 "$work/log")"
report=$work/map/report.md
[ -s "$report" ] || fail "no report.md"
grep -q "PASS" "$report" || fail "no check passed: $(grep -E 'PASS|FAIL' "$report")"
if grep -q "FAIL" "$report"; then
  fail "a check failed: $(grep FAIL "$report")"
fi
# Every point has iterations or a named failure (map.json: one object per solve).
python3 - "$work/map/map.json" <<'PY'
import json, sys
names = {"cycling", "stagnation", "divergence", "drift", "iteration-limit", "singular-step"}
n = 0
for point in json.load(open(sys.argv[1]))["points"]:
    n += 1
    if not point["converged"] and point.get("failure") not in names:
        sys.exit(f"robustness_quick: a point without a named failure: {point}")
if n < 30:
    sys.exit(f"robustness_quick: only {n} solves in the quick map")
print(f"robustness_quick: {n} solves, every failure named")
PY
