"""The punch shape Phi(x1, x2): the surface ``x3 = -Phi(x1, x2)`` of a rigid polynomial punch (1.1).

A :class:`Punch` holds a polynomial in the canonical coordinates ``thinlayer.symbols.x1, x2``
with symbolic or numeric coefficients.  Its *scaled* form (1.2), (2.13) is

    Phi^*(xi) = Lambda * Phi(H_* xi; theta(theta^*)),

where ``theta(theta^*)`` expresses the punch parameters through their scaled ("starred")
counterparts.  For the elliptic paraboloid (1.1), ``R_j = R_j^*/epsilon = Lambda R_j^*`` and
Phi^* reproduces (2.13).  A punch without a scaling map keeps its parameters, and then
Lambda stays visible in Phi^*.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any, ClassVar

import mpmath
import numpy as np

from .. import symbols as S
from .._lazy import lazy_function, lazy_module
from ..display import fmt
from ..errors import InputTypeError, WorkLimitError, boundary_methods
from ..parse import MAX_PARAMETERS, ExpressionError, as_expr, check_cost, expression_cost, parse_expression, sympy_value
from .base import LevelSet, PunchError, Tip, TipKind, TipParameter, points, positive_depth, register_tip

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it
normal_latex = lazy_function("thinlayer.normal", "normal_latex")  # the printers subclass sympy's


class PunchTooLargeError(PunchError, WorkLimitError):
    """A punch whose degree, terms or parameters exceed a documented limit (refused before any work)."""


#: Most terms of a punch once expanded, and its largest total degree in all symbols (coordinates and parameters).
#: Measured on 2 cores at load 12 (about 3x an idle machine): Punch.general(20), 230 terms of degree 21, inner
#: expansion 4 s; x_1**2 (a+b)**58 + x_2**2 (degree 60) force law 9 s; x_1**2 (a+b+c+d+e)**8 (495 terms)
#: force law 40 s and the punch itself 8 s; (x_1**2 + x_2**2)(a+...+j)**3 (440 terms) over 300 s.
MAX_TERMS = 300
MAX_TOTAL_DEGREE = 60

#: Largest total degree of a punch.  Measured: the inner expansion of a degree-40 punch (21 terms) takes
#: 3.0 s with a symbolic nu (10.8 s at degree 60), 0.55 s with nu = 3/10.
MAX_DEGREE = 40


def _plain_positive(x: Any) -> bool:
    """Whether ``x`` is a plain positive number (an int below 2^53 or a float in [1e-150, 1e150], not a bool): a
    radius whose curvature ``1/(2R)`` is the float the symbolic route gives; any other value goes that route.
    """
    if isinstance(x, bool):
        return False
    if isinstance(x, int):
        return 0 < x < 2**53
    return isinstance(x, float) and 1e-150 <= x <= 1e150


def _degree_bound(expr: sp.Expr) -> int:
    """An upper bound of the total degree in (x1, x2), read off the expression tree without expanding it."""
    if expr in (S.x1, S.x2):
        return 1
    if isinstance(expr, sp.Add):
        return max((_degree_bound(a) for a in expr.args), default=0)
    if isinstance(expr, sp.Mul):
        return sum(_degree_bound(a) for a in expr.args)
    if isinstance(expr, sp.Pow) and expr.exp.is_Integer and expr.exp > 0:
        return int(expr.exp) * _degree_bound(expr.base)
    return 0


@boundary_methods
@dataclass(frozen=True)
class Punch(Tip):
    """A rigid punch ``x3 = -Phi(x1, x2)`` with polynomial Phi (1.1).

    Parameters
    ----------
    expr : sympy.Expr
        Phi as a sympy expression (or string), polynomial in ``x1, x2`` of total degree at most
        :data:`MAX_DEGREE` = 40 (checked before the polynomial is built; the inner expansion of a degree-40
        punch takes 3.0 s with a symbolic nu).
    x1, x2 : sympy.Symbol
        The coordinate symbols used in ``expr`` (default: the canonical ``thinlayer.symbols.x1, x2``).
    scaling : tuple
        Optional mapping ``{parameter: expression in starred parameters and Lambda}`` defining
        the scaled form (1.2).  Default: none.
    name : str
        A label for reports.

    Examples
    --------
    >>> from thinlayer import Punch
    >>> p = Punch.elliptic_paraboloid()
    >>> p.parameters
    (R_1, R_2)
    >>> p.degree
    2
    """

    #: the paper's equation this result reproduces
    equation: ClassVar[str] = "1.1"

    expr: sp.Expr
    scaling: tuple = ()
    name: str = "punch"
    _poly: sp.Poly = field(default=None, repr=False, compare=False)
    #: a catalogue punch with numbers for its radii: ``("paraboloid", R)`` or ``("elliptic", R1, R2)``.  Its Phi
    #: (``expr``, ``polynomial``) is built on first use; the numeric questions (``quadric``, ``sphere_radius``,
    #: ``axisymmetric``, ``profile``, ``parameters``) are answered from the numbers, without sympy (issue 28 item 6)
    _spec: tuple | None = field(default=None, repr=False, compare=False)

    def __init__(self, expr, x1: sp.Symbol | None = None, x2: sp.Symbol | None = None, scaling: dict | None = None,
                 name: str = "punch"):
        x1 = S.x1 if x1 is None else x1
        x2 = S.x2 if x2 is None else x2
        if isinstance(expr, str):
            try:
                expr = parse_expression(expr, what="punch")
            except ExpressionError as exc:
                raise (PunchTooLargeError if isinstance(exc, WorkLimitError) else PunchError)(
                    f"the punch: {exc}") from None
        if expr is None or isinstance(expr, (bool, bytes)):
            raise PunchError(f"the punch must be a polynomial in x_1, x_2 (a sympy expression or a string such as "
                             f"'x_1**2/2 + x_2**2/2'), got {expr!r}")
        try:
            expr = as_expr(expr, "the punch")
        except (TypeError, ValueError) as exc:
            raise PunchError(str(exc)) from None
        if not isinstance(x1, sp.Symbol) or not isinstance(x2, sp.Symbol) or x1 == x2:
            raise PunchError(f"x1 and x2 must be two different sympy Symbols, got {x1!r}, {x2!r}")
        # the user's coordinates may be any symbols (also unassumed ones): map onto the canonical ones
        expr = expr.xreplace({x1: S.x1, x2: S.x2})
        if _degree_bound(expr) <= 4 * MAX_DEGREE:  # (a degree above it is refused below, naming x_1, x_2)
            try:
                cost = expression_cost(expr)
                check_cost(expr, "punch", cost=cost)  # a sympy expression given directly: the limits of a string
            except WorkLimitError as exc:
                raise PunchTooLargeError(str(exc)) from None
            for value, limit, what in ((cost.terms, MAX_TERMS, "terms once expanded"),
                                       (cost.degree, MAX_TOTAL_DEGREE, "as total degree in x_1, x_2 and its "
                                                                       "parameters")):
                if value > limit:
                    raise PunchTooLargeError(
                        f"the punch has {value} {what}, above the limit {limit} of a punch: deriving its force law "
                        f"then takes minutes (Punch.general(20), 230 terms of degree 21, is the largest measured "
                        "in seconds); give numbers for some parameters (Punch.subs) or a smaller polynomial")
        if expr.has(sp.zoo, sp.oo, sp.nan):
            raise PunchError(f"the punch expression {expr} is not finite")
        if not expr.is_polynomial(S.x1, S.x2):
            bad = [a for a in sp.preorder_traversal(expr)
                   if isinstance(a, (sp.Function, sp.Pow)) and a.has(S.x1, S.x2)
                   and not (isinstance(a, sp.Pow) and a.exp.is_Integer and a.exp >= 0)]
            what = f" (offending part: {bad[0]})" if bad else ""
            raise PunchError(
                f"the punch Phi = {expr} is not a polynomial in {x1}, {x2}{what}; thinlayer needs "
                "Phi(x1, x2) = sum c_ij x1^i x2^j with coefficients free of x1, x2"
            )
        bound = _degree_bound(expr)
        if bound > MAX_DEGREE:  # before sp.Poly, whose dense form of x_1**100000 alone is huge
            deg = sp.Poly(expr, S.x1, S.x2).total_degree() if bound <= 4 * MAX_DEGREE else bound
            if deg > MAX_DEGREE:
                raise PunchTooLargeError(f"the punch has degree {deg} in x_1, x_2, above the limit {MAX_DEGREE}: "
                                         "the inner expansion of a degree-40 punch already takes 3 s with a "
                                         "symbolic nu; give a polynomial of lower degree")
        poly = sp.Poly(expr, S.x1, S.x2)
        if poly.total_degree() < 1:
            raise PunchError(f"the punch Phi = {expr} is constant; it must depend on {x1} or {x2}")
        sc = tuple(sorted(((as_expr(k), as_expr(v)) for k, v in (scaling or {}).items()), key=lambda kv: str(kv[0])))
        for k, _ in sc:
            if not isinstance(k, sp.Symbol) or k not in expr.free_symbols:
                raise PunchError(f"scaling key {k!r} is not a parameter of the punch {expr}")
        object.__setattr__(self, "expr", expr)
        object.__setattr__(self, "scaling", sc)
        object.__setattr__(self, "name", name)
        object.__setattr__(self, "_poly", poly)
        object.__setattr__(self, "_spec", None)

    @classmethod
    def _from_radii(cls, spec: tuple, name: str) -> "Punch":
        """A catalogue punch with plain positive numbers for its radii, its Phi built on first use (``_spec``)."""
        obj = object.__new__(cls)
        for key, value in (("scaling", ()), ("name", name), ("_poly", None), ("_spec", spec)):
            object.__setattr__(obj, key, value)
        return obj

    def __getattr__(self, attr: str) -> Any:
        """``expr`` of a catalogue punch built from its numbers (:meth:`_from_radii`), on first use."""
        spec = self.__dict__.get("_spec")
        if attr != "expr" or spec is None:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {attr!r}")
        if spec[0] == "paraboloid":
            expr = (S.x1**2 + S.x2**2) / (2 * as_expr(spec[1]))
        else:
            expr = S.x1**2 / (2 * as_expr(spec[1])) + S.x2**2 / (2 * as_expr(spec[2]))
        built = Punch(expr, name=self.name)
        object.__setattr__(self, "expr", built.expr)
        object.__setattr__(self, "_poly", built.polynomial)
        return built.expr

    @property
    def formula_text(self) -> str | None:
        """Phi of the catalogue kind in Unicode maths with its symbolic radii (``(x₁² + x₂²)/(2R)``), as
        :func:`thinlayer.normal.normal_text` prints it (a test holds them equal), for a catalogue punch with numbers;
        None otherwise.  ``thinlayer solve`` prints it beside the values without loading the printer.
        """
        return None if self._spec is None else CATALOGUE_TEXT[self._spec[0]]

    @property
    def formula_values(self) -> dict[str, float]:
        """The radii of :attr:`formula_text` with their numbers (``{"R": 10}``, ``{"R1": 10, "R2": 5}``), empty for
        a punch that is not a catalogue punch with numbers.
        """
        spec = self._spec
        if spec is None:
            return {}
        return {"R": spec[1]} if spec[0] == "paraboloid" else {"R1": spec[1], "R2": spec[2]}

    def _spec_coefficients(self) -> tuple[float, float] | None:
        """``(c1, c2)`` of ``Phi = c1 x1^2 + c2 x2^2`` of a catalogue punch with numbers (``c = 1/(2R)``), else None."""
        spec = self._spec
        if spec is None:
            return None
        r1, r2 = (spec[1], spec[1]) if spec[0] == "paraboloid" else spec[1:]
        return 1 / (2 * r1), 1 / (2 * r2)

    # ---- catalogue (models) ------------------------------------------------------------
    @classmethod
    def elliptic_paraboloid(cls, R1=None, R2=None) -> "Punch":
        """``Phi = x1^2/(2 R1) + x2^2/(2 R2)`` (1.1); symbols R_1, R_2 when not given."""
        if _plain_positive(R1) and _plain_positive(R2):  # numbers: Phi is built on first use (issue 28 item 6)
            return cls._from_radii(("elliptic", R1, R2), "elliptic paraboloid")
        r1 = sp.Symbol("R_1", positive=True) if R1 is None else as_expr(R1)
        r2 = sp.Symbol("R_2", positive=True) if R2 is None else as_expr(R2)
        for nm, r in (("R1", r1), ("R2", r2)):
            if r.is_number and not r > 0:
                raise PunchError(f"{nm} must be positive, got {r}")
        scaling = {r: S.Lambda * S.starred(r) for r in (r1, r2) if isinstance(r, sp.Symbol)}
        return cls(S.x1**2 / (2 * r1) + S.x2**2 / (2 * r2), scaling=scaling, name="elliptic paraboloid")

    @classmethod
    def paraboloid(cls, R=None) -> "Punch":
        """Paraboloid of revolution ``Phi = (x1^2 + x2^2)/(2R)``."""
        if _plain_positive(R):  # a number: Phi is built on first use (issue 28 item 6)
            return cls._from_radii(("paraboloid", R), "paraboloid of revolution")
        r = sp.Symbol("R", positive=True) if R is None else as_expr(R)
        scaling = {r: S.Lambda * S.starred(r)} if isinstance(r, sp.Symbol) else {}
        return cls((S.x1**2 + S.x2**2) / (2 * r), scaling=scaling, name="paraboloid of revolution")

    @classmethod
    def flat(cls, a) -> Tip:
        """Flat-ended cylinder of radius ``a`` (not a polynomial: a :class:`~thinlayer.punch.FlatPunch`), (F.1).

        ``thinlayer.solve`` answers it by the flat-punch models of :mod:`thinlayer.contact.flat_punch`.
        """
        from .flat import FlatPunch

        return FlatPunch(a)

    @classmethod
    def cone(cls, half_angle=None) -> Tip:
        """Cone ``Phi = r cot(alpha)``, half-angle in degrees (:class:`~thinlayer.punch.Cone`)."""
        from .cone import Cone

        return Cone(half_angle)

    @classmethod
    def sphere(cls, R=None) -> Tip:
        """Exact sphere ``Phi = R - sqrt(R^2 - r^2)`` (:class:`~thinlayer.punch.Sphere`)."""
        from .sphere import Sphere

        return Sphere(R)

    @classmethod
    def blunted_cone(cls, R=None, half_angle=None) -> Tip:
        """Cone with a spherical apex, tangent join (:class:`~thinlayer.punch.BluntedCone`), angle in degrees."""
        from .blunted_cone import BluntedCone

        return BluntedCone(R, half_angle)

    @classmethod
    def power_law(cls, C=None, n=None) -> Tip:
        """``Phi = C r^n``, real ``n >= 1`` (:class:`~thinlayer.punch.PowerLaw`)."""
        from .power_law import PowerLaw

        return PowerLaw(C, n)

    @classmethod
    def revolution(cls, expr) -> Tip:
        """A profile ``Phi(r)`` read by the restricted grammar (:class:`~thinlayer.punch.Revolution`)."""
        from .revolution import Revolution

        return Revolution(expr)

    @classmethod
    def pyramid(cls, half_angle=None, sides=4) -> Tip:
        """Regular pyramid of 3 or 4 faces, face angle (axis to face) in degrees (:class:`~thinlayer.punch.Pyramid`)."""
        from .pyramid import Pyramid

        return Pyramid(half_angle, sides)

    @classmethod
    def berkovich(cls) -> Tip:
        """The modified Berkovich pyramid: 3 faces at 65.27 degrees from the axis (projected area 24.5 delta0^2; the
        original Berkovich angle 65.03 is ``Punch.pyramid(65.03, sides=3)``).
        """
        from .pyramid import BERKOVICH_ANGLE, Pyramid

        return Pyramid(BERKOVICH_ANGLE, 3)

    @classmethod
    def vickers(cls) -> Tip:
        """The Vickers pyramid: 4 faces, 136 degrees between opposite faces, i.e. 68 degrees from the axis to a face."""
        from .pyramid import VICKERS_ANGLE, Pyramid

        return Pyramid(VICKERS_ANGLE, 4)

    @classmethod
    def from_expr(cls, text) -> Tip:
        """A tip from a formula in ``x1, x2`` read by the restricted grammar: a polynomial punch, or a polyhedral tip
        (:class:`~thinlayer.punch.Polyhedral`) when the formula takes ``max(...)`` of linear forms.
        """
        from ..parse import parse_expression
        from .pyramid import Polyhedral

        expr = parse_expression(text, what="tip") if isinstance(text, str) else text
        if isinstance(expr, sp.Basic) and expr.has(sp.Max, sp.Min):
            return Polyhedral(expr)
        return cls(expr)

    @classmethod
    def fourth_degree(cls, R=None, K=None) -> "Punch":
        """Fourth-degree paraboloid ``Phi = (x1^2 + x2^2)/(2R) + (x1^2 + x2^2)^2/K^3`` (section 5)."""
        r = sp.Symbol("R", positive=True) if R is None else as_expr(R)
        k = sp.Symbol("K", positive=True) if K is None else as_expr(K)
        rr = S.x1**2 + S.x2**2
        return cls(rr / (2 * r) + rr**2 / k**3, name="fourth-degree paraboloid")

    @classmethod
    def general(cls, degree: int, prefix: str = "c") -> "Punch":
        """The general polynomial of a degree: ``sum_{1 <= i+j <= degree} c_{ij} x1^i x2^j`` with symbolic c_ij."""
        if isinstance(degree, bool) or not isinstance(degree, int) or degree < 1:
            raise PunchError(f"degree must be a positive integer, got {degree!r}")
        if degree > MAX_DEGREE:
            raise PunchTooLargeError(f"degree = {degree} exceeds the limit {MAX_DEGREE} of a punch (the inner "
                                     "expansion of a degree-40 punch takes 3 s with a symbolic nu)")
        count = (degree + 1) * (degree + 2) // 2 - 1
        if count > MAX_PARAMETERS:
            raise PunchTooLargeError(f"degree = {degree} gives {count} coefficients, above the limit {MAX_PARAMETERS} "
                                     "of parameters (degree <= 20: 230 coefficients, the inner expansion takes 4 s "
                                     "with a symbolic nu; degree 40 took 74 s)")
        terms = [sp.Symbol(f"{prefix}_{i}{j}" if degree < 10 else f"{prefix}_{i},{j}") * S.x1**i * S.x2**j
                 for i in range(degree + 1) for j in range(degree + 1 - i) if i + j]
        return cls(sp.Add(*terms), name=f"general polynomial of degree {degree}")

    # ---- properties --------------------------------------------------------------------
    @property
    def degree(self) -> int:
        """Total degree in (x1, x2)."""
        return 2 if self._spec is not None else self.polynomial.total_degree()

    @property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """Free symbols other than x1, x2, sorted by name."""
        if self._spec is not None:
            return ()
        return tuple(sorted(self.expr.free_symbols - {S.x1, S.x2}, key=lambda q: q.name))

    def laplacian(self, power: int = 1) -> sp.Expr:
        """``Delta^power Phi`` in (x1, x2), computed on the polynomial representation."""
        p = self.polynomial
        for _ in range(power):
            p = p.diff(S.x1).diff(S.x1) + p.diff(S.x2).diff(S.x2)
        return p.as_expr()

    def subs(self, values: Mapping) -> "Punch":
        """A new punch with parameters replaced (scaling entries of replaced parameters dropped).

        ``values`` maps a parameter (its name or its Symbol) to a number, a sympy expression or a string, which is
        read by the restricted grammar (:func:`thinlayer.parse.parse_expression`), never evaluated.
        """
        if not isinstance(values, Mapping):
            raise InputTypeError(f"the punch's parameter values must be a dict such as {{'R': 10}}, got "
                                 f"{type(values).__name__}")
        by_name = {q.name: q for q in self.parameters}
        out = {}
        for k, v in values.items():
            key = by_name.get(k) if isinstance(k, str) else k if isinstance(k, sp.Symbol) else None
            if key is None or key not in self.parameters:
                raise PunchError(f"{k!r} is not a parameter of the punch; its parameters are "
                                 f"{', '.join(by_name) or 'none'}")
            try:
                out[key] = parse_expression(v, what=f"the value of {key.name}") if isinstance(v, str) \
                    else check_cost(as_expr(v, f"the value of {key.name}"), f"the value of {key.name}")
            except WorkLimitError as exc:
                raise PunchTooLargeError(str(exc)) from None
            except (TypeError, ValueError) as exc:
                raise PunchError(str(exc)) from None
        sc = {k: v for k, v in self.scaling if k not in out}
        return Punch(self.expr.xreplace(out), scaling=sc, name=self.name)

    def scaled(self, Hs: sp.Expr | None = None, v1: sp.Symbol | None = None, v2: sp.Symbol | None = None) -> sp.Expr:
        """Phi^*(xi) = Lambda Phi(H_* xi; theta(theta^*)) (1.2), (2.13); by default in ``H_*``, ``xi_1``, ``xi_2``."""
        Hs, v1, v2 = (S.H_s if Hs is None else Hs), (S.xi1 if v1 is None else v1), (S.xi2 if v2 is None else v2)
        Hs, v1, v2 = sympy_value(Hs, "Hs"), sympy_value(v1, "v1", symbol=True), sympy_value(v2, "v2", symbol=True)
        e = self.expr.xreplace({S.x1: Hs * v1, S.x2: Hs * v2}).xreplace(dict(self.scaling))
        return sp.expand(S.Lambda * e)

    # ---- the tip protocol (thinlayer.punch.base.Tip) --------------------------------------
    @property
    def kind(self) -> str:
        """The catalogue entry the punch was built from (:data:`~thinlayer.punch.TIPS` key), else ``"polynomial"``."""
        return _KIND_OF_NAME.get(self.name, "polynomial")

    @property
    def description(self) -> str:
        """One phrase for result summaries: the name and Phi."""
        return f"{self.name} Phi = {self.expr}"

    @property
    def is_polynomial(self) -> bool:
        """True: Phi is a polynomial (answered without building it)."""
        return True

    @property
    def polynomial(self) -> sp.Poly:
        """Phi as a ``sympy.Poly`` in ``(x1, x2)``; its coefficients hold the parameters."""
        if self._poly is None:
            self.expr  # noqa: B018 - a catalogue punch with numbers builds Phi and its polynomial on first use
        return self._poly

    @property
    def axisymmetric(self) -> bool:
        """Whether ``x1 dPhi/dx2 - x2 dPhi/dx1 = 0`` identically (Phi depends on ``r`` only); the one place the
        axisymmetry of a polynomial punch is decided.
        """
        c = self._spec_coefficients()
        if c is not None:
            return c[0] == c[1]
        return _axisymmetric(self.expr)

    @property
    def smoothness(self) -> str:
        """``"smooth"``: a polynomial."""
        return "smooth"

    @property
    def max_inner_order(self) -> None:
        """None: the inner series (2.26) of a polynomial terminates, every order exists."""
        return None

    @property
    def fixed_contact(self) -> bool:
        """False: the contact grows with the depth."""
        return False

    @property
    def quadric(self) -> tuple[float, float, float] | None:
        """``(k1, k2, angle)`` with ``k1 <= k2`` the eigenvalues of K in ``Phi = x.Kx/2`` (``1/R1``, ``1/R2``) and the
        angle of the eigenvector of ``k1``, when Phi is a numeric positive-definite quadratic form; else None.
        """
        c = self._spec_coefficients()
        if c is not None:  # the same numbers as _quadric of Phi: a11 = 2 c1, a22 = 2 c2, a12 = 0
            return _quadric_of(2 * c[0], 2 * c[1], 0.0)
        return _quadric(self.expr) if self.is_numeric else None

    @property
    def sphere_radius(self) -> float | None:
        """``R`` when ``Phi = (x1^2 + x2^2)/(2R)`` exactly (numeric ``R > 0``); else None."""
        c = self._spec_coefficients()
        if c is not None:
            return 1.0 / (2.0 * c[0]) if c[0] == c[1] else None
        if not self.is_numeric:
            return None
        terms = dict(self.polynomial.terms())
        if set(terms) != {(2, 0), (0, 2)} or terms[(2, 0)] != terms[(0, 2)] or not terms[(2, 0)] > 0:
            return None
        return 1.0 / (2.0 * float(terms[(2, 0)]))

    def profile(self, x1: Any, x2: Any) -> np.ndarray:
        """Phi at the points ``(x1, x2)`` (numpy, broadcast); needs a numeric punch."""
        self._need_numbers("its profile")
        x1, x2 = points(x1, "x1"), points(x2, "x2")
        c = self._spec_coefficients()
        out = c[0] * x1**2 + c[1] * x2**2 if c is not None else _compiled(self.expr)(x1, x2)
        return np.asarray(out, dtype=float) + np.zeros(np.broadcast(x1, x2).shape)

    def level_set(self, delta0: Any) -> LevelSet | None:
        """The integrals of the force law over ``{Phi < delta0}`` (:class:`~thinlayer.punch.LevelSet`): closed form
        for a positive-definite quadric (an ellipse of semi-axes ``sqrt(2 delta0/k_i)``), exact integration of the
        radial polynomial for an axisymmetric punch, None for a general non-axisymmetric polynomial (the contour
        stages compute those).  Needs a numeric punch.
        """
        self._need_numbers("its level set")
        d = positive_depth(delta0)
        q = self.quadric
        if q is not None:
            return _quadric_level_set(q[0], q[1], d)
        if self.axisymmetric:
            return _radial_level_set(self.expr, d)
        return None

    def _need_numbers(self, what: str) -> None:
        if not self.is_numeric:
            raise PunchError(f"{what} needs numbers for the parameters {', '.join(q.name for q in self.parameters)} "
                             "of the punch: use Punch.subs({...})")

    def latex(self) -> str:
        return rf"\Phi(x_1, x_2) = {normal_latex(self.expr)} \tag{{1.1}}"

    def lambdify(self, args=None, backend: str = "numpy"):
        """Numeric Phi; default argument order ``(x1, x2, *parameters)``."""
        from ..results import checked_lambdify

        args = (S.x1, S.x2, *self.parameters) if args is None else args
        return checked_lambdify(args, self.expr, backend)

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """``Phi(x1, x2, *parameters)`` (1.1) as the one output."""
        return (S.x1, S.x2, *self.parameters), {"Phi": self.expr}

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        pars = ", ".join(q.name for q in self.parameters) or "none"
        return [f"Punch ({self.name}): Φ(x₁, x₂) = {fmt(self.expr)}   (1.1)",
                f"  degree {self.degree}, parameters: {pars}"]




# =============================================================================================
# shape questions, cached by Phi
# =============================================================================================
#: Phi of the catalogue punches with symbolic radii as :func:`thinlayer.normal.normal_text` prints it
#: (tests/contact/test_cold_start.py holds them equal to the printer's output)
CATALOGUE_TEXT = {"paraboloid": "(x₁² + x₂²)/(2R)", "elliptic": "x₂²/(2R₂) + x₁²/(2R₁)"}
#: the kind of the catalogue punches, by the name the catalogue gives them
_KIND_OF_NAME = {"paraboloid of revolution": "paraboloid", "elliptic paraboloid": "elliptic_paraboloid",
                 "fourth-degree paraboloid": "fourth_degree"}


@lru_cache(maxsize=512)
def _axisymmetric(expr: sp.Expr) -> bool:
    e = sp.expand(expr)
    return bool(sp.expand(S.x1 * sp.diff(e, S.x2) - S.x2 * sp.diff(e, S.x1)) == 0)


@lru_cache(maxsize=512)
def _quadric(expr: sp.Expr) -> tuple[float, float, float] | None:
    poly = sp.Poly(sp.expand(expr), S.x1, S.x2)
    if poly.total_degree() != 2 or not all(sum(m) == 2 for m in poly.monoms()):
        return None
    a11 = float(poly.coeff_monomial(S.x1**2)) * 2
    a22 = float(poly.coeff_monomial(S.x2**2)) * 2
    a12 = float(poly.coeff_monomial(S.x1 * S.x2))
    return _quadric_of(a11, a22, a12)


def _quadric_of(a11: float, a22: float, a12: float) -> tuple[float, float, float] | None:
    """``(k1, k2, angle)`` of the positive-definite form ``[[a11, a12], [a12, a22]]`` (:attr:`Punch.quadric`)."""
    lam, vec = np.linalg.eigh(np.array([[a11, a12], [a12, a22]]))
    if not lam.min() > 0:
        return None
    return float(lam[0]), float(lam[1]), float(math.atan2(vec[1, 0], vec[0, 0]))


@lru_cache(maxsize=64)
def _compiled(expr: sp.Expr):
    return sp.lambdify((S.x1, S.x2), expr, "numpy")


def _quadric_level_set(k1: float, k2: float, d: float) -> LevelSet:
    """The ellipse ``k1 y1^2/2 + k2 y2^2/2 < d``: semi-axes ``A = sqrt(2d/k1) >= B = sqrt(2d/k2)`` (3.1)."""
    A, B = math.sqrt(2 * d / k1), math.sqrt(2 * d / k2)
    area = math.pi * A * B
    volume = area * d / 2  # iint (d - Phi) over the ellipse: the mean of d - Phi is d/2
    if k1 == k2:
        perimeter, radius, second = 2 * math.pi * A, A, 3 * k1 * 2 * math.pi * A  # Laplacian + Phi_nn = 3k
    else:
        perimeter, radius, second = float(4 * A * mpmath.ellipe(1 - (B / A) ** 2)), None, None
    flux = (k1 + k2) * area  # iint Laplacian Phi
    return LevelSet(area, volume, perimeter, flux, 2 * area / perimeter, radius, second)


def _radial_level_set(expr: sp.Expr, d: float) -> LevelSet:
    """``{g(t) < d}``, ``t = r^2``, ``g(t) = Phi(sqrt t, 0)``: a union of annuli bounded by the real roots of
    ``g - d`` (mpmath at 30 digits); area, volume, flux and the second-order flux integrate the polynomial ``g``
    exactly over them (``dx = pi dt``).
    """
    t = sp.Symbol("t", nonnegative=True)
    g = sp.Poly(sp.expand(expr.xreplace({S.x2: 0})).xreplace({S.x1: sp.sqrt(t)}), t)
    with mpmath.workdps(30):
        co = [mpmath.mpf(str(sp.N(c, 35))) for c in g.all_coeffs()]  # highest power first
        n = len(co) - 1

        def value(x, k=0):  # the k-th derivative of g at x
            return mpmath.polyval([c * mpmath.ff(n - i, k) for i, c in enumerate(co[: n + 1 - k])], x)

        if co[0] < 0:
            raise PunchError(f"the level set {{Phi < {d:g}}} of Phi = {expr} is unbounded: the tip falls away")
        roots = mpmath.polyroots(co[:-1] + [co[-1] - d], maxsteps=200, extraprec=120)
        cuts = sorted({mpmath.re(z) for z in roots if abs(mpmath.im(z)) <= 1e-20 * (1 + abs(z)) and mpmath.re(z) > 0})
        edges = [mpmath.mpf(0), *cuts]
        ivals = [(lo, hi) for lo, hi in zip(edges, cuts) if value((lo + hi) / 2) < d]
        prim = [c / (n - i + 1) for i, c in enumerate(co)] + [mpmath.mpf(0)]  # the antiderivative of g
        area = volume = perimeter = flux = second = mpmath.mpf(0)
        for lo, hi in ivals:
            area += mpmath.pi * (hi - lo)
            volume += mpmath.pi * (d * (hi - lo) - (mpmath.polyval(prim, hi) - mpmath.polyval(prim, lo)))
            for x in (lo, hi):
                if x > 0:
                    r = mpmath.sqrt(x)
                    perimeter += 2 * mpmath.pi * r
                    flux += 4 * mpmath.pi * x * abs(value(x, 1))  # 2 pi r |dPhi/dr|, dPhi/dr = 2 r g'(t)
                    second += 2 * mpmath.pi * r * (6 * value(x, 1) + 8 * x * value(x, 2))  # Laplacian + Phi_nn
        radius = float(mpmath.sqrt(ivals[0][1])) if len(ivals) == 1 and ivals[0][0] == 0 else None
        half = float(2 * area / perimeter) if perimeter > 0 else 0.0
        return LevelSet(float(area), float(volume), float(perimeter), float(flux), half, radius, float(second))


# =============================================================================================
# registry rows
# =============================================================================================
def _polynomial(expr) -> Punch:
    """A polynomial punch from its formula (read by the restricted grammar)."""
    return Punch(expr)


_LENGTH = "length"
register_tip(TipKind("paraboloid", Punch.paraboloid, (
    TipParameter("R", _LENGTH, "radius of curvature at the apex", ("radius",)),),
    "paraboloid of revolution Phi = (x1^2 + x2^2)/(2R) (1.1)"))
register_tip(TipKind("elliptic_paraboloid", Punch.elliptic_paraboloid, (
    TipParameter("R1", _LENGTH, "radius of curvature along x1", ("R_1",)),
    TipParameter("R2", _LENGTH, "radius of curvature along x2", ("R_2",))),
    "elliptic paraboloid Phi = x1^2/(2 R1) + x2^2/(2 R2) (1.1)"))
register_tip(TipKind("fourth_degree", Punch.fourth_degree, (
    TipParameter("R", _LENGTH, "radius of curvature at the apex", ("radius",)),
    TipParameter("K", _LENGTH, "length of the quartic term (x1^2 + x2^2)^2/K^3")),
    "fourth-degree paraboloid Phi = r^2/(2R) + r^4/K^3 (section 5)"))
register_tip(TipKind("polynomial", _polynomial, (
    TipParameter("expr", "expression", "formula Phi(x_1, x_2)", ("Phi",), required=True),),
    "any polynomial Phi(x1, x2), read by the restricted grammar (1.1)"))
