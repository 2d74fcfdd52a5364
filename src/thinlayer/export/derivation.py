"""Derivation files (TOML) and the LaTeX report of a derivation.

A derivation file names the layer, the punch and the orders; :func:`load_derivation`
validates it (every error names the key and what is valid) and :func:`run_derivation`
carries out the stages of the paper and collects their LaTeX into one document.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Any

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover
    import tomli as tomllib

from ..layers.kernels import BondedLayer, FrictionlessLayer, LayerKernel
from ..punch import Punch
from .report import ReportTextError, check_symbol_names, check_title
from .units import unit_latex  # noqa: F401 - kept importable from here


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
    units: dict | None = None
    flat_punch: dict | None = None
    second_order: dict | None = None


@dataclass(frozen=True)
class ErrataDocument:
    """The document ``thinlayer report errata``: the whole errata registry (:mod:`thinlayer.errata`), no derivation
    file; :func:`write_report` writes it like a report (``<out>/errata.tex``).
    """

    name: str = "errata"
    title: str = "Errata of the publications thinlayer re-derives"
    validation: None = None


#: bare names the report command takes beside the catalogue's: documents that are no derivation file
DOCUMENTS = {"errata": ErrataDocument}


#: the schema: table -> {key: (python types, what is valid)}; any other key is an error
SCHEMA: dict[str, dict[str, tuple[tuple[type, ...], str]]] = {
    "derivation": {"name": ((str,), "a file-name-safe string (letters, digits, '-', '_')"),
                   "title": ((str,), "a string")},
    "layer": {"model": ((str,), "'bonded' or 'frictionless'"),
              "nu": ((str, int, float), "'symbolic', an exact string like '3/10' or a number")},
    "coefficients": {"order": ((int,), "an integer from 1 to 30")},
    "punch": {"kind": ((str,), "a catalogue name, or 'flat' (a flat-ended cylinder, with [flat_punch])"),
              "expr": ((str,), "a polynomial in x_1, x_2 as a string")},
    "flat_punch": {"a_over_H": ((list,), "a list of punch radius over thickness values in (0, 200]"),
                   "nu": ((list,), "a list of Poisson ratios in (-1, 1/2] (columns of the table)")},
    "inner": {"order": ((int,), "a positive integer (number of terms)")},
    "edge_shift": {"nu": ((list,), "a list of numbers in (-1, 1/2)")},
    "contact": {"delta0": ((int, float), "a number > 0"), "force": ((int, float), "a number > 0"),
                "H": ((int, float), "a number > 0"), "mu": ((int, float), "a number > 0 (shear modulus)"),
                "E": ((int, float), "a number > 0 (Young's modulus)"),
                "nu": ((int, float), "a number in (-1, 1/2]"),
                "model": ((str,), "'auto', 'asymptotic', 'compressible', 'two-term', 'incompressible', "
                                  "'any-thickness' or 'direct'"),
                "tol": ((int, float), "a relative tolerance > 0, e.g. 0.05"),
                "parameters": ((dict,), "a table of numbers, e.g. {R_1 = 4, R_2 = 1}")},
    "validation": {"nu": ((list,), "a list of Poisson ratios"), "H_over_a": ((list,), "a list of H/a values"),
                   "shapes": ((list,), "a list of shape names")},
    "second_order": {"nu": ((list,), "a list of 1 to 12 Poisson ratios in (-1, 1/2) (numbers, or exact strings "
                                     "like '3/10') or 'frictionless' (the rows of the table of r_3)")},
    "units": {"length": ((str,), "a length unit such as 'mm' or 'um'"),
              "stress": ((str,), "a stress unit such as 'MPa' or 'N/mm^2' (of mu and E)"),
              "force": ((str,), "a force unit such as 'N' or 'mN'")},
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


#: the dimension (kg, m, s) of each key of [units] and examples of it
UNIT_KINDS = {"length": ((0, 1, 0), "'mm', 'um', 'nm', 'm'"),
              "force": ((1, 1, -2), "'N', 'mN', 'uN', 'nN', 'kg m/s^2'"),
              "stress": ((1, -1, -2), "'MPa', 'kPa', 'GPa', 'Pa', 'N/mm^2'")}


def _units_table(ut: Any) -> dict | None:
    """Validate ``[units]``: the units of lengths, of the moduli and of forces, for the report's numbers.

    Each is parsed by the unit grammar (:func:`thinlayer.export.units.parse_unit`, never evaluated),
    must have the dimension of its key, and, when all three are given, stress = force / length^2
    (one consistent system: the report computes forces from moduli and lengths).  The values are the
    units' LaTeX (:class:`~thinlayer.export.units.UnitLatex`, which also sets a power of the unit).
    """
    from .units import FORMS, UnitError, UnitLatex, dimension_name, parse_unit

    if ut is None:
        return None
    out = {}
    for key, val in ut.items():
        try:
            unit = parse_unit(val)
        except UnitError as exc:
            raise DerivationFileError(f"[units] {key} = {_short(val)}: {exc}; {FORMS}") from exc
        dim, examples = UNIT_KINDS[key]
        if unit.dimension != dim:
            raise DerivationFileError(f"[units] {key} = {_short(val)} is {dimension_name(unit.dimension)} "
                                      f"({unit.text()}), not {dimension_name(dim)}: give {dimension_name(dim)} "
                                      f"unit such as {examples}")
        out[key] = UnitLatex(unit)
    if len(out) == 3:
        length, force, stress = (out[k].unit for k in ("length", "force", "stress"))
        implied = force.decade - 2 * length.decade
        if implied != stress.decade:
            raise DerivationFileError(
                f"[units] are inconsistent: force/length^2 = {force.text()}/({length.text()})^2 is 10^{implied} Pa but "
                f"stress = {stress.text()} is 10^{stress.decade} Pa; the report's forces come from moduli times "
                "lengths squared, so give one system, e.g. mm, N, MPa or m, N, Pa or um, uN, MPa")
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


#: the default table of [flat_punch]: a/H from thick to thin, nu from 0 to incompressible
FLAT_DEFAULT = {"a_over_H": [0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0], "nu": [0.0, 0.3, 0.45, 0.5]}


def _flat_table(ft: Any, needed: bool) -> dict | None:
    """``[flat_punch]``: the a/H values (<= 30, in (0, 200]) and the nu values (<= 8, in (-1, 1/2]) of the table."""
    if ft is None:
        return dict(FLAT_DEFAULT) if needed else None
    out = {}
    for key, lo, hi, most, closed in (("a_over_H", 0.0, 200.0, 30, True), ("nu", -1.0, 0.5, 8, True)):
        vals = ft.get(key, FLAT_DEFAULT[key])
        ok = (0 < len(vals) <= most and all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                                and lo < v <= hi for v in vals))
        if not ok:
            raise DerivationFileError(f"[flat_punch] {key} = {_short(vals)}: a list of 1 to {most} numbers in "
                                      f"({lo:g}, {hi:g}]")
        out[key] = [float(v) for v in vals]
    return out


#: the default rows of the table of [second_order]: nu from 0 to nearly incompressible, and the frictionless base
SECOND_ORDER_NUS = ("0", "1/4", "3/10", "2/5", "9/20", "frictionless")
#: the most rows of that table (each r_3 by three factorisations, ~0.2 s)
SECOND_ORDER_MOST = 12
_EXACT_NU = re.compile(r"[-+]?[0-9]{1,6}(\.[0-9]{1,6})?(/[0-9]{1,6})?")


def _second_order_table(st: Any, layer: LayerKernel, punch: Punch | None) -> dict | None:
    """``[second_order]``: the section of (SO.1)-(SO.10) and the nu values of its table of ``r_3``.

    Each value is a number or an exact string (``"3/10"``, parsed by :class:`fractions.Fraction`, never
    evaluated) with ``-1 < nu < 1/2``, or ``"frictionless"`` (the layer on a frictionless base).
    """
    if st is None:
        return None
    if punch is None or not (layer.base == "frictionless" or _compressible_bonded(layer)):
        raise DerivationFileError("[second_order] is for the compressible expansion of a polynomial punch (a bonded "
                                  "layer with nu < 1/2 or the frictionless base), not the flat punch or nu = 1/2")
    vals = st.get("nu", list(SECOND_ORDER_NUS))
    what = (f"a list of 1 to {SECOND_ORDER_MOST} Poisson ratios in (-1, 1/2) (numbers, or exact strings like "
            "'3/10') or 'frictionless'")
    if not 0 < len(vals) <= SECOND_ORDER_MOST:
        raise DerivationFileError(f"[second_order] nu = {_short(vals)}: {what}")
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
            raise DerivationFileError(f"[second_order] nu: {_short(v)} is invalid: {what}")
        if not -1 < num < Fraction(1, 2):
            raise DerivationFileError(f"[second_order] nu: {_short(v)} is outside (-1, 1/2): {what}")
        out.append(num)
    return {"nu": out}


def _punch_table(pu: dict) -> Punch | None:
    """The punch of ``[punch]``: a catalogue ``kind`` or a polynomial ``expr``; its symbol names checked.

    ``kind = "flat"`` (the flat-ended cylinder) gives ``None``: its report is the section of ``[flat_punch]``.
    """
    if ("kind" in pu) == ("expr" in pu):
        raise DerivationFileError("[punch] needs exactly one of 'kind' (a catalogue punch) or 'expr' (a polynomial)")
    if pu.get("kind") == "flat":
        return None
    if "kind" in pu:
        if pu["kind"] not in _KINDS:
            raise DerivationFileError(f"[punch] kind = {_short(pu['kind'])}: valid kinds are "
                                      f"{sorted([*_KINDS, 'flat'])}")
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


#: a catalogue name: the stem of a file of the catalogue, e.g. ``sphere``
_CATALOGUE_NAME = re.compile(r"[A-Za-z0-9][A-Za-z0-9_-]{0,99}")


def catalogue_folder() -> Path | None:
    """The folder of the derivation catalogue: ``thinlayer/derivations`` in an installed wheel, else the
    repository's top-level ``derivations/`` (a source checkout or an editable install); None if neither exists.
    """
    here = Path(__file__).resolve()
    packaged = here.parents[1] / "derivations"
    if packaged.is_dir():
        return packaged
    if here.parents[2].name == "src":  # src/thinlayer/export/derivation.py in a checkout
        source = here.parents[3] / "derivations"
        if source.is_dir():
            return source
    return None


def catalogue() -> dict[str, Path]:
    """The catalogue's derivation files by name (the file stem): ``{"sphere": .../sphere.toml, ...}``."""
    folder = catalogue_folder()
    return {} if folder is None else {f.stem: f for f in sorted(folder.glob("*.toml"))}


def resolve_derivation(name_or_path: str | Path) -> Path:
    """The derivation file a command line names: an existing file, else a catalogue entry.

    ``sphere`` (a catalogue name), ``sphere.toml`` and ``derivations/sphere.toml`` (the examples of
    ``thinlayer report --help``) all name the catalogue's ``sphere.toml`` when no such file exists in
    the current folder; an existing file always wins.

    Parameters
    ----------
    name_or_path : str or Path
        A path to a TOML file or the name of a catalogue entry.

    Returns
    -------
    Path
        The file to load with :func:`load_derivation`.

    Raises
    ------
    DerivationFileError
        neither a file nor a catalogue name; the message lists the catalogue.

    Examples
    --------
    >>> resolve_derivation("sphere").name
    'sphere.toml'
    """
    path = Path(name_or_path)
    if path.exists():
        return path
    cat = catalogue()
    stem = path.stem if path.suffix == ".toml" else path.name
    bare = path.parent in (Path(""), Path(".")) or path.parent.name == "derivations"
    if bare and _CATALOGUE_NAME.fullmatch(stem) and stem in cat and path.suffix in ("", ".toml"):
        return cat[stem]
    names = ", ".join([*cat, *DOCUMENTS]) or "none installed"
    raise DerivationFileError(f"{name_or_path}: does not exist, and it is no name of the derivation catalogue "
                              f"({names})")


def load_derivation(path: str | Path) -> Derivation | ErrataDocument:
    """Read and validate a derivation file (or name a document of :data:`DOCUMENTS`, e.g. ``errata``).

    Parameters
    ----------
    path : str or Path
        A catalogue name such as ``sphere`` (:func:`resolve_derivation`) or a TOML file with the tables
        ``[derivation]``, ``[layer]``, ``[punch]`` and optionally
        ``[coefficients]``, ``[inner]``, ``[edge_shift]``, ``[contact]``, ``[validation]``, ``[second_order]``;
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
    if isinstance(path, str) and path in DOCUMENTS and not Path(path).exists():
        return DOCUMENTS[path]()
    path = resolve_derivation(path) if not Path(path).is_dir() else Path(path)
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
    if punch is None:
        extra = [t for t in ("inner", "contact", "validation") if t in data]
        if extra:
            raise DerivationFileError(f"[{extra[0]}] is for a polynomial punch; with [punch] kind = 'flat' the report "
                                      "is the table of [flat_punch] (thinlayer solve --flat for one contact)")
    contact = _contact_table(data.get("contact"), layer, punch, None if layer_nu == "symbolic" else layer_nu)
    validation = _validation_table(data.get("validation"))
    units = _units_table(data.get("units"))
    flat = _flat_table(data.get("flat_punch"), punch is None)
    second = _second_order_table(data.get("second_order"), layer, punch)
    return Derivation(name, title, layer, punch, corder, iorder, tuple(es), contact, validation, units, flat, second)


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
    from .report import derivation_document

    if isinstance(der, ErrataDocument):
        from ._errata_section import errata_document
        from .report import Document

        return errata_document(Document(der.title))
    if der.punch is not None:
        check_symbol_names((q.name for q in der.punch.expr.free_symbols), "punch")
    return derivation_document(der, figure_dir, force)



def write_report(der: Derivation, out_dir: str | Path, pdf: bool | None = False, force: bool = False,
                 temp_root: str | Path | None = None) -> Path:
    """Write ``<out_dir>/<name>.tex`` (and the PDF and its log with ``pdf=True``) without losing any file.

    Every file the run would write is checked before anything is written: the .tex is replaced
    only when thinlayer wrote it and nobody edited it since (the hash in its first line) or with
    ``force``; an existing PDF, log or validation figure only with ``force``.  A link at any of
    these counts as an existing file (with ``force`` the link itself is replaced, never the file it
    points to); a link at the lock file or the figure folder is refused even with ``force``.  The
    text is generated completely first; with ``pdf`` it is compiled in a private temporary folder
    inside ``out_dir`` and only then are the PDF, the log and the .tex each replaced atomically, so a
    run interrupted before the end (a LaTeX error, Ctrl-C, SIGTERM, SIGKILL) leaves the earlier .tex
    and PDF as they were.  The whole run holds a lock on ``<out_dir>/<name>`` so that a concurrent
    run of the same name stops with an error instead of mixing files; under it the temporary files
    left by a killed earlier run of the same name are removed.  ``out_dir`` itself may be a link (the
    user's choice: it is followed).

    Parameters
    ----------
    der : Derivation
        The derivation to report.
    out_dir : str or Path
        The output folder (created if missing).
    pdf : bool or None
        Whether to compile the PDF too (needs pdflatex); ``None``: when pdflatex is installed (else the .tex
        only: :func:`thinlayer.export.report.pdf_hint` says how to get the PDF).  With ``True`` and no
        pdflatex the .tex is written and then ``NoLatexEngineError`` (an ``OSError``) is raised.
    force : bool
        Whether to overwrite existing files.
    temp_root : str or Path, optional
        Where the PDF's temporary folder is created (default: ``out_dir``).

    Returns
    -------
    Path
        The .tex file.
    """
    from ..validation.output import atomic_write, check_folder, output_lock, refuse_existing
    from .latex_files import build_pdf, check_writable, latex_available, latex_engine, pdf_outputs, write_tex

    missing_engine = bool(pdf) and not latex_available()
    pdf = latex_available() if pdf is None else bool(pdf) and not missing_engine
    out = Path(out_dir)
    tex = out / f"{der.name}.tex"
    figures = out / f"{der.name}-figures" if der.validation is not None else None
    targets = [tex, *pdf_outputs(tex)]
    if figures is not None:
        from ..validation.plots import figure_files

        targets += figure_files(figures, "validation", ("pdf",))

    def check() -> None:
        check_writable(tex, force)
        if pdf:
            refuse_existing(pdf_outputs(tex), force)
        if figures is not None:
            check_folder(figures)
            refuse_existing(targets[3:], force)

    if out.exists() and not out.is_dir():
        raise NotADirectoryError(f"--out {out} is a file, not a folder")
    check()
    with output_lock(out, der.name, targets):
        check()  # again, now that no concurrent run can write these files
        text = report_latex(der, figures, force=force)
        if pdf:
            try:
                pdf_bytes, log = build_pdf(text, der.name, out if temp_root is None else temp_root, figures, tex)
            except RuntimeError:  # LaTeX's error: the .tex is written for reading it, the PDF is not
                write_tex(text, tex, force)
                raise
            pdf_path, log_path = pdf_outputs(tex)
            atomic_write(pdf_path, pdf_bytes)
            atomic_write(log_path, log)
        write_tex(text, tex, force)
    if missing_engine:
        latex_engine()  # NoLatexEngineError, after the .tex is written
    return tex
