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
