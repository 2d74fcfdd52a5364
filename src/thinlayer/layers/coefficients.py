"""Stage (2.20)/(4.2): the Maclaurin coefficients of the layer kernel.

    L(s)/s = A (1 + m_1 s^2 + m_2 s^4 + ...)            (2.20)
    s/L(s) = A^{-1} (1 + M_1 s^2 + M_2 s^4 + ...),
    M_k = - sum_{j=0}^{k-1} m_{k-j} M_j,  M_0 = 1       (4.2)

Computed by power-series arithmetic on the closed-form Taylor coefficients of the
numerator and denominator of L(s)/s (never by ``sympy.series`` on the whole expression):

* symbolic nu (or kappa): fraction-free division in the polynomial ring QQ[nu]; the
  denominators are products of powers of the factors of ``N_0`` and ``D_0`` and are
  cancelled by exact division, which avoids a gcd per coefficient;
* exact rational nu: arithmetic in QQ;
* float nu: mpmath at the layer's precision.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING, Any

import mpmath
import sympy as sp
from sympy import QQ
from sympy.polys.rings import ring

from .. import symbols as S
from .._checks import check_bounded
from .._checks import check_order as _check_order
from .._series import (
    bonded_series_parts,
    powers,
    quotient_field,
    quotient_fraction_free,
    reciprocal_recurrence,
)
from ..display import RichDisplay, fmt
from ..parse import as_expr
from ..results import checked_lambdify

if TYPE_CHECKING:
    from .kernels import LayerKernel


class _PolyDomain:
    """Polynomials in one symbol over QQ (sympy's sparse ring)."""

    kind = "poly"

    def __init__(self, layer: LayerKernel):
        sym = layer.parameter
        self.ring, self.gen = ring([sym], QQ)
        self.one, self.zero = self.ring.one, self.ring.zero
        if sym == S.kappa or not hasattr(layer, "kappa"):
            self.kappa = self.gen
        else:
            self.kappa = 3 - 4 * self.gen

    def const(self, p: int, q: int) -> Any:
        return self.ring(QQ(p, q))


class _RationalDomain:
    kind = "rational"
    one, zero = QQ(1), QQ(0)

    def __init__(self, layer: LayerKernel):
        k = getattr(layer, "kappa", None)
        self.kappa = QQ(int(k.p), int(k.q)) if k is not None else None

    @staticmethod
    def const(p: int, q: int) -> Any:
        return QQ(p, q)


class _MpmathDomain:
    kind = "mpmath"

    def __init__(self, layer: Any):
        self.dps = layer.dps
        with mpmath.workdps(self.dps + 10):
            self.kappa = mpmath.mpf(layer.kappa)
            self.one, self.zero = mpmath.mpf(1), mpmath.mpf(0)

    def const(self, p: int, q: int) -> Any:
        with mpmath.workdps(self.dps + 10):
            return mpmath.mpf(p) / q


def _domain(layer: LayerKernel):
    if layer.parameter is not None:
        return _PolyDomain(layer)
    nu = getattr(layer, "nu", None)
    if isinstance(nu, mpmath.mpf):
        return _MpmathDomain(layer)
    return _RationalDomain(layer)


def _cancel_known(num, den_factors: dict, content) -> tuple[Any, dict, Any]:
    """Cancel ``num / (content * prod f^e)`` by exact division by the known factors f."""
    out = dict(den_factors)
    for f, e in den_factors.items():
        while e > 0 and num:
            q, r = num.div(f)
            if r:
                break
            num, e = q, e - 1
        out[f] = e
    return num, out, content


def _flip(f) -> tuple[int, Any]:
    """(sign, f) with the constant term of f made non-negative: ``2 nu - 1 -> -(1 - 2 nu)``."""
    return (-1, -f) if f.coeff(1) < 0 else (1, f)


def _poly_ratio_expr(num, den_factors: dict, content, domain: _PolyDomain) -> sp.Expr:
    """Sympy expression ``num / (content * prod f^e)``: factored denominator, and a factored
    numerator when its degree is small enough for factoring to be cheap.
    """
    if not num:
        return sp.Integer(0)
    c, prim = num.primitive()
    sign = 1
    if prim.degree() <= 4:
        fc, flist = prim.factor_list()
        c = c * fc
        nfac = []
        for f, e in flist:
            sg, f = _flip(f)
            sign *= sg**e
            nfac.append(sp.Pow(f.as_expr(), e))
        numer = sp.Mul(*nfac)
    else:
        numer = prim.as_expr()
    dfac = []
    for f, e in den_factors.items():
        if e:
            sg, f = _flip(f)
            sign *= sg**e
            dfac.append(sp.Pow(f.as_expr(), e))
    ratio = sign * c / content
    return sp.Rational(int(ratio.numerator), int(ratio.denominator)) * numer / sp.Mul(*dfac)


@dataclass(frozen=True)
class KernelCoefficients(RichDisplay):
    """A, (m_0..m_order) of (2.20) and (M_0..M_order) of (4.2) for one layer.

    For a symbolic layer the entries are sympy expressions (rational functions of nu or
    kappa with factored denominators); for an exact nu, sympy Rationals; for a float nu,
    mpmath numbers at the layer's precision.

    Attributes
    ----------
    layer, order, A, m, M
    """

    layer: LayerKernel
    order: int
    A: Any
    m: tuple
    M: tuple

    equation = "2.20"

    @property
    def A_expr(self) -> sp.Expr:
        return _to_expr(self.A, self.layer)

    def m_expr(self, n: int) -> sp.Expr:
        return _to_expr(self.m[n], self.layer)

    def M_expr(self, k: int) -> sp.Expr:
        return _to_expr(self.M[k], self.layer)

    def series(self, s: sp.Expr = S.s) -> sp.Expr:
        """The truncated series (2.20): ``A (1 + m_1 s^2 + ... + m_order s^(2 order))``."""
        return self.A_expr * sp.Add(*[self.m_expr(k) * s ** (2 * k) for k in range(self.order + 1)])

    def reciprocal_series(self, s: sp.Expr = S.s) -> sp.Expr:
        """The truncated ``s/L(s) = A^{-1}(1 + M_1 s^2 + ...)`` of section 5."""
        return sp.Add(*[self.M_expr(k) * s ** (2 * k) for k in range(self.order + 1)]) / self.A_expr

    def latex(self) -> str:
        """LaTeX of A (2.4), the m_n (2.20) and the M_k (4.2)."""
        lines = [rf"\mathcal{{A}} = {sp.latex(self.A_expr)} \tag{{2.4}}"]
        for n in range(1, self.order + 1):
            lines.append(rf"m_{{{n}}} = {sp.latex(self.m_expr(n))} \tag{{2.20}}")
        for k in range(1, self.order + 1):
            lines.append(rf"M_{{{k}}} = {sp.latex(self.M_expr(k))} \tag{{4.2}}")
        return " \\\\\n".join(lines)

    def lambdify(self, backend: str = "numpy"):
        """Numeric function ``f(nu) -> (A, m_1..m_order, M_1..M_order)`` (symbolic layers only).

        The argument is the layer's parameter (nu, or kappa when ``parameter='kappa'``).
        """
        p = self.layer.parameter
        if p is None:
            raise ValueError("the coefficients of a numeric layer are numbers already")
        exprs = [self.A_expr] + [self.m_expr(n) for n in range(1, self.order + 1)]
        exprs += [self.M_expr(k) for k in range(1, self.order + 1)]
        return checked_lambdify([p], exprs, backend)

    @property
    def codegen_name(self) -> str:
        """The default name of generated functions."""
        return "kernel_coefficients"

    @property
    def codegen_source(self) -> str:
        """What the header of generated code quotes."""
        return f"KernelCoefficients, paper eq. (2.20) and (4.2), {self.layer!r}, order {self.order}"

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """``A, m_1..m_N, M_1..M_N`` (2.20), (4.2) as functions of the layer's parameter (symbolic layers)."""
        p = self.layer.parameter
        if self.layer.symbolic_coefficients:
            raise ValueError("the coefficients of a GenericLayer are the symbols A, m_n themselves; pass the "
                             "expressions you need (e.g. M_expr(k)) with args=[m_1, ...]")
        if p is None:
            raise ValueError("these kernel coefficients have no symbolic parameter (a numeric or parameter-free "
                             "layer): they are numbers already; use e.g. kernel_coefficients(BondedLayer(), n)")
        outs = {"A": self.A_expr, **{f"m_{n}": self.m_expr(n) for n in range(1, self.order + 1)},
                **{f"M_{k}": self.M_expr(k) for k in range(1, self.order + 1)}}
        return (p,), outs

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        out = [f"KernelCoefficients of {self.layer}, n <= {self.order}   (2.4), (2.20), (4.2)"]
        w = len(f"m_{self.order}")
        out.append(f"  {'A':<{w}} = {fmt(self.A_expr if self.layer.parameter is not None else self.A)}")
        for n in range(1, self.order + 1):
            out.append(f"  {f'm_{n}':<{w}} = {fmt(self.m[n])}")
        for k in range(1, self.order + 1):
            out.append(f"  {f'M_{k}':<{w}} = {fmt(self.M[k])}")
        return out


def _to_expr(x: Any, layer: LayerKernel) -> sp.Expr:
    if isinstance(x, sp.Basic):
        return x
    if isinstance(x, mpmath.mpf):
        return sp.Float(x, getattr(layer, "dps", 15))
    return as_expr(x)


def _symbolic_coefficients(layer: LayerKernel, order: int) -> KernelCoefficients:
    """A layer known by its coefficients: ``A``, ``m_n`` plain symbols, ``M_k`` polynomials in them by (4.2)."""
    m = [sp.Integer(1)] + [layer.m_symbol(n) for n in range(1, order + 1)]
    M = reciprocal_recurrence(m, order, sp.Integer(1), sp.Integer(0))
    return KernelCoefficients(layer, order, layer.A_symbol, tuple(m), tuple(sp.expand(x) for x in M))


#: Largest order accepted per kind of coefficient arithmetic, with the measured time of that order
#: (kernel_coefficients(layer, n), cold cache, on the 2-core build machine).  Checked before any work.
ORDER_LIMITS: dict[str, tuple[int, str]] = {
    "poly": (30, "symbolic nu (or kappa) coefficients cost 2.9 s at order 30, 15 s at 40 and 31 s at 50 "
                 "(growing like order^5); give a number for nu (BondedLayer('3/10') or 0.3) for higher orders"),
    "rational": (200, "exact rational coefficients cost 1.2 s at order 200 and 4.7 s at 300"),
    "mpmath": (500, "float (mpmath) coefficients cost 2.1 s at order 500 and 5.8 s at 1000"),
    "generic": (12, "the M_k of a GenericLayer are polynomials in m_1..m_k whose size grows like the partitions "
                    "of k: 1.3 s at order 12, 10.5 s at 16, 198 s at 20"),
    "incompressible": (200, "exact incompressible coefficients cost 0.36 s at order 200 and 1.7 s at 300"),
}


def _domain_kind(layer: LayerKernel) -> str:
    if layer.symbolic_coefficients:
        return "generic"
    if layer.parameter is not None:
        return "poly"
    return "mpmath" if isinstance(getattr(layer, "nu", None), mpmath.mpf) else "rational"


def order_limit(layer: LayerKernel) -> tuple[int, str]:
    """The largest coefficient order :func:`kernel_coefficients` accepts for ``layer`` and why.

    Returns
    -------
    tuple of (int, str)
        The limit and the reason (with the measured time at the limit), see :data:`ORDER_LIMITS`.

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> order_limit(BondedLayer())[0], order_limit(BondedLayer("3/10"))[0], order_limit(BondedLayer(0.3))[0]
    (30, 200, 500)
    """
    return ORDER_LIMITS[_domain_kind(layer)]


def check_coefficient_order(layer: LayerKernel, order: int, name: str = "order") -> int:
    """``order`` checked against :func:`order_limit` (a :class:`~thinlayer._checks.WorkLimitError` above it)."""
    limit, reason = order_limit(layer)
    return check_bounded(order, name, limit, reason)


@lru_cache(maxsize=256)
def kernel_coefficients(layer: LayerKernel, order: int) -> KernelCoefficients:
    """A, m_n (2.20) and M_k by the recurrence (4.2), for n, k <= ``order``.

    Parameters
    ----------
    layer : LayerKernel
        Any :class:`~thinlayer.layers.kernels.LayerKernel` with a small-s expansion.
    order : int
        Highest index n of m_n and M_n (a non-negative integer).  Bounded before any work starts
        (:data:`ORDER_LIMITS`): 30 for a symbolic nu (2.9 s measured), 200 for an exact nu (1.2 s),
        500 for a float nu (2.1 s), 12 for a GenericLayer (1.3 s).

    Raises
    ------
    thinlayer._checks.WorkLimitError
        (a ValueError) above the limit, naming it and the measured cost.

    Examples
    --------
    >>> from thinlayer import BondedLayer, kernel_coefficients
    >>> c = kernel_coefficients(BondedLayer(), 1)
    >>> c.m[1]
    -nu*(1 - 4*nu)/(3*(1 - 2*nu)*(1 - nu))
    """
    order = check_coefficient_order(layer, _check_order(order, "order"))
    if layer.symbolic_coefficients:
        return _symbolic_coefficients(layer, order)
    dom = _domain(layer)
    if dom.kind == "mpmath":
        with mpmath.workdps(dom.dps + 10):
            num, den = layer.series_parts(order, dom)
    else:
        num, den = layer.series_parts(order, dom)
    if dom.kind == "poly":
        A, m, M = _coefficients_poly(num, den, order, dom)
    elif dom.kind == "mpmath":
        with mpmath.workdps(dom.dps + 10):
            q = quotient_field(num, den, order)
            m = [qi / q[0] for qi in q]
            M = reciprocal_recurrence(m, order, dom.one, dom.zero)
            A = q[0]
        with mpmath.workdps(dom.dps):
            A, m, M = +A, [+x for x in m], [+x for x in M]
    else:
        q = quotient_field(num, den, order)
        m = [qi / q[0] for qi in q]
        M = reciprocal_recurrence(m, order, dom.one, dom.zero)
        A = sp.Rational(int(q[0].numerator), int(q[0].denominator))
        m = [sp.Rational(int(x.numerator), int(x.denominator)) for x in m]
        M = [sp.Rational(int(x.numerator), int(x.denominator)) for x in M]
    return KernelCoefficients(layer, order, A, tuple(m), tuple(M))


def _coefficients_poly(num, den, order, dom: _PolyDomain):
    T = quotient_fraction_free(num, den, order, dom.one)
    T0, d0 = T[0], den[0]
    c_T0, f_T0 = T0.factor_list()
    c_d0, f_d0 = d0.factor_list()

    def ratio(numer, eT0: int, ed0: int) -> sp.Expr:
        factors: dict = {}
        for f, e in f_T0:
            factors[f] = factors.get(f, 0) + e * eT0
        for f, e in f_d0:
            factors[f] = factors.get(f, 0) + e * ed0
        content = c_T0**eT0 * c_d0**ed0
        numer, factors, content = _cancel_known(numer, factors, content)
        return _poly_ratio_expr(numer, factors, content, dom)

    A = ratio(T0, 0, 1)
    # m_n = T_n / (T_0 d0^n)
    m = [sp.Integer(1)] + [ratio(T[n], 1, n) for n in range(1, order + 1)]
    # (4.2) with a common denominator: M_k = U_k / (T_0^k d0^k),
    # U_k = - sum_{j<k} T_{k-j} U_j T_0^{k-j-1}
    T0p = powers(T0, order, dom.one)
    U = [dom.one]
    for k in range(1, order + 1):
        acc = dom.zero
        for j in range(k):
            acc -= T[k - j] * U[j] * T0p[k - j - 1]
        U.append(acc)
    M = [sp.Integer(1)] + [ratio(U[k], k, k) for k in range(1, order + 1)]
    return A, m, M


def reciprocal_by_inversion(layer: LayerKernel, order: int) -> tuple:
    """M_0..M_order from the direct inversion ``s/L(s) = D(s^2)/N(s^2)`` (independent of (4.2)).

    Used to cross-check the recurrence (4.2).  Returns sympy objects (or mpmath numbers).  The order is
    bounded as in :func:`kernel_coefficients`.
    """
    order = check_coefficient_order(layer, _check_order(order, "order"))
    if layer.symbolic_coefficients:
        return _symbolic_coefficients(layer, order)
    dom = _domain(layer)
    ctx = mpmath.workdps(dom.dps + 10) if dom.kind == "mpmath" else _nullcontext()
    with ctx:
        num, den = layer.series_parts(order, dom)
    if dom.kind == "poly":
        T = quotient_fraction_free(den, num, order, dom.one)  # r_k = T_k / N_0^(k+1)
        out = [sp.cancel(T[k].as_expr() / (T[0].as_expr() * num[0].as_expr() ** k)) for k in range(order + 1)]
        return tuple(out)
    ctx = mpmath.workdps(dom.dps + 10) if dom.kind == "mpmath" else _nullcontext()
    with ctx:
        r = quotient_field(den, num, order)
        out = [x / r[0] for x in r]
    if dom.kind == "rational":
        return tuple(sp.Rational(int(x.numerator), int(x.denominator)) for x in out)
    return tuple(out)


class _nullcontext:
    def __enter__(self):
        return self

    def __exit__(self, *a):
        return False


@dataclass(frozen=True)
class IncompressibleCoefficients:
    """Maclaurin coefficients ``L(s)/s = sum_n c_n s^{2n}`` of the incompressible kernel (I.1).

    Attributes
    ----------
    order : int
        Highest n.
    c : tuple
        ``(c_0, ..., c_order)`` as sympy Rationals; ``c_0 = A = 0``, ``c_1 = 2/3``.
    """

    order: int
    c: tuple

    equation = "I.1"

    def series(self, s: sp.Expr = S.s) -> sp.Expr:
        """The truncated series ``sum_{n <= order} c_n s^{2n}``."""
        return sp.Add(*[cn * s ** (2 * n) for n, cn in enumerate(self.c)])

    def latex(self) -> str:
        terms = " + ".join(rf"\left({sp.latex(cn)}\right) s^{{{2 * n}}}" for n, cn in enumerate(self.c) if n)
        return rf"\frac{{\mathcal{{L}}(s)}}{{s}} = {terms} + \dots,\quad \mathcal{{A}} = c_0 = 0 \tag{{I.1}}"

    def lambdify(self, backend: str = "numpy") -> Callable:
        """``f() -> (c_0, ..., c_order)`` (numbers; no arguments)."""
        return checked_lambdify([], list(self.c), backend)


@lru_cache(maxsize=32)
def incompressible_coefficients(order: int) -> IncompressibleCoefficients:
    """``c_n`` of ``L(s)/s = c_1 s^2 + c_2 s^4 + ...`` for the incompressible layer (I.1).

    Power-series division of the closed-form Taylor coefficients of the numerator and denominator
    of (2.3) at ``kappa = 1`` over QQ (as :func:`thinlayer.kernel_coefficients` does for ``nu < 1/2``).
    ``order <= 200`` (0.36 s measured; 1.7 s at 300), checked before any work.

    Examples
    --------
    >>> incompressible_coefficients(3).c
    (0, 2/3, -6/5, 46/21)
    """
    limit, reason = ORDER_LIMITS["incompressible"]
    order = check_bounded(_check_order(order, "order"), "order", limit, reason)
    num, den = bonded_series_parts(QQ(1), order, QQ)
    q = quotient_field(num, den, order)
    return IncompressibleCoefficients(order, tuple(sp.Rational(int(x.numerator), int(x.denominator)) for x in q))
