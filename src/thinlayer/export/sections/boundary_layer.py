r"""The report's sections on the boundary layer (3.15)-(3.25) and the force law (1.8) with the contact area (3.25).

For the frictionless base the exact edge shift (Wiener--Hopf) is tabulated beside Alexandrov's (3.25).
"""
from __future__ import annotations

from typing import Any

import sympy as sp

from ... import symbols as S
from .base import SEPARATOR, incompressible_bonded, nl, num, signed_sum

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render", "alexandrov_generic_latex"]

KEY = None
SCHEMA: dict = {}
ORDER = 30


def parse(table: Any, context: Any) -> None:
    return None


def applies(der: Any) -> bool:
    return der.punch is not None and not incompressible_bonded(der.layer)


def alexandrov_generic_latex() -> str:
    """(3.19)-(3.25) with A, B, C, m_1 as symbols (the nu-dependent closed forms are unreadably long)."""
    from ...asymptotics.boundary_layer import AlexandrovParameters, AlexandrovSolution

    A = sp.Symbol(r"\mathcal{A}", positive=True)
    B, C = sp.symbols("B C", positive=True)
    m1 = sp.Symbol("m_1", real=True)
    par = AlexandrovParameters(A=A, m1=m1, B=B, C=C)
    rows = [rf"\tilde{{\mathcal{{L}}}}(s) = {sp.latex(S.s * par.symbol())} \tag{{3.19}}",
            r"B = \frac{1}{\mathcal{A} + \sqrt{\mathcal{A}^2 + 2 m_1}}, \quad "
            r"C = \frac{B}{\mathcal{A}} \tag{3.20--3.21}",
            AlexandrovSolution(par, 1 / sp.sqrt(C) - 1 / (2 * B)).latex()]
    return SEPARATOR.join(rows)


def render(doc: Any, der: Any, context: Any) -> None:
    from ...asymptotics.boundary_layer import AlexandrovParameters, AlexandrovSolution
    from ...asymptotics.force_law import boundary_layer_force_defect, force_law

    layer, punch = der.layer, der.punch
    law = force_law(layer, punch)
    A = sp.Symbol(r"\mathcal{A}", positive=True)
    B, C = sp.symbols("B C", positive=True)
    m1 = sp.Symbol("m_1", real=True)
    tau, h = sp.Symbol(r"\tau", positive=True), sp.Symbol("h", real=True)
    doc.section("Boundary layer").text(
        r"Near the edge of the contact area the inner expansion fails; the boundary layer (3.15)--(3.18) is "
        r"solved with Alexandrov's approximation of the kernel~\cite{alexandrov}, (3.19), whose constants $B$ and $C$ "
        r"match $\mathcal{A}$ and $m_1$, (3.20) and (3.21) (the latter corrected, see Errata):")
    sol = AlexandrovSolution(AlexandrovParameters(A=A, m1=m1, B=B, C=C), 1 / sp.sqrt(C) - 1 / (2 * B))
    s = sp.Symbol("s")
    doc.math(rf"\tilde{{\mathcal{{L}}}}(s) = {nl(sp.S.One * s * sp.sqrt(B**2 + s**2) / (C + s**2))} \tag{{3.19}}")
    doc.math(r"B = \frac{1}{\mathcal{A} + \sqrt{\mathcal{A}^2 + 2 m_1}},\quad C = \frac{B}{\mathcal{A}}"
             r" \tag{3.20--3.21}")
    lhs = r"\frac{\mathcal{A}\,\tilde q^{**}}{\vartheta H_* b_1^*}"
    doc.text(r"The boundary-layer pressure for an edge at $v = h$, (3.23); the edge condition (3.18), "
             r"$\tilde q^{**} = 0$ at the edge, fixes $h = h^*$ of (3.25) below and gives its form in the edge "
             r"variable $v$, (3.24):")
    doc.math(rf"{lhs}(s, h + \tau) = {nl(sol.q_general(tau, h))} \tag{{3.23}}")
    h_star = sp.Symbol("h^*", real=True)
    doc.math(rf"{lhs}(s, v) = {nl(AlexandrovSolution(sol.params, h_star).q(sp.Symbol('v', real=True)))} \tag{{3.24}}")
    doc.text(r"so that the contact edge lies the distance $h^* H$ inside the leading contour $\Gamma_0$, (3.25):")
    doc.math(rf"h^* = {nl(1 / sp.sqrt(C) - 1 / (2 * B))} \tag{{3.25}}")
    force_words = ("the first correction is of relative order $(H/a)^3$, since $m_1 = 0$"
                   if layer.base == "frictionless" else "with the correction of relative order $(H/a)^2$")
    doc.section("Force and contact area").text(
        rf"The force is the integral of the inner terms $p_0 + p_1$ plus the force defect of the boundary layer, "
        rf"{force_words}; $a$ is the contact half-width. The defect of the boundary layer,")
    defect = nl(boundary_layer_force_defect())
    doc.math(rf"\int_{{-\infty}}^{{\infty}}\left(\hat Q(v) - \max(v, 0)\right) dv = {defect}")
    doc.text(r"gives the force law (1.8) for any punch,")
    rem_P = r" + O\!\left(P_0 \frac{H^3}{a^3}\right)"
    rem_A = r" + O\!\left(|\omega_0| \frac{H^2}{a^2}\right)"
    th = layer.vartheta
    general = signed_sum([(th / (layer.A * S.H), r"\iint_{\omega_0}(\delta_0 - \Phi)\,d\mathbf{x}"),
                          (law.coefficient, r"\oint_{\Gamma_0}|\nabla\Phi|\,ds")])
    doc.math(rf"P = {general}{rem_P} \tag{{1.8}}")
    if law.P0 is not None:
        rel = sp.factor(sp.cancel(law.P1 / law.P0))
        corr = rf"\left({signed_sum([(sp.S.One, ''), (rel, '')])}\right)" if rel != 0 else ""
        doc.text(r"and, for this punch, in closed form, with the contact area (3.25) ($h^*$ the edge shift):")
        doc.math(rf"P = {nl(law.P0)}{corr}{rem_P} \tag{{1.8}}")
        area = signed_sum([(law.area0, ""), (-S.H * law.perimeter, "h^*")])
        doc.math(rf"|\omega| = {area}{rem_A} \tag{{3.25}}")
    else:
        doc.math(r"|\omega| = |\omega_0| - h^* H |\Gamma_0|" + rem_A + r" \tag{3.25}")
    if layer.base == "frictionless":
        from ...asymptotics.wiener_hopf import edge_shift_alexandrov, edge_shift_exact

        doc.table(r"Edge shift of the frictionless base: exact (Wiener--Hopf) and Alexandrov's "
                  r"(3.25)~\cite{alexandrov}.", "rr",
                  [r"$h^*$ exact", r"$h^*$ (3.25)"],
                  [[f"${num(edge_shift_exact(layer), 8)}$", f"${num(edge_shift_alexandrov(layer), 8)}$"]])
