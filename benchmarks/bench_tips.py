"""Timings of the tips of revolution through fit() (issue 24 items 6 and 7).

Targets: an axisymmetric-tip law (the cone 70's thin-layer law (1.8) through its level set, with its estimate) on
1e6 depths in <= 50 ms; a warm fit of E to 1,000 points of a cone curve in <= 10 ms.  Also, for information: the
blunted cone's law (no closed form: Newton inversion and Gauss-Legendre volumes) on 1e4 depths, and a fit of E, H
and the contact point.  ``run()`` returns ``(name, seconds, target)`` rows, best of a few calls; the table printed
by ``benchmarks/run.py`` should be read with the machine's load (``uptime``) beside it.
"""
from __future__ import annotations

from _timing import best, main


def run() -> list[tuple[str, float, str]]:
    import math

    import numpy as np

    from thinlayer import BondedLayer, Punch
    from thinlayer.contact.fit import fit
    from thinlayer.contact.models import MODEL_REGISTRY
    from thinlayer.contact.problem import Depth, Elastic, Frictionless, Problem

    entry = next(m for m in MODEL_REGISTRY if m.name == "tip-law")
    rows = []
    rng = np.random.default_rng(1)
    for tip, n, target in ((Punch.cone(70), 1_000_000, "<= 50 ms"), (Punch.sphere(10), 1_000_000, "<= 50 ms"),
                           (Punch.blunted_cone(0.5, 70), 10_000, "")):
        curve = entry.force_curve(Problem(BondedLayer(0.3), tip, Elastic(1.0, 0.3), Frictionless(), Depth(1.0), 0.1,
                                          math.inf))
        d = rng.uniform(0.2, 2.0, n) if tip.kind != "sphere" else rng.uniform(0.05, 1.0, n)
        curve.force(d[:10])  # warm: the law's closed forms compiled once
        rows.append((f"tip law with estimate, {tip.name}, {n:.0e} depths", best(lambda c=curve, d=d: c.force(d)),
                     target))
    d = np.linspace(0.3, 1.2, 1000)
    P = 50 * d**3 * (1 + 0.01 * rng.standard_normal(d.size))
    cone = Punch.cone(70)
    fit(d, P, punch=cone, H=0.2, nu=0.3)  # warm
    rows.append(("warm fit of E, cone 70, 1000 points", best(lambda: fit(d, P, punch=cone, H=0.2, nu=0.3)),
                 "<= 10 ms"))
    rows.append(("fit of E, H and contact point, cone 70, 1000 points",
                 best(lambda: fit(d, P, punch=cone, H=0.2, nu=0.3, fit_H=True, fit_offset=True)), ""))
    return rows


if __name__ == "__main__":
    main(run)
