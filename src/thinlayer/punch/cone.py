r"""The cone ``Phi = r cot(alpha)`` of half-angle alpha (issue 24): a tip with an apex.

Inner order (2.26): with ``Laplacian f = (1/r)(r f')'``,

    Laplacian Phi = cot(alpha)/r,        Laplacian^2 Phi = cot(alpha) (1/r)(r (-1/r^2))' = cot(alpha)/r^3.

The force (1.8) integrates the inner terms over the contact disc, ``int p_k r dr``: ``p_1 ~ Laplacian Phi ~ 1/r`` is
integrable (``int_0 r^{-1} r dr`` converges), ``p_2 ~ Laplacian^2 Phi ~ r^{-3}`` is not (``int_0 r^{-2} dr``
diverges).  So the inner expansion holds to order 1 (:attr:`Cone.max_inner_order` = 1, also found by
:func:`~thinlayer.punch._radial.apex_inner_order`); beyond it the apex region ``r ~ H`` has its own problem.

Level set: ``a = delta0 tan(alpha)``, ``V = 2 pi int_0^a (delta0 - r cot alpha) r dr = pi a^2 delta0/3 =
pi tan^2(alpha) delta0^3/3``, ``J = 2 pi a cot(alpha) = 2 pi delta0``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from .. import symbols as S
from .._lazy import lazy_module
from ..errors import boundary_methods
from ._radial import RadialTip, angle_degrees, r, radians
from .base import TipKind, TipParameter, register_tip

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it


@boundary_methods
@dataclass(frozen=True, init=False)
class Cone(RadialTip):
    """A rigid cone of half-angle ``alpha`` (the angle between its axis and its side): ``Phi = r cot(alpha)``.

    Parameters
    ----------
    half_angle : number or str, optional
        In DEGREES, ``0 < alpha < 90`` (``Cone(70)``; a string is read by the restricted grammar).  Left out, the
        angle is the symbol ``alpha``, IN DEGREES like the number, for a symbolic law: ``Phi = r cot(pi alpha/180)``
        (``Cone().subs({"alpha": 70})`` is ``Cone(70)``).

    Examples
    --------
    >>> from thinlayer import Punch
    >>> Punch.cone(45).radial_profile([0.0, 2.0])
    array([0., 2.])
    >>> Punch.cone(70).max_inner_order
    1
    """

    values: tuple
    name: ClassVar[str] = "cone"

    def __init__(self, half_angle: Any = None) -> None:
        object.__setattr__(self, "values", (("half_angle", angle_degrees(half_angle)),))

    def _rebuild(self, values: dict) -> Cone:
        return Cone(values["half_angle"])

    @property
    def alpha(self) -> sp.Expr:
        """The half-angle in radians: ``pi alpha/180`` of the half-angle in degrees (:attr:`half_angle`)."""
        return radians(self.half_angle)

    @property
    def half_angle(self) -> sp.Expr:
        """The half-angle in degrees (a number, or the symbol ``alpha`` in degrees)."""
        return self.values[0][1]

    @property
    def kind(self) -> str:
        """``"cone"``."""
        return "cone"

    @property
    def radial_expr(self) -> sp.Expr:
        """``r cot(alpha)``."""
        return r * sp.cot(self.alpha)

    @property
    def smoothness(self) -> str:
        """``"apex"``."""
        return "apex"

    @property
    def max_inner_order(self) -> int:
        """1 (module docstring)."""
        return 1

    def contact_radius_expr(self) -> sp.Expr:
        """``a = delta0 tan(alpha)``."""
        return S.delta0 * sp.tan(self.alpha)


register_tip(TipKind("cone", Cone, (
    TipParameter("half_angle", "angle", "half-angle of the cone in degrees (0 < alpha < 90)", ("angle", "alpha")),),
    "cone Phi = r cot(alpha), half-angle alpha in degrees (issue 24)"))
