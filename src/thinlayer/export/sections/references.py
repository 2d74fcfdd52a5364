r"""The references of a report: the works it cites (``\cite{key}``), in the order of their first citation.

Entries come from the bibliography registry :mod:`thinlayer.references`; a report lists exactly the keys its
text cites (a work named only through another's reference list brings that work in too).
"""
from __future__ import annotations

import re
from typing import Any

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render", "cited_keys", "references_section"]

KEY = None
SCHEMA: dict = {}
ORDER = 1000  # the last section: everything the report cites

_CITE = re.compile(r"\\cite\{([^{}]*)\}")


def cited_keys(latex: str) -> list[str]:
    r"""The citation keys of ``latex`` in the order of their first ``\cite``.

    >>> cited_keys(r"see \cite{b} and \cite{a,b}")
    ['b', 'a']
    """
    out: list[str] = []
    for m in _CITE.finditer(latex):
        for key in m.group(1).split(","):
            key = key.strip()
            if key and key not in out:
                out.append(key)
    return out


def references_section(doc: Any) -> Any:
    """Append the references of everything ``doc`` cites so far (a ``thebibliography``, numbered by first citation)."""
    from ... import references

    keys = cited_keys("\n".join(doc.parts))
    items = [references.latex_item(k) for k in keys]
    for k in list(keys):  # a work cited through another's reference list cites that one too
        for extra in cited_keys(references.latex_item(k)):
            if extra not in keys:
                keys.append(extra)
                items.append(references.latex_item(extra))
    if not items:
        return doc
    doc.parts.append("\n".join([rf"\begin{{thebibliography}}{{{len(items)}}}", *items, r"\end{thebibliography}"]))
    return doc


def parse(table: Any, context: Any) -> None:
    return None


def applies(der: Any) -> bool:
    return True


def render(doc: Any, der: Any, context: Any) -> None:
    references_section(doc)
