"""Stages (2.14)-(2.23): kernel moments and the moment asymptotic expansion.

Moments (2.15) of the kernel k(xi) (2.12).  With ``k(xi) = (1/4) iint F(|s|) e^{i s.xi} ds``,
``F = L(s)/s``, and ``int xi^m e^{i s xi} d xi = 2 pi (-i)^m delta^{(m)}(s)`` one finds (2.19):
odd moments vanish, and

    mu_{2k, 2n-2k} = (-1)^n pi^2 d^{2k}_{s1} d^{2n-2k}_{s2} F(0)
                   = (-1)^n pi^2 A m_n C(n, k) (2k)! (2n-2k)!          (2.21, derived)

because only the term ``A m_n (s1^2 + s2^2)^n`` of (2.20) survives and the coefficient of
``s1^{2k} s2^{2n-2k}`` in it is C(n, k).  The printed (2.21) has ``2^n k! (n-k)!`` in place of
``(2k)! (2n-2k)!`` -- see :mod:`thinlayer.errata`.  With the derived moments,
``mu_alpha / alpha! = (-1)^n pi^2 A m_n C(n, k)``, which is exactly the weight in (2.22).

Moment expansion (2.14), (2.22):

    k(Lambda xi) ~ sum_n (-1)^n pi^2 A m_n Lambda^{-2n-2} Delta^n delta(xi),

so that the convolution (2.23) acts on a smooth density as the operator series
``sum_n (-1)^n pi^2 A m_n Lambda^{-2n-2} Delta^n``.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

from .. import symbols as S
from .._checks import check_order as _check_order
from ..display import RichDisplay, fmt
from ..errors import boundary, boundary_methods
from ..layers.coefficients import check_coefficient_order
from ..layers.kernels import LayerKernel
from ..layers.moments import kernel_moment
from ..normal import join_signed, normal_latex
from ..parse import sympy_value
from ..results import checked_lambdify
from ..symbols import laplacian


@boundary_methods
@dataclass(frozen=True)
class MomentExpansion(RichDisplay):
    """The moment asymptotic expansion of ``k(Lambda xi)`` through ``Lambda^{-2 order - 2}`` (2.22).

    As an operator on smooth densities (2.23):
    ``sum_{n=0}^{order} (-1)^n pi^2 A m_n Lambda^{-2n-2} Delta^n``.
    """

    layer: LayerKernel
    order: int

    equation = "2.22"

    def weights(self) -> tuple[sp.Expr, ...]:
        """The weights ``w_n = (-1)^n pi^2 A m_n`` of ``Lambda^{-2n-2} Delta^n`` (2.22)."""
        c = self.layer.coefficients(self.order)
        return tuple((-1) ** n * sp.pi**2 * c.A_expr * c.m_expr(n) for n in range(self.order + 1))

    def apply(self, f: sp.Expr, v1: sp.Symbol = S.xi1, v2: sp.Symbol = S.xi2, Lam: sp.Expr = S.Lambda) -> sp.Expr:
        """The truncated operator series applied to a density f(v1, v2): the right side of (2.23)."""
        f, v1, v2, Lam = (sympy_value(f, "f"), sympy_value(v1, "v1", symbol=True),
                         sympy_value(v2, "v2", symbol=True), sympy_value(Lam, "Lam"))
        return sp.Add(*[w * Lam ** (-2 * n - 2) * laplacian(f, v1, v2, n) for n, w in enumerate(self.weights())])

    def pairing(self, phi: sp.Expr, v1: sp.Symbol = S.xi1, v2: sp.Symbol = S.xi2, Lam: sp.Expr = S.Lambda) -> sp.Expr:
        """``<k(Lambda xi), phi>`` by (2.16).

        ``sum_{|alpha| <= 2 order + 1} mu_alpha D^alpha phi(0) / (alpha! Lambda^{|alpha|+2})``.

        Built from the individual moments (2.21), not from the Laplacian form, so that
        comparing it with :meth:`apply` checks (2.21) against (2.22).
        """
        phi, v1, v2, Lam = (sympy_value(phi, "phi"), sympy_value(v1, "v1", symbol=True),
                         sympy_value(v2, "v2", symbol=True), sympy_value(Lam, "Lam"))
        terms = []
        for total in range(2 * self.order + 2):
            for a1 in range(total + 1):
                a2 = total - a1
                mu_a = kernel_moment(self.layer, a1, a2)
                if mu_a == 0:
                    continue
                d = sp.diff(phi, v1, a1, v2, a2) if (a1 or a2) else phi
                d0 = d.subs({v1: 0, v2: 0})
                terms.append(mu_a * d0 / (sp.factorial(a1) * sp.factorial(a2) * Lam ** (total + 2)))
        return sp.Add(*terms)

    def latex(self) -> str:
        """``k(Lambda xi) ~ sum_n ...`` with the weights written out, tagged (2.22)."""
        parts = []
        for n, w in enumerate(self.weights()):
            op = r"\delta(\boldsymbol{\xi})" if n == 0 else rf"\Delta^{{{n}}}\delta(\boldsymbol{{\xi}})" if n > 1 else r"\Delta\delta(\boldsymbol{\xi})"  # noqa: E501 (one formula)
            tex = normal_latex(w)
            parts.append((rf"\left({tex}\right)" if isinstance(w, sp.Add) else tex) + rf" \Lambda^{{{-2 * n - 2}}} {op}"
                         if w != 0 else "")
        return r"k(\Lambda\boldsymbol{\xi}) \sim " + join_signed(parts) + r" + \dots \tag{2.22}"

    def lambdify(self, backend: str = "numpy"):
        """Numeric weights ``f(*params) -> (w_0, ..., w_order)`` with the layer's parameter as argument."""
        p = self.layer.parameter
        return checked_lambdify([p] if p is not None else [], list(self.weights()), backend)

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """The weights ``w_n`` (2.22) as outputs, with the layer's parameter (if any) as the argument."""
        p = self.layer.parameter
        return ((p,) if p is not None else ()), {f"w_{n}": w for n, w in enumerate(self.weights())}

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        out = [(f"MomentExpansion of {self.layer}: k(Λξ) ~ Σₙ wₙ Λ^(-2n-2) Δⁿ δ(ξ), "
               f"n <= {self.order}   (2.22)")]
        sub = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
        out += [f"  w{str(n).translate(sub)} = {fmt(w)}" for n, w in enumerate(self.weights())]
        return out


@boundary
@lru_cache(maxsize=64)
def moment_expansion(layer: LayerKernel, order: int) -> MomentExpansion:
    """The moment asymptotic expansion (2.14)/(2.22) of ``k(Lambda xi)`` through n = ``order``.

    ``order`` is bounded by the layer's coefficient order limit
    (:data:`thinlayer.layers.coefficients.ORDER_LIMITS`; 30 for a symbolic nu, 2.9 s), checked here.
    """
    return MomentExpansion(layer, check_coefficient_order(layer, _check_order(order, "order")))
