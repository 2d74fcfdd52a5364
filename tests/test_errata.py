"""The errata registry: every entry re-derives its equation by an independent route."""
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
