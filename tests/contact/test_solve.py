"""The front door :func:`thinlayer.solve` (issue 13): arguments, models, inverse problems, refusals.

The agreement with the direct solver over the acceptance grid is in ``tests/test_solve_acceptance.py``; here
the independent references are closed forms: the compressible sphere's leading force
``pi vartheta R delta0^2/(A H)`` (1.8) and the incompressible sphere's ``2 pi mu R^2 delta0^3/H^3`` (I.11).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import thinlayer as tl
from thinlayer.asymptotics.solution import ValidityError

SPHERE = tl.Punch.paraboloid(10)
ELLIPSE = tl.Punch.elliptic_paraboloid(40, 10)


def test_E_and_mu_are_the_same_modulus():
    a = tl.solve(tl.BondedLayer(0.3), SPHERE, delta0=0.1, H=0.05, E=2.6)
    b = tl.solve(tl.BondedLayer(0.3), SPHERE, delta0=0.1, H=0.05, mu=1.0)
    assert a.force == b.force and a.mu == 1.0 and a.E == pytest.approx(2.6, rel=1e-15)
    # the leading term (1.8) for the sphere: pi vartheta R delta0^2/(A H), A = (1/2 - nu)/(1 - nu)^2
    P0 = math.pi / 0.7 * 10 * 0.01 / (0.2 / 0.49 * 0.05)
    assert a.force == pytest.approx(P0, rel=2e-3)


@pytest.mark.parametrize("kw", [{}, {"mu": 1.0, "E": 2.0}])
def test_exactly_one_elastic_modulus(kw):
    with pytest.raises(TypeError, match="exactly one of mu= .* or E="):
        tl.solve(tl.BondedLayer(0.3), SPHERE, delta0=0.1, H=0.05, **kw)


def test_every_poisson_ratio_up_to_one_half_and_both_bases():
    for layer, kw in [(tl.BondedLayer(0), {}), (tl.BondedLayer("1/2"), {}), (tl.IncompressibleLayer(), {}),
                      (tl.FrictionlessLayer(0.3), {}), (tl.FrictionlessLayer(), {"nu": 0.3}),
                      (tl.FrictionlessLayer(0.5), {})]:
        ans = tl.solve(layer, SPHERE, delta0=0.1, H=0.05, mu=1.0, **kw)
        assert ans.force > 0 and ans.contact_radius > 0
        assert ans.model in ("compressible", "incompressible", "any-thickness")
    with pytest.raises(ValueError, match="disagrees"):
        tl.solve(tl.FrictionlessLayer(0.3), SPHERE, delta0=0.1, H=0.05, mu=1.0, nu=0.4)
    with pytest.raises(ValueError, match="symbolic"):
        tl.solve(tl.BondedLayer(), SPHERE, delta0=0.1, H=0.05, mu=1.0)


def test_incompressible_sphere_closed_form():
    ans = tl.solve(tl.BondedLayer(0.5), SPHERE, delta0=0.1, H=0.01, mu=1.3)
    assert ans.model == "incompressible"
    assert ans.force == pytest.approx(2 * math.pi * 1.3 * 100 * 0.1**3 / 0.01**3, rel=1e-12)
    h = 1.4590811364  # (I.12) at nu = 1/2
    assert ans.contact_radius == pytest.approx(2.0 - h * 0.01, rel=1e-9)
    assert ans.error_estimate["force"] == pytest.approx(2 * h * 0.01 / 2.0, rel=1e-8)


@pytest.mark.parametrize(("layer", "punch", "H", "model"), [
    (tl.BondedLayer(0.3), SPHERE, 0.07, "compressible"),
    (tl.BondedLayer(0.3), ELLIPSE, 0.14, "compressible"),
    (tl.BondedLayer(0.499), SPHERE, 0.02, "two-term"),
    (tl.BondedLayer(0.5), SPHERE, 0.01, "incompressible"),
    (tl.BondedLayer(0.5), ELLIPSE, 0.02, "incompressible"),
    (tl.BondedLayer(0.49), SPHERE, 0.28, "direct"),
    (tl.BondedLayer(0.49), ELLIPSE, 0.7, "direct"),
])
def test_the_inverse_problem_returns_the_depth(layer, punch, H, model):
    fwd = tl.solve(layer, punch, delta0=0.1, H=H, mu=1.0, model=model, tol=0.2)
    back = tl.solve(layer, punch, force=fwd.force, H=H, mu=1.0, model=model, tol=0.2)
    assert fwd.model == back.model == model
    assert back.delta0 == pytest.approx(0.1, rel=1e-9) and back.force == pytest.approx(fwd.force, rel=1e-9)


def test_asymptotic_refuses_naming_every_model():
    with pytest.raises(ValidityError) as err:
        tl.solve(tl.BondedLayer(0.49), SPHERE, delta0=0.1, H=0.5, mu=1.0, model="asymptotic")
    msg = str(err.value)
    assert "\n" not in msg and all(m in msg for m in ("compressible:", "two-term:", "incompressible:"))
    with pytest.raises(ValidityError, match="does not apply: the two-term model is derived for the sphere"):
        tl.solve(tl.BondedLayer(0.49), ELLIPSE, delta0=0.1, H=0.05, mu=1.0, model="two-term")
    with pytest.raises(ValidityError, match="exceed tol"):
        tl.solve(tl.BondedLayer(0.5), SPHERE, delta0=0.1, H=0.1, mu=1.0, model="incompressible")


def test_auto_says_which_model_and_why():
    ans = tl.solve(tl.BondedLayer(0.49), SPHERE, delta0=0.1, H=0.28, mu=1.0)
    assert ans.model == "any-thickness" and "any-thickness: any-thickness law for the sphere" in ans.reason
    assert ans.reason.startswith("compressible: the asymptotic force")
    assert "compressible: compressible" not in ans.reason
    text = str(ans)
    assert "any-thickness model" in text and "force" in text and "contact radius" in text
    assert set(ans.as_dict()) >= {"model", "reason", "force", "contact_radius", "max_pressure", "error_estimate"}
    # an axisymmetric quartic beyond the thick-layer series' range: the law does not cover it, the direct solver does
    quartic = tl.Punch("x_1**4 + 2*x_1**2*x_2**2 + x_2**4")
    ans = tl.solve(tl.BondedLayer(0.3), quartic, delta0=0.5, H=0.5, mu=1.0)
    assert ans.model == "direct" and "any-thickness: the thick-layer expansion needs" in ans.reason


def test_pressure_is_vectorised_and_zero_outside():
    for H, model in ((0.05, "compressible"), (0.01, "incompressible"), (0.3, "direct")):
        ans = tl.solve(tl.BondedLayer(0.5 if model == "incompressible" else 0.3), SPHERE, delta0=0.1, H=H,
                       mu=1.0, model=model, tol=0.5)
        x = np.linspace(-3, 3, 7)[:, None] * np.ones((1, 5))
        p = ans.pressure(x, 0.0 * x)
        assert p.shape == (7, 5) and np.all(p >= 0) and np.all(p[np.abs(x) > 1.2 * ans.contact_radius] == 0)
        assert ans.max_pressure >= float(ans.pressure(0.0, 0.0)) > 0


def test_2d_direct_refuses_a_grid_beyond_the_limit():
    with pytest.raises(ValidityError, match="cells to resolve H"):
        tl.solve(tl.BondedLayer(0.3), ELLIPSE, delta0=0.1, H=0.001, mu=1.0, model="direct")


def test_half_width_is_twice_area_over_perimeter_for_elongated_contacts():
    # H/a uses a = 2|omega|/|Gamma| (the paper's scale), not the radius of the equal-area disc
    import mpmath

    for layer, H, model in ((tl.BondedLayer(0.3), 0.02, "compressible"), (tl.BondedLayer(0.5), 0.01, "incompressible")):
        ans = tl.solve(layer, tl.Punch.elliptic_paraboloid(40, 2.5), delta0=0.01, H=H, mu=1.0, model=model, tol=1.0)
        a, b = ans.semi_axes
        perimeter = mpmath.quad(lambda t: mpmath.sqrt((a * mpmath.sin(t)) ** 2 + (b * mpmath.cos(t)) ** 2),
                                [0, mpmath.pi / 2]) * 4
        expected = float(mpmath.pi * a * b * 2 / perimeter)
        if model == "compressible":  # the scale of the expansion: the rigid overlap {Phi < delta0} (omega_0, Gamma_0)
            c = tl.contact_contour(ans.punch.expr, 0.01)
            expected = 2 * c.area / c.perimeter
        assert ans.half_width == pytest.approx(expected, rel=1e-9)
        assert ans.half_width < 0.9 * math.sqrt(ans.contact_area / math.pi)  # axes 4:1: ratio 0.84
