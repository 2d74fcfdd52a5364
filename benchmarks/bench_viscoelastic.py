"""Timings of the viscoelastic force histories (issue 27): the Lee-Radok integral and its front door.

``run()`` returns ``(name, seconds, target)`` rows; nothing runs at import.
Target (issue 27 item 6): a Lee-Radok force history of 10,000 time steps <= 50 ms.
"""
from __future__ import annotations

import numpy as np
from _timing import best, main


def run() -> list[tuple[str, float, str]]:
    from thinlayer import BondedLayer, PowerLaw, Prony, Punch, viscoelastic_force
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
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
