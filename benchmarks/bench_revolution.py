"""Timings of the any-thickness laws of the tips of revolution (issue 24 item 3; :mod:`thinlayer.numerics.revolution`,
:mod:`thinlayer.contact.revolution_law`).

Targets (issue 24 item 7): every self-similar axisymmetric-tip law on 1e6 depths in <= 50 ms once built -- the
power-law tip's law (``r^1.5``, bonded nu = 0.45: ``P/P_0`` and ``c/c_0`` with their estimates, one pass) and the
cone's table law (frictionless: the ratios, and the estimates); the builds are timed once, for information.  Both
evaluations are vectorised numpy (no per-point Python, no binary search: uniform grids in log chi, ``np.take``, in
place), bit-identical to the earlier formulas (tests/contact/test_revolution_law.py, test_any_thickness_tips.py).
For the tips whose shape parameters do not scale out (exact sphere, blunted cone) the equation is solved per depth:
the time of one depth (root search in c, estimate and slopes included) at c_0/H = 1, 10 and 25.  Read with ``uptime``.
"""
from __future__ import annotations

import time

from _timing import best, main


def run() -> list[tuple[str, float, str]]:
    import numpy as np

    from thinlayer import BondedLayer, Punch
    from thinlayer.contact.revolution_law import power_law_law
    from thinlayer.numerics.revolution import revolution_contact

    rows = []
    t0 = time.perf_counter()
    law = power_law_law(1.5, 0.45)
    rows.append(("power-law law r^1.5, nu = 0.45: table build (once per nu, base, n)", time.perf_counter() - t0, ""))
    chi = np.random.default_rng(1).uniform(0.01, 29.0, 1_000_000)

    rows.append(("power-law law with estimate, 1e6 depths", best(lambda: law.evaluate(chi), repeat=7), "<= 50 ms"))
    from thinlayer.contact.any_thickness_tips import cone_law

    t0 = time.perf_counter()
    cone = cone_law(0.3, "frictionless")
    rows.append(("cone table law, frictionless: build (once per process)", time.perf_counter() - t0, ""))
    chi_c = np.random.default_rng(2).uniform(0.01, 0.99 * cone.chi_max, 1_000_000)
    rows.append(("cone table law, P/P_0 and c/c_0, 1e6 depths", best(lambda: cone.ratios(chi_c), repeat=7),
                 "<= 50 ms"))
    rows.append(("cone table law, both estimates, 1e6 depths", best(lambda: cone.error_estimate(chi_c), repeat=7),
                 "<= 50 ms"))
    from thinlayer.contact.any_thickness_pyramids import pyramid_law

    pyr = pyramid_law(4, 0.45)
    chi_p = np.random.default_rng(3).uniform(0.0, 10.0, 1_000_000)
    rows.append(("pyramid law (4 sides, nu = 0.45), P/P_hs, 1e6 depths", best(lambda: pyr.ratios(chi_p), repeat=7),
                 "<= 50 ms"))
    lay = BondedLayer(0.45)
    for tip in (Punch.sphere(10), Punch.blunted_cone(1, 70)):
        a = tip.level_set(0.5).half_width
        for c0h in (1.0, 10.0, 25.0):
            H = 0.7 * a / c0h  # c_0 ~ 0.7 a for these tips at delta0 = 0.5
            rows.append((f"{tip.name}, one depth at c0/H ~ {c0h:g} (solve of (F.13) with estimate)",
                         best(lambda t=tip, h=H: revolution_contact(lay, t, 0.5, h), repeat=2), ""))
    return rows


if __name__ == "__main__":
    main(run)
