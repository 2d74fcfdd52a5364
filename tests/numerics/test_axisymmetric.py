"""Tests of the direct axisymmetric contact solver :mod:`thinlayer.numerics.axisymmetric`.

The expected values come from routes independent of the solver:

* Hertz's closed form for the half-space (L = 1), derived below from Boussinesq's solution;
* a first-order large-H correction of Hertz (rigid-base shift of the displacement);
* the surface displacement recomputed in physical space with complete elliptic integrals;
* the thin-layer force law (derived here from the inner expansion (2.26)-(2.31) plus the
  Wiener-Hopf boundary layer (3.15)) and the exact Wiener-Hopf edge shift, both evaluated by
  quadrature of L(u) only -- the solver never sees A or m_1.

Derivations used as references
------------------------------
Hertz (L = 1).  With vartheta = mu/(1-nu) Boussinesq reads w = (1/(2 pi vartheta)) iint p/|x-y|.
For p = p0 sqrt(1 - r^2/c^2) the classical potential integral gives, for r < c,
iint p/|x-y| dy = (pi^2 p0/(4c)) (2c^2 - r^2), so w = pi p0 (2c^2 - r^2)/(8 c vartheta).  Matching
w = delta0 - r^2/(2R): p0 = 4 vartheta c/(pi R), delta0 = c^2/R, and P = (2/3) pi c^2 p0 = 8 vartheta c^3/(3R).

Large H.  L(aH) - 1 is concentrated at a ~ 1/H, where pbar(a) J0(a r) ~ pbar(0) = P/(2 pi); so
u3 = u3_Hertz - kappa0 P/(2 pi vartheta H) + O(P c^2/(vartheta H^3)), kappa0 = int_0^oo (1 - L(u)) du: a
rigid shift.  At fixed c:  P = 8 vartheta c^3/(3R) and delta0 R/c^2 = 1 - 4 kappa0 c/(3 pi H), up to O((c/H)^3).

Thin layer.  u3 = (A H/vartheta) K(H sqrt(-Laplacian)) p with K(k) = L(k)/(A k) = 1 + m_1 k^2 + ... (2.20),
so the inner pressure is p = vartheta/(A H) (delta0 - Phi - 2 m_1 H^2/R) for the paraboloid
(the printed (2.30), (2.31) have the opposite sign).  Near the edge, with v = (c0 - r)/H,
the Wiener-Hopf problem (3.15) with K = K+ K-, K+(k) = 1 + K1 k + K2 k^2 + ..., has the bounded solution
Q+(k) = -g/(k^2 K+(k)); hence the edge lies at v = h* = -i K1, i.e.

    h* = -(1/pi) int_0^oo log(L(t)/(A t)) t^{-2} dt,

(Alexandrov's (3.19) gives h = sqrt(A/B) - 1/(2B), (3.25)), and the force per unit length of edge differs
from the inner linear profile's by g H^2 (K2 - K1^2/2) = g H^2 m_1/2.  Integrating: inner part
-4 m_1 H^2/(R delta0), boundary layer +2 m_1 H^2/(R delta0), hence

    P = (pi vartheta R delta0^2/(A H)) [1 - 2 m_1 H^2/(R delta0) + O(eps^3)],    eps = H/sqrt(2 R delta0),

and c = sqrt(2 R delta0) - h* H + O(H eps).
"""
from __future__ import annotations

import math
from dataclasses import FrozenInstanceError

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy import integrate

from thinlayer import BondedLayer, FrictionlessLayer, GenericLayer, HalfSpace
from thinlayer.numerics import (
    AxisymmetricContact,
    contact_for_radius,
    solve_axisymmetric,
    surface_displacement,
)
from thinlayer.numerics._spectral import basis_transform

slow = pytest.mark.slow


# --------------------------------------------------------------------------- references
def hertz(R: float, delta0: float, vartheta: float) -> tuple[float, float]:
    """Hertz contact radius and force for L = 1 (module docstring)."""
    c = math.sqrt(R * delta0)
    return c, 8 * vartheta * c**3 / (3 * R)


def exact_edge_shift(layer) -> float:
    """Wiener-Hopf edge shift h* = -(1/pi) int_0^oo log(L(t)/(A t))/t^2 dt (module docstring), in mpmath."""
    with mpmath.workdps(30):
        A = layer.L_numeric(0, "mpmath", over_u=True)  # lim L(t)/t (2.4), at the working precision

        def f(t):
            return mpmath.log(layer.L_numeric(t, "mpmath", over_u=True) / A) / t**2

        t0 = mpmath.mpf("1e-8")  # below t0 the integrand is m_1 + O(t^2): add t0 f(t0), error O(t0^3)
        total = t0 * f(t0) + mpmath.quad(f, [t0, 0.5, 2, 8, mpmath.inf])
    return -float(total) / math.pi


def alexandrov_edge_shift(layer) -> float:
    """(3.25) with (3.19), B/C = A and the derived second condition m_1 = 1/(2B^2) - 1/C."""
    A, m1 = float(layer.A), float(layer.m(1))
    B = (-A + math.sqrt(A * A + 2 * m1)) / (2 * m1)
    return math.sqrt(A / B) - 1 / (2 * B)


def paraboloid(R: float):
    return lambda r: r**2 / (2 * R)


def thin_layer_run(layer, c_over_H: float, nu=None, R: float = 1000.0, H: float = 1.0):
    """Solve at delta0 with sqrt(2 R delta0) = c_over_H * H; return (eps, P/P0 - 1, predicted, (c - c0)/H)."""
    delta0 = c_over_H**2 * H**2 / (2 * R)
    res = solve_axisymmetric(layer, paraboloid(R), delta0, H, nu=nu)
    A, m1 = float(layer.A), float(layer.m(1))
    P0 = math.pi * res.vartheta * R * delta0**2 / (A * H)  # leading term, (2.29) integrated (1.8)
    c0 = math.sqrt(2 * R * delta0)  # (3.1)
    return H / c0, res.force / P0 - 1, -2 * m1 * H**2 / (R * delta0), (res.radius - c0) / H, res


# --------------------------------------------------------------------------- building blocks
@pytest.mark.parametrize("n", [0, 1, 3])
@pytest.mark.parametrize("b", [0.7, 6.0])
def test_basis_hankel_transform_against_quadrature(n, b):
    # int_0^1 (1-x^2)^{-1/2} P_n^{(0,-1/2)}(1-2x^2) J0(b x) x dx, by mpmath with x = sin(theta)
    mpmath.mp.dps = 20
    f = lambda th: mpmath.jacobi(n, 0, -0.5, mpmath.cos(2 * th)) * mpmath.besselj(0, b * mpmath.sin(th)) \
        * mpmath.sin(th)
    ref = float(mpmath.quad(f, [0, mpmath.pi / 4, mpmath.pi / 2]))
    assert float(basis_transform(n, np.array(b))) == pytest.approx(ref, rel=1e-12, abs=1e-14)


# --------------------------------------------------------------------------- half-space limit
def test_hertz_half_space_exact():
    R, delta0, nu = 2.0, 0.01, 0.3
    vt = 1 / (1 - nu)
    res = solve_axisymmetric(HalfSpace(), paraboloid(R), delta0, H=1.0, nu=nu)
    c, P = hertz(R, delta0, vt)
    assert res.radius == pytest.approx(c, rel=1e-10)
    assert res.force == pytest.approx(P, rel=1e-10)  # (1.8)
    p_hertz = 4 * vt * c / (math.pi * R) * np.sqrt(np.clip(1 - res.r**2 / c**2, 0, None))
    # (the end point r = c is excluded: sqrt(c - r) there amplifies the 1e-12 difference of the radii)
    assert np.max(np.abs(res.pressure - p_hertz)[:-1]) < 1e-9 * p_hertz[0]


def test_hertz_with_mu_scales_force():
    # P is proportional to vartheta = mu/(1-nu) (2.1); c does not depend on it
    a = solve_axisymmetric(HalfSpace(), paraboloid(1.0), 0.01, 1.0, mu=3.0, nu=0.25)
    c, P = hertz(1.0, 0.01, 3.0 / 0.75)
    assert (a.radius, a.force) == (pytest.approx(c, rel=1e-10), pytest.approx(P, rel=1e-10))


@pytest.mark.parametrize("H_over_c", [50.0, 200.0])
def test_thick_bonded_layer_tends_to_hertz(H_over_c):
    layer, nu, R = BondedLayer(0.3), 0.3, 1.0
    vt = 1 / (1 - nu)
    kappa0 = integrate.quad(lambda u: 1 - float(layer.L_numeric(u)), 0, np.inf, limit=200)[0]
    # fixed contact radius: P is Hertz's to O((c/H)^3), delta0 carries the rigid-base shift
    c = 1.0
    res = contact_for_radius(layer, paraboloid(R), c, H_over_c * c)
    assert res.force == pytest.approx(8 * vt * c**3 / (3 * R), rel=2 / H_over_c**3)
    assert res.delta0 * R / c**2 - 1 == pytest.approx(-4 * kappa0 * c / (3 * math.pi * H_over_c),
                                                     rel=0.01, abs=1 / H_over_c**2)
    # prescribed depth: close to Hertz (radius within 1% at H = 50 c), deviations ~ c/H, as predicted
    delta0 = 0.01
    cH, PH = hertz(R, delta0, vt)
    res = solve_axisymmetric(layer, paraboloid(R), delta0, H_over_c * cH)
    first_order = 2 * kappa0 / (3 * math.pi * H_over_c)  # c/c_H - 1 from delta_eff = delta0 + kappa0 P/(2 pi vt H)
    assert abs(res.radius / cH - 1) < 0.01
    assert res.radius / cH - 1 == pytest.approx(first_order, rel=0.05)
    assert res.force / PH - 1 == pytest.approx(3 * first_order, rel=0.05)


# --------------------------------------------------------------------------- consistency of the solution
@pytest.fixture(scope="module")
def thin_045():
    return solve_axisymmetric(BondedLayer(0.45), paraboloid(1000.0), 0.05, 1.0)  # c0/H = 10


def test_displacement_matches_punch_inside_and_gap_outside(thin_045):
    res = thin_045
    c, R, d0 = res.radius, 1000.0, res.delta0
    inside = c * np.array([0.0, 0.4, 0.8, 0.97, 0.999])
    u = surface_displacement(res, inside)  # physical-space elliptic-integral route
    np.testing.assert_allclose(u, d0 - inside**2 / (2 * R), rtol=0, atol=1e-10 * d0)  # (1.5), equality
    outside = c * np.array([1.002, 1.05, 1.3])
    gap = surface_displacement(res, outside) - (d0 - outside**2 / (2 * R))
    assert np.all(gap > 0)  # (1.5), inequality
    assert np.all(np.diff(gap) > 0)


def test_pressure_admissible_and_force_by_quadrature(thin_045):
    res = thin_045
    assert np.all(res.pressure >= -1e-12 * res.pressure.max())  # (2.7)
    assert res.pressure[-1] == 0.0 and res.r[-1] == res.radius
    # bounded edge: p ~ const * sqrt(c - r)  (pressure vanishes continuously, (3.18))
    eta = np.array([1e-4, 1e-6])
    k = res.pressure_at(res.radius * (1 - eta)) / np.sqrt(eta)
    assert k[1] == pytest.approx(k[0], rel=1e-3) and k[0] > 0
    P = 2 * math.pi * integrate.quad(lambda r: float(res.pressure_at(r)) * r, 0, res.radius,
                                     limit=200, epsrel=1e-12)[0]
    assert res.force == pytest.approx(P, rel=1e-10)  # (1.8)


def test_spectral_convergence_in_modes(thin_045):
    res = thin_045
    fine = solve_axisymmetric(BondedLayer(0.45), paraboloid(1000.0), 0.05, 1.0, n=int(1.6 * res.modes),
                              error_estimate=False)
    assert abs(fine.force / res.force - 1) < 1e-9
    assert abs(fine.radius - res.radius) < 1e-7
    assert res.force_error < 1e-8 and res.radius_error < 1e-6  # the coarse-vs-fine estimates


def test_sympy_profile_equals_callable():
    r, R = sp.Symbol("r"), 1000.0
    a = solve_axisymmetric(BondedLayer(0.3), r**2 / (2 * R), 0.05, 1.0, error_estimate=False)
    b = solve_axisymmetric(BondedLayer(0.3), paraboloid(R), 0.05, 1.0, error_estimate=False)
    assert a.radius == pytest.approx(b.radius, rel=1e-13) and a.force == pytest.approx(b.force, rel=1e-13)


def test_result_is_frozen_and_prints(thin_045):
    with pytest.raises(FrozenInstanceError):
        thin_045.radius = 1.0
    with pytest.raises(ValueError):
        thin_045.pressure[0] = 1.0
    assert isinstance(thin_045, AxisymmetricContact)
    assert "c = " in thin_045.latex() and "P = " in thin_045.latex()


# --------------------------------------------------------------------------- thin-layer asymptotics
@pytest.mark.parametrize("nu, c_over_H", [(0.45, 40.0), (0.3, 30.0)])
def test_inner_pressure_correction_sign(nu, c_over_H):
    # centre pressure = vartheta/(A H) (delta0 - 2 m_1 H^2/R) up to exp(-gamma c/H): derived (2.30), (2.31)
    layer, R, H = BondedLayer(nu), 1000.0, 1.0
    delta0 = c_over_H**2 / (2 * R)
    res = solve_axisymmetric(layer, paraboloid(R), delta0, H, error_estimate=False)
    A, m1 = float(layer.A), float(layer.m(1))
    shift = float(res.pressure_at(0.0)) * A * H / res.vartheta - delta0
    assert shift == pytest.approx(-2 * m1 * H**2 / R, rel=1e-6)


@pytest.mark.parametrize("nu", [0.45, 0.3])
def test_thin_layer_force_law(nu):
    layer = BondedLayer(nu)
    _, dev1, pred1, _, _ = thin_layer_run(layer, 10.0)
    _, dev2, pred2, _, _ = thin_layer_run(layer, 20.0)
    # sign and size of the eps^2 correction -2 m_1 H^2/(R delta0)
    assert np.sign(dev2) == np.sign(pred2) and 0.8 < dev2 / pred2 < 1.0
    # the remainder is O(eps^3): halving eps divides it by ~8
    ratio = (dev1 - pred1) / (dev2 - pred2)
    assert 7.0 < ratio < 9.5


def test_frictionless_base_force_law_third_order():
    # frictionless base: m_1 = 0, so P/P0 - 1 = O(eps^3) directly
    layer = FrictionlessLayer()
    assert float(layer.m(1)) == 0
    e1, dev1, _, _, _ = thin_layer_run(layer, 10.0, nu=0.3)
    _, dev2, _, s2, _ = thin_layer_run(layer, 20.0, nu=0.3)
    assert abs(dev1) < e1**3 and 7.0 < dev1 / dev2 < 9.5
    assert s2 == pytest.approx(-exact_edge_shift(layer), abs=2e-3)


@pytest.mark.parametrize("nu", [0.45, 0.3])
def test_edge_shift_two_point(nu):
    layer = BondedLayer(nu)
    *_, s1, _ = thin_layer_run(layer, 10.0)
    *_, s2, _ = thin_layer_run(layer, 20.0)
    extrap = 2 * s2 - s1  # removes the O(eps) term
    assert extrap == pytest.approx(-exact_edge_shift(layer), abs=0.015)


# --------------------------------------------------------------------------- slow convergence study
@slow
@pytest.mark.parametrize("nu", [0.45, 0.3])
def test_thin_layer_convergence_study(nu):
    layer = BondedLayer(nu)
    rows = [thin_layer_run(layer, cH) for cH in (10.0, 20.0, 40.0, 80.0)]
    rem = [dev - pred for _, dev, pred, _, _ in rows]
    ratios = [rem[i] / rem[i + 1] for i in range(3)]
    shifts = [s for *_, s, _ in rows]
    h_exact, h_alex = exact_edge_shift(layer), alexandrov_edge_shift(layer)
    # Richardson in eps (ratio 2): s = -h + a eps + b eps^2
    rich = [(8 * shifts[i + 2] - 6 * shifts[i + 1] + shifts[i]) / 3 for i in range(2)]
    print(f"\nnu={nu}: A={float(layer.A):.6f} m1={float(layer.m(1)):.6f}")
    for (eps, dev, pred, s, res), r in zip(rows, rem):
        print(f"  c0/H={1 / eps:5.1f} modes={res.modes:3d} P/P0-1={dev:+.9e} -2m1H^2/(R d0)={pred:+.9e} "
              f"remainder={r:+.4e} rem*(c0/H)^3={r / eps**3:+.5f} (c-c0)/H={s:+.8f} "
              f"err(c)={res.radius_error:.1e} err(P)={res.force_error:.1e}")
    print(f"  remainder ratios (eps halved): {ratios}")
    print(f"  (c-c0)/H Richardson: {rich}; exact -h* = {-h_exact:.7f}; Alexandrov -h = {-h_alex:.7f}")
    for (_, dev, pred, _, _) in rows:
        assert np.sign(dev) == np.sign(pred)
    for q in ratios:
        assert 7.5 < q < 8.6  # remainder O(eps^3)
    assert rich[-1] == pytest.approx(-h_exact, abs=2e-4)
    assert abs(rich[-1] + h_exact) < 0.1 * abs(h_alex - h_exact)  # resolves the exact shift, not (3.25)'s


@slow
def test_default_modes_converged_at_large_ratio():
    layer = BondedLayer(0.45)
    R, H, d0 = 1000.0, 1.0, 80.0**2 / 2000.0
    a = solve_axisymmetric(layer, paraboloid(R), d0, H, error_estimate=False)
    b = solve_axisymmetric(layer, paraboloid(R), d0, H, n=int(1.5 * a.modes), error_estimate=False)
    assert abs(a.force / b.force - 1) < 1e-10 and abs(a.radius - b.radius) < 1e-7


# --------------------------------------------------------------------------- bad input
def test_bad_input_messages():
    good = paraboloid(1.0)
    with pytest.raises(TypeError, match="layer"):
        solve_axisymmetric("bonded", good, 0.1, 1.0)
    with pytest.raises(ValueError, match="numeric Poisson"):
        solve_axisymmetric(BondedLayer(), good, 0.1, 1.0)
    with pytest.raises(ValueError, match="cannot be evaluated"):
        solve_axisymmetric(GenericLayer(), good, 0.1, 1.0, nu=0.3)
    with pytest.raises(ValueError, match="nu="):
        solve_axisymmetric(HalfSpace(), good, 0.1, 1.0)
    with pytest.raises(ValueError, match="disagrees"):
        solve_axisymmetric(BondedLayer(0.3), good, 0.1, 1.0, nu=0.2)
    with pytest.raises(ValueError, match="delta0"):
        solve_axisymmetric(BondedLayer(0.3), good, -0.1, 1.0)
    with pytest.raises(ValueError, match="H"):
        solve_axisymmetric(BondedLayer(0.3), good, 0.1, 0.0)
    with pytest.raises(TypeError, match="delta0"):
        solve_axisymmetric(BondedLayer(0.3), good, "0.1", 1.0)
    with pytest.raises(TypeError, match="n "):
        solve_axisymmetric(BondedLayer(0.3), good, 0.1, 1.0, n=10.5)
    with pytest.raises(ValueError, match="n "):
        solve_axisymmetric(BondedLayer(0.3), good, 0.1, 1.0, n=2)
    with pytest.raises(ValueError, match="free symbols"):
        solve_axisymmetric(BondedLayer(0.3), sp.Symbol("r") ** 2 / sp.Symbol("R"), 0.1, 1.0)
    with pytest.raises(TypeError, match="Phi_r"):
        solve_axisymmetric(BondedLayer(0.3), 3.0, 0.1, 1.0)
    with pytest.raises(ValueError, match="never reaches"):
        solve_axisymmetric(BondedLayer(0.3), lambda r: 1 - np.exp(-r), 2.0, 1.0)
    with pytest.raises(ValueError, match="radius"):
        contact_for_radius(BondedLayer(0.3), good, 0.0, 1.0)
    with pytest.raises(TypeError, match="AxisymmetricContact"):
        surface_displacement(None, [0.0])


# --------------------------------------------------------------------------- one solver, two ways to give the punch
def test_punch_and_profile_forms_agree():
    from thinlayer import Punch

    R = 1000.0
    a = solve_axisymmetric(BondedLayer(0.3), Punch.paraboloid(R=R), 0.05, 1.0, error_estimate=False)
    b = solve_axisymmetric(BondedLayer(0.3), "x_1**2/2000 + x_2**2/2000", 0.05, 1.0, error_estimate=False)
    c = solve_axisymmetric(BondedLayer(0.3), paraboloid(R), 0.05, 1.0, error_estimate=False)
    assert a.punch == Punch.paraboloid(R=R) and b.punch is not None and c.punch is None
    assert a.force == pytest.approx(c.force, rel=1e-12) and b.radius == pytest.approx(c.radius, rel=1e-12)
    assert a.contact_radius == a.radius and a.contact_area == pytest.approx(math.pi * a.radius**2)
    d = contact_for_radius(BondedLayer(0.3), Punch.paraboloid(R=R), a.radius, 1.0, error_estimate=False)
    assert d.delta0 == pytest.approx(0.05, rel=1e-9) and d.punch == a.punch


def test_half_space_needs_no_thickness():
    res = solve_axisymmetric(HalfSpace(), paraboloid(2.0), 0.5, nu=0.3, error_estimate=False)
    assert res.radius == pytest.approx(1.0, rel=1e-10)
    with pytest.raises(ValueError, match="thickness H"):
        solve_axisymmetric(BondedLayer(0.3), paraboloid(2.0), 0.5)


def test_numeric_layer_nu():
    from thinlayer.layers.kernels import IncompressibleLayer
    from thinlayer.numerics._layer import numeric_layer_nu

    assert numeric_layer_nu(BondedLayer(0.3), None) == 0.3
    assert numeric_layer_nu(BondedLayer(0.3), 0.3) == 0.3
    assert numeric_layer_nu(FrictionlessLayer(), 0.25) == 0.25
    assert numeric_layer_nu(IncompressibleLayer(), None) == 0.5
    with pytest.raises(ValueError, match="admissible"):
        numeric_layer_nu(HalfSpace(), 0.5)
    with pytest.raises(TypeError, match="nu must be"):
        numeric_layer_nu(HalfSpace(), "0.3")
