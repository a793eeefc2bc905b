#!/usr/bin/env bash
# drivers/bench-scene4.sh [--repeat K] [-o OUTDIR]: the cost of the convexification loop of
# scene 4 at the thesis's size (the ball of datafiles/scene4/ball.dat on the mesh T of
# drivers/scene4.sh: 512 uniform boundary segments, grading 0.011, 21068 dofs, 128 contact
# elements) against one factorization of its stiffness matrix.
#
# The bulk is linear, so the loop condenses it once (one sparse factorization with the Schur
# complement onto Gamma3) and every outer iteration reuses that condensed problem: the target of
# issue 11 is a solve costing at most (outer iterations) x 0.2 of one factorization beyond that
# one factorization, i.e. (phases - floor) / floor <= 0.2 x outer.
#   phases: every sig-solve phase of summary.json but sig-assemble's (frames, factorize, schur,
#           solve: the condensation and the whole loop, every outer iteration's expansion to the
#           body for the norm of V included)
#   floor:  one analyze + factorization + solve of the stiffness matrix of the same mesh, Gamma3
#           held by DIRICHLET (the deck without its contact cards, SOLVER method=linear), by MUMPS
#           and by CHOLMOD, the faster taken
# Cases: fig42 (a = 2, b = 0.02, alpha = 1), fig45 (a = 1, b = 0.5, alpha = 100) and slow
# (a = 2, b = 1, alpha = 100: the map's slowest of these at the thesis's size), pdas gamma = 2e2.
# K rounds (default 5) run round robin; medians; run it on a quiet machine
# (nothing else building or running) for figures worth quoting. Writes
# OUTDIR/bench.md, bench.json and times.tsv (default out/bench-scene4).
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/bench-scene4.sh [--repeat K] [-o OUTDIR]
  --repeat K   timed rounds, medians reported (default 5)
  -o OUTDIR    results folder (default out/bench-scene4)
  -h, --help   this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/bench-scene4.sh${*:+ $*}"
parse_repeat_out out/bench-scene4 5 "$@"
template=$root/datafiles/scene4/ball.dat
require_decks "$template"
require_stages mesh material contact assemble solve post

mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -rf "$out"/base "$out"/case_* "$out"/floor*
base=$out/base
mkdir -p "$base"
# The thesis's size: mesh T of drivers/scene4.sh.
deck_variant "$template" "$base/ball.dat" --set MESH.grading=0.011 --set OUTPUT.vtk=no
build_base "$base/ball.dat" "$base" "the thesis-size ball"

declare -A cases=([fig42]="" [fig45]="--set FRICTION.a=1 --set FRICTION.b=0.5 --set FRICTION.alpha=100"
  [slow]="--set FRICTION.b=1 --set FRICTION.alpha=100")
runs=()
for name in fig42 fig45 slow; do
  dir=$out/case_$name
  mkdir -p "$dir"
  link_ds ../base "$dir" nopo mili tae
  # shellcheck disable=SC2086
  deck_variant "$base/ball.dat" "$dir/ball.dat" ${cases[$name]}
  if cmp -s <(grep -i '^FRICTION' "$dir/ball.dat") <(grep -i '^FRICTION' "$base/ball.dat"); then
    link_ds ../base "$dir" cont
  else
    run_stage contact "$dir/ball.dat" "$dir" || die "sig-contact failed for case $name"
  fi
  runs+=("$name $dir")
done
floor=$out/floor
mkdir -p "$floor"
link_ds ../base "$floor" nopo mili
deck_variant "$base/ball.dat" "$floor/ball.dat" --replace-card CONTACT "DIRICHLET ref=3 ux=0 uy=0" \
  --drop-card FRICTION --drop-card CONVEXIFICATION --drop SOLVER.gamma --drop SOLVER.eps \
  --drop SOLVER.maxit --set SOLVER.method=linear
run_stage assemble "$floor/ball.dat" "$floor" || die "cannot assemble the floor problem"
for backend in mumps cholmod; do
  dir=$out/floor_$backend
  mkdir -p "$dir"
  link_ds ../floor "$dir" nopo mili tae
  deck_variant "$floor/ball.dat" "$dir/ball.dat" --set "SOLVER.linear=$backend"
  runs+=("floor_$backend $dir")
done

echo "bench-scene4.sh: $repeat rounds, results in $out"
printf 'name\trun\tsummary\n' >"$out/times.tsv"
for k in $(seq 1 "$repeat"); do
  for entry in "${runs[@]}"; do
    name=${entry%% *}
    dir=${entry#* }
    run_stage solve "$dir/ball.dat" "$dir" && run_stage post "$dir/ball.dat" "$dir" ||
      die "timing run $name failed"
    cp "$dir/summary.json" "$dir/summary.$k.json"
    printf '%s\t%s\t%s\n' "$name" "$k" "$dir/summary.$k.json" >>"$out/times.tsv"
  done
  echo "bench-scene4.sh: round $k of $repeat timed"
done

bench_provenance >"$out/command.txt"

"$python" - "$out" <<'EOF'
import csv, json, statistics, sys
from pathlib import Path

out = Path(sys.argv[1])
info = dict(l.split(": ", 1) for l in (out / "command.txt").read_text().splitlines() if ": " in l)
runs = {}
with open(out / "times.tsv") as f:
    for row in csv.DictReader(f, delimiter="\t"):
        s = json.loads(Path(row["summary"]).read_text())
        t = {p: float(v) for p, v in s["times"].items() if p != "assemble"}
        loop = s.get("convexification") or {}
        runs.setdefault(row["name"], []).append({
            "phases": sum(t.values()), "times": t, "dofs": s["dofs"], "converged": s["converged"],
            "outer": loop.get("outer_iterations"), "inner": s["iterations"]})
median = {n: statistics.median(r["phases"] for r in rs) for n, rs in runs.items()}
backend = min(("mumps", "cholmod"), key=lambda b: median[f"floor_{b}"])
floor = median[f"floor_{backend}"]
CASES = {"fig42": "Fig 4.2: a = 2, b = 0.02, alpha = 1", "fig45": "Fig 4.5: a = 1, b = 0.5, alpha = 100",
         "slow": "a = 2, b = 1, alpha = 100"}
rows, result = [], {"floor_backend": backend, "floor_seconds": floor, "cases": {}}
for name, title in CASES.items():
    rs = runs[name]
    phases = median[name]
    outer = rs[0]["outer"]
    beyond = (phases - floor) / floor
    target = 0.2 * outer
    per_phase = {p: statistics.median(r["times"][p] for r in rs) for p in rs[0]["times"]}
    ok = all(r["converged"] for r in rs)
    # The same measure against the run's own factorization (with the Schur complement).
    own = per_phase["factorize"]
    beyond_own = (phases - own) / own
    rows.append([title, rs[0]["dofs"], f"{outer} ({rs[0]['inner']})" if ok else "Nv",
                 f"{phases:.3f}", ", ".join(f"{p} {v:.3f}" for p, v in per_phase.items()),
                 f"{phases / floor:.2f}", f"{beyond:.2f}", f"{beyond_own:.2f}", f"{target:.1f}",
                 "PASS" if ok and max(beyond, beyond_own) <= target else "FAIL"])
    result["cases"][name] = {"title": title, "outer": outer, "inner": rs[0]["inner"],
                             "phases_median": phases, "phases": per_phase,
                             "beyond_floor_over_floor": beyond,
                             "beyond_own_factorization": beyond_own, "target": target,
                             "pass": ok and max(beyond, beyond_own) <= target}
n = len(runs["fig42"])
lines = [f"# Scene 4 benchmark: the convexification loop at the thesis's size", "",
         f"Produced by `{info['command']}` on {info['date']} ({info['host']}, revision "
         f"{info['revision']}). Medians of {n} rounds, round robin. Phases = every sig-solve "
         "phase but assembly; the floor = one analyze + factorization + solve of the stiffness "
         "matrix of the same mesh (Gamma3 held, no contact) by MUMPS and CHOLMOD, the faster "
         f"taken: {backend}, {floor:.3f} s (mumps {median['floor_mumps']:.3f} s, cholmod "
         f"{median['floor_cholmod']:.3f} s). Target (issue 11): (phases - floor) / floor <= 0.2 "
         "x outer iterations; the same is shown against the run's own factorization (MUMPS with "
         "the Schur complement onto Gamma3, its `factorize` phase), and both must hold.", "",
         "| case | dofs | outer (inner) | phases s | per phase s | phases / floor | "
         "(phases - floor) / floor | (phases - factorize) / factorize | target 0.2 x outer | "
         "result |",
         "|---|---|---|---|---|---|---|---|---|---|"]
lines += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
(out / "bench.md").write_text("\n".join(lines) + "\n")
(out / "bench.json").write_text(json.dumps(result, indent=1) + "\n")
print("\n".join(lines))
EOF
