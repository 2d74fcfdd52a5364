"""What several models share: the tip's shape, the depth for a given force, the extent of the overlap."""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property, lru_cache
from typing import Any

import numpy as np
import sympy as sp

from ... import symbols as S
from ...asymptotics.solution import ValidityError
from ...punch import FlatPunch

__all__ = ["LazyExtent", "TipShape", "depth_for_force", "extent_of", "fast_size", "phi_numpy", "tip_shape"]


@dataclass(frozen=True)
class TipShape:
    """What the models need to know of a numeric tip."""

    axisymmetric: bool
    quadric: tuple[float, float, float] | None  # (1/R1, 1/R2, angle) for Phi = x.Hx/2 (principal curvatures)
    fixed_contact: bool = False

    @property
    def sphere(self) -> bool:
        return self.quadric is not None and math.isclose(self.quadric[0], self.quadric[1], rel_tol=1e-12)


@lru_cache(maxsize=256)
def tip_shape(punch: Any) -> TipShape:
    """The shape of a numeric tip (cached per tip)."""
    if isinstance(punch, FlatPunch):
        return TipShape(True, None, True)
    e = sp.expand(punch.expr)
    axi = sp.expand(S.x1 * sp.diff(e, S.x2) - S.x2 * sp.diff(e, S.x1)) == 0
    poly = sp.Poly(e, S.x1, S.x2)
    quad = None
    if poly.total_degree() == 2 and all(sum(m) == 2 for m in poly.monoms()):
        a11 = float(poly.coeff_monomial(S.x1**2)) * 2
        a22 = float(poly.coeff_monomial(S.x2**2)) * 2
        a12 = float(poly.coeff_monomial(S.x1 * S.x2))
        lam, vec = np.linalg.eigh(np.array([[a11, a12], [a12, a22]]))
        if lam.min() > 0:
            quad = (float(lam[0]), float(lam[1]), float(math.atan2(vec[1, 0], vec[0, 0])))
    return TipShape(bool(axi), quad)


@lru_cache(maxsize=256)
def phi_numpy(punch: Any) -> Callable:
    """``Phi(x1, x2)`` compiled for numpy (cached per tip)."""
    return sp.lambdify((S.x1, S.x2), punch.expr, "numpy")


class LazyExtent:
    """:func:`extent_of` computed on first use (``Indentation.max_pressure`` is the only user)."""

    def __init__(self, punch: Any, delta0: float):
        self.args = (punch, delta0)

    @cached_property
    def value(self) -> float:
        return extent_of(*self.args)


def extent_of(punch: Any, delta0: float) -> float:
    """A half-width of a square that holds {Phi < delta0}: bisection along 16 rays (all at once)."""
    f = phi_numpy(punch)
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
