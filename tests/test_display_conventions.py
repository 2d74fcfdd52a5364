"""Results in the REPL, IPython and sympy (issue 17, item 5): a short repr, readable text, ``sympy.latex``."""
from __future__ import annotations

import sympy as sp

import thinlayer as tl


def _results():
    layer, punch = tl.BondedLayer("3/10"), tl.Punch.paraboloid(10)
    return [tl.kernel_coefficients(layer, 2), tl.inner_pressure(layer, punch), tl.force_law(layer, punch),
            tl.solve(layer, punch, delta0=0.1, H=0.05, mu=1.0),
            tl.asymptotics.solution.compressible_solution(layer, punch, delta0=0.1, H=0.05, mu=1.0),
            tl.solve_axisymmetric(layer, punch, 0.1, 0.3)]


def test_short_repr_readable_pretty_text_and_sympy_latex():
    class Printer:  # IPython's pretty printer, reduced to what _repr_pretty_ uses
        def __init__(self):
            self.out = ""

        def text(self, s):
            self.out += s

    for res in _results():
        r = repr(res)
        assert len(r) <= 110 and "\n" not in r, r
        assert r == str(res).splitlines()[0][:110] or r.endswith("...")
        pr = Printer()
        res._repr_pretty_(pr, False)
        assert pr.out == str(res)
        tex = sp.latex(res)
        assert r"\mathtt" not in tex and tex == res.latex(), tex[:200]  # the result's own LaTeX
