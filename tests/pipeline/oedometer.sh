#!/usr/bin/env bash
# Requirement (issue 23): Dirichlet conditions on contact nodes are honoured in the node's frame.
# The oedometer: a unit square on the foundation x2 <= 0, rollers ux = 0 on both sides (the
# DIRICHLET cards of refs 1 and 4 hold the bottom corners too, which are contact nodes of ref 3),
# a pressure q on the top. P1 holds the confined state exactly: u1 = 0, u2 = u2(0) - q x2 /
# (lambda + 2 mu), u2(0) = 0 on a Signorini wall, -q / cn for a compliance, -g beyond a
# compliance-unilateral layer's wall; every bottom node carries the normal force q w_i, and sticks
# (no shear, the corners' slip held by their rollers). Each law (compliance, compliance-unilateral
# below and beyond its wall, Signorini with Coulomb friction) with pdas and alm: displacements to
# 1e-10 of their maximum, normal forces to 1e-10 of q, corners included, and a roller on a
# contact node's normal component takes that node out of contact with a warning.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"

E=200
nu=0.3
q=2
deck() { # deck FILE CONTACT_FIELDS FRICTION_CARD METHOD
  cat >"$1" <<EOF
TITLE oedometer, rollers on the contact corners
# Units: GPa and m.
MESH generator=rectangle lx=1 ly=1 nx=8 ny=8
MATERIAL law=hooke E=$E nu=$nu plane=strain
DIRICHLET ref=1 ux=0
DIRICHLET ref=4 ux=0
PRESSURE ref=2 p=$q
CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 $2
$3
SOLVER method=$4 gamma=100 r=100 eps=1e-12
OUTPUT vtk=no
EOF
}

check() { # check DIR BOTTOM_U2 STATUS
  /usr/bin/python3 - "$1" "$2" "$3" "$bin" "$E" "$nu" "$q" <<'PY'
import csv, json, subprocess, sys
out, bottom, status, bindir = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
E, nu, q = map(float, sys.argv[5:8])
lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
dump = lambda f, names: {a["name"]: a["values"] for a in json.loads(subprocess.run(
    [f"{bindir}/sig-dump", "--json", "--values=" + names, f], capture_output=True, text=True,
    check=True).stdout)["arrays"] if "values" in a}
u = dump(f"{out}/case.b", "u")["u"]
xy = json.loads(subprocess.run([f"{bindir}/sig-dump", "--json", "--values", f"{out}/case.nopo"],
                               capture_output=True, text=True, check=True).stdout)["coordinates"]
nodes = list(zip(xy[0::2], xy[1::2]))
scale = abs(bottom) + q / (lam + 2 * mu)
worst = max(max(abs(u[2 * i]), abs(u[2 * i + 1] - (bottom - q * y / (lam + 2 * mu))))
            for i, (x, y) in enumerate(nodes))
problems = []
if worst > 1e-10 * scale:
    problems.append(f"displacement off the exact state by {worst / scale:.2e} of its scale")
for row in csv.DictReader(open(f"{out}/contact.csv")):
    x = float(row["x1"])
    w = 1 / 16 if x in (0.0, 1.0) else 1 / 8
    if abs(float(row["multiplier"]) - q * w) > 1e-10 * q:
        problems.append(f"node at x1 = {x}: normal force {row['multiplier']}, exact {q * w}")
    if row["normal_status"] != status:
        problems.append(f"node at x1 = {x}: status {row['normal_status']}, expected {status}")
    if row["friction_status"] not in ("S=", "-"):
        problems.append(f"node at x1 = {x}: friction status {row['friction_status']}")
if problems:
    print("\n".join(problems))
    sys.exit(1)
PY
}

cn=10
declare -A cases=(
  [compliance]="law=compliance cn=$cn|$(python3 -c "print(-$q / $cn)")|CN"
  [layer]="law=compliance-unilateral cn=$cn g=0.5|$(python3 -c "print(-$q / $cn)")|CN"
  [wall]="law=compliance-unilateral cn=$cn g=0.05|-0.05|CU"
  [coulomb]="law=signorini|0|CU"
)
for name in "${!cases[@]}"; do
  IFS='|' read -r fields bottom status <<<"${cases[$name]}"
  friction=""
  [ "$name" = coulomb ] && friction="FRICTION ref=3 law=coulomb mu=0.3"
  for method in pdas alm; do
    dir=$work/$name-$method
    deck "$dir.dat" "$fields" "$friction" "$method"
    SIG_BIN=$bin drivers/chain.sh "$dir.dat" -o "$dir" >"$dir.log" 2>&1 ||
      { tail -5 "$dir.log"; die "$name $method: the chain failed"; }
    grep -q "converged in" "$dir.log" || { tail -3 "$dir.log"; die "$name $method: Nv"; }
    check "$dir" "$bottom" "$status" || die "$name $method: not the exact oedometer state"
    echo "oedometer: $name $method exact"
  done
done

# A roller on the normal component of a contact node: out of contact, said so.
dir=$work/normal_roller
deck "$dir.dat" "law=signorini" "DIRICHLET ref=3 uy=0" pdas
sed -i '/^DIRICHLET ref=4/d' "$dir.dat"
SIG_BIN=$bin drivers/chain.sh "$dir.dat" -o "$dir" >"$dir.log" 2>&1 || { tail -5 "$dir.log"; die "normal roller: the chain failed"; }
grep -q "has its normal component held by a DIRICHLET card: it is out of the contact set" "$dir.log" ||
  die "normal roller: no warning naming the held node"
grep -q ",held," "$dir/contact.csv" || die "normal roller: contact.csv does not say held"
echo "oedometer: a held normal component is out of contact, with a warning"
