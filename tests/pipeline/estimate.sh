#!/usr/bin/env bash
# Requirement (issue 29): sig-estimate gives per-triangle error indicators of a solved static
# case with contact and a global estimate whose effectivity (estimate / true error) lies in
# [0.3, 3] and which falls at the rate of the error. On datafiles/first/block.dat (Coulomb
# friction on Gamma3, no Dirichlet condition) at nx = 8, 16, 32, the true error is sig-error's
# against the same deck at nx = 128 (the structured rectangles nest: exact prolongation):
#  - effectivity in [0.3, 3] on each mesh, and the rates log2(e_h / e_h/2) of the estimate and
#    of the error within 0.15 of each other (both about 0.7: the block's corners and the ends of
#    the contact zone keep the solution out of H^2);
#  - case.est holds one indicator per triangle whose squares sum to the estimate's square,
#    sig-dump prints it, the .vtu holds the cell field error_indicator;
#  - a stale case.b (TRACTION changed), a missing one, a march (TIME card) without its case.hist
#    (a march is estimated from its kept states: tests/pipeline/adapt.sh) and a
#    large-deformation law (case.mili of law=svk) are refused.
set -euo pipefail
source tests/pipeline/lib/common.sh
require_stages mesh material contact assemble solve post estimate error dump

for n in 8 16 32 128; do
  sed -e "s/nx=16 ny=8/nx=$n ny=$((n / 2))/" datafiles/first/block.dat >"$work/b$n.dat"
  grep -q "nx=$n " "$work/b$n.dat" || die "block.dat no longer has nx=16 ny=8"
  SIG_BIN=$bin drivers/chain.sh "$work/b$n.dat" -o "$work/b$n" >"$work/chain$n.log" 2>&1 ||
    { tail -20 "$work/chain$n.log"; die "chain.sh failed on nx = $n"; }
done
for n in 8 16 32; do
  "$bin/sig-estimate" "$work/b$n.dat" -o "$work/b$n" >"$work/estimate$n.log" 2>&1 ||
    { cat "$work/estimate$n.log"; die "sig-estimate failed on nx = $n"; }
  "$bin/sig-dump" --json --values=estimate,indicator "$work/b$n/case.est" >"$work/est$n.json"
  "$bin/sig-error" --json "$work/b$n" "$work/b128" >"$work/err$n.json"
done

checks=$((checks + 1))
"$python" - "$work" <<'PY' || fail "effectivity, rates or indicators (above)"
import json, math, sys
work = sys.argv[1]
bad = []
previous = None
for n in (8, 16, 32):
    arrays = {a["name"]: a for a in json.load(open(f"{work}/est{n}.json"))["arrays"]}
    eta = arrays["estimate"]["values"][0]
    indicators = arrays["indicator"]["values"]
    error = json.load(open(f"{work}/err{n}.json"))["error"]
    effectivity = eta / error
    print(f"nx = {n}: estimate {eta:.6g}, error {error:.6g}, effectivity {effectivity:.3f}")
    if len(indicators) != n * n:
        bad.append(f"nx = {n}: {len(indicators)} indicators for {n * n} triangles")
    if abs(math.sqrt(sum(e * e for e in indicators)) - eta) > 1e-12 * eta:
        bad.append(f"nx = {n}: the indicators' squares do not sum to the estimate's")
    if not 0.3 <= effectivity <= 3:
        bad.append(f"nx = {n}: effectivity {effectivity:.3f} outside [0.3, 3]")
    if previous:
        rate_eta, rate_error = math.log2(previous[0] / eta), math.log2(previous[1] / error)
        print(f"  rates: estimate {rate_eta:.3f}, error {rate_error:.3f}")
        if abs(rate_eta - rate_error) > 0.15 or rate_eta < 0.5:
            bad.append(f"nx = {n}: estimate rate {rate_eta:.3f}, error rate {rate_error:.3f}")
    previous = (eta, error)
for b in bad:
    print("FAIL:", b)
sys.exit(1 if bad else 0)
PY

checks=$((checks + 3))
"$bin/sig-dump" "$work/b8/case.est" | grep -q "^DS EST" || fail "sig-dump does not print case.est"
grep -q 'Name="error_indicator"' "$work/b8/b8_estimate.vtu" ||
  fail "b8_estimate.vtu has no cell field error_indicator"
grep -q "^sig-estimate: eta = " "$work/estimate8.log" || fail "sig-estimate does not print eta"

# Bad input: a stale case.b, a missing one, a march without its case.hist.
cp -r "$work/b8" "$work/stale"
sed -e 's/f=0.2,-1/f=0.2,-1.5/' "$work/b8.dat" >"$work/stale.dat"
refused "stale case.b" estimate "$work/stale.dat" "$work/stale" "case.b is stale" "TRACTION" \
  "rerun sig-assemble"
rm "$work/stale/case.b"
refused "missing case.b" estimate "$work/b8.dat" "$work/stale" "case.b"
cp "$work/b8.dat" "$work/march.dat"
echo "TIME scheme=midpoint T=1 k=0.1" >>"$work/march.dat"
refused "a march without case.hist" estimate "$work/march.dat" "$work/b8" "case.hist" \
  "DS file not found"
sed -e 's/^MATERIAL .*/MATERIAL law=svk E=100 nu=0.3 plane=strain/' "$work/b8.dat" >"$work/svk.dat"
"$bin/sig-mesh" "$work/svk.dat" -o "$work/svk" >/dev/null && "$bin/sig-material" "$work/svk.dat" -o "$work/svk" >/dev/null ||
  die "sig-mesh or sig-material failed on an svk deck"
refused "a large-deformation law" estimate "$work/svk.dat" "$work/svk" "case.mili" "sub-domain 1" \
  "small-strain solutions only"
finish "effectivity and rate on the frictional block, indicators, bad inputs: $checks checks"
