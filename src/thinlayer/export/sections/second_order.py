r"""The report's section on the second order (SO.1)-(SO.10), from a ``[second_order]`` table.

Everything printed is derived by the engine when the report is made: the boundary layer (SO.5)-(SO.8) by
:func:`thinlayer.asymptotics.second_order.second_order_boundary_layer` (the Wiener--Hopf solution in sympy), the
force and area laws (SO.9), (SO.10) of the file's punch by
:func:`thinlayer.asymptotics.second_order.second_order_law`, and the constants ``h^*``, ``m_1``, ``r_3`` by
:func:`thinlayer.asymptotics.second_order.edge_constants` (``r_3`` by three factorisations; their largest
difference is the table's check column).  Formulas go through the report's normalisation
(:func:`thinlayer.export._normal.normal_latex`).
"""
from __future__ import annotations

import math
import re
from fractions import Fraction
from typing import Any

import sympy as sp

from ... import symbols as S
from .._normal import float_latex, normal_latex
from ..units import unit_power
from .base import DerivationFileError, compressible_bonded, short

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render", "SECOND_ORDER_NUS", "SECOND_ORDER_MOST"]

KEY = "second_order"
SCHEMA = {"nu": ((list,), "a list of 1 to 12 Poisson ratios in (-1, 1/2) (numbers, or exact strings like '3/10') "
                          "or 'frictionless' (the rows of the table of r_3)")}
ORDER = 70
#: the default rows of the table of [second_order]: nu from 0 to nearly incompressible, and the frictionless base
SECOND_ORDER_NUS = ("0", "1/4", "3/10", "2/5", "9/20", "frictionless")
#: the most rows of that table (each r_3 by three factorisations, ~0.2 s)
SECOND_ORDER_MOST = 12
_EXACT_NU = re.compile(r"[-+]?[0-9]{1,6}(\.[0-9]{1,6})?(/[0-9]{1,6})?")


def parse(st: Any, context: Any) -> dict | None:
    """``[second_order]``: the section of (SO.1)-(SO.10) and the nu values of its table of ``r_3``.

    Each value is a number or an exact string (``"3/10"``, parsed by :class:`fractions.Fraction`, never
    evaluated) with ``-1 < nu < 1/2``, or ``"frictionless"`` (the layer on a frictionless base).
    """
    if st is None:
        return None
    layer, punch = context.layer, context.punch
    if punch is None or not (layer.base == "frictionless" or compressible_bonded(layer)):
        raise DerivationFileError("[second_order] is for the compressible expansion of a polynomial punch (a bonded "
                                  "layer with nu < 1/2 or the frictionless base), not the flat punch or nu = 1/2")
    vals = st.get("nu", list(SECOND_ORDER_NUS))
    what = (f"a list of 1 to {SECOND_ORDER_MOST} Poisson ratios in (-1, 1/2) (numbers, or exact strings like "
            "'3/10') or 'frictionless'")
    if not 0 < len(vals) <= SECOND_ORDER_MOST:
        raise DerivationFileError(f"[second_order] nu = {short(vals)}: {what}")
    out = []
    for v in vals:
        if v == "frictionless":
            out.append(v)
            continue
        if isinstance(v, str) and _EXACT_NU.fullmatch(v.strip()):
            num: Any = Fraction(v.strip())
        elif isinstance(v, (int, float)) and not isinstance(v, bool):
            num = float(v)
        else:
            raise DerivationFileError(f"[second_order] nu: {short(v)} is invalid: {what}")
        if not -1 < num < Fraction(1, 2):
            raise DerivationFileError(f"[second_order] nu: {short(v)} is outside (-1, 1/2): {what}")
        out.append(num)
    return {"nu": out}


def applies(der: Any) -> bool:
    return der.sections.get(KEY) is not None

#: significant digits of the constants h^*, m_1, r_3 and 12 r_3 in the report
DIGITS = 10
#: ``h^*`` as the report prints it: braced, so that its square is ``{h^{*}}^{2}``
_H_STAR = sp.Symbol("{h^{*}}", real=True)


_FRAC_POWER = re.compile(r"\^\{\\frac\{(\d+)\}\{(\d+)\}\}")


def _nl(expr: Any) -> str:
    r""":func:`normal_latex` with powers denested (``R^{9/4}``, not ``(R^3)^{3/4}``) and fractional exponents
    inline (``\delta_0^{3/4}``: no fraction inside the fraction of a law).
    """
    expr = sp.powdenest(expr if isinstance(expr, sp.Basic) else sp.Float(expr), force=True)  # engine output
    return _FRAC_POWER.sub(r"^{\1/\2}", normal_latex(expr))


def _layer_of(value: Any) -> Any:
    from ...layers.kernels import BondedLayer, FrictionlessLayer

    if value == "frictionless":
        return FrictionlessLayer()
    if isinstance(value, Fraction):
        return BondedLayer(sp.Rational(value.numerator, value.denominator))
    return BondedLayer(float(value))


def _nu_label(value: Any) -> str:
    if value == "frictionless":
        return r"frictionless base"
    if isinstance(value, Fraction):
        return f"${value.numerator}$" if value.denominator == 1 else f"${value.numerator}/{value.denominator}$"
    return f"${float_latex(value, 6)}$"


def _numeric_layer(layer: Any) -> bool:
    """Whether the constants of ``layer`` are numbers (a numeric nu, or the frictionless base)."""
    return layer.base == "frictionless" or (layer.parameter is None and layer.numeric_nu is not None)


def _boundary_layer(doc: Any) -> None:
    from ...asymptotics import second_order as so

    bl = so.second_order_boundary_layer()
    sub = {so.h0_: _H_STAR}
    Phi, dPhi = sp.Symbol(r"\Phi"), sp.Symbol(r"\Phi'")
    transform = bl.transform.subs(sp.Derivative(so.Phi_(so.p_), so.p_), dPhi).subs(so.Phi_(so.p_), Phi).subs(sub)
    doc.section("Second order: the boundary layer at a curved contour").text(
        r"The first approximation (3.15)--(3.25) treats the edge of the contact area as straight and the punch "
        r"near it as a plane. At the next order the curvature $\kappa$ of $\Gamma_0$ (positive where $\omega_0$ "
        r"is convex) and the normal curvature $\Phi_{nn}$ of the punch enter through $\epsilon = \kappa H$ and "
        r"$\beta = H\Phi_{nn}/(2|\nabla\Phi|)$ (SO.2), (SO.3). In the edge variable $v$ the layer's symbol becomes "
        r"$F(w) - \frac{i\epsilon}{2} F'(w)$, $F(s) = \mathcal{L}(s)/s$, and the right-hand side "
        r"$(h + \tau) - \beta (h + \tau)^2$. Its Wiener--Hopf factor $F_+ = \sqrt{\mathcal{A}}\,\Phi(p)$ on "
        r"$w = ip$ enters through three constants of the layer, (SO.4):")
    doc.math(r"\log \Phi(p) = - h^* p - \frac{m_1}{2} p^2 + r_3 p^3 + O(p^4) \tag{SO.4}")
    doc.text(r"with $h^*$ the edge shift (3.25), $m_1$ of (2.20) and $r_3$ the cubic Wiener--Hopf constant. Solving "
             r"(SO.3) to first order in $\epsilon$ and $\beta$ (the principal part of the right-hand side over "
             r"$S_-$ at $w = 0$; the condition (3.18) that the pressure vanishes at the edge) gives the edge, "
             r"the Laplace transform of the boundary-layer pressure $\hat q = \mathcal{A} Q$ in $\tau = v - h$, "
             r"its far field (the inner terms $p_0 + p_1$ seen from the edge, so the matching needs no new "
             r"constant) and the force defect:")
    doc.math(rf"h = {normal_latex(bl.edge_shift.subs(sub))} \tag{{SO.5}}")
    doc.math(rf"\int_0^\infty \hat q\, e^{{-p\tau}}\, d\tau = {normal_latex(transform)} \tag{{SO.6}}")
    doc.math(rf"\hat q(v) = {normal_latex(bl.far_field.subs(sub))} + o(1),\quad v \to \infty \tag{{SO.7}}")
    doc.math(rf"\mathcal{{A}} D = {normal_latex(bl.force_defect.subs(sub))} \tag{{SO.8}}")
    doc.text(r"with $\Phi = \Phi(p)$ and $\Phi' = d\Phi/dp$.")


def _constants(doc: Any, layer: Any) -> None:
    from ...asymptotics.second_order import edge_constants

    if not _numeric_layer(layer):
        doc.text(r"The constants $h^*$, $m_1$ and $r_3$ are numbers for each Poisson ratio: this derivation's "
                 r"layer has a symbolic $\nu$, so they are given for the values of Table~\ref{tab:r3} below "
                 r"(\texttt{thinlayer.asymptotics.second\_order.edge\_constants} for any other).")
        return
    c = edge_constants(layer)
    doc.text(r"For this derivation's layer the constants are (the largest difference of $r_3$ between three "
             rf"factorisations of $F$ is ${float_latex(c.r3_spread, 2)}$):")
    doc.math(rf"h^* = {float_latex(c.h_star, DIGITS)},\quad m_1 = {float_latex(c.m1, DIGITS)},\quad "
             rf"r_3 = {float_latex(c.r3, DIGITS)} \tag{{SO.4}}")


def _laws(doc: Any, der: Any) -> None:
    from ...asymptotics.force_law import h_star
    from ...asymptotics.second_order import edge_constants, r_3, second_order_law

    layer, punch = der.layer, der.punch
    law = second_order_law(layer, punch)
    th, A = layer.vartheta, layer.A
    e1 = r"\oint_{\Gamma_0}\left(\Delta\Phi + \Phi_{nn}\right) ds"
    e2 = r"\oint_{\Gamma_0}\frac{\Delta\Phi}{|\nabla\Phi|}\, ds"
    doc.section("Second order: force and contact area").text(
        r"The force is the integral of the inner terms plus the defect (SO.8) around the edge, with the area "
        r"element $(1 - \kappa n)\,dn\,ds$; the contact edge lies at $n = H h(s)$. With "
        r"$|\nabla\Phi|\,\kappa = \Delta\Phi - \Phi_{nn}$ on $\Gamma_0$ and $\oint\kappa\,ds = 2\pi$ this gives "
        r"the force law (SO.9) and the area law (SO.10) for any punch:")
    doc.math(r"P = P_0 + P_1 + P_2 + O\!\left(P_0 \frac{H^4}{a^4}\right),\quad "
             rf"P_2 = {normal_latex(sp.factor(th * S.H**2 * r_3 / (2 * A)))} {e1} \tag{{SO.9}}")
    doc.math(r"|\omega| = |\omega_0| - h^* H |\Gamma_0| + \pi {h^*}^2 H^2"
             + _term(-layer.m(1) * S.H**2 / 2, e2) + r" + O\!\left(|\omega_0| \frac{H^3}{a^3}\right) \tag{SO.10}")
    doc.text(r"where $P_0 + P_1$ is the force law (1.8) and $|\omega_0|$, $|\Gamma_0|$ the area and the length of "
             r"the leading contour.")
    sub = {h_star: _H_STAR}
    if law.P2 is None:
        doc.text(r"This punch's contour has no closed form: the edge integrals are evaluated on the numerical "
                 r"contour $\Gamma_0$ (\texttt{thinlayer.solve(..., order=2)}).")
        return
    elliptic = law.E1.has(sp.elliptic_e, sp.elliptic_k)
    if elliptic:
        doc.text(r"For a quadratic punch $\Phi = \mathbf{x}^T K \mathbf{x}/2 + \dots$ with eigenvalues "
                 r"$\lambda_1 \ge \lambda_2$ of $K$ (here the curvatures $1/R_1$, $1/R_2$), "
                 r"$k = \sqrt{1 - \lambda_2/\lambda_1}$ and $D_0 = \delta_0 - \min\Phi$, the edge integrals are "
                 r"($ds/|\nabla\Phi| = dt/\sqrt{\lambda_1\lambda_2}$ on the ellipse; $\mathrm{K}(k)$ and "
                 r"$\mathrm{E}(k)$ the complete elliptic integrals of the first and second kind of modulus $k$):")
        doc.lines([r"\oint_{\Gamma_0}\left(\Delta\Phi + \Phi_{nn}\right) ds = (\lambda_1 + \lambda_2)|\Gamma_0| + "
                   r"4\sqrt{\frac{2 D_0}{\lambda_1\lambda_2}}\left((\lambda_1 + \lambda_2)\sqrt{\lambda_1}\,"
                   r"\mathrm{E}(k) - \lambda_2\sqrt{\lambda_1}\,\mathrm{K}(k)\right)",
                   r"\oint_{\Gamma_0}\frac{\Delta\Phi}{|\nabla\Phi|}\, ds = "
                   r"\frac{2\pi(\lambda_1 + \lambda_2)}{\sqrt{\lambda_1\lambda_2}}"])
    else:
        doc.text(r"For this punch the edge integrals have closed forms, and")
        doc.math(rf"P_2 = {_nl(sp.factor(law.P2))} \tag{{SO.9}}")
        doc.math(rf"|\omega| = {_nl(law.contact_area.subs(sub))} \tag{{SO.10}}")
    if law.first.kind == "quadratic" and not elliptic:
        doc.text(r"that is, for the sphere, with the leading contact radius $a$:")
        P = r"P = P_0\left(1 - 4 m_1 \frac{H^2}{a^2} + 12 r_3 \frac{H^3}{a^3}\right),\quad "
        c = r"c = a - h^* H - m_1 \frac{H^2}{a}"
        if _numeric_layer(layer):
            k = edge_constants(layer)
            h2, h3, h2a = r"\frac{H^2}{a^2}", r"\frac{H^3}{a^3}", r"\frac{H^2}{a}"
            P = rf"P = P_0\left(1{_signed(-4 * k.m1, h2)}{_signed(12 * k.r3, h3)}\right),\quad "
            c = rf"c = a{_signed(-k.h_star, 'H')}{_signed(-k.m1, h2a)}"
        doc.math(P + c + r" \tag{SO.9--SO.10}")
    _numbers(doc, der, law)


def _term(coefficient: Any, factor: str) -> str:
    """`` + c X`` or `` - c X`` with the coefficient normalised; nothing when it is zero."""
    c = sp.factor(coefficient)
    if c == 0:
        return ""
    text = normal_latex(c)
    return (f" - {text[2:]}" if text.startswith("- ") else f" + {text}") + f" {factor}"


def _signed(x: float, factor: str) -> str:
    """`` + 0.5 X`` or `` - 0.5 X`` (six digits): a term of a sum; nothing when ``x`` is zero."""
    if x == 0:
        return ""
    return (" - " if x < 0 else " + ") + float_latex(abs(x), 6) + " " + factor


def _numbers(doc: Any, der: Any, law: Any) -> None:
    """The second-order force and area at the numbers of ``[contact]`` next to the first-order ones."""
    from ...asymptotics.second_order import second_order_law

    c = der.sections.get("contact")
    if c is None or "delta0" not in c:
        return
    layer = c.get("layer", der.layer)
    if not _numeric_layer(layer):
        return
    nu = c.get("nu", layer.numeric_nu)
    mu = c["mu"] if "mu" in c else (c["E"] / (2 * (1 + nu)) if nu is not None else None)
    if mu is None:
        return
    v = second_order_law(layer, der.punch).evaluate(c["delta0"], c["H"], mu, parameters=c["parameters"], nu=c.get("nu"))
    if not all(math.isfinite(x) for x in (v.force, v.area, v.P2)):
        return
    u = der.units or {}
    F = rf"\,{u['force']}" if "force" in u else ""
    L2 = "" if "length" not in u else rf"\,{unit_power(u['length'], 2)}"
    doc.text(r"At the numbers of the contact solution below (first order: $P_0 + P_1$ and (3.25)):")
    doc.lines([rf"P_0 + P_1 = {float_latex(v.force_first)}{F},\quad P_2 = {float_latex(v.P2)}{F},\quad "
               rf"P = {float_latex(v.force)}{F}",
               rf"|\omega| = {float_latex(v.area_first)}{L2} \ \text{{(first order)}},\quad "
               rf"|\omega| = {float_latex(v.area)}{L2} \ \text{{(second order)}}"])


def _table(doc: Any, nus: list) -> None:
    from ...asymptotics.second_order import edge_constants

    rows = []
    for value in nus:
        k = edge_constants(_layer_of(value))
        rows.append([_nu_label(value), f"${float_latex(k.h_star, DIGITS)}$", f"${float_latex(k.m1, DIGITS)}$",
                     f"${float_latex(k.r3, DIGITS)}$", f"${float_latex(k.sphere_coefficient, DIGITS)}$",
                     f"${float_latex(k.r3_spread, 2)}$"])
    doc.table(r"The constants of the second order (SO.4): the edge shift $h^*$, $m_1$ of (2.20), the cubic "
              r"Wiener--Hopf constant $r_3$ and the sphere's coefficient $12 r_3$ of $(H/a)^3$ in (SO.9). Check: "
              r"the largest difference of $r_3$ between three factorisations of $F$.", "lrrrrr",
              [r"$\nu$", "$h^*$", "$m_1$", "$r_3$", "$12 r_3$", "check"], rows, label="tab:r3")


def render(doc: Any, der: Any, context: Any) -> None:
    """Append the second-order sections to ``doc`` (a :class:`thinlayer.export.report.Document`)."""
    _boundary_layer(doc)
    _constants(doc, der.layer)
    _laws(doc, der)
    _table(doc, der.sections[KEY]["nu"])
