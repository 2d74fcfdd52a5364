r"""The front door: force, contact size and pressure of a rigid punch on a layer, by the model that holds.

:func:`solve` answers a user's question ("sphere R = 10 on a layer H = 0.5, E = 2, nu = 0.45, pressed
d = 0.1: force, contact radius, pressure?") for a layer bonded to a rigid base with
``-1 < nu <= 1/2`` or lying on a frictionless base, any thickness and any smooth polynomial punch.
It tries the thin-layer models in this order and keeps the first whose error estimate is within ``tol``:

``"compressible"``
    the paper's expansion (2.22)-(3.25): force (1.8) with its first correction, contact area with the
    exact edge shift h^* (3.25), composite pressure (:func:`thinlayer.asymptotics.solution.compressible_solution`).
    Estimate: :func:`thinlayer.asymptotics.force_law.error_estimate` (powers of
    ``kappa^2 = |P1/P0| + (1 + h^*^2)(H/a)^2``); it grows like ``m_1 ~ 1/(3(1 - 2 nu))`` near nu = 1/2.
``"two-term"``
    the sphere in the two-term model (I.10)-(I.12), ``1/4 < nu < 1/2`` (bonded base).
``"incompressible"``
    nu = 1/2 (bonded base): the model (I.3)-(I.4) for the sphere (I.11), the elliptic paraboloid (I.6)-(I.8)
    and any axisymmetric polynomial punch (I.9).

Both nearly-incompressible models neglect the edge layer of width ``H`` (I.12): the true contact edge
lies ``h H`` inside the model's (``h`` from :func:`two_term_edge_shift`, 1.459 at nu = 1/2), which
changes the force at relative order ``h H/c``.  Their estimates are ``2 h H/c`` for the force and the
area (the factor 2 covers the unknown order-one constant of that term) and ``2 (h H/c)^2`` for the
corrected radius ``c - h H``; the acceptance tests check them against the direct solver.

Where no thin-layer model holds, ``model="auto"`` tries for an axisymmetric punch ``"any-thickness"``
(:mod:`thinlayer.contact.any_thickness`): the sphere at any ``H/a`` by the law (T.7) (thick-layer series,
a table of direct solutions shipped with the package, thin-layer asymptotics; estimate <= 2.1e-4, the
pressure from the direct solver on first use), another axisymmetric punch by the thick-layer series (T.5)
where its estimate (T.8) is within ``tol``.  Where that does not hold either, it solves the problem
directly (``"direct"``): the axisymmetric
spectral solver (:func:`thinlayer.numerics.solve_axisymmetric`, its estimate from a run with 0.7 times the
modes) for an axisymmetric punch, otherwise the 2D FFT solver (:func:`thinlayer.numerics.solve_2d`, its
estimate the change from a grid of half the cells: an upper bound for a method converging at least
linearly in the cell size).  ``model="asymptotic"`` refuses instead, naming each model and why it fails.
"""
from __future__ import annotations

import math
import numbers
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from typing import Any, ClassVar

import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import InputError, InputTypeError, ThinlayerError, check_choice, parse_nu, positive
from ..asymptotics.incompressible import (
    incompressible_axisymmetric,
    incompressible_ellipse,
    two_term_edge_shift,
    two_term_sphere,
)
from ..asymptotics.solution import DEFAULT_TOL, ValidityError, compressible_solution, numeric_punch
from ..display import RichDisplay
from ..errors import boundary, boundary_methods
from ..layers.kernels import IncompressibleLayer, LayerKernel
from ..punch import FlatPunch, Punch

__all__ = ["Indentation", "DirectComparison", "MODELS", "solve", "ELASTIC_HINT"]

#: the values of ``model``
MODELS = ("auto", "asymptotic", "compressible", "two-term", "incompressible", "any-thickness", "direct")
#: the asymptotic models, in the order ``"auto"`` tries them
ASYMPTOTIC = ("compressible", "two-term", "incompressible")
ELASTIC_HINT = "give exactly one of mu= (shear modulus) or E= (Young's modulus), with the Poisson ratio nu"
#: cells per side of the 2D direct solver at most (memory about 1 GB at 1024, see numerics.fft2d.memory_estimate)
MAX_CELLS_2D = 1024


# =============================================================================================
# the punch's shape
# =============================================================================================
@dataclass(frozen=True)
class _Shape:
    """What the models need to know of a numeric punch."""

    axisymmetric: bool
    quadric: tuple[float, float, float] | None  # (1/R1, 1/R2, angle) for Phi = x.Hx/2 (principal curvatures)

    @property
    def sphere(self) -> bool:
        return self.quadric is not None and math.isclose(self.quadric[0], self.quadric[1], rel_tol=1e-12)


@lru_cache(maxsize=256)
def _shape(punch: Punch) -> _Shape:
    e = sp.expand(punch.expr)
    axi = sp.expand(S.x1 * sp.diff(e, S.x2) - S.x2 * sp.diff(e, S.x1)) == 0
    poly = sp.Poly(e, S.x1, S.x2)
    quad = None
    if poly.total_degree() == 2 and all(sum(m) == 2 for m in poly.monoms()):
        a11 = float(poly.coeff_monomial(S.x1**2)) * 2
        a22 = float(poly.coeff_monomial(S.x2**2)) * 2
        a12 = float(poly.coeff_monomial(S.x1 * S.x2))
        lam, vec = np.linalg.eigh(np.array([[a11, a12], [a12, a22]]))
        if lam.min() > 0:
            quad = (float(lam[0]), float(lam[1]), float(math.atan2(vec[1, 0], vec[0, 0])))
    return _Shape(bool(axi), quad)


# =============================================================================================
# the result
# =============================================================================================
@boundary_methods
@dataclass(frozen=True, eq=False)
class Indentation(RichDisplay):
    r"""The answer of :func:`solve`: force, contact size and pressure, with the model and its error estimate.

    Attributes
    ----------
    layer, punch
        The layer and the (numeric) punch.
    delta0, force : float
        Indentation depth and total force (1.8); one was given, the other computed.
    H, mu, E, nu : float
        Thickness, shear modulus, Young's modulus ``E = 2 mu (1 + nu)`` and Poisson ratio.
    contact_area : float
        Area of the contact region.
    contact_radius : float or None
        Radius of the contact disc (axisymmetric punches; None otherwise).
    semi_axes : tuple of float or None
        Semi-axes of an elliptic contact (elliptic paraboloid punches, where the model gives them).
    model : str
        ``"compressible"``, ``"two-term"``, ``"incompressible"`` or ``"direct"``.
    reason : str
        Why this model: the estimates of the models tried before it.
    error_estimate : dict
        Relative error estimates: ``{"force", "contact_area"}`` and ``"contact_radius"`` where defined.
    tol : float
        The tolerance the estimates were accepted with.
    detail : Any
        The model's own result (``ContactSolution``, ``SphereValues``, ``AxisymmetricContact``, ...).
    """

    equation: ClassVar[str] = "1.8"

    layer: LayerKernel
    punch: Punch
    delta0: float
    force: float
    H: float
    mu: float
    nu: float
    contact_area: float
    contact_radius: float | None
    semi_axes: tuple[float, float] | None
    model: str
    reason: str
    error_estimate: dict
    tol: float
    detail: Any = field(repr=False)
    _pressure: Callable = field(repr=False)
    _extent: float = field(repr=False)

    @property
    def E(self) -> float:
        """Young's modulus ``E = 2 mu (1 + nu)``."""
        return 2.0 * self.mu * (1.0 + self.nu)

    @property
    def half_width(self) -> float:
        """``a = 2 |omega|/|Gamma|`` for the models with a contour, the radius (or its area equivalent) otherwise."""
        if self.contact_radius is not None:
            return self.contact_radius
        if self.model == "compressible":
            return float(self.detail.half_width)
        if self.semi_axes is not None:  # an ellipse: |Gamma| = 4 a E(1 - b^2/a^2), a >= b
            import mpmath

            a, b = max(self.semi_axes), min(self.semi_axes)
            return math.pi * a * b / (2.0 * a * float(mpmath.ellipe(1.0 - (b / a) ** 2)))
        return math.sqrt(self.contact_area / math.pi)

    @property
    def H_over_a(self) -> float:
        return self.H / self.half_width

    def pressure(self, x1: Any, x2: Any) -> np.ndarray:
        """Contact pressure ``p(x1, x2)`` (vectorised over numpy arrays; zero outside the contact)."""
        x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
        return np.asarray(self._pressure(x1, x2), dtype=float)

    @cached_property
    def max_pressure(self) -> float:
        """The largest contact pressure: sampled on a 161 x 161 grid over the contact, then polished locally.

        ``inf`` for the flat punch, whose pressure is singular at the edge (F.8).
        """
        from scipy import optimize

        if getattr(self.punch, "singular_edge", False):
            return math.inf
        w = self._extent.value if isinstance(self._extent, _LazyExtent) else self._extent
        g = np.linspace(-w, w, 161)
        X1, X2 = np.meshgrid(g, g, indexing="ij")
        P = self.pressure(X1, X2)
        k = np.unravel_index(int(np.argmax(P)), P.shape)
        x0 = np.array([X1[k], X2[k]])
        res = optimize.minimize(lambda z: -float(self.pressure(z[0], z[1])), x0, method="Nelder-Mead",
                                options={"xatol": 1e-10 * w, "fatol": 1e-14 * max(P[k], 1e-300)})
        return float(max(P[k], -res.fun))

    def compare_direct(self, **options: Any) -> DirectComparison:
        """Solve the same problem (same ``delta0``) with the direct solver and put both side by side.

        ``options`` go to the direct solver (``n`` modes or cells).  When this result is itself
        ``"direct"``, the comparison is with a refined direct solution (1.4 times the modes or cells).
        """
        refine = self.model == "direct"
        if isinstance(self.punch, FlatPunch):  # the exact solution, refined when this answer is itself exact
            n = options.get("n")
            if n is None and refine:
                from ..numerics.flat_punch import flat_punch_kappa

                n = min(int(1.4 * flat_punch_kappa(self.layer, self.H_over_a ** -1, error_estimate=False).nodes), 400)
            other = _flat(self.layer, self.punch, self.delta0, None, self.H, self.mu, self.nu, "direct", math.inf, n)
            return DirectComparison(self, other)
        other = _direct(self.layer, self.punch, self.delta0, self.H, self.mu, self.nu, refine=refine,
                        previous=self.detail if refine else None, **options)
        return DirectComparison(self, other)

    # ---- output ----------------------------------------------------------------------------
    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        est = self.error_estimate
        base = "" if self.layer.base == "bonded" else ", frictionless base"
        lines = [
            f"Indentation ({self.model} model): "
            + getattr(self.punch, "description", f"{self.punch.name} Phi = {getattr(self.punch, 'expr', '')}"),
            f"  layer nu = {self.nu:.6g}{base}, H = {self.H:.6g}, mu = {self.mu:.6g} (E = {self.E:.6g}), "
            f"delta0 = {self.delta0:.8g}, H/a = {self.H_over_a:.3g}",
            f"  force           P = {self.force:.8g}   (+- {100 * est['force']:.2g} %)",
            f"  contact area      = {self.contact_area:.8g}   (+- {100 * est['contact_area']:.2g} %)",
        ]
        if self.contact_radius is not None:
            lines.append(f"  contact radius  c = {self.contact_radius:.8g}   "
                         f"(+- {100 * est.get('contact_radius', math.nan):.2g} %)")
        if self.semi_axes is not None:
            lines.append(f"  semi-axes         = {self.semi_axes[0]:.8g}, {self.semi_axes[1]:.8g}")
        lines.append(f"  model: {self.model} -- {self.reason}")
        return lines

    @property
    def equations(self) -> tuple[str, str]:
        """The equations of the force and of the contact size in the model used."""
        if self.model == "compressible":
            return "1.8", "3.25"
        if self.model == "direct" and not isinstance(self.punch, FlatPunch):
            return "1.5-1.8", "1.5-1.8"
        if self.model == "any-thickness":
            return "T.7", "T.7"
        if isinstance(self.punch, FlatPunch):
            from .flat_punch import EQUATIONS

            return EQUATIONS[self.model]
        if self.model == "two-term" or self.contact_radius is not None and self.semi_axes is None:
            return ("I.11", "I.12") if self.punch.name.startswith("paraboloid") else ("I.9", "I.12")
        return "I.8", "I.7"

    def latex(self) -> str:
        est = self.error_estimate
        tf, ta = self.equations
        rows = [rf"P = {_tex_num(self.force)}\ \left(\pm {100 * est['force']:.2g}\,\%\right) \tag{{{tf}}}",
                rf"|\omega| = {_tex_num(self.contact_area)}\ \left(\pm {100 * est['contact_area']:.2g}\,\%\right)"
                rf" \tag{{{ta}}}"]
        if self.contact_radius is not None:
            rows.append(rf"c = {_tex_num(self.contact_radius)}")
        rows.append(rf"\text{{model: {self.model}}},\quad H/a = {self.H_over_a:.3g},\quad \nu = {self.nu:.6g}")
        return " \\\\\n".join(rows)

    def as_dict(self) -> dict[str, Any]:
        """The numbers as a JSON-ready dictionary."""
        return {"model": self.model, "reason": self.reason, "force": self.force, "delta0": self.delta0,
                "contact_area": self.contact_area, "contact_radius": self.contact_radius,
                "semi_axes": list(self.semi_axes) if self.semi_axes else None,
                "max_pressure": self.max_pressure if math.isfinite(self.max_pressure) else None,
                "H": self.H, "mu": self.mu, "E": self.E, "nu": self.nu, "H_over_a": self.H_over_a,
                "error_estimate": dict(self.error_estimate), "tol": self.tol}


def _tex_num(x: float) -> str:
    m, e = f"{x:.7e}".split("e")
    e = int(e)
    return f"{x:.8g}" if -3 <= e <= 5 else rf"{float(m):.8g} \times 10^{{{e}}}"


@boundary_methods
@dataclass(frozen=True, eq=False)
class DirectComparison(RichDisplay):
    """An :class:`Indentation` beside the direct solution of the same problem (:meth:`Indentation.compare_direct`).

    Attributes
    ----------
    solution, direct : Indentation
        The answer and the direct solution (``direct.model == "direct"``).
    rows : list of tuple
        ``(quantity, solution value, direct value, relative difference, the solution's estimate)``.
    """

    solution: Indentation
    direct: Indentation

    @property
    def rows(self) -> list[tuple[str, float, float, float, float]]:
        out = []
        for key in ("force", "contact_area", "contact_radius"):
            a, b = getattr(self.solution, key), getattr(self.direct, key)
            if a is None or b is None:
                continue
            out.append((key, a, b, abs(a - b) / abs(b), self.solution.error_estimate.get(key, math.nan)))
        return out

    @property
    def within_estimate(self) -> bool:
        """Whether every difference is inside the solution's estimate plus the direct solution's own."""
        return all(d <= e + self.direct.error_estimate.get(k, 0.0) for k, _, _, d, e in self.rows)

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        lines = [f"{self.solution.model} model vs direct solver ({self.direct.reason})",
                 f"  {'quantity':<15}{self.solution.model:>16}{'direct':>16}{'difference':>12}{'estimate':>12}"]
        for k, a, b, d, e in self.rows:
            lines.append(f"  {k:<15}{a:>16.8g}{b:>16.8g}{100 * d:>11.3g}%{100 * e:>11.3g}%")
        return lines

    def latex(self) -> str:
        return " \\\\\n".join(rf"\text{{{k.replace('_', ' ')}}}: {_tex_num(a)}\ \text{{vs}}\ {_tex_num(b)}"
                              for k, a, b, _, _ in self.rows)


# =============================================================================================
# the models
# =============================================================================================
def _check_model_layer(layer: Any, nu: Any) -> tuple[LayerKernel, float]:
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a thinlayer layer, e.g. BondedLayer(0.3) or FrictionlessLayer(0.3); "
                        f"got {layer!r}")
    if layer.base not in ("bonded", "frictionless") or not layer.has_thickness or layer.symbolic_coefficients:
        raise InputTypeError(f"solve() answers for a layer on a rigid base: BondedLayer(nu) (-1 < nu <= 1/2) or "
                        f"FrictionlessLayer(nu); got {layer!r}")
    if layer.parameter is not None:
        raise InputError("solve() needs a numeric Poisson ratio: BondedLayer(0.3) or BondedLayer('3/10'), "
                         "not the symbolic BondedLayer()")
    given = layer.poisson_ratio(nu)
    nv = parse_nu(given, floats="float", upper_closed=True, symbols=False, example="0.3, '3/10' or 0.5")
    return layer, float(nv)


def _elastic(mu: Any, E: Any, nu: float) -> float:
    if (mu is None) == (E is None):
        raise InputTypeError(f"solve(): {ELASTIC_HINT}" + ("" if mu is None else "; both were given"))
    if mu is not None:
        return positive(mu, "mu")
    mm = positive(E, "E") / (2.0 * (1.0 + nu))
    if not (math.isfinite(mm) and mm > 0):
        raise InputError(f"E = {E!r} gives the shear modulus mu = E/(2(1 + nu)) = {mm!r}: out of the double range")
    return mm


def _estimate_ok(est: dict, tol: float) -> bool:
    return all(v <= tol for v in est.values())


def _fmt_est(est: dict) -> str:
    return ", ".join(f"{k.replace('_', ' ')} {100 * v:.3g} %" for k, v in est.items())


class _NotApplicable(Exception):
    """A model that does not apply to this layer or punch (the message says why)."""


def _compressible(layer, punch, shape, delta0, force, H, mu, nu, tol, options) -> Indentation:
    if not layer.has_compressible_expansion:
        raise _NotApplicable("nu = 1/2 on a bonded base: A = 0 in (2.4), no compressible expansion")
    sol = compressible_solution(layer, punch, delta0=delta0, H=H, mu=mu, force=force, nu=nu, tol=tol, **options)
    est = dict(sol.error_estimate)
    radius = None
    if shape.axisymmetric:
        radius = math.sqrt(sol.contact_area / math.pi)
        est["contact_radius"] = est["contact_area"] / 2
    axes = None
    if shape.quadric is not None and not shape.axisymmetric:
        semi = [math.sqrt(2 * sol.delta0 / k) for k in shape.quadric[:2]]
        if sol.order == 2:  # (SO.5): h = h* + m1 H (kappa/2 + Phi_nn/(2g)); at the end of axis i kappa = a_i/a_j^2
            m1 = float(layer.m(1))
            axes = tuple(a - H * (sol.edge_shift + m1 * H * (a / b**2 + 1 / a) / 2)
                         for a, b in (semi, semi[::-1]))
        else:  # the contour moves inward by h* H along its normal (3.25)
            axes = tuple(a - sol.edge_shift * H for a in semi)
    extent = _LazyExtent(punch, sol.delta0)  # needed by max_pressure only
    return Indentation(layer, punch, sol.delta0, sol.force, H, mu, nu, sol.contact_area, radius, axes,
                       "compressible", "", est, tol, sol, sol.pressure, extent)


@lru_cache(maxsize=256)
def _phi_numpy(punch: Punch) -> Callable:
    return sp.lambdify((S.x1, S.x2), punch.expr, "numpy")


class _LazyExtent:
    """:func:`_extent_of` computed on first use (``Indentation.max_pressure`` is the only user)."""

    def __init__(self, punch: Punch, delta0: float):
        self.args = (punch, delta0)

    @cached_property
    def value(self) -> float:
        return _extent_of(*self.args)


def _extent_of(punch: Punch, delta0: float) -> float:
    """A half-width of a square that holds {Phi < delta0}: bisection along 16 rays (all at once)."""
    f = _phi_numpy(punch)
    t = np.linspace(0, 2 * np.pi, 16, endpoint=False)
    c, s = np.cos(t), np.sin(t)
    hi = np.ones(16)
    with np.errstate(over="ignore", invalid="ignore"):
        for _ in range(1100):  # double until outside (or 1e300)
            inside = (np.asarray(f(hi * c, hi * s), dtype=float) < delta0) & (hi < 1e300)
            if not inside.any():
                break
            hi = np.where(inside, 2.0 * hi, hi)
        lo = np.zeros(16)
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            inside = np.asarray(f(mid * c, mid * s), dtype=float) < delta0
            lo, hi = np.where(inside, mid, lo), np.where(inside, hi, mid)
    return 1.05 * float(hi.max())


def _two_term_pressure(model, c: float, H: float, mu: float, R: float) -> Callable:
    """``p(r)`` of the sphere in the two-term model (I.10)-(I.11), stable for every ``k c``.

    ``-Delta p + k^2 p = F (delta0 - r^2/(2R))``, ``F = vartheta/(c_1 H^3)``, ``p(c) = p'(c) = 0``:
    ``p = alpha_0 + alpha_1 r^2 + B I_0(k r)`` with ``alpha_1 = -F/(2 R k^2)``, ``B = -2 alpha_1 c/(k I_1(k c))``
    and ``alpha_0 = -alpha_1 c^2 - B I_0(k c)``; the Bessel ratios are taken scaled (``ive``) so that nothing
    overflows.  At ``k = 0`` (nu = 1/2): ``p = F (c^2 - r^2)^2/(32 R)``.
    """
    from scipy import special

    c0, c1, th = float(model.c0), float(model.c1), float(model.vartheta.subs(S.mu, mu))
    F = th / (c1 * H**3)
    k = math.sqrt(c0 / c1) / H if c0 else 0.0

    def p(r):
        r = np.abs(np.asarray(r, dtype=float))
        rr = np.minimum(r, c)
        if k * c < 1e-3:  # the incompressible limit (relative error (k c)^2 / 10 below 1e-7)
            val = F * (c * c - rr * rr) ** 2 / (32 * R)
        else:
            a1 = -F / (2 * R * k * k)
            b_over = -2 * a1 * c / k  # B I_1(k c)
            ratio_r = special.ive(0, k * rr) / special.ive(1, k * c) * np.exp(k * (rr - c))
            ratio_c = special.ive(0, k * c) / special.ive(1, k * c)
            val = a1 * (rr * rr - c * c) + b_over * (ratio_r - ratio_c)
        return np.where(r < c, np.maximum(val, 0.0), 0.0)

    return p


@lru_cache(maxsize=64)
def _incompressible_ellipse(R1: float, R2: float):
    return incompressible_ellipse(sp.Float(R1, 17), sp.Float(R2, 17))


@lru_cache(maxsize=64)
def _edge_h(layer: LayerKernel) -> float:
    return float(two_term_edge_shift(layer, dps=15))


def _two_term(layer, punch, shape, delta0, force, H, mu, nu, tol, incompressible: bool) -> Indentation:
    name = "incompressible" if incompressible else "two-term"
    if layer.base != "bonded":
        raise _NotApplicable(f"the {name} model is derived for a bonded base")
    if incompressible and nu != 0.5:
        raise _NotApplicable(f"nu = {nu:.6g} < 1/2 (the incompressible model is nu = 1/2)")
    if not incompressible and not 0.25 < nu < 0.5:
        raise _NotApplicable(f"the two-term model needs 1/4 < nu < 1/2, got nu = {nu:.6g}")
    if not incompressible and not shape.sphere:
        raise _NotApplicable("the two-term model is derived for the sphere (paraboloid) only")
    if incompressible and not (shape.axisymmetric or shape.quadric is not None):
        raise _NotApplicable("the incompressible model is closed-form for axisymmetric punches and the "
                             "elliptic paraboloid; this punch needs the direct solver")
    h = _edge_h(layer)
    if shape.sphere:
        R = 1.0 / shape.quadric[0]
        model = two_term_sphere(layer)

        def at(d0):
            return model.evaluate(d0, R, H, mu)

        d0 = _depth_for_force(lambda d: at(d).force, force, math.sqrt(force / mu) if force else 1.0) \
            if force is not None else delta0
        v = at(d0)
        c = v.radius
        hc = h * H / c
        radius = v.radius_corrected
        if not radius > 0:
            raise ValidityError(f"solve(): the {name} model's corrected radius c - h H = {radius:.3g} <= 0 "
                                f"(H/c = {H / c:.3g}): far outside the thin-layer range", "contact_radius",
                                math.inf, tol, "direct")
        est = {"force": 2 * hc, "contact_area": 2 * hc, "contact_radius": 2 * hc * hc}
        p_r = _two_term_pressure(model, c, H, mu, R)
        return Indentation(layer, punch, d0, v.force, H, mu, nu, math.pi * radius**2, radius, None, name, "", est,
                           tol, v, lambda x1, x2: p_r(np.hypot(x1, x2)), 1.2 * c)
    if shape.quadric is not None:  # elliptic paraboloid at nu = 1/2 (I.6)-(I.8)
        k1, k2, ang = shape.quadric
        model = _incompressible_ellipse(1 / k1, 1 / k2)

        def at(d0):
            return model.evaluate(d0, H, mu)

        d0 = _depth_for_force(lambda d: at(d).force, force, 1.0) if force is not None else delta0
        v = at(d0)
        a, b, C = v.a, v.b, v.C
        hc = h * H / math.sqrt(a * b)
        est = {"force": 2 * hc, "contact_area": 2 * hc}
        cs, sn = math.cos(ang), math.sin(ang)

        def p(x1, x2):
            y1, y2 = cs * x1 + sn * x2, -sn * x1 + cs * x2
            q = 1 - (y1 / a) ** 2 - (y2 / b) ** 2
            return np.where(q > 0, C * np.maximum(q, 0.0) ** 2, 0.0)

        axes = (max(a - h * H, 0.0), max(b - h * H, 0.0))
        return Indentation(layer, punch, d0, v.force, H, mu, nu, math.pi * axes[0] * axes[1], None, axes, name, "",
                           est, tol, v, p, 1.2 * max(a, b))
    model = incompressible_axisymmetric(punch)  # any axisymmetric polynomial punch (I.9)

    def at(d0):
        return model.evaluate(d0, H, mu)

    d0 = _depth_for_force(lambda d: at(d).force, force, 1.0) if force is not None else delta0
    v = at(d0)
    c = v.radius
    hc = h * H / c
    radius = c - h * H
    est = {"force": 2 * hc, "contact_area": 2 * hc, "contact_radius": 2 * hc * hc}
    return Indentation(layer, punch, d0, v.force, H, mu, nu, math.pi * max(radius, 0.0) ** 2, radius, None, name,
                       "", est, tol, v, lambda x1, x2: v.pressure(np.hypot(x1, x2)), 1.2 * c)


def _fast_size(n: float) -> int:
    """The smallest 5-smooth integer >= n (fast FFT sizes)."""
    m = max(int(math.ceil(n)), 1)
    while True:
        k = m
        for f in (2, 3, 5):
            while k % f == 0:
                k //= f
        if k == 1:
            return m
        m += 1


def _depth_for_force(force_of: Callable[[float], float], target: float, guess: float) -> float:
    """The depth whose force is ``target`` (the force increases with the depth).

    Secant steps on ``log P`` against ``log delta0`` (``P ~ delta0^gamma`` with ``gamma`` between 1 and 3 for
    every model: few steps from a good guess), safeguarded by a bracket and Brent's method.
    """
    from scipy import optimize

    def g(logd):
        P = force_of(math.exp(logd))
        if not (0 < P < math.inf):  # the depth or the force left the double range on the way
            raise ValidityError(f"solve(): no depth found for the force {target:.4g}: at depth {math.exp(logd):.3g} "
                                f"the model's force is {P!r}, outside the double range", "force")
        return math.log(P) - math.log(target)

    x0 = math.log(max(guess, 1e-300))
    g0 = g(x0)
    x1 = x0 - g0 / 2.0  # gamma ~ 2 (a sphere on a thin compressible layer)
    g1 = g(x1)
    pts = [(x0, g0), (x1, g1)]
    for _ in range(12):
        if abs(g1) < 1e-13:
            return math.exp(x1)
        if g1 == g0:
            break
        x0, g0, x1 = x1, g1, x1 - g1 * (x1 - x0) / (g1 - g0)
        g1 = g(x1)
        pts.append((x1, g1))
    lows = [x for x, v in pts if v < 0]
    highs = [x for x, v in pts if v > 0]
    lo = max(lows) if lows else min(x for x, _ in pts) - 1.0
    hi = min(highs) if highs else max(x for x, _ in pts) + 1.0
    for _ in range(100):
        if g(lo) < 0:
            break
        lo -= 2.0
    for _ in range(100):
        if g(hi) > 0:
            break
        hi += 2.0
    if not (g(lo) < 0 < g(hi)):
        raise ValidityError(f"solve(): no depth gives the force {target:.6g}", "force")
    return math.exp(optimize.brentq(g, lo, hi, xtol=1e-14, rtol=1e-13))


def _direct(layer, punch, delta0, H, mu, nu, refine=False, previous=None, force=None, tol=DEFAULT_TOL,
            n=None, estimate=True) -> Indentation:
    """The direct numerical solution (axisymmetric spectral or 2D FFT), with its estimate from a coarser run."""
    from ..numerics import solve_2d, solve_axisymmetric
    from ..numerics.fft2d import memory_estimate

    shape = _shape(punch)
    free_nu = nu if layer.numeric_nu is None else None
    if force is not None:
        guess = delta0 if delta0 is not None else 1.0
        delta0 = _depth_for_force(lambda d: _direct(layer, punch, d, H, mu, nu, n=n, estimate=False).force, force,
                                  guess)
    if shape.axisymmetric:
        modes = n
        if refine and previous is not None:
            modes = int(1.4 * previous.modes) + 1
        res = solve_axisymmetric(layer, punch, delta0, H, mu, n=modes, nu=free_nu, error_estimate=estimate)
        c = res.radius
        floor = 1e-9  # the spectral estimate can read zero; the solver's own tolerances are ~1e-12
        est = {"force": max(res.force_error, floor), "contact_radius": max(res.radius_error / c, floor),
               "contact_area": max(2 * res.radius_error / c, floor)}
        why = f"axisymmetric spectral solver, {res.modes} modes (estimate: change from ~0.7x the modes)"
        return Indentation(layer, punch, delta0, res.force, H, mu, nu, res.contact_area, c, None, "direct", why,
                           est, tol, res, lambda x1, x2: res.pressure_at(np.hypot(x1, x2)), 1.2 * c)
    # 2D: a square around the overlap {Phi < delta0} (wider near nu = 1/2, where the contact outgrows it), cells
    # resolving H (Delta <= H/7.2, so that the check run at 0.7 times the cells still has Delta <= H/5) and the
    # contact (>= 128 across); widened when the contact reaches the boundary
    half = _extent_of(punch, delta0) * (1.15 if nu < 0.4 or layer.base != "bonded" else 1.6) + 1.5 * H
    for _ in range(4):
        cells = n
        if cells is None:
            cells = _fast_size(max(14.4 * half / H, 128))
            if refine and previous is not None:
                cells = _fast_size(1.4 * previous.n)
            if cells > MAX_CELLS_2D and not refine:
                raise ValidityError(
                    f"solve(): the direct 2D solution needs {cells} x {cells} cells to resolve H = {H:.3g} over the "
                    f"contact (half-width {half:.3g}; about {memory_estimate(cells) / 2**30:.1f} GiB) -- more than "
                    f"the {MAX_CELLS_2D} x {MAX_CELLS_2D} allowed; give n= explicitly, or a larger tol for an "
                    "asymptotic model", "force", math.inf, tol, "direct")
        try:
            res = solve_2d(layer, punch, delta0=delta0, H=H, mu=mu, n=cells, extent=half, nu=free_nu)
            if not estimate:
                coarse = res
                break
            coarse = solve_2d(layer, punch, delta0=delta0, H=H, mu=mu, n=_fast_size(0.7 * cells), extent=half,
                              nu=free_nu)
            break
        except ValueError as exc:
            if "reaches the boundary" not in str(exc):
                raise
            half *= 1.4
    else:
        raise ValidityError("solve(): the direct 2D solution's contact keeps reaching the domain boundary",
                            "force", math.inf, tol, "direct")
    # error ~ C Delta^p with p >= 1: the fine grid's error is |P_n - P_0.7n|/(0.7^-p - 1) <= 2.34 |P_n - P_0.7n|
    n, nc = cells, coarse.n
    est = {"force": max(2.5 * abs(res.force - coarse.force) / res.force, 1e-9),
           "contact_area": max(2.5 * abs(res.contact_area - coarse.contact_area) / res.contact_area, 1e-9)}
    why = f"2D FFT solver, {n} x {n} cells (estimate: 2.5 x the change from {nc} x {nc})"
    x1, x2 = res.x1, res.x2

    def p(a, b):
        i = np.clip(np.rint((a - x1[0]) / res.spacing).astype(int), 0, x1.size - 1)
        j = np.clip(np.rint((b - x2[0]) / res.spacing).astype(int), 0, x2.size - 1)
        inside = (a >= x1[0] - res.spacing / 2) & (a <= x1[-1] + res.spacing / 2) & \
                 (b >= x2[0] - res.spacing / 2) & (b <= x2[-1] + res.spacing / 2)
        return np.where(inside, res.pressure[i, j], 0.0)

    radius = res.contact_radius if shape.axisymmetric else None
    return Indentation(layer, punch, delta0, res.force, H, mu, nu, res.contact_area, radius, None, "direct", why,
                       est, tol, res, p, half)


# =============================================================================================
# the front door
# =============================================================================================
@boundary
def solve(layer: LayerKernel, punch: Any, delta0: Any = None, H: Any = None, mu: Any = None, *, E: Any = None,
          force: Any = None, nu: Any = None, model: str = "auto", tol: Any = DEFAULT_TOL,
          parameters: dict | None = None, n: int | None = None, **options: Any) -> Indentation:
    r"""Force, contact size and pressure of a rigid punch pressed into a layer, by the model that holds.

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` with ``-1 < nu <= 1/2`` (``BondedLayer(0.5)`` is the incompressible layer) or
        ``FrictionlessLayer(nu)`` (a frictionless base).
    punch : Punch or str
        Any smooth polynomial punch with numeric coefficients (or ``parameters`` giving them).
    delta0, force : Any
        Exactly one: the indentation depth, or the total force (the depth is then found).
    H : Any
        Layer thickness.
    mu, E : Any
        Exactly one: the shear modulus, or Young's modulus ``E = 2 mu (1 + nu)``.
    nu : Any
        The Poisson ratio, when the layer was built without one (``FrictionlessLayer()``).
    model : str
        ``"auto"`` (default: the first asymptotic model within ``tol``, then the any-thickness law, else the
        direct solver),
        ``"asymptotic"`` (the same but refuse instead of the direct solver), or one model:
        ``"compressible"``, ``"two-term"``, ``"incompressible"``, ``"any-thickness"``, ``"direct"``.
    tol : Any
        Largest accepted relative error estimate (default 0.05).
    parameters : dict, optional
        Values of the punch's parameters.
    n : int, optional
        Modes (axisymmetric) or cells per side (2D) of the direct solver.
    options
        For the compressible model: ``order``, ``terms``, ``boundary_layer``
        (:func:`thinlayer.asymptotics.solution.compressible_solution`).

    Returns
    -------
    Indentation
        ``force``, ``contact_area``, ``contact_radius`` (axisymmetric), ``semi_axes`` (ellipses),
        ``pressure(x1, x2)``, ``max_pressure``, ``model``, ``reason``, ``error_estimate``,
        ``compare_direct()``.

    Raises
    ------
    ValidityError
        With ``model="asymptotic"`` or a named model whose estimate exceeds ``tol``; the one-line message
        names each model tried and its estimate.

    Examples
    --------
    The sphere on a thin layer: the leading force ``P0 = pi vartheta R delta0^2/(A H)`` (1.8),
    ``A = (1/2 - nu)/(1 - nu)^2``, ``vartheta = mu/(1 - nu)``, ``mu = E/(2(1 + nu))``; its first correction
    ``-2 m_1 H^2/(R delta0)``, ``m_1 = 1/14``; the contact radius ``sqrt(2 R delta0) - h^* H`` (3.25):

    >>> import math
    >>> from thinlayer import BondedLayer, Punch, solve
    >>> ans = solve(BondedLayer(0.3), Punch.paraboloid(10), delta0=0.1, H=0.05, E=2.6)
    >>> P0 = math.pi * (1.0 / 0.7) * 10 * 0.1**2 / (0.2 / 0.49 * 0.05)
    >>> ans.model, round(ans.force / P0 - 1, 6), round(-2 / 14 * 0.05**2 / (10 * 0.1), 6)
    ('compressible', -0.000357, -0.000357)
    >>> round((math.sqrt(2) - ans.contact_radius) / 0.05, 2)     # h*(0.3) = 0.1221 (Wiener-Hopf), + O(H)
    0.12
    >>> ans = solve(BondedLayer(0.49), Punch.paraboloid(10), delta0=0.1, H=0.5, E=2.0)
    >>> ans.model, ans.error_estimate["force"] < 1e-4       # no asymptotic model holds at H/a = 0.35
    ('any-thickness', True)
    >>> ans = solve(BondedLayer(0.49), Punch.paraboloid(10), delta0=0.1, H=0.5, E=2.0, model="direct")
    >>> ans.error_estimate["force"] < 1e-6
    True
    """
    layer, nu_v = _check_model_layer(layer, nu)
    mm = _elastic(mu, E, nu_v)
    choice = check_choice(model, MODELS, "model")
    if H is None:
        raise InputTypeError("solve() needs the layer thickness H")
    HH = positive(H, "H")
    tol_v = _tol(tol)
    if (delta0 is None) == (force is None):
        raise InputTypeError("give exactly one of delta0 (indentation) and force (the inverse problem)")
    d0 = positive(delta0, "delta0") if delta0 is not None else None
    Pt = positive(force, "force") if force is not None else None
    if isinstance(punch, FlatPunch):  # not a polynomial: the flat-punch models (F.1)-(F.19)
        if options or parameters:
            raise InputTypeError("the flat punch takes no parameters or options, got "
                            f"{sorted({**(parameters or {}), **options})}")
        return _flat(layer, punch, d0, Pt, HH, mm, nu_v, choice, tol_v, n)
    pn = numeric_punch(punch, parameters)
    shape = _shape(pn)
    if layer.numeric_nu is None:
        layer = type(layer)(nu_v) if layer.base == "frictionless" else layer
    if nu_v == 0.5 and layer.base == "bonded" and layer.has_compressible_expansion:
        layer = IncompressibleLayer()
    if choice == "direct":
        return _direct(layer, pn, d0, HH, mm, nu_v, force=Pt, tol=tol_v, n=n)
    if choice == "any-thickness":
        if options:
            raise InputTypeError(f"the options {sorted(options)} belong to the compressible model, not any-thickness")
        return _any_thickness(layer, pn, d0, Pt, HH, mm, nu_v, tol_v)
    tried: list[str] = []
    guess = None
    names = ASYMPTOTIC if choice in ("auto", "asymptotic") else (choice,)
    for name in names:
        try:
            # the options (order, terms, boundary_layer) are the compressible model's: "auto" tries the others without
            opts = options if name == "compressible" or choice not in ("auto", "asymptotic") else {}
            ans = _asymptotic(name, layer, pn, shape, d0, Pt, HH, mm, nu_v, tol_v, opts)
        except _NotApplicable as exc:
            tried.append(f"{name}: {exc}")
            continue
        except ValidityError as exc:
            # beyond the double range where the model holds: no other model would do better (where it does not
            # hold, e.g. delta0 = 1e-300 with H/a = 1e148, the next model answers or gives the true reason)
            if exc.model == "other units" and exc.estimate <= tol_v:
                raise
            tried.append(f"{name}: " + str(exc).replace("solve(): ", "").removeprefix(f"{name}: "))
            if choice not in ("auto", "asymptotic"):
                raise
            continue
        except (ArithmeticError, ValueError) as exc:
            if isinstance(exc, ThinlayerError):
                raise
            # the model's own numbers left the double range (e.g. R = 1e-199: R delta0 underflows): the next model
            tried.append(f"{name}: no answer at these numbers ({type(exc).__name__}: {exc})")
            if choice not in ("auto", "asymptotic"):
                raise ValidityError(f"solve(): the {name} model has no answer at these numbers ({type(exc).__name__}: "
                                    f"{exc}); use model='auto' or other units", "force") from None
            continue
        if _estimate_ok(ans.error_estimate, tol_v):
            why = "; ".join(tried + [f"{name}: estimates {_fmt_est(ans.error_estimate)} within tol "
                                     f"{100 * tol_v:.3g} %"])
            return _with_reason(ans, why, tol_v)
        tried.append(f"{name}: estimates {_fmt_est(ans.error_estimate)} exceed tol {100 * tol_v:.3g} %")
        guess = guess or ans.delta0  # a depth for the direct solver's inverse problem to start from
        if choice not in ("auto", "asymptotic"):
            raise ValidityError(f"solve(): the {name} model's {tried[-1].split(': ', 1)[1]} (H/a = "
                                f"{ans.H_over_a:.3g}); use model='auto' or model='direct'", "force",
                                max(ans.error_estimate.values()), tol_v, "direct")
    if choice in ("two-term", "incompressible", "compressible"):
        raise ValidityError(f"solve(): the {choice} model does not apply: {tried[-1].split(': ', 1)[1]}",
                            "force", math.inf, tol_v, "direct")
    if choice == "asymptotic":
        raise ValidityError("solve(): no asymptotic model holds to tol = " + f"{100 * tol_v:.3g} % -- "
                            + "; ".join(tried) + "; use model='auto' or 'direct'", "force", math.inf, tol_v,
                            "direct")
    if shape.axisymmetric:  # the any-thickness law (T.7) before the direct solver: the sphere at any H/a
        from .any_thickness import NotTabulatedError

        try:
            ans = _any_thickness(layer, pn, d0, Pt, HH, mm, nu_v, tol_v)
            return _with_reason(ans, "; ".join(tried + [f"any-thickness: {ans.reason}"]), tol_v)
        except (NotTabulatedError, ValidityError) as exc:
            if getattr(exc, "model", "") == "other units":  # the law holds here: no other model does better
                raise
            tried.append("any-thickness: " + str(exc).replace("solve(): ", ""))
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):  # the solver checks finiteness
        ans = _direct(layer, pn, d0 if d0 is not None else guess, HH, mm, nu_v, force=Pt, tol=tol_v, n=n)
    return _with_reason(ans, "; ".join(tried + [f"direct: {ans.reason}"]), tol_v)


def _asymptotic(name, layer, punch, shape, d0, Pt, H, mu, nu, tol, options) -> Indentation:
    if name == "compressible":
        return _compressible(layer, punch, shape, d0, Pt, H, mu, nu, math.inf, options)
    if options:
        raise InputTypeError(f"the options {sorted(options)} belong to the compressible model, not {name}")
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):  # refused below if not finite
        ans = _two_term(layer, punch, shape, d0, Pt, H, mu, nu, tol, incompressible=(name == "incompressible"))
    if not (math.isfinite(ans.force) and ans.force > 0):
        raise ValidityError(f"solve(): the {name} model's force {ans.force:.4g} is not a positive finite number",
                            "force", math.inf, tol, "direct")
    return ans


def _flat(layer, punch, d0, Pt, H, mu, nu, choice, tol, n=None) -> Indentation:
    """The flat-ended cylinder (F.1): exact Fredholm solution, thin-layer law or thick series."""
    from .flat_punch import flat_punch_fields

    if nu == 0.5 and layer.base == "bonded" and layer.has_compressible_expansion:
        layer = IncompressibleLayer()
    try:
        fields = flat_punch_fields(layer, punch.radius, H, d0, Pt, mu, nu, choice, tol, n)
    except ValueError as exc:
        if choice == "asymptotic" or "max_error" in str(exc):
            raise ValidityError(f"solve(): {exc}".replace("max_error", "tol"), "force", math.inf, tol,
                                "direct") from None
        raise
    fields["punch"] = punch
    return Indentation(**fields)


def _any_thickness(layer, punch, d0, Pt, H, mu, nu, tol) -> Indentation:
    """The any-thickness law (T.7) for the sphere, the thick-layer series (T.5) for other axisymmetric punches."""
    from .any_thickness import NotTabulatedError, any_thickness_fields

    try:
        return Indentation(**any_thickness_fields(layer, punch, delta0=d0, force=Pt, H=H, mu=mu, nu=nu, tol=tol))
    except NotTabulatedError:
        raise
    except ValidityError as exc:
        if exc.model == "other units":  # the law holds, its numbers leave the double range: the true reason
            raise ValidityError(f"solve(): {exc}", exc.quantity, exc.estimate, exc.tol, exc.model) from None
        raise
    except ValueError as exc:  # the estimate exceeds tol
        raise ValidityError(f"solve(): {exc}", "force", math.inf, tol, "direct") from None


def _with_reason(ans: Indentation, why: str, tol: float) -> Indentation:
    import dataclasses

    return dataclasses.replace(ans, reason=why, tol=tol)


def _tol(tol: Any) -> float:
    if isinstance(tol, bool) or not isinstance(tol, (numbers.Real, sp.Number)) or not float(tol) > 0:
        raise InputError(f"tol must be a positive number (the largest accepted relative error estimate, "
                         f"e.g. 0.05; math.inf accepts any), got {tol!r}")
    return float(tol)
