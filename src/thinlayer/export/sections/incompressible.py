r"""The report's sections for the incompressible layer bonded to its base (nu = 1/2, A = 0): the Maclaurin data and
the thin-layer operator (I.1), (I.2), the obstacle problem (I.3)-(I.5), its solution for the sphere (I.11), the
elliptic paraboloid (I.6)-(I.8) or an axisymmetric punch (I.9), and the edge correction (I.12).
"""
from __future__ import annotations

from typing import Any

import sympy as sp

from ... import symbols as S
from .base import axisymmetric, incompressible_bonded, nl, num, signed_sum, sphere_rows, tagged

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render"]

KEY = None  # [coefficients] order: a core table
SCHEMA: dict = {}
ORDER = 50


def parse(table: Any, context: Any) -> None:
    return None


def applies(der: Any) -> bool:
    return der.punch is not None and incompressible_bonded(der.layer)


def _zero(expr: Any) -> str:
    """``expr = 0`` with the sign of its first term positive (the sign of an equation's side is free)."""
    text = nl(sp.factor(expr))
    return (text[2:] if text.startswith("- ") else text) + " = 0"


def render(doc: Any, der: Any, context: Any) -> None:
    from ...asymptotics.incompressible import (
        incompressible_axisymmetric,
        incompressible_ellipse,
        obstacle_problem,
        thin_layer_operator,
        two_term_edge_shift,
        two_term_sphere,
    )
    from ...layers.coefficients import incompressible_coefficients

    layer, punch = der.layer, der.punch
    doc.section("Incompressible layer: Maclaurin data and thin-layer operator").text(
        r"At $\nu = 1/2$ the coefficient $\mathcal{A}$ of (2.4) vanishes: the compressible expansion "
        r"(2.20)--(3.25) does not exist, and the leading operator is of second order, (I.1) and (I.2):")
    co = incompressible_coefficients(der.coefficient_order)
    series = signed_sum([(cn, rf"s^{{{2 * n}}}") for n, cn in enumerate(co.c) if n])
    doc.math(rf"\frac{{\mathcal{{L}}(s)}}{{s}} = {series} + \dots,\quad \mathcal{{A}} = c_0 = 0 \tag{{I.1}}")
    op = thin_layer_operator(layer)
    ops = [r"p", r"\Delta p"] + [rf"\Delta^{{{n}}} p" for n in range(2, len(op.c))]
    terms = signed_sum([((-1) ** n * cn * S.H ** (2 * n + 1) / op.vartheta, ops[n]) for n, cn in enumerate(op.c)])
    doc.math(rf"u_3 = {terms} + \dots \tag{{I.2}}")
    doc.section("Punch and the obstacle problem").text(r"The punch, (1.1), and the obstacle problem (I.3)--(I.5):")
    doc.math(rf"\Phi(x_1, x_2) = {nl(punch.expr)} \tag{{1.1}}")
    ob = obstacle_problem(layer, punch)
    lhs = r"-\Delta p" if ob.is_incompressible else rf"-\Delta p + {nl(ob.k2)}\, p"
    rows = [(rf"{lhs} = {nl(ob.source)},\quad \mathbf{{x}} \in \omega", ob.equation),
            (r"p = \frac{\partial p}{\partial n} = 0 \ \text{on}\ \partial\omega,\quad p > 0 \ \text{in}\ \omega",
             "I.4")]
    if ob.is_incompressible:
        rows.append((rf"\iint_\omega \left({nl(S.delta0 - punch.expr)}\right) d\mathbf{{x}} = 0", "I.5"))
    tagged(doc, rows)
    traits = der.punch_traits  # the catalogue punches' closed forms are in their own symbols (R; R_1, R_2)
    if "sphere" in traits:
        doc.section("Solution for the sphere (I.11)").text(r"In terms of the contact radius $c$:")
        tagged(doc, sphere_rows(two_term_sphere(layer)))
    elif "elliptic paraboloid" in traits:
        el = incompressible_ellipse()
        doc.section("Solution for the elliptic paraboloid (I.6)--(I.8)").text(
            r"The contact area is an ellipse with semi-axes $a \ge b$; its aspect $t = a^2/b^2$ solves (I.6) with "
            r"$r = R_1/R_2$, and the semi-axes, the constant $C$ of the pressure and the force follow, (I.7), (I.8):")
        tagged(doc, [(_zero(el.aspect_equation), "I.6"), (rf"t = {nl(el.t)}", "I.6"),
                     (rf"a^2 = {nl(el.a2_t)},\quad b^2 = {nl(el.b2_t)}", "I.7"), (rf"C = {nl(el.C_t)}", "I.7"),
                     (rf"P = {nl(el.force_t)}", "I.8")])
    elif axisymmetric(punch):
        ax = incompressible_axisymmetric(punch)
        doc.section("Solution for an axisymmetric punch (I.9)").text(
            r"The contact radius $c$ solves the first equation; the pressure and the force in terms of $c$:")
        tagged(doc, [(_zero(ax.radius_equation), "I.9"), (rf"p(r) = {nl(ax.pressure_of_c)}", "I.9"),
                     (rf"P = {nl(ax.force_of_c)}", "I.9")])
    h = float(two_term_edge_shift(layer, dps=15))
    doc.section("Edge correction (I.12)").text(
        rf"The model's edge lies $h H$ outside the true contact edge, $h = {num(h, 8)}$ at $\nu = 1/2$ "
        r"(the edge layer of width $H$ that the model neglects); \texttt{thinlayer.solve} reports the corrected "
        r"radius $c - hH$ and estimates the model's force error by $2hH/c$.")
