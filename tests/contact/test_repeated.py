"""Repeated solves (issue 18 item 2): what depends on (layer, punch) only is prepared once, and the force law
evaluates over arrays of depths.

The cached answers equal fresh ones (caches cleared), different layers and punches never share an entry, and
:func:`force_arrays` equals :func:`thinlayer.solve` point by point and the closed form of (1.8) for the sphere,
``P = pi vartheta R delta0^2/(A H) (1 - 2 m1 H^2/(R delta0))``, with ``A`` and ``m1`` from sympy's own series of
the kernel (2.3) (not the engine's coefficient code).  Times are in benchmarks/bench_repeated.py.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

import thinlayer as tl
from thinlayer.asymptotics import contour as contour_mod
from thinlayer.asymptotics import force_law as fl
from thinlayer.asymptotics import solution as solution_mod
from thinlayer.asymptotics.incompressible import leading as leading_mod
from thinlayer.asymptotics.incompressible import two_term as two_term_mod
from thinlayer.asymptotics.solution import force_arrays
from thinlayer.contact.models import two_term as two_term_model

SPHERE = tl.Punch.paraboloid(10)
ELLIPSE = tl.Punch.elliptic_paraboloid(40, 10)
QUARTIC = tl.Punch("x_1**2/2 + x_2**2 + x_1**3/5 + x_1*x_2/10 + x_1**4 + x_2**4")


def _clear():
    for f in (fl._force_law_cached, fl._compiled_closed_forms, fl._compiled_expr, two_term_model.edge_h,
              two_term_model.incompressible_ellipse_cached,
              contour_mod._polynomial_cached, contour_mod._gauss_legendre,
              solution_mod._array_law, leading_mod._ellipse_functions, two_term_mod._edge_shift_float):
        f.cache_clear()


@pytest.mark.parametrize("layer, punch, H, model", [
    (tl.BondedLayer(0.3), SPHERE, 0.02, "compressible"), (tl.BondedLayer(0.3), ELLIPSE, 0.02, "compressible"),
    (tl.FrictionlessLayer(0.3), SPHERE, 0.02, "compressible"), (tl.BondedLayer(0.45), SPHERE, 0.005, "two-term"),
    (tl.BondedLayer(0.5), SPHERE, 0.005, "incompressible"), (tl.BondedLayer(0.5), ELLIPSE, 0.005, "incompressible"),
    (tl.BondedLayer(0.3), QUARTIC, 0.01, "compressible"),
])
def test_cached_answers_equal_fresh_ones(layer, punch, H, model):
    runs = [(0.1, H, 1.0), (0.13, 1.3 * H, 2.5), (0.07, 0.8 * H, 0.4)]
    cached = [tl.solve(layer, punch, delta0=d, H=h, mu=m, model=model, tol=1.0) for d, h, m in runs]
    again = [tl.solve(layer, punch, delta0=d, H=h, mu=m, model=model, tol=1.0) for d, h, m in runs]
    fresh = []
    for d, h, m in runs:
        _clear()
        fresh.append(tl.solve(layer, punch, delta0=d, H=h, mu=m, model=model, tol=1.0))
    for a, b, c in zip(cached, again, fresh):
        for key in ("force", "contact_area", "delta0"):
            assert getattr(a, key) == getattr(b, key) == pytest.approx(getattr(c, key), rel=1e-15, abs=0)
        assert a.error_estimate == pytest.approx(c.error_estimate, rel=1e-14)
        assert a.max_pressure == pytest.approx(c.max_pressure, rel=1e-12)


def test_layers_and_punches_never_share_a_cache_entry():
    f = [tl.solve(layer, punch, delta0=0.1, H=0.02, mu=1.0, model="compressible").force
         for layer in (tl.BondedLayer(0.3), tl.FrictionlessLayer(0.3), tl.BondedLayer("3/10"), tl.BondedLayer(0.31))
         for punch in (tl.Punch.paraboloid(10), tl.Punch.paraboloid(11))]
    assert f[0] == pytest.approx(f[4], rel=1e-14)  # 0.3 and 3/10 are the same layer
    others = [f[k] for k in (0, 1, 2, 3, 6, 7)]
    assert len({round(v, 12) for v in others}) == len(others)
    R = tl.Punch("x_1**2/(2*R) + x_2**2/(2*R)")
    p10 = tl.solve(tl.BondedLayer(0.3), R, delta0=0.1, H=0.02, mu=1.0, parameters={"R": 10}).force
    p11 = tl.solve(tl.BondedLayer(0.3), R, delta0=0.1, H=0.02, mu=1.0, parameters={"R": 11}).force
    assert p10 == pytest.approx(f[0], rel=1e-14) and p11 == pytest.approx(f[1], rel=1e-14)


def test_cached_polynomial_terms_are_not_shared():
    expr, terms = contour_mod._polynomial(QUARTIC)
    terms.append((9, 9, 1.0))  # a caller's change of its list must not reach the next contour
    assert (9, 9, 1.0) not in contour_mod._polynomial(QUARTIC)[1]
    u, _ = contour_mod._gauss_legendre(8)
    with pytest.raises(ValueError):
        u[0] = 0.0


@pytest.mark.parametrize("nu", [0.3, 0.45, 0.49])
def test_two_term_scalar_evaluation_is_the_vectorised_law_to_the_last_bit(nu):
    """The scalar evaluate() of the repeated solves and the array form lambdify() of (I.11) give the same doubles."""
    model = two_term_mod.two_term_sphere(tl.BondedLayer(nu))
    f = model.lambdify()
    rng = np.random.default_rng(7)
    for d0, R, H, mu in zip(rng.uniform(0.01, 1, 40), rng.uniform(1, 20, 40), 10 ** rng.uniform(-3, 0, 40),
                            rng.uniform(0.5, 3, 40)):
        v = model.evaluate(float(d0), float(R), float(H), float(mu))
        depth, force = f(v.radius, float(R), float(H), float(mu))
        assert float(force) == v.force
        assert float(depth) == pytest.approx(d0, rel=1e-13)


def _A_m1(nu: float) -> tuple[float, float]:
    u = sp.Symbol("u")
    k = 3 - 4 * sp.nsimplify(nu)
    L = (2 * k * sp.sinh(2 * u) - 4 * u) / (2 * k * sp.cosh(2 * u) + 1 + k**2 + 4 * u**2)
    ser = sp.series(L / u, u, 0, 4).removeO()
    A = ser.coeff(u, 0)
    return float(A), float(ser.coeff(u, 2) / A)


@pytest.mark.parametrize("nu", [0.0, 0.3, 0.45])
def test_force_arrays_sphere_against_the_closed_form(nu):
    A, m1 = _A_m1(nu)
    R, H, mu = 10.0, 0.02, 1.3
    d = np.geomspace(0.02, 2.0, 200)
    out = force_arrays(tl.BondedLayer(nu), tl.Punch.paraboloid(R), d, H=H, mu=mu, tol=1.0)
    expected = math.pi * mu / (1 - nu) * R * d**2 / (A * H) * (1 - 2 * m1 * H**2 / (R * d))
    assert out.valid.all()
    np.testing.assert_allclose(out.force, expected, rtol=1e-12)


@pytest.mark.parametrize("layer, punch", [(tl.BondedLayer(0.3), SPHERE), (tl.BondedLayer(0.3), ELLIPSE),
                                          (tl.FrictionlessLayer(0.3), SPHERE),
                                          (tl.BondedLayer(0.45), tl.Punch("x_1**2/2 + x_2**2 + x_1/10 + 1/100"))])
def test_force_arrays_equal_solve_and_flag_what_solve_refuses(layer, punch):
    rng = np.random.default_rng(1)
    d = np.sort(rng.uniform(0.005, 1.0, 20))
    out = force_arrays(layer, punch, d, H=0.02, mu=1.3)
    for i, d0 in enumerate(d):
        try:
            ans = tl.solve(layer, punch, delta0=float(d0), H=0.02, mu=1.3, model="compressible")
        except ValueError:
            assert not out.valid[i] and math.isnan(out.force[i])
            continue
        assert out.valid[i]
        assert out.force[i] == pytest.approx(ans.force, rel=1e-12)
        assert out.contact_area[i] == pytest.approx(ans.contact_area, rel=1e-12)
        assert out.error_estimate["force"][i] == pytest.approx(ans.error_estimate["force"], rel=1e-12)


def test_force_arrays_never_return_an_unflagged_bad_force():
    d = np.array([-1.0, 0.0, 1e-12, 0.1, 1e200, np.inf, np.nan])
    out = force_arrays(tl.BondedLayer(0.3), SPHERE, d, H=0.02)
    ok = out.force[out.valid]
    assert np.all(np.isfinite(ok) & (ok > 0)) and out.valid.tolist() == [False, False, False, True, False, False,
                                                                          False]
    assert np.all(np.isnan(out.force[~out.valid]))
    with pytest.raises(ValueError, match="closed-form law"):
        force_arrays(tl.BondedLayer(0.3), tl.Punch("x_1**2 + x_2**4"), d, H=0.02)
