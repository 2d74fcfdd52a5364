"""Issue 24 item 1: the pyramidal tips (punch/pyramid.py) -- shape, level set, inner order, grammar, refusals.

Independent sources: the nominal projected-area functions of indenters (Vickers and modified Berkovich 24.5 delta0^2,
original Berkovich 23.96 delta0^2: Oliver & Pharr, J. Mater. Res. 7 (1992) 1564; ISO 14577-2), the polygon built by
scipy from the planes (Polyhedral) against the closed forms integrated over sectors (Pyramid), a brute-force grid
sum of (delta0 - Phi)_+, and mpmath line integrals of |grad Phi| along the polygon.
"""
from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp

import thinlayer as tl
from thinlayer import symbols as S
from thinlayer.errors import ThinlayerError, WorkLimitError
from thinlayer.parse import ExpressionError
from thinlayer.punch import TIPS, Polyhedral, PunchError, Pyramid, tip_from_spec

ANGLES = (20, 35, 50, 65.27, 80)


@pytest.mark.parametrize(("tip", "area", "rel"), [
    (tl.Punch.vickers(), 24.5, 2e-3),              # Oliver & Pharr (1992): A = 24.5 h^2 (24.504 exactly)
    (tl.Punch.berkovich(), 24.5, 2e-3),            # modified Berkovich, same area function
    (tl.Punch.pyramid(65.03, sides=3), 23.96, 1e-3),   # original Berkovich (ISO 14577-2: 23.96 h^2)
])
def test_nominal_area_functions(tip, area, rel):
    assert tip.level_set(1.0).area == pytest.approx(area, rel=rel)
    assert tip.level_set(2.0).area == pytest.approx(4 * area, rel=rel)


def test_nominal_angles_stated():
    assert float(tl.Punch.berkovich().alpha) == pytest.approx(math.radians(65.27), rel=1e-15)
    assert tl.Punch.berkovich().sides == 3
    assert float(tl.Punch.vickers().alpha) == pytest.approx(math.radians(136 / 2), rel=1e-15)
    assert tl.Punch.vickers().sides == 4


@pytest.mark.parametrize("sides", [3, 4])
@pytest.mark.parametrize("angle", ANGLES)
def test_closed_forms_equal_the_polygon(sides, angle):
    """Sector integrals (Pyramid) against the scipy polygon of the same planes (Polyhedral), and the brief's forms."""
    tip = Pyramid(angle, sides)
    general = Polyhedral(tip.expr)
    for d in (0.3, 1.0, 7.0):
        a, b = tip.level_set(d), general.level_set(d)
        for k in ("area", "volume", "perimeter", "flux", "half_width"):
            assert getattr(a, k) == pytest.approx(getattr(b, k), rel=1e-12), k
        rho = d * math.tan(math.radians(angle))
        t = math.tan(math.pi / sides)
        assert a.area == pytest.approx(sides * rho**2 * t, rel=1e-13)
        assert a.perimeter == pytest.approx(2 * sides * rho * t, rel=1e-13)
        assert a.volume == pytest.approx(a.area * d / 3, rel=1e-13)
        assert a.flux == pytest.approx(a.perimeter / math.tan(math.radians(angle)), rel=1e-13)
        assert a.half_width == pytest.approx(rho, rel=1e-13)


def test_symbolic_level_set_ladder():
    """The sympy sector integrals: == first, then the difference expanded/simplified, paired with mpmath."""
    for n in (3, 4):
        e = Pyramid(None, n).level_set_expressions()
        al = Pyramid(None, n).alpha
        expect = {"area": n * (S.delta0 * sp.tan(al))**2 * sp.tan(sp.pi / n),
                  "volume": n * (S.delta0 * sp.tan(al))**2 * sp.tan(sp.pi / n) * S.delta0 / 3,
                  "flux": 2 * n * sp.tan(sp.pi / n) * S.delta0}
        for k, v in expect.items():
            diff = e[k] - v
            assert e[k] == v or sp.expand(diff) == 0 or sp.simplify(diff) == 0, k
            num = {S.delta0: sp.Rational(7, 5), al: sp.Rational(3, 5)}
            assert mpmath.almosteq(mpmath.mpf(sp.N(e[k].subs(num), 30)), mpmath.mpf(sp.N(v.subs(num), 30)), 1e-25)


@pytest.mark.parametrize("tip", [Pyramid(35, 4), Pyramid(50, 3), Polyhedral("max(x1, -2*x2, -x1 + x2, 3*x2 - x1)")])
def test_volume_by_grid_sum_and_flux_by_line_integral(tip):
    d = 1.0
    ls = tip.level_set(d)
    verts = tip.polygon(d)
    # V: a midpoint sum of (delta0 - Phi)_+ on a fine grid (the kinks cost O(h^2))
    lo, hi = verts.min(axis=0) - 0.01, verts.max(axis=0) + 0.01
    m = 1500
    x = lo[0] + (np.arange(m) + 0.5) * (hi[0] - lo[0]) / m
    y = lo[1] + (np.arange(m) + 0.5) * (hi[1] - lo[1]) / m
    X, Y = np.meshgrid(x, y, indexing="ij")
    V = np.maximum(d - tip.profile(X, Y), 0).sum() * (hi[0] - lo[0]) * (hi[1] - lo[1]) / m**2
    assert V == pytest.approx(ls.volume, rel=1e-5)
    # J = oint |grad Phi| ds by mpmath along each edge, |grad Phi| by a central difference inside the face
    J = mpmath.mpf(0)
    for p, q in zip(verts, np.roll(verts, -1, axis=0)):
        mid = 0.5 * (p + q)
        inward = -mid / np.linalg.norm(mid) * 1e-6
        h = 1e-7
        c = mid + inward
        gx = (tip.profile(c[0] + h, c[1]) - tip.profile(c[0] - h, c[1])) / (2 * h)
        gy = (tip.profile(c[0], c[1] + h) - tip.profile(c[0], c[1] - h)) / (2 * h)
        J += mpmath.quad(lambda s: math.hypot(gx, gy) * np.linalg.norm(q - p), [0, 1])
    assert float(J) == pytest.approx(ls.flux, rel=1e-6)


@pytest.mark.parametrize("tip", [Pyramid(35, 4), Pyramid(65.27, 3), Polyhedral("max(x1, -2*x2, -x1 + x2, 3*x2 - x1)")])
def test_divergence_theorem_on_the_ridges(tip):
    """iint Laplacian Phi over omega0 = the ridges' line measure (|jump of grad Phi| x length to the corner) = J."""
    d = 1.3
    verts = tip.polygon(d)
    g = np.array([[float(a), float(b)] for a, b in tip.planes])
    mass = 0.0
    for v in verts:  # each corner ends one ridge: the two faces meeting there have the largest Phi at v
        vals = g @ v
        i, j = np.argsort(vals)[-2:]
        assert vals[i] == pytest.approx(d, rel=1e-12) and vals[j] == pytest.approx(d, rel=1e-12)
        t = v / np.linalg.norm(v)
        normal = np.array([-t[1], t[0]])
        mass += abs((g[i] - g[j]) @ normal) * np.linalg.norm(v)  # the jump of the normal derivative across it
    assert mass == pytest.approx(tip.level_set(d).flux, rel=1e-12)
    # and by a mollified Laplacian: Phi_eps = Phi * Gaussian, Laplacian by finite differences, summed over omega0
    eps, m = 0.01, 801
    lim = np.abs(verts).max() * 1.02
    x = np.linspace(-lim, lim, m)
    h = x[1] - x[0]
    X, Y = np.meshgrid(x, x, indexing="ij")
    k = np.arange(-6, 7)
    w = np.exp(-0.5 * (k * h / eps) ** 2)
    w /= w.sum()
    P = tip.profile(X, Y)
    from scipy.ndimage import convolve1d

    Pe = convolve1d(convolve1d(P, w, axis=0, mode="nearest"), w, axis=1, mode="nearest")
    lap = (np.roll(Pe, 1, 0) + np.roll(Pe, -1, 0) + np.roll(Pe, 1, 1) + np.roll(Pe, -1, 1) - 4 * Pe) / h**2
    d_in = d - 15 * eps  # off the smoothed contour: {Phi < d_in} holds the ridges' mass scaled by d_in/d
    inside = P < d_in
    assert (lap[inside].sum() * h * h) == pytest.approx(mass * d_in / d, rel=0.02)


def test_shape_answers_and_orientation():
    p4, p3 = Pyramid(35, 4), Pyramid(50, 3)
    for p in (p4, p3):
        assert (p.axisymmetric, p.polynomial, p.smoothness, p.max_inner_order, p.fixed_contact) == \
            (False, None, "ridge", 1, False)
        assert p.quadric is None and p.sphere_radius is None
    c = 1 / math.tan(math.radians(35))
    # faces normal to +-x1, +-x2: Phi = cot(alpha) |x1| on the x1 axis, the ridge along the diagonal
    assert p4.profile(np.array([2.0, -2.0, 0.0]), np.array([0.0, 0.0, -2.0])) == pytest.approx([2 * c] * 3)
    assert p4.profile(1.0, 1.0) == pytest.approx(c)
    # 3 sides: one face normal to -x2
    c3 = 1 / math.tan(math.radians(50))
    assert p3.profile(0.0, -1.0) == pytest.approx(c3)
    assert p3.profile(0.0, 1.0) == pytest.approx(c3 * math.cos(math.pi / 3))  # a ridge: r cot(alpha) cos(pi/N)
    poly = p3.polygon(1.0)
    assert poly[:, 1].min() == pytest.approx(-math.tan(math.radians(50)))  # the face's edge at x2 = -rho
    assert p4.profile(np.zeros((3, 4)), np.ones((3, 4))).shape == (3, 4)
    assert "\\max" in p4.latex() and "\\cot" in p4.latex() and "\\tag{1.1}" in p4.latex()


def test_from_expr_is_the_pyramid():
    cot = 1 / math.tan(math.radians(35))
    tip = tl.Punch.from_expr(f"max(x1, -x1, x2, -x2)*{cot!r}")
    ref = tl.Punch.pyramid(35)
    rng = np.random.default_rng(1)
    x, y = rng.normal(size=(2, 1000))
    assert np.allclose(tip.profile(x, y), ref.profile(x, y), rtol=1e-15, atol=0)
    for k in ("area", "volume", "perimeter", "flux"):
        assert getattr(tip.level_set(1.0), k) == pytest.approx(getattr(ref.level_set(1.0), k), rel=1e-13)
    # with a parameter, substituted through the grammar
    c = tl.Punch.from_expr("c*max(x_1, -x_1, x_2, -x_2)")
    assert [q.name for q in c.parameters] == ["c"]
    assert np.allclose(c.subs({"c": repr(cot)}).profile(x, y), ref.profile(x, y), rtol=1e-15, atol=0)
    # symbolically: the same Phi (difference cancels)
    diff = sp.cot(ref.alpha) * sp.Max(S.x1, -S.x1, S.x2, -S.x2) - ref.expr
    assert diff == 0 or sp.simplify(diff) == 0
    # a polynomial stays a Punch
    assert tl.Punch.from_expr("x1**2 + x2**2").polynomial is not None


def test_spec_and_registry():
    assert "pyramid" in TIPS and "polyhedral" in TIPS
    a = tip_from_spec("pyramid:face_angle=35,sides=3")
    assert a.sides == 3 and float(a.alpha) == pytest.approx(math.radians(35))
    b = tip_from_spec("polyhedral:expr=max(x_1, -x_1, x_2, -x_2)")
    assert b.level_set(1.0).area == pytest.approx(4.0)
    sym = tl.Punch.pyramid()
    assert [q.name for q in sym.parameters] == ["alpha"]
    assert sym.subs({"alpha": 35}).level_set(1.0).area == pytest.approx(tl.Punch.pyramid(35).level_set(1.0).area)
    with pytest.raises(PunchError, match="needs numbers"):
        sym.level_set(1.0)


@pytest.mark.parametrize(("args", "match"), [
    ((0, 4), "between 0 and 90"), ((90, 4), "between 0 and 90"), ((-5, 4), "between 0 and 90"),
    (("nan", 4), "unknown name"), ((35, 5), "3 or 4"), ((35, True), "3 or 4"), ((35, 3.5), "3 or 4"),
    (("__import__('os').system('true') or 35", 4), "not allowed"),
])
def test_pyramid_refusals(args, match):
    with pytest.raises(ThinlayerError, match=match) as exc:
        tl.Punch.pyramid(*args)
    assert isinstance(exc.value, (ValueError, TypeError)) and "\n" not in str(exc.value)


@pytest.mark.parametrize(("text", "kind", "match"), [
    ("max(x1, x2)", PunchError, "surround the origin"),
    ("max(x1, 2*x1, 3*x1)", PunchError, "surround the origin"),
    ("max(x1, -x1, x2)", PunchError, "not positive in every direction|surround"),
    ("min(x1, -x1, x2, -x2)", PunchError, "concave"),
    ("-max(x1, -x1, x2, -x2)", PunchError, "positive"),
    ("max(x1 + 1, -x1, x2, -x2)", PunchError, "constant term"),
    ("max(x1, -x1, x2, -x2)**2", PunchError, "positive multiple"),
    ("max(x1**2, x2)", ExpressionError, "not a linear form"),
    ("max(" + ",".join(["x1"] * 65) + ")", WorkLimitError, "more than 64"),
    ("max(x1, __import__('os'))", ExpressionError, "not allowed"),
    ("max(x1,,x2)", ExpressionError, "not allowed"),
])
def test_polyhedral_refusals(text, kind, match):
    with pytest.raises(kind, match=match) as exc:
        tl.Punch.from_expr(text)
    assert "\n" not in str(exc.value)


def test_extreme_coordinates():
    p = tl.Punch.pyramid(35, 3)
    with np.errstate(all="raise"):
        v = p.profile(np.array([1e300, -1e300, np.inf, 0.0]), np.array([0.0, 1e300, 0.0, -np.inf]))
    assert np.all(v > 0) and not np.isnan(v).any()
