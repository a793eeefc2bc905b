#!/usr/bin/env bash
# drivers/bench-ball.sh [--repeat N] [--steps S] [-o OUTDIR]: the speed target of issue 5 for
# scene 8a: each contact strategy of the ball impact at the thesis's mesh size (7706 nodes, 128
# contact nodes: meshes/ball.geo with h = 0.08, grading = 0.017) and 2000 steps (T = 2,
# k = 1e-3, the impact at t = 1.5 s), timed against the same march without contact, whose
# every step is one solve with the factorized step matrix K + (4 / k^2) M of the same size.
#
# Per strategy: the wall time of sig-march (median of N runs, default 3), the time per step,
# its ratio to the contact-free step, and "< 1 min: yes/no". Nothing is asserted: the numbers go
# to OUTDIR/report.md (default out/bench-ball) and bench.csv. States are kept only at the start
# and the end, so output does not weigh in the times.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3), GMSH (default gmsh).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/bench-ball.sh [--repeat N] [--steps S] [-o OUTDIR]
  --repeat N  runs per strategy, the median is reported (default 3)
  --steps S   time steps of k = 1e-3 (default 2000; the impact needs S > 1500)
  -o OUTDIR   results folder (default out/bench-ball)
Environment: SIG_BIN, PYTHON, GMSH (default gmsh).
EOF
}

out=out/bench-ball
repeat=3
steps=2000
parse_options --repeat=repeat --steps=steps -o=out -- "$@"
require_positive --repeat "$repeat"
require_positive --steps "$steps"
require_stages mesh material contact assemble march
gmsh=${GMSH:-gmsh}
command -v "$gmsh" >/dev/null || die "no gmsh ($gmsh)"
template=$root/datafiles/scene8a/ball.dat
mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -rf "$out/base" "$out/runs"
mkdir -p "$out/base" "$out/runs"

T=$("$python" -c "print($steps * 1e-3)")
"$gmsh" "$root/meshes/ball.geo" -2 -format msh41 -setnumber cy 25 -setnumber R 10 \
  -setnumber N 128 -setnumber h 0.08 -setnumber grading 0.017 -o "$out/base/thesis.msh" \
  >"$out/base/gmsh.log" 2>&1 || die "gmsh failed (see $out/base/gmsh.log)"

# deck OUTPUT CONTACT_FIELDS MASS: ball.dat on the thesis mesh, 2 kept states, no VTK. An empty
# CONTACT_FIELDS drops the CONTACT card: the contact-free reference.
deck() {
  local contact=(--replace-card CONTACT "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 $2")
  [ -n "$2" ] || contact=(--drop-card CONTACT)
  deck_variant "$template" "$1" --replace-card MESH "MESH file=$out/base/thesis.msh" "${contact[@]}" \
    --replace-card TIME "TIME scheme=midpoint T=$T k=1e-3 output_every=$steps mass=$3" \
    --replace-card OUTPUT "OUTPUT vtk=no"
}

deck "$out/base/ball.dat" "" consistent
build_base "$out/base/ball.dat" "$out/base" "the base case" mesh material assemble
nodes=$(grep -m1 -oE '[0-9]+ nodes' "$out/base/mesh.log" | cut -d' ' -f1)

r=1e12
g=5e-4
declare -A fields=(
  [no-contact]="|consistent"
  [signorini]="strategy=signorini|consistent"
  [compliance]="strategy=compliance r=$r|consistent"
  [specific-penalty]="strategy=specific-penalty r=$r|consistent"
  [emm]="strategy=signorini|emm"
  [two-step]="strategy=two-step|consistent"
  [ipm]="strategy=ipm r=$r gap=$g|consistent"
  [ipm-emm]="strategy=ipm r=$r gap=$g|emm"
)
methods=(no-contact signorini compliance specific-penalty emm two-step ipm ipm-emm)

for method in "${methods[@]}"; do
  dir=$out/runs/$method
  mkdir -p "$dir"
  link_ds "$out/base" "$dir" nopo mili tae
  f=${fields[$method]}
  deck "$dir/ball.dat" "${f%|*}" "${f#*|}"
  if [ -n "${f%|*}" ]; then
    run_stage contact "$dir/ball.dat" "$dir" || die "cannot build the contact elements of $method"
  fi
done

# Round robin: run i of every method before run i + 1 of any, so that a burst of load on the
# shared machine falls on all methods alike rather than on the runs of one.
echo "method,run,wall_seconds,steps_done" >"$out/bench.csv"
for ((i = 1; i <= repeat; i++)); do
  for method in "${methods[@]}"; do
    dir=$out/runs/$method
    t0=$(date +%s.%N)
    status=ok
    "$bin/sig-march" "$dir/ball.dat" -o "$dir" >"$dir/march.log" 2>&1 || status=failed
    t1=$(date +%s.%N)
    done_steps=$(($(wc -l <"$dir/energy.csv" 2>/dev/null || echo 2) - 2))
    [ $status = ok ] || done_steps=-1
    echo "$method,$i,$("$python" -c "print(f'{$t1 - $t0:.3f}')"),$done_steps" >>"$out/bench.csv"
  done
  echo "bench-ball.sh: round $i of $repeat done"
done
for method in "${methods[@]}"; do
  echo "bench-ball.sh: $method: $(grep "^$method," "$out/bench.csv" | cut -d, -f3 | tr '\n' ' ')s"
done

"$python" - "$out" "$nodes" "$steps" "$repeat" <<'PY'
import csv, statistics, sys
from pathlib import Path
out, nodes, steps, repeat = Path(sys.argv[1]), sys.argv[2], int(sys.argv[3]), sys.argv[4]
rows = list(csv.DictReader(open(out / "bench.csv")))
methods = list(dict.fromkeys(r["method"] for r in rows))
walls = {m: [float(r["wall_seconds"]) for r in rows if r["method"] == m] for m in methods}
median = {m: statistics.median(w) for m, w in walls.items()}
done = {m: min(int(r["steps_done"]) for r in rows if r["method"] == m) for m in methods}
free_step = median["no-contact"] / steps
md = ["# Benchmark: scene 8a at the thesis's mesh size", "",
      f"Command: `drivers/bench-ball.sh --repeat {repeat} --steps {steps}`. Mesh: {nodes} nodes "
      "(thesis: 7820), 128 contact nodes on the whole circle; T = "
      f"{steps * 1e-3:g} s, k = 1e-3 ({steps} steps), the impact at t = 1.5 s. Wall time of "
      f"sig-march (reading the DS files, factorizing, marching, writing case.hist), median of "
      f"{repeat}. The reference is the same march without contact: each of its steps is one "
      f"solve with the factorized step matrix K + (4 / k^2) M, {free_step * 1e3:.3f} ms.", "",
      "| strategy | wall (s) | runs (s) | per step (ms) | ratio to a contact-free step (one "
      "solve) | steps done | < 1 min |",
      "|---|---|---|---|---|---|---|"]
for m in methods:
    per = median[m] / steps
    steps_done = done[m] if done[m] >= 0 else "stage failed"
    spread = " ".join(f"{w:.2f}" for w in walls[m])
    md.append(f"| {m} | {median[m]:.2f} | {spread} | {per * 1e3:.3f} | {per / free_step:.2f} | "
              f"{steps_done} | {'yes' if median[m] < 60 and done[m] == steps else 'no'} |")
md += ["", "The machine is shared (2 cores): the spread of the runs is the noise of the "
       "other users; the runs go round robin (run i of every strategy, then run i + 1), so that "
       "noise falls on all strategies alike. A strategy whose Newton fails stops its march "
       "there (steps done < "
       f"{steps}); its time is then not the time of the whole run and it is marked no.", ""]
(out / "report.md").write_text("\n".join(md))
print(out / "report.md")
PY
