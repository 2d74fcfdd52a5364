"""The viscoelastic front door (issue 27 item 4): ``solve(..., material=..., history=...)`` through the registry.

Independent references: mpmath quadrature of Lee-Radok's integral over the public elastic law
(:func:`thinlayer.force_any_thickness`, the sphere at any thickness (T.7)); the creep compliances of the standard
linear solid ``J(t) = 1/E_inf - (1/E_inf - 1/E0) exp(-t E_inf/(E0 tau))`` and of the power law
``J(t) = (t/t0)^alpha/(E0 Gamma(1 - alpha) Gamma(1 + alpha))`` (each checked here against its defining identity
``int_0^t E(t - s) dJ(s) = 1`` by mpmath quadrature).
"""
from __future__ import annotations

import json
import math

import mpmath
import numpy as np
import pytest

from thinlayer import BondedLayer, Punch, force_any_thickness, solve
from thinlayer.contact.hereditary import ViscoelasticForce, inverse_hereditary
from thinlayer.contact.materials import KelvinVoigt, PowerLaw, StandardLinearSolid
from thinlayer.errors import ThinlayerError

L, TIP, H = BondedLayer(0.5), Punch.paraboloid(10.0), 1.0
E0, EINF, TAU = 3.0, 1.0, 0.2
SLS = StandardLinearSolid(E0, EINF, TAU)


def _F(d):
    """The sphere's elastic force at unit shear modulus (T.7), by the public any-thickness law."""
    return force_any_thickness(np.asarray(d, dtype=float), 10.0, H, mu=1.0, nu=0.5)


def test_depth_history_against_quadrature_of_lee_radok():
    t = np.linspace(0.0, 1.5, 1501)
    d = 0.12 * np.minimum(t, 1.0)  # ramp-hold
    ans = solve(L, TIP, H=H, material=SLS, history=(t, d))
    assert isinstance(ans, ViscoelasticForce) and ans.valid.all() and ans.control == "depth"
    assert "lee-radok" in ans.reason and ans.model == "any-thickness"

    # by parts: int_0^t E(t - s) dF = E(0) F(t) + int_0^t E'(t - s) F(s) ds (F(0) = 0), Gauss-Legendre on pieces
    # split where the integrand's slope jumps (the hold at s = 1; chi = 1 at delta = 0.1, the law's branch point)
    x, w = np.polynomial.legendre.leggauss(60)
    for k in (300, 1000, 1500):
        tk = t[k]
        edges = sorted({0.0, min(tk, 0.1 / 0.12), min(tk, 1.0), tk})
        total = E0 * _F(d[k])
        for lo, hi in zip(edges[:-1], edges[1:]):
            s = 0.5 * (hi - lo) * x + 0.5 * (hi + lo)
            dEdu = -(E0 - EINF) / TAU * np.exp(-(tk - s) / TAU)
            total += 0.5 * (hi - lo) * np.sum(w * dEdu * _F(0.12 * np.minimum(s, 1.0)))
        assert ans.force[k] == pytest.approx(total / 3.0, rel=1e-5), k  # 2(1 + nu) = 3; O(h^2), h = 1e-3


def test_force_history_creep_against_the_creep_compliance():
    # a step force P0 from t = 0: F(delta(t)) = 2(1 + nu) P0 J(t)
    Jsls = lambda t: 1 / EINF - (1 / EINF - 1 / E0) * np.exp(-t * EINF / (E0 * TAU))  # noqa: E731
    with mpmath.workdps(20):  # the identity int_0^t E(t - s) dJ(s) = 1 (J(0) = 1/E0 a step)
        tv = 0.7
        val = SLS.relaxation(tv)[()] / E0 + mpmath.quad(
            lambda s: (EINF + (E0 - EINF) * mpmath.exp(-(tv - s) / TAU)) * (1 / EINF - 1 / E0) * EINF / (E0 * TAU)
            * mpmath.exp(-s * EINF / (E0 * TAU)), [0, tv])
        assert abs(val - 1) < 1e-15
    P0 = 5.0
    t = np.linspace(0.0, 1.0, 401)
    ans = solve(L, TIP, H=H, material=SLS, history=(t, np.full_like(t, P0)), control="force")
    assert ans.valid.all() and ans.control == "force"
    assert np.allclose(_F(ans.depths) / (3 * P0 * Jsls(t)), 1.0, rtol=2e-5, atol=0)  # O(h^2), h = 2.5e-3
    # round trip: the depths back through the depth door give the forces
    back = solve(L, TIP, H=H, material=SLS, history=(t, ans.depths))
    assert np.allclose(back.force, P0, rtol=1e-10)


def test_power_law_and_kelvin_voigt_creep():
    a = 0.3
    pl = PowerLaw(2.0, 1.0, a)
    with mpmath.workdps(20):  # int_0^t E(t - s) dJ(s) = 1 for J = t^a/(E0 Gamma(1-a) Gamma(1+a))
        tv, am = mpmath.mpf("0.8"), mpmath.mpf(a)
        c = am / (mpmath.gamma(1 - am) * mpmath.gamma(1 + am))  # E0 J'(s) = c s^(a-1); E(u) = E0 u^-a
        # split at tv/2; s = x^(1/a) on the first half, tv - s = y^(1/(1-a)) on the second: smooth integrands
        half = tv / 2
        val = c / am * mpmath.quad(lambda x: (tv - x ** (1 / am)) ** -am, [0, half**am]) \
            + c / (1 - am) * mpmath.quad(lambda y: (tv - y ** (1 / (1 - am))) ** (am - 1), [0, half ** (1 - am)])
        assert abs(val - 1) < 1e-12
    for N, tol in ((200, 2e-3), (400, 1e-3)):  # first order at the last node (the t^-a start)
        t = np.linspace(0.0, 2.0, N + 1)
        F = inverse_hereditary(pl, t, np.ones_like(t))
        assert abs(F[-1] / (2.0**a / (2.0 * math.gamma(1 - a) * math.gamma(1 + a))) - 1) < tol
    kv = KelvinVoigt(2.0, 0.5)
    t = np.linspace(0.0, 2.0, 401)
    F = inverse_hereditary(kv, t, np.ones_like(t))
    assert abs(F[-1] / ((1 - math.exp(-2.0 * 2 / 0.5)) / 2) - 1) < 1e-4


def test_shrinking_contact_ting_for_prony_else_flagged_never_a_number():
    t = np.linspace(0.0, 2.0, 401)
    d = 0.1 * np.minimum(t, 1.0) - 0.05 * np.maximum(t - 1.0, 0.0)  # approach, then retract
    shrinking = t > 1.0
    # a Prony series under a depth history: the registry's Ting row (T3)-(T5) (tested against the direct solver in
    # test_ting.py), the same numbers as ting_force
    from thinlayer.contact.ting import ting_force

    ans = solve(L, TIP, H=H, material=SLS, history=(t, d))
    ref = ting_force(L, TIP, H, SLS, t, d)
    assert "Ting (T3)-(T5)" in ans.reason and ans.valid.all() == ref.valid.all()
    assert np.array_equal(ans.force, ref.force, equal_nan=True) and np.isfinite(ans.force[shrinking]).any()
    # Lee-Radok for the same force while the contact grows
    assert np.allclose(ans.force[~shrinking], solve(L, TIP, H=H, material=SLS, history=(t[~shrinking],
                                                                                          d[~shrinking])).force)
    # a power law: no Ting here, so Lee-Radok flags the shrinking part
    ans = solve(L, TIP, H=H, material=PowerLaw(2.0, 1.0, 0.2), history=(t, d))
    assert ans.valid[~shrinking].all() and not ans.valid[shrinking].any()
    assert np.isnan(ans.force[shrinking]).all() and np.isfinite(ans.force[~shrinking]).all()
    assert "Ting" in ans.reason and "NOT VALID" in str(ans) and "NOT VALID" in repr(ans)
    out = json.loads(ans.to_json())
    assert out["force"][-1] is None and out["valid"][-1] is False
    # force control: a falling force shrinks the contact too
    P = np.concatenate([np.linspace(0, 5, 201), np.linspace(5, 2, 201)[1:]])
    ans = solve(L, TIP, H=H, material=SLS, history=(np.linspace(0.0, 2.0, 401), P), control="force")
    assert not ans.valid[-1] and np.isnan(ans.depths[-1]) and "shrinks" in ans.reason


def test_result_is_immutable_and_prints():
    t = np.linspace(0.0, 1.0, 11)
    ans = solve(L, TIP, H=H, material=SLS, history=(t, 0.1 * t))
    with pytest.raises(ValueError):
        ans.force[0] = 1.0
    with pytest.raises(AttributeError):
        ans.nu = 0.3
    assert r"E(t) = 1 + 2\,e^{-t/0.2}" in ans.latex()
    assert json.loads(ans.to_json())["control"] == "depth"


@pytest.mark.parametrize("kwargs,match", [
    (dict(material=SLS, history=([0.0, 1.0], [0.0, 0.1]), mu=1.0), "leave out mu"),
    (dict(material=SLS, history=([0.0, 1.0], [0.0, 0.1]), delta0=0.1), "leave out delta0"),
    (dict(material=SLS), "needs both"),
    (dict(material=SLS, history="0,1"), "pair"),
    (dict(material=SLS, history=([0.0, 1.0], [0.0, 0.1]), control="speed"), "control"),
    (dict(material="sls", history=([0.0, 1.0], [0.0, 0.1])), "material"),
    (dict(material=SLS, history=([0.0, 1.0], [0.0, -0.1]), control="force"), "forces must be >= 0"),
    (dict(material=SLS, history=([1.0, 0.0], [0.0, 0.1])), "increasing"),
])
def test_bad_input_one_line(kwargs, match):
    with pytest.raises(ThinlayerError, match=match) as exc:
        solve(L, TIP, H=H, **kwargs)
    assert "\n" not in str(exc.value)
    with pytest.raises(ThinlayerError, match="finite thickness"):
        solve(L, TIP, H=math.inf, material=SLS, history=([0.0, 1.0], [0.0, 0.1]))
