#!/usr/bin/env bash
# Requirement (issue 28, "quasistatic and backward-Euler marches in velocity ... friction in time
# ... with the cone"; issue 23, "friction in every march"): the marches in velocity take friction
# of the slip rate in 2D and 3D on one code path, and the backward-Euler march runs on a 3D mesh.
# The case, datafiles/scene3d/creep_slip.dat: a Kelvin-Voigt pad (nu = 0, eta1 = 0), its top
# clamped sideways and pressed by p, its base on a foundation and dragged by a traction q along
# the in-plane (0.6, 0.8) (2D: a strip, the pull along x1), Coulomb friction mu, its sides
# carrying the complementary shear. Its stresses are uniform, so P1 holds the exact solution in
# both dimensions (u affine in height), against which 2D and 3D are checked alike:
#   quasistatic, law=damped, every step and node: N = p w, the sinking rate p / cn; with q > mu p
#     the slip along the pull, |T| = mu N and the pad's shear creeping by the march's
#     backward-Euler recurrence s_n - s_inf = (s_{n-1} - s_inf) eta2 / (eta2 + k E), s_inf =
#     2 H (q - mu p) / E, the vertical strain likewise towards -p / E; with q < mu p stick, T =
#     q w, no shear (1e-9 of each quantity's scale); case.hist's velocity_t, force_t {rows, p}
#     in 2D, {rows, p, 2} in 3D.
#   backward Euler, law=compliance, rho > 0 (its transient is not uniform: the mass's waves):
#     stick taken to rest, the static state u3 = -p / cn - p x3 / E, T = q w; a slide (Tresca at
#     the threshold q, no clamp, no pressure, an initial velocity V) moving rigidly at V with
#     T = s w at every node and step.
#   the laws, per node and step, where the field has no closed form: |T| = mu(|w_t|, w_n) N
#     along w_t (or w_t = 0 and |T| <= mu(0) N): Coulomb and nonmonotone (of=slip-rate, the
#     convexification loop in every step) in the backward Euler, nonmonotone and mu1 (of the
#     normal velocity) in the quasistatic march.
# (About 4 s: fourteen chains.)
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"

deck3=$root/datafiles/scene3d/creep_slip.dat
[ -r "$deck3" ] || die "no $deck3"
cp "$deck3" "$work/creep_slip3d.dat"
cp "$root/datafiles/scene3d/creep_slip.msh" "$work/"
# The 2D strip of the same height: plane strain, the rectangle's references 3 (base), 2 (top), 1
# and 4 (the sides x1 = 0 and 1).
sed -e 's/^MESH .*/MESH generator=rectangle lx=1 ly=0.5 nx=4 ny=2/' \
  -e 's/^DIRICHLET ref=2 ux=0 uy=0/DIRICHLET ref=2 ux=0/' \
  -e 's/^TRACTION ref=1 f=0.18,0.24,0$/TRACTION ref=3 f=0.3,0/' \
  -e 's/^TRACTION ref=3 f=0,0,0.06$/TRACTION ref=1 f=0,0.1/' \
  -e 's/^TRACTION ref=4 f=0,0,-0.06$/TRACTION ref=4 f=0,-0.1/' -e '/^TRACTION ref=[56] /d' \
  -e 's/^CONTACT ref=1 .*normal=0,0,1/CONTACT ref=3 obstacle=plane point=0,0 normal=0,1/' \
  -e 's/^FRICTION ref=1/FRICTION ref=3/' "$deck3" >"$work/creep_slip2d.dat"
[ "$(grep -c '^TRACTION' "$work/creep_slip2d.dat")" = 3 ] && grep -q "generator=rectangle" "$work/creep_slip2d.dat" &&
  grep -q "ref=3 f=0.3,0$" "$work/creep_slip2d.dat" ||
  die "the 2D variant of $deck3 was not made (its cards changed?)"

# Variants: stick (q = 0.1 < mu p, no shear: the side tractions 0); the backward-Euler march
# (compliance, a mass): the stick one far past its time constants (to rest), the slip one and its
# nonmonotone friction (the convexification in every step) over six steps, the slide (Tresca, no
# clamp, no pressure, q = the threshold, an initial velocity), and the slip one run to rest at
# eps = 1e-10 (berest: the slip rate falls to 1e-13 at the bound, a degenerate solution where the
# 3D step fixes the slip direction near the disc's edge, contact_newton.cpp; before, it stopped at
# step 12 of 20 in 3D).
variant() { # variant D NAME SED...
  local d=$1 name=$2
  shift 2
  sed "$@" "$work/creep_slip${d}d.dat" >"$work/${name}${d}d.dat"
}
stick=(-e 's/f=0.18,0.24,0$/f=0.06,0.08,0/' -e 's/f=0.3,0$/f=0.1,0/'
  -e 's/f=0,0,-\?0.0[68]$/f=0,0,0/' -e 's/f=0,-\?0.1$/f=0,0/')
be=(-e 's/law=damped cn=10/law=compliance cn=1000/' -e 's/eta2=10$/eta2=10 rho=1/'
  -e 's/^TIME .*/TIME scheme=backward-euler T=3 k=0.5/')
for d in 2 3; do
  variant $d stick "${stick[@]}"
  variant $d mu1 -e 's/law=coulomb mu=0.2/law=mu1 mu=0.2/' \
    -e 's/law=damped cn=10/law=damped-unilateral cn=10 g=0.2/'
  variant $d nonmono -e 's/law=coulomb mu=0.2/law=nonmonotone a=0.2 b=0.1 alpha=50 of=slip-rate/' \
    -e 's/T=0.5 k=0.05/T=0.25 k=0.05/'
  echo "CONVEXIFICATION eps=1e-10" >>"$work/nonmono${d}d.dat"
  variant $d be "${be[@]}"
  variant $d bestick "${be[@]}" "${stick[@]}" -e 's/T=3 k=0.5/T=10 k=0.5/'
  variant $d berest "${be[@]}" -e 's/T=3 k=0.5/T=10 k=0.5/' -e 's/eps=1e-12/eps=1e-10/'
  variant $d benonmono "${be[@]}" \
    -e 's/law=coulomb mu=0.2/law=nonmonotone a=0.2 b=0.1 alpha=50 of=slip-rate/'
  echo "CONVEXIFICATION eps=1e-8" >>"$work/benonmono${d}d.dat"
  variant $d beslide "${be[@]}" "${stick[@]}" -e '/^DIRICHLET/d' -e '/^PRESSURE/d' \
    -e 's/law=coulomb mu=0.2/law=tresca threshold=0.1/'
  [ $d = 2 ] && echo "INITIAL v=0.01,0" >>"$work/beslide2d.dat"
  [ $d = 3 ] && echo "INITIAL v=0.006,0.008,0" >>"$work/beslide3d.dat"
done
for name in creep_slip stick mu1 nonmono be bestick benonmono beslide berest; do
  for d in 2 3; do
    "$root/drivers/chain.sh" "$work/$name${d}d.dat" -o "$work/$name$d" >"$work/$name$d.log" 2>&1 ||
      { tail -20 "$work/$name$d.log"; die "drivers/chain.sh $name${d}d.dat failed"; }
  done
done

"$python" - "$work" "$bin" <<'PY'
import json, math, subprocess, sys
from pipeline_checks import check, finish
work, bindir = sys.argv[1], sys.argv[2]
E, eta, H, p, cn, mu = 100.0, 10.0, 0.5, 1.0, 10.0, 0.2

def dump(path):
    return json.loads(subprocess.run([f"{bindir}/sig-dump", "--json", "--values", path],
                                     capture_output=True, text=True, check=True).stdout)

def rows(a):
    width = len(a["values"]) // a["shape"][0]
    return [a["values"][i:i + width] for i in range(0, len(a["values"]), width)]

def run(name, d):
    x = dump(f"{work}/{name}{d}/case.nopo")["coordinates"]
    h = {a["name"]: a for a in dump(f"{work}/{name}{d}/case.hist")["arrays"] if "values" in a}
    return [x[i:i + d] for i in range(0, len(x), d)], h

def creep(k, steps, start, limit):
    """The march's backward-Euler recurrence of (E / 2) s + (eta / 2) s' = (E / 2) limit."""
    s = [start]
    for _ in range(steps):
        s.append(limit + (s[-1] - limit) * eta / (eta + k * E))
    return s

def pull(d):
    return [1.0] if d == 2 else [0.6, 0.8]

def check_nodes(label, d, h, step, normal_rate, slip_rate, T_per_weight, N_per_weight):
    """Step `step`'s contact values at every node against the exact ones."""
    t = d - 1
    w = h["weight"]["values"]
    vn = rows(h["velocity_n"])[step]
    fn = rows(h["force_n"])[step]
    vt = rows(h["velocity_t"])[step]
    ft = rows(h["force_t"])[step]
    off = 0.0
    for i, wi in enumerate(w):
        if normal_rate is not None:
            off = max(off, abs(vn[i] - normal_rate) / abs(normal_rate))
        off = max(off, abs(fn[i] - N_per_weight * wi) / (p * wi))
        for c in range(t):
            off = max(off, abs(vt[t * i + c] - slip_rate * pull(d)[c]) / max(abs(slip_rate), 1e-3))
            off = max(off, abs(ft[t * i + c] - T_per_weight * wi * pull(d)[c]) / (p * wi))
    return off

def check_field(d, x, u, s, e, base):
    """u: the pad's state, u_t = s (1 - x_d / H) along the pull, u_d = base + e x_d."""
    off = 0.0
    for i, xi in enumerate(x):
        z = xi[-1]
        for c in range(d - 1):
            off = max(off, abs(u[d * i + c] - s * (1 - z / H) * pull(d)[c]))
        off = max(off, abs(u[d * i + d - 1] - (base + e * z)))
    return off

# The quasistatic march, every step.
for name, q in (("creep_slip", 0.3), ("stick", 0.1)):
    results = {}
    for d in (2, 3):
        x, h = run(name, d)
        k = h["k"]["values"][0]
        steps = len(h["time"]["values"]) - 1
        slipping = q > mu * p
        s = creep(k, steps, 0.0, 2 * H * (q - mu * p) / E if slipping else 0.0)
        e = creep(k, steps, 0.0, -p / E)
        nodes = fields = 0.0
        for n in range(1, steps + 1):
            rate = (s[n] - s[n - 1]) / k
            nodes = max(nodes, check_nodes(name, d, h, n, p / cn, rate, mu * p if slipping else q, p))
            fields = max(fields, check_field(d, x, rows(h["u"])[n], s[n], e[n], -n * k * p / cn)
                         / (abs(s[-1]) + abs(e[-1]) * H + p / cn))
        status = {v for r in rows(h["friction_status"])[1:] for v in r}
        # case.hist's layout: d - 1 tangential components a node (history_io.hpp).
        nodes_ = len(h["weight"]["values"])
        shape = [steps + 1, nodes_] + ([2] if d == 3 else [])
        check(h["velocity_t"]["shape"] == shape and h["force_t"]["shape"] == shape and
              h["force_n"]["shape"] == [steps + 1, nodes_],
              f"quasistatic {name} {d}D: velocity_t and force_t of shape {shape}")
        check(h["converged"]["values"] == [1] and steps == 10, f"quasistatic {name} {d}D: 10 steps done")
        check(nodes < 1e-9, f"quasistatic {name} {d}D: per node N = p w, rate p / cn, the slip rate "
              f"of the recurrence, T = {'mu N' if slipping else 'q w'} along the pull "
              f"(worst {nodes:.1e})")
        check(fields < 1e-9, f"quasistatic {name} {d}D: the pad's displacement at every step "
              f"(worst {fields:.1e} of its scale)")
        check(status == ({2} if slipping else {1}), f"quasistatic {name} {d}D: friction statuses "
              f"{sorted(status)} ({'slip' if slipping else 'stick'})")
        results[d] = s[-1]
    if name == "creep_slip":
        check(results[2] > 0.98 * 2 * H * (q - mu * p) / E,
              f"the slip crept to {results[2]:.6g} of s_inf = {2 * H * (q - mu * p) / E:.6g}")

def law_check(d, h, coefficient):
    """Every step, every node: slipping (status 2), |T| = coefficient(|w_t|, w_n) N along w_t; or
    sticking (status 1), w_t = 0 and |T| <= coefficient(0, w_n) N. The worst departure of |T| from
    its law, relative to N, and the steps' counts of slipping and sticking nodes."""
    t = d - 1
    off, counts = 0.0, {1: 0, 2: 0, "other": 0}
    for n in range(1, len(h["time"]["values"])):
        vt, ft = rows(h["velocity_t"])[n], rows(h["force_t"])[n]
        fn, status = rows(h["force_n"])[n], rows(h["friction_status"])[n]
        vn = rows(h["velocity_n"])[n]
        for i in range(len(fn)):
            w, T = vt[t * i:t * i + t], ft[t * i:t * i + t]
            rate = math.sqrt(sum(c * c for c in w))
            if status[i] == 2 and rate > 0:
                bound = coefficient(rate, vn[i]) * fn[i]
                off = max(off, max(abs(T[c] - bound * w[c] / rate) for c in range(t)) / fn[i])
            elif status[i] == 1 and rate == 0:
                size = math.sqrt(sum(c * c for c in T))
                off = max(off, max(size - coefficient(0.0, vn[i]) * fn[i], 0.0) / fn[i])
            else:
                status[i] = "other"
            counts[status[i]] += 1
    return off, counts

a_, b_, alpha = 0.2, 0.1, 50.0
nonmonotone = lambda r, v_n: (a_ - b_) * math.exp(-alpha * r) + b_
# mu1 of the normal velocity v_n, the asperities' depth g = 0.2 a velocity bound here.
mu1 = lambda r, v_n: mu * min(max(v_n, 0.0) / 0.2, 1.0)
for name, coefficient, tolerance, steps in (
        ("be", lambda r, v_n: mu, 1e-9, 6), ("benonmono", nonmonotone, 1e-8, 6),
        ("nonmono", nonmonotone, 1e-8, 5), ("mu1", mu1, 1e-9, 10)):
    march = "backward Euler" if name.startswith("be") else "quasistatic"
    for d in (2, 3):
        x, h = run(name, d)
        off, counts = law_check(d, h, coefficient)
        check(h["converged"]["values"] == [1] and len(h["time"]["values"]) == steps + 1,
              f"{march} {name} {d}D: {steps} steps done")
        everywhere = name in ("be", "mu1")
        slips = counts[2] == steps * len(h["weight"]["values"]) if everywhere else counts[2] > 0
        check(slips and counts["other"] == 0 and off < tolerance,
              f"{march} {name} {d}D: slipping node-steps {counts[2]}, sticking {counts[1]}; "
              f"|T| = mu(|w_t|) N along w_t, or w_t = 0 and |T| <= mu(0) N "
              f"(worst {off:.1e} of N, tolerance {tolerance:g})")

# Slip, to rest (berest): the rate falls to round-off at the bound, where stick and slip are one
# state (the statuses may read either): 20 steps done, and |T| = mu N at every node and step.
for d in (2, 3):
    x, h = run("berest", d)
    last = len(h["time"]["values"]) - 1
    t = d - 1
    off = 0.0
    for n in range(1, last + 1):
        ft, fn = rows(h["force_t"])[n], rows(h["force_n"])[n]
        for i in range(len(fn)):
            size = math.sqrt(sum(c * c for c in ft[t * i:t * i + t]))
            off = max(off, abs(size - mu * fn[i]) / fn[i])
    check(h["converged"]["values"] == [1] and last == 20 and off < 1e-8,
          f"backward Euler berest {d}D: 20 steps done, |T| = mu N at every node and step "
          f"(worst {off:.1e} of N)")

# Stick, to rest: the static state, u3 = -p / cn - p x3 / E, no shear, T = q w.
for d in (2, 3):
    x, h = run("bestick", d)
    last = len(h["time"]["values"]) - 1
    nodes = check_nodes("bestick", d, h, last, None, 0.0, 0.1, p)
    fields = check_field(d, x, rows(h["u"])[last], 0.0, -p / E, -p / 1000.0) / (p / E * H + p / 1000.0)
    check(h["converged"]["values"] == [1] and last == 20, f"backward Euler bestick {d}D: 20 steps done")
    check(nodes < 1e-9 and fields < 1e-9, f"backward Euler bestick {d}D: at rest, the static "
          f"state (worst {fields:.1e}), N = p w, T = q w (worst {nodes:.1e})")

# The slide: the pad moves rigidly at V, the Tresca force s w balancing the pull at every node.
V = 0.01
for d in (2, 3):
    x, h = run("beslide", d)
    steps = len(h["time"]["values"]) - 1
    off = 0.0
    for n in range(1, steps + 1):
        t_n = h["time"]["values"][n]
        off = max(off, check_nodes("beslide", d, h, n, None, V, 0.1, 0.0) / (V + 0.1))
        u = rows(h["u"])[n]
        for i in range(len(x)):
            for c in range(d - 1):
                off = max(off, abs(u[d * i + c] - V * t_n * pull(d)[c]) / (V * t_n))
            off = max(off, abs(u[d * i + d - 1]) / (V * t_n))
    check(h["converged"]["values"] == [1] and steps == 6 and off < 1e-9,
          f"backward Euler beslide {d}D: {steps} steps, rigid slide at V with T = s w "
          f"(worst {off:.1e})")
finish("creep_slip")
PY
[ "$failures" -eq 0 ] || exit 1
echo "$test_name: passed"
