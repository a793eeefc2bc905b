#!/usr/bin/env bash
# Requirement (issue 10): static Coulomb friction on the frictional Hertz deck, a half disc held by
# contact and friction alone. drivers/friction_hertz.sh --quick runs every method; PDAS, ALM and
# projection converge, agree on every nodal force to 1e-6 of its maximum and on every status; the
# loads are balanced (sum N = P, sum T = Q), the Coulomb cone holds, sticking nodes do not slip
# and slipping ones carry mu N along their slip; the report says PASS; from u = 0 (no INITIAL
# card, a single node touching) the run converges to the same forces and statuses (issue 23),
# and the frictionless floating body is refused as out of equilibrium.
set -euo pipefail
bin=${SIG_BIN:?SIG_BIN is not set}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
SIG_BIN=$bin drivers/friction_hertz.sh --quick -o "$work" > "$work/driver.log" 2>&1 ||
  { tail -20 "$work/driver.log"; echo "friction_hertz.sh failed"; exit 1; }
grep -q "checks PASS" "$work/driver.log" || { tail -5 "$work/driver.log"; exit 1; }

/usr/bin/python3 - "$work" <<'PY'
import csv, json, sys
from pathlib import Path
out = Path(sys.argv[1])
P, Q, mu = 32.0, 6.4, 0.4  # datafiles/friction/hertz_coulomb.dat: 2R (p, q), Coulomb mu
def rows(d):
    return list(csv.DictReader(open(out / "N256" / d / "contact.csv")))
fail = []
ref = rows("pdas_1e2")
for run in ("pdas_1e2", "alm_1e2", "projection_1", "pdas_1e2_from_zero"):
    s = json.load(open(out / "N256" / run / "summary.json"))
    if not s["converged"]:
        fail.append(f"{run}: not converged ({s['failure']})")
        continue
    r = rows(run)
    N = [float(x["multiplier"]) for x in r]
    T = [float(x["tangential_multiplier"]) for x in r]
    for key in ("multiplier", "tangential_multiplier"):
        scale = max(abs(float(x[key])) for x in ref)
        worst = max(abs(float(a[key]) - float(b[key])) for a, b in zip(r, ref))
        if worst > 1e-6 * scale:
            fail.append(f"{run}: {key} differs from pdas by {worst / scale:.2e} of its maximum")
    if [(x["normal_status"], x["friction_status"]) for x in r] != \
            [(x["normal_status"], x["friction_status"]) for x in ref]:
        fail.append(f"{run}: statuses differ from pdas")
    if abs(sum(N) - P) > 1e-8 * P or abs(sum(T) - Q) > 1e-8 * P:
        fail.append(f"{run}: sum N = {sum(N)} (P = {P}), sum T = {sum(T)} (Q = {Q})")
    counts = {k: sum(x["friction_status"] == k for x in r) for k in ("S=", "S+", "S-")}
    if counts["S="] == 0 or counts["S+"] == 0:
        fail.append(f"{run}: statuses {counts}: expected a stick zone and slip towards +x1")
    for x in r:
        n, t, slip, status = float(x["multiplier"]), float(x["tangential_multiplier"]), \
            float(x["slip"]), x["friction_status"]
        if abs(t) > mu * n + 1e-9 * P:
            fail.append(f"{run}: node {x['node']}: |T| = {abs(t)} beyond mu N = {mu * n}")
        if status == "S=" and abs(slip) > 1e-12:
            fail.append(f"{run}: node {x['node']} sticks but slips by {slip}")
        if status in ("S+", "S-") and (abs(abs(t) - mu * n) > 1e-9 * P or t * slip < 0):
            fail.append(f"{run}: node {x['node']} slips ({slip}) with T = {t}, mu N = {mu * n}")
    print(f"friction_hertz_quick: {run}: {s['iterations']} iterations, statuses {counts}")
if fail:
    print("\n".join("FAIL: " + f for f in fail))
    sys.exit(1)
PY

# Same answers under mpirun (issue 27): the pdas run's sig-solve again as 1 and 2 ranks
# (oversubscribed; each rank holds the rows of its METIS part of K, MUMPS factorizes them
# together); displacements, multipliers and statuses agree with the one-process run to 1e-8
# relative, and case.b records the ranks, the ordering and MUMPS's statistics per rank.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
for np in 1 2; do
  dir=$work/np$np
  mkdir -p "$dir"
  cp -L "$work"/N256/pdas_1e2/hertz.dat "$work"/N256/pdas_1e2/case.* "$work"/N256/base/case.*.prov \
    "$dir"/
  rm -f "$dir/case.b" "$dir/case.post"
  mpirun --oversubscribe -np "$np" "$bin/sig-solve" "$dir/hertz.dat" -o "$dir" > "$dir/solve.log" 2>&1 ||
    { cat "$dir/solve.log"; echo "FAIL: mpirun -np $np sig-solve"; exit 1; }
  grep -q "ordering amd, $np rank" "$dir/solve.log" || { cat "$dir/solve.log"; exit 1; }
done
/usr/bin/python3 - "$bin" "$work" <<'PY'
import json, subprocess, sys
bin, work = sys.argv[1:]
def arrays(d):
    out = subprocess.run([f"{bin}/sig-dump", "--json", "--values", f"{work}/{d}/case.b"],
                         capture_output=True, text=True, check=True).stdout
    return {a["name"]: a.get("values") for a in json.loads(out)["arrays"]}
one = arrays("N256/pdas_1e2")
fail = []
for np in (1, 2):
    b = arrays(f"np{np}")
    if b["ranks"] != [np] or b["ordering"] != "amd":
        fail.append(f"np {np}: ranks {b['ranks']}, ordering {b['ordering']}")
    for key in ("u", "multiplier", "tangential_multiplier"):
        scale = max(abs(x) for x in one[key])
        worst = max(abs(x - y) for x, y in zip(one[key], b[key]))
        if len(b[key]) != len(one[key]) or worst > 1e-8 * scale:
            fail.append(f"np {np}: {key} differs by {worst / scale:.2e} of its maximum")
        print(f"friction_hertz_quick: np = {np}: {key} within {worst / scale:.1e} of one process")
    for key in ("normal_status", "friction_status", "iterations"):
        if b[key] != one[key]:
            fail.append(f"np {np}: {key} differs from one process")
    # MUMPS's statistics, one value per rank gathered from the ranks: the sums are its totals.
    for total, per_rank in (("mumps_flops", "mumps_rank_flops"),
                            ("mumps_factor_entries", "mumps_rank_entries")):
        shares = b[per_rank]
        if (len(shares) != np or min(shares) <= 0 or
                abs(sum(shares) - b[total][0]) > 1e-9 * b[total][0]):
            fail.append(f"np {np}: {per_rank} {shares} do not share {total} {b[total][0]}")
if fail:
    print("\n".join("FAIL: " + f for f in fail))
    sys.exit(1)
PY

# Without friction the same body has no sideways support: no equilibrium exists, and sig-solve
# says so before it factorizes (non-zero exit, nothing written), naming the free motion, on a
# coarse mesh and on a finer one (where the factorization alone would lose the singular pivot in
# round-off).
die() {
  echo "FAIL: $*" >&2
  exit 1
}
python=/usr/bin/python3
source drivers/lib/hertz_deck.sh
sed -e '/^FRICTION/d' datafiles/friction/hertz_coulomb.dat > "$work/frictionless.template.dat"
for n in 64 256; do
  deck=$work/frictionless_$n.dat
  hertz_deck "$work/frictionless.template.dat" "$deck" "$n" ""
  dir=$work/frictionless_$n
  mkdir -p "$dir"
  build_base "$deck" "$dir" "the frictionless case of N = $n"
  status=0
  message=$("$bin/sig-solve" "$deck" -o "$dir" 2>&1) || status=$?
  [ "$status" -ne 0 ] || { echo "FAIL: N = $n: sig-solve accepted a body held by nothing"; exit 1; }
  grep -q "the body is free to move: nothing holds the translation along x1 (0 imposed dofs and" <<< "$message" ||
    { echo "FAIL: N = $n: the message does not say why: $message"; exit 1; }
  [ ! -e "$dir/case.b" ] || { echo "FAIL: N = $n: case.b written"; exit 1; }
done
echo "friction_hertz_quick: the frictionless floating body is refused: no equilibrium to find"
