r"""Adhesive (JKR) answers of :func:`thinlayer.solve` (issue 26 item 5): force, contact radius and depth.

``solve(..., work_of_adhesion=w)`` walks the adhesive rows of the model registry
(:mod:`thinlayer.contact.models.adhesion`): the thin-layer JKR law (J.11)/(J.15) of
:mod:`thinlayer.asymptotics.adhesion` where its error estimate is within ``tol``, else the direct JKR solver
(J.1)-(J.6) of :mod:`thinlayer.numerics.adhesion`.  For the flat-ended cylinder (Kendall) the direct solver answers
(J.13).

*Which state.*  At a given depth (displacement control) the JKR curve ``delta(c)`` has, for
``delta_min < delta < 0``, two states: the **stable** one (``d delta/dc > 0``, the larger radius) and the
**unstable** one.  At a given force (load control) the same holds for ``P(c)`` with ``-P_off < P < 0``.
``branch="stable"`` (default) or ``"unstable"`` picks one; the answer says which (``ans.branch``).  Below
``delta_min`` (or a pull beyond the pull-off force) there is no contact: refused with one line.

*Signs.*  The depth may be negative (the punch above the undeformed surface).  The force is reported as a
magnitude ``force >= 0`` with ``tensile`` True when the punch is pulled (the text says "tensile (pulling)
force"); ``signed_force`` is ``-force`` then.  The given force is signed (compressive positive).

*Estimates.*  Relative error estimates are measured against the scales of the problem: the force against
``max(|P|, pi w R)`` (the flat punch: ``max(|P|, P_off)``), the depth against ``max(|delta|, c^2/R)``, the contact
radius against ``c``; so that a state at zero force or depth (jump-in) has a finite estimate.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np

from .._checks import InputError
from .._lazy import lazy_module
from ..display import RichDisplay

optimize = lazy_module("scipy.optimize")

__all__ = ["AdhesiveIndentation", "NoContactError", "PullOff", "jkr_radius", "relative_estimates", "slope"]

#: the search for a bracket steps the radius by this factor (each step one evaluation)
_STEP = 1.6


class NoContactError(InputError):
    """The given depth (or pull) lies beyond the JKR curve: the punch has come off (no contact state)."""


def jkr_radius(fun: Callable[[float], float], target: float, guess: float, branch: str, what: str,
               c_min: float = 0.0, xtol: float = 1e-12) -> float:
    """The contact radius with ``fun(c) = target`` on the ``branch`` (``fun`` is ``delta(c)`` or ``P(c)``, J.6).

    The stable root is the largest ``c`` at which ``fun`` crosses ``target`` upward; the unstable one the root
    below the minimum of ``fun``.  ``fun`` is assumed to fall from ``fun(0+) = 0`` to one minimum and then rise
    (the JKR curve of a paraboloid).  Raises :class:`NoContactError` when ``target`` lies below the minimum.
    """
    def root(lo: float, hi: float) -> float:
        return float(optimize.brentq(lambda x: fun(x) - target, lo, hi, xtol=xtol * hi, rtol=1e-13))

    c0, v0 = guess, fun(guess)
    c1, v1 = c0 * _STEP, fun(c0 * _STEP)
    if v1 > v0 and branch == "stable" and v0 < target:  # right of the minimum, below the target: step up
        lo, hi, v = c0, c1, v1
        for _ in range(80):
            if v >= target:
                return root(lo, hi)
            lo, hi = hi, hi * _STEP
            v = fun(hi)
        raise InputError(f"no contact radius up to {hi:.4g} reaches the given {what}")
    c_m = None
    if v1 > v0:  # rising at c0: step down to the minimum (or a stable root)
        a, va = c0, v0
        for _ in range(80):
            b = a / _STEP
            if b < c_min:
                c_m = a
                break
            vb = fun(b)
            if vb >= va:
                lo_b, hi_b = b, a * _STEP
                break
            if branch == "stable" and vb < target:
                return root(b, a)
            a, va = b, vb
        else:
            raise InputError(f"no minimum of the JKR curve found down to c = {a:.4g}")
    else:  # falling at c0: step up to the minimum
        a, va = c1, v1
        for _ in range(80):
            b = a * _STEP
            vb = fun(b)
            if vb >= va:
                lo_b, hi_b = a / _STEP, b
                break
            a, va = b, vb
        else:
            raise InputError(f"no minimum of the JKR curve found up to c = {a:.4g}")
    if c_m is None:
        res = optimize.minimize_scalar(fun, bounds=(lo_b, hi_b), method="bounded", options={"xatol": 1e-9 * hi_b})
        c_m = float(res.x)
    v_m = fun(c_m)
    if v_m > target:
        raise NoContactError(f"the given {what} {target:.6g} lies beyond the JKR curve (its minimum is {v_m:.6g} at "
                             f"c = {c_m:.6g}): the punch has come off, no contact state")
    if branch == "stable":
        top = c_m * _STEP
        while fun(top) < target:
            top *= _STEP
        return root(c_m, top)
    lo = c_m / _STEP
    for _ in range(200):
        if lo < c_min:
            raise NoContactError(f"no unstable state with {what} {target:.6g} above c = {c_min:.4g}")
        if fun(lo) > target:
            return root(lo, c_m)
        lo /= _STEP
    raise NoContactError(f"no unstable state with {what} {target:.6g}")


@dataclass(frozen=True)
class PullOff(RichDisplay):
    """Pull-off and jump-in of an adhesive contact (J.6), from the direct JKR curve or a law (``source``).

    Forces are magnitudes of the tensile (pulling) force at which the contact is lost.

    Attributes
    ----------
    load_force, load_radius : float
        float
        Pull-off under load control: ``-min P(c)`` and the contact radius there.
    displacement_force, displacement_radius, displacement_depth : float or None
        float or None
        Under displacement control: the force (tensile magnitude), radius and depth at ``min delta(c)``;
        None where the sampled curve has no interior minimum.
    jump_in_displacement_radius, jump_in_load_radius : float or None
        float or None
        Radius of the stable state at ``delta = 0`` and at ``P = 0`` (jump-in on approach).
    curve : Any
        The :class:`~thinlayer.numerics.adhesion.JKRCurve` (None for the flat punch and the any-thickness law).
    source : str
        Where the numbers come from: ``"direct JKR curve"`` (J.6), ``"any-thickness JKR law"`` (J.16) or
        ``"flat punch (J.13)"``.
    """

    load_force: float
    load_radius: float
    displacement_force: float | None
    displacement_radius: float | None
    displacement_depth: float | None
    jump_in_displacement_radius: float | None
    jump_in_load_radius: float | None
    curve: Any = field(default=None, repr=False)
    source: str = "direct JKR curve"

    equation = "J.6"

    def latex(self) -> str:
        out = rf"P_{{\mathrm{{off}}}}^{{\mathrm{{load}}}} = {self.load_force:.8g}"
        if self.displacement_force is not None:
            out += rf",\quad P_{{\mathrm{{off}}}}^{{\mathrm{{disp}}}} = {self.displacement_force:.8g}"
        return out + r" \tag{J.6}"

    def text_lines(self) -> list[str]:
        def fmt(x: float | None) -> str:
            return "none on the sampled range" if x is None else f"{x:.8g}"

        return [f"PullOff ({self.source})   (J.6)",
                f"  pull-off force, load control: {self.load_force:.8g} tensile (pulling), contact radius "
                f"{self.load_radius:.8g}",
                f"  pull-off force, displacement control: {fmt(self.displacement_force)} tensile (pulling), contact "
                f"radius {fmt(self.displacement_radius)}, depth {fmt(self.displacement_depth)}",
                f"  jump-in: contact radius {fmt(self.jump_in_displacement_radius)} (displacement control, delta = 0), "
                f"{fmt(self.jump_in_load_radius)} (load control, P = 0)"]


@dataclass(frozen=True, eq=False, kw_only=True)
class AdhesiveIndentation(RichDisplay):
    r"""The adhesive (JKR) answer of :func:`thinlayer.solve` (module docstring: branches, signs, estimates).

    Attributes
    ----------
    layer, punch
        The layer and the numeric punch.
    H, mu, nu, work_of_adhesion : float
        float
        Thickness, shear modulus, Poisson ratio, ``w``.
    delta0 : float
        Depth (negative: the punch above the undeformed surface).
    force : float
        The magnitude of the force, ``>= 0``.
    tensile : bool
        True when the force pulls the punch away from the layer (``signed_force < 0``).
    contact_radius, contact_area : float
        float
        Contact radius ``c`` and ``pi c^2``.
    branch : str
        ``"stable"`` or ``"unstable"`` (under the given control).
    control : str
        ``"displacement"`` (depth given) or ``"load"`` (force given).
    model, reason : str
        str
        The model and why.
    error_estimate : dict
        Relative estimates ``{"force", "depth", "contact_radius"}`` (module docstring: the scales).
    tol : float
        The tolerance the estimates were accepted with.
    detail : Any
        The model's own state (:class:`~thinlayer.numerics.adhesion.AdhesiveState`, the law, ...).
    """

    equation = "J.5"

    layer: Any
    punch: Any
    H: float
    mu: float
    nu: float
    work_of_adhesion: float
    delta0: float
    force: float
    tensile: bool
    contact_radius: float
    branch: str
    control: str
    model: str
    reason: str
    error_estimate: dict
    tol: float
    equations: tuple = ("J.5", "J.5")
    detail: Any = field(default=None, repr=False)
    _pull_off: Callable[[], PullOff] | None = field(default=None, repr=False)
    entry: Any = field(default=None, repr=False, compare=False)

    @property
    def signed_force(self) -> float:
        """The force with its sign: compressive positive, tensile negative."""
        return -self.force if self.tensile else self.force

    @property
    def contact_area(self) -> float:
        return math.pi * self.contact_radius**2

    @property
    def half_width(self) -> float:
        return self.contact_radius

    @property
    def H_over_a(self) -> float:  # noqa: N802 - the paper's H/a
        return self.H / self.contact_radius

    @property
    def E(self) -> float:  # noqa: N802 - Young's modulus is E
        return 2.0 * self.mu * (1.0 + self.nu)

    @cached_property
    def pull_off(self) -> PullOff:
        """Pull-off force and radius under load and displacement control, and jump-in (J.6), from the direct
        JKR curve (:func:`~thinlayer.numerics.adhesion.jkr_curve`; computed on first use: tens of direct solves).
        """
        if self._pull_off is None:
            raise InputError("this answer has no pull-off computation")
        return self._pull_off()

    def force_words(self) -> str:
        return ("tensile (pulling) force" if self.tensile else "compressive (pushing) force")

    def text_lines(self) -> list[str]:
        est = self.error_estimate
        return [f"AdhesiveIndentation: {self.punch!r} on {self.layer}, H = {self.H:.6g}, mu = {self.mu:.6g}, "
                f"nu = {self.nu:.6g}, work of adhesion w = {self.work_of_adhesion:.6g}   ({', '.join(self.equations)})",
                f"  model: {self.model} ({self.reason})",
                f"  {self.control} control, {self.branch} branch",
                f"  force: {self.force:.10g} {self.force_words()} (estimate {100 * est['force']:.3g} %)",
                f"  contact radius: {self.contact_radius:.10g} (estimate {100 * est['contact_radius']:.3g} %)",
                f"  depth: {self.delta0:.10g}" + (" (punch above the undeformed surface)" if self.delta0 < 0 else "")
                + f" (estimate {100 * est['depth']:.3g} %)"]

    def latex(self) -> str:
        sign = r"\ \text{(tensile)}" if self.tensile else ""
        return (rf"|P| = {self.force:.8g}{sign},\quad c = {self.contact_radius:.8g},\quad "
                rf"\delta_0 = {self.delta0:.8g} \tag{{{self.equations[0]}}}")

    def as_dict(self) -> dict[str, Any]:
        return {"force": self.force, "tensile": self.tensile, "signed_force": self.signed_force,
                "contact_radius": self.contact_radius, "delta0": self.delta0, "branch": self.branch,
                "control": self.control, "model": self.model, "error_estimate": dict(self.error_estimate)}


def relative_estimates(dP: float, dd: float, dc: float, P: float, delta: float, c: float, P_scale: float,
                       d_scale: float) -> dict:
    """The relative estimates from absolute ones (module docstring: the scales)."""
    return {"force": float(dP / max(abs(P), P_scale)), "depth": float(dd / max(abs(delta), d_scale)),
            "contact_radius": float(dc / c)}


def slope(fun: Callable[[float], Any], c: float, rel: float = 1e-4) -> np.ndarray:
    """Central difference of a vector function of the radius."""
    h = rel * c
    return (np.asarray(fun(c + h), dtype=float) - np.asarray(fun(c - h), dtype=float)) / (2 * h)
