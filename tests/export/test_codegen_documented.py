"""Generated code says what it computes (issue 28, item 5): every argument and output described in every language,
and the numbers of one layer (h*, r_3, A, m_1, ...) folded in as named constants that say where they come from.

The values are checked against independent routes: the constant h* against the Wiener-Hopf edge shift computed
afresh at a higher precision, the generated functions (numpy and compiled C, Fortran, Rust) against the laws'
own numeric evaluation (``evaluate``), which never goes through the generated expressions.
"""
from __future__ import annotations

import functools
import re
import shutil

import numpy as np
import pytest
import sympy as sp
from test_codegen import load_module, run_c, run_fortran, run_rust

import thinlayer as tl
from thinlayer.asymptotics.flat_punch import thick_flat_punch, thin_flat_punch
from thinlayer.asymptotics.second_order import second_order_law
from thinlayer.asymptotics.wiener_hopf import edge_shift
from thinlayer.export.codegen import LANGUAGES, generate
from thinlayer.export.codegen.meanings import describe_argument

COMMENT = {"c": " *", "fortran": "!", "rust": "//", "julia": "#", "octave": "  %", "python": ""}


def _entry(text: str, prefix: str, label: str) -> str:
    """The text after ``label --`` in the header, continuation lines (indented by 6) joined."""
    lines = text.splitlines()
    for k, ln in enumerate(lines):
        m = re.match(rf"{re.escape(prefix)}\s+{re.escape(label)} -- (.*)$", ln)
        if m:
            parts = [m.group(1)]
            for nxt in lines[k + 1:]:
                if not nxt.startswith(prefix + "      "):
                    break
                parts.append(nxt[len(prefix):].strip())
            return " ".join(parts)
    return ""


def _results():
    L, par = tl.BondedLayer(), tl.Punch.paraboloid()
    return {
        "inner": tl.inner_pressure(tl.BondedLayer("3/10"), tl.Punch.elliptic_paraboloid()),
        "coefficients": tl.kernel_coefficients(L, 2),
        "force-symbolic": tl.force_law(L, par),
        "force-0.3": tl.force_law(tl.BondedLayer(0.3), par),
        "force-frictionless": tl.force_law(tl.FrictionlessLayer(), tl.Punch.elliptic_paraboloid()),
        "second-order": second_order_law(tl.BondedLayer("3/10"), par),
        "flat-thin": thin_flat_punch(tl.BondedLayer(0.2)),
        "flat-thick": thick_flat_punch(tl.BondedLayer(0.3), 6),
        "incompressible": tl.two_term_sphere(tl.IncompressibleLayer()),
    }


KEYS = ("inner", "coefficients", "force-symbolic", "force-0.3", "force-frictionless", "second-order", "flat-thin",
        "flat-thick", "incompressible")
# the results are built on first use (3.6 s of sympy), once per worker, not at collection in every worker; the
# module's tests run on one worker (xdist group)
pytestmark = pytest.mark.xdist_group("codegen-documented")


@functools.lru_cache(maxsize=1)
def results() -> dict:
    out = _results()
    assert tuple(out) == KEYS, (tuple(out), KEYS)
    return out


@pytest.mark.parametrize("key", KEYS)
def test_every_argument_and_output_is_described_in_every_language(key):
    res = results()[key]
    for lang in LANGUAGES:
        gc = generate(res, lang)
        text = gc.source
        for ident, sym in zip(gc.arguments, gc.symbols):
            # the header entry of the argument: identifier, sympy name and what it is, with units and equation
            note = _entry(text, COMMENT[lang], f"{ident}: {sym.name}")
            assert note, (key, lang, ident)
            assert "no description" not in note and re.search(r"\[[^]]+\] \([A-Z]?\.?[0-9.]+\)$", note), note
        for out in gc.outputs:
            assert re.search(rf"{re.escape(out)} -- \S", text), (key, lang, out)
        if lang == "python":  # the function's own docstring lists them too (numpydoc)
            doc = text.split(f"def {gc.function_name}(", 1)[1]
            assert "Parameters" in doc or not gc.arguments
            assert all(f"    {a} : float or numpy.ndarray" in doc for a in (*gc.arguments, *gc.outputs))


def test_a_punch_parameter_is_described_as_one():
    punch = tl.Punch("x_1**2/(2*a) + x_2**2/(2*b)")
    gc = generate(tl.inner_pressure(tl.BondedLayer("3/10"), punch), "c")
    assert " *   a: a -- parameter a of the punch shape Phi" in gc.source
    assert describe_argument("q_9") == "a symbol of the expression (no description known)"


def test_numeric_nu_folds_the_edge_shift_in_as_a_named_constant():
    law = results()["force-0.3"]
    ref = float(edge_shift(tl.BondedLayer(0.3).edge_shift_key, kernel="exact", dps=30))  # afresh, 30 digits
    for lang in LANGUAGES:
        gc = generate(law, lang)
        assert "h_s" not in gc.arguments and "h^*" not in [s.name for s in gc.symbols]
        m = re.search(r"h_s = ([0-9.]+)(?:d0)?;?(?:\s+# (.*))?$", gc.source, flags=re.M)
        assert m, lang
        assert float(m.group(1)) == pytest.approx(ref, rel=2e-16, abs=0)
        assert "edge shift h*(nu=0.3), exact Wiener-Hopf solution (3.18), (3.25)" in gc.source
    py = generate(law, "python").source
    assert re.search(r"^    h_s = 0\.12207064785\d+  # edge shift h\*\(nu=0\.3\), exact Wiener-Hopf solution "
                     r"\(3\.18\), \(3\.25\)$", py, flags=re.M), py
    # a symbolic nu keeps h* an argument (it is a function of nu without closed form), described as such
    sym = generate(results()["force-symbolic"], "python")
    assert "h_s" in sym.arguments and "thinlayer.edge_shift_exact(nu)" in sym.source


def test_second_order_and_flat_punch_name_their_layer_constants():
    so = generate(results()["second-order"], "c").source
    assert re.search(r"const double r_3 = 0\.05300837\d+;", so) and "(SO.4)" in so
    assert re.search(r"const double h_s = 0\.12207064\d+;", so)
    thin = generate(results()["flat-thin"], "fortran").source
    for name, eq in (("A", "(2.4)"), ("m_1", "(2.20)"), ("h_s", "(3.25)")):
        assert re.search(rf"^{name} = -?[0-9.]+d0$", thin, flags=re.M) and eq in thin, name
    thick = generate(results()["flat-thick"], "rust").source
    assert all(re.search(rf"let c_{k} = -?[0-9.]+;", thick) for k in range(1, 7)) and "(F.18)" in thick


def _law_points():
    return np.array([[0.1, 0.05, 1.0, 10.0], [0.02, 0.01, 2.5, 3.0], [0.3, 0.2, 0.7, 50.0]])


def _law_reference(law, points, h):
    out = []
    for d0, H, mu, R in points:
        v = law.evaluate(d0, H, mu, edge_shift=h, parameters={"R": R})
        out.append([v.force, v.area0, v.area])
    return np.array(out)


def test_generated_force_law_with_the_constant_agrees_with_evaluate(tmp_path):
    law = results()["force-0.3"]
    h = float(edge_shift(tl.BondedLayer(0.3).edge_shift_key, kernel="exact", dps=30))
    pts = _law_points()
    ref = _law_reference(law, pts, h)
    gc = generate(law, "python")
    f = getattr(load_module(gc, tmp_path), gc.function_name)
    got = np.array(f(*pts.T)).T
    np.testing.assert_allclose(got, ref, rtol=1e-13)
    runners = {"c": run_c, "fortran": run_fortran, "rust": run_rust}
    tools = {"c": "gcc", "fortran": "gfortran", "rust": "rustc"}
    for lang, run in runners.items():
        if shutil.which(tools[lang]) is None:
            continue  # the compilers are optional; test_codegen.py says so when one is missing
        out = run(generate(law, lang), pts, tmp_path / lang)
        np.testing.assert_allclose(out, ref, rtol=1e-13, err_msg=lang)


def test_flat_punch_constants_agree_with_the_model(tmp_path):
    x = np.array([0.05, 0.3, 0.79, 2.0, 10.0, 60.0])
    for key in ("flat-thin", "flat-thick"):
        model = results()[key]
        gc = generate(model, "python")
        kappa, _ = getattr(load_module(gc, tmp_path / key), gc.function_name)(x)
        np.testing.assert_allclose(kappa, model(x), rtol=1e-13)
    assert sp.Symbol("A", real=True) in results()["flat-thin"].codegen_constants()
