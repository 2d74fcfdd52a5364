r"""The exact sphere ``Phi = R - sqrt(R^2 - r^2)`` for ``r <= R`` (the cap, not the paraboloid ``r^2/(2R)``).

Beyond ``r = R`` the tip is absent (``Phi = +inf``: :attr:`Sphere.support_radius` = R); a depth needs
``delta0 < R``.  Evaluated as ``r^2/(R + sqrt(R^2 - r^2))`` (no cancellation at small r).

Phi is analytic in ``r^2`` on ``r < R``: every ``Laplacian^k Phi`` is bounded on a contact disc ``a < R``, so the
inner expansion has no apex limit (``max_inner_order`` None) and the tip is ``"smooth"`` though not a polynomial.

Level set: ``a = sqrt(delta0 (2R - delta0))``, ``V = 2 pi int_0^a (delta0 - R + sqrt(R^2 - r^2)) r dr =
pi delta0^2 (R - delta0/3)`` (the volume of the cap), ``J = 2 pi a Phi'(a) = 2 pi a^2/(R - delta0)``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from .. import symbols as S
from .._lazy import lazy_module
from ..errors import boundary_methods
from ._radial import RadialTip, length_value, r
from .base import TipKind, TipParameter, register_tip

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it


@boundary_methods
@dataclass(frozen=True, init=False)
class Sphere(RadialTip):
    """A rigid sphere of radius ``R``: ``Phi = R - sqrt(R^2 - r^2)`` on ``r <= R``, absent beyond.

    Parameters
    ----------
    R : number or str, optional
        The radius (positive; a string is read by the restricted grammar); the symbol ``R`` if left out.

    Examples
    --------
    >>> from thinlayer import Punch
    >>> round(float(Punch.sphere(2).radial_profile(1.0)), 14)     # 2 - sqrt(3) = 0.26794919243112...
    0.26794919243112
    """

    values: tuple
    name: ClassVar[str] = "exact sphere"

    def __init__(self, R: Any = None) -> None:
        object.__setattr__(self, "values", (("R", length_value(R, "R")),))

    def _rebuild(self, values: dict) -> Sphere:
        return Sphere(values["R"])

    @property
    def R(self) -> sp.Expr:
        """The radius."""
        return self.values[0][1]

    @property
    def kind(self) -> str:
        """``"sphere"``."""
        return "sphere"

    @property
    def radial_expr(self) -> sp.Expr:
        """``R - sqrt(R^2 - r^2)`` on ``r <= R``, ``oo`` beyond."""
        R = self.R
        return sp.Piecewise((R - sp.sqrt(R**2 - r**2), r <= R), (sp.oo, True))

    @property
    def numeric_expr(self) -> sp.Expr:
        """``r^2/(R + sqrt(R^2 - r^2))``: the same values without cancellation."""
        R = self.R
        return sp.Piecewise((r**2 / (R + sp.sqrt(R**2 - r**2)), r <= R), (sp.oo, True))

    @property
    def support_radius(self) -> float:
        """``R``: the tip is absent beyond."""
        self._need_numbers("its rim")
        return float(self.R)

    @property
    def smoothness(self) -> str:
        """``"smooth"``: analytic in ``r^2`` on the cap."""
        return "smooth"

    @property
    def max_inner_order(self) -> None:
        """None: every ``Laplacian^k Phi`` is bounded on a contact disc inside the cap (module docstring)."""
        return None

    def level_set_expressions(self) -> dict[str, sp.Expr]:
        """The generic integrals (:meth:`RadialTip.level_set_expressions`) with ``sqrt(R^2 - a^2) = R - delta0``
        (``delta0 < R``): ``V = pi delta0^2 (R - delta0/3)``, ``J = 2 pi a^2/(R - delta0)``.
        """
        out = dict(super().level_set_expressions())
        R, a2 = self.R, S.delta0 * (2 * self.R - S.delta0)
        s = sp.sqrt(R**2 - a2)
        for k in ("volume", "flux"):
            e = out[k].subs(sp.sqrt(sp.expand(R**2 - a2)), R - S.delta0).subs(s, R - S.delta0)
            out[k] = sp.factor(sp.simplify(e))
        return out

    def contact_radius_expr(self) -> sp.Expr:
        """``a = sqrt(delta0 (2R - delta0))``."""
        return sp.sqrt(S.delta0 * (2 * self.R - S.delta0))


register_tip(TipKind("sphere", Sphere, (
    TipParameter("R", "length", "radius of the sphere", ("radius",)),),
    "exact sphere Phi = R - sqrt(R^2 - r^2), r <= R (issue 24)"))
