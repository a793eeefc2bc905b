"""sigreport.impact (the runs of scenes 8a and 8b) and sigreport.fits: the measures of an
energy.csv, the one stability status both impact reports use, a convergence rate."""
import math

import pytest

from sigreport import loglog_slope
from sigreport.impact import (SMALLEST_CHANGE, energy_measures, impact_window, read_energy_rows,
                              speed_point, stability_status)

ENERGY = """time,total,active_nodes,max_penetration,newton_iterations
0,100,0,0,0
0.1,100,0,0,0
0.2,99,3,0.002,4
0.3,98.5,5,0.004,5
0.4,98.5,0,0,0
"""


def run_of(tmp_path, text=ENERGY, k=0.1, T=0.4, hist=None):
    (tmp_path / "energy.csv").write_text(text)
    run = {"rows": read_energy_rows(tmp_path), "hist": hist or {}, "k": k, "T": T,
           "wall": 2.0}
    run.update(energy_measures(run))
    return run


def test_energy_measures(tmp_path):
    run = run_of(tmp_path)
    assert run["converged"] and run["steps"] == 4 and run["e0"] == 100
    assert run["change"] == pytest.approx(-1.5) and run["penetration"] == 0.004
    assert run["impact_step"] == 2 and run["impact_time"] == 0.2 and run["max_active"] == 5
    assert run["newton"] == 9 and run["contact"] == [2, 3]
    # A march that stopped early, or that says so, did not converge; no k: every row is planned.
    assert not run_of(tmp_path, T=0.5)["converged"]
    assert not run_of(tmp_path, hist={"converged": 0})["converged"]
    assert run_of(tmp_path, k=math.nan, T=math.nan)["converged"]
    (tmp_path / "energy.csv").write_text("time,total\n")
    assert read_energy_rows(tmp_path) is None and read_energy_rows(tmp_path / "none") is None


def test_window_and_speed_point(tmp_path):
    run = run_of(tmp_path)
    assert impact_window([run], before=0.05, after=1.0) == pytest.approx((0.15, 1.2))
    assert impact_window([dict(run, impact_time=math.nan)], 1, 1) == (-math.inf, math.inf)
    assert speed_point(run, "k=0.1") == (5.0, 1.5, "k=0.1")  # wall / T, |dE| / E0 in %
    assert speed_point(dict(run, change=1e-9), "").y == SMALLEST_CHANGE
    assert speed_point(dict(run, converged=False), "").y is None


@pytest.mark.parametrize("converged, change, chatter, gain, loss, status", [
    (False, -0.5, True, 0.1, 0.1, "Nv"),
    (True, 0.05, False, 0.1, 0.1, "ok"),
    (True, 0.2, False, 0.1, 0.1, "gain"),
    (True, -0.5, False, 0.1, 0.1, "dissipates"),   # 8a: a visible loss is 0.1 %
    (True, -0.5, False, 0.1, 1.0, "ok"),           # 8b: only a loss beyond 1 % is flagged
    (True, -0.5, True, 0.1, 0.1, "dissipates+chatter"),
    (True, 0.2, True, 0.1, 1.0, "gain+chatter"),
])
def test_stability_status(converged, change, chatter, gain, loss, status):
    run = {"converged": converged, "change": change}
    assert stability_status(run, gain=gain, loss=loss, chatter=chatter) == status


def test_loglog_slope():
    h = [1 / 8, 1 / 16, 1 / 32]
    assert loglog_slope(h, [x for x in h]) == pytest.approx(1)
    assert loglog_slope(h, [3 * x ** 2 for x in h]) == pytest.approx(2)
    assert loglog_slope(h[:1], [1.0]) is None
