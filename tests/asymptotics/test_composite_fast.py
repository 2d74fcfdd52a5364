"""Issue 18 item 4: the faster composite pressure (closed-form foot point for a quadratic punch, Newton with a
second-order start stopped point by point, the band cut where |Qhat - v| < 1e-11) against the previous algorithm.
"""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from scipy import optimize

from thinlayer import BondedLayer, Punch
from thinlayer import symbols as S
from thinlayer.asymptotics.composite import composite_pressure


def _previous(comp, x1, x2):
    """The previous evaluation: first-order start, 8 Newton steps on every point, correction on the whole table."""
    f, fx, fy = comp._phi(x1, x2)
    with np.errstate(divide="ignore", invalid="ignore"):
        gn = np.hypot(fx, fy)
        v_est = (comp.delta0 - f) / (gn * comp.H)
        ex, ey = fx / gn, fy / gn
        t = (comp.delta0 - f) / gn
        ok = np.isfinite(t)
        t = np.where(ok, t, 0.0)
        for _ in range(8):
            f2, gx, gy = comp._phi(x1 + t * ex, x2 + t * ey)
            t = t - (f2 - comp.delta0) / (gx * ex + gy * ey)
        g = np.hypot(gx, gy)
    v = np.where(ok & np.isfinite(t), t / comp.H, np.inf)
    zt, ct = comp._table
    full_band = comp.h + zt[-1] ** 2
    w = np.sqrt(np.clip(v - comp.h, 0.0, None)) / zt[1]
    i = np.minimum(w.astype(np.intp), len(zt) - 2)
    w -= i
    corr = np.where(v < full_band, ct[i] * (1 - w) + ct[i + 1] * w, 0.0)
    p_in = comp._p_in(x1, x2)
    near = (v_est < 1.25 * full_band + 1) & (v_est > min(comp.h, 0.0) - 1)
    p = np.where(v_est > 0, p_in, 0.0)
    p = np.where(near, np.where(v > comp.h, p_in + comp.amplitude * g * corr, 0.0), p)
    return np.maximum(p, 0.0), v, g


CASES = [
    ("ellipse exact", BondedLayer(0.3), Punch.elliptic_paraboloid(4, 1), 0.5, 0.05, "exact"),
    ("ellipse alexandrov", BondedLayer(0.3), Punch.elliptic_paraboloid(4, 1), 0.5, 0.05, "alexandrov"),
    ("quartic", BondedLayer(0.25), Punch(S.x1**2 / 2 + S.x2**2 + S.x1**3 / 5 + (S.x1**2 + S.x2**2) ** 2 / 4),
     0.3, 0.02, "exact"),
]


@pytest.mark.parametrize("name, layer, punch, delta0, H, bl", CASES, ids=[c[0] for c in CASES])
def test_same_pressure_as_the_previous_algorithm(name, layer, punch, delta0, H, bl):
    comp = composite_pressure(layer, punch, delta0, H, boundary_layer=bl)
    rng = np.random.default_rng(7)
    x1, x2 = rng.uniform(-2.2, 2.2, 200_000), rng.uniform(-1.2, 1.2, 200_000)
    new = comp(x1, x2)
    old, _, g = _previous(comp, x1, x2)
    assert np.array_equal(new > 0, old > 0)
    # what the band cut may change: amplitude * g * 1e-11 (the exact table's own noise is ~5e-12)
    tol = comp.amplitude * np.nan_to_num(g, nan=0.0, posinf=0.0) * 2e-11 + 1e-12 * np.abs(old)
    assert np.all(np.abs(new - old) <= tol)


def test_quadratic_closed_form_equals_newton():
    comp = composite_pressure(BondedLayer(0.3), Punch.elliptic_paraboloid(4, 1), 0.5, 0.05)
    assert comp._quadratic
    newton = dataclasses.replace(comp, _quadratic=False)
    rng = np.random.default_rng(8)
    x1, x2 = rng.uniform(-2.1, 2.1, 50_000), rng.uniform(-1.05, 1.05, 50_000)
    v1, g1 = comp.local(x1, x2)
    v2, g2 = newton.local(x1, x2)
    fin = np.isfinite(v2) & (np.abs(v2) < 2 * comp.band)
    assert np.allclose(v1[fin], v2[fin], rtol=1e-12, atol=1e-10)
    assert np.allclose(g1[fin], g2[fin], rtol=1e-11)
    assert np.array_equal(comp(x1, x2) > 0, newton(x1, x2) > 0)
    np.testing.assert_allclose(comp(x1, x2), newton(x1, x2), rtol=1e-11, atol=1e-11)


def test_newton_foot_point_against_root_finding():
    # a quartic punch: Newton from the second-order start, each point to its own tolerance; reference by brentq
    punch = Punch(S.x1**2 / 2 + S.x2**2 + S.x1**3 / 5 + (S.x1**2 + S.x2**2) ** 2 / 4)
    comp = composite_pressure(BondedLayer(0.25), punch, 0.3, 0.02)
    assert not comp._quadratic
    rng = np.random.default_rng(9)
    x1, x2 = rng.uniform(-0.6, 0.6, 40), rng.uniform(-0.4, 0.4, 40)
    v, g = comp.local(x1, x2)
    for a, b, vv, gg in zip(x1, x2, v, g):
        f, fx, fy = (float(q[0]) for q in comp._phi(np.array([a]), np.array([b])))
        n = np.hypot(fx, fy)
        e = np.array([fx, fy]) / n
        along = lambda t: float(comp._phi(np.array([a + t * e[0]]), np.array([b + t * e[1]]))[0][0]) - comp.delta0
        lo, hi = (0.0, 1.0) if f < comp.delta0 else (-1.0, 0.0)
        t = optimize.brentq(along, lo, hi, xtol=1e-15)
        assert vv == pytest.approx(t / comp.H, abs=1e-9)
        _, gx, gy = (float(q[0]) for q in comp._phi(np.array([a + t * e[0]]), np.array([b + t * e[1]])))
        assert gg == pytest.approx(np.hypot(gx, gy), rel=1e-10)


def test_beyond_the_band_the_composite_is_the_inner_pressure():
    comp = composite_pressure(BondedLayer(0.3), Punch.elliptic_paraboloid(4, 1), 0.5, 0.05)
    zt, ct = comp._table
    assert comp.band < comp.h + zt[-1] ** 2  # cut where |Qhat - v| < 1e-11
    vt = comp.h + zt**2
    assert np.all(np.abs(ct[vt >= comp.band]) < 1e-11)
    x1 = np.linspace(0.025, 1.5, 60)  # on the major axis: v = (2 - x1)/H, from 10 to 39.5
    v, _ = comp.local(x1, 0 * x1)
    np.testing.assert_allclose(v, (2 - x1) / 0.05, rtol=1e-12)
    inside = v >= comp.band
    assert inside.any() and not inside.all()
    np.testing.assert_array_equal(comp(x1, 0 * x1)[inside], comp._p_in(x1, 0 * x1)[inside])
