"""Tests of the direct two-dimensional contact solver :mod:`thinlayer.numerics` (FFT + Polonsky-Keer).

Every expected value comes from a route independent of the solver:

* Hertz's closed forms for the half-space (L = 1), circular and elliptic (derivations below);
* the independent axisymmetric spectral solver :func:`thinlayer.numerics.solve_axisymmetric`
  (Galerkin in a Jacobi basis, Hankel-space kernel: it shares no code with the FFT solver
  except the kernel evaluation ``L_numeric``);
* the thin-layer force law ``P = (vartheta/(A H)) [iint_O (delta0 - Phi) - (m_1 H^2/2) iint_O Laplacian(Phi)]``
  (O = {Phi < delta0}), from the inner expansion (2.26)-(2.28) plus the boundary layer
  (see the derivation in tests/test_direct.py, generalised below), with A, m_1 from the symbolic
  coefficients (2.4), (2.20);
* mpmath quadrature of the correction kernel, the sum rule ``sum C = A H/vartheta`` and explicit
  (non-FFT) summation of the discrete convolution.

Hertz, circle.  With ``E* = 2 vartheta = 2 mu/(1 - nu)`` (Boussinesq with the normalisation of
(2.1): ``u3 = (1/(pi E*)) iint p/|x - y|``), a sphere ``Phi = r^2/(2R)`` gives ``a = sqrt(R delta0)``,
``P = (4/3) E* R^{1/2} delta0^{3/2} = 8 vartheta a^3/(3R)``.

Hertz, ellipse (Johnson, Contact Mechanics, section 3.6 and 4.2).  For
``p = p0 sqrt(1 - x1^2/a^2 - x2^2/b^2)``, b = a sqrt(1 - e^2),
``iint p/|x - y| dy = L - M x1^2 - N x2^2`` with ``L = pi p0 b K(e)``,
``M = pi p0 b (K - E)/(e^2 a^2)``, ``N = pi p0 b (a^2 E/b^2 - K)/(e^2 a^2)`` (K, E complete elliptic
integrals of modulus e).  Matching ``delta0 - x1^2/(2R1) - x2^2/(2R2)``: ``R1/R2 = (E/(1-e^2) - K)/(K - E)``
fixes e, ``a^2 = delta0 (K - E)/(K e^2/(2 R1))``, ``p0 = E* delta0/(b K)``, ``P = (2/3) pi a b p0``.
(Limit e -> 0: (K - E)/e^2 -> pi/4, K -> pi/2, a^2 = R delta0: the circle.)

Thin layer, any convex punch.  The inner pressure to O(eps^2) is ``p = (vartheta/(A H))
(delta0 - Phi - m_1 H^2 Laplacian Phi)`` ((2.26)-(2.28) with (2.20); for the paraboloid this is the
corrected (2.30)); the boundary layer adds ``g H^2 m_1/2`` per unit length of contour, g the
inward slope ``(vartheta/(A H)) |grad Phi|`` of the inner pressure.  Since grad Phi is normal to
the level line, ``oint |grad Phi| ds = iint_O Laplacian Phi``, which gives the law above with a
relative remainder O(eps^3), eps = H/(smallest half-width of O).  For the paraboloid it is
``1 - 2 m_1 H^2/(R delta0)``, whose remainder against the direct solver is 0.64 eps^3 (checked below).
"""
from __future__ import annotations

import math
from dataclasses import FrozenInstanceError

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy import integrate, optimize, special

from thinlayer import BondedLayer, FrictionlessLayer, GenericLayer, HalfSpace, Punch
from thinlayer import symbols as S
from thinlayer.numerics import (
    AxisymmetricContact,
    AxisymmetricPunchContact,
    CoarseGridWarning,
    Contact2D,
    ContactConvergenceError,
    influence_coefficients,
    layer_correction_kernel,
    solve_2d,
    solve_axisymmetric,
    surface_displacement,
)
from thinlayer.numerics._influence import Convolver as _Convolver

slow = pytest.mark.slow
NU = 0.3
VT = 1.0 / (1.0 - NU)  # vartheta for mu = 1


# --------------------------------------------------------------------------- references
def hertz_elliptic(R1: float, R2: float, delta0: float, estar: float) -> tuple[float, float, float]:
    """Semi-axes a (along x1), b and force P of Hertz's elliptic contact (module docstring), R1 >= R2."""

    def ratio(e):
        m = e * e
        K, E = special.ellipk(m), special.ellipe(m)
        return (E / (1 - m) - K) / (K - E) - R1 / R2

    e = optimize.brentq(ratio, 1e-6, 1 - 1e-12, xtol=1e-15)
    m = e * e
    K, E = special.ellipk(m), special.ellipe(m)
    a = math.sqrt(delta0 * (K - E) / (K * m / (2 * R1)))
    b = a * math.sqrt(1 - m)
    p0 = estar * delta0 / (b * K)
    return a, b, 2.0 / 3.0 * math.pi * a * b * p0


def thin_layer_force(layer, punch: Punch, delta0: float, H: float, vartheta: float) -> float:
    """The O(eps^2) thin-layer force law of the module docstring, integrals over O = {Phi < delta0} in polar form."""
    A, m1 = float(layer.A), float(layer.m(1))
    phi = sp.lambdify((S.x1, S.x2), punch.expr)
    lap = sp.lambdify((S.x1, S.x2), punch.laplacian())

    def rho(th):  # O is star-shaped about the tip (origin) for the punches used here: first crossing
        def f(r):
            return phi(r * math.cos(th), r * math.sin(th)) - delta0

        hi = 1.0
        while f(hi) <= 0:
            hi *= 2.0
        return optimize.brentq(f, 0.0, hi, xtol=1e-13)

    def integral(f):
        return integrate.quad(lambda th: integrate.quad(lambda r: f(r * math.cos(th), r * math.sin(th)) * r,
                                                        0.0, rho(th), epsabs=0, epsrel=1e-12)[0],
                              0.0, 2 * math.pi, epsabs=0, epsrel=1e-11, limit=200)[0]

    return vartheta / (A * H) * (integral(lambda x, y: delta0 - phi(x, y)) - 0.5 * m1 * H**2 * integral(lap))


# --------------------------------------------------------------------------- influence coefficients
def test_half_space_coefficients_match_quadrature():
    """Love's closed form against adaptive quadrature of Boussinesq's 1/(2 pi vartheta r) over a cell."""
    d = 0.7
    C = influence_coefficients(HalfSpace(), None, d, 12, nu=NU, mu=2.0)
    vt = 2.0 / (1 - NU)
    assert C[0, 0] == pytest.approx(4 * d * math.asinh(1.0) / (2 * math.pi * vt), rel=1e-14)
    for k, l in [(1, 0), (2, 3), (11, 7)]:
        ref, _ = integrate.dblquad(lambda y, x: 1.0 / math.hypot(x, y), k * d - d / 2, k * d + d / 2,
                                   l * d - d / 2, l * d + d / 2, epsabs=0, epsrel=1e-12)
        assert C[k, l] == pytest.approx(ref / (2 * math.pi * vt), rel=1e-10)
        assert C[k, l] == C[l, k]


@pytest.mark.parametrize("layer", [BondedLayer(0.3), BondedLayer(0.45), FrictionlessLayer()], ids=repr)
def test_correction_kernel_against_mpmath(layer):
    """g_c(r) = (1/2pi) int (L(t) - 1) J0(t r) dt (H = 1) by mpmath quadrature with the mpmath kernel."""
    rs = [0.0, 0.4, 2.5, 9.0]
    g = layer_correction_kernel(layer, 1.0, np.array(rs))
    for r, val in zip(rs, g):
        ref = mpmath.quad(lambda t, r=r: (layer.L_numeric(t, "mpmath") - 1) * mpmath.besselj(0, t * r),
                          [0, 1, 2, 4, 8, 16, 30]) / (2 * mpmath.pi)
        assert val == pytest.approx(float(ref), abs=1e-14)
    # scaling with H: g_c(r; H) = g_c(r/H; 1)/H
    assert layer_correction_kernel(layer, 2.0, np.array([5.0]))[0] == pytest.approx(g[2] / 2.0, rel=1e-12)


def test_layer_table_equals_a_table_of_the_grid(monkeypatch):
    """The per-layer table of H g_c(rho H) (knots every 1/40, kept per process) gives the coefficients the grid's own
    table (knots every <= H/40 on [0, r_tab], the construction before the cache) gives, to the splines' error; and
    its values do not depend on which grid asked first (one quadrature per unit interval of rho)."""
    from thinlayer.numerics import _influence

    layer, H = BondedLayer(0.3), 0.05
    for d, n in [(0.01, 128), (0.0075, 160)]:
        _influence._layer_table.cache_clear()
        _influence._layer_segment.cache_clear()
        tabled = influence_coefficients(layer, H, d, n)
        with monkeypatch.context() as m:
            m.setattr(_influence, "_RHO_TABLE", 0)  # every grid builds its own table, as before the cache
            own = influence_coefficients(layer, H, d, n)
        assert np.abs(tabled - own).max() <= 1e-10 * np.abs(own).max()
    first = _influence._layer_table(layer, 52)(np.array([0.3, 7.77, 40.1]))
    _influence._layer_table.cache_clear()
    _influence._layer_segment.cache_clear()
    _influence._layer_table(layer, 9)
    assert np.array_equal(_influence._layer_table(layer, 52)(np.array([0.3, 7.77, 40.1])), first)


@pytest.mark.parametrize("layer", [BondedLayer(0.3), BondedLayer(0.45), BondedLayer(0.499), BondedLayer(-0.9),
                                   FrictionlessLayer()], ids=repr)
def test_layer_kernel_negligible_beyond_cutoff(layer):
    """The full kernel 1/(2 pi r) + g_c(r) has decayed to rounding at 50 H (the cut-off of the coefficients)."""
    r = np.array([50.0, 60.0])
    H = 2.0
    tail = layer_correction_kernel(layer, H, H * r) + 1 / (2 * math.pi * H * r)
    assert np.all(np.abs(tail) < 1e-15 / H)  # 1/(2 pi H) ~ 0.08/H at r = 0


@pytest.mark.parametrize("layer, nu", [(BondedLayer(0.3), None), (BondedLayer(0.45), None),
                                       (FrictionlessLayer(), 0.2)], ids=["b0.3", "b0.45", "frictionless"])
@pytest.mark.parametrize("cells_per_H", [5, 12])
def test_sum_rule(layer, nu, cells_per_H):
    """sum over the plane of C = displacement under uniform unit pressure = A H / vartheta (2.4).

    A comes from the symbolic coefficient (independent of the numerics).  The tolerance 1e-7 bounds the
    cubic-spline error of the g_c table (spacing H/40: ~(1/40)^4/384 times H^5 g_c'''' = O(1e-9)).
    """
    H, mu = 1.7, 1.3
    d = H / cells_per_H
    n = math.ceil(52 * H / d)
    C = influence_coefficients(layer, H, d, n, nu=nu, mu=mu)
    total = C[0, 0] + 2 * C[1:, 0].sum() + 2 * C[0, 1:].sum() + 4 * C[1:, 1:].sum()
    nu_val = float(layer.nu) if nu is None else nu
    assert total == pytest.approx(float(layer.A) * H * (1 - nu_val) / mu, rel=1e-7)


def test_fft_convolution_equals_direct_sum():
    """The zero-padded FFT convolution equals the explicit aperiodic sum (no wrap-around)."""
    n = 13
    C = influence_coefficients(BondedLayer(0.3), 1.0, 0.2, n)
    rng = np.random.default_rng(1)
    p = rng.uniform(0, 1, (n, n))
    i = np.arange(n)
    K = C[np.abs(i[:, None, None, None] - i[None, None, :, None]),
          np.abs(i[None, :, None, None] - i[None, None, None, :])]
    ref = np.einsum("ijkl,kl->ij", K, p)
    assert np.allclose(_Convolver(C, 1)(p), ref, rtol=0, atol=1e-14 * np.abs(ref).max())


# --------------------------------------------------------------------------- half-space: Hertz
def test_hertz_sphere():
    """Force and contact radius of a sphere against Hertz, n = 64 (Delta = a/25.6).

    Tolerances from the discretisation: the piecewise-constant force error is c (Delta/a)^2 with
    c = 0.03..0.08 over several depths (second test), allowed 0.25 (Delta/a)^2 = 3.8e-4; the
    sub-cell edge estimate lies within 0.02 Delta of Hertz's a, allowed 0.1 Delta.
    """
    R, delta0 = 2.0, 0.5
    a, P = math.sqrt(R * delta0), 8 * VT * math.sqrt(R * delta0) ** 3 / (3 * R)
    res = solve_2d(HalfSpace(), Punch.paraboloid(R=R), delta0=delta0, n=64, extent=1.25 * a, nu=NU)
    h = res.spacing
    assert res.residual <= 1e-10
    assert res.force == pytest.approx(P, rel=0.25 * (h / a) ** 2)
    assert abs(res.contact_radius - a) < 0.1 * h
    assert abs(math.sqrt(res.contact_area_cells / math.pi) - a) < h  # the staircase estimate is cruder
    # Hertz pressure p0 sqrt(1 - r^2/a^2), p0 = 4 vartheta a/(pi R), at the cell centres well inside
    X1, X2 = np.meshgrid(res.x1, res.x2, indexing="ij")
    rr = np.hypot(X1, X2)
    ph = 4 * VT * a / (math.pi * R) * np.sqrt(np.clip(1 - (rr / a) ** 2, 0, None))
    inner = rr < 0.8 * a
    assert np.abs(res.pressure - ph)[inner].max() < 0.01 * ph.max()
    # axisymmetry of the grid solution (square grid centred on the tip): p(x1, x2) = p(x2, x1) = p(-x1, x2)
    p = res.pressure
    assert np.allclose(p, p.T, rtol=0, atol=1e-8 * p.max())
    assert np.allclose(p, p[::-1], rtol=0, atol=1e-8 * p.max())


@pytest.mark.parametrize("delta0", [1.0, 0.6])
def test_hertz_grid_refinement(delta0):
    """Grid refinement n = 32..256 on a fixed square: the force error falls like Delta^q with q ~ 2.

    Measured orders (least-squares slope of log error vs log Delta) are 2.0-2.2; asserted q > 1.5, every
    error below 0.25 (Delta/a)^2, and the sub-cell radius within 0.1 Delta at every level.
    """
    a, P = math.sqrt(delta0), 8 * VT * math.sqrt(delta0) ** 3 / 3
    errs, hs = [], []
    for n in (32, 64, 128, 256):
        res = solve_2d(HalfSpace(), Punch.paraboloid(R=1), delta0=delta0, n=n, extent=1.25, nu=NU)
        h = res.spacing
        err = abs(res.force / P - 1)
        assert err < 0.25 * (h / a) ** 2
        assert abs(res.contact_radius - a) < 0.1 * h
        errs.append(err)
        hs.append(h)
    order = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert order > 1.5
    assert errs[-1] < errs[0] / 16


def test_force_controlled_matches_hertz_and_depth_control():
    """Prescribed force (original Polonsky-Keer): delta0 = (3P/(4 E* R^{1/2}))^{2/3} and consistency."""
    P, R = 2.0, 1.5
    d0 = (3 * P / (4 * 2 * VT * math.sqrt(R))) ** (2 / 3)
    a = math.sqrt(R * d0)
    ext = 1.3 * a
    res = solve_2d(HalfSpace(), Punch.paraboloid(R=R), force=P, n=128, extent=ext, nu=NU)
    h = res.spacing
    assert res.force == pytest.approx(P, rel=1e-13)
    # delta0 ~ P^{2/3}: allowed (2/3) of the force tolerance of test_hertz_sphere
    assert res.delta0 == pytest.approx(d0, rel=(2 / 3) * 0.25 * (h / a) ** 2)
    assert abs(res.contact_radius - a) < 0.1 * h
    back = solve_2d(HalfSpace(), Punch.paraboloid(R=R), delta0=res.delta0, n=128, extent=ext, nu=NU)
    assert back.force == pytest.approx(P, rel=1e-8)
    assert np.allclose(back.pressure, res.pressure, rtol=0, atol=1e-7 * res.max_pressure)


def test_elliptic_hertz_half_space():
    """Non-axisymmetric punch R1/R2 = 4 on the half-space against Hertz's elliptic solution (e from K, E)."""
    R1, R2, delta0 = 4.0, 1.0, 1.0
    a, b, P = hertz_elliptic(R1, R2, delta0, 2 * VT)
    assert a / b == pytest.approx(2.5007, abs=1e-4)  # Johnson's table: R1/R2 = 4 -> a/b ~ 2.5
    res = solve_2d(HalfSpace(), Punch.elliptic_paraboloid(R1=R1, R2=R2), delta0=delta0, n=128,
                   extent=1.2 * a, nu=NU)
    h = res.spacing
    assert res.force == pytest.approx(P, rel=0.25 * (h / b) ** 2)
    assert res.contact_area == pytest.approx(math.pi * a * b, rel=0.2 * h / b)  # edge within 0.1 Delta
    # every contour vertex lies within 0.25 Delta of Hertz's ellipse (measured: 0.15 Delta, rms 0.05 Delta)
    pts = np.vstack(res.contour)
    x, y = pts[:, 0], pts[:, 1]
    s = np.hypot(x / a, y / b)
    dist = (s - 1) * s / np.hypot(x / a**2, y / b**2)  # first-order distance to the ellipse s = 1
    assert np.abs(dist).max() < 0.25 * h
    assert np.abs(x).max() == pytest.approx(a, abs=0.25 * h)
    assert np.abs(y).max() == pytest.approx(b, abs=0.25 * h)
    p = res.pressure
    assert np.allclose(p, p[::-1], rtol=0, atol=1e-8 * p.max())
    assert np.allclose(p, p[:, ::-1], rtol=0, atol=1e-8 * p.max())
    assert len(res.contour) == 1 and np.array_equal(res.contour[0][0], res.contour[0][-1])


def test_discrete_contact_conditions_by_explicit_summation():
    """p >= 0, gap >= 0 and p gap = 0 with u3 recomputed by an explicit sum (not the FFT)."""
    n = 24
    res = solve_2d(FrictionlessLayer(), Punch(S.x1**2 + S.x2**2 / 2 + S.x1 * S.x2 / 4), delta0=0.1, H=0.5, n=n,
                   extent=0.7, nu=0.25)
    C = influence_coefficients(FrictionlessLayer(), 0.5, res.spacing, n, nu=0.25)
    i = np.arange(n)
    K = C[np.abs(i[:, None, None, None] - i[None, None, :, None]),
          np.abs(i[None, :, None, None] - i[None, None, None, :])]
    u = np.einsum("ijkl,kl->ij", K, res.pressure)
    X1, X2 = np.meshgrid(res.x1, res.x2, indexing="ij")
    gap = u - (0.1 - (X1**2 + X2**2 / 2 + X1 * X2 / 4))
    contact = res.pressure > 0
    assert np.all(res.pressure >= 0)
    assert np.abs(gap[contact]).max() < 1e-9 * 0.1
    assert gap[~contact].min() > -1e-9 * 0.1
    assert np.allclose(gap, res.gap, rtol=0, atol=1e-12)
    assert 0 < contact.sum() < n * n


# --------------------------------------------------------------------------- layers against the axisymmetric solver
def test_thin_layer_against_direct_solver():
    """Sphere on a thin bonded layer, H/a ~ 0.1, nu = 0.3, n = 256 (Delta = H/10) vs solve_axisymmetric.

    The 2D error is set by the boundary layer of width ~H at the edge, resolved by 10 cells:
    O((Delta/H)^2) = 1e-2 in a strip carrying O(H/a) = 0.1 of the force, so ~1e-3; measured 2e-5 for P
    and 1e-4 for c.  Allowed: 2e-3 for P, 0.1 Delta for c, 3e-3 p_max for the pressure inside 0.9 c.
    """
    layer, R, delta0, H = BondedLayer(NU), 1000.0, 0.05, 1.0
    ref = solve_axisymmetric(layer, lambda r: r**2 / (2 * R), delta0, H)
    assert 9.5 < ref.radius / H < 10.5
    res = solve_2d(layer, Punch.paraboloid(R=R), delta0=delta0, H=H, n=256)
    assert res.spacing <= H / 9.9
    assert res.force == pytest.approx(ref.force, rel=2e-3)
    assert abs(res.contact_radius - ref.radius) < 0.1 * res.spacing
    j = np.argmin(np.abs(res.x2))
    pr = ref.pressure_at(np.hypot(res.x1, res.x2[j]))
    inner = np.abs(res.x1) < 0.9 * ref.radius
    assert np.abs(res.pressure[:, j] - pr)[inner].max() < 3e-3 * pr.max()


@pytest.mark.parametrize("layer, nu", [(BondedLayer(0.45), None), (FrictionlessLayer(), 0.25)],
                         ids=["bonded0.45", "frictionless"])
@pytest.mark.parametrize("H", [1.0, 0.25])
def test_layers_of_finite_thickness_against_direct_solver(layer, nu, H):
    """H/a = 1 and 4, n = 64 (Delta = a/23): force and radius within 1.5e-3 (measured 1.6e-4..6.9e-4)."""
    kw = {} if nu is None else {"nu": nu}
    ref = solve_axisymmetric(layer, Punch.paraboloid(R=1), 0.5, H, **kw)
    res = solve_2d(layer, Punch.paraboloid(R=1), delta0=0.5, H=H, n=64, **kw)
    assert res.force == pytest.approx(ref.force, rel=1.5e-3)
    assert res.contact_radius == pytest.approx(ref.contact_radius, rel=1.5e-3)


def test_direct_thin_layer_force_law():
    """The thin-layer force law used below, checked on the paraboloid against the direct solver: remainder ~ eps^3."""
    layer, H = BondedLayer(NU), 1.0
    for c in (10.0, 20.0):
        R = 1000.0
        delta0 = c**2 / (2 * R)
        eps = H / c
        ref = solve_axisymmetric(layer, lambda r, R=R: r**2 / (2 * R), delta0, H)
        law = thin_layer_force(layer, Punch.paraboloid(R=R), delta0, H, VT)
        assert law == pytest.approx(math.pi * VT * R * delta0**2 / (float(layer.A) * H)
                                    * (1 - 2 * float(layer.m(1)) * H**2 / (R * delta0)), rel=1e-10)
        assert abs(ref.force / law - 1) < eps**3


# --------------------------------------------------------------------------- non-axisymmetric punches on a thin layer
def test_thin_layer_elliptic_paraboloid():
    """R1/R2 = 4, eps = H/b = 0.1: force vs the thin-layer law (remainder ~0.4 eps^3; allowed 2 eps^3)."""
    layer, H = BondedLayer(NU), 1.0
    punch = Punch.elliptic_paraboloid(R1=2000, R2=500)
    delta0 = 0.1  # O: semi-axes 20 H and 10 H
    res = solve_2d(layer, punch, delta0=delta0, H=H, n=256)
    law = thin_layer_force(layer, punch, delta0, H, VT)
    assert law == pytest.approx(math.pi * VT * 1000 * delta0**2 / (float(layer.A) * H)
                                * (1 - float(layer.m(1)) * H**2 * (1 / 2000 + 1 / 500) / delta0), rel=1e-9)
    assert res.force == pytest.approx(law, rel=2 * 0.1**3)
    pts = np.vstack(res.contour)
    # the edge lies ~h* H inside the overlap ellipse (h* ~ 0.1-0.3 for nu = 0.3, see test_direct)
    assert 19.0 < np.abs(pts[:, 0]).max() < 20.0 and 9.0 < np.abs(pts[:, 1]).max() < 10.0
    p = res.pressure
    assert np.allclose(p, p[::-1], rtol=0, atol=1e-8 * p.max())
    assert np.allclose(p, p[:, ::-1], rtol=0, atol=1e-8 * p.max())


def test_thin_layer_non_symmetric_cubic_punch():
    """Phi = (x1^2 + x2^2/4)/(2R) + gamma x1^3 (convex on the contact, no x1 -> -x1 symmetry)."""
    layer, H, R = BondedLayer(NU), 1.0, 500.0
    gamma = 1.0 / (6 * R * 40.0)  # Phi_11 > 0 for x1 > -40 H
    punch = Punch((S.x1**2 + S.x2**2 / 4) / (2 * R) + gamma * S.x1**3, name="cubic")
    delta0 = 0.1
    res = solve_2d(layer, punch, delta0=delta0, H=H, n=256)
    assert res.force > 0 and res.residual <= 1e-10
    law = thin_layer_force(layer, punch, delta0, H, VT)
    assert res.force == pytest.approx(law, rel=2 * 0.1**3)
    p = res.pressure
    assert np.allclose(p, p[:, ::-1], rtol=0, atol=1e-8 * p.max())  # x2 -> -x2 symmetry is kept
    assert not np.allclose(p, p[::-1], rtol=0, atol=1e-3 * p.max())  # x1 -> -x1 is not a symmetry
    centroid = (p.sum(axis=1) @ res.x1) / p.sum()
    assert centroid < -0.1 * H  # the punch is lower at negative x1
    pts = np.vstack(res.contour)
    assert -pts[:, 0].min() > pts[:, 0].max()
    assert res.contact_area == pytest.approx(res.contact_area_cells, rel=2 * res.spacing / 10.0)


# --------------------------------------------------------------------------- result object
def test_result_is_immutable():
    res = solve_2d(HalfSpace(), Punch.paraboloid(R=1), delta0=1.0, n=32, extent=1.3, nu=NU)
    assert isinstance(res, Contact2D) and res.pressure.shape == (32, 32) and res.x1.shape == (32,)
    with pytest.raises(FrozenInstanceError):
        res.force = 1.0
    with pytest.raises(ValueError):
        res.pressure[0, 0] = 1.0
    assert res.contact_mask.sum() * res.spacing**2 == pytest.approx(res.contact_area_cells)
    assert "P =" in res.latex() and res.equation == "1.5-1.8"


# --------------------------------------------------------------------------- bad input
def _bonded():
    return BondedLayer(NU)


@pytest.mark.parametrize("kwargs, exc, words", [
    ({"delta0": 0.0, "H": 1.0}, ValueError, "delta0"),
    ({"delta0": -1.0, "H": 1.0}, ValueError, "delta0"),
    ({"delta0": float("nan"), "H": 1.0}, ValueError, "delta0"),
    ({"delta0": 0.05, "H": 0.0}, ValueError, "H"),
    ({"delta0": 0.05, "H": -1.0}, ValueError, "H"),
    ({"delta0": 0.05}, ValueError, "thickness H"),
    ({"H": 1.0}, ValueError, "exactly one"),
    ({"delta0": 0.05, "H": 1.0, "force": 1.0}, ValueError, "exactly one"),
    ({"force": 1.0, "H": 1.0}, ValueError, "extent"),
    ({"delta0": 0.05, "H": 1.0, "n": 1}, ValueError, "n (cells"),
    ({"delta0": 0.05, "H": 1.0, "n": 64.0}, TypeError, "integer"),
    ({"delta0": 0.05, "H": 1.0, "tol": 0.0}, ValueError, "tol"),
    ({"delta0": 0.05, "H": 1.0, "maxiter": 0}, ValueError, "maxiter"),
    ({"delta0": 0.05, "H": 1.0, "extent": (-10, 10, -5, 5)}, ValueError, "square"),
    ({"delta0": 0.05, "H": 1.0, "extent": "big"}, TypeError, "extent"),
    ({"delta0": 0.05, "H": 1.0, "mu": -1.0}, ValueError, "mu"),
])
def test_bad_arguments(kwargs, exc, words):
    with pytest.raises(exc, match=words.replace("(", r"\(")):
        solve_2d(_bonded(), Punch.paraboloid(R=100), **kwargs)


def test_grid_too_coarse_for_the_layer():
    with pytest.raises(ValueError, match=r"Delta = 0\.5 > H/5 = 0\.2 \(H = 1.*n >= 160"):
        solve_2d(_bonded(), Punch.paraboloid(R=100), delta0=1.0, H=1.0, n=64, extent=16.0)


def test_contact_reaching_the_domain_boundary():
    with pytest.raises(ValueError, match=r"reaches the boundary.*domain is \[-1, 1\]"):
        solve_2d(HalfSpace(), Punch.paraboloid(R=1), delta0=1.0, n=32, extent=1.0, nu=NU)


def test_non_convergence_reports_numbers_and_last_iterate():
    with pytest.raises(ContactConvergenceError, match=r"residual .* > tol 1\.0e-10 after 3 iterations") as info:
        solve_2d(HalfSpace(), Punch.paraboloid(R=1), delta0=1.0, n=64, extent=1.3, nu=NU, maxiter=3)
    assert isinstance(info.value.result, Contact2D) and info.value.result.iterations == 3


@pytest.mark.parametrize("layer, words", [
    (BondedLayer(), "numeric Poisson ratio"),
    (HalfSpace(), "pass nu="),
])
def test_bad_layers(layer, words):
    with pytest.raises(ValueError, match=words):
        solve_2d(layer, Punch.paraboloid(R=1), delta0=1.0, H=1.0, n=32, extent=1.3)
    with pytest.raises(ValueError, match="cannot be evaluated numerically"):
        solve_2d(GenericLayer(), Punch.paraboloid(R=1), delta0=1.0, H=1.0, n=32, extent=1.3, nu=NU)


def test_bad_layer_type_and_nu():
    with pytest.raises(TypeError, match="LayerKernel"):
        solve_2d("bonded", Punch.paraboloid(R=1), delta0=1.0, H=1.0)
    with pytest.raises(ValueError, match="outside the admissible range"):
        solve_2d(HalfSpace(), Punch.paraboloid(R=1), delta0=1.0, nu=0.5, n=32, extent=1.3)


def test_bad_punches():
    with pytest.raises(ValueError, match=r"free parameter\(s\) R_1, R_2"):
        solve_2d(_bonded(), Punch.elliptic_paraboloid(), delta0=0.05, H=1.0)
    with pytest.raises(ValueError, match="does not touch the layer: min Phi = 1"):
        solve_2d(_bonded(), Punch(S.x1**2 + S.x2**2 + 1), delta0=0.5, H=1.0)
    with pytest.raises(ValueError, match="unbounded"):
        solve_2d(_bonded(), Punch(S.x1**2, name="cylinder"), delta0=0.5, H=1.0)
    with pytest.raises(TypeError, match="Punch"):
        solve_2d(_bonded(), 3.0, delta0=0.5, H=1.0)


def test_coarse_contact_warns():
    with pytest.warns(CoarseGridWarning, match="cells across"):
        solve_2d(HalfSpace(), Punch.paraboloid(R=1), delta0=0.01, n=16, extent=0.4, nu=NU)


# --------------------------------------------------------------------------- axisymmetric wrapper
def test_axisymmetric_wrapper_matches_direct_solver():
    layer, R, H, delta0 = BondedLayer(NU), 1000.0, 1.0, 0.05
    res = solve_axisymmetric(layer, Punch.paraboloid(R=R), delta0, H)
    ref = solve_axisymmetric(layer, lambda r: r**2 / (2 * R), delta0, H)
    assert isinstance(res, AxisymmetricPunchContact) and isinstance(res, AxisymmetricContact)
    assert res.contact_radius == pytest.approx(ref.radius, rel=1e-12)
    assert res.force == pytest.approx(ref.force, rel=1e-12)
    assert res.contact_area == pytest.approx(math.pi * ref.radius**2, rel=1e-12)
    assert res.punch == Punch.paraboloid(R=R)
    with pytest.raises(FrozenInstanceError):
        res.radius = 1.0
    # the result works with the check route thinlayer.numerics.surface_displacement
    assert surface_displacement(res, [0.0])[0] == pytest.approx(delta0, rel=1e-8)


def test_axisymmetric_wrapper_half_space_and_quartic():
    res = solve_axisymmetric(HalfSpace(), Punch.paraboloid(R=2), 0.5, nu=NU)
    assert res.contact_radius == pytest.approx(1.0, rel=1e-10)  # Hertz a = sqrt(R delta0)
    quartic = Punch.fourth_degree(R=1000, K=40)
    ref = solve_axisymmetric(BondedLayer(NU), lambda r: r**2 / 2000 + r**4 / 40**3, 0.05, 1.0)
    res = solve_axisymmetric(BondedLayer(NU), quartic, 0.05, 1.0)
    assert res.force == pytest.approx(ref.force, rel=1e-12)


def test_axisymmetric_wrapper_rejects_bad_punches():
    with pytest.raises(ValueError, match=r"'elliptic paraboloid' Phi = .* is not axisymmetric"):
        solve_axisymmetric(_bonded(), Punch.elliptic_paraboloid(R1=2, R2=1), 0.05, 1.0)
    with pytest.raises(ValueError, match="not axisymmetric"):
        solve_axisymmetric(_bonded(), Punch(S.x1**2 + S.x2**2 + S.x1**3 / 10), 0.05, 1.0)
    with pytest.raises(ValueError, match=r"free parameter\(s\) R"):
        solve_axisymmetric(_bonded(), Punch.paraboloid(), 0.05, 1.0)
    with pytest.raises(ValueError, match="thickness H"):
        solve_axisymmetric(_bonded(), Punch.paraboloid(R=1), 0.05)
    # a radial profile Phi(r) (callable or sympy expression in r) is accepted as well; anything else is not
    with pytest.raises(TypeError, match="Punch"):
        solve_axisymmetric(_bonded(), 3.0, 0.05, 1.0)


def test_axisymmetric_wrapper_against_2d_solver_for_a_quartic_punch():
    """Both solvers on the fourth-degree paraboloid (section 5), H/c ~ 0.2: force within 2e-3."""
    layer, H = BondedLayer(NU), 1.0
    punch = Punch.fourth_degree(R=200, K=20)
    ref = solve_axisymmetric(layer, punch, 0.1, H)
    res = solve_2d(layer, punch, delta0=0.1, H=H, n=128)
    assert res.force == pytest.approx(ref.force, rel=2e-3)
    assert abs(res.contact_radius - ref.contact_radius) < 0.1 * res.spacing


# --------------------------------------------------------------------------- long runs
@slow
def test_thin_layer_against_direct_solver_fine_grid():
    """n = 1024 (Delta = H/40): force within 1e-4 and radius within 0.05 Delta of the direct solver."""
    layer, R, delta0, H = BondedLayer(NU), 1000.0, 0.05, 1.0
    ref = solve_axisymmetric(layer, lambda r: r**2 / (2 * R), delta0, H)
    res = solve_2d(layer, Punch.paraboloid(R=R), delta0=delta0, H=H, n=1024)
    assert res.force == pytest.approx(ref.force, rel=1e-4)
    assert abs(res.contact_radius - ref.radius) < 0.05 * res.spacing


@slow
def test_hertz_grid_refinement_to_512():
    errs, hs = [], []
    for n in (64, 128, 256, 512):
        res = solve_2d(HalfSpace(), Punch.paraboloid(R=1), delta0=0.83, n=n, extent=1.25, nu=NU)
        errs.append(abs(res.force / (8 * VT * 0.83**1.5 / 3) - 1))
        hs.append(res.spacing)
        assert abs(res.contact_radius - math.sqrt(0.83)) < 0.1 * res.spacing
    assert np.polyfit(np.log(hs), np.log(errs), 1)[0] > 1.5
