"""Derivation files (TOML) and the LaTeX report of a derivation.

A derivation file names the layer, the punch and the orders; :func:`load_derivation`
validates it (every error names the key and what is valid) and :func:`run_derivation`
carries out the stages of the paper and collects their LaTeX into one document.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import sympy as sp

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover
    import tomli as tomllib

from ..asymptotics.inner import inner_pressure
from ..asymptotics.moment_expansion import moment_expansion
from ..layers.coefficients import kernel_coefficients
from ..layers.kernels import BondedLayer, FrictionlessLayer, LayerKernel
from ..layers.moments import kernel_moment
from ..punch import Punch
from .report import SEPARATOR, ReportTextError, check_symbol_names, check_title


class DerivationFileError(ValueError):
    """A derivation file is malformed: the message names the key and what is valid."""


@dataclass(frozen=True)
class Derivation:
    """A validated derivation file: what :func:`report_latex` derives, in the paper's order."""

    name: str
    title: str
    layer: LayerKernel
    punch: Punch
    coefficient_order: int
    inner_order: int | None
    edge_shift_nus: tuple
    contact: dict | None = None
    validation: dict | None = None


#: the schema: table -> {key: (python types, what is valid)}; any other key is an error
SCHEMA: dict[str, dict[str, tuple[tuple[type, ...], str]]] = {
    "derivation": {"name": ((str,), "a file-name-safe string (letters, digits, '-', '_')"),
                   "title": ((str,), "a string")},
    "layer": {"model": ((str,), "'bonded' or 'frictionless'"),
              "nu": ((str, int, float), "'symbolic', an exact string like '3/10' or a number")},
    "coefficients": {"order": ((int,), "an integer from 1 to 30")},
    "punch": {"kind": ((str,), "a catalogue name"), "expr": ((str,), "a polynomial in x_1, x_2 as a string")},
    "inner": {"order": ((int,), "a positive integer (number of terms)")},
    "edge_shift": {"nu": ((list,), "a list of numbers in (-1, 1/2)")},
    "contact": {"delta0": ((int, float), "a number > 0"), "force": ((int, float), "a number > 0"),
                "H": ((int, float), "a number > 0"), "mu": ((int, float), "a number > 0 (shear modulus)"),
                "E": ((int, float), "a number > 0 (Young's modulus)"),
                "nu": ((int, float), "a number in (-1, 1/2]"),
                "model": ((str,), "'auto', 'asymptotic', 'compressible', 'two-term', 'incompressible' or 'direct'"),
                "tol": ((int, float), "a relative tolerance > 0, e.g. 0.05"),
                "parameters": ((dict,), "a table of numbers, e.g. {R_1 = 4, R_2 = 1}")},
    "validation": {"nu": ((list,), "a list of Poisson ratios"), "H_over_a": ((list,), "a list of H/a values"),
                   "shapes": ((list,), "a list of shape names")},
}
_TOP_KEYS = set(SCHEMA)
_REQUIRED = ("derivation", "layer", "punch")
#: the range of a dimensional number of [contact] (beyond it squares and cubes leave double precision)
NUMBER_RANGE = (1e-30, 1e30)


def _type_name(kinds: tuple[type, ...]) -> str:
    names = {str: "a string", int: "an integer", float: "a number", list: "a list", dict: "a table"}
    return " or ".join(dict.fromkeys(names[k] for k in kinds))


def check_schema(data: dict) -> None:
    """Every table and key of a derivation file known, every value of the right type.

    Parameters
    ----------
    data : dict
        The parsed TOML.

    Raises
    ------
    DerivationFileError
        naming the table, the key and the valid keys (or the expected type).
    """
    unknown = sorted(set(data) - _TOP_KEYS)
    if unknown:
        raise DerivationFileError(f"unknown table(s) {unknown}; valid tables are {sorted(_TOP_KEYS)}")
    for t in _REQUIRED:
        if t not in data:
            raise DerivationFileError(f"the table [{t}] is required")
    for table, keys in SCHEMA.items():
        if table not in data:
            continue
        tab = data[table]
        if not isinstance(tab, dict):
            raise DerivationFileError(f"[{table}] must be a table with keys {sorted(keys)}, got {tab!r}")
        bad = sorted(set(tab) - set(keys))
        if bad:
            raise DerivationFileError(f"[{table}] unknown key(s) {bad}; valid keys are {sorted(keys)}")
        for key, (kinds, what) in keys.items():
            if key in tab:
                val = tab[key]
                if isinstance(val, bool) or not isinstance(val, kinds):
                    raise DerivationFileError(f"[{table}] {key} = {_short(val)} is invalid: expected {what} "
                                              f"({_type_name(kinds)})")


def _short(val: Any) -> str:
    text = repr(val)
    return text if len(text) <= 60 else text[:50] + " ..."


def _validation_table(vt: Any) -> dict | None:
    """Validate ``[validation]``: a small study against the direct numerics for the report."""
    if vt is None:
        return None
    from ..validation import check_nus, check_ratios, check_shapes

    checks = (("nu", lambda v: list(check_nus(v, "nu")), [0.3]),
              ("H_over_a", lambda v: list(check_ratios(v, "H_over_a")), [0.1, 0.05, 0.025]),
              ("shapes", lambda v: list(check_shapes(v)), ["sphere"]))
    out = {}
    for key, check, default in checks:
        try:
            out[key] = check(vt.get(key, default))
        except (TypeError, ValueError, ArithmeticError) as exc:
            raise DerivationFileError(f"[validation] {key} = {_short(vt.get(key))}: {exc}") from exc
    return out


def _positive_number(table: dict, key: str, where: str) -> float:
    """A finite number in :data:`NUMBER_RANGE` (a TOML value already of type int or float)."""
    val = table[key]
    lo, hi = NUMBER_RANGE
    if not (isinstance(val, (int, float)) and lo <= abs(float(val)) <= hi and val > 0):
        raise DerivationFileError(f"[{where}] {key} = {val!r} is invalid: expected a number > 0 from {lo:g} to {hi:g}")
    return float(val)


def _contact_table(ct: Any, layer: LayerKernel, punch: Punch, layer_nu: Any) -> dict | None:
    """Validate ``[contact]``: numeric parameters for :func:`thinlayer.solve`."""
    if ct is None:
        return None
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
        from ..contact.solve import MODELS

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
    elif _compressible_bonded(layer) and layer.parameter is not None:
        if nu is None:
            raise DerivationFileError("[contact] needs 'nu' (a number in (-1, 1/2)) because [layer] nu is symbolic")
    if nu is not None and _compressible_bonded(layer):
        try:
            out["layer"] = BondedLayer(nu)
        except (ValueError, TypeError, ArithmeticError) as exc:
            raise DerivationFileError(f"[contact] nu = {nu!r}: {exc}") from exc
    pars = ct.get("parameters", {})
    for k in pars:
        if isinstance(pars[k], bool) or not isinstance(pars[k], (int, float)):
            raise DerivationFileError(f"[contact] parameters.{k} = {_short(pars[k])} is invalid: expected a "
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


def _compressible_bonded(layer: LayerKernel) -> bool:
    """A compressible layer bonded to its base (not the incompressible limit): the (3.15)-(3.25) sections apply."""
    return layer.base == "bonded" and layer.has_compressible_expansion


def _need(table: dict, key: str, where: str, kinds: tuple, what: str) -> Any:
    if key not in table:
        raise DerivationFileError(f"[{where}] is missing the key '{key}' ({what})")
    val = table[key]
    if not isinstance(val, kinds) or isinstance(val, bool):
        raise DerivationFileError(f"[{where}] {key} = {val!r} is invalid: expected {what}")
    return val


def _layer_table(lay: dict) -> LayerKernel:
    """The layer of ``[layer]``: ``model`` (bonded or frictionless) and ``nu`` (symbolic, exact or a number)."""
    model = lay.get("model", "bonded")
    if model not in ("bonded", "frictionless"):
        raise DerivationFileError(f"[layer] model = {model!r}: valid models are 'bonded' and 'frictionless'")
    if model == "frictionless":
        if "nu" in lay:
            raise DerivationFileError(f"[layer] nu = {lay['nu']!r} contradicts model = 'frictionless' (its kernel does "
                                      "not depend on nu): remove it; [contact] nu sets vartheta = mu/(1 - nu)")
        return FrictionlessLayer()
    nu = lay.get("nu", "symbolic")
    if nu == "symbolic":
        return BondedLayer()
    try:
        return BondedLayer(nu)
    except (ValueError, TypeError, ArithmeticError) as exc:
        raise DerivationFileError(f"[layer] nu = {_short(nu)}: {exc}") from exc


_KINDS = {"elliptic_paraboloid": Punch.elliptic_paraboloid, "paraboloid": Punch.paraboloid,
          "fourth_degree": Punch.fourth_degree}


def _punch_table(pu: dict) -> Punch:
    """The punch of ``[punch]``: a catalogue ``kind`` or a polynomial ``expr``; its symbol names checked."""
    if ("kind" in pu) == ("expr" in pu):
        raise DerivationFileError("[punch] needs exactly one of 'kind' (a catalogue punch) or 'expr' (a polynomial)")
    if "kind" in pu:
        if pu["kind"] not in _KINDS:
            raise DerivationFileError(f"[punch] kind = {_short(pu['kind'])}: valid kinds are {sorted(_KINDS)}")
        punch = _KINDS[pu["kind"]]()
    else:
        try:
            punch = Punch(pu["expr"])
        except (ValueError, TypeError, ArithmeticError, RecursionError) as exc:
            raise DerivationFileError(f"[punch]: {exc}") from exc
    try:
        check_symbol_names((q.name for q in punch.expr.free_symbols), "[punch]")
    except ReportTextError as exc:
        raise DerivationFileError(str(exc)) from exc
    return punch


def _read_tables(path: Path) -> dict:
    """The TOML of a derivation file: a missing file, a folder, binary or non-UTF-8 content is one clear error."""
    if path.is_dir():
        raise DerivationFileError("is a folder, not a derivation file (give a .toml file, e.g. "
                                  "derivations/sphere.toml)")
    if not path.exists():
        raise DerivationFileError("does not exist")
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise DerivationFileError(f"cannot be read: {exc.strerror or exc}") from exc
    if len(raw) > 1_000_000:
        raise DerivationFileError(f"is {len(raw)} bytes long; a derivation file is at most 1 MB")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise DerivationFileError(f"is not a UTF-8 text file (byte {exc.start}); a derivation file is TOML "
                                  "text") from exc
    if "\x00" in text:
        raise DerivationFileError("is a binary file (it holds NUL bytes); a derivation file is TOML text")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise DerivationFileError(f"is not valid TOML: {str(exc).splitlines()[0]}") from exc
    check_schema(data)
    return data


def load_derivation(path: str | Path) -> Derivation:
    """Read and validate a derivation file.

    Parameters
    ----------
    path : str or Path
        A TOML file with the tables ``[derivation]``, ``[layer]``, ``[punch]`` and optionally
        ``[coefficients]``, ``[inner]``, ``[edge_shift]``, ``[contact]``, ``[validation]``;
        the keys of each are those of :data:`SCHEMA`.

    Returns
    -------
    Derivation
        The validated contents.

    Raises
    ------
    DerivationFileError
        one line starting with the file's name, naming the table, the key and what is valid
        (unknown keys, wrong types, values out of range, contradictions between tables).
    """
    path = Path(path)
    try:
        return _load(path)
    except DerivationFileError as exc:
        raise DerivationFileError(f"{path}: {exc}") from exc


def _load(path: Path) -> Derivation:
    data = _read_tables(path)
    d = data["derivation"]
    name = _need(d, "name", "derivation", (str,), "a file-name-safe string")
    if not re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9_-]{0,99}", name):
        raise DerivationFileError(f"[derivation] name = {_short(name)}: use ASCII letters, digits, '-' and '_' "
                                  "only, starting with a letter or digit (at most 100 characters)")
    title = d.get("title", name)
    try:
        check_title(title, "[derivation] title")
    except ReportTextError as exc:
        raise DerivationFileError(str(exc)) from exc
    layer = _layer_table(data["layer"])
    corder = data.get("coefficients", {}).get("order", 3)
    if not 1 <= corder <= 30:
        raise DerivationFileError(f"[coefficients] order = {corder!r}: an integer from 1 to 30")
    punch = _punch_table(data["punch"])
    iorder = data.get("inner", {}).get("order")
    if iorder is not None and not 1 <= iorder <= 30:
        raise DerivationFileError(f"[inner] order = {iorder!r}: a positive integer (number of terms) up to 30")
    es = data.get("edge_shift", {}).get("nu", [])
    if not all(isinstance(v, (int, float)) and not isinstance(v, bool) and -1 < v < 0.5 for v in es) or len(es) > 50:
        raise DerivationFileError(f"[edge_shift] nu = {_short(es)}: a list of at most 50 numbers in (-1, 1/2)")
    layer_nu = data["layer"].get("nu")
    contact = _contact_table(data.get("contact"), layer, punch, None if layer_nu == "symbolic" else layer_nu)
    validation = _validation_table(data.get("validation"))
    return Derivation(name, title, layer, punch, corder, iorder, tuple(es), contact, validation)


def report_latex(der: Derivation, figure_dir: str | Path | None = None, force: bool = False) -> str:
    """The whole LaTeX document of a derivation, in the paper's order (see :mod:`thinlayer.export.report`).

    With ``figure_dir`` (a folder next to the .tex file) the validation plots are written there and
    included; without it the report has the validation tables only.

    Parameters
    ----------
    der : Derivation
        A derivation, e.g. from :func:`load_derivation`.
    figure_dir : str or Path, optional
        Where to write the validation plots (next to the .tex file).
    force : bool
        Whether existing plot files may be replaced.

    Returns
    -------
    str
        The LaTeX document: kernel (2.3), coefficients (2.20), (4.2), moments (2.21), (2.22), inner
        expansion (2.24)-(2.31), (4.1), boundary layer (3.15)-(3.25), force law (1.8), edge shift,
        contact solution, validation and errata.
    """
    from .report import Document, errata_section

    check_symbol_names((q.name for q in der.punch.expr.free_symbols), "punch")
    doc = Document(der.title)
    _kernel_sections(doc, der)
    _inner_sections(doc, der)
    _boundary_layer_sections(doc, der.layer, der.punch)
    _two_term_section(doc, der)
    if der.edge_shift_nus:
        _edge_shift_section(doc, der.edge_shift_nus)
    if der.contact is not None:
        _contact_section(doc, der)
    if der.validation is not None:
        _validation_section(doc, der.validation, figure_dir, force)
    errata_section(doc)
    return doc.latex()


def _kernel_sections(doc: Any, der: Derivation) -> None:
    """Kernel (2.3), coefficients (2.20), (4.2) (tabulated when numeric), moments (2.21) and (2.22)."""
    layer = der.layer
    doc.section("Layer kernel (2.3), (2.4)").math(rf"\mathcal{{L}}(u) = {sp.latex(layer.L())} \tag{{2.3}}")
    if layer.base == "bonded" and not layer.has_compressible_expansion:
        _incompressible_sections(doc, der)
        return
    co = kernel_coefficients(layer, der.coefficient_order)
    doc.section("Coefficients (2.20), (4.2)").math(co.latex())
    if not layer.symbolic_coefficients and layer.parameter is None:  # numbers: tabulate them
        rows = [[str(n), f"{float(co.m[n]):.12g}", f"{float(co.M[n]):.12g}"]
                for n in range(1, der.coefficient_order + 1)]
        doc.table("rrr", ["$n$", "$m_n$ (2.20)", "$M_n$ (4.2)"], rows)
    doc.section("Kernel moments (2.21) and the moment expansion (2.22)")
    mom = []
    for n in range(min(3, der.coefficient_order) + 1):
        for k in range(n + 1):
            val = sp.factor(kernel_moment(layer, 2 * k, 2 * n - 2 * k))
            mom.append(rf"\mu_{{{2 * k},{2 * n - 2 * k}}} = {sp.latex(val)} \tag{{2.21}}")
    doc.math(SEPARATOR.join(mom)).math(moment_expansion(layer, min(2, der.coefficient_order)).latex())


def _incompressible_sections(doc: Any, der: Derivation) -> None:
    """At nu = 1/2: the data (I.1), the thin-layer operator (I.2), the obstacle problem (I.3)-(I.5) and its solution.

    Closed forms for the sphere (I.11), the elliptic paraboloid (I.6)-(I.8) and any axisymmetric punch (I.9); the
    edge correction (I.12).
    """
    from ..asymptotics.incompressible import (
        incompressible_axisymmetric,
        incompressible_ellipse,
        obstacle_problem,
        thin_layer_operator,
        two_term_edge_shift,
        two_term_sphere,
    )
    from ..layers.coefficients import incompressible_coefficients

    layer, punch = der.layer, der.punch
    doc.section("Incompressible layer: Maclaurin data (I.1) and thin-layer operator (I.2)").text(
        "At $\\nu = 1/2$ the coefficient $\\mathcal{A}$ of (2.4) vanishes: the compressible expansion (2.20)--(3.25) "
        "does not exist, and the leading operator is of second order.")
    doc.math(incompressible_coefficients(der.coefficient_order).latex()).math(thin_layer_operator(layer).latex())
    doc.section("Punch and the obstacle problem (I.3)--(I.5)").math(punch.latex())
    doc.math(obstacle_problem(layer, punch).latex())
    kind = punch.name
    if kind.startswith("paraboloid"):
        doc.section("Solution for the sphere (I.11)").math(two_term_sphere(layer).latex())
    elif kind == "elliptic paraboloid":
        doc.section("Solution for the elliptic paraboloid (I.6)--(I.8)").math(incompressible_ellipse().latex())
    elif _axisymmetric(punch):
        doc.section("Solution for an axisymmetric punch (I.9)").math(incompressible_axisymmetric(punch).latex())
    h = float(two_term_edge_shift(layer, dps=15))
    doc.section("Edge correction (I.12)").text(
        f"The model's edge lies $h H$ outside the true contact edge, $h = {h:.10f}$ at $\\nu = 1/2$ "
        "(the edge layer of width $H$ that the model neglects); thinlayer.solve reports the corrected radius "
        "$c - hH$ and estimates the model's force error by $2hH/c$.")


def _axisymmetric(punch: Punch) -> bool:
    from .. import symbols as S

    e = punch.expr
    return sp.expand(S.x1 * sp.diff(e, S.x2) - S.x2 * sp.diff(e, S.x1)) == 0


def _two_term_section(doc: Any, der: Derivation) -> None:
    """The two-term model of the sphere (I.10)-(I.12), for a bonded layer with symbolic nu or 1/4 < nu < 1/2."""
    from ..asymptotics.incompressible import two_term_sphere

    layer = der.layer
    nu = layer.numeric_nu
    if not (der.punch.name.startswith("paraboloid") and layer.base == "bonded" and layer.has_compressible_expansion
            and (nu is None or 0.25 < nu < 0.5)):
        return
    doc.section("Nearly incompressible layer: the two-term model (I.10)--(I.12)").text(
        "Near $\\nu = 1/2$ the compressible expansion needs $\\lambda^2 = (a/H)^2/m_1 \\gg 1$ (I.13); the two-term "
        "model (I.10), $-\\Delta p + k^2 p = f$ with $f = \\vartheta (\\delta_0 - \\Phi)/(c_1 H^3)$ and "
        "$k^2 = 1/(m_1 H^2)$, holds in both regimes. For the sphere, in terms of the contact radius $c$:")
    doc.math(two_term_sphere(layer).latex())


def _inner_sections(doc: Any, der: Derivation) -> None:
    """The punch, the inner expansion (2.24)-(2.31), (4.1) and, for an ellipse, the contact area (3.1)."""
    layer, punch = der.layer, der.punch
    if layer.base == "bonded" and not layer.has_compressible_expansion:
        return  # nu = 1/2: the obstacle problem (I.3) replaces the inner expansion
    doc.section("Punch and inner expansion (2.24)--(2.31), (4.1)").math(punch.latex())
    doc.math(inner_pressure(layer, punch, der.inner_order).latex())
    if punch.name == "elliptic paraboloid":
        from ..asymptotics.contour import ellipse_contour

        doc.section("Leading contact area (3.1)").math(ellipse_contour().latex())


def _boundary_layer_sections(doc: Any, layer: LayerKernel, punch: Punch) -> None:
    """Boundary layer (3.15)-(3.25) and force law (1.8): frictionless base or compressible bonded layer."""
    from ..asymptotics.force_law import force_law

    if layer.base == "frictionless":
        from ..asymptotics.wiener_hopf import edge_shift_alexandrov, edge_shift_exact

        doc.section("Boundary layer and edge shift (frictionless base)").text(
            "The kernel does not depend on $\\nu$; $m_1 = 0$, so Alexandrov's (3.20)--(3.21) give "
            "$B = 1/(2\\mathcal{A})$, $C = B/\\mathcal{A}$, and the force has no correction of relative order "
            "$(H/a)^2$: the first correction is of order $(H/a)^3$ (second-order boundary layer, not derived "
            "here; measured by the direct solver).")
        doc.table("rr", ["$h^*$ exact (Wiener--Hopf)", "$h^*$ (3.25)"],
                  [[f"{float(edge_shift_exact(layer)):.10f}", f"{float(edge_shift_alexandrov(layer)):.10f}"]])
        doc.section("Force and contact area").math(force_law(layer, punch).latex())
    if _compressible_bonded(layer):
        from .report import alexandrov_generic_latex

        doc.section("Boundary layer (3.15)--(3.25)").text(
            "Alexandrov's approximation (3.19) with $B$, $C$ fitted to $\\mathcal{A}$ (3.20) and $m_1$ (3.21); "
            "the solution in terms of $\\mathcal{A}$, $B$, $C$ (values per $\\nu$ in the edge-shift table):")
        doc.math(alexandrov_generic_latex())
        doc.section("Force and contact area with their first corrections in $H$").text(
            "Inner terms $p_0 + p_1$ plus the boundary layer's force defect; $a$ is the contact half-width.")
        doc.math(force_law(layer, punch).latex())


def _edge_shift_section(doc: Any, nus: tuple) -> None:
    """B, C (3.20)-(3.21) and the edge shift h*: exact (Wiener-Hopf) and Alexandrov's (3.25), per nu."""
    from ..asymptotics.boundary_layer import alexandrov_parameters
    from ..asymptotics.wiener_hopf import edge_shift_alexandrov, edge_shift_exact

    rows = []
    for v in nus:
        B, C = alexandrov_parameters(BondedLayer(v)).numeric()
        rows.append([f"{v:g}", f"{float(B):.8f}", f"{float(C):.8f}", f"{float(edge_shift_exact(v)):.10f}",
                     f"{float(edge_shift_alexandrov(v)):.10f}"])
    doc.section("Edge shift of the contact area").text(
        "The contour of the contact area lies at the distance $h^* H$ inside $\\Gamma_0$: exact "
        "Wiener--Hopf value and Alexandrov's approximation (3.25).")
    doc.table("rrrrr", ["$\\nu$", "$B$", "$C$", "$h^*$ exact", "$h^*$ (3.25)"], rows)


def _contact_section(doc: Any, der: Derivation) -> None:
    """The contact solution for the numeric parameters of ``[contact]`` (:func:`thinlayer.solve`)."""
    from ..contact.solve import solve

    c = der.contact
    ans = solve(c.get("layer", der.layer), der.punch, delta0=c.get("delta0"), force=c.get("force"), H=c["H"],
                mu=c.get("mu"), E=c.get("E"), parameters=c["parameters"], nu=c.get("nu"),
                model=c.get("model", "auto"), tol=c.get("tol", 0.05))
    doc.section("Contact solution for numeric parameters").text(
        f"Model: {ans.model} (thinlayer.solve chooses the first model whose error estimates are within the "
        f"tolerance {100 * ans.tol:g}\\,\\%; otherwise the direct numerical solver). The estimates are relative.")
    doc.math(ans.detail.latex() if ans.model == "compressible" else ans.latex())


def _validation_section(doc: Any, v: dict, figure_dir: str | Path | None, force: bool = False) -> None:
    """The validation table against the direct numerics (and its plots with ``figure_dir``)."""
    from ..validation import validation_study

    study = validation_study(v["nu"], v["H_over_a"], v["shapes"], progress=False)
    doc.section("Validation against the direct numerical solution").text(
        "Asymptotic results (thinlayer.solve) against the direct numerical solution of the full "
        "contact problem (thinlayer.numerics); relative errors, observed orders and the edge "
        "shift from the numerical contact radius. Plots: run thinlayer validate with the option plots.")
    doc.text("{\\footnotesize\n" + study.latex() + "\n}")
    if figure_dir is not None:
        figs = _validation_figures(study, Path(figure_dir), force)
        for fig in figs:
            doc.text(rf"\begin{{center}}\includegraphics[width=0.8\linewidth]{{{Path(figure_dir).name}/{fig}}}"
                     r"\end{center}")


def _validation_figures(study, folder: Path, force: bool = False) -> list[str]:
    """The study's plots as PDF files in ``folder``; [] (tables only) when matplotlib is missing."""
    try:
        paths = study.plots(folder, formats=("pdf",), force=force)
    except ImportError:
        return []
    return [p.name for p in paths if p.suffix == ".pdf"]


def write_report(der: Derivation, out_dir: str | Path, pdf: bool = False, force: bool = False,
                 temp_root: str | Path | None = None) -> Path:
    """Write ``<out_dir>/<name>.tex`` (and the PDF and its log with ``pdf=True``) without losing any file.

    Every file the run would write is checked before anything is written: the .tex is replaced
    only when thinlayer wrote it and nobody edited it since (the hash in its first line) or with
    ``force``; an existing PDF, log or validation figure only with ``force``.  The text is
    generated completely first, each file is replaced atomically, the PDF is compiled in a
    temporary folder, and the whole run holds a lock on ``<out_dir>/<name>`` so that a concurrent
    run of the same name stops with an error instead of mixing files.

    Parameters
    ----------
    der : Derivation
        The derivation to report.
    out_dir : str or Path
        The output folder (created if missing).
    pdf : bool
        Whether to compile the PDF too (needs pdflatex).
    force : bool
        Whether to overwrite existing files.
    temp_root : str or Path, optional
        Where the PDF's temporary folder is created (default: the system's).

    Returns
    -------
    Path
        The .tex file.
    """
    from ..validation.output import output_lock, refuse_existing
    from .report import check_writable, compile_pdf, latex_engine, pdf_outputs, write_tex

    out = Path(out_dir)
    tex = out / f"{der.name}.tex"
    figures = out / f"{der.name}-figures" if der.validation is not None else None

    def check() -> None:
        check_writable(tex, force)
        if pdf:
            refuse_existing(pdf_outputs(tex), force)
        if figures is not None:
            from ..validation.plots import figure_files

            refuse_existing(figure_files(figures, "validation", ("pdf",)), force)

    if out.exists() and not out.is_dir():
        raise NotADirectoryError(f"--out {out} is a file, not a folder")
    check()
    if pdf:
        latex_engine()  # fail before writing anything when no engine is installed
    with output_lock(out, der.name):
        check()  # again, now that no concurrent run can write these files
        text = report_latex(der, figures, force=force)
        write_tex(text, tex, force)
        if pdf:
            compile_pdf(tex, temp_root)
    return tex
