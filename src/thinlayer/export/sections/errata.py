r"""The errata of a report, and the errata document (``thinlayer report errata``).

A report carries the entries of :mod:`thinlayer.errata` that concern it (:meth:`thinlayer.errata.Concern.selects`):
the equations it uses (every ``\tag`` and every equation number cited in parentheses in its text, ranges such as
``(3.15)--(3.18)`` expanded), its punch (:func:`punch_kinds`) and its layer (:func:`layer_kinds`).  The errata
document carries every entry, grouped by publication.  Entries quoted from a secondary source say so in their
heading and name the source.
"""
from __future__ import annotations

import re
from collections.abc import Iterable
from typing import Any

from ..._checks import InputError
from ...display import latex_escape
from .base import axisymmetric

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render", "prose", "errata_section", "errata_document",
           "equations_used", "punch_kinds", "layer_kinds", "report_errata"]

KEY = None
SCHEMA: dict = {}
ORDER = 900  # after every section whose equations it looks at

_TAG = re.compile(r"\\tag\{([^{}]*)\}")
_NUMBER = r"(?:[A-Z]{1,2}\.\d+|\d+\.\d+)"
#: a cited equation number, or a range of them: ``(2.21)``, ``(3.15)--(3.18)``, ``(F.6)-(F.7)``
_REF = re.compile(rf"\(({_NUMBER})\)(?:\s*(?:--|-|\u2013)\s*\(({_NUMBER})\))?")


def prose(text: str) -> str:
    r"""Project prose with inline math (the errata's fields): ``$...$`` kept as math, the rest escaped.

    Only for thinlayer's own text; a user's text goes through :func:`escape` whole.

    >>> prose("with $p = -\\sigma_{33} > 0$ & more")
    'with $p = -\\sigma_{33} > 0$ \\& more'
    """
    parts = text.split("$")
    if len(parts) % 2 == 0:
        raise InputError(f"unbalanced $ in {text!r}")
    # a long file or module name may break after an underscore rather than run into the margin
    return "".join(f"${q}$" if k % 2 else latex_escape(q).replace(r"\_", r"\_\allowbreak{}")
                   for k, q in enumerate(parts))


def _expand(first: str, last: str | None) -> list[str]:
    """``["3.15", "3.16", ..., "3.18"]`` for a range of one family; the two ends alone otherwise."""
    if last is None:
        return [first]
    (fa, _, na), (fb, _, nb) = first.rpartition("."), last.rpartition(".")
    if fa == fb and na.isdigit() and nb.isdigit() and 0 <= int(nb) - int(na) <= 40:
        return [f"{fa}.{k}" for k in range(int(na), int(nb) + 1)]
    return [first, last]


def equations_used(latex: str) -> set[str]:
    r"""The equation numbers a report's LaTeX displays (``\tag``) or cites in parentheses, ranges expanded.

    >>> sorted(equations_used(r"see (3.15)--(3.18) and \tag{SO.9--SO.10} (F.1)"))
    ['3.15', '3.16', '3.17', '3.18', 'F.1', 'SO.10', 'SO.9']
    """
    out: set[str] = set()
    for m in _TAG.finditer(latex):
        a, _, b = m.group(1).partition("--")
        out.update(_expand(a.strip(), b.strip() or None))
    for m in _REF.finditer(latex):
        out.update(_expand(m.group(1), m.group(2)))
    return out


def punch_kinds(der: Any) -> set[str]:
    """The kinds of :data:`thinlayer.errata.PUNCHES` a derivation's punch belongs to."""
    if der.punch is None:  # the flat punch, or a tip of revolution (its own section)
        return {"axisymmetric"} if der.sections.get("tip") is not None else {"flat"}
    kinds = {"smooth", *der.punch_traits}  # the catalogue punch's: "sphere", "elliptic paraboloid"
    if axisymmetric(der.punch):
        kinds.add("axisymmetric")
    return kinds


def layer_kinds(der: Any) -> set[str]:
    """The kinds of :data:`thinlayer.errata.LAYERS` a derivation's layer (and its flat-punch table) covers."""
    layer = der.layer
    if layer.shear_free_base:
        return {"compressible", "frictionless"}
    if not layer.has_compressible_expansion:
        return {"incompressible"}
    kinds = {"compressible"}
    nu = layer.numeric_nu
    if nu is None or nu > 0.25:
        kinds.add("nearly incompressible")
    flat = der.sections.get("flat_punch")
    if flat is not None and any(float(v) == 0.5 for v in flat.get("nu", ())):
        kinds.add("incompressible")
    return kinds


def report_errata(der: Any, body: str) -> tuple[Any, ...]:
    """The entries of :mod:`thinlayer.errata` a derivation's report carries, given the report's LaTeX so far."""
    from ... import errata

    return errata.select(equations_used(body), punch_kinds(der), layer_kinds(der))


# ---------------------------------------------------------------------------------------------
# layout of one entry
# ---------------------------------------------------------------------------------------------
_VALUE = re.compile(r"\\kappa\(([^()]*)\) = ([-\d.]+)")
#: widest printed-and-derived pair (visible characters, roughly) set on one line
_ONE_LINE = 70
#: rows of a table of values set as one unbreakable box; a longer one is a longtable with its header repeated
_ONE_PAGE = 25
_KINDS = {"misprint": "misprint", "notation": "notation", "ambiguous": "ambiguous reading",
          "published series": "published series", "secondary": "secondary source"}


def _values(form: str) -> list[tuple[str, str]] | None:
    r"""``[(x, y), ...]`` of a form that is exactly a list ``\kappa(x) = y,\ ...``, else None."""
    pairs = _VALUE.findall(form)
    return pairs if pairs and r",\ ".join(rf"\kappa({x}) = {y}" for x, y in pairs) == form else None


def _visible(form: str) -> int:
    """About how many symbols a LaTeX formula shows (commands count as one, braces and scripts as none)."""
    s = re.sub(r"\\(?:frac|tfrac|left|right|quad|qquad|mathcal|boldsymbol|text)\b", "", form)
    s = re.sub(r"\\[a-zA-Z]+", "x", s)
    return len(re.sub(r"\\.|[{}^_ ]", "", s))


def value_table(pairs_p: list[tuple[str, str]], pairs_d: list[tuple[str, str]], quoted: bool) -> str:
    r"""A ``longtable`` of quoted (or printed) and derived values, one row per argument, its header repeated on a
    continued page: it never splits into loose fragments.
    """
    head = (r"$a/h$ & " + ("quoted" if quoted else "printed") + r" $\kappa$ & derived $\kappa$ & deviation \\")
    rows = []
    for (x, y), (_, z) in zip(pairs_p, pairs_d):
        dev = 100 * (float(y) / float(z) - 1)
        rows.append(rf"${x}$ & ${y}$ & ${z}$ & ${dev:+.2f}\,\%$ \\")
    if len(rows) <= _ONE_PAGE:  # short: one unbreakable box, never split
        body = [r"\begin{tabular}{rrrr}", r"\hline", head, r"\hline", *rows, r"\hline", r"\end{tabular}"]
        return "\n".join([r"\par\noindent\parbox{\linewidth}{\centering\footnotesize", *body, "}\\par"])
    return "\n".join([r"{\footnotesize", r"\begin{longtable}{rrrr}", r"\hline", head, r"\hline", r"\endfirsthead",
                      r"\multicolumn{4}{l}{\emph{(continued)}} \\", r"\hline", head, r"\hline", r"\endhead",
                      r"\hline", r"\endlastfoot", *rows, r"\end{longtable}}"])


def _forms(doc: Any, e: Any) -> None:
    """The printed and derived forms: a table of values, one line, or two lines when they are long."""
    p, d = _values(e.printed), _values(e.derived)
    printed = "quoted" if e.kind == "secondary" else "printed"
    if p and d and [x for x, _ in p] == [x for x, _ in d]:
        doc.parts.append(value_table(p, d, e.kind == "secondary") + "\n")
    elif _visible(e.printed) + _visible(e.derived) > _ONE_LINE:
        doc.lines([rf"\text{{{printed}: }} {e.printed}", rf"\text{{derived: }} {e.derived}"])
    else:
        doc.math(rf"\text{{{printed}: }} {e.printed}\qquad \text{{derived: }} {e.derived}")


def _heading(e: Any) -> str:
    escape = latex_escape
    kind = _KINDS.get(e.kind, escape(e.kind))
    if e.source == "argatov":
        return rf"({e.where.strip('()') or e.equation}) {prose(e.quantity)} ({kind})"
    where = f", {escape(e.where)}" if e.where else ""
    return rf"{escape(e.equation)}~\cite{{{e.source}}}{where}: {prose(e.quantity)} ({kind})"


def _entry(doc: Any, e: Any) -> None:
    tail = ""
    if e.quoted_from:
        tail += (rf" \emph{{Quoted from:}} {prose(e.quoted_from)} --- a secondary source, not the publication's own "
                 r"text; the entry stays so until the values are checked against the original.")
    if e.cites:
        tail += " See " + ", ".join(rf"\cite{{{k}}}" for k in e.cites) + "."
    doc.text(rf"\paragraph{{{_heading(e)}.}} {prose(e.evidence)}{tail}")
    _forms(doc, e)


def parse(table: Any, context: Any) -> None:
    return None


def applies(der: Any) -> bool:
    return True


def render(doc: Any, der: Any, context: Any) -> None:
    """The section Errata of a derivation's report: the entries that concern the report so far."""
    from ... import errata

    errata_section(doc, report_errata(der, "\n".join(doc.parts)), len(errata.ENTRIES))


def errata_section(doc: Any, entries: Iterable[Any], total: int) -> Any:
    """The section Errata of a report: ``entries`` (those that concern it) out of ``total`` in the registry."""
    entries = tuple(entries)
    doc.section("Errata")
    lead = (r"Where the derivation differs from the publications it rests on: the seed paper \cite{argatov}, whose "
            r"equation numbers head its entries, and the published series and tables set beside the engine's "
            r"results, each headed by its publication. Each entry is re-derived by an "
            r"independent check (\texttt{thinlayer.errata}) that confirms the derived form and refutes the printed "
            rf"one. This report lists the {len(entries)} of the registry's {total} entries that concern its "
            r"equations, punch and layer; the whole registry is the document \texttt{thinlayer report errata}.")
    if not entries:
        lead = (rf"None of the {total} entries of the errata registry (\texttt{{thinlayer.errata}}) concerns this "
                r"report's equations, punch and layer; the whole registry is the document "
                r"\texttt{thinlayer report errata}. The seed paper is \cite{argatov}.")
    doc.text(lead)
    for e in entries:
        _entry(doc, e)
    return doc


#: the publications of the registry in the errata document's order, with their headings
_GROUPS = (("argatov", "The seed paper"), ("dimitriadis2002", "Dimitriadis et al. (2002)"),
           ("garcia2018", "Garcia and Garcia (2018)"), ("gavara2012", "Gavara and Chadwick (2012)"),
           ("hayes1972", "Hayes et al. (1972)"))


def errata_document(doc: Any) -> str:
    """The whole errata registry written into ``doc`` (a new :class:`thinlayer.export.report.Document`), ending with
    the references: the document ``thinlayer report errata``.
    """
    from ... import errata
    from .references import references_section

    doc.text(r"Every entry of the registry \texttt{thinlayer.errata}: where a publication's printed formula or value "
             r"differs from thinlayer's derivation, with the evidence and an independent check that confirms the "
             r"derived form and refutes the printed one (the test suite runs them all). An entry "
             r"of the seed paper quotes its equation; an entry whose printed value was read not in the publication "
             r"but in another source is marked \emph{secondary source} and names that source. Each report of a "
             r"derivation carries only the entries that concern its equations, punch and layer.")
    known = {k for k, _ in _GROUPS}
    groups = list(_GROUPS) + [(k, k) for k in dict.fromkeys(e.source for e in errata.ENTRIES) if k not in known]
    for key, title in groups:
        entries = [e for e in errata.ENTRIES if e.source == key]
        if not entries:
            continue
        doc.section(rf"{title} \protect\cite{{{key}}}")
        if key == "argatov":
            doc.text(r"Each entry is headed by the number of the paper's equation whose print it corrects.")
        for e in entries:
            _entry(doc, e)
    references_section(doc)
    return doc.latex()
