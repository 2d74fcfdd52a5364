"""Timings of the leading contact contour Gamma_0 (3.1)-(3.14).

``run()`` returns ``(name, seconds, target)`` rows (best of several repetitions); nothing is
computed at import.
"""
from __future__ import annotations

import time


def _best(fn, repeat: int = 5) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def run() -> list[tuple[str, float, str]]:
    import sympy as sp

    from thinlayer.asymptotics.contour import contact_contour
    from thinlayer.symbols import x1, x2

    ellipse = x1**2 / (2 * 4.0) + x2**2 / (2 * 1.0)
    nonsym = x1**2 / 2 + x2**2 + sp.Rational(3, 10) * x1**3 + sp.Rational(1, 5) * x1 * x2 + x1**4 + x2**4
    quartic = (x1**2 + x2**2) / 20 + (x1**2 + x2**2) ** 2 / 125
    contact_contour(ellipse, 0.5)  # warm-up (imports, first FFT plans)
    c = contact_contour(ellipse, 0.5)
    rows = [
        ("contact_contour elliptic paraboloid R1=4, R2=1, delta0=0.5",
         _best(lambda: contact_contour(ellipse, 0.5)), "< 0.05 s"),
        ("contact_contour non-symmetric quartic, delta0=0.05",
         _best(lambda: contact_contour(nonsym, 0.05)), "< 0.2 s"),
        ("contact_contour fourth-degree paraboloid, delta0=0.3",
         _best(lambda: contact_contour(quartic, 0.3)), "< 0.2 s"),
        ("ContactContour.integrate (polynomial, star-shaped)",
         _best(lambda: c.integrate(lambda u, v: u * u + v)), "< 0.01 s"),
        ("ContactContour.rho/b1/b2 at 10^4 points",
         _best(lambda: (c.rho(_grid(c)), c.b1(_grid(c)), c.b2(_grid(c))), 3), "< 0.5 s"),
    ]
    return rows


def _grid(c):
    import numpy as np

    return np.linspace(0.0, c.perimeter, 10_000)


if __name__ == "__main__":  # pragma: no cover
    for name, sec, target in run():
        print(f"{name:60s} {sec * 1e3:9.2f} ms   target {target}")
