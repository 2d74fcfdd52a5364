"""Tests of the leading contact area omega_0 and its contour Gamma_0 (3.1)-(3.14).

Every expected value comes from an independent route: closed forms for the ellipse and the
circle (derived in the comments), the complete elliptic integral (mpmath.ellipe), polar
quadrature with a root finder (scipy), the implicit-curve curvature formula differentiated by
sympy, the divergence and Gauss-Bonnet theorems.
"""
from __future__ import annotations

import dataclasses
import math
from types import SimpleNamespace

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad
from scipy.optimize import brentq

from thinlayer import symbols as S
from thinlayer.asymptotics._contour_region import Poly2 as _Poly2
from thinlayer.asymptotics._contour_region import as_polynomial as _as_polynomial
from thinlayer.asymptotics._contour_region import region_curve as _region_curve
from thinlayer.asymptotics._contour_spectral import nodes_by_ode as _nodes_by_ode
from thinlayer.asymptotics._contour_spectral import nodes_by_reference as _nodes_by_reference
from thinlayer.asymptotics.contour import (
    ContactContour,
    contact_contour,
    ellipse_contour,
)

x1, x2 = S.x1, S.x2


def elliptic(R1, R2):
    return x1**2 / (2 * R1) + x2**2 / (2 * R2)  # (1.1)


def implicit(Phi):
    """Numeric Phi, grad, Hessian and the implicit-curve curvature, from sympy derivatives."""
    fx, fy = sp.diff(Phi, x1), sp.diff(Phi, x2)
    fxx, fxy, fyy = sp.diff(Phi, x1, 2), sp.diff(Phi, x1, x2), sp.diff(Phi, x2, 2)
    # curvature of {Phi = c}, CCW around {Phi < c}: (Phi_yy Phi_x^2 - 2 Phi_xy Phi_x Phi_y + Phi_xx Phi_y^2)/|grad|^3
    kappa = (fyy * fx**2 - 2 * fxy * fx * fy + fxx * fy**2) / (fx**2 + fy**2) ** sp.Rational(3, 2)
    lam = sp.lambdify((x1, x2), [Phi, fx, fy, fxx, fxy, fyy, kappa, sp.diff(Phi, x1, 2) + sp.diff(Phi, x2, 2)])
    return lambda a, b: [np.asarray(v, dtype=float) * np.ones(np.shape(a)) for v in lam(a, b)]


# --------------------------------------------------------------------------------------------
# elliptic paraboloid (1.1), (3.1)
# --------------------------------------------------------------------------------------------
ELLIPSES = [(4.0, 1.0, 0.5), (10.0, 3.0, 0.02), (2.5, 2.5, 0.3)]


@pytest.fixture(scope="module", params=ELLIPSES, ids=lambda p: f"R1={p[0]},R2={p[1]},d0={p[2]}")
def ellipse(request):
    R1, R2, d0 = request.param
    return R1, R2, d0, contact_contour(elliptic(R1, R2), d0)


def test_ellipse_perimeter_area_against_closed_forms(ellipse):
    R1, R2, d0, c = ellipse
    # (3.1): x1^2/(2 R1) + x2^2/(2 R2) = d0  <=>  x1^2/a^2 + x2^2/b^2 = 1, a^2 = 2 d0 R1, b^2 = 2 d0 R2
    a, b = math.sqrt(2 * d0 * R1), math.sqrt(2 * d0 * R2)
    e2 = 1 - R2 / R1  # (3.1)
    assert c.perimeter == pytest.approx(float(4 * a * mpmath.ellipe(e2)), rel=1e-12)
    assert c.area == pytest.approx(math.pi * a * b, rel=1e-12)
    assert c.centroid == pytest.approx((0.0, 0.0), abs=1e-12 * a)
    s = np.linspace(0, c.perimeter, 4001)
    p = c.f(s)
    assert np.max(p[:, 0]) == pytest.approx(a, rel=1e-6)  # semi-axes (3.1), sampled
    assert np.max(p[:, 1]) == pytest.approx(b, rel=1e-6)
    np.testing.assert_allclose((p[:, 0] / a) ** 2 + (p[:, 1] / b) ** 2, 1.0, atol=1e-13)


def test_ellipse_curvature_radius_b1_b2_closed_forms(ellipse):
    R1, R2, d0, c = ellipse
    a, b = math.sqrt(2 * d0 * R1), math.sqrt(2 * d0 * R2)
    s = np.random.default_rng(1).uniform(0, c.perimeter, 500)
    p = c.f(s)
    X, Y = p[:, 0], p[:, 1]
    # curvature radius of x^2/a^2 + y^2/b^2 = 1 at (x, y): a^2 b^2 (x^2/a^4 + y^2/b^4)^(3/2)
    rho_exact = a**2 * b**2 * (X**2 / a**4 + Y**2 / b**4) ** 1.5
    np.testing.assert_allclose(c.rho(s), rho_exact, rtol=1e-9)  # after (3.6)
    # inward normal (3.3) of the ellipse: -grad Phi / |grad Phi|, grad Phi = (x/R1, y/R2)
    gx, gy = X / R1, Y / R2
    g = np.hypot(gx, gy)
    np.testing.assert_allclose(c.normal(s), -np.column_stack([gx, gy]) / g[:, None], atol=1e-11)
    np.testing.assert_allclose(c.g(s), g, rtol=1e-12)
    # (3.14), dimensional: b1 = -(f1 n1/R1 + f2 n2/R2) = |grad Phi|, 2 b2 = -(n1^2/R1 + n2^2/R2)
    n1, n2 = -gx / g, -gy / g
    np.testing.assert_allclose(c.b1(s), -(X * n1 / R1 + Y * n2 / R2), rtol=1e-11)
    np.testing.assert_allclose(c.b2(s), -0.5 * (n1**2 / R1 + n2**2 / R2), rtol=1e-11)
    np.testing.assert_allclose(np.linalg.norm(c.tangent(s), axis=1), 1.0, atol=1e-11)


def test_ellipse_expansion_is_exact_for_a_quadratic_punch(ellipse):
    # (3.13): delta0 - Phi(f + n n0) = b1 n + b2 n^2, exactly when Phi is quadratic
    R1, R2, d0, c = ellipse
    s = np.linspace(0, c.perimeter, 37)
    for n in (-0.3, 0.01, 0.2):
        x = c.local_to_cartesian(s, n)  # (3.4)
        lhs = d0 - (x[:, 0] ** 2 / (2 * R1) + x[:, 1] ** 2 / (2 * R2))
        np.testing.assert_allclose(lhs, c.b1(s) * n + c.b2(s) * n**2, atol=1e-12)


def test_ellipse_integrals(ellipse):
    R1, R2, d0, c = ellipse
    a, b = math.sqrt(2 * d0 * R1), math.sqrt(2 * d0 * R2)
    assert c.integrate(lambda u, v: np.ones_like(u)) == pytest.approx(math.pi * a * b, rel=1e-12)
    # iint x1^2 = pi a^3 b / 4 (x1 = a r cos t, x2 = b r sin t)
    assert c.integrate(lambda u, v: u**2) == pytest.approx(math.pi * a**3 * b / 4, rel=1e-12)
    # iint sqrt(d0 - Phi) = a b sqrt(d0) 2 pi int_0^1 sqrt(1 - r^2) r dr = 2 pi a b sqrt(d0) / 3
    F = lambda u, v: np.sqrt(d0 - u**2 / (2 * R1) - v**2 / (2 * R2))
    assert c.integrate(F) == pytest.approx(2 * math.pi * a * b * math.sqrt(d0) / 3, rel=1e-10)
    # iint 1/sqrt(d0 - Phi) = 2 pi a b / sqrt(d0): integrable edge singularity
    G = lambda u, v: 1 / F(u, v)
    assert c.integrate(G) == pytest.approx(2 * math.pi * a * b / math.sqrt(d0), rel=1e-10)
    # oint ds = perimeter, oint x1^2 ds compared with an mpmath quadrature of the ellipse
    ref = mpmath.quad(lambda t: (a * mpmath.cos(t)) ** 2 * mpmath.sqrt((a * mpmath.sin(t)) ** 2
                                                                       + (b * mpmath.cos(t)) ** 2),
                      [0, mpmath.pi / 2, mpmath.pi, 3 * mpmath.pi / 2, 2 * mpmath.pi])
    assert c.boundary_integral(lambda u, v: u**2) == pytest.approx(float(ref), rel=1e-11)


def test_ellipse_orientation_and_periodicity(ellipse):
    c = ellipse[3]
    s = np.linspace(0, c.perimeter, 50)
    p, t = c.f(s), c.tangent(s)
    assert np.all(p[:, 0] * t[:, 1] - p[:, 1] * t[:, 0] > 0)  # counterclockwise about the centre
    np.testing.assert_allclose(c.f(s + c.perimeter), p, atol=1e-12)
    # the inward normal (3.3) points into omega_0
    assert np.all(c.contains(*(p + 1e-4 * c.normal(s)).T))
    assert not np.any(c.contains(*(p - 1e-4 * c.normal(s)).T))
    np.testing.assert_allclose(c.local_to_cartesian(s, 0.0), p)


def test_ellipse_contour_closed_form_symbolic():
    e = ellipse_contour()
    R1, R2 = sp.Symbol("R_1", positive=True), sp.Symbol("R_2", positive=True)
    # independent derivation: the x1-intercept of Phi = delta0
    a_sol = [r for r in sp.solve(sp.Eq(elliptic(R1, R2).subs(x2, 0), S.delta0), x1) if r.is_positive]
    assert len(a_sol) == 1 and sp.simplify(a_sol[0] - e.a) == 0
    b_sol = [r for r in sp.solve(sp.Eq(elliptic(R1, R2).subs(x1, 0), S.delta0), x2) if r.is_positive]
    assert sp.simplify(b_sol[0] - e.b) == 0
    assert sp.simplify(e.e2 - (1 - e.b**2 / e.a**2)) == 0  # e^2 = 1 - b^2/a^2 (3.1)
    assert sp.simplify(e.e2 - (1 - R2 / R1)) == 0
    assert r"\tag{3.1}" in e.latex()
    num = ellipse_contour(4, 1, sp.Rational(1, 2))
    assert num.a == 2 and num.b == 1 and num.e2 == sp.Rational(3, 4)
    assert float(num.perimeter) == pytest.approx(float(8 * mpmath.ellipe(0.75)), rel=1e-14)
    c = contact_contour(elliptic(4, 1), 0.5)
    assert c.perimeter == pytest.approx(float(num.perimeter), rel=1e-12)
    s = np.linspace(0, c.perimeter, 9)
    p = c.f(s)
    np.testing.assert_allclose(c.rho(s), [float(num.curvature_radius(u, v)) for u, v in p], rtol=1e-9)
    # R1 < R2: the major axis is along x2
    assert ellipse_contour(1, 4, 1).e2 == sp.Rational(3, 4)


def test_scaled_semi_axis_misprint_in_3_1():
    # (1.2): delta0 = eps delta0*, R_j = R_j*/eps; (2.8): x = H* xi.  The scaled semi-axis is
    # sqrt(2 delta0 R1)/H* = sqrt(2 delta0* R1*)/H*; printed (3.1) reads sqrt(2 delta0* R1)/H*.
    e = ellipse_contour()
    a_s, b_s = e.scaled_semi_axes()
    R1s, R2s = S.starred(e.R1), S.starred(e.R2)
    assert sp.simplify(a_s - sp.sqrt(2 * S.delta0_s * R1s) / S.H_s) == 0
    assert sp.simplify(b_s - sp.sqrt(2 * S.delta0_s * R2s) / S.H_s) == 0
    assert S.epsilon not in a_s.free_symbols
    printed = sp.sqrt(2 * S.delta0_s * e.R1) / S.H_s
    ratio = sp.simplify(printed.subs(e.R1, R1s / S.epsilon) / a_s)
    assert sp.simplify(ratio - 1 / sp.sqrt(S.epsilon)) == 0  # off by eps^(-1/2) unless R1 -> R1*
    # numerically, from the dimensional contour
    eps, Hs, d0s, R1v, R2v = 0.01, 1.3, 0.7, 2.0, 0.9
    c = contact_contour(elliptic(R1v / eps, R2v / eps), eps * d0s)
    xi = c.f(np.linspace(0, c.perimeter, 20001)) / Hs
    assert xi[:, 0].max() == pytest.approx(math.sqrt(2 * d0s * R1v) / Hs, rel=1e-7)


def test_b_coefficients_relation_to_starred_3_14():
    # dimensional b1 = eps H* b1*, b2 = eps b2*, with b_j* of (3.14) in the scaled variables (2.8)
    eps, Hs, d0s, R1s, R2s = 0.02, 0.8, 0.5, 1.7, 0.6
    c = contact_contour(elliptic(R1s / eps, R2s / eps), eps * d0s)
    s = np.linspace(0, c.perimeter, 41)
    f_s = c.f(s) / Hs  # f*(s*), s* = s/H*
    n1, n2 = c.normal(s).T  # unit vectors are not scaled
    b1s = -f_s[:, 0] * n1 / R1s - f_s[:, 1] * n2 / R2s  # (3.14)
    b2s = 0.5 * (-(n1**2) / R1s - n2**2 / R2s)  # (3.14)
    np.testing.assert_allclose(c.b1(s), eps * Hs * b1s, rtol=1e-11)
    np.testing.assert_allclose(c.b2(s), eps * b2s, rtol=1e-11)
    B1, B2 = c.b_star(s, eps, Hs)
    np.testing.assert_allclose(B1, b1s, rtol=1e-11)
    np.testing.assert_allclose(B2, b2s, rtol=1e-11)
    with pytest.raises(ValueError, match="epsilon"):
        c.b_star(s, 0.0, Hs)
    # (3.13) in scaled form with Phi* of (2.13): delta0* - Phi*(f* + n* n0) = H*^2 (b1* n* + b2* n*^2)
    for nst in (0.05, -0.1):
        xi = f_s + nst * np.column_stack([n1, n2])
        Phis = Hs**2 * (xi[:, 0] ** 2 / (2 * R1s) + xi[:, 1] ** 2 / (2 * R2s))  # (2.13)
        np.testing.assert_allclose(d0s - Phis, Hs**2 * (b1s * nst + b2s * nst**2), atol=1e-12)


@settings(max_examples=12, deadline=None)
@given(st.floats(0.5, 20.0), st.floats(1.0, 8.0), st.floats(1e-3, 2.0))
def test_ellipse_property(R2, ratio, d0):
    R1 = R2 * ratio
    c = contact_contour(elliptic(R1, R2), d0)
    a, b = math.sqrt(2 * d0 * R1), math.sqrt(2 * d0 * R2)
    assert c.perimeter == pytest.approx(float(4 * a * mpmath.ellipe(1 - R2 / R1)), rel=1e-10)  # (3.1)
    assert c.area == pytest.approx(math.pi * a * b, rel=1e-10)


def test_ode_route_agrees_with_reference_route():
    # the two independent constructions of the arc-length nodes (normal projection from a smooth
    # reference curve; integration of the unit tangent field) give the same curve
    P = _Poly2(_as_polynomial(elliptic(3, 1))[1])
    poly, _, _ = _region_curve(P, 0.4, "ellipse")
    Z1, L1 = _nodes_by_reference(P, 0.4, poly, 256, 1e-12)
    Z2, L2 = _nodes_by_ode(P, 0.4, poly, 256, 1e-12)
    a, b = math.sqrt(2 * 0.4 * 3), math.sqrt(2 * 0.4 * 1)
    ref = float(4 * a * mpmath.ellipe(1 - 1 / 3))
    assert L1 == pytest.approx(ref, rel=1e-12)
    assert L2 == pytest.approx(ref, rel=1e-10)
    for Z, L in ((Z1, L1), (Z2, L2)):
        np.testing.assert_allclose((Z.real / a) ** 2 + (Z.imag / b) ** 2, 1.0, atol=1e-13)
        # equal arc length: the ellipse's own arc-length integral between consecutive nodes
        t = np.unwrap(np.arctan2(Z.imag / b, Z.real / a))
        for j in range(0, 256, 37):
            arc = mpmath.quad(lambda u: mpmath.sqrt((a * mpmath.sin(u)) ** 2 + (b * mpmath.cos(u)) ** 2),
                              [t[j], t[j + 1]])
            assert float(arc) == pytest.approx(L / 256, rel=1e-9)


# --------------------------------------------------------------------------------------------
# paraboloid of revolution and fourth-degree paraboloid (section 5)
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("R, K, d0", [(10.0, 5.0, 0.3), (1.0, 2.0, 0.05), (2.0, None, 0.4)])
def test_fourth_degree_paraboloid_circle(R, K, d0):
    q = x1**2 + x2**2
    Phi = q / (2 * R) + (q**2 / K**3 if K else 0)
    c = contact_contour(Phi, d0)
    # r^2/(2R) + r^4/K^3 = d0: r^2 = K^3/2 (-1/(2R) + sqrt(1/(4R^2) + 4 d0/K^3)); r^2 = 2 R d0 if no K
    r2 = K**3 / 2 * (-1 / (2 * R) + math.sqrt(1 / (4 * R**2) + 4 * d0 / K**3)) if K else 2 * R * d0
    r = math.sqrt(r2)
    k3 = K**3 if K else math.inf
    assert c.perimeter == pytest.approx(2 * math.pi * r, rel=1e-12)
    assert c.area == pytest.approx(math.pi * r2, rel=1e-12)
    s = np.linspace(0, c.perimeter, 64, endpoint=False)
    np.testing.assert_allclose(np.linalg.norm(c.f(s), axis=1), r, rtol=1e-12)
    np.testing.assert_allclose(c.rho(s), r, rtol=1e-9)
    # Phi(r) radial: g = Phi'(r) = r/R + 4 r^3/K^3; b2 = -Phi''(r)/2 = -(1/R + 12 r^2/K^3)/2
    np.testing.assert_allclose(c.g(s), r / R + 4 * r**3 / k3, rtol=1e-12)
    np.testing.assert_allclose(c.b1(s), r / R + 4 * r**3 / k3, rtol=1e-11)
    np.testing.assert_allclose(c.b2(s), -0.5 * (1 / R + 12 * r2 / k3), rtol=1e-11)
    # iint (d0 - Phi) = 2 pi (d0 r^2/2 - r^4/(8R) - r^6/(6K^3))
    Phin = sp.lambdify((x1, x2), Phi)
    val = c.integrate(lambda u, v: d0 - Phin(u, v))
    assert val == pytest.approx(2 * math.pi * (d0 * r2 / 2 - r2**2 / (8 * R) - r2**3 / (6 * k3)), rel=1e-11)


def test_shifted_tilted_ellipse_centroid_and_minimum():
    # (x1-3)^2 + (x2+1)^2/4 + 1/2 = 7/10: semi-axes sqrt(1/5), sqrt(4/5), centre (3, -1)
    Phi = (x1 - 3) ** 2 + (x2 + 1) ** 2 / 4 + sp.Rational(1, 2)
    c = contact_contour(Phi, sp.Rational(7, 10))
    assert c.centroid == pytest.approx((3.0, -1.0), abs=1e-12)
    assert c.area == pytest.approx(math.pi * math.sqrt(0.2 * 0.8), rel=1e-12)
    assert c.min_point == pytest.approx((3.0, -1.0), abs=1e-9)
    assert c.min_value == pytest.approx(0.5, abs=1e-14)
    a, b = math.sqrt(0.8), math.sqrt(0.2)  # major axis along x2
    assert c.perimeter == pytest.approx(float(4 * a * mpmath.ellipe(1 - b * b / (a * a))), rel=1e-12)
    assert c.integrate(lambda u, v: u) == pytest.approx(3.0 * c.area, rel=1e-12)
    assert c.is_star_shaped


# --------------------------------------------------------------------------------------------
# a non-symmetric polynomial punch
# --------------------------------------------------------------------------------------------
NONSYM = x1**2 / 2 + x2**2 + sp.Rational(3, 10) * x1**3 + sp.Rational(1, 5) * x1 * x2 + x1**4 + x2**4


@pytest.fixture(scope="module", params=[0.05, 0.6])
def nonsym(request):
    return request.param, contact_contour(NONSYM, request.param)


def _polar_reference(d0):
    """Area, perimeter and centroid by polar quadrature about the minimum (scipy quad + brentq)."""
    phi = sp.lambdify((x1, x2), NONSYM, "math")
    grad = sp.lambdify((x1, x2), [sp.diff(NONSYM, x1), sp.diff(NONSYM, x2)], "math")

    def r_of(t):
        return brentq(lambda r: phi(r * math.cos(t), r * math.sin(t)) - d0, 0.0, 10.0, xtol=1e-15)

    def rp_of(t):  # implicit differentiation: dr/dt = -Phi_t/Phi_r
        r = r_of(t)
        fx, fy = grad(r * math.cos(t), r * math.sin(t))
        phi_r = math.cos(t) * fx + math.sin(t) * fy
        phi_t = -r * math.sin(t) * fx + r * math.cos(t) * fy
        return r, -phi_t / phi_r

    kw = {"limit": 200, "epsabs": 1e-14, "epsrel": 1e-13}
    area = quad(lambda t: 0.5 * r_of(t) ** 2, 0, 2 * math.pi, **kw)[0]
    per = quad(lambda t: math.hypot(*rp_of(t)), 0, 2 * math.pi, **kw)[0]
    mx = quad(lambda t: r_of(t) ** 3 * math.cos(t) / 3, 0, 2 * math.pi, **kw)[0]
    my = quad(lambda t: r_of(t) ** 3 * math.sin(t) / 3, 0, 2 * math.pi, **kw)[0]
    return area, per, (mx / area, my / area)


def test_nonsymmetric_against_polar_quadrature(nonsym):
    d0, c = nonsym
    area, per, cen = _polar_reference(d0)
    assert c.area == pytest.approx(area, rel=1e-11)
    assert c.perimeter == pytest.approx(per, rel=1e-11)
    assert c.centroid == pytest.approx(cen, abs=1e-11 * math.sqrt(area))
    assert c.integrate(lambda u, v: np.ones_like(u)) == pytest.approx(area, rel=1e-11)
    assert c.min_point == pytest.approx((0.0, 0.0), abs=1e-9)


def test_nonsymmetric_geometry_against_implicit_formulas(nonsym):
    d0, c = nonsym
    ev = implicit(NONSYM)
    s = np.random.default_rng(7).uniform(0, c.perimeter, 400)
    p = c.f(s)
    Phi, fx, fy, fxx, fxy, fyy, kappa, _ = ev(p[:, 0], p[:, 1])
    np.testing.assert_allclose(Phi, d0, atol=1e-14)  # on Gamma_0
    np.testing.assert_allclose(np.linalg.norm(c.tangent(s), axis=1), 1.0, atol=1e-10)  # natural param.
    np.testing.assert_allclose(c.curvature(s), kappa, rtol=1e-8, atol=1e-8 * np.abs(kappa).max())
    g = np.hypot(fx, fy)
    n = -np.column_stack([fx, fy]) / g[:, None]  # inward normal of {Phi < d0}
    np.testing.assert_allclose(c.normal(s), n, atol=1e-10)  # (3.3)
    np.testing.assert_allclose(c.b1(s), g, rtol=1e-10)  # b1 = -grad Phi . n0 = |grad Phi|
    np.testing.assert_allclose(c.b2(s), -0.5 * (fxx * n[:, 0] ** 2 + 2 * fxy * n[:, 0] * n[:, 1]
                                                 + fyy * n[:, 1] ** 2), rtol=1e-9)


def test_nonsymmetric_expansion_remainder_is_cubic(nonsym):
    # delta0 - Phi(f + n n0) - b1 n - b2 n^2 = O(n^3) (3.13)
    d0, c = nonsym
    Phin = sp.lambdify((x1, x2), NONSYM)
    s = np.linspace(0, c.perimeter, 50, endpoint=False)
    rem = []
    for n in (4e-3, 2e-3):
        x = c.local_to_cartesian(s, n)
        rem.append(np.max(np.abs(d0 - Phin(x[:, 0], x[:, 1]) - c.b1(s) * n - c.b2(s) * n**2)))
    assert 6.0 < rem[0] / rem[1] < 10.0  # halving n divides an n^3 remainder by 8


def test_nonsymmetric_integral_theorems(nonsym):
    c = nonsym[1]
    ev = implicit(NONSYM)
    # divergence theorem: iint Laplacian(Phi) = oint grad Phi . n_out ds = oint |grad Phi| ds
    lhs = c.integrate(lambda u, v: ev(u, v)[7])
    assert lhs == pytest.approx(c.boundary_integral(lambda u, v: np.hypot(*ev(u, v)[1:3])), rel=1e-11)
    assert lhs == pytest.approx(c.boundary_integral(c.g, of="s"), rel=1e-11)
    # Gauss-Bonnet with the implicit curvature: oint kappa ds = 2 pi
    assert c.boundary_integral(lambda u, v: ev(u, v)[6]) == pytest.approx(2 * math.pi, rel=1e-11)
    assert c.accuracy.turning_number == pytest.approx(1.0, abs=1e-9)


def test_contains_and_inward_normal(nonsym):
    c = nonsym[1]
    assert c.contains(*c.centroid)
    s = np.linspace(0, c.perimeter, 80)
    p, nn = c.f(s), c.normal(s)
    h = 1e-3 * math.sqrt(c.area)
    assert np.all(c.contains(p[:, 0] + h * nn[:, 0], p[:, 1] + h * nn[:, 1]))
    assert not np.any(c.contains(p[:, 0] - h * nn[:, 0], p[:, 1] - h * nn[:, 1]))
    assert c.contains(np.zeros((3, 4)), np.zeros((3, 4))).shape == (3, 4)
    assert c.f(np.zeros((2, 5))).shape == (2, 5, 2)


def test_non_star_shaped_region_green_quadrature():
    # a bent region: x2 in x1^2 -+ w(x1), w = sqrt(d0 - x1^4/10), |x1| < (10 d0)^(1/4)
    d0 = 0.3
    c = contact_contour((x2 - x1**2) ** 2 + x1**4 / 10, d0)
    assert not c.is_star_shaped
    X = (10 * d0) ** 0.25
    w = lambda t: mpmath.sqrt(d0 - t**4 / 10)
    area = float(mpmath.quad(lambda t: 2 * w(t), [-X, 0, X]))
    m2 = float(mpmath.quad(lambda t: 2 * w(t) * t**2, [-X, 0, X]))  # iint x2 = int 2 w x1^2
    assert c.area == pytest.approx(area, rel=1e-9)
    assert c.integrate(lambda u, v: np.ones_like(u)) == pytest.approx(area, rel=1e-9)
    assert c.integrate(lambda u, v: v) == pytest.approx(m2, rel=1e-9)
    assert c.centroid[1] == pytest.approx(m2 / area, rel=1e-9)


def test_accepts_punch_like_objects_and_strings():
    ref = contact_contour(elliptic(4, 1), 0.5)
    c1 = contact_contour(SimpleNamespace(expr=elliptic(4, 1)), 0.5)
    c2 = contact_contour("x_1**2/8 + x_2**2/2", sp.Rational(1, 2))
    plain = sp.Symbol("x_1") ** 2 / 8 + sp.Symbol("x_2") ** 2 / 2  # same names, no assumptions
    c3 = contact_contour(plain, 0.5)
    for c in (c1, c2, c3):
        assert c.perimeter == pytest.approx(ref.perimeter, rel=1e-13)
    assert isinstance(ref, ContactContour)
    with pytest.raises(dataclasses.FrozenInstanceError):
        ref.delta0 = 1.0
    assert "x_{1}" in ref.latex() and r"\Gamma_0" in ref.latex()


def test_fixed_n_reports_accuracy():
    c = contact_contour(elliptic(4, 1), 0.5, n=32)
    assert len(c.nodes) == 32
    assert c.accuracy.speed_error > 1e-8  # too few nodes for this ellipse, and it says so
    fine = contact_contour(elliptic(4, 1), 0.5)
    assert fine.accuracy.speed_error < 1e-10 and fine.accuracy.level_distance < 1e-13


# --------------------------------------------------------------------------------------------
# errors
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("d0", [0, -0.1, float("nan"), float("inf")])
def test_bad_delta0(d0):
    with pytest.raises(ValueError, match="delta0"):
        contact_contour(elliptic(1, 1), d0)


def test_bad_delta0_types():
    with pytest.raises(TypeError, match="delta0"):
        contact_contour(elliptic(1, 1), True)
    with pytest.raises(TypeError, match="delta0"):
        contact_contour(elliptic(1, 1), "deep")
    with pytest.raises(ValueError, match="delta_0"):
        contact_contour(elliptic(1, 1), S.delta0)


def test_bad_phi():
    R = sp.Symbol("R_1", positive=True)
    with pytest.raises(ValueError, match="R_1"):
        contact_contour(elliptic(R, 1), 0.1)
    with pytest.raises(ValueError, match="not a polynomial"):
        contact_contour(sp.cos(x1) + x2**2, 0.1)
    with pytest.raises(ValueError, match="not a polynomial"):
        contact_contour(x1**2 + x2**2 + 1 / (1 + x1**2), 0.1)
    y1 = sp.Symbol("x1")
    with pytest.raises(ValueError, match="x_1, x_2"):
        contact_contour(y1**2 + x2**2, 0.1)
    with pytest.raises(ValueError, match="n "):
        contact_contour(elliptic(1, 1), 0.1, n=31)


def test_no_contact_names_the_minimum():
    with pytest.raises(ValueError, match=r"min Phi = 1\b"):
        contact_contour(x1**2 + x2**2 + 1, 0.5)
    with pytest.raises(ValueError, match=r"min Phi = 0\.25"):
        contact_contour((x1 - 1) ** 2 + (x2 + 2) ** 2 + sp.Rational(1, 4), 0.25)


@pytest.mark.parametrize("Phi", [x1**2 - x2**2, x1**2, x1 + x2, x1**3 + x2**2], ids=str)
def test_unbounded(Phi):
    with pytest.raises(ValueError, match="unbounded"):
        contact_contour(Phi, 0.1)


def test_double_well_two_components():
    Phi = (x1**2 - 1) ** 2 + x2**2  # minima at (+-1, 0), saddle value 1 at the origin
    with pytest.raises(ValueError, match="2 components"):
        contact_contour(Phi, 0.5)
    with pytest.raises(ValueError, match="components"):
        contact_contour(Phi, 1e-6)  # two tiny regions, far apart relative to their size
    with pytest.raises(ValueError, match="not smooth"):
        contact_contour(Phi, 1)  # the figure eight through the saddle
    c = contact_contour(Phi, 1.5)  # one peanut-shaped region above the saddle
    assert c.contains(0.0, 0.0) and c.accuracy.turning_number == pytest.approx(1.0)


def test_annulus_has_a_hole():
    with pytest.raises(ValueError, match="hole"):
        contact_contour((x1**2 + x2**2 - 1) ** 2, 0.25)
    with pytest.raises(ValueError, match="hole"):
        contact_contour((x1**2 + x2**2 - 1) ** 2 + x1 / 10, 0.25)


def test_ellipse_contour_bad_input():
    with pytest.raises(ValueError, match="R1"):
        ellipse_contour(-1, 1, 1)
    with pytest.raises(ValueError, match="delta0"):
        ellipse_contour(1, 1, 0)
    with pytest.raises(TypeError, match="symbolic"):
        ellipse_contour(2, 1, 1).scaled_semi_axes()


def test_integrate_bad_input():
    c = contact_contour(elliptic(1, 1), 0.1)
    with pytest.raises(TypeError):
        c.integrate(3.0)
    with pytest.raises(ValueError, match="n_radial"):
        c.integrate(lambda u, v: u, n_radial=1)
    with pytest.raises(ValueError, match="of must be"):
        c.boundary_integral(lambda s: s, of="t")
