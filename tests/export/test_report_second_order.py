"""The report's second-order section (issue 16, item 4): ``[second_order]`` in a derivation file.

What is checked: the section is there exactly when the table is; its constants are those of
:func:`edge_constants` for the file's layer (a symbolic nu gets a sentence instead); the table of r_3 has one row
per nu asked for, its 12 r_3 column is twelve times its r_3 column and its check column (the spread between three
factorisations) is tiny; the boundary-layer lines reduce to the first-order ones at eps = beta = 0 (the printed
(SO.5) and (SO.8)); the sphere's relative form carries -4 m_1 and 12 r_3; the PDF compiles without overfull lines.
"""
from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import pytest
import sympy as sp
from sympy.parsing.sympy_parser import implicit_multiplication_application, parse_expr, standard_transformations

from thinlayer import BondedLayer, FrictionlessLayer
from thinlayer.asymptotics.second_order import edge_constants
from thinlayer.export.derivation import load_derivation, report_latex, write_report
from thinlayer.export.report import latex_available, overfull_boxes

ROOT = Path(__file__).resolve().parents[2]
BASE = """[derivation]
name = "so"
title = "Sphere"
[layer]
nu = "{nu}"
[punch]
kind = "paraboloid"
"""
CONTACT = """[contact]
delta0 = 0.1
H = 0.05
parameters = {R = 10}
"""


def _tex(tmp_path, nu="3/10", second="[second_order]\nnu = ['0', '3/10', 0.45, 'frictionless']\n"):
    f = tmp_path / "so.toml"
    f.write_text(BASE.format(nu=nu) + (CONTACT if nu != "symbolic" else "") + second)
    return report_latex(load_derivation(f))


def _numbers(row: str) -> list[float]:
    """The numbers of a table row: ``$1.2 \\cdot 10^{-15}$`` as 1.2e-15."""
    out = []
    for cell in row.split("&")[1:]:
        m = re.search(r"\$(-?[\d.]+)(?: \\cdot 10\^\{(-?\d+)\})?\$", cell)
        out.append(float(m.group(1)) * 10 ** int(m.group(2) or 0) if m else float("nan"))
    return out


def test_section_only_with_the_table(tmp_path):
    assert "Second order" not in _tex(tmp_path, second="")
    tex = _tex(tmp_path)
    for title in ("Second order: the boundary layer at a curved contour", "Second order: force and contact area"):
        assert rf"\section{{{title}}}" in tex
    for tag in ("SO.4", "SO.5", "SO.6", "SO.8", "SO.9", "SO.10"):
        assert rf"\tag{{{tag}}}" in tex, tag


def test_constants_of_the_files_layer(tmp_path):
    tex = _tex(tmp_path)
    c = edge_constants(BondedLayer(sp.Rational(3, 10)))
    line = next(ln for ln in tex.splitlines() if r"h^* = " in ln and r"r_3 = " in ln)
    got = [float(x) for x in re.findall(r"(?:h\^\*|m_1|r_3) = (-?[\d.]+)", line)]
    assert got == pytest.approx([c.h_star, c.m1, c.r3], rel=1e-9)  # printed to 10 significant digits
    sym = _tex(tmp_path, nu="symbolic")
    assert r"this derivation's layer has a symbolic $\nu$" in sym
    assert not any(r"h^* = " in ln and r"r_3 = " in ln for ln in sym.splitlines())


def test_table_of_r3(tmp_path):
    tex = _tex(tmp_path)
    body = tex.split(r"\label{tab:r3}", 1)[1].split(r"\end{tabular}", 1)[0]
    rows = [ln for ln in body.splitlines() if ln.endswith(r"\\") and "&" in ln and r"$\nu$" not in ln]
    labels = [r.split("&")[0].strip() for r in rows]
    assert labels == ["$0$", "$3/10$", "$0.45$", "frictionless base"]
    layers = [BondedLayer(0), BondedLayer(sp.Rational(3, 10)), BondedLayer(0.45), FrictionlessLayer()]
    for row, layer in zip(rows, layers):
        h, m1, r3, twelve, spread = _numbers(row)
        c = edge_constants(layer)
        assert [h, m1, r3] == pytest.approx([c.h_star, c.m1, c.r3], rel=1e-9, abs=1e-12)
        assert twelve == pytest.approx(12 * r3, rel=1e-9)  # the sphere's coefficient of (H/a)^3
        assert 0 <= spread < 1e-10  # three factorisations agree


def test_boundary_layer_lines_reduce_to_the_first_order(tmp_path):
    # at eps = beta = 0: h = h* (3.18) and A D = m_1/2 (the first-order defect); read back from the printed LaTeX
    tex = _tex(tmp_path)
    eps, beta, m1, h = sp.symbols("epsilon beta m_1 h")

    def parse(tag):
        line = next(ln for ln in tex.splitlines() if rf"\tag{{{tag}}}" in ln)
        rhs = line.split(" = ", 1)[1].split(r"}\tag", 1)[0]
        rhs = (rhs.replace("{h^{*}}", "h").replace(r"\beta", "beta").replace(r"\epsilon", "epsilon")
               .replace("m_{1}", "m_1").replace("r_{3}", "r_3").replace(r"\left(", "(").replace(r"\right)", ")"))
        rhs = re.sub(r"\\frac\{([^{}]*)\}\{([^{}]*)\}", r"((\1)/(\2))", rhs)
        tr = standard_transformations + (implicit_multiplication_application,)
        return parse_expr(rhs, local_dict={"h": h, "beta": beta, "epsilon": eps, "m_1": m1, "r_3": sp.Symbol("r_3")},
                          transformations=tr)

    edge = parse("SO.5")
    assert sp.simplify(edge.subs({eps: 0, beta: 0}) - h) == 0
    assert sp.simplify(sp.diff(edge, eps) - m1 / 2) == 0 and sp.simplify(sp.diff(edge, beta) - m1) == 0
    defect = parse("SO.8")
    assert sp.simplify(defect.subs({eps: 0, beta: 0}) - m1 / 2) == 0


def test_sphere_relative_form(tmp_path):
    tex = _tex(tmp_path)
    line = next(ln for ln in tex.splitlines() if r"\tag{SO.9--SO.10}" in ln)
    c = edge_constants(BondedLayer(sp.Rational(3, 10)))
    m = re.search(r"P_0\\left\(1 - ([\d.]+) \\frac\{H\^2\}\{a\^2\} \+ ([\d.]+) \\frac\{H\^3\}\{a\^3\}", line)
    assert float(m.group(1)) == pytest.approx(4 * c.m1, rel=1e-5)
    assert float(m.group(2)) == pytest.approx(12 * c.r3, rel=1e-5)
    assert re.search(r"c = a - ([\d.]+) H", line).group(1) == f"{c.h_star:.6g}"


def test_catalogue_files_enable_it():
    for name in ("sphere", "elliptic_paraboloid"):
        assert load_derivation(ROOT / "derivations" / f"{name}.toml").second_order is not None


@pytest.mark.skipif(not latex_available(), reason="pdflatex is not installed")
def test_pdf_without_overfull_lines(tmp_path):
    for name in ("sphere", "elliptic_paraboloid"):
        der = load_derivation(ROOT / "derivations" / f"{name}.toml")
        der = dataclasses.replace(der, sections={**der.sections, "validation": None})
        tex = write_report(der, tmp_path / name, pdf=True)
        log = tex.with_suffix(".log").read_text()
        assert not overfull_boxes(log), (name, overfull_boxes(log))


def test_numbers_at_the_contact_point(tmp_path):
    from thinlayer import Punch
    from thinlayer.asymptotics.second_order import second_order_law

    tex = _tex(tmp_path)
    line = next(ln for ln in tex.splitlines() if "P_0 + P_1 = " in ln and "P_2 = " in ln)
    got = {k: float(v) for k, v in re.findall(r"(P_0 \+ P_1|P_2|P) = ([\d.]+)", line)}
    v = second_order_law(BondedLayer(sp.Rational(3, 10)), Punch.paraboloid()).evaluate(0.1, 0.05, 1.0,
                                                                                       parameters={"R": 10})
    assert got["P_0 + P_1"] == pytest.approx(v.force_first, rel=1e-5) and got["P_2"] == pytest.approx(v.P2, rel=1e-5)
    assert got["P"] == pytest.approx(got["P_0 + P_1"] + got["P_2"], rel=1e-5)
