"""Timings of the viscoelastic force histories (issue 27): the Lee-Radok integral and its front door.

``run()`` returns ``(name, seconds, target)`` rows; nothing runs at import.
Targets (issue 27 item 6): a Lee-Radok force history of 10,000 time steps <= 50 ms; a fit of an approach-retract
curve <= 1 s; the direct time-stepping solver (numerics/viscoelastic) at 200 radial nodes x 1,000 steps <= 30 s.
"""
from __future__ import annotations

import numpy as np
from _timing import best, main


def run() -> list[tuple[str, float, str]]:
    from thinlayer import BondedLayer, PowerLaw, Prony, Punch, StandardLinearSolid, viscoelastic_force
    from thinlayer.contact.hereditary import hereditary_integral

    t = np.linspace(0.0, 2.0, 10_001)
    d = 0.05 * np.minimum(t, 1.0)  # ramp-hold
    F = d**1.5
    prony = Prony(0.5, [(2.0, 0.01), (1.0, 0.1), (0.5, 1.0)])
    rows: list[tuple[str, float, str]] = [
        ("Lee-Radok integral, Prony 3 terms, 10,000 steps", best(lambda: hereditary_integral(prony, t, F), 5),
         "<= 50 ms"),
        ("Lee-Radok integral, power law (FFT), 10,000 steps",
         best(lambda: hereditary_integral(PowerLaw(1.0, 1.0, 0.3), t, F), 5), "<= 50 ms"),
    ]
    tg = 2.0 * (np.arange(10_001) / 10_000) ** 2  # a graded (non-uniform) grid: the Prony blocks
    rows.append(("Lee-Radok integral, Prony 3 terms, 10,000 graded steps",
                 best(lambda: hereditary_integral(prony, tg, 0.05 * tg), 5), "<= 50 ms"))
    layer, tip = BondedLayer(0.3), Punch.paraboloid(10.0)
    viscoelastic_force(layer, tip, 1.0, prony, t[:10], d[:10])  # the law's tables loaded once
    rows.append(("viscoelastic_force sphere, any-thickness law, Prony, 10,000 steps (ramp-hold)",
                 best(lambda: viscoelastic_force(layer, tip, 1.0, prony, t, d), 3), "<= 0.5 s"))
    # a fit of an approach-retract curve (SLS, 1,001 points, 0.3 % noise; the retraction by Ting's method)
    from thinlayer.contact.visco_fit import fit_viscoelastic

    L5, sls = BondedLayer(0.5), StandardLinearSolid(3.0, 1.0, 0.3)
    ta = np.linspace(0.0, 2.0, 1001)
    da = np.where(ta <= 1.0, 0.1 * ta, 0.1 - 0.1 * (ta - 1.0))
    from thinlayer import solve

    Pa = solve(L5, tip, H=1.0, material=sls, history=(ta, da)).force
    Pa = Pa + np.random.default_rng(0).normal(0.0, 0.003 * np.max(Pa), ta.size)
    fit_viscoelastic(L5, tip, 1.0, curves=[(ta, da, Pa)])  # the law's tables loaded once
    rows.append(("fit_viscoelastic SLS, approach-retract (Ting), 1,001 points",
                 best(lambda: fit_viscoelastic(L5, tip, 1.0, curves=[(ta, da, Pa)]), 3), "<= 1 s"))
    # approach-retract on a tip-position axis (z0 = 0.02, baseline 0.05, the approach starts 0.03 above contact), with
    # H free (starting 30 % off) and the contact point and baseline fitted: Lee-Radok on the approach, then Ting
    zt = np.where(ta <= 1.0, 0.05 - 0.13 * ta, -0.08 + 0.13 * (ta - 1.0))
    dz = np.where(ta <= 1.0, np.maximum(0.02 - zt, 0.0), 0.02 - zt)
    Pz = np.nan_to_num(solve(L5, tip, H=1.0, material=sls, history=(ta, dz)).force) + 0.05
    Pz = Pz + np.random.default_rng(1).normal(0.0, 0.003 * np.max(Pz), ta.size)
    rows.append(("fit_viscoelastic SLS, approach-retract (Ting), 1,001 points, H + contact point + baseline free",
                 best(lambda: fit_viscoelastic(L5, tip, 1.3, curves=[(ta, zt, Pz)], fit_H=True, contact_point=True),
                      3), "<= 1 s"))
    rows += _ting_and_direct()
    return rows


def _ting_and_direct() -> list[tuple[str, float, str]]:
    """Ting's method (10,000 steps) and the direct solver (200 nodes x 1,000 steps, one cold call: ~20 s)."""
    from _timing import once

    from thinlayer import BondedLayer, Punch, StandardLinearSolid
    from thinlayer.contact.ting import ting_force
    from thinlayer.numerics.viscoelastic import solve_history

    layer, tip, sls = BondedLayer(0.5), Punch.paraboloid(1.0), StandardLinearSolid(3.0, 1.0, 0.2)
    t = np.linspace(0.0, 1.0, 10_001)
    d = 0.02 * np.minimum(t, 1.0 - t)  # approach-retract, a_max/H ~ 1.5 at H = 0.1
    ting_force(layer, tip, 0.1, sls, t[:10], d[:10])  # the law's tables loaded once
    rows = [("ting_force sphere, bonded layer, SLS, approach-retract, 10,000 steps",
             best(lambda: ting_force(layer, tip, 0.1, sls, t, d), 3), "<= 0.5 s")]
    t2 = np.linspace(0.0, 1.0, 1_000)
    rows.append(("solve_history (direct solver) sphere, bonded layer, SLS, 200 nodes x 1,000 steps",
                 once(lambda: solve_history(layer, tip, 0.1, sls, t2, 0.02 * np.minimum(t2, 1.0 - t2), nodes=200)),
                 "<= 30 s"))
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
