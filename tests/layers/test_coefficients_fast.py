"""Issue 18 item 1: the fast coefficient paths give the same exact results.

* the direct scaled quotients (``N/D`` for m_n, ``D/N`` for M_k) against the fraction-free division and (4.2);
* the python-flint backend against the default pure-Python (Kronecker) arithmetic: identical expressions;
* the per-layer cache: lower orders served from the highest computed, and orders extended one at a time,
  identical to a fresh computation;
* a layer whose ``D_0`` has a repeated factor that the radical does not clear (the fallback ``g = D_0``).
"""
from __future__ import annotations

import math
import subprocess
import sys
from dataclasses import dataclass, field

import mpmath as mp
import pytest
import sympy as sp

from thinlayer import BondedLayer, FrictionlessLayer, GenericLayer, kernel_coefficients
from thinlayer import symbols as S
from thinlayer._series import quotient_fraction_free
from thinlayer.layers.coefficients import _domain
from thinlayer.layers.kernels import LayerKernel

SYMBOLIC = [BondedLayer(), BondedLayer(parameter="kappa")]


def _same(a, b) -> bool:
    """Identical sympy objects (structure and printed form), or equal numbers of the same type."""
    return a == b and type(a) is type(b) and str(a) == str(b)


@pytest.mark.parametrize("layer", SYMBOLIC, ids=str)
def test_direct_quotients_match_fraction_free_division(layer):
    # m_n = T_n / (T_0 D_0^n) from the fraction-free N/D of the previous implementation, cancelled by sympy
    order = 12
    c = kernel_coefficients(layer, order, backend="python")
    dom = _domain(layer)
    num, den = layer.series_parts(order, dom)
    T = quotient_fraction_free(num, den, order, dom.one)
    K, _ = sp.field([layer.parameter], sp.QQ)
    for n in range(order + 1):
        assert K(c.m[n]) == K(T[n].as_expr()) / (K(T[0].as_expr()) * K(den[0].as_expr()) ** n), n
    assert K(c.A) == K(num[0].as_expr()) / K(den[0].as_expr())


@pytest.mark.parametrize("layer", SYMBOLIC, ids=str)
def test_direct_reciprocal_satisfies_recurrence_4_2(layer):
    # M_k now comes from the direct quotient D/N: it must satisfy sum_j m_{k-j} M_j = 0 (4.2) exactly
    order = 12
    c = kernel_coefficients(layer, order, backend="python")
    K, _ = sp.field([layer.parameter], sp.QQ)  # rational functions: exact sums without sympy.cancel
    m, M = [K(x) for x in c.m], [K(x) for x in c.M]
    assert M[0] == 1
    for k in range(1, order + 1):
        assert sum((m[k - j] * M[j] for j in range(k + 1)), K.zero) == 0, k


def test_flint_backend_identical_expressions():
    pytest.importorskip("flint", reason="python-flint is not installed (optional: pip install 'thinlayer[fast]'); "
                                        "the flint backend cannot be compared")
    for layer in SYMBOLIC:
        for order in (0, 1, 7, 24):
            py = kernel_coefficients(layer, order, backend="python")
            fl = kernel_coefficients(layer, order, backend="flint")
            assert _same(py.A, fl.A)
            assert len(py.m) == len(fl.m) == order + 1
            assert all(_same(a, b) for a, b in zip(py.m + py.M, fl.m + fl.M))


def test_default_path_needs_no_flint():
    # python-flint made unimportable: the default ("auto") and "python" backends work, "flint" says what is missing
    code = (
        "import sys; sys.modules['flint'] = None\n"
        "from thinlayer import BondedLayer, kernel_coefficients\n"
        "c = kernel_coefficients(BondedLayer(), 6)\n"
        "assert c.m == kernel_coefficients(BondedLayer(), 6, backend='python').m\n"
        "try:\n"
        "    kernel_coefficients(BondedLayer(), 2, backend='flint')\n"
        "except ImportError as e:\n"
        "    print('ImportError:', e)\n"
        "print(c.M[2])\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300,
                         stdin=subprocess.DEVNULL)
    assert out.returncode == 0, out.stderr
    assert "ImportError: python-flint is not installed" in out.stdout
    assert "(3 - 4*nu)*(-56*nu**3 + 100*nu**2 - 32*nu + 3)/(180*(1 - 2*nu)**2*(1 - nu)**2)" in out.stdout


def test_unknown_backend_refused():
    with pytest.raises(ValueError, match="backend must be one of"):
        kernel_coefficients(BondedLayer(), 2, backend="gmpy")


LAYERS = [BondedLayer(), BondedLayer("3/10"), BondedLayer(0.3, dps=40), FrictionlessLayer(), GenericLayer()]


@pytest.mark.parametrize("layer", LAYERS, ids=repr)
def test_cache_serves_lower_orders_identical_to_fresh(layer):
    kernel_coefficients.cache_clear()
    high = 9
    big = kernel_coefficients(layer, high)
    for order in (0, 1, 4, high):
        served = kernel_coefficients(layer, order)
        fresh = kernel_coefficients(layer, order, backend="python")  # an explicit backend computes afresh
        assert served.order == fresh.order == order
        assert _same(served.A, fresh.A)
        assert all(_same(a, b) for a, b in zip(served.m + served.M, fresh.m + fresh.M))
        assert served.m == big.m[: order + 1] and served.M == big.M[: order + 1]
    assert kernel_coefficients(layer, 4) is kernel_coefficients(layer, 4)


@pytest.mark.parametrize("layer", LAYERS, ids=repr)
def test_extending_one_order_at_a_time_identical_to_one_call(layer):
    kernel_coefficients.cache_clear()
    for n in range(0, 11):  # what layer.m(n), layer.M(n) in a loop do
        kernel_coefficients(layer, n)
    grown = kernel_coefficients(layer, 10)
    fresh = kernel_coefficients(layer, 10, backend="python")
    assert _same(grown.A, fresh.A)
    assert all(_same(a, b) for a, b in zip(grown.m + grown.M, fresh.m + fresh.M))


def test_float_layer_keeps_its_precision_through_the_cache():
    kernel_coefficients.cache_clear()
    kernel_coefficients(BondedLayer(0.3, dps=40), 12)
    c40 = kernel_coefficients(BondedLayer(0.3, dps=40), 5)
    c30 = kernel_coefficients(BondedLayer(0.3), 5)  # dps is part of the layer, hence of the cache key
    assert all(isinstance(x, mp.mpf) for x in c40.m)
    assert c40.m[5] != c30.m[5] and abs(c40.m[5] - c30.m[5]) < mp.mpf(10) ** -28 * abs(c30.m[5])


t = sp.Symbol("t")


@dataclass(frozen=True)
class _OddLayer(LayerKernel):
    """A made-up layer in one parameter t: ``N = (1 + t) e^{2z} - 3 t z``, ``D = (1 + t)^2 (2 - t) cosh z + t z``.

    ``D_0 = (1+t)^2 (2-t)``: with the radical ``g = (1+t)(2-t)``, ``D_1 g / D_0 = t / (1+t)`` is no polynomial,
    so the quotient ``N/D`` falls back to ``g = D_0``; ``D/N`` keeps the radical of ``N_0 = 1 + t``.
    """

    name: str = field(default="odd", init=False)

    @property
    def parameter(self):
        return t

    def L(self, u=S.u):
        raise NotImplementedError

    def L_numeric(self, u, backend="numpy", over_u=False):
        raise NotImplementedError

    def series_parts(self, n, dom):
        x = dom.gen
        num, den = [], []
        f = 1
        for k in range(n + 1):
            if k:
                f *= k
            num.append((1 + x) * dom.const(2**k, f) - (3 * x if k == 1 else 0))
            ch = dom.const(1, math.factorial(k)) if k % 2 == 0 else dom.zero
            den.append((1 + x) ** 2 * (2 - x) * ch + (x if k == 1 else 0))
        return num, den


def test_generic_parameter_layer_with_fallback_scaling():
    layer = _OddLayer()
    order = 7
    c = kernel_coefficients(layer, order, backend="python")
    dom = _domain(layer)
    K, _ = sp.field([t], sp.QQ)
    num, den = ([K(p.as_expr()) for p in part] for part in layer.series_parts(order, dom))
    q = []
    for k in range(order + 1):  # the quotient N/D over the field of rational functions of t
        q.append((num[k] - sum((den[j] * q[k - j] for j in range(1, k + 1)), K.zero)) / den[0])
    m = [x / q[0] for x in q]
    M = [K.one]
    for k in range(1, order + 1):  # (4.2)
        M.append(-sum((m[k - j] * M[j] for j in range(k)), K.zero))
    assert K(c.A) == q[0]
    for k in range(order + 1):
        assert K(c.m[k]) == m[k], k
        assert K(c.M[k]) == M[k], k
