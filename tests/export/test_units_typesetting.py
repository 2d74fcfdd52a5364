"""Units parsed by a grammar and typeset right; long user strings never run off the page (issue 23, item 6).

The expected LaTeX of each unit is written out by hand (the way siunitx or a careful author sets it); the
PDF checks compile real documents with pdflatex and read its log for errors and overfull boxes.
"""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest
import sympy as sp

from thinlayer import symbols as S
from thinlayer.export.derivation import DerivationFileError, load_derivation, write_report
from thinlayer.export.latex_files import build_pdf, overfull_boxes
from thinlayer.export.report import MAX_TITLE, Document, parameter_length_powers, title_latex
from thinlayer.export.units import UnitError, UnitLatex, parse_unit, unit_power

ROOT = Path(__file__).resolve().parents[2]
HAVE_TEX = shutil.which("pdflatex") is not None
needs_tex = pytest.mark.skipif(not HAVE_TEX, reason="needs pdflatex")

#: every form the grammar accepts: text -> (LaTeX, LaTeX squared, normal form)
ACCEPTED = {
    "m": (r"\mathrm{m}", r"\mathrm{m}^{2}", "m"),
    "mm": (r"\mathrm{mm}", r"\mathrm{mm}^{2}", "mm"),
    "cm": (r"\mathrm{cm}", r"\mathrm{cm}^{2}", "cm"),
    "um": (r"\mu\mathrm{m}", r"{\mu\mathrm{m}}^{2}", "\u00b5m"),
    "\u00b5m": (r"\mu\mathrm{m}", r"{\mu\mathrm{m}}^{2}", "\u00b5m"),  # micro sign
    "\u03bcm": (r"\mu\mathrm{m}", r"{\mu\mathrm{m}}^{2}", "\u00b5m"),  # Greek mu
    "nm": (r"\mathrm{nm}", r"\mathrm{nm}^{2}", "nm"),
    "N": (r"\mathrm{N}", r"\mathrm{N}^{2}", "N"),
    "mN": (r"\mathrm{mN}", r"\mathrm{mN}^{2}", "mN"),
    "uN": (r"\mu\mathrm{N}", r"{\mu\mathrm{N}}^{2}", "\u00b5N"),
    "nN": (r"\mathrm{nN}", r"\mathrm{nN}^{2}", "nN"),
    "Pa": (r"\mathrm{Pa}", r"\mathrm{Pa}^{2}", "Pa"),
    "kPa": (r"\mathrm{kPa}", r"\mathrm{kPa}^{2}", "kPa"),
    "MPa": (r"\mathrm{MPa}", r"\mathrm{MPa}^{2}", "MPa"),
    "GPa": (r"\mathrm{GPa}", r"\mathrm{GPa}^{2}", "GPa"),
    "s": (r"\mathrm{s}", r"\mathrm{s}^{2}", "s"),
    "ms": (r"\mathrm{ms}", r"\mathrm{ms}^{2}", "ms"),
    "kg": (r"\mathrm{kg}", r"\mathrm{kg}^{2}", "kg"),
    "m^2": (r"\mathrm{m}^{2}", r"\mathrm{m}^{4}", "m^2"),
    "N/m^2": (r"\mathrm{N}/\mathrm{m}^{2}", r"\mathrm{N}^{2}/\mathrm{m}^{4}", "N/m^2"),
    "N/mm^2": (r"\mathrm{N}/\mathrm{mm}^{2}", r"\mathrm{N}^{2}/\mathrm{mm}^{4}", "N/mm^2"),
    "N / mm ^ 2": (r"\mathrm{N}/\mathrm{mm}^{2}", r"\mathrm{N}^{2}/\mathrm{mm}^{4}", "N/mm^2"),
    "N*m^-2": (r"\mathrm{N}/\mathrm{m}^{2}", r"\mathrm{N}^{2}/\mathrm{m}^{4}", "N/m^2"),
    "N.m^-2": (r"\mathrm{N}/\mathrm{m}^{2}", r"\mathrm{N}^{2}/\mathrm{m}^{4}", "N/m^2"),
    "kg m/s^2": (r"\mathrm{kg}\,\mathrm{m}/\mathrm{s}^{2}", r"\mathrm{kg}^{2}\,\mathrm{m}^{2}/\mathrm{s}^{4}",
                 "kg m/s^2"),
    "kg/(m*s^2)": (r"\mathrm{kg}/(\mathrm{m}\,\mathrm{s}^{2})", r"\mathrm{kg}^{2}/(\mathrm{m}^{2}\,\mathrm{s}^{4})",
                   "kg/(m s^2)"),
    "(kg)/(m s^2)": (r"\mathrm{kg}/(\mathrm{m}\,\mathrm{s}^{2})", r"\mathrm{kg}^{2}/(\mathrm{m}^{2}\,\mathrm{s}^{4})",
                     "kg/(m s^2)"),
    "s^-1": (r"\mathrm{s}^{-1}", r"\mathrm{s}^{-2}", "s^-1"),
    "m m": (r"\mathrm{m}^{2}", r"\mathrm{m}^{4}", "m^2"),
    "(um)^3": (r"{\mu\mathrm{m}}^{3}", r"{\mu\mathrm{m}}^{6}", "\u00b5m^3"),
    "Pa s": (r"\mathrm{Pa}\,\mathrm{s}", r"\mathrm{Pa}^{2}\,\mathrm{s}^{2}", "Pa s"),
}

#: refused, with what the message says
REFUSED = {
    "m^2^2": "unexpected '^'", "mm^10": "integer from 1 to 9", "m^0": "integer from 1 to 9", "m^": "ends too early",
    "N/m/s": "second '/'", r"\input{x}": "is not allowed", "$m$": "character '$'",
    "m\u00b2": "character", "(m": "not closed", "m)": "unexpected ')'", "2 m": "expected a unit symbol",
    "1/s": "expected a unit symbol", "kgg": "unknown unit symbol", "inch": "unknown unit symbol",
    "Mpa": "unknown unit symbol", "m/m": "pure number", "": "1 to 40 characters", "m" * 41: "1 to 40 characters",
    "m**2": "expected a unit symbol", "((((((m))))))": "nest too deeply", "m^-": "ends too early",
    "__import__('os')": "character '_'",
}


@pytest.mark.parametrize("text", list(ACCEPTED))
def test_every_accepted_form_typesets_and_powers_combine(text):
    first, squared, normal = ACCEPTED[text]
    u = parse_unit(text)
    assert (u.latex(), u.latex(2), u.text()) == (first, squared, normal)
    for n in (1, 2, 3, -1):  # one exponent per symbol: never a superscript on a superscript
        assert not re.search(r"\^\{-?[0-9]+\}\^", u.latex(n)), u.latex(n)
    assert unit_power(UnitLatex(u), 2) == squared and UnitLatex(u) == first
    assert parse_unit(u.text()) == u  # the normal form reads back to the same unit


@pytest.mark.parametrize("text", list(REFUSED))
def test_refused_forms_say_why_in_one_line(text):
    with pytest.raises(UnitError) as exc:
        parse_unit(text)
    assert REFUSED[text] in str(exc.value) and "\n" not in str(exc.value)


def _with_units(tmp_path: Path, **units: str) -> Path:
    base = (ROOT / "derivations" / "sphere.toml").read_text().split("[units]")[0]
    f = tmp_path / "u.toml"
    f.write_text(base + "[units]\n" + "".join(f'{k} = "{v}"\n' for k, v in units.items()))
    return f


@pytest.mark.parametrize("key, value, message", [
    ("length", "m^2", "is an area (m^2), not a length"),
    ("length", "N", "is a force (N), not a length"),
    ("force", "mm", "is a length (mm), not a force"),
    ("stress", "N", "is a force (N), not a stress"),
    ("stress", "s^-1", "of dimension s^-1"),
    ("length", "m^2^2", "a unit is SI symbols"),
    ("force", "\\\\input{x}", "a unit is SI symbols"),
])
def test_the_schema_refuses_with_file_table_key_and_valid_forms(tmp_path, key, value, message):
    units = {"length": "mm", "stress": "MPa", "force": "N"}
    units[key] = value
    f = _with_units(tmp_path, **units)
    with pytest.raises(DerivationFileError) as exc:
        load_derivation(f)
    text = str(exc.value)
    assert message in text and "\n" not in text and text.startswith(str(f)) and f"[units] {key} = " in text


@pytest.mark.parametrize("length, stress, force", [("m", "MPa", "N"), ("mm", "Pa", "N"), ("um", "MPa", "mN")])
def test_an_inconsistent_system_is_refused(tmp_path, length, stress, force):
    with pytest.raises(DerivationFileError, match="inconsistent"):
        load_derivation(_with_units(tmp_path, length=length, stress=stress, force=force))


@pytest.mark.parametrize("length, stress, force", [("mm", "MPa", "N"), ("um", "kPa", "nN"), ("nm", "GPa", "nN"),
                                                   ("um", "MPa", "uN"), ("m", "Pa", "N"), ("mm", "N/mm^2", "N"),
                                                   ("m", "kg/(m s^2)", "kg m/s^2"), ("cm", "N/cm^2", "N")])
def test_consistent_systems_are_accepted(tmp_path, length, stress, force):
    # independent: 1 force unit = 1 stress unit * (1 length unit)^2, from the SI prefixes by hand
    der = load_derivation(_with_units(tmp_path, length=length, stress=stress, force=force))
    assert set(der.units) == {"length", "stress", "force"}


def test_parameter_powers_follow_from_phi_being_a_length():
    R, K, a, R1, R2 = sp.symbols("R K a R_1 R_2", positive=True)
    x1, x2 = S.x1, S.x2
    assert parameter_length_powers((x1**2 + x2**2) / (2 * R), ["R"]) == {"R": 1}
    assert parameter_length_powers((x1**2 + x2**2) / (2 * R) + (x1**2 + x2**2) ** 2 / K**3, ["R", "K"]) == \
        {"R": 1, "K": 1}
    assert parameter_length_powers(x1**4 / K, ["K"]) == {"K": 3}
    assert parameter_length_powers(x1**2 / (2 * R) + x1**4 / 8, ["R"]) == {"R": 1}  # a number's unit is the user's
    assert parameter_length_powers(x1**2 / 8 + x2**2 / 2, []) == {}
    assert parameter_length_powers(a * x1**2, ["a"]) == {"a": -1}
    assert parameter_length_powers(x1**2 / (R1 + R2), ["R_1", "R_2"]) == {"R_1": None, "R_2": None}
    assert parameter_length_powers(x1**2 * a**2, ["a"]) == {"a": None}  # a half power: no unit printed


# ------------------------------------------------------------------------------------------------
# through pdflatex
# ------------------------------------------------------------------------------------------------
def _compile(doc: Document, tmp_path: Path) -> str:
    pdf, log = build_pdf(doc.latex(), "doc", tmp_path)
    assert pdf.startswith(b"%PDF")
    return log


@needs_tex
def test_every_accepted_unit_compiles_at_every_power(tmp_path):
    doc = Document("Units")
    doc.section("Every accepted unit, to the powers 1, 2, 3 and -1")
    rows = []
    for text in ACCEPTED:
        u = parse_unit(text)
        rows.append(rf"1.5\,{u.latex()},\quad 2.25\,{u.latex(2)},\quad 3.375\,{u.latex(3)},\quad "
                    rf"0.6\,{u.latex(-1)}")
    doc.lines(rows)
    log = _compile(doc, tmp_path)  # a LaTeX error ("Double superscript") would raise here
    assert "Double superscript" not in log and overfull_boxes(log) == []


TITLES = {
    "W": "W" * MAX_TITLE,  # the widest Latin capital
    "Omega": "\u03a9" * MAX_TITLE,  # a Greek capital, set as math
    "backslash": "\\" * MAX_TITLE,
    "specials": "%$#&{}~^_" * 22,
    "accents": "\u00c9" * MAX_TITLE,
    "long words": ("M" * 60 + " ") * 3 + "M" * 17,
}


@needs_tex
@pytest.mark.parametrize("name", list(TITLES))
def test_the_longest_titles_stay_on_the_page(tmp_path, name):
    title = TITLES[name][:MAX_TITLE]
    assert len(title) <= MAX_TITLE
    doc = Document(title)
    doc.section("Text").text("A paragraph.")
    log = _compile(doc, tmp_path)
    assert overfull_boxes(log) == [], overfull_boxes(log)
    assert r"\allowbreak{}" in title_latex(title)


@needs_tex
def test_a_report_with_units_and_the_longest_names_has_no_overfull_box(tmp_path):
    """The longest title and name, two 64-character parameters (one of them a length cubed), micro units."""
    n1, n2 = "R" + "a" * 63, "S" + "b" * 63
    f = tmp_path / "long.toml"
    f.write_text(f'[derivation]\nname = "{"n" * 100}"\ntitle = "{"W" * MAX_TITLE}"\n[layer]\nnu = "3/10"\n'
                 f'[punch]\nexpr = "(x_1**2 + x_2**2)/(2*{n1}) + x_1**4/{n2}"\n'
                 f"[contact]\ndelta0 = 0.1\nH = 0.01\nE = 2.6\nparameters = {{{n1} = 4, {n2} = 100}}\n"
                 '[units]\nlength = "um"\nstress = "kPa"\nforce = "nN"\n')
    tex = write_report(load_derivation(f), tmp_path / "out", pdf=True)
    text = tex.read_text()
    assert r"{\mu\mathrm{m}}^{2} \pm" in text  # the contact area: micrometres squared, one exponent
    assert rf"{n2} = 100\,{{\mu\mathrm{{m}}}}^{{3}}" in text  # x_1^4/S: S is a length cubed
    assert rf"{n1} = 4\,\mu\mathrm{{m}}" in text and r"\,\mathrm{nN}" in text and r"\,\mathrm{kPa}" in text
    log = tex.with_suffix(".log").read_text()
    assert overfull_boxes(log) == [], overfull_boxes(log)
    pdftoppm = shutil.which("pdftoppm")
    if pdftoppm:  # the pages render (looked at by eye when this test was written)
        subprocess.run([pdftoppm, "-r", "30", "-png", "-f", "1", "-l", "1", str(tex.with_suffix(".pdf")),
                        str(tmp_path / "page")], check=True, stdin=subprocess.DEVNULL, timeout=300)
        assert list(tmp_path.glob("page*.png"))
