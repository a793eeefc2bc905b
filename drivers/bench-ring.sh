#!/usr/bin/env bash
# drivers/bench-ring.sh [--quick] [--n N] [--repeat K] [-o OUTDIR] [--no-getfem]: how fast the
# hyperelastic ring of scene 7b (large deformation, 14 load steps) solves, against the floor of a
# Newton method and against GetFEM.
#
# On the ring of datafiles/scene7b/ring.dat at N = 512 (--quick: 128; --n N any even N):
#  - pdas gamma = 1e3, alm r = 1e3, projection c = 1e4: sig-bench-finite-strain (modules/solver/
#    app) runs the solve of sig-solve K times (default 3) in one process: median wall time of
#    solve_finite_strain_stage, Newton iterations, reactions;
#  - the floor, timed in the same process: one numeric factorization + solve of the bulk tangent
#    at the final state (Dirichlet dofs eliminated: the pattern the Newton matrix is factorized
#    on, same backend), median of K, times the method's Newton iterations; the symbolic analysis
#    (once per solve) and one assembly of force + tangent are reported beside it;
#  - GetFEM 5.4 (postproc/getfem_ring.py: the same mesh rebuilt node for node, its 'Ciarlet
#    Geymonat' finite-strain brick, nodal contact, the same 14 load steps) when /usr/bin/python3
#    can import getfem: median of 3 timed solves, its Newton iterations, its vertical reaction on
#    AB against ours.
# Every ratio divides two times measured in this one script run. Writes OUTDIR/report.md
# (default out/bench-ring) and the raw OUTDIR/<method>/bench.json, OUTDIR/getfem.json.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3); one BLAS thread
# (drivers/lib/environment.sh).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/bench-ring.sh [--quick] [--n N] [--repeat K] [-o OUTDIR] [--no-getfem]
  --quick      N = 128 instead of 512
  --n N        nodes around the ring (even; default 512)
  --repeat K   timed solves per method, medians reported (default 3)
  -o OUTDIR    results folder (default out/bench-ring)
  --no-getfem  skip the GetFEM comparison
  -h, --help   this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/bench-ring.sh${*:+ $*}"
template=$root/datafiles/scene7b/ring.dat
out=out/bench-ring
n=512
repeat=3
getfem=1
while [ $# -gt 0 ]; do
  case $1 in
    --quick) n=128 ;;
    --n | --repeat | -o)
      [ $# -ge 2 ] || die "$1 needs a value"
      case $1 in
        --n) n=$2 ;;
        --repeat) repeat=$2 ;;
        -o) out=$2 ;;
      esac
      shift
      ;;
    --no-getfem) getfem=0 ;;
    -h | --help)
      usage
      exit 0
      ;;
    *)
      usage >&2
      die "unknown argument '$1'"
      ;;
  esac
  shift
done
[[ $n =~ ^[0-9]+$ ]] && [ "$n" -ge 4 ] && [ $((n % 2)) -eq 0 ] || die "--n must be an even integer >= 4, got '$n'"
[[ $repeat =~ ^[0-9]+$ ]] && [ "$repeat" -ge 1 ] || die "--repeat must be a positive integer, got '$repeat'"
require_stages mesh material contact assemble bench-finite-strain
[ -r "$template" ] || die "cannot read the template deck $template"

methods=(pdas alm projection)
declare -A parameter=([pdas]=gamma [alm]=r [projection]=c)
declare -A value=([pdas]=1e3 [alm]=1e3 [projection]=1e4)

# deck OUTPUT METHOD FIELD VALUE: the template at N, the SOLVER card's method and parameter
# replaced (any r=, gamma=, c= of the template dropped), no VTK output (timing only).
deck() {
  deck_variant "$template" "$1" --set "MESH.N=$n" --drop SOLVER.gamma --drop SOLVER.c \
    --drop SOLVER.r --set "SOLVER.method=$2" --set "SOLVER.$3=$4" --set OUTPUT.vtk=no
}

mkdir -p "$out"
out=$(cd "$out" && pwd)
echo "bench-ring.sh: N = $n, $repeat runs per method, results in $out"
rm -rf "$out/base" "${methods[@]/#/$out/}" "$out/getfem.json"
mkdir -p "$out/base"
deck "$out/base/ring.dat" pdas gamma 1e3
for stage in mesh material contact assemble; do
  "$bin/sig-$stage" "$out/base/ring.dat" -o "$out/base" >"$out/base/$stage.log" 2>&1 ||
    die "sig-$stage failed (see $out/base/$stage.log)"
done

for method in "${methods[@]}"; do
  dir=$out/$method
  mkdir -p "$dir"
  for ds in nopo mili cont tae; do ln -s "../base/case.$ds" "$dir/case.$ds"; done
  deck "$dir/ring.dat" "$method" "${parameter[$method]}" "${value[$method]}"
  "$bin/sig-bench-finite-strain" "$dir/ring.dat" -o "$dir" --repeat "$repeat" >"$dir/bench.log" 2>&1 ||
    die "sig-bench-finite-strain failed for $method (see $dir/bench.log)"
  cat "$dir/bench.log"
done

getfem_json=
if [ $getfem -eq 1 ]; then
  if /usr/bin/python3 -c 'import getfem' 2>/dev/null; then
    getfem_json=$out/getfem.json
    /usr/bin/python3 "$root/postproc/getfem_ring.py" --deck "$out/base/ring.dat" --repeat 3 \
      --json "$getfem_json" || die "postproc/getfem_ring.py failed"
  else
    echo "bench-ring.sh: /usr/bin/python3 cannot import getfem: no GetFEM comparison"
  fi
fi

{
  echo "command: $invocation"
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "host: $(uname -n), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "revision: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
} >"$out/command.txt"

"$python" - "$out" "$n" "$getfem_json" <<'EOF'
import json, sys
from pathlib import Path

out, n, getfem_json = Path(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
parameter = {"pdas": "gamma = 1e3", "alm": "r = 1e3", "projection": "c = 1e4"}
runs = {m: json.loads((out / m / "bench.json").read_text()) for m in parameter}
getfem = json.loads(Path(getfem_json).read_text()) if getfem_json else None
info = dict(l.split(": ", 1) for l in (out / "command.txt").read_text().splitlines())

header = ["method", "parameter", "Newton iterations", "solve s (median)", "factorize + solve s",
          "floor s", "solve / floor", "s per iteration", "reaction_y"]
if getfem:
    header.append("speed-up vs GetFEM")
rows = []
for name, r in runs.items():
    its = str(r["iterations"]) if r["converged"] else f"Nv ({r['iterations']})"
    row = [name, parameter[name], its, f"{r['solve_seconds_median']:.3f}",
           f"{r['factor_solve_seconds_median']:.4f}", f"{r['floor_seconds']:.3f}",
           f"{r['solve_seconds_median'] / r['floor_seconds']:.2f}",
           f"{r['solve_seconds_median'] / max(r['iterations'], 1):.4f}", f"{r['reaction_y']:.6g}"]
    if getfem:
        row.append(f"{getfem['solve_seconds_median'] / r['solve_seconds_median']:.2f}x")
    rows.append(row)
if getfem:
    its = str(getfem["newton_iterations"]) if getfem["converged"] else f"Nv ({getfem['newton_iterations']})"
    rows.append(["GetFEM", "nodal contact v2, r = E", its, f"{getfem['solve_seconds_median']:.3f}",
                 "—", "—", "—", f"{getfem['solve_seconds_median'] / max(getfem['newton_iterations'], 1):.4f}",
                 f"{getfem['reaction_y']:.6g}", "1.00x"])

p = runs["pdas"]
lines = [f"# Ring benchmark (scene 7b), N = {n}", ""]
lines.append(f"Produced by `{info['command']}` on {info['date']} ({info['host']}, revision "
             f"{info['revision']}). {p['dofs']} dofs ({p['free_dofs']} free), 14 load steps, "
             f"linear solver {p['backend']}, one BLAS thread. Solve = median of "
             f"{len(p['solve_seconds'])} runs of the Newton solve of sig-solve "
             f"(sig-bench-finite-strain, reading the case files excluded). Floor = one numeric "
             f"factorization + solve of the tangent at the final state on the Newton matrix's "
             f"pattern (median of {len(p['factor_solve_seconds'])}) x the method's Newton "
             f"iterations: what a Newton method cannot beat with this linear solver. The symbolic "
             f"analysis, once per solve, is {p['analyze_seconds']:.3f} s; one assembly of the "
             f"hyperelastic force and tangent {p['assembly_seconds_median']:.3f} s; bulk assemblies "
             f"per Newton iteration (line-search trials): "
             + ", ".join(f"{m} {r['bulk_evaluations'] / max(r['iterations'], 1):.2f}" for m, r in runs.items())
             + ". Beyond the floor, an iteration costs these assemblies and the set-up of the "
             "Newton matrix (frames, decoupled rows, residual).")
lines += ["", "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
lines += ["| " + " | ".join(r) + " |" for r in rows]
if getfem:
    ry = {m: r["reaction_y"] for m, r in runs.items()}
    diff = {m: abs(v - getfem["reaction_y"]) / abs(getfem["reaction_y"]) for m, v in ry.items()}
    lines += ["", f"GetFEM {getfem['getfem_version']} (postproc/getfem_ring.py): "
              f"{getfem['description']}. {getfem['dofs']} dofs, {getfem['contact_nodes']} contact "
              f"nodes, Newton per step {getfem['newton_per_step']}. Solve median "
              f"{getfem['solve_seconds_median']:.3f} s "
              f"({', '.join(f'{t:.3f}' for t in getfem['solve_seconds'])}). Speed-up = GetFEM's "
              f"median / ours.", "",
              "Vertical reaction on AB (the force the supports exert on the ring): GetFEM "
              f"{getfem['reaction_y']:.7g} (its contact forces sum to {getfem['contact_force_sum']:.7g}); "
              + ", ".join(f"{m} {ry[m]:.7g} (relative difference {diff[m]:.1e})" for m in ry) + "."]
text = "\n".join(lines) + "\n"
(out / "report.md").write_text(text)
print(text)
print(f"written: {out / 'report.md'}")
EOF
