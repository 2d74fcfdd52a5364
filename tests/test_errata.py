"""The errata registry: every entry re-derives its equation by an independent route."""
import re

import pytest

from thinlayer import errata


@pytest.mark.parametrize("entry", errata.ENTRIES, ids=lambda e: f"{e.equation}:{e.quantity[:25]}")
def test_each_erratum_is_confirmed(entry):
    assert entry.verify(), f"({entry.equation}) {entry.quantity}: derived form not confirmed"
    assert entry.printed != entry.derived and entry.evidence


def test_registry_names_equations():
    eqs = errata.equations()
    for eq in ("2.21", "2.30", "2.31", "3.1", "3.21"):
        assert eq in eqs
    assert errata.get("(2.21)") and errata.get("2.30")
    assert errata.get("1.1") == ()
    assert "2.21" in errata.latex_table()


#: ASCII math in prose, outside $...$ (issue 17: the errata of other papers reached the report as plain text)
_ASCII_PROSE = [r"\*", r"\^", r"\bsqrt\b", r"\be-?\d", r"\d[eE]-\d", r"~",
                r"\b(?:nu|chi|alpha|beta|kappa|vartheta|delta|lambda|pi|mu)(?:_\w+)?\b", r"\btests/"]


def _ascii_prose(text: str) -> list[str]:
    parts = text.split("$")
    assert len(parts) % 2 == 1, f"unbalanced $ in {text!r}"
    prose = " ".join(parts[0::2])
    return [m.group(0) for pat in _ASCII_PROSE for m in [re.search(pat, prose)] if m]


@pytest.mark.parametrize("entry", errata.ENTRIES, ids=lambda e: f"{e.equation}:{e.quantity[:25]}")
def test_prose_fields_are_typeset(entry):
    # the quantity and the evidence reach the report's LaTeX through report.prose(): math only inside $...$
    from thinlayer.export.report import prose

    for field in (entry.quantity, entry.evidence):
        assert not _ascii_prose(field), f"({entry.equation}) ASCII math {_ascii_prose(field)} in {field[:120]!r}"
        prose(field)  # balanced, escapable


def test_ascii_prose_check_can_fail():
    assert _ascii_prose("nu = 1/2 (chi = sqrt(R delta)/h)") and _ascii_prose("b_1 s^2") and _ascii_prose("to 1e-10")
    assert not _ascii_prose(r"$\nu = 1/2$ ($\chi = \sqrt{R\delta}/h$), thinlayer.numerics.flat_punch, to $10^{-10}$")


# --------------------------------------------------------------------------- provenance (issue 28 item 2)
def test_every_entry_quotes_its_publication_or_names_its_secondary_source():
    # an erratum of a publication quotes the publication itself (its table or equation); a value read only in
    # another source is typed "secondary" and names that source, until it is checked against the original
    from thinlayer import references

    for e in errata.ENTRIES:
        references.get(e.source)  # a known publication
        if e.source == "argatov":
            assert e.where == f"({e.equation})" and e.kind != "secondary", e.quantity
        elif e.kind == "secondary":
            assert e.quoted_from.strip() and e.quoted_from not in e.where, e.quantity
        else:
            assert re.fullmatch(r"(?:Table \d+|Eq\. \(?[\w.]+\)?|\([\w.]+\))", e.where), (e.equation, e.where)


def test_secondary_entries_say_so_where_the_report_prints_them():
    from thinlayer.export.sections.errata import _heading

    hayes = errata.get("Hayes 1972")
    assert len(hayes) == 4
    for e in hayes:
        assert e.kind == "secondary" and "as quoted in" in e.quantity and "secondary source" in _heading(e)
        assert "Table 1" not in e.where  # the table itself was not read: no claim about it
        assert e.quoted_from.split(",")[0] in e.quantity and "file" in e.quoted_from


def test_every_entry_says_what_it_concerns():
    for e in errata.ENTRIES:
        c = e.concerns
        assert c.equations and all(c.equations), e.quantity
    with pytest.raises(ValueError, match="punch"):
        errata.Concern(("1.1",), ("cylinder",))


def test_concern_rules_select_and_refuse():
    ellipse = errata.Concern(("3.1",), ("elliptic paraboloid",))
    assert ellipse.selects(["3.1"], ["smooth", "elliptic paraboloid"], ["compressible"])
    assert not ellipse.selects(["3.1"], ["smooth", "sphere"], ["compressible"])  # the punch
    assert not ellipse.selects(["2.21"], ["elliptic paraboloid"], ["compressible"])  # the equations
    moments = errata.Concern(("2.21",), layers=("compressible",))
    assert not moments.selects(["2.21"], ["sphere"], ["incompressible"])  # the layer
    assert {e.equation for e in errata.select(["F.1"], ["flat"], ["compressible"])} == {"Hayes 1972"}
