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

from . import symbols as S
from .display import RichDisplay
from .kernels import LayerKernel, _check_order
from .results import checked_lambdify


def laplacian(f: sp.Expr, v1: sp.Symbol, v2: sp.Symbol, power: int = 1) -> sp.Expr:
    """``Delta^power f`` in the variables (v1, v2)."""
    for _ in range(power):
        f = sp.diff(f, v1, 2) + sp.diff(f, v2, 2)
    return f


def kernel_moment(layer: LayerKernel, a1: int, a2: int):
    """The moment mu_{a1 a2} = iint k(xi) xi1^a1 xi2^a2 dxi of the kernel (2.12), (2.15).

    Zero when a1 or a2 is odd (2.19); otherwise the derived (2.21)::

        mu_{2k, 2n-2k} = (-1)^n pi^2 A m_n C(n, k) (2k)! (2n-2k)!

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> BondedLayer("3/10").moment(0, 0)
    20*pi**2/49
    >>> BondedLayer("3/10").moment(1, 2)
    0
    """
    a1 = _check_order(a1, "a1")
    a2 = _check_order(a2, "a2")
    if a1 % 2 or a2 % 2:
        return sp.Integer(0)
    n, k = (a1 + a2) // 2, a1 // 2
    c = layer.coefficients(n)
    return (
        (-1) ** n * sp.pi**2 * c.A_expr * c.m_expr(n)
        * sp.binomial(n, k) * sp.factorial(2 * k) * sp.factorial(2 * n - 2 * k)
    )


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
        return sp.Add(*[w * Lam ** (-2 * n - 2) * laplacian(f, v1, v2, n) for n, w in enumerate(self.weights())])

    def pairing(self, phi: sp.Expr, v1: sp.Symbol = S.xi1, v2: sp.Symbol = S.xi2, Lam: sp.Expr = S.Lambda) -> sp.Expr:
        """``<k(Lambda xi), phi>`` by (2.16): ``sum_{|alpha| <= 2 order + 1} mu_alpha D^alpha phi(0) / (alpha! Lambda^{|alpha|+2})``.

        Built from the individual moments (2.21), not from the Laplacian form, so that
        comparing it with :meth:`apply` checks (2.21) against (2.22).
        """
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
            op = r"\delta(\boldsymbol{\xi})" if n == 0 else rf"\Delta^{{{n}}}\delta(\boldsymbol{{\xi}})" if n > 1 else r"\Delta\delta(\boldsymbol{\xi})"
            parts.append(rf"\left({sp.latex(w)}\right) \Lambda^{{{-2 * n - 2}}} {op}")
        return r"k(\Lambda\boldsymbol{\xi}) \sim " + " + ".join(parts) + r" + \dots \tag{2.22}"

    def lambdify(self, backend: str = "numpy"):
        """Numeric weights ``f(*params) -> (w_0, ..., w_order)`` with the layer's parameter as argument."""
        p = self.layer.parameter
        return checked_lambdify([p] if p is not None else [], list(self.weights()), backend)


@lru_cache(maxsize=64)
def moment_expansion(layer: LayerKernel, order: int) -> MomentExpansion:
    """The moment asymptotic expansion (2.14)/(2.22) of ``k(Lambda xi)`` through n = ``order``."""
    return MomentExpansion(layer, _check_order(order, "order"))
