#!/usr/bin/env bash
# drivers/bench-pipeline.sh [-o OUTDIR] [--n N] [--grading G] [--repeat K] [--compression C]: what the stages
# around the solve cost, against the solve and against the disk (issue 27, "the pipeline at
# scale").
#
# The scene-7a Hertz deck (datafiles/scene7a/hertz.dat: PDAS gamma = 1e2, OUTPUT vtk=yes) at MESH
# N (default 2048) and grading G (default 0, the thesis's uniform mesh: 1.55M dofs at N = 2048),
# its .vtu compressed by C (OUTPUT compression=, default lz4: the choice at this size, zlib being
# the deck's default), through every stage, sig-mesh to sig-post, K times (default 3) in a fresh folder each round.
# Per stage: the wall time of its process and its phases, which each stage appends to
# $SIG_PHASE_TIMES (core/phase_times.hpp): read (DS and mesh files read and checked: CRCs,
# fingerprints, provenance), write (encoded, written, fsynced, renamed; the .vtu included),
# gmsh (gmsh's own mesh generation, exempt), assemble, solve (sig-solve's factorizations and
# contact iterations); "other" is the rest of the wall time (process start, the deck, the
# stage's own computing). Medians over the K rounds. The ratio of a stage's I/O (read + write) to
# the solve phase of sig-solve in the same round, the issue's target being at most 0.1 for every
# stage. The sizes of the DS files, and the disk's raw speed measured in the same run: dd of a
# file of case.tae's size, written with conv=fdatasync (as the stages fsync what they write) and
# read back with iflag=direct (past the page cache, which nothing here drops), after every round.
# Writes OUTDIR/bench.md (default out/bench-pipeline) and the raw times in OUTDIR/times.tsv.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/bench-pipeline.sh [-o OUTDIR] [--n N] [--grading G] [--repeat K]
  --n N          boundary segments on Gamma3 (default 2048)
  --grading G    MESH grading (default 0: the thesis's uniform mesh)
  --repeat K     rounds of the whole chain, medians reported (default 3)
  --compression C  the .vtu's compression: lz4 (default), zlib or none (OUTPUT compression=)
  -o OUTDIR      results folder (default out/bench-pipeline)
  -h, --help     this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/bench-pipeline.sh${*:+ $*}"
out=out/bench-pipeline
n=2048
grading=0
repeat=3
compression=lz4
parse_options --n=n --grading=grading --repeat=repeat --compression=compression -o=out -- "$@"
case $compression in lz4 | zlib | none) ;; *) die "--compression must be lz4, zlib or none, got '$compression'" ;; esac
[[ $n =~ ^[0-9]+$ ]] && [ "$n" -ge 4 ] && [ $((n % 2)) -eq 0 ] || die "--n must be an even integer >= 4, got '$n'"
[[ $grading =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]] || die "--grading must be a number >= 0, got '$grading'"
require_positive --repeat "$repeat"
stages=(mesh material contact assemble solve post)
require_stages "${stages[@]}"
template=$root/datafiles/scene7a/hertz.dat
require_decks "$template"
command -v dd >/dev/null || die "no dd for the disk's speed"

mkdir -p "$out"
out=$(cd "$out" && pwd)
source "$root/drivers/lib/hertz_deck.sh"
deck=$out/hertz.dat
hertz_deck "$template" "$deck" "$n" "$grading"
deck_variant "$deck" "$deck.tmp" --set OUTPUT.compression="$compression"
mv "$deck.tmp" "$deck"

echo "bench-pipeline.sh: N = $n, grading $grading, $repeat rounds, results in $out"
printf 'round\tstage\tphase\tseconds\n' >"$out/times.tsv"
printf 'round\tfile\tbytes\n' >"$out/sizes.tsv"
printf 'round\tbytes\twrite_s\tread_s\n' >"$out/disk.tsv"
progress_begin "$repeat"
for k in $(seq 1 "$repeat"); do
  dir=$out/run
  rm -rf "$dir"
  mkdir -p "$dir"
  phases=$dir/phases.tsv
  for stage in "${stages[@]}"; do
    t0=${EPOCHREALTIME/./}
    SIG_PHASE_TIMES=$phases run_stage "$stage" "$deck" "$dir" || die "sig-$stage failed in round $k"
    t1=${EPOCHREALTIME/./}
    printf '%s\tsig-%s\twall\t%s\n' "$k" "$stage" "$(((t1 - t0) / 1000))e-3" >>"$out/times.tsv"
  done
  sed "s/^/$k\t/" "$phases" >>"$out/times.tsv"
  for file in "$dir"/case.* "$dir"/*.vtu; do
    printf '%s\t%s\t%s\n' "$k" "$(basename "$file")" "$(stat -c %s "$file")" >>"$out/sizes.tsv"
  done
  # The disk: a file of the TAE's size, written and synced as the stages do, read past the cache.
  bytes=$(stat -c %s "$dir/case.tae")
  blocks=$(((bytes + 4194303) / 4194304))
  t0=${EPOCHREALTIME/./}
  dd if=/dev/zero of="$out/disk.bin" bs=4M count="$blocks" conv=fdatasync status=none
  t1=${EPOCHREALTIME/./}
  dd if="$out/disk.bin" of=/dev/null bs=4M iflag=direct status=none
  t2=${EPOCHREALTIME/./}
  rm -f "$out/disk.bin"
  printf '%s\t%s\t%s\t%s\n' "$k" "$((blocks * 4194304))" "$(((t1 - t0) / 1000))e-3" \
    "$(((t2 - t1) / 1000))e-3" >>"$out/disk.tsv"
  progress_step "round $k"
done

{
  bench_provenance
  echo "outdir: $out"
  echo "n: $n"
  echo "grading: $grading"
  echo "compression: $compression"
  echo "uptime: $(uptime)"
} >"$out/command.txt"
cp "$dir/summary.json" "$out/summary.json"

"$python" - "$out" <<'EOF'
import csv, json, statistics, sys
from collections import defaultdict
from pathlib import Path

out = Path(sys.argv[1])
info = dict(l.split(": ", 1) for l in (out / "command.txt").read_text().splitlines() if ": " in l)
# times[stage][phase][round] = seconds
times = defaultdict(lambda: defaultdict(dict))
with open(out / "times.tsv") as f:
    for row in csv.DictReader(f, delimiter="\t"):
        times[row["stage"]][row["phase"]][int(row["round"])] = float(row["seconds"])
rounds = sorted(times["sig-solve"]["wall"])
stages = ["sig-mesh", "sig-material", "sig-contact", "sig-assemble", "sig-solve", "sig-post"]
compute = {"gmsh", "assemble", "solve"}


def value(stage, phase, k):
    return times[stage][phase].get(k, 0.0)


def io(stage, k):
    return value(stage, "read", k) + value(stage, "write", k)


def other(stage, k):
    timed = sum(v.get(k, 0.0) for p, v in times[stage].items() if p not in ("wall", "total"))
    return value(stage, "wall", k) - timed


def med(f):
    return statistics.median(f(k) for k in rounds)


summary = json.loads((out / "summary.json").read_text())
lines = [f"# Pipeline benchmark: scene 7a Hertz, N = {info['n']}, MESH grading = {info['grading']}, "
         f".vtu compression {info.get('compression', 'zlib')}", "",
         f"Produced by `{info['command']}` on {info['date']} ({info['host']}, revision "
         f"{info['revision']}); at the end: `{info['uptime'].strip()}`. {summary['dofs']} dofs, "
         f"PDAS, {summary['iterations']} iterations. Medians of {len(rounds)} rounds of the whole "
         f"chain. Phases from `SIG_PHASE_TIMES` (core/phase_times.hpp): read = DS and mesh files "
         f"read and checked (CRCs, fingerprints, provenance), write = encoded, written, fsynced and "
         f"renamed (the .vtu too), gmsh = gmsh's own mesh generation (exempt), assemble and solve "
         f"= the computations; other = wall - the phases (process start, the deck, the stage's own "
         f"computing). I/O / solve = (read + write) / sig-solve's solve phase, per round then the "
         f"median: the target is at most 0.1 for every stage.", "",
         "| stage | wall s | read s | write s | gmsh s | assemble s | solve s | other s | I/O / solve | <= 0.1 |",
         "|---|---|---|---|---|---|---|---|---|---|"]
solve = lambda k: value("sig-solve", "solve", k)
total_wall = 0.0
for stage in stages:
    ratio = med(lambda k: io(stage, k) / solve(k))
    total_wall += med(lambda k: value(stage, "wall", k))
    row = [stage] + [f"{med(lambda k: value(stage, p, k)):.3f}" for p in ("wall", "read", "write", "gmsh", "assemble", "solve")]
    row += [f"{med(lambda k: other(stage, k)):.3f}", f"{ratio:.3f}",
            "—" if stage == "sig-solve" else ("PASS" if ratio <= 0.1 else "FAIL")]
    lines.append("| " + " | ".join(row) + " |")
chain = med(lambda k: sum(value(s, "wall", k) for s in stages))
io_all = med(lambda k: sum(io(s, k) for s in stages))
lines += ["", f"Whole chain: {chain:.3f} s of wall time for a solve phase of {med(solve):.3f} s; the "
          f"reading and writing of all stages {io_all:.3f} s ({io_all / med(solve):.2f} x the solve).", ""]

sizes = defaultdict(dict)
with open(out / "sizes.tsv") as f:
    for row in csv.DictReader(f, delimiter="\t"):
        sizes[row["file"]][int(row["round"])] = int(row["bytes"])
disk = {}
with open(out / "disk.tsv") as f:
    for row in csv.DictReader(f, delimiter="\t"):
        disk[int(row["round"])] = (int(row["bytes"]), float(row["write_s"]), float(row["read_s"]))
write_speed = statistics.median(b / w for b, w, r in disk.values())
read_speed = statistics.median(b / r for b, w, r in disk.values())
lines += ["## Files and the disk", "",
          f"The disk, measured after every round: dd of {next(iter(disk.values()))[0] / 1e6:.0f} MB "
          f"(case.tae's size in 4 MiB blocks), written with conv=fdatasync at {write_speed / 1e6:.0f} MB/s "
          f"and read back with iflag=direct at {read_speed / 1e6:.0f} MB/s (medians). A file's time at "
          f"the disk's speed: its size / that speed.", "",
          "| file | bytes | MB | at disk write speed s | at disk read speed s |", "|---|---|---|---|---|"]
for name in sorted(sizes):
    b = statistics.median(sizes[name].values())
    lines.append(f"| {name} | {b:.0f} | {b / 1e6:.1f} | {b / write_speed:.3f} | {b / read_speed:.3f} |")
lines.append("")
text = "\n".join(lines)
(out / "bench.md").write_text(text)
print(text)
print(f"written: {out / 'bench.md'}")
EOF
