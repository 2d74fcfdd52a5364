r"""The report's section on a viscoelastic layer: the Lee-Radok force of the sphere under a ramp (V.11).

From a ``[viscoelastic]`` table: a standard linear solid ``E(t) = E_inf + (E0 - E_inf) exp(-t/tau)`` (constant nu)
and a ramp ``delta = v t``.  The closed form is the engine's derivation
(:func:`thinlayer.contact.visco_closed.sls_ramp_force`: sympy integrates Lee-Radok's hereditary integral over the
thin-layer force law (1.8)); the section prints it and its check against the engine's hereditary integral
(:func:`thinlayer.contact.hereditary.hereditary_integral`, 4,001 nodes) at the table's numbers.

``[viscoelastic]`` keys: ``E0``, ``E_inf`` (``0 < E_inf <= E0``), ``tau`` (``> 0``), ``speed`` (``v > 0``),
``duration`` (the ramp's length in time, ``> 0``), ``R`` and ``H`` (``> 0``, default 1 and 0.05), all numbers in the
units of ``[units]``.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np
import sympy as sp

from .base import DerivationFileError, compressible_bonded, nl, num, paraboloid_of_revolution, short

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render"]

KEY = "viscoelastic"
_NUMBER = ((int, float), "a finite number > 0")
SCHEMA = {k: _NUMBER for k in ("E0", "E_inf", "tau", "speed", "duration", "R", "H")}
ORDER = 106


def parse(tab: Any, context: Any) -> dict | None:
    """``[viscoelastic]``: the standard linear solid, the ramp and the sphere, checked; the punch a paraboloid of
    revolution on a compressible bonded layer with a numeric Poisson ratio.
    """
    if tab is None:
        return None

    punch, layer = context.punch, context.layer
    if not paraboloid_of_revolution(punch):
        raise DerivationFileError("[viscoelastic] is derived for the paraboloid of revolution r^2/(2R): give [punch] "
                                  "kind = \"paraboloid\"")
    if not compressible_bonded(layer) or layer.numeric_nu is None:
        raise DerivationFileError("[viscoelastic] needs a compressible bonded layer with a numeric Poisson ratio "
                                  "([layer] model = \"bonded\", nu < 1/2)")
    out = {}
    for key, default in (("E0", None), ("E_inf", None), ("tau", None), ("speed", None), ("duration", None),
                         ("R", 1.0), ("H", 0.05)):
        val = tab.get(key, default)
        if val is None:
            raise DerivationFileError(f"[viscoelastic] {key} is required: a finite number > 0")
        if isinstance(val, bool) or not isinstance(val, (int, float)) or not (math.isfinite(val) and val > 0):
            raise DerivationFileError(f"[viscoelastic] {key} = {short(val)} is invalid: expected a finite number > 0")
        out[key] = float(val)
    if out["E_inf"] > out["E0"]:
        raise DerivationFileError(f"[viscoelastic] E_inf = {short(out['E_inf'])} exceeds E0 = {short(out['E0'])}: "
                                  "a standard linear solid relaxes, 0 < E_inf <= E0")
    return out


def applies(der: Any) -> bool:
    return der.sections.get(KEY) is not None


def render(doc: Any, der: Any, context: Any) -> None:
    """Append the viscoelastic section to ``doc`` (a :class:`thinlayer.export.report.Document`)."""
    from ...contact.hereditary import hereditary_integral
    from ...contact.materials import StandardLinearSolid
    from ...contact.visco_closed import sls_ramp_force

    tab = der.sections[KEY]
    res = sls_ramp_force(der.layer)
    doc.section("Viscoelastic layer: the sphere under a ramp").text(
        r"Assumptions: a linear viscoelastic layer with a constant Poisson ratio (so that the shear relaxation "
        r"modulus is $E(t)/(2(1+\nu))$), frictionless contact, a contact that grows (a ramp). Lee and Radok's "
        r"hereditary integral then carries the elastic law $F(\delta)$ at unit shear modulus over the history, "
        r"and for the standard linear solid $E(t) = E_\infty + (E_0 - E_\infty)e^{-t/\tau}$ under $\delta = vt$ it "
        r"integrates in closed form (sympy; (V.$n$) numbers this extension of \texttt{thinlayer}):")
    doc.math(r"P(t) = \frac{1}{2(1+\nu)}\int_0^t E(t-s)\,\frac{d}{ds}F(\delta(s))\,ds,\quad "
             rf"F(\delta) = {nl(res.elastic.subs(sp.Symbol('delta_0', real=True), sp.Symbol('delta')))}")
    doc.math(rf"{res.latex_display(nl)} \tag{{V.11}}")
    E0, Ei, tau, v, T = tab["E0"], tab["E_inf"], tab["tau"], tab["speed"], tab["duration"]
    vals = {"E_0": E0, "E_infty": Ei, "tau": tau, "v": v, "H": tab["H"], "R": tab["R"]}
    grid = np.linspace(0.0, T, 4001)
    sym = {x.name: x for x in res.elastic.free_symbols}
    F = sp.lambdify(sym["delta_0"], res.elastic.subs({sym["H"]: tab["H"], sym["R"]: tab["R"]}), "numpy")
    num_P = hereditary_integral(StandardLinearSolid(E0, Ei, tau), grid, F(v * grid)) / (2 * (1 + float(res.nu)))
    closed = res.lambdify()(*[vals[a.name] if a.name in vals else grid[1:] for a in res.arguments])
    worst = float(np.max(np.abs(num_P[1:] - closed)) / np.max(np.abs(closed)))
    doc.text(rf"Checks: $\tau P' + P = (E_\infty F + \tau E_0\, dF/dt)/(2(1+\nu))$ (the solid's differential form) "
             r"and the limits $\tau \to \infty$, $\tau \to 0$ (the elastic law with $E_0$, $E_\infty$) hold exactly "
             rf"(sympy). At $E_0 = {num(E0)}$, $E_\infty = {num(Ei)}$, $\tau = {num(tau)}$, $v = {num(v)}$, "
             rf"$R = {num(tab['R'])}$, $H = {num(tab['H'])}$ over $0 < t \le {num(T)}$, (V.11) equals the engine's "
             rf"hereditary integral on 4{{,}}001 nodes to ${num(worst, 2)}$ of the largest force. The law holds where "
             r"the thin-layer law (1.8) does ($c \gg H$, its estimate) and while the contact grows; the retraction "
             r"needs Ting's method (\texttt{solve(material=, history=)}).")
