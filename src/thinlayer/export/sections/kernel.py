r"""The report's sections on the layer: its kernel (2.3), the coefficients (2.4), (2.20), (4.2), the kernel moments
(2.21) and the moment expansion (2.22).  The incompressible layer (A = 0) has the kernel only: its Maclaurin data
are the section of :mod:`thinlayer.export.sections.incompressible`.
"""
from __future__ import annotations

from typing import Any

import sympy as sp

from .base import incompressible_bonded, nl, nu_latex, num, signed_sum

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render"]

KEY = None  # [coefficients] order is a core table (the incompressible section reads it too)
SCHEMA: dict = {}
ORDER = 10


def parse(table: Any, context: Any) -> None:
    return None


def applies(der: Any) -> bool:
    return True


def render(doc: Any, der: Any, context: Any) -> None:
    from ...asymptotics.moment_expansion import moment_expansion
    from ...layers.coefficients import kernel_coefficients
    from ...layers.moments import kernel_moment

    layer = der.layer
    nu = nu_latex(layer)
    base = "bonded to" if layer.base == "bonded" else "lying without friction on"
    ratio = "" if nu == r"\nu" else rf", with Poisson ratio $\nu = {nu}$"
    doc.section("Layer kernel").text(rf"The layer of thickness $H$ is {base} a rigid base{ratio}. Its kernel, (2.3):")
    doc.math(rf"\mathcal{{L}}(u) = {nl(layer.L())} \tag{{2.3}}")
    if incompressible_bonded(layer):
        return
    order = der.coefficient_order
    co = kernel_coefficients(layer, order)
    doc.section("Coefficients of the kernel").text(
        r"The Maclaurin series $\mathcal{L}(s)/s = \mathcal{A}(1 + m_1 s^2 + m_2 s^4 + \dots)$, (2.4) and (2.20), "
        r"and its reciprocal $s/\mathcal{L}(s) = \mathcal{A}^{-1}(1 + M_1 s^2 + M_2 s^4 + \dots)$, (4.2), computed "
        r"by series arithmetic on (2.3):")
    doc.math(rf"\mathcal{{A}} = {nl(co.A_expr)} \tag{{2.4}}")
    doc.group([rf"m_{{{n}}} = {nl(co.m_expr(n))}" for n in range(1, order + 1)], "2.20")
    doc.group([rf"M_{{{n}}} = {nl(co.M_expr(n))}" for n in range(1, order + 1)], "4.2")
    if not layer.symbolic_coefficients and layer.parameter is None:
        rows = [[f"${n}$", f"${num(co.m[n])}$", f"${num(co.M[n])}$"] for n in range(1, order + 1)]
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
        rows += [" = ".join(names) + f" = {nl(val)}" for val, names in seen.items()]
    doc.group(rows, "2.21")
    me = moment_expansion(layer, min(2, order))
    ops = [r"\Lambda^{-2}\delta(\boldsymbol{\xi})", r"\Lambda^{-4}\Delta\delta(\boldsymbol{\xi})",
           r"\Lambda^{-6}\Delta^{2}\delta(\boldsymbol{\xi})"]
    doc.text(r"and the moment asymptotic expansion of the kernel, (2.22):")
    doc.math(r"k(\Lambda\boldsymbol{\xi}) \sim " + signed_sum(list(zip(me.weights(), ops))) + r" + \dots \tag{2.22}")
