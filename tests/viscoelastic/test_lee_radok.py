"""The Lee-Radok hereditary integral (issue 27 item 2): closed forms, exactness, refinement, the thin layer.

Independent references: the Hertz sphere under a ramp with a standard linear solid, integrated by sympy (and the
sympy result checked by mpmath quadrature); mpmath quadrature of the same integral for piecewise-linear histories;
integration by parts with mpmath quadrature on the thin bonded layer.
"""
from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp

from thinlayer import BondedLayer, Punch
from thinlayer.contact.hereditary import MAX_NONUNIFORM_POWER, force_curve_for, hereditary_integral, viscoelastic_force
from thinlayer.contact.materials import KelvinVoigt, PowerLaw, Prony, StandardLinearSolid
from thinlayer.errors import WorkLimitError

E0, EINF, TAU, V = 3.0, 1.0, 0.2, 0.05


def _sls_ramp_closed_form():
    """``int_0^t E(t - s) d/ds (v s)^{3/2} ds`` for ``E = E_inf + (E0 - E_inf) exp(-t/tau)``, integrated by sympy."""
    s, t = sp.symbols("s t", positive=True)
    E = EINF + (E0 - EINF) * sp.exp(-(t - s) / sp.Rational(TAU).limit_denominator(1000))
    integrand = E * sp.diff((sp.Rational(V).limit_denominator(1000) * s) ** sp.Rational(3, 2), s)
    return t, sp.integrate(sp.expand(integrand), (s, 0, t))


def _real(z) -> float:
    """The real value of sympy's erfc-of-imaginary closed form (its imaginary part cancels)."""
    z = mpmath.mpc(z)
    assert abs(z.imag) <= 1e-20 * abs(z.real)
    return float(z.real)


def test_sympy_closed_form_against_mpmath_quadrature():
    # Hertz (H.1): P = (4/3) E* R^(1/2) delta^(3/2); Lee-Radok with delta = v t
    t, expr = _sls_ramp_closed_form()
    f = sp.lambdify(t, expr, modules="mpmath")
    with mpmath.workdps(30):
        for tv in (0.01, 0.3, 1.0, 5.0):
            quad = mpmath.quad(lambda s: (EINF + (E0 - EINF) * mpmath.exp(-(tv - s) / TAU)) * 1.5 * V**1.5
                               * mpmath.sqrt(s), [0, tv])
            assert abs(f(mpmath.mpf(tv)) - quad) < 1e-13 * abs(quad)  # the quadrature uses the float tau, v


def test_hertz_sls_ramp_to_1e6():
    # graded grid t_k = T (k/N)^2: the history (v t)^{3/2} is interpolated linearly in time
    t_sym, expr = _sls_ramp_closed_form()
    f = sp.lambdify(t_sym, expr, modules="mpmath")
    m = StandardLinearSolid(E0, EINF, TAU)
    t = 1.0 * (np.arange(1001) / 1000.0) ** 2
    got = hereditary_integral(m, t, (V * t) ** 1.5)
    with mpmath.workdps(30):
        ref = np.array([_real(f(mpmath.mpf(x))) for x in t[1::20]])
    err = np.max(np.abs(got[1::20] / ref - 1))
    assert err < 1e-6, err
    # the force of a sphere R = 4 on the half-space at nu = 0.3: (4/3) sqrt(R)/(1 - nu^2) times the integral
    assert got[-1] * (4 / 3) * 2 / (1 - 0.09) == pytest.approx(_real(f(mpmath.mpf(1))) * (4 / 3) * 2 / 0.91, rel=1e-6)


def test_observed_order_is_two():
    t_sym, expr = _sls_ramp_closed_form()
    with mpmath.workdps(30):
        exact = _real(sp.lambdify(t_sym, expr, modules="mpmath")(mpmath.mpf(1)))
    m = StandardLinearSolid(E0, EINF, TAU)
    errs = []
    for n in (250, 500, 1000):
        t = (np.arange(n + 1) / n) ** 2
        errs.append(abs(hereditary_integral(m, t, (V * t) ** 1.5)[-1] / exact - 1))
    orders = [math.log2(errs[k] / errs[k + 1]) for k in range(2)]
    assert all(1.9 < p < 2.1 for p in orders), orders


def _piecewise_linear_quadrature(E, t, F, n):
    """``F[0] E(t_n - t_0) + sum_k r_k int_{t_{k-1}}^{t_k} E(t_n - s) ds`` by mpmath quadrature."""
    total = F[0] * E(t[n] - t[0]) if F[0] else mpmath.mpf(0)
    for k in range(1, n + 1):
        r = (F[k] - F[k - 1]) / (t[k] - t[k - 1])
        total += r * mpmath.quad(lambda s: E(t[n] - s), [t[k - 1], t[k]])
    return total


def _history(seed, n, start=0.0):
    rng = np.random.default_rng(seed)
    t = np.cumsum(rng.uniform(0.01, 0.3, n))
    t = t - t[0]
    F = np.concatenate([[start], start + np.cumsum(rng.uniform(0.0, 1.0, n - 1))])
    return t, F


def test_prony_exact_for_piecewise_linear_histories():
    m = Prony(0.3, [(2.0, 0.05), (1.0, 0.7), (0.5, 20.0)])
    t, F = _history(1, 40, start=0.4)  # a step of 0.4 at t = 0, then a non-uniform ramp
    got = hereditary_integral(m, t, F)
    E = lambda u: m.E_inf + sum(e * mpmath.exp(-u / tau) for e, tau in m.terms)  # noqa: E731
    for n in (0, 1, 17, 39):
        assert got[n] == pytest.approx(float(_piecewise_linear_quadrature(E, t, F, n)), rel=1e-12)


def test_prony_blocks_carry_over_long_histories():
    # t/tau up to 2000: many blocks of 30 tau; the ramp's exact value t - tau (1 - exp(-t/tau)) + ...
    m = Prony(0.0, [(1.0, 0.01)])
    t = np.linspace(0.0, 20.0, 4001)
    got = hereditary_integral(m, t, t)
    np.testing.assert_allclose(got, 0.01 * -np.expm1(-t / 0.01), rtol=1e-12, atol=1e-300)


@pytest.mark.parametrize("uniform", [True, False])
def test_power_law_exact_for_piecewise_linear_histories(uniform):
    m = PowerLaw(2.0, 0.5, 0.3)
    if uniform:
        t = np.linspace(0.0, 3.0, 41)
        F = np.sin(t) + t
    else:
        t, F = _history(2, 40)
    got = hereditary_integral(m, t, F)
    E = lambda u: m.E0 * (u / m.t0) ** -m.alpha  # noqa: E731
    for n in (1, 7, len(t) - 1):
        assert got[n] == pytest.approx(float(_piecewise_linear_quadrature(E, t, F, n)), rel=1e-10)


def test_power_law_fft_path_equals_the_direct_sum():
    m = PowerLaw(1.0, 1.0, 0.6)
    t = np.linspace(0.0, 2.0, 3001)
    F = t**1.5
    fft = hereditary_integral(m, t, F)
    t2 = t.copy()
    t2[1] *= 1 + 1e-9  # breaks the uniform grid: the O(N^2) product integration
    direct = hereditary_integral(m, t2, F)
    np.testing.assert_allclose(fft[5:], direct[5:], rtol=1e-7)


def test_power_law_non_uniform_work_is_refused_before_it_starts():
    t = np.cumsum(np.linspace(1.0, 2.0, MAX_NONUNIFORM_POWER + 1))
    with pytest.raises(WorkLimitError, match="uniform grid"):
        hereditary_integral(PowerLaw(1.0, 1.0, 0.5), t, t)


def test_kelvin_voigt_is_spring_plus_rate():
    t = np.array([0.0, 1.0, 3.0])
    F = np.array([0.0, 2.0, 3.0])
    np.testing.assert_allclose(hereditary_integral(KelvinVoigt(1.5, 0.5), t, F), [0.0, 3.0 + 1.0, 4.5 + 0.25])
    assert hereditary_integral(KelvinVoigt(1.5, 0.5), t, F + 1)[0] == np.inf  # a step: the impulse is infinite


def test_thin_bonded_layer_against_quadrature_by_parts():
    # P(t) = [E(0) F(t) + int_0^t E'(t - s) F(s) ds] / (2 (1 + nu)), F(s) = the any-thickness law (T.7) at
    # delta = v s, mu = 1; sphere R = 10 on a bonded layer H = 0.5 at nu = 0.3: sqrt(R delta)/H up to 1.8
    layer, tip, H, nu, v = BondedLayer(0.3), Punch.paraboloid(10.0), 0.5, 0.3, 0.08
    m = StandardLinearSolid(E0, EINF, TAU)
    t = (np.arange(2001) / 2000.0) ** 2
    out = viscoelastic_force(layer, tip, H, m, t, v * t, model="any-thickness")
    assert out.valid.all() and out.model == "any-thickness"
    curve = force_curve_for(layer, tip, H, nu, 1e-3, v * t, "any-thickness")
    F = lambda s: float(curve.force(np.array([v * float(s)]))[0])  # noqa: E731
    for T in (0.25, 1.0):
        n = int(np.searchsorted(t, T))
        Tn = float(t[n])
        ref = (m.instantaneous * F(Tn) - (E0 - EINF) / TAU
               * mpmath.quad(lambda s: mpmath.exp(-(Tn - s) / TAU) * F(s), [0, Tn / 2, Tn])) / (2 * (1 + nu))
        assert out.force[n] == pytest.approx(float(ref), rel=1e-6)
    # thinner than the half-space: the force is above Hertz's at the same history
    hertz = hereditary_integral(m, t, 8 / 3 / (1 - nu) * math.sqrt(10.0) * (v * t) ** 1.5) / (2 * (1 + nu))
    assert out.force[-1] > 1.5 * hertz[-1]
