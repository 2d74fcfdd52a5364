"""Accuracy and time of :func:`thinlayer.numerics.solve_2d` on a 4-sided pyramid (issue 24 item 4).

The problem: ``Punch.pyramid(35, sides=4)`` at delta0 = 1 on ``BondedLayer(0.3)``, H = a/10 (a = the inradius of
the level-set square), the square ``[-1.25 a, 1.25 a]^2``, tol = 1e-10.  Solved at n = 256, 512, 1024 cells per side;
the accuracy of each grid (``err`` in the row's name) is its force's distance to the Richardson extrapolation of
the three (order from the last two differences).  The time rows: the best of 3 wall times at 512^2 (target 2 s,
issue 24 item 7) and one at 1024^2, each with its process CPU time (all threads) beside it: on a shared machine the
wall time is the CPU time plus the wait for a core (``uptime`` is printed in the table's header).
"""
from __future__ import annotations

import math
import time

from _timing import Row, main


def run() -> list[Row]:
    import thinlayer as tl
    from thinlayer.numerics import solve_2d

    tip = tl.Punch.pyramid(35, 4)
    a = tip.level_set(1.0).half_width
    H = 0.1 * a
    layer = tl.BondedLayer(0.3)

    def solve(n):
        return solve_2d(layer, tip, delta0=1.0, H=H, n=n, extent=1.25 * a, tol=1e-10, workers=2)

    solve(128)  # imports, caches
    out = {}
    for n, repeat in ((256, 1), (512, 3), (1024, 1)):
        best = (math.inf, math.inf, None)
        for _ in range(repeat):
            t0, c0 = time.perf_counter(), time.process_time()
            res = solve(n)
            best = min(best, (time.perf_counter() - t0, time.process_time() - c0, res), key=lambda b: b[0])
        out[n] = best
    P = [out[n][2].force for n in (256, 512, 1024)]
    d1, d2 = P[1] - P[0], P[2] - P[1]
    p = math.log2(abs(d1 / d2)) if d2 else math.inf
    rich = P[2] + d2 / (2**p - 1) if math.isfinite(p) and p > 0 else P[2]
    rows = []
    for n, target in ((512, "<= 2 s"), (1024, "")):
        wall, cpu, res = out[n]
        err = abs(res.force / rich - 1)
        rows.append(Row(f"pyramid solve_2d {n}^2: force err {err:.1e} ({res.iterations} it.)", wall, target))
        rows.append(Row(f"  pyramid solve_2d {n}^2, CPU time (all threads)", cpu, "<= 2 s" if n == 512 else ""))
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
