"""Generated code that reads well and runs cleanly (issue 17, item 4).

* numbers without floating-point noise (``3.4999999999999996`` is ``3.5``, a 30-digit Float made from
  a double is printed as the double), exact rationals exact;
* common subexpressions computed once (the composite pressure's long expression appears once, not in
  both the condition and the branch of its ``Piecewise``);
* the numpy module is branch-safe: no "invalid value in sqrt" outside the contact, where the boundary
  layer's ``sqrt(v - h)`` has a negative argument, and the same values as sympy inside it.
"""
from __future__ import annotations

import importlib.util
import math
import re
import warnings

import numpy as np
import pytest
import sympy as sp

from thinlayer import BondedLayer, Punch, checked_lambdify, kernel_coefficients
from thinlayer.export.codegen import LANGUAGES, generate
from thinlayer.export.codegen.printers import clean_float

V, HH, B = sp.symbols("v h B", positive=True)


@pytest.fixture(scope="module")
def composite():
    from thinlayer.asymptotics.solution import compressible_solution

    sol = compressible_solution(BondedLayer(0.3), Punch.paraboloid(2), delta0=0.25, H=0.02,
                                boundary_layer="alexandrov")
    return sol.composite


def _boundary_q():
    tau = V - HH
    return sp.Piecewise((V * sp.erf(sp.sqrt(B * tau)) + sp.sqrt(tau / (sp.pi * B)) * sp.exp(-B * tau), V > HH),
                        (0, True))


_NUMBER = re.compile(r"(?<![\w.])(\d+\.\d+)(?:[eEdD][-+]?\d+)?")


def _noisy(literal: str) -> bool:
    """A decimal of 16 or more digits that a decimal at least 3 digits shorter matches to 4 units in the last place."""
    digits = literal.replace(".", "").lstrip("0")
    if len(digits) < 16:
        return False
    x = float(literal)
    return any(abs(float(f"{x:.{d}g}") - x) <= 4 * math.ulp(x) for d in range(1, len(digits) - 2))


def test_noise_detector_detects_noise():
    assert _noisy("3.4999999999999996") and _noisy("0.24999999999999990748141461457")
    assert not _noisy("0.14519285684593675") and not _noisy("3.5") and not _noisy("0.3333333333333333")


@pytest.mark.parametrize("language", LANGUAGES)
def test_no_floating_point_noise(composite, language):
    src = generate(composite, language).source
    noisy = [m.group(1) for m in _NUMBER.finditer(src) if _noisy(m.group(1))]
    assert not noisy, f"{language}: noisy literals {noisy}"


def test_clean_float_stays_within_four_ulps():
    rng = np.random.default_rng(3)
    for x in [*rng.standard_normal(200) * 10.0 ** rng.integers(-20, 20, 200), 3.4999999999999996, 1 / 3]:
        y = float(clean_float(x))
        assert abs(y - x) <= 4 * math.ulp(x)


@pytest.mark.parametrize("language", ["c", "fortran", "rust", "julia", "octave", "python"])
def test_exact_rationals_stay_exact(language):
    src = generate(kernel_coefficients(BondedLayer(), 2), language).source
    assert not [m.group(1) for m in _NUMBER.finditer(src.split("\n\n", 1)[-1]) if len(m.group(1)) > 8]


@pytest.mark.parametrize("language", LANGUAGES)
def test_common_subexpressions_computed_once(composite, language):
    """The composite's Piecewise holds its long branch in its condition too: erf appears once in the body."""
    src = generate(composite, language).source
    code = "\n".join(ln for ln in src.splitlines() if not ln.lstrip().startswith(("//", "#", "%", "!", "*")))
    calls = len(re.findall(r"(?<!fn )(?<![\w.])_?erf\(", code))  # not Rust's helper `fn erf(`
    assert calls == 1, f"{language}: erf( appears {calls} times\n{src}"


def _load(gc, tmp_path):
    (path,) = gc.write(tmp_path)
    spec = importlib.util.spec_from_file_location(f"gen_{gc.function_name}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return getattr(mod, gc.function_name)


def test_numpy_module_is_branch_safe_outside_the_contact(composite, tmp_path):
    args, outs = composite.codegen_expressions()
    f = _load(generate(composite, "python"), tmp_path)
    r = np.linspace(0.0, 1.5, 301)  # the contact edge is at r = 1 - h* H ~ 0.997
    x1, x2 = r * np.cos(0.3), r * np.sin(0.3)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a RuntimeWarning of numpy fails the test
        p = f(x1, x2, 0.02, 1.0)
    ref = checked_lambdify(args, outs["p"], "mpmath")
    want = np.array([float(ref(a, b, 0.02, 1.0)) for a, b in zip(x1, x2)])
    assert np.all(p[r > 1.0] == 0) and np.all(p[r < 0.99] > 0)
    np.testing.assert_allclose(p, want, rtol=1e-12, atol=0)


def test_numpy_module_boundary_layer_below_its_edge(tmp_path):
    q = _boundary_q()
    f = _load(generate(q, "python", name="q", args=[V, HH, B]), tmp_path)
    v = np.linspace(-1.0, 3.0, 41)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        got = f(v, 0.3, 1.2)
    ref = [float(q.subs({V: x, HH: sp.Rational(3, 10), B: sp.Rational(6, 5)}).evalf(30)) if x > 0 else None
           for x in v]
    for x, g, w in zip(v, got, ref):
        if w is not None:  # v must be positive for sympy (a positive symbol)
            assert g == pytest.approx(w, rel=1e-13, abs=1e-300), x
        else:
            assert g == 0
