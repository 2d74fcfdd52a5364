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

import sympy as sp

from .. import symbols as S
from ..display import latex_escape
from ..parse import as_expr
from ._errata_section import prose  # noqa: F401 (re-exported: thinlayer.export.report.prose)
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


def errata_section(doc: Document, der: Any) -> Document:
    """The errata that concern the report so far (:mod:`thinlayer.export._errata_section`)."""
    from .. import errata
    from ._errata_section import errata_section as section
    from ._errata_section import report_errata

    return section(doc, report_errata(der, "\n".join(doc.parts)), len(errata.ENTRIES))


def alexandrov_generic_latex() -> str:
    """(3.19)-(3.25) with A, B, C, m_1 as symbols (the nu-dependent closed forms are unreadably long)."""
    from ..asymptotics.boundary_layer import AlexandrovParameters, AlexandrovSolution

    A = sp.Symbol(r"\mathcal{A}", positive=True)
    B, C = sp.symbols("B C", positive=True)
    m1 = sp.Symbol("m_1", real=True)
    par = AlexandrovParameters(A=A, m1=m1, B=B, C=C)
    rows = [rf"\tilde{{\mathcal{{L}}}}(s) = {sp.latex(S.s * par.symbol())} \tag{{3.19}}",
            r"B = \frac{1}{\mathcal{A} + \sqrt{\mathcal{A}^2 + 2 m_1}}, \quad "
            r"C = \frac{B}{\mathcal{A}} \tag{3.20--3.21}",
            AlexandrovSolution(par, 1 / sp.sqrt(C) - 1 / (2 * B)).latex()]
    return SEPARATOR.join(rows)


# ---------------------------------------------------------------------------------------------
# the document of a derivation, in the paper's order
# ---------------------------------------------------------------------------------------------
#: the source paper, cited by its title
PAPER = "The pressure of a punch in the form of an elliptic paraboloid on a thin elastic layer"


def _nl(expr: Any) -> str:
    from ._normal import normal_latex

    return normal_latex(expr)


def _num(x: Any, digits: int = 6) -> str:
    from ._normal import float_latex

    return float_latex(x, digits)


def _nu_latex(layer: Any) -> str:
    """The Poisson ratio of a layer: symbolic, an exact fraction, or a decimal (never 49/100 for 0.49)."""
    nu = layer.numeric_nu
    if layer.parameter is not None or nu is None:
        return r"\nu"
    exact = getattr(layer, "nu", None)
    if isinstance(exact, sp.Rational):  # inline: 1/2, not a \frac
        return str(exact.p) if exact.q == 1 else f"{exact.p}/{exact.q}"
    return _num(nu, 6)


def _unit(units: dict | None, kind: str, power: int = 1) -> str:
    r"""``\,\mathrm{mm}^{2}``: the unit of [units] for ``kind`` (length, stress, force) to ``power``, or nothing."""
    if not units or kind not in units:
        return ""
    from .units import unit_power

    return rf"\,{unit_power(units[kind], power)}"


def _lines(*rows: str) -> str:
    return SEPARATOR.join(r for r in rows if r)


def _signed_sum(parts: list[tuple[Any, str]]) -> str:
    """``c_1 X_1 + c_2 X_2 ...`` with each coefficient normalised, zero terms dropped, one sign per term."""
    out = ""
    for coef, suffix in parts:
        coef = as_expr(coef)
        if coef == 0:
            continue
        body = _nl(coef)
        neg = body.startswith("- ")
        body = body[2:] if neg else body
        body = "" if body == "1" and suffix else body
        text = (body + " " + suffix).strip()
        out += (("- " if neg else "") + text) if not out else ((" - " if neg else " + ") + text)
    return out or "0"


def derivation_document(der: Any, figure_dir: str | Path | None = None, force: bool = False) -> str:
    """The LaTeX report of a validated derivation (:func:`thinlayer.export.derivation.report_latex`)."""
    doc = Document(der.title)
    layer = der.layer
    doc.text(
        rf"This report carries out, with \texttt{{thinlayer}}, the asymptotic analysis of \emph{{{PAPER}}}"
        r"~\cite{argatov} for the punch and the layer of the derivation file below. Equation numbers in parentheses "
        r"are those of that paper; (I.$n$), (F.$n$), (SO.$n$) number the extensions of \texttt{thinlayer} (the "
        r"incompressible layer, the flat punch, the second order). Every formula is derived here, not copied: "
        r"where a printed source differs, the section Errata says so.")
    _kernel_part(doc, der)
    if der.punch is None:  # the flat-ended cylinder: its own section below
        pass
    elif layer.base == "bonded" and not layer.has_compressible_expansion:
        _incompressible_part(doc, der)
    else:
        _inner_part(doc, der)
        _boundary_part(doc, der)
        _two_term_part(doc, der)
    if der.edge_shift_nus:
        _edge_shift_part(doc, der.edge_shift_nus)
    if getattr(der, "second_order", None) is not None:
        from ._second_order_section import second_order_part

        second_order_part(doc, der)
    if der.contact is not None:
        _contact_part(doc, der)
    if der.validation is not None:
        _validation_part(doc, der.validation, figure_dir, force)
    if getattr(der, "flat_punch", None) is not None:
        from ._flat_section import flat_punch_part

        flat_punch_part(doc, layer, der.flat_punch)
    errata_section(doc, der)
    from ._references_section import references_section

    references_section(doc)
    return doc.latex()


def _kernel_part(doc: Document, der: Any) -> None:
    from ..layers.coefficients import kernel_coefficients
    from ..layers.moments import kernel_moment

    layer = der.layer
    nu = _nu_latex(layer)
    base = "bonded to" if layer.base == "bonded" else "lying without friction on"
    ratio = "" if nu == r"\nu" else rf", with Poisson ratio $\nu = {nu}$"
    doc.section("Layer kernel").text(rf"The layer of thickness $H$ is {base} a rigid base{ratio}. Its kernel, (2.3):")
    doc.math(rf"\mathcal{{L}}(u) = {_nl(layer.L())} \tag{{2.3}}")
    if layer.base == "bonded" and not layer.has_compressible_expansion:
        return
    order = der.coefficient_order
    co = kernel_coefficients(layer, order)
    doc.section("Coefficients of the kernel").text(
        r"The Maclaurin series $\mathcal{L}(s)/s = \mathcal{A}(1 + m_1 s^2 + m_2 s^4 + \dots)$, (2.4) and (2.20), "
        r"and its reciprocal $s/\mathcal{L}(s) = \mathcal{A}^{-1}(1 + M_1 s^2 + M_2 s^4 + \dots)$, (4.2), computed "
        r"by series arithmetic on (2.3):")
    doc.math(rf"\mathcal{{A}} = {_nl(co.A_expr)} \tag{{2.4}}")
    doc.group([rf"m_{{{n}}} = {_nl(co.m_expr(n))}" for n in range(1, order + 1)], "2.20")
    doc.group([rf"M_{{{n}}} = {_nl(co.M_expr(n))}" for n in range(1, order + 1)], "4.2")
    if not layer.symbolic_coefficients and layer.parameter is None:
        rows = [[f"${n}$", f"${_num(co.m[n])}$", f"${_num(co.M[n])}$"] for n in range(1, order + 1)]
        doc.table("Coefficients $m_n$ of (2.20) and $M_n$ of (4.2) as decimals.", "rrr",
                  ["$n$", "$m_n$", "$M_n$"], rows)
    doc.section("Kernel moments and the moment expansion").text(
        r"The even moments $\mu_{2k,2n-2k}$ of the kernel, (2.19) evaluated by (2.21) in its corrected form "
        r"(see Errata); moments of equal value are written once:")
    rows = []
    for n in range(min(3, order) + 1):
        seen: dict = {}
        for k in range(n + 1):
            val = sp.factor(kernel_moment(layer, 2 * k, 2 * n - 2 * k))
            seen.setdefault(val, []).append(rf"\mu_{{{2 * k},{2 * n - 2 * k}}}")
        rows += [" = ".join(names) + f" = {_nl(val)}" for val, names in seen.items()]
    doc.group(rows, "2.21")
    from ..asymptotics.moment_expansion import moment_expansion

    me = moment_expansion(layer, min(2, order))
    ops = [r"\Lambda^{-2}\delta(\boldsymbol{\xi})", r"\Lambda^{-4}\Delta\delta(\boldsymbol{\xi})",
           r"\Lambda^{-6}\Delta^{2}\delta(\boldsymbol{\xi})"]
    doc.text(r"and the moment asymptotic expansion of the kernel, (2.22):")
    doc.math(r"k(\Lambda\boldsymbol{\xi}) \sim " + _signed_sum(list(zip(me.weights(), ops))) + r" + \dots \tag{2.22}")


def _inner_part(doc: Document, der: Any) -> None:
    from ..asymptotics.inner import inner_pressure

    layer, punch = der.layer, der.punch
    ip = inner_pressure(layer, punch, der.inner_order)
    doc.section("Punch and inner expansion").text(r"The punch, (1.1):")
    doc.math(rf"\Phi(x_1, x_2) = {_nl(punch.expr)} \tag{{1.1}}")
    doc.text(r"Inserting the moment expansion (2.22) into the integral equation (2.10) gives the inner terms "
             r"$p_k^*$ in the scaled variables (1.2), (2.8): $p_0^*$ by (2.27), the others by the closed form (4.1) "
             r"(equal to the recursion (2.28)):")
    doc.math(rf"p_0^*(\boldsymbol{{\xi}}) = {_nl(ip.scaled_terms[0])} \tag{{2.27}}")
    rest = [rf"p_{{{k}}}^*(\boldsymbol{{\xi}}) = {_nl(t)}" for k, t in enumerate(ip.scaled_terms) if k]
    if rest:
        doc.group(rest, "4.1")
    doc.text(r"In the dimensional variables the inner pressure, (2.26), is")
    doc.math(rf"p(x_1, x_2) \sim {_nl(ip.pressure)} \tag{{2.26}}")
    if punch.name == "elliptic paraboloid":
        from ..asymptotics.contour import ellipse_contour

        e = ellipse_contour()
        doc.text(r"Its leading contact area is bounded by the ellipse $\Phi = \delta_0$, (3.1), with semi-axes")
        doc.math(rf"a = {_nl(e.a)},\quad b = {_nl(e.b)},\quad e^2 = {_nl(1 - e.b**2 / e.a**2)} \tag{{3.1}}")


def _boundary_part(doc: Document, der: Any) -> None:
    from ..asymptotics.boundary_layer import AlexandrovParameters, AlexandrovSolution
    from ..asymptotics.force_law import boundary_layer_force_defect, force_law

    layer, punch = der.layer, der.punch
    law = force_law(layer, punch)
    A = sp.Symbol(r"\mathcal{A}", positive=True)
    B, C = sp.symbols("B C", positive=True)
    m1 = sp.Symbol("m_1", real=True)
    tau, v, h = sp.Symbol(r"\tau", positive=True), sp.Symbol("v", real=True), sp.Symbol("h", real=True)
    doc.section("Boundary layer").text(
        r"Near the edge of the contact area the inner expansion fails; the boundary layer (3.15)--(3.18) is "
        r"solved with Alexandrov's approximation of the kernel~\cite{alexandrov}, (3.19), whose constants $B$ and $C$ "
        r"match $\mathcal{A}$ and $m_1$, (3.20) and (3.21) (the latter corrected, see Errata):")
    sol = AlexandrovSolution(AlexandrovParameters(A=A, m1=m1, B=B, C=C), 1 / sp.sqrt(C) - 1 / (2 * B))
    doc.math(rf"\tilde{{\mathcal{{L}}}}(s) = {_nl(sp.S.One * sp.Symbol('s') * sp.sqrt(B**2 + sp.Symbol('s')**2) / (C + sp.Symbol('s')**2))} \tag{{3.19}}")  # noqa: E501 (one formula)
    doc.math(r"B = \frac{1}{\mathcal{A} + \sqrt{\mathcal{A}^2 + 2 m_1}},\quad C = \frac{B}{\mathcal{A}}"
             r" \tag{3.20--3.21}")
    lhs = r"\frac{\mathcal{A}\,\tilde q^{**}}{\vartheta H_* b_1^*}"
    doc.text(r"The boundary-layer pressure for an edge at $v = h$, (3.23); the edge condition (3.18), "
             r"$\tilde q^{**} = 0$ at the edge, fixes $h = h^*$ of (3.25) below and gives its form in the edge "
             r"variable $v$, (3.24):")
    doc.math(rf"{lhs}(s, h + \tau) = {_nl(sol.q_general(tau, h))} \tag{{3.23}}")
    h_star = sp.Symbol("h^*", real=True)
    doc.math(rf"{lhs}(s, v) = {_nl(AlexandrovSolution(sol.params, h_star).q(v))} \tag{{3.24}}")
    doc.text(r"so that the contact edge lies the distance $h^* H$ inside the leading contour $\Gamma_0$, (3.25):")
    doc.math(rf"h^* = {_nl(1 / sp.sqrt(C) - 1 / (2 * B))} \tag{{3.25}}")
    force_words = ("the first correction is of relative order $(H/a)^3$, since $m_1 = 0$"
                   if layer.base == "frictionless" else "with the correction of relative order $(H/a)^2$")
    doc.section("Force and contact area").text(
        rf"The force is the integral of the inner terms $p_0 + p_1$ plus the force defect of the boundary layer, "
        rf"{force_words}; $a$ is the contact half-width. The defect of the boundary layer,")
    defect = _nl(boundary_layer_force_defect())
    doc.math(rf"\int_{{-\infty}}^{{\infty}}\left(\hat Q(v) - \max(v, 0)\right) dv = {defect}")
    doc.text(r"gives the force law (1.8) for any punch,")
    rem_P = r" + O\!\left(P_0 \frac{H^3}{a^3}\right)"
    rem_A = r" + O\!\left(|\omega_0| \frac{H^2}{a^2}\right)"
    th = layer.vartheta
    general = _signed_sum([(th / (layer.A * S.H), r"\iint_{\omega_0}(\delta_0 - \Phi)\,d\mathbf{x}"),
                           (law.coefficient, r"\oint_{\Gamma_0}|\nabla\Phi|\,ds")])
    doc.math(rf"P = {general}{rem_P} \tag{{1.8}}")
    if law.P0 is not None:
        rel = sp.factor(sp.cancel(law.P1 / law.P0))
        corr = rf"\left({_signed_sum([(sp.S.One, ''), (rel, '')])}\right)" if rel != 0 else ""
        doc.text(r"and, for this punch, in closed form, with the contact area (3.25) ($h^*$ the edge shift):")
        doc.math(rf"P = {_nl(law.P0)}{corr}{rem_P} \tag{{1.8}}")
        area = _signed_sum([(law.area0, ""), (-S.H * law.perimeter, "h^*")])
        doc.math(rf"|\omega| = {area}{rem_A} \tag{{3.25}}")
    else:
        doc.math(r"|\omega| = |\omega_0| - h^* H |\Gamma_0|" + rem_A + r" \tag{3.25}")
    if layer.base == "frictionless":
        from ..asymptotics.wiener_hopf import edge_shift_alexandrov, edge_shift_exact

        doc.table(r"Edge shift of the frictionless base: exact (Wiener--Hopf) and Alexandrov's "
                  r"(3.25)~\cite{alexandrov}.", "rr",
                  [r"$h^*$ exact", r"$h^*$ (3.25)"],
                  [[f"${_num(edge_shift_exact(layer), 8)}$", f"${_num(edge_shift_alexandrov(layer), 8)}$"]])


def _two_term_part(doc: Document, der: Any) -> None:
    from ..asymptotics.incompressible import two_term_sphere

    layer = der.layer
    nu = layer.numeric_nu
    if not (der.punch.name.startswith("paraboloid") and layer.base == "bonded" and layer.has_compressible_expansion
            and (nu is None or 0.25 < nu < 0.5)):
        return
    doc.section("Nearly incompressible layer: the two-term model").text(
        r"Near $\nu = 1/2$ the compressible expansion needs $\lambda^2 = (a/H)^2/m_1 \gg 1$ (I.13); the two-term "
        r"model (I.10), $-\Delta p + k^2 p = f$ with $f = \vartheta (\delta_0 - \Phi)/(c_1 H^3)$ and "
        r"$k^2 = 1/(m_1 H^2)$, holds in both regimes. For the sphere, in terms of the contact radius $c$:")
    _tagged(doc, _sphere_rows(two_term_sphere(layer)))


def _tagged(doc: Document, rows: list[tuple[str, str]]) -> None:
    """Display ``(line, tag)`` rows, consecutive rows with the same tag as one group under one tag."""
    k = 0
    while k < len(rows):
        j = k
        while j < len(rows) and rows[j][1] == rows[k][1]:
            j += 1
        doc.group([r for r, _ in rows[k:j]], rows[k][1])
        k = j


def _sphere_rows(ts: Any) -> list[tuple[str, str]]:
    """(I.10), (I.11) of a :class:`TwoTermSphere`, each formula by the report's policy."""
    rows = [] if ts.is_incompressible else [(rf"k^2 = {_nl(ts.k2)}", "I.10")]
    rows += [(rf"\delta_0 = {_nl(ts.delta0_of_c)}", "I.11"), (rf"P = {_nl(ts.force_of_c)}", "I.11")]
    if not ts.is_incompressible:
        rows.append((r"\delta_0 = \frac{c^2 (1 - 2\psi(kc))}{2R},\quad P = 2\pi f_2 c^6 \chi(kc),\quad "
                     r"\psi(x) = \frac{x I_0(x)/I_1(x) - 2}{x^2},\quad \chi(x) = \frac{1/4 - \psi(x)}{x^2}", "I.11"))
    return rows


def _zero(expr: Any) -> str:
    """``expr = 0`` with the sign of its first term positive (the sign of an equation's side is free)."""
    text = _nl(sp.factor(expr))
    return (text[2:] if text.startswith("- ") else text) + " = 0"


def _incompressible_part(doc: Document, der: Any) -> None:
    from ..asymptotics.incompressible import (
        incompressible_axisymmetric,
        incompressible_ellipse,
        obstacle_problem,
        thin_layer_operator,
        two_term_edge_shift,
        two_term_sphere,
    )
    from ..layers.coefficients import incompressible_coefficients

    layer, punch = der.layer, der.punch
    doc.section("Incompressible layer: Maclaurin data and thin-layer operator").text(
        r"At $\nu = 1/2$ the coefficient $\mathcal{A}$ of (2.4) vanishes: the compressible expansion "
        r"(2.20)--(3.25) does not exist, and the leading operator is of second order, (I.1) and (I.2):")
    co = incompressible_coefficients(der.coefficient_order)
    series = _signed_sum([(cn, rf"s^{{{2 * n}}}") for n, cn in enumerate(co.c) if n])
    doc.math(rf"\frac{{\mathcal{{L}}(s)}}{{s}} = {series} + \dots,\quad \mathcal{{A}} = c_0 = 0 \tag{{I.1}}")
    op = thin_layer_operator(layer)
    ops = [r"p", r"\Delta p"] + [rf"\Delta^{{{n}}} p" for n in range(2, len(op.c))]
    terms = _signed_sum([((-1) ** n * cn * S.H ** (2 * n + 1) / op.vartheta, ops[n]) for n, cn in enumerate(op.c)])
    doc.math(rf"u_3 = {terms} + \dots \tag{{I.2}}")
    doc.section("Punch and the obstacle problem").text(r"The punch, (1.1), and the obstacle problem (I.3)--(I.5):")
    doc.math(rf"\Phi(x_1, x_2) = {_nl(punch.expr)} \tag{{1.1}}")
    ob = obstacle_problem(layer, punch)
    lhs = r"-\Delta p" if ob.is_incompressible else rf"-\Delta p + {_nl(ob.k2)}\, p"
    rows = [(rf"{lhs} = {_nl(ob.source)},\quad \mathbf{{x}} \in \omega", ob.equation),
            (r"p = \frac{\partial p}{\partial n} = 0 \ \text{on}\ \partial\omega,\quad p > 0 \ \text{in}\ \omega",
             "I.4")]
    if ob.is_incompressible:
        rows.append((rf"\iint_\omega \left({_nl(S.delta0 - punch.expr)}\right) d\mathbf{{x}} = 0", "I.5"))
    _tagged(doc, rows)
    kind = punch.name
    if kind.startswith("paraboloid"):
        doc.section("Solution for the sphere (I.11)").text(r"In terms of the contact radius $c$:")
        _tagged(doc, _sphere_rows(two_term_sphere(layer)))
    elif kind == "elliptic paraboloid":
        el = incompressible_ellipse()
        doc.section("Solution for the elliptic paraboloid (I.6)--(I.8)").text(
            r"The contact area is an ellipse with semi-axes $a \ge b$; its aspect $t = a^2/b^2$ solves (I.6) with "
            r"$r = R_1/R_2$, and the semi-axes, the constant $C$ of the pressure and the force follow, (I.7), (I.8):")
        _tagged(doc, [(_zero(el.aspect_equation), "I.6"), (rf"t = {_nl(el.t)}", "I.6"),
                      (rf"a^2 = {_nl(el.a2_t)},\quad b^2 = {_nl(el.b2_t)}", "I.7"), (rf"C = {_nl(el.C_t)}", "I.7"),
                      (rf"P = {_nl(el.force_t)}", "I.8")])
    elif _axisymmetric_punch(punch):
        ax = incompressible_axisymmetric(punch)
        doc.section("Solution for an axisymmetric punch (I.9)").text(
            r"The contact radius $c$ solves the first equation; the pressure and the force in terms of $c$:")
        _tagged(doc, [(_zero(ax.radius_equation), "I.9"), (rf"p(r) = {_nl(ax.pressure_of_c)}", "I.9"),
                      (rf"P = {_nl(ax.force_of_c)}", "I.9")])
    h = float(two_term_edge_shift(layer, dps=15))
    doc.section("Edge correction (I.12)").text(
        rf"The model's edge lies $h H$ outside the true contact edge, $h = {_num(h, 8)}$ at $\nu = 1/2$ "
        r"(the edge layer of width $H$ that the model neglects); \texttt{thinlayer.solve} reports the corrected "
        r"radius $c - hH$ and estimates the model's force error by $2hH/c$.")

def _axisymmetric_punch(punch: Any) -> bool:
    e = punch.expr
    return sp.expand(S.x1 * sp.diff(e, S.x2) - S.x2 * sp.diff(e, S.x1)) == 0


def _edge_shift_part(doc: Document, nus: tuple) -> None:
    from ..asymptotics.boundary_layer import alexandrov_parameters
    from ..asymptotics.wiener_hopf import edge_shift_alexandrov, edge_shift_exact
    from ..layers.kernels import BondedLayer

    rows = []
    for v in nus:
        B, C = alexandrov_parameters(BondedLayer(v)).numeric()
        rows.append([f"${_num(v)}$", f"${_num(B)}$", f"${_num(C)}$", f"${_num(edge_shift_exact(v))}$",
                     f"${_num(edge_shift_alexandrov(v))}$"])
    doc.section("Edge shift of the contact area").text(
        r"The contour of the contact area lies the distance $h^* H$ inside $\Gamma_0$ (Table~\ref{tab:edge}).")
    doc.table(r"Alexandrov's constants $B$, $C$, (3.20)--(3.21), and the edge shift $h^*$: exact "
              r"(Wiener--Hopf) and Alexandrov's approximation (3.25)~\cite{alexandrov}.", "rrrrr",
              [r"$\nu$", "$B$", "$C$", r"$h^*$ exact", r"$h^*$ (3.25)"], rows, label="tab:edge")


def parameter_length_powers(expr: Any, names: list[str]) -> dict[str, int | None]:
    r"""The power of length of each punch parameter, from :math:`\Phi` being a length in lengths :math:`x_1, x_2`.

    Each term of the expanded punch, a number times powers of :math:`x_1, x_2` and of the parameters,
    gives one linear equation for the parameters' powers :math:`d_k` (:math:`i + j + \sum_k e_k d_k = 1`);
    terms without a parameter fix nothing (a number's unit is the user's).  A power the terms do not fix
    as one integer is None (the report then prints no unit for it).

    >>> import sympy as sp; from thinlayer import symbols as S
    >>> R, K = sp.symbols("R K", positive=True)
    >>> parameter_length_powers((S.x1**2 + S.x2**2) / (2 * R) + S.x1**4 / K**3, ["R", "K"])
    {'R': 1, 'K': 1}
    """
    unknown = {n: sp.Symbol(f"d_{k}") for k, n in enumerate(names)}
    rows = []
    for term in sp.Add.make_args(sp.expand(expr)):
        if not any(getattr(s, "name", None) in unknown for s in term.free_symbols):
            continue  # a number's unit is the user's: it fixes no parameter
        eq = -sp.S.One
        for base, e in term.as_powers_dict().items():
            if base.is_number:
                continue
            if not (base.is_Symbol and e.is_Rational):
                return dict.fromkeys(names)
            eq += e * (1 if base in (S.x1, S.x2) else unknown.get(base.name, sp.nan))
        if eq.has(sp.nan):
            return dict.fromkeys(names)
        rows.append(eq)
    sol = sp.linsolve(rows, list(unknown.values())) if rows else sp.S.EmptySet
    if not isinstance(sol, sp.FiniteSet) or len(sol) != 1:
        return dict.fromkeys(names)
    values = next(iter(sol))
    return {n: int(v) if v.is_Integer else None for n, v in zip(names, values)}


def _contact_part(doc: Document, der: Any) -> None:
    from ..contact.solve import solve

    c, u = der.contact, der.units
    ans = solve(c.get("layer", der.layer), der.punch, delta0=c.get("delta0"), force=c.get("force"), H=c["H"],
                mu=c.get("mu"), E=c.get("E"), parameters=c["parameters"], nu=c.get("nu"),
                model=c.get("model", "auto"), tol=c.get("tol", 0.05))
    L, F, Sg = (lambda p=1: _unit(u, "length", p)), _unit(u, "force"), _unit(u, "stress")
    doc.section("Contact solution for numeric parameters").text(
        rf"Model: {escape(ans.model)}. \texttt{{thinlayer.solve}} chooses the first model whose error estimates "
        rf"are within the tolerance ${_num(100 * ans.tol)}\,\%$; otherwise the direct numerical solver. "
        r"Table~\ref{tab:contact} lists the data and the results; the estimates are relative"
        + ("." if u else r" (no \texttt{[units]} in the derivation file: numbers in any consistent units)."))
    powers = parameter_length_powers(der.punch.expr, list(c["parameters"]))
    pars = [rf"\fitcell{{0.7\linewidth}}{{${sp.latex(sp.Symbol(k))} = {_num(v)}{L(powers[k]) if powers[k] else ''}$}}"
            for k, v in c["parameters"].items()]
    modulus = (rf"$E = {_num(c['E'])}{Sg}$" if "E" in c else rf"$\mu = {_num(ans.mu)}{Sg}$")
    rows = [[r"indentation $\delta_0$", f"${_num(ans.delta0)}{L()}$"], [r"thickness $H$", f"${_num(ans.H)}{L()}$"],
            ["modulus", modulus], [r"Poisson ratio $\nu$", f"${_num(ans.nu)}$"]]
    rows += [["punch" if k == 0 else "", p] for k, p in enumerate(pars)]
    est = ans.error_estimate
    rows += [[r"force $P$", rf"${_num(ans.force)}{F} \pm {_num(100 * est['force'], 2)}\,\%$"],
             [r"contact area $|\omega|$", rf"${_num(ans.contact_area)}{L(2)} \pm "
                                          rf"{_num(100 * est['contact_area'], 2)}\,\%$"]]
    if ans.contact_radius is not None:
        rows.append([r"contact radius $c$", f"${_num(ans.contact_radius)}{L()}$"])
    rows.append([r"$H/a$", f"${_num(ans.H_over_a, 4)}$"])
    doc.table(rf"Contact solution (model {escape(ans.model)}) for the parameters of the derivation file.", "ll",
              ["quantity", "value"], rows, label="tab:contact")
    if ans.model == "compressible":
        v = ans.detail.values
        doc.text(r"The force (1.8) and the contact area (3.25) as leading term and first correction:")
        corr = "" if v.P1 == 0 else f" {'-' if v.P1 < 0 else '+'} {_num(abs(v.P1))}"
        doc.math(rf"P = {_num(v.P0)}{corr} = {_num(v.force)}{F} \tag{{1.8}}")
        sign = "-" if v.edge_shift >= 0 else "+"
        doc.math(rf"|\omega| = {_num(v.area0)} {sign} {_num(abs(v.edge_shift))} \cdot {_num(ans.H)} \cdot "
                 rf"{_num(v.perimeter)} = {_num(v.area)}{L(2)} \tag{{3.25}}")


def _validation_part(doc: Document, v: dict, figure_dir: str | Path | None, force: bool = False) -> None:
    from ..validation import validation_study

    study = validation_study(v["nu"], v["H_over_a"], v["shapes"], progress=False)
    doc.section("Validation against the direct numerical solution").text(
        r"The asymptotic results (\texttt{thinlayer.solve}) against the direct numerical solution of the full "
        r"contact problem (1.5)--(1.8) (\texttt{thinlayer.numerics}): relative errors, their observed orders in "
        r"$H/a$, and the edge shift measured from the numerical contact radius (Table~\ref{tab:validation}).")
    doc.float_table(r"Validation: errors of the asymptotics against the direct numerics; observed orders "
                    r"against the claimed ones; the edge shift extrapolated to $H/a = 0$. The study is "
                    r"dimensionless, independent of the units of the contact solution: $\mu = 1$, the sphere "
                    r"$R = 1$, the elliptic paraboloid $R_1 = 4$, $R_2 = R = 1$, $\delta_0 = R/2$; "
                    r"$\bar P_{\rm num} = P_{\rm num}/(\mu R^2)$ is the numerical force in units of $\mu R^2$, the "
                    r"errors are relative.",
                    "{\\footnotesize\\setlength{\\tabcolsep}{3pt}\n"
                    + study.latex().replace("contact\\_area", "contact area")
                    .replace("force\\_leading", "force, leading").replace("contact area\\_leading",
                                                                          "contact area, leading")
                    .replace("force\\_second", "force, 2nd order")
                    .replace("contact area\\_second", "contact area, 2nd order") + "\n}",
                    label="tab:validation")
    if figure_dir is None:
        return
    figs, why = _figures(study, Path(figure_dir), force)
    if not figs:
        doc.text(rf"(Figures omitted: {why}.)")
    captions = {
        "validation_errors": r"Relative errors of the asymptotic force, contact area and pressure against the "
                             r"direct numerical solution, log--log in $H/a$; dashed: the claimed slope.",
        "validation_pressure": r"Contact pressure along a principal axis: direct numerical solution (solid) and "
                               r"composite asymptotic expansion (dashed); right: near the edge.",
        "validation_contours": r"Contact contour: numerical, and the leading contour $\Gamma_0$ moved in by "
                               r"$h^* H$ with the exact and Alexandrov's $h^*$.",
        "validation_edge_shift": r"Sphere: edge shift $(a_0 - c)/H$ from the numerics against $H/a$, with the "
                                 r"exact and Alexandrov's $h^*$ and the extrapolation to $H/a = 0$.",
    }
    for fig in figs:
        doc.figure(f"{Path(figure_dir).name}/{fig}", captions.get(Path(fig).stem, ""))


def _figures(study: Any, folder: Path, force: bool = False) -> tuple[list[str], str]:
    """The study's plots as PDF files in ``folder``, or ``([], why)`` when matplotlib is missing."""
    try:
        paths = study.plots(folder, formats=("pdf",), force=force)
    except ImportError:
        import logging

        # the install hint goes to the console (the log), never onto the page
        logging.getLogger(__name__).warning("validation figures omitted from the report: matplotlib is not "
                                            "installed; pip install 'thinlayer[plot]'")
        return [], "matplotlib is not installed"
    return [p.name for p in paths if p.suffix == ".pdf"], ""
