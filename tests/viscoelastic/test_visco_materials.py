"""Viscoelastic materials (issue 27 item 1): relaxation moduli, complex moduli against quadrature, refusals."""
from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from thinlayer.contact.materials import KelvinVoigt, PowerLaw, Prony, StandardLinearSolid
from thinlayer.errors import InputError, InputTypeError


def test_prony_relaxation_is_the_sum_of_its_branches():
    m = Prony(0.5, [(2.0, 0.1), (1.0, 3.0)])
    t = np.array([0.0, 0.1, 1.0, 30.0])
    expected = [0.5 + 2.0 * math.exp(-x / 0.1) + math.exp(-x / 3.0) for x in t]
    np.testing.assert_allclose(m.relaxation(t), expected, rtol=1e-15)
    assert m.instantaneous == 3.5
    assert m.relaxation(np.inf) == 0.5


def test_standard_linear_solid_is_a_one_term_prony_series():
    m = StandardLinearSolid(5.0, 2.0, 0.25)
    assert m == Prony(2.0, [(3.0, 0.25)])
    assert float(m.relaxation(0.0)) == 5.0
    assert StandardLinearSolid(2.0, 2.0, 1.0).terms == ()  # E0 = E_inf: elastic


@pytest.mark.parametrize("omega", [0.01, 0.7, 3.0, 25.0])
def test_prony_complex_modulus_against_quadrature(omega):
    # E*(w) = i w int_0^inf E(t) exp(-i w t) dt; the branch E_i exp(-t/tau_i) by mpmath quadrature
    m = Prony(0.5, [(2.0, 0.1), (1.0, 0.6)])
    quad = m.E_inf
    for e, tau in m.terms:
        # [0, 40 tau] (the tail exp(-40) ~ 4e-18 is below the tolerance) cut every half period
        pts = mpmath.linspace(0, 40 * tau, max(8, math.ceil(40 * tau * omega / math.pi)) + 1)
        re = mpmath.quad(lambda t: e * mpmath.exp(-t / tau) * mpmath.cos(omega * t), pts)
        im = mpmath.quad(lambda t: -e * mpmath.exp(-t / tau) * mpmath.sin(omega * t), pts)
        quad += complex(1j * omega * complex(re, im))
    assert abs(complex(m.complex_modulus(omega)) - quad) < 1e-12 * abs(quad)


def test_prony_complex_modulus_has_no_overflow():
    m = Prony(1.0, [(2.0, 1.0)])
    out = m.complex_modulus(np.array([0.0, 1e300, np.inf]))
    np.testing.assert_allclose(out.real, [1.0, 3.0, 3.0])
    np.testing.assert_allclose(out.imag, [0.0, 2e-300, 0.0], atol=1e-310)


@pytest.mark.parametrize("alpha", [0.2, 0.5, 0.8])
def test_power_law_complex_modulus_against_quadrature(alpha):
    # E*(w) = i w E0 t0^alpha int_0^inf t^-alpha exp(-i w t) dt, by quadrature along the ray t = -i s (the
    # integrand decays in the lower right quadrant: Jordan's lemma), complex powers on the principal branch
    m = PowerLaw(2.0, 0.5, alpha)
    w = 1.3
    # and s = u^(1/beta), beta = 1 - alpha, to remove the singularity at s = 0 (ds = s^alpha du / beta)
    beta = 1 - alpha

    def f(u):
        s = u ** (1 / beta)
        return (-1j * s) ** (-alpha) * mpmath.exp(-1j * w * (-1j * s)) * (-1j) * s**alpha / beta

    integral = mpmath.quad(f, [0, 1, mpmath.inf])
    quad = complex(1j * w * m.E0 * m.t0**alpha * integral)
    assert abs(complex(m.complex_modulus(w)) - quad) < 1e-9 * abs(quad)
    np.testing.assert_allclose(m.relaxation(np.array([0.5, 2.0])), [2.0, 2.0 * 4.0 ** -alpha], rtol=1e-15)
    assert m.relaxation(0.0) == np.inf


def test_kelvin_voigt_regular_part_and_complex_modulus():
    m = KelvinVoigt(3.0, 0.5)
    np.testing.assert_array_equal(m.relaxation([0.0, 1.0]), [3.0, 3.0])
    assert complex(m.complex_modulus(2.0)) == 3.0 + 1.0j
    assert m.impulse == 0.5 and m.instantaneous == math.inf


def test_materials_are_immutable_and_print_latex():
    m = Prony(1.0, [(2.0, 0.5)])
    with pytest.raises(AttributeError):
        m.E_inf = 2.0
    assert m.latex() == r"E(t) = 1 + 2\,e^{-t/0.5}"
    assert PowerLaw(1.0, 2.0, 0.25).latex() == r"E(t) = 1\,(t/2)^{-0.25}"
    assert KelvinVoigt(1.0, 0.5).latex() == r"E(t) = 1 + 0.5\,\delta(t)"


@pytest.mark.parametrize("build, kind, words", [
    (lambda: Prony(-1.0, []), InputError, "E_inf"),
    (lambda: Prony(1.0, [(1.0, 0.0)]), InputError, "tau_i"),
    (lambda: Prony(1.0, [(1.0,)]), InputTypeError, "terms[0]"),
    (lambda: Prony(0.0, []), InputError, "all zero"),
    (lambda: Prony(1.0, "ab"), InputTypeError, "terms"),
    (lambda: StandardLinearSolid(1.0, 2.0, 1.0), InputError, "must not exceed"),
    (lambda: KelvinVoigt(1.0, 0.0), InputError, "eta"),
    (lambda: PowerLaw(1.0, 1.0, 1.0), InputError, "0 < alpha < 1"),
    (lambda: PowerLaw(1.0, "1", 0.5), InputTypeError, "t0"),
    (lambda: PowerLaw(float("nan"), 1.0, 0.5), InputError, "E0"),
])
def test_bad_material_inputs_are_one_line(build, kind, words):
    with pytest.raises(kind) as exc:
        build()
    assert words in str(exc.value) and "\n" not in str(exc.value)


def test_negative_time_is_refused():
    with pytest.raises(InputError, match="t must be >= 0"):
        Prony(1.0, [(1.0, 1.0)]).relaxation([-1.0])
