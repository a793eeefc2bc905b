#!/usr/bin/env bash
# drivers/bench-hertz3d.sh [--h H] [--grading G] [--mu MU [--shift DX] [--drop DZ]] [--repeat K]
#                          [--cases LIST] [-o OUTDIR] [--no-getfem] [--no-whole]: how fast the 3D Hertz ball
# solves (issue 26), frictionless or with Coulomb friction, against the floor of the problem and
# against GetFEM.
#
# The half ball of meshes/half_ball.geo (R = 8, graded towards the pole: size H + G x
# distance; defaults 0.025 and 0.1, GetFEM's fine mesh of datafiles/scene3d/GETFEM.md, 28887
# dofs), E = 150, nu = 0.3, a traction of total P = 14 on its flat top (Hertz's a = R / 10), held
# there in x1 and x2, on the rigid plane x3 = 0, frictionless. With --mu MU, Coulomb friction of
# coefficient MU and the top clamped and moved by (DX, 0, -DZ) (defaults 0.02 and 0.07: DIRICHLET
# ref=2 ux=DX uy=0 uz=-DZ, the traction on held dofs then going into the reactions), the top
# dragged sideways and down so that the contact sticks at its centre and slips at its rim (the
# problem of tests/pipeline/getfem_friction3d_match.sh; a shift with the tilts free would roll
# the ball); projection is not run then. Runs:
#  - pdas, alm and projection (their default parameters) condensing the candidates of initial gap
#    below a^2 / R (SOLVER candidate_gap=, the nodes within about 1.4 a of the pole), CHOLMOD
#    (the whole stiffness factorized supernodally, the condensed unknowns last, the Schur
#    complement read off the factor: solver/cholmod_split.hpp) and, for pdas, MUMPS (the Schur
#    complement inside its factorization, ICNTL(19));
#  - pdas condensing every node of the curved face (unless --no-whole): the dense Schur complement
#    the candidates avoid;
#  - the floor: the stiffness of the same mesh without contact, the flat top clamped (DIRICHLET
#    ux=uy=uz=0 there: the curved face stays free, so that the matrix has the contact solve's free
#    dofs but the top's third component), `SOLVER method=linear`: one analyze + factorization +
#    solve by MUMPS and by CHOLMOD.
# For each, the median over K runs (default 5, round robin so that load bursts fall on all alike)
# of sig-solve's phases (summary.json's times but sig-assemble's) and of the sig-solve process's
# wall time; with GetFEM 5.4 importable by /usr/bin/python3, postproc/getfem_hertz3d.py on the
# same mesh (its own start and rigid-motion constraints: its docstring), median of 3 timed solves;
# with --mu the same problem as ours (--clamp-top --top-shift DX --top-drop DZ --pressure, the
# same traction, both stopped at 1e-10: ours SOLVER eps=1e-10, relative increment and residual,
# GetFEM's max_res relative to its source terms; its start is its rigid shift u_z = -a^2 / (4 R),
# ours rest), and the largest
# difference of the nodal forces between the two is reported. The peak resident memory of each
# sig-solve process (/usr/bin/time's maximum RSS) is reported beside the times.
# Every ratio divides two times of this one script run. Table printed and written to
# OUTDIR/bench.md (default out/bench-hertz3d), raw times to OUTDIR/times.tsv.
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/bench-hertz3d.sh [--h H] [--grading G] [--mu MU [--shift DX] [--drop DZ]]
                                [--repeat K] [--cases LIST] [-o OUTDIR] [--no-getfem] [--no-whole]
  --h H          mesh size at the pole (default 0.025)
  --grading G    growth of the size per unit distance from the pole (default 0.1)
  --mu MU        Coulomb friction of coefficient MU, the top clamped and moved (default 0:
                 frictionless, the top held in x1 and x2 and pressed)
  --shift DX     with --mu: the top's displacement along x1 (default 0.02)
  --drop DZ      with --mu: the top's displacement along -x3 (default 0.07)
  --repeat K     timed runs per case, medians reported (default 5)
  --cases LIST   the contact runs to time, comma-separated among pdas, pdas_mumps, alm,
                 projection, pdas_whole (default all; the floors always run)
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
selected=all
mu=0
shift_x=0.02
drop=0.07
parse_options --h=h --grading=grading --mu=mu --shift=shift_x --drop=drop --repeat=repeat -o=out \
  --cases=selected --no-getfem:getfem=0 --no-whole:whole=0 -- "$@"
number='^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$'
[[ $h =~ $number ]] || die "--h must be a positive number, got '$h'"
[[ $grading =~ $number ]] || die "--grading must be a number >= 0, got '$grading'"
[[ $mu =~ $number ]] || die "--mu must be a number >= 0, got '$mu'"
[[ $shift_x =~ $number ]] || die "--shift must be a number >= 0, got '$shift_x'"
[[ $drop =~ $number ]] || die "--drop must be a number >= 0, got '$drop'"
friction=$("$python" -c "print(1 if $mu > 0 else 0)")
if [ "$selected" != all ]; then
  for name in ${selected//,/ }; do
    [[ " pdas pdas_mumps alm projection pdas_whole " == *" $name "* ]] ||
      die "--cases: unknown run '$name' (pdas, pdas_mumps, alm, projection, pdas_whole)"
  done
fi
[ -x /usr/bin/time ] || die "/usr/bin/time is needed for the peak memory (Debian: time)"
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
    if [ "$friction" -eq 1 ]; then
      echo "# Hertz half ball with Coulomb friction mu = $mu (drivers/bench-hertz3d.sh): R = $R,"
      echo "# E = $E, nu = $nu, the flat top clamped and moved by ($shift_x, 0, -$drop), GPa-m."
    else
      echo "# Frictionless Hertz half ball (drivers/bench-hertz3d.sh): R = $R, E = $E, nu = $nu,"
      echo "# a traction of total P = $P on the flat top, GPa-m."
    fi
    echo "TITLE bench-hertz3d"
    echo "MESH file=$mesh"
    echo "MATERIAL law=hooke E=$E nu=$nu"
    if [ -n "$floor" ]; then
      echo "DIRICHLET ref=2 ux=0 uy=0 uz=0"
      echo "BODYFORCE f=0,0,-$traction"
    else
      if [ "$friction" -eq 1 ]; then
        echo "DIRICHLET ref=2 ux=$shift_x uy=0 uz=-$drop"
      else
        echo "DIRICHLET ref=2 ux=0 uy=0"
      fi
      echo "TRACTION ref=2 f=0,0,-$traction"
      echo "CONTACT ref=3 obstacle=plane point=0,0,0 normal=0,0,1 law=signorini exclude=2"
      [ "$friction" -eq 0 ] || echo "FRICTION ref=3 law=coulomb mu=$mu"
    fi
    echo "SOLVER $solver$([ -n "$floor" ] || [ "$friction" -eq 0 ] || echo " eps=1e-10")"
    echo "OUTPUT vtk=no"
  } >"$file"
}

runs=()
echo "bench-hertz3d.sh: h = $h, grading = $grading, mu = $mu, $repeat runs per case, results in $out"
printf 'name\trun\twall_us\tsummary\tmaxrss_kb\n' >"$out/times.tsv"
base=$out/base
rm -rf "$base" "$out"/run_* "$out"/floor*
mkdir -p "$base"
write_deck "$base/hertz3d.dat" "method=pdas"
build_base "$base/hertz3d.dat" "$base" "the base case"
cases=("pdas method=pdas candidate_gap=$candidate_gap"
  "pdas_mumps method=pdas linear=mumps candidate_gap=$candidate_gap"
  "alm method=alm candidate_gap=$candidate_gap")
[ "$friction" -eq 1 ] || cases+=("projection method=projection candidate_gap=$candidate_gap")
[ $whole -eq 0 ] || cases+=("pdas_whole method=pdas")
for entry in "${cases[@]}"; do
  name=${entry%% *}
  [ "$selected" = all ] || [[ ",$selected," == *",$name,"* ]] || continue
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
    /usr/bin/time -f %M -o "$dir/maxrss.$k" "$bin/sig-solve" "$dir/hertz3d.dat" -o "$dir" \
      >"$dir/solve.log" 2>&1 || { cat "$dir/solve.log" >&2; die "timing run $name failed (log: $dir/solve.log)"; }
    t1=$(date +%s%N)
    run_stage post "$dir/hertz3d.dat" "$dir" || die "sig-post of $name failed"
    cp "$dir/summary.json" "$dir/summary.$k.json"
    printf '%s\t%s\t%s\t%s\t%s\n' "$name" "$k" "$(((t1 - t0) / 1000))" "$dir/summary.$k.json" \
      "$(tail -1 "$dir/maxrss.$k")" >>"$out/times.tsv"
  done
  echo "bench-hertz3d.sh: round $k of $repeat timed"
done

getfem_json=
if [ $getfem -eq 1 ]; then
  if /usr/bin/python3 -c 'import getfem' 2>/dev/null; then
    getfem_json=$out/getfem.json
    load=(--P $P)
    [ "$friction" -eq 0 ] || load=(--mu "$mu" --clamp-top --top-shift "$shift_x" --top-drop "$drop" --pressure "$traction" --eps 1e-10)
    echo "bench-hertz3d.sh: GetFEM (load average $(cut -d' ' -f1-3 /proc/loadavg))"
    /usr/bin/python3 "$root/postproc/getfem_hertz3d.py" --msh "$mesh" --R $R --E $E --nu $nu \
      "${load[@]}" --repeat 3 --json "$getfem_json" --workdir "$out/getfem" >"$out/getfem.log" 2>&1 ||
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
  echo "mu: $mu"
  echo "top: $([ "$friction" -eq 1 ] && echo "clamped and moved by ($shift_x, 0, -$drop)" || echo "held in x1 and x2, traction $traction")"
} >"$out/command.txt"

"$python" - "$out" <<'EOF'
import csv, json, math, statistics, sys
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
            "dofs": s["dofs"], "contact": s.get("contact_nodes", 0),
            "friction": s.get("friction_status_counts", {}), "rss": int(row["maxrss_kb"]) / 1024**2})
med = {n: {k: statistics.median(r[k] for r in rs) for k in ("wall", "phases", "schur", "rss")}
       for n, rs in runs.items()}
friction = float(info.get("mu", "0")) > 0
floor_name = min(("floor_mumps", "floor_cholmod"), key=lambda n: med[n]["phases"])
floor = med[floor_name]["phases"]
getfem = json.loads(Path(info["getfem"]).read_text()) if info.get("getfem") else None
k = len(runs[floor_name])
title = (f"3D Hertz ball with Coulomb friction mu = {info['mu']}" if friction else "Frictionless 3D Hertz ball")
lines = [f"# {title} benchmark (issue 26)", "",
         f"Produced by `{info['command']}` on {info['date']} ({info['host']}, revision "
         f"{info['revision']}). Top {info['top']}. "
         f"Mesh meshes/half_ball.geo, h = {info['h']}, grading = "
         f"{info['grading']}: {runs[floor_name][0]['dofs']} dofs. Medians of {k} runs taken round "
         f"robin. Phases = summary.json's times without sig-assemble's `assemble`; wall = the "
         f"sig-solve process (reading case.tae included). Candidates: the contact nodes of initial "
         f"gap <= a^2 / R = {float(info['candidate_gap']):.4g} (a = {float(info['a_hertz']):.4g}, "
         f"Hertz's); CHOLMOD but for pdas_mumps. The floor: one analyze + factorize + solve of the "
         f"stiffness of the same mesh, its top clamped, no contact, the faster of MUMPS and CHOLMOD "
         f"({floor_name[6:]}, {floor:.3f} s). Peak memory: the sig-solve process's maximum resident "
         f"set (/usr/bin/time), median; the floor's holds its factor.", "",
         "| run | converged | iterations | contact nodes (stick / slip) | phases (s) | of which Schur (s) | wall (s) | phases / floor | peak memory (GB) |",
         "|---|---|---|---|---|---|---|---|---|"]
for name in [n for n in runs if not n.startswith("floor")] + ["floor_mumps", "floor_cholmod"]:
    r, m = runs[name][0], med[name]
    f = r["friction"]
    zone = f"{r['contact']} ({f.get('S=', 0)} / {f.get('S+', 0)})" if friction and r["contact"] else f"{r['contact']}"
    lines.append(f"| {name} | {'yes' if all(x['converged'] for x in runs[name]) else 'Nv'} | "
                 f"{r['iterations']} | {zone} | {m['phases']:.3f} | {m['schur']:.3f} | "
                 f"{m['wall']:.3f} | {m['phases'] / floor:.2f} | {m['rss']:.2f} |")
if getfem:
    g = getfem["solve_seconds_median"]
    lines += ["", f"GetFEM {getfem.get('getfem_version', '')} on the same mesh "
              f"({getfem['dofs']} dofs, {getfem['contact_candidates']} contact candidates): "
              f"{getfem['newton_iterations']} Newton iterations, md.solve {g:.3f} s (median of "
              f"{len(getfem['solve_seconds'])}), {'converged' if getfem['converged'] else 'Nv'}. "
              f"Ratio GetFEM / ours (phases): " +
              ", ".join(f"{n} {g / med[n]['phases']:.1f}x" for n in runs if not n.startswith("floor"))
              + "."]
    if friction:
        step = getfem["steps"][0]
        theirs = {tuple(round(n[c], 9) for c in "xyz"): n for n in step["nodes"]}
        largest = max(n["normal_force"] for n in theirs.values())
        first = next(n for n in runs if not n.startswith("floor"))
        ours = list(csv.DictReader(open(out / f"run_{first}" / "contact.csv")))
        dn = dt = 0.0
        for r in ours:
            n = theirs[tuple(round(float(r[c]), 9) for c in ("x1", "x2", "x3"))]
            dn = max(dn, abs(float(r["multiplier"]) - n["normal_force"]))
            # ours: the force of the body on the plane, GetFEM's: of the plane on the body
            dt = max(dt, math.dist([float(r[f"tangential_force_{k}"]) for k in (1, 2, 3)],
                                   [-t for t in n["tangential_force"]]))
        lines += ["", f"Same problem: GetFEM's stick / slip {step.get('stick_nodes')} / {step.get('slip_nodes')}; "
                  f"{first}'s nodal forces against GetFEM's: normal within {dn / largest:.2g}, tangential "
                  f"within {dt / largest:.2g} of the largest normal force ({largest:.4g})."]
else:
    lines += ["", "GetFEM: not run."]
text = "\n".join(lines) + "\n"
(out / "bench.md").write_text(text)
print(text)
EOF
