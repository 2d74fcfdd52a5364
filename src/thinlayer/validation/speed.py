r"""Speed of the asymptotic force against the direct solvers at equal accuracy (issue 4; sphere, a_0 = 1).

The asymptotic force ``P_0 + P_1`` (1.8) has a relative error ``O((H/a)^3)``; each direct solver is
run at the cheapest resolution of a ladder whose force error is no larger, and the times compared.
"""
from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from .._checks import check_int
from .cases import DELTA0, SPHERE_R, bonded_layer, check_nu, check_ratio

__all__ = ["SpeedComparison", "speed_comparison"]


@dataclass(frozen=True)
class SpeedComparison:
    """Time of the asymptotic force against direct numerics tuned to the same accuracy (sphere).

    ``asymptotic_error`` is the relative error of ``P_0 + P_1`` against the converged axisymmetric
    force; each numerical method is run at the cheapest resolution of a ladder whose force error is
    no larger (None when no rung reaches it); ``fft2d_coarsest`` says that the 2D grid is the coarsest
    the solver accepts (Delta = H/5), whose error may be well below the target.  Times are the best of
    ``repeat`` runs.
    """

    nu: float
    H_over_a: float
    force_reference: float
    asymptotic_error: float
    seconds_solve: float
    seconds_force_law: float
    fft2d_n: int | None
    fft2d_error: float | None
    seconds_fft2d: float | None
    fft2d_coarsest: bool
    axisymmetric_modes: int | None
    axisymmetric_error: float | None
    seconds_axisymmetric: float | None

    @property
    def ratio_fft2d(self) -> float | None:
        """``t(solve_2d) / t(thinlayer.solve)`` at equal force accuracy."""
        return None if self.seconds_fft2d is None else self.seconds_fft2d / self.seconds_solve

    @property
    def ratio_axisymmetric(self) -> float | None:
        return None if self.seconds_axisymmetric is None else self.seconds_axisymmetric / self.seconds_solve

    @property
    def ratio_fft2d_law(self) -> float | None:
        """``t(solve_2d) / t(force law)``: the lambdified closed form (1.8) alone."""
        return None if self.seconds_fft2d is None else self.seconds_fft2d / self.seconds_force_law


def _best(fn: Callable[[], Any], repeat: int) -> tuple[float, Any]:
    best, out = float("inf"), None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best, out


def speed_comparison(nu: float = 0.3, H_over_a: float = 0.1, *, repeat: int = 3, max_n: int = 1024,
                     workers: int | None = None) -> SpeedComparison:
    """Speed of the asymptotic force (1.8) against the direct solvers at equal accuracy (sphere, a_0 = 1).

    The 2D solver's ladder starts at its coarsest admissible grid (Delta = H/5) and grows by ~25 %
    up to ``max_n``; the axisymmetric ladder adds two modes at a time from 4.  The asymptotic time is
    :func:`thinlayer.solve` (everything: force, area, edge shifts) and, separately, one call of the
    lambdified force law.

    Parameters
    ----------
    nu : float
        Poisson ratio, -1 < nu < 1/2.
    H_over_a : float
        Thickness ratio in [0.0125, 0.2].
    repeat : int
        Runs per timing (the best is kept), at least 1.
    max_n : int
        The largest 2D grid tried.
    workers : int, optional
        FFT threads of the 2D solver.

    Returns
    -------
    SpeedComparison
    """
    from ..asymptotics.force_law import force_law
    from ..asymptotics.solution import compressible_solution as solve
    from ..numerics import solve_axisymmetric
    from ..punch import Punch

    v, eps = check_nu(nu), check_ratio(H_over_a)
    repeat = check_int(repeat, "repeat", 1)
    layer, punch = bonded_layer(v), Punch.paraboloid(R=SPHERE_R)
    H = eps * math.sqrt(2 * SPHERE_R * DELTA0)
    ref = solve_axisymmetric(layer, punch, DELTA0, H)
    sol = solve(layer, punch, delta0=DELTA0, H=H)  # warm the caches (edge shifts, force law)
    err = abs(sol.force / ref.force - 1.0)
    t_solve, _ = _best(lambda: solve(layer, punch, delta0=DELTA0, H=H, tol=math.inf), max(repeat, 5))
    f = force_law(layer, punch).lambdify()
    h = sol.edge_shift
    f(DELTA0, H, 1.0, h)
    calls = 2000
    t_law, _ = _best(lambda: [f(DELTA0, H, 1.0, h) for _ in range(calls)], repeat)
    t_law /= calls
    n2, e2, t2, coarsest = _fft2d_ladder(layer, punch, H, ref.force, err, repeat, max_n, workers)
    ma, ea, ta = _axisymmetric_ladder(layer, punch, H, ref.force, err, repeat)
    return SpeedComparison(v, eps, ref.force, err, t_solve, t_law, n2, e2, t2, coarsest, ma, ea, ta)


def _fft2d_ladder(layer: Any, punch: Any, H: float, force: float, err: float, repeat: int, max_n: int,
                  workers: int | None) -> tuple[int | None, float | None, float | None, bool]:
    """The coarsest 2D grid whose force error is at most ``err``: ``(n, error, seconds, coarsest)``."""
    from ..numerics import solve_2d

    W = 0.54 * 2.0 + min(2.0 * H, 0.3)  # solve_2d's default square for this punch
    n = 16 * math.ceil(2 * W * 5.0 / H / 16.0)
    first = n
    tol = min(1e-8, err / 100.0)
    while n <= max_n:
        r = solve_2d(layer, punch, delta0=DELTA0, H=H, n=n, tol=tol, workers=workers)
        e = abs(r.force / force - 1.0)
        if e <= err:
            t, _ = _best(lambda n=n: solve_2d(layer, punch, delta0=DELTA0, H=H, n=n, tol=tol, workers=workers),
                         repeat if n <= 512 else 1)
            return n, e, t, n == first
        n = 16 * math.ceil(1.25 * n / 16.0)
    return None, None, None, False


def _axisymmetric_ladder(layer: Any, punch: Any, H: float, force: float, err: float, repeat: int
                         ) -> tuple[int | None, float | None, float | None]:
    """The fewest axisymmetric modes whose force error is at most ``err``: ``(modes, error, seconds)``."""
    from ..numerics import solve_axisymmetric

    for modes in range(4, 200, 2):
        try:
            r = solve_axisymmetric(layer, punch, DELTA0, H, n=modes, error_estimate=False)
        except ValueError:
            continue
        e = abs(r.force / force - 1.0)
        if e <= err:
            t, _ = _best(lambda m=modes: solve_axisymmetric(layer, punch, DELTA0, H, n=m, error_estimate=False),
                         repeat)
            return modes, e, t
    return None, None, None
