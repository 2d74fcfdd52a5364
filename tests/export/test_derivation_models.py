"""Derivation files for every layer of the front door (issue 13, item 3): nu = 1/2, E or mu, the model.

The incompressible sphere's force is checked against ``P = 2 pi mu R^2 delta0^3/H^3`` (the closed form of
(I.11) at ``c^2 = 4 R delta0``, derived by hand in :mod:`thinlayer.asymptotics.incompressible`).
"""
from __future__ import annotations

import math
from pathlib import Path

import pytest

import thinlayer as tl
from thinlayer.export.derivation import DerivationFileError, load_derivation, report_latex

ROOT = Path(__file__).resolve().parents[2]

SPHERE = """
[derivation]
name = "s"
title = "t"

[layer]
model = "{model}"
{nu_line}

[punch]
kind = "paraboloid"

[contact]
delta0 = 0.1
H = {H}
{extra}
parameters = {{R = 10}}
"""


def _write(tmp_path, model="bonded", nu_line='nu = "1/2"', H=0.01, extra="E = 3.0"):
    path = tmp_path / "d.toml"
    path.write_text(SPHERE.format(model=model, nu_line=nu_line, H=H, extra=extra))
    return path


def test_incompressible_sphere_report():
    der = load_derivation(ROOT / "derivations" / "incompressible_sphere.toml")
    assert der.layer == tl.IncompressibleLayer()
    text = report_latex(der)
    for tag in ("2.3", "I.1", "I.2", "I.3", "I.4", "I.11"):
        assert rf"\tag{{{tag}}}" in text, tag
    assert "Model: incompressible" in text and "Edge correction (I.12)" in text
    assert "% ;" not in text and "5\\,\\%" in text  # the percent sign is escaped in prose
    ans = tl.solve(tl.BondedLayer(0.5), tl.Punch.paraboloid(10), delta0=0.1, H=0.01, E=3.0)
    mu = 3.0 / 3.0
    assert ans.force == pytest.approx(2 * math.pi * mu * 100 * 0.1**3 / 0.01**3, rel=1e-12)


def test_incompressible_ellipse_and_quartic_reports(tmp_path):
    for kind, section in (('kind = "elliptic_paraboloid"', "(I.6)--(I.8)"),
                          ('kind = "fourth_degree"', "(I.9)")):
        path = tmp_path / "e.toml"
        path.write_text(f'[derivation]\nname = "e"\ntitle = "e"\n[layer]\nnu = 0.5\n[punch]\n{kind}\n')
        text = report_latex(load_derivation(path))
        assert section in text and r"\tag{I.3}" in text


def test_contact_elastic_constants_and_model(tmp_path):
    der = load_derivation(_write(tmp_path, extra='E = 3.0\nmodel = "direct"\ntol = 0.1'))
    assert der.contact["model"] == "direct" and der.contact["tol"] == 0.1 and der.contact["E"] == 3.0
    with pytest.raises(DerivationFileError, match="both 'mu' and 'E'"):
        load_derivation(_write(tmp_path, extra="E = 3.0\nmu = 1.0"))
    with pytest.raises(DerivationFileError, match="valid models"):
        load_derivation(_write(tmp_path, extra='mu = 1.0\nmodel = "fastest"'))
    der = load_derivation(_write(tmp_path, model="frictionless", nu_line="", extra="mu = 1.0\nnu = 0.5", H=0.1))
    text = report_latex(der)
    assert "Model: compressible" in text


def test_two_term_section_for_a_compressible_sphere(sphere_latex):
    text = sphere_latex  # report_latex(load_derivation(ROOT / "derivations" / "sphere.toml")), built once
    assert "the two-term model" in text and "(I.10)" in text and r"\tag{I.11}" in text


def test_latex_numbers_keep_their_magnitude():
    from thinlayer.contact.solve import _tex_num

    assert _tex_num(628318.53) == "628318.53" and _tex_num(6.28) == "6.28"
    assert _tex_num(3.2e12) == r"3.2 \times 10^{12}" and _tex_num(1.5e-7) == r"1.5 \times 10^{-7}"
