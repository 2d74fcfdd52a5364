r"""The report's section on adhesion (JKR) of the sphere on the layer (J.1)-(J.24), from an ``[adhesion]`` table.

The laws are the engine's own derivations: the superposition and the energy release rate (J.1)-(J.5)
(:mod:`thinlayer.numerics.adhesion`), the thin-layer JKR law (J.7)-(J.15) and its second-order depth (J.24)
(:func:`thinlayer.asymptotics.adhesion.adhesion_derivation`, :func:`~thinlayer.asymptotics.adhesion.thin_layer_jkr`),
the two-term law near nu = 1/2 (J.19)-(J.23) (:mod:`thinlayer.asymptotics.adhesion_two_term`, for a bonded layer
with ``1/4 < nu <= 1/2``) and the any-thickness law (J.16)-(J.18) (:mod:`thinlayer.contact.adhesion_sphere`),
whose pull-off forces over ``H/R`` are tabulated and whose JKR curves on the layer are drawn against the
half-space's (JKR 1971).

``[adhesion]`` keys: ``work_of_adhesion`` (required, ``> 0``, in the units of [units]: stress times length),
``R`` (the sphere's radius; default ``[contact] parameters.R`` or 1), ``mu`` (default ``[contact] mu`` or 1) and
``H_over_R`` (the thicknesses of the table and the figure, 1 to 8 values in ``[1e-3, 1e3]``).
"""
from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from .base import DerivationFileError, nl, num, paraboloid_of_revolution, short

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render", "figure_files", "ADHESION_DEFAULT_H_OVER_R",
           "FIGURE"]

KEY = "adhesion"
SCHEMA = {"work_of_adhesion": ((int, float), "a number > 0 (stress times length, in the units of [units])"),
          "R": ((int, float), "the sphere's radius, a number > 0"),
          "mu": ((int, float), "the shear modulus, a number > 0"),
          "H_over_R": ((list,), "a list of 1 to 8 thickness over radius values in [0.001, 1000]")}
ORDER = 105
#: the thicknesses of the pull-off table and the figure by default
ADHESION_DEFAULT_H_OVER_R = [0.03, 0.1, 0.3, 1.0, 3.0]
#: the figure's file name in the report's figure folder
FIGURE = "adhesion_jkr.pdf"


def _positive(tab: dict, key: str, default: float) -> float:
    val = tab.get(key, default)
    if isinstance(val, bool) or not isinstance(val, (int, float)) or not (math.isfinite(val) and val > 0):
        raise DerivationFileError(f"[adhesion] {key} = {short(val)} is invalid: expected a finite number > 0")
    return float(val)


def parse(tab: Any, context: Any) -> dict | None:
    """``[adhesion]``: the work of adhesion (required), R, mu and H/R values, checked; the punch a paraboloid of
    revolution and the layer on a rigid base with a numeric Poisson ratio.
    """
    if tab is None:
        return None
    if "work_of_adhesion" not in tab:
        raise DerivationFileError("[adhesion] work_of_adhesion is required: a number > 0 (the JKR work of adhesion)")
    punch, layer = context.punch, context.layer
    if not paraboloid_of_revolution(punch):
        raise DerivationFileError("[adhesion] is derived for the paraboloid of revolution r^2/(2R): give [punch] "
                                  "kind = \"paraboloid\"")
    if not layer.on_rigid_base or not layer.has_thickness or (layer.numeric_nu is None
                                                              and not layer.shear_free_base):
        raise DerivationFileError("[adhesion] needs a layer on a rigid base with a numeric Poisson ratio ([layer] "
                                  "model = \"bonded\" with nu, \"incompressible\" or \"frictionless\")")
    contact = context.tables.get("contact", {})
    out = {"work_of_adhesion": _positive(tab, "work_of_adhesion", 0.0),
           "R": _positive(tab, "R", contact.get("parameters", {}).get("R", 1.0)),
           "mu": _positive(tab, "mu", contact.get("mu", 1.0))}
    vals = tab.get("H_over_R", ADHESION_DEFAULT_H_OVER_R)
    good = (isinstance(vals, list) and 0 < len(vals) <= 8 and all(
        isinstance(v, (int, float)) and not isinstance(v, bool) and 1e-3 <= v <= 1e3 for v in vals))
    if not good:
        raise DerivationFileError(f"[adhesion] H_over_R = {short(vals)}: a list of 1 to 8 numbers in [0.001, 1000]")
    out["H_over_R"] = sorted(float(v) for v in vals)
    return out


def applies(der: Any) -> bool:
    return der.sections.get(KEY) is not None


def figure_files(der: Any, folder: Path) -> list[Path]:
    """The figure :func:`render` writes into ``folder`` (checked before anything is written)."""
    return [Path(folder) / FIGURE]


def _layer_nu(layer: Any) -> tuple[Any, float]:
    if layer.shear_free_base:
        return layer, 0.3 if layer.numeric_nu is None else float(layer.numeric_nu)
    return layer, float(layer.numeric_nu)


def _curves(layer: Any, nu: float, tab: dict) -> tuple[list, list]:
    """``[(H/R, radii, P, delta, pull-off, its error)]`` of the any-thickness law and the half-space's JKR curve."""
    import numpy as np

    from ...contact.adhesion_sphere import any_thickness_jkr

    R, mu, w = tab["R"], tab["mu"], tab["work_of_adhesion"]
    law = any_thickness_jkr(layer, nu if layer.numeric_nu is None else None)
    Es = 2 * mu / (1 - nu)
    a0 = (9 * math.pi * w * R * R / (2 * Es)) ** (1 / 3)  # JKR (1971): the contact radius at zero load
    radii = a0 * np.geomspace(0.05, 2.0, 60)
    rows = []
    for hr in tab["H_over_R"]:
        d, P = law.evaluate(radii, hr * R, R, w, mu)
        c, P_off, err = law.pull_off(hr * R, R, w, mu)
        rows.append((hr, radii, P, d, P_off, err))
    half = (radii, 4 * Es * radii**3 / (3 * R) - np.sqrt(8 * math.pi * w * Es * radii**3),
            radii**2 / R - np.sqrt(2 * math.pi * w * radii / Es))
    return rows, [half]


def _draw(rows: list, half: tuple, scale: float, R: float, path: Path, force: bool) -> str:
    """The figure (P over pi w R against c/R) as PDF; '' or why it is omitted."""
    if path.exists() and not force:
        return f"{path.name} exists (write the report with force/--overwrite to replace it)"
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return "matplotlib is not installed"
    fig, ax = plt.subplots(figsize=(6.0, 3.6))
    for hr, radii, P, _, _, _ in rows:
        ax.plot(radii / R, P / scale, label=rf"$H/R = {hr:g}$")
    ax.plot(half[0] / R, half[1] / scale, "k--", label="half-space (JKR 1971)")
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set_xlabel(r"contact radius $c/R$")
    ax.set_ylabel(r"force $P/(\pi w R)$")
    ax.set_ylim(-2.2, 4.0)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path)
    plt.close(fig)
    return ""


def _two_term(doc: Any, nu: float) -> None:
    """The two-term JKR law (J.19)-(J.22) of the nearly incompressible bonded layer, with its assumptions."""
    from ...asymptotics.adhesion_two_term import two_term_jkr

    law = two_term_jkr(nu)
    m1 = "\\infty" if law.A == 0 else num(law.m1, 6)
    doc.text(r"\emph{Nearly incompressible thin layer: the two-term model.} Near $\nu = 1/2$ the compressible law "
             r"(J.11) needs $\lambda^2 = (c/H)^2/m_1 \gg 1$ and the incompressible one (J.15) $\lambda^2 \ll 1$ "
             r"(I.13); "
             r"the two-term model (I.10), $(H/\vartheta)(\mathcal{A} p - \mathcal{A} m_1 H^2 \Delta p) = \delta - "
             r"\Phi$, holds for every $\lambda$. Assumptions: as above, the layer bonded, $1/4 < \nu \le 1/2$ "
             r"($m_1 > 0$), $c \gg H$. The smooth part is the two-term sphere (I.11) at the model edge "
             r"$a_e = c + hH$ ($h$ of (I.12)); the flat part solves (I.10) with $p(a_e) = 0$ (the edge is fixed), "
             r"$k^2 = 1/(m_1 H^2)$, $c_1 = \mathcal{A} m_1$, and (J.4) gives $G$:")
    for _, tex in law.derivation.steps():
        doc.math(tex)
    doc.text(r"with $\psi = (x I_0/I_1 - 2)/x^2$, $\chi = (1/4 - \psi)/x^2$ of (I.11) and $\psi_F = "
             r"8(1 - 2 I_1/(x I_0))/x^2$ of (F.15). As $x \to 0$ this is (J.15) exactly; as $x \to \infty$ "
             r"(Hankel's expansion) $G$ is (J.10) to $O(H/c)$ and $\delta_1$ is (J.11) plus the $m_1 H^2/R$ of the "
             r"second order (J.24), both checked in \texttt{sympy}. Against the direct solver at "
             r"$\nu = 0.45$, $0.49$, $0.499$ and $c/H = 5$ to $40$ the two-term law's error falls like $(H/c)^3$ "
             r"(at $c/H = 20$: $3\times 10^{-4}$ to $10^{-2}$ in $\delta$) where (J.11) and (J.15) err by tens of "
             rf"percent. Here $\nu = {num(nu, 6)}$: $m_1 = {m1}$, $h = {num(law.h, 8)}$, $c_1 = {num(law.c1, 8)}$.")


def render(doc: Any, der: Any, context: Any) -> None:
    """Append the adhesion section to ``doc`` (a :class:`thinlayer.export.report.Document`)."""
    from ...asymptotics.adhesion import adhesion_derivation, thin_layer_jkr
    from .base import incompressible_bonded

    tab = der.sections[KEY]
    layer, nu = _layer_nu(der.layer)
    R, w = tab["R"], tab["work_of_adhesion"]
    doc.section("Adhesion: JKR contact of the sphere on the layer").text(
        r"Assumptions: the paraboloid $\Phi = r^2/(2R)$, frictionless contact, the layer bonded to (or lying on) a "
        r"rigid base, JKR adhesion (a short-range attraction: the work of adhesion $w$ is spent at the contact edge, "
        r"the pressure may be tensile inside the contact). (J.$n$) numbers this extension of \texttt{thinlayer}, as "
        r"in its modules \texttt{numerics.adhesion}, \texttt{asymptotics.adhesion} and "
        r"\texttt{contact.adhesion\_sphere}.")
    doc.text(r"\emph{Superposition at a fixed contact radius.} At the contact radius $c$ the problem is linear in the "
             r"depth: the smooth-edge (non-adhesive) state at $c$ plus a flat punch of radius $c$ pressed to "
             r"$d \le 0$, whose edge is singular; the energy release rate follows from the flat punch's compliance, "
             r"and $G = w$ fixes $d$:")
    doc.math(r"\delta = \delta_1(c) + d,\quad P = P_1(c) + S(c)\,d,\quad S(c) = 4\vartheta c\,\kappa(c/H) \tag{J.1}")
    doc.math(r"G = \frac{d^2 S'(c)}{4\pi c} = \frac{\vartheta d^2}{\pi c}\,\frac{d(\lambda\kappa)}{d\lambda} = "
             r"\frac{\vartheta d^2 f(1)^2}{\pi c} = w,\quad \lambda = \frac{c}{H} \tag{J.4}")
    if incompressible_bonded(layer):
        law = thin_layer_jkr(0.5, 1)
        doc.text(r"\emph{Thin incompressible layer} ($\nu = 1/2$): the smooth part from the operator (I.2), the flat "
                 r"part from (F.14) and Krein's identity (F.9), at first order in the edge correction $h$ (I.12), "
                 r"$a_e = c + hH$:")
        doc.group([rf"\delta = {nl(law.depth_display)}", rf"P = {nl(law.force_display)}"], "J.15")
    elif layer.shear_free_base:
        doc.text(r"\emph{Thin layer.} The thin-layer JKR law (J.8)--(J.15) is derived for the bonded base; on the "
                 r"frictionless base the any-thickness law below answers at every thickness.")
    else:
        der_adh = adhesion_derivation(nu)
        hs, edge = der_adh.half_space, der_adh.edge_layer
        doc.text(r"\emph{Half-space} ($\mathcal{L} = 1$, $E^* = 2\vartheta$): the superposition gives JKR (1971), "
                 r"with the pull-off forces under load and displacement control:")
        doc.group([rf"P = {nl(hs.force)}", rf"\delta = {nl(hs.depth)}",
                   rf"P_{{\mathrm{{off}}}} = {nl(hs.pull_off_load)}\ (\text{{load}}),\quad "
                   rf"{nl(hs.pull_off_displacement)}\ (\text{{displacement}})"], "J.7")
        doc.text(r"\emph{Thin compressible layer.} Near the edge the outer pressure is $p_e + p_s n$; the adhesive "
                 r"edge layer, solved by the Wiener--Hopf factorisation of the boundary layer (3.15)--(3.22), gives "
                 r"the stress intensity and the energy release rate (the new layer constant is $\sqrt{2\mathcal{A}}$"
                 rf"; here $\mathcal{{A}} = {num(edge.A, 8)}$, $h^* = {num(edge.h, 8)}$):")
        doc.group([rf"K_I = {nl(edge.stress_intensity_expr)}", rf"G = {nl(edge.release_rate_expr)}"], "J.8")
        doc.text(r"With the curvature of the edge (the flat part's compliance, (J.10)) and $G = w$, the thin-layer JKR "
                 r"law of the paraboloid at order 0 ($a_e = c$) and order 1 ($a_e = c + h^* H$), its pull-off force "
                 r"at order 0, and Kendall's thin-film detachment force of a flat punch of radius $c$ with its first "
                 r"correction:")
        for law in der_adh.jkr:
            doc.group([rf"G = {nl(law.release_rate)} = w",
                       rf"\delta = {nl(law.depth_display)}", rf"P = {nl(law.force_display)}"], "J.11")
        doc.group([rf"P_{{\mathrm{{off}}}} = {nl(der_adh.jkr[0].pull_off_leading)}"], "J.12")
        doc.group([rf"P_{{\mathrm{{off}}}} = {nl(der_adh.flat.force)}"], "J.13")
        law2 = thin_layer_jkr(nu, 2)
        doc.text(r"\emph{Next order.} The edge shift at second order (SO.5) puts the smooth contact edge at "
                 r"$c = a - h^* H - m_1 H^2/a$; inverted, $a(c) = c + h^* H + m_1 H^2/c$ gives $\delta_1$ to relative "
                 r"$O((H/c)^3)$. The flat punch's stiffness $\kappa = (\pi/(4\mathcal{A}))(\lambda + 2h^* + C_2/\lambda"
                 r" + \dots)$ (F.11) enters $G$ through $S'(c)$, where $C_2$ drops out: $G$ of (J.10) is right to "
                 r"$O((H/c)^2)$, and the force of order 1 already is (its $m_1$ terms cancel, (SO.8)--(SO.9)). The "
                 r"depth to the next order (the force unchanged; its next order needs the contact radius to "
                 rf"$O(H^3/a^2)$, not derived), with $m_1 = {num(law2.m1, 8)}$:")
        doc.group([rf"\delta = {nl(law2.depth_display)},\quad a_e = c + h^* H,\quad a_2 = a_e + \frac{{m_1 H^2}}{{c}}"],
                  "J.24")
    if not layer.shear_free_base and 0.25 < nu <= 0.5:
        _two_term(doc, nu)
    doc.text(r"\emph{Any thickness.} $\delta_1$, $P_1$ from the sphere's any-thickness law (T.7) at the contact "
             r"radius $c$; $\kappa$ and $g = d(\lambda\kappa)/d\lambda$ from the flat punch (F.6)--(F.18); the "
             r"error estimate (J.18) adds the ingredients' own:")
    doc.math(r"\delta = \delta_1(c) - \sqrt{\frac{\pi c w}{\vartheta\, g(c/H)}},\quad P = P_1(c) - 4\vartheta c\,"
             r"\kappa(c/H)\sqrt{\frac{\pi c w}{\vartheta\, g(c/H)}} \tag{J.16}")
    rows, (half,) = _curves(layer, nu, tab)
    scale = math.pi * w * R
    thin = 3.0 if incompressible_bonded(layer) else 2.0
    body = [[f"${num(hr, 4)}$", f"${num(P_off / scale, 6)}$", f"${num(err / scale, 2)}$"]
            for hr, _, _, _, P_off, err in rows]
    lead = "" if layer.shear_free_base else (rf"; the thin-layer leading value (J.12) is ${num(thin, 2)}$ "
                                             r"(the bonded layer)")
    doc.table(rf"Pull-off force under load control, $P_{{\mathrm{{off}}}}/(\pi w R)$, of the sphere on the layer "
              rf"against $H/R$ by the any-thickness law (J.16), with its estimate (J.18); $w = {num(w, 6)}$, "
              rf"$R = {num(R, 6)}$, $\mu = {num(tab['mu'], 6)}$. The half-space (JKR 1971) gives $1.5${lead}.",
              "rrr", ["$H/R$", r"$P_{\mathrm{off}}/(\pi w R)$", "estimate"], body, label="tab:adhesion-pull-off")
    if context.figure_dir is None:
        return
    why = _draw(rows, half, scale, R, Path(context.figure_dir) / FIGURE, context.force)
    if why:
        doc.text(rf"(Figure omitted: {why}.)")
        return
    doc.figure(f"{Path(context.figure_dir).name}/{FIGURE}",
               r"The JKR curve $P(c)$ of the sphere on the layer by the any-thickness law (J.16) for each $H/R$ of "
               r"the table (solid) against the half-space's, JKR (1971) (dashed): the thinner the layer, the stiffer "
               r"the contact and the larger the pull-off force, up to the thin-layer value (J.12).")
