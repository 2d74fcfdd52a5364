"""Small oscillations around a depth (issue 27 item 2): the linearised Lee-Radok law and the bottom-effect correction.

Independent references: mpmath quadrature of the branch integral; the steady state of the (exact for piecewise
linear histories) hereditary integral over a long sinusoidal history; the flat punch's stiffness kappa(a/H) (F.1)
at the same contact radius (the identity dP/d delta = flat-punch stiffness of the current contact); the leading
thin-layer force (1.8) and (I.11) differentiated by hand in the test.
"""
from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp

from thinlayer import BondedLayer, FrictionlessLayer, Punch, flat_punch_stiffness
from thinlayer.contact.hereditary import force_curve_for, hereditary_integral
from thinlayer.contact.materials import PowerLaw, StandardLinearSolid
from thinlayer.contact.oscillation import (
    MAX_RELATIVE_AMPLITUDE,
    contact_stiffness,
    oscillation,
    oscillation_law,
)
from thinlayer.errors import InputError, ThinlayerError


def test_derived_branch_modulus_against_the_material_and_quadrature():
    law = oscillation_law()
    y = law.symbols
    w, tau, E1 = y["omega"], y["tau"], y["E_1"]
    expected = E1 * sp.I * w * tau / (1 + sp.I * w * tau)
    # ladder: ==, then cancel of the difference
    assert law.branch_modulus == expected or sp.cancel(law.branch_modulus - expected) == 0
    sls = StandardLinearSolid(3.0, 1.0, 0.2)
    for wv in (0.3, 5.0, 40.0):
        got = complex(law.sls_modulus.subs({y["E_0"]: 3, y["E_inf"]: 1, tau: sp.Rational(1, 5), w: wv}))
        assert abs(got - complex(sls.complex_modulus(wv))) < 1e-14 * abs(got)
    # the branch's steady response by mpmath quadrature at t = 0.7: eps S Im[E* exp(i w t)]
    tv, wv, tv_tau = 0.7, 3.0, 0.2
    with mpmath.workdps(25):
        quad = mpmath.quad(lambda u: 2.0 * mpmath.exp(-u / tv_tau) * wv * mpmath.cos(wv * (tv - u)), [0, mpmath.inf])
    Es = 2.0 * 1j * wv * tv_tau / (1 + 1j * wv * tv_tau)
    assert abs(float(quad) - (Es * np.exp(1j * wv * tv)).imag) < 1e-13
    resp = law.branch_response.subs({y["E_1"]: 2, tau: sp.Rational(1, 5), w: 3, y["t"]: sp.Rational(7, 10),
                                     y["epsilon"]: 1, y["S"]: 1})
    assert abs(float(resp) - float(quad)) < 1e-13


def test_thin_layer_closed_forms_against_the_any_thickness_law():
    law = oscillation_law()
    # (1.8): P0 = 2 pi mu R delta0^2 (1 - nu)/(H (1 - 2 nu)), mu = E/(2(1 + nu)) -> K* = d/d delta0 at mu = E*/(2(1+nu))
    y = law.symbols
    R, d0, H, nu, Es = y["R"], y["delta_0"], y["H"], y["nu"], sp.Symbol("E^*(omega)")
    by_hand = 2 * sp.pi * R * d0 * (1 - nu) / (H * (1 - 2 * nu)) * Es / (1 + nu)
    assert sp.cancel(law.thin_sphere - by_hand) == 0
    # (I.11): P = pi mu c^6/(32 H^3 R), delta0 = c^2/(4 R): P = 2 pi mu R^2 delta0^3/H^3, mu = E*/3
    assert sp.cancel(law.thin_sphere_incompressible - 2 * sp.pi * Es * R**2 * d0**2 / H**3) == 0
    # numbers: the layer's S on a thin incompressible layer approaches (I.11) (leading order: relative error O(H/c))
    cs = contact_stiffness(BondedLayer(0.5), Punch.paraboloid(10.0), 0.05, 0.1, model="any-thickness")
    val = float(law.thin_sphere_incompressible.subs({R: 10, d0: sp.Rational(1, 10), H: sp.Rational(1, 20), Es: 1}))
    assert abs(cs.stiffness / 3 / val - 1) < 0.1, (cs.stiffness, val)
    assert "E^{*" in law.latex() and "OscillationLaw" in str(law)


@pytest.mark.slow
def test_thin_compressible_closed_form_against_the_compressible_law():
    law = oscillation_law()
    y = law.symbols
    for H_ in (0.04, 0.02, 0.01):
        cs = contact_stiffness(BondedLayer(0.3), Punch.paraboloid(10.0), H_, 0.1)
        val = float(law.thin_sphere.subs({y["R"]: 10, y["delta_0"]: sp.Rational(1, 10), y["H"]: H_, y["nu"]: 0.3,
                                          sp.Symbol("E^*(omega)"): 1}))
        assert abs(cs.stiffness / 2.6 / val - 1) < 2 * H_ / math.sqrt(2.0), (H_, cs.stiffness / 2.6, val)


@pytest.mark.parametrize("layer,nu,d0", [
    (BondedLayer(0.5), 0.5, 0.13), (BondedLayer(0.5), 0.5, 0.1),
    pytest.param(FrictionlessLayer(0.3), 0.3, 0.1, marks=pytest.mark.slow),
    pytest.param(FrictionlessLayer(0.3), 0.3, 0.4, marks=pytest.mark.slow)])
def test_stiffness_is_the_flat_punch_stiffness_of_the_contact(layer, nu, d0):
    # dP/d delta of a smooth punch = the flat punch's stiffness at the same contact radius: 4 c kappa(c/H)/(1 - nu)
    # (d0 = 0.1: chi = 1, where the any-thickness law's slope jumps; the estimate must cover it)
    cs = contact_stiffness(layer, Punch.paraboloid(10.0), 1.0, d0)
    kappa = float(flat_punch_stiffness(layer, cs.contact_radius / 1.0))
    assert cs.stiffness == pytest.approx(4 * cs.contact_radius * kappa / (1 - nu), rel=cs.estimate)
    # the half-space (Hertz): 4 sqrt(R delta0)/(1 - nu); the layer is stiffer
    assert cs.half_space_stiffness == pytest.approx(4 * math.sqrt(10 * d0) / (1 - nu), rel=1e-15)
    assert cs.bottom_effect > 1


@pytest.mark.parametrize("layer,tip,nu,d0", [
    (BondedLayer(0.5), Punch.paraboloid(10.0), 0.5, 0.13),
    pytest.param(BondedLayer(0.3), Punch.flat(1.0), 0.3, 0.1, marks=pytest.mark.slow)])
def test_steady_state_of_a_long_sinusoidal_history_to_1e6(layer, tip, nu, d0):
    # hold at delta0 from t = 0, plus eps sin(w t): the hereditary integral (exact for piecewise-linear F) minus
    # the hold alone; the first harmonic over the last 4 periods against eps S E*(w)/(2(1 + nu)).  The sphere's
    # depth keeps chi = sqrt(R delta0)/H = 1.14 away from chi = 1, where the any-thickness law's slope jumps by
    # 2e-4 (within its estimate): there S is known to that estimate only
    H = 1.0
    m = StandardLinearSolid(3.0, 1.0, 0.1)
    eps, w = 1e-5 * d0, 10.0
    period = 2 * math.pi / w
    n_per = 4000
    t = np.linspace(0.0, 12 * period, 12 * n_per + 1)  # 7.5 s = 75 tau: the transient exp(-t/tau) is gone
    d = d0 + eps * np.sin(w * t)
    curve = force_curve_for(layer.with_nu(nu), tip, H, nu, 0.05, d)
    F = curve.force(d)
    Fh = np.full_like(t, curve.force(np.array([d0]))[0])
    dP = (hereditary_integral(m, t, F) - hereditary_integral(m, t, Fh)) / (2 * (1 + nu))
    last = slice(8 * n_per, 12 * n_per)  # four whole periods (the end point left out)
    tt = t[last]
    basis = np.stack([np.sin(w * tt), np.cos(w * tt), np.ones_like(tt), np.sin(2 * w * tt), np.cos(2 * w * tt)], 1)
    coef, *_ = np.linalg.lstsq(basis, dP[last], rcond=None)
    measured = complex(coef[0], coef[1]) / eps  # Im[K* e^{iwt}] = Re K* sin + Im K* cos
    osc = oscillation(layer, tip, H, m, d0, w, eps)
    assert osc.valid
    assert abs(measured / complex(osc.dynamic_stiffness[0]) - 1) < 1e-6
    assert osc.force_amplitude[0] == pytest.approx(abs(measured) * eps, rel=1e-6)
    assert osc.phase[0] == pytest.approx(math.atan2(coef[1], coef[0]), abs=1e-6)


def test_bottom_effect_correction_recovers_the_modulus():
    m = PowerLaw(2.0, 1.0, 0.2)
    osc = oscillation(BondedLayer(0.5), Punch.paraboloid(10.0), 0.5, m, 0.1, [0.1, 1.0, 10.0], 1e-3)
    cs = osc.stiffness
    back = cs.complex_modulus(osc.dynamic_stiffness)
    assert np.allclose(back, m.complex_modulus([0.1, 1.0, 10.0]), rtol=1e-14)
    naive = cs.half_space_complex_modulus(osc.dynamic_stiffness)
    assert np.allclose(naive / back, cs.bottom_effect, rtol=1e-14) and cs.bottom_effect > 5
    assert np.allclose(osc.phase, math.pi * 0.2 / 2)  # the power law's loss angle, any frequency
    assert osc.omega.flags.writeable is False and "omega" in osc.as_dict()


def test_large_amplitude_flagged_and_bad_input_refused():
    osc = oscillation(BondedLayer(0.5), Punch.paraboloid(10.0), 1.0, StandardLinearSolid(3.0, 1.0, 0.1), 0.1, 1.0,
                      0.1 * (MAX_RELATIVE_AMPLITUDE * 2))
    assert not osc.valid and "NOT VALID" in str(osc) and "NOT VALID" in osc.reason
    args = (BondedLayer(0.5), Punch.paraboloid(10.0), 1.0, StandardLinearSolid(3.0, 1.0, 0.1), 0.1)
    for bad in ([-1.0], [math.nan], "1"):
        with pytest.raises(InputError, match="omega"):
            oscillation(*args, bad, 1e-3)
    with pytest.raises(ThinlayerError, match="amplitude"):
        oscillation(*args, 1.0, -1e-3)
    with pytest.raises(ThinlayerError, match="delta0"):
        contact_stiffness(BondedLayer(0.5), Punch.paraboloid(10.0), 1.0, 0.0)


@pytest.mark.slow
def test_against_the_direct_solver_within_the_estimate():
    # the direct time-stepping solver moves the contact edge itself: the first harmonic of the last of 3 periods
    from thinlayer.numerics.viscoelastic import solve_history

    layer, tip, m = BondedLayer(0.5), Punch.paraboloid(10.0), StandardLinearSolid(3.0, 1.0, 0.1)
    d0, w, eps = 0.13, 10.0, 0.02 * 0.13
    period = 2 * math.pi / w
    t = np.concatenate([np.linspace(0, 1.0, 101), 1.0 + np.linspace(0, 3 * period, 601)[1:]])
    hold = np.where(t < 0.05, d0 * t / 0.05, d0)
    dP = (solve_history(layer, tip, 1.0, m, t, hold + np.where(t > 1.0, eps * np.sin(w * (t - 1.0)), 0.0),
                        nodes=200).force - solve_history(layer, tip, 1.0, m, t, hold, nodes=200).force)
    last = t > 1.0 + 2 * period + 1e-12
    tt = t[last] - 1.0
    basis = np.stack([np.sin(w * tt), np.cos(w * tt), np.ones_like(tt), np.sin(2 * w * tt), np.cos(2 * w * tt)], 1)
    coef, *_ = np.linalg.lstsq(basis, dP[last], rcond=None)
    osc = oscillation(layer, tip, 1.0, m, d0, w, eps)
    err = abs(complex(coef[0], coef[1]) / eps / complex(osc.dynamic_stiffness[0]) - 1)
    assert 0.005 < err <= osc.estimate, (err, osc.estimate)  # the edge's first-order effect shows, within the estimate
