#!/usr/bin/env bash
# drivers/bench-mpi.sh [-o OUTDIR] [--n N] [--grading G] [--repeat K] [--ranks LIST]: the
# distributed solve at scale (issue 27, "Scale"): sig-solve under mpirun at np = 1 and 2 on the
# largest 2D Hertz this machine solves in tens of seconds.
#
# The scene-7a Hertz deck (datafiles/scene7a/hertz.dat: PDAS gamma = 1e2, SOLVER linear=mumps,
# without VTK output) at MESH N (default 2048) and grading G (default 0, the thesis's uniform
# mesh: 1.55M dofs, N + 1 contact unknowns at N = 2048). sig-mesh to sig-assemble run once; then
# K rounds (default 3), each sig-solve as 1, then 2 ranks (--ranks, comma separated, 1 first)
# under mpirun (mpirun_ranks, lib/environment.sh), round robin so that load bursts on the shared
# machine fall on every rank count alike, and sig-post for summary.json. Per run: the solve's
# phases (summary.json `times` without sig-assemble's `assemble`: factorize = MUMPS's analysis
# and partial factorization with the Schur complement, frames, schur, solve = the contact Newton
# and the expansion), the wall time of the mpirun job, the peak resident memory of every rank
# (/usr/bin/time -f %M around each rank) and MUMPS's statistics (summary.json `mumps`: INFOG,
# RINFOG and every rank's INFO, RINFO). Medians over the K rounds; the parallel efficiency
# T_1 / (P T_P) of each phase. Writes OUTDIR/bench.md (default out/bench-mpi) and the raw table
# OUTDIR/runs.tsv.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/bench-mpi.sh [-o OUTDIR] [--n N] [--grading G] [--repeat K] [--ranks LIST]
  --n N          boundary segments on Gamma3 (default 2048)
  --grading G    MESH grading (default 0: the thesis's uniform mesh)
  --repeat K     rounds, medians reported (default 3)
  --ranks LIST   the numbers of ranks, comma separated, 1 first (default 1,2)
  -o OUTDIR      results folder (default out/bench-mpi)
  -h, --help     this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/bench-mpi.sh${*:+ $*}"
out=out/bench-mpi
n=2048
grading=0
repeat=3
ranks=1,2
parse_options --n=n --grading=grading --repeat=repeat --ranks=ranks -o=out -- "$@"
[[ $n =~ ^[0-9]+$ ]] && [ "$n" -ge 4 ] && [ $((n % 2)) -eq 0 ] ||
  die "--n must be an even integer >= 4, got '$n'"
[[ $grading =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]] ||
  die "--grading must be a number >= 0, got '$grading'"
require_positive --repeat "$repeat"
[[ $ranks =~ ^1(,[1-9][0-9]*)*$ ]] ||
  die "--ranks must be numbers of ranks, comma separated, 1 first, got '$ranks'"
IFS=, read -r -a rank_counts <<<"$ranks"
require_stages mesh material contact assemble solve post
command -v mpirun >/dev/null || die "no mpirun (OpenMPI, drivers/setup.sh)"
[ -x /usr/bin/time ] || die "no /usr/bin/time for the ranks' peak memory (apt-get install time)"
template=$root/datafiles/scene7a/hertz.dat
require_decks "$template"

mkdir -p "$out"
out=$(cd "$out" && pwd)
source "$root/drivers/lib/hertz_deck.sh"
base=$out/base
rm -rf "$base" "$out"/np*
mkdir -p "$base"
hertz_deck "$template" "$base/hertz.dat" "$n" "$grading"
deck_variant "$base/hertz.dat" "$base/hertz.dat" --set OUTPUT.vtk=no
echo "bench-mpi.sh: N = $n, grading $grading: sig-mesh to sig-assemble once, in $base"
build_base "$base/hertz.dat" "$base" "the base case"
for np in "${rank_counts[@]}"; do
  mkdir -p "$out/np$np"
  link_ds ../base "$out/np$np" nopo mili cont tae
  cp "$base/hertz.dat" "$out/np$np/hertz.dat"
done

# The peak resident memory of each rank (KB), in PREFIX.<rank>: /usr/bin/time around the rank.
# shellcheck disable=SC2016 # expanded by the rank's shell
per_rank_time='exec /usr/bin/time -f %M -o "$0.$OMPI_COMM_WORLD_RANK" "$@"'

printf 'ranks\trun\twall_s\tpeak_rss_kb\tsummary\n' >"$out/runs.tsv"
for k in $(seq 1 "$repeat"); do
  for np in "${rank_counts[@]}"; do
    dir=$out/np$np
    t0=$(date +%s%N)
    if ! mpirun_ranks "$np" bash -c "$per_rank_time" "$dir/rss.$k" "$bin/sig-solve" \
      "$dir/hertz.dat" -o "$dir" >"$dir/solve.$k.log" 2>&1; then
      cat "$dir/solve.$k.log" >&2
      die "sig-solve failed at np = $np (log: $dir/solve.$k.log)"
    fi
    t1=$(date +%s%N)
    run_stage post "$dir/hertz.dat" "$dir" || die "sig-post failed at np = $np"
    cp "$dir/summary.json" "$dir/summary.$k.json"
    rss=$(for r in $(seq 0 $((np - 1))); do tail -n1 "$dir/rss.$k.$r"; done | paste -sd,)
    wall=$(awk -v ns=$((t1 - t0)) 'BEGIN { printf "%.3f", ns / 1e9 }')
    printf '%s\t%s\t%s\t%s\t%s\n' "$np" "$k" "$wall" "$rss" "$dir/summary.$k.json" >>"$out/runs.tsv"
    echo "bench-mpi.sh: round $k of $repeat, np = $np: mpirun $wall s, peak RSS per rank $rss KB"
  done
done
bench_provenance >"$out/command.txt"
echo "grading: $grading" >>"$out/command.txt"

"$python" - "$out" "$n" <<'EOF'
import csv, json, statistics, sys
from pathlib import Path

out, n = Path(sys.argv[1]), int(sys.argv[2])
info = dict(l.split(": ", 1) for l in (out / "command.txt").read_text().splitlines() if ": " in l)
runs = {}
with open(out / "runs.tsv") as f:
    for row in csv.DictReader(f, delimiter="\t"):
        s = json.loads(Path(row["summary"]).read_text())
        t = {p: float(v) for p, v in s["times"].items() if p != "assemble"}
        runs.setdefault(int(row["ranks"]), []).append({
            "wall": float(row["wall_s"]), "phases": sum(t.values()), "times": t,
            "analysis": s["mumps"]["analysis_seconds"],
            "rss": [int(v) for v in row["peak_rss_kb"].split(",")], "summary": s})
ranks = sorted(runs)
first = runs[ranks[0]][0]["summary"]
phases = list(runs[ranks[0]][0]["times"])
med = {p: {"wall": statistics.median(r["wall"] for r in rs),
           "phases": statistics.median(r["phases"] for r in rs),
           "analysis": statistics.median(r["analysis"] for r in rs),
           **{ph: statistics.median(r["times"][ph] for r in rs) for ph in phases},
           "rss": [statistics.median(r["rss"][i] for r in rs) for i in range(p)]}
       for p, rs in runs.items()}
for p, rs in runs.items():
    assert all(r["summary"]["ranks"] == p for r in rs), f"summary.json says another ranks than {p}"
    assert all(r["summary"]["converged"] for r in rs), f"np = {p}: a run did not converge"

def eff(p, key):
    return med[1][key] / (p * med[p][key]) if med[p][key] > 0 else float("nan")

K = len(runs[1])
lines = [f"# The distributed solve: Hertz at N = {n}, MESH grading = {info['grading']}", "",
         f"Produced by `{info['command']}` on {info['date']} ({info['host']}, revision "
         f"{info['revision']}). {first['dofs']} dofs, {first['mumps']['schur_size']:.0f} contact "
         f"unknowns (MUMPS's Schur complement), MUMPS ordering {first['ordering']}, PDAS "
         f"{first['iterations']} iterations. Medians of {K} runs per rank count, taken round "
         f"robin.",
         "",
         "**Read these times as a shared 2-core machine's**: other sessions compiled and ran on it "
         "meanwhile, and with 2 cores np = 2 cannot show a speed-up beyond 2 (more ranks than "
         "cores are oversubscribed and only slower). The statistics of MUMPS (flops, factor "
         "entries, memory) do not depend on the load.", "",
         "## Times (medians, seconds)", "",
         "Phases: summary.json `times` without sig-assemble's `assemble`; factorize = MUMPS's "
         "analysis + partial factorization, the Schur complement included (analysis: of it, "
         "MUMPS's analysis, on the host); solve = the contact "
         "Newton on the dense complement (every rank) and the expansion. Wall: the mpirun job "
         "(MPI's start, reading case.tae, writing case.b included). Efficiency: T_1 / (P T_P).", "",
         "| ranks | " + " | ".join(phases) + " | analysis | phases | wall | efficiency (phases) | "
         "efficiency (factorize) | peak RSS per rank (MB) |",
         "|" + "---|" * (len(phases) + 7)]
for p in ranks:
    m = med[p]
    lines.append(f"| {p} | " + " | ".join(f"{m[ph]:.2f}" for ph in phases) +
                 f" | {m['analysis']:.2f} | {m['phases']:.2f} | {m['wall']:.2f} | "
                 f"{eff(p, 'phases'):.2f} | {eff(p, 'factorize'):.2f} | " +
                 ", ".join(f"{v / 1024:.0f}" for v in m["rss"]) + " |")

lines += ["", "## MUMPS's statistics (first run of each rank count)", "",
          "Totals: RINFOG(3) flops of the elimination (RINFOG(1) the analysis's estimate), "
          "INFOG(29) factor entries, INFOG(11) the largest front, INFOG(21)/INFOG(22) the memory "
          "the factorization used on the largest rank / on all. Per rank (rank 0, the host, "
          "holding the Schur complement, first): RINFO(3) flops, INFO(27) factor entries, "
          "INFO(22) MB, INFO(23) pivots eliminated.", "",
          "| ranks | flops | estimate | factor entries | largest front | MB max / total | "
          "flops per rank | entries per rank | MB per rank | pivots per rank |",
          "|" + "---|" * 10]
for p in ranks:
    s = runs[p][0]["summary"]["mumps"]
    share = lambda key, fmt: ", ".join(fmt(v) for v in s[key])
    lines.append(f"| {p} | {s['flops']:.3e} | {s['flops_estimate']:.3e} | "
                 f"{s['factor_entries']:.3e} | {s['largest_front']:.0f} | "
                 f"{s['memory_max_mb']:.0f} / {s['memory_total_mb']:.0f} | "
                 f"{share('rank_flops', lambda v: f'{v:.2e}')} | "
                 f"{share('rank_entries', lambda v: f'{v:.2e}')} | "
                 f"{share('rank_memory_mb', lambda v: f'{v:.0f}')} | "
                 f"{share('rank_pivots', lambda v: f'{v:.0f}')} |")
m = runs[1][0]["summary"]["mumps"]
lines += ["", f"Dense contact block: the Schur complement is {m['schur_size']:.0f}^2 doubles = "
          f"{8 * m['schur_size'] ** 2 / 2 ** 20:.0f} MB on every rank (broadcast), and each PDAS "
          f"iteration factorizes its active part densely on every rank.",
          "", "Raw runs: `runs.tsv` (ranks, run, wall s, peak RSS per rank KB, summary.json)."]
(out / "bench.md").write_text("\n".join(lines) + "\n")
print("\n".join(lines))
EOF
