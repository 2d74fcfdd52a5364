"""Any thickness for every tip of revolution (issue 24 item 3): the second-kind equation (F.6) with the tip's load
(F.10)-(F.15) of :mod:`thinlayer.numerics.revolution`, and the laws of :mod:`thinlayer.contact.revolution_law`.

Independent sources: the Abel integral (F.11) and Sneddon's half-space values by mpmath quadrature (not the engine's
quadrature); the layer by the direct spectral solver (:mod:`thinlayer.numerics.axisymmetric`, a pressure basis without
Copson's representation).  The wide grid (shapes x nu x c/H up to 30) runs with THINLAYER_SLOW=1.
"""
from __future__ import annotations

import math
from functools import lru_cache

import mpmath as mp
import numpy as np
import pytest

import thinlayer as tl
from thinlayer.contact.revolution_law import law_from_table, power_law_table, self_similar_exponent
from thinlayer.numerics import contact_for_radius, solve_axisymmetric
from thinlayer.numerics.flat_punch import flat_punch_kappa
from thinlayer.numerics.revolution import abel_load, revolution_contact, revolution_contact_for_radius

TIPS = {
    "sphere": lambda: tl.Punch.sphere(10),
    "blunted": lambda: tl.Punch.blunted_cone(1, 70),
    "power1.5": lambda: tl.Punch.power_law(1, 1.5),
    "cone70": lambda: tl.Punch.cone(70),
}


def _mp_slope(tip: str):
    """Phi'(r) of each tip written out here (not the engine's): sphere R = 10, blunted cone R = 1 / 70 deg, r^1.5."""
    if tip == "sphere":
        return lambda r: r / mp.sqrt(100 - r * r), ()
    if tip == "blunted":
        b = mp.cos(mp.radians(70))
        return (lambda r: r / mp.sqrt(1 - r * r) if r < b else mp.cot(mp.radians(70))), (b,)
    if tip == "power1.5":
        return lambda r: mp.mpf(1.5) * mp.sqrt(r), ()
    return lambda r: mp.cot(mp.radians(70)), ()


def _mp_h(tip: str, s: float) -> mp.mpf:
    """h(s) = s int_0^s Phi'(r)/sqrt(s^2 - r^2) dr (F.11), r = s sin(theta), by mpmath (tanh-sinh)."""
    f, joins = _mp_slope(tip)
    cuts = [mp.asin(b / s) for b in joins if b < s]
    return s * mp.quad(lambda th: f(s * mp.sin(th)), [0, *cuts, mp.pi / 2])


@pytest.mark.parametrize("tip", list(TIPS))
def test_the_abel_load_is_the_abel_integral(tip):
    # (F.11) against mpmath; the blunted cone on both sides of its join r_t = cos 70 deg = 0.342
    slope = TIPS[tip]()
    s = np.array([0.05, 0.3, 0.5, 2.0, 7.0])
    h = abel_load(slope.radial_slope, slope.radial_breakpoints, s)
    with mp.workdps(25):
        ref = [float(_mp_h(tip, float(v))) for v in s]
    np.testing.assert_allclose(h, ref, rtol=1e-13, atol=0)


def test_half_space_equals_sneddon_closed_forms():
    # Sneddon (1965), derived again here: E* = 2 vartheta; the cone P = (2/pi) E* tan(a) d^2 with d = (pi/2) c cot(a);
    # the exact sphere d = (c/2) ln((R + c)/(R - c)), P = (E*/2) ((R^2 + c^2) ln((R + c)/(R - c)) - 2 R c); the power
    # law d = k_n c^n, P = 2 E* k_n c^(n+1) n/(n + 1), k_n = (n/2) B(n/2, 1/2) by mpmath
    hs, nu = tl.HalfSpace(), 0.3
    vt = 1.0 / (1.0 - nu)
    c = 0.7
    res = revolution_contact_for_radius(hs, tl.Punch.cone(70), c, nu=nu)
    d = math.pi / 2 * c / math.tan(math.radians(70))
    assert res.delta0 == pytest.approx(d, rel=1e-13)
    assert res.force == pytest.approx(2 / math.pi * 2 * vt * math.tan(math.radians(70)) * d * d, rel=1e-12)
    R, c = 10.0, 6.0
    res = revolution_contact_for_radius(hs, tl.Punch.sphere(R), c, nu=nu)
    lg = math.log((R + c) / (R - c))
    assert res.delta0 == pytest.approx(c / 2 * lg, rel=1e-13)
    assert res.force == pytest.approx(vt * ((R * R + c * c) * lg - 2 * R * c), rel=1e-12)
    n, c = 1.5, 0.8
    k = float(n / 2 * mp.beta(n / 2, 0.5))
    res = revolution_contact_for_radius(hs, tl.Punch.power_law(1, n), c, nu=nu)
    assert res.delta0 == pytest.approx(k * c**n, rel=1e-12)
    assert res.force == pytest.approx(4 * vt * k * c ** (n + 1) * n / (n + 1), rel=1e-12)
    # and at a prescribed depth the radius comes back
    back = revolution_contact(hs, tl.Punch.power_law(1, n), k * c**n, nu=nu)
    assert back.radius == pytest.approx(c, rel=1e-12)


@lru_cache(maxsize=None)
def _pair(tip: str, layer: str, c: float):
    lay = {"b45": tl.BondedLayer(0.45), "inc": tl.IncompressibleLayer(), "fr": tl.FrictionlessLayer(0.3)}[layer]
    nu = 0.3 if layer == "fr" else None
    return (revolution_contact_for_radius(lay, TIPS[tip](), c, 1.0, nu=nu),
            contact_for_radius(lay, TIPS[tip](), c, 1.0, nu=nu))


@pytest.mark.parametrize(("tip", "layer", "c"), [("sphere", "b45", 1.5), ("blunted", "fr", 2.0),
                                                 ("power1.5", "inc", 3.0)])
def test_the_equation_agrees_with_the_direct_solver(tip, layer, c):
    # a prescribed contact radius c/H: delta0 and P from (F.13), (F.14) against the spectral Galerkin solver
    mine, ref = _pair(tip, layer, c)
    for v, w, e, ew in ((mine.delta0, ref.delta0, mine.delta0_error, ref.delta0_error / ref.delta0),
                        (mine.force, ref.force, mine.force_error, ref.force_error)):
        assert abs(v / w - 1) <= e + ew, (tip, layer, v / w - 1, e, ew)
        assert abs(v / w - 1) < 1e-9


def test_the_force_grows_with_the_flat_punch_stiffness():
    # dP/d delta0 = 4 vartheta c kappa(c/H) (F.15): the edge condition makes P stationary in c at fixed delta0;
    # finite differences of two prescribed radii, nothing but (F.13), (F.14) and the flat punch's kappa (F.7)
    lay, tip = tl.BondedLayer(0.45), tl.Punch.sphere(10)
    a = revolution_contact_for_radius(lay, tip, 1.5, 1.0, error_estimate=False)
    b = revolution_contact_for_radius(lay, tip, 1.5 * (1 + 1e-5), 1.0, error_estimate=False)
    slope = (b.force - a.force) / (b.delta0 - a.delta0)
    kappa = flat_punch_kappa(lay, 1.5 * (1 + 5e-6)).kappa
    assert slope == pytest.approx(4 * a.vartheta * 1.5 * (1 + 5e-6) * kappa, rel=1e-6)


def test_solve_auto_answers_a_power_law_tip_at_any_thickness_forward_and_inverse():
    lay, tip = tl.BondedLayer(0.5), tl.Punch.power_law(1, 1.5)
    mine, ref = _pair("power1.5", "inc", 3.0)
    ans = tl.solve(lay, tip, delta0=mine.delta0, H=1.0, mu=1.0)
    assert ans.model == "any-thickness" and "(F.6)" in ans.reason
    assert abs(ans.force / ref.force - 1) <= ans.error_estimate["force"] + ref.force_error
    assert abs(ans.contact_radius / 3.0 - 1) <= ans.error_estimate["contact_radius"] + 1e-12
    inv = tl.solve(lay, tip, force=ans.force, H=1.0, mu=1.0)
    assert inv.model == "any-thickness"
    assert abs(inv.delta0 / mine.delta0 - 1) <= inv.error_estimate["delta0"] + ans.error_estimate["force"]


def test_self_similar_tips_are_read_from_the_profile():
    assert self_similar_exponent(tl.Punch.power_law(2, 1.5)) == (2.0, 1.5)
    C, n = self_similar_exponent(tl.Punch.cone(45))
    assert n == 1.0 and C == pytest.approx(1.0, rel=1e-15)
    assert self_similar_exponent(tl.Punch.sphere(10)) is None
    assert self_similar_exponent(tl.Punch.blunted_cone(1, 70)) is None


def _table_check(law, n: float, layer, nu: float, radii) -> float:
    """Off-node points of the equation (independent of the interpolation) within the law's estimate; the largest."""
    k = float(n / 2 * mp.beta(n / 2, 0.5))
    worst = 0.0
    for s in radii:
        res = revolution_contact_for_radius(layer, tl.Punch.power_law(1, n), s, 1.0,
                                            nu=nu if layer.numeric_nu is None else None)
        c0 = (res.delta0 / k) ** (1 / n)
        P0 = 4 * res.vartheta * k * c0 ** (n + 1) * n / (n + 1)
        (Pr,), (cr,) = law.ratios([c0])
        (eP,), (ec,) = law.error_estimate([c0])
        assert abs(Pr / (res.force / P0) - 1) <= eP + res.force_error + 2 * res.delta0_error, (s, Pr, eP)
        assert abs(cr / (s / c0) - 1) <= ec + res.delta0_error, (s, cr, ec)
        worst = max(worst, eP, ec)
    return worst


@lru_cache(maxsize=1)
def _small_law():
    """A small table (5 radii c/H in [0.05, 0.6]) of r^1.5 on the frictionless base (5 solves, shared)."""
    return law_from_table(power_law_table(1.5, 0.3, "frictionless", (0.05, 0.6, 5)), 1.5, 0.3, "frictionless")


def test_the_power_law_table_law_holds_off_its_nodes_within_its_estimate():
    # the small table, checked between its nodes
    n, nu = 1.5, 0.3
    law = _small_law()
    assert _table_check(law, n, tl.FrictionlessLayer(0.3), nu, (0.2,)) < 2e-2  # h = 0.62 in log c; GRID has 0.18


def _pointwise(law, chi):
    """The law's interpolation written point by point (the formula before the vectorised evaluate, issue 24 item 7)."""
    from thinlayer.contact.any_thickness_tips import CHI_SERIES

    x0, h, Y, Z, EY, EZ = law.splines
    out = []
    for c in chi:
        if c < CHI_SERIES:
            fc, rc, ser = law.series
            pv = np.polynomial.polynomial.polyval
            eP, ec = ser(np.array([c]))
            out.append((pv(c, fc), pv(c, rc), eP[0], ec[0]))
            continue
        t = (math.log(c) - x0) / h
        k = min(int(t), Y.size - 2)
        w = t - k
        out.append((Y[k] + w * (Y[k + 1] - Y[k]), Z[k] + w * (Z[k + 1] - Z[k]), EY[k], EZ[k]))
    return np.array(out).T


def test_the_vectorised_evaluation_is_the_pointwise_formula_bit_for_bit():
    """evaluate() (in place, np.take, the slopes stored once) gives the point-by-point interpolation's values exactly,
    below and above the series' end, on any shape; chi <= 0, NaN and chi > chi_max are refused in one line."""
    from thinlayer.contact.any_thickness_tips import NotTabulatedError

    # a synthetic smooth table (no solve: the evaluation is under test, not the law's values)
    chi_t = np.geomspace(0.04, 30.0, 14)
    data = {"chi": chi_t, "y": np.log1p(0.7 * chi_t + 0.02 * chi_t**2), "z": -0.1 * np.log1p(chi_t),
            "ed": np.full(14, 1e-9), "eP": np.full(14, 1e-9)}
    law = law_from_table(data, 1.0, 0.3, "frictionless")  # n = 1: the cone's series (T.9), cached
    rng = np.random.default_rng(7)
    chi = np.concatenate([rng.uniform(1e-3, 0.06, 50), rng.uniform(0.06, law.chi_max, 200), [0.06, law.chi_max]])
    got = law.evaluate(chi)
    ref = _pointwise(law, chi)
    for g, r in zip(got, ref):
        assert np.array_equal(g, r)
    square = law.evaluate(chi[:36].reshape(6, 6))
    assert all(a.shape == (6, 6) and np.array_equal(a.ravel(), b[:36]) for a, b in zip(square, got))
    assert all(np.shape(a) == () for a in law.evaluate(0.3))
    for bad, words in ((0.0, "positive"), (float("nan"), "positive"), (1.01 * law.chi_max, "thin layer")):
        with pytest.raises(NotTabulatedError, match=words):
            law.evaluate([0.2, bad])


@pytest.mark.slow
@pytest.mark.parametrize(("n", "nu", "base"), [(1.5, 0.5, "bonded"), (1.0, 0.45, "bonded"), (3.0, 0.3, "frictionless")])
def test_the_power_law_law_within_1e_4_up_to_chi_30(n, nu, base):
    from thinlayer.contact.revolution_law import power_law_law

    law = power_law_law(n, nu, base)
    lay = tl.FrictionlessLayer(0.3) if base == "frictionless" else tl.BondedLayer(nu)
    assert law.chi_max >= 30
    assert _table_check(law, n, lay, nu, (0.07, 0.6, 2.9, 11.0, 27.0)) < 1e-4


# --------------------------------------------------------------------------- the wide grid (THINLAYER_SLOW=1)
LAYERS = {"bonded nu=0.3": tl.BondedLayer(0.3), "bonded nu=0.45": tl.BondedLayer(0.45),
          "bonded nu=0.5": tl.BondedLayer(0.5), "frictionless": tl.FrictionlessLayer(0.3)}
GRID_C = (0.1, 1.0, 5.0, 15.0, 30.0)


def grid_row(tip: str, layer: str, chi: float) -> dict:
    """The equation at a prescribed depth against the direct solver at that depth: chi = a/H (a the overlap)."""
    lay = LAYERS[layer]
    t = TIPS[tip]()
    a = t.level_set(0.5).half_width
    H = a / chi
    nu = 0.3 if layer == "frictionless" else None
    mine = revolution_contact(lay, t, 0.5, H, nu=nu)
    ref = solve_axisymmetric(lay, t, 0.5, H, nu=nu)
    return {"c/H": mine.radius / H, "dP": abs(mine.force / ref.force - 1), "eP": mine.force_error,
            "eP_ref": ref.force_error, "dc": abs(mine.radius / ref.radius - 1), "ec": mine.radius_error,
            "ec_ref": ref.radius_error / ref.radius}


@pytest.mark.slow
@pytest.mark.parametrize("tip", list(TIPS))
@pytest.mark.parametrize("layer", list(LAYERS))
@pytest.mark.parametrize("chi", GRID_C)
def test_grid_every_tip_within_its_estimate_and_1e_4(tip, layer, chi):
    row = grid_row(tip, layer, chi)
    assert row["dP"] <= row["eP"] + row["eP_ref"] and row["dc"] <= row["ec"] + row["ec_ref"], row
    assert row["dP"] < 1e-4 and row["dc"] < 1e-4 and row["eP"] < 1e-4, row


if __name__ == "__main__":  # the grid's table for the report
    print(f"{'tip':9} {'layer':15} {'a/H':>5} {'c/H':>7} {'|dP|':>9} {'est P':>9} {'|dc|':>9} {'est c':>9}")
    for t in TIPS:
        for lay in LAYERS:
            for chi in GRID_C:
                r = grid_row(t, lay, chi)
                print(f"{t:9} {lay:15} {chi:5g} {r['c/H']:7.3g} {r['dP']:9.2e} {r['eP']:9.2e} {r['dc']:9.2e} "
                      f"{r['ec']:9.2e}", flush=True)


@pytest.mark.slow
@pytest.mark.parametrize(("nu", "base", "s"), [(0.45, "bonded", 1.0), (0.45, "bonded", 20.0), (0.5, "bonded", 8.0),
                                               (0.3, "frictionless", 25.0)])
def test_the_cone_table_within_its_estimate_of_the_equation(nu, base, s):
    # cross-check of the packaged cone table (direct spectral solutions, interpolated in chi and nu) by the equation
    from thinlayer.contact.any_thickness_tips import cone_law

    lay = tl.FrictionlessLayer(0.3) if base == "frictionless" else tl.BondedLayer(nu)
    res = revolution_contact_for_radius(lay, tl.Punch.cone(45), s, 1.0, nu=nu if base == "frictionless" else None)
    c0 = 2 / math.pi * res.delta0
    law = cone_law(nu, base)
    (Pr,), (cr,) = law.ratios([c0])
    (eP,), (ec,) = law.error_estimate([c0])
    assert abs(Pr / (res.force / (4 / math.pi * res.vartheta * res.delta0**2)) - 1) <= eP + res.force_error
    assert abs(cr / (s / c0) - 1) <= ec + res.delta0_error
