"""Timings of the any-thickness law and of curve fitting (issue 15).

Targets: the sphere's force for 1e6 depths in <= 50 ms (the law of one (nu, base) built once and cached, about
20 ms); a fit of E, H and the contact point to a 1,000-point curve in <= 0.5 s.  ``run()`` returns
``(name, seconds, target)`` rows, best of three calls.
"""
from __future__ import annotations

from _timing import best, main


def run() -> list[tuple[str, float, str]]:
    import numpy as np

    from thinlayer.contact.any_thickness import any_thickness_law, force_any_thickness
    from thinlayer.contact.fit import fit

    rows = []
    rng = np.random.default_rng(1)
    delta = rng.uniform(1e-4, 4.0, 1_000_000)  # chi = sqrt(R delta)/H from 0.003 to 6.3
    for nu, base in ((0.5, "bonded"), (0.3, "bonded"), (0.3, "frictionless")):
        any_thickness_law(nu, base)  # warm: the law of (nu, base) is cached
        rows.append((f"force_any_thickness 1e6 depths nu={nu} {base}",
                     best(lambda nu=nu, base=base: force_any_thickness(delta, 10.0, 1.0, E=1.0, nu=nu, base=base)),
                     "< 0.05 s"))
    from thinlayer.contact.any_thickness import TABLE_PATH, build_law

    with np.load(TABLE_PATH) as f:
        table = {k: f[k] for k in f.files}
    rows.append(("build the law of a new nu (0.4321): moments, spline, estimates",
                 best(lambda: build_law(table, 0.4321, "bonded"), 1), "< 1 s"))
    d = np.linspace(-0.05, 2.0, 1000)
    P = force_any_thickness(d - 0.02, 10.0, 1.5, E=3.0, nu=0.45) + rng.normal(0, 0.01, d.size)
    fit(d, P, punch=10.0, H=1.0, nu=0.45, fit_H=True, fit_offset=True)  # warm the law
    rows.append(("fit E only, 1000 points", best(lambda: fit(d, P, punch=10.0, H=1.5, nu=0.45)), "< 0.5 s"))
    rows.append(("fit E, H and contact point, 1000 points",
                 best(lambda: fit(d, P, punch=10.0, H=1.0, nu=0.45, fit_H=True, fit_offset=True)), "< 0.5 s"))
    return rows


if __name__ == "__main__":
    main(run)
