r"""Rich display of result objects: LaTeX in Jupyter, readable text in a terminal.

Every result object of thinlayer inherits :class:`RichDisplay`, which adds two methods and
nothing else:

* ``_repr_latex_()`` -- Jupyter (and nbconvert) render the object's own ``latex()`` as one
  display block, each line tagged with the paper's equation number;
* ``__str__()`` -- ``print(result)`` gives a few lines of plain text: what the object is, the
  equations it reproduces and its main values (formulas in sympy's ``str`` form, numbers to 12
  digits).  ``repr()`` is left alone: it stays the dataclass representation.

The text of each class is written by a formatter registered here with :func:`text_for`, so the
modules of the paper's stages only name the mixin among their bases.

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

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

import mpmath
import sympy as sp

__all__ = ["RichDisplay", "Table", "display_math", "fmt", "table", "text_for"]

#: class name -> formatter returning the lines of ``str(obj)``
_TEXT: dict[str, Callable[[Any], list[str]]] = {}
#: class name -> LaTeX for classes without a ``latex()`` method (the layer kernels)
_LATEX: dict[str, Callable[[Any], str]] = {}


def text_for(*names: str) -> Callable:
    """Register a formatter ``f(obj) -> list of lines`` for ``str()`` of the named classes."""

    def deco(f: Callable[[Any], list[str]]) -> Callable[[Any], list[str]]:
        for n in names:
            _TEXT[n] = f
        return f

    return deco


def _lookup(table: dict, obj: Any) -> Callable | None:
    for cls in type(obj).__mro__:
        f = table.get(cls.__name__)
        if f is not None:
            return f
    return None


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

    A class without a formatter prints its ``repr``; one without ``latex()`` has no LaTeX form:

    >>> class Plain(RichDisplay):
    ...     def __repr__(self):
    ...         return "Plain()"
    >>> str(Plain()), Plain()._repr_latex_()
    ('Plain()', None)
    """

    __slots__ = ()

    def _repr_latex_(self) -> str | None:
        """Jupyter's LaTeX representation: ``latex()`` as one display block (None: plain text)."""
        f = _lookup(_LATEX, self)
        if f is not None:
            tex = f(self)
        elif callable(getattr(self, "latex", None)):
            tex = self.latex()
        else:
            return None
        return display_math(tex)

    def __str__(self) -> str:
        f = _lookup(_TEXT, self)
        if f is None:
            return repr(self)
        return "\n".join(f(self))


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
            raise ValueError(f"a row has {len(r)} cells but the header has {len(head)}: {r}")
    return Table(head, body)


# ---------------------------------------------------------------------------------------------
# layers (kernels.py)
# ---------------------------------------------------------------------------------------------
@text_for("BondedLayer")
def _text_bonded(layer) -> list[str]:
    if layer.parameter is not None:
        return [f"BondedLayer({layer.parameter_name})"]
    return [f"BondedLayer(nu={fmt(layer.nu, 15)})"]


@text_for("FrictionlessLayer", "HalfSpace")
def _text_plain_layer(layer) -> list[str]:
    return [f"{type(layer).__name__}()"]


@text_for("GenericLayer")
def _text_generic_layer(layer) -> list[str]:
    return ["GenericLayer(A, m_1, m_2, ...)"]


def _latex_layer(layer) -> str:
    name = r"\text{" + str(layer) + r"}:\quad "
    try:
        L = layer.L()
    except ValueError:  # GenericLayer: known only through its coefficients
        return name + r"\frac{\mathcal{L}(s)}{s} = \mathcal{A}\left(1 + m_1 s^2 + m_2 s^4 + \dots\right) \tag{2.20}"
    if L.has(sp.Float):  # a float nu: kappa to 15 digits, not the layer's working precision
        L = L.evalf(15)
    tag = rf" \tag{{{layer.equation}}}" if layer.equation else ""
    return name + rf"\mathcal{{L}}(u) = {sp.latex(L)}" + tag


_LATEX["LayerKernel"] = _latex_layer


def _latex_edge_shift_table(tab) -> str:
    """The table as a LaTeX ``array`` (MathJax renders no ``tabular``)."""
    rows = [r"\nu & h^*\ \text{(exact)} & \tilde h^*\ \text{(3.25)} & \text{difference} \\ \hline"]
    for nu, he, ha in tab.rows:
        rows.append(f"{float(nu):g} & {mpmath.nstr(he, 10)} & {mpmath.nstr(ha, 10)} & {mpmath.nstr(he - ha, 3)} \\\\")
    return r"\begin{array}{rrrr}" + " ".join(rows) + r"\end{array}"


_LATEX["EdgeShiftTable"] = _latex_edge_shift_table


# ---------------------------------------------------------------------------------------------
# stages of the paper
# ---------------------------------------------------------------------------------------------
@text_for("KernelCoefficients")
def _text_coefficients(c) -> list[str]:
    out = [f"KernelCoefficients of {c.layer}, n <= {c.order}   (2.4), (2.20), (4.2)"]
    w = len(f"m_{c.order}")
    out.append(f"  {'A':<{w}} = {fmt(c.A_expr if c.layer.parameter is not None else c.A)}")
    for n in range(1, c.order + 1):
        out.append(f"  {f'm_{n}':<{w}} = {fmt(c.m[n])}")
    for k in range(1, c.order + 1):
        out.append(f"  {f'M_{k}':<{w}} = {fmt(c.M[k])}")
    return out


@text_for("MomentExpansion")
def _text_moments(me) -> list[str]:
    out = [(f"MomentExpansion of {me.layer}: k(Lambda xi) ~ sum_n w_n Lambda^(-2n-2) Delta^n delta(xi), "
           f"n <= {me.order}   (2.22)")]
    out += [f"  w_{n} = {fmt(w)}" for n, w in enumerate(me.weights())]
    return out


@text_for("Punch")
def _text_punch(p) -> list[str]:
    pars = ", ".join(q.name for q in p.parameters) or "none"
    return [f"Punch ({p.name}): Phi(x_1, x_2) = {fmt(p.expr)}   (1.1)",
            f"  degree {p.degree}, parameters: {pars}"]


@text_for("InnerPressure")
def _text_inner(ip) -> list[str]:
    how = "closed form (4.1)" if ip.method == "closed" else "recursion (2.28)"
    out = [(f"InnerPressure: {ip.punch.name} on {ip.layer}, {ip.order} term{'s' if ip.order != 1 else ''} "
           f"({how})   (2.26)"), f"  Phi = {fmt(ip.punch.expr)}"]
    out += [f"  p_{k} = {fmt(t)}" for k, t in enumerate(ip.terms)]
    out.append(f"  arguments of lambdify(): ({', '.join(a.name for a in ip.arguments)})")
    return out


@text_for("ContactContour")
def _text_contour(c) -> list[str]:
    acc = c.accuracy
    return [
        f"ContactContour: Gamma_0 = {{{fmt(c.Phi)} = {fmt(c.delta0)}}}   (3.3)-(3.14)",
        f"  perimeter |Gamma_0| = {fmt(c.perimeter)}, area |omega_0| = {fmt(c.area)}",
        f"  centroid ({fmt(c.centroid[0])}, {fmt(c.centroid[1])}), {len(c.nodes)} nodes",
        (f"  accuracy: distance from Gamma_0 {acc.level_distance:.1e}, arc-length speed {acc.speed_error:.1e}, "
        f"turning number {acc.turning_number:.12g}"),
    ]


@text_for("EllipseContour")
def _text_ellipse(e) -> list[str]:
    return [
        "EllipseContour: x_1**2/a**2 + x_2**2/b**2 = 1   (3.1)",
        f"  a   = {fmt(e.a)}",
        f"  b   = {fmt(e.b)}",
        f"  e^2 = {fmt(e.e2)}",
        f"  area |omega_0| = {fmt(e.area)}, perimeter |Gamma_0| = {fmt(e.perimeter)}",
    ]


@text_for("AlexandrovParameters")
def _text_alexandrov_parameters(p) -> list[str]:
    return [
        "AlexandrovParameters: L~(s)/s = sqrt(s**2 + B**2)/(s**2 + C)   (3.19)-(3.21)",
        f"  A   = {fmt(p.A)}",
        f"  m_1 = {fmt(p.m1)}",
        f"  B   = {fmt(p.B)}",
        f"  C   = {fmt(p.C)}",
    ]


@text_for("AlexandrovSolution")
def _text_alexandrov_solution(s) -> list[str]:
    return [
        ("AlexandrovSolution: Q(v) = v erf(sqrt(B (v - h))) + sqrt((v - h)/(pi B)) exp(-B (v - h)), v > h"
        "   (3.23)-(3.25)"),
        f"  B  = {fmt(s.params.B)}",
        f"  C  = {fmt(s.params.C)}",
        f"  h* = {fmt(s.h)}",
    ]


@text_for("WienerHopfSolution")
def _text_wiener_hopf(w) -> list[str]:
    if isinstance(w.nu, str):
        which = "frictionless base"
    else:  # a float nu is kept as its exact binary value: show it as the float
        which = f"nu = {fmt(w.nu) if w.nu.q < 10**6 else fmt(float(w.nu), 15)}"
    return [
        f"WienerHopfSolution: {w.kernel} kernel, {which} (normaliser {w.normaliser})   (3.18), (3.22)",
        f"  h* = {fmt(w.h)}   (Alexandrov (3.25): {fmt(w.h_alexandrov)})",
        f"  A = {fmt(w.A)}, m_1 = {fmt(w.m1)}",
        f"  qhat(tau) - tau - h* = O(exp(-{w.sigma:.6g} tau)); table for 0 <= tau <= {w.tau_max:.6g}",
    ]


@text_for("ForceLaw")
def _text_force_law(law) -> list[str]:
    out = [f"ForceLaw: {law.punch.name} on {law.layer}, {law.kind}   (1.8), (3.25)",
           f"  Phi = {fmt(law.punch.expr)}"]
    if law.P0 is not None:
        out += ["  P  = P0 + P1 + O(P0 (H/a)**3)",
                f"  P0 = {fmt(law.P0)}",
                f"  P1 = {fmt(law.P1)}",
                f"  |omega| = {fmt(law.area0)} - h* H ({fmt(law.perimeter)}) + O(|omega| (H/a)**2)"]
    else:
        out += ["  P  = vartheta/(A H) iint_omega0 (delta0 - Phi) dx + c oint_Gamma0 |grad Phi| ds + O(P0 (H/a)**3)",
                f"  c  = {fmt(law.coefficient)}",
                "  no closed form: use .evaluate(delta0, H, mu, ...) (integrals over the contact contour)"]
    return out


@text_for("CompositePressure")
def _text_composite(c) -> list[str]:
    kind = "exact (2.3)" if c.boundary_layer == "exact" else "Alexandrov (3.24)"
    return [
        f"CompositePressure: inner ({c.inner.order} terms) + {kind} boundary layer - common part   (2.26), (3.24)",
        f"  {c.punch.name}: Phi = {fmt(c.punch.expr)} on {c.layer}",
        f"  delta0 = {c.delta0:.6g}, H = {c.H:.6g}, mu = {c.mu:.6g}",
        f"  h* = {c.h:.10g}, amplitude vartheta/A = {c.amplitude:.10g}, boundary layer for n/H < {c.band:.4g}",
    ]


@text_for("AxisymmetricContact")
def _text_axisymmetric(r) -> list[str]:
    punch = getattr(r, "punch", None)
    what = f" of {punch.name} Phi = {fmt(punch.expr)}" if punch is not None else ""
    layer = str(r.layer) if "nu=" in str(r.layer) else f"{r.layer}, nu = {r.nu:.6g}"
    return [
        f"{type(r).__name__}: direct numerical solution{what}   (1.5)-(1.8)",
        f"  {layer}, mu = {r.mu:.6g}, H = {r.H:.6g}, delta0 = {r.delta0:.10g}",
        f"  contact radius c = {r.radius:.12g}  (+- {r.radius_error:.1e})",
        f"  force          P = {r.force:.12g}  (+- {r.force_error:.1e} P), {r.modes} modes",
    ]
