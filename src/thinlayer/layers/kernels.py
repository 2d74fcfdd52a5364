"""Layer kernels L(u): the symbol of the surface compliance of an elastic layer.

The normal surface displacement under a pressure p is (2.1)

    u_3 = (1 / (4 pi^2 vartheta)) iint p_hat(alpha) L(alpha H)/alpha e^{-i alpha.x} d alpha,

with ``vartheta = mu/(1 - nu)``.  Every layer model is a :class:`LayerKernel` sibling with
one interface: the symbolic ``L(u)``, its Maclaurin data ``L(s)/s = N(s^2)/D(s^2)`` (from
which (2.20) and (4.2) follow by power-series arithmetic), and a numerically stable
evaluation in numpy and mpmath.

* :class:`BondedLayer` -- layer bonded to a rigid base (2.3), the paper's case;
* :class:`FrictionlessLayer` -- layer resting on a rigid base without friction,
  ``L(u) = (cosh 2u - 1)/(sinh 2u + 2u)``;
* :class:`HalfSpace` -- ``L = 1`` (the limit ``H -> infinity``), which has no thin-layer
  expansion and says so.
"""
from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from fractions import Fraction
from functools import lru_cache
from typing import Any, ClassVar

import mpmath
import numpy as np

from .. import symbols as S
from .._checks import InputError, as_fraction, check_bounded, parse_nu
from .._checks import check_order as _check_order
from .._lazy import lazy_function, lazy_module, loaded_types
from .._series import bonded_series_parts, taylor_cosh, taylor_sinh
from ..display import RichDisplay, fmt, latex_escape
from ..errors import boundary_methods
from ..parse import sympy_value
from . import numeric as kernel_numeric
from .coefficients import incompressible_coefficients, kernel_coefficients
from .moments import kernel_moment

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it
normal_latex = lazy_function("thinlayer.normal", "normal_latex")  # the printers subclass sympy's

#: largest mpmath precision (decimal digits) of a float-nu layer
MAX_DPS = 1000


class IncompressibleLayerError(InputError):
    """nu = 1/2 makes the compressible bonded layer degenerate (A = 0)."""


def _as_nu(nu: Any) -> sp.Basic | mpmath.mpf:
    """Validate and normalise a Poisson ratio (:func:`thinlayer._checks.parse_nu`); nu = 1/2 has its own layer."""
    if nu is None:
        return S.nu
    try:
        return parse_nu(nu)
    except ValueError:
        try:  # the one value the range check refuses that has a layer of its own
            half = parse_nu(nu, upper_closed=True) == sp.Rational(1, 2)
        except ValueError:
            half = False
        if not half:
            raise
    raise IncompressibleLayerError(
        "nu = 1/2 (incompressible) makes A = 4(kappa-1)/(kappa+1)^2 vanish in (2.4): the "
        "compressible thin-layer expansion does not exist; use IncompressibleLayer() (the incompressible "
        "model, thinlayer.asymptotics.incompressible) or -1 < nu < 1/2."
    )


def _is_half(nu: Any) -> bool:
    """Whether ``nu`` is a valid spelling of exactly 1/2 (0.5, "1/2", Rational(1, 2)); False for anything else."""
    try:
        return as_fraction(parse_nu(nu, floats="float", upper_closed=True, symbols=False)) == Fraction(1, 2)
    except (TypeError, ValueError):
        return False


class _LazySymbol:
    """A class attribute that is a sympy Symbol, made on first access (importing the module needs no sympy)."""

    def __init__(self, name: str, **assumptions: Any):
        self.name, self.assumptions = name, assumptions

    def __get__(self, obj: Any, owner: Any = None) -> Any:
        return sp.Symbol(self.name, **self.assumptions)


@boundary_methods
class LayerKernel(RichDisplay, ABC):
    """Interface of a layer model: symbolic L(u), Maclaurin data of L(s)/s, numerics."""

    name: str = "layer"
    equation: str = ""

    # ---- symbolic -------------------------------------------------------------------
    @abstractmethod
    def L(self, u: sp.Expr | None = None) -> sp.Expr:
        """The kernel L(u) as a sympy expression."""

    @abstractmethod
    def series_parts(self, n: int, dom: Any) -> tuple[list[Any], list[Any]]:
        """Taylor coefficients ``N_k, D_k`` (k <= n) with ``L(s)/s = N(s^2)/D(s^2)``.

        ``dom`` supplies ``const(p, q)`` (the rational p/q in the domain) and ``kappa``
        (the layer's kappa in the domain) -- see :mod:`thinlayer.layers.coefficients`.
        """

    @abstractmethod
    def L_numeric(self, u: Any, backend: str = "numpy", over_u: bool = False) -> Any:
        """L(u) (or L(u)/u with ``over_u``) evaluated stably for every u >= 0."""

    @property
    def parameter(self) -> sp.Symbol | None:
        """The symbol the coefficients depend on (None for a parameter-free or numeric layer)."""
        return None

    @property
    def is_numeric(self) -> bool:
        """Whether the coefficients are numbers (no free parameter)."""
        return self.parameter is None

    # ---- what callers ask of a layer (instead of checking its type) ------------------------
    #: whether the layer has a finite thickness H (False for the half-space)
    has_thickness: ClassVar[bool] = True
    #: whether ``L(s)/s = A(1 + m_1 s^2 + ...)`` with ``A > 0`` exists (2.20): the compressible expansion
    has_compressible_expansion: ClassVar[bool] = True
    #: whether the Maclaurin data are plain symbols (``A``, ``m_n``) rather than derived from ``L(u)``
    symbolic_coefficients: ClassVar[bool] = False
    #: the base under the layer: ``"bonded"``, ``"frictionless"`` or None (no base).  Data: callers outside
    #: ``layers/`` do not compare it; they ask the members below
    base: ClassVar[str | None] = None
    #: words for summaries: the layer is "<base_phrase> a rigid base" ("bonded to", "lying without friction on");
    #: None without a base
    base_phrase: ClassVar[str | None] = None
    #: what a one-line summary adds about the base: "" for the paper's bonded base, "frictionless base" otherwise
    base_note: ClassVar[str] = ""
    #: whether the two-term model (I.10) (nu -> 1/2 with m_1 > 0) is derived for this layer: a bonded base
    has_two_term_model: ClassVar[bool] = False
    #: whether the incompressible model (I.2)-(I.9) is derived for this layer at nu = 1/2: a bonded base
    has_incompressible_model: ClassVar[bool] = False
    #: whether the boundary layer (3.15)-(3.25) and its edge shift h* are derived for this layer
    has_edge_shift: ClassVar[bool] = False
    #: whether the kernel L(u) depends on Poisson's ratio (False: frictionless base, half-space; nu then enters
    #: only through vartheta = mu/(1 - nu) (2.1))
    kernel_depends_on_nu: ClassVar[bool] = True
    #: whether the base carries no shear (the frictionless base): m_1 = 0, so the first correction of the force
    #: law (1.8) is of relative order (H/a)^3; the kernel is nu-free and nu comes from the caller (vartheta, (2.1));
    #: reports add the exact/Alexandrov edge-shift table and the frictionless errata kinds
    shear_free_base: ClassVar[bool] = False

    @property
    def base_label(self) -> str | None:
        """The base as a key for tables, JSON and the CLI: ``"bonded"``, ``"frictionless"``, or None (no base)."""
        return self.base

    @property
    def on_rigid_base(self) -> bool:
        """Whether the layer lies on a rigid base (bonded or frictionless): what ``solve()`` answers for."""
        return self.base is not None

    @property
    def kernel_key(self) -> "LayerKernel":
        """The layer reduced to what its kernel ``L(u)`` depends on: the key of caches of kernel-only quantities
        (a frictionless layer without its nu; every other layer itself).
        """
        return self

    def with_nu(self, nu: Any) -> "LayerKernel":
        """The layer of the same base at the numeric Poisson ratio ``nu`` (a bonded base at nu = 1/2 is
        :class:`IncompressibleLayer`).
        """
        raise InputError(f"{self!r} has no base to put at nu = {nu!r}: with_nu needs BondedLayer, "
                         "IncompressibleLayer or FrictionlessLayer")

    def incompressible_at(self, nu: Any) -> bool:
        """Whether this layer at Poisson's ratio ``nu`` is the incompressible layer (I.1): a bonded base at
        nu = 1/2 (the compressible expansion (2.20) degenerates there, A = 0).
        """
        return False

    @property
    def numeric_nu(self) -> float | None:
        """The Poisson ratio the layer fixes, as a float; None when it fixes none (symbolic or nu-free)."""
        return None

    def poisson_ratio(self, nu: Any = None) -> Any:
        """The Poisson ratio that defines ``vartheta = mu/(1 - nu)`` (2.1): the layer's own, or ``nu``.

        A layer that fixes nu (:attr:`numeric_nu`) returns it, and a given ``nu`` must agree with it; a
        layer that fixes none (a frictionless base, the half-space) needs ``nu``, returned as given for the
        caller to parse.
        """
        fixed = self.numeric_nu
        if fixed is None:
            if nu is None:
                raise InputError(f"{self!r} does not fix Poisson's ratio: pass nu= (-1 < nu < 1/2) "
                                 "to define vartheta = mu/(1 - nu)")
            return nu
        if nu is not None and abs(float(nu) - fixed) > 1e-12:
            raise InputError(f"nu={nu!r} disagrees with the layer's Poisson ratio {fixed}")
        return fixed

    @property
    def vartheta(self) -> sp.Expr:
        """``vartheta = mu/(1 - nu)`` (2.1), with the layer's nu when it fixes one."""
        return S.VARTHETA

    @property
    def edge_shift_key(self) -> Any:
        """What the edge shift h* (3.18), (3.25) of this layer depends on: its exact nu, or the base name."""
        raise InputError(f"the edge shift needs a numeric layer with a finite thickness, got {self!r}")

    @property
    def constants_key(self) -> tuple | None:
        """A key of the layer's per-nu numbers in the disk cache (:mod:`thinlayer._cache`): plain strings and ints,
        made without sympy (a float nu by its exact binary value); None when the layer has no such numbers.
        """
        return None

    def taylor_coefficients(self, order: int) -> tuple:
        """``c_n`` of ``L(s)/s = sum_n c_n s^{2n}`` (n <= order): ``c_n = A m_n`` (2.20), or (I.1) at nu = 1/2.

        The weights of the operator series (2.22)-(2.23) are ``(-1)^n pi^2 c_n``.
        """
        co = self.coefficients(order)
        return tuple(co.A_expr * co.m_expr(n) for n in range(order + 1))

    def latex(self) -> str:
        """The kernel as a tagged LaTeX line (2.3), or the coefficient form (2.20) when L(u) is unknown."""
        name = r"\text{" + latex_escape(str(self)) + r"}:\quad "
        try:
            L = self.L()
        except ValueError:  # known only through its coefficients
            return name + r"\frac{\mathcal{L}(s)}{s} = \mathcal{A}\left(1 + m_1 s^2 + m_2 s^4 + \dots\right) \tag{2.20}"
        if L.has(sp.Float):  # a float nu: kappa to 15 digits, not the layer's working precision
            L = L.evalf(15)
        tag = rf" \tag{{{self.equation}}}" if self.equation else ""
        return name + rf"\mathcal{{L}}(u) = {normal_latex(L)}" + tag

    # ---- stages of the paper (delegated) ----------------------------------------------
    def coefficients(self, order: int):
        """A, m_1..m_order (2.20) and M_1..M_order (4.2): :func:`thinlayer.kernel_coefficients`."""
        return kernel_coefficients(self, order)

    @property
    def A(self):
        """``A = lim_{s->0} L(s)/s`` (2.4)."""
        return self.coefficients(0).A

    def m(self, n: int):
        """m_n of ``L(s)/s = A(1 + m_1 s^2 + m_2 s^4 + ...)`` (2.20); ``m(0) = 1``."""
        return self.coefficients(_check_order(n, "n")).m[n]

    def M(self, k: int):
        """M_k of ``s/L(s) = A^{-1}(1 + M_1 s^2 + ...)``, by the recurrence (4.2); ``M(0) = 1``."""
        return self.coefficients(_check_order(k, "k")).M[k]

    def moment(self, a1: int, a2: int):
        """Kernel moment mu_{a1 a2} (2.15), derived form of (2.19)/(2.21)."""
        return kernel_moment(self, a1, a2)

    def small_u(self, order: int, u: sp.Expr | None = None) -> sp.Expr:
        """Maclaurin polynomial of L(u) through u^(2*order+1): ``A u (1 + m_1 u^2 + ...)`` (2.4), (2.20)."""
        u = S.u if u is None else sympy_value(u, "u")
        c = self.coefficients(order)
        return sp.Add(*[c.A_expr * c.m_expr(k) * u ** (2 * k + 1) for k in range(order + 1)])


@boundary_methods
@dataclass(frozen=True, eq=True)
class BondedLayer(LayerKernel):
    """Elastic layer bonded to a rigid base (the paper's layer), kernel (2.3)::

        L(u) = (2 kappa sinh 2u - 4u) / (2 kappa cosh 2u + 1 + kappa^2 + 4u^2),  kappa = 3 - 4 nu.

    Parameters
    ----------
    nu : Any
        Poisson ratio.  ``None`` (default) keeps the symbol nu; an exact number (int,
        Fraction, sympy Rational or a string such as ``"3/10"``) gives exact rational
        coefficients; a float gives mpmath numbers at ``dps`` digits.  Must lie in (-1, 1/2).
    parameter : str
        ``"nu"`` or ``"kappa"``: the variable of symbolic coefficients.
    dps : int
        mpmath precision (decimal digits) for a float nu, 5 <= dps <= 1000.

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> BondedLayer().A
    (1 - 2*nu)/(2*(1 - nu)**2)
    >>> BondedLayer("3/10").m(1)
    1/14
    """

    nu: Any = None
    parameter_name: str = "nu"
    dps: int = 30
    name: str = field(default="bonded", init=False)
    equation: str = field(default="2.3", init=False)
    #: "symbolic", "exact" or "float": part of equality and hash, so that caches keyed by the layer
    #: never hand the float layer's coefficients to the exact one (0.5 == Rational(1, 2) in Python)
    kind: str = field(default="symbolic", init=False, repr=False)

    def __new__(cls, nu: Any = None, parameter: str = "nu", dps: int = 30):
        """``BondedLayer(1/2)`` is the incompressible layer: it returns ``IncompressibleLayer()``.

        At nu = 1/2 the kernel (2.3) is the same formula (kappa = 1) but A = 0 (2.4), so the compressible
        expansion (2.20) does not exist; the layer with the incompressible data (I.1) stands in for it.
        """
        if cls is BondedLayer and nu is not None and _is_half(nu):
            return IncompressibleLayer()
        return super().__new__(cls)

    def __init__(self, nu: Any = None, parameter: str = "nu", dps: int = 30):
        if parameter not in ("nu", "kappa"):
            raise InputError(f"parameter must be 'nu' or 'kappa', got {parameter!r}")
        if isinstance(dps, bool) or not isinstance(dps, int) or dps < 5:
            raise InputError(f"dps must be an integer >= 5, got {dps!r}")
        check_bounded(dps, "dps", MAX_DPS, "the float coefficients are computed at dps + 10 digits; at dps = 1000 "
                                           "order 200 costs 0.5 s, and the cost grows like dps^1.6")
        val = _as_nu(nu)
        if parameter == "kappa" and not isinstance(val, sp.Symbol):
            raise InputError("parameter='kappa' needs a symbolic layer (nu=None)")
        object.__setattr__(self, "nu", val)
        object.__setattr__(self, "parameter_name", parameter)
        object.__setattr__(self, "dps", dps)
        object.__setattr__(self, "name", "bonded")
        object.__setattr__(self, "equation", "2.3")
        symbol = loaded_types("sympy", "Symbol")  # a float nu never needs sympy
        kind = "symbolic" if isinstance(val, symbol) else "float" if isinstance(val, mpmath.mpf) else "exact"
        object.__setattr__(self, "kind", kind)

    @property
    def parameter(self) -> sp.Symbol | None:
        if isinstance(self.nu, loaded_types("sympy", "Symbol")):
            return S.kappa if self.parameter_name == "kappa" else self.nu
        return None

    @property
    def kappa(self):
        """Kappa = 3 - 4 nu (2.3): a sympy expression, a Rational, or an mpmath number."""
        if self.parameter_name == "kappa":
            return S.kappa
        if isinstance(self.nu, mpmath.mpf):
            with mpmath.workdps(self.dps):
                return 3 - 4 * self.nu
        return 3 - 4 * self.nu

    @property
    def nu_expr(self) -> sp.Expr:
        """Nu as a sympy object (in terms of kappa when ``parameter='kappa'``)."""
        if self.parameter_name == "kappa":
            return (3 - S.kappa) / 4
        return sp.Float(self.nu, self.dps) if isinstance(self.nu, mpmath.mpf) else self.nu

    base: ClassVar[str | None] = "bonded"
    base_phrase: ClassVar[str | None] = "bonded to"
    has_two_term_model: ClassVar[bool] = True
    has_incompressible_model: ClassVar[bool] = True
    has_edge_shift: ClassVar[bool] = True

    def with_nu(self, nu: Any) -> LayerKernel:
        """``BondedLayer(nu)`` at this layer's precision (``IncompressibleLayer()`` at nu = 1/2)."""
        return BondedLayer(nu, dps=self.dps)

    def incompressible_at(self, nu: Any) -> bool:
        """Whether ``nu`` is exactly 1/2."""
        return _is_half(nu)

    @property
    def vartheta(self) -> sp.Expr:
        """Vartheta = mu/(1 - nu) (2.1)."""
        return S.mu / (1 - self.nu_expr)

    @property
    def numeric_nu(self) -> float | None:
        """Nu as a float, None for a symbolic layer."""
        return None if self.parameter is not None else float(self.nu)

    @property
    def edge_shift_key(self) -> sp.Rational:
        """The exact rational nu (a float nu is taken as its exact binary value)."""
        if self.parameter is not None:
            raise InputError("the Wiener-Hopf solution needs a numeric layer; got a symbolic BondedLayer "
                             "(give BondedLayer(0.3), BondedLayer('3/10') or a number)")
        return parse_nu(self.nu, floats="exact")

    @property
    def constants_key(self) -> tuple | None:
        """``("bonded", kind, nu, dps)``: a float nu by its exact binary value (mantissa, exponent), an exact one as
        ``p/q``; None for a symbolic layer.
        """
        if self.kind == "float":
            sign, man, exp, _ = self.nu._mpf_  # the exact binary value, signed
            return ("bonded", "float", -int(man) if sign else int(man), int(exp), self.dps)
        if self.kind == "exact":
            return ("bonded", "exact", f"{int(self.nu.p)}/{int(self.nu.q)}", self.dps)
        return None

    def _kappa_expr(self) -> sp.Expr:
        k = self.kappa
        return sp.Float(k, self.dps) if isinstance(k, mpmath.mpf) else k

    def L(self, u: sp.Expr | None = None) -> sp.Expr:
        u = S.u if u is None else sympy_value(u, "u")
        k = self._kappa_expr()
        return (2 * k * sp.sinh(2 * u) - 4 * u) / (2 * k * sp.cosh(2 * u) + 1 + k**2 + 4 * u**2)

    def large_u(self, u: sp.Expr | None = None) -> sp.Expr:
        """Leading behaviour of ``L(u) - 1`` as u -> oo (2.4): ``-(4u^2 + 4u + 1 + kappa^2) e^{-2u}/kappa``.

        Derivation: ``L - 1 = -(2 kappa e^{-2u} + 1 + kappa^2 + 4u + 4u^2)/(kappa e^{2u} + ...)``,
        so the remainder is ``O(u^2 e^{-2u})`` as printed in (2.4).
        """
        u = S.u if u is None else sympy_value(u, "u")
        k = self._kappa_expr()
        return -(4 * u**2 + 4 * u + 1 + k**2) * sp.exp(-2 * u) / k

    def series_parts(self, n: int, dom: Any) -> tuple[list[Any], list[Any]]:
        return bonded_series_parts(dom.kappa, n, dom.const)

    def L_numeric(self, u: Any, backend: str = "numpy", over_u: bool = False) -> Any:
        """Stable L(u) (or L(u)/u): see :mod:`thinlayer.layers.numeric`.  Needs a numeric nu."""
        if self.parameter is not None:
            raise InputError("numeric evaluation needs a numeric nu; build BondedLayer(nu=0.3) or similar")
        if backend == "numpy":
            return kernel_numeric.bonded_numpy(u, float(self.kappa), over_u)
        if backend == "mpmath":
            return kernel_numeric.bonded_mpmath(u, _kappa_mpmath(self.nu, self.dps, mpmath.mp.prec), over_u)
        raise InputError(f"backend must be 'numpy' or 'mpmath', got {backend!r}")

    def __repr__(self) -> str:
        return f"BondedLayer(nu={self.nu})"

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        if self.parameter is not None:
            return [f"BondedLayer({self.parameter_name})"]
        return [f"BondedLayer(nu={fmt(self.nu, 15)})"]


@lru_cache(maxsize=256)
def _kappa_mpmath(nu: Any, dps: int, prec: int) -> mpmath.mpf:
    """``kappa = 3 - 4 nu`` (2.3) as an mpmath number at ``prec`` bits, for a numeric nu: an exact rational's
    correctly rounded, a float nu's (an mpmath number at the layer's ``dps``) rounded again.  Kept per (nu, dps,
    precision): the mpmath kernel needs it at every node of a quadrature.
    """
    if isinstance(nu, loaded_types("sympy", "Rational")):
        k = 3 - 4 * nu
        with mpmath.workprec(prec):
            return mpmath.mpf(int(k.p)) / int(k.q)
    with mpmath.workdps(dps):  # as the property kappa computes it
        k = 3 - 4 * nu
    with mpmath.workprec(prec):
        return mpmath.mpf(k)


@boundary_methods
@dataclass(frozen=True)
class FrictionlessLayer(LayerKernel):
    """Layer lying on a rigid base without friction: ``L(u) = (cosh 2u - 1)/(sinh 2u + 2u)``.

    Independent of nu with the normalisation (2.1); ``A = 1/2``.
    """

    #: Poisson ratio (optional): the kernel does not depend on it, ``vartheta = mu/(1 - nu)`` (2.1) does
    nu: Any = None
    name: str = field(default="frictionless", init=False)
    equation: str = field(default="", init=False)
    base: ClassVar[str | None] = "frictionless"
    base_phrase: ClassVar[str | None] = "lying without friction on"
    base_note: ClassVar[str] = "frictionless base"
    has_edge_shift: ClassVar[bool] = True
    kernel_depends_on_nu: ClassVar[bool] = False
    shear_free_base: ClassVar[bool] = True

    @property
    def kernel_key(self) -> LayerKernel:
        """``FrictionlessLayer()``: the kernel does not depend on nu."""
        return FrictionlessLayer()

    def with_nu(self, nu: Any) -> LayerKernel:
        """``FrictionlessLayer(nu)``."""
        return FrictionlessLayer(nu)

    def __post_init__(self):
        if self.nu is not None:
            object.__setattr__(self, "nu", parse_nu(self.nu, floats="float", upper_closed=True, symbols=False,
                                                    example="FrictionlessLayer(0.3) or FrictionlessLayer('1/2')"))

    @property
    def numeric_nu(self) -> float | None:
        """The Poisson ratio given to the layer, as a float (None when none was given)."""
        return None if self.nu is None else float(self.nu)

    @property
    def edge_shift_key(self) -> str:
        """``"frictionless"``: the kernel, hence h*, does not depend on nu."""
        return "frictionless"

    @property
    def constants_key(self) -> tuple:
        """``("frictionless",)``: the kernel's numbers do not depend on nu."""
        return ("frictionless",)

    def L(self, u: sp.Expr | None = None) -> sp.Expr:
        u = S.u if u is None else sympy_value(u, "u")
        return (sp.cosh(2 * u) - 1) / (sp.sinh(2 * u) + 2 * u)

    def series_parts(self, n: int, dom: Any) -> tuple[list[Any], list[Any]]:
        ch = taylor_cosh(2, n + 1, dom.const)  # (cosh 2s - 1)/s^2 = sum_{k>=0} ch[k+1] s^{2k}
        num = ch[1 : n + 2]
        den = taylor_sinh(2, n, dom.const)  # (sinh 2s + 2s)/s
        den[0] = den[0] + dom.const(2, 1)
        return num, den

    def L_numeric(self, u: Any, backend: str = "numpy", over_u: bool = False) -> Any:
        if backend == "numpy":
            return kernel_numeric.frictionless_numpy(u, over_u)
        if backend == "mpmath":
            return kernel_numeric.frictionless_mpmath(u, over_u)
        raise InputError(f"backend must be 'numpy' or 'mpmath', got {backend!r}")

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return [f"{type(self).__name__}({'' if self.nu is None else 'nu=' + fmt(self.nu, 15)})"]


@boundary_methods
@dataclass(frozen=True)
class HalfSpace(LayerKernel):
    """The elastic half-space, ``L = 1``: the limit of every layer as H -> oo.

    It has no thin-layer (small-s) expansion: ``L(s)/s = 1/s`` is singular at s = 0.
    """

    name: str = field(default="half-space", init=False)
    equation: str = field(default="2.4", init=False)
    has_thickness: ClassVar[bool] = False
    has_compressible_expansion: ClassVar[bool] = False
    kernel_depends_on_nu: ClassVar[bool] = False

    def with_nu(self, nu: Any) -> LayerKernel:
        """Itself: the half-space kernel carries no nu (nu enters only through vartheta = mu/(1 - nu) (2.1))."""
        return self

    def L(self, u: sp.Expr | None = None) -> sp.Expr:
        u = S.u if u is None else sympy_value(u, "u")
        return sp.Integer(1)

    def series_parts(self, n: int, dom: Any) -> tuple[list[Any], list[Any]]:
        raise InputError(
            "the half-space kernel L = 1 has no expansion L(s)/s = A(1 + m_1 s^2 + ...) (2.20): "
            "the thin-layer analysis needs a layer of finite thickness (BondedLayer, FrictionlessLayer)"
        )

    def L_numeric(self, u: Any, backend: str = "numpy", over_u: bool = False) -> Any:
        """``L = 1``; ``L/u = 1/u`` (inf at u = 0, 0 at u = inf).  nan or u < 0 is a ValueError."""
        if backend == "numpy":
            u = kernel_numeric.check_u(u)
            if not over_u:
                return np.ones_like(u)
            with np.errstate(divide="ignore", over="ignore"):  # 1/u beyond the double range (u < 5.6e-309) is inf
                return 1.0 / u
        if backend == "mpmath":
            u = kernel_numeric.check_u_mpmath(u)
            if not over_u:
                return mpmath.mpf(1)
            return mpmath.inf if u == 0 else 1 / u
        raise InputError(f"backend must be 'numpy' or 'mpmath', got {backend!r}")

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return [f"{type(self).__name__}()"]


@boundary_methods
@dataclass(frozen=True)
class GenericLayer(LayerKernel):
    """A layer known only through its coefficients: ``A`` and ``m_n`` stay plain symbols.

    Results built on it read like the paper's formulas, e.g. (2.30) in terms of ``A`` and
    ``m_1``; the ``M_k`` follow from (4.2) as polynomials in the ``m_n``.
    """

    name: str = field(default="generic", init=False)
    equation: str = field(default="2.20", init=False)
    symbolic_coefficients: ClassVar[bool] = True

    @property
    def vartheta(self) -> sp.Expr:
        """The plain symbol vartheta (2.1): a generic layer fixes no nu."""
        return S.vartheta

    #: the symbol of ``A`` (2.4): a generic layer's coefficients are symbols (made on first use)
    A_symbol = _LazySymbol(r"\mathcal{A}", positive=True)

    @staticmethod
    def m_symbol(n: int) -> sp.Symbol:
        return sp.Symbol(f"m_{n}")

    def L(self, u: sp.Expr | None = None) -> sp.Expr:
        u = S.u if u is None else sympy_value(u, "u")
        raise InputError("a GenericLayer has no closed-form L(u); use BondedLayer or FrictionlessLayer")

    def series_parts(self, n: int, dom: Any) -> tuple[list[Any], list[Any]]:
        raise InputError("a GenericLayer has no Taylor data; its coefficients are symbols")

    def L_numeric(self, u: Any, backend: str = "numpy", over_u: bool = False) -> Any:
        raise InputError("a GenericLayer cannot be evaluated numerically")

    @property
    def parameter(self) -> sp.Symbol | None:
        return self.A_symbol

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return ["GenericLayer(A, m_1, m_2, ...)"]


def _kernel_23(kappa: sp.Expr, u: sp.Expr) -> sp.Expr:
    """The bonded-layer kernel (2.3) for a given kappa."""
    return (2 * kappa * sp.sinh(2 * u) - 4 * u) / (2 * kappa * sp.cosh(2 * u) + 1 + kappa**2 + 4 * u**2)


@boundary_methods
@dataclass(frozen=True)
class IncompressibleLayer(LayerKernel):
    """The incompressible layer bonded to a rigid base: kernel (2.3) at ``nu = 1/2``, ``kappa = 1``::

        L(u) = (2 sinh 2u - 4u)/(2 cosh 2u + 2 + 4u^2),   vartheta = mu/(1 - nu) = 2 mu.

    ``A = lim L(s)/s = 0`` (2.4), so the compressible coefficients ``m_n`` of (2.20) do not exist
    (:meth:`coefficients`, :meth:`m`, :meth:`M` raise :class:`~thinlayer.IncompressibleLayerError`);
    the small-s data are ``L(s)/s = c_1 s^2 + c_2 s^4 + ...`` (:func:`incompressible_coefficients`).
    Every stage that needs only ``L(u)`` works, e.g. :func:`thinlayer.numerics.solve_axisymmetric`.

    Examples
    --------
    >>> from thinlayer.asymptotics.incompressible import IncompressibleLayer
    >>> layer = IncompressibleLayer()
    >>> layer.A, layer.nu, layer.vartheta
    (0, 1/2, 2*mu)
    >>> layer.small_u(2)
    -6*u**5/5 + 2*u**3/3
    """

    name: str = field(default="incompressible", init=False)
    equation: str = field(default="2.3", init=False)
    has_compressible_expansion: ClassVar[bool] = False
    base: ClassVar[str | None] = "bonded"
    base_phrase: ClassVar[str | None] = "bonded to"
    has_two_term_model: ClassVar[bool] = True
    has_incompressible_model: ClassVar[bool] = True

    def with_nu(self, nu: Any) -> LayerKernel:
        """Itself at nu = 1/2, ``BondedLayer(nu)`` otherwise."""
        return self if _is_half(nu) else BondedLayer(nu)

    def incompressible_at(self, nu: Any) -> bool:
        """Whether ``nu`` is exactly 1/2."""
        return _is_half(nu)

    @property
    def numeric_nu(self) -> float:
        """0.5."""
        return 0.5

    def taylor_coefficients(self, order: int) -> tuple:
        """``c_n`` of (I.1): ``c_0 = A = 0``, ``c_1 = 2/3``, ..."""
        return incompressible_coefficients(order).c

    # ---- constants -------------------------------------------------------------------------
    @property
    def nu(self) -> sp.Rational:
        """Poisson's ratio, exactly 1/2."""
        return sp.Rational(1, 2)

    @property
    def kappa(self) -> sp.Integer:
        """Kappa = 3 - 4 nu = 1 (2.3)."""
        return 3 - 4 * self.nu

    @property
    def nu_expr(self) -> sp.Expr:
        return self.nu

    @property
    def vartheta(self) -> sp.Expr:
        """Vartheta = mu/(1 - nu) = 2 mu (2.1)."""
        return S.mu / (1 - self.nu)

    @property
    def A(self) -> sp.Expr:
        """``A = lim_{s->0} L(s)/s`` (2.4): zero, from the leading Taylor coefficients."""
        return incompressible_coefficients(0).c[0]

    # ---- symbolic --------------------------------------------------------------------------
    def L(self, u: sp.Expr | None = None) -> sp.Expr:
        u = S.u if u is None else sympy_value(u, "u")
        return _kernel_23(self.kappa, u)

    def large_u(self, u: sp.Expr | None = None) -> sp.Expr:
        """Leading behaviour of ``L(u) - 1`` as u -> oo: ``-(4u^2 + 4u + 2) e^{-2u}`` (kappa = 1 in (2.4))."""
        u = S.u if u is None else sympy_value(u, "u")
        k = self.kappa
        return -(4 * u**2 + 4 * u + 1 + k**2) * sp.exp(-2 * u) / k

    def series_parts(self, n: int, dom: Any) -> tuple[list[Any], list[Any]]:
        """Taylor coefficients of ``L(s)/s = N(s^2)/D(s^2)`` (k <= n); ``N_0 = 0``."""
        return bonded_series_parts(dom.kappa, n, dom.const)

    def small_u(self, order: int, u: sp.Expr | None = None) -> sp.Expr:
        """Maclaurin polynomial of L(u) through ``u^(2 order + 1)``: ``c_1 u^3 + c_2 u^5 + ...`` (I.1)."""
        u = S.u if u is None else sympy_value(u, "u")
        c = incompressible_coefficients(_check_order(order, "order")).c
        return sp.Add(*[c[k] * u ** (2 * k + 1) for k in range(order + 1)])

    def moment(self, a1: int, a2: int) -> sp.Expr:
        """Kernel moment (2.15): ``mu_{2k,2n-2k} = (-1)^n pi^2 c_n C(n,k) (2k)! (2n-2k)!`` (2.21) with ``c_n`` (I.1)."""
        a1 = _check_order(a1, "a1")
        a2 = _check_order(a2, "a2")
        if a1 % 2 or a2 % 2:
            return sp.Integer(0)
        n, k = (a1 + a2) // 2, a1 // 2
        c = incompressible_coefficients(n).c[n]
        return (-1) ** n * sp.pi**2 * c * sp.binomial(n, k) * sp.factorial(2 * k) * sp.factorial(2 * n - 2 * k)

    def coefficients(self, order: int):
        raise IncompressibleLayerError(
            "the incompressible layer has A = 0 (2.4): the coefficients m_n of L(s)/s = A(1 + m_1 s^2 + ...) "
            "(2.20) do not exist; use thinlayer.asymptotics.incompressible.incompressible_coefficients(order) for "
            "L(s)/s = c_1 s^2 + c_2 s^4 + ... (I.1), or thin_layer_operator(layer, order)"
        )

    def m(self, n: int):
        return self.coefficients(n)

    def M(self, k: int):
        return self.coefficients(k)

    # ---- numeric ---------------------------------------------------------------------------
    def L_numeric(self, u: Any, backend: str = "numpy", over_u: bool = False) -> Any:
        """Stable L(u) (or L(u)/u), the bonded-layer numerics of :mod:`thinlayer.layers.numeric` at kappa = 1."""
        if backend == "numpy":
            return kernel_numeric.bonded_numpy(u, 1.0, over_u)
        if backend == "mpmath":
            return kernel_numeric.bonded_mpmath(u, mpmath.mpf(1), over_u)
        raise InputError(f"backend must be 'numpy' or 'mpmath', got {backend!r}")

    def __repr__(self) -> str:
        return "IncompressibleLayer()"

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return ["IncompressibleLayer()"]
