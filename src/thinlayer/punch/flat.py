"""The flat-ended cylinder (F.1): a tip whose contact is its face, whatever the depth.

Not a polynomial: ``Phi = 0`` on the disc ``r < a`` and ``+inf`` outside, the contact is the disc and the pressure
is singular at its edge like ``(a^2 - r^2)^(-1/2)`` (F.8).  ``thinlayer.solve`` answers it by the flat-punch models
of :mod:`thinlayer.contact.flat_punch`.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from .. import symbols as S
from .._lazy import lazy_module
from ..errors import InputTypeError, boundary_methods
from .base import LevelSet, PunchError, Tip, TipKind, TipParameter, points, positive_depth, register_tip

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it


@boundary_methods
@dataclass(frozen=True, init=False)
class FlatPunch(Tip):
    """A rigid flat-ended cylinder of radius ``a``: ``u3 = w0`` on the disc ``r < a``, a fixed contact (F.1).

    Not a polynomial punch: the contact is the disc whatever the depth, and the pressure is singular at its
    edge like ``(a^2 - r^2)^(-1/2)`` (F.8).  ``radius`` is a positive finite float; a string is read by the
    restricted grammar (``"1/2"``, ``"2.5e-3"``), never evaluated.

    As a :class:`~thinlayer.punch.Tip`: ``expr`` is ``Piecewise((0, x1^2 + x2^2 < a^2), (oo, True))``, ``polynomial``
    None, ``smoothness`` ``"edge-singular"``, ``max_inner_order`` 0, ``fixed_contact`` True.

    Examples
    --------
    >>> from thinlayer import Punch
    >>> Punch.flat("3/2")
    FlatPunch: flat-ended cylinder of radius a = 1.5   (F.1)
    """

    radius: float
    name: ClassVar[str] = "flat-ended cylinder"
    equation: ClassVar[str] = "F.1"
    axisymmetric: ClassVar[bool] = True
    #: the pressure is unbounded at the edge r = a (F.8)
    singular_edge: ClassVar[bool] = True

    def __init__(self, a) -> None:
        from ..parse import parse_number

        try:
            value = float(parse_number(a, "the radius a of the flat punch"))
        except (ValueError, TypeError) as exc:
            raise PunchError(str(exc)) from None
        if not (value > 0 and value < float("inf")):
            raise PunchError(f"the radius a of the flat punch must be a positive finite number, got {a!r}")
        object.__setattr__(self, "radius", value)

    # ---- the tip protocol -----------------------------------------------------------------
    @property
    def kind(self) -> str:
        """``"flat"``."""
        return "flat"

    @property
    def description(self) -> str:
        """One phrase for result summaries."""
        return f"flat-ended cylinder, radius a = {self.radius:.8g}"

    @property
    def expr(self) -> sp.Expr:
        """``Phi = 0`` on the disc ``r < a``, ``+oo`` outside (F.1), as a sympy Piecewise in ``x1, x2``."""
        return sp.Piecewise((sp.Integer(0), S.x1**2 + S.x2**2 < sp.Float(self.radius) ** 2), (sp.oo, True))

    @property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """``()``: the radius is a number."""
        return ()

    def subs(self, values: Mapping) -> FlatPunch:
        """The punch itself: it has no parameters (an empty mapping only)."""
        if not isinstance(values, Mapping):
            raise InputTypeError(f"the punch's parameter values must be a dict, got {type(values).__name__}")
        if values:
            raise PunchError(f"{', '.join(map(repr, values))} is not a parameter of the flat punch: it has none "
                             "(its radius is a number)")
        return self

    @property
    def smoothness(self) -> str:
        """``"edge-singular"``: the pressure is unbounded at the edge (F.8)."""
        return "edge-singular"

    @property
    def max_inner_order(self) -> int:
        """0: the inner expansion (2.26) of a constant Phi stops at its leading term (F.10)."""
        return 0

    @property
    def fixed_contact(self) -> bool:
        """True: the contact is the face ``r < a`` at every depth."""
        return True

    def profile(self, x1: Any, x2: Any) -> np.ndarray:
        """0 on the face ``r < a``, ``+inf`` outside."""
        r2 = points(x1, "x1") ** 2 + points(x2, "x2") ** 2
        return np.where(r2 < self.radius**2, 0.0, np.inf)

    def level_set(self, delta0: Any) -> LevelSet:
        """The face: area ``pi a^2``, volume ``pi a^2 delta0``, perimeter ``2 pi a``; ``flux`` None (``grad Phi`` is
        unbounded at the edge).
        """
        d = positive_depth(delta0)
        a = self.radius
        return LevelSet(math.pi * a * a, math.pi * a * a * d, 2 * math.pi * a, None, a, a, None)

    def latex(self) -> str:
        return rf"u_3 = w_0 \ \text{{on}}\ r < a,\quad a = {self.radius:.8g} \tag{{F.1}}"

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return [f"FlatPunch: flat-ended cylinder of radius a = {self.radius:.8g}   (F.1)"]


register_tip(TipKind("flat", FlatPunch, (
    TipParameter("a", "length", "radius of the flat face", ("radius",), required=True),),
    "flat-ended cylinder of radius a (F.1)"))
