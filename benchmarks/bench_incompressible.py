"""Benchmarks of the incompressible layer and the two-term model (issue 7, item 2)."""
from __future__ import annotations

import numpy as np
from _timing import best, main


def run() -> list[tuple[str, float, str]]:
    from thinlayer import Punch
    from thinlayer.asymptotics.incompressible import leading as inc
    from thinlayer.asymptotics.incompressible import two_term as inc2
    from thinlayer.layers.kernels import BondedLayer, IncompressibleLayer
    from thinlayer.numerics import obstacle as grid
    from thinlayer.numerics import solve_axisymmetric

    rows = []

    def ellipse():
        inc._ellipse_generic.cache_clear()
        inc._ellipse.cache_clear()
        e = inc.incompressible_ellipse()
        assert e.force_t.has(inc.t_sym)

    rows.append(("ellipse closed form (I.6)-(I.8), derived from scratch", best(ellipse, 1), "< 3 s"))

    def sphere():
        inc2._sphere_generic.cache_clear()
        inc2._two_term_sphere.cache_clear()
        inc2.two_term_sphere(BondedLayer("49/100"))
        inc2.two_term_sphere()

    rows.append(("two-term sphere (I.11), Bessel and k = 0 derivations", best(sphere, 1), "< 2 s"))

    def edge():
        inc2._edge_shift_cached.cache_clear()
        inc2.two_term_edge_shift(IncompressibleLayer())

    rows.append(("edge correction h(1/2) (I.12), mpmath quadrature", best(edge), "< 0.5 s"))

    ts = inc2.two_term_sphere(BondedLayer(0.499))
    ts.evaluate(0.2, 1000.0, 1.0)
    rows.append(("two-term sphere: radius and force for one depth", best(lambda: ts.evaluate(0.2, 1000.0, 1.0)),
                 "< 20 ms"))

    x = np.random.default_rng(0).uniform(0, 50, 10**6)
    rows.append(("psi, chi (I.11) on 10^6 points", best(lambda: inc2._psi_chi(x)), "< 1 s"))

    pun = Punch.elliptic_paraboloid(2, 1)
    rows.append(("grid obstacle solver, ellipse, 161^2 nodes",
                 best(lambda: grid.solve_obstacle_grid(IncompressibleLayer(), pun, 0.1, 0.1, n=161)), "< 1 s"))
    rows.append(("grid obstacle solver, ellipse, 321^2 nodes",
                 best(lambda: grid.solve_obstacle_grid(IncompressibleLayer(), pun, 0.1, 0.1, n=321), 1), "< 5 s"))

    layer = IncompressibleLayer()
    rows.append(("direct solver at nu = 1/2, sphere, a/H = 40",
                 best(lambda: solve_axisymmetric(layer, lambda r: r * r / 2000.0, 0.4, 1.0), 1), "< 3 s"))
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
