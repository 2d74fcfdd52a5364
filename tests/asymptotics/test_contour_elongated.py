"""Elongated contact contours (aspect ratio 1 to 1e30, coefficients 1e-70 to 1e30 in one punch) (3.1)-(3.14).

Every expected value comes from a route other than the engine's (round frame, Chebyshev panels for the
arc length):

* ellipses ``a x1^2 + b x2^2 < delta0``: area ``pi delta0/sqrt(a b)``, perimeter
  ``4 sqrt(delta0/a_min) E(1 - a_min/a_max)`` with the complete elliptic integral ``mpmath.ellipe`` at a
  working precision that holds ``1 - m`` (mpmath loses ``1 - m`` below about ``10^-dps/2``), checked
  against Carlson's ``2 R_G(0, 1 - m, 1)``;
* rotated ellipses: the eigenvalues of the float coefficients actually in Phi, in 60-digit arithmetic;
* quartics: graph (``x2 = +-Y(x1)``) or polar quadrature in scaled variables with mpmath (tanh-sinh,
  split at the tips, roots by ``mpmath.findroot``), from the float coefficients of Phi;
* geometry: the implicit-curve formulas of Phi (sympy derivatives), the ellipse's arc-length integral.
"""
from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy.optimize import brentq

import thinlayer as tl
from thinlayer import BondedLayer, Punch, contact_contour
from thinlayer import symbols as S
from thinlayer.asymptotics.force_law import force_law
from thinlayer.symbols import x1, x2


def _E(m1: float, digits: int) -> float:
    """E(m) for ``m = 1 - m1`` by mpmath.ellipe at a precision that represents ``1 - m1``; Carlson cross-check."""
    with mpmath.workdps(digits + 40):
        m1 = mpmath.mpf(m1)
        e = mpmath.ellipe(1 - m1)
        carlson = 2 * mpmath.elliprg(0, m1, 1)
        assert abs(e / carlson - 1) < mpmath.mpf(10) ** -30
        return float(e)


def _ellipse_reference(a: float, b: float, d0: float):
    amin, amax = min(a, b), max(a, b)
    digits = int(max(0.0, math.log10(amax / amin)))
    area = math.pi * d0 / math.sqrt(a * b)
    per = 4 * math.sqrt(d0 / amin) * _E(amin / amax, digits)
    return area, per


# --------------------------------------------------------------------------------------------
# ellipses (3.1), a/b from 1 to 1e60
# --------------------------------------------------------------------------------------------
ELLIPSES = [(1.0, 1.0, 1.0), (1.0, 10.0, 0.3), (1e-1, 1e1, 1.0), (1.0, 1e4, 2.0), (1e-4, 1e4, 1e-3),
            (1e8, 1.0, 1.0), (1e-6, 1e6, 1e6), (1e-10, 1e10, 1.0), (1e-30, 1e30, 1.0), (1e30, 1e-30, 1e-20),
            (1e-15, 1e25, 1e10), (1e-60, 1.0, 1.0), (1.0, 1e60, 1e-40), (1e-70, 1e-10, 1e-30)]


@pytest.mark.parametrize(("a", "b", "d0"), ELLIPSES, ids=lambda v: f"{v:g}")
def test_ellipse_area_and_perimeter(a, b, d0):
    """``a x1^2 + b x2^2 < d0``: area pi d0/sqrt(ab), perimeter 4 sqrt(d0/a_min) E(1 - a_min/a_max)."""
    c = contact_contour(sp.Float(a, 17) * x1**2 + sp.Float(b, 17) * x2**2, d0)
    area, per = _ellipse_reference(a, b, d0)
    assert abs(c.area / area - 1) < 1e-13, (c.area, area)
    assert abs(c.perimeter / per - 1) < 1e-13, (c.perimeter, per)
    assert c.centroid == pytest.approx((0.0, 0.0), abs=1e-13 * math.sqrt(d0 / min(a, b)))
    assert c.integrate(lambda u, v: np.ones_like(u)) == pytest.approx(area, rel=1e-13)
    assert c.boundary_integral(lambda u, v: np.ones_like(u)) == pytest.approx(per, rel=1e-13)


@pytest.mark.parametrize("theta", [0.3, math.pi / 4, 2.0])
@pytest.mark.parametrize("k", [2, 6, 10, 14])
def test_rotated_ellipse(theta, k):
    """Eigenvalues 1 and 10^k rotated by theta: exact for the float coefficients actually in Phi.

    The reference takes the three coefficients of Phi (doubles), forms ``Q = [[c20, c11/2], [c11/2, c02]]``
    and its eigenvalues in 60 digits: ``|omega_0| = pi d0/sqrt(det Q)``, perimeter
    ``4 sqrt(d0/lo) E(1 - lo/hi)``.  (The doubles differ from the intended ellipse by ~1e-16 10^k: the
    engine must give the contour of the punch as written.)
    """
    ct, st = math.cos(theta), math.sin(theta)
    lo_, hi_ = 1.0, 10.0**k
    Phi = (sp.Float(lo_ * ct * ct + hi_ * st * st, 17) * x1**2 + sp.Float(2 * (lo_ - hi_) * ct * st, 17) * x1 * x2
           + sp.Float(lo_ * st * st + hi_ * ct * ct, 17) * x2**2)
    d0 = 0.7
    c = contact_contour(Phi, d0)
    with mpmath.workdps(60):
        al, be, ga = (mpmath.mpf(float(Phi.coeff(x1, 2))), mpmath.mpf(float(Phi.coeff(x1, 1).coeff(x2, 1))),
                      mpmath.mpf(float(Phi.coeff(x2, 2))))
        det = al * ga - be * be / 4
        hi = (al + ga) / 2 + mpmath.sqrt(((al - ga) / 2) ** 2 + be * be / 4)
        lo = det / hi
        area = float(mpmath.pi * d0 / mpmath.sqrt(det))
        per = float(4 * mpmath.sqrt(d0 / lo) * 2 * mpmath.elliprg(0, lo / hi, 1))
    assert abs(c.area / area - 1) < 1e-13
    assert abs(c.perimeter / per - 1) < 1e-13
    assert c.integrate(lambda u, v: np.ones_like(u)) == pytest.approx(area, rel=1e-13)
    assert c.boundary_integral(lambda u, v: np.ones_like(u)) == pytest.approx(per, rel=1e-13)


# --------------------------------------------------------------------------------------------
# the geometry of an elongated ellipse against the closed forms
# --------------------------------------------------------------------------------------------
@pytest.fixture(scope="module", params=[1e3, 1e6], ids=lambda r: f"ratio={r:g}")
def long_ellipse(request):
    """``x1^2/a^2 + x2^2/b^2 = 1`` with a = 2 r, b = 2 (Phi = x1^2/(2 R1) + x2^2/(2 R2), d0 = 2, R1 = r^2)."""
    r = request.param
    R1, R2, d0 = r * r, 1.0, 2.0
    return R1, R2, d0, contact_contour(x1**2 / sp.Float(2 * R1, 17) + x2**2 / (2 * R2), d0)


def test_long_ellipse_points_normals_curvature(long_ellipse):
    R1, R2, d0, c = long_ellipse
    a, b = math.sqrt(2 * d0 * R1), math.sqrt(2 * d0 * R2)
    L, N = c.perimeter, len(c.nodes)
    # the tips: x2(s) = 0 next to the nodes of largest |x1| (brentq on the contour's own f2)
    tips = [brentq(lambda q: c.f(q)[1], (j - 1) * L / N, (j + 1) * L / N, xtol=1e-16 * L)
            for j in (int(np.argmax(c.nodes[:, 0])), int(np.argmin(c.nodes[:, 0])))]
    near = np.concatenate([t + L * np.array([-1e-4, -1e-9, 0.0, 1e-9, 1e-4]) for t in tips])
    s = np.concatenate([np.random.default_rng(3).uniform(0, L, 400), near])
    p = c.f(s)
    X, Y = p[:, 0], p[:, 1]
    np.testing.assert_allclose((X / a) ** 2 + (Y / b) ** 2, 1.0, atol=1e-13)
    gx, gy = X / R1, Y / R2
    g = np.hypot(gx, gy)
    np.testing.assert_allclose(c.normal(s), -np.column_stack([gx, gy]) / g[:, None], atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(c.tangent(s), axis=1), 1.0, atol=1e-12)
    rho_exact = a**2 * b**2 * (X**2 / a**4 + Y**2 / b**4) ** 1.5  # after (3.6)
    np.testing.assert_allclose(c.rho(s), rho_exact, rtol=1e-7)
    np.testing.assert_allclose(c.g(s), g, rtol=1e-12)
    n1, n2 = -gx / g, -gy / g
    np.testing.assert_allclose(c.b1(s), g, rtol=1e-9)  # (3.14): b1 = |grad Phi|
    np.testing.assert_allclose(c.b2(s), -0.5 * (n1**2 / R1 + n2**2 / R2), rtol=1e-7, atol=1e-9 / R2)
    # the tips: |x1| = a, curvature radius b^2/a (3.1)
    np.testing.assert_allclose(np.abs(c.f(np.array(tips))[:, 0]), a, rtol=1e-13)
    np.testing.assert_allclose(c.rho(np.array(tips)), b * b / a, rtol=1e-7)


def test_long_ellipse_expansion_is_exact(long_ellipse):
    """(3.13): delta0 - Phi(f + n n0) = b1 n + b2 n^2 exactly for a quadratic punch (n up to b/2)."""
    R1, R2, d0, c = long_ellipse
    b = math.sqrt(2 * d0 * R2)
    s = np.linspace(0, c.perimeter, 73)
    for n in (-0.3 * b, 0.01 * b, 0.5 * b):
        x = c.local_to_cartesian(s, n)  # (3.4)
        lhs = d0 - (x[:, 0] ** 2 / (2 * R1) + x[:, 1] ** 2 / (2 * R2))
        np.testing.assert_allclose(lhs, c.b1(s) * n + c.b2(s) * n**2, atol=1e-11 * d0)


def test_long_ellipse_equal_arc_length_nodes(long_ellipse):
    """The nodes sit at equal arc length: the ellipse's own arc integral between them (mpmath)."""
    R1, R2, d0, c = long_ellipse
    a, b = math.sqrt(2 * d0 * R1), math.sqrt(2 * d0 * R2)
    Z = c.nodes
    N = len(Z)
    t = np.unwrap(np.arctan2(Z[:, 1] / b, Z[:, 0] / a))
    for j in range(N - 1):
        lo, hi = sorted((t[j], t[j + 1]))
        tips = [k * math.pi for k in range(math.ceil(lo / math.pi), math.floor(hi / math.pi) + 1)]
        if j % 41 and not tips:
            continue  # every 41st interval, and every one across a tip (split there: the near-kink of the speed)
        with mpmath.workdps(30):
            arc = mpmath.quad(lambda u: mpmath.sqrt((a * mpmath.sin(u)) ** 2 + (b * mpmath.cos(u)) ** 2),
                              [lo, *tips, hi])
        assert float(arc) == pytest.approx(c.perimeter / N, rel=1e-9)


def test_long_ellipse_integrals(long_ellipse):
    R1, R2, d0, c = long_ellipse
    a, b = math.sqrt(2 * d0 * R1), math.sqrt(2 * d0 * R2)
    # iint x1^2 = pi a^3 b/4; iint sqrt(d0 - Phi) = 2 pi a b sqrt(d0)/3; iint 1/sqrt(d0 - Phi) = 2 pi a b/sqrt(d0)
    assert c.integrate(lambda u, v: u**2) == pytest.approx(math.pi * a**3 * b / 4, rel=1e-12)
    F = lambda u, v: np.sqrt(np.maximum(d0 - u**2 / (2 * R1) - v**2 / (2 * R2), 0.0))
    assert c.integrate(F) == pytest.approx(2 * math.pi * a * b * math.sqrt(d0) / 3, rel=1e-10)
    assert c.integrate(lambda u, v: 1 / F(u, v)) == pytest.approx(2 * math.pi * a * b / math.sqrt(d0), rel=1e-10)
    # oint x1^2 ds: mpmath on the angle parametrisation, split at the tips t = 0, pi
    with mpmath.workdps(30):
        ref = mpmath.quad(lambda t: (a * mpmath.cos(t)) ** 2 * mpmath.sqrt((a * mpmath.sin(t)) ** 2
                                                                          + (b * mpmath.cos(t)) ** 2),
                          [0, mpmath.pi / 2, mpmath.pi, 3 * mpmath.pi / 2, 2 * mpmath.pi])
    assert c.boundary_integral(lambda u, v: u**2) == pytest.approx(float(ref), rel=1e-11)
    # divergence theorem: oint |grad Phi| ds = iint Laplacian Phi = (1/R1 + 1/R2) pi a b
    lap = (1 / R1 + 1 / R2) * math.pi * a * b
    assert c.boundary_integral(c.g, of="s") == pytest.approx(lap, rel=1e-11)
    assert c.boundary_integral(c.g, of="s", n=5000) == pytest.approx(lap, rel=1e-11)
    # Gauss-Bonnet with the closed-form curvature of the ellipse: oint kappa ds = 2 pi (tip radius b^2/a)
    kap = lambda u, v: 1 / (a**2 * b**2 * (u**2 / a**4 + v**2 / b**4) ** 1.5)
    assert c.boundary_integral(kap) == pytest.approx(2 * math.pi, rel=1e-9)
    assert c.accuracy.turning_number == pytest.approx(1.0, abs=1e-9)


def test_long_ellipse_higher_derivatives(long_ellipse):
    """d^3 f/ds^3 = kappa' n0 - kappa^2 f' (Frenet): against a central difference of kappa, and f'' = kappa n0."""
    R1, R2, d0, c = long_ellipse
    a = math.sqrt(2 * d0 * R1)
    s = np.random.default_rng(5).uniform(0, c.perimeter, 200)
    s = s[np.abs(c.f(s)[:, 0]) < 0.8 * a][:40]  # away from the tips, where kappa varies on the scale b^2/a
    h = 1e-5 * c.perimeter
    dk = (c.curvature(s + h) - c.curvature(s - h)) / (2 * h)
    k = c.curvature(s)
    T, Nn = c.tangent(s), c.normal(s)
    err2 = np.linalg.norm(c.derivative(s, 2) - k[:, None] * Nn, axis=1)
    assert np.all(err2 <= 1e-12 * np.abs(k))
    expect = dk[:, None] * Nn - (k * k)[:, None] * T
    err = np.linalg.norm(c.derivative(s, 3) - expect, axis=1)
    assert np.all(err <= 1e-5 * np.linalg.norm(expect, axis=1))
    np.testing.assert_allclose(c.derivative(s, 0), c.f(s))


# --------------------------------------------------------------------------------------------
# non-elliptic elongated punches
# --------------------------------------------------------------------------------------------
def _graph_reference(c2: float, c4: float, d0: float, scale: float):
    """``Phi = c2 X^2 + c4 X^4 + x2^2``, ``X = x1/scale`` (graph form): area, perimeter, iint (d0 - Phi), iint x1^2.

    ``|x2| < Y(X)``, ``Y^2 = d0 - c2 X^2 - c4 X^4 = c4 (X0^2 - X^2)(X^2 + beta)``, ``beta = X0^2 + c2/c4``.  With
    ``X = X0 (1 - tau^2)``: ``Y = tau G``, ``G^2 = c4 X0 (X0 + X)(X^2 + beta)``, smooth up to the tip tau = 0,
    and ``ds = sqrt(scale^2 X'(tau)^2 + Y'(tau)^2) dtau`` on each quarter (mpmath, tanh-sinh).
    """
    with mpmath.workdps(30):
        c2, c4, d0, sc = (mpmath.mpf(v) for v in (c2, c4, d0, scale))
        X0 = mpmath.sqrt(2 * d0 / (c2 + mpmath.sqrt(c2 * c2 + 4 * c4 * d0)))  # the positive root, no cancellation
        beta = X0**2 + c2 / c4
        X = lambda t: X0 * (1 - t * t)
        G = lambda x: mpmath.sqrt(c4 * X0 * (X0 + x) * (x * x + beta))
        dG = lambda x: c4 * X0 * (x * x + beta + 2 * x * (X0 + x)) / (2 * G(x))
        Y = lambda t: t * G(X(t))
        dY = lambda t: G(X(t)) + t * dG(X(t)) * (-2 * X0 * t)
        jac = lambda t: 2 * X0 * t  # |dX/dtau|

        def q(f):
            return mpmath.quad(lambda t: f(t) * jac(t), [0, 1])

        area = 4 * sc * q(Y)
        per = 4 * mpmath.quad(lambda t: mpmath.sqrt((sc * jac(t)) ** 2 + dY(t) ** 2), [0, 1])
        vol = 4 * sc * q(lambda t: Y(t) ** 3 * 2 / 3)  # int_{-Y}^{Y} (Y^2 - y^2) dy = 4 Y^3/3
        m2 = 4 * sc**3 * q(lambda t: X(t) ** 2 * Y(t))
        return float(area), float(per), float(vol), float(m2)


@pytest.mark.parametrize(("c2", "c4", "d0"), [(1e-20, 1e-40, 1.0), (1e-40, 1e-40, 0.5), (1.0, 1e-8, 3.0)])
def test_quartic_graph_form(c2, c4, d0):
    """``c2 x1^2 + x2^2 + c4 x1^4`` (e.g. 1e-20 x1^2 + x2^2 + 1e-40 x1^4, aspect ratio ~1e10)."""
    Phi = sp.Float(c2, 17) * x1**2 + x2**2 + sp.Float(c4, 17) * x1**4
    c = contact_contour(Phi, d0)
    scale = c4 ** -0.25  # x1 = scale X: c4 x1^4 = X^4
    area, per, vol, m2 = _graph_reference(c2 * scale**2, 1.0, d0, scale)
    assert abs(c.area / area - 1) < 1e-12
    assert abs(c.perimeter / per - 1) < 1e-12
    assert c.integrate(lambda u, v: d0 - (c2 * u**2 + v**2 + c4 * u**4)) == pytest.approx(vol, rel=1e-11)
    assert c.integrate(lambda u, v: u**2) == pytest.approx(m2, rel=1e-11)
    # on the level set, with the inward normal -grad Phi/|grad Phi| (3.3)
    s = np.random.default_rng(11).uniform(0, c.perimeter, 300)
    p = c.f(s)
    u, v = p[:, 0], p[:, 1]
    np.testing.assert_allclose(c2 * u**2 + v**2 + c4 * u**4, d0, rtol=1e-13)
    gx, gy = 2 * c2 * u + 4 * c4 * u**3, 2 * v
    g = np.hypot(gx, gy)
    np.testing.assert_allclose(c.normal(s), -np.column_stack([gx, gy]) / g[:, None], atol=1e-9)
    np.testing.assert_allclose(c.b1(s), g, rtol=1e-9)


#: in X = 1e-10 x1, Y = x2: X^2 + Y^2 + X^4 + X^2 Y^2/2 + 3 X Y/10 + X^3/5 (a tilted, asymmetric quartic)
MIXED = {(2, 0): 1e-20, (0, 2): 1.0, (4, 0): 1e-40, (2, 2): 5e-21, (1, 1): 3e-11, (3, 0): 2e-31}


def _polar_reference(coeffs: dict, d0: float, scale: float):
    """Area and perimeter of ``sum c_ij x1^i x2^j < d0`` by polar quadrature in ``X = x1/scale``, ``Y = x2``.

    ``rho(t)`` the boundary radius (Newton's method on the polynomial in rho from the quadratic estimate, then
    checked to be the first crossing: ``dPhi/drho > 0``); ``x1' = scale (rho' cos t - rho sin t)``,
    ``x2' = rho' sin t + rho cos t`` with ``rho' = -Phi_t/Phi_rho``; the perimeter integrand is split at the tips
    (``x1' = 0``, findroot).
    """
    with mpmath.workdps(30):
        sc = mpmath.mpf(scale)
        C = {(i, j): mpmath.mpf(v) * sc**i for (i, j), v in coeffs.items()}

        def coefficients(t):  # Phi(rho, t) = sum_k A_k rho^k, A_k = sum_{i+j=k} c_ij cos^i t sin^j t
            cs, sn = mpmath.cos(t), mpmath.sin(t)
            A = [mpmath.mpf(0)] * 5
            for (i, j), cc in C.items():
                A[i + j] += cc * cs**i * sn**j
            return A, cs, sn

        def phi_t(r, cs, sn):  # dPhi/dt, differentiated term by term
            return sum(cc * r ** (i + j) * ((j * cs ** (i + 1) * sn ** (j - 1) if j else 0)
                                            - (i * cs ** (i - 1) * sn ** (j + 1) if i else 0))
                       for (i, j), cc in C.items())

        def rho_at(t):
            """The boundary radius by Newton's method on the polynomial in rho, from the quadratic estimate."""
            A, cs, sn = coefficients(t)
            r = mpmath.sqrt(d0 / A[2])
            for _ in range(60):
                p = sum(a * r**k for k, a in enumerate(A)) - d0
                dp = sum(k * a * r ** (k - 1) for k, a in enumerate(A) if k)
                step = p / dp
                r -= step
                if abs(step) < mpmath.mpf(10) ** -28 * r:
                    break
            else:
                raise AssertionError("Newton did not converge")
            dp = sum(k * a * r ** (k - 1) for k, a in enumerate(A) if k)
            assert dp > 0  # the first crossing: Phi increases through d0
            return r, dp, cs, sn

        def rho(t):
            return rho_at(t)[0]

        def drho(t):
            r, dp, cs, sn = rho_at(t)
            return r, -phi_t(r, cs, sn) / dp

        def dx1(t):
            r, rp = drho(t)
            return sc * (rp * mpmath.cos(t) - r * mpmath.sin(t))

        def speed(t):
            r, rp = drho(t)
            return mpmath.hypot(sc * (rp * mpmath.cos(t) - r * mpmath.sin(t)), rp * mpmath.sin(t) + r * mpmath.cos(t))

        area = sc * mpmath.quad(lambda t: rho(t) ** 2 / 2, mpmath.linspace(0, 2 * mpmath.pi, 9))
        t0 = mpmath.findroot(dx1, 0.0)
        t1 = mpmath.findroot(dx1, mpmath.pi)
        pts = [t0, (t0 + t1) / 2, t1, (t1 + t0 + 2 * mpmath.pi) / 2, t0 + 2 * mpmath.pi]
        per = mpmath.quad(speed, pts)
        return float(area), float(per)


def test_mixed_quartic_against_polar_quadrature():
    """An asymmetric, tilted quartic with coefficients 1e-40..1 (aspect ratio ~1e10)."""
    Phi = sum(sp.Float(v, 17) * x1**i * x2**j for (i, j), v in MIXED.items())
    c = contact_contour(Phi, 1.0)
    area, per = _polar_reference(MIXED, 1.0, 1e10)
    assert abs(c.area / area - 1) < 1e-12
    assert abs(c.perimeter / per - 1) < 1e-12
    # divergence theorem with the Laplacian from sympy: iint Laplacian Phi = oint |grad Phi| ds
    lap = sp.lambdify((x1, x2), sp.diff(Phi, x1, 2) + sp.diff(Phi, x2, 2))
    lhs = c.integrate(lambda u, v: lap(u, v) * np.ones_like(u))
    assert lhs == pytest.approx(c.boundary_integral(c.g, of="s"), rel=1e-11)
    # on the level set, Phi evaluated in 30 digits from the float coefficients
    s = np.linspace(0, c.perimeter, 97)
    with mpmath.workdps(30):
        for u, v in c.f(s):
            val = sum(mpmath.mpf(cc) * mpmath.mpf(u) ** i * mpmath.mpf(v) ** j for (i, j), cc in MIXED.items())
            assert abs(float(val) - 1.0) < 1e-13


def test_coefficients_from_1e_minus_70_to_1e30_in_one_punch():
    """``1e-70 x1^4 + 1e30 x2^2 < 1``: X = 10^-17.5 x1, Y = 1e15 x2: X^4 + Y^2 < 1 (aspect ratio ~3e32).

    Area ``10^2.5 int_{-1}^{1} 2 sqrt(1 - X^4) dX = 10^2.5 B(1/4, 3/2)``; perimeter
    ``4 10^17.5 int_0^1 sqrt(1 + 1e-65 Y'(X)^2) dX`` (mpmath, tanh-sinh at the end X = 1).
    """
    c = contact_contour(sp.Float("1e-70") * x1**4 + sp.Float("1e30") * x2**2, 1)
    with mpmath.workdps(40):
        sx = mpmath.mpf(10) ** mpmath.mpf(17.5)
        area = float(sx * mpmath.mpf(10) ** -15 * mpmath.beta(mpmath.mpf(1) / 4, mpmath.mpf(3) / 2))
        eps2 = (mpmath.mpf(10) ** -15 / sx) ** 2
        per = float(4 * sx * mpmath.quad(lambda X: mpmath.sqrt(1 + eps2 * 4 * X**6 / (1 - X**4)), [0, 1]))
    assert abs(c.area / area - 1) < 1e-13
    assert abs(c.perimeter / per - 1) < 1e-13


def test_stretched_bent_region_is_not_star_shaped():
    """``(x2 - 1e-40 x1^2)^2 + 1e-80 x1^4/10 < 0.3``: the bent region of test_contour stretched 1e20 times along x1.

    With ``X = 1e-20 x1``: ``|x2 - X^2| < w(X) = sqrt(0.3 - X^4/10)``, so ``|omega_0| = 1e20 int 2 w dX`` and
    ``iint x2 = 1e20 int 2 w X^2 dX`` (mpmath); not star-shaped, so ``integrate`` takes Green's theorem.
    """
    d0 = 0.3
    c = contact_contour((x2 - sp.Float("1e-40") * x1**2) ** 2 + sp.Float("1e-80") * x1**4 / 10, d0)
    assert not c.is_star_shaped
    with mpmath.workdps(30):
        X = (10 * mpmath.mpf(d0)) ** 0.25
        w = lambda t: mpmath.sqrt(max(mpmath.mpf(d0) - t**4 / 10, 0))
        area = float(1e20 * mpmath.quad(lambda t: 2 * w(t), [-X, 0, X]))
        m2 = float(1e20 * mpmath.quad(lambda t: 2 * w(t) * t**2, [-X, 0, X]))
    assert c.area == pytest.approx(area, rel=1e-12)
    assert c.integrate(lambda u, v: np.ones_like(u)) == pytest.approx(area, rel=1e-12)
    assert c.integrate(lambda u, v: v) == pytest.approx(m2, rel=1e-12)
    assert c.centroid[1] == pytest.approx(m2 / area, rel=1e-12)


@pytest.mark.parametrize("r", [1e40, 1e60, 1e90])
def test_extreme_aspect_ratios_below_the_limit(r):
    """``x1^2/r^2 + x2^2 < 1``, r up to 1e90 (ASPECT_MAX = 1e100): area pi r, perimeter 4 r E(1 - 1/r^2)."""
    c = contact_contour(x1**2 / sp.Float(r * r, 17) + x2**2, 1)
    area, per = _ellipse_reference(1 / (r * r), 1.0, 1.0)
    assert abs(c.area / area - 1) < 1e-13
    assert abs(c.perimeter / per - 1) < 1e-13


# --------------------------------------------------------------------------------------------
# the force law and solve() on elongated punches
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("Phi", [sp.Float("1e-30") * x1**2 + sp.Float("1e30") * x2**2,
                                 sp.Float("3e20") * x1**2 + sp.Float("2e5") * x1 * x2 + sp.Float("1e-5") * x2**2])
def test_contour_route_equals_closed_form_force_law(Phi):
    """The numeric (contour) route of the force law (1.8), (3.25) against its closed form for a quadratic punch.

    Aspect ratios 1e30 and ~5e12 (with a mixed term); ``H`` a thousandth of the half-width ``2 |omega|/|Gamma|``.
    """
    law = force_law(BondedLayer(0.3), Punch(Phi))
    assert law.kind == "quadratic"
    generic = type(law)(law.layer, law.punch, "contour", None, None, None, None, law.coefficient, law.p1_factor)
    d0 = 0.4
    first = law.evaluate(d0, 1.0, 1.3)
    H = 1e-3 * 2 * first.area0 / first.perimeter
    closed = law.evaluate(d0, H, 1.3, edge_shift=0.1)
    num = generic.evaluate(d0, H, 1.3, edge_shift=0.1)
    for q in ("P0", "P1", "area0", "perimeter", "V", "J"):
        assert getattr(num, q) == pytest.approx(getattr(closed, q), rel=1e-11), q


def test_solve_on_an_elongated_quartic():
    """``thinlayer.solve`` on ``1e-20 x1^2 + x2^2 + 1e-40 x1^4`` (aspect ratio ~1e10, H/a ~ 6e-4).

    Expected force ``P = vartheta/(A H) iint (d0 - Phi) + c oint |grad Phi| ds`` (1.8) with the two
    integrals from mpmath (graph form; ``oint |grad Phi| ds = iint Laplacian Phi``, divergence theorem)
    and ``vartheta = mu/(1 - nu)``, ``A``, ``c`` from the layer and the law.
    """
    Phi = sp.Float("1e-20") * x1**2 + x2**2 + sp.Float("1e-40") * x1**4
    d0, H, mu, nu = 1.0, 1e-3, 2.0, 0.3
    sol = tl.solve(BondedLayer(nu), Punch(Phi), delta0=d0, H=H, mu=mu)
    assert sol.model == "compressible"
    area, per, vol, m2 = _graph_reference(1.0, 1.0, d0, 1e10)
    lap = (2e-20 + 2.0) * area + 12e-40 * m2  # Laplacian Phi = 2e-20 + 2 + 12e-40 x1^2
    layer = BondedLayer(nu)
    law = force_law(layer, Punch(Phi))
    vartheta = mu / (1 - nu)
    P0 = vartheta / (float(layer.A) * H) * vol
    coef = float(law.coefficient.subs({S.H: H, S.mu: mu, S.nu: nu}))
    assert sol.force == pytest.approx(P0 + coef * lap, rel=1e-11)
    assert abs(coef * lap / P0) > 1e-8  # the correction (1.4e-7 of P0) is resolved by the 1e-11 check


# --------------------------------------------------------------------------------------------
# bounded work
# --------------------------------------------------------------------------------------------
def test_elongation_costs_nothing():
    """Aspect ratios 1, 1e6 and 1e30: the same node count, a bounded number of panels (times: bench_contour.py)."""
    nodes = []
    for a in (1.0, 1e-12, 1e-60):
        Phi = sp.Float(a, 17) * x1**2 + x2**2
        c = contact_contour(Phi, 1)
        nodes.append(len(c.nodes))
        s = np.linspace(0, c.perimeter, 10_000)
        assert np.all(np.isfinite(c.curvature(s)))
    assert nodes[1] == nodes[2] <= 2 * nodes[0]
