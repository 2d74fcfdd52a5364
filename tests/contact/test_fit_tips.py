"""fit() with every tip of revolution (issue 24 item 6): the tip-law and direct models' force curves.

The synthetic data come from the direct axisymmetric solver (independent of the tip law); the fitted E must be
within the law's own estimate, and with noise the standard error must cover the true E as often as it claims.
"""
import math
import os

import numpy as np
import pytest

from thinlayer import BondedLayer, FrictionlessLayer, Punch, solve
from thinlayer.contact.fit import curve_entries, fit
from thinlayer.contact.models import MODEL_REGISTRY
from thinlayer.contact.problem import Depth, Elastic, Frictionless, Problem
from thinlayer.numerics import solve_axisymmetric

SLOW = os.environ.get("THINLAYER_SLOW") == "1"
E, NU, H = 3.0, 0.3, 0.2
MU = E / (2 * (1 + NU))
TIPS = {"cone70": (Punch.cone(70), (0.5, 0.7, 0.9, 1.1)),
        "sphere": (Punch.sphere(10), (0.15, 0.2, 0.25, 0.3)),
        "blunted": (Punch.blunted_cone(0.5, 70), (0.5, 0.7, 0.9, 1.1))}


def direct_forces(layer, tip, depths, mu=MU, H=H):
    return np.array([solve_axisymmetric(layer, tip, d, H=H, mu=mu, error_estimate=False).force for d in depths])


@pytest.fixture(scope="module")
def cone_data():
    tip, d = TIPS["cone70"]
    d = np.array(d)
    return tip, d, direct_forces(BondedLayer(NU), tip, d)


@pytest.mark.parametrize("name", ["sphere", "blunted"] if SLOW else ["blunted"])
def test_fit_tip_law_recovers_E_from_direct_solutions(name):
    """Thin layer (c/H from 5 to 20): the tip law's E within its own estimate (its model_error over the data)."""
    tip, d = TIPS[name]
    d = np.array(d)
    P = direct_forces(BondedLayer(NU), tip, d)
    r = fit(d, P, punch=tip, H=H, nu=NU)
    assert r.model == "tip-law" and r.valid and r.tip is tip
    assert abs(r.E / E - 1) <= r.model_error, (r.E, r.model_error)
    assert r.model_error < 0.05 and r.chi_max > 5


def test_fit_cone_tip_law(cone_data):
    """The cone 70: tip law within its estimate; model="auto" takes the cone's any-thickness law (T.9), within its
    own (smaller) estimate."""
    tip, d, P = cone_data
    r = fit(d, P, punch=tip, H=H, nu=NU, model="tip-law")
    assert r.model == "tip-law" and abs(r.E / E - 1) <= r.model_error < 0.05
    ra = fit(d, P, punch=tip, H=H, nu=NU)
    assert ra.model == "any-thickness" and abs(ra.E / E - 1) <= ra.model_error < 1e-3  # measured 1.1e-8, est. 4.2e-5


@pytest.mark.skipif(not SLOW, reason="builds the direct solver's table (10 solver runs, ~20 s CPU): THINLAYER_SLOW=1")
def test_fit_cone_direct(cone_data):
    """The cone 70 with the tabulated direct solver: E within its own estimate (1e-3 or less)."""
    tip, d, P = cone_data
    rd = fit(d, P, punch=tip, H=H, nu=NU, model="direct")
    assert rd.model == "direct" and abs(rd.E / E - 1) <= rd.model_error <= 1e-3, (rd.E, rd.model_error)
    # the force curve's values equal the solver's at a depth between the nodes
    assert rd.predict([0.8]) == pytest.approx(direct_forces(BondedLayer(NU), tip, [0.8]), rel=rd.model_error)


def test_fit_with_noise_has_honest_standard_errors_cone(cone_data):
    """1 % noise, 12 seeds: the true E lies within 2 standard errors in at least 10 (expected 11.4), and the spread
    of the fitted E agrees with the mean standard error within a factor 2."""
    tip, d, P = cone_data
    dd = np.repeat(d, 3)
    PP = np.repeat(P, 3)
    Es, ses, hits = [], [], 0
    for seed in range(12):
        rng = np.random.default_rng(seed)
        f = PP * (1 + 0.01 * rng.standard_normal(PP.size))
        r = fit(dd, f, punch=tip, H=H, nu=NU, sigma=0.01 * PP)
        Es.append(r.E)
        ses.append(r.E_se)
        hits += abs(r.E - E) <= 2 * r.E_se
    assert hits >= 10, hits
    assert 0.5 < np.std(Es, ddof=1) / np.mean(ses) < 2.0


def test_tip_law_curve_equals_solve():
    """The force curve is the model solve() answers with (forces and contact radius at three depths)."""
    tip, layer = Punch.cone(70), FrictionlessLayer(0.4)
    entry = next(m for m in MODEL_REGISTRY if m.name == "tip-law")
    curve = entry.force_curve(Problem(layer, tip, Elastic(1.0, 0.4), Frictionless(), Depth(1.0), 0.1, math.inf))
    for d0 in (0.5, 1.0, 2.0):
        ans = solve(layer, tip, delta0=d0, H=0.1, mu=1.0, model="tip-law", tol=math.inf)
        assert curve.force([d0])[0] == pytest.approx(ans.force, rel=1e-12)
        assert curve.contact_radius([d0])[0] == pytest.approx(ans.contact_radius, rel=1e-12)
        assert curve.estimate([d0])[0] == pytest.approx(max(ans.error_estimate["force"],
                                                             ans.error_estimate["contact_area"]), rel=1e-12)


def test_tip_law_slopes_are_the_derivatives():
    """d log P/d log delta and d log P/d log H of the tip-law curve against central differences."""
    tip, layer = Punch.power_law(1, 1.5), BondedLayer(0.3)
    entry = next(m for m in MODEL_REGISTRY if m.name == "tip-law")

    def curve(HH):
        return entry.force_curve(Problem(layer, tip, Elastic(1.0, 0.3), Frictionless(), Depth(1.0), HH, math.inf))

    d, h = np.array([0.5, 1.0, 2.0]), 1e-5
    gd, gH = curve(0.1).slopes(d)
    P = curve(0.1).force
    assert gd == pytest.approx((np.log(P(d * (1 + h))) - np.log(P(d * (1 - h)))) / (2 * h), rel=1e-7)
    assert gH == pytest.approx((np.log(curve(0.1 * (1 + h)).force(d)) - np.log(curve(0.1 * (1 - h)).force(d)))
                               / (2 * h), rel=1e-7)


def test_fit_tip_refusals():
    d, P = np.array([0.5, 1.0, 1.5]), np.array([1.0, 8.0, 27.0])
    with pytest.raises(ValueError, match="no force curve for the cone.*tip-law, any-thickness, direct"):
        fit(d, P, punch=Punch.cone(70), H=0.2, nu=0.3, model="hertz")
    with pytest.raises(ValueError, match="alpha"):
        fit(d, P, punch=Punch.cone(), H=0.2, nu=0.3)
    assert curve_entries(Punch.cone(70), 0.3, "bonded")[:1] == ["tip-law"]


@pytest.mark.parametrize("tip", [Punch.cone(70), Punch.sphere(10)])
@pytest.mark.parametrize("layer", [BondedLayer(0.3), FrictionlessLayer(0.3)])
def test_tip_law_curve_is_the_scalar_law_to_1e_15(tip, layer):
    """The vectorised curve (closed forms compiled once, benchmarks/bench_tips.py) gives the scalar route's numbers
    (TipForceLaw.evaluate through tip.level_set, solve()'s estimate and radius) to 1e-15 relative; 0 at depths <= 0,
    NaN where the estimate exceeds tol."""
    entry = next(m for m in MODEL_REGISTRY if m.name == "tip-law")
    curve = entry.force_curve(Problem(layer, tip, Elastic(1.0, 0.3), Frictionless(), Depth(1.0), 0.02, 0.2))
    depths = [0.07, 0.3, 0.77, 1.9] if tip.kind == "sphere" else [0.3, 0.77, 1.9, 5.5]
    d = np.array([*depths, 0.0, -1.0, 1e-6])
    P, A, est, c = curve.force(d), curve.contact_area(d), curve.estimate(d), curve.contact_radius(d)
    for k, d0 in enumerate(depths):
        ans = solve(layer, tip, delta0=d0, H=0.02, mu=1.0, nu=0.3, model="tip-law", tol=math.inf)
        assert P[k] == pytest.approx(ans.force, rel=1e-15, abs=0)
        assert A[k] == pytest.approx(ans.contact_area, rel=1e-15, abs=0)
        assert c[k] == pytest.approx(ans.contact_radius, rel=1e-15, abs=0)
        assert est[k] == pytest.approx(max(ans.error_estimate.values()), rel=1e-15, abs=0)
    assert P[4] == P[5] == A[4] == A[5] == c[4] == c[5] == 0.0
    assert np.isnan(P[6]) and np.isnan(A[6]) and np.isnan(c[6]) and est[6] > 0.2


def test_tip_law_curve_in_blocks_leaves_the_depths_alone():
    """More depths than a block (contact/models/tip_law.py BLOCK): the same numbers as the scalar route at entries of
    every block (1e-15), fresh writable results, the caller's depths unchanged (the law reuses its own arrays only)."""
    from thinlayer.contact.models.tip_law import BLOCK

    tip, layer = Punch.cone(70), BondedLayer(0.3)
    entry = next(m for m in MODEL_REGISTRY if m.name == "tip-law")
    curve = entry.force_curve(Problem(layer, tip, Elastic(1.0, 0.3), Frictionless(), Depth(1.0), 0.02, math.inf))
    d = np.linspace(0.2, 2.0, 2 * BLOCK + 7)
    d[5] = -1.0  # a depth without contact among them
    keep = d.copy()
    P, A, est = curve.force(d), curve.contact_area(d), curve.estimate(d)
    assert np.array_equal(d, keep) and P.flags.writeable and A.flags.writeable
    assert P[5] == A[5] == est[5] == 0.0
    for k in (0, BLOCK - 1, BLOCK, 2 * BLOCK + 6):
        ans = solve(layer, tip, delta0=float(d[k]), H=0.02, mu=1.0, model="tip-law", tol=math.inf)
        assert P[k] == pytest.approx(ans.force, rel=1e-15, abs=0)
        assert A[k] == pytest.approx(ans.contact_area, rel=1e-15, abs=0)
        assert est[k] == pytest.approx(max(ans.error_estimate.values()), rel=1e-15, abs=0)
