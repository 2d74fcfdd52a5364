"""Issue 24 item 6 (pyramids): fit() through the pyramid's thin-layer law (contact/models/pyramid_law.py force_curve).

The synthetic curve is the direct solver's (:func:`thinlayer.numerics.solve_2d`, independent of the law): E must come
back within the law's own force estimate at the depths fitted.  The force curve equals solve()'s answer depth by depth
(the same law (1.8), (3.25) through the scalar route, ``tip.level_set``).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import thinlayer as tl
from thinlayer.contact.fit import fit
from thinlayer.contact.models import MODEL_REGISTRY
from thinlayer.contact.problem import Depth, Elastic, Frictionless, Problem
from thinlayer.numerics import solve_2d


def _curve(tip, layer, H, nu):
    entry = next(m for m in MODEL_REGISTRY if m.name == "tip-law" and m.force_curve(
        Problem(layer, tip, Elastic(1.0, nu), Frictionless(), Depth(1.0), H, math.inf)) is not None)
    return entry.force_curve(Problem(layer, tip, Elastic(1.0, nu), Frictionless(), Depth(1.0), H, 0.1))


@pytest.mark.parametrize("tip", [tl.Punch.pyramid(35, 4), tl.Punch.berkovich()])
def test_force_curve_equals_solve(tip):
    """Vectorised curve == solve(model='tip-law') at a few depths (force, area, estimate), NaN past tol, 0 at d <= 0."""
    layer, H = tl.BondedLayer(0.3), 0.05
    curve = _curve(tip, layer, H, 0.3)
    d = np.array([0.5, 1.0, 2.0])
    P, A, est = curve.force(d), curve.contact_area(d), curve.estimate(d)
    for i, di in enumerate(d):
        ans = tl.solve(layer, tip, delta0=di, H=H, mu=1.0, nu=0.3, model="tip-law", tol=1.0)
        assert P[i] == pytest.approx(ans.force, rel=1e-12)
        assert A[i] == pytest.approx(ans.contact_area, rel=1e-12)
        assert est[i] == pytest.approx(max(ans.error_estimate.values()), rel=1e-12)
    shallow = curve.force(np.array([0.02, 0.0, -1.0]))
    assert np.isnan(shallow[0]) and not curve.valid(np.array([0.02]))[0]
    assert shallow[1] == shallow[2] == 0.0
    gd, gH = curve.slopes(d)
    h = 1e-6  # the slopes against central differences of the curve itself
    fd = (np.log(curve.force(d * (1 + h))) - np.log(curve.force(d * (1 - h)))) / (2 * h)
    np.testing.assert_allclose(gd, fd, rtol=1e-6)
    up, down = _curve(tip, layer, H * (1 + h), 0.3), _curve(tip, layer, H * (1 - h), 0.3)
    fH = (np.log(up.force(d)) - np.log(down.force(d))) / (2 * h)
    np.testing.assert_allclose(gH, fH, rtol=1e-6)


def test_fit_recovers_E_from_the_direct_solver():
    """solve_2d's forces (mu = 1, nu = 0.3, bonded, H/a = 0.1 .. 0.17): fit(punch=Punch.pyramid(35)) gives
    E = 2 (1 + nu) within the law's force estimate at the depths fitted."""
    tip, layer, nu = tl.Punch.pyramid(35, 4), tl.BondedLayer(0.3), 0.3
    a1 = tip.level_set(1.0).half_width
    H = 0.1 * a1
    depths = np.array([0.6, 0.8, 1.0])
    forces = []
    for d in depths:
        ext = 1.05 * float(np.abs(tip.polygon(d)).max()) + 2.5 * H
        n = int(2 * ext / (H / 8)) + 1
        forces.append(solve_2d(layer, tip, delta0=float(d), H=H, n=n, extent=ext, tol=1e-10).force)
    res = fit(depths, np.array(forces), punch=tip, H=H, nu=nu, model="tip-law")
    assert res.model == "tip-law"
    est = _curve(tip, layer, H, nu).estimate(depths)
    assert np.all(est < 0.1)
    err = abs(res.E / (2 * (1 + nu)) - 1)
    print(f"E error {err:.3g}, estimates {est}")
    assert err <= est.max(), (res.E, est)
    # by default fit() takes the pyramid's any-thickness table (issue 25 item 1), inside the same bound
    auto = fit(depths, np.array(forces), punch=tip, H=H, nu=nu)
    assert auto.model == "any-thickness"
    assert abs(auto.E / (2 * (1 + nu)) - 1) <= est.max(), (auto.E, est)
