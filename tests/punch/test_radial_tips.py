"""Tips of revolution (issue 24): cone, exact sphere, blunted cone, power law, revolution."""
import math
import os

import mpmath
import numpy as np
import pytest
import sympy as sp

import thinlayer as tl
from thinlayer import BondedLayer, Punch
from thinlayer import symbols as S
from thinlayer.parse import ExpressionError, parse_expression
from thinlayer.punch import TIPS, PunchError, tip_from_spec
from thinlayer.punch._radial import apex_inner_order, r

SLOW = os.environ.get("THINLAYER_SLOW") == "1"


def test_kinds_registered_and_specs():
    for kind in ("cone", "sphere", "blunted_cone", "power_law", "revolution"):
        assert kind in TIPS
    assert tip_from_spec("cone:angle=70") == Punch.cone(70)
    assert tip_from_spec("sphere:R=3").R == 3
    assert tip_from_spec("blunted_cone:R=1,angle=60").join_radius == pytest.approx(0.5, rel=1e-15)
    assert tip_from_spec("power_law:C=2,n=1.5").n == sp.Rational(3, 2)
    assert tip_from_spec("revolution:expr=R - sqrt(R**2 - r**2)").radial_expr == sp.Symbol("R") - sp.sqrt(
        sp.Symbol("R") ** 2 - r**2)


@pytest.mark.parametrize("bad", [0, 90, -5, 120, "abc", "1/0"])
def test_angle_in_degrees_validated(bad):
    with pytest.raises((PunchError, ValueError)):
        Punch.cone(bad)


def test_angle_is_degrees():
    assert Punch.cone(45).radial_profile([2.0])[0] == pytest.approx(2.0, rel=1e-15)
    assert Punch.cone(70).alpha == 7 * sp.pi / 18  # exact


def test_symbolic_angle_is_degrees_too():
    """No unit trap (issue 24 item 6): the symbol alpha is the angle in degrees in the expression, its LaTeX, subs()
    and parameters alike; the expression converts it explicitly."""
    alpha = sp.Symbol("alpha", positive=True)
    for sym, num in ((Punch.cone(), Punch.cone(70)), (Punch.blunted_cone(2), Punch.blunted_cone(2, 70))):
        assert sym.subs({"alpha": 70}).expr == num.expr
        assert sym.expr.subs(alpha, 70) == num.expr  # the printed expression read with degrees
        assert sym.half_angle == alpha and num.half_angle == 70
        assert r"\frac{\pi \alpha}{180}" in sym.latex()
    rr = 1.3
    assert float(Punch.cone().radial_expr.subs({alpha: 70, r: rr})) == pytest.approx(
        float(Punch.cone(70).radial_profile([rr])[0]), rel=1e-15)
    assert float(Punch.cone().radial_expr.subs({alpha: 70, r: rr})) == pytest.approx(rr / math.tan(math.radians(70)),
                                                                                       rel=1e-15)


@pytest.mark.parametrize("payload", ["sqrt(__import__('os').system('true'))", "exp(r)", "r.__class__",
                                     "abs(r)(1)", "getattr(r, 'x')", "lambda: 1", "r**a", "x_1**2 + r"])
def test_revolution_refuses_code(payload):
    with pytest.raises((PunchError, ExpressionError)):
        Punch.revolution(payload)


def test_radial_grammar_bounds():
    assert parse_expression("r**1.5", radial=True) == r ** sp.Rational(3, 2)
    with pytest.raises(ExpressionError):  # the same refusals as the polynomial grammar
        parse_expression("(r + a + b + c + d)**1000", radial=True)
    with pytest.raises(ExpressionError):
        parse_expression("r**(1/10001)", radial=True)
    with pytest.raises(ExpressionError):  # calls stay refused outside radial profiles
        parse_expression("sqrt(x_1)")


def test_revolution_must_start_at_zero_and_increase():
    with pytest.raises(PunchError):
        Punch.revolution("1 + r")
    with pytest.raises(PunchError):
        Punch.revolution("r - r**2")


def test_inner_order_from_the_apex():
    # Laplacian^k r^n = n^2 (n-2)^2 ... r^(n-2k): integrable in the plane iff n - 2k > -2 (power_law docstring)
    for n, want in ((1, 1), (sp.Rational(3, 2), 1), (3, 2), (sp.Rational(5, 2), 2), (5, 3)):
        assert Punch.power_law(1, n).max_inner_order == want
        assert apex_inner_order(r**n)[0] == want  # the general reading of the apex agrees
        assert Punch.power_law(1, n).smoothness == "apex"
    assert Punch.power_law(1, 4).max_inner_order is None and Punch.power_law(1, 4).smoothness == "smooth"
    # cone: Laplacian Phi = cot/r, Laplacian^2 Phi = cot/r^3 (cone.py docstring)
    cot = sp.cot(Punch.cone().alpha)
    lap = sp.diff(r * sp.diff(r * cot, r), r) / r
    assert sp.simplify(lap - cot / r) == 0
    assert sp.simplify(sp.diff(r * sp.diff(lap, r), r) / r - cot / r**3) == 0
    assert Punch.cone(70).max_inner_order == 1 and Punch.cone(70).smoothness == "apex"
    assert Punch.sphere(1).max_inner_order is None and Punch.sphere(1).smoothness == "smooth"
    assert Punch.blunted_cone(1, 70).max_inner_order == 1
    assert Punch.revolution("r**2/2 + r**3").max_inner_order == 2


def test_every_tip_member_answers():
    for tip in (Punch.cone(70), Punch.sphere(2), Punch.blunted_cone(0.5, 70), Punch.power_law(2, 1.5),
                Punch.revolution("r**2/2 + r**3")):
        assert tip.axisymmetric and tip.polynomial is None and not tip.fixed_contact
        assert tip.quadric is None and tip.sphere_radius is None
        assert tip.kind in TIPS and tip.latex() and str(tip)
        x = np.array([0.1, 0.3])
        assert np.allclose(tip.profile(x, 0 * x), tip.radial_profile(x), rtol=1e-15)
        assert np.allclose(tip.profile(0 * x, x), tip.radial_profile(x), rtol=1e-15)
        assert tip.radial_profile(0.0) == 0.0
        ls = tip.level_set(0.2)
        assert ls.area > 0 and ls.volume > 0 and ls.flux > 0


def test_blunted_cone_join_continuous():
    tip = Punch.blunted_cone(1.0, 70)
    rt = tip.join_radius
    assert rt == pytest.approx(math.cos(math.radians(70)), rel=1e-15)
    lo, hi = rt * (1 - 1e-9), rt * (1 + 1e-9)
    assert tip.radial_profile(lo)[()] == pytest.approx(tip.radial_profile(hi)[()], rel=1e-8)
    assert tip.radial_slope(lo)[()] == pytest.approx(tip.radial_slope(hi)[()], rel=1e-8)
    assert tip.radial_slope(hi)[()] == pytest.approx(1 / math.tan(math.radians(70)), rel=1e-14)


def test_sphere_profile_stable_and_absent_beyond():
    tip = Punch.sphere(1e3)
    assert tip.radial_profile(1e-6)[()] == pytest.approx(1e-12 / 2e3, rel=1e-14)  # no cancellation
    assert tip.radial_profile(2e3)[()] == math.inf
    with pytest.raises(PunchError):
        tip.level_set(1e3)


@pytest.mark.parametrize("tip", [Punch.cone(70), Punch.sphere(2), Punch.power_law(1.3, 1.5),
                                 Punch.blunted_cone(0.5, 70), Punch.revolution("r**2/2 + r**3")])
def test_level_set_against_mpmath(tip):
    d = 0.3
    ls = tip.level_set(d)
    f = sp.lambdify(r, tip.radial_expr, "mpmath")
    a = mpmath.findroot(lambda s: f(s) - d, ls.radius)
    pts = [0, *[b for b in tip.radial_breakpoints if b < a], a]
    V = mpmath.quad(lambda s: 2 * mpmath.pi * s * (d - f(s)), pts)
    slope = mpmath.diff(f, a)
    assert ls.radius == pytest.approx(float(a), rel=1e-12)
    assert ls.volume == pytest.approx(float(V), rel=1e-11)
    assert ls.flux == pytest.approx(float(2 * mpmath.pi * a * slope), rel=1e-9)


def test_cone_leading_law_symbolic():
    from thinlayer.asymptotics.tip_law import tip_force_law

    layer = BondedLayer()
    law = tip_force_law(layer, Punch.cone())
    al = Punch.cone().alpha
    want = sp.pi * layer.vartheta * sp.tan(al) ** 2 * S.delta0**3 / (3 * layer.A * S.H)  # issue 24 item 2
    diff = law.P0 - want
    assert diff == 0 or sp.cancel(diff) == 0 or sp.simplify(diff) == 0
    # the level set it comes from: V = pi tan^2 delta0^3/3, J = 2 pi delta0 (cone.py docstring)
    ex = Punch.cone().level_set_expressions()
    assert sp.simplify(ex["volume"] - sp.pi * sp.tan(al) ** 2 * S.delta0**3 / 3) == 0
    assert sp.simplify(ex["flux"] - 2 * sp.pi * S.delta0) == 0
    # J = iint Laplacian Phi (divergence theorem through the apex)
    a = ex["radius"]
    assert sp.simplify(sp.integrate(2 * sp.pi * r * sp.cot(al) / r, (r, 0, a)) - ex["flux"]) == 0
    assert law.remainder_order == 3
    # numeric: P0 at numbers against the mpmath quadrature of V
    byname = {"delta_0": 0.7, "H": 0.1, "mu": 1.0, "nu": 0.3, "alpha": 70}  # the symbol alpha is in degrees
    num = {q: byname[q.name] for q in law.P0.free_symbols}
    Vq = mpmath.quad(lambda s: 2 * mpmath.pi * s * (0.7 - s / mpmath.tan(math.radians(70))),
                     [0, 0.7 * math.tan(math.radians(70))])
    lay = BondedLayer(0.3)
    want_num = float((lay.vartheta / (lay.A * S.H)).subs({S.H: 0.1, S.mu: 1})) * float(Vq)
    assert float(law.P0.subs(num)) == pytest.approx(want_num, rel=1e-12)


def test_revolution_max_min_of_linear_forms():
    """max/min of linear forms in r (issue 24 item 1): read by the grammar, a Piecewise of the pieces with its
    breakpoints; the values are the forms' max/min (checked against numpy's on a grid); refusals like the rest."""
    steep = tl.Punch.revolution("max(r/2, 2*r - 3)")
    flat = tl.Punch.revolution("min(2*r, r/2 + 3/2) + r**2/10")
    assert steep.radial_breakpoints == (2.0,) and flat.radial_breakpoints == (1.0,)
    rr = np.linspace(0.0, 6.0, 61)
    np.testing.assert_allclose(steep.radial_profile(rr), np.maximum(rr / 2, 2 * rr - 3), rtol=0, atol=1e-15)
    np.testing.assert_allclose(flat.radial_profile(rr), np.minimum(2 * rr, rr / 2 + 1.5) + rr**2 / 10, atol=1e-15)
    np.testing.assert_allclose(steep.radial_slope(np.array([1.0, 3.0])), [0.5, 2.0])
    assert steep.max_inner_order == 1 and steep.smoothness == "apex"  # a cone at the apex
    # symbolic coefficients stay a Max until .subs gives numbers
    sym = tl.Punch.revolution("max(a*r, 2*r - 3)")
    assert sym.radial_breakpoints == () and sym.subs({"a": "1/2"}).radial_breakpoints == (2.0,)
    with pytest.raises(tl.PunchError, match="not a linear form in r"):
        tl.Punch.revolution("max(r**2, r)")
    with pytest.raises(tl.PunchError, match="increasing"):  # flat-ended: not increasing from the apex
        tl.Punch.revolution("max(0, 2*r - 1)")
    with pytest.raises(tl.PunchError, match="increasing"):
        tl.Punch.revolution("min(r, -r)")
    with pytest.raises(tl.WorkLimitError, match="more than 64"):
        tl.Punch.revolution("max(" + ", ".join(["r"] * 70) + ")")
    with pytest.raises(tl.PunchError, match="x_1, x_2"):
        tl.Punch.revolution("max(x1, r)")


def test_revolution_max_solved_by_the_direct_solver():
    """Below its kink (contact radius 1 < 2) max(r/2, 2r - 3) is the cone r/2: the axisymmetric direct solver gives the
    same depth and force (a cone by another route: Punch.cone of cot(alpha) = 1/2); beyond it (radius 3) the depth
    is the profile's own, above the cone's."""
    from thinlayer.numerics.axisymmetric import contact_for_radius

    tip = tl.Punch.revolution("max(r/2, 2*r - 3)")
    cone = tl.Punch.cone(math.degrees(math.atan(2.0)))
    kw = dict(H=1.0, mu=1.0, n=24, error_estimate=False)
    a, b = (contact_for_radius(tl.BondedLayer(0.3), t, 1.0, **kw) for t in (tip, cone))
    assert a.force == pytest.approx(b.force, rel=1e-12) and a.delta0 == pytest.approx(b.delta0, rel=1e-12)
    deep, deep_cone = (contact_for_radius(tl.BondedLayer(0.3), t, 3.0, **kw) for t in (tip, cone))
    assert deep.delta0 > deep_cone.delta0 and deep.force > 0


@pytest.mark.skipif(not SLOW, reason="three direct solves, 10 s (THINLAYER_SLOW=1)")
def test_revolution_max_between_its_cones():
    """Beyond the kink the force lies between the cones r/2 (below the profile) and 2r (above it): frictionless
    contact is monotone in the profile (measured 7.65 < 70.3 < 116.2 at delta0 = 2, H = 1)."""
    P = [tl.solve(tl.BondedLayer(0.3), tl.Punch.revolution(e), delta0=2.0, H=1.0, mu=1.0, model="direct",
                  tol=1e-4).force for e in ("2*r", "max(r/2, 2*r - 3)", "r/2")]
    assert P[0] < P[1] < P[2] and 0.3 < P[1] / P[2] < 0.9
