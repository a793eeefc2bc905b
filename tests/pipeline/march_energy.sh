#!/usr/bin/env bash
# Requirement (issue 5): sig-march marches elastodynamics without contact and conserves the
# discrete energy (8.33). A free disc thrown with a uniform velocity (datafiles/dynamics/
# free_disc.dat) keeps E = 1/2 rho A |v0|^2 (A: the area of the inscribed N-gon) with no elastic
# energy (a translation is in the kernel of K); the same disc clamped on its left quarter
# exchanges kinetic and elastic energy and still conserves the total, with the midpoint rule and
# with Newmark's scheme, to 1e-8 relative. energy.csv has the exact agreed header, and a bad TIME
# card (k=-1) is refused naming the file, the line and the field.
set -euo pipefail
bin=${SIG_BIN:?SIG_BIN is not set}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
deck=datafiles/dynamics/free_disc.dat
failures=0

# check_energy CSV EXPECTED_E0 MIN_ELASTIC_FRACTION MAX_ELASTIC_FRACTION LABEL
check_energy() {
  python3 - "$@" <<'PY' || failures=$((failures + 1))
import csv, sys
path, expected_e0, label = sys.argv[1], sys.argv[2], sys.argv[5]
min_el, max_el = float(sys.argv[3]), float(sys.argv[4])
header = ("step,time,kinetic,elastic,total,contact_work,max_penetration,active_nodes,"
          "newton_iterations,interface,friction_work,wall_work,normal_force,tangential_force")
with open(path) as f:
    first = f.readline().rstrip("\n")
    rows = list(csv.DictReader([first + "\n"] + f.readlines()))
ok = True
if first != header:
    print(f"FAIL {label}: header {first!r}"); ok = False
e0 = float(rows[0]["total"])
drift = max(abs(float(r["total"]) - e0) for r in rows) / e0
elastic = max(abs(float(r["elastic"])) for r in rows) / e0
steps = len(rows) - 1
print(f"{label}: {steps} steps to t = {float(rows[-1]['time']):.6g}, E0 = {e0:.12g}, "
      f"max |E - E0| / E0 = {drift:.3e}, max elastic / E0 = {elastic:.3e}")
if drift > 1e-8:
    print(f"FAIL {label}: energy drift {drift:.3e} > 1e-8"); ok = False
if not (min_el <= elastic <= max_el):
    print(f"FAIL {label}: max elastic / E0 = {elastic:.3e} not in [{min_el}, {max_el}]"); ok = False
if expected_e0 != "-" and abs(e0 - float(expected_e0)) > 1e-9 * float(expected_e0):
    print(f"FAIL {label}: E0 = {e0!r}, expected 1/2 rho A |v0|^2 = {expected_e0}"); ok = False
if any(int(r["newton_iterations"]) != (1 if int(r["step"]) > 0 else 0) for r in rows):
    print(f"FAIL {label}: newton_iterations is not 1 per step"); ok = False
if abs(float(rows[-1]["time"]) - 1.0) > 1e-12 or steps != 100:
    print(f"FAIL {label}: {steps} steps to t = {rows[-1]['time']}, expected 100 to t = 1")
    ok = False
sys.exit(0 if ok else 1)
PY
}

# 1. The free disc: R = 1, N = 32 arc segments, rho = 1000, v0 = (0, -10).
# 1/2 rho A |v0|^2 with A = (N / 2) R^2 sin(2 pi / N), the inscribed N-gon of the generator.
e0=$(python3 -c 'import math; N = 32; print(repr(500 * N / 2 * math.sin(2 * math.pi / N) * 100))')
drivers/chain.sh "$deck" -o "$work/free" > "$work/free.log" 2>&1 ||
  { cat "$work/free.log"; exit 1; }
[ -s "$work/free/case.hist" ] || { echo "FAIL: no case.hist"; failures=$((failures + 1)); }
check_energy "$work/free/energy.csv" "$e0" 0 1e-12 "free disc, midpoint"
# The kept states (case.hist, read through sig-dump as the reports read it) are the translation
# u = v0 t, v = v0, and sig-post lists one .vtu per state with its time in free_disc.pvd.
PYTHONDONTWRITEBYTECODE=1 PYTHONPATH=postproc python3 - "$work/free" <<'PY' || failures=$((failures + 1))
import re, sys
from sigreport import read_ds
folder = sys.argv[1]
hist = read_ds(folder + "/case.hist", arrays=["u", "v", "output_time"])
outputs, ndof = hist.shape("u")
u, v, times = hist["u"], hist["v"], hist["output_time"]
error = 0.0
for s, t in enumerate(times):
    for i in range(0, ndof, 2):
        state = u[s * ndof + i:s * ndof + i + 2] + v[s * ndof + i:s * ndof + i + 2]
        error = max(error, max(abs(a - b) for a, b in zip(state, (0.0, -10.0 * t, 0.0, -10.0))))
pvd = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', open(folder + "/free_disc.pvd").read())
print(f"case.hist: {outputs} states of {ndof} dofs at t = {times[0]:g} .. {times[-1]:g}, "
      f"max |(u, v) - (v0 t, v0)| = {error:.3e}; free_disc.pvd lists {len(pvd)} .vtu")
ok = outputs == 11 and error < 1e-9 and len(pvd) == 11
ok = ok and all(abs(float(t) - s / 10) < 1e-12 for s, (t, _) in enumerate(pvd))
vtu = open(folder + "/" + pvd[-1][1], "rb").read()
ok = ok and b'Name="velocity"' in vtu and b'Name="displacement"' in vtu
sys.exit(0 if ok else print("FAIL: case.hist states or free_disc.pvd") or 1)
PY

# 2. Clamped on its left quarter (ref 1): kinetic energy turns into elastic energy.
for scheme in midpoint newmark; do
  sed -e '/^INITIAL/a DIRICHLET ref=1 ux=0 uy=0' -e "s/scheme=midpoint/scheme=$scheme/" "$deck" \
    > "$work/clamped_$scheme.dat"
  drivers/chain.sh "$work/clamped_$scheme.dat" -o "$work/clamped_$scheme" > "$work/c.log" 2>&1 ||
    { cat "$work/c.log"; exit 1; }
  check_energy "$work/clamped_$scheme/energy.csv" - 0.01 1 "clamped disc, $scheme"
done

# 3. A bad TIME card is refused with file:line and the field.
sed -e 's/ k=0.01 / k=-1 /' "$deck" > "$work/bad.dat"
line=$(grep -n '^TIME' "$work/bad.dat" | cut -d: -f1)
status=0
message=$("$bin/sig-march" "$work/bad.dat" -o "$work/free" 2>&1) || status=$?
if [ "$status" -eq 0 ] || ! grep -qF "bad.dat:$line:" <<< "$message" ||
  ! grep -qF "'k'" <<< "$message"; then
  echo "FAIL: k=-1 not refused with bad.dat:$line and field 'k' (exit $status): $message"
  failures=$((failures + 1))
else
  echo "bad TIME card refused: $message"
fi

[ "$failures" -eq 0 ] || exit 1
echo "march_energy: energy conserved to 1e-8 (midpoint, newmark), header exact, bad card refused"
