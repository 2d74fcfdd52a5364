"""Timings of the boundary layer (3.15)-(3.25): kernels N, N~, Alexandrov's B, C, h and Q.

``run()`` returns ``(name, seconds, target)`` rows (best of several repetitions); nothing is
computed at import.
"""
from __future__ import annotations

from _timing import best, main


def run() -> list[tuple[str, float, str]]:
    import mpmath
    import numpy as np

    from thinlayer import BondedLayer
    from thinlayer.asymptotics.boundary_layer import (
        alexandrov_kernel,
        alexandrov_kernel_numpy,
        alexandrov_parameters,
        alexandrov_solution,
        boundary_layer_kernel,
    )
    from thinlayer.layers.coefficients import kernel_coefficients

    layer = BondedLayer(0.3)
    sol = alexandrov_solution(layer)
    ts = np.geomspace(1e-3, 30, 1000)
    vs = np.linspace(-1, 20, 10**5)

    def symbolic():
        kernel_coefficients.cache_clear()
        from thinlayer.asymptotics.boundary_layer import _parameters_cached

        _parameters_cached.cache_clear()
        alexandrov_solution(BondedLayer())

    with mpmath.workdps(15):
        rows = [
            ("boundary_layer_kernel N(t=1) (3.17), nu=0.3, dps=15",
             best(lambda: boundary_layer_kernel(layer, 1.0), 2), "< 2 s"),
            ("alexandrov_kernel N~(t=1) laplace route, dps=15",
             best(lambda: alexandrov_kernel(layer, 1.0)), "< 0.2 s"),
            ("alexandrov_kernel_numpy N~ at 1000 points",
             best(lambda: alexandrov_kernel_numpy(layer, ts)), "< 0.05 s"),
            ("alexandrov_parameters + solution, symbolic nu (cold caches)",
             best(symbolic, 2), "< 2 s"),
            ("alexandrov_parameters, float nu (cached)",
             best(lambda: alexandrov_parameters(layer)), "< 1e-4 s"),
            ("AlexandrovSolution.q_numeric at 1e5 points",
             best(lambda: sol.q_numeric(vs)), "< 0.02 s"),
        ]
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
