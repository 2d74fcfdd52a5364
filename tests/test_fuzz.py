"""Fuzz suite (hypothesis): random polynomial punches, Poisson ratios, thicknesses and indentations.

Every call of :func:`thinlayer.solve` either answers or raises one of the documented errors (a ``ValueError``:
:class:`~thinlayer.asymptotics.solution.ValidityError` outside the model's validity, ``PunchError``, a contour
error); any other exception is a crash and fails the test.  An answer has ``P > 0``, a positive contact area,
``p >= 0`` everywhere it is sampled, a finite error estimate, and the force grows with the indentation and falls
with the layer thickness.  A few hundred examples run by default; ``THINLAYER_SLOW=1`` runs many more.
"""
from __future__ import annotations

import math
import os

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import thinlayer as tl
from thinlayer import symbols as S

SLOW = os.environ.get("THINLAYER_SLOW") == "1"
EXAMPLES = 2000 if SLOW else 60
FUZZ = settings(max_examples=EXAMPLES, deadline=None, derandomize=not SLOW,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])

x1, x2 = S.x1, S.x2


@st.composite
def punches(draw):
    """A convex-ish polynomial punch: a positive-definite quadratic, a tilt, and small cubic/quartic terms."""
    a = draw(st.floats(0.02, 5.0))
    b = draw(st.floats(0.02, 5.0))
    c = draw(st.floats(-0.9, 0.9)) * math.sqrt(a * b)  # keeps the quadratic part positive definite
    expr = sp.Rational(str(round(a, 4))) * x1**2 + sp.Rational(str(round(b, 4))) * x2**2 \
        + sp.Rational(str(round(c, 4))) * x1 * x2
    if draw(st.booleans()):
        expr += sp.Rational(str(round(draw(st.floats(-0.05, 0.05)), 4))) * x1
    if draw(st.booleans()):
        expr += sp.Rational(str(round(draw(st.floats(0.0, 0.5)), 4))) * (x1**2 + x2**2) ** 2
    return tl.Punch(expr)


layers = st.one_of(
    st.sampled_from(["-0.5", "0", "0.2", "3/10", "0.4", "0.45", "0.49"]).map(tl.BondedLayer),
    st.just(tl.FrictionlessLayer()),
)


def _solve(layer, punch, delta0, H):
    nu = 0.3 if layer.numeric_nu is None else None
    return tl.solve(layer, punch, delta0=delta0, H=H, mu=1.0, nu=nu, model="asymptotic")


def _answer_or_documented_error(layer, punch, delta0, H):
    try:
        return _solve(layer, punch, delta0, H)
    except ValueError:  # ValidityError, PunchError, contour errors: documented, one clear line
        return None


def _check_answer(sol):
    assert math.isfinite(sol.force) and sol.force > 0, sol
    assert math.isfinite(sol.contact_area) and sol.contact_area > 0, sol
    est = getattr(sol, "error_estimate", None)
    if est is not None:
        values = est.values() if isinstance(est, dict) else [est]
        assert all(math.isfinite(float(v)) and float(v) >= 0 for v in values), est
    # the pressure on a grid over (and beyond) the contact region
    r = math.sqrt(sol.contact_area / math.pi) * 1.5
    g = np.linspace(-r, r, 41)
    X1, X2 = np.meshgrid(g, g)
    p = np.asarray(sol.pressure(X1, X2), dtype=float)
    assert np.all(np.isfinite(p)) and np.all(p >= 0), float(np.nanmin(p))


@FUZZ
@given(layer=layers, punch=punches(), delta0=st.floats(0.01, 2.0), H_over_a=st.floats(0.01, 0.6))
def test_solve_answers_well_or_refuses_clearly(layer, punch, delta0, H_over_a):
    a = math.sqrt(delta0 / float(max(punch.expr.coeff(x1, 2).subs(x2, 0), punch.expr.coeff(x2, 2).subs(x1, 0))))
    H = H_over_a * a
    sol = _answer_or_documented_error(layer, punch, delta0, H)
    if sol is not None:
        _check_answer(sol)


@FUZZ
@given(layer=layers, R=st.floats(0.5, 50.0), delta0=st.floats(0.01, 1.0), H_over_a=st.floats(0.01, 0.3))
def test_force_grows_with_indentation_and_falls_with_thickness(layer, R, delta0, H_over_a):
    punch = tl.Punch.paraboloid(R=sp.Rational(str(round(R, 3))))
    a = math.sqrt(delta0 / float(punch.expr.coeff(x1, 2)))  # contact radius sqrt(2 R delta0)
    H = H_over_a * a
    base = _answer_or_documented_error(layer, punch, delta0, H)
    deeper = _answer_or_documented_error(layer, punch, 1.1 * delta0, H)
    thicker = _answer_or_documented_error(layer, punch, delta0, 1.1 * H)
    assume(base is not None)
    _check_answer(base)
    if deeper is not None:
        assert deeper.force > base.force
    if thicker is not None:
        assert thicker.force < base.force


@pytest.mark.parametrize("kwargs", [
    {"H": 1e300}, {"H": 1e-300}, {"mu": 1e308}, {"mu": 1e-308}, {"delta0": 1e-300}, {"delta0": 1e6},
    {"H": float("inf")}, {"H": float("nan")}, {"mu": float("inf")}, {"delta0": -1.0}, {"H": 0.0},
])
def test_extreme_inputs_answer_finitely_or_refuse(kwargs):
    args = {"delta0": 0.1, "H": 0.05, "mu": 1.0, **kwargs}
    try:
        sol = tl.solve(tl.BondedLayer(0.3), tl.Punch.paraboloid(R=10), model="asymptotic", **args)
    except ValueError as exc:
        assert "\n" not in str(exc) and str(exc)
        return
    _check_answer(sol)
