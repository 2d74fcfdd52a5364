"""Benchmarks of the symbolic core (issue 2 speed targets; issue 18 item 1 for the kernel coefficients).

Kernel coefficients with symbolic nu: the medians of five cold calls (thinlayer's coefficient cache cleared),
side by side with ``sympy.series`` of ``L(s)/s`` to the same order (sympy's cache cleared before each of the
two, once for sympy: it takes seconds).  ``sympy.series`` gives only ``A m_n``, thinlayer also the ``M_k``.
Targets: order <= 10 in <= 15 ms, >= 200x sympy.series at order 8, order 50 in <= 1 s (above the order limit
30 that bounds the stages built on the coefficients: lifted for this row only).
"""
from __future__ import annotations

import numpy as np
from _timing import Row, best, main, median, once


def _coefficient_rows() -> list[Row]:
    import sympy as sp
    from sympy.core.cache import clear_cache

    from thinlayer import BondedLayer, kernel_coefficients
    from thinlayer import symbols as S
    from thinlayer.layers import coefficients as coef

    layer = BondedLayer()

    def coeffs(n, backend=None, cold_sympy=False):
        def f():
            if cold_sympy:
                clear_cache()
            kernel_coefficients.cache_clear()
            c = kernel_coefficients(layer, n, backend=backend)
            assert c.M[n] != 0
        return f

    coeffs(3)()  # imports and the polynomial machinery once
    rows = []
    expr = layer.L(S.s) / S.s
    for n in (4, 6, 8):
        ours = median(coeffs(n, cold_sympy=True), 5)
        peer = once(lambda n=n: (clear_cache(), sp.series(expr, S.s, 0, 2 * n + 1).removeO()))
        rows.append(Row(f"m_n, M_k n <= {n}, symbolic nu (all caches cold)", ours,
                        ">= 200x" if n == 8 else "<= 15 ms", "sympy.series", peer))
    rows.append(Row("m_n, M_k n <= 10, symbolic nu (median of 7)", median(coeffs(10), 7), "<= 15 ms"))
    rows.append(Row("m_n, M_k n <= 30, symbolic nu", median(coeffs(30), 3), "< 5 s"))

    limit = coef.ORDER_LIMITS["poly"]
    coef.ORDER_LIMITS["poly"] = (50, "benchmark")
    try:
        t50 = median(coeffs(50, backend="python"), 3)
        rows.append(Row("m_n, M_k n <= 50, symbolic nu, pure Python", t50, "<= 1 s"))
        try:
            import flint  # noqa: F401
        except ImportError:
            rows.append(Row("m_n, M_k n <= 50, python-flint backend: not installed", float("nan"), "<= 1 s"))
        else:
            rows.append(Row("m_n, M_k n <= 50, symbolic nu, python-flint", median(coeffs(50, backend="flint"), 3),
                            "<= 1 s", "pure Python", t50))
    finally:
        coef.ORDER_LIMITS["poly"] = limit

    def loop(N=30):
        kernel_coefficients.cache_clear()
        for n in range(1, N + 1):
            layer.m(n)
            layer.M(n)

    rows.append(Row("m(n), M(n) for n = 1..30 in a loop (cache by layer)", median(loop, 3), ">= 0.67x",
                    "one call, order 30", median(coeffs(30), 3)))
    return rows


def run() -> list[Row | tuple]:
    from thinlayer import BondedLayer, Punch, inner_pressure, kernel_coefficients

    rows: list[Row | tuple] = _coefficient_rows()
    layer = BondedLayer()
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
