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

import numbers
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import mpmath
import sympy as sp

from . import kernel_numeric
from . import symbols as S
from ._series import taylor_cosh, taylor_sinh
from .display import RichDisplay


class IncompressibleLayerError(ValueError):
    """nu = 1/2 makes the compressible bonded layer degenerate (A = 0)."""


def _as_nu(nu: Any) -> sp.Basic | mpmath.mpf:
    """Validate and normalise a Poisson ratio: a Symbol, an exact Rational or an mpmath float."""
    if nu is None:
        return S.nu
    if isinstance(nu, sp.Symbol):
        return nu
    if isinstance(nu, sp.Basic) and not nu.is_number:
        raise TypeError(f"nu must be None, a Symbol or a number, got the expression {nu!r}")
    if isinstance(nu, bool):
        raise TypeError("nu must be a number, got a bool")
    if isinstance(nu, (sp.Rational, numbers.Integral, Fraction)):
        val: Any = sp.Rational(nu)
    elif isinstance(nu, str):
        try:
            val = sp.Rational(nu)
        except (TypeError, ValueError, sp.SympifyError) as exc:
            raise ValueError(f"nu={nu!r} is not a number; give e.g. '3/10', 0.3 or None") from exc
    elif isinstance(nu, (float, sp.Float, mpmath.mpf, numbers.Real)):
        val = mpmath.mpf(nu if not isinstance(nu, sp.Float) else str(nu))
    else:
        raise TypeError(f"nu must be None, a Symbol, a rational or a float, got {type(nu).__name__}")
    if val == sp.Rational(1, 2) or val == mpmath.mpf(0.5):
        raise IncompressibleLayerError(
            "nu = 1/2 (incompressible) makes A = 4(kappa-1)/(kappa+1)^2 vanish in (2.4): the "
            "compressible thin-layer expansion does not exist; the incompressible-layer model is "
            "not yet available in thinlayer. Use -1 < nu < 1/2."
        )
    if not (-1 < val < sp.Rational(1, 2) if isinstance(val, sp.Rational) else -1 < val < 0.5):
        raise ValueError(f"Poisson ratio nu={nu!r} is outside the admissible range -1 < nu < 1/2")
    return val


class LayerKernel(RichDisplay, ABC):
    """Interface of a layer model: symbolic L(u), Maclaurin data of L(s)/s, numerics."""

    name: str = "layer"
    equation: str = ""

    # ---- symbolic -------------------------------------------------------------------
    @abstractmethod
    def L(self, u: sp.Expr = S.u) -> sp.Expr:
        """The kernel L(u) as a sympy expression."""

    @abstractmethod
    def series_parts(self, n: int, dom: Any) -> tuple[list[Any], list[Any]]:
        """Taylor coefficients ``N_k, D_k`` (k <= n) with ``L(s)/s = N(s^2)/D(s^2)``.

        ``dom`` supplies ``const(p, q)`` (the rational p/q in the domain) and ``kappa``
        (the layer's kappa in the domain) -- see :mod:`thinlayer.coefficients`.
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
        return self.parameter is None

    # ---- stages of the paper (delegated) ----------------------------------------------
    def coefficients(self, order: int):
        """A, m_1..m_order (2.20) and M_1..M_order (4.2): :func:`thinlayer.kernel_coefficients`."""
        from .coefficients import kernel_coefficients

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
        from .moments import kernel_moment

        return kernel_moment(self, a1, a2)

    def small_u(self, order: int, u: sp.Expr = S.u) -> sp.Expr:
        """Maclaurin polynomial of L(u) through u^(2*order+1): ``A u (1 + m_1 u^2 + ...)`` (2.4), (2.20)."""
        c = self.coefficients(order)
        return sp.Add(*[c.A_expr * c.m_expr(k) * u ** (2 * k + 1) for k in range(order + 1)])


def _check_order(n: Any, name: str) -> int:
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        raise TypeError(f"{name} must be a non-negative integer, got {n!r}")
    if n < 0:
        raise ValueError(f"{name} must be a non-negative integer, got {n}")
    return int(n)


@dataclass(frozen=True, eq=True)
class BondedLayer(LayerKernel):
    """Elastic layer bonded to a rigid base (the paper's layer), kernel (2.3)::

        L(u) = (2 kappa sinh 2u - 4u) / (2 kappa cosh 2u + 1 + kappa^2 + 4u^2),  kappa = 3 - 4 nu.

    Parameters
    ----------
    nu:
        Poisson ratio.  ``None`` (default) keeps the symbol nu; an exact number (int,
        Fraction, sympy Rational or a string such as ``"3/10"``) gives exact rational
        coefficients; a float gives mpmath numbers at ``dps`` digits.  Must lie in (-1, 1/2).
    parameter:
        ``"nu"`` or ``"kappa"``: the variable of symbolic coefficients.
    dps:
        mpmath precision (decimal digits) for a float nu.

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> BondedLayer().A
    (1/2 - nu)/(1 - nu)**2
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

    def __init__(self, nu: Any = None, parameter: str = "nu", dps: int = 30):
        if parameter not in ("nu", "kappa"):
            raise ValueError(f"parameter must be 'nu' or 'kappa', got {parameter!r}")
        if isinstance(dps, bool) or not isinstance(dps, int) or dps < 5:
            raise ValueError(f"dps must be an integer >= 5, got {dps!r}")
        val = _as_nu(nu)
        if parameter == "kappa" and not isinstance(val, sp.Symbol):
            raise ValueError("parameter='kappa' needs a symbolic layer (nu=None)")
        object.__setattr__(self, "nu", val)
        object.__setattr__(self, "parameter_name", parameter)
        object.__setattr__(self, "dps", dps)
        object.__setattr__(self, "name", "bonded")
        object.__setattr__(self, "equation", "2.3")
        kind = "symbolic" if isinstance(val, sp.Symbol) else "float" if isinstance(val, mpmath.mpf) else "exact"
        object.__setattr__(self, "kind", kind)

    @property
    def parameter(self) -> sp.Symbol | None:
        if isinstance(self.nu, sp.Symbol):
            return S.kappa if self.parameter_name == "kappa" else self.nu
        return None

    @property
    def kappa(self):
        """kappa = 3 - 4 nu (2.3): a sympy expression, a Rational, or an mpmath number."""
        if self.parameter_name == "kappa":
            return S.kappa
        if isinstance(self.nu, mpmath.mpf):
            with mpmath.workdps(self.dps):
                return 3 - 4 * self.nu
        return 3 - 4 * self.nu

    @property
    def nu_expr(self) -> sp.Expr:
        """nu as a sympy object (in terms of kappa when ``parameter='kappa'``)."""
        if self.parameter_name == "kappa":
            return (3 - S.kappa) / 4
        return sp.Float(self.nu, self.dps) if isinstance(self.nu, mpmath.mpf) else self.nu

    @property
    def vartheta(self) -> sp.Expr:
        """vartheta = mu/(1 - nu) (2.1)."""
        return S.mu / (1 - self.nu_expr)

    def _kappa_expr(self) -> sp.Expr:
        k = self.kappa
        return sp.Float(k, self.dps) if isinstance(k, mpmath.mpf) else k

    def L(self, u: sp.Expr = S.u) -> sp.Expr:
        k = self._kappa_expr()
        return (2 * k * sp.sinh(2 * u) - 4 * u) / (2 * k * sp.cosh(2 * u) + 1 + k**2 + 4 * u**2)

    def large_u(self, u: sp.Expr = S.u) -> sp.Expr:
        """Leading behaviour of ``L(u) - 1`` as u -> oo (2.4): ``-(4u^2 + 4u + 1 + kappa^2) e^{-2u}/kappa``.

        Derivation: ``L - 1 = -(2 kappa e^{-2u} + 1 + kappa^2 + 4u + 4u^2)/(kappa e^{2u} + ...)``,
        so the remainder is ``O(u^2 e^{-2u})`` as printed in (2.4).
        """
        k = self._kappa_expr()
        return -(4 * u**2 + 4 * u + 1 + k**2) * sp.exp(-2 * u) / k

    def series_parts(self, n: int, dom: Any) -> tuple[list[Any], list[Any]]:
        k = dom.kappa
        sh = taylor_sinh(2, n, dom.const)  # sinh(2s)/s
        ch = taylor_cosh(2, n, dom.const)  # cosh(2s)
        num = [2 * k * c for c in sh]
        num[0] = num[0] - dom.const(4, 1)
        den = [2 * k * c for c in ch]
        den[0] = den[0] + 1 + k * k
        if n >= 1:
            den[1] = den[1] + dom.const(4, 1)
        return num, den

    def L_numeric(self, u: Any, backend: str = "numpy", over_u: bool = False) -> Any:
        """Stable L(u) (or L(u)/u): see :mod:`thinlayer.kernel_numeric`.  Needs a numeric nu."""
        if self.parameter is not None:
            raise ValueError("numeric evaluation needs a numeric nu; build BondedLayer(nu=0.3) or similar")
        if backend == "numpy":
            return kernel_numeric.bonded_numpy(u, float(self.kappa), over_u)
        if backend == "mpmath":
            k = self.kappa
            k = mpmath.mpf(k.p) / k.q if isinstance(k, sp.Rational) else k
            return kernel_numeric.bonded_mpmath(u, k, over_u)
        raise ValueError(f"backend must be 'numpy' or 'mpmath', got {backend!r}")

    def __repr__(self) -> str:
        return f"BondedLayer(nu={self.nu})"


@dataclass(frozen=True)
class FrictionlessLayer(LayerKernel):
    """Layer lying on a rigid base without friction: ``L(u) = (cosh 2u - 1)/(sinh 2u + 2u)``.

    Independent of nu with the normalisation (2.1); ``A = 1/2``.
    """

    name: str = field(default="frictionless", init=False)
    equation: str = field(default="", init=False)

    def L(self, u: sp.Expr = S.u) -> sp.Expr:
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
        raise ValueError(f"backend must be 'numpy' or 'mpmath', got {backend!r}")


@dataclass(frozen=True)
class HalfSpace(LayerKernel):
    """The elastic half-space, ``L = 1``: the limit of every layer as H -> oo.

    It has no thin-layer (small-s) expansion: ``L(s)/s = 1/s`` is singular at s = 0.
    """

    name: str = field(default="half-space", init=False)
    equation: str = field(default="2.4", init=False)

    def L(self, u: sp.Expr = S.u) -> sp.Expr:
        return sp.Integer(1)

    def series_parts(self, n: int, dom: Any) -> tuple[list[Any], list[Any]]:
        raise ValueError(
            "the half-space kernel L = 1 has no expansion L(s)/s = A(1 + m_1 s^2 + ...) (2.20): "
            "the thin-layer analysis needs a layer of finite thickness (BondedLayer, FrictionlessLayer)"
        )

    def L_numeric(self, u: Any, backend: str = "numpy", over_u: bool = False) -> Any:
        import numpy as np

        if backend == "numpy":
            u = np.asarray(u, dtype=float)
            return 1.0 / u if over_u else np.ones_like(u)
        if backend == "mpmath":
            return 1 / mpmath.mpf(u) if over_u else mpmath.mpf(1)
        raise ValueError(f"backend must be 'numpy' or 'mpmath', got {backend!r}")


@dataclass(frozen=True)
class GenericLayer(LayerKernel):
    """A layer known only through its coefficients: ``A`` and ``m_n`` stay plain symbols.

    Results built on it read like the paper's formulas, e.g. (2.30) in terms of ``A`` and
    ``m_1``; the ``M_k`` follow from (4.2) as polynomials in the ``m_n``.
    """

    name: str = field(default="generic", init=False)
    equation: str = field(default="2.20", init=False)

    A_symbol = sp.Symbol(r"\mathcal{A}", positive=True)

    @staticmethod
    def m_symbol(n: int) -> sp.Symbol:
        return sp.Symbol(f"m_{n}")

    def L(self, u: sp.Expr = S.u) -> sp.Expr:
        raise ValueError("a GenericLayer has no closed-form L(u); use BondedLayer or FrictionlessLayer")

    def series_parts(self, n: int, dom: Any) -> tuple[list[Any], list[Any]]:
        raise ValueError("a GenericLayer has no Taylor data; its coefficients are symbols")

    def L_numeric(self, u: Any, backend: str = "numpy", over_u: bool = False) -> Any:
        raise ValueError("a GenericLayer cannot be evaluated numerically")

    @property
    def parameter(self) -> sp.Symbol | None:
        return self.A_symbol
