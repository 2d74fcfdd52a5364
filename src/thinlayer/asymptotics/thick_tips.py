r"""Thick layers under any tip of revolution: the series (T.5) seeded by the tip's half-space moments (T.9).

The shape enters (T.5) at order 0 only (:mod:`thinlayer.asymptotics.thick_layer`, (T.9)): Sneddon's half-space
solution of the profile, ``g(x) = x int_0^{pi/2} Phi'(x sin t) dt``, gives

    delta~^(0) = g(c)/c,     M_j^(0) = 4 (2j + 1) B_j c^{-(2j+2)} int_0^c (g(c) - g(x)) x^{2j} dx,

and every higher order is the shape-free response :func:`~thinlayer.asymptotics.thick_layer.seed_response`
weighted by these moments.  For the self-similar tips (cone, power law) the moments are exact numbers and the series
is :func:`~thinlayer.asymptotics.thick_layer.thick_power_law_series`; the exact sphere ``R - sqrt(R^2 - r^2)`` and
the blunted cone depend on ``c/R`` as well, so here the moments are computed per contact radius by Gauss-Legendre
quadrature (panels split at the blunted cone's join, where ``Phi''`` jumps) and the series is summed at that radius:

    delta0(c) = c sum_m eps^m delta~^(m)(c),     P(c) = vartheta c^2 sum_m eps^m M_0^(m)(c),     eps = c/H.

The estimate is (T.8): the last two terms, relative, at least :data:`ROUNDING`; inf from ``eps = 0.9`` on (the series
converges for c < H).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from .._checks import InputError, positive
from ..layers.kernels import LayerKernel
from .thick_layer import EPS_LIMIT, MAX_THICK_ORDER, ThickValues, seed_response

__all__ = ["RadialThickExpansion", "half_space_moments", "radial_thick_expansion"]

#: Gauss-Legendre nodes per panel (in the angle and in x)
_NODES = 64


@lru_cache(maxsize=1)
def _gauss() -> tuple[np.ndarray, np.ndarray]:
    return np.polynomial.legendre.leggauss(_NODES)


def _panels(a: float, b: float, cuts: tuple[float, ...]) -> list[tuple[float, float]]:
    pts = [a, *sorted(v for v in cuts if a < v < b), b]
    return list(zip(pts[:-1], pts[1:]))


def _apex_rule() -> tuple[np.ndarray, np.ndarray]:
    """Nodes and weights on [0, 1] of ``int_0^1 f(y) dy`` with ``y = s^4``: an apex singularity ``y^{n-1}`` of the
    power law becomes ``s^{4n-1}`` (``n = 3/2``: ``s^5``), smooth enough for Gauss-Legendre to rounding.
    """
    t, w = _gauss()
    sv = 0.5 * (t + 1.0)
    return sv**4, 0.5 * w * 4.0 * sv**3


def _g(tip: Any, x: np.ndarray, joins: tuple[float, ...]) -> np.ndarray:
    """``g(x) = x int_0^{pi/2} Phi'(x sin t) dt`` (Sneddon's transform of the profile), vectorised over x; the
    angle is split where ``x sin t`` crosses a join (one join at most: the blunted cone's); the panel at the apex
    by the rule :func:`_apex_rule`.
    """
    t, w = _gauss()
    ya, wa = _apex_rule()
    x = np.asarray(x, dtype=float)
    cut = np.full_like(x, 0.5 * math.pi)
    if joins:
        cut = np.arcsin(np.minimum(1.0, joins[0] / x))
    acc = cut * (tip.radial_slope(x[:, None] * np.sin(cut[:, None] * ya[None, :])) @ wa)
    a, b = cut, np.full_like(x, 0.5 * math.pi)
    th = 0.5 * (b - a)[:, None] * t[None, :] + 0.5 * (a + b)[:, None]
    acc += 0.5 * (b - a) * (tip.radial_slope(x[:, None] * np.sin(th)) @ w)
    return x * acc


def _B(j: int) -> float:
    return 4 ** (j + 1) * math.factorial(j) * math.factorial(j + 1) / (2 * math.factorial(2 * j + 2))


def half_space_moments(tip: Any, c: float, J: int) -> tuple[float, np.ndarray]:
    r"""``(delta~^(0), [M_0^(0) .. M_{J-1}^(0)])`` of the tip at contact radius ``c`` (T.9): depth in units of c,
    moments in units of ``c^{2j+2}`` (``vartheta = 1``).  ``M_0^(0) c^2 vartheta`` is Sneddon's half-space force.
    """
    joins = tuple(float(v) for v in getattr(tip, "radial_breakpoints", ()) or () if 0 < float(v) < c)[:1]
    t, w = _gauss()
    gc = float(_g(tip, np.array([c]), joins)[0])
    ya, wa = _apex_rule()
    xs, ws = [], []
    for a, b in _panels(0.0, c, joins):
        if a == 0.0:  # the apex: g ~ x^n
            xs.append(b * ya)
            ws.append(b * wa)
        else:
            xs.append(0.5 * (b - a) * t + 0.5 * (a + b))
            ws.append(0.5 * (b - a) * w)
    x, wx = np.concatenate(xs), np.concatenate(ws)
    f = (gc - _g(tip, x, joins)) * wx
    M = np.array([4 * (2 * j + 1) * _B(j) * float(np.dot(f, x ** (2 * j))) / c ** (2 * j + 2) for j in range(J)])
    return gc / c, M


@dataclass(frozen=True)
class RadialThickExpansion:
    """The thick-layer series (T.9) of one numeric tip of revolution, summed per contact radius."""

    tip: Any
    order: int

    def terms(self, layer: LayerKernel, c: float, H: float) -> tuple[np.ndarray, np.ndarray]:
        """``(depth terms, force terms)`` at contact radius ``c`` (``vartheta = 1``): ``delta0 = sum``, ``P = sum``."""
        D, P = seed_response(self.order, layer)
        J = D.shape[0]
        d0, M = half_space_moments(self.tip, c, J)
        eps = c / H
        powers = eps ** np.arange(self.order + 1)
        dt = c * (M @ D) * powers
        pt = c * c * (M @ P) * powers
        dt[0] += c * d0
        pt[0] += c * c * M[0]
        return dt, pt

    def evaluate(self, layer: LayerKernel, delta0: float | None, H: float, mu: float, nu: float,
                 force: float | None = None) -> ThickValues:
        """Contact radius and force for a prescribed depth (or the depth for a prescribed force); (T.8) estimate.

        Raises
        ------
        ValueError
            When the contact needs ``c >= 0.9 H`` (the layer is not thick) or reaches the tip's rim.
        """
        from scipy import optimize

        HH = positive(H, "H")
        vt = positive(mu, "mu") / (1.0 - nu)
        top = EPS_LIMIT * HH
        rim = getattr(self.tip, "support_radius", math.inf)
        if math.isfinite(rim):
            top = min(top, 0.9 * rim)
        target, which = (positive(delta0, "delta0"), 0) if force is None else (positive(force, "force") / vt, 1)

        def value(c: float) -> float:
            return float(np.sum(self.terms(layer, c, HH)[which]))

        # the first crossing on a geometric scan upwards (near c = H the truncated series need not be monotone)
        hi = top * 1e-9
        while value(min(hi, top)) < target:
            lo, hi = hi, hi * 2.0
            if lo >= top:
                raise InputError(f"the thick-layer series (T.9) needs a contact radius below {top:.4g} (0.9 H, and "
                                 "0.9 R for a sphere): the layer is not thick here; use the direct solver "
                                 "(model='auto')")
        if hi == top * 1e-9:
            raise InputError("the depth (or force) is below the range of the thick-layer series' scan (c > 1e-9 H)")
        hi = min(hi, top)
        c = optimize.brentq(lambda cc: value(cc) - target, lo, hi, xtol=1e-15 * top, rtol=4e-15)
        dt, pt = self.terms(layer, c, HH)
        d, P = float(np.sum(dt)), float(np.sum(pt))
        eps = c / HH
        ferr = _tail(pt, P, eps)
        derr = _tail(dt, d, eps)
        # the radius follows the depth: d delta0/dc ~ delta0/c (cone) to 2 delta0/c (sphere): at most the depth's tail
        return ThickValues(d, c, vt * P, eps, self.order, ferr + derr, derr)


#: the estimate's floor: rounding of the sums and the quadrature of the moments (measured 1e-15 against the direct
#: solver for the cone, the exact sphere, the blunted cone and r^(3/2))
ROUNDING = 1e-13


def _tail(terms: np.ndarray, total: float, eps: float) -> float:
    if eps >= EPS_LIMIT or not total:
        return math.inf
    return max(float((abs(terms[-1]) + abs(terms[-2])) / abs(total)), ROUNDING)


def radial_thick_expansion(tip: Any, order: int = 16) -> RadialThickExpansion:
    """The thick-layer series (T.9) of a numeric tip of revolution (cone, exact sphere, blunted cone, power law).

    Examples
    --------
    >>> from thinlayer import BondedLayer, Punch
    >>> ex = radial_thick_expansion(Punch.cone(70), order=12)
    >>> v = ex.evaluate(BondedLayer(0.45), 0.01, H=1.0, mu=1.0, nu=0.45)
    >>> round(v.radius / (2 / math.pi * 0.01 * math.tan(math.radians(70))), 4)   # c/c_0 = 1 + (b_0/pi) chi + ...
    1.0092
    """
    if not getattr(tip, "axisymmetric", False) or not hasattr(tip, "radial_slope"):
        raise InputError(f"the thick-layer series (T.9) needs a tip of revolution, got {tip!r}")
    if getattr(tip, "parameters", ()):
        raise InputError(f"the tip's parameters {[str(p) for p in tip.parameters]} need values")
    if isinstance(order, bool) or not isinstance(order, int) or not 2 <= order <= MAX_THICK_ORDER:
        raise InputError(f"order must be an integer in [2, {MAX_THICK_ORDER}], got {order!r}")
    return RadialThickExpansion(tip, order)
