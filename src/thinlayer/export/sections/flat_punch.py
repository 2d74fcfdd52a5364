"""The report's section on the flat-ended cylindrical punch (F.1)-(F.19), from a ``[flat_punch]`` table.

The laws are the engine's own derivations (:func:`thinlayer.asymptotics.flat_punch.thin_flat_punch_derivation`,
:func:`thinlayer.asymptotics.flat_punch.thick_flat_punch_coefficients`), printed through the report's
normalisation; the table of ``kappa`` over ``a/H`` (rows) and ``nu`` (columns) comes from the exact Fredholm
solution (F.6)-(F.7), each value with its estimate (the largest one is stated in the caption).
"""
from __future__ import annotations

from typing import Any

import sympy as sp

from .._normal import float_latex, normal_latex
from .base import DerivationFileError, short

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render", "FLAT_DEFAULT"]

KEY = "flat_punch"
SCHEMA = {"a_over_H": ((list,), "a list of punch radius over thickness values in (0, 200]"),
          "nu": ((list,), "a list of Poisson ratios in (-1, 1/2] (columns of the table)")}
ORDER = 100
#: the default table of [flat_punch]: a/H from thick to thin, nu from 0 to incompressible
FLAT_DEFAULT = {"a_over_H": [0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0], "nu": [0.0, 0.3, 0.45, 0.5]}

#: the thick series shown through this power of a/H (its coefficients in the moments b_k of 1 - L)
SHOWN_ORDER = 4


def parse(ft: Any, context: Any) -> dict | None:
    """``[flat_punch]``: the a/H values (<= 30, in (0, 200]) and the nu values (<= 8, in (-1, 1/2]) of the table.

    A flat punch (``[punch] kind = "flat"``) without the table gets :data:`FLAT_DEFAULT`.
    """
    if ft is None:
        return dict(FLAT_DEFAULT) if context.tables.get("punch", {}).get("kind") == "flat" else None
    out = {}
    for key, lo, hi, most in (("a_over_H", 0.0, 200.0, 30), ("nu", -1.0, 0.5, 8)):
        vals = ft.get(key, FLAT_DEFAULT[key])
        ok = (0 < len(vals) <= most and all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                                and lo < v <= hi for v in vals))
        if not ok:
            raise DerivationFileError(f"[flat_punch] {key} = {short(vals)}: a list of 1 to {most} numbers in "
                                      f"({lo:g}, {hi:g}]")
        out[key] = [float(v) for v in vals]
    return out


def applies(der: Any) -> bool:
    return der.sections.get(KEY) is not None


def render(doc: Any, der: Any, context: Any) -> None:
    """Append the flat-punch section to ``doc`` (a :class:`thinlayer.export.report.Document`)."""
    layer, table = der.layer, der.sections[KEY]
    from ...asymptotics.flat_punch import thick_flat_punch_coefficients, thin_flat_punch_derivation
    from ...contact.flat_punch import stiffness_table

    d = thin_flat_punch_derivation()
    h_star = sp.Symbol("h^*", real=True)  # the edge shift of (3.25): one symbol with the other sections
    doc.section("Flat-ended cylindrical punch").text(
        r"A rigid flat-ended cylinder of radius $a$ pressed to the depth $w_0$: the contact is the disc $r < a$ "
        r"whatever the depth, and the pressure is singular at its edge. Its stiffness factor $\kappa$ is defined "
        r"by (F.1); $\lambda = a/H$; (F.$n$) numbers this extension of \texttt{thinlayer}, as in its modules "
        r"\texttt{numerics.flat\_punch} and \texttt{asymptotics.flat\_punch}.")
    doc.math(r"P = \frac{4 \mu a w_0\, \kappa(\lambda)}{1 - \nu} \tag{F.1}")
    doc.text(r"\emph{Exact stiffness.} For an axisymmetric pressure the Fourier integral (2.1) becomes a Hankel "
             r"integral, (F.2); Copson's representation $\bar p(\alpha) = \int_0^a \phi(t)\cos(\alpha t)\,dt$ gives a "
             r"pressure that vanishes for $r > a$, (F.3):")
    doc.math(r"u_3(r) = \frac{1}{\vartheta}\int_0^\infty \bar p(\alpha)\,\mathcal{L}(\alpha H)\,J_0(\alpha r)\,"
             r"d\alpha,\quad \bar p(\alpha) = \int_0^a p(\rho)\,J_0(\alpha\rho)\,\rho\,d\rho \tag{F.2}")
    doc.math(r"p(r) = \frac{\phi(a)}{\sqrt{a^2 - r^2}} - \int_r^a \frac{\phi'(t)\,dt}{\sqrt{t^2 - r^2}},\quad "
             r"P = 2\pi\int_0^a \phi(t)\,dt \tag{F.3}")
    doc.text(r"With $J_0(\alpha r) = \frac{2}{\pi}\int_0^r \cos(\alpha s)\,(r^2 - s^2)^{-1/2} ds$ the punch condition "
             r"$u_3 = w_0$ on $r < a$ is an Abel equation, solved by (F.4); splitting $\mathcal{L} = 1 - (1 - "
             r"\mathcal{L})$, the part 1 inverts by the Fourier cosine theorem, (F.5):")
    doc.math(r"\frac{1}{\vartheta}\int_0^\infty \mathcal{L}(\alpha H)\cos(\alpha s)\int_0^a \phi(t)\cos(\alpha t)\,dt"
             r"\,d\alpha = w_0,\quad 0 \le s < a \tag{F.4}")
    doc.math(r"\int_0^\infty \cos(\alpha s)\int_0^a \phi(t)\cos(\alpha t)\,dt\,d\alpha = \frac{\pi}{2}\,\phi(s) "
             r"\tag{F.5}")
    doc.text(r"so that, with $s = a x$, $t = a y$ and $\phi(a y) = 2\vartheta w_0 f(y)/\pi$, a Fredholm equation of "
             r"the second kind, (F.6), gives the stiffness, (F.7), the pressure with its edge singularity of "
             r"strength $f(1)$, (F.8), and Krein's identity, (F.9), an independent check of the solver:")
    doc.math(r"f(x) - \int_0^1 k(x, y)\,f(y)\,dy = 1,\quad k(x, y) = \frac{2}{\pi}\int_0^\infty "
             r"\left(1 - \mathcal{L}(t/\lambda)\right)\cos(t x)\cos(t y)\,dt \tag{F.6}")
    doc.math(r"\kappa(\lambda) = \int_0^1 f(x)\,dx \tag{F.7}")
    doc.math(r"p(r) = \frac{2\vartheta w_0}{\pi a}\left(\frac{f(1)}{\sqrt{1 - x^2}} - \int_x^1 "
             r"\frac{f'(y)\,dy}{\sqrt{y^2 - x^2}}\right),\quad x = \frac{r}{a} \tag{F.8}")
    doc.math(r"\frac{d(\lambda\kappa)}{d\lambda} = f(1)^2 \tag{F.9}")
    doc.text(
        r"\emph{Thin layer.} The flat punch is the limit $R \to \infty$ of the paraboloid: of the inner expansion "
        r"(2.26), (4.1) only $p_0$ survives, which gives (F.10). The boundary layer of section 4 with the flat "
        r"punch's constant right side is the derivative of the smooth punch's, with the exact edge shift $h^*$ "
        r"(3.25); its excess force gives (F.11), and the punch acts as if its radius were $a + h^* H$ (F.12):")
    sub = {d.h: h_star}
    doc.group([rf"\kappa_0 = {normal_latex(d.leading)}"], "F.10")
    doc.group([rf"\kappa = {normal_latex(d.two_term.subs(sub))} + O(\lambda^{{-1}})"], "F.11")
    doc.group([rf"\kappa = {normal_latex(d.resummed.subs(sub))}"], "F.12")
    doc.text(
        r"\emph{Incompressible layer} ($\nu = 1/2$, $\mathcal{A} = 0$): the operator (I.2) on the disc with "
        r"Dirichlet's condition at the edge, moved to $r = a + hH$ by the edge correction $h$ of (I.12):")
    doc.group([rf"\kappa_0 = {normal_latex(d.incompressible_leading)}"], "F.13")
    doc.group([rf"\kappa = {normal_latex(d.incompressible_two_term)} + O(\lambda)"], "F.14")
    doc.text(
        r"\emph{Nearly incompressible layer} ($1/4 < \nu < 1/2$): the two-term operator (I.10) with $c_1 = "
        r"\mathcal{A} m_1$ and the Dirichlet condition at the edge moved by its $h$ of (I.12) joins (F.12) and "
        r"(F.14), (F.15); the thin model's error estimate, (F.16), is an envelope of the remainders measured "
        r"against the exact solution (F.6)--(F.7), not a derived bound:")
    doc.math(r"\kappa = \frac{\pi (\lambda + h)^4\,\psi(x)}{32\, c_1 \lambda},\quad x = \frac{\lambda + h}"
             r"{\sqrt{m_1}},\quad \psi(x) = \frac{8}{x^2}\left(1 - \frac{2 I_1(x)}{x\, I_0(x)}\right) \tag{F.15}")
    doc.math(r"\epsilon_{\mathrm{thin}} = \min\left(\frac{|m_1| + {h^*}^2 + 0.02}{\lambda^3},\ "
             r"\frac{2.5}{\lambda^2}\right) \tag{F.16}")
    coeffs = thick_flat_punch_coefficients(SHOWN_ORDER)
    terms = []
    for k, c in enumerate(coeffs):
        if k == 0:
            continue
        coef = normal_latex(sp.factor(c))
        power = r"\lambda" if k == 1 else r"\lambda^{%d}" % k
        if isinstance(sp.factor(c), sp.Add):  # a sum: in parentheses before the power
            coef = r"\left(" + coef + r"\right)"
        terms.append(coef + r"\," + power)
    series = "1 + " + " + ".join(terms)
    doc.text(
        r"\emph{Thick layer.} Expanding $\cos(\lambda u x)\cos(\lambda u y)$ in the kernel of (F.6) in powers of "
        r"$\lambda$ gives a degenerate kernel at each order, (F.17), through the moments $b_n$ of $1 - \mathcal{L}$, "
        r"(T.2); solving order by order on the half-space's flat punch gives the series (F.18), and its error "
        r"estimate is the size of its last two terms, (F.19), for $\lambda$ below about 0.8 (the radius of "
        r"convergence):")
    doc.math(r"k(x, y) = \frac{2}{\pi}\sum_{n \ge 0} (-1)^n \lambda^{2n+1} b_n \sum_{j + l = n} "
             r"\frac{x^{2j} y^{2l}}{(2j)!\,(2l)!},\quad b_n = \int_0^\infty u^{2n}\left(1 - \mathcal{L}(u)\right) du "
             r"\tag{F.17}")
    doc.group([rf"\kappa = {series} + O(\lambda^{{{SHOWN_ORDER + 1}}})"], "F.18")
    doc.math(r"\epsilon_{\mathrm{thick}} = \frac{|c_N \lambda^N| + |c_{N-1} \lambda^{N-1}|}{\kappa},\quad "
             r"\kappa = \sum_{k=0}^{N} c_k \lambda^k \tag{F.19}")
    ratios = [float(v) for v in table["a_over_H"]]
    frictionless = layer.shear_free_base
    nus = [0.3] if frictionless else [float(v) for v in table["nu"]]
    cols, worst = [], 0.0
    for nu in nus:
        lay = layer.with_nu(nu)
        kappa, est, _ = stiffness_table(lay, ratios, "exact")
        cols.append([float(k) for k in kappa])
        worst = max(worst, float(max(est)))
    head = ["$a/H$"] + (["$\\kappa$"] if frictionless else [rf"$\nu = {float_latex(nu, 6)}$" for nu in nus])
    rows = [[f"${float_latex(x, 6)}$"] + [f"${float_latex(c[i], 6)}$" for c in cols] for i, x in enumerate(ratios)]
    base = ("a layer on a frictionless base (independent of $\\nu$)" if frictionless
            else "a layer bonded to a rigid base")
    doc.table(rf"Stiffness factor $\kappa(a/H)$ (F.1) of the flat punch on {base}, from the exact Fredholm "
              rf"equation (F.6)--(F.7); the largest estimated relative error of the entries is "
              rf"${float_latex(max(worst, 1e-16), 2)}$.", "r" * len(head), head, rows, label="tab:flat-kappa")
