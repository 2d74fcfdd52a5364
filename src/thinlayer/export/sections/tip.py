r"""The report's section on a tip of revolution that is not a polynomial (issue 24): ``[punch] kind = "cone"``,
``"sphere"``, ``"blunted_cone"``, ``"power_law"``, ``"revolution"`` (any kind of :data:`thinlayer.punch.TIPS` whose tip
is not a polynomial), its parameters in ``[punch]``, and an optional ``[tip]`` table for the comparison.

The section prints the profile, the thin-layer law (1.8) of the tip
(:func:`thinlayer.asymptotics.tip_law.tip_force_law`: ``P_0``, ``P_1`` and the order of the remainder with its source,
the apex or the join), whether an any-thickness law exists for the tip, and a table of the force against the depth:
the tip law with its estimate beside the direct axisymmetric solver (the independent reference).
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
    if not tip.axisymmetric:
        raise DerivationFileError(f"[punch] kind = {kind!r}: the report's tip section is for tips of revolution")
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
    ratios = tt.get("c_over_H", DEFAULT_RATIOS)
    if not (0 < len(ratios) <= 12 and all(isinstance(v, (int, float)) and not isinstance(v, bool) and 2 <= v <= 200
                                          for v in ratios)):
        raise DerivationFileError(f"[tip] c_over_H = {short(ratios)}: a list of 1 to 12 numbers in [2, 200]")
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
    return (r"\emph{Any thickness.} No any-thickness law for this tip yet: where the thin-layer law's estimate "
            r"exceeds the tolerance, \texttt{solve()} answers with the direct axisymmetric solver, and "
            r"\texttt{fit(model=\"direct\")} fits with it (tabulated).")


def render(doc: Any, der: Any, context: Any) -> None:
    """Append the tip section to ``doc``."""
    from ...asymptotics.tip_law import tip_force_law
    from ...contact.models import MODEL_REGISTRY
    from ...contact.problem import Depth, Elastic, Frictionless, Problem
    from ...numerics import solve_axisymmetric

    spec = der.sections[KEY]
    tip, layer = spec["tip"], der.layer
    law = tip_force_law(layer, tip)
    order = tip.max_inner_order
    doc.section(f"Tip of revolution: {tip.name}")
    doc.text(r"A rigid tip of revolution $x_3 = -\Phi(r)$ that is not a polynomial, so that the inner expansion "
             r"(2.26) holds only as far as $\Delta^k \Phi$ is integrable over the contact disc (at an apex "
             r"$\Phi \sim C r^n$, $\Delta^k\Phi \sim r^{n-2k}$):")
    doc.math(tip.latex())
    doc.text(rf"Inner expansion: to order {'unlimited' if order is None else order} (smoothness at the apex: "
             rf"{tip.smoothness}). The force law (1.8) through the level set $\{{\Phi < \delta_0\}}$ of radius $a$, "
             r"with $V = \iint(\delta_0 - \Phi)_+$ and $J = \oint|\nabla\Phi|\,ds = 2\pi a \Phi'(a)$, is")
    doc.math(law.latex())
    sources = (law.remainder_sources.replace("_", r"\_").replace("^", r"\^{}")
               .replace("~", r"\ensuremath{\sim}"))
    doc.text(rf"Order of the remainder: $O(P_0 (H/a)^{{{law.remainder_order:g}}})$, from {sources}.")
    doc.text(_any_thickness_status(layer, tip, spec["nu"]))
    # the table: tip law (with its estimate) against the direct solver at depths of given c/H
    H, nu = spec["H"], spec["nu"]
    lay = layer if layer.numeric_nu is not None else layer.with_nu(nu)
    entry = next(m for m in MODEL_REGISTRY if m.name == "tip-law")
    curve = entry.force_curve(Problem(lay, tip, Elastic(1.0, nu), Frictionless(), Depth(1.0), H, math.inf))
    rows, worst = [], 0.0
    for k in spec["c_over_H"]:
        d0 = float(tip.radial_profile([k * H])[0])  # the depth whose level set has radius a = k H
        if not math.isfinite(d0):
            continue
        P = float(curve.force([d0])[0])
        est = float(curve.estimate([d0])[0])
        ref = solve_axisymmetric(lay, tip, d0, H=H, mu=1.0, error_estimate=False)
        err = abs(P / ref.force - 1)
        worst = max(worst, err / est if est > 0 else math.inf)
        rows.append([f"${float_latex(k, 4)}$", f"${float_latex(d0, 6)}$", f"${float_latex(P, 8)}$",
                     f"${float_latex(ref.force, 8)}$", f"${float_latex(err, 2)}$", f"${float_latex(est, 2)}$"])
    head = ["$a/H$", r"$\delta_0$", r"$P$ (tip law)", r"$P$ (direct)", "difference", "estimate"]
    doc.table(rf"Force at $\mu = 1$ of the {tip.name} on the layer ($\nu = {float_latex(nu, 4)}$, $H = "
              rf"{float_latex(H, 4)}$): the thin-layer law (1.8) with its estimate against the direct "
              rf"axisymmetric solver of (1.5)--(1.8); the largest difference is "
              rf"${float_latex(worst, 2)}$ times its estimate.", "rrrrrr", head, rows, label="tab:tip-force")
    _ = normal_latex  # the laws above print through the report's normalisation (TipForceLaw.latex)
