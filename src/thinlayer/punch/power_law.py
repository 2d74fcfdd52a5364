r"""The power-law tip ``Phi = C r^n``, real ``n >= 1`` (issue 24).

Inner order (2.26): ``Laplacian r^m = m^2 r^{m-2}``, so ``Laplacian^k Phi = C n^2 (n-2)^2 ... (n-2k+2)^2 r^{n-2k}``.
The force integrates it against ``r dr``: it exists iff ``n - 2k > -2``.  An even integer n makes the product vanish
from ``k = n/2 + 1`` on (a polynomial: no limit, ``"smooth"``); otherwise the order is the largest
``k < n/2 + 1`` and the tip has an ``"apex"`` (``n = 1``, the cone: 1; ``n = 3/2``: 1; ``n = 3``: 2).

Level set: ``a = (delta0/C)^{1/n}``, ``V = 2 pi int_0^a (delta0 - C r^n) r dr = pi a^2 delta0 n/(n + 2)``,
``J = 2 pi a C n a^{n-1} = 2 pi n delta0``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

from .. import symbols as S
from .._lazy import lazy_module
from ..errors import boundary_methods
from ..parse import parse_number
from ._radial import RadialTip, length_value, r
from .base import PunchError, TipKind, TipParameter, register_tip

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it


def _exponent(n: Any) -> sp.Expr:
    if n is None:
        return sp.Symbol("n", positive=True)
    if isinstance(n, sp.Symbol):
        return sp.Symbol(n.name, positive=True)
    try:
        v = parse_number(n, "the exponent n")
    except (TypeError, ValueError) as exc:
        raise PunchError(str(exc)) from None
    if isinstance(v, sp.Float):  # a decimal is exact: 1.5 is 3/2
        v = sp.Rational(str(v))
    if not (v >= 1 and math.isfinite(float(v)) and v <= 1000):
        raise PunchError(f"the exponent n of the power law C r^n must be a real number with 1 <= n <= 1000, got {n!r}")
    return v


@boundary_methods
@dataclass(frozen=True, init=False)
class PowerLaw(RadialTip):
    """A rigid tip ``Phi = C r^n`` (``C > 0`` of dimension length^(1-n), real ``n >= 1``).

    Examples
    --------
    >>> from thinlayer import Punch
    >>> tip = Punch.power_law(2, 1.5)
    >>> tip.smoothness, tip.max_inner_order
    ('apex', 1)
    >>> Punch.power_law(1, 4).max_inner_order is None      # r^4: a polynomial
    True
    """

    values: tuple
    name: ClassVar[str] = "power-law tip"

    def __init__(self, C: Any = None, n: Any = None) -> None:
        object.__setattr__(self, "values", (("C", length_value(C, "C")), ("n", _exponent(n))))

    def _rebuild(self, values: dict) -> PowerLaw:
        return PowerLaw(values["C"], values["n"])

    @property
    def C(self) -> sp.Expr:
        """The coefficient."""
        return self.values[0][1]

    @property
    def n(self) -> sp.Expr:
        """The exponent."""
        return self.values[1][1]

    @property
    def kind(self) -> str:
        """``"power_law"``."""
        return "power_law"

    @property
    def radial_expr(self) -> sp.Expr:
        """``C r^n``."""
        return self.C * r**self.n

    @property
    def max_inner_order(self) -> int | None:
        """The largest ``k < n/2 + 1``, None for an even integer n (module docstring)."""
        n = self.n
        if not n.is_number:
            raise PunchError("the inner order of C r^n needs a number for n")
        if n.is_integer and n % 2 == 0:
            return None
        return int(sp.ceiling(n / 2 + 1)) - 1

    @property
    def smoothness(self) -> str:
        """``"smooth"`` for an even integer n, else ``"apex"``."""
        n = self.n
        return "smooth" if n.is_number and n.is_integer and n % 2 == 0 else "apex"

    def contact_radius_expr(self) -> sp.Expr:
        """``a = (delta0/C)^{1/n}``."""
        return (S.delta0 / self.C) ** (1 / self.n)


register_tip(TipKind("power_law", PowerLaw, (
    TipParameter("C", "number", "coefficient C of Phi = C r^n"),
    TipParameter("n", "number", "exponent n >= 1 of Phi = C r^n", ("exponent",))),
    "power-law tip Phi = C r^n, real n >= 1 (issue 24)"))
