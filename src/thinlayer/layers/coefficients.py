"""Stage (2.20)/(4.2): the Maclaurin coefficients of the layer kernel.

    L(s)/s = A (1 + m_1 s^2 + m_2 s^4 + ...)            (2.20)
    s/L(s) = A^{-1} (1 + M_1 s^2 + M_2 s^4 + ...),
    M_k = - sum_{j=0}^{k-1} m_{k-j} M_j,  M_0 = 1       (4.2)

Computed by power-series arithmetic on the closed-form Taylor coefficients of the
numerator and denominator of ``L(s)/s = N(z)/D(z)``, ``z = s^2`` (never by ``sympy.series``
on the whole expression):

* symbolic nu (or kappa): both quotients ``N/D`` (the m_n) and ``D/N`` (the M_k, the same
  numbers as (4.2), checked in the tests) are computed directly in the polynomial ring QQ[nu]
  after the substitution ``z = g y``, ``g`` the product of the distinct factors of ``D_0``
  (of ``N_0`` for ``D/N``): then ``D(g y)/D_0 = 1 + ...`` has polynomial coefficients, the
  quotient needs no division, and its coefficients ``C_n`` carry the reduced denominators
  (``m_n = C_n / (N_0 g^n)``: for the bonded layer ``(1 - 2 nu)(1 - nu)^n``) instead of the
  ``D_0^n`` of a fraction-free division.  The products are done by Kronecker substitution
  (a polynomial is packed into one big integer, so a product of polynomials is one product of
  integers), or by python-flint's ``fmpq_poly`` when it is installed (:mod:`._flint`, the
  ``fast`` extra); both give the same exact polynomials;
* exact rational nu: arithmetic in QQ;
* float nu: mpmath at the layer's precision.

Results are cached per layer at the highest order computed so far: a lower order is served
from it, a higher one extends it (the recurrences are incremental), so asking for
``m(1), m(2), ..., m(N)`` costs about as much as asking for ``N`` once.
"""
from __future__ import annotations

import importlib
import threading
from collections import OrderedDict
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import lru_cache
from math import gcd, lcm
from typing import TYPE_CHECKING, Any

import mpmath

from .. import symbols as S
from .._checks import InputError, check_bounded
from .._checks import check_order as _check_order
from .._lazy import lazy_function, lazy_module
from .._series import (
    bonded_series_parts,
    quotient_field,
    quotient_fraction_free,
    reciprocal_recurrence,
)
from ..display import RichDisplay, fmt
from ..errors import boundary
from ..parse import as_expr
from ..results import checked_lambdify
from . import _flint

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it
join_signed = lazy_function("thinlayer.normal", "join_signed")
normal_latex = lazy_function("thinlayer.normal", "normal_latex")  # the printers subclass sympy's

try:  # GMP integers make the Kronecker products several times faster; plain ints otherwise
    from gmpy2 import mpz as _big
except ImportError:  # pragma: no cover - gmpy2 is the usual companion of sympy
    _big = int

if TYPE_CHECKING:
    from .kernels import LayerKernel


class _PolyDomain:
    """Polynomials in one symbol over QQ (sympy's sparse ring)."""

    kind = "poly"

    def __init__(self, layer: LayerKernel):
        sym = layer.parameter
        self.ring, self.gen = importlib.import_module("sympy.polys.rings").ring([sym], sp.QQ)
        self.one, self.zero = self.ring.one, self.ring.zero
        if sym == S.kappa or not hasattr(layer, "kappa"):
            self.kappa = self.gen
        else:
            self.kappa = 3 - 4 * self.gen

    def const(self, p: int, q: int) -> Any:
        return self.ring(sp.QQ(p, q))


class _RationalDomain:
    kind = "rational"

    def __init__(self, layer: LayerKernel):
        self.one, self.zero = sp.QQ(1), sp.QQ(0)
        k = getattr(layer, "kappa", None)
        self.kappa = sp.QQ(int(k.p), int(k.q)) if k is not None else None

    @staticmethod
    def const(p: int, q: int) -> Any:
        return sp.QQ(p, q)


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


def _divides(f, num) -> bool:
    """Whether the primitive polynomial f divides num exactly (a root test for a linear f)."""
    if f.degree() != 1:
        return not num.div(f)[1]
    a, b = int(f.coeff(f.ring.gens[0]).numerator), int(f.coeff(1).numerator)
    # a^deg num(-b/a) == 0, by Horner's rule on integers after clearing num's denominators
    co, _ = _int_poly(num)
    acc, ap = 0, 1
    for c in reversed(co):
        acc = acc * -b + c * ap
        ap *= a
    return acc == 0


def _cancel_known(num, den_factors: dict, content) -> tuple[Any, dict, Any]:
    """Cancel ``num / (content * prod f^e)`` by exact division by the known factors f."""
    out = dict(den_factors)
    for f, e in den_factors.items():
        while e > 0 and num and _divides(f, num):
            q, r = num.div(f)
            if r:  # pragma: no cover - _divides said it divides
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

    Above degree 4 the expanded numerator is built term by term with the constant factor already
    folded into its coefficients: the same expression as ``ratio * prim.as_expr() / prod f^e`` (which
    distributes ``ratio`` over the sum), without building the sum twice.
    """
    if not num:
        return sp.Integer(0)
    c, prim = num.primitive()
    sign = 1
    nfac = []
    if prim.degree() <= 4:
        fc, flist = prim.factor_list()
        c = c * fc
        for f, e in flist:
            sg, f = _flip(f)
            sign *= sg**e
            nfac.append(sp.Pow(f.as_expr(), e))
    dfac = []
    for f, e in den_factors.items():
        if e:
            sg, f = _flip(f)
            sign *= sg**e
            dfac.append(sp.Pow(_factor_expr(f), e))
    ratio = sign * c / content
    r = sp.Rational(int(ratio.numerator), int(ratio.denominator))
    if prim.degree() <= 4:  # one Mul: the factored form stays (r * (1 - 2 nu) alone would distribute to 1/2 - nu)
        return sp.Mul(r, *nfac, *[sp.Pow(b, -e) for b, e in (d.as_base_exp() for d in dfac)])
    x = domain.ring.symbols[0]
    numer = sp.Add(*[sp.Mul(r * int(a), x**i) for (i,), a in prim.items()])
    return sp.Mul(numer, *[sp.Pow(b, -e) for b, e in (d.as_base_exp() for d in dfac)])


@lru_cache(maxsize=256)
def _factor_expr(f) -> sp.Expr:
    """``f.as_expr()`` for a small factor of a denominator (the same few factors recur in every coefficient)."""
    return f.as_expr()


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

    def series(self, s: sp.Expr | None = None) -> sp.Expr:
        """The truncated series (2.20): ``A (1 + m_1 s^2 + ... + m_order s^(2 order))``."""
        s = S.s if s is None else s
        return self.A_expr * sp.Add(*[self.m_expr(k) * s ** (2 * k) for k in range(self.order + 1)])

    def reciprocal_series(self, s: sp.Expr | None = None) -> sp.Expr:
        """The truncated ``s/L(s) = A^{-1}(1 + M_1 s^2 + ...)`` of section 5."""
        s = S.s if s is None else s
        return sp.Add(*[self.M_expr(k) * s ** (2 * k) for k in range(self.order + 1)]) / self.A_expr

    def latex(self) -> str:
        """LaTeX of A (2.4), the m_n (2.20) and the M_k (4.2)."""
        lines = [rf"\mathcal{{A}} = {normal_latex(self.A_expr)} \tag{{2.4}}"]
        for n in range(1, self.order + 1):
            lines.append(rf"m_{{{n}}} = {normal_latex(self.m_expr(n))} \tag{{2.20}}")
        for k in range(1, self.order + 1):
            lines.append(rf"M_{{{k}}} = {normal_latex(self.M_expr(k))} \tag{{4.2}}")
        return " \\\\\n".join(lines)

    def lambdify(self, backend: str = "numpy"):
        """Numeric function ``f(nu) -> (A, m_1..m_order, M_1..M_order)`` (symbolic layers only).

        The argument is the layer's parameter (nu, or kappa when ``parameter='kappa'``).
        """
        p = self.layer.parameter
        if p is None:
            raise InputError("the coefficients of a numeric layer are numbers already")
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
            raise InputError("the coefficients of a GenericLayer are the symbols A, m_n themselves; pass the "
                             "expressions you need (e.g. M_expr(k)) with args=[m_1, ...]")
        if p is None:
            raise InputError("these kernel coefficients have no symbolic parameter (a numeric or parameter-free "
                             "layer): they are numbers already; use e.g. kernel_coefficients(BondedLayer(), n)")
        outs = {"A": self.A_expr, **{f"m_{n}": self.m_expr(n) for n in range(1, self.order + 1)},
                **{f"M_{k}": self.M_expr(k) for k in range(1, self.order + 1)}}
        return (p,), outs

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        out = [f"KernelCoefficients of {self.layer}, n <= {self.order}   (2.4), (2.20), (4.2)"]
        sub = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
        w = len(f"m{self.order}")
        out.append(f"  {'𝒜':<{w}} = {fmt(self.A_expr if self.layer.parameter is not None else self.A)}")
        for n in range(1, self.order + 1):
            out.append(f"  {'m' + str(n).translate(sub):<{w}} = {fmt(self.m[n])}")
        for k in range(1, self.order + 1):
            out.append(f"  {'M' + str(k).translate(sub):<{w}} = {fmt(self.M[k])}")
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
    "poly": (30, "symbolic nu (or kappa) coefficients cost 0.1 s at order 30 and 0.3 s at 50; the limit also "
                 "bounds the stages built on them (the inner expansion); give a number for nu "
                 "(BondedLayer('3/10') or 0.3) for higher orders"),
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


#: Coefficient arithmetic for a symbolic layer: ``"python"`` (Kronecker products of Python/GMP integers),
#: ``"flint"`` (python-flint's fmpq_poly, the ``fast`` extra) or ``"auto"`` (flint when it is installed).
BACKENDS = ("auto", "python", "flint")


@boundary
def kernel_coefficients(layer: LayerKernel, order: int, *, backend: str | None = None) -> KernelCoefficients:
    """A, m_n (2.20) and M_k (4.2), for n, k <= ``order``.

    Parameters
    ----------
    layer : LayerKernel
        Any :class:`~thinlayer.layers.kernels.LayerKernel` with a small-s expansion.
    order : int
        Highest index n of m_n and M_n (a non-negative integer).  Bounded before any work starts
        (:data:`ORDER_LIMITS`): 30 for a symbolic nu, 200 for an exact nu, 500 for a float nu,
        12 for a GenericLayer.
    backend : {None, "auto", "python", "flint"}
        Arithmetic of a symbolic layer's polynomials (the results are the same exact expressions).
        None (default): the cached coefficients of ``layer``, computed with ``"auto"`` (python-flint when it
        is installed, else pure Python).  An explicit backend computes afresh and caches nothing
        (for comparisons); ``"flint"`` raises ImportError without python-flint.

    Returns
    -------
    KernelCoefficients
        Served from the coefficients of the highest order computed so far for this layer when that is
        at least ``order``; a higher order extends them.  ``kernel_coefficients.cache_clear()`` forgets them.

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
    >>> kernel_coefficients(BondedLayer(), 1, backend="python").m == c.m
    True
    """
    order = check_coefficient_order(layer, _check_order(order, "order"))
    if backend is not None:
        if backend not in BACKENDS:
            raise InputError(f"backend must be one of {BACKENDS}, got {backend!r}")
        eng = _engine(layer, backend)
        eng.extend(order)
        return eng.view(order)
    with _LOCK:
        eng = _ENGINES.get(layer)
        if eng is None:
            eng = _ENGINES[layer] = _engine(layer, "auto")
            if len(_ENGINES) > _MAX_LAYERS:
                _ENGINES.popitem(last=False)
        else:
            _ENGINES.move_to_end(layer)
        if eng.order < order:
            eng.extend(order)
        return eng.view(order)


def _cache_clear() -> None:
    """Forget every cached coefficient (the next call computes from scratch)."""
    with _LOCK:
        _ENGINES.clear()


kernel_coefficients.cache_clear = _cache_clear  # type: ignore[attr-defined]

_LOCK = threading.RLock()
_MAX_LAYERS = 64
_ENGINES: OrderedDict[Any, Any] = OrderedDict()


def _engine(layer: LayerKernel, backend: str):
    if layer.symbolic_coefficients:
        return _GenericEngine(layer)
    dom = _domain(layer)
    if dom.kind == "poly":
        return _PolyEngine(layer, dom, backend)
    if dom.kind == "mpmath":
        return _MpmathEngine(layer, dom)
    return _RationalEngine(layer, dom)


class _Engine:
    """The coefficients of one layer up to ``order`` (-1: none yet), extended on demand."""

    def __init__(self, layer: LayerKernel):
        self.layer, self.order = layer, -1
        self.A: Any = None
        self.m: list = []
        self.M: list = []
        self._views: dict[int, KernelCoefficients] = {}
        self._parts: tuple[Sequence[Any], Sequence[Any]] | None = None

    def view(self, order: int) -> KernelCoefficients:
        v = self._views.get(order)
        if v is None:
            v = KernelCoefficients(self.layer, order, self.A, tuple(self.m[: order + 1]), tuple(self.M[: order + 1]))
            self._views[order] = v
        return v

    def extend(self, order: int) -> None:
        raise NotImplementedError

    def series_parts(self, order: int, dom: Any) -> tuple[Sequence[Any], Sequence[Any]]:
        """The layer's Taylor data to at least ``order``, computed a few orders ahead (cheap: closed forms) so
        that extending one order at a time does not recompute them every time.
        """
        parts = self._parts
        if parts is None or len(parts[0]) <= order:
            parts = self._parts = self.layer.series_parts(max(order, min(2 * order, order + 16)), dom)
        return parts


class _GenericEngine(_Engine):
    """GenericLayer: A, m_n plain symbols, M_k polynomials in them by (4.2) (recomputed to extend)."""

    def extend(self, order: int) -> None:
        if order <= self.order:
            return
        c = _symbolic_coefficients(self.layer, order)
        self.A, self.m, self.M, self.order = c.A, list(c.m), list(c.M), order


class _RationalEngine(_Engine):
    """Exact rational nu: the recurrences of :func:`~thinlayer._series.quotient_field` and (4.2) over QQ."""

    def __init__(self, layer: LayerKernel, dom: Any):
        super().__init__(layer)
        self.dom = dom
        self._q: list = []
        self._mq: list = []
        self._Mq: list = []

    def _continue(self, num: Sequence[Any], den: Sequence[Any], order: int) -> int:
        """Continue q (the quotient num/den), m = q/q_0 and M (4.2) to ``order``; the first new index."""
        q, mq, Mq = self._q, self._mq, self._Mq
        start = len(q)
        for k in range(start, order + 1):
            acc = num[k]
            for j in range(1, k + 1):
                acc -= den[j] * q[k - j]
            q.append(acc / den[0])
            mq.append(q[k] / q[0])
            if k == 0:
                Mq.append(self.dom.one)
            else:
                acc = self.dom.zero
                for j in range(k):
                    acc -= mq[k - j] * Mq[j]
                Mq.append(acc)
        return start

    def extend(self, order: int) -> None:
        if order <= self.order:
            return
        num, den = self.series_parts(order, self.dom)
        start = self._continue(num, den, order)
        rat = lambda x: sp.Rational(int(x.numerator), int(x.denominator))
        if start == 0:
            self.A = rat(self._q[0])
        self.m += [rat(x) for x in self._mq[start:]]
        self.M += [rat(x) for x in self._Mq[start:]]
        self.order = order


class _MpmathEngine(_RationalEngine):
    """Float nu: the same recurrences in mpmath at dps + 10 digits, rounded to the layer's dps."""

    def extend(self, order: int) -> None:
        if order <= self.order:
            return
        dps = self.dom.dps
        with mpmath.workdps(dps + 10):
            num, den = self.series_parts(order, self.dom)
            start = self._continue(num, den, order)
        with mpmath.workdps(dps):
            if start == 0:
                self.A = +self._q[0]
            self.m += [+x for x in self._mq[start:]]
            self.M += [+x for x in self._Mq[start:]]
        self.order = order


def _int_poly(p) -> tuple[list[int], int]:
    """(integer coefficients, lowest first; positive denominator) of a polynomial over QQ in one variable."""
    if not p:
        return [], 1
    items = [(k[0], c) for k, c in p.items()]
    d = 1
    for _, c in items:
        d = lcm(d, int(c.denominator))
    co = [0] * (max(i for i, _ in items) + 1)
    for i, c in items:
        co[i] = int(c.numerator) * (d // int(c.denominator))
    return co, d


def _from_int_poly(co: Sequence[int], d: int, ring_: Any) -> Any:
    """The ring element ``sum co[i] x^i / d`` (inverse of :func:`_int_poly`)."""
    dom = ring_.domain
    return ring_.from_dict({(i,): dom(c, d) for i, c in enumerate(co) if c})


def _reduced(co: list[int], d: int) -> tuple[list[int], int]:
    """``co/d`` with the common factor of the coefficients and the denominator removed, trailing zeros dropped."""
    while co and not co[-1]:
        co.pop()
    if not co:
        return [], 1
    g = gcd(d, *co)
    if g != 1:
        co, d = [c // g for c in co], d // g
    return co, d


class _Packed:
    """A polynomial ``coeffs/den`` over QQ with its integer numerator packed at ``x = 2^B``."""

    __slots__ = ("coeffs", "den", "norm", "v")

    def __init__(self, coeffs: list[int], den: int):
        self.coeffs, self.den = coeffs, den
        self.norm = sum(abs(c) for c in coeffs)  # the 1-norm bounds every coefficient of a product
        self.v: Any = 0


def _pack(coeffs: Sequence[int], B: int) -> Any:
    v = _big(0)
    for c in reversed(coeffs):
        v = (v << B) + c
    return v


def _unpack(v: Any, B: int) -> list[int]:
    """The signed base-2^B digits of v, lowest first: the coefficients of a polynomial packed at x = 2^B."""
    out, mask, half, full = [], (1 << B) - 1, 1 << (B - 1), 1 << B
    while v:
        r = int(v & mask)
        if r >= half:
            r -= full
        out.append(r)
        v = (v - r) >> B
    return out


class _KroneckerQuotient:
    """Coefficients ``C_k`` of ``P(y)/Q(y)``, ``Q_0 = 1``, with polynomial coefficients over QQ.

    ``C_k = P_k - sum_{j=1}^k Q_j C_{k-j}`` evaluated at ``x = 2^B`` (Kronecker substitution, a ring
    homomorphism ZZ[x] -> ZZ): each product of polynomials is one product of (GMP) integers.  The
    coefficients of ``C_k`` are read back as signed base-2^B digits, exactly, because ``B`` is kept above
    the bit length of the 1-norm bound ``sum |Q_j|_1 |C_{k-j}|_1`` (the packed values are recomputed when
    ``B`` grows).  Same interface as :class:`thinlayer.layers._flint.FlintQuotient`.
    """

    name = "python"

    def __init__(self) -> None:
        self._P: list[_Packed] = []
        self._Q: list[_Packed] = []
        self._C: list[_Packed] = []
        self._B = 64

    def _repack(self, B: int) -> None:
        self._B = B
        for e in (*self._P, *self._Q, *self._C):
            e.v = _pack(e.coeffs, B)

    def extend(self, P: Sequence[tuple[list[int], int]], Q: Sequence[tuple[list[int], int]]
               ) -> list[tuple[list[int], int]]:
        for dst, src in ((self._P, P), (self._Q, Q)):
            for co, d in src[len(dst):]:
                e = _Packed(co, d)
                e.v = _pack(co, self._B)
                dst.append(e)
        Pl, Ql, Cl = self._P, self._Q, self._C
        start = len(Cl)
        for k in range(start, len(Pl)):
            pk = Pl[k]
            dens = [Ql[j].den * Cl[k - j].den for j in range(1, k + 1)]
            L = lcm(pk.den, *dens)
            bound = pk.norm * (L // pk.den)
            for j in range(1, k + 1):
                bound += Ql[j].norm * Cl[k - j].norm * (L // dens[j - 1])
            need = bound.bit_length() + 2
            if need > self._B:
                self._repack(max(need + need // 4, 2 * self._B))
            acc = pk.v * (L // pk.den)
            for j in range(1, k + 1):
                f = L // dens[j - 1]
                t = Ql[j].v * Cl[k - j].v
                acc -= t * f if f != 1 else t
            co, d = _reduced(_unpack(acc, self._B), L)
            e = _Packed(co, d)
            e.v = acc // (L // d)  # the reduced numerator, packed: exact
            Cl.append(e)
        return [(e.coeffs, e.den) for e in Cl[start:]]


def _quotient_backend(backend: str):
    if backend == "flint" or (backend == "auto" and _flint.available()):
        return _flint.FlintQuotient()
    return _KroneckerQuotient()


def _factored(p) -> tuple[Any, dict]:
    """``(content, {primitive factor: exponent})`` of a nonzero polynomial."""
    c, fl = p.factor_list()
    return c, dict(fl)


class _ScaledQuotient:
    """The coefficients ``q_k = C_k / (a_0 g^k)`` of ``a(z)/b(z)`` for polynomial-valued series a, b.

    With ``z = g y`` and ``g`` the product of the distinct factors of ``b_0`` (``b_0`` itself when that
    fails to make ``b_k g^k / b_0`` polynomials), ``a(z)/b(z) = (1/b_0) sum_k a_k g^k y^k / (1 + sum_{k>=1}
    (b_k g^k / b_0) y^k)``, a quotient by a series with constant term 1: ring operations only.  ``C_0 = a_0``.
    """

    def __init__(self, b0, backend: str):
        self.b0 = b0
        self._backend = backend
        content, factors = _factored(b0)
        self._use_radical(factors)

    def _use_radical(self, factors: dict | None) -> None:
        one = self.b0.ring.one
        if factors is None:  # the fallback: g = b_0, always exact
            self.g = self.b0
            self.g_content, self.g_factors = _factored(self.b0)
        else:
            self.g = one
            for f in factors:
                self.g *= f
            self.g_content, self.g_factors = 1, {f: 1 for f in factors}
        self._gp = [one]
        self._P: list = []
        self._Q: list = []
        self._arith = _quotient_backend(self._backend)
        self.C: list = []

    def extend(self, a: Sequence[Any], b: Sequence[Any]) -> int:
        """Continue ``C`` to ``len(a) - 1``; returns the first new index (0 after a restart)."""
        n = len(a) - 1
        while True:
            gp = self._gp
            while len(gp) <= n:
                gp.append(gp[-1] * self.g)
            ok = True
            for k in range(len(self._P), n + 1):
                if k == 0:
                    qk = self.b0.ring.one
                else:
                    qk, r = (b[k] * gp[k]).div(self.b0)
                    if r:
                        ok = False
                        break
                self._P.append(_int_poly(a[k] * gp[k]))
                self._Q.append(_int_poly(qk))
            if ok:
                break
            self._use_radical(None)  # a factor of b_0 repeated beyond what g^k supplies: g = b_0
        start = len(self.C)
        ring_ = self.b0.ring
        self.C += [_from_int_poly(co, d, ring_) for co, d in self._arith.extend(self._P, self._Q)]
        return start


class _PolyEngine(_Engine):
    """Symbolic nu (or kappa): m_n from ``N/D``, M_k from ``D/N`` (:class:`_ScaledQuotient`), cached as expressions."""

    def __init__(self, layer: LayerKernel, dom: _PolyDomain, backend: str):
        super().__init__(layer)
        self.dom, self.backend = dom, backend
        self._nd: _ScaledQuotient | None = None
        self._dn: _ScaledQuotient | None = None

    def _setup(self, num, den) -> None:
        N0, D0 = num[0], den[0]
        if not N0:
            raise InputError(f"A = 0 for {self.layer!r}: the expansion (2.20) does not exist")
        self._N0, self._D0 = _factored(N0), _factored(D0)
        self._nd = _ScaledQuotient(D0, self.backend)
        self._dn = _ScaledQuotient(N0, self.backend)
        c_d0, f_d0 = self._D0
        self.A = self._ratio(N0, c_d0, f_d0)
        self.m, self.M = [sp.Integer(1)], [sp.Integer(1)]

    def _ratio(self, numer, content, factors: dict) -> sp.Expr:
        numer, factors, content = _cancel_known(numer, dict(factors), content)
        return _poly_ratio_expr(numer, factors, content, self.dom)

    @staticmethod
    def _denominator(base: tuple[Any, dict], q: _ScaledQuotient, k: int) -> tuple[Any, dict]:
        """``base * g^k`` as (content, factors)."""
        c, f = base
        factors = dict(f)
        for h, e in q.g_factors.items():
            factors[h] = factors.get(h, 0) + e * k
        return c * q.g_content**k, factors

    def extend(self, order: int) -> None:
        if order <= self.order:
            return
        num, den = self.series_parts(order, self.dom)
        num, den = num[: order + 1], den[: order + 1]
        if self._nd is None:
            self._setup(num, den)
        assert self._nd is not None and self._dn is not None
        for q, a, b, base, out in ((self._nd, num, den, self._N0, self.m), (self._dn, den, num, self._D0, self.M)):
            q.extend(a, b)
            # m_n = C_n / (N_0 g^n) (q_0 = N_0/D_0);  M_k = R_k / (D_0 h^k) (r_0 = D_0/N_0)
            for k in range(len(out), order + 1):
                content, factors = self._denominator(base, q, k)
                out.append(self._ratio(q.C[k], content, factors))
        self.order = order


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

    def series(self, s: sp.Expr | None = None) -> sp.Expr:
        """The truncated series ``sum_{n <= order} c_n s^{2n}``."""
        s = S.s if s is None else s
        return sp.Add(*[cn * s ** (2 * n) for n, cn in enumerate(self.c)])

    def latex(self) -> str:
        terms = join_signed([rf"{normal_latex(cn)}\, s^{{{2 * n}}}" for n, cn in enumerate(self.c) if n and cn != 0])
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
    num, den = bonded_series_parts(sp.QQ(1), order, sp.QQ)
    q = quotient_field(num, den, order)
    return IncompressibleCoefficients(order, tuple(sp.Rational(int(x.numerator), int(x.denominator)) for x in q))
