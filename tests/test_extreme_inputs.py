"""Issue 23 item 5: at extreme values only thinlayer's exceptions (or correct answers) come out.

Every argument of ``solve``, ``fit``, ``force_arrays``, ``solve_axisymmetric`` and ``flat_punch_stiffness`` is driven
through :data:`EXTREMES` (tiny, huge, infinite and undefined floats, zero and negative numbers, a huge integer, a
Fraction, numpy scalars, an array where a scalar is expected, a bool, None), the others held at ordinary values.  An
answer must be positive and finite; an error a thinlayer ``ValueError``/``TypeError`` with one line; no numpy
warning may leak.  Where an answer is given at an extreme, it is held against an independent closed form: Hertz's
``P = (8/3) mu/(1 - nu) sqrt(R) delta0^(3/2)`` when the layer is far thicker than the contact (H/a >> 1).
"""
from __future__ import annotations

import math
import warnings
from fractions import Fraction
from functools import cache

import numpy as np
import pytest

import thinlayer as tl
from thinlayer.errors import ThinlayerError

EXTREMES = {
    "1e-300": 1e-300, "1e-199": 1e-199, "1e300": 1e300, "inf": math.inf, "-inf": -math.inf, "nan": math.nan,
    "0": 0, "-1": -1.0, "10**400": 10**400, "Fraction(1,3)": Fraction(1, 3), "np.float64(0.2)": np.float64(0.2),
    "np.int64(3)": np.int64(3), "array": np.array([0.1, 0.2]), "True": True, "None": None,
}

LAYER = tl.BondedLayer(0.3)
SPHERE = tl.Punch.paraboloid(10)


def hertz(R: float, d0: float, mu: float = 1.0, nu: float = 0.3) -> float:
    """Hertz's force of a sphere on the half-space, the independent closed form."""
    return 8.0 / 3.0 * mu / (1.0 - nu) * math.sqrt(R) * d0**1.5


@cache
def b0(nu: float = 0.3) -> float:
    """``b_0 = int_0^oo (1 - L(u)) du`` of the bonded layer (2.3), by scipy quadrature (independent of thinlayer).

    A thick layer stiffens Hertz's force to ``1 + 2 b_0 chi/pi + O(chi^2)``, ``chi = sqrt(R delta0)/H`` (T.7).
    """
    from scipy.integrate import quad

    k = 3 - 4 * nu

    def one_minus_L(u):
        e = math.exp(-2 * u)  # (2.3) divided by cosh 2u: stable for every u
        num = k * (1 - e * e) - 4 * u * e
        den = k * (1 + e * e) + (1 + k * k + 4 * u * u) * e
        return 1 - num / den

    return quad(one_minus_L, 0, math.inf, limit=200)[0]


def thick_hertz(R: float, d0: float, H: float) -> tuple[float, float]:
    """Hertz's force with the first thick-layer correction, and the size of the next term (chi^2)."""
    chi = math.sqrt(R * d0) / H
    return hertz(R, d0) * (1 + 2 * b0() * chi / math.pi), 5 * chi * chi


def _positive_finite(x) -> bool:
    a = np.asarray(x, dtype=float)
    return bool(a.size and np.all(np.isfinite(a)) and np.all(a > 0))


def _outcome(call) -> str:
    """``"error"``, ``"answer"``, or what went wrong."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # a numpy warning leaking is a failure
        warnings.simplefilter("ignore", tl.errors.ValidityWarning)  # a fit marked invalid says so itself
        try:
            out = call()
        except ThinlayerError as exc:
            text = str(exc)
            ok = isinstance(exc, (ValueError, TypeError)) and text.strip() and "\n" not in text.strip()
            return "error" if ok else f"{type(exc).__name__} without one line: {text[:200]!r}"
        except Exception as exc:  # noqa: BLE001 - anything else leaked
            return f"{type(exc).__name__}: {str(exc)[:200]}"
    return "answer" if out is not None else "returned None"


SOLVE_ARGS = {
    "delta0": lambda v: tl.solve(LAYER, SPHERE, delta0=v, H=0.05, mu=1.0),
    "H": lambda v: tl.solve(LAYER, SPHERE, delta0=0.1, H=v, mu=1.0),
    "mu": lambda v: tl.solve(LAYER, SPHERE, delta0=0.1, H=0.05, mu=v),
    "E": lambda v: tl.solve(LAYER, SPHERE, delta0=0.1, H=0.05, E=v),
    "force": lambda v: tl.solve(LAYER, SPHERE, force=v, H=0.05, mu=1.0),
    "nu": lambda v: tl.solve(tl.FrictionlessLayer(), SPHERE, delta0=0.1, H=0.05, mu=1.0, nu=v),
    "tol": lambda v: tl.solve(LAYER, SPHERE, delta0=0.1, H=0.05, mu=1.0, tol=v),
    "R": lambda v: tl.solve(LAYER, tl.Punch.paraboloid(v), delta0=0.1, H=0.05, mu=1.0),
    "a (flat)": lambda v: tl.solve(LAYER, tl.Punch.flat(v), delta0=0.1, H=0.05, mu=1.0),
    "n": lambda v: tl.solve(LAYER, SPHERE, delta0=0.1, H=0.05, mu=1.0, model="direct", n=v),
}
D = np.linspace(0.05, 1.0, 8)


@cache
def _curve() -> np.ndarray:
    return tl.force_any_thickness(D, 10.0, 2.0, E=3.0, nu=0.5)


FIT_ARGS = {
    "delta": lambda v: tl.fit(v, _curve(), punch=10.0, H=2.0),
    "delta[0]": lambda v: tl.fit([v, *D[1:]], _curve(), punch=10.0, H=2.0),
    "force": lambda v: tl.fit(D, v, punch=10.0, H=2.0),
    "punch": lambda v: tl.fit(D, _curve(), punch=v, H=2.0),
    "H": lambda v: tl.fit(D, _curve(), punch=10.0, H=v),
    "nu": lambda v: tl.fit(D, _curve(), punch=10.0, H=2.0, nu=v),
    "E0": lambda v: tl.fit(D, _curve(), punch=10.0, H=2.0, E0=v),
    "sigma": lambda v: tl.fit(D, _curve(), punch=10.0, H=2.0, sigma=v),
}
ARRAY_ARGS = {
    "delta0": lambda v: tl.force_arrays(LAYER, SPHERE, v, 0.05),
    "H": lambda v: tl.force_arrays(LAYER, SPHERE, [0.1], v),
    "mu": lambda v: tl.force_arrays(LAYER, SPHERE, [0.1], 0.05, mu=v),
    "tol": lambda v: tl.force_arrays(LAYER, SPHERE, [0.1], 0.05, tol=v),
}
AXI_ARGS = {  # few modes and no estimate: the point is what comes out, not accuracy
    "delta0": lambda v: tl.solve_axisymmetric(LAYER, SPHERE, v, 0.5, n=24, error_estimate=False),
    "H": lambda v: tl.solve_axisymmetric(LAYER, SPHERE, 0.1, v, n=24, error_estimate=False),
    "mu": lambda v: tl.solve_axisymmetric(LAYER, SPHERE, 0.1, 0.5, mu=v, n=24, error_estimate=False),
    "n": lambda v: tl.solve_axisymmetric(LAYER, SPHERE, 0.1, 0.5, n=v, error_estimate=False),
}
FLAT_ARGS = {
    "a_over_H": lambda v: tl.flat_punch_stiffness(LAYER, v),
    "a_over_H (thin)": lambda v: tl.flat_punch_stiffness(LAYER, v, "thin"),
    "max_error": lambda v: tl.flat_punch_stiffness(LAYER, 30.0, "thin", max_error=v),
}
SWEEP = [(f"{fn}({arg}={name})", call, value)
         for fn, table in (("solve", SOLVE_ARGS), ("fit", FIT_ARGS), ("force_arrays", ARRAY_ARGS),
                           ("solve_axisymmetric", AXI_ARGS), ("flat_punch_stiffness", FLAT_ARGS))
         for arg, call in table.items() for name, value in EXTREMES.items()]


@pytest.mark.parametrize("name, call, value", SWEEP, ids=[s[0] for s in SWEEP])
def test_only_thinlayer_errors_or_answers(name, call, value):
    got = _outcome(lambda: call(value))
    assert got in ("error", "answer"), f"{name}: {got}"


@pytest.mark.parametrize("arg", ["delta0", "H", "mu", "E", "force", "R"])
@pytest.mark.parametrize("value", [1e-300, 1e-199, 1e300])
def test_solve_answers_are_positive_and_finite(arg, value):
    """Where solve() answers at an extreme, force and contact area are positive finite numbers."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        try:
            ans = SOLVE_ARGS[arg](value)
        except ThinlayerError:
            return
    assert _positive_finite(ans.force) and _positive_finite(ans.contact_area), (arg, value, ans.force)
    assert all(e <= ans.tol for e in ans.error_estimate.values())


@pytest.mark.parametrize("delta0", [1e-200, 1e-100, 1e-12])
def test_tiny_depth_is_hertz(delta0):
    """delta0 tiny: H/a huge, the half-space; the any-thickness law answers with Hertz's force (independent)."""
    ans = tl.solve(LAYER, SPHERE, delta0=delta0, H=0.05, mu=1.0)
    assert ans.model == "any-thickness" and ans.H_over_a > 1e4
    P, rest = thick_hertz(10.0, delta0, 0.05)
    assert ans.force == pytest.approx(P, rel=rest + 1e-12)
    assert ans.contact_radius == pytest.approx(math.sqrt(10.0 * delta0), rel=2 * math.sqrt(10 * delta0) / 0.05 + 1e-12)


def test_tiny_depth_below_the_double_range_gives_the_true_reason():
    """delta0 = 1e-300: Hertz's force 1.2e-449 cannot be a double; the message names the half-space law."""
    with pytest.raises(tl.ValidityError, match="below the double range.*half-space: Hertz.*other units"):
        tl.solve(LAYER, SPHERE, delta0=1e-300, H=0.05, mu=1.0)


@pytest.mark.parametrize("force", [1e-300, 1e-250, 1e-30])
def test_tiny_force_is_hertz(force):
    """A force of 1e-300 (it raised 'math domain error'): the depth is Hertz's, delta0 = (P/K)^(2/3)."""
    ans = tl.solve(LAYER, SPHERE, force=force, H=0.05, mu=1.0)
    k = 8.0 / 3.0 / 0.7 * math.sqrt(10.0)
    d_hertz = (force / k) ** (2.0 / 3.0)
    assert ans.force == force and ans.delta0 == pytest.approx(d_hertz, rel=math.sqrt(10 * d_hertz) / 0.05 + 1e-9)


@pytest.mark.parametrize("H", [1e3, 1e6, 1e100, 1e300])
def test_thick_layer_is_the_half_space(H):
    """H/a >> 1: solve() answers Hertz's force with the thick-layer term 2 b_0 chi/pi (b_0 by scipy quadrature)."""
    ans = tl.solve(LAYER, SPHERE, delta0=0.1, H=H, mu=1.0)
    P, rest = thick_hertz(10.0, 0.1, H)
    assert ans.force == pytest.approx(P, rel=rest + 1e-12)
    assert ans.force != pytest.approx(hertz(10.0, 0.1), rel=1e-6) or H > 1e5  # the layer is seen at H = 1e3


def test_the_issue_cases_are_thinlayer_errors():
    """ZeroDivisionError (R = 1e-199), NotImplementedError (order=3), scipy's NaN (delta0 = 1e300): now one line."""
    with pytest.raises(tl.ValidityError, match="below the double range"):
        tl.solve(LAYER, tl.Punch.paraboloid(1e-199), delta0=1e-200, H=1e-201, mu=1.0)
    with pytest.raises(tl.NotDerivedError, match="order <= 2"):
        tl.solve(LAYER, SPHERE, delta0=0.1, H=0.05, mu=1.0, order=3)
    with pytest.raises(tl.ValidityError, match="beyond the double range"):
        tl.solve(LAYER, SPHERE, delta0=1e300, H=0.05, mu=1.0)


def test_flat_punch_of_radius_1e_300_refused_without_warnings():
    """Its contact area pi a^2 = 3e-600 is not a double (it came back as 0 with divide-by-zero warnings)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(tl.InputError, match="contact area pi a\\^2 is 3.1e-600, below the double range"):
            tl.solve(LAYER, tl.Punch.flat(1e-300), delta0=0.1, H=0.05, mu=1.0)
        ans = tl.solve(LAYER, tl.Punch.flat(1e-100), delta0=0.1, H=0.05, mu=1.0)
    # a/H = 2e-99: the half-space, P = 4 mu a w0/(1 - nu) (Boussinesq's rigid flat punch, independent)
    assert ans.force == pytest.approx(4 * 1e-100 * 0.1 / 0.7, rel=1e-9)
