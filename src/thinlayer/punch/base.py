"""The tip protocol: what every rigid tip ``x3 = -Phi(x1, x2)`` answers (1.1), and the registry of tip kinds.

A caller never asks for a tip's concrete class or compares its name: it asks the tip.  :class:`Tip` declares the
questions (axisymmetry, smoothness, the highest inner order (2.26) the shape supports, whether the contact set is
fixed, the principal curvatures of a quadric, the level-set integrals of the force law (1.8), (3.25) at a depth
delta0), and :data:`TIPS` lists the kinds a user can name (``tip_from_spec("paraboloid:R=10")``, the CLI's
``--tip``, a derivation file's ``[punch] kind``).  A new tip is one module: a :class:`Tip` subclass and one
``register_tip(TipKind(...))`` line, imported by ``thinlayer/punch/__init__.py``.
"""
from __future__ import annotations

import importlib
import math
import sys
from abc import ABC, abstractmethod
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from .._lazy import lazy_module
from ..display import RichDisplay
from ..errors import InputError, boundary_methods

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it


class PunchError(InputError):
    """The punch is not a polynomial in (x1, x2) or is otherwise inadmissible."""


#: the values of :attr:`Tip.smoothness`
SMOOTHNESS = ("smooth", "apex", "ridge", "edge-singular")


@dataclass(frozen=True)
class LevelSet:
    r"""The integrals of the force law (1.8), (3.25) over the level set ``omega0 = {Phi < delta0}`` of a tip.

    Attributes
    ----------
    area : float
        ``|omega0|``.
    volume : float
        ``V = iint (delta0 - Phi)_+ dx`` (the leading force is ``vartheta V/(A H)``, (2.27), (1.8)).
    perimeter : float
        ``|Gamma0|``, the length of the contour.
    flux : float or None
        ``J = oint_{Gamma0} |grad Phi| ds = iint_{omega0} Laplacian Phi dx`` (divergence theorem; the first
        correction of (1.8)); None where ``grad Phi`` is unbounded on the contour (the edge of a flat punch).
    half_width : float
        ``a = 2 |omega0| / |Gamma0|`` (the radius of a disc; the length of ``H/a``).
    radius : float or None
        The radius of the contact disc of an axisymmetric tip whose level set is a disc; None otherwise.
    second_order_flux : float or None
        ``oint_{Gamma0} (Laplacian Phi + Phi_nn) ds`` where it is computed (axisymmetric polynomials); else None.
    """

    area: float
    volume: float
    perimeter: float
    flux: float | None
    half_width: float
    radius: float | None = None
    second_order_flux: float | None = None


@boundary_methods
class Tip(RichDisplay, ABC):
    """A rigid tip ``x3 = -Phi(x1, x2)`` pressed into the layer (1.1): the interface every tip answers.

    Data every tip carries (attributes or properties of the subclass):

    ``name`` (a human label, ``"paraboloid of revolution"``), ``kind`` (its :data:`TIPS` key), ``description`` (one
    phrase for summaries), ``equation`` (its defining equation, ``"1.1"``, ``"F.1"``), ``expr`` (Phi as a sympy
    expression in ``thinlayer.symbols.x1, x2``).

    Capabilities (no caller asks for the concrete class): :attr:`axisymmetric`, :attr:`polynomial`,
    :attr:`smoothness`, :attr:`max_inner_order`, :attr:`fixed_contact`, :attr:`quadric`, :attr:`sphere_radius`,
    :meth:`profile`, :meth:`radial_profile`, :meth:`level_set`.
    """

    __slots__ = ()

    #: the paper's equation defining the tip
    equation: ClassVar[str] = "1.1"

    # ---- identity ---------------------------------------------------------------------------
    @property
    @abstractmethod
    def kind(self) -> str:
        """The registry key of the tip's kind (:data:`TIPS`): ``"paraboloid"``, ``"flat"``, ``"polynomial"``, ..."""

    @property
    @abstractmethod
    def description(self) -> str:
        """One phrase for result summaries."""

    @property
    @abstractmethod
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """The free parameters of Phi (symbols other than x1, x2), sorted by name; ``()`` for a numeric tip."""

    @abstractmethod
    def subs(self, values: Mapping) -> Tip:
        """A new tip with parameters replaced; string values are read by the restricted grammar, never evaluated."""

    @property
    def is_numeric(self) -> bool:
        """Whether Phi has no free parameter (every numeric question below needs it)."""
        return not self.parameters

    # ---- shape ------------------------------------------------------------------------------
    @property
    @abstractmethod
    def axisymmetric(self) -> bool:
        """Whether Phi depends on ``r = |x|`` only: decided by the tip, in one place."""

    @property
    def is_polynomial(self) -> bool:
        """Whether Phi is a polynomial (:attr:`polynomial` is not None); a tip that knows it without building the
        polynomial (the punch with numbers, issue 28 item 6) answers here.
        """
        return self.polynomial is not None

    @property
    def polynomial(self) -> sp.Poly | None:
        """Phi as a ``sympy.Poly`` in ``(x1, x2)`` (coefficients may hold parameters), or None if not a polynomial."""
        return None

    @property
    def smoothness(self) -> str:
        """``"smooth"``, ``"apex"`` (a cone's tip), ``"ridge"`` (a pyramid's edges) or ``"edge-singular"`` (F.8)."""
        return "smooth"

    @property
    def max_inner_order(self) -> int | None:
        """The highest order of the inner expansion (2.26) the shape supports; None = unlimited (the series of a
        polynomial terminates).
        """
        return None

    @property
    def fixed_contact(self) -> bool:
        """Whether the contact set does not depend on the depth (the face of a flat punch)."""
        return False

    @property
    def quadric(self) -> tuple[float, float, float] | None:
        """``(k1, k2, angle)``: principal curvatures ``k1 <= k2`` (``1/R1``, ``1/R2``) and the angle of the first
        principal axis, when Phi is a numeric positive-definite quadratic form ``x.Kx/2``; else None.
        """
        return None

    @property
    def sphere_radius(self) -> float | None:
        """``R`` when Phi is a quadric with equal curvatures (the paraboloid of revolution ``r^2/(2R)``); else None."""
        q = self.quadric
        if q is None or q[0] != q[1]:
            return None
        return 1.0 / q[0]

    # ---- numbers ----------------------------------------------------------------------------
    @abstractmethod
    def profile(self, x1: Any, x2: Any) -> Any:
        """Phi at the points ``(x1, x2)`` (numpy arrays broadcast), ``+inf`` where the tip is absent."""

    def radial_profile(self, r: Any) -> Any:
        """``Phi(r, 0)`` of an axisymmetric tip (numpy)."""
        if not self.axisymmetric:
            raise PunchError(f"the {self.name} is not axisymmetric: it has no radial profile Phi(r)")
        r = points(r, "r")
        return self.profile(r, 0.0 * r)

    def radial_slope(self, r: Any) -> Any:
        """``dPhi/dr`` of an axisymmetric tip at the radii ``r`` (numpy), where the tip knows it in closed form; the
        direct axisymmetric solver uses it for the half-space part of the edge condition.  Default: a
        :class:`PunchError` (the solver then works without it).
        """
        raise PunchError(f"the {self.name} has no closed-form radial slope dPhi/dr")

    @property
    def radial_breakpoints(self) -> tuple[float, ...]:
        """Radii where Phi'' of an axisymmetric tip jumps (a blunted cone's tangent join); ``()`` by default."""
        return ()

    @property
    def support_radius(self) -> float:
        """The radius beyond which the tip is absent (``Phi = +inf``: the exact sphere's ``R``); ``inf`` by default."""
        return math.inf

    @abstractmethod
    def level_set(self, delta0: Any) -> LevelSet | None:
        """The integrals of the force law over ``{Phi < delta0}`` (:class:`LevelSet`), or None where the tip has
        no closed form or 1D quadrature for them (a general non-axisymmetric polynomial: the contour stages of
        :mod:`thinlayer.asymptotics` compute those).
        """

    @abstractmethod
    def latex(self) -> str:
        """The defining equation of the tip as a tagged LaTeX line."""


def is_polynomial_tip(obj: Any) -> bool:
    """Whether ``obj`` is a tip whose Phi is a polynomial (:attr:`Tip.polynomial`): what the symbolic stages
    (2.26)-(3.25) and the polynomial solvers take.  Callers ask this instead of checking a tip's class.
    """
    return isinstance(obj, Tip) and obj.is_polynomial


def points(x: Any, what: str) -> np.ndarray:
    """Coordinates as a float array, or a :class:`PunchError` naming them (a string is never evaluated)."""
    if isinstance(x, (str, bytes)):
        raise PunchError(f"the coordinates {what} must be numbers or a numpy array, got {x!r:.60}")
    try:
        return np.asarray(x, dtype=float)
    except (TypeError, ValueError) as exc:
        raise PunchError(f"the coordinates {what} must be numbers or a numpy array: {exc}") from None


def positive_depth(delta0: Any) -> float:
    """``delta0`` as a positive finite float, or a :class:`PunchError` naming it."""
    if isinstance(delta0, (int, float)) and not isinstance(delta0, bool) and abs(delta0) < 2**1000:
        value = float(delta0)  # a plain number: the float the grammar route gives, without sympy
    else:
        from ..parse import parse_number

        try:
            value = float(parse_number(delta0, "the depth delta0"))
        except (TypeError, ValueError) as exc:
            raise PunchError(str(exc)) from None
    if not (value > 0 and math.isfinite(value)):
        raise PunchError(f"the depth delta0 must be a positive finite number, got {delta0!r}")
    return value


# =============================================================================================
# the registry of tip kinds
# =============================================================================================
#: the values of :attr:`TipParameter.unit_kind`
UNIT_KINDS = ("length", "angle", "number", "expression", "profile")


@dataclass(frozen=True)
class TipParameter:
    """One parameter of a tip kind, as a user names it in ``kind:key=value``.

    ``unit_kind`` is ``"length"``, ``"angle"`` (degrees), ``"number"``, ``"expression"`` (a formula in ``x_1, x_2``,
    read by the restricted grammar) or ``"profile"`` (a radial profile in ``r``, read with ``radial=True``);
    ``aliases`` are other keys accepted for it; ``required`` says whether the constructor
    needs it (otherwise a missing value stays a symbol).
    """

    name: str
    unit_kind: str
    description: str
    aliases: tuple[str, ...] = ()
    required: bool = False

    def __post_init__(self):
        if not self.name.isidentifier() or self.unit_kind not in UNIT_KINDS:
            raise ValueError(f"TipParameter({self.name!r}, {self.unit_kind!r}): the name must be an identifier and "
                             f"the unit kind one of {', '.join(UNIT_KINDS)}")


@dataclass(frozen=True)
class TipKind:
    """A row of :data:`TIPS`: the kind's key, its constructor (called with the parameters by name), its parameters
    and a one-line summary.
    """

    kind: str
    constructor: Callable[..., Tip]
    parameters: tuple[TipParameter, ...]
    summary: str

    @property
    def form(self) -> str:
        """The spec a user writes, e.g. ``"paraboloid:R=<length>"``."""
        keys = ",".join(f"{p.name}=<{p.unit_kind}>" for p in self.parameters)
        return f"{self.kind}:{keys}" if keys else self.kind


#: tip kinds by key, in the order of :data:`CATALOGUE` (:func:`catalogue` imports them all)
TIPS: dict[str, TipKind] = {}
#: the modules of the tip kinds, in the order the registry lists them; :func:`catalogue` imports them on first use
CATALOGUE = ("blunted_cone", "cone", "flat", "polynomial", "power_law", "pyramid", "revolution", "sphere")


def tip_kind(kind: str) -> TipKind | None:
    """The registry row of ``kind`` (None if there is none), importing the tip modules only if it is not loaded."""
    row = TIPS.get(kind)
    return row if row is not None else catalogue().get(kind)


def catalogue() -> dict[str, TipKind]:
    """:data:`TIPS` with every kind of :data:`CATALOGUE` registered (their modules imported on first use).

    ``import thinlayer.punch`` loads the polynomial punch and the flat punch only: the tips of revolution build
    sympy constants at import, which a numeric ``solve()`` of a paraboloid does not need (issue 28 item 6).
    """
    if not all(f"{__package__}.{m}" in sys.modules for m in CATALOGUE):
        for m in CATALOGUE:
            importlib.import_module(f"{__package__}.{m}")
        order = {f"{__package__}.{m}": i for i, m in enumerate(CATALOGUE)}
        rows = sorted(TIPS.values(), key=lambda row: order.get(getattr(row.constructor, "__module__", ""), len(order)))
        TIPS.clear()
        TIPS.update((row.kind, row) for row in rows)
    return TIPS


def register_tip(row: TipKind) -> TipKind:
    """Add a kind to :data:`TIPS`, checking its contract: a new identifier key, a callable constructor, a tuple of
    :class:`TipParameter` with distinct names and aliases, a summary.  Returns the row.
    """
    problems = []
    if not isinstance(row, TipKind):
        raise TypeError(f"register_tip takes a TipKind, got {type(row).__name__}")
    if not row.kind.isidentifier():
        problems.append(f"the key {row.kind!r} is not an identifier")
    if row.kind in TIPS:
        problems.append(f"the key {row.kind!r} is registered already")
    if not callable(row.constructor):
        problems.append("the constructor is not callable")
    if not isinstance(row.parameters, tuple) or not all(isinstance(p, TipParameter) for p in row.parameters):
        problems.append("parameters must be a tuple of TipParameter")
    else:
        keys = [k for p in row.parameters for k in (p.name, *p.aliases)]
        if len(keys) != len(set(keys)):
            problems.append(f"parameter names and aliases repeat: {keys}")
    if not isinstance(row.summary, str) or not row.summary:
        problems.append("the summary is empty")
    if problems:
        raise ValueError(f"register_tip({row.kind!r}): " + "; ".join(problems))
    TIPS[row.kind] = row
    return row
