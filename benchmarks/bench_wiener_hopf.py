"""Timings of the Wiener--Hopf edge shift and boundary layer (thinlayer.asymptotics.wiener_hopf).

``run()`` returns ``(name, seconds, target)`` rows; nothing runs at import.
Targets: ``h_exact`` to 8 digits in under 1 s per nu (fresh nu, no cache).
"""
from __future__ import annotations

from _timing import main, once


def run() -> list[tuple[str, float, str]]:
    from thinlayer.asymptotics.wiener_hopf import (
        _layer,
        _solution,
        boundary_layer_exact,
        edge_shift_alexandrov,
        edge_shift_exact,
    )

    rows: list[tuple[str, float, str]] = []
    for nu in (-0.5, 0.0, 0.3, 0.45, 0.49, 0.4999):
        # dps=16 gives ~1e-14 (far beyond 8 digits); the default dps=20 is shown too
        rows.append((f"edge_shift_exact(nu={nu}, dps=16)", once(edge_shift_exact, nu, dps=16), "< 1 s"))
        rows.append((f"edge_shift_exact(nu={nu}, dps=20)", once(edge_shift_exact, nu, dps=20), "< 1 s"))
    rows.append(("edge_shift_alexandrov(0.3)", once(edge_shift_alexandrov, 0.3), "< 10 ms"))
    _solution.cache_clear()
    _layer.cache_clear()
    rows.append(("boundary_layer_exact(0.3) (table build)", once(boundary_layer_exact, 0.3), "< 10 s"))
    sol = boundary_layer_exact(0.3)
    rows.append(("WienerHopfSolution.q(2.0) mpmath, panel rule (first call builds rule)",
                 once(sol.q, 2.0), "< 3 s"))
    rows.append(("WienerHopfSolution.q(3.0) mpmath, panel rule", once(sol.q, 3.0), "< 2 s"))

    import numpy as np

    tau = np.linspace(0, 50, 100_000)
    rows.append(("WienerHopfSolution.q_numpy(1e5 points)", once(sol.q_numpy, tau), "< 50 ms"))
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
