r"""The bibliography: every publication thinlayer cites, keyed by a citation key.

Each field of an entry is taken from a record of the publication itself (the record is named in
``record``); a field that could not be checked against such a record is left out, and ``note`` says
what is missing.  Reports cite by key (``\cite{hayes1972}``) and list only what they cite
(:func:`thinlayer.export.sections.references.references_section`); the errata registry names the
publication of each entry by its key (:attr:`thinlayer.errata.Erratum.source`).

>>> from thinlayer import references
>>> references.get("hayes1972").year
1972
"""
from __future__ import annotations

from dataclasses import dataclass

from .display import latex_escape

__all__ = ["Reference", "ENTRIES", "get", "latex_item"]


@dataclass(frozen=True)
class Reference:
    """One publication: only the fields a record of it confirms (``None`` or empty: not confirmed).

    ``record`` names where the fields were read; ``note`` says what could not be confirmed. ``cited_as``
    is set for a work known only from another publication's reference list (``"argatov, ref. 17"``).
    """

    key: str
    authors: tuple[str, ...] = ()
    title: str | None = None
    journal: str | None = None
    year: int | None = None
    volume: str | None = None
    issue: str | None = None
    pages: str | None = None
    doi: str | None = None
    publisher: str | None = None
    record: str = ""
    note: str = ""
    cited_as: str = ""

    def latex(self) -> str:
        r"""The entry as LaTeX text for a ``\bibitem`` (plain fields escaped)."""
        parts = []
        if self.authors:
            parts.append(latex_escape(_join(self.authors)))
        if self.title:
            parts.append(r"\emph{" + latex_escape(self.title) + "}")
        venue = []
        if self.journal:
            venue.append(latex_escape(self.journal))
        if self.volume:
            venue.append(r"\textbf{" + latex_escape(self.volume) + "}" + (f"({latex_escape(self.issue)})" if self.issue
                                                                          else ""))
        if self.pages:
            venue.append(latex_escape(self.pages.replace("-", "--")))
        if self.publisher:
            venue.append(latex_escape(self.publisher))
        if self.year:
            venue.append(f"({self.year})")
        if venue:
            parts.append(" ".join(venue))
        if self.doi:
            parts.append(r"doi:\,\texttt{" + latex_escape(self.doi) + "}")
        text = ", ".join(parts)
        if self.note:
            text += (". " if text else "") + latex_escape(self.note)
        return text.rstrip(".") + "."


def _join(names: tuple[str, ...]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


#: the seed paper's title, as its own text gives it (the project's copy carries no authors and no journal)
SEED_TITLE = "The pressure of a punch in the form of an elliptic paraboloid on a thin elastic layer"

ENTRIES: tuple[Reference, ...] = (
    Reference(
        "argatov", title=SEED_TITLE,
        record="the title page of the project's copy of the paper (shared/paper/thin-layer-punch.md)",
        note="The seed paper; the project's copy gives neither its authors nor its journal, year, volume, pages or "
             "DOI, and no record of the publication could be consulted, so they are not given here"),
    Reference(
        "hayes1972", authors=("W. C. Hayes", "L. M. Keer", "G. Herrmann", "L. F. Mockros"),
        title="A mathematical analysis for indentation tests of articular cartilage",
        journal="Journal of Biomechanics", year=1972, volume="5", issue="5", pages="541-551",
        record="Northwestern University's research record of the article and the scan of its first page "
               "(J. Biomechanics 1972, Vol. 5, pp. 541-551, Pergamon Press)",
        note="DOI not confirmed by a record, so not given"),
    Reference(
        "dimitriadis2002", authors=("E. K. Dimitriadis", "F. Horkay", "J. Maresca", "B. Kachar", "R. S. Chadwick"),
        title="Determination of elastic moduli of thin layers of soft material using the atomic force microscope",
        journal="Biophysical Journal", year=2002, pages="2798-2810", doi="10.1016/S0006-3495(02)75620-8",
        record="a bibliographic database record of the article (authors, title, DOI, pages)",
        note="Volume not confirmed by a record, so not given"),
    Reference(
        "garcia2018", authors=("Garcia", "Garcia"), journal="Biophysical Journal", year=2018, volume="114",
        pages="2923",
        record="thinlayer's own citation (thinlayer.asymptotics.thick_layer.PUBLISHED_SERIES)",
        note="Cited as thinlayer records it; title, initials, last page and DOI could not be checked against a "
             "record of the publication (no copy or record of it was found: "
             "thinlayer.validation.published_sources.READ_ATTEMPTS). Documents that cite it give Pablo D. Garcia "
             "and Ricardo Garcia, 'Determination of the elastic moduli of a single cell cultured on a rigid support "
             "by force microscopy', Biophysical Journal 114(12), 2923-2932, doi 10.1016/j.bpj.2018.05.012 (the "
             "reference list of ViscoIndent's documentation, an Igor Pro fitting procedure): a secondary record"),
    Reference(
        "gavara2012", authors=("N. Gavara", "R. S. Chadwick"),
        title="Determination of the elastic moduli of thin samples and adherent cells using conical atomic force "
              "microscope tips",
        journal="Nature Nanotechnology", year=2012, volume="7", issue="11", pages="733-736",
        doi="10.1038/nnano.2012.163",
        record="the publisher's page of the article (nature.com, title, abstract and figure titles) and the first "
               "page of its author manuscript in PubMed Central, PMC3492504, NIHMS402200, PMID 23023646 (authors, "
               "journal, volume, issue, pages, DOI)",
        note="Only the title page, abstract and first paragraph could be read; the article's equations were not "
             "(addresses tried: thinlayer.validation.published_sources.READ_ATTEMPTS)"),
    Reference(
        "efremov2017", authors=("Y. M. Efremov", "W.-H. Wang", "S. D. Hardy", "R. L. Geahlen", "A. Raman"),
        title="Measuring nanoscale viscoelastic parameters of cells directly from AFM force-displacement curves",
        journal="Scientific Reports", year=2017, volume="7", pages="1541", doi="10.1038/s41598-017-01784-3",
        record="the article's page in PubMed Central, PMC5431511, PMID 28484282 (its opening: journal, date, volume, "
               "article number, DOI, authors, title, abstract)",
        note="Only the opening (abstract, first paragraphs) could be read; the equations were not "
             "(addresses tried: thinlayer.validation.published_sources.READ_ATTEMPTS)"),
    Reference(
        "garcia2020", authors=("P. D. Garcia", "C. R. Guerrero", "R. Garcia"),
        title="Nanorheology of living cells measured by AFM-based force-distance curves", journal="Nanoscale",
        year=2020, doi="10.1039/C9NR10316C",
        record="the article's open-access HTML at pubs.rsc.org (its opening: authors, title, dates, abstract; the DOI "
               "from the page's address)",
        note="Volume and pages not in the part read; only the opening could be read (addresses tried: "
             "thinlayer.validation.published_sources.READ_ATTEMPTS)"),
    Reference(
        "sanchez2021", authors=("J. G. Sanchez", "F. M. Espinosa", "R. Miguez", "R. Garcia"),
        title="The viscoelasticity of adherent cells follows a single power-law with distinct local variations "
              "within a single cell and across cell lines",
        journal="Nanoscale", year=2021, volume="13", pages="16339-16348", doi="10.1039/D1NR03894J",
        record="the article's open-access HTML at pubs.rsc.org (its opening: DOI, journal, volume, pages, title, "
               "authors, abstract)",
        note="Only the opening could be read; the bottom-effect model it prints lies past it (addresses tried: "
             "thinlayer.validation.published_sources.READ_ATTEMPTS)"),
    Reference(
        "moura2025", authors=("A. L. D. Moura", "J. R. Tejedor", "F. M. Espinosa", "L. A. Dominguez",
                              "J. S. de Sousa", "R. Garcia"),
        title="Evidence of the bottom stiffness effect on atomic force microscopy-based cell mechanobiology",
        journal="Nanoscale", year=2025, doi="10.1039/D5NR01236H",
        record="a mirror of the article's open-access HTML (its opening: authors, title, dates, abstract; the DOI from "
               "the page's address)",
        note="Volume and pages not in the part read; only the opening could be read"),
    Reference(
        "shull2002", authors=("K. R. Shull",), title="Contact mechanics and the adhesion of soft solids",
        journal="Materials Science and Engineering: R: Reports", year=2002, volume="36", issue="1", pages="1-45",
        record="Northwestern University's research record of the article (author, title, journal, volume, issue, "
               "pages, date, abstract)",
        note="DOI not shown in the record read, so not given; the review's text could not be read (addresses tried: "
             "thinlayer.validation.published_sources.READ_ATTEMPTS)"),
    Reference(
        "sneddon1965", authors=("I. N. Sneddon",),
        title="The relation between load and penetration in the axisymmetric Boussinesq problem for a punch of "
              "arbitrary profile",
        journal="International Journal of Engineering Science", year=1965, volume="3", pages="47-57",
        publisher="Pergamon Press",
        record="the first page of a scan of the article (Int. J. Engng Sci. Vol. 3, pp. 47-57, Pergamon Press 1965)",
        note="Only its first page (title, abstract, introduction) could be read; DOI not confirmed by a record"),
    Reference(
        "boussinesq1885", authors=("J. Boussinesq",),
        title="Application des potentiels \u00e0 l'\u00e9tude de l'\u00e9quilibre et du mouvement des solides "
              "\u00e9lastiques", publisher="Gauthier-Villars, Paris", year=1885,
        record="reference lists of later articles that cite it"),
    Reference(
        "alexandrov", cited_as="argatov, ref. 17",
        note="Alexandrov's method of the boundary layer and his approximation (3.19) of the kernel, as cited by the "
             "seed paper (its reference [17]); the seed paper's reference list is not in the project's copy, so the "
             "work is named as the paper names it"),
)

_BY_KEY = {r.key: r for r in ENTRIES}


def get(key: str) -> Reference:
    """The entry of a citation key (``KeyError`` naming the known keys otherwise)."""
    try:
        return _BY_KEY[key]
    except KeyError:
        raise KeyError(f"no reference {key!r}; known: {', '.join(_BY_KEY)}") from None


def latex_item(key: str) -> str:
    r"""``\bibitem{key} ...`` of an entry; a work known only through another's reference list names it."""
    ref = get(key)
    body = ref.latex()
    if ref.cited_as:
        via, _, num = ref.cited_as.partition(", ")
        body = rf"Cited in \cite{{{via}}}, {latex_escape(num)}. " + body
    return rf"\bibitem{{{key}}} {body}"
