"""Any thickness for the tips of revolution (issue 24 item 3): the thick-layer series (T.9) and the cone's law.

Independent routes: the series' exact rationals against the same series seeded by quadrature of the profile;
the half-space constants against mpmath quadrature and Sneddon; the series and the law against the direct solver
(:func:`thinlayer.numerics.contact_for_radius`, which uses no series, only the kernel L), off the table's nodes.
Small by default; ``THINLAYER_SLOW=1`` runs the whole grid of the brief.
"""
import math
import os

import mpmath
import numpy as np
import pytest
import sympy as sp

import thinlayer as tl
from thinlayer import BondedLayer, FrictionlessLayer, Punch
from thinlayer.asymptotics.thick_layer import (
    power_law_half_space,
    thick_power_law_series,
    thick_sphere_series,
)
from thinlayer.asymptotics.thick_tips import half_space_moments, radial_thick_expansion
from thinlayer.contact._tips_table_build import direct_point
from thinlayer.contact.any_thickness import NotTabulatedError, any_thickness_fields
from thinlayer.contact.any_thickness_tips import CHI_SERIES, TIPS_TABLE_PATH, _packaged, cone_law
from thinlayer.layers.kernels import IncompressibleLayer
from thinlayer.numerics import contact_for_radius

SLOW = os.environ.get("THINLAYER_SLOW") == "1"
TAN70 = math.tan(math.radians(70))


def _layer(nu, base):
    if base == "frictionless":
        return FrictionlessLayer(nu)
    return IncompressibleLayer() if nu == 0.5 else BondedLayer(nu)


# --------------------------------------------------------------------------- (T.9): the series
@pytest.mark.parametrize("order", [4, 9])
def test_power_law_series_at_n2_is_the_sphere_series(order):
    """(T.9) with n = 2 and the paraboloid's seed gives (T.7) unchanged: ``==`` after expand, and in numbers."""
    a, b = thick_sphere_series(order), thick_power_law_series(2, order)
    for x, y in zip(a.force + a.radius, b.force + b.radius):
        assert sp.expand(x - y) == 0
    fa, ra = a.coefficients(BondedLayer(0.3))
    fb, rb = b.coefficients(BondedLayer(0.3))
    assert np.array_equal(fa, fb) and np.array_equal(ra, rb)


@pytest.mark.parametrize("n", [1, sp.Rational(3, 2), 2, 3])
def test_half_space_constant_against_quadrature_and_sneddon(n):
    """``k_n = n int_0^1 t^{n-1}/sqrt(1 - t^2) dt = n int_0^{pi/2} sin^{n-1} s ds`` (T.9) by mpmath; Sneddon's cone
    ``pi/2`` and Hertz's 2."""
    k = power_law_half_space(n)
    q = mpmath.quad(lambda s: mpmath.mpf(n.p if hasattr(n, "p") else n) / (n.q if hasattr(n, "q") else 1)
                    * mpmath.sin(s) ** (mpmath.mpf(float(n)) - 1), [0, mpmath.pi / 2])
    assert float(k) == pytest.approx(float(q), rel=1e-13)
    if n == 1:
        assert sp.simplify(k - sp.pi / 2) == 0
    if n == 2:
        assert k == 2


def test_cone_series_first_terms():
    """The cone's first coefficients (T.9): ``P/P_0 = 1 + 2 (b_0/pi) chi + 5 (b_0/pi)^2 chi^2 + ...``."""
    s = thick_power_law_series(1, 3)
    b0, b1 = sp.symbols("b_0 b_1", positive=True)
    assert s.force[1] == 2 * b0 / sp.pi
    assert sp.expand(s.force[2] - 5 * b0**2 / sp.pi**2) == 0
    assert sp.expand(s.force[3] - (14 * b0**3 / sp.pi**3 - b1 / (2 * sp.pi))) == 0
    assert sp.expand(s.radius[1] - b0 / sp.pi) == 0


def test_quadrature_seed_equals_exact_series():
    """The cone through the quadrature route (T.9) equals the exact rational series, to rounding."""
    tip = Punch.cone(70)
    d0, M = half_space_moments(tip, 1.0, 3)
    assert d0 == pytest.approx(math.pi / 2 / TAN70, rel=1e-14)                 # Sneddon: delta0 = (pi/2) c cot alpha
    assert M[0] == pytest.approx(math.pi / TAN70, rel=1e-14)                    # P = pi vartheta c^2 cot alpha
    layer = BondedLayer(0.45)
    ex = radial_thick_expansion(tip, 16)
    fc, rc = thick_power_law_series(1, 16).coefficients(layer)
    d = 0.02
    v = ex.evaluate(layer, d, 1.0, 1.0, 0.45)
    c0 = 2 / math.pi * d * TAN70
    pv = np.polynomial.polynomial.polyval
    assert v.force / (4 / math.pi / 0.55 * TAN70 * d * d) == pytest.approx(pv(c0, fc), rel=1e-13)
    assert v.radius / c0 == pytest.approx(pv(c0, rc), rel=1e-13)


TIPS = {
    "cone": Punch.cone(70),
    "power law 3/2": Punch.power_law(1, "3/2"),
    "exact sphere": Punch.sphere(2.0),
    "blunted cone": Punch.blunted_cone(0.5, 70),
}


@pytest.mark.parametrize("name", list(TIPS) if SLOW else ["cone", "exact sphere"])
def test_thick_series_remainder_order_against_direct(name):
    """Truncated after eps^N, the series misses the direct solution by ``O(eps^{N'})``, N' the next non-zero order:
    at fixed contact radius c (fixed seed), halving eps = c/H divides the error by ``2^{N'}``.
    """
    tip = TIPS[name]
    layer = BondedLayer(0.45)
    ex = radial_thick_expansion(tip, 12)
    c = 0.4
    vt = 1.0 / (1.0 - 0.45)
    runs = []
    for H in (4.0, 8.0):
        dt, pt = ex.terms(layer, c, H)  # depth and force terms (force at vartheta = 1)
        runs.append((H, dt, vt * pt, contact_for_radius(layer, tip, c, H=H, mu=1.0)))
    for N in (1, 2):
        for which in (0, 1):  # depth, force
            errs = []
            for H, dt, pt, res in runs:
                terms = (dt, pt)[which]
                errs.append(abs(np.sum(terms[:N + 1]) / (res.delta0, res.force)[which] - 1))
            H, dt, pt, _ = runs[0]
            terms = (dt, pt)[which]
            nxt = next(m for m in range(N + 1, 12) if abs(terms[m]) > 1e-9 * abs(terms[0]))
            observed = math.log(errs[0] / errs[1]) / math.log(2.0)
            assert observed == pytest.approx(nxt, abs=0.35), (name, N, which, errs, nxt)


# --------------------------------------------------------------------------- the cone's law
def test_cone_table_is_packaged_and_regenerates():
    """Three shipped nodes re-solved by the direct solver (the builder's own function) agree to 1e-9."""
    assert TIPS_TABLE_PATH.exists()
    data = _packaged()
    s = data["s"]
    nus = [float(v) for v in data["nu"]]
    for row, base, nu, j in ((0, "frictionless", 0.3, 5), (1 + nus.index(0.45 if 0.45 in nus else 0.46), "bonded",
                                                             0.45 if 0.45 in nus else 0.46, 17),
                             (1, "bonded", 0.5, 25 if SLOW else 12)):
        chi, Pr, cr, _ = direct_point(1, base, nu, float(s[j]))
        assert chi == pytest.approx(data["chi"][row, j], rel=1e-9)
        assert math.log(Pr) == pytest.approx(data["y"][row, j], abs=1e-9)
        assert math.log(cr) == pytest.approx(data["z"][row, j], abs=1e-9)


def test_cone_law_is_angle_free_and_tends_to_sneddon():
    """``P/P_0`` and ``c/c_0`` do not depend on the angle (direct, 50 and 70 degrees); chi -> 0 is Sneddon."""
    a = contact_for_radius(BondedLayer(0.45), Punch.cone(50), 0.7, H=1.0)
    b = contact_for_radius(BondedLayer(0.45), Punch.cone(70), 0.7, H=1.0)
    assert a.force / a.delta0**2 / math.tan(math.radians(50)) == pytest.approx(b.force / b.delta0**2 / TAN70, rel=1e-10)
    P, c = cone_law(0.45).ratios([1e-6])
    assert P[0] == pytest.approx(1.0, abs=3e-6) and c[0] == pytest.approx(1.0, abs=2e-6)


def _grid():
    chis = [0.1, 0.3, 1.0, 3.0, 10.0, "thin"]
    cases = [(x, nu, "bonded") for x in chis for nu in (0.3, 0.45, 0.5)] + [(x, 0.3, "frictionless") for x in chis]
    if SLOW:
        return cases
    return [(0.3, 0.45, "bonded"), (3.0, 0.5, "bonded"), ("thin", 0.45, "bonded"), (1.0, 0.3, "frictionless")]


@pytest.mark.parametrize("chi,nu,base", _grid())
def test_cone_law_against_direct_solver(chi, nu, base):
    """|law - direct| <= estimate <= 1e-4 (force and radius), the direct solution at a prescribed contact radius
    near the requested chi (its chi read back from its depth), "thin" the table's end (c/H ~ 30).
    """
    layer = _layer(nu, base)
    law = cone_law(nu, base)
    target = 0.95 * law.chi_max if chi == "thin" else chi
    P0 = cone_law(nu, base).ratios([target])[1][0]  # c/c_0 at the target: the radius to prescribe
    res = contact_for_radius(layer, Punch.cone(70), target * P0, H=1.0, mu=1.0,
                             nu=nu if base == "frictionless" else None)
    c0 = 2 / math.pi * res.delta0 * TAN70
    Pd, cd = res.force / (4 / math.pi / (1 - nu) * TAN70 * res.delta0**2), res.radius / c0
    (Pl,), (cl,) = law.ratios([c0])
    (eP,), (ec,) = law.error_estimate([c0])
    assert abs(Pl / Pd - 1) <= eP, (chi, nu, base, abs(Pl / Pd - 1), eP)
    assert abs(cl / cd - 1) <= ec, (chi, nu, base, abs(cl / cd - 1), ec)
    if chi != "thin" and chi <= 3.0 or nu == 0.45 or base == "frictionless":
        assert eP <= 1e-4 and ec <= 1e-4  # covered at 1e-4 (measured: near nu = 1/2 beyond chi ~ 5 it is not)
    if max(eP, ec) > 1e-4:  # not covered at 1e-4: the table declines there, the equation (F.6) answers within 1e-4
        f = any_thickness_fields(layer, Punch.cone(70), delta0=res.delta0, H=1.0, mu=1.0,
                                 nu=nu if base == "frictionless" else None, tol=1e-4)
        assert "(F.6)" in f["reason"] and max(f["error_estimate"].values()) <= 1e-4
        assert abs(f["force"] / res.force - 1) <= f["error_estimate"]["force"] + res.force_error


def test_cone_law_series_joins_the_table():
    """At chi = CHI_SERIES the series (T.9) and the table of direct solutions meet within both estimates."""
    for nu, base in ((0.45, "bonded"), (0.5, "bonded"), (0.3, "frictionless")):
        law = cone_law(nu, base)
        lo, hi = law.ratios([CHI_SERIES * (1 - 1e-9), CHI_SERIES * (1 + 1e-6)])
        assert lo[0] == pytest.approx(lo[1], rel=1e-5) and hi[0] == pytest.approx(hi[1], rel=1e-5)


def test_cone_law_vectorised_evaluation_is_scipys_spline_bit_for_bit():
    """ratios()/error_estimate() (uniform knots, gathered coefficients, the series on the low points only; issue 24
    item 7) give exactly the values of the law's scipy CubicSplines and the series (T.9) as np.where over all points
    did, on any shape; chi <= 0, NaN, chi > chi_max refused in one line."""
    from thinlayer.contact.any_thickness_tips import ConeLaw, cone_law_from

    # the frictionless law without its measured estimate (whose first build takes 30 s or more), the estimate
    # splines replaced by two other splines on the same knots: the evaluation is under test
    bare = cone_law_from(_packaged(), 0.3, "frictionless", with_estimate=False)
    s0, s1 = bare.splines[:2]
    law = ConeLaw(0.3, "frictionless", bare.chi_max, (s0, s1, s1, s0), bare.series)
    rng = np.random.default_rng(3)
    chi = np.concatenate([rng.uniform(1e-4, CHI_SERIES, 40), rng.uniform(CHI_SERIES, law.chi_max, 400),
                          [CHI_SERIES, law.chi_max, float(np.exp(law.splines[0].x[7]))]])
    fc, rc, ser = law.series
    pv = np.polynomial.polynomial.polyval
    x = np.log(chi)
    low = chi <= CHI_SERIES
    ref = [np.exp(np.where(low, np.log(pv(np.minimum(chi, CHI_SERIES), c)), law.splines[j](x)))
           for j, c in ((0, fc), (1, rc))]
    ref += [np.where(low, s, law.splines[j](x)) for j, s in zip((2, 3), ser(np.minimum(chi, CHI_SERIES)))]
    got = [*law.ratios(chi), *law.error_estimate(chi)]
    assert all(np.array_equal(g, r) for g, r in zip(got, ref))
    sq = law.ratios(chi[:16].reshape(4, 4))
    assert sq[0].shape == (4, 4) and np.array_equal(sq[0].ravel(), got[0][:16])
    for bad, words in ((0.0, "positive"), (float("nan"), "positive"), (1.01 * law.chi_max, "thin layer")):
        with pytest.raises(tl.InputError, match=words):
            law.ratios([0.5, bad])


# --------------------------------------------------------------------------- the front door
def test_solve_auto_picks_the_cone_law_forward_and_inverse():
    ans = tl.solve(BondedLayer(0.45), Punch.cone(70), delta0=0.5, H=1.0, mu=1.0, tol=1e-4)
    assert ans.model == "any-thickness" and max(ans.error_estimate.values()) <= 1e-4
    assert "cone" in ans.reason
    inv = tl.solve(BondedLayer(0.45), Punch.cone(70), force=ans.force, H=1.0, mu=1.0, tol=1e-4)
    assert inv.model == "any-thickness" and inv.delta0 == pytest.approx(0.5, rel=1e-10)
    fr = tl.solve(FrictionlessLayer(0.3), Punch.cone(70), delta0=0.5, H=1.0, mu=1.0, tol=1e-4)
    assert fr.model == "any-thickness" and fr.force < ans.force


def test_law_declines_outside_its_range():
    """Bonded nu < 0.3, chi beyond the table and beyond the equation's c_0/H <= 30: NotTabulatedError (auto goes on
    to the next model, the direct solver at the end), never an unflagged answer."""
    with pytest.raises(NotTabulatedError):
        any_thickness_fields(BondedLayer(0.2), Punch.cone(70), delta0=0.5, H=1.0, mu=1.0, tol=1e-4)
    with pytest.raises(NotTabulatedError, match="beyond"):
        any_thickness_fields(BondedLayer(0.45), Punch.cone(70), delta0=100.0, H=1.0, mu=1.0, tol=1e-4)
    # the exact sphere beyond c ~ H: no longer declined (issue 24 item 3): the equation (F.6) answers within 1e-4
    f = any_thickness_fields(BondedLayer(0.45), Punch.sphere(2.0), delta0=0.5, H=1.0, mu=1.0, tol=1e-4)
    assert "(F.6)" in f["reason"] and max(f["error_estimate"].values()) <= 1e-4
    with pytest.raises(NotTabulatedError, match="beyond"):  # beyond its range c_0/H <= 30: the thin layer
        any_thickness_fields(BondedLayer(0.45), Punch.sphere(2.0), delta0=0.5, H=0.02, mu=1.0, tol=1e-4)


@pytest.mark.parametrize("name", ["exact sphere", "blunted cone"] if not SLOW else list(TIPS))
def test_other_tips_thick_series_within_estimate(name):
    """Exact sphere, blunted cone (and under SLOW the power law): the any-thickness model answers by (T.9) at
    c/H ~ 0.1, its estimate <= 1e-4 covering the direct solver's difference."""
    tip = TIPS[name]
    layer = BondedLayer(0.45)
    res = contact_for_radius(layer, tip, 0.1, H=1.0, mu=1.0)
    f = any_thickness_fields(layer, tip, delta0=res.delta0, H=1.0, mu=1.0, tol=1e-4)
    assert max(f["error_estimate"].values()) <= 1e-4
    assert abs(f["force"] / res.force - 1) <= f["error_estimate"]["force"]
    assert abs(f["contact_radius"] / res.radius - 1) <= f["error_estimate"]["contact_radius"]
