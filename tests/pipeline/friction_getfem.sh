#!/usr/bin/env bash
# Pipeline test, static frictional contact against GetFEM 5.4 (postproc/getfem_friction.py): the
# half disc R = 8 (E = 150, nu = 0.3, plane strain, P1, gmsh's half_disc.geo with N = 64 arc
# segments, grading 0.1) under the traction f = (0.4, -2) on its top edge, with NO Dirichlet
# condition: held by the rigid foundation x2 >= 0 and friction alone, Coulomb mu = 0.4 (q < mu p)
# and Tresca with threshold 1 (classical: |tangential pressure| <= 1 on every node of Gamma3).
# Both codes start from the rigid shift u0 = (0, -h^2/R), h = pi R / N. The requirements:
#  - GetFEM has sig-mesh's nodes (count and coordinates to 1e-12) and converges;
#  - for each law, each of our pdas (gamma = 100), alm (r = 100) and projection (c = 10; c = 0.01
#    takes about 1000 iterations for Tresca) converges, and its nodal normal and tangential
#    forces agree with GetFEM's: max over nodes |ours - GetFEM| <= 1e-6 max |GetFEM's force|, in
#    contact.csv's units and signs (multiplier N >= 0 pressing, tangential_multiplier T with the
#    force of the foundation on the body -T t, t = (1, 0));
#  - the statuses are identical: GetFEM's derived from its solution by getfem_friction.py (in
#    contact when N > 1e-9 max N; stick S= when |slip| <= 1e-9 R, else S+/S- by the sign of the
#    slip; Coulomb: friction status '-' off contact, Tresca: on every node);
#  - both solutions satisfy the law they solve: the resultant of the contact forces balances the
#    load to 1e-9, |T| <= bound (mu N, or threshold x weight) to 1e-9 max |T|, |T| = bound with T
#    of the sign of the slip where slipping, and zero slip where stuck.
# Prints a table per case; fails naming the case and the node. Run from the repository root with
# SIG_BIN set (ctest does both); exit 77 (skipped) when the executables, gmsh or GetFEM
# (/usr/bin/python3 -c 'import getfem') are missing.
set -euo pipefail

source "$(dirname "$0")/lib/common.sh"
python=/usr/bin/python3 # Debian's interpreter: python3-getfem is built for it
require_stages mesh material contact assemble solve post
require_command gmsh
require_python getfem numpy scipy # Debian: python3-getfem

n=64
R=8
shift_u2=$("$python" -c "import math; h = math.pi * $R / $n; print(repr(h * h / $R))")
declare -A friction=([coulomb]="law=coulomb mu=0.4" [tresca]="law=tresca threshold=1")
declare -A solver=([pdas]="gamma=100" [alm]="r=100" [projection]="c=10")

# write_deck FILE LAW METHOD
write_deck() {
  cat >"$1" <<EOF
TITLE frictional half disc vs GetFEM ($2, $3)
# Units: GPa and m, as scene 7a. No Dirichlet condition: contact and friction hold the body.
MESH generator=half-disc R=$R N=$n grading=0.1
MATERIAL law=hooke E=150 nu=0.3 plane=strain
TRACTION ref=2 f=0.4,-2
CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=signorini
FRICTION ref=3 ${friction[$2]}
SOLVER method=$3 ${solver[$3]} eps=1e-10 maxit=200 linear=mumps
INITIAL u=0,-$shift_u2  # the rigid shift h^2/R, h = pi R / N
OUTPUT vtk=no
EOF
}

for law in coulomb tresca; do
  for method in pdas alm projection; do
    dir=$work/$law/$method
    mkdir -p "$dir"
    write_deck "$dir/deck.dat" "$law" "$method"
    SIG_BIN=$bin "$root/drivers/chain.sh" "$dir/deck.dat" -o "$dir" >"$dir/chain.log" 2>&1 ||
      { cat "$dir/chain.log" >&2; die "$law/$method: drivers/chain.sh failed"; }
  done
  # GetFEM on the same deck; --nopo checks it has sig-mesh's nodes. A GetFEM Newton that does
  # not converge is reported by the comparison below (the script exits 1 after its JSON).
  "$python" "$root/postproc/getfem_friction.py" --deck "$work/$law/pdas/deck.dat" --repeat 1 \
    --json "$work/$law/getfem.json" --workdir "$work/$law/getfem" --nopo "$work/$law/pdas/case.nopo" ||
    [ -s "$work/$law/getfem.json" ] || die "$law: postproc/getfem_friction.py failed"
done

"$python" - "$work" <<'EOF'
import csv, json, sys
from pathlib import Path
import numpy as np

work = Path(sys.argv[1])
R = 8.0
AGREE, LAW_TOL = 1e-6, 1e-9
failures = []


def fail(what):
    failures.append(what)
    print("FAIL  " + what)


def law_checks(case, who, x1, N, T, slip, fstat, w, spec):
    """The solution satisfies the friction law it solves (evidence when the codes disagree)."""
    load = np.array([0.4, -2.0]) * 2 * R
    res = np.array([0.0, 1.0]) * N.sum() - np.array([1.0, 0.0]) * T.sum()  # force on the body
    err = np.linalg.norm(res + load) / np.linalg.norm(load)
    if err > LAW_TOL:
        fail(f"{case}/{who}: contact forces ({res[0]:.9g}, {res[1]:.9g}) do not balance the load: {err:.2e}")
    bound = spec["mu"] * np.maximum(N, 0) if spec["law"] == "coulomb" else spec["threshold"] * w
    scale = max(np.abs(T).max(), 1e-300)
    for i in np.nonzero(np.abs(T) > bound + LAW_TOL * scale)[0]:
        fail(f"{case}/{who}: node at x1 = {x1[i]:.6f}: |T| = {abs(T[i]):.9g} beyond the bound {bound[i]:.9g}")
    for i in np.nonzero(np.isin(fstat, ("S+", "S-")))[0]:
        if abs(abs(T[i]) - bound[i]) > LAW_TOL * scale or np.sign(T[i]) != np.sign(slip[i]):
            fail(f"{case}/{who}: slipping node at x1 = {x1[i]:.6f}: T = {T[i]:.9g}, bound {bound[i]:.9g}, slip {slip[i]:.3g}")
    for i in np.nonzero(fstat == "S=")[0]:
        if abs(slip[i]) > LAW_TOL * R:
            fail(f"{case}/{who}: stuck node at x1 = {x1[i]:.6f} slips by {slip[i]:.3g}")


for law in ("coulomb", "tresca"):
    g = json.loads((work / law / "getfem.json").read_text())
    spec = {"law": law, "mu": g["mu"], "threshold": g["threshold"]}
    G = g["nodes"]
    gx = np.array([[p["x1"], p["x2"]] for p in G])
    gN = np.array([p["normal_force"] for p in G])
    gT = np.array([p["tangential_force"] for p in G])
    gslip = np.array([p["slip"] for p in G])
    gw = np.array([p["weight"] for p in G])
    gstat = np.array([p["status"] for p in G])
    gfric = np.array([p["friction_status"] for p in G])
    gnormal = np.array([p["normal_status"] for p in G])
    Nmax, Tmax = np.abs(gN).max(), np.abs(gT).max()
    label = f"mu = {g['mu']:g}" if law == "coulomb" else f"threshold {g['threshold']:g}"
    print(f"\n== {law} ({label}), N = {g['n']}, {g['dofs']} dofs, GetFEM {g['getfem_version']}: "
          f"Newton {g['newton_iterations'][0]}, {'converged' if g['converged'] else 'NOT converged'}, "
          f"{g['active_nodes']} in contact, friction {g['stick_nodes']} S=, {g['slip_nodes']} S+/S-; "
          f"max N {Nmax:.6g}, max |T| {Tmax:.6g}")
    mc = g["mesh_check"]
    if not mc or mc["max_distance"] > 1e-12:
        fail(f"{law}: GetFEM's nodes were not checked to be sig-mesh's to 1e-12")
    if not g["converged"]:
        fail(f"{law}/getfem: Newton did not converge ({g['newton_iterations']} iterations)")
    law_checks(law, "getfem", gx[:, 0], gN, gT, gslip, gfric, gw, spec)

    ours = {}
    for method in ("pdas", "alm", "projection"):
        d = work / law / method
        s = json.loads((d / "summary.json").read_text())
        with open(d / "contact.csv", newline="") as fh:
            rows = list(csv.DictReader(fh))
        case = f"{law}/{method}"
        ox = np.array([[float(r["x1"]), float(r["x2"])] for r in rows])
        if len(rows) != len(G) or np.abs(ox - gx).max() > 1e-12:
            fail(f"{case}: contact.csv rows are not GetFEM's contact nodes in boundary order")
            continue
        o = {"node": [r["node"] for r in rows], "conv": s["converged"], "its": s["iterations"],
             "N": np.array([float(r["multiplier"]) for r in rows]),
             "T": np.array([float(r["tangential_multiplier"]) for r in rows]),
             "slip": np.array([float(r["slip"]) for r in rows]),
             "status": np.array([r["status"] for r in rows]),
             "normal": np.array([r["normal_status"] for r in rows]),
             "fric": np.array([r["friction_status"] for r in rows])}
        ours[method] = o
        if not o["conv"]:
            fail(f"{case}: did not converge in {o['its']} iterations ({s.get('failure', '')})")
        dN, dT = np.abs(o["N"] - gN), np.abs(o["T"] - gT)
        o["dN"], o["dT"] = dN.max() / Nmax, dT.max() / Tmax
        for what, diff, scale, mine, theirs in (("normal", dN, Nmax, o["N"], gN), ("tangential", dT, Tmax, o["T"], gT)):
            i = int(np.argmax(diff))
            if diff[i] > AGREE * scale:
                fail(f"{case}: node {o['node'][i]} (x1 = {gx[i, 0]:.6f}): {what} force {mine[i]:.9g} vs "
                     f"GetFEM {theirs[i]:.9g}, max |diff| / max = {diff[i] / scale:.2e} > {AGREE:g}")
        differ = [i for i in range(len(G))
                  if (o["status"][i], o["normal"][i], o["fric"][i]) != (gstat[i], gnormal[i], gfric[i])]
        o["mismatch"] = len(differ)
        for i in differ[:5]:
            fail(f"{case}: node {o['node'][i]} (x1 = {gx[i, 0]:.6f}): status {o['normal'][i]} {o['fric'][i]} "
                 f"vs GetFEM {gnormal[i]} {gfric[i]}")
        if len(differ) > 5:
            fail(f"{case}: and {len(differ) - 5} more nodes with statuses other than GetFEM's")
        if o["conv"]:
            law_checks(law, method, gx[:, 0], o["N"], o["T"], o["slip"], o["fric"], gw, spec)

    print(f"{'method':<11} {'conv':>4} {'its':>4} {'max|dN|/Nmax':>13} {'max|dT|/Tmax':>13} {'statuses':>9}")
    for method, o in ours.items():
        print(f"{method:<11} {'yes' if o['conv'] else 'NO':>4} {o['its']:>4} {o['dN']:>13.2e} {o['dT']:>13.2e} "
              f"{'same' if o['mismatch'] == 0 else str(o['mismatch']) + ' differ':>9}")
    shown = [i for i in range(len(G)) if gstat[i] == "contact" or any(o["status"][i] == "contact" for o in ours.values())]
    print(f"{'x1':>9} {'N GetFEM':>11} {'T GetFEM':>11} {'slip':>10} {'GetFEM':>7}" +
          "".join(f" {m:>10}" for m in ours))
    for i in shown:
        print(f"{gx[i, 0]:9.5f} {gN[i]:11.6f} {gT[i]:11.6f} {gslip[i]:10.3e} {gnormal[i] + ' ' + gfric[i]:>7}" +
              "".join(f" {o['normal'][i] + ' ' + o['fric'][i]:>10}" for o in ours.values()))
    if law == "tresca":
        free = [i for i in range(len(G)) if i not in shown]
        counts = {k: int(np.sum(gfric[free] == k)) for k in ("S=", "S+", "S-")}
        print(f"(the {len(free)} free nodes, Tresca friction on them: GetFEM {counts}; statuses compared above)")

if failures:
    sys.exit(f"\nfriction_getfem: {len(failures)} check(s) failed")
print("\nfriction_getfem: all checks passed")
EOF
