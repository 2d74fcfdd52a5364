"""Where each publication compared in :mod:`thinlayer.validation` was looked for, and what each address held.

The project reads publications only through stored copies (the search tool's corpora of web pages, documentation
and public code, and snapshots of public repositories); the machine has no access to the live web (checked: a
request to Europe PMC's REST service does not resolve).  The stored web pages return the opening of a page only
(about 2,400 characters: title, authors, abstract, the first paragraphs), never its body, whatever the query, so the
equations of an article are out of reach unless a repository holds its text.  Every attempt is listed, rounds in
order, so that an entry typed ``"secondary"`` in :mod:`thinlayer.errata` always says where its original was sought.

``READ_ATTEMPTS = {citation key: ((address or query, what was found), ...)}``.
"""
from __future__ import annotations

__all__ = ["READ_ATTEMPTS", "RECORDS"]

#: an address that held the opening of a page, read for the bibliographic record (references.py) and the abstract
_OPENING = "the stored page's opening only (title, authors, abstract, first paragraphs); the equations lie past it"

READ_ATTEMPTS: dict[str, tuple[tuple[str, str], ...]] = {
    "gavara2012": (
        ("https://pmc.ncbi.nlm.nih.gov/articles/PMC3492504",
         "the author manuscript in PubMed Central, stored: its opening only (Nat Nanotechnol 2012 Sep 30; "
         "7(11):733-736, doi 10.1038/nnano.2012.163, PMCID PMC3492504, NIHMSID NIHMS402200, PMID 23023646; "
         "abstract; the first paragraph of the text). The BECC formula lies past the part returned. (The brief's "
         "PMC3835343 is not this article's PMCID.)"),
        ("https://www.nature.com/articles/nnano.2012.163",
         "the publisher's page: abstract, figure titles and reference list; the text is behind a paywall"),
        ("pages corpus: queries on the BECC formula, its wording, the supplementary information, Europe PMC",
         "no other copy of the article or of its supplementary information"),
        ("find_string 'nnano.2012.163', 'Gavara2012', 'Gavara_2012'",
         "PyFMRheo's bec_gavara_cone citing the nature.com page, and a log of a failed full-text download of "
         "PMC3492504: no copy of the article"),
        ("docs and issues corpora; find_string 'Bottom Effect Cone Correction', 'Gavara N, Chadwick'",
         "a README of a MATLAB analysis repository and a reference list citing another Gavara & Chadwick article: no "
         "equation"),
        ("round 3: pages corpus, the printed form as a query ('8E tan theta delta^2/3pi [1 + 1.7795 2 tan theta/pi^2 "
         "delta/h') and 'bottom effect cone correction conical tip thin sample'",
         "the nature.com page again (abstract, figure titles) and unrelated pages; no body text"),
        ("round 3: find_string 'bottom effect cone correction'",
         "one README of a MATLAB PeakForce-QNM repository that names BECC: no equation"),
        ("round 3: find_string 'elastic moduli of a single cell' (an Igor Pro HertzFit procedure)",
         "the procedure writes 1 + 1.7795*2*tan/pi^2*chi + 16*1.7795^2*tan^2*chi^2 for Gavara & Chadwick: a third "
         "repository with the quoted form, still no copy of the article"),
        ("round 3: live web (https://www.ebi.ac.uk/europepmc/webservices/rest/PMC3492504/fullTextXML)",
         "not reachable from this machine (the host does not resolve)"),
    ),
    "garcia2018": (
        ("pages corpus: title, 'Biophys J. 2018;114(12):2923-2932', doi 10.1016/j.bpj.2018.05.012, PMC6026379",
         "no stored page of the article (PubMed Central, Europe PMC, cell.com, PubMed): only later articles of the "
         "same group (Nanoscale 2021 d1nr03894j, Nanoscale 2025 d5nr01236h), of which only the opening is returned"),
        ("docs and issues corpora: Garcia 2018 bottom-effect coefficients, cone, pyramid", "nothing on the article"),
        ("find_string 'single cell cultured on a rigid support'", "no hit"),
        ("find_string 'j.bpj.2018.05.012', 'Garcia2018.pdf'",
         "code that cites the DOI (yu-efremov/ViscoIndent bottom_effect_correction.py, an Igor HertzFit procedure, a "
         "PyFMRheo example): a secondary source, the same coefficients; no copy of the article"),
        ("round 3: pages corpus, 'Determination of the elastic moduli of a single cell cultured on a rigid support by "
         "force microscopy' and the coefficients with the power-law model as a query",
         "no page of the article; the openings of Sanchez et al. 2021 (d1nr03894j), Garcia et al. 2020 "
         "(c9nr10316c) and Moura et al. 2025 (d5nr01236h), which reprint the model further on, are all that is "
         "returned"),
        ("round 3: snapshot of github:yu-efremov/ViscoIndent (commit c90ee84), ViscoIndent_Documentation.pdf read "
         "with pdftotext",
         "the documentation (Y. Efremov, rev. August 2022) cites 'Pablo D. Garcia and Ricardo Garcia. Determination of "
         "the Elastic Moduli of a Single Cell Cultured on a Rigid Support by Force Microscopy. Biophysical Journal, "
         "114(12):2923-2932, 2018' as its source of the bottom-effect coefficients; no formula in the document"),
        ("round 3: jlopezalo/PyFMRheo, src/pyfmrheo/models/ting.py and routines/TingFit.py (stored commit 50d459d), "
         "read for the bottom-effect-corrected Ting form that issue 27 item 5 names",
         "TingModel declares apply_bec_flag and bec_model but its force (analytical power-law and numerical forms) "
         "uses neither: the stored version applies no bottom-effect correction inside Ting's model, so there is no "
         "PyFMRheo form to compare; the cone coefficients it quotes are those of correction_factors.py"),
    ),
    "efremov2017": (
        ("https://pmc.ncbi.nlm.nih.gov/articles/PMC5431511 (pages corpus, title and body phrases as queries)",
         "the PubMed Central page, stored: " + _OPENING + " (Sci Rep 2017 May 8;7:1541, doi "
         "10.1038/s41598-017-01784-3, PMCID PMC5431511, PMID 28484282; the method rests on the elastic-viscoelastic "
         "correspondence principle, SLS and power-law rheology)"),
        ("pages corpus: Ting's retraction condition, t1, bottom-effect correction with Ting's model",
         "other articles' openings; the body of PMC5431511 is not returned"),
        ("find_string 's41598-017-01784-3'",
         "three files of one repository that cite the DOI in docstrings: no formula"),
        ("snapshot of github:yu-efremov/ViscoIndent (the first author's code, commit c90ee84): Ting_numerical.py, "
         "bottom_effect_correction.py, ViscoIndent_Documentation.pdf",
         "the implemented form (a secondary source): the documentation cites Efremov et al. 2017 for the numerical "
         "Ting algorithm and Garcia & Garcia 2018 for the bottom-effect coefficients"),
        ("live web (Europe PMC full text XML)", "not reachable from this machine"),
    ),
    "garcia2020": (
        ("https://pubs.rsc.org/ja/content/articlehtml/2020/nr/c9nr10316c",
         "the RSC open-access HTML, stored: " + _OPENING + " (Pablo D. Garcia, Carlos R. Guerrero, Ricardo Garcia, "
         "'Nanorheology of living cells measured by AFM-based force-distance curves', Nanoscale, first published 15 "
         "April 2020; the abstract says the method incorporates bottom-effect corrections, a power-law rheology "
         "model and the deformation history)"),
    ),
    "sanchez2021": (
        ("https://pubs.rsc.org/en/content/articlehtml/2021/nr/d1nr03894j",
         "the RSC open-access HTML, stored twice: " + _OPENING + " (Juan G. Sanchez, Francisco M. Espinosa, Ruben "
         "Miguez, Ricardo Garcia, Nanoscale 2021, 13, 16339-16348, doi 10.1039/D1NR03894J)"),
        ("pages corpus: the printed coefficients with the power-law model as a query",
         "the same opening; the page's body (where the bottom-effect model is printed) is not returned"),
    ),
    "moura2025": (
        ("https://rsc.66557.net/en/content/articlehtml/2025/nr/d5nr01236h (a mirror of the RSC HTML)",
         "stored: " + _OPENING + " (Afonso L. D. Moura, Jaime R. Tejedor, Francisco M. Espinosa, Lazaro A. "
         "Dominguez, Jeanlex S. de Sousa, Ricardo Garcia, 'Evidence of the bottom stiffness effect on atomic force "
         "microscopy-based cell mechanobiology', Nanoscale, first published 5 June 2025)"),
    ),
    "shull2002": (
        ("https://www.scholars.northwestern.edu/en/publications/contact-mechanics-and-the-adhesion-of-soft-solids",
         "the university's research record: author, title, journal, volume, issue, pages, date and abstract; no "
         "text of the review"),
        ("pages corpus: 'Shull 2002 Contact mechanics and the adhesion of soft solids'; the thin-film JKR "
         "corrections as a query", "the same record; no copy of the review"),
        ("code corpus and find_string: Shull's thin-layer corrections (compliance, load and displacement factors "
         "in a/h), the DOI 10.1016/S0927-796X(01)00039-0",
         "no implementation quoting them and no copy: nothing to compare, not even as a secondary source"),
        ("docs corpus: 'Shull confinement correction JKR thin layer compliance f(a/h)'",
         "an R package's thin-film Hertz correction after Long et al. (2011) and unrelated simulation manuals: no "
         "quotation of Shull's forms"),
    ),
    "johnson2001": (
        ("pages corpus: 'Johnson Sridhar 2001 adhesion between a spherical indenter and an elastic solid with a "
         "compliant elastic coating J Phys D'",
         "no page of the article; a book chapter's abstract that summarises it (JKR holds for thick and for thin "
         "layers, not in between): no formula"),
    ),
    "sridhar1997": (
        ("pages corpus: 'Sridhar Johnson Fleck 1997 adhesion mechanics of the surface force apparatus J Phys D 30 "
         "1710'", "no page of the article, no record of it"),
        ("code corpus: JKR on a bonded layer, pull-off against a/h",
         "AtomicJ's thin-sample JKR-compatible models (Lebedev-Chebyshev), not these publications: no quotation"),
    ),
}

#: citation keys whose bibliographic record was read in an address above (the fields of references.py come from it)
RECORDS = {
    "efremov2017": READ_ATTEMPTS["efremov2017"][0][0],
    "garcia2020": READ_ATTEMPTS["garcia2020"][0][0],
    "sanchez2021": READ_ATTEMPTS["sanchez2021"][0][0],
    "moura2025": READ_ATTEMPTS["moura2025"][0][0],
    "shull2002": READ_ATTEMPTS["shull2002"][0][0],
}
