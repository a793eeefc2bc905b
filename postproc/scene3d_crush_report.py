#!/usr/bin/python3
"""The hyperelastic crush report (issue 28): the hollow Ciarlet-Geymonat ball of
datafiles/scene3d/crush.dat pressed on a plane, in one and in several load steps, every method of
sig-solve's large-deformation solve against GetFEM 5.4 on the same mesh.

    postproc/scene3d_crush_report.py OUTDIR

OUTDIR is what drivers/scene3d_crush.sh wrote: per mesh (coarse, fine) and number of load steps
S, <mesh>/steps<S>/<method>/case.b (sig-solve) and <mesh>/steps<S>/getfem.json
(postproc/getfem_crush3d.py, absent with --no-getfem). Writes OUTDIR/report.md,
OUTDIR/summary.json and OUTDIR/scene.json; exit 1 when a check fails.

Per run and load step the vertical reaction on the top: ours, the sum of the contact forces at
that step (case.b step_multiplier: with no other load they balance the press; at the last step
case.b's reaction_z, the internal force on the held dofs, is checked against it), GetFEM's (the
internal force of its law summed over the top's x3 dofs), and their relative difference; the
Newton iterations per method and load step (case.b step_iterations, and the small-strain start's
contact iterations), GetFEM's beside them.
"""
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from sigreport import Checks, Table, finish_report, main_guard  # noqa: E402
from sigreport.ds import read_ds  # noqa: E402
from sigreport.scene import read_command  # noqa: E402

METHODS = ("pdas", "alm", "projection", "penalty")
EXACT = ("pdas", "alm", "projection")  # penalty's foundation is compliant: another problem
GETFEM_TOL = 1e-6  # the issue's: reaction against GetFEM
BALANCE_TOL = 1e-8  # our reaction_z against the contact forces (Newton eps 1e-10)


def our_run(folder):
    """Per load step the iterations and the reaction, from case.b; None when the run left none."""
    path = folder / "case.b"
    if not path.is_file():
        return None
    b = read_ds(path, ["converged", "step_iterations", "step_multiplier", "step_status", "reaction_z",
                       "start_iterations", "time_solve", "dofs"])
    multipliers = b.array("step_multiplier")
    return {"converged": bool(b.scalar("converged")),
            "step_iterations": [int(i) for i in b["step_iterations"]],
            "step_reaction": [-float(row.sum()) for row in multipliers],
            "step_contact_nodes": [int(row.sum()) for row in b.array("step_status")],
            "reaction_z": float(b.scalar("reaction_z")),
            "start_iterations": int(b.scalar("start_iterations")) if "start_iterations" in b else None,
            "solve_seconds": float(b.scalar("time_solve")), "dofs": int(b.scalar("dofs"))}


def contact_nodes(ours, getfem, k):
    """"n" or "n / m" (GetFEM's m) nodes in contact at load step k."""
    text = str(ours["step_contact_nodes"][k]) if ours and k < len(ours["step_contact_nodes"]) else "—"
    if getfem:
        text += f" / {getfem['steps'][k]['contact_nodes']}" if k < len(getfem["steps"]) else " / —"
    return text


def relative(ours, theirs):
    return abs(ours - theirs) / abs(theirs)


def main():
    out = Path(sys.argv[1])
    info = read_command(out, required=("command",))
    meshes = [m for m in ("coarse", "fine") if (out / m).is_dir()]
    checks = Checks()
    lines = ["# The hyperelastic crush: a hollow Ciarlet-Geymonat ball pressed on a plane", "",
             f"Produced by `{info['command']}` ({info.get('date', '?')}, revision "
             f"{info.get('revision', '?')}). The deck: datafiles/scene3d/crush.dat (the top held and "
             "lowered by 0.5 R, frictionless plane, Newton eps = 1e-10); GetFEM: "
             "postproc/getfem_crush3d.py on the same mesh. Reactions: the vertical force of the "
             "press on the ball (negative: downwards); ours per step is the sum of the contact "
             "forces. Penalty (r = 1e4) solves another problem, a compliant foundation: its "
             "difference is the foundation's, not compared at 1e-6.", ""]
    summary = {"meshes": {}}
    unconverged, balance, far, path = [], 0.0, [], 0.0
    compared = 0
    for mesh in meshes:
        step_counts = sorted(int(p.name[5:]) for p in (out / mesh).glob("steps*"))
        summary["meshes"][mesh] = {}
        finals = {}
        for steps in step_counts:
            folder = out / mesh / f"steps{steps}"
            runs = {m: our_run(folder / m) for m in METHODS}
            getfem_path = folder / "getfem.json"
            getfem = json.loads(getfem_path.read_text()) if getfem_path.is_file() else None
            summary["meshes"][mesh][steps] = {"ours": runs, "getfem": getfem}
            dofs = next((r["dofs"] for r in runs.values() if r), "?")
            lines += [f"## {mesh} mesh ({dofs} dofs), {steps} load step{'s' if steps > 1 else ''}", ""]
            header = ["load step", "nodes in contact (pdas)"] + [f"{m} reaction" for m in METHODS]
            if getfem:
                header[1] += " / GetFEM"
                header += ["GetFEM reaction"] + [f"{m} vs GetFEM" for m in METHODS]
            table = Table(header)
            for k in range(steps):
                row = [f"{k + 1} ({(k + 1) / steps:.3g})", contact_nodes(runs["pdas"], getfem, k)]
                for m in METHODS:
                    r = runs[m]
                    row.append(f"{r['step_reaction'][k]:.10g}" if r and k < len(r["step_reaction"]) else "—")
                if getfem:
                    g = getfem["steps"][k]["reaction_z"] if k < len(getfem["steps"]) else None
                    row.append(f"{g:.10g}" if g is not None else "—")
                    for m in METHODS:
                        r = runs[m]
                        if g is None or not r or k >= len(r["step_reaction"]):
                            row.append("—")
                            continue
                        d = relative(r["step_reaction"][k], g)
                        row.append(f"{d:.1e}")
                        if m in EXACT:
                            compared += 1
                            if d > GETFEM_TOL:
                                far.append(f"{mesh}/{steps} steps/{m} step {k + 1}: {d:.2g}")
                table.add(*row)
            lines += [table.markdown(), ""]
            its = Table(["method", "Newton iterations per load step", "total",
                         "small-strain start (contact iterations)", "solve s"])
            for m in METHODS:
                r = runs[m]
                if not r:
                    its.add(m, "no case.b", "—", "—", "—")
                    unconverged.append(f"{mesh}/{steps}/{m}")
                    continue
                its.add(m, " ".join(map(str, r["step_iterations"])) + ("" if r["converged"] else " Nv"),
                        sum(r["step_iterations"]), r["start_iterations"], f"{r['solve_seconds']:.3f}")
                if not r["converged"]:
                    unconverged.append(f"{mesh}/{steps}/{m}")
                    continue
                balance = max(balance, relative(r["reaction_z"], r["step_reaction"][-1]))
                finals.setdefault(m, []).append(r["reaction_z"])
            if getfem:
                its.add("GetFEM", " ".join(str(s["newton_iterations"]) for s in getfem["steps"])
                        + ("" if getfem["converged"] else " Nv"), getfem["newton_iterations"], "rest",
                        f"{getfem['solve_seconds_median']:.3f}")
                if not getfem["converged"]:
                    unconverged.append(f"{mesh}/{steps}/GetFEM")
            lines += [its.markdown(), ""]
            if getfem:
                lines += [f"GetFEM {getfem['getfem_version']}: {getfem['description']}.", ""]
        for values in finals.values():
            path = max(path, (max(values) - min(values)) / abs(values[0]))

    checks.add("every run converges (ours and GetFEM's)", not unconverged,
               ", ".join(unconverged) or "all")
    checks.add(f"our reaction_z is the contact forces' sum to {BALANCE_TOL:g}", balance <= BALANCE_TOL,
               ours=f"{balance:.2g}", target=f"<= {BALANCE_TOL:g}")
    checks.add("one and several load steps end at the same reaction (path independence), per method",
               path <= GETFEM_TOL, ours=f"{path:.2g}", target=f"<= {GETFEM_TOL:g}")
    name = f"pdas, alm and projection: the reaction of every load step is GetFEM's to {GETFEM_TOL:g}"
    if compared:
        checks.add(name, not far, "; ".join(far) or f"{compared} compared",
                   ours=f"{compared - len(far)}/{compared}", tolerance=f"{GETFEM_TOL:g} relative")
    else:
        checks.add(name, None, "no GetFEM (python3-getfem) or --no-getfem")
    lines += ["## Checks", "", checks.table().markdown(), ""]
    return finish_report(out, "\n".join(lines) + "\n", "3d_crush", "Hyperelastic crush in 3D", info,
                         checks, summary)


if __name__ == "__main__":
    main_guard(main)
