r"""Rich display of result objects: LaTeX in Jupyter, readable text in a terminal.

Every result object of thinlayer inherits :class:`RichDisplay`, which adds two methods and
nothing else:

* ``_repr_latex_()`` -- Jupyter (and nbconvert) render the object's own ``latex()`` as one
  display block, each line tagged with the paper's equation number;
* ``__str__()`` -- ``print(result)`` gives a few lines of text: what the object is, the
  equations it reproduces and its main values (formulas in the normal form of :mod:`thinlayer.normal`
  as Unicode maths, ``(1 - 2ν)/(2(1 - ν)²)``; numbers to 12 digits).  On a stream that cannot take
  Unicode (``sys.stdout.encoding``) the text falls back to ASCII (:func:`thinlayer.normal.to_ascii`).
  ``repr()`` is left alone: it stays the dataclass representation (or the first line of the text).

Each class writes its own text in a ``text_lines()`` method and its own LaTeX in ``latex()``
(the :class:`~thinlayer.results.Result` protocol); a class may override ``_display_tex()`` when
Jupyter should show something other than ``latex()`` (a table as an ``array``).

Examples
--------
The coefficients (2.20), (4.2) of a layer with an exact Poisson ratio:

>>> from thinlayer import BondedLayer, Punch, kernel_coefficients, inner_pressure
>>> print(kernel_coefficients(BondedLayer("3/10"), 2))
KernelCoefficients of BondedLayer(nu=3/10), n <= 2   (2.4), (2.20), (4.2)
  𝒜  = 20/49
  m₁ = 1/14
  m₂ = -53/490
  M₁ = -1/14
  M₂ = 111/980

What Jupyter receives for a punch (1.1), and the inner expansion (2.26) as text:

>>> print(Punch.paraboloid(R=1)._repr_latex_())
$$\begin{gather*}\Phi(x_1, x_2) = \frac{x_{1}^{2}}{2} + \frac{x_{2}^{2}}{2} \tag{1.1}\end{gather*}$$
>>> ip = inner_pressure(BondedLayer("3/10"), Punch.paraboloid(R=1))
>>> print(ip)
InnerPressure: paraboloid of revolution on BondedLayer(nu=3/10), 2 terms (closed form (4.1))   (2.26)
  Φ   = x₁²/2 + x₂²/2
  p₀  = 7μ (2δ₀ - x₁² - x₂²)/(4H)
  p₁  = -H μ/2
  p₀* = -49ϑ (H*² Λ ξ₁² + H*² Λ ξ₂² - 2δ₀*)/(40H*)   (scaled, ξ = x/H*, 2.27)
  p₁* = -7H* Λ ϑ/20   (scaled, ξ = x/H*, 4.1)
  arguments of lambdify(): (x_1, x_2, delta_0, H, mu)
>>> print(BondedLayer(0.3), BondedLayer(), BondedLayer(parameter="kappa"))
BondedLayer(nu=0.3) BondedLayer(nu) BondedLayer(kappa)
"""
from __future__ import annotations

import sys
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import mpmath

from ._lazy import lazy_module, loaded_types
from .errors import InputError

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it

__all__ = ["RichDisplay", "Table", "display_math", "fmt", "latex_escape", "table"]

def display_math(tex: str) -> str:
    r"""The LaTeX of a result (lines joined by ``\\`` and a newline) as one display block for Jupyter.

    ``$$\begin{gather*} ... \end{gather*}$$``: one centred line per equation, each keeping its
    ``\tag`` (MathJax and KaTeX both accept ``\tag`` in ``gather*``, unlike in ``aligned``).

    >>> display_math(r"a = 1 \tag{2.4} \\" + "\n" + r"b = 2")
    '$$\\begin{gather*}a = 1 \\tag{2.4} \\\\ b = 2\\end{gather*}$$'
    """
    body = " \\\\ ".join(part.strip() for part in tex.split("\\\\\n"))
    return "$$\\begin{gather*}" + body + "\\end{gather*}$$"


def fmt(x: Any, digits: int = 12) -> str:
    """A number or a formula as short text: the normal form (:func:`thinlayer.normal.normal_text`, Unicode
    maths); mpmath and floats to ``digits`` digits.

    >>> fmt(sp.Rational(3, 10)), fmt(mpmath.mpf(2) / 3), fmt(0.1 + 0.2), fmt(sp.sqrt(2) / 2)
    ('3/10', '0.666666666667', '0.3', '√2/2')
    >>> nu = sp.Symbol("nu")
    >>> fmt((sp.Rational(1, 2) - nu) / (1 - nu) ** 2)
    '(1 - 2ν)/(2(1 - ν)²)'
    """
    if isinstance(x, (mpmath.mpf, mpmath.mpc)):
        return mpmath.nstr(x, digits)
    if isinstance(x, float):
        return f"{x:.{digits}g}"
    Float, Basic = loaded_types("sympy", "Float", "Basic") or ((), ())  # no sympy object without sympy
    if isinstance(x, Float):
        return mpmath.nstr(mpmath.mpf(x), digits)
    if isinstance(x, Basic):
        from .normal import normal_text

        return normal_text(x, digits=digits)
    return str(x)


def _unicode_ok(text: str) -> bool:
    """Whether ``sys.stdout`` can take ``text`` (an unknown encoding, as in a StringIO, is taken as Unicode)."""
    encoding = getattr(sys.stdout, "encoding", None)
    if not encoding:
        return True
    try:
        text.encode(encoding)
    except (UnicodeEncodeError, LookupError):
        return False
    return True


class RichDisplay:
    """Mixin: ``_repr_latex_`` from ``latex()`` for Jupyter, ``__str__`` as readable text.

    Adds no state (``__slots__ = ()``), so it sits among the bases of frozen dataclasses.

    Examples
    --------
    Alexandrov's boundary layer for nu = 0 (A = 1/2, m_1 = 0), (3.23)-(3.25), in the normal form of
    :mod:`thinlayer.normal` (Unicode maths):

    >>> from thinlayer import BondedLayer, Punch, alexandrov_solution, ellipse_contour, force_law
    >>> print(alexandrov_solution(BondedLayer(0)))
    AlexandrovSolution: Q(v) = v erf(√(B (v - h))) + √((v - h)/(π B)) exp(-B (v - h)), v > h   (3.23)-(3.25)
      B  = 1
      C  = 2
      h* = √2/2 - 1/2

    The contact ellipse (3.1) of R_1 = 4, R_2 = 1 at delta_0 = 1/2:

    >>> print(ellipse_contour(4, 1, sp.Rational(1, 2)))
    EllipseContour: x₁²/a² + x₂²/b² = 1   (3.1)
      a  = 2
      b  = 1
      e² = 3/4
      area |ω₀| = 2π, perimeter |Γ₀| = 8E(√3/2)   (E(k): complete elliptic integral of the second kind, modulus k = e)

    For nu = 1/4 the coefficient m_1 vanishes, and with it the first correction of the force (1.8):

    >>> print(force_law(BondedLayer("1/4"), Punch.paraboloid()))
    ForceLaw: paraboloid of revolution on BondedLayer(nu=1/4), quadratic   (1.8), (3.25)
      Φ  = (x₁² + x₂²)/(2R)
      P  = P₀ + P₁ + O(P₀ (H/a)³)
      P₀ = 3π R δ₀² μ/H
      P₁ = 0
      |ω| = 2π R δ₀ - h* H (2π √(2R δ₀)) + O(|ω| (H/a)²)

    A class without ``text_lines()`` prints its ``repr``; one without ``latex()`` has no LaTeX form:

    >>> class Plain(RichDisplay):
    ...     def __repr__(self):
    ...         return "Plain()"
    >>> str(Plain()), Plain()._repr_latex_()
    ('Plain()', None)
    """

    __slots__ = ()

    def __init_subclass__(cls, **kwargs: Any) -> None:
        """A class that formats itself (``text_lines``) and writes no ``__repr__`` gets the short one below.

        Set here, before ``@dataclass`` runs, so that the dataclass keeps it instead of listing every field
        (a 950-character repr in the REPL).
        """
        super().__init_subclass__(**kwargs)
        if "__repr__" not in cls.__dict__ and "text_lines" in cls.__dict__:
            cls.__repr__ = RichDisplay._short_repr

    def _short_repr(self) -> str:
        first = self.text_lines()[0] if self.text_lines() else type(self).__name__
        return first if len(first) <= 110 else first[:107] + "..."

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:
        """IPython's text form (the REPL of IPython, Jupyter's text/plain): the readable text, not the repr."""
        printer.text(type(self).__name__ + "(...)" if cycle else str(self))

    def _latex(self, printer: Any = None) -> str:
        """``sympy.latex(result)``: the result's own LaTeX (sympy's printer hook)."""
        tex = self._display_tex()
        if tex is not None:
            return tex
        from .normal import to_ascii

        return r"\text{" + latex_escape(to_ascii(str(self))) + "}"

    def _display_tex(self) -> str | None:
        """The LaTeX Jupyter shows: ``latex()`` when the class has one, else None (plain text)."""
        latex = getattr(self, "latex", None)
        return latex() if callable(latex) else None

    def _repr_latex_(self) -> str | None:
        """Jupyter's LaTeX representation: ``latex()`` as one display block (None: plain text)."""
        tex = self._display_tex()
        return None if tex is None else display_math(tex)

    def __str__(self) -> str:
        lines = getattr(self, "text_lines", None)
        if not callable(lines):
            return repr(self)
        text = "\n".join(lines())
        if _unicode_ok(text):
            return text
        from .normal import to_ascii

        return to_ascii(text)


@dataclass(frozen=True)
class Table:
    """A small table: Markdown in Jupyter (cells may hold ``$...$`` math), aligned text in a terminal.

    Made by :func:`table`; ``header`` and ``rows`` hold the cells as strings.
    """

    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]

    def _repr_markdown_(self) -> str:
        def cell(text: str) -> str:  # a "|" outside $...$ would end the cell (write \lvert, \rvert in math)
            parts = text.split("$")
            return "$".join(q if k % 2 else q.replace("|", "\\|") for k, q in enumerate(parts))

        lines = ["| " + " | ".join(map(cell, self.header)) + " |", "|" + "---:|" * len(self.header)]
        lines += ["| " + " | ".join(map(cell, r)) + " |" for r in self.rows]
        return "\n".join(lines)

    def __str__(self) -> str:
        cols = list(zip(self.header, *self.rows))
        widths = [max(len(c) for c in col) for col in cols]
        out = ["  ".join(h.rjust(w) for h, w in zip(self.header, widths))]
        out += ["  ".join(c.rjust(w) for c, w in zip(r, widths)) for r in self.rows]
        return "\n".join(out)


def table(header: Iterable[str], rows: Iterable[Iterable[Any]], digits: int = 12) -> Table:
    r"""A :class:`Table` with every cell formatted by :func:`fmt` (numbers to ``digits`` digits).

    >>> t = table(["nu", "A", "m_1"], [[sp.Rational(3, 10), sp.Rational(20, 49), sp.Rational(1, 14)],
    ...                               [0.25, 0.444444444444, 0.0]], digits=6)
    >>> print(t)
      nu         A   m_1
    3/10     20/49  1/14
    0.25  0.444444     0
    >>> print(t._repr_markdown_().splitlines()[1])
    |---:|---:|---:|
    >>> print(table(["a|b", "$\\lvert x \\rvert$"], [[1, 2]])._repr_markdown_().splitlines()[0])
    | a\|b | $\lvert x \rvert$ |
    """
    head = tuple(str(h) for h in header)
    body = tuple(tuple(fmt(c, digits) for c in r) for r in rows)
    for r in body:
        if len(r) != len(head):
            raise InputError(f"a row has {len(r)} cells but the header has {len(head)}: {r}")
    return Table(head, body)


def latex_escape(text: str) -> str:
    r"""Plain prose -> LaTeX text mode: every special character escaped.

    >>> print(latex_escape("50% & x_1 \\input{f}"))
    50\% \& x\_1 \textbackslash{}input\{f\}
    """
    rep = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_",
           "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}",
           "<": r"\textless{}", ">": r"\textgreater{}", "|": r"\textbar{}"}
    return "".join(rep.get(ch, ch) for ch in text)
