"""The adapted convergence studies of the scene reports (issue 29; scenes 4 and 5): the targets,
the loop's adapt.csv (drivers/adapt.sh), the references' own estimates, the loop's cost and the
chart of the error against the dofs, uniform and adapted side by side.

    steps = read_adapt_csv(folder)            # [{step, dofs, estimate, estimate_s, refine_s, ...}]
    eta = est_value(folder)                   # sig-estimate's eta (case.est), None when absent
    corrected(error, eta)                     # the error against the exact solution, estimated
    per_dof_ratios(steps, ladder, eta, eta_u) # adapted / uniform error at equal dofs, per step
    loop_cost(steps, last)                    # (stages' own seconds, wall seconds) to step last
    one_process_wall(uniform)                 # the uniform chain run in one process, or None
    adapted_figure(path, steps, ladder, ...)  # the PNG's name
"""
import csv
import math
from pathlib import Path

from .charts import pyplot
from .ds import read_ds
from .errors import ReportError
from .figure import save_figure

# The targets: slope against dofs, effectivity on every mesh, the finest uniform mesh's
# error reached with a fifth of its dofs and half its time.
ADAPT_SLOPE, ADAPT_SLOPE_TOL = 0.5, 0.075
EFFECTIVITY_RANGE = (0.3, 3.0)
DOFS_FRACTION, TIME_FRACTION = 0.2, 0.5


def read_adapt_csv(folder, name="adapt.csv"):
    """adapt.csv of drivers/adapt.sh in `folder` (or `name`, sig-adapt's loop.csv): one dict a
    step with step and dofs (int), estimate, estimate_s, refine_s, wall_s, refine_wall_s and
    elapsed_s (float)."""
    path = Path(folder) / name
    if not path.is_file():
        raise ReportError(f"{path}: missing (the scene driver's adaptive loop did not run)")
    with path.open() as f:
        return [{"step": int(row["step"]), "dofs": int(row["dofs"]),
                 **{key: float(row[key]) for key in ("estimate", "estimate_s", "refine_s",
                                                     "wall_s", "refine_wall_s",
                                                     "elapsed_s")}}
                for row in csv.DictReader(f)]


def est_value(folder):
    """sig-estimate's eta of a run folder (case.est), or None."""
    path = Path(folder) / "case.est"
    if not path.is_file():
        return None
    return float(read_ds(path, arrays=["estimate"]).array("estimate")[0])


def corrected(error, reference_estimate):
    """The error of a mesh against the exact solution from its error against a reference and the
    reference's own estimated error, added in quadrature: a heuristic. For a linear problem in its
    energy norm on nested spaces Galerkin orthogonality makes it exact,
    ||u - u_h||^2 = ||u_ref - u_h||^2 + ||u - u_ref||^2; contact, friction and the L2 norm of the
    strain make it an estimate (the reports keep the raw errors beside)."""
    return math.hypot(error, reference_estimate)


def per_dof_ratios(steps, ladder, eta_overkill, eta_uniform):
    """Each adapted mesh within the uniform ladder's dofs against the uniform error at its dofs
    (log-log interpolated on the ladder), both corrected by their references' own estimates:
    [(step, ratio)], each step its dict of `steps`; a ratio <= 1 is "no worse per dof"."""
    import numpy as np
    log_d = np.log([u["dofs"] for u in ladder])
    log_e = np.log([corrected(u["error"], eta_uniform) for u in ladder])
    return [(s, corrected(s["error"], eta_overkill) /
             math.exp(np.interp(math.log(s["dofs"]), log_d, log_e)))
            for s in steps if ladder[0]["dofs"] <= s["dofs"] <= ladder[-1]["dofs"]]


def loop_cost(steps, last):
    """The adaptive loop's cost up to step `last` (its estimate included, its refinement not):
    the stages' own times (solve + estimate + refine) and the loop's wall clock, elapsed_s: from
    drivers/adapt.sh's call of sig-adapt (the process's start included) to the end of step
    `last`'s estimate, every stage and sync of the steps before in it."""
    own = sum(s["solve_s"] + s["estimate_s"] for s in steps[:last + 1]) + \
        sum(s["refine_s"] for s in steps[:last])
    return own, steps[last]["elapsed_s"]


def one_process_wall(uniform):
    """The wall clock of the uniform mesh's chain run in one process as the loop's steps are
    (drivers/lib/adapted.sh: sig-adapt --steps 1 in UNIFORM/one_process, its estimate included),
    or None when it was not run."""
    path = Path(uniform) / "one_process"
    return read_adapt_csv(path, "loop.csv")[0]["elapsed_s"] if (path / "loop.csv").is_file() \
        else None


def one_process_text(one_process, wall):
    """The clause on the uniform mesh run in one process, the loop's way, for the reports."""
    if one_process is None:
        return ""
    return (f"; the uniform mesh run the loop's way (one process, sig-adapt --steps 1, its "
            f"estimate included) takes {one_process:.2f} s: {wall / one_process:.2f} of it")


def adapted_figure(path, steps, ladder, eta_overkill, eta_uniform, ref, slope, title,
                   others=()):
    """Error against dofs: the adapted meshes against the overkill reference, the uniform ones
    against their reference `ref` (a label, "n = 512"), each also with its reference's estimated
    error added in quadrature; `others`, (label, ladder) pairs, more uniform families (their
    errors as measured)."""
    fig, ax = pyplot().subplots(figsize=(6.4, 4.8))
    ad = [s["dofs"] for s in steps]
    un = [u["dofs"] for u in ladder]
    ax.loglog(ad, [s["error"] for s in steps], "o-", color="C0",
              label=f"adapted, against the overkill (slope {slope:.2f})")
    ax.loglog(ad, [corrected(s["error"], eta_overkill) for s in steps], "o:", color="C0",
              alpha=0.5, ms=3, label="adapted, + the overkill's own estimate")
    ax.loglog(un, [u["error"] for u in ladder], "s-", color="C3",
              label=f"uniform, against {ref}")
    ax.loglog(un, [corrected(u["error"], eta_uniform) for u in ladder], "s:", color="C3",
              alpha=0.5, ms=3, label=f"uniform, + {ref}'s own estimate")
    for i, (label, other) in enumerate(others):
        ax.loglog([u["dofs"] for u in other], [u["error"] for u in other], "^-",
                  color=f"C{i + 1}", label=label)
    x0, y0 = ad[-1], steps[-1]["error"]
    ax.loglog([ad[0], x0], [y0 * (ad[0] / x0) ** -0.5, y0], "k--", lw=0.8, label="dofs^(-1/2)")
    ax.set_xlabel("dofs (-)")
    ax.set_ylabel("||u_ref - u_h||_V (m)")
    ax.set_title(title, fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    fig.tight_layout()
    return save_figure(fig, path).name


def add_reach_checks(checks, figure, finest_name, uniform, reached, costs, solve="solve"):
    """The checks of the finest uniform mesh's error reached (issue 29): with at most a fifth of
    its dofs, and the loop up to there in at most half its time, the stages' own and the wall
    clocks. `costs` = (dofs ratio, loop own s, uniform own s, loop wall s, uniform wall s);
    `uniform` names the uniform mesh ("n = 64"), `solve` its stage ("solve", "march")."""
    ratio, own, uniform_own, wall, uniform_wall = costs
    checks.add(f"{figure} adapted: {finest_name}'s error reached with at most a fifth of its "
               "dofs", ratio <= DOFS_FRACTION,
               ours=f"step {reached['step']}, {reached['dofs']} dofs: {ratio:.3f}",
               target="<= 0.2")
    checks.add(f"{figure} adapted: the whole loop to that error ({solve} + estimate + refine, "
               f"the stages' own times) in at most half {uniform}'s {solve} time",
               own / uniform_own <= TIME_FRACTION,
               ours=f"{own:.3f} s / {uniform_own:.3f} s = {own / uniform_own:.2f}",
               target="<= 0.5")
    checks.add(f"{figure} adapted: the whole loop to that error in at most half {uniform}'s "
               "time, wall clocks: sig-adapt's process (mesh ... post, estimate, refine a step) "
               "against drivers/chain.sh's processes (mesh ... post), start-ups included",
               wall / uniform_wall <= TIME_FRACTION,
               ours=f"{wall:.2f} s / {uniform_wall:.2f} s = {wall / uniform_wall:.2f}",
               target="<= 0.5")
