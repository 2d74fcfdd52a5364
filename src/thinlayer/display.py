r"""Rich display of result objects: LaTeX in Jupyter, readable text in a terminal.

Every result object of thinlayer inherits :class:`RichDisplay`, which adds two methods and
nothing else:

* ``_repr_latex_()`` -- Jupyter (and nbconvert) render the object's own ``latex()`` as one
  display block, each line tagged with the paper's equation number;
* ``__str__()`` -- ``print(result)`` gives a few lines of plain text: what the object is, the
  equations it reproduces and its main values (formulas in sympy's ``str`` form, numbers to 12
  digits).  ``repr()`` is left alone: it stays the dataclass representation.

Each class writes its own text in a ``text_lines()`` method and its own LaTeX in ``latex()``
(the :class:`~thinlayer.results.Result` protocol); a class may override ``_display_tex()`` when
Jupyter should show something other than ``latex()`` (a table as an ``array``).

Examples
--------
The coefficients (2.20), (4.2) of a layer with an exact Poisson ratio:

>>> from thinlayer import BondedLayer, Punch, kernel_coefficients, inner_pressure
>>> print(kernel_coefficients(BondedLayer("3/10"), 2))
KernelCoefficients of BondedLayer(nu=3/10), n <= 2   (2.4), (2.20), (4.2)
  A   = 20/49
  m_1 = 1/14
  m_2 = -53/490
  M_1 = -1/14
  M_2 = 111/980

What Jupyter receives for a punch (1.1), and the inner expansion (2.26) as text:

>>> print(Punch.paraboloid(R=1)._repr_latex_())
$$\begin{gather*}\Phi(x_1, x_2) = \frac{x_{1}^{2}}{2} + \frac{x_{2}^{2}}{2} \tag{1.1}\end{gather*}$$
>>> ip = inner_pressure(BondedLayer("3/10"), Punch.paraboloid(R=1))
>>> print(ip)
InnerPressure: paraboloid of revolution on BondedLayer(nu=3/10), 2 terms (closed form (4.1))   (2.26)
  Phi = x_1**2/2 + x_2**2/2
  p_0 = 7*mu*(delta_0 - x_1**2/2 - x_2**2/2)/(2*H)
  p_1 = -H*mu/2
  arguments of lambdify(): (x_1, x_2, delta_0, H, mu)
>>> print(BondedLayer(0.3), BondedLayer(), BondedLayer(parameter="kappa"))
BondedLayer(nu=0.3) BondedLayer(nu) BondedLayer(kappa)
"""
from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import mpmath
import sympy as sp

from .errors import InputError

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
    """A number or a formula as short text: sympy ``str``; mpmath and floats to ``digits`` digits.

    >>> fmt(sp.Rational(3, 10)), fmt(mpmath.mpf(2) / 3), fmt(0.1 + 0.2), fmt(sp.sqrt(2) / 2)
    ('3/10', '0.666666666667', '0.3', 'sqrt(2)/2')
    """
    if isinstance(x, (mpmath.mpf, mpmath.mpc)):
        return mpmath.nstr(x, digits)
    if isinstance(x, float):
        return f"{x:.{digits}g}"
    if isinstance(x, sp.Float):
        return mpmath.nstr(mpmath.mpf(x), digits)
    if isinstance(x, sp.Basic):
        return sp.sstr(x)
    return str(x)


class RichDisplay:
    """Mixin: ``_repr_latex_`` from ``latex()`` for Jupyter, ``__str__`` as readable text.

    Adds no state (``__slots__ = ()``), so it sits among the bases of frozen dataclasses.

    Examples
    --------
    Alexandrov's boundary layer for nu = 0 (A = 1/2, m_1 = 0), (3.23)-(3.25):

    >>> from thinlayer import BondedLayer, Punch, alexandrov_solution, ellipse_contour, force_law
    >>> print(alexandrov_solution(BondedLayer(0)))
    AlexandrovSolution: Q(v) = v erf(sqrt(B (v - h))) + sqrt((v - h)/(pi B)) exp(-B (v - h)), v > h   (3.23)-(3.25)
      B  = 1
      C  = 2
      h* = -1/2 + sqrt(2)/2

    The contact ellipse (3.1) of R_1 = 4, R_2 = 1 at delta_0 = 1/2:

    >>> print(ellipse_contour(4, 1, sp.Rational(1, 2)))
    EllipseContour: x_1**2/a**2 + x_2**2/b**2 = 1   (3.1)
      a   = 2
      b   = 1
      e^2 = 3/4
      area |omega_0| = 2*pi, perimeter |Gamma_0| = 8*elliptic_e(3/4)

    For nu = 1/4 the coefficient m_1 vanishes, and with it the first correction of the force (1.8):

    >>> print(force_law(BondedLayer("1/4"), Punch.paraboloid()))
    ForceLaw: paraboloid of revolution on BondedLayer(nu=1/4), quadratic   (1.8), (3.25)
      Phi = (x_1**2 + x_2**2)/(2*R)
      P  = P0 + P1 + O(P0 (H/a)**3)
      P0 = 3*pi*R*delta_0**2*mu/H
      P1 = 0
      |omega| = 2*pi*R*delta_0 - h* H (2*sqrt(2)*pi*sqrt(R)*sqrt(delta_0)) + O(|omega| (H/a)**2)

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
        return tex if tex is not None else r"	ext{" + latex_escape(str(self)) + "}"

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
        return "\n".join(lines()) if callable(lines) else repr(self)


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
