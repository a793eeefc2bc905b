"""Convergence rates: the least-squares slope of log(error) against log(h) (or of any positive
quantity against another).

    loglog_slope([1/16, 1/32, 1/64], [4e-2, 2e-2, 1e-2])   # 1.0
"""
import math


def loglog_slope(xs, ys):
    """The least-squares slope of log y against log x; None for fewer than two points."""
    if len(xs) < 2:
        return None
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)
