#!/usr/bin/env bash
# drivers/bench-scene6.sh [--repeat K] [-o OUTDIR]: the cost of scene 6's march (sig-march
# scheme=backward-euler on datafiles/scene6/rail.dat: friction of the slip rate, the
# convexification loop in every step) at
#   n256   h = k = 1/256, the reference of Fig 6.5 (the thesis: 132610 dofs, 16797 s)
#   n64    h = k = 1/64
# with CHOLMOD (the step matrix factorized whole, Gamma3 last, a split solve per step) and MUMPS
# (its Schur complement and split solve). Each case also marches without contact (no CONTACT,
# FRICTION, CONVEXIFICATION card): a step is then the right side and one forward-backward solve
# with the factorized step matrix, the floor. The runs go round robin, K of each (default 3), and
# medians are reported from case.hist (time_factorize, time_march, the steps' seconds and their
# parts: right side, contact problem, condensation and expansion):
#   - setup + march of the reference under 30 s, with one sparse factorization;
#   - a step against one solve plus the contact problem's share: at most 1.2x.
# Run it on a quiet machine (nothing else building or running) for figures worth quoting.
# Writes OUTDIR/report.md and OUTDIR/bench.json (default out/bench-scene6).
#
# Environment: SIG_BIN (default build/bin), PYTHON (default /usr/bin/python3), BENCH_CASES (the
# cases, default "n256 n64").
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/bench-scene6.sh [--repeat K] [-o OUTDIR]
  --repeat K   marches per case, backend and variant, medians reported (default 3)
  -o OUTDIR    results folder (default out/bench-scene6)
  -h, --help   this message
Environment: SIG_BIN (stage executables, default build/bin), PYTHON (default /usr/bin/python3),
BENCH_CASES (default "n256 n64").
EOF
}

invocation="drivers/bench-scene6.sh${*:+ $*}"
parse_repeat_out out/bench-scene6 3 "$@"
template=$root/datafiles/scene6/rail.dat
[ -r "$template" ] || die "cannot read $template"
require_stages mesh material contact assemble march

mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -rf "$out"/n256_* "$out"/n64_*
cases=(${BENCH_CASES:-n256 n64})
backends=(cholmod mumps)
start=$SECONDS
for name in "${cases[@]}"; do
  n=${name#n}
  k=$("$python" -c "print(repr(1 / $n))")
  for backend in "${backends[@]}"; do
    for variant in contact floor; do
      dir=$out/${name}_${backend}_$variant
      mkdir -p "$dir"
      edits=(--set MESH.nx=$n --set MESH.ny=$n --set TIME.k=$k --set TIME.output_every=$n
        --set SOLVER.linear=$backend --set OUTPUT.vtk=no)
      [ $variant = floor ] &&
        edits+=(--drop-card CONTACT --drop-card FRICTION --drop-card CONVEXIFICATION
          --drop SOLVER.method --drop SOLVER.eps)
      deck_variant "$template" "$dir/rail.dat" "${edits[@]}"
      build_base "$dir/rail.dat" "$dir" "$name $backend $variant"
    done
  done
done
# Round robin: every case, backend and variant once per round.
for r in $(seq 1 "$repeat"); do
  for dir in "$out"/n*_*_*; do
    "$bin/sig-march" "$dir/rail.dat" -o "$dir" >"$dir/march.log" 2>&1 ||
      { cat "$dir/march.log" >&2; die "sig-march failed in $dir"; }
    mv "$dir/case.hist" "$dir/run$r.hist"
  done
  echo "bench-scene6.sh: round $r of $repeat done ($((SECONDS - start)) s)"
done
seconds=$((SECONDS - start))

PYTHONPATH=$root/postproc "$python" - "$out" "$invocation" "$repeat" "$seconds" \
  "$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)" <<'EOF'
import json
import statistics
import sys
from pathlib import Path

from sigreport import read_ds

out, invocation, repeat, seconds, revision = sys.argv[1:6]
out, repeat = Path(out), int(repeat)
titles = {"n256": "h = k = 1/256 (Fig 6.5's reference)", "n64": "h = k = 1/64"}
cases = {c: titles.get(c, c) for c in sorted({p.name.split("_")[0] for p in out.glob("n*_*_*")},
                                             key=lambda c: -int(c[1:]))}
ARRAYS = ["time_factorize", "time_march", "sparse_factorizations", "dense_factorizations",
          "ndof", "newton_iterations", "step_seconds", "step_seconds_right_side",
          "step_seconds_contact", "step_seconds_products", "converged"]


def runs(case, backend, variant):
    folder = out / f"{case}_{backend}_{variant}"
    return [read_ds(folder / f"run{r}.hist", arrays=ARRAYS) for r in range(1, repeat + 1)]


def median_of_steps(ds_list, name):
    return statistics.median(v for ds in ds_list for v in ds[name][1:])


def right_sides(ds):
    """Per step, the right side's work inside the step's clock: the load at t_n
    (step_seconds_right_side) and the products K u_n, M w_n that accept() forms for the next
    right side and the energies (step_seconds_products)."""
    return [r + p for r, p in zip(ds["step_seconds_right_side"][1:],
                                  ds["step_seconds_products"][1:])]


bench = {}
for case in cases:
    for backend in ("cholmod", "mumps"):
        contact, floor = runs(case, backend, "contact"), runs(case, backend, "floor")
        step = median_of_steps(contact, "step_seconds")
        share = median_of_steps(contact, "step_seconds_contact")
        solve = statistics.median(s - r for ds in floor
                                  for s, r in zip(ds["step_seconds"][1:], right_sides(ds)))
        bench[f"{case}_{backend}"] = {
            "dofs": contact[0].scalar("ndof"),
            "converged": all(ds.scalar("converged") for ds in contact),
            "setup_s": statistics.median(ds.scalar("time_factorize") for ds in contact),
            "march_s": statistics.median(ds.scalar("time_march") for ds in contact),
            "total_s": statistics.median(ds.scalar("time_factorize") + ds.scalar("time_march")
                                         for ds in contact),
            "sparse": max(ds.scalar("sparse_factorizations") for ds in contact),
            "dense": max(ds.scalar("dense_factorizations") for ds in contact),
            "newton": sum(contact[0]["newton_iterations"]),
            "step_ms": 1e3 * step,
            "right_side_ms": 1e3 * statistics.median(r for ds in contact for r in right_sides(ds)),
            "contact_ms": 1e3 * share,
            "floor_solve_ms": 1e3 * solve,
            "ratio": step / (solve + share),
            "ratio_without_contact": (step - share) / solve,
        }
(out / "bench.json").write_text(json.dumps(bench, indent=1) + "\n")
lines = [
    "# Scene 6 benchmark: the dynamic march with the convexification loop in every step\n",
    f"Command: `{invocation}` ({repeat} marches per case, backend and variant, round robin, "
    f"medians; {seconds} s; revision {revision}). Times from case.hist: the setup (frames, one "
    "sparse factorization of M/k + k K with the Schur complement onto Gamma3, the condensed "
    "problem's Cholesky) and the march (every step). The floor is one forward-backward solve "
    "with the factorized step matrix: the step of the same march without contact, less its "
    "right side. The right side is the load at t_n and the products K u, M w (formed when a "
    "step is accepted, for the next right side and the energies). The contact share is the "
    "step's contact problem (every convex solve of the loop).\n",
    "| case | backend | dofs | setup s | march s | setup + march s | step ms | right side ms | "
    "contact ms | floor solve ms | step / (floor + contact) | (step - contact) / floor | "
    "factorizations sparse / dense | Newton iterations |",
    "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
]
for key, d in bench.items():
    case, backend = key.split("_")
    lines.append(f"| {cases[case]} | {backend} | {d['dofs']} | {d['setup_s']:.3g} | "
                 f"{d['march_s']:.3g} | {d['total_s']:.3g} | {d['step_ms']:.3g} | "
                 f"{d['right_side_ms']:.3g} | {d['contact_ms']:.3g} | {d['floor_solve_ms']:.3g} | "
                 f"{d['ratio']:.2f} | {d['ratio_without_contact']:.2f} | {d['sparse']} / "
                 f"{d['dense']} | {d['newton']} |")
checks = []
if "n256" in cases:
    best = min(("cholmod", "mumps"), key=lambda b: bench[f"n256_{b}"]["total_s"])
    ref = bench[f"n256_{best}"]
    checks.append(("the reference h = k = 1/256 under 30 s (setup + march; the thesis 16797 s)",
                   ref["total_s"] < 30 and ref["converged"], f"{ref['total_s']:.2f} s ({best})"))
checks += [
    ("one sparse factorization for the march", all(d["sparse"] == 1 for d in bench.values()),
     "1 in every run"),
]
for key, d in bench.items():
    checks.append((f"{key}: a step at most 1.2x (one solve + the contact share)",
                   d["ratio"] <= 1.2, f"{d['ratio']:.2f} (beside the contact share: "
                   f"{d['ratio_without_contact']:.2f} solves)"))
lines += ["", "## Checks\n", "| target | measured | result |", "|---|---|---|"]
lines += [f"| {name} | {measured} | {'PASS' if ok else 'FAIL'} |" for name, ok, measured in checks]
(out / "report.md").write_text("\n".join(lines) + "\n")
print((out / "report.md").read_text())
EOF
