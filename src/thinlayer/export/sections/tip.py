r"""The report's section on a tip that is not a polynomial (issue 24): ``[punch] kind = "cone"``, ``"sphere"``,
``"blunted_cone"``, ``"power_law"``, ``"revolution"``, ``"pyramid"``, ``"polyhedral"`` (any kind of
:data:`thinlayer.punch.TIPS` whose tip is not a polynomial), its parameters in ``[punch]``, and an optional ``[tip]``
table for the comparison.

The section prints the profile, the thin-layer law (1.8) of the tip (:func:`thinlayer.asymptotics.tip_law.tip_force_law`
for a tip of revolution, :func:`thinlayer.asymptotics.pyramid_law.polyhedral_force_law` for a polyhedral one, each
law refusing the other's tips: ``P_0``, ``P_1`` and the order of the remainder with its source, the apex, the join or
the corners), whether an any-thickness law exists for the tip, and a table of the force against the depth: the tip
law with its estimate beside the direct solver (axisymmetric, or :func:`thinlayer.numerics.solve_2d` for a tip that is
not of revolution: its grid grows like ``(a/H)^2``, so its rows are ``a/H <= 12``, default 3, 5, 8).
"""
from __future__ import annotations

import math
from typing import Any

from .._normal import float_latex, normal_latex
from .base import DerivationFileError, short

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render", "tip_kinds", "tip_of"]

KEY = "tip"
SCHEMA = {"H": ((int, float), "the layer thickness of the table (> 0)"),
          "nu": ((int, float), "the Poisson ratio of the table when [layer] nu is symbolic, in (-1, 1/2)"),
          "c_over_H": ((list,), "a list of 1 to 12 contact radii over the thickness, in [2, 200] (rows of the "
                                "table)")}
ORDER = 65
#: the default rows of the table: contact radius (of the level set) over the thickness
DEFAULT_RATIOS = [3.0, 5.0, 10.0, 20.0, 40.0]
#: the rows of a tip that is not of revolution (the 2D direct solver, cells H/8) and their largest a/H
DEFAULT_RATIOS_2D, MAX_RATIO_2D = [3.0, 5.0, 8.0], 12.0


def tip_kinds() -> tuple[str, ...]:
    """The kinds of ``[punch] kind`` this section reads: the registered tips that are not polynomials and have a
    varying contact (every key of :data:`thinlayer.punch.TIPS` but the polynomial and flat ones).
    """
    from ...punch import TIPS

    return tuple(k for k in TIPS if k not in ("paraboloid", "elliptic_paraboloid", "fourth_degree", "polynomial",
                                              "flat"))


def tip_parameters() -> dict[str, tuple[tuple[type, ...], str]]:
    """The ``[punch]`` keys of the tip kinds (their parameters in the tip registry), for the file's schema."""
    from ...punch import TIPS

    out: dict[str, tuple[tuple[type, ...], str]] = {}
    for k in tip_kinds():
        for p in TIPS[k].parameters:
            out.setdefault(p.name, ((str, int, float), f"{p.description} (with kind = {k!r})"))
    return out


def tip_of(pu: dict) -> Any:
    """The tip of a ``[punch]`` table of a tip kind, its parameters as keys (one clear error otherwise)."""
    from ...punch import TIPS

    kind = pu["kind"]
    row = TIPS[kind]
    names = {p.name for p in row.parameters}
    extra = sorted(set(pu) - names - {"kind"})
    if extra:
        raise DerivationFileError(f"[punch] kind = {kind!r} takes the keys {sorted(names)}, not {extra}")
    missing = [p.name for p in row.parameters if p.name not in pu]
    if missing:
        raise DerivationFileError(f"[punch] kind = {kind!r} needs {', '.join(missing)} (the form is {row.form}; "
                                  f"valid kinds are paraboloid, elliptic_paraboloid, fourth_degree, flat and "
                                  f"{', '.join(tip_kinds())} with their parameters)")
    try:
        tip = row.constructor(**{p.name: pu[p.name] for p in row.parameters})
    except (ValueError, TypeError, ArithmeticError) as exc:
        raise DerivationFileError(f"[punch] kind = {kind!r}: {exc}") from None
    return tip


def parse(tt: Any, context: Any) -> dict | None:
    """``[punch]`` of a tip kind (the tip), with ``[tip]``: H, the table's nu and its rows ``c/H``."""
    pu = context.tables.get("punch", {})
    if pu.get("kind") not in tip_kinds():
        if tt is not None:
            raise DerivationFileError(f"[tip] is for [punch] kind = one of {list(tip_kinds())}")
        return None
    tip = tip_of(pu)
    tt = tt or {}
    H = tt.get("H", 1.0)
    if not (isinstance(H, (int, float)) and 0 < H < math.inf):
        raise DerivationFileError(f"[tip] H = {short(H)}: a positive number")
    layer_nu = context.layer.numeric_nu
    nu = tt.get("nu", 0.3 if layer_nu is None else float(layer_nu))
    if layer_nu is not None and "nu" in tt and float(tt["nu"]) != float(layer_nu):
        raise DerivationFileError(f"[tip] nu = {short(tt['nu'])} contradicts [layer] nu = {layer_nu}")
    if not -1 < nu < 0.5:
        raise DerivationFileError(f"[tip] nu = {short(nu)}: in (-1, 1/2) (the thin-layer law needs A != 0)")
    top = 200 if tip.axisymmetric else MAX_RATIO_2D
    ratios = tt.get("c_over_H", DEFAULT_RATIOS if tip.axisymmetric else DEFAULT_RATIOS_2D)
    if not (isinstance(ratios, list) and 0 < len(ratios) <= 12
            and all(isinstance(v, (int, float)) and not isinstance(v, bool) and 2 <= v <= top for v in ratios)):
        raise DerivationFileError(f"[tip] c_over_H = {short(ratios)}: a list of 1 to 12 numbers in [2, {top:g}]"
                                  + ("" if tip.axisymmetric else " (the 2D direct solver's grid grows like (a/H)^2)"))
    return {"tip": tip, "H": float(H), "nu": float(nu), "c_over_H": [float(v) for v in ratios]}


def applies(der: Any) -> bool:
    return der.sections.get(KEY) is not None


def _any_thickness_status(layer: Any, tip: Any, nu: float) -> str:
    from ...contact.models import MODEL_REGISTRY
    from ...contact.problem import Depth, Elastic, Frictionless, Problem

    problem = Problem(layer, tip, Elastic(1.0, nu), Frictionless(), Depth(1.0), 1.0, math.inf)
    for m in MODEL_REGISTRY:
        if m.name == "any-thickness" and m.fits and m.force_curve(problem) is not None:
            return (r"\emph{Any thickness.} The any-thickness model of \texttt{solve()} has a law for this tip "
                    r"(\texttt{model=\"any-thickness\"}).")
    from ...contact.fit import curve_entries

    base = layer.base or "bonded"
    solver = "axisymmetric" if tip.axisymmetric else "two-dimensional (FFT)"
    direct = "direct" in curve_entries(tip, nu, base)
    fits = (r", and \texttt{fit(model=\"direct\")} fits with it (tabulated)." if direct
            else r"; \texttt{fit()} has the thin-layer law only for this tip.")
    return (r"\emph{Any thickness.} No any-thickness law for this tip yet: where the thin-layer law's estimate "
            rf"exceeds the tolerance, \texttt{{solve()}} answers with the direct {solver} solver{fits}")


def _law(layer: Any, tip: Any) -> Any:
    """The tip's thin-layer law (1.8): the law of tips of revolution, else the polyhedral one (each refuses the
    other's tips with an InputError; neither: the last refusal, one line).
    """
    from ...asymptotics.pyramid_law import polyhedral_force_law
    from ...asymptotics.tip_law import tip_force_law
    from ...errors import InputError

    try:
        return tip_force_law(layer, tip)
    except InputError:
        return polyhedral_force_law(layer, tip)


def _depth_at(tip: Any, a: float) -> float:
    """The depth whose level set has ``a = 2|omega0|/|Gamma0|`` (the radius of a disc, the inradius of a regular
    polygon) equal to ``a``.
    """
    if tip.axisymmetric:
        return float(tip.radial_profile([a])[0])
    from scipy.optimize import brentq

    def f(d):
        ls = tip.level_set(d)
        return 2 * ls.area / ls.perimeter - a

    hi = 1.0
    while f(hi) < 0 and hi < 1e300:
        hi *= 2.0
    lo = hi
    while f(lo) > 0 and lo > 1e-300:
        lo *= 0.5
    return float(brentq(f, lo, hi, xtol=1e-300, rtol=1e-15))


def _direct_force(layer: Any, tip: Any, d0: float, H: float) -> float:
    """The direct solver's force at ``mu = 1`` (axisymmetric; else solve_2d with cells H/8 on a square around the
    level set).
    """
    from ...numerics import solve_2d, solve_axisymmetric

    if tip.axisymmetric:
        return solve_axisymmetric(layer, tip, d0, H=H, mu=1.0, error_estimate=False).force
    import numpy as np

    ext = 1.05 * float(np.abs(tip.polygon(d0)).max()) + 2.5 * H
    return solve_2d(layer, tip, delta0=d0, H=H, n=int(2 * ext / (H / 8)) + 1, extent=ext, tol=1e-10, mu=1.0).force


def render(doc: Any, der: Any, context: Any) -> None:
    """Append the tip section to ``doc``."""
    from ...contact.models import MODEL_REGISTRY
    from ...contact.problem import Depth, Elastic, Frictionless, Problem

    spec = der.sections[KEY]
    tip, layer = spec["tip"], der.layer
    law = _law(layer, tip)
    order = tip.max_inner_order
    if tip.axisymmetric:
        doc.section(f"Tip of revolution: {tip.name}")
        doc.text(r"A rigid tip of revolution $x_3 = -\Phi(r)$ that is not a polynomial, so that the inner expansion "
                 r"(2.26) holds only as far as $\Delta^k \Phi$ is integrable over the contact disc (at an apex "
                 r"$\Phi \sim C r^n$, $\Delta^k\Phi \sim r^{n-2k}$):")
        level = r"of radius $a$, with $V = \iint(\delta_0 - \Phi)_+$ and $J = \oint|\nabla\Phi|\,ds = 2\pi a \Phi'(a)$"
    else:
        doc.section(f"Polyhedral tip: {tip.description}")
        doc.text(r"A rigid polyhedral tip $x_3 = -\Phi(x_1, x_2)$, a maximum of planes: $\Phi$ is homogeneous of "
                 r"degree 1 with ridges, $\Delta\Phi$ a line measure on them, so the inner expansion (2.26) holds to "
                 r"order 1 away from the apex and the corners of the contact polygon:")
        level = (r"(a polygon of inradius $a = 2|\omega_0|/|\Gamma_0|$), with $V = \iint(\delta_0 - \Phi)_+$ and "
                 r"$J = \oint|\nabla\Phi|\,ds = \cot(\alpha)|\Gamma_0|$ (the mass of $\Delta\Phi$ on the ridges)")
    doc.math(tip.latex())
    doc.text(rf"Inner expansion: to order {'unlimited' if order is None else order} (smoothness at the apex: "
             rf"{tip.smoothness}). The force law (1.8) through the level set $\{{\Phi < \delta_0\}}$ {level}, is")
    doc.math(law.latex())
    sources = (law.remainder_sources.replace("_", r"\_").replace("^", r"\^{}")
               .replace("~", r"\ensuremath{\sim}"))
    doc.text(rf"Order of the remainder: $O(P_0 (H/a)^{{{law.remainder_order:g}}})$, from {sources}.")
    doc.text(_any_thickness_status(layer, tip, spec["nu"]))
    # the table: tip law (with its estimate) against the direct solver at depths of given c/H
    H, nu = spec["H"], spec["nu"]
    lay = layer if layer.numeric_nu is not None else layer.with_nu(nu)
    problem = Problem(lay, tip, Elastic(1.0, nu), Frictionless(), Depth(1.0), H, math.inf)
    curve = next(c for c in (m.force_curve(problem) for m in MODEL_REGISTRY if m.name == "tip-law") if c is not None)
    rows, worst = [], 0.0
    for k in spec["c_over_H"]:
        d0 = _depth_at(tip, k * H)  # the depth whose level set has a = k H
        if not math.isfinite(d0):
            continue
        P = float(curve.force([d0])[0])
        est = float(curve.estimate([d0])[0])
        ref_force = _direct_force(lay, tip, d0, H)
        err = abs(P / ref_force - 1)
        worst = max(worst, err / est if est > 0 else math.inf)
        rows.append([f"${float_latex(k, 4)}$", f"${float_latex(d0, 6)}$", f"${float_latex(P, 8)}$",
                     f"${float_latex(ref_force, 8)}$", f"${float_latex(err, 2)}$", f"${float_latex(est, 2)}$"])
    head = ["$a/H$", r"$\delta_0$", r"$P$ (tip law)", r"$P$ (direct)", "difference", "estimate"]
    doc.table(rf"Force at $\mu = 1$ of the {tip.name} on the layer ($\nu = {float_latex(nu, 4)}$, $H = "
              rf"{float_latex(H, 4)}$): the thin-layer law (1.8) with its estimate against the direct "
              rf"{'axisymmetric' if tip.axisymmetric else 'two-dimensional (cells $H/8$)'} solver of (1.5)--(1.8); "
              rf"the largest difference is "
              rf"${float_latex(worst, 2)}$ times its estimate.", "rrrrrr", head, rows, label="tab:tip-force")
    _ = normal_latex  # the laws above print through the report's normalisation (TipForceLaw.latex)
