"""The report's sections are a registry (:mod:`thinlayer.export.sections`, issue 29 item 4).

A section registered from outside (here: a toy section defined in the test, removed afterwards) reaches the
derivation file's schema, its parsing and the report without any edit of ``report.py`` or ``derivation.py``;
the contract is checked when a section registers.
"""
from __future__ import annotations

import types
from pathlib import Path

import pytest

from thinlayer.export import sections
from thinlayer.export.derivation import SCHEMA, DerivationFileError, load_derivation, report_latex
from thinlayer.export.sections import SectionContractError, register_section, unregister_section

SRC = Path(__file__).resolve().parents[2] / "src" / "thinlayer" / "export"

BASE = """
[derivation]
name = "toy"
title = "Toy"
[layer]
model = "frictionless"
[coefficients]
order = 1
[punch]
kind = "flat"
[flat_punch]
a_over_H = [1.0]
nu = [0.3]
"""


def _toy() -> types.ModuleType:
    toy = types.ModuleType("toy_section")
    toy.KEY = "toy_note"
    toy.SCHEMA = {"words": ((str,), "a short note")}
    toy.ORDER = 950  # after the errata (900), before the references (1000)

    def parse(table, context):
        if table is None:
            return None
        if not table.get("words", "").isalpha():
            raise DerivationFileError("[toy_note] words: letters only")
        return table["words"]

    toy.parse = parse
    toy.applies = lambda der: der.sections.get("toy_note") is not None
    toy.render = lambda doc, der, context: doc.section("Toy note").text(f"The note says {der.sections['toy_note']}.")
    return toy


@pytest.fixture
def toy():
    section = register_section(_toy())
    try:
        yield section
    finally:
        unregister_section(section)


def test_a_registered_section_reaches_the_schema_the_parser_and_the_report(toy, tmp_path):
    before = (SRC / "report.py").read_bytes(), (SRC / "derivation.py").read_bytes()
    assert SCHEMA["toy_note"] == {"words": ((str,), "a short note")}
    f = tmp_path / "toy.toml"
    f.write_text(BASE + '[toy_note]\nwords = "hello"\n')
    der = load_derivation(f)
    assert der.sections["toy_note"] == "hello" and der.toy_note == "hello"
    tex = report_latex(der)
    assert r"\section{Toy note}" in tex and "The note says hello." in tex
    # in ORDER: after the errata, before the references
    assert tex.index(r"\section{Errata}") < tex.index(r"\section{Toy note}") < tex.index("thebibliography")
    # its own parse error, through the file's error
    f.write_text(BASE + '[toy_note]\nwords = "two words"\n')
    with pytest.raises(DerivationFileError, match=r"toy\.toml: \[toy_note\] words: letters only"):
        load_derivation(f)
    # the schema's own checks apply to it: an unknown key is named with the valid ones
    f.write_text(BASE + '[toy_note]\ncolour = "red"\n')
    unknown = r"\[toy_note\] unknown key\(s\) \['colour'\]; valid keys are \['words'\]"
    with pytest.raises(DerivationFileError, match=unknown):
        load_derivation(f)
    # without the table the section does not apply
    f.write_text(BASE)
    assert r"\section{Toy note}" not in report_latex(load_derivation(f))
    assert ((SRC / "report.py").read_bytes(), (SRC / "derivation.py").read_bytes()) == before


def test_an_unregistered_section_leaves_schema_and_report(tmp_path):
    toy = register_section(_toy())
    unregister_section(toy)
    assert "toy_note" not in SCHEMA and toy not in sections.SECTIONS
    f = tmp_path / "toy.toml"
    f.write_text(BASE + '[toy_note]\nwords = "hello"\n')
    with pytest.raises(DerivationFileError, match=r"unknown table\(s\) \['toy_note'\]"):
        load_derivation(f)


@pytest.mark.parametrize("change, message", [
    ({"ORDER": None}, "does not declare ORDER"),
    ({"ORDER": 900}, "ORDER = 900 is that of section"),
    ({"ORDER": 1.5}, "must be an int"),
    ({"KEY": "contact"}, "KEY = 'contact' is read by section"),
    ({"KEY": "punch"}, "is a core table"),
    ({"KEY": "Bad Key"}, "must be None or a table name"),
    ({"SCHEMA": {"words": (str, "no tuple")}}, r"SCHEMA\['words'\] must be"),
    ({"render": "not callable"}, "render must be callable"),
])
def test_the_contract_is_checked_at_registration(change, message):
    toy = _toy()
    for name, value in change.items():
        if value is None:
            delattr(toy, name)
        else:
            setattr(toy, name, value)
    with pytest.raises(SectionContractError, match=message):
        register_section(toy)
    assert toy not in sections.SECTIONS


def test_sections_in_order_and_report_module_small():
    orders = [s.ORDER for s in sections.SECTIONS]
    assert orders == sorted(orders) and len(set(orders)) == len(orders)
    names = [s.__name__.rsplit(".", 1)[1] for s in sections.SECTIONS]
    assert names[0] == "intro" and names[-2:] == ["errata", "references"]
    assert len((SRC / "report.py").read_text().splitlines()) < 500
    # no section names a model or the punch's catalogue name: they ask hooks (report_rows, punch_traits)
    for path in (SRC / "sections").glob("*.py"):
        text = path.read_text()
        assert ".model ==" not in text and "punch.name" not in text and "name.startswith" not in text, path.name
