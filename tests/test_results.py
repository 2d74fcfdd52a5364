"""The Result protocol (results.py): every stage's result knows its equation, its LaTeX and its text."""
import pytest
import sympy as sp

import thinlayer as tl
from thinlayer.results import Result, SymbolicResult


def _results():
    layer = tl.BondedLayer("3/10")
    punch = tl.Punch.paraboloid(R=1)
    yield "layer", layer, Result
    yield "punch", punch, SymbolicResult
    yield "coefficients (2.20)", tl.kernel_coefficients(layer, 2), SymbolicResult
    yield "moment expansion (2.22)", tl.moment_expansion(layer, 2), SymbolicResult
    yield "inner pressure (2.26)", tl.inner_pressure(layer, punch), SymbolicResult
    yield "ellipse (3.1)", tl.ellipse_contour(4, 1, sp.Rational(1, 2)), Result
    yield "Alexandrov (3.23)", tl.alexandrov_solution(tl.BondedLayer(0)), Result
    yield "force law (1.8)", tl.force_law(layer, punch), SymbolicResult
    yield "solution", tl.solve(tl.BondedLayer(0.3), punch, delta0=0.1, H=0.05, mu=1.0), Result


@pytest.mark.parametrize("what,result,protocol", list(_results()), ids=lambda x: x if isinstance(x, str) else "")
def test_results_follow_the_protocol(what, result, protocol):
    assert isinstance(result, protocol), f"{what}: {type(result).__name__} lacks part of {protocol.__name__}"
    lines = result.text_lines()
    assert lines and all(isinstance(s, str) for s in lines)
    assert str(result) == "\n".join(lines)  # print() shows exactly the text lines
    tex = result.latex()
    assert result.equation and "\\tag{" in tex, (what, tex[:200])  # every result is tagged with its equation
