r"""The blunted cone: a spherical cap of radius R joined tangentially to a cone of half-angle alpha (issue 24).

The cap ``R - sqrt(R^2 - r^2)`` has slope ``r/sqrt(R^2 - r^2)``, equal to the cone's ``cot(alpha)`` at

    r_t = R cos(alpha)        (then ``sqrt(R^2 - r_t^2) = R sin(alpha)``),

where the cap's height is ``R (1 - sin alpha)``.  The cone ``r cot(alpha) - b`` meets it there when
``R cos^2(alpha)/sin(alpha) - b = R (1 - sin alpha)``, i.e. ``b = R (1/sin(alpha) - 1)``.  So Phi and Phi' are
continuous at ``r_t``; ``Phi''`` jumps from ``R^2/(R sin alpha)^3 = 1/(R sin^3 alpha)`` to 0.

Inner order (2.26): ``Laplacian Phi`` jumps at ``r_t`` (bounded, integrable), ``Laplacian^2 Phi`` holds a line
source ``delta(r - r_t)`` there -- not a function: the inner expansion holds to order 1 (``max_inner_order`` = 1),
whatever the depth; the tip is ``"smooth"`` at its apex (the cap) but not a polynomial.  The direct solver splits
its load integrals at ``r_t`` (:attr:`BluntedCone.radial_breakpoints`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

from .._lazy import lazy_module
from ..errors import boundary_methods
from ._radial import RadialTip, angle_degrees, length_value, r, radians
from .base import TipKind, TipParameter, register_tip

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it


@boundary_methods
@dataclass(frozen=True, init=False)
class BluntedCone(RadialTip):
    """A cone of half-angle alpha (degrees) whose apex is a sphere of radius R, joined tangentially at
    ``r_t = R cos(alpha)`` (module docstring).

    Examples
    --------
    >>> from thinlayer import Punch
    >>> tip = Punch.blunted_cone(1, 60)
    >>> round(tip.join_radius, 12)
    0.5
    """

    values: tuple
    name: ClassVar[str] = "blunted cone"

    def __init__(self, R: Any = None, half_angle: Any = None) -> None:
        object.__setattr__(self, "values", (("R", length_value(R, "R")), ("half_angle", angle_degrees(half_angle))))

    def _rebuild(self, values: dict) -> BluntedCone:
        return BluntedCone(values["R"], values["half_angle"])

    @property
    def R(self) -> sp.Expr:
        """The radius of the spherical cap."""
        return self.values[0][1]

    @property
    def alpha(self) -> sp.Expr:
        """The half-angle in radians: ``pi alpha/180`` of the half-angle in degrees (:attr:`half_angle`)."""
        return radians(self.half_angle)

    @property
    def half_angle(self) -> sp.Expr:
        """The half-angle in degrees (a number, or the symbol ``alpha`` in degrees)."""
        return self.values[1][1]

    @property
    def kind(self) -> str:
        """``"blunted_cone"``."""
        return "blunted_cone"

    def _pieces(self, cap: sp.Expr) -> sp.Expr:
        R, al = self.R, self.alpha
        rt = R * sp.cos(al)
        return sp.Piecewise((cap, r <= rt), (r * sp.cot(al) - R * (1 / sp.sin(al) - 1), True))

    @property
    def radial_expr(self) -> sp.Expr:
        """``R - sqrt(R^2 - r^2)`` for ``r <= R cos(alpha)``, ``r cot(alpha) - R (1/sin(alpha) - 1)`` beyond."""
        return self._pieces(self.R - sp.sqrt(self.R**2 - r**2))

    @property
    def numeric_expr(self) -> sp.Expr:
        """The cap as ``r^2/(R + sqrt(R^2 - r^2))`` (no cancellation)."""
        return self._pieces(r**2 / (self.R + sp.sqrt(self.R**2 - r**2)))

    @property
    def join_radius(self) -> float:
        """``r_t = R cos(alpha)``."""
        self._need_numbers("its join")
        return float(self.R * sp.cos(self.alpha))

    @property
    def radial_breakpoints(self) -> tuple[float, ...]:
        """``(r_t,)``: Phi'' jumps there."""
        return (self.join_radius,)

    @property
    def smoothness(self) -> str:
        """``"smooth"`` at the apex (a spherical cap); not a polynomial, and Phi'' jumps at the join."""
        return "smooth"

    @property
    def max_inner_order(self) -> int:
        """1: ``Laplacian^2 Phi`` has a line source at the join (module docstring)."""
        return 1

    def contact_radius_expr(self) -> None:
        """None: the radius is a Piecewise of delta0 (found by root finding)."""
        return None

    def level_set(self, delta0: Any):
        """By quadrature split at the join (the radius by root finding)."""
        out = super().level_set(delta0)
        if math.isclose(out.radius, self.join_radius, rel_tol=1e-12):  # Phi'' is one-sided there
            return type(out)(out.area, out.volume, out.perimeter, out.flux, out.half_width, out.radius, None)
        return out


register_tip(TipKind("blunted_cone", BluntedCone, (
    TipParameter("R", "length", "radius of the spherical apex", ("radius",)),
    TipParameter("half_angle", "angle", "half-angle of the cone in degrees (0 < alpha < 90)", ("angle", "alpha"))),
    "cone of half-angle alpha (degrees) with a spherical apex of radius R, tangent join (issue 24)"))
