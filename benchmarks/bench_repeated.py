"""Repeated solves (issue 18 item 2): a second ``solve()`` of the same layer and punch with other delta0, H, mu,
and the force law over an array of depths.

What depends on (layer, punch) only is prepared once (the symbolic law (1.8) compiled, the edge shifts, the punch's
shape); the first call is the peer of the second (ratio = first/second).  Targets: a second solve <= 1 ms (sphere
and elliptic paraboloid; the general polynomial needs its contour at every depth and is shown for information),
the vectorised law on 10^6 depths <= 50 ms.
"""
from __future__ import annotations

import statistics
import time

from _timing import Row, main


def _median_of(calls, repeat: int = 200) -> float:
    times = []
    for k in range(repeat):
        t0 = time.perf_counter()
        calls(k)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def run() -> list[Row]:
    import numpy as np

    import thinlayer as tl
    from thinlayer.asymptotics import force_law as fl
    from thinlayer.asymptotics.solution import force_arrays

    sphere, ellipse = tl.Punch.paraboloid(10), tl.Punch.elliptic_paraboloid(40, 10)
    quartic = tl.Punch("x_1**2/2 + x_2**2 + x_1**3/5 + x_1*x_2/10 + x_1**4 + x_2**4")
    cases = [
        ("compressible sphere nu=0.3", tl.BondedLayer(0.3), sphere, 0.02, "compressible", "<= 1 ms"),
        ("compressible ellipse 4:1 nu=0.3", tl.BondedLayer(0.3), ellipse, 0.02, "compressible", "<= 1 ms"),
        ("compressible sphere, frictionless base", tl.FrictionlessLayer(0.3), sphere, 0.02, "compressible",
         "<= 1 ms"),
        ("two-term sphere nu=0.45", tl.BondedLayer(0.45), sphere, 0.005, "two-term", "<= 1 ms"),
        ("incompressible sphere", tl.BondedLayer(0.5), sphere, 0.005, "incompressible", "<= 1 ms"),
        ("incompressible ellipse 4:1", tl.BondedLayer(0.5), ellipse, 0.005, "incompressible", "<= 1 ms"),
        ("auto sphere nu=0.3", tl.BondedLayer(0.3), sphere, 0.02, "auto", "<= 1 ms"),
        ("compressible quartic (contour per depth)", tl.BondedLayer(0.3), quartic, 0.02, "compressible", ""),
    ]
    rows = []
    for name, layer, punch, H, model, target in cases:
        fl._force_law_cached.cache_clear()
        t0 = time.perf_counter()
        tl.solve(layer, punch, delta0=0.1, H=H, mu=1.0, model=model, tol=1.0)
        first = time.perf_counter() - t0

        def again(k, layer=layer, punch=punch, H=H, model=model):
            return tl.solve(layer, punch, delta0=0.1 + 1e-4 * k, H=H * (1 + 1e-3 * k), mu=1.0 + k, model=model,
                            tol=1.0)

        rows.append(Row(f"second solve(): {name} (median of 200)", _median_of(again, 200 if target else 20),
                        target, "first call", first))
    d = np.linspace(0.01, 1.0, 10**6)
    for name, punch in (("sphere", sphere), ("ellipse 4:1", ellipse)):
        layer = tl.BondedLayer(0.3)
        force_arrays(layer, punch, d[:10], H=0.02)
        t0 = time.perf_counter()
        for k in range(20):
            tl.solve(layer, punch, delta0=float(d[k * 1000]), H=0.02, mu=1.0, model="compressible", tol=1.0)
        per_solve = (time.perf_counter() - t0) / 20
        rows.append(Row(f"force_arrays: {name}, 10^6 depths (vs 10^6 solve() calls)",
                        min(_median_of(lambda k: force_arrays(layer, punch, d, H=0.02, mu=1.3), 5) for _ in range(1)),
                        "<= 50 ms", "solve() per depth", per_solve * 1e6))
    return rows


if __name__ == "__main__":
    main(run)
