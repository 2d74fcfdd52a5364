"""Issue 24 item 3: the thin-layer law of a pyramid (asymptotics/pyramid_law.py) and its solve() entry.

Checks: P0 and P1 against the level set computed independently (scipy polygon of the planes); the coefficient of J
is the engine's (the same as the cone's, which is checked against the direct solver elsewhere); the observed order of
the remainder |P - P0 - P1|/P0 against solve_2d (log-log slope over 4 thicknesses, equal to the derived 3 within
0.3); the estimates of the solve() entry cover the measured errors; auto picks the law or the direct solver.
"""
from __future__ import annotations

import math
import os

import mpmath
import numpy as np
import pytest
import sympy as sp

import thinlayer as tl
from thinlayer import symbols as S
from thinlayer.asymptotics.pyramid_law import REMAINDER_ORDER, polyhedral_force_law
from thinlayer.asymptotics.tip_law import tip_force_law
from thinlayer.numerics import solve_2d
from thinlayer.punch import Polyhedral

SLOW = os.environ.get("THINLAYER_SLOW") == "1"


def _direct(layer, tip, H, nu=None, cells_per_H=8):
    """solve_2d at delta0 = 1 on a square around the level set, Delta = H/cells_per_H."""
    R = float(np.abs(tip.polygon(1.0)).max())
    ext = 1.05 * R + 2.5 * H
    n = int(2 * ext / (H / cells_per_H)) + 1
    return solve_2d(layer, tip, delta0=1.0, H=H, n=n, extent=ext, tol=1e-10, nu=nu)


@pytest.mark.parametrize("sides", [3, 4])
def test_closed_form_law_ladder(sides):
    """P0, P1 symbolic (sector integrals) == the numeric polygon route; (1.8), (2.27), (4.1)."""
    layer = tl.BondedLayer(sp.Rational(3, 10))
    law = polyhedral_force_law(layer, tl.Punch.pyramid(None, sides))
    al = tl.Punch.pyramid(None, sides).alpha
    t = sp.tan(sp.pi / sides)
    expect0 = layer.vartheta / (layer.A * S.H) * sides * t * sp.tan(al)**2 * S.delta0**3 / 3
    expect1 = law.coefficient * 2 * sides * t * S.delta0
    for got, want in ((law.P0, expect0), (law.P1, expect1)):
        diff = got - want
        assert got == want or sp.expand(diff) == 0 or sp.simplify(diff) == 0
    # mpmath: the closed form at numbers equals the polygon's V and J (scipy hull), 35 degrees
    num = tl.Punch.pyramid(35, sides)
    general = Polyhedral(num.expr)
    P0, P1 = polyhedral_force_law(layer, general).evaluate(1.3, 0.05, 1.0)
    sub = {S.delta0: sp.Rational(13, 10), S.H: sp.Rational(1, 20), S.mu: 1, al: sp.pi * 35 / 180}
    assert mpmath.almosteq(mpmath.mpf(sp.N(law.P0.subs(sub), 20)), P0, 1e-12)
    assert mpmath.almosteq(mpmath.mpf(sp.N(law.P1.subs(sub), 20)), P1, 1e-12)


def test_first_correction_relative_to_the_cone():
    """The coefficient of J is the layer's: P1(pyramid)/P1(cone) = J ratio = N tan(pi/N)/pi at the same depth."""
    layer = tl.BondedLayer(0.3)
    P1_pyr = polyhedral_force_law(layer, tl.Punch.pyramid(35, 4)).evaluate(1.0, 0.1)[1]
    P1_cone = tip_force_law(layer, tl.Punch.cone(70)).evaluate(1.0, 0.1)[1]
    assert P1_pyr / P1_cone == pytest.approx(4 / math.pi, rel=1e-12)


def test_latex_and_order():
    law = polyhedral_force_law(tl.BondedLayer(0.3), tl.Punch.pyramid(35, 3))
    assert law.remainder_order == REMAINDER_ORDER == 3.0
    tex = law.latex()
    assert r"\tag{1.8}" in tex and "O" in tex and "(H/a)^{3}" in tex
    assert "corner" in law.remainder_sources and "apex" in law.remainder_sources
    with pytest.raises(tl.InputError, match="polyhedral tip"):
        polyhedral_force_law(tl.BondedLayer(0.3), tl.Punch.cone(70))
    with pytest.raises(tl.InputError, match="finite thickness"):
        polyhedral_force_law(tl.HalfSpace(), tl.Punch.pyramid(35))


@pytest.mark.parametrize(("layer", "nu"), [(tl.BondedLayer(0.3), None)] + (
    [(tl.FrictionlessLayer(), 0.3), (tl.BondedLayer(0.45), None)] if SLOW else []))
def test_observed_order_of_the_remainder(layer, nu):
    """log-log slope of |P_direct - P0 - P1|/P0 against H/a (a = inradius), 4 thicknesses: 3 within 0.3."""
    tip = tl.Punch.pyramid(35, 4)
    a = tip.level_set(1.0).half_width
    law = polyhedral_force_law(layer, tip)
    ratios = (0.1, 0.15, 0.2, 0.3) if not SLOW else (0.05, 0.1, 0.15, 0.2, 0.3)
    rem = []
    for x in ratios:
        res = _direct(layer, tip, x * a, nu, cells_per_H=8 if not SLOW else 12)
        P0, P1 = law.evaluate(1.0, x * a, nu=nu)
        rem.append(abs(res.force - P0 - P1) / P0)
    slope = np.polyfit(np.log(ratios), np.log(rem), 1)[0]
    assert abs(slope - REMAINDER_ORDER) < 0.3, (slope, rem)


@pytest.mark.parametrize(("tip", "layer", "nu", "x"), [
    (tl.Punch.pyramid(35, 4), tl.BondedLayer(0.3), None, 0.1),
    (tl.Punch.pyramid(35, 4), tl.FrictionlessLayer(), 0.3, 0.2),
    (tl.Punch.berkovich(), tl.BondedLayer(0.45), None, 0.2),
] + ([(tl.Punch.pyramid(35, 4), tl.BondedLayer(0.45), None, 0.05),
      (tl.Punch.berkovich(), tl.BondedLayer(0.3), None, 0.05),
      (tl.Punch.berkovich(), tl.FrictionlessLayer(), 0.3, 0.05)] if SLOW else []))
def test_estimates_cover_the_direct_solution(tip, layer, nu, x):
    a = tip.level_set(1.0).half_width
    H = x * a
    ans = tl.solve(layer, tip, delta0=1.0, H=H, mu=1.0, nu=nu, model="tip-law", tol=1.0)
    ref = _direct(layer, tip, H, nu, cells_per_H=10)
    assert ans.model == "tip-law"
    assert abs(ans.force / ref.force - 1) <= ans.error_estimate["force"]
    assert abs(ans.contact_area / ref.contact_area - 1) <= ans.error_estimate["contact_area"]


def test_solve_auto_chooses_law_or_direct():
    tip = tl.Punch.pyramid(35, 4)
    a = tip.level_set(1.0).half_width
    thin = tl.solve(tl.BondedLayer(0.3), tip, delta0=1.0, H=0.05 * a, mu=1.0)
    assert thin.model == "tip-law" and thin.force > 0 and thin.error_estimate["force"] < 0.05
    thick = tl.solve(tl.BondedLayer(0.3), tip, delta0=1.0, H=0.6 * a, mu=1.0, n=128)
    assert thick.model == "direct" and "tip-law: estimates" in thick.reason
    # the inverse problem through the law
    back = tl.solve(tl.BondedLayer(0.3), tip, force=thin.force, H=0.05 * a, mu=1.0)
    assert back.delta0 == pytest.approx(1.0, rel=1e-9)
    # bonded nu = 1/2: no law of order 1, said so
    with pytest.raises(tl.ValidityError, match=r"tip-law: nu = 1/2 on a bonded base: A = 0"):
        tl.solve(tl.BondedLayer(0.5), tip, delta0=1.0, H=0.3 * a, mu=1.0, model="asymptotic")
