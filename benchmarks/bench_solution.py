"""Timings of the contact solution (thinlayer.asymptotics.solution, force_law, composite).

``run()`` returns ``(name, seconds, target)`` rows (best of a few repetitions where the call is
repeatable); nothing runs at import.  Targets (issue 3): ``solve`` for an elliptic paraboloid
with numeric parameters under 0.2 s; the composite pressure on 10^6 points within 0.1 s (issue 18).
"""
from __future__ import annotations

from _timing import best, main, median, timed


def run() -> list[tuple[str, float, str]]:
    import numpy as np

    from thinlayer import BondedLayer, Punch
    from thinlayer.asymptotics.solution import _edge_shifts
    from thinlayer.asymptotics.solution import compressible_solution as solve
    from thinlayer.layers.coefficients import kernel_coefficients

    punch = Punch.elliptic_paraboloid(4, 1)
    rows = []

    # cold: a Poisson ratio not seen before (edge shift, coefficients and symbolic law computed)
    def cold(nu=[0.21]):
        nu[0] += 0.001
        kernel_coefficients.cache_clear()
        _edge_shifts.cache_clear()
        solve(BondedLayer(round(nu[0], 6)), punch, delta0=0.5, H=0.05)

    cold()  # imports
    rows.append(("solve(elliptic paraboloid), fresh nu (cold caches)", best(cold), "< 0.2 s"))
    layer = BondedLayer(0.3)
    solve(layer, punch, delta0=0.5, H=0.05)
    rows.append(("solve(elliptic paraboloid), same nu, new delta0, H",
                 best(lambda: solve(layer, punch, delta0=0.4, H=0.04)), "< 0.2 s"))
    rows.append(("solve(elliptic paraboloid, force=P) inverse problem",
                 best(lambda: solve(layer, punch, force=20.0, H=0.04)), "< 0.2 s"))
    quartic = Punch.fourth_degree(1, 1)
    rows.append(("solve(fourth-degree paraboloid) (numeric contour)",
                 best(lambda: solve(layer, quartic, delta0=0.5, H=0.05)), "< 0.5 s"))
    rows.append(("solve(fourth-degree paraboloid, force=P) inverse (Brent)",
                 best(lambda: solve(layer, quartic, force=20.0, H=0.05), 1), "< 2 s"))

    sol = solve(layer, punch, delta0=0.5, H=0.05)
    secs, comp = timed(lambda: sol.composite)
    rows.append(("composite pressure build, exact boundary layer (first use per nu)", secs, "< 10 s"))
    rng = np.random.default_rng(0)
    x1 = rng.uniform(-2.1, 2.1, 10**6)
    x2 = rng.uniform(-1.05, 1.05, 10**6)
    comp(x1, x2)
    rows.append(("composite pressure on 10^6 points (box around the ellipse, median of 7)",
                 median(lambda: comp(x1, x2), 7), "<= 0.1 s"))
    alex = solve(layer, punch, delta0=0.5, H=0.05, boundary_layer="alexandrov").composite
    alex(x1, x2)
    rows.append(("composite pressure on 10^6 points, Alexandrov boundary layer (median of 7)",
                 median(lambda: alex(x1, x2), 7), "<= 0.1 s"))
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
