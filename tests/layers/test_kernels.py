"""Layer kernels: (2.3), the limits (2.4), and stable numerics for every u >= 0."""
import math

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from thinlayer import BondedLayer, FrictionlessLayer, HalfSpace, IncompressibleLayerError
from thinlayer import symbols as S


def reference_L(u, nu, dps=60):
    """(2.3) straight from the printed formula at very high precision (no rearrangement)."""
    with mp.workdps(dps):
        u, k = mp.mpf(u), 3 - 4 * mp.mpf(nu)
        return (2 * k * mp.sinh(2 * u) - 4 * u) / (2 * k * mp.cosh(2 * u) + 1 + k**2 + 4 * u**2)


def test_symbolic_kernel_is_2_3():
    # (2.3) with kappa = 3 - 4 nu
    L = BondedLayer().L(S.u)
    k = 3 - 4 * S.nu
    printed = (2 * k * sp.sinh(2 * S.u) - 4 * S.u) / (2 * k * sp.cosh(2 * S.u) + 1 + k**2 + 4 * S.u**2)
    assert sp.simplify(L - printed) == 0


def test_small_u_limit_A_2_4():
    # (2.4): L(u) = A u + O(u^3), A = 4(kappa-1)/(kappa+1)^2
    layer = BondedLayer()
    k = 3 - 4 * S.nu
    assert sp.cancel(layer.A - 4 * (k - 1) / (k + 1) ** 2) == 0
    lim = sp.limit(layer.L(S.u) / S.u, S.u, 0)
    assert sp.cancel(lim - layer.A) == 0


@pytest.mark.parametrize("nu", [-0.9, -0.3, 0.0, 0.3, 0.45, 0.499])
@pytest.mark.parametrize("u", [0.0, 1e-12, 1e-6, 1e-3, 0.3, 0.999, 1.0, 1.001, 3.0, 20.0, 300.0, 1e4])
def test_numpy_kernel_is_accurate_everywhere(u, nu):
    layer = BondedLayer(nu)
    val = layer.L_numeric(u)
    ref = reference_L(u, nu)
    assert np.isfinite(val)
    if u == 0:
        assert val == 0
    else:
        assert abs(val - float(ref)) <= 4e-15 * abs(float(ref)), (u, nu, val, ref)
    # L/u tends to A without 0/0
    lu = layer.L_numeric(u, over_u=True)
    refu = float(ref / mp.mpf(u)) if u else float(mp.mpf(4) * (2 - 4 * mp.mpf(nu)) / (4 - 4 * mp.mpf(nu)) ** 2)
    assert abs(lu - refu) <= 4e-15 * abs(refu)


@pytest.mark.parametrize("u", ["1e-12", "0.5", "1e4"])
def test_mpmath_kernel_at_precision(u):
    layer = BondedLayer("3/10")
    with mp.workdps(40):
        val = layer.L_numeric(mp.mpf(u), backend="mpmath")
        ref = reference_L(u, mp.mpf(3) / 10, dps=120)
        assert abs(val - ref) <= mp.mpf(10) ** -38 * abs(ref)


def test_large_u_behaviour_2_4():
    # (2.4): L(u) = 1 + O(u^2 e^{-2u}); the engine's leading term of L - 1 must be asymptotic to it
    layer = BondedLayer(sp.Rational(1, 4))
    lead = layer.large_u(S.u)
    for u in (10, 20, 40):
        with mp.workdps(80):
            diff = reference_L(u, mp.mpf(1) / 4, 80) - 1
            ratio = diff / mp.mpf(sp.N(lead.subs(S.u, u), 60))
        assert abs(ratio - 1) < 10 * math.exp(-2 * u) * u**2 + 1e-30
    assert sp.limit(lead / (S.u**2 * sp.exp(-2 * S.u)), S.u, sp.oo) == -4 / layer.kappa


def test_vectorised_and_positive():
    u = np.concatenate([[0.0], np.logspace(-14, 4, 400)])
    for layer in (BondedLayer(0.3), FrictionlessLayer()):
        v = layer.L_numeric(u)
        assert v.shape == u.shape and np.all(np.isfinite(v))
        assert np.all(v[1:] > 0) and np.all(v <= 1 + 1e-15)  # continuous and positive (2.4)


def test_frictionless_kernel_numerics():
    layer = FrictionlessLayer()
    for u in (1e-10, 0.2, 2.0, 50.0, 1e4):
        with mp.workdps(60):
            ref = (mp.cosh(2 * mp.mpf(u)) - 1) / (mp.sinh(2 * mp.mpf(u)) + 2 * mp.mpf(u))
        assert abs(layer.L_numeric(u) - float(ref)) <= 4e-15 * float(ref)
        assert abs(layer.L_numeric(u, "mpmath") - ref) <= mp.mpf(10) ** -14 * ref
        # L(u)/u, used by the boundary-layer kernel F = L(s)/s (3.17)
        assert abs(float(layer.L_numeric(u, over_u=True)) - float(ref / u)) <= 4e-15 * float(ref / u)
        assert abs(layer.L_numeric(u, "mpmath", over_u=True) - ref / u) <= mp.mpf(10) ** -14 * ref / u
    assert float(layer.L_numeric(0.0, over_u=True)) == 0.5
    assert layer.A == sp.Rational(1, 2)


def test_half_space_is_a_sibling_without_expansion():
    hs = HalfSpace()
    assert hs.L() == 1
    assert float(hs.L_numeric(3.0)) == 1.0
    with pytest.raises(ValueError, match="half-space"):
        hs.A


@pytest.mark.parametrize("bad", [-1, -1.5, 0.6, 2, "7/10"])
def test_poisson_ratio_out_of_range(bad):
    with pytest.raises(ValueError, match="-1 < nu < 1/2"):
        BondedLayer(bad)


@pytest.mark.parametrize("half", [0.5, "1/2", sp.Rational(1, 2)])
def test_bonded_layer_at_one_half_is_the_incompressible_layer(half):
    from thinlayer import IncompressibleLayer

    layer = BondedLayer(half)
    assert layer == IncompressibleLayer() and layer.numeric_nu == 0.5
    # the same kernel (2.3) at kappa = 1, but A = 0 (2.4): the compressible coefficients (2.20) are refused
    assert layer.L_numeric(0.7) == pytest.approx(BondedLayer(0.4999999999).L_numeric(0.7), rel=1e-8)
    with pytest.raises(IncompressibleLayerError, match="incompressible"):
        layer.coefficients(1)


@pytest.mark.parametrize("nu", [0.3, "3/10", 0.5, -0.5])
def test_frictionless_layer_takes_a_poisson_ratio(nu):
    layer = FrictionlessLayer(nu)
    assert layer.poisson_ratio() == pytest.approx(float(sp.Rational(str(nu))) if isinstance(nu, str) else nu)
    assert layer.L_numeric(0.7) == FrictionlessLayer().L_numeric(0.7)  # the kernel does not depend on nu
    with pytest.raises(ValueError, match="disagrees"):
        layer.poisson_ratio(0.1)
    with pytest.raises(ValueError, match="nu"):
        FrictionlessLayer(0.7)


def test_bad_nu_types():
    with pytest.raises(TypeError):
        BondedLayer(True)
    with pytest.raises(ValueError, match="not a number"):
        BondedLayer("abc")
    with pytest.raises(ValueError, match="parameter"):
        BondedLayer(parameter="lambda")


def test_kappa_parametrisation():
    a = BondedLayer(parameter="kappa").m(2)
    b = BondedLayer().m(2)
    assert sp.cancel(a.subs(S.kappa, 3 - 4 * S.nu) - b) == 0
