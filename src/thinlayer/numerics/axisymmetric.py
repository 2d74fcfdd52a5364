"""Axisymmetric punches: the spectral solver :func:`thinlayer.numerics.direct.solve_axisymmetric` driven by a Punch.

A :class:`~thinlayer.punch.Punch` is axisymmetric when ``Phi(x1, x2)`` depends on ``x1^2 + x2^2``
only, i.e. when its angular derivative vanishes identically::

    d Phi / d theta = x1 dPhi/dx2 - x2 dPhi/dx1 = 0.

This is checked exactly on the polynomial (sympy), and the radial profile ``Phi(r) = Phi(r, 0)``
is passed to the direct solver (spectral Galerkin method, see :mod:`thinlayer.numerics.direct`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

import sympy as sp

from .. import symbols as S
from ..layers.kernels import HalfSpace, LayerKernel
from ..punch import Punch
from . import direct as _direct
from .direct import AxisymmetricContact

__all__ = ["AxisymmetricPunchContact", "radial_profile", "solve_axisymmetric"]

#: the radius symbol of the radial profile Phi(r)
r = sp.Symbol("r", nonnegative=True)


@dataclass(frozen=True)
class AxisymmetricPunchContact(AxisymmetricContact):
    """:class:`thinlayer.numerics.direct.AxisymmetricContact` of a :class:`~thinlayer.punch.Punch`.

    Adds the punch and the names shared with :class:`~thinlayer.numerics.Contact2D`:
    ``contact_radius`` (= ``radius``, c) and ``contact_area`` (``pi c^2``).
    """

    punch: Any = None

    @property
    def contact_radius(self) -> float:
        """Contact radius c (the pressure vanishes continuously at r = c)."""
        return self.radius

    @property
    def contact_area(self) -> float:
        """Area of the contact disc, ``pi c^2``."""
        return math.pi * self.radius**2


def _as_punch(punch: Any) -> Punch:
    if isinstance(punch, (str, sp.Basic)):
        punch = Punch(punch)
    if not isinstance(punch, Punch):
        raise TypeError(f"punch must be a thinlayer Punch (or a polynomial expression in x1, x2), "
                        f"got {punch!r} ({type(punch).__name__})")
    return punch


def radial_profile(punch: Any) -> sp.Expr:
    """The profile ``Phi(r)`` of an axisymmetric punch, as a sympy expression in :data:`r`.

    Parameters
    ----------
    punch:
        A :class:`~thinlayer.punch.Punch` with numeric parameters.

    Raises
    ------
    ValueError
        If the punch has free parameters (named) or is not axisymmetric.

    Examples
    --------
    >>> from thinlayer import Punch
    >>> radial_profile(Punch.fourth_degree(R=2, K=1))
    r**4 + r**2/4
    """
    punch = _as_punch(punch)
    if punch.parameters:
        names = ", ".join(str(q) for q in punch.parameters)
        raise ValueError(f"the punch '{punch.name}' Phi = {punch.expr} has free parameter(s) {names}: "
                         f"substitute numbers first, e.g. punch.subs({{'{punch.parameters[0]}': 1.0}})")
    phi = punch.expr
    angular = sp.expand(S.x1 * sp.diff(phi, S.x2) - S.x2 * sp.diff(phi, S.x1))
    if angular != 0:
        raise ValueError(f"the punch '{punch.name}' Phi = {punch.expr} is not axisymmetric "
                         f"(x1 dPhi/dx2 - x2 dPhi/dx1 = {angular} is not zero): use "
                         "thinlayer.numerics.solve_2d for a general punch")
    return sp.expand(phi.xreplace({S.x1: r, S.x2: sp.Integer(0)}))


def solve_axisymmetric(layer: LayerKernel, punch: Any, delta0: float, H: float | None = None, mu: float = 1.0,
                       **kw: Any) -> AxisymmetricPunchContact:
    """Direct solution of (1.5)-(1.8) for an axisymmetric punch via :func:`thinlayer.numerics.direct.solve_axisymmetric`.

    Parameters
    ----------
    layer:
        ``BondedLayer(nu)`` (numeric nu), ``FrictionlessLayer()`` or ``HalfSpace()``.
    punch:
        An axisymmetric :class:`~thinlayer.punch.Punch` with numeric parameters, e.g.
        ``Punch.paraboloid(R=100)``.
    delta0:
        Indentation depth (> 0).
    H:
        Layer thickness (> 0; may be omitted for ``HalfSpace``).
    mu:
        Shear modulus.
    **kw:
        Passed on: ``n`` (modes), ``nu`` (for layers without a Poisson ratio), ``error_estimate``.

    Returns
    -------
    AxisymmetricPunchContact
        The direct result (``radius``, ``force``, ``pressure``, error estimates, ...) with
        ``punch``, ``contact_radius`` and ``contact_area``.

    Examples
    --------
    Hertz (half-space): ``c^2 = R delta0``.

    >>> from thinlayer import HalfSpace, Punch
    >>> res = solve_axisymmetric(HalfSpace(), Punch.paraboloid(R=2), 0.5, nu=0.3)
    >>> round(res.contact_radius, 10), round(res.contact_area, 10)
    (1.0, 3.1415926536)
    """
    punch = _as_punch(punch)
    profile = radial_profile(punch)
    if H is None:
        if not isinstance(layer, HalfSpace):
            raise ValueError(f"{type(layer).__name__} needs the layer thickness H > 0")
        H = 1.0  # ignored by the half-space kernel
    res = _direct.solve_axisymmetric(layer, profile, delta0, H, mu, **kw)
    values = {f.name: getattr(res, f.name) for f in fields(res) if f.init}
    return AxisymmetricPunchContact(**values, punch=punch)
