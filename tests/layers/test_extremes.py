"""Issue 12 item 8: L(u) and L(u)/u finite and accurate for every u >= 0 (1e300 and inf included), for
every layer and both backends; nan and u < 0 refused with the same ValueError by numpy and mpmath."""
from __future__ import annotations

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import thinlayer as tl
from thinlayer.asymptotics.incompressible import IncompressibleLayer

LAYERS = [tl.BondedLayer(0.3), tl.BondedLayer("3/10"), tl.BondedLayer(-0.9), tl.BondedLayer(0.499),
          tl.FrictionlessLayer(), IncompressibleLayer(), tl.HalfSpace()]
U = np.array([0.0, 5e-324, 1e-300, 1e-150, 1e-12, 1e-3, 0.3, 0.99, 1.0, 1.01, 2.0, 7.5, 20.0, 40.0, 371.0, 373.0,
              1e3, 1e10, 1.3e154, 1e155, 1e200, 1e300, 1.7e308, np.inf])


def _direct(layer, u, over_u):
    """The closed forms (2.3) and cosh/sinh of the frictionless base, in mpmath at 60 digits (independent
    of the scaled, cancellation-free forms of thinlayer.layers.numeric)."""
    extra = int(-3 * mpmath.log10(u)) if 0 < u < 1 else 0  # L - A u ~ u^3: cancellation at small u
    with mpmath.workdps(60 + extra):
        u = mpmath.mpf(u)
        if u == 0:
            return (mpmath.mpf(1) if layer.base is None else mpmath.mpf(0)) if not over_u else None
        if mpmath.isinf(u):
            return mpmath.mpf(0) if over_u else mpmath.mpf(1)
        if layer.base is None:
            L = mpmath.mpf(1)
        elif layer.base == "frictionless":
            L = (mpmath.cosh(2 * u) - 1) / (mpmath.sinh(2 * u) + 2 * u)
        else:
            nu = mpmath.mpf(3) / 10 if str(layer) == "BondedLayer(nu=3/10)" else mpmath.mpf(layer.numeric_nu)
            k = 3 - 4 * nu  # the float layers hold the binary value of nu
            L = (2 * k * mpmath.sinh(2 * u) - 4 * u) / (2 * k * mpmath.cosh(2 * u) + 1 + k**2 + 4 * u**2)
        return +(L / u if over_u else L)


@pytest.mark.parametrize("layer", LAYERS, ids=str)
@pytest.mark.parametrize("over_u", [False, True])
def test_finite_and_accurate_everywhere(layer, over_u):
    got = np.asarray(layer.L_numeric(U, "numpy", over_u=over_u), dtype=float)
    got_mp = [layer.L_numeric(mpmath.mpf(u), "mpmath", over_u=over_u) for u in U]
    for u, g, gm in zip(U, got, got_mp):
        ref = _direct(layer, u, over_u)
        if ref is None:  # L/u at u = 0: the limit A (or inf for the half-space)
            if layer.base is None:
                assert g == np.inf and gm == mpmath.inf
            else:
                assert np.isfinite(g) and abs(g - float(gm)) <= 1e-15 * abs(g)
            continue
        if layer.base is None and over_u and u < 1 / 1.7976931348623157e308:
            assert g == np.inf  # 1/u is beyond the float range
            continue
        assert np.isfinite(g) and mpmath.isfinite(gm), (u, g, gm)
        tolerance = 1e-15 * abs(float(ref)) + (1e-320 if u < 1e-300 else 0.0)
        assert abs(g - float(ref)) <= tolerance, (u, g, float(ref))
        assert abs(float(gm) - float(ref)) <= tolerance, (u, gm, float(ref))
    if over_u:
        assert got[-1] == 0.0 and got_mp[-1] == 0  # L/u -> 0 at inf
    else:
        assert got[-1] == 1.0 and got_mp[-1] == 1


@pytest.mark.parametrize("nu", ["3/10", "0", "-1/2", "49/100"])
def test_large_u_against_asymptote(nu):
    """(2.4): L = 1 - (4u^2 + 4u + 1 + kappa^2) e^{-2u}/kappa + O(u^2 e^{-4u}); beyond u = 25 the remainder is
    below 1e-40, so the asymptote is an independent value of L to far better than 1e-15."""
    from fractions import Fraction
    k = 3 - 4 * Fraction(nu)
    layer = tl.BondedLayer(nu)
    for u in [25.0, 30.0, 60.0, 200.0, 1e5, 1e300]:
        with mpmath.workdps(40):
            asym = 1 - (4 * mpmath.mpf(u) ** 2 + 4 * u + 1 + mpmath.mpf(k.numerator) ** 2 / k.denominator ** 2) \
                * mpmath.exp(-2 * mpmath.mpf(u)) / (mpmath.mpf(k.numerator) / k.denominator)
        got = float(layer.L_numeric(u))
        assert abs(got - float(asym)) <= 1.2e-16 * float(asym)
        assert abs(float(layer.L_numeric(u, "mpmath")) - float(asym)) <= 1.2e-16 * float(asym)
        assert abs(float(layer.L_numeric(u, over_u=True)) - float(asym) / u) <= 2.3e-16 * float(asym) / u


@settings(max_examples=150, deadline=None)
@given(st.floats(min_value=0.0, max_value=1.7e308, allow_nan=False))
def test_hypothesis_numpy_equals_mpmath(u):
    for layer in (tl.BondedLayer(0.3), tl.FrictionlessLayer(), IncompressibleLayer()):
        for over_u in (False, True):
            a = float(layer.L_numeric(u, over_u=over_u))
            b = float(layer.L_numeric(u, "mpmath", over_u=over_u))
            assert np.isfinite(a) and abs(a - b) <= 5e-16 * abs(b) + 1e-323


@pytest.mark.parametrize("layer", LAYERS, ids=str)
@pytest.mark.parametrize("bad, shown", [(float("nan"), "nan"), (-1.0, "-1.0"), (-np.inf, "-inf"), (-1e-300, "-1e-300")])
@pytest.mark.parametrize("over_u", [False, True])
def test_nan_and_negative_rejected_alike(layer, bad, shown, over_u):
    msg = f"u must be a real number >= 0 (inf allowed), got u = {shown}"
    with pytest.raises(ValueError) as e_np:
        layer.L_numeric(bad, "numpy", over_u=over_u)
    with pytest.raises(ValueError) as e_mp:
        layer.L_numeric(bad, "mpmath", over_u=over_u)
    assert str(e_np.value) == str(e_mp.value) == msg
    with pytest.raises(ValueError, match="u must be a real number >= 0"):
        layer.L_numeric(np.array([1.0, bad, 2.0]), "numpy", over_u=over_u)


def test_no_floating_point_warnings():
    with np.errstate(all="raise"):
        for layer in LAYERS[:-1]:
            layer.L_numeric(U[U > 0], over_u=True)
            layer.L_numeric(U)


def _kernel_in_mpmath_arithmetic(u, kappa, frictionless, over_u):
    """L(u) of the module docstring of thinlayer.layers.numeric, every operation in mpmath (the construction the
    engine used before its MPFR kernel): guard digits 3 log10(1/u) + 5 below u = 1, 5 above."""
    u = mpmath.mpf(u)
    extra = max(0, int(-3 * mpmath.log10(u)) + 5) if u < 1 else 5
    with mpmath.extradps(extra):
        E = mpmath.exp(-2 * u)
        if frictionless:
            a = -mpmath.expm1(-2 * u)
            val = a * a / (-mpmath.expm1(-4 * u) + 4 * u * E)
        else:
            x = 2 * u
            S = (mpmath.sinh(x) - x) * E if x < 40 else (1 - E * E) / 2 - x * E
            val = (2 * kappa * S + 4 * u * (kappa - 1) * E) / (kappa * (1 + E * E) + (1 + kappa**2 + 4 * u * u) * E)
        if over_u:
            val = val / u
    return +val


@pytest.mark.parametrize("dps", [15, 20, 50])
def test_mpfr_kernel_is_the_mpmath_kernel_to_the_bit(dps):
    """(2.3) in the mpmath backend is computed in MPFR (gmpy2) at mpmath's precision plus the same guard digits: both
    round every step to nearest, so the values are mpmath's own to the last bit, from u = 1e-12 to 1e3."""
    rng = np.random.default_rng(dps)
    with mpmath.workdps(dps):
        for layer, frictionless in [(tl.BondedLayer("3/10"), False), (tl.BondedLayer(0.49), False),
                                    (tl.FrictionlessLayer(), True)]:
            k = None if frictionless else layer.kappa  # (2.3): a Rational, or an mpmath number at the layer's dps
            kappa = k if k is None or isinstance(k, mpmath.mpf) else mpmath.mpf(int(k.p)) / int(k.q)
            for u in 10.0 ** rng.uniform(-12, 3, 40):
                for over_u in (False, True):
                    got = layer.L_numeric(mpmath.mpf(u), "mpmath", over_u=over_u)
                    assert got == _kernel_in_mpmath_arithmetic(u, kappa, frictionless, over_u), (layer, u, over_u)
