"""Reading the input of code generation (thinlayer.export.codegen.spec): bad inputs and their messages."""
from __future__ import annotations

import pytest
import sympy as sp

from thinlayer import BondedLayer, FrictionlessLayer, GenericLayer, MissingArgumentError, kernel_coefficients
from thinlayer.export.codegen import generate


def test_bad_inputs():
    x = sp.Symbol("x")
    with pytest.raises(ValueError, match="cannot generate code from a object"):
        generate(object(), "c")
    with pytest.raises(ValueError, match="strings are not parsed"):
        generate("x**2", "c", args=[x])
    with pytest.raises(ValueError, match="args is required"):
        generate(x**2, "c")
    with pytest.raises(ValueError, match="must be a sympy Symbol"):
        generate(x**2, "c", args=["x"])
    with pytest.raises(ValueError, match="repeat"):
        generate(x**2, "c", args=[x, x])
    with pytest.raises(ValueError, match="complex"):
        generate(sp.I * x, "c", args=[x])
    with pytest.raises(ValueError, match="not a sympy expression"):
        generate({"a": sp.Eq(x, 1)}, "c", args=[x])
    with pytest.raises(ValueError, match="no symbolic parameter"):
        generate(kernel_coefficients(BondedLayer(sp.Rational(1, 4)), 1), "c")
    with pytest.raises(ValueError, match="no symbolic parameter"):
        generate(kernel_coefficients(FrictionlessLayer(), 1), "c")
    with pytest.raises(ValueError, match="GenericLayer"):
        generate(kernel_coefficients(GenericLayer(), 1), "c")
    with pytest.raises(MissingArgumentError, match="y"):
        generate(x + sp.Symbol("y"), "c", args=[x])
    with pytest.raises(NotImplementedError, match="g"):
        generate(sp.Function("g")(x), "c", args=[x])
    with pytest.raises(NotImplementedError):
        generate(sp.besselj(0, x), "python", args=[x])
