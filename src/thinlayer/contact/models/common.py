"""What several models share: the depth for a given force, the extent of the overlap, FFT sizes."""
from __future__ import annotations

import math
from collections.abc import Callable
from functools import cached_property
from typing import Any

import numpy as np

from ...asymptotics.solution import ValidityError

__all__ = ["LazyExtent", "depth_for_force", "extent_of", "fast_size", "polynomial_reason"]


class LazyExtent:
    """:func:`extent_of` computed on first use (``Indentation.max_pressure`` is the only user)."""

    def __init__(self, punch: Any, delta0: float):
        self.args = (punch, delta0)

    @cached_property
    def value(self) -> float:
        return extent_of(*self.args)


def extent_of(punch: Any, delta0: float) -> float:
    """A half-width of a square that holds {Phi < delta0}: bisection along 16 rays (all at once)."""
    f = punch.profile  # the tip's own vectorised Phi
    t = np.linspace(0, 2 * np.pi, 16, endpoint=False)
    c, s = np.cos(t), np.sin(t)
    hi = np.ones(16)
    with np.errstate(over="ignore", invalid="ignore"):
        for _ in range(1100):  # double until outside (or 1e300)
            inside = (np.asarray(f(hi * c, hi * s), dtype=float) < delta0) & (hi < 1e300)
            if not inside.any():
                break
            hi = np.where(inside, 2.0 * hi, hi)
        lo = np.zeros(16)
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            inside = np.asarray(f(mid * c, mid * s), dtype=float) < delta0
            lo, hi = np.where(inside, mid, lo), np.where(inside, hi, mid)
    return 1.05 * float(hi.max())


def fast_size(n: float) -> int:
    """The smallest 5-smooth integer >= n (fast FFT sizes)."""
    m = max(int(math.ceil(n)), 1)
    while True:
        k = m
        for f in (2, 3, 5):
            while k % f == 0:
                k //= f
        if k == 1:
            return m
        m += 1


def depth_for_force(force_of: Callable[[float], float], target: float, guess: float) -> float:
    """The depth whose force is ``target`` (the force increases with the depth).

    Secant steps on ``log P`` against ``log delta0`` (``P ~ delta0^gamma`` with ``gamma`` between 1 and 3 for
    every model: few steps from a good guess), safeguarded by a bracket and Brent's method.
    """
    from scipy import optimize

    def g(logd):
        P = force_of(math.exp(logd))
        if not (0 < P < math.inf):  # the depth or the force left the double range on the way
            raise ValidityError(f"solve(): no depth found for the force {target:.4g}: at depth {math.exp(logd):.3g} "
                                f"the model's force is {P!r}, outside the double range", "force")
        return math.log(P) - math.log(target)

    x0 = math.log(max(guess, 1e-300))
    g0 = g(x0)
    x1 = x0 - g0 / 2.0  # gamma ~ 2 (a sphere on a thin compressible layer)
    g1 = g(x1)
    pts = [(x0, g0), (x1, g1)]
    for _ in range(12):
        if abs(g1) < 1e-13:
            return math.exp(x1)
        if g1 == g0:
            break
        x0, g0, x1 = x1, g1, x1 - g1 * (x1 - x0) / (g1 - g0)
        g1 = g(x1)
        pts.append((x1, g1))
    lows = [x for x, v in pts if v < 0]
    highs = [x for x, v in pts if v > 0]
    lo = max(lows) if lows else min(x for x, _ in pts) - 1.0
    hi = min(highs) if highs else max(x for x, _ in pts) + 1.0
    for _ in range(100):
        if g(lo) < 0:
            break
        lo -= 2.0
    for _ in range(100):
        if g(hi) > 0:
            break
        hi += 2.0
    if not (g(lo) < 0 < g(hi)):
        raise ValidityError(f"solve(): no depth gives the force {target:.6g}", "force")
    return math.exp(optimize.brentq(g, lo, hi, xtol=1e-14, rtol=1e-13))


def polynomial_reason(tip: Any) -> str | None:
    """None for a polynomial punch; else why a model built on the polynomial inner expansion (2.26)-(3.25) does not
    take this tip, read from the tip's answers (smoothness, inner order), never from its class or name.
    """
    if tip.is_polynomial:
        return None
    order = tip.max_inner_order
    if tip.smoothness == "apex":
        why = (f"the {tip.name} has an apex (Laplacian^{order + 1} Phi not integrable there; inner order {order})"
               if order is not None else f"the {tip.name} has an apex")
    elif order is not None:
        why = f"the {tip.name} is not a polynomial (its inner expansion stops at order {order})"
    else:
        why = f"the {tip.name} is not a polynomial"
    return f"needs a polynomial punch; {why}"
