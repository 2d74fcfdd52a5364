"""Derivation files of tips of revolution (issue 24 item 6): ``[punch] kind = "cone" | "sphere" | ...`` with their
parameters, the report's tip section (the law in LaTeX with its order and why, the any-thickness status, the force
table against the direct solver), and one clear error per bad file."""
from __future__ import annotations

from pathlib import Path

import pytest

from thinlayer.export.derivation import DerivationFileError, load_derivation, report_latex
from thinlayer.punch import Punch

ROOT = Path(__file__).resolve().parents[2]


def _file(tmp_path, punch: str, tip: str = "[tip]\nH = 1.0\nc_over_H = [10]\n", nu: str = '"3/10"') -> Path:
    path = tmp_path / "tip.toml"
    path.write_text(f'[derivation]\nname = "tip"\ntitle = "A tip"\n\n[layer]\nmodel = "bonded"\nnu = {nu}\n\n'
                    f"[coefficients]\norder = 2\n\n[punch]\n{punch}\n\n{tip}")
    return path


def test_shipped_cone_and_exact_sphere_load():
    cone = load_derivation(ROOT / "derivations" / "cone.toml")
    assert cone.punch is None and cone.tip["tip"] == Punch.cone(70) and cone.tip["c_over_H"] == [3, 5, 10, 20, 40]
    sphere = load_derivation(ROOT / "derivations" / "sphere_exact.toml")
    assert sphere.tip["tip"] == Punch.sphere(10) and sphere.tip["nu"] == 0.45
    assert cone.flat_punch is None and cone.validation is None


def test_cone_report_section(tmp_path):
    der = load_derivation(_file(tmp_path, 'kind = "cone"\nhalf_angle = 70'))
    tex = report_latex(der)
    assert r"\section{Tip of revolution: cone}" in tex
    assert r"\tan^{2}" in tex and r"O\!\left(P_0 (H/a)^{3}\right)" in tex  # P0 ~ tan^2(alpha) delta0^3, order 3
    assert "apex region" in tex and "Any thickness" in tex
    assert r"\label{tab:tip-force}" in tex and "(tip law)" in tex and "(direct)" in tex
    assert r"\section{Inner expansion" not in tex  # the polynomial stages do not run on a cone


@pytest.mark.parametrize("punch,tip,words", [
    ('kind = "cone"', "", "needs half_angle"),
    ('kind = "cone"\nhalf_angle = 95', "", "strictly between 0 and 90"),
    ('kind = "cone"\nhalf_angle = 70\nR = 2', "", "takes the keys ['half_angle'], not ['R']"),
    ('kind = "sphere"\nR = -1', "", "positive"),
    ('kind = "paraboloid"\nR = 2', "", "takes no parameters here"),
    ('kind = "paraboloid"', "[tip]\nH = 1.0\n", "[tip] is for [punch] kind"),
    ('kind = "cone"\nhalf_angle = 70', "[tip]\nc_over_H = [1]\n", "c_over_H"),
    ('kind = "cone"\nhalf_angle = 70', "[validation]\nnu = [0.3]\n", "is for a polynomial punch"),
    ('kind = "wedge"', "", "valid kinds are"),
])
def test_bad_tip_files_are_one_clear_error(tmp_path, punch, tip, words):
    with pytest.raises(DerivationFileError) as exc:
        load_derivation(_file(tmp_path, punch, tip))
    assert words in str(exc.value) and "\n" not in str(exc.value)


def test_pyramid_report_section(tmp_path):
    """[punch] kind = "pyramid": the section prints the pyramid's law (P0 ~ tan^2(alpha) delta0^3 through the
    4 tan(pi/4) polygon, P1 ~ J = 8 delta0), its order 3 and why (the apex and the corners), and the table against
    solve_2d with the largest difference within its estimate (the law's estimate covers the direct solver)."""
    der = load_derivation(_file(tmp_path, 'kind = "pyramid"\nhalf_angle = 35\nsides = 4',
                                tip="[tip]\nH = 1.0\nc_over_H = [8]\n"))
    assert der.tip["tip"] == Punch.pyramid(35, 4) and der.tip["c_over_H"] == [8.0]
    tex = report_latex(der)
    assert r"\section{Polyhedral tip: 4-sided pyramid, face angle 35 deg}" in tex
    assert r"O\!\left(P_0 (H/a)^{3}\right)" in tex and "apex" in tex and "corners" in tex
    assert r"\tan^{2}" in tex and r"\delta_{0}^{3}" in tex  # P0 = vartheta 4 tan^2(alpha) delta0^3/(3 A H)
    assert r"\label{tab:tip-force}" in tex and "two-dimensional" in tex
    assert r"\section{Tip of revolution" not in tex
    worst = tex.split("the largest difference is $")[1].split("$")[0]
    assert r"\times" not in worst and float(worst) < 1.0, worst  # within its estimate
    # the pyramid's any-thickness table (T.12 and solve_2d ratios, contact/any_thickness_pyramids.py) is a registry
    # row that fits (issue 25 item 1): the section names it instead of the direct solver
    assert "The any-thickness model of \\texttt{solve()} has a law for this tip" in tex
    assert "has the thin-layer law only for this tip" not in tex


@pytest.mark.parametrize(("punch", "tip", "words"), [
    ('kind = "pyramid"\nhalf_angle = 35\nsides = 5', "", "3 or 4"),
    ('kind = "pyramid"\nhalf_angle = 35\nsides = 4', "[tip]\nc_over_H = [20]\n", "numbers in [2, 12]"),
    ('kind = "pyramid"\nsides = 4', "", "needs half_angle"),
])
def test_bad_pyramid_files_are_one_clear_error(tmp_path, punch, tip, words):
    with pytest.raises(DerivationFileError, match=words.replace("[", r"\[").replace("]", r"\]")) as info:
        load_derivation(_file(tmp_path, punch, tip))
    assert "\n" not in str(info.value)
