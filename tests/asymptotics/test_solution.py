"""Force law (1.8), contact-area law (3.25), composite pressure and ``solve`` (section 3 of the paper).

Independent routes: the closed forms are checked against numerical integrals over the spectral
contour; the laws and the composite pressure against the direct numerical solution of the full
contact problem (:mod:`thinlayer.numerics.axisymmetric`, which uses no thin-layer series); the force defect of
the boundary layer against quadrature of the Wiener--Hopf solution.
"""
from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp

from thinlayer import BondedLayer, FrictionlessLayer, GenericLayer, Punch, PunchError, solve_axisymmetric
from thinlayer import symbols as S
from thinlayer.asymptotics.force_law import boundary_layer_force_defect, force_law, h_star
from thinlayer.asymptotics.solution import compressible_solution as solve
from thinlayer.asymptotics.wiener_hopf import boundary_layer_exact

r = sp.Symbol("r", nonnegative=True)
R1, R2 = sp.symbols("R_1 R_2", positive=True)


# ------------------------------------------------------------------------------ force defect
def test_force_defect_is_half_m1_symbolically():
    # derived from the Laplace transform of (3.23)-(3.24) with (3.20), (3.21)
    assert boundary_layer_force_defect() == sp.Symbol("m_1", real=True) / 2


@pytest.mark.parametrize("nu", ["3/10", "-1/2", "9/20"])
def test_force_defect_exact_kernel_by_quadrature(nu):
    # the exact (Wiener-Hopf) boundary layer has the same defect: it depends on the kernel through m_1 only
    sol = boundary_layer_exact(nu)
    assert sol.force_defect() == pytest.approx(float(sol.m1) / 2, abs=1e-9)


# ------------------------------------------------------------------------------ the symbolic law
def test_elliptic_paraboloid_law_symbolic():
    law = force_law(BondedLayer(), Punch.elliptic_paraboloid())
    assert law.kind == "quadratic"
    A, m1 = BondedLayer().A, BondedLayer().m(1)
    th = S.mu / (1 - S.nu)
    # leading term: vartheta/(A H) times the paraboloid's volume over the ellipse, pi delta0^2 sqrt(R1 R2)
    vol = sp.integrate(sp.integrate(
        (S.delta0 - S.x1**2 / (2 * R1) - S.x2**2 / (2 * R2)).subs({S.x1: sp.sqrt(2 * S.delta0 * R1) * r * sp.cos(S.s),
                                                                   S.x2: sp.sqrt(2 * S.delta0 * R2) * r * sp.sin(S.s)})
        * 2 * S.delta0 * sp.sqrt(R1 * R2) * r, (r, 0, 1)), (S.s, 0, 2 * sp.pi))
    assert sp.simplify(law.P0 - th / (A * S.H) * vol) == 0
    # first correction (1.8): P1/P0 = -m1 H^2 (1/R1 + 1/R2)/delta0
    rel = sp.cancel(law.P1 / law.P0 + m1 * S.H**2 * (1 / R1 + 1 / R2) / S.delta0)
    assert rel == 0 or sp.simplify(rel) == 0
    # area law: pi a b - h* H |Gamma_0| with the ellipse's perimeter 4 a E(1 - b^2/a^2)
    a, b = sp.sqrt(2 * S.delta0 * R1), sp.sqrt(2 * S.delta0 * R2)
    target = sp.pi * a * b - h_star * S.H * 4 * a * sp.elliptic_e(1 - b**2 / a**2)
    assert sp.simplify(law.contact_area - target) == 0
    for tag in ("1.8", "3.25"):
        assert rf"\tag{{{tag}}}" in law.latex()


@pytest.mark.parametrize("nu", [0.3, -0.5, 0.45])
def test_closed_forms_equal_contour_integrals(nu):
    # quadratic (rotated, shifted) and radial monomial: closed form vs spectral contour quadrature
    layer = BondedLayer(nu)
    quad = Punch(S.x1**2 / 3 + S.x1 * S.x2 / 5 + S.x2**2 / 2 - S.x1 / 7 + S.x2 / 11 + sp.Rational(1, 50))
    mono = Punch((S.x1**2 + S.x2**2) ** 2 / 4)
    for punch, kind in ((quad, "quadratic"), (mono, "radial-monomial")):
        law = force_law(layer, punch)
        assert law.kind == kind
        closed = law.evaluate(0.3, 0.02, 1.7, edge_shift=0.1)
        from thinlayer.asymptotics.contour import contact_contour

        num = law.evaluate(0.3, 0.02, 1.7, edge_shift=0.1, contour=contact_contour(punch.expr, 0.3))
        generic = type(law)(law.layer, law.punch, "contour", None, None, None, None, law.coefficient, law.p1_factor)  # numeric route  # noqa: E501 (one formula or one table row)
        num = generic.evaluate(0.3, 0.02, 1.7, edge_shift=0.1)
        for q in ("P0", "P1", "area0", "perimeter", "V", "J"):
            assert getattr(num, q) == pytest.approx(getattr(closed, q), rel=1e-10), q


def test_p1_factor_read_off_inner_expansion():
    # p_1 = (vartheta H/A) M_1 Laplacian(Phi) (4.1), M_1 = -m_1 (4.2)
    layer = BondedLayer()
    law = force_law(layer, Punch.general(4))
    assert law.kind == "contour"
    assert sp.simplify(law.p1_factor + S.mu / (1 - S.nu) * S.H * layer.m(1) / layer.A) == 0
    assert sp.simplify(law.coefficient + S.mu / (1 - S.nu) * S.H * layer.m(1) / (2 * layer.A)) == 0


def test_frictionless_base_has_no_first_correction():
    law = force_law(FrictionlessLayer(), Punch.paraboloid())
    assert law.P1 == 0


def test_force_law_lambdify_and_inverse():
    law = force_law(BondedLayer(sp.Rational(3, 10)), Punch.elliptic_paraboloid())
    f = law.lambdify()
    args = dict(zip(law.arguments, [0.5, 0.1, 2.0, 1.0, 4.0, 0.12]))
    assert [a.name for a in law.arguments] == ["delta_0", "H", "mu", "R_1", "R_2", "h^*"]
    P, area = f(*args.values())
    v = law.evaluate(0.5, 0.1, 2.0, edge_shift=0.12, parameters={"R_1": 1.0, "R_2": 4.0})
    assert P == pytest.approx(v.force, rel=1e-13) and area == pytest.approx(v.area, rel=1e-13)
    d0 = law.indentation(v.force, 0.1, 2.0, parameters={R1: 1.0, R2: 4.0})
    assert d0 == pytest.approx(0.5, rel=1e-12)


# ------------------------------------------------------------------------------ against the direct solver
def _sphere_runs(nu, ratios):
    layer, R, H = BondedLayer(nu), 1000.0, 1.0
    out = []
    for cH in ratios:
        d0 = cH**2 / (2 * R)
        direct = solve_axisymmetric(layer, r**2 / (2 * R), d0, H, error_estimate=False)
        out.append((direct, solve(layer, Punch.paraboloid(R), delta0=d0, H=H)))
    return out


@pytest.fixture(scope="module")
def sphere03():
    return _sphere_runs(0.3, (10.0, 20.0, 40.0))


def test_force_law_against_direct_solution(sphere03):
    rem, frac = [], []
    for direct, sol in sphere03:
        rem.append(direct.force / sol.force - 1)
        frac.append((direct.force - sol.force_leading) / (sol.force - sol.force_leading))
    # the first correction has the sign and size of the direct solution's deviation from P0 ...
    assert all(0.75 < q < 1.0 for q in frac) and frac[0] < frac[1] < frac[2]
    # ... and the remainder is O((H/a)^3): halving H/a divides it by ~8
    assert 7.0 < rem[0] / rem[1] < 9.0 and 7.0 < rem[1] / rem[2] < 9.0
    # the stated remainder bound P0 (H/a)^3 holds
    for (direct, sol), q in zip(sphere03, rem):
        assert abs(q) < sol.order_of_accuracy["force"][1]


def test_contact_area_against_direct_solution(sphere03):
    errs = []
    for direct, sol in sphere03:
        area = math.pi * direct.radius**2
        errs.append(area / sol.contact_area - 1)
        # the first correction accounts for most of the change from |omega_0|
        assert abs(area - sol.contact_area) < 0.1 * abs(area - sol.contact_area_leading)
        # and Alexandrov's h* does worse than the exact one
        assert abs(area - sol.contact_area) < abs(area - sol.contact_area_alexandrov)
    assert 3.0 < errs[0] / errs[1] < 5.0 and 3.0 < errs[1] / errs[2] < 5.0  # O((H/a)^2)


def test_fourth_degree_punch_against_direct_solution():
    # a non-quadratic punch (numeric contour route): Phi = r^2/2 + r^4, contact radius ~ 0.71
    layer = BondedLayer(0.3)
    punch = Punch.fourth_degree(1, 1)
    d0 = 0.25 + 0.25
    frac, rem = [], []
    for cH in (10.0, 20.0, 40.0):
        H = 1 / cH
        direct = solve_axisymmetric(layer, r**2 / 2 + r**4, d0, H, error_estimate=False)
        sol = solve(layer, punch, delta0=d0, H=H)
        assert sol.law.kind == "contour"
        frac.append((direct.force - sol.force_leading) / (sol.force - sol.force_leading))
        rem.append(direct.force / sol.force - 1)
    # sign and size of the first correction (approaching 1 like H/a), third-order remainder
    assert all(0.4 < q < 1.0 for q in frac) and frac[0] < frac[1] < frac[2] and frac[2] > 0.8
    assert rem[1] / rem[2] > 6.0


def test_composite_pressure_against_direct_solution(sphere03):
    errs, inner_errs = [], []
    for direct, sol in sphere03:
        c = direct.radius
        rr = np.linspace(0.0, 1.05 * c, 3001)
        pd = direct.pressure_at(rr)
        pc = sol.pressure(rr, 0 * rr)
        pin = np.where(rr < math.sqrt(2 * 1000.0 * sol.delta0), np.maximum(sol.composite._p_in(rr, 0 * rr), 0), 0)
        errs.append(np.abs(pc - pd).max() / pd.max())
        inner_errs.append(np.abs(pin - pd).max() / pd.max())
        assert errs[-1] < sol.order_of_accuracy["pressure_composite"][1]
    # better than the inner expansion alone, and converging at least like (H/a)^1.5
    assert all(e < 0.5 * i for e, i in zip(errs, inner_errs))
    assert errs[0] / errs[1] > 2.8 and errs[1] / errs[2] > 2.8


# ------------------------------------------------------------------------------ the composite pressure
@pytest.fixture(scope="module")
def ellipse_solution():
    return solve(BondedLayer(0.3), Punch.elliptic_paraboloid(4, 1), delta0=0.5, H=0.01)


def test_composite_equals_inner_away_from_edge(ellipse_solution):
    sol = ellipse_solution
    comp = sol.composite
    x = np.linspace(-0.5, 0.5, 11)
    X, Y = np.meshgrid(x, x / 2)
    p_inner = sol.composite.inner.lambdify()(X, Y, 0.5, 0.01, 1.0)  # v > 50 here: beyond the band
    np.testing.assert_allclose(comp(X, Y), p_inner, rtol=1e-14, atol=0)  # rounding of two lambdifications


def test_composite_zero_outside_and_nonnegative(ellipse_solution):
    sol = ellipse_solution
    rng = np.random.default_rng(3)
    X, Y = rng.uniform(-2.5, 2.5, 20000), rng.uniform(-1.3, 1.3, 20000)
    p = sol.pressure(X, Y)
    assert p.shape == X.shape and np.all(p >= 0)
    v, _ = sol.composite.local(X, Y)
    assert np.all(p[v <= sol.edge_shift] == 0)
    assert np.all(p[v > sol.edge_shift + 1e-6] > 0)
    # contact area from the pressure's support vs the area law (Monte Carlo, 3 sigma)
    frac = (p > 0).mean() * 5.0 * 2.6
    sigma = 5.0 * 2.6 * math.sqrt(frac / 13 * (1 - frac / 13) / X.size)
    assert abs(frac - sol.contact_area) < 3 * sigma + sol.order_of_accuracy["contact_area"][1] * sol.contact_area


def test_local_coordinates_on_a_circle():
    # for a paraboloid of revolution the gradient line is the radius: v = (a - r)/H exactly
    sol = solve(BondedLayer(0.3), Punch.paraboloid(2), delta0=0.25, H=0.01)
    a = 1.0
    rr = np.linspace(0.8, 1.2, 41)
    th = np.linspace(0, 2 * np.pi, 41)
    v, g = sol.composite.local(rr * np.cos(th), rr * np.sin(th))
    assert np.allclose(v, (a - rr) / 0.01, atol=1e-9)
    assert np.allclose(g, a / 2, rtol=1e-12)


def test_boundary_layer_profile_normalisation():
    # along a normal, p_c - p_in = (vartheta g/A) (Qhat(v) - v): check against the mpmath solution q(tau)
    sol = solve(BondedLayer(0.3), Punch.paraboloid(2), delta0=0.25, H=0.01)
    comp = sol.composite
    wh = boundary_layer_exact("3/10")
    th, A = 1.0 / 0.7, float(BondedLayer(0.3).A)
    for v in (0.3, 1.0, 4.0):
        x = 1.0 - v * 0.01
        q = float(wh.q(v - wh.h, dps=15))
        pin = float(comp._p_in(np.array([x]), np.array([0.0]))[0])
        expected = pin + th * 0.5 / A * (q - v)
        assert float(comp(x, 0.0)) == pytest.approx(expected, rel=1e-7)


def test_alexandrov_composite_differs_by_edge_shift():
    sol = solve(BondedLayer(0.3), Punch.paraboloid(2), delta0=0.25, H=0.01, boundary_layer="alexandrov")
    assert sol.composite.h == pytest.approx(sol.edge_shift_alexandrov, abs=1e-12)
    x = 1.0 - 0.5 * (sol.edge_shift + sol.edge_shift_alexandrov) * 0.01
    exact = solve(BondedLayer(0.3), Punch.paraboloid(2), delta0=0.25, H=0.01)
    assert float(sol.pressure(x, 0.0)) == 0.0 and float(exact.pressure(x, 0.0)) > 0.0


def test_non_symmetric_punch_composite():
    # a cubic-quartic punch with a smooth convex contour: the pressure vanishes on a curve inside Gamma_0
    punch = Punch(S.x1**2 / 2 + S.x2**2 + S.x1**3 / 5 + (S.x1**2 + S.x2**2) ** 2 / 4)
    sol = solve(BondedLayer(0.25), punch, delta0=0.3, H=0.02)
    c = sol.contour
    s = np.linspace(0, c.perimeter, 64, endpoint=False)
    pts = c.f(s)
    nrm = c.normal(s)
    for d, positive in ((-0.1, False), (sol.edge_shift - 0.05, False), (sol.edge_shift + 0.05, True), (3.0, True)):
        q = pts + d * 0.02 * nrm
        p = sol.pressure(q[:, 0], q[:, 1])
        assert np.all(p > 0) if positive else np.all(p == 0)


# ------------------------------------------------------------------------------ solve()
def test_solve_inverse_problem():
    layer = BondedLayer(0.3)
    sol = solve(layer, Punch.elliptic_paraboloid(4, 1), delta0=0.5, H=0.1, mu=2.0)
    back = solve(layer, Punch.elliptic_paraboloid(4, 1), force=sol.force, H=0.1, mu=2.0)
    assert back.delta0 == pytest.approx(0.5, rel=1e-12)
    quartic = Punch.fourth_degree(1, 1)
    sol = solve(layer, quartic, delta0=0.5, H=0.05)
    back = solve(layer, quartic, force=sol.force, H=0.05)
    assert back.delta0 == pytest.approx(0.5, rel=1e-9)
    lead = solve(layer, quartic, force=sol.force_leading, H=0.05, order=0)
    assert lead.delta0 == pytest.approx(0.5, rel=1e-9) and lead.force == lead.force_leading


def test_solve_parameters_and_output():
    sol = solve(BondedLayer("3/10"), Punch.elliptic_paraboloid(), delta0=0.5, H=0.1,
                parameters={"R_1": 4, "R_2": 1})
    assert sol.edge_shift == pytest.approx(0.12207064786, abs=1e-10)  # value of test_wiener_hopf's table
    tex = sol.latex()
    for tag in ("1.8", "3.25"):
        assert rf"\tag{{{tag}}}" in tex
    text = str(sol)
    assert "force" in text and "edge shift" in text and "Alexandrov" in text
    orders = sol.order_of_accuracy
    assert set(orders) == {"force", "contact_area", "pressure_interior", "pressure_composite"}
    assert orders["pressure_interior"][0].startswith("inner expansion with 2 terms: O(p_0 (H/a)^(4))")
    assert sol._repr_latex_().startswith("$$")


def test_solve_bad_input():
    layer, punch = BondedLayer(0.3), Punch.paraboloid(1)
    with pytest.raises(ValueError, match="delta0"):
        solve(layer, punch, delta0=0.0, H=0.1)
    with pytest.raises(ValueError, match="delta0"):
        solve(layer, punch, delta0=-1.0, H=0.1)
    with pytest.raises(ValueError, match="H"):
        solve(layer, punch, delta0=0.1, H=0.0)
    with pytest.raises(ValueError, match="H"):
        solve(layer, punch, delta0=0.1, H=-2)
    with pytest.raises(ValueError, match="no contact"):
        solve(layer, Punch(punch.expr + 1), delta0=0.5, H=0.1)
    with pytest.raises(ValueError, match="no contact"):  # a non-quadratic punch: found by the contour
        solve(layer, Punch(punch.expr + (S.x1**2 + S.x2**2) ** 2 + 1), delta0=0.5, H=0.1)
    with pytest.raises(ValueError, match="critical point|smooth"):  # a figure eight through a saddle
        solve(layer, Punch((S.x1**2 - 1) ** 2 + S.x2**2), delta0=1.0, H=0.1)
    with pytest.raises(ValueError, match="hole|simply|connected"):  # an annulus
        solve(layer, Punch((S.x1**2 + S.x2**2 - 1) ** 2), delta0=0.25, H=0.01)
    with pytest.raises(ValueError, match="components|connected"):  # two islands
        solve(layer, Punch((S.x1**2 - 1) ** 2 + S.x2**2), delta0=0.5, H=0.01)
    with pytest.raises(NotImplementedError, match="second correction"):  # (SO.9)-(SO.10) are the last derived
        solve(layer, punch, delta0=0.1, H=0.1, order=3)
    with pytest.raises(ValueError, match="numeric Poisson"):
        solve(BondedLayer(), punch, delta0=0.1, H=0.1)
    with pytest.raises(NotImplementedError, match="BondedLayer"):
        solve(GenericLayer(), punch, delta0=0.1, H=0.1)
    with pytest.raises(PunchError, match="R"):
        solve(layer, Punch.paraboloid(), delta0=0.1, H=0.1)
    with pytest.raises(PunchError, match="polynomial"):
        solve(layer, Punch.paraboloid(1).expr + sp.exp(S.x1), delta0=0.1, H=0.1)
    with pytest.raises(PunchError, match="not positive definite"):
        solve(layer, Punch(S.x1**2 - S.x2**2), delta0=0.1, H=0.1)
    with pytest.raises(TypeError, match="exactly one"):
        solve(layer, punch, delta0=0.1, force=1.0, H=0.1)
    with pytest.raises(TypeError, match="exactly one"):
        solve(layer, punch, H=0.1)
    with pytest.raises(ValueError, match="boundary_layer"):
        solve(layer, punch, delta0=0.1, H=0.1, boundary_layer="approximate")
    with pytest.raises(ValueError, match="terms"):
        solve(layer, punch, delta0=0.1, H=0.1, terms=0)
    with pytest.raises(ValueError, match="force"):
        solve(layer, punch, force=-1.0, H=0.1)
    with pytest.raises(ValueError, match="nu"):
        BondedLayer(0.7)


def test_composite_pressure_negative_edge_shift_against_direct_solution():
    # nu = 0.45: h* < 0, the contact extends beyond Gamma_0; the composite must follow it
    errs, inner_errs = [], []
    for direct, sol in _sphere_runs(0.45, (20.0, 40.0)):
        assert sol.edge_shift < 0 and direct.radius > math.sqrt(2 * 1000.0 * sol.delta0)
        rr = np.linspace(0.0, 1.05 * direct.radius, 3001)
        pd = direct.pressure_at(rr)
        a0 = math.sqrt(2 * 1000.0 * sol.delta0)
        pin = np.where(rr < a0, np.maximum(sol.composite._p_in(rr, 0 * rr), 0), 0)
        errs.append(np.abs(sol.pressure(rr, 0 * rr) - pd).max() / pd.max())
        inner_errs.append(np.abs(pin - pd).max() / pd.max())
        # the composite is zero beyond the derived edge a0 - h* H and positive inside it, except in a
        # zone where p_1 < 0 (m_1 = 2.18 here) outweighs the boundary layer's sqrt rise: width O(H (H/a)^2)
        edge = a0 - sol.edge_shift * sol.H
        assert float(sol.pressure(edge + 0.01, 0.0)) == 0
        v_zone = (float(BondedLayer(0.45).m(1)) * sol.H * 2 / 1000.0 / (a0 / 1000.0)) ** 2 * math.pi / (
            4 * float(BondedLayer(0.45).A))  # g Qhat = |p_1| A/vartheta with Qhat ~ 2 sqrt(A tau/pi)
        assert float(sol.pressure(edge - 1.5 * v_zone * sol.H, 0.0)) > 0
    assert all(e < 0.3 * i for e, i in zip(errs, inner_errs))
    assert errs[0] / errs[1] > 2.8


# ------------------------------------------------------------------------------ frictionless base
def test_frictionless_edge_shift_and_boundary_layer():
    from thinlayer.asymptotics.wiener_hopf import edge_shift_alexandrov, edge_shift_exact

    layer = FrictionlessLayer()
    hs = [edge_shift_exact(layer, normaliser=n) for n in ("alexandrov", "sqrt", "tanh")]
    assert max(hs) - min(hs) < 1e-15
    # independent: h = -(1/pi) int_0^oo log(L(t)/(A t))/t^2 dt straight from the kernel (no normaliser)
    def f(t):
        with mpmath.workdps(90):  # cosh 2t - 1 and the log of a ratio near 1 cancel ~2 log10(1/t) digits each
            t = mpmath.mpf(t)
            val = mpmath.log(2 * (mpmath.cosh(2 * t) - 1) / (t * (mpmath.sinh(2 * t) + 2 * t))) / t**2
        return +val

    with mpmath.workdps(30):
        t0 = mpmath.mpf("1e-9")
        ref = -(t0 * f(t0) + mpmath.quad(f, [t0, 0.5, 2, 8, mpmath.inf])) / mpmath.pi
    assert float(hs[0]) == pytest.approx(float(ref), abs=1e-12)
    # Alexandrov: m_1 = 0 gives B = 1/(2A) = 1, C = 2, h = 1/sqrt(2) - 1/2 (3.25)
    assert float(edge_shift_alexandrov(layer)) == pytest.approx(math.sqrt(0.5) - 0.5, abs=1e-15)
    sol = boundary_layer_exact(layer)
    assert sol.sigma == pytest.approx(math.pi)  # first zero of F(iy) = (1 - cos 2y)/(y (sin 2y + 2y))
    tau = np.linspace(0, 12, 400)
    q = sol.q_numpy(tau)
    assert abs(q[0]) < 1e-12 and np.all(q[1:] > 0)  # (3.18) to the table accuracy; positive (2.7)
    for t in (0.05, 1.0, 4.0):
        assert float(sol.q(t)) == pytest.approx(float(sol.q_numpy(t)), abs=1e-9)
    assert sol.force_defect() == pytest.approx(0.0, abs=1e-9)  # = m_1/2 = 0


def test_frictionless_solve_against_direct_solution():
    layer, R = FrictionlessLayer(), 1000.0
    rem, area_rem = [], []
    for cH in (10.0, 20.0):
        d0 = cH**2 / (2 * R)
        direct = solve_axisymmetric(layer, r**2 / (2 * R), d0, 1.0, nu=0.3, error_estimate=False)
        sol = solve(layer, Punch.paraboloid(R), delta0=d0, H=1.0, nu=0.3)
        assert sol.force == sol.force_leading  # m_1 = 0: no (H/a)^2 correction
        rem.append(direct.force / sol.force - 1)
        area_rem.append(math.pi * direct.radius**2 / sol.contact_area - 1)
        rr = np.linspace(0, 1.05 * direct.radius, 2001)
        pd = direct.pressure_at(rr)
        assert np.abs(sol.pressure(rr, 0 * rr) - pd).max() < 1e-3 * pd.max()
    assert abs(rem[0]) < (1 / 10.0) ** 3 and 7.0 < rem[0] / rem[1] < 9.0  # O((H/a)^3)
    assert 3.5 < area_rem[0] / area_rem[1] < 4.5  # O((H/a)^2) with the exact h*
    with pytest.raises(ValueError, match="nu="):
        solve(layer, Punch.paraboloid(R), delta0=0.1, H=1.0)


def test_fourth_degree_paraboloid_closed_form_against_direct_solution():
    # Phi = r^4/(4 R^3) (the paper's concluding remarks): a radial monomial, closed-form law
    R = 1.0
    punch = Punch((S.x1**2 + S.x2**2) ** 2 / (4 * R**3))
    layer = BondedLayer(0.3)
    law = force_law(BondedLayer(), Punch((S.x1**2 + S.x2**2) ** 2 / (4 * sp.Symbol("R", positive=True) ** 3)))
    assert law.kind == "radial-monomial"
    # |omega_0| = pi a^2 with a^4 = 4 R^3 delta0; V = (2/3) pi a^2 delta0 (hand integral of delta0 - r^4/(4R^3))
    Rs = sp.Symbol("R", positive=True)
    a2 = sp.sqrt(4 * Rs**3 * S.delta0)
    assert sp.simplify(law.area0 - sp.pi * a2) == 0
    assert sp.simplify(law.V - sp.Rational(2, 3) * sp.pi * a2 * S.delta0) == 0
    frac, rem = [], []
    d0 = 0.25  # a = 1
    for cH in (10.0, 20.0, 40.0):
        H = 1 / cH
        direct = solve_axisymmetric(layer, r**4 / 4, d0, H, error_estimate=False)
        sol = solve(layer, punch, delta0=d0, H=H)
        frac.append((direct.force - sol.force_leading) / (sol.force - sol.force_leading))
        rem.append(direct.force / sol.force - 1)
    assert all(0.5 < q < 1.0 for q in frac) and frac[0] < frac[1] < frac[2]
    assert rem[1] / rem[2] > 6.0
