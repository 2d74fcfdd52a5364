"""The incompressible model (I.9a)-(I.9c) for tips of revolution (issue 24): cone, power law, exact sphere, blunted
cone.

Independent routes: the closed forms against scipy quadrature of the radial problem written out here from (I.3)-(I.4)
(``-(H^3/3 mu)(1/r)(r p')' = delta0 - Phi``, ``p = p' = 0`` at ``c``); the power law n = 2 against the paraboloid's
(I.9)/(I.11) solution; the pressure against the force (1.8); the model against the direct solver at nu = 1/2.
"""
from __future__ import annotations

import math

import pytest
import sympy as sp

import thinlayer as tl
from thinlayer import symbols as S
from thinlayer.asymptotics.incompressible import incompressible_axisymmetric, incompressible_tip


def _reference(phi, delta0: float, H: float, mu: float, c_hi: float, joins=()) -> tuple[float, float]:
    """(c, P) from (I.3)-(I.4) by scipy: F(c) = int_0^c (delta0 - Phi) s ds = 0 and P = 2 pi int_0^c p r dr with
    p(r) = (3 mu/H^3) int_r^c F(q)/q dq, the order of integration exchanged: P = pi (3 mu/H^3) int_0^c q F(q) dq --
    a double integral of F, not the engine's by-parts form (I.9c) int r^3 (Phi - delta0) dr; ``phi`` is the profile
    written out in the test, not the tip's."""
    from scipy import integrate, optimize

    def F(c):
        pts = [j for j in joins if j < c] or None
        return integrate.quad(lambda s: (delta0 - phi(s)) * s, 0, c, points=pts, epsabs=0, epsrel=1e-11)[0]

    a = optimize.brentq(lambda s: phi(s) - delta0, 0, c_hi)
    c = optimize.brentq(F, a, c_hi, xtol=1e-15)
    P = math.pi * 3 * mu / H**3 * integrate.quad(lambda q: q * F(q), 0, c, points=[j for j in joins if j < c] or None,
                                                 epsabs=0, epsrel=1e-12)[0]
    return c, P


def test_cone_closed_form_is_derived_and_equals_quadrature():
    sol = incompressible_tip(tl.Punch.cone())
    alpha = next(q for q in sol.tip.parameters if q.name == "alpha")
    # (I.9a): c = 3 delta0 tan(alpha)/2;  (I.9c): P = 243 pi mu tan^4(alpha) delta0^5/(640 H^3)  (ladder: ==, cancel);
    # the symbol alpha is the angle in degrees, so the expressions carry pi alpha/180
    rad = sp.pi * alpha / 180
    c_expected = 3 * S.delta0 * sp.tan(rad) / 2
    P_expected = 243 * sp.pi * S.mu * sp.tan(rad) ** 4 * S.delta0**5 / (640 * S.H**3)
    assert sol.radius == c_expected or sp.cancel(sol.radius - c_expected) == 0
    assert sol.force == P_expected or sp.cancel(sp.expand_trig(sol.force - P_expected)) == 0
    # numbers: the closed form, the engine's quadrature and an independent mpmath double integral
    t = math.tan(math.radians(70))
    c_ref, P_ref = _reference(lambda s: s / t, 0.5, 0.05, 1.3, 2 * t)
    v = incompressible_tip(tl.Punch.cone(70)).evaluate(0.5, 0.05, 1.3)
    assert v.radius == pytest.approx(1.5 * 0.5 * t, rel=1e-13) and c_ref == pytest.approx(v.radius, rel=1e-12)
    assert v.force == pytest.approx(P_ref, rel=1e-10)
    assert v.force == pytest.approx(243 * math.pi * 1.3 * t**4 * 0.5**5 / (640 * 0.05**3), rel=1e-12)


def test_power_law_two_is_the_paraboloid():
    # C r^2 with C = 1/(2R) is the paraboloid: (I.9a)-(I.9c) must give (I.9)/(I.11) (c^2 = 4 R delta0, P = 2 pi mu R^2
    # delta0^3/H^3), symbolically and in numbers
    R = 7.0
    v = incompressible_tip(tl.Punch.power_law(1 / (2 * R), 2)).evaluate(0.2, 0.1, 1.0)
    assert v.radius == pytest.approx(math.sqrt(4 * R * 0.2), rel=1e-12)
    assert v.force == pytest.approx(2 * math.pi * R**2 * 0.2**3 / 0.1**3, rel=1e-11)
    w = incompressible_axisymmetric(tl.Punch.paraboloid(R)).evaluate(0.2, 0.1, 1.0)
    assert v.force == pytest.approx(w.force, rel=1e-11) and v.radius == pytest.approx(w.radius, rel=1e-12)
    sol = incompressible_tip(tl.Punch.power_law())
    C, n = sorted(sol.tip.parameters, key=lambda q: q.name)
    c2 = sol.radius.subs({n: 2, C: 1 / (2 * sp.Symbol("R", positive=True))})
    assert sp.simplify(c2**2 - 4 * sp.Symbol("R", positive=True) * S.delta0) == 0


_CA, _SA = math.cos(math.radians(70)), math.sin(math.radians(70))
#: the profiles written out: exact sphere R = 10; blunted cone R = 1, 70 deg (cap to R cos(alpha), then the tangent
#: cone r cot(alpha) - R (1/sin(alpha) - 1)); power law 0.3 r^1.5
PROFILES = {
    "sphere": (lambda: tl.Punch.sphere(10), lambda s: 10 - math.sqrt(100 - s * s), 9.99, ()),
    "blunted": (lambda: tl.Punch.blunted_cone(1, 70),
                lambda s: 1 - math.sqrt(1 - s * s) if s <= _CA else s * _CA / _SA - (1 / _SA - 1), 10.0, (_CA,)),
    "power1.5": (lambda: tl.Punch.power_law(0.3, 1.5), lambda s: 0.3 * s**1.5, 10.0, ()),
}


@pytest.mark.parametrize("name", list(PROFILES))
def test_quadrature_tips_equal_the_double_integral_and_the_pressure_integrates_to_the_force(name):
    from scipy import integrate

    make, phi, c_hi, joins = PROFILES[name]
    d0, H, mu = 0.5, 0.05, 1.0
    v = incompressible_tip(make()).evaluate(d0, H, mu)
    c_ref, P_ref = _reference(phi, d0, H, mu, c_hi, joins)
    assert v.radius == pytest.approx(c_ref, rel=1e-10)
    assert v.force == pytest.approx(P_ref, rel=1e-9)
    P = 2 * math.pi * integrate.quad(lambda r: r * float(v.pressure(r)), 0, v.radius, limit=400)[0]
    assert P == pytest.approx(v.force, rel=1e-5)  # the pressure table (cumulative trapezoid, 4001 points)
    assert float(v.pressure(v.radius * 1.01)) == 0.0 and float(v.pressure(0.0)) > 0


def test_exact_sphere_equation_is_stated_without_a_closed_root():
    sol = incompressible_tip(tl.Punch.sphere())
    assert sol.radius is None and sol.force is None and sol.radius_equation is not None
    assert "I.9c" in sol.latex() and r"\int" in sol.latex()


def test_auto_chooses_the_incompressible_model_for_a_cone_at_nu_half_and_it_agrees_with_the_direct_solver():
    a = 0.5 * math.tan(math.radians(70))
    ans = tl.solve(tl.BondedLayer(0.5), tl.Punch.cone(70), delta0=0.5, H=a / 60, mu=1.0)
    assert ans.model == "incompressible" and ans.error_estimate["force"] <= 0.05
    ans = tl.solve(tl.BondedLayer(0.5), tl.Punch.cone(70), delta0=0.5, H=a / 10, mu=1.0, model="incompressible",
                   tol=1.0)
    cmp = ans.compare_direct()
    for key, value, direct, diff, est in cmp.rows:
        assert diff <= est + cmp.direct.error_estimate[key], f"{key}: {value} vs {direct}: {diff:.3g} > {est:.3g}"


def test_not_for_polynomials_or_non_axisymmetric_tips():
    with pytest.raises(TypeError):
        incompressible_tip(tl.Punch.paraboloid())
