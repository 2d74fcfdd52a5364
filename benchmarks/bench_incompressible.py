"""Benchmarks of the incompressible layer and the two-term model (issue 7, item 2)."""
from __future__ import annotations

import time

import numpy as np


def _best(fn, repeat=3):
    best = float("inf")
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def run() -> list[tuple[str, float, str]]:
    from thinlayer import Punch
    from thinlayer.asymptotics import incompressible as inc
    from thinlayer.numerics.direct import solve_axisymmetric

    rows = []

    def ellipse():
        inc._ellipse_generic.cache_clear()
        inc._ellipse.cache_clear()
        e = inc.incompressible_ellipse()
        assert e.force_t.has(inc.t_sym)

    rows.append(("ellipse closed form (I.6)-(I.8), derived from scratch", _best(ellipse, 1), "< 3 s"))

    def sphere():
        inc._sphere_generic.cache_clear()
        inc._two_term_sphere.cache_clear()
        inc.two_term_sphere("49/100")
        inc.two_term_sphere()

    rows.append(("two-term sphere (I.11), Bessel and k = 0 derivations", _best(sphere, 1), "< 2 s"))

    def edge():
        inc._edge_shift_cached.cache_clear()
        inc.two_term_edge_shift(0.5)

    rows.append(("edge correction h(1/2) (I.12), mpmath quadrature", _best(edge), "< 0.5 s"))

    ts = inc.two_term_sphere(0.499)
    ts.evaluate(0.2, 1000.0, 1.0)
    rows.append(("two-term sphere: radius and force for one depth", _best(lambda: ts.evaluate(0.2, 1000.0, 1.0)),
                 "< 20 ms"))

    x = np.random.default_rng(0).uniform(0, 50, 10**6)
    rows.append(("psi, chi (I.11) on 10^6 points", _best(lambda: inc._psi_chi(x)), "< 1 s"))

    pun = Punch.elliptic_paraboloid(2, 1)
    rows.append(("grid obstacle solver, ellipse, 161^2 nodes",
                 _best(lambda: inc.solve_obstacle_grid(pun, 0.1, 0.1, n=161)), "< 1 s"))
    rows.append(("grid obstacle solver, ellipse, 321^2 nodes",
                 _best(lambda: inc.solve_obstacle_grid(pun, 0.1, 0.1, n=321), 1), "< 5 s"))

    layer = inc.IncompressibleLayer()
    rows.append(("direct solver at nu = 1/2, sphere, a/H = 40",
                 _best(lambda: solve_axisymmetric(layer, lambda r: r * r / 2000.0, 0.4, 1.0), 1), "< 3 s"))
    return rows


if __name__ == "__main__":
    for name, secs, target in run():
        print(f"{name:<62} {secs:10.4f}  {target}")
