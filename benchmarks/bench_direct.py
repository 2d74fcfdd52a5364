"""Timings of the direct axisymmetric contact solver (:mod:`thinlayer.numerics.axisymmetric`).

``run()`` returns ``(name, seconds, target)`` rows; nothing runs at import.
"""
from __future__ import annotations

from _timing import main, once


def run() -> list[tuple[str, float, str]]:
    """Time representative solves (with the default coarse-vs-fine error estimate)."""
    from thinlayer import BondedLayer, HalfSpace
    from thinlayer.numerics import contact_for_radius, solve_axisymmetric, surface_displacement

    R, H = 1000.0, 1.0

    def para(r):
        return r**2 / (2 * R)

    rows: list[tuple[str, float, str]] = []
    rows.append(("direct: Hertz, half-space (L = 1)",
                 once(lambda: solve_axisymmetric(HalfSpace(), para, 0.05, H, nu=0.3)), "< 0.1 s"))
    for nu in (0.3, 0.45):
        for cH in (10, 40, 80):
            d0 = cH**2 * H**2 / (2 * R)
            rows.append((f"direct: solve_axisymmetric nu={nu} c/H={cH}",
                         once(lambda d0=d0, nu=nu: solve_axisymmetric(BondedLayer(nu), para, d0, H)),
                         "< 2 s" if cH <= 40 else "< 6 s"))
    rows.append(("direct: contact_for_radius nu=0.45 c/H=40",
                 once(lambda: contact_for_radius(BondedLayer(0.45), para, 40.0, H)), "< 0.5 s"))
    res = solve_axisymmetric(BondedLayer(0.45), para, 0.05, H)
    rows.append(("direct: surface_displacement, 10 radii (check route)",
                 once(lambda: surface_displacement(res, [res.radius * k / 8 for k in range(10)])), "< 5 s"))
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
