r"""The thin-layer force law (1.8) of a tip of revolution, read through its level set (issue 24).

The general law of :mod:`thinlayer.asymptotics.force_law` is

    P = (vartheta/(A H)) V + coefficient * J + remainder,        coefficient = (vartheta H/A)(M_1 + m_1/2),

with ``V = iint (delta0 - Phi)_+`` and ``J = oint |grad Phi| ds = iint Laplacian Phi`` over the level set
``{Phi < delta0}``.  Its derivation uses the inner terms ``p_0``, ``p_1`` (2.26)-(2.27), (4.1) and the boundary layer
(3.15)-(3.25) at the contour; it holds for a tip whose inner expansion reaches order 1
(:attr:`~thinlayer.punch.Tip.max_inner_order` >= 1), which needs ``Laplacian Phi`` integrable: the divergence
theorem ``iint Laplacian Phi = oint |grad Phi|`` then holds because ``2 pi r Phi'(r) -> 0`` at an apex.  The
coefficient is the engine's, derived on any polynomial punch (it does not depend on the punch); V and J come from the
tip's :meth:`~thinlayer.punch._radial.RadialTip.level_set_expressions` (symbolic) or ``level_set`` (numeric).

Order of the remainder (relative to ``P_0``, ``a`` the level-set radius):

* the boundary layer's next order (curvature of ``Gamma_0``, ``p_1`` seen by the boundary layer): ``O((H/a)^3)``
  (module docstring of :mod:`~thinlayer.asymptotics.force_law`);
* an apex ``Phi ~ C r^n`` (n not an even integer): the inner expansion fails in the region ``r ~ H``, where the
  pressure differs from ``p_0 + p_1`` by ``O(vartheta H C r^{n-2})``, i.e. a force ``O(vartheta C H^{n+1})``; against
  ``P_0 ~ vartheta C a^{n+2}/H`` that is ``O((H/a)^{n+2})``.  The next inner term ``p_2 ~ H^3 Laplacian^2 Phi
  ~ H^3 r^{n-4}`` integrated from ``r ~ H`` gives the same order (``n < 2``) -- no logarithm for ``n != 2``.

So the remainder is ``O((H/a)^q)`` with ``q = min(3, n + 2)`` -- for the cone (``n = 1``) ``q = 3``: at a fixed
contact radius ``|P - P_0 - P_1| ~ vartheta cot(alpha) H^2``.  For the cone
``V = pi tan^2(alpha) delta0^3/3``, ``J = 2 pi delta0``:

    P_0 = pi vartheta tan^2(alpha) delta0^3/(3 A H),        P_1 = 2 pi delta0 (vartheta H/A)(M_1 + m_1/2).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np
import sympy as sp

from .. import symbols as S
from ..display import RichDisplay, fmt
from ..errors import InputError, boundary, boundary_methods
from ..layers.kernels import LayerKernel
from ..normal import normal_latex
from ..punch import Punch, Tip
from .force_law import force_law, lambdify_law

__all__ = ["TipForceLaw", "level_set_arrays", "tip_force_law"]


@boundary_methods
@dataclass(frozen=True)
class TipForceLaw(RichDisplay):
    """``P(delta0) = P0 + P1 + O(P0 (H/a)^q)`` for a tip of revolution (module docstring).

    Attributes
    ----------
    layer, tip
        The layer kernel and the tip.
    P0, P1 : sympy.Expr or None
        The leading force and its first correction in ``delta_0, H, nu`` and the tip's parameters (None when the
        level set has no closed form: then :meth:`evaluate`).
    coefficient : sympy.Expr
        ``(vartheta H/A)(M_1 + m_1/2)``, the engine's (:func:`~thinlayer.asymptotics.force_law.force_law`).
    remainder_order : float
        ``q``: the remainder is ``O(P0 (H/a)^q)``.
    remainder_sources : str
        Where the remainder comes from.
    """

    layer: LayerKernel
    tip: Tip
    P0: sp.Expr | None
    P1: sp.Expr | None
    coefficient: sp.Expr
    remainder_order: float
    remainder_sources: str

    equation = "1.8"

    @property
    def force(self) -> sp.Expr | None:
        """``P0 + P1``."""
        return None if self.P0 is None else self.P0 + self.P1

    def evaluate(self, delta0: float, H: float, mu: float = 1.0, nu: float | None = None) -> tuple[float, float]:
        """``(P0, P1)`` at numbers, through the tip's numeric level set (any tip of revolution); ``nu`` for a layer
        whose kernel fixes none (the frictionless base: ``vartheta = mu/(1 - nu)`` keeps the symbol).
        """
        ls = self.tip.level_set(delta0)
        sub = {S.H: H, S.mu: mu} if nu is None else {S.H: H, S.mu: mu, S.nu: nu}
        th = float((self.layer.vartheta / (self.layer.A * S.H)).subs(sub))
        k = float(self.coefficient.subs(sub))
        return th * ls.volume, k * ls.flux

    def constants(self, H: float, mu: float = 1.0, nu: float | None = None) -> tuple[float, float]:
        """``(vartheta/(A H), coefficient)`` at numbers: ``P0 = first * V``, ``P1 = second * J``."""
        return _constants(self.layer, float(H), float(mu), None if nu is None else float(nu))

    def arrays(self, delta0: Any, H: float, mu: float = 1.0, nu: float | None = None,
               derivative: bool = True) -> dict[str, np.ndarray]:
        r"""``P0``, ``P1``, the level-set radius ``a`` and ``dP/d delta0`` at an array of depths (vectorised).

        From the level set (module docstring): ``P0 = vartheta V/(A H)``, ``P1 = coefficient J`` and, with
        ``dV/d delta0 = pi a^2`` (the area of the level set) and ``J = 2 pi a Phi'(a)``, ``da/d delta0 = 1/Phi'(a)``,

            dP/d delta0 = (vartheta/(A H)) pi a^2 + coefficient 2 pi (1 + a Phi''(a)/Phi'(a)).

        The closed forms of :meth:`~thinlayer.punch._radial.RadialTip.level_set_expressions` where the tip has them;
        otherwise ``a`` by Newton's method on ``Phi(a) = delta0`` (from a monotone table) and
        ``V = pi int_0^a s^2 Phi'(s) ds`` (by parts) by Gauss-Legendre quadrature split at the tip's joins.
        ``nu`` as in :meth:`evaluate`; ``derivative=False`` leaves ``dP`` out.
        """
        d = np.asarray(delta0, dtype=float)
        c0, c1 = self.constants(H, mu, nu)
        a, V, J = level_set_arrays(self.tip, d)
        if not derivative:  # V and J are the compiled forms' own arrays: scaled in place where writable
            return {"P0": _scaled(V, c0, d), "P1": _scaled(J, c1, d), "radius": a}
        slope = self.tip.radial_slope(a)
        curv = self.tip.radial_curvature(a)
        with np.errstate(all="ignore"):
            dP = c0 * np.pi * a * a + c1 * 2 * np.pi * (1.0 + a * curv / slope)
        return {"P0": c0 * V, "P1": c1 * J, "radius": a, "dP": dP}

    codegen_name = "tip_force_law"

    def codegen_expressions(self):
        """``(arguments, {name: expression})`` for :mod:`thinlayer.export.codegen`: ``force`` ``P0 + P1`` (1.8) and
        ``contact_radius`` ``a - h^* H`` (3.25), in ``delta_0, H, mu`` and the layer's and tip's symbols (an angle in
        degrees).  Closed forms only: a tip whose level-set radius solves ``Phi(a) = delta0`` by root finding (the
        blunted cone: ``a`` is a Piecewise of the depth across the join, and its volume is not elementary in
        ``delta0`` on both sides) has none; generate its profile instead, or use :meth:`evaluate`.
        """
        if self.P0 is None:
            raise InputError(f"no closed-form force law for the {self.tip.name}: its level-set radius comes from root "
                             "finding (Phi(a) = delta0 has no closed-form solution here); code generation needs one")
        from .force_law import h_star, law_arguments

        radius = self.tip.level_set_expressions()["radius"] - h_star * S.H
        outs = {"force": self.force, "contact_radius": radius}
        args = tuple(q for q in law_arguments(self.force, radius) if q != h_star)
        if not self.codegen_constants():
            args = args + (h_star,)
        return args, outs

    def codegen_constants(self) -> dict:
        """``{h^*: (number, note)}`` of a layer with one edge shift (as the polynomial force law's)."""
        return force_law(self.layer, Punch.paraboloid()).codegen_constants()

    def lambdify(self, args=None, backend: str = "numpy"):
        """``P0 + P1`` as a numeric function of ``(delta_0, H, mu, ...)`` (closed forms only)."""
        if self.P0 is None:
            raise InputError(f"the force law of the {self.tip.name} has no closed form: use .evaluate(delta0, H, mu)")
        from .force_law import law_arguments

        args = law_arguments(self.force) if args is None else args
        return lambdify_law(args, (self.force,), backend)

    def latex(self) -> str:
        q = f"{self.remainder_order:g}"
        body = r"\frac{\vartheta V}{\mathcal{A} H} + " + normal_latex(self.coefficient) + r"\, J" \
            if self.P0 is None else _sum_latex(normal_latex(self.P0), normal_latex(self.P1))
        return rf"P = {body} + O\!\left(P_0 (H/a)^{{{q}}}\right) \tag{{1.8}}"

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        lines = [f"TipForceLaw: {self.tip.name} on {self.layer}   (1.8)"]
        if self.P0 is not None:
            lines += [f"  P0 = {fmt(self.P0)}", f"  P1 = {fmt(self.P1)}"]
        else:
            lines += [f"  P = vartheta V/(A H) + ({fmt(self.coefficient)}) J  (V, J from the level set)"]
        lines.append(f"  remainder O(P0 (H/a)^{self.remainder_order:g}): {self.remainder_sources}")
        return lines


def _sum_latex(a: str, b: str) -> str:
    """``a + b`` in LaTeX, ``a - c`` when ``b`` is ``-c``."""
    return f"{a} {b}" if b.lstrip().startswith("-") else f"{a} + {b}"


@lru_cache(maxsize=64)
def _constants(layer: LayerKernel, H: float, mu: float, nu: float | None) -> tuple[float, float]:
    sub = {S.H: H, S.mu: mu} if nu is None else {S.H: H, S.mu: mu, S.nu: nu}
    coefficient = force_law(layer, Punch.paraboloid()).coefficient
    return float((layer.vartheta / (layer.A * S.H)).subs(sub)), float(coefficient.subs(sub))


@lru_cache(maxsize=64)
def _closed_level_set(tip: Tip):
    """``delta0 -> (a, V, J)`` compiled from the closed forms, or None."""
    exprs = tip.level_set_expressions()
    if exprs is None:
        return None
    return sp.lambdify(S.delta0, (exprs["radius"], exprs["volume"], exprs["flux"]), "numpy", cse=True,
                       printer=_ProductPowers)


def _product_powers_printer():
    from sympy.printing.numpy import NumPyPrinter

    class ProductPowers(NumPyPrinter):
        """numpy's ``x**3`` is a general ``pow`` (about 12x a multiplication on 1e6 doubles): a power of a symbol
        to a small integer ``n >= 3`` prints as ``(x*x*...*x)`` (within 2 ulp of ``pow``; overflows alike).
        """

        def _print_Pow(self, expr, rational=False):
            n = expr.exp
            if expr.base.is_Symbol and n.is_Integer and 3 <= n <= 6:
                return "(" + "*".join([self._print(expr.base)] * int(n)) + ")"
            return super()._print_Pow(expr, rational=rational)

    return ProductPowers


_ProductPowers = _product_powers_printer()


#: Gauss-Legendre nodes of the volume quadrature on each smooth piece (:func:`level_set_arrays`)
GAUSS_NODES = 48


def level_set_arrays(tip: Tip, delta0: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    r"""``(a, V, J)`` of a tip of revolution at an array of depths (the level set ``{Phi < delta0}``, a disc).

    Closed forms where the tip has them; else ``a`` by Newton's method on ``Phi(a) = delta0`` started from a
    monotone table of Phi, ``V = pi int_0^a s^2 Phi'(s) ds`` (``2 pi int_0^a (delta0 - Phi) s ds`` by parts) by
    Gauss-Legendre quadrature on each piece between the tip's joins (Phi'' jumps there), ``J = 2 pi a Phi'(a)``.
    """
    d = np.asarray(delta0, dtype=float)
    closed = _closed_level_set(tip)
    if closed is not None:
        with np.errstate(all="ignore"):
            a, V, J = (np.asarray(v, dtype=float) for v in closed(d))
        return tuple(v if v.shape == d.shape else np.broadcast_to(v, d.shape) for v in (a, V, J))
    a = _invert_profile(tip, d)
    t, w = np.polynomial.legendre.leggauss(GAUSS_NODES)
    edges = [0.0, *sorted(b for b in tip.radial_breakpoints if b > 0), math.inf]
    V = np.zeros_like(a)
    for lo, hi in zip(edges[:-1], edges[1:]):
        top = np.minimum(a, hi)
        span = np.where(top > lo, top - lo, 0.0)
        s = lo + 0.5 * span[..., None] * (t + 1.0)
        V += np.pi * 0.5 * span * np.sum(w * s * s * tip.radial_slope(s.ravel()).reshape(s.shape), axis=-1)
    return a, V, 2 * np.pi * a * tip.radial_slope(a)


def _scaled(v: np.ndarray, c: float, d: np.ndarray) -> np.ndarray:
    """``c * v``, in ``v``'s own memory when it is a writable array of its own (never the depths ``d``)."""
    if v.flags.writeable and v.flags.owndata and v is not d and v.shape == d.shape and v.ndim:
        v *= c
        return v
    return c * v


def _invert_profile(tip: Tip, d: np.ndarray) -> np.ndarray:
    """The radius ``a`` with ``Phi(a) = d`` (vectorised Newton steps from a table; Phi increasing)."""
    dmax = float(np.max(d)) if d.size else 1.0
    rim = tip.support_radius
    hi = 0.999999 * rim if math.isfinite(rim) else 1.0
    while not math.isfinite(rim) and float(tip.radial_profile(np.array([hi]))[0]) < dmax and hi < 1e300:
        hi *= 2.0
    grid = np.concatenate([[0.0], np.geomspace(1e-9 * hi, hi, 2000)])
    phi = tip.radial_profile(grid)
    a = np.interp(d, phi, grid)
    for _ in range(8):
        f = tip.radial_profile(a) - d
        step = f / tip.radial_slope(a)
        a = np.clip(a - np.where(np.isfinite(step), step, 0.0), 0.5 * a, np.minimum(2.0 * a + 1e-300, hi))
    return a


def _apex_exponent(tip: Tip) -> float | None:
    """``n`` of ``Phi ~ C r^n`` at the apex when n is not an even integer (an apex), else None."""
    if tip.smoothness != "apex":
        return None
    from ..punch._radial import r

    first = tip.radial_expr.args[0][0] if isinstance(tip.radial_expr, sp.Piecewise) else tip.radial_expr
    _, e = sp.simplify(first).as_leading_term(r).as_coeff_exponent(r)
    return float(e) if e.is_number else None


@boundary
def tip_force_law(layer: LayerKernel, tip: Any) -> TipForceLaw:
    """The force law (1.8) of a tip of revolution through its level set (module docstring).

    Examples
    --------
    >>> from thinlayer import BondedLayer, Punch
    >>> law = tip_force_law(BondedLayer(), Punch.cone())
    >>> law.remainder_order
    3.0
    """
    if not isinstance(layer, LayerKernel) or not layer.has_thickness:
        raise InputError(f"the thin-layer law needs a layer of finite thickness (e.g. BondedLayer(0.3)), got {layer!r}")
    if not isinstance(tip, Tip) or not tip.axisymmetric or tip.polynomial is not None or tip.fixed_contact:
        raise InputError(f"tip_force_law takes a tip of revolution that is not a polynomial (Punch.cone(70), "
                         f"Punch.sphere(R), ...); polynomial punches: thinlayer.force_law; got {tip!r:.80}")
    order = tip.max_inner_order
    if order is not None and order < 1:
        raise InputError(f"the inner expansion of the {tip.name} stops before order 1: no first correction")
    # the coefficient of J is the engine's, derived on a polynomial punch: it does not depend on the shape
    coefficient = force_law(layer, Punch.paraboloid()).coefficient
    exprs = tip.level_set_expressions()
    th = layer.vartheta / (layer.A * S.H)
    P0 = P1 = None
    if exprs is not None:
        P0 = sp.factor(th * exprs["volume"])
        P1 = sp.factor(coefficient * exprs["flux"])
    n = _apex_exponent(tip)
    if n is None:
        q, why = 3.0, "the boundary layer's next order (curvature of the contour)"
    else:
        q = min(3.0, n + 2.0)
        why = (f"the boundary layer's next order (H/a)^3 and the apex region r ~ H, (H/a)^{n + 2:g} (Phi ~ r^{n:g})"
               if not math.isclose(n + 2, 3) else "the boundary layer's next order and the apex region r ~ H, both "
                                                  "(H/a)^3 (Phi ~ r)")
    if tip.radial_breakpoints:
        why += "; valid while the contour stays off the join r_t (Laplacian^2 Phi has a line source there)"
    return TipForceLaw(layer, tip, P0, P1, coefficient, q, why)
