r"""What the report's sections share: the contract's contexts, the derivation-file error and small helpers.

A section module (:mod:`thinlayer.export.sections`) parses its table of a derivation file with a
:class:`ParseContext` (the core tables already read) and renders into a
:class:`thinlayer.export.report.Document` with a :class:`RenderContext` (where figures go).  The LaTeX
helpers here print through the reports' normalisation policy (:mod:`thinlayer.export._normal`).
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import sympy as sp

from ... import symbols as S
from ...parse import as_expr

__all__ = ["DerivationFileError", "ParseContext", "RenderContext", "SEPARATOR", "axisymmetric", "compressible_bonded",
           "incompressible_bonded", "nl", "num", "nu_latex", "polynomial_only", "short", "signed_sum", "sphere_rows",
           "tagged", "unit"]

#: how the stages join their tagged LaTeX lines (:func:`thinlayer.export.report.equations` splits at it)
SEPARATOR = " \\\\\n"


class DerivationFileError(ValueError):
    """A derivation file is malformed: the message names the key and what is valid."""


@dataclass(frozen=True)
class ParseContext:
    """What a section's ``parse`` may read besides its own table: the core tables, read and checked.

    Attributes
    ----------
    layer : LayerKernel
        The layer of ``[layer]``.
    punch : Punch or None
        The punch of ``[punch]`` (None: the flat-ended cylinder, ``kind = "flat"``).
    coefficient_order : int
        ``[coefficients] order``.
    units : dict or None
        The units of ``[units]`` (:class:`thinlayer.export.units.UnitLatex` by kind), None without the table.
    tables : mapping
        The whole file as parsed TOML (schema-checked), for a contradiction between tables.
    """

    layer: Any
    punch: Any
    coefficient_order: int
    units: dict | None
    tables: Mapping[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class RenderContext:
    """What a section's ``render`` may need besides the derivation: where figures go, and whether they may be replaced.

    Attributes
    ----------
    figure_dir : Path or None
        The folder next to the .tex file for figures (None: a report without figures).
    force : bool
        Whether existing figure files may be replaced.
    """

    figure_dir: Path | None = None
    force: bool = False


# ---------------------------------------------------------------------------------------------
# parsing
# ---------------------------------------------------------------------------------------------
def short(val: Any) -> str:
    """``repr(val)``, cut to about 60 characters for an error message."""
    text = repr(val)
    return text if len(text) <= 60 else text[:50] + " ..."


def incompressible_bonded(layer: Any) -> bool:
    """The incompressible layer bonded to its base (nu = 1/2, A = 0): sections (I.1)-(I.12), not (2.24)-(3.25)."""
    return layer.has_incompressible_model and not layer.has_compressible_expansion


def compressible_bonded(layer: Any) -> bool:
    """A compressible layer bonded to its base (not the incompressible limit): the (3.15)-(3.25) sections apply."""
    return layer.has_two_term_model and layer.has_compressible_expansion


def paraboloid_of_revolution(punch: Any) -> bool:
    """The punch is ``r^2/(2R)`` with its one parameter ``R`` (the tables derived for the sphere: [adhesion],
    [viscoelastic]).
    """
    import sympy as sp

    from ... import symbols as S

    return punch is not None and len(punch.parameters) == 1 and sp.expand(
        punch.expr - (S.x1**2 + S.x2**2) / (2 * punch.parameters[0])) == 0


def polynomial_only(key: str, table: Any, context: ParseContext) -> None:
    """Refuse the table ``[key]`` beside a flat punch: it is for a polynomial punch."""
    if table is not None and context.punch is None:
        kind = context.tables.get("punch", {}).get("kind")
        if kind != "flat":
            raise DerivationFileError(f"[{key}] is for a polynomial punch; with [punch] kind = {kind!r} the report "
                                      "is the tip's section with its table of [tip] (thinlayer solve --tip for one "
                                      "contact)")
        raise DerivationFileError(f"[{key}] is for a polynomial punch; with [punch] kind = 'flat' the report "
                                  "is the table of [flat_punch] (thinlayer solve --flat for one contact)")


def axisymmetric(punch: Any) -> bool:
    r"""Whether the punch's :math:`\Phi` is invariant under rotation about the :math:`x_3` axis."""
    e = punch.expr
    return sp.expand(S.x1 * sp.diff(e, S.x2) - S.x2 * sp.diff(e, S.x1)) == 0


# ---------------------------------------------------------------------------------------------
# LaTeX
# ---------------------------------------------------------------------------------------------
def nl(expr: Any) -> str:
    """A formula by the reports' normalisation policy (:func:`thinlayer.export._normal.normal_latex`)."""
    from .._normal import normal_latex

    return normal_latex(expr)


def num(x: Any, digits: int = 6) -> str:
    """A number to ``digits`` significant digits (:func:`thinlayer.normal.float_latex`)."""
    from .._normal import float_latex

    return float_latex(x, digits)


def nu_latex(layer: Any) -> str:
    """The Poisson ratio of a layer: symbolic, an exact fraction, or a decimal (never 49/100 for 0.49)."""
    nu = layer.numeric_nu
    if layer.parameter is not None or nu is None:
        return r"\nu"
    exact = getattr(layer, "nu", None)
    if isinstance(exact, sp.Rational):  # inline: 1/2, not a \frac
        return str(exact.p) if exact.q == 1 else f"{exact.p}/{exact.q}"
    return num(nu, 6)


def unit(units: dict | None, kind: str, power: int = 1) -> str:
    r"""``\,\mathrm{mm}^{2}``: the unit of [units] for ``kind`` (length, stress, force) to ``power``, or nothing."""
    if not units or kind not in units:
        return ""
    from ..units import unit_power

    return rf"\,{unit_power(units[kind], power)}"


def signed_sum(parts: list[tuple[Any, str]]) -> str:
    """``c_1 X_1 + c_2 X_2 ...`` with each coefficient normalised, zero terms dropped, one sign per term."""
    out = ""
    for coef, suffix in parts:
        coef = as_expr(coef)
        if coef == 0:
            continue
        body = nl(coef)
        neg = body.startswith("- ")
        body = body[2:] if neg else body
        body = "" if body == "1" and suffix else body
        text = (body + " " + suffix).strip()
        out += (("- " if neg else "") + text) if not out else ((" - " if neg else " + ") + text)
    return out or "0"


def tagged(doc: Any, rows: list[tuple[str, str]]) -> None:
    """Display ``(line, tag)`` rows, consecutive rows with the same tag as one group under one tag."""
    k = 0
    while k < len(rows):
        j = k
        while j < len(rows) and rows[j][1] == rows[k][1]:
            j += 1
        doc.group([r for r, _ in rows[k:j]], rows[k][1])
        k = j


def sphere_rows(ts: Any) -> list[tuple[str, str]]:
    """(I.10), (I.11) of a :class:`TwoTermSphere`, each formula by the report's policy."""
    rows = [] if ts.is_incompressible else [(rf"k^2 = {nl(ts.k2)}", "I.10")]
    rows += [(rf"\delta_0 = {nl(ts.delta0_of_c)}", "I.11"), (rf"P = {nl(ts.force_of_c)}", "I.11")]
    if not ts.is_incompressible:
        rows.append((r"\delta_0 = \frac{c^2 (1 - 2\psi(kc))}{2R},\quad P = 2\pi f_2 c^6 \chi(kc),\quad "
                     r"\psi(x) = \frac{x I_0(x)/I_1(x) - 2}{x^2},\quad \chi(x) = \frac{1/4 - \psi(x)}{x^2}", "I.11"))
    return rows
