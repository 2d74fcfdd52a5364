r"""The LaTeX report of a derivation, in the paper's order, and its compilation to PDF.

The stages return LaTeX as tagged lines joined by ``" \\\\\n"``; the report splits them into single
displayed equations, keeps each ``\tag{..}`` (the paper's equation number) and sets the body with
``\fiteq``, which scales an equation down to the line width only when it would run off the page.
The files (the generated mark, the .tex, the PDF compile in a private temporary folder) are handled by
:mod:`thinlayer.export.latex_files`, whose names are importable from here too.  A title's long runs
without a space get break points (:func:`title_latex`) and a long user name in a table cell is scaled
to its column (``\fitcell``), so that no line runs off the page.

Untrusted text never reaches LaTeX raw: the title goes through :func:`title_latex` (every special
character escaped, Greek letters as math symbols, any other character LaTeX cannot set refused by
:func:`check_title`), symbol names are checked by :func:`check_symbol_names`, and the PDF is compiled
with ``-no-shell-escape`` and ``openin_any=p``, ``openout_any=p`` (no ``\write18``, no reading or
writing outside the temporary folder).
"""
from __future__ import annotations

import re
import unicodedata
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from ..display import latex_escape
from .latex_files import (  # noqa: F401 - the report's file functions, kept importable from here
    GENERATED_MARK,
    INSTALL_TEX,
    NoLatexEngineError,
    build_pdf,
    check_writable,
    compile_pdf,
    content_hash,
    first_error,
    latex_available,
    latex_engine,
    latex_environment,
    marked,
    overfull_boxes,
    pdf_hint,
    pdf_outputs,
    write_tex,
)
from .sections.boundary_layer import alexandrov_generic_latex  # noqa: F401 - kept importable from here
from .sections.contact import parameter_length_powers  # noqa: F401 - kept importable from here
from .sections.errata import prose  # noqa: F401 (re-exported: thinlayer.export.report.prose)
from .sections.intro import PAPER  # noqa: F401 - the source paper, cited by its title


class ReportTextError(ValueError):
    """A user's text or symbol name that cannot go into a LaTeX report safely."""


#: Greek letters -> math-mode commands (omicron and the capitals that look Latin are set as Latin letters)
_GREEK = {chr(0x3B1 + i): n for i, n in enumerate(
    r"\alpha \beta \gamma \delta \epsilon \zeta \eta \theta \iota \kappa \lambda \mu \nu \xi o \pi "
    r"\rho \varsigma \sigma \tau \upsilon \phi \chi \psi \omega".split())}
_GREEK.update({chr(0x391 + i): n for i, n in enumerate(
    r"A B \Gamma \Delta E Z H \Theta I K \Lambda M N \Xi O \Pi P - \Sigma T \Upsilon \Phi X \Psi \Omega".split())
    if n != "-"})  # U+03A2 is unassigned
#: Latin-1 and Latin Extended-A characters pdflatex's default (OT1) fonts cannot set
_UNSET = set("\u00ab\u00bb\u00d0\u00de\u00f0\u00fe\u0104\u0105\u0110\u0111\u0118\u0119\u0126\u0127\u012e\u012f"
             "\u0138\u013f\u0140\u0149\u014a\u014b\u0166\u0167\u0172\u0173\u017f")
#: longest title
MAX_TITLE = 200
_SAFE_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}")


def _settable(ch: str) -> bool:
    if " " <= ch <= "~" or ch in _GREEK:
        return True
    return "\u00a0" <= ch <= "\u017f" and ch not in _UNSET


def check_title(title: object, where: str = "title") -> str:
    """The title if LaTeX can set it: a string of printable characters, at most :data:`MAX_TITLE` long.

    ASCII, the Latin letters with accents of Latin-1 and Latin Extended-A that LaTeX's default fonts
    have, and Greek letters (set as math symbols) are accepted; anything else (control characters,
    other scripts, emoji) is a :class:`ReportTextError` naming the character.

    Parameters
    ----------
    title : object
        The user's title.
    where : str
        How to name it in the error.

    Returns
    -------
    str
        ``title``.
    """
    if not isinstance(title, str):
        raise ReportTextError(f"{where} = {title!r} is invalid: expected a string")
    if not title.strip() or len(title) > MAX_TITLE:
        raise ReportTextError(f"{where}: expected a non-empty string of at most {MAX_TITLE} characters, "
                              f"got {len(title)}")
    for ch in title:
        if not _settable(ch):
            name = unicodedata.name(ch, "control character")
            raise ReportTextError(f"{where}: the character {ch!r} (U+{ord(ch):04X} {name}) cannot be set by LaTeX; "
                                  "use ASCII, accented Latin letters or Greek letters")
    return title


#: a run of more than :data:`LONG_RUN` characters without a space gets a break point after every :data:`BREAK_EVERY`th
#: (at the title's \LARGE size 12 of the widest letters take 200 pt of the 483 pt line)
LONG_RUN, BREAK_EVERY = 24, 12


def title_latex(title: str) -> str:
    r"""A checked title (:func:`check_title`) in LaTeX: special characters escaped, Greek letters as math.

    A run of more than :data:`LONG_RUN` characters without a space (a file name, a formula) gets a
    break point (``\allowbreak{}``) after every :data:`BREAK_EVERY` characters, so that it wraps
    instead of running off the page; ordinary words are left whole.

    >>> title_latex("a_b " + "x" * 26).count(r"\allowbreak{}")
    2
    """
    check_title(title)
    out = []
    for word in re.split(r"( )", title):
        long_run = len(word) > LONG_RUN
        for k, ch in enumerate(word):
            if long_run and k and k % BREAK_EVERY == 0:
                out.append(r"\allowbreak{}")
            out.append((rf"\ensuremath{{{_GREEK[ch]}}}" if _GREEK[ch].startswith("\\") else _GREEK[ch])
                       if ch in _GREEK else latex_escape(ch))
    return "".join(out)


def check_symbol_names(names: Iterable[str], where: str = "punch") -> None:
    r"""Refuse a symbol name sympy's LaTeX printer would copy raw into the report (``\input{..}``, ``$``, ``%``).

    Parameters
    ----------
    names : iterable of str
        Names of the symbols of a user's formula.
    where : str
        Where they come from, for the error.

    Raises
    ------
    ReportTextError
        naming the symbol and what a valid name is.
    """
    for n in names:
        if not _SAFE_NAME.fullmatch(n):
            raise ReportTextError(f"{where}: the symbol name {n!r} is not allowed in a report: a name is a letter "
                                  "followed by at most 63 letters, digits and underscores")


PREAMBLE = r"""\documentclass[10pt]{article}
\usepackage[margin=2cm]{geometry}
\usepackage{amsmath,amssymb,graphicx}
\usepackage{float,longtable}
\allowdisplaybreaks
\numberwithin{figure}{section}
\numberwithin{table}{section}
\newsavebox{\fitbox}
% an equation at its natural size, or scaled to the line (minus room for the tag) if wider
\newcommand{\fiteq}[1]{\sbox{\fitbox}{$\displaystyle #1$}%
  \ifdim\wd\fitbox>\dimexpr\linewidth-5em\relax
    \resizebox{\dimexpr\linewidth-5em\relax}{!}{\usebox{\fitbox}}%
  \else\usebox{\fitbox}\fi}
% a table cell at its natural size, or scaled to the given width if wider (a long user name)
\newcommand{\fitcell}[2]{\sbox{\fitbox}{#2}%
  \ifdim\wd\fitbox>#1\relax\resizebox{#1}{!}{\usebox{\fitbox}}\else\usebox{\fitbox}\fi}
"""

_TAG = re.compile(r"\\tag\{([^{}]*)\}\s*$")
SEPARATOR = " \\\\\n"


def equations(block: str) -> str:
    """One ``equation*`` per line of a stage's LaTeX, each fitted to the page and tagged."""
    out = []
    for line in block.split(SEPARATOR):
        line = line.strip()
        if not line:
            continue
        m = _TAG.search(line)
        tag = ""
        if m:
            tag = rf"\tag{{{m.group(1)}}}"
            line = line[: m.start()].rstrip()
        out.append(rf"\begin{{equation*}}\fiteq{{{line}}}{tag}\end{{equation*}}")
    return "\n".join(out) + "\n"


def escape(text: str) -> str:
    """Plain prose -> LaTeX text mode."""
    return latex_escape(text)


class Document:
    """A report under construction: sections, prose, equations and tables."""

    def __init__(self, title: str):
        self.parts = [PREAMBLE.rstrip(), rf"\title{{{title_latex(title)}}}", r"\author{thinlayer}",
                      r"\date{}", r"\begin{document}", r"\maketitle", r"\small"]

    def section(self, title: str) -> "Document":
        self.parts.append(rf"\section{{{title}}}")
        return self

    def text(self, latex_text: str) -> "Document":
        """A paragraph; one that continues a sentence after a display (lower-case start) is not indented."""
        lead = r"\noindent " if latex_text[:1].islower() else ""
        self.parts.append(lead + latex_text.rstrip() + "\n")
        return self

    def lines(self, rows: list[str]) -> "Document":
        """Untagged displayed lines, one below the other, each fitted to the page."""
        body = " \\\\\n".join(rf"\fiteq{{{r}}}" for r in rows)
        self.parts.append(rf"\begin{{gather*}}{body}\end{{gather*}}" + "\n")
        return self

    def math(self, block: str) -> "Document":
        self.parts.append(equations(block))
        return self

    def group(self, lines: list[str], tag: str) -> "Document":
        r"""Lines that share one equation number: one display, one ``\tag`` for all of them."""
        if len(lines) == 1:
            return self.math(rf"{lines[0]} \tag{{{tag}}}")
        body = " \\\\\n".join(rf"\fiteq{{{ln}}}" for ln in lines)
        self.parts.append(rf"\begin{{equation*}}\begin{{gathered}}{body}\end{{gathered}}\tag{{{tag}}}\end{{equation*}}"
                          + "\n")
        return self

    def table(self, caption: str, columns: str, header: list[str], rows: list[list[str]],
              label: str | None = None) -> "Document":
        """A numbered table with its caption above (LaTeX source text: the caller escapes user text)."""
        body = [rf"\begin{{tabular}}{{{columns}}}", r"\hline", " & ".join(header) + r" \\ \hline"]
        body += [" & ".join(r) + r" \\" for r in rows]
        body += [r"\hline", r"\end{tabular}"]
        return self.float_table(caption, "\n".join(body), label)

    def float_table(self, caption: str, tabular: str, label: str | None = None) -> "Document":
        lab = rf"\label{{{label}}}" if label else ""
        self.parts.append(rf"\begin{{table}}[H]\centering\caption{{{caption}}}{lab}" + "\n" + tabular
                          + "\n" + r"\end{table}" + "\n")
        return self

    def figure(self, path: str, caption: str) -> "Document":
        """A numbered figure at the text width with its caption below."""
        self.parts.append(rf"\begin{{figure}}[H]\centering\includegraphics[width=\linewidth]{{{path}}}"
                          rf"\caption{{{caption}}}\end{{figure}}" + "\n")
        return self

    def latex(self) -> str:
        """The document, its first line the generated mark with the hash of the rest."""
        return marked("\n".join(self.parts + [r"\end{document}", ""]))


# ---------------------------------------------------------------------------------------------
# the document of a derivation: the registered sections (thinlayer.export.sections) in their order
# ---------------------------------------------------------------------------------------------
def derivation_document(der: Any, figure_dir: str | Path | None = None, force: bool = False) -> str:
    """The LaTeX report of a validated derivation (:func:`thinlayer.export.derivation.report_latex`).

    Every section of :data:`thinlayer.export.sections.SECTIONS` (in its ``ORDER``) whose ``applies(der)`` holds
    renders itself into the document; a section's figures go to ``figure_dir`` (replaced only with ``force``).
    """
    from .sections import SECTIONS, RenderContext

    doc = Document(der.title)
    context = RenderContext(None if figure_dir is None else Path(figure_dir), force)
    for section in tuple(SECTIONS):
        if section.applies(der):
            section.render(doc, der, context)
    return doc.latex()
