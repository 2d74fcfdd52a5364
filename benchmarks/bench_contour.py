"""Timings of the leading contact contour Gamma_0 (3.1)-(3.14).

``run()`` returns ``(name, seconds, target)`` rows (best of several repetitions); nothing is
computed at import.
"""
from __future__ import annotations

from _timing import best, main


def run() -> list[tuple[str, float, str]]:
    import sympy as sp

    from thinlayer.asymptotics.contour import contact_contour
    from thinlayer.symbols import x1, x2

    ellipse = x1**2 / (2 * 4.0) + x2**2 / (2 * 1.0)
    nonsym = x1**2 / 2 + x2**2 + sp.Rational(3, 10) * x1**3 + sp.Rational(1, 5) * x1 * x2 + x1**4 + x2**4
    quartic = (x1**2 + x2**2) / 20 + (x1**2 + x2**2) ** 2 / 125
    long_ellipse = sp.Float("1e-30") * x1**2 + sp.Float("1e30") * x2**2  # aspect ratio 1e30
    long_quartic = sp.Float("1e-70") * x1**4 + sp.Float("1e30") * x2**2  # aspect ratio ~3e32
    contact_contour(ellipse, 0.5)  # warm-up (imports, first FFT plans)
    c = contact_contour(ellipse, 0.5)
    cl = contact_contour(long_ellipse, 1.0)
    rows = [
        ("contact_contour elliptic paraboloid R1=4, R2=1, delta0=0.5",
         best(lambda: contact_contour(ellipse, 0.5), 5), "< 0.05 s"),
        ("contact_contour non-symmetric quartic, delta0=0.05",
         best(lambda: contact_contour(nonsym, 0.05), 5), "< 0.2 s"),
        ("contact_contour fourth-degree paraboloid, delta0=0.3",
         best(lambda: contact_contour(quartic, 0.3), 5), "< 0.2 s"),
        ("ContactContour.integrate (polynomial, star-shaped)",
         best(lambda: c.integrate(lambda u, v: u * u + v), 5), "< 0.01 s"),
        ("ContactContour.rho/b1/b2 at 10^4 points",
         best(lambda: (c.rho(_grid(c)), c.b1(_grid(c)), c.b2(_grid(c))), 3), "< 0.5 s"),
        # elongated contours (round frame): about the cost of the round ellipse above
        ("contact_contour ellipse of aspect ratio 1e30, delta0=1",
         best(lambda: contact_contour(long_ellipse, 1.0), 5), "< 0.1 s"),
        ("contact_contour 1e-70 x1^4 + 1e30 x2^2 (aspect ratio 3e32)",
         best(lambda: contact_contour(long_quartic, 1.0), 5), "< 0.1 s"),
        ("ContactContour.rho/b1/b2 at 10^4 points, aspect ratio 1e30",
         best(lambda: (cl.rho(_grid(cl)), cl.b1(_grid(cl)), cl.b2(_grid(cl))), 3), "< 0.5 s"),
        ("ContactContour force-law integrals V, J, aspect ratio 1e30",
         best(lambda: (cl.integrate(lambda u, v: 1.0 - cl.phi(u, v)), cl.boundary_integral(cl.g, of="s")), 5),
         "< 0.05 s"),
    ]
    return rows


def _grid(c):
    import numpy as np

    return np.linspace(0.0, c.perimeter, 10_000)


if __name__ == "__main__":  # pragma: no cover
    main(run)
