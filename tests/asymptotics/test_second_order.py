"""Second order (SO.1)-(SO.10): the derivation checked by independent routes.

* (SO.4) ``r_3`` by three factorisations, two precisions, and Alexandrov's kernel in closed form.
* (SO.5)-(SO.7) the derived boundary layer: its transform is the one of the real-space form (SO.7) (Laplace rules),
  its far field is the inner expansion ``p_0 + p_1`` of :mod:`thinlayer.asymptotics.inner` seen from the edge, and
  the numerical profile's brackets decay (the identity ``int (qhat_0 - tau - h) = m_1/2 + h^2/2``).
* (SO.9), (SO.10) against the direct axisymmetric solver (no asymptotics): the remainders' observed orders, the
  Richardson limit of ``(P - P_0 - P_1)/(P_0 (H/a)^3)``, the error estimates, and the composite pressure.
* The closed forms of the edge integrals against a trapezoidal rule on the ellipse.
"""
from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp

from thinlayer import BondedLayer, FrictionlessLayer, Punch
from thinlayer import symbols as S
from thinlayer.asymptotics.composite import composite_pressure
from thinlayer.asymptotics.inner import inner_pressure
from thinlayer.asymptotics.second_order import (
    Phi_,
    beta,
    composite_pressure_second_order,
    edge_constants,
    eps,
    h0_,
    m1_,
    p_,
    second_order_boundary_layer,
    second_order_error_estimate,
    second_order_law,
    second_order_profile,
)
from thinlayer.asymptotics.wiener_hopf import edge_cubic, edge_shift
from thinlayer.numerics import solve_axisymmetric

SPHERE = Punch.paraboloid(R=1)
R2 = S.x1**2 + S.x2**2


def _layer(nu):
    return FrictionlessLayer() if nu == "frictionless" else BondedLayer(nu)


def _kw(nu):
    return {"nu": 0.3} if nu == "frictionless" else {}


# ------------------------------------------------------------------------------------------- (SO.4)
@pytest.mark.parametrize("nu", ["-1/2", "0", "3/10", "9/20", "49/100", "frictionless"])
def test_r3_is_the_same_for_three_factorisations_and_two_precisions(nu):
    vals = [edge_cubic(nu, normaliser=n, dps=20) for n in ("alexandrov", "sqrt", "tanh")]
    assert max(vals) - min(vals) < 1e-12 * max(1.0, abs(vals[0]))
    hi = edge_cubic(nu, dps=30)
    assert abs(hi - vals[0]) < 1e-15 * max(1.0, abs(hi))


@pytest.mark.parametrize("nu", ["0", "3/10", "9/20"])
def test_r3_of_alexandrovs_kernel_is_its_closed_form(nu):
    """With F = F~ (3.19) the factor is Phi~(p) = sqrt(1 + p/B)/(1 + p/sqrt C): its p^3 coefficient is
    1/(6 B^3) - 1/(3 C^(3/2)); the quadrature (against the sqrt normaliser) must reproduce it."""
    lay = BondedLayer(sp.Rational(nu))
    A, m1 = mpmath.mpf(sp.Rational(lay.A).p) / sp.Rational(lay.A).q, mpmath.mpf(str(sp.Rational(lay.m(1)).evalf(30)))
    invC = A**2 * (1 + mpmath.sqrt(1 + 2 * m1 / A**2))
    C = 1 / invC
    B = A * C
    closed = 1 / (6 * B**3) - 1 / (3 * C**1.5)
    num = edge_cubic(nu, kernel="alexandrov", normaliser="sqrt")
    assert abs(num - closed) < 1e-12 * abs(closed)


def test_edge_constants_collect_h_m1_r3():
    c = edge_constants(BondedLayer(sp.Rational(3, 10)))
    assert c.m1 == pytest.approx(1 / 14, rel=1e-15)  # m_1(3/10) = 1/14 (2.20)
    assert c.h_star == pytest.approx(float(edge_shift("3/10")), rel=1e-15)
    assert c.r3 == pytest.approx(float(edge_cubic("3/10", normaliser="tanh")), rel=1e-12)
    assert c.r3_spread < 1e-12
    with pytest.raises(ValueError, match="numeric layer"):
        edge_constants(BondedLayer())


# ------------------------------------------------------------------------------------------- (SO.5)-(SO.8)
def test_transform_is_that_of_the_real_space_form():
    """(SO.6) -> (SO.7): L[tau f] = -d/dp L[f], L[int_0^tau f] = L[f]/p with L[qhat_0] = 1/(p^2 Phi)."""
    bl = second_order_boundary_layer()
    Phi = Phi_(p_)
    L_q0 = 1 / (p_**2 * Phi)
    L_tau_q0 = -sp.diff(L_q0, p_)
    L_I0 = L_q0 / p_
    real_space = L_q0 + eps * (h0_ * L_q0 / 2 + L_tau_q0 / 2 - L_I0) + beta * (-2 * L_I0)
    diff = sp.expand(bl.transform - real_space)
    assert diff == 0 or sp.simplify(diff) == 0


def test_far_field_is_the_inner_expansion_seen_from_the_edge():
    """The boundary layer's polynomial tail must be p_0 + p_1 of the inner expansion (2.26), (4.1), computed by
    the inner stage for a sphere R on a layer with m_1 = m, in the boundary-layer variables:
    v = (a - r)/H, eps = H/a, beta = H Phi_nn/(2 g) = H/(2 a), p = (vartheta g/A) qhat, g = a/R."""
    bl = second_order_boundary_layer()
    nu = sp.Rational(9, 20)
    lay = BondedLayer(nu)
    R, a, H, v = sp.symbols("R a H_ v", positive=True)
    inner = inner_pressure(lay, Punch(R2 / (2 * R)), order=2)
    p_in = sp.expand(inner.pressure.subs({S.x2: 0, S.x1: a - H * v, S.delta0: a**2 / (2 * R), S.H: H}))
    scale = lay.vartheta * (a / R) / lay.A
    qin = sp.expand(sp.simplify(p_in / scale))
    far = bl.far_field.subs({sp.Symbol("v"): v, eps: H / a, beta: H / (2 * a), m1_: lay.m(1)})
    assert sp.expand(qin - far) == 0


def test_edge_and_defect_reduce_to_the_first_order_ones():
    """eps = beta = 0: h = h^* (3.18) and A D = m_1/2 (the first-order defect of :mod:`force_law`)."""
    bl = second_order_boundary_layer()
    assert bl.edge_shift.subs({eps: 0, beta: 0}) == h0_
    assert sp.expand(bl.force_defect.subs({eps: 0, beta: 0}) - m1_ / 2) == 0
    assert "SO.5" in bl.latex() and "SO.8" in bl.latex()


@pytest.mark.parametrize("nu", [0.0, 0.3, 0.45, "frictionless"])
def test_profile_brackets_decay(nu):
    """Each bracket of qhat minus its far field decays: this checks int_0^oo (qhat_0 - tau - h) = m_1/2 + h^2/2
    (the identity behind A D = m_1/2) on the Wiener-Hopf table, an independent route."""
    prof = second_order_profile(_layer(nu))
    v = prof.h_star + prof.tau_max * np.array([0.7, 1.0, 2.0])  # qhat_0 - tau - h* ~ e^{-36 tau/tau_max}
    for e_, b_ in ((0.1, 0.0), (0.0, 0.1), (0.05, 0.02)):
        assert np.all(np.abs(prof.decaying(v + prof.edge(e_, b_) - prof.h_star, e_, b_)) < 1e-8)
    assert float(prof.Qhat(prof.edge(0.05, 0.02), 0.05, 0.02)) == 0.0  # (3.18) at the shifted edge


# ------------------------------------------------------------------------------------------- against the direct solver
def _remainders(layer, punch, nus_kw, hs, d0=0.5):
    law = second_order_law(layer, punch)
    rows = []
    a = law.evaluate(d0, 1.0, 1.0, **nus_kw).first.half_width
    for e in hs:
        v = law.evaluate(d0, e * a, 1.0, **nus_kw)
        d = solve_axisymmetric(layer, punch, d0, e * a, 1.0, **nus_kw)
        rows.append({
            "eps": e, "v": v, "d": d,
            "P1": (d.force - v.force_first) / v.P0, "P2": (d.force - v.force) / v.P0,
            "A1": (d.contact_area - v.area_first) / v.area0, "A2": (d.contact_area - v.area) / v.area0,
        })
    return rows


def _orders(rows, key):
    return [math.log(abs(r0[key] / r1[key])) / math.log(r0["eps"] / r1["eps"]) for r0, r1 in zip(rows, rows[1:])]


@pytest.mark.parametrize("nu, hs", [(0.3, (0.2, 0.1, 0.05)), (0.0, (0.2, 0.1, 0.05)),
                                    ("frictionless", (0.2, 0.1, 0.05)), (0.45, (0.035, 0.025, 0.0175, 0.0125))])
def test_sphere_remainders_fall_at_fourth_and_third_order(nu, hs):
    rows = _remainders(_layer(nu), SPHERE, _kw(nu), hs)
    assert min(_orders(rows, "P2")) >= 3.8, [(r["eps"], r["P2"]) for r in rows]
    assert min(_orders(rows, "A2")) >= 2.8, [(r["eps"], r["A2"]) for r in rows]
    for r in rows:  # the new terms improve on the first order
        assert abs(r["P2"]) < abs(r["P1"]) / 3 and abs(r["A2"]) < abs(r["A1"])


@pytest.mark.parametrize("nu, hs", [(0.3, (0.1, 0.07, 0.05, 0.035, 0.025)),
                                    (0.45, (0.05, 0.035, 0.025, 0.018, 0.0125))])
def test_richardson_limit_of_the_direct_solver_is_12_r3(nu, hs):
    """The new force coefficient from the direct solver alone: c(eps) = (P - P0 - P1)/(P0 eps^3) extrapolated to
    eps = 0 (polynomial of degree 2 through five points) equals 12 r_3 of the sphere (SO.9)."""
    rows = _remainders(_layer(nu), SPHERE, _kw(nu), hs)
    c = np.array([r["P1"] / r["eps"] ** 3 for r in rows])
    limit = np.polyfit(np.array(hs), c, 2)[-1]
    assert limit == pytest.approx(edge_constants(_layer(nu)).sphere_coefficient, rel=1e-4)


@pytest.mark.parametrize("which", ["quartic", "mixed"])
@pytest.mark.parametrize("nu", [0.0, 0.3, 0.45])
def test_other_punches_fall_at_fourth_and_third_order(which, nu):
    """Phi = r^4/4 (closed forms of the radial monomial) and Phi = r^2/2 + r^4/4 (numerical contour)."""
    punch = Punch(R2**2 / 4) if which == "quartic" else Punch(R2 / 2 + R2**2 / 4)
    assert second_order_law(_layer(nu), punch).first.kind == ("radial-monomial" if which == "quartic" else "contour")
    rows = _remainders(_layer(nu), punch, {}, (0.1, 0.07, 0.05))
    assert min(_orders(rows, "P2")) >= 3.75
    assert min(_orders(rows, "A2")) >= 2.7
    assert abs(rows[-1]["P2"]) < abs(rows[-1]["P1"]) / 4


def test_error_estimates_bound_the_true_errors():
    """E_P, E_A of :func:`second_order_error_estimate` against the direct solver: 3 punches x 4 nu x 4 H/a."""
    worst = {"force": math.inf, "contact_area": math.inf}
    for punch in (SPHERE, Punch(R2**2 / 4), Punch(R2 / 2 + R2**2 / 4)):
        for nu in (0.0, 0.3, 0.45, 0.49):
            for r in _remainders(BondedLayer(nu), punch, {}, (0.2, 0.14, 0.1, 0.05)):
                est = second_order_error_estimate(r["v"])
                worst["force"] = min(worst["force"], est["force"] / abs(r["P2"]))
                worst["contact_area"] = min(worst["contact_area"], est["contact_area"] / abs(r["A2"]))
    assert worst["force"] >= 1.0 and worst["contact_area"] >= 1.0, worst


@pytest.mark.parametrize("nu", [0.0, 0.3, 0.45])
def test_composite_pressure_second_order_against_the_direct_solver(nu):
    """max |p_c - p_direct|/p_max near the edge: first-order composite O(H/a), second order at least O((H/a)^2)."""
    lay = BondedLayer(nu)
    errs1, errs2 = [], []
    for e in (0.1, 0.05, 0.025):
        d = solve_axisymmetric(lay, SPHERE, 0.5, e)
        r = np.linspace(0.0, 1.0, 4001)
        pd = d.pressure_at(r)
        pm = pd.max()
        errs1.append(np.abs(composite_pressure(lay, SPHERE, 0.5, e)(r, 0 * r) - pd).max() / pm)
        errs2.append(np.abs(composite_pressure_second_order(lay, SPHERE, 0.5, e)(r, 0 * r) - pd).max() / pm)
    assert all(e2 < e1 for e1, e2 in zip(errs1, errs2))
    assert math.log(errs2[0] / errs2[2]) / math.log(4) >= 2.0, errs2


# ------------------------------------------------------------------------------------------- closed forms
def test_ellipse_edge_integrals_against_the_trapezoidal_rule():
    """E1 = oint (Lap Phi + Phi_nn) ds with K(m), E(m), and E2 = oint Lap/|grad| ds, for R1/R2 = 4."""
    R1, R2_, d0 = 4.0, 1.0, 0.5
    law = second_order_law(BondedLayer(0.3), Punch.elliptic_paraboloid(R1=R1, R2=R2_))
    v = law.evaluate(d0, 0.05)
    a1, a2 = math.sqrt(2 * R1 * d0), math.sqrt(2 * R2_ * d0)
    t = 2 * np.pi * np.arange(4096) / 4096
    x, y = a1 * np.cos(t), a2 * np.sin(t)
    speed = np.hypot(a1 * np.sin(t), a2 * np.cos(t))
    gx, gy = x / R1, y / R2_
    g2 = gx * gx + gy * gy
    lap = 1 / R1 + 1 / R2_
    phinn = (gx * gx / R1 + gy * gy / R2_) / g2
    E1 = np.sum((lap + phinn) * speed) * 2 * np.pi / 4096
    E2 = np.sum(lap / np.sqrt(g2) * speed) * 2 * np.pi / 4096
    assert v.E1 == pytest.approx(E1, rel=1e-12) and v.E2 == pytest.approx(E2, rel=1e-12)


def test_lambdify_and_codegen_agree_with_evaluate():
    lay = BondedLayer(sp.Rational(3, 10))
    law = second_order_law(lay, SPHERE)
    f = law.lambdify()
    assert [q.name for q in law.arguments if q.name not in ("r_3", "h^*")] == ["delta_0", "H", "mu"]
    P, A = f(0.5, 0.05, 2.0)
    v = law.evaluate(0.5, 0.05, 2.0)
    assert P == pytest.approx(v.force, rel=1e-13) and A == pytest.approx(v.area, rel=1e-13)
    args, outs = law.codegen_expressions()
    assert set(outs) == {"force", "contact_area"}
    ell = second_order_law(lay, Punch.elliptic_paraboloid(R1=4, R2=1))
    with pytest.raises(ValueError, match="elliptic integrals"):
        ell.codegen_expressions()
    Pe, Ae = ell.lambdify()(0.5, 0.05, 1.0)
    ve = ell.evaluate(0.5, 0.05, 1.0)
    assert Pe == pytest.approx(ve.force, rel=1e-12) and Ae == pytest.approx(ve.area, rel=1e-12)
