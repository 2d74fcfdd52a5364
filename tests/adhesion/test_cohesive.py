"""Maugis-Dugdale adhesion on the layer (thinlayer.numerics.cohesive, (D.1)-(D.9); issue 26 item 2).

Independent routes: the half-space equations derived by sympy from (D.3)-(D.6) with ``k = 0`` against Maugis (1992)
as printed; the solver (quadrature of the Abel load and of the zone integrals, collocation of (F.6)) against those
closed forms solved by mpmath; the JKR limit against the JKR direct solver of thinlayer.numerics.adhesion (J.5); the
DMT limit 2 pi w R; refinement in the collocation nodes.
"""
import functools
import math
import os

import mpmath as mp
import numpy as np
import pytest
import sympy as sp
from scipy import optimize

from thinlayer import BondedLayer, FrictionlessLayer, HalfSpace, Punch
from thinlayer._checks import InputError
from thinlayer.numerics.adhesion import adhesive_state
from thinlayer.numerics.cohesive import (
    LAMBDA_OVER_TABOR,
    half_space_equations,
    maugis_dugdale,
    maugis_lambda,
    pull_off,
    tabor_parameter,
)

SLOW = os.environ.get("THINLAYER_SLOW") == "1"
slow = pytest.mark.skipif(not SLOW, reason="long validation run: THINLAYER_SLOW=1")

A, m, lam = sp.symbols("A m lambda", positive=True)
K = 4.0 / 3.0  # E* = 1 (vartheta = 1/2): K = 4 E*/3
SPHERE = Punch.paraboloid(R=1)


def h0_of(lmb: float, w: float = 1.0, R: float = 1.0) -> float:
    """The Dugdale range giving Maugis's lambda (D.8) with E* = 1."""
    return w / (lmb / 2 * (math.pi * w * K**2 / R) ** (1 / 3))


@functools.lru_cache(maxsize=None)
def closed_form(module: str = "math"):
    """The derived half-space equations (D.7) as functions of (A, m, lambda) (``math`` floats or ``mpmath``)."""
    eq = half_space_equations()
    return {k: sp.lambdify((A, m, lam), v, module) for k, v in eq.items()}


def closed_form_state(lmb: float, a_bar: float, m_guess: float):
    """``(m, Pbar, dbar)`` of the derived closed form at the reduced radius ``a_bar``: gap = 1 solved by mpmath."""
    F = closed_form("mpmath")
    mp.mp.dps = 30
    mm = mp.findroot(lambda x: F["gap"](a_bar, x, lmb) - 1, m_guess)
    return float(mm), float(F["force"](a_bar, mm, lmb)), float(F["delta"](a_bar, mm, lmb))


def closed_form_pull_off(lmb: float) -> float:
    """``-min_A Pbar(A)`` of the derived closed form (D.7) in floats (Brent for m, bounded Brent for A): the force is
    stationary at the minimum, so its error is ~1e-15 relative."""
    F = closed_form()

    def m_of(a):
        hi = 2.0
        while F["gap"](a, hi, lmb) < 1:  # the gap rises from 0 at m = 1
            hi *= 2
        return optimize.brentq(lambda x: F["gap"](a, x, lmb) - 1, 1.0, hi, xtol=1e-15, rtol=1e-15)

    def P(a):
        return F["force"](a, m_of(a), lmb)

    grid = np.geomspace(1e-4, 3.0, 60)
    i = int(np.argmin([P(a) for a in grid]))
    res = optimize.minimize_scalar(P, bounds=(grid[max(i - 1, 0)], grid[i + 1]), method="bounded",
                                   options={"xatol": 1e-10})
    return -float(res.fun)


# --------------------------------------------------------------------------- (D.7) the derivation
def test_derived_half_space_equations_are_maugis_as_printed():
    """(D.7): the three equations derived from (D.3)-(D.6) at k = 0 equal Maugis (1992) as printed (his notation:
    reduced radius A, m = b/a, lambda; J. Colloid Interface Sci. 150 (1992) 243, the Dugdale model's equations)."""
    eq = half_space_equations()
    r = sp.sqrt(m**2 - 1)
    printed = {
        "gap": (lam * A**2 / 2 * (r + (m**2 - 2) * sp.atan(r))
                + sp.Rational(4, 3) * lam**2 * A * (r * sp.atan(r) - m + 1)),
        "force": A**3 - lam * A**2 * (r + m**2 * sp.atan(r)),
        "delta": A**2 - sp.Rational(4, 3) * lam * A * r,
    }
    for key, pub in printed.items():
        diff = sp.expand(eq[key] - pub.rewrite(sp.acos))
        # ladder: ==, expand, then atan(sqrt(m^2-1)) = acos(1/m) for m > 1 and simplify last
        diff = sp.simplify(diff.subs(sp.atan(r), sp.acos(1 / m)))
        assert diff == 0, (key, diff)
        for vals in ((0.7, 1.3, 0.4), (2.0, 3.5, 1.7)):  # numeric pair of the symbolic check
            sub = dict(zip((A, m, lam), vals))
            assert abs(float(eq[key].subs(sub)) - float(pub.subs(sub))) < 1e-13


def test_tabor_and_maugis_parameters():
    """(D.8): lambda = 2 (9/(16 pi))^(1/3) mu_T with sigma0 = w/h0, K = 4E*/3 (symbolic, then numeric)."""
    R, w, E, h0 = sp.symbols("R w E h0", positive=True)
    Ks = sp.Rational(4, 3) * E
    lam_s = 2 * (w / h0) * (R / (sp.pi * w * Ks**2)) ** sp.Rational(1, 3)
    mu_t = (R * w**2 / (E**2 * h0**3)) ** sp.Rational(1, 3)
    ratio = sp.simplify(sp.powsimp(lam_s / mu_t, force=True))
    assert sp.simplify(ratio - 2 * (sp.Rational(9, 16) / sp.pi) ** sp.Rational(1, 3)) == 0
    assert abs(float(ratio) - LAMBDA_OVER_TABOR) < 1e-15
    assert abs(maugis_lambda(2.0, 3.0, 0.5, 0.1) / tabor_parameter(2.0, 3.0, 0.5, 0.1) - LAMBDA_OVER_TABOR) < 1e-14
    # Maugis's 1.16 mu_T(z0) with the Lennard-Jones match h0 = 0.971 z0
    assert abs(LAMBDA_OVER_TABOR / 0.971 - 1.16) < 0.003


# --------------------------------------------------------------------------- the half-space: solver = closed form
@pytest.mark.parametrize("lmb,c", [(0.1, 0.3), (1.0, 1.0), (5.0, 2.0)])
def test_half_space_solver_equals_derived_closed_form(lmb, c):
    """The solver on HalfSpace (quadratures) at a fixed contact radius against the derived closed form: 1e-10."""
    st = maugis_dugdale(HalfSpace(), SPHERE, mu=0.5, w=1.0, h0=h0_of(lmb), radius=c, nu=0.0, error_estimate=False)
    a_bar = c / (math.pi / K) ** (1 / 3)
    mm, Pb, db = closed_form_state(lmb, a_bar, st.zone_radius / c)
    assert abs(st.zone_radius / c - mm) < 1e-10 * mm
    assert abs(st.force / math.pi - Pb) < 1e-10 * max(1.0, abs(Pb))
    assert abs(st.delta / (math.pi**2 / K**2) ** (1 / 3) - db) < 1e-10 * max(1.0, abs(db))
    assert abs(st.maugis_lambda - lmb) < 1e-12 * lmb


@pytest.mark.parametrize("lmb", [1.0] + ([0.1, 0.2, 0.5, 2.0, 3.0, 5.0] if SLOW else []))
def test_half_space_pull_off_equals_maugis_to_1e6(lmb):
    """Pull-off on the half-space: solver against the derived closed form minimised by mpmath, to 1e-6."""
    st = pull_off(HalfSpace(), SPHERE, mu=0.5, w=1.0, h0=h0_of(lmb), nu=0.0, error_estimate=False)
    ref = closed_form_pull_off(lmb)
    assert abs(-st.force / math.pi - ref) < 1e-6 * ref
    assert st.tensile


def test_dmt_and_jkr_limits_of_the_closed_form():
    """lambda -> 0: Pbar -> 2 (DMT, 2 pi w R); lambda -> oo: 3/2 (JKR); the approach is monotone."""
    vals = {lmb: closed_form_pull_off(lmb) for lmb in (0.003, 0.03, 30.0, 300.0)}
    assert 2.0 - 1e-3 < vals[0.003] < 2.0 and vals[0.03] < vals[0.003]
    assert 1.5 < vals[300.0] < 1.5 + 1e-4 and vals[30.0] > vals[300.0]


# --------------------------------------------------------------------------- the layer
def test_jkr_limit_on_the_layer_equals_the_jkr_solver():
    """lambda -> oo at a fixed contact radius on a bonded layer (c/H = 1): P_MD - P_JKR falls like lambda^-2
    (measured ratio 3.99 per doubling from lambda = 20), and the Richardson value of lambda = 40, 80 equals the JKR
    direct solver (J.5) to 1e-6."""
    layer, H, mu = BondedLayer(0.3), 1.0, 0.35
    jkr = adhesive_state(layer, SPHERE, 1.0, H, mu, work_of_adhesion=1.0)
    P = {lmb: maugis_dugdale(layer, SPHERE, H, mu, w=1.0, h0=h0_of(lmb), radius=1.0, error_estimate=False)
         for lmb in (20.0, 40.0, 80.0)}
    d1, d2 = P[40.0].force - P[20.0].force, P[80.0].force - P[40.0].force
    assert 3.9 < d1 / d2 < 4.1
    rich_P = P[80.0].force + (P[80.0].force - P[40.0].force) / 3
    rich_d = P[80.0].delta + (P[80.0].delta - P[40.0].delta) / 3
    assert abs(rich_P - jkr.force) < 1e-6 * abs(jkr.force) + jkr.force_error
    assert abs(rich_d - jkr.delta) < 1e-6 * abs(jkr.delta) + jkr.delta_error


def test_thick_layer_tends_to_the_half_space():
    """H = 1000 R: the layer's state equals the half-space's to 1e-8 (the correction is O((c/H)^3))."""
    kw = dict(mu=0.35, w=1.0, h0=h0_of(1.0), radius=1.0, error_estimate=False)
    thick = maugis_dugdale(BondedLayer(0.3), SPHERE, 1000.0, **kw)
    half = maugis_dugdale(HalfSpace(), SPHERE, nu=0.3, **kw)
    assert abs(thick.force - half.force) < 1e-8 * abs(half.force)
    assert abs(thick.zone_radius - half.zone_radius) < 1e-8


@pytest.mark.parametrize("layer,H,nu", [(BondedLayer(0.3), 0.5, None), (FrictionlessLayer(), 0.5, 0.3)])
def test_refinement_in_the_nodes(layer, H, nu):
    """c/H = 2: default nodes against 1.6 times as many agree to 1e-10; the estimate (0.7 n, coarser rules) is
    below 1e-8 and at least the observed change."""
    kw = dict(mu=0.35, w=1.0, h0=h0_of(1.0), radius=1.0, nu=nu)
    st = maugis_dugdale(layer, SPHERE, H, **kw)
    fine = maugis_dugdale(layer, SPHERE, H, n=round(1.6 * st.nodes), error_estimate=False, **kw)
    change = abs(st.force - fine.force)
    assert change < 1e-10 * abs(st.force)
    assert st.force_error < 1e-8 * abs(st.force)
    assert st.force_error >= change or change < 1e-12


@pytest.mark.parametrize("layer,H,nu", [(HalfSpace(), None, 0.3)] + ([(BondedLayer(0.3), 2.0, None)] if SLOW else []))
def test_prescribed_depth_and_force_return_the_state_at_that_radius(layer, H, nu):
    """delta0= and force= find the contact radius of maugis_dugdale(radius=) on the stable branch."""
    kw = dict(mu=0.35, w=1.0, h0=h0_of(1.0), error_estimate=False, nu=nu)
    ref = maugis_dugdale(layer, SPHERE, H, radius=2.0, **kw)
    by_d = maugis_dugdale(layer, SPHERE, H, delta0=ref.delta, **kw)
    by_P = maugis_dugdale(layer, SPHERE, H, force=ref.force, **kw)
    assert abs(by_d.radius - 2.0) < 1e-9 and abs(by_P.radius - 2.0) < 1e-9
    assert "D.9" in ref.latex() and ("[tensile]" in str(ref)) == ref.tensile


@slow
@pytest.mark.parametrize("H_over_R", [1.0, 0.3])
def test_pull_off_on_the_layer_refines_and_tends_to_the_jkr_solver(H_over_R):
    """Item 2: the pull-off force on a bonded layer (nu = 0.3, w/(E* R) = 0.01).  Refinement: 1.5 times the nodes
    changes it by less than 1e-10 at lambda = 1.  Large lambda: P_MD - P_JKR falls like lambda^-2, and the
    Richardson value of lambda = 10, 20 equals the pull-off of the JKR direct solver (J.6) to 2e-5 (half-space:
    3.3e-6, the next order lambda^-3 left)."""
    import numpy as np

    from thinlayer.numerics.adhesion import jkr_curve

    w, mu = 0.01, 0.35
    h0 = {lmb: w / (lmb / 2 * (math.pi * w * K**2) ** (1 / 3)) for lmb in (1.0, 10.0, 20.0)}
    layer = BondedLayer(0.3)
    st = pull_off(layer, SPHERE, H_over_R, mu, w=w, h0=h0[1.0])
    fine = pull_off(layer, SPHERE, H_over_R, mu, w=w, h0=h0[1.0], n=round(1.5 * st.nodes), error_estimate=False)
    assert abs(st.force - fine.force) < 1e-10 * abs(st.force)
    P10, P20 = (pull_off(layer, SPHERE, H_over_R, mu, w=w, h0=h0[v], error_estimate=False).force for v in (10.0, 20.0))
    c0 = (6 * math.pi * w / K) ** (1 / 3)
    jkr = jkr_curve(layer, SPHERE, np.geomspace(0.2 * c0, 1.2 * c0, 25), H_over_R, mu, work_of_adhesion=w)
    rich = P20 + (P20 - P10) / 3
    assert abs(rich / jkr.pull_off_load.force - 1) < 2e-5
    assert P10 < P20 < jkr.pull_off_load.force < 0  # MD pulls harder and approaches JKR from above


@pytest.mark.parametrize("layer,H,nu", [(HalfSpace(), None, 0.3), (BondedLayer(0.3), 0.5, None)])
def test_pressure_integrates_to_the_force_and_is_maugis_on_the_half_space(layer, H, nu):
    """(D.11): 2 pi int p r dr (quadrature of pressure_at) equals the force (D.5) to 1e-10; p = -sigma0 on the zone,
    continuous at c; on the half-space p is Maugis's Hertz-plus-arctan pressure to 1e-10."""
    import numpy as np
    from scipy import integrate

    st = maugis_dugdale(layer, SPHERE, H, 0.35, w=1.0, h0=h0_of(1.0), radius=1.0, nu=nu, error_estimate=False)
    c, b = st.radius, st.zone_radius
    inner = integrate.quad(lambda r: 2 * math.pi * r * st.lambdify()(r)[0], 0, c, limit=200, epsabs=1e-13,
                           epsrel=1e-13)[0]
    assert abs((inner - st.sigma0 * math.pi * (b * b - c * c)) / st.force - 1) < 1e-10
    edge = st.pressure_at([c * (1 - 1e-12), c, 0.5 * (c + b), 1.01 * b])
    assert np.allclose(edge, [-st.sigma0, -st.sigma0, -st.sigma0, 0.0], atol=1e-5 * st.sigma0)
    if H is None:
        r = np.linspace(0.0, 0.99, 7)
        hertz = 4 * st.vartheta * c / math.pi * np.sqrt(1 - (r / c) ** 2)  # p0 = 2 E* c/(pi R), R = 1
        maugis = hertz - 2 * st.sigma0 / math.pi * np.arctan(np.sqrt((b * b - c * c) / (c * c - r * r)))
        assert np.abs(st.pressure_at(r) - maugis).max() < 1e-10


def test_abel_load_of_the_module_equals_the_revolution_solver():
    """(F.11) h(s) of the module's fixed 40-point rule against thinlayer.numerics.revolution.abel_load (graded
    rule) and, for the sphere, the closed form s^2/R."""
    import numpy as np

    from thinlayer.numerics import cohesive
    from thinlayer.numerics.revolution import abel_load

    slope, R = cohesive._slope_of(Punch.fourth_degree(R=2, K=1))
    s = np.linspace(0.0, 3.0, 7)
    assert np.allclose(cohesive._h(slope, s), abel_load(slope, (), s), rtol=1e-13, atol=1e-14)
    assert R == 2.0
    slope, _ = cohesive._slope_of(SPHERE)
    assert np.allclose(cohesive._h(slope, s), s**2, rtol=1e-14, atol=1e-15)


def test_bad_input_is_one_clear_line():
    kw = dict(w=1.0, radius=1.0, nu=0.3)
    with pytest.raises(InputError, match="exactly one of h0"):
        maugis_dugdale(HalfSpace(), SPHERE, **kw)
    with pytest.raises(InputError, match="exactly one of h0"):
        maugis_dugdale(HalfSpace(), SPHERE, h0=1.0, sigma0=1.0, **kw)
    with pytest.raises(InputError, match="not axisymmetric"):
        maugis_dugdale(HalfSpace(), Punch("x1**2 + 2*x2**2"), h0=1.0, **kw)
    with pytest.raises(InputError, match="exactly one of radius"):
        maugis_dugdale(HalfSpace(), SPHERE, h0=1.0, w=1.0, radius=1.0, delta0=0.1, nu=0.3)
    with pytest.raises(InputError, match="needs the layer thickness"):
        maugis_dugdale(BondedLayer(0.3), SPHERE, h0=1.0, **{**kw, "nu": None})
    with pytest.raises(ValueError, match="w"):
        maugis_dugdale(HalfSpace(), SPHERE, h0=1.0, **{**kw, "w": -1.0})
