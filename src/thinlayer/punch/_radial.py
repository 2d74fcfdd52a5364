r"""What the tips of revolution that are not polynomials share (cone, exact sphere, blunted cone, power law, any
profile ``Phi(r)``): :class:`RadialTip`.

A radial tip is given by its profile ``Phi(r)`` (a sympy expression in :data:`thinlayer.parse.RADIUS`, a
``Piecewise`` where it has pieces), ``Phi(0) = 0``, increasing.  From it, in one place:

* ``expr`` (Phi in ``x1, x2``), the vectorised :meth:`radial_profile`, :meth:`radial_slope` (compiled once per
  profile);
* the level-set integrals of the force law (1.8), (3.25) over the disc ``{Phi < delta0}`` of radius ``a``:
  ``|omega0| = pi a^2``, ``V = 2 pi int_0^a (delta0 - Phi) r dr``, ``|Gamma0| = 2 pi a``,
  ``J = oint |grad Phi| ds = 2 pi a Phi'(a)`` (equal to ``iint Laplacian Phi`` by the divergence theorem when
  ``r Phi'(r) -> 0`` at the apex, as for every profile here) and ``oint (Laplacian Phi + Phi_nn) ds =
  2 pi a (2 Phi''(a) + Phi'(a)/a)``; symbolic where ``Phi(a) = delta0`` solves in closed form
  (:meth:`RadialTip.level_set_expressions`), by quadrature otherwise;
* the order of the inner expansion (2.26) the shape supports, from the singularity of ``Laplacian^k Phi`` at the
  apex (:func:`apex_inner_order`).

Angles are given in degrees (``Punch.cone(70)``: half-angle 70 degrees, ``0 < alpha < 90``), and a symbolic angle
is in degrees too: the symbol ``alpha`` of ``Punch.cone()`` is the half-angle in degrees and every expression converts
it explicitly, ``cot(pi alpha/180)``, so that ``Punch.cone().subs({"alpha": 70})``, ``Punch.cone().expr.subs(alpha,
70)`` and ``Punch.cone(70)`` are one tip (issue 24 item 6: no unit trap between the printed law and its numbers).
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from functools import cached_property, lru_cache
from typing import Any

import numpy as np

from .. import symbols as S
from .._lazy import lazy_module
from ..display import fmt
from ..errors import InputTypeError
from ..normal import normal_latex
from ..parse import RADIUS, parse_number
from .base import LevelSet, PunchError, Tip, points, positive_depth

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it

#: the radius r of a profile Phi(r)
r = RADIUS
#: the half-angle of a cone IN DEGREES when it is left symbolic (expressions use ``pi ALPHA/180``)
ALPHA = sp.Symbol("alpha", positive=True)
#: the most orders of Laplacian^k Phi examined at the apex (:func:`apex_inner_order`)
MAX_APEX_ORDER = 8


def length_value(value: Any, name: str) -> sp.Expr:
    """A positive finite length (number, sympy number or string read by the grammar), or a Symbol ``name`` if None."""
    if value is None:
        return sp.Symbol(name, positive=True)
    if isinstance(value, sp.Symbol):
        return sp.Symbol(value.name, positive=True)
    try:
        v = parse_number(value, f"the {name}")
    except (TypeError, ValueError) as exc:
        raise PunchError(str(exc)) from None
    if not (v > 0 and math.isfinite(float(v))):
        raise PunchError(f"the {name} must be a positive finite number, got {value!r}")
    return v


def angle_value(value: Any, name: str = "half-angle") -> sp.Expr:
    """A half-angle given in DEGREES, ``0 < alpha < 90``, returned in radians (exact ``p pi/180`` for an exact
    input); ``pi alpha/180`` for a symbol (:data:`ALPHA`, in degrees, if None).
    """
    return radians(angle_degrees(value, name))


def radians(degrees: sp.Expr) -> sp.Expr:
    """``pi degrees/180``: the explicit conversion every angle expression carries."""
    return degrees * sp.pi / 180


def angle_degrees(value: Any, name: str = "half-angle") -> sp.Expr:
    """A half-angle in DEGREES, ``0 < alpha < 90``, kept in degrees (a positive Symbol in degrees; :data:`ALPHA`
    if None).  The tip stores this and converts with :func:`radians` in its expressions.
    """
    if value is None:
        return ALPHA
    if isinstance(value, sp.Symbol):
        return sp.Symbol(value.name, positive=True)
    try:
        deg = parse_number(value, f"the {name} (degrees)")
    except (TypeError, ValueError) as exc:
        raise PunchError(str(exc)) from None
    if not (0 < deg < 90):
        raise PunchError(f"the {name} must lie strictly between 0 and 90 degrees (it is given in degrees, "
                         f"e.g. 70), got {value!r}")
    return deg


def laplacian_r(f: sp.Expr) -> sp.Expr:
    """``Laplacian f = (1/r) d/dr (r df/dr)`` of a radial function."""
    return sp.expand(sp.diff(r * sp.diff(f, r), r) / r)


@lru_cache(maxsize=128)
def apex_inner_order(phi: sp.Expr) -> tuple[int | None, bool]:
    r"""``(order, singular)``: the highest k with ``Laplacian^k Phi`` locally integrable at the apex r = 0, and whether
    some ``Laplacian^k Phi`` is unbounded there.

    The inner term ``p_k`` of (2.26) is ``~ H^{2k-1} Laplacian^k (delta0 - Phi)``; the force (1.8) integrates it over
    the contact disc, ``int p_k r dr``, which exists iff ``Laplacian^k Phi = O(r^e)`` with ``e > -2``.  For
    ``Phi ~ C r^n`` (n not an even integer) ``Laplacian^k Phi = C n^2 (n-2)^2 ... (n-2k+2)^2 r^{n-2k}``, so the order
    is the largest k with ``n - 2k > -2``; an even integer n makes the series terminate (order None, unlimited).
    Read off the leading term at r = 0 of the first piece of Phi; examined up to :data:`MAX_APEX_ORDER`, which is
    returned when nothing singular is found before (a lower bound; None only when the series terminates).
    """
    f = phi.args[0][0] if isinstance(phi, sp.Piecewise) else phi
    singular = False
    for k in range(1, MAX_APEX_ORDER + 1):
        f = laplacian_r(f)
        if f == 0:
            return None, singular
        lead = sp.simplify(f).as_leading_term(r)
        _, e = lead.as_coeff_exponent(r)
        if e.is_number and e < 0:
            singular = True
        if e.is_number and e <= -2:
            return k - 1, True
    return MAX_APEX_ORDER, singular


@lru_cache(maxsize=128)
def _compiled(expr: sp.Expr):
    """``(Phi, Phi', Phi'')`` of a numeric profile as numpy functions of r."""
    d1 = sp.diff(expr, r)
    d2 = sp.diff(d1, r)
    return tuple(sp.lambdify(r, e, "numpy") for e in (expr, d1, d2))


@lru_cache(maxsize=256)
def _profile_of(tip: Any):
    """Phi of a numeric tip compiled from its ``numeric_expr``, per tip (a subclass builds the expression anew at
    each access).
    """
    return _compiled(tip.numeric_expr)[0]


@lru_cache(maxsize=256)
def _derivatives_of(tip: Any) -> tuple:
    """``(Phi, Phi', Phi'')`` of a numeric tip compiled from its ``radial_expr``, per tip."""
    return _compiled(tip.radial_expr)


def _evaluate(fn, rr: np.ndarray) -> np.ndarray:
    with np.errstate(all="ignore"):  # the branches a Piecewise discards may be nan
        out = np.asarray(fn(rr), dtype=float)
    return np.broadcast_to(out, rr.shape).copy()


class RadialTip(Tip):
    """A tip of revolution ``x3 = -Phi(r)`` that is not a polynomial (module docstring).  Subclasses give
    ``name``, ``kind``, ``radial_expr`` (the exact profile), ``_rebuild(values)`` and the tip's own answers
    (smoothness, level set in closed form, ...).
    """

    __slots__ = ()

    #: the order in which the parameters are shown and passed to :meth:`_rebuild`
    values: tuple

    # ---- identity and parameters ---------------------------------------------------------------
    @property
    def radial_expr(self) -> sp.Expr:  # pragma: no cover - every subclass defines it
        raise NotImplementedError

    @property
    def numeric_expr(self) -> sp.Expr:
        """The profile as it is evaluated in floats (a subclass may give a cancellation-free form)."""
        return self.radial_expr

    @property
    def axisymmetric(self) -> bool:
        """True: Phi depends on ``r`` only."""
        return True

    @property
    def expr(self) -> sp.Expr:
        """Phi in ``x1, x2``: the profile at ``r = sqrt(x1^2 + x2^2)``."""
        return self.radial_expr.xreplace({r: sp.sqrt(S.x1**2 + S.x2**2)})

    @cached_property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """The free symbols of Phi other than r, sorted by name (kept on the immutable tip: every numeric method asks
        for it, and a subclass builds ``radial_expr`` anew at each access).
        """
        return tuple(sorted(self.radial_expr.free_symbols - {r}, key=lambda q: q.name))

    @property
    def description(self) -> str:
        """One phrase for result summaries."""
        return f"{self.name} Phi(r) = {self.radial_expr}"

    def subs(self, values: Mapping) -> RadialTip:
        """A new tip with symbolic parameters replaced (lengths as numbers, angles in degrees; strings read by the
        restricted grammar, never evaluated).
        """
        if not isinstance(values, Mapping):
            raise InputTypeError(f"the tip's parameter values must be a dict, got {type(values).__name__}")
        if not values:
            return self
        names = {q.name for q in self.parameters}
        current = dict(self.values)
        for k, v in values.items():
            key = k.name if isinstance(k, sp.Symbol) else k
            if key not in names:
                raise PunchError(f"{k!r} is not a parameter of the {self.name}; its parameters are "
                                 f"{', '.join(sorted(names)) or 'none'}")
            slot = next(s for s, val in current.items() if isinstance(val, sp.Symbol) and val.name == key)
            current[slot] = v
        return self._rebuild(current)

    def _rebuild(self, values: dict) -> RadialTip:  # pragma: no cover - every subclass defines it
        raise NotImplementedError

    def _need_numbers(self, what: str) -> None:
        if not self.is_numeric:
            raise PunchError(f"{what} needs numbers for the parameters {', '.join(q.name for q in self.parameters)} "
                             f"of the {self.name}: use .subs({{...}})")

    # ---- numbers ---------------------------------------------------------------------------------
    def radial_profile(self, rr: Any) -> np.ndarray:
        """``Phi(|r|)`` (numpy, vectorised), ``+inf`` where the tip is absent."""
        self._need_numbers("its profile")
        rr = np.abs(points(rr, "r"))
        return _evaluate(_profile_of(self), rr)

    def radial_slope(self, rr: Any) -> np.ndarray:
        """``dPhi/dr`` at ``|r|`` (numpy, vectorised)."""
        self._need_numbers("its slope")
        rr = np.abs(points(rr, "r"))
        return _evaluate(_derivatives_of(self)[1], rr)

    def radial_curvature(self, rr: Any) -> np.ndarray:
        """``d^2 Phi/dr^2`` at ``|r|`` (numpy, vectorised; the one-sided value at a join)."""
        self._need_numbers("its curvature")
        rr = np.abs(points(rr, "r"))
        return _evaluate(_derivatives_of(self)[2], rr)

    def profile(self, x1: Any, x2: Any) -> np.ndarray:
        """Phi at the points ``(x1, x2)`` (numpy, broadcast): the profile at ``hypot(x1, x2)``."""
        return self.radial_profile(np.hypot(points(x1, "x1"), points(x2, "x2")))

    # ---- shape -------------------------------------------------------------------------------------
    @property
    def max_inner_order(self) -> int | None:
        """From the apex (:func:`apex_inner_order`)."""
        return apex_inner_order(self.radial_expr)[0]

    @property
    def smoothness(self) -> str:
        """``"apex"`` when some ``Laplacian^k Phi`` is unbounded at r = 0, else ``"smooth"``."""
        return "apex" if apex_inner_order(self.radial_expr)[1] else "smooth"

    @property
    def rim_depth(self) -> float:
        """``Phi`` at the rim :attr:`support_radius` (``inf`` without a rim): the deepest depth with a level set.
        Read just inside the rim when the rim itself rounds out of the profile's domain (the exact sphere with a
        float ``R``: ``R^2 - r^2`` rounds below zero at ``r = R``).
        """
        rim = self.support_radius
        if not math.isfinite(rim):
            return math.inf
        top = float(self.radial_profile(np.array([rim]))[0])
        return top if math.isfinite(top) else float(self.radial_profile(np.array([rim * (1 - 4e-16)]))[0])

    # ---- level set -----------------------------------------------------------------------------------
    def contact_radius_expr(self) -> sp.Expr | None:
        """The radius ``a(delta0)`` of ``{Phi < delta0}`` in closed form, or None (then by root finding)."""
        return None

    def level_set_expressions(self) -> dict[str, sp.Expr] | None:
        r"""The level-set integrals as sympy expressions in ``thinlayer.symbols.delta0`` (and the tip's parameters),
        derived from the profile: ``radius`` a (:meth:`contact_radius_expr`), ``area`` ``pi a^2``,
        ``volume`` ``2 pi int_0^a (delta0 - Phi) r dr``, ``perimeter`` ``2 pi a``, ``flux`` ``2 pi a Phi'(a)``;
        None without a closed-form radius.
        """
        a = self.contact_radius_expr()
        if a is None:
            return None
        return _level_set_expressions(self.radial_expr, a)

    def level_set(self, delta0: Any) -> LevelSet:
        """The level-set integrals at a depth: closed forms where :meth:`level_set_expressions` has them, else the
        radius by Brent's method on ``Phi(a) = delta0`` and the volume by adaptive quadrature (split at the joins).
        """
        self._need_numbers("its level set")
        d = positive_depth(delta0)
        rim = self.support_radius
        if math.isfinite(rim) and not d < self.rim_depth:
            raise PunchError(f"the depth delta0 = {d:g} reaches the rim of the {self.name} (r = "
                             f"{self.support_radius:g}): its level set needs delta0 below Phi there")
        exprs = self.level_set_expressions()
        if exprs is not None:
            v = {k: float(e.subs(S.delta0, d)) for k, e in exprs.items()}
            a = v["radius"]
            slope = v["flux"] / (2 * math.pi * a)
            second = 2 * math.pi * a * (2 * float(self.radial_curvature(np.array([a]))[0]) + slope / a)
            return LevelSet(v["area"], v["volume"], v["perimeter"], v["flux"], a, a, second)
        from scipy import integrate  # lazy: importing thinlayer.punch loads no scipy

        a = self._radius_by_root(d)
        pts = [b for b in self.radial_breakpoints if 0 < b < a]
        vol, _ = integrate.quad(lambda s: 2 * math.pi * s * (d - float(self.radial_profile(np.array([s]))[0])),
                                0.0, a, points=pts or None, limit=200, epsabs=0, epsrel=1e-13)
        slope = float(self.radial_slope(np.array([a]))[0])
        flux = 2 * math.pi * a * slope
        second = 2 * math.pi * a * (2 * float(self.radial_curvature(np.array([a]))[0]) + slope / a)
        return LevelSet(math.pi * a * a, vol, 2 * math.pi * a, flux, a, a, second)

    def _radius_by_root(self, d: float) -> float:
        from scipy import optimize  # lazy: importing thinlayer.punch loads no scipy

        hi = min(1.0, 0.5 * self.support_radius)
        for _ in range(2200):
            if float(self.radial_profile(np.array([hi]))[0]) > d:
                break
            hi *= 2.0
        else:
            raise PunchError(f"the profile of the {self.name} never reaches delta0 = {d:g}")
        return float(optimize.brentq(lambda s: float(self.radial_profile(np.array([s]))[0]) - d, 0.0, hi,
                                     xtol=1e-15 * hi, rtol=1e-15, maxiter=300))

    # ---- display ------------------------------------------------------------------------------------
    def latex(self) -> str:
        return rf"\Phi(r) = {normal_latex(self.radial_expr)} \tag{{{self.equation}}}"

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """``Phi(r, *parameters)`` as the one output."""
        return (r, *self.parameters), {"Phi": self.radial_expr}

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        pars = ", ".join(q.name for q in self.parameters) or "none"
        try:
            order = self.max_inner_order
            shape = f"smoothness {self.smoothness}, inner order {'unlimited' if order is None else order}"
        except PunchError:  # a symbolic exponent
            shape = "smoothness and inner order need numbers"
        return [f"{type(self).__name__} ({self.name}): Φ(r) = {fmt(self.radial_expr)}",
                f"  {shape}, parameters: {pars}"]


@lru_cache(maxsize=128)
def _level_set_expressions(phi: sp.Expr, a: sp.Expr) -> dict[str, sp.Expr]:
    piece = phi.args[0][0] if isinstance(phi, sp.Piecewise) else phi
    s = sp.Symbol("s", positive=True)
    # the level set is the disc r < a: Phi below delta0 on it (the first piece of a Piecewise covers it)
    V = sp.simplify(2 * sp.pi * sp.integrate((S.delta0 - piece.xreplace({r: s})) * s, (s, 0, a)))
    slope = sp.diff(piece, r).xreplace({r: a})
    return {"radius": a, "area": sp.pi * a**2, "volume": V, "perimeter": 2 * sp.pi * a,
            "flux": sp.simplify(2 * sp.pi * a * slope)}


def check_profile(tip: RadialTip) -> None:
    """Refuse a numeric profile that is not ``Phi(0) = 0`` and increasing on a sample (one line naming it)."""
    if not tip.is_numeric:
        return
    R = tip.support_radius
    top = 0.999 * R if math.isfinite(R) else 1e3
    rr = np.concatenate([[0.0], np.geomspace(1e-6 * min(top, 1.0), top, 400)])
    phi = tip.radial_profile(rr)
    if not abs(phi[0]) <= 1e-14 * max(1.0, float(np.max(np.abs(phi[np.isfinite(phi)])))):
        raise PunchError(f"the profile of the {tip.name} must vanish at r = 0 (the apex touches first), got "
                         f"Phi(0) = {phi[0]:g}")
    if not (np.all(np.isfinite(phi)) and np.all(np.diff(phi) > 0)):
        bad = int(np.argmax(~(np.isfinite(phi[1:]) & (np.diff(phi) > 0))))
        raise PunchError(f"the profile of the {tip.name} must be finite and increasing for r > 0; it is not near "
                         f"r = {rr[bad + 1]:.4g}")


__all__ = ["ALPHA", "RadialTip", "angle_degrees", "angle_value", "apex_inner_order", "check_profile", "laplacian_r",
           "length_value", "r", "radians"]
