"""The closed form (V.11) of the thin-layer sphere under a ramp with a standard linear solid, against two
independent numerical routes: mpmath quadrature of the Lee-Radok integral, and the engine's hereditary integral
(a recursive update per Prony term, exact for a history linear between nodes: second order for this quadratic F)."""
from __future__ import annotations

import mpmath
import numpy as np
import sympy as sp

from thinlayer import BondedLayer, StandardLinearSolid
from thinlayer.contact.hereditary import hereditary_integral
from thinlayer.contact.visco_closed import sls_ramp_force

VALS = {"E_0": 3.0, "E_infty": 1.0, "H": 0.05, "R": 10.0, "tau": 0.2, "v": 0.05}


def _numbers(res, times):
    args = [VALS[a.name] if a.name in VALS else times for a in res.arguments]
    return res.lambdify()(*args)


def test_closed_form_against_quadrature_and_the_hereditary_integral():
    for layer in (BondedLayer(sp.Rational(3, 10)), BondedLayer(sp.Rational(1, 10))):
        res = sls_ramp_force(layer)
        nu = float(res.nu)
        sym = {x.name: x for x in res.elastic.free_symbols}
        el = res.elastic.subs({sym["H"]: VALS["H"], sym["R"]: VALS["R"]})
        F = sp.lambdify(sym["delta_0"], el, "mpmath")
        dF = sp.lambdify(sym["delta_0"], sp.diff(el, sym["delta_0"]), "mpmath")
        assert F(0.1) != 0
        E0, Ei, tau, v = VALS["E_0"], VALS["E_infty"], VALS["tau"], VALS["v"]
        times = np.array([0.1, 0.5, 1.0, 2.0])
        closed = _numbers(res, times)
        for tk, pk in zip(times, closed):
            quad = mpmath.quad(lambda s: (Ei + (E0 - Ei) * mpmath.exp(-(tk - s) / tau)) * dF(v * s) * v, [0, tk])
            assert abs(quad / (2 * (1 + nu)) - pk) < 1e-12 * abs(pk), (layer, tk)
        grid = np.linspace(0.0, 2.0, 4001)
        Fg = np.array([float(F(v * x)) for x in grid])
        num = hereditary_integral(StandardLinearSolid(E0, Ei, tau), grid, Fg) / (2 * (1 + nu))
        ref = _numbers(res, grid[1:])
        assert np.max(np.abs(num[1:] - ref)) < 1e-6 * np.max(np.abs(ref))


def test_viscoelastic_table_in_a_derivation_file(tmp_path):
    """The [viscoelastic] table: the shipped file renders (V.11) with its check; bad tables are one clear line."""
    from pathlib import Path

    import pytest

    from thinlayer.export.derivation import load_derivation, report_latex
    from thinlayer.export.sections.base import DerivationFileError

    shipped = Path(__file__).resolve().parents[2] / "derivations" / "sphere_viscoelastic.toml"
    tex = report_latex(load_derivation(shipped))
    assert r"\section{Viscoelastic layer: the sphere under a ramp}" in tex and r"\tag{V.11}" in tex
    import re

    m = re.search(r"4\{,\}001 nodes to \$([0-9.]+)(?:\s*\\cdot\s*10\^\{(-?[0-9]+)\})?\$", tex)
    assert m, tex[tex.index("4{,}001"):][:80]
    worst = float(m.group(1)) * 10.0 ** int(m.group(2) or 0)
    assert worst < 1e-6
    text = shipped.read_text()
    for old, new, words in (("E_inf = 1.0", "E_inf = 4.0", "exceeds E0"),
                            ("tau = 0.2       # s\n", "", "tau is required"),
                            ('kind = "paraboloid"', 'kind = "elliptic_paraboloid"', "paraboloid of revolution")):
        path = tmp_path / "v.toml"
        path.write_text(text.replace(old, new))
        with pytest.raises(DerivationFileError, match=words) as info:
            load_derivation(path)
        assert "\n" not in str(info.value)
