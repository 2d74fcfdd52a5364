r"""Polyhedral tips ``Phi = max_k g_k . x`` (issue 24): the regular pyramid (3 or 4 faces, Berkovich, Vickers) and
any convex polyhedral cone with its apex at the origin, read from ``max(...)`` of linear forms.

Geometry.  A face of the pyramid of face angle ``alpha`` (the angle between the axis and a FACE) with outward
in-plane normal ``n_k`` is ``x3 = -cot(alpha) n_k . x``, so

    Phi(x) = cot(alpha) max_k n_k . x,      n_k = (cos t_k, sin t_k),      t_k = -pi/2 + 2 pi k/N   (N = 3, 4)

(orientation: one face normal to -x2 for N = 3; faces normal to +-x1, +-x2 for N = 4).  The level set
``{Phi < delta0}`` is the regular N-gon of inradius ``rho = delta0 tan(alpha)``.  Split into N triangular sectors
(distance s from the apex along n_k, half-width ``s tan(pi/N)`` across), :meth:`Pyramid.level_set_expressions`
integrates (sympy, not transcribed):

    |omega0| = N int_0^rho 2 s tan(pi/N) ds = N rho^2 tan(pi/N),
    V        = N int_0^rho (delta0 - s cot(alpha)) 2 s tan(pi/N) ds = |omega0| delta0/3,
    |Gamma0| = 2 N rho tan(pi/N),       J = oint |grad Phi| ds = cot(alpha) |Gamma0| = 2 N tan(pi/N) delta0.

The general polyhedral tip computes the same numbers from its polygon (polar dual of the hull of the g_k, scipy),
which is the independent route the tests compare with.

Inner order (2.26).  Phi is linear on each face, so the Laplacian vanishes there; across a ridge (between faces k and
k+1) grad Phi jumps by ``cot(alpha) (n_{k+1} - n_k)``, of length ``2 cot(alpha) sin(pi/N)``.  In the sense of
distributions ``Laplacian Phi = sum_ridges 2 cot(alpha) sin(pi/N) delta_ridge``: a line measure whose mass in a
disc of radius r is O(r), as the cone's ``cot(alpha)/r`` (a measure, the force integral of ``p_1`` exists).  The
divergence theorem holds for it: the ridges reach the contour at the N corners, at distance ``rho/cos(pi/N)``, so

    iint_{omega0} Laplacian Phi = N 2 cot(alpha) sin(pi/N) rho/cos(pi/N) = cot(alpha) |Gamma0| = J

(checked in tests/punch/test_pyramid.py, exactly and against a mollified Laplacian by quadrature).  ``Laplacian^2 Phi``
is ``delta''`` across each ridge: no measure, so ``p_2`` has no force integral -- the inner expansion holds to order 1
(:attr:`Polyhedral.max_inner_order` = 1), as for the cone.  Smoothness ``"ridge"``.
"""
from __future__ import annotations

import math
import numbers
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, ClassVar

import numpy as np
import sympy as sp

from .. import symbols as S
from ..display import fmt
from ..errors import InputTypeError, WorkLimitError, boundary_methods
from ..parse import parse_expression, parse_number
from ._radial import angle_value
from .base import LevelSet, PunchError, Tip, TipKind, TipParameter, points, positive_depth, register_tip

__all__ = ["BERKOVICH_ANGLE", "BERKOVICH_ORIGINAL_ANGLE", "MAX_FACES", "VICKERS_ANGLE", "Polyhedral", "Pyramid"]

#: the modified Berkovich face angle (degrees, axis to face): its projected area 3 sqrt(3) tan^2(alpha) delta0^2
#: = 24.5 delta0^2 equals the Vickers pyramid's
BERKOVICH_ANGLE = sp.Rational(6527, 100)
#: the original Berkovich face angle (degrees), area 23.96 delta0^2
BERKOVICH_ORIGINAL_ANGLE = sp.Rational(6503, 100)
#: the Vickers face angle: 136 degrees between opposite faces, 68 degrees from the axis to a face
VICKERS_ANGLE = sp.Integer(68)
#: most faces of a polyhedral tip read from max(...) (each one a plane of the hull; beyond, a smooth tip is better)
MAX_FACES = 64


class PolyhedralError(PunchError):
    """A ``max(...)`` formula that is not a convex polyhedral tip with its apex at the origin."""


def _unit_normals(sides: int) -> list[tuple[sp.Expr, sp.Expr]]:
    """``n_k = (cos t_k, sin t_k)``, ``t_k = -pi/2 + 2 pi k/N``: exact for N = 3, 4."""
    return [(sp.cos(-sp.pi / 2 + 2 * sp.pi * k / sides), sp.sin(-sp.pi / 2 + 2 * sp.pi * k / sides))
            for k in range(sides)]


def _sides_value(sides: Any) -> int:
    if isinstance(sides, bool) or not isinstance(sides, (numbers.Integral, sp.Integer, str)):
        raise PunchError(f"the number of sides of a pyramid must be 3 or 4, got {sides!r:.40}")
    if isinstance(sides, str):
        try:
            sides = parse_number(sides, "the number of sides")
        except (TypeError, ValueError) as exc:
            raise PunchError(str(exc)) from None
    if sides not in (3, 4):
        raise PunchError(f"the number of sides of a pyramid must be 3 or 4, got {sides!r:.40}")
    return int(sides)


def _linear_planes(expr: sp.Expr) -> list[tuple[sp.Expr, sp.Expr]]:
    """The gradients ``(a_k, b_k)`` of ``Phi = max_k (a_k x1 + b_k x2)`` read off a formula, or a PolyhedralError."""
    def planes(e: sp.Expr) -> list[tuple[sp.Expr, sp.Expr]]:
        if isinstance(e, sp.Max):
            return [g for arg in e.args for g in planes(arg)]
        if isinstance(e, sp.Min):
            raise PolyhedralError("min(...) makes Phi concave there: a tip is a max of planes (convex), e.g. "
                                  "max(x1, -x1, x2, -x2)/2")
        if isinstance(e, sp.Mul):
            scale = [f for f in e.args if not f.has(S.x1, S.x2)]
            rest = [f for f in e.args if f.has(S.x1, S.x2)]
            c = sp.Mul(*scale)
            if len(rest) == 1 and isinstance(rest[0], sp.Max):
                if not (c.is_positive or (c.free_symbols and not c.is_negative)):
                    raise PolyhedralError(f"the factor {c} in front of max(...) must be positive")
                return [(c * a, c * b) for a, b in planes(rest[0])]
        if e.has(sp.Max, sp.Min):
            raise PolyhedralError(f"{e} is not a positive multiple of max(...) of linear forms")
        poly = sp.Poly(e, S.x1, S.x2) if e.is_polynomial(S.x1, S.x2) else None
        if poly is None or poly.total_degree() > 1:
            raise PolyhedralError(f"{e} is not a linear form in x1, x2")
        if poly.coeff_monomial(1) != 0:
            raise PolyhedralError(f"{e} has a constant term: a polyhedral tip has its apex at the origin, Phi(0) = 0 "
                                  "(write max(...) of forms a*x1 + b*x2)")
        return [(poly.coeff_monomial(S.x1), poly.coeff_monomial(S.x2))]

    out = planes(expr)
    if len(out) > MAX_FACES:
        raise type("PolyhedralTooLargeError", (PolyhedralError, WorkLimitError), {})(
            f"the tip has {len(out)} planes, above the limit {MAX_FACES}")
    return out


@lru_cache(maxsize=128)
def _float_planes(planes: tuple) -> tuple[tuple[float, float], ...]:
    """The plane gradients as floats (evaluated once per tip: sympy's evalf is slow)."""
    out = []
    for a, b in planes:
        fa, fb = float(a), float(b)
        if not (math.isfinite(fa) and math.isfinite(fb)):
            raise PunchError(f"the plane gradient ({a}, {b}) of a polyhedral tip is not finite")
        out.append((fa, fb))
    return tuple(out)


@lru_cache(maxsize=128)
def _polygon(grads: tuple[tuple[float, float], ...]) -> tuple[np.ndarray, np.ndarray]:
    """``(vertices, active)`` of the unit level set ``{max_k g_k . x < 1}``: its vertices counter-clockwise and, for
    the edge from vertex i to i+1, the index of its plane.  The polygon is the polar dual of the convex hull of the
    g_k: an edge per hull vertex, a vertex per hull edge.  A PolyhedralError when the origin is not inside the hull
    (then the level set is unbounded: Phi is not positive in some direction).
    """
    from scipy.spatial import ConvexHull, QhullError  # lazy: importing thinlayer.punch loads no scipy

    g = np.array(grads, dtype=float)
    try:
        hull = ConvexHull(g)
    except (QhullError, ValueError):
        raise PolyhedralError("the planes' gradients do not surround the origin (fewer than 3 planes, or collinear "
                              "gradients): the level set {Phi < delta0} is unbounded (a tip needs Phi > 0 in every "
                              "direction)") from None
    if not np.all(hull.equations[:, 2] < -1e-12 * np.abs(g).max()):
        raise PolyhedralError("Phi = max of the planes is not positive in every direction: the level set "
                              "{Phi < delta0} is unbounded (give planes whose gradients surround the origin)")
    idx = hull.vertices  # counter-clockwise in 2D
    verts = []
    for i, j in zip(idx, np.roll(idx, -1)):
        verts.append(np.linalg.solve(g[[i, j]], np.ones(2)))  # g_i.x = g_j.x = 1: the corner between edges i, j
    # the edge between corner (prev, i) and corner (i, next) lies on plane i: edge m runs from vertex m-1 to m
    verts = np.array(verts)
    return np.roll(verts, 1, axis=0), idx.copy()


@boundary_methods
@dataclass(frozen=True, init=False)
class Polyhedral(Tip):
    r"""A convex polyhedral tip with its apex at the origin, ``Phi = max_k (a_k x1 + b_k x2)``.

    Parameters
    ----------
    expr : str or sympy.Expr
        ``max(...)`` of linear forms in ``x1, x2`` (times a positive factor), read by the restricted grammar
        (:func:`thinlayer.parse.parse_expression`), never evaluated; e.g.
        ``"max(x1, -x1, x2, -x2)/2"`` (a 4-sided pyramid of face angle ``atan(2)``).  At most :data:`MAX_FACES`
        planes; their gradients must surround the origin (Phi > 0 in every direction).

    Examples
    --------
    >>> from thinlayer import Punch
    >>> tip = Punch.from_expr("max(x1, -x1, x2, -x2)")
    >>> tip.level_set(1.0).area
    4.0
    """

    values: tuple
    name: ClassVar[str] = "polyhedral tip"

    def __init__(self, expr: Any) -> None:
        if isinstance(expr, str):
            expr = parse_expression(expr, what="polyhedral tip")
        elif not isinstance(expr, sp.Expr):
            raise InputTypeError(f"a polyhedral tip is a max(...) formula (a string or sympy expression), got "
                                 f"{type(expr).__name__}")
        grads = _linear_planes(expr)
        object.__setattr__(self, "values", (("expr", expr), ("planes", tuple(grads))))
        if self.is_numeric:
            _polygon(self._numeric_gradients())  # refuses an unbounded level set now

    # ---- identity ---------------------------------------------------------------------------------
    @property
    def kind(self) -> str:
        """``"polyhedral"``."""
        return "polyhedral"

    @property
    def expr(self) -> sp.Expr:
        """Phi as a sympy expression (a ``Max`` of linear forms)."""
        return self.values[0][1]

    @property
    def planes(self) -> tuple[tuple[sp.Expr, sp.Expr], ...]:
        """The gradients ``(a_k, b_k)`` of the faces."""
        return self.values[1][1]

    @property
    def description(self) -> str:
        return f"{self.name} Phi = {self.expr}"

    @property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """The free symbols of Phi other than x1, x2, sorted by name."""
        return tuple(sorted(self.expr.free_symbols - {S.x1, S.x2}, key=lambda q: q.name))

    def subs(self, values: Mapping) -> Tip:
        """A new tip with parameters replaced (values read by the restricted grammar, never evaluated)."""
        if not isinstance(values, Mapping):
            raise InputTypeError(f"the tip's parameter values must be a dict, got {type(values).__name__}")
        names = {q.name: q for q in self.parameters}
        rep = {}
        for k, v in values.items():
            key = k.name if isinstance(k, sp.Symbol) else k
            if key not in names:
                raise PunchError(f"{k!r} is not a parameter of the {self.name}; its parameters are "
                                 f"{', '.join(sorted(names)) or 'none'}")
            try:
                rep[names[key]] = parse_number(v, f"the parameter {key}")
            except (TypeError, ValueError) as exc:
                raise PunchError(str(exc)) from None
        return Polyhedral(self.expr.xreplace(rep)) if rep else self

    # ---- shape ------------------------------------------------------------------------------------
    @property
    def axisymmetric(self) -> bool:
        """False: Phi has ridges in the directions of the polygon's corners."""
        return False

    @property
    def smoothness(self) -> str:
        """``"ridge"``: grad Phi jumps across the ridges (module docstring)."""
        return "ridge"

    @property
    def max_inner_order(self) -> int:
        """1: ``Laplacian Phi`` is a line measure on the ridges, ``Laplacian^2 Phi`` no measure (module docstring)."""
        return 1

    @property
    def homogeneity(self) -> int:
        """``Phi(t x) = t Phi(x)``: degree 1 (the remainder's apex and corner orders follow from it)."""
        return 1

    def _need_numbers(self, what: str) -> None:
        if not self.is_numeric:
            raise PunchError(f"{what} needs numbers for the parameters {', '.join(q.name for q in self.parameters)} "
                             f"of the {self.name}: use .subs({{...}})")

    def _numeric_gradients(self) -> tuple[tuple[float, float], ...]:
        return _float_planes(self.planes)

    # ---- numbers ----------------------------------------------------------------------------------
    def profile(self, x1: Any, x2: Any) -> np.ndarray:
        """``max_k (a_k x1 + b_k x2)`` at the points (numpy, broadcast)."""
        self._need_numbers("its profile")
        X, Y = np.broadcast_arrays(points(x1, "x1"), points(x2, "x2"))
        out = np.full(X.shape, -np.inf)
        with np.errstate(over="ignore", invalid="ignore"):
            for a, b in self._numeric_gradients():
                np.fmax(out, a * X + b * Y, out=out)  # fmax: 0 * inf is nan, not a maximum
        return out

    def polygon(self, delta0: Any) -> np.ndarray:
        """The vertices of the level set ``{Phi < delta0}``, counter-clockwise, shape ``(m, 2)``."""
        self._need_numbers("its level set")
        d = positive_depth(delta0)
        return d * _polygon(self._numeric_gradients())[0]

    def _polygon_level_set(self, d: float) -> LevelSet:
        verts, active = _polygon(self._numeric_gradients())
        g = np.array(self._numeric_gradients())
        v, w = d * verts, d * np.roll(verts, -1, axis=0)
        area = 0.5 * float(np.sum(v[:, 0] * w[:, 1] - w[:, 0] * v[:, 1]))
        lengths = np.hypot(*(w - v).T)
        perimeter = float(lengths.sum())
        flux = float(np.sum(lengths * np.hypot(*g[active].T)))  # |grad Phi| = |g_k| on edge k
        # Phi homogeneous of degree 1: |{Phi < t}| = area t^2/d^2, so V = int_0^d |{Phi < t}| dt = area d/3
        return LevelSet(area, area * d / 3.0, perimeter, flux, 2.0 * area / perimeter)

    def level_set(self, delta0: Any) -> LevelSet:
        """The level-set integrals from the polygon (module docstring)."""
        self._need_numbers("its level set")
        return self._polygon_level_set(positive_depth(delta0))

    # ---- display ----------------------------------------------------------------------------------
    def latex(self) -> str:
        return rf"\Phi(x_1, x_2) = {sp.latex(self.expr)} \tag{{{self.equation}}}"

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """``Phi(x1, x2, *parameters)`` as the one output."""
        return (S.x1, S.x2, *self.parameters), {"Phi": self.expr}

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        pars = ", ".join(q.name for q in self.parameters) or "none"
        return [f"{type(self).__name__} ({self.name}): Φ = {fmt(self.expr)}",
                f"  smoothness ridge, inner order 1, parameters: {pars}"]


@boundary_methods
@dataclass(frozen=True, init=False)
class Pyramid(Polyhedral):
    r"""A regular pyramid of ``sides`` = 3 or 4 faces and face angle alpha (between the axis and a FACE):
    ``Phi = cot(alpha) max_k n_k . x`` (module docstring; one face normal to -x2 for 3 sides, faces normal to
    +-x1, +-x2 for 4).

    Parameters
    ----------
    half_angle : number or str, optional
        The face angle in DEGREES, ``0 < alpha < 90`` (a string is read by the restricted grammar).  Left out, the
        symbol ``alpha`` (in degrees; the expressions carry ``pi alpha/180``) for a symbolic law.
        Not the edge angle (axis to ridge), which is larger.
    sides : int
        3 or 4.

    Examples
    --------
    >>> from thinlayer import Punch
    >>> round(Punch.vickers().level_set(1.0).area, 2)     # the Vickers area function 24.5 delta0^2
    24.5
    >>> Punch.pyramid(35, sides=4).max_inner_order
    1
    """

    name: ClassVar[str] = "pyramid"

    def __init__(self, half_angle: Any = None, sides: Any = 4) -> None:
        alpha = angle_value(half_angle, "face angle")
        n = _sides_value(sides)
        normals = _unit_normals(n)
        expr = sp.cot(alpha) * sp.Max(*(a * S.x1 + b * S.x2 for a, b in normals))
        grads = tuple((sp.cot(alpha) * a, sp.cot(alpha) * b) for a, b in normals)
        object.__setattr__(self, "values", (("expr", expr), ("planes", grads), ("half_angle", alpha),
                                            ("sides", n)))

    @property
    def kind(self) -> str:
        """``"pyramid"``."""
        return "pyramid"

    @property
    def alpha(self) -> sp.Expr:
        """The face angle in radians."""
        return self.values[2][1]

    @property
    def sides(self) -> int:
        """3 or 4."""
        return self.values[3][1]

    @property
    def description(self) -> str:
        deg = self.alpha * 180 / sp.pi
        shown = f"{float(deg):g} deg" if deg.is_number else str(self.alpha)
        return f"{self.sides}-sided pyramid, face angle {shown}"

    def subs(self, values: Mapping) -> Tip:
        """A new pyramid with its angle given (in degrees, like the constructor), e.g. ``.subs({"alpha": 35})``."""
        if not isinstance(values, Mapping):
            raise InputTypeError(f"the tip's parameter values must be a dict, got {type(values).__name__}")
        names = {q.name for q in self.parameters}
        angle = None
        for k, v in values.items():
            key = k.name if isinstance(k, sp.Symbol) else k
            if key not in names:
                raise PunchError(f"{k!r} is not a parameter of the {self.name}; its parameters are "
                                 f"{', '.join(sorted(names)) or 'none'}")
            angle = v
        return Pyramid(angle, self.sides) if values else self

    def level_set_expressions(self) -> dict[str, sp.Expr]:
        """The level-set integrals in ``delta0`` and alpha, integrated over the N sectors (module docstring)."""
        return _pyramid_level_set(self.alpha, self.sides)

    def level_set(self, delta0: Any) -> LevelSet:
        """The closed forms of :meth:`level_set_expressions` at a depth (float arithmetic, no overflow)."""
        self._need_numbers("its level set")
        d = positive_depth(delta0)
        n, t = self.sides, math.tan(float(self.alpha))
        rho = d * t  # closed forms (module docstring), evaluated stably: rho^2 as rho*rho, no overflow of d^3
        tn = math.tan(math.pi / n)
        area = n * rho * rho * tn
        perimeter = 2 * n * rho * tn
        return LevelSet(area, area / 3.0 * d, perimeter, 2 * n * tn * d, rho)

    def polygon(self, delta0: Any) -> np.ndarray:
        """The vertices of the regular N-gon ``{Phi < delta0}`` (counter-clockwise)."""
        return super().polygon(delta0)


@lru_cache(maxsize=32)
def _pyramid_level_set(alpha: sp.Expr, n: int) -> dict[str, sp.Expr]:
    s = sp.Symbol("s", positive=True)
    rho = S.delta0 * sp.tan(alpha)
    width = 2 * s * sp.tan(sp.pi / n)  # the sector's width at distance s from the apex
    area = sp.simplify(n * sp.integrate(width, (s, 0, rho)))
    volume = sp.simplify(n * sp.integrate((S.delta0 - s * sp.cot(alpha)) * width, (s, 0, rho)))
    perimeter = sp.simplify(n * width.subs(s, rho))
    flux = sp.simplify(sp.cot(alpha) * perimeter)  # |grad Phi| = cot(alpha) on every edge
    return {"inradius": rho, "area": area, "volume": volume, "perimeter": perimeter, "flux": flux}


def pyramid(half_angle: Any = None, sides: Any = 4) -> Pyramid:
    """The registry's constructor (``pyramid:half_angle=35,sides=4``)."""
    return Pyramid(half_angle, sides)


register_tip(TipKind("pyramid", pyramid, (
    TipParameter("half_angle", "angle", "face angle of the pyramid in degrees, axis to face (0 < alpha < 90)",
                 ("angle", "alpha", "face_angle")),
    TipParameter("sides", "number", "number of faces, 3 or 4")),
    "regular pyramid Phi = cot(alpha) max_k n_k.x, face angle alpha in degrees, 3 or 4 sides (issue 24)"))
register_tip(TipKind("polyhedral", Polyhedral, (
    TipParameter("expr", "expression", "max(...) of linear forms in x_1, x_2", (), True),),
    "convex polyhedral tip Phi = max(a_k x_1 + b_k x_2, ...), apex at the origin (issue 24)"))
