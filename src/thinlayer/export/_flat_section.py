"""The report's section on the flat-ended cylindrical punch (F.1)-(F.19), from a ``[flat_punch]`` table.

The laws are the engine's own derivations (:func:`thinlayer.asymptotics.flat_punch.thin_flat_punch_derivation`,
:func:`thinlayer.asymptotics.flat_punch.thick_flat_punch_coefficients`), printed through the report's
normalisation; the table of ``kappa`` over ``a/H`` (rows) and ``nu`` (columns) comes from the exact Fredholm
solution (F.6)-(F.7), each value with its estimate (the largest one is stated in the caption).
"""
from __future__ import annotations

from typing import Any

import sympy as sp

from ._normal import float_latex, normal_latex

__all__ = ["flat_punch_part"]

#: the thick series shown through this power of a/H (its coefficients in the moments b_k of 1 - L)
SHOWN_ORDER = 4


def flat_punch_part(doc: Any, layer: Any, table: dict) -> None:
    """Append the flat-punch section to ``doc`` (a :class:`thinlayer.export.report.Document`)."""
    from ..asymptotics.flat_punch import thick_flat_punch_coefficients, thin_flat_punch_derivation
    from ..contact.flat_punch import stiffness_table
    from ..layers.kernels import BondedLayer, FrictionlessLayer, IncompressibleLayer

    d = thin_flat_punch_derivation()
    doc.section("Flat-ended cylindrical punch").text(
        r"A rigid flat-ended cylinder of radius $a$ pressed to the depth $w_0$: the contact is the disc $r < a$ "
        r"whatever the depth, and the pressure is singular at its edge. Its stiffness factor $\kappa$ is defined "
        r"by (F.1); $\lambda = a/H$; (F.$n$) numbers this extension of \texttt{thinlayer}.")
    doc.math(r"P = \frac{4 \mu a w_0\, \kappa(\lambda)}{1 - \nu} \tag{F.1}")
    doc.text(
        r"\emph{Thin layer.} The flat punch is the limit $R \to \infty$ of the paraboloid: of the inner expansion "
        r"(2.26), (4.1) only $p_0$ survives, which gives (F.10). The boundary layer of section 4 with the flat "
        r"punch's constant right side is the derivative of the smooth punch's, with the exact edge shift $h$ "
        r"(3.18); its excess force gives (F.11), and the punch acts as if its radius were $a + hH$ (F.12):")
    doc.group([rf"\kappa_0 = {normal_latex(d.leading)}"], "F.10")
    doc.group([rf"\kappa = {normal_latex(d.two_term)} + O(\lambda^{{-1}})"], "F.11")
    doc.group([rf"\kappa = {normal_latex(d.resummed)}"], "F.12")
    doc.text(
        r"\emph{Incompressible layer} ($\nu = 1/2$, $\mathcal{A} = 0$): the operator (I.2) on the disc with "
        r"Dirichlet's condition at the edge, moved to $r = a + hH$ by the edge layer (I.12):")
    doc.group([rf"\kappa_0 = {normal_latex(d.incompressible_leading)}"], "F.13")
    doc.group([rf"\kappa = {normal_latex(d.incompressible_two_term)} + O(\lambda)"], "F.14")
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
        r"\emph{Thick layer.} With $\mathcal{L} = 1 + (\mathcal{L} - 1)$ the regular part of the kernel acts "
        r"through the moments $b_k = \int_0^\infty u^{2k} (1 - \mathcal{L}(u))\, du$ (F.17), (T.2); solving order by "
        r"order on the half-space's flat punch gives the series (F.18):")
    doc.group([rf"\kappa = {series} + O(\lambda^{{{SHOWN_ORDER + 1}}})"], "F.18")
    ratios = [float(v) for v in table["a_over_H"]]
    frictionless = layer.base == "frictionless"
    nus = [0.3] if frictionless else [float(v) for v in table["nu"]]
    cols, worst = [], 0.0
    for nu in nus:
        lay = FrictionlessLayer(nu) if frictionless else (IncompressibleLayer() if nu == 0.5 else BondedLayer(nu))
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
