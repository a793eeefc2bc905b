#!/usr/bin/env bash
# drivers/bench-hertz3d.sh [--h H] [--grading G] [--repeat K] [-o OUTDIR] [--no-getfem]
#                          [--no-whole]: how fast the frictionless 3D Hertz ball solves (issue 26),
# against the floor of the problem and against GetFEM.
#
# The half ball of meshes/half_ball.geo (R = 8, graded towards the pole: size H + G x
# distance; defaults 0.025 and 0.1, GetFEM's fine mesh of datafiles/scene3d/GETFEM.md, 28887
# dofs), E = 150, nu = 0.3, a traction of total P = 14 on its flat top (Hertz's a = R / 10), held
# there in x1 and x2, on the rigid plane x3 = 0, frictionless. Runs:
#  - pdas, alm and projection (their default parameters) condensing the candidates of initial gap
#    below a^2 / R (SOLVER candidate_gap=, the nodes within about 1.4 a of the pole), CHOLMOD
#    (the Schur complement by block solves with the interior's factor) and, for pdas, MUMPS (the
#    Schur complement inside its factorization, ICNTL(19));
#  - pdas condensing every node of the curved face (unless --no-whole): the dense Schur complement
#    the candidates avoid;
#  - the floor: the stiffness of the same mesh without contact, the flat top clamped (DIRICHLET
#    ux=uy=uz=0 there: the curved face stays free, so that the matrix has the contact solve's free
#    dofs but the top's third component), `SOLVER method=linear`: one analyze + factorization +
#    solve by MUMPS and by CHOLMOD.
# For each, the median over K runs (default 5, round robin so that load bursts fall on all alike)
# of sig-solve's phases (summary.json's times but sig-assemble's) and of the sig-solve process's
# wall time; with GetFEM 5.4 importable by /usr/bin/python3, postproc/getfem_hertz3d.py on the
# same mesh (its own start and rigid-motion constraints: its docstring), median of 3 timed solves.
# Every ratio divides two times of this one script run. Table printed and written to
# OUTDIR/bench.md (default out/bench-hertz3d), raw times to OUTDIR/times.tsv.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/bench-hertz3d.sh [--h H] [--grading G] [--repeat K] [-o OUTDIR] [--no-getfem]
                                [--no-whole]
  --h H          mesh size at the pole (default 0.025)
  --grading G    growth of the size per unit distance from the pole (default 0.1)
  --repeat K     timed runs per case, medians reported (default 5)
  -o OUTDIR      results folder (default out/bench-hertz3d)
  --no-getfem    skip the GetFEM comparison
  --no-whole     skip the run condensing every contact node
  -h, --help     this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3).
EOF
}

invocation="drivers/bench-hertz3d.sh${*:+ $*}"
out=out/bench-hertz3d
h=0.025
grading=0.1
repeat=5
getfem=1
whole=1
parse_options --h=h --grading=grading --repeat=repeat -o=out --no-getfem:getfem=0 \
  --no-whole:whole=0 -- "$@"
number='^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$'
[[ $h =~ $number ]] || die "--h must be a positive number, got '$h'"
[[ $grading =~ $number ]] || die "--grading must be a number >= 0, got '$grading'"
require_positive --repeat "$repeat"
require_stages mesh material contact assemble solve post
command -v gmsh >/dev/null || die "gmsh is needed to mesh meshes/half_ball.geo"

mkdir -p "$out"
out=$(cd "$out" && pwd)
R=8
E=150
nu=0.3
P=14
# Hertz's contact radius, the candidates' gap bound a^2 / R and the top traction P / (pi R^2).
read -r a_hertz candidate_gap traction < <("$python" -c "
import math
R, E, nu, P = $R, $E, $nu, $P
a = (3 * P * R / (4 * E / (1 - nu * nu))) ** (1 / 3)
print(a, a * a / R, P / (math.pi * R * R))")

mesh=$out/half_ball.msh
gmsh "$root/meshes/half_ball.geo" -3 -format msh22 -setnumber R $R -setnumber h "$h" \
  -setnumber grading "$grading" -o "$mesh" >"$out/gmsh.log" 2>&1 || die "gmsh failed (log: $out/gmsh.log)"

# write_deck FILE SOLVER-FIELDS [floor]: the deck, or the floor's (the top clamped, no contact).
write_deck() {
  local file=$1 solver=$2 floor=${3:-}
  {
    echo "# Frictionless Hertz half ball (drivers/bench-hertz3d.sh): R = $R, E = $E, nu = $nu,"
    echo "# a traction of total P = $P on the flat top, GPa-m."
    echo "TITLE bench-hertz3d"
    echo "MESH file=$mesh"
    echo "MATERIAL law=hooke E=$E nu=$nu"
    if [ -n "$floor" ]; then
      echo "DIRICHLET ref=2 ux=0 uy=0 uz=0"
      echo "BODYFORCE f=0,0,-$traction"
    else
      echo "DIRICHLET ref=2 ux=0 uy=0"
      echo "TRACTION ref=2 f=0,0,-$traction"
      echo "CONTACT ref=3 obstacle=plane point=0,0,0 normal=0,0,1 law=signorini exclude=2"
    fi
    echo "SOLVER $solver"
    echo "OUTPUT vtk=no"
  } >"$file"
}

runs=()
echo "bench-hertz3d.sh: h = $h, grading = $grading, $repeat runs per case, results in $out"
printf 'name\trun\twall_us\tsummary\n' >"$out/times.tsv"
base=$out/base
rm -rf "$base" "$out"/run_* "$out"/floor*
mkdir -p "$base"
write_deck "$base/hertz3d.dat" "method=pdas"
build_base "$base/hertz3d.dat" "$base" "the base case"
cases=("pdas method=pdas candidate_gap=$candidate_gap"
  "pdas_mumps method=pdas linear=mumps candidate_gap=$candidate_gap"
  "alm method=alm candidate_gap=$candidate_gap"
  "projection method=projection candidate_gap=$candidate_gap")
[ $whole -eq 0 ] || cases+=("pdas_whole method=pdas")
for entry in "${cases[@]}"; do
  name=${entry%% *}
  dir=$out/run_$name
  mkdir -p "$dir"
  link_ds ../base "$dir" nopo mili cont tae
  write_deck "$dir/hertz3d.dat" "${entry#* }"
  runs+=("$name $dir")
done
floor=$out/floor
mkdir -p "$floor"
link_ds ../base "$floor" nopo mili
write_deck "$floor/hertz3d.dat" "method=linear" floor
run_stage assemble "$floor/hertz3d.dat" "$floor" || die "cannot assemble the floor problem"
for backend in mumps cholmod; do
  dir=$out/floor_$backend
  mkdir -p "$dir"
  link_ds ../floor "$dir" nopo mili tae
  write_deck "$dir/hertz3d.dat" "method=linear linear=$backend" floor
  runs+=("floor_$backend $dir")
done

for k in $(seq 1 "$repeat"); do
  for entry in "${runs[@]}"; do
    name=${entry%% *}
    dir=${entry#* }
    t0=$(date +%s%N)
    run_stage solve "$dir/hertz3d.dat" "$dir" || die "timing run $name failed"
    t1=$(date +%s%N)
    run_stage post "$dir/hertz3d.dat" "$dir" || die "sig-post of $name failed"
    cp "$dir/summary.json" "$dir/summary.$k.json"
    printf '%s\t%s\t%s\t%s\n' "$name" "$k" "$(((t1 - t0) / 1000))" "$dir/summary.$k.json" >>"$out/times.tsv"
  done
  echo "bench-hertz3d.sh: round $k of $repeat timed"
done

getfem_json=
if [ $getfem -eq 1 ]; then
  if /usr/bin/python3 -c 'import getfem' 2>/dev/null; then
    getfem_json=$out/getfem.json
    /usr/bin/python3 "$root/postproc/getfem_hertz3d.py" --msh "$mesh" --R $R --E $E --nu $nu \
      --P $P --repeat 3 --json "$getfem_json" --workdir "$out/getfem" >"$out/getfem.log" 2>&1 ||
      { tail -20 "$out/getfem.log" >&2; die "postproc/getfem_hertz3d.py failed"; }
  else
    echo "bench-hertz3d.sh: /usr/bin/python3 cannot import getfem: no GetFEM comparison"
  fi
fi

{
  bench_provenance
  echo "h: $h"
  echo "grading: $grading"
  echo "candidate_gap: $candidate_gap"
  echo "a_hertz: $a_hertz"
  echo "getfem: $getfem_json"
} >"$out/command.txt"

"$python" - "$out" <<'EOF'
import csv, json, statistics, sys
from pathlib import Path

out = Path(sys.argv[1])
info = dict(l.split(": ", 1) for l in (out / "command.txt").read_text().splitlines() if ": " in l)
runs = {}
with open(out / "times.tsv") as f:
    for row in csv.DictReader(f, delimiter="\t"):
        s = json.loads(Path(row["summary"]).read_text())
        t = s["times"]
        runs.setdefault(row["name"], []).append({
            "wall": int(row["wall_us"]) * 1e-6,
            "phases": sum(float(v) for p, v in t.items() if p != "assemble"),
            "schur": float(t.get("schur", 0.0)),
            "iterations": s.get("iterations", 0), "converged": s.get("converged", True),
            "dofs": s["dofs"], "contact": s.get("contact_nodes", 0)})
med = {n: {k: statistics.median(r[k] for r in rs) for k in ("wall", "phases", "schur")}
       for n, rs in runs.items()}
floor_name = min(("floor_mumps", "floor_cholmod"), key=lambda n: med[n]["phases"])
floor = med[floor_name]["phases"]
getfem = json.loads(Path(info["getfem"]).read_text()) if info.get("getfem") else None
k = len(runs[floor_name])
lines = [f"# Frictionless 3D Hertz ball benchmark (issue 26)", "",
         f"Produced by `{info['command']}` on {info['date']} ({info['host']}, revision "
         f"{info['revision']}). Mesh meshes/half_ball.geo, h = {info['h']}, grading = "
         f"{info['grading']}: {runs[floor_name][0]['dofs']} dofs. Medians of {k} runs taken round "
         f"robin. Phases = summary.json's times without sig-assemble's `assemble`; wall = the "
         f"sig-solve process (reading case.tae included). Candidates: the contact nodes of initial "
         f"gap <= a^2 / R = {float(info['candidate_gap']):.4g} (a = {float(info['a_hertz']):.4g}, "
         f"Hertz's); CHOLMOD but for pdas_mumps. The floor: one analyze + factorize + solve of the "
         f"stiffness of the same mesh, its top clamped, no contact, the faster of MUMPS and CHOLMOD "
         f"({floor_name[6:]}, {floor:.3f} s).", "",
         "| run | converged | iterations | contact nodes | phases (s) | of which Schur (s) | wall (s) | phases / floor |",
         "|---|---|---|---|---|---|---|---|"]
for name in [n for n in runs if not n.startswith("floor")] + ["floor_mumps", "floor_cholmod"]:
    r, m = runs[name][0], med[name]
    lines.append(f"| {name} | {'yes' if all(x['converged'] for x in runs[name]) else 'Nv'} | "
                 f"{r['iterations']} | {r['contact']} | {m['phases']:.3f} | {m['schur']:.3f} | "
                 f"{m['wall']:.3f} | {m['phases'] / floor:.2f} |")
if getfem:
    g = getfem["solve_seconds_median"]
    lines += ["", f"GetFEM {getfem.get('getfem_version', '')} on the same mesh "
              f"({getfem['dofs']} dofs, {getfem['contact_candidates']} contact candidates): "
              f"{getfem['newton_iterations']} Newton iterations, md.solve {g:.3f} s (median of "
              f"{len(getfem['solve_seconds'])}), {'converged' if getfem['converged'] else 'Nv'}. "
              f"Ratio GetFEM / ours (phases): " +
              ", ".join(f"{n} {g / med[n]['phases']:.1f}x" for n in runs if not n.startswith("floor"))
              + "."]
else:
    lines += ["", "GetFEM: not run."]
text = "\n".join(lines) + "\n"
(out / "bench.md").write_text(text)
print(text)
EOF
