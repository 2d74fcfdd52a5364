"""Identifiers of the generated code (thinlayer.export.codegen.names): sanitising, reserved words, collisions."""
from __future__ import annotations

import pytest
import sympy as sp

from thinlayer import BondedLayer, Punch, inner_pressure
from thinlayer.export.codegen import NameCollisionError, generate, identifier

# (2.26) for the elliptic paraboloid (1.1), nu = 3/10 (the inner-pressure case of test_codegen.py)
ELLIPSE_INNER = inner_pressure(BondedLayer(sp.Rational(3, 10)), Punch.elliptic_paraboloid())


def test_identifiers():
    assert identifier("H_*", "c") == "H_s"
    assert identifier("delta_0^*", "rust") == "delta_0_s"
    assert identifier("x_{1}", "julia") == "x_1"
    assert identifier("\\vartheta", "octave") == "vartheta"
    assert identifier("μ", "fortran") == "mu" and identifier("Δ", "c") == "Delta"
    assert identifier("2x", "c") == "v_2x"
    assert identifier("\\mathcal{A}", "rust") == "A" and identifier("\\boldsymbol{\\xi}_1", "c") == "xi_1"
    assert identifier("lambda", "python") == "lambda_" and identifier("lambda", "c") == "lambda"
    assert identifier("end", "julia") == "end_" and identifier("END", "fortran") == "END_"
    assert identifier("exp", "c") == "exp_"  # would shadow the math function


def test_bad_language():
    with pytest.raises(ValueError, match="c, fortran, rust, julia, octave, python"):
        generate(ELLIPSE_INNER, "cobol")
    assert generate(ELLIPSE_INNER, "MATLAB").language == "octave"


def test_bad_function_names():
    x = sp.Symbol("x")
    for name, lang in [("for", "c"), ("fn", "rust"), ("end", "julia"), ("function", "octave"),
                       ("lambda", "python"), ("EXP", "fortran"), ("2f", "c"), ("my-f", "python"),
                       ("f" * 64, "fortran")]:
        with pytest.raises(ValueError, match="function name"):
            generate(x, lang, name=name, args=[x])
    assert generate(x, "c", name="f" * 64, args=[x]).function_name == "f" * 64  # only Fortran limits length


def test_name_collisions():
    Hs, H_s = sp.Symbol("H_*"), sp.Symbol("H_s")
    with pytest.raises(NameCollisionError, match=r"argument H_\* -> 'H_s'; argument H_s -> 'H_s'"):
        generate(Hs + H_s, "c", args=[Hs, H_s])
    R, r = sp.symbols("R r")
    assert generate(R * r, "c", name="rr", args=[R, r]).arguments == ("R", "r")
    with pytest.raises(NameCollisionError, match="Fortran ignores case"):
        generate(R * r, "fortran", name="rr", args=[R, r])
    lam, lam_ = sp.symbols("lambda lambda_")
    with pytest.raises(NameCollisionError, match="lambda_"):
        generate(lam + lam_, "python", name="f", args=[lam, lam_])
    x = sp.Symbol("x")
    with pytest.raises(NameCollisionError, match="function name"):
        generate(x, "julia", name="x", args=[x])
    out = sp.Symbol("out")
    with pytest.raises(NameCollisionError, match="output array"):
        generate([out, 2 * out], "c", args=[out])
    with pytest.raises(NameCollisionError, match="argument x -> 'x'; output 'x' -> 'x'"):
        generate({"p": x, "x": 2 * x}, "rust", args=[x])
