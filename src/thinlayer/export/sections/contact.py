r"""The report's section on the contact solution for the numbers of ``[contact]`` (:func:`thinlayer.solve`).

A table of the data and the results, in the units of ``[units]``; what only one model has to show (the
compressible model's leading terms and corrections of (1.8) and (3.25)) comes from its result's own hook,
``report_rows(units)`` of ``Indentation.detail``, so that this section names no model.
"""
from __future__ import annotations

from typing import Any

import sympy as sp

from ... import symbols as S
from ...display import latex_escape
from .base import DerivationFileError, compressible_bonded, num, polynomial_only, short, unit

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render", "NUMBER_RANGE", "parameter_length_powers"]

KEY = "contact"
SCHEMA = {"delta0": ((int, float), "a number > 0"), "force": ((int, float), "a number > 0"),
          "H": ((int, float), "a number > 0"), "mu": ((int, float), "a number > 0 (shear modulus)"),
          "E": ((int, float), "a number > 0 (Young's modulus)"),
          "nu": ((int, float), "a number in (-1, 1/2]"),
          "model": ((str,), "'auto', 'asymptotic', 'compressible', 'two-term', 'incompressible', "
                            "'any-thickness' or 'direct'"),
          "tol": ((int, float), "a relative tolerance > 0, e.g. 0.05"),
          "parameters": ((dict,), "a table of numbers, e.g. {R_1 = 4, R_2 = 1}")}
ORDER = 80
#: the range of a dimensional number of [contact] (beyond it squares and cubes leave double precision)
NUMBER_RANGE = (1e-30, 1e30)


def _positive_number(table: dict, key: str, where: str) -> float:
    """A finite number in :data:`NUMBER_RANGE` (a TOML value already of type int or float)."""
    val = table[key]
    lo, hi = NUMBER_RANGE
    if not (isinstance(val, (int, float)) and lo <= abs(float(val)) <= hi and val > 0):
        raise DerivationFileError(f"[{where}] {key} = {val!r} is invalid: expected a number > 0 from {lo:g} to {hi:g}")
    return float(val)


def parse(ct: Any, context: Any) -> dict | None:
    """Validate ``[contact]``: numeric parameters for :func:`thinlayer.solve`."""
    polynomial_only(KEY, ct, context)
    if ct is None:
        return None
    layer, punch = context.layer, context.punch
    layer_nu = context.tables["layer"].get("nu")
    layer_nu = None if layer_nu == "symbolic" else layer_nu
    if ("delta0" in ct) == ("force" in ct):
        raise DerivationFileError("[contact] needs exactly one of 'delta0' (indentation) or 'force' (inverse problem)")
    if "H" not in ct:
        raise DerivationFileError("[contact] is missing the key 'H' (a number > 0)")
    out = {key: _positive_number(ct, key, "contact") for key in ("delta0", "force", "H", "mu", "E") if key in ct}
    if "mu" in out and "E" in out:
        raise DerivationFileError("[contact] gives both 'mu' and 'E': give one elastic modulus (mu shear, E Young's)")
    if "mu" not in out and "E" not in out:
        out["mu"] = 1.0  # the report's numbers are then per unit shear modulus, as the symbolic sections
    if "model" in ct:
        from ...contact.solve import MODELS

        if ct["model"] not in MODELS:
            raise DerivationFileError(f"[contact] model = {ct['model']!r}: valid models are {list(MODELS)}")
        out["model"] = ct["model"]
    if "tol" in ct:
        out["tol"] = _positive_number(ct, "tol", "contact")
    nu = ct.get("nu")
    if nu is not None and layer_nu is not None:
        raise DerivationFileError(f"[contact] nu = {nu!r} contradicts [layer] nu = {layer_nu!r}: give nu in one "
                                  "place ([layer] for the whole derivation, or [contact] with [layer] nu = 'symbolic')")
    if layer.base == "frictionless":
        if not isinstance(nu, (int, float)) or not -1 < nu <= 0.5:
            raise DerivationFileError(f"[contact] nu = {nu!r}: the frictionless base needs a number in (-1, 1/2] "
                                      "for vartheta = mu/(1 - nu)")
        out["nu"] = float(nu)
    elif compressible_bonded(layer) and layer.parameter is not None:
        if nu is None:
            raise DerivationFileError("[contact] needs 'nu' (a number in (-1, 1/2)) because [layer] nu is symbolic")
    if nu is not None and compressible_bonded(layer):
        from ...layers.kernels import BondedLayer

        try:
            out["layer"] = BondedLayer(nu)
        except (ValueError, TypeError, ArithmeticError) as exc:
            raise DerivationFileError(f"[contact] nu = {nu!r}: {exc}") from exc
    pars = ct.get("parameters", {})
    for k in pars:
        if isinstance(pars[k], bool) or not isinstance(pars[k], (int, float)):
            raise DerivationFileError(f"[contact] parameters.{k} = {short(pars[k])} is invalid: expected a "
                                      "number; parameters is a table of numbers, e.g. {R_1 = 4, R_2 = 1}")
        _positive_number(pars, k, "contact.parameters")
    names = {q.name for q in punch.parameters}
    bad = set(pars) - names
    if bad:
        raise DerivationFileError(f"[contact] parameters {sorted(bad)} are not parameters of the punch "
                                  f"({', '.join(sorted(names)) or 'it has none'})")
    missing = names - set(pars)
    if missing:
        raise DerivationFileError(f"[contact] parameters: values missing for {sorted(missing)}")
    out["parameters"] = dict(pars)
    return out


def applies(der: Any) -> bool:
    return der.sections.get(KEY) is not None


def parameter_length_powers(expr: Any, names: list[str]) -> dict[str, int | None]:
    r"""The power of length of each punch parameter, from :math:`\Phi` being a length in lengths :math:`x_1, x_2`.

    Each term of the expanded punch, a number times powers of :math:`x_1, x_2` and of the parameters,
    gives one linear equation for the parameters' powers :math:`d_k` (:math:`i + j + \sum_k e_k d_k = 1`);
    terms without a parameter fix nothing (a number's unit is the user's).  A power the terms do not fix
    as one integer is None (the report then prints no unit for it).

    >>> import sympy as sp; from thinlayer import symbols as S
    >>> R, K = sp.symbols("R K", positive=True)
    >>> parameter_length_powers((S.x1**2 + S.x2**2) / (2 * R) + S.x1**4 / K**3, ["R", "K"])
    {'R': 1, 'K': 1}
    """
    unknown = {n: sp.Symbol(f"d_{k}") for k, n in enumerate(names)}
    rows = []
    for term in sp.Add.make_args(sp.expand(expr)):
        if not any(getattr(s, "name", None) in unknown for s in term.free_symbols):
            continue  # a number's unit is the user's: it fixes no parameter
        eq = -sp.S.One
        for base, e in term.as_powers_dict().items():
            if base.is_number:
                continue
            if not (base.is_Symbol and e.is_Rational):
                return dict.fromkeys(names)
            eq += e * (1 if base in (S.x1, S.x2) else unknown.get(base.name, sp.nan))
        if eq.has(sp.nan):
            return dict.fromkeys(names)
        rows.append(eq)
    sol = sp.linsolve(rows, list(unknown.values())) if rows else sp.S.EmptySet
    if not isinstance(sol, sp.FiniteSet) or len(sol) != 1:
        return dict.fromkeys(names)
    values = next(iter(sol))
    return {n: int(v) if v.is_Integer else None for n, v in zip(names, values)}


def render(doc: Any, der: Any, context: Any) -> None:
    from ...contact.solve import solve

    c, u = der.sections[KEY], der.units
    ans = solve(c.get("layer", der.layer), der.punch, delta0=c.get("delta0"), force=c.get("force"), H=c["H"],
                mu=c.get("mu"), E=c.get("E"), parameters=c["parameters"], nu=c.get("nu"),
                model=c.get("model", "auto"), tol=c.get("tol", 0.05))
    L, F, Sg = (lambda p=1: unit(u, "length", p)), unit(u, "force"), unit(u, "stress")
    model = latex_escape(ans.model)
    doc.section("Contact solution for numeric parameters").text(
        rf"Model: {model}. \texttt{{thinlayer.solve}} chooses the first model whose error estimates "
        rf"are within the tolerance ${num(100 * ans.tol)}\,\%$; otherwise the direct numerical solver. "
        r"Table~\ref{tab:contact} lists the data and the results; the estimates are relative"
        + ("." if u else r" (no \texttt{[units]} in the derivation file: numbers in any consistent units)."))
    powers = parameter_length_powers(der.punch.expr, list(c["parameters"]))
    pars = [rf"\fitcell{{0.7\linewidth}}{{${sp.latex(sp.Symbol(k))} = {num(v)}{L(powers[k]) if powers[k] else ''}$}}"
            for k, v in c["parameters"].items()]
    modulus = (rf"$E = {num(c['E'])}{Sg}$" if "E" in c else rf"$\mu = {num(ans.mu)}{Sg}$")
    rows = [[r"indentation $\delta_0$", f"${num(ans.delta0)}{L()}$"], [r"thickness $H$", f"${num(ans.H)}{L()}$"],
            ["modulus", modulus], [r"Poisson ratio $\nu$", f"${num(ans.nu)}$"]]
    rows += [["punch" if k == 0 else "", p] for k, p in enumerate(pars)]
    est = ans.error_estimate
    rows += [[r"force $P$", rf"${num(ans.force)}{F} \pm {num(100 * est['force'], 2)}\,\%$"],
             [r"contact area $|\omega|$", rf"${num(ans.contact_area)}{L(2)} \pm "
                                          rf"{num(100 * est['contact_area'], 2)}\,\%$"]]
    if ans.contact_radius is not None:
        rows.append([r"contact radius $c$", f"${num(ans.contact_radius)}{L()}$"])
    rows.append([r"$H/a$", f"${num(ans.H_over_a, 4)}$"])
    doc.table(rf"Contact solution (model {model}) for the parameters of the derivation file.", "ll",
              ["quantity", "value"], rows, label="tab:contact")
    report_rows = getattr(ans.detail, "report_rows", None)  # what only this model's result has to show
    if report_rows is not None:
        lead, lines = report_rows({"force": F, "area": L(2)})
        doc.text(lead)
        for line in lines:
            doc.math(line)
