"""Moments (2.15) of the kernel k(xi) (2.12), from its Maclaurin data (2.20).

With ``k(xi) = (1/4) iint F(|s|) e^{i s.xi} ds``, ``F = L(s)/s``, odd moments vanish (2.19) and

    mu_{2k, 2n-2k} = (-1)^n pi^2 A m_n C(n, k) (2k)! (2n-2k)!          (2.21, derived)

(the printed (2.21) differs -- see :mod:`thinlayer.errata`).  The moments are data of the kernel
itself, so they live with the layers; the moment *expansion* (2.22) is the first asymptotic stage.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from .._checks import check_order as _check_order_public
from .._lazy import lazy_module
from ..errors import boundary
from .coefficients import check_coefficient_order

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it

if TYPE_CHECKING:
    from .kernels import LayerKernel


@boundary
def kernel_moment(layer: LayerKernel, a1: int, a2: int):
    """The moment mu_{a1 a2} = iint k(xi) xi1^a1 xi2^a2 dxi of the kernel (2.12), (2.15).

    Zero when a1 or a2 is odd (2.19); otherwise the derived (2.21)::

        mu_{2k, 2n-2k} = (-1)^n pi^2 A m_n C(n, k) (2k)! (2n-2k)!

    ``(a1 + a2)/2`` is bounded by the coefficient order limit of the layer
    (:data:`thinlayer.layers.coefficients.ORDER_LIMITS`, e.g. 30 for a symbolic nu: 2.9 s).

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> BondedLayer("3/10").moment(0, 0)
    20*pi**2/49
    >>> BondedLayer("3/10").moment(1, 2)
    0
    """
    a1 = _check_order_public(a1, "a1")
    a2 = _check_order_public(a2, "a2")
    if a1 % 2 or a2 % 2:
        return sp.Integer(0)
    n, k = (a1 + a2) // 2, a1 // 2
    check_coefficient_order(layer, n, "(a1 + a2)/2, the coefficient order of the moment")
    c = layer.coefficients(n)
    return (
        (-1) ** n * sp.pi**2 * c.A_expr * c.m_expr(n)
        * sp.binomial(n, k) * sp.factorial(2 * k) * sp.factorial(2 * n - 2 * k)
    )
