"""The reports' figures are readable: every axis that shows a measure carries its label with a
unit, texts do not collide, legends do not cover the data (sigreport.figure.save_figure, the one
way a report writes a PNG), and no report writes a PNG any other way."""
import ast
import os
import shutil
import subprocess
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from sigreport import ChartError, axis_unit, save_figure  # noqa: E402
from sigreport.figure import collisions, missing_units  # noqa: E402

POSTPROC = Path(__file__).resolve().parents[2] / "postproc"
PNG = b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("label, unit", [
    ("x1 (m)", "m"), ("time [s]", "s"), ("cn (GPa s/m)", "GPa s/m"), ("psi (m^-2)", "m^-2"),
    ("relative error (-)", "-"), ("energy change (%)", "%"), ("alpha (1/m)", "1/m"),
    ("outer loop (iterations)", "iterations"), ("normal pressure p(u_nu) (GPa)", "GPa"),
    ("E_k (mm, MPa)", "mm, MPa"), ("eta (GPa.s)", "GPa.s"),
    ("x1", None), ("", None), ("h = k", None), ("contact nodes (active set)", None),
    ("discrete energy E / E0 (8.33)", None), ("(m) the unit first", None),
    ("relative error (pressure L2 on Gamma3; energy norm)", None), ("x1 (m) ", "m"),
])
def test_axis_unit_is_the_unit_at_the_end_of_the_label(label, unit):
    assert axis_unit(label) == unit


def line_figure(xlabel, ylabel):
    fig, ax = plt.subplots(figsize=(4, 3))
    ax.plot([1, 2, 3], [1, 4, 9], label="u")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    return fig


def test_a_labelled_figure_is_saved(tmp_path):
    path = save_figure(line_figure("mesh size h (m)", "relative error (-)"), tmp_path / "ok.png")
    assert path == tmp_path / "ok.png" and path.read_bytes()[:8] == PNG
    assert not plt.get_fignums()  # closed


def test_an_axis_without_its_unit_is_refused(tmp_path):
    # The deliberate failure: the y axis shows numbers but its label has no unit.
    with pytest.raises(ChartError, match=r"axes 1 of 1: y label 'relative error' has no unit"):
        save_figure(line_figure("mesh size h (m)", "relative error"), tmp_path / "bad.png")
    assert not (tmp_path / "bad.png").exists() and not plt.get_fignums()
    # An unlabelled axis is refused too; one without tick labels shows no measure.
    fig = line_figure("", "relative error (-)")
    assert missing_units(fig) == ["axes 1 of 1: x label '' has no unit in parentheses or brackets"]
    fig.axes[0].set_xticks([])
    assert missing_units(fig) == []
    plt.close(fig)


def test_every_axes_of_a_grid_is_checked(tmp_path):
    fig, axes = plt.subplots(1, 2)
    for ax in axes:
        ax.plot([0, 1], [0, 1])
        ax.set_xlabel("t (s)")
    axes[0].set_ylabel("x1 (m)")
    axes[1].set_ylabel("x2")
    assert missing_units(fig) == ["axes 2 of 2: y label 'x2' has no unit in parentheses or "
                                  "brackets"]
    fig.colorbar(axes[0].scatter([0, 1], [0, 1], c=[1, 2]), ax=axes[0], label="count")
    assert "axes 3 of 3: y label 'count' has no unit in parentheses or brackets" in \
        missing_units(fig)
    plt.close(fig)


def test_colliding_texts_are_refused(tmp_path):
    fig = line_figure("t (s)", "x (m)")
    fig.axes[0].annotate("N=128", (2, 4))
    fig.axes[0].annotate("N=256", (2, 4))
    with pytest.raises(ChartError, match="texts on top of each other: axes 1 text 'N=128' and "
                                         "axes 1 text 'N=256'"):
        save_figure(fig, tmp_path / "clash.png")
    assert not (tmp_path / "clash.png").exists()


def test_crowded_log_ticks_are_untangled(tmp_path):
    # Less than a decade on a narrow log axis: matplotlib labels 1.2 x 10^1, 1.4 x 10^1, ... and
    # they overlap (scene 8b's speed chart); save_figure writes them as plain numbers.
    fig, ax = plt.subplots(figsize=(3, 2.5))
    ax.loglog([10.5, 23.5], [1e-5, 2], "o-")
    ax.set_xlabel("wall time per simulated second (s/s)")
    ax.set_ylabel("|dE| / E0 (%)")
    fig.tight_layout()
    assert any("x tick" in c for c in collisions(fig))
    save_figure(fig, tmp_path / "ticks.png")
    assert collisions(fig) == []
    labels = [t.get_text() for t in ax.get_xticklabels(minor=True) if t.get_text()]
    assert labels and all("times" not in t for t in labels)


def test_a_title_over_a_tick_label_is_lifted(tmp_path):
    # A log y axis ending on a decade puts its top label "10^0" half above the axes, into the
    # title (the frictional Hertz speed chart, when the measured points set such limits).
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.loglog([0.01, 3], [1e-4, 0.5], "o")
    ax.set_ylim(1e-4, 1.0)
    ax.set_title("Frictional Hertz: speed against accuracy (hollow on the grey line: Nv)")
    size = ax.title.get_fontsize()
    ax.set_xlabel("sig-solve time (s)")
    ax.set_ylabel("tangential traction error (-)")
    fig.tight_layout()
    assert any("title" in c and "y tick" in c for c in collisions(fig))
    save_figure(fig, tmp_path / "title.png")
    assert collisions(fig) == []
    assert ax.get_title().startswith("Frictional Hertz") and ax.title.get_fontsize() == size


def test_a_legend_over_the_data_moves_beside_the_axes(tmp_path):
    fig, ax = plt.subplots(figsize=(4, 3))
    for k in range(6):
        ax.plot([0, 1], [0.1 * k, 1 - 0.1 * k], label=f"curve {k} with a long name")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("u (m)")
    ax.legend(loc="center")
    width = fig.get_size_inches()[0]
    save_figure(fig, tmp_path / "legend.png")
    legend = ax.get_legend()
    assert legend.get_bbox_to_anchor().x0 > ax.get_window_extent().x1  # right of the axes
    assert fig.get_size_inches()[0] > width and len(legend.get_texts()) == 6


def calls_savefig(path):
    """The lines of a Python file that call .savefig(...)."""
    tree = ast.parse(path.read_text(), str(path))
    return [node.lineno for node in ast.walk(tree) if isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute) and node.func.attr == "savefig"]


def test_no_report_writes_a_figure_but_through_save_figure():
    scripts = sorted(POSTPROC.rglob("*.py"))
    assert len(scripts) > 20 and POSTPROC / "scene4_report.py" in scripts
    offenders = {str(p.relative_to(POSTPROC)): calls_savefig(p) for p in scripts
                 if p != POSTPROC / "sigreport" / "figure.py"}
    assert {p: lines for p, lines in offenders.items() if lines} == {}
    assert calls_savefig(POSTPROC / "sigreport" / "figure.py")  # the scan sees a call


def test_a_report_draws_its_figures_through_the_checks(scene, bin_dir, tmp_path):
    # Scene 7a's report on the canned runs: its speed-accuracy chart goes through save_figure;
    # with an axis label stripped of its unit the same report fails, naming the file.
    env = dict(os.environ, SIG_BIN=str(bin_dir), PYTHONDONTWRITEBYTECODE="1")
    run = [sys.executable, str(POSTPROC / "scene7a_report.py"), str(scene)]
    done = subprocess.run(run, capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    assert (scene / "speed_vs_accuracy.png").read_bytes()[:8] == PNG
    broken = tmp_path / "postproc"
    shutil.copytree(POSTPROC, broken, ignore=shutil.ignore_patterns("__pycache__"))
    report = broken / "scene7a_report.py"
    report.write_text(report.read_text().replace(
        'ylabel="relative L2 pressure error vs Hertz (-)"', 'ylabel="relative L2 error"'))
    (scene / "speed_vs_accuracy.png").unlink()
    done = subprocess.run([sys.executable, str(report), str(scene)], capture_output=True,
                          text=True, env=env)
    assert done.returncode == 1
    assert "speed_vs_accuracy.png: not saved, an axis without its unit" in done.stderr
    assert not (scene / "speed_vs_accuracy.png").exists()
