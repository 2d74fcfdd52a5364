"""The flat punch in derivation files and reports (issue 14 item 5): ``[punch] kind = "flat"`` and ``[flat_punch]``.

The table's exact kappa is checked against the two asymptotic routes inside their own estimates: the thin-layer
law (F.12)/(F.15)/(F.14) at a/H = 50 and the thick series (F.18) at a/H = 0.05 (independent of the Fredholm
solver that fills the table).
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from thinlayer import BondedLayer, IncompressibleLayer
from thinlayer.asymptotics.flat_punch import thick_flat_punch, thin_flat_punch
from thinlayer.export.derivation import DerivationFileError, load_derivation, report_latex

ROOT = Path(__file__).resolve().parents[2]
BASE = "[derivation]\nname='f'\n[layer]\nnu='symbolic'\n[coefficients]\norder=1\n[punch]\nkind='flat'\n"


def _table(tex: str) -> dict[tuple[float, str], float]:
    body = tex.split(r"\label{tab:flat-kappa}", 1)[1].split(r"\end{tabular}", 1)[0]
    lines = [ln for ln in body.splitlines() if ln.strip().endswith(r"\\") and ln.strip().startswith("$")]
    header = re.findall(r"\\nu = ([\d.]+)", body)
    out = {}
    for ln in lines:
        cells = [c.strip().strip("$").replace(r" \\", "") for c in ln.rstrip(r"\ ").split("&")]
        x = float(cells[0])
        for nu, val in zip(header, cells[1:]):
            out[(x, nu)] = float(val.strip().rstrip("\\").strip().strip("$"))
    return out


def test_catalogue_flat_punch_report(tmp_path):
    der = load_derivation(ROOT / "derivations" / "flat_punch.toml")
    tex = report_latex(der)
    for tag in ("F.1", "F.10", "F.11", "F.12", "F.13", "F.14", "F.18"):
        assert tex.count(rf"\tag{{{tag}}}") == 1, tag
    for bad in ("**", "sqrt(", "lambda*", "pi*"):
        assert bad not in tex.split(r"\maketitle", 1)[1].split(r"\section{Errata}")[0], bad
    table = _table(tex)
    assert len(table) == 10 * 5
    for nu, layer in (("0.3", BondedLayer(0.3)), ("0.5", IncompressibleLayer())):
        thin = thin_flat_punch(layer)
        assert abs(table[(50.0, nu)] / float(thin(50.0)) - 1) <= float(thin.error_estimate(50.0)) + 5e-6
        thick = thick_flat_punch(layer)
        assert abs(table[(0.05, nu)] / float(thick(0.05)) - 1) <= float(thick.error_estimate(0.05)) + 5e-6


def test_flat_punch_table_is_validated(tmp_path):
    f = tmp_path / "f.toml"
    for extra, match in ((("[flat_punch]\na_over_H=[0]\n"), "a_over_H"), ("[flat_punch]\na_over_H=[500]\n", "200"),
                         ("[flat_punch]\nnu=[0.6]\n", "nu"), ("[flat_punch]\nnu='0.3'\n", "expected a list"),
                         ("[flat_punch]\nnuu=[0.3]\n", "nuu"),
                         ("[contact]\ndelta0=0.1\nH=0.1\n", "kind = 'flat'"),
                         ("[flat_punch]\na_over_H=" + str(list(range(1, 40))) + "\n", "1 to 30")):
        f.write_text(BASE + extra)
        with pytest.raises(DerivationFileError, match=match) as exc:
            load_derivation(f)
        assert "\n" not in str(exc.value)


def test_flat_punch_section_next_to_a_polynomial_punch(tmp_path):
    f = tmp_path / "g.toml"
    f.write_text(BASE.replace("kind='flat'", "kind='paraboloid'").replace("nu='symbolic'", "model='frictionless'")
                 + "[flat_punch]\na_over_H=[0.5, 5]\n")
    tex = report_latex(load_derivation(f))
    assert r"\section{Flat-ended cylindrical punch}" in tex and "frictionless base" in tex
    assert r"\tag{2.26}" in tex or r"\tag{4.1}" in tex  # the paraboloid's own sections are still there
