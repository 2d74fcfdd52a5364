"""Issue 29 item 2: every tip answers the protocol of thinlayer.punch.Tip, and tip_from_spec reads only the grammar.

Expected values come from closed forms written out here (the paraboloid's disc ``a^2 = 2 R delta0``, the flat face,
the ellipse of (3.1)) and from mpmath quadrature of the defining integrals, not from the engine.
"""
from __future__ import annotations

import math
import pickle

import mpmath
import numpy as np
import pytest
import sympy as sp

from thinlayer import symbols as S
from thinlayer.errors import InputError
from thinlayer.punch import (
    SMOOTHNESS,
    TIPS,
    FlatPunch,
    LevelSet,
    Punch,
    Tip,
    TipKind,
    TipParameter,
    TipSpecError,
    register_tip,
    tip_from_spec,
)

#: a value of each unit kind for a spec built from a registry row
EXAMPLE = {"length": "3/2", "angle": "70", "number": "1/2", "expression": "x_1**2 + 2*x_2**2 + x_1**4",
           "profile": "2*r**(3/2) + r**2"}
#: values where the kind's range excludes the generic example (issue 24: the power law needs n >= 1)
EXAMPLE_OF = {("power_law", "n"): "3/2", ("pyramid", "sides"): "3",
              ("polyhedral", "expr"): "max(x_1, -x_1/2 + x_2, -x_2 - x_1/3)"}


def _spec(row: TipKind) -> str:
    values = (EXAMPLE_OF.get((row.kind, p.name), EXAMPLE[p.unit_kind]) for p in row.parameters)
    return row.kind + ":" + ",".join(f"{p.name}={v}" for p, v in zip(row.parameters, values))


@pytest.mark.parametrize("kind", sorted(TIPS))
def test_every_registered_kind_answers_the_protocol(kind):
    row = TIPS[kind]
    tip = tip_from_spec(_spec(row))
    assert isinstance(tip, Tip)
    assert tip.kind == kind
    assert isinstance(tip.name, str) and tip.name
    assert isinstance(tip.description, str) and tip.description
    assert isinstance(tip.equation, str) and tip.equation
    assert isinstance(tip.axisymmetric, bool)
    assert isinstance(tip.expr, sp.Basic) and tip.expr.free_symbols <= {S.x1, S.x2}
    assert tip.polynomial is None or isinstance(tip.polynomial, sp.Poly)
    assert tip.parameters == () and tip.is_numeric
    assert tip.subs({}) == tip
    assert tip.smoothness in SMOOTHNESS
    assert tip.max_inner_order is None or (isinstance(tip.max_inner_order, int) and tip.max_inner_order >= 0)
    assert isinstance(tip.fixed_contact, bool)
    q = tip.quadric
    assert q is None or (len(q) == 3 and 0 < q[0] <= q[1])
    assert tip.sphere_radius is None or tip.sphere_radius > 0
    # the profile is Phi: compared with the sympy expression at a point inside the tip
    x = np.array([0.1, 0.3])
    y = np.array([0.2, -0.1])
    prof = tip.profile(x, y)
    assert prof.shape == (2,)
    for k in range(2):
        want = float(tip.expr.subs({S.x1: sp.Float(x[k]), S.x2: sp.Float(y[k])}))
        assert prof[k] == pytest.approx(want, rel=1e-12, abs=1e-15)
    if tip.axisymmetric:
        assert np.allclose(tip.radial_profile(np.hypot(x, y)), prof, rtol=1e-12, atol=1e-15)
    ls = tip.level_set(0.5)
    if ls is None:
        assert tip.polynomial is not None and not tip.axisymmetric and tip.quadric is None
    else:
        assert isinstance(ls, LevelSet)
        assert ls.area > 0 and ls.volume > 0 and ls.perimeter > 0
        assert ls.half_width == pytest.approx(2 * ls.area / ls.perimeter, rel=1e-12)
        assert (ls.radius is not None) == tip.axisymmetric
    text = tip.latex()
    assert isinstance(text, str) and all(ord(c) >= 32 for c in text)
    assert f"\\tag{{{tip.equation}}}" in text


def test_the_registry_rows_of_today():
    """The five kinds the design names (paraboloid, elliptic paraboloid, fourth degree, flat, polynomial)."""
    assert set(TIPS) >= {"paraboloid", "elliptic_paraboloid", "fourth_degree", "flat", "polynomial"}
    # issue 24 adds the tips of revolution (tests/punch/test_radial_tips.py) and the polyhedral tips
    # (tests/punch/test_pyramid.py)
    assert set(TIPS) - {"paraboloid", "elliptic_paraboloid", "fourth_degree", "flat", "polynomial"} == {
        "cone", "sphere", "blunted_cone", "power_law", "revolution", "pyramid", "polyhedral"}
    assert TIPS["flat"].form == "flat:a=<length>"
    assert [p.name for p in TIPS["elliptic_paraboloid"].parameters] == ["R1", "R2"]


def test_spec_builds_the_catalogue_punch():
    assert tip_from_spec("paraboloid:R=10") == Punch.paraboloid(10)
    assert tip_from_spec("paraboloid:radius=10") == Punch.paraboloid(10)  # an alias
    assert tip_from_spec("elliptic_paraboloid:R1=4, R2=1") == Punch.elliptic_paraboloid(4, 1)
    assert tip_from_spec("fourth_degree:R=1,K=2") == Punch.fourth_degree(1, 2)
    assert tip_from_spec("flat:a=1/2") == FlatPunch(0.5)
    assert tip_from_spec("paraboloid") == Punch.paraboloid()  # a parameter left out stays a symbol
    assert tip_from_spec("polynomial:expr=x_1**2 + x_2**2").expr == S.x1**2 + S.x2**2


@pytest.mark.parametrize("spec", [
    "paraboloid:R=__import__('os').system('touch {m}') or 1",
    "polynomial:expr=x_1**2 + x_2**2 + 0*__import__('os').system('touch {m}')",
    "flat:a=(lambda: __import__('os').system('touch {m}'))()",
    "elliptic_paraboloid:R1=1,R2=exec('open(\"{m}\", \"w\")')",
])
def test_spec_never_runs_a_payload(spec, tmp_path):
    marker = tmp_path / "pwned"
    with pytest.raises(InputError) as err:
        tip_from_spec(spec.replace("{m}", str(marker)))
    assert not marker.exists()
    assert "\n" not in str(err.value)


@pytest.mark.parametrize("spec, words", [
    # (was "pyramid:angle=35" before issue 24 registered the pyramid: an unknown kind still)
    ("wedge:angle=35", ["unknown tip kind 'wedge'", "paraboloid:R=<length>", "flat:a=<length>"]),
    ("paraboloid:Q=1", ["unknown key 'Q'", "paraboloid:R=<length>"]),
    ("paraboloid:R", ["is not key=value", "paraboloid:R=<length>"]),
    ("paraboloid:R=1,radius=2", ["given twice"]),
    ("flat", ["misses a", "flat:a=<length>"]),
    ("", ["unknown tip kind ''", "polynomial:expr=<expression>"]),
])
def test_spec_refuses_unknown_kinds_and_keys_naming_the_valid_forms(spec, words):
    with pytest.raises(TipSpecError) as err:
        tip_from_spec(spec)
    assert isinstance(err.value, InputError) and isinstance(err.value, ValueError)
    for w in words:
        assert w in str(err.value)


def test_spec_refuses_a_non_string():
    with pytest.raises(TypeError, match="must be a string"):
        tip_from_spec(10)


# ---- level sets against closed forms and quadrature ---------------------------------------------------------
def test_level_set_of_the_paraboloid():
    """Phi = r^2/(2R) < delta0 is the disc a^2 = 2 R delta0 (Hertz); the volume by mpmath quadrature."""
    R, d = 10.0, 0.5
    ls = Punch.paraboloid(R).level_set(d)
    a = math.sqrt(2 * R * d)
    assert ls.radius == pytest.approx(a, rel=1e-14)
    assert ls.area == pytest.approx(math.pi * a * a, rel=1e-14)
    assert ls.perimeter == pytest.approx(2 * math.pi * a, rel=1e-14)
    assert ls.half_width == pytest.approx(a, rel=1e-14)
    vol = mpmath.quad(lambda r: 2 * mpmath.pi * r * (d - r * r / (2 * R)), [0, a])
    assert ls.volume == pytest.approx(float(vol), rel=1e-13)
    assert ls.flux == pytest.approx(2 * math.pi * a * (a / R), rel=1e-13)  # oint |dPhi/dr| ds
    assert ls.second_order_flux == pytest.approx(2 * math.pi * a * (3 / R), rel=1e-13)  # Lap + Phi_rr = 3/R


def test_level_set_of_the_flat_punch():
    """The face r < a at every depth: area pi a^2, volume pi a^2 delta0 (mpmath), perimeter 2 pi a."""
    a = 1.5
    for d in (0.01, 3.0):
        ls = FlatPunch(a).level_set(d)
        assert ls.area == pytest.approx(math.pi * a * a, rel=1e-15)
        assert ls.volume == pytest.approx(float(mpmath.quad(lambda r: 2 * mpmath.pi * r * d, [0, a])), rel=1e-14)
        assert ls.perimeter == pytest.approx(2 * math.pi * a, rel=1e-15)
        assert ls.radius == a and ls.half_width == a
        assert ls.flux is None  # grad Phi is unbounded at the edge (F.8)


def test_level_set_of_the_elliptic_paraboloid():
    """The ellipse (3.1), semi-axes sqrt(2 R_i delta0); perimeter and flux by quadrature along it."""
    R1, R2, d = 4.0, 1.0, 0.5
    ls = Punch.elliptic_paraboloid(R1, R2).level_set(d)
    A, B = math.sqrt(2 * R1 * d), math.sqrt(2 * R2 * d)
    assert ls.area == pytest.approx(math.pi * A * B, rel=1e-14)

    def column(x):  # int (delta0 - Phi) dy across the ellipse at x
        b = B * mpmath.sqrt(max(1 - (x / A) ** 2, 0))
        return mpmath.quad(lambda y: d - x * x / (2 * R1) - y * y / (2 * R2), [-b, b])

    assert ls.volume == pytest.approx(float(mpmath.quad(column, [-A, A])), rel=1e-10)
    speed = lambda t: mpmath.hypot(A * mpmath.sin(t), B * mpmath.cos(t))  # noqa: E731
    assert ls.perimeter == pytest.approx(float(mpmath.quad(speed, [0, 2 * mpmath.pi])), rel=1e-13)

    def grad_ds(t):  # |grad Phi| ds on x = A cos t, y = B sin t
        x, y = A * mpmath.cos(t), B * mpmath.sin(t)
        return mpmath.hypot(x / R1, y / R2) * speed(t)

    assert ls.flux == pytest.approx(float(mpmath.quad(grad_ds, [0, 2 * mpmath.pi])), rel=1e-12)
    assert ls.radius is None


def test_level_set_of_the_fourth_degree_paraboloid():
    """Phi = r^2/(2R) + r^4/K^3: the radius by mpmath.findroot, the volume by mpmath.quad."""
    R, K, d = 1.0, 2.0, 0.3
    ls = Punch.fourth_degree(R, K).level_set(d)
    phi = lambda r: r * r / (2 * R) + r**4 / K**3  # noqa: E731
    a = mpmath.findroot(lambda r: phi(r) - d, 0.7)
    assert ls.radius == pytest.approx(float(a), rel=1e-14)
    assert ls.volume == pytest.approx(float(mpmath.quad(lambda r: 2 * mpmath.pi * r * (d - phi(r)), [0, a])), rel=1e-13)
    dphi = mpmath.diff(phi, a)
    assert ls.flux == pytest.approx(float(2 * mpmath.pi * a * dphi), rel=1e-12)


def test_level_set_of_an_annulus_and_refusals():
    """Phi = (r^2 - 1)^2 < 1/4 is the annulus 1/2 < r^2 < 3/2; a falling tip and symbols are refused."""
    ls = Punch("(x_1**2 + x_2**2 - 1)**2").level_set("1/4")
    assert ls.area == pytest.approx(math.pi * (1.5 - 0.5), rel=1e-14)
    assert ls.perimeter == pytest.approx(2 * math.pi * (math.sqrt(1.5) + math.sqrt(0.5)), rel=1e-14)
    assert ls.radius is None
    vol = mpmath.quad(lambda r: 2 * mpmath.pi * r * (0.25 - (r * r - 1) ** 2), [mpmath.sqrt(0.5), mpmath.sqrt(1.5)])
    assert ls.volume == pytest.approx(float(vol), rel=1e-13)
    with pytest.raises(InputError, match="unbounded"):
        Punch("x_1**2 + x_2**2 - (x_1**2 + x_2**2)**2").level_set(1)
    with pytest.raises(InputError, match="needs numbers for the parameters R"):
        Punch.paraboloid().level_set(1)
    with pytest.raises(InputError, match="positive finite"):
        Punch.paraboloid(1).level_set(-1)
    assert Punch("x_1**2 + 2*x_2**2 + x_1**4").level_set(1) is None  # the contour stages compute that one


# ---- shape answers -------------------------------------------------------------------------------------------
@pytest.mark.parametrize("expr, axi", [
    ("x_1**2 + x_2**2", True), ("(x_1**2 + x_2**2)**2/3 + x_1**2 + x_2**2", True), ("x_1**2 + 2*x_2**2", False),
    ("x_1*x_2", False), ("(x_1**2 + x_2**2)**2 + x_1", False), ("(x_1**2 + x_2**2)/(2*R)", True),
])
def test_axisymmetry_is_the_tips_answer(expr, axi):
    assert Punch(expr).axisymmetric is axi


def test_quadric_and_sphere_radius():
    k1, k2, angle = Punch("x_1**2 + x_1*x_2 + x_2**2").quadric  # K = [[2, 1], [1, 2]]: eigenvalues 1, 3
    assert (k1, k2) == pytest.approx((1.0, 3.0), rel=1e-14)
    assert abs(math.cos(angle)) == pytest.approx(math.sqrt(0.5), rel=1e-12)  # the axis x1 = -x2
    assert Punch.paraboloid(4).sphere_radius == 4.0
    assert Punch.paraboloid(4).quadric == (0.25, 0.25, 0.0)
    assert Punch.elliptic_paraboloid(4, 1).sphere_radius is None
    assert Punch("x_1**2 - x_2**2").quadric is None  # not positive definite
    assert Punch("x_1**2 + x_2**2 + x_1").quadric is None  # not a quadratic form
    assert Punch.paraboloid().quadric is None and Punch.paraboloid().sphere_radius is None  # symbolic
    flat = FlatPunch(1)
    assert (flat.fixed_contact, flat.smoothness, flat.max_inner_order, flat.polynomial) == (True, "edge-singular", 0,
                                                                                            None)
    assert flat.profile(0.5, 0.0) == 0.0 and flat.profile(1.5, 0.0) == math.inf


def test_punch_with_a_profile_still_pickles():
    p = Punch.paraboloid(2)
    p.profile(1.0, 1.0)
    assert pickle.loads(pickle.dumps(p)) == p


def test_flat_punch_latex_has_no_control_characters():
    """The TAB bug: '\\t' of '\\text' and '\\tag' in a non-raw string printed a TAB (issue 29)."""
    text = FlatPunch(1.5).latex()
    assert not any(ord(c) < 32 for c in text), repr(text)
    assert r"\text{on}" in text and text.endswith(r"\tag{F.1}")
    assert text == r"u_3 = w_0 \ \text{on}\ r < a,\quad a = 1.5 \tag{F.1}"


# ---- the registry contract -----------------------------------------------------------------------------------
def test_register_tip_checks_the_contract():
    par = TipParameter("c", "length", "a length")
    with pytest.raises(ValueError, match="registered already"):
        register_tip(TipKind("flat", FlatPunch, (par,), "again"))
    with pytest.raises(ValueError, match="not callable"):
        register_tip(TipKind("toy_tip", 3, (par,), "a toy"))
    with pytest.raises(ValueError, match="repeat"):
        register_tip(TipKind("toy_tip", FlatPunch, (par, TipParameter("d", "length", "d", ("c",))), "a toy"))
    with pytest.raises(ValueError, match="identifier"):
        register_tip(TipKind("toy tip", FlatPunch, (par,), "a toy"))
    with pytest.raises(ValueError, match="unit kind"):
        TipParameter("c", "furlong", "a length")
    assert "toy_tip" not in TIPS


def test_a_new_kind_is_one_registration():
    """A kind registered outside the package is read by tip_from_spec without touching it."""
    row = register_tip(TipKind("toy_tip", lambda c: FlatPunch(2 * c), (TipParameter("c", "length", "half a"),),
                               "a flat punch of radius 2c"))
    try:
        assert tip_from_spec("toy_tip:c=3/4") == FlatPunch(1.5)
        assert "toy_tip:c=<length>" in str(pytest.raises(TipSpecError, tip_from_spec, "nope").value)
    finally:
        del TIPS[row.kind]
