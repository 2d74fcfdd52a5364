"""Timings of the flat-ended punch: exact stiffness, thin and thick asymptotics, the front door.

``run()`` returns ``(name, seconds, target)`` rows; nothing runs at import.
Targets (issue 14): the exact kappa to 1e-5 in under 1 s for a/H <= 20; the asymptotic forms in microseconds
once their coefficients are cached (computed once per Poisson ratio).
"""
from __future__ import annotations

import numpy as np
from _timing import best, main, once


def run() -> list[tuple[str, float, str]]:
    from thinlayer import BondedLayer, FrictionlessLayer
    from thinlayer.asymptotics.flat_punch import _thick, _thin, thick_flat_punch, thin_flat_punch
    from thinlayer.contact.flat_punch import flat_punch_stiffness
    from thinlayer.layers.kernels import IncompressibleLayer
    from thinlayer.numerics.flat_punch import _t_rule, flat_punch_kappa

    rows: list[tuple[str, float, str]] = []
    for layer in (BondedLayer(0.3), IncompressibleLayer()):
        for lam in (0.05, 1.0, 5.0, 20.0, 50.0, 200.0):
            _t_rule.cache_clear()
            rows.append((f"flat exact kappa {layer}, a/H={lam:g}",
                         once(flat_punch_kappa, layer, lam), "< 1 s" if lam <= 20 else "< 2 s"))
    rows.append(("flat exact kappa, Nystrom route, nu=0.3, a/H=20",
                 once(flat_punch_kappa, BondedLayer(0.3), 20.0, method="nystrom"), "< 2 s"))
    for layer in (BondedLayer(0.3), BondedLayer(0.45), IncompressibleLayer(), FrictionlessLayer()):
        _thin.cache_clear()
        rows.append((f"flat thin, first call (edge shifts) {layer}", once(thin_flat_punch, layer), "< 3 s"))
        th = thin_flat_punch(layer)
        rows.append((f"flat thin, one value (cached) {layer}", best(lambda th=th: th(30.0), 200), "< 100 us"))
    th = thin_flat_punch(BondedLayer(0.3))
    x = np.linspace(5.0, 100.0, 1_000_000)
    rows.append(("flat thin, 1e6 values, nu=0.3 (Bessel ratios)", best(lambda: th(x), 3), "< 0.5 s"))
    _thick.cache_clear()
    rows.append(("flat thick, first call (moments), nu=0.3, order 12",
                 once(thick_flat_punch, BondedLayer(0.3)), "< 1 s"))
    tk = thick_flat_punch(BondedLayer(0.3))
    rows.append(("flat thick, one value (cached), nu=0.3", best(lambda: tk(0.3), 200), "< 100 us"))
    rows.append(("flat_punch_stiffness(..., 'thin'), one value",
                 best(lambda: flat_punch_stiffness(BondedLayer(0.3), 30.0, "thin"), 200), "< 1 ms"))
    rows.append(("flat_punch_stiffness(..., 'auto'), 5 values",
                 best(lambda: flat_punch_stiffness(BondedLayer(0.3), [0.1, 1.0, 2.0, 30.0, 500.0], "auto"), 3),
                 "< 0.1 s"))
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
