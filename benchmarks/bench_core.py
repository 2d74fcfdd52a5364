"""Benchmarks of the symbolic core (issue 2 speed targets)."""
from __future__ import annotations

import numpy as np
from _timing import best, main


def run() -> list[tuple[str, float, str]]:
    from thinlayer import BondedLayer, Punch, inner_pressure, kernel_coefficients

    rows = []
    layer = BondedLayer()

    def coeffs(n):
        def f():
            kernel_coefficients.cache_clear()
            c = kernel_coefficients(layer, n)
            assert c.M[n] != 0
        return f

    coeffs(3)()  # warm the polynomial machinery once
    rows.append(("m_n, M_k for n <= 10, symbolic nu", best(coeffs(10)), "< 0.1 s"))
    rows.append(("m_n, M_k for n <= 30, symbolic nu", best(coeffs(30), 1), "< 5 s"))

    punch = Punch.general(12)
    kernel_coefficients(layer, 6)
    rows.append(("inner expansion, degree-12 punch, symbolic coefficients",
                 best(lambda: inner_pressure(layer, punch)), "< 1 s"))

    ip = inner_pressure(BondedLayer(0.3), Punch.elliptic_paraboloid(R1=2.0, R2=1.0))
    f = ip.lambdify()
    x = np.random.default_rng(0).uniform(-1, 1, 10**6)
    y = np.random.default_rng(1).uniform(-1, 1, 10**6)
    f(x, y, 0.1, 0.05, 1.0)
    rows.append(("lambdified inner pressure on 10^6 points", best(lambda: f(x, y, 0.1, 0.05, 1.0)), "< 50 ms"))
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
