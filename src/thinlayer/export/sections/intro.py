r"""The report's opening paragraph: what it derives, from which paper, and how its equations are numbered."""
from __future__ import annotations

from typing import Any

__all__ = ["PAPER", "KEY", "SCHEMA", "ORDER", "parse", "applies", "render"]

#: the source paper, cited by its title
PAPER = "The pressure of a punch in the form of an elliptic paraboloid on a thin elastic layer"

KEY = None
SCHEMA: dict = {}
ORDER = 0


def parse(table: Any, context: Any) -> None:
    return None


def applies(der: Any) -> bool:
    return True


def render(doc: Any, der: Any, context: Any) -> None:
    doc.text(
        rf"This report carries out, with \texttt{{thinlayer}}, the asymptotic analysis of \emph{{{PAPER}}}"
        r"~\cite{argatov} for the punch and the layer of the derivation file below. Equation numbers in parentheses "
        r"are those of that paper; (I.$n$), (F.$n$), (SO.$n$) number the extensions of \texttt{thinlayer} (the "
        r"incompressible layer, the flat punch, the second order). Every formula is derived here, not copied: "
        r"where a printed source differs, the section Errata says so.")
