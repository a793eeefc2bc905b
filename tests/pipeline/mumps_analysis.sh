#!/usr/bin/env bash
# Requirement (issue 27, "Scale": the largest 3D ball that factorizes in minutes is chosen from
# MUMPS's analysis, drivers/bench-mpi.sh --analysis-only): sig-solve with SIG_MUMPS_ANALYSIS=FILE
# appends one line of the analysis's estimates to FILE and stops there, exit 0 and no case.b
# written (StageExit: past the contact zone's retries, which catch sig::Error). On a coarse half
# ball with linear=mumps and a zone that holds the contact at once (one analysis), the line's
# order is the solve's (summary.json's pivots, the Schur variables among them), its Schur
# variables the solve's condensed candidates, and its flops RINFOG(1) and largest front INFOG(5)
# those of the full solve's analysis and factorization (summary.json `mumps`: flops_estimate, and
# the largest front INFOG(11), which no delayed pivot makes larger here).
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_command gmsh "the half ball generator meshes through gmsh"

cp "$root/tests/pipeline/data/mumps_ball.dat" "$work/ball.dat"
"$root/drivers/chain.sh" "$work/ball.dat" -o "$work/full" >"$work/full.log" 2>&1 ||
  { tail -20 "$work/full.log"; die "drivers/chain.sh ball.dat failed"; }
mkdir "$work/analysis"
for ds in nopo mili cont tae; do
  ln -s "$work/full/case.$ds" "$work/analysis/case.$ds"
done
status=0
SIG_MUMPS_ANALYSIS=$work/estimates.tsv "$bin/sig-solve" "$work/ball.dat" -o "$work/analysis" \
  >"$work/analysis.log" 2>&1 || status=$?
checks=$((checks + 1))
[ "$status" -eq 0 ] || fail "sig-solve with SIG_MUMPS_ANALYSIS exited $status: $(tail -3 "$work/analysis.log")"
checks=$((checks + 1))
[ ! -e "$work/analysis/case.b" ] || fail "sig-solve with SIG_MUMPS_ANALYSIS wrote case.b"
checks=$((checks + 1))
grep -q "stopped after the analysis" "$work/analysis.log" ||
  fail "the log does not say the stage stopped after the analysis: $(cat "$work/analysis.log")"
checks=$((checks + 1))
"$python" - "$work/estimates.tsv" "$work/full/summary.json" <<'PY' || fail "the estimates"
import json, sys
lines = open(sys.argv[1]).read().splitlines()
s = json.load(open(sys.argv[2]))
m = s["mumps"]
problems = []
if len(lines) != 1:
    problems.append(f"{len(lines)} lines, not one analysis")
f = lines[0].split("\t")
if len(f) != 10:
    problems.append(f"{len(f)} fields, not 10: {lines[0]}")
n, schur, flops, front = int(f[0]), int(f[1]), float(f[4]), int(f[6])
if n != sum(m["rank_pivots"]):
    problems.append(f"order {n}, the solve's {sum(m['rank_pivots'])} pivots")
if schur != m["schur_size"] or schur < 1:
    problems.append(f"{schur} Schur variables, the solve's {m['schur_size']}")
if abs(flops - m["flops_estimate"]) > 1e-12 * m["flops_estimate"]:
    problems.append(f"RINFOG(1) {flops}, the solve's {m['flops_estimate']}")
if front != m["largest_front"]:
    problems.append(f"INFOG(5) {front}, the solve's INFOG(11) {m['largest_front']}")
if problems:
    print("\n".join(problems))
    sys.exit(1)
PY
finish "SIG_MUMPS_ANALYSIS: MUMPS's estimates, the full solve's, and the stage stopped"
