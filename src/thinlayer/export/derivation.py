"""Derivation files (TOML) and the LaTeX report of a derivation.

A derivation file names the layer, the punch and the orders; :func:`load_derivation`
validates it (every error names the key and what is valid) and :func:`run_derivation`
carries out the stages of the paper and collects their LaTeX into one document.
"""
from __future__ import annotations

import re
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover
    import tomli as tomllib

from ..layers.kernels import BondedLayer, FrictionlessLayer, LayerKernel
from ..punch import Punch
from .report import ReportTextError, check_symbol_names, check_title
from .sections import CORE_TABLES, SECTIONS, ParseContext, figure_files, parse_sections
from .sections import schema as sections_schema
from .sections.base import DerivationFileError
from .units import unit_latex  # noqa: F401 - kept importable from here

__all__ = ["CORE_SCHEMA", "DOCUMENTS", "Derivation", "DerivationFileError", "ErrataDocument", "SCHEMA", "catalogue",
           "catalogue_folder", "check_schema", "load_derivation", "report_latex", "resolve_derivation", "write_report"]


@dataclass(frozen=True)
class Derivation:
    """A validated derivation file: what :func:`report_latex` derives, in the paper's order.

    The core tables (:data:`CORE_SCHEMA`) are fields; every other table belongs to a report section
    (:mod:`thinlayer.export.sections`) and its parsed value is ``sections[KEY]`` (None when the file has no such
    table), also readable as an attribute: ``der.contact is der.sections["contact"]``.

    Attributes
    ----------
    punch_traits : frozenset of str
        What the file's catalogue punch (``[punch] kind``) is beyond its formula, in the words of
        :data:`thinlayer.errata.PUNCHES` (``"sphere"``, ``"elliptic paraboloid"``): the sections that print a
        catalogue punch's closed forms in its own symbols (the ellipse (3.1), the sphere's (I.11)) ask for it
        instead of the punch's name.  Empty for a punch given by ``expr``.
    """

    name: str
    title: str
    layer: LayerKernel
    punch: Punch | None
    coefficient_order: int
    units: dict | None = None
    sections: Mapping[str, Any] = field(default_factory=dict)
    punch_traits: frozenset = frozenset()

    def __getattr__(self, key: str) -> Any:
        # only reached when no field has the name: a section's table by its KEY (None when the file has none)
        if key.startswith("_") or key == "sections":
            raise AttributeError(key)
        if any(s.KEY == key for s in SECTIONS):
            return self.sections.get(key)
        raise AttributeError(f"'Derivation' object has no attribute {key!r}")


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


#: the schema of the core tables (read here): table -> {key: (python types, what is valid)}
CORE_SCHEMA: dict[str, dict[str, tuple[tuple[type, ...], str]]] = {
    "derivation": {"name": ((str,), "a file-name-safe string (letters, digits, '-', '_')"),
                   "title": ((str,), "a string")},
    "layer": {"model": ((str,), "'bonded' or 'frictionless'"),
              "nu": ((str, int, float), "'symbolic', an exact string like '3/10' or a number")},
    "coefficients": {"order": ((int,), "an integer from 1 to 30")},
    "punch": {"kind": ((str,), "a catalogue name, 'flat' (a flat-ended cylinder, with [flat_punch]) or a tip of "
                               "revolution ('cone', 'sphere', 'blunted_cone', 'power_law', ... with its parameters)"),
              "expr": ((str,), "a polynomial in x_1, x_2 as a string")},
    "units": {"length": ((str,), "a length unit such as 'mm' or 'um'"),
              "stress": ((str,), "a stress unit such as 'MPa' or 'N/mm^2' (of mu and E)"),
              "force": ((str,), "a force unit such as 'N' or 'mN'")},
}
assert tuple(CORE_SCHEMA) == CORE_TABLES


class _Schema(Mapping):
    """The derivation file's schema, table -> {key: (python types, what is valid)}; any other key is an error.

    The core tables' (:data:`CORE_SCHEMA`) and the registered report sections' fragments
    (:func:`thinlayer.export.sections.schema`), assembled at each reading: a section registered later is in it.
    """

    def _tables(self) -> dict[str, dict[str, tuple[tuple[type, ...], str]]]:
        from .sections.tip import tip_parameters

        core = {**CORE_SCHEMA, "punch": {**CORE_SCHEMA["punch"], **tip_parameters()}}
        return {**core, **sections_schema()}

    def __getitem__(self, table: str) -> dict[str, tuple[tuple[type, ...], str]]:
        return self._tables()[table]

    def __iter__(self) -> Iterator[str]:
        return iter(self._tables())

    def __len__(self) -> int:
        return len(self._tables())

    def __repr__(self) -> str:
        return f"SCHEMA({self._tables()!r})"


#: the schema: table -> {key: (python types, what is valid)}; any other key is an error
SCHEMA: Mapping[str, dict[str, tuple[tuple[type, ...], str]]] = _Schema()
_REQUIRED = ("derivation", "layer", "punch")


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
    schema = dict(SCHEMA)
    unknown = sorted(set(data) - set(schema))
    if unknown:
        raise DerivationFileError(f"unknown table(s) {unknown}; valid tables are {sorted(schema)}")
    for t in _REQUIRED:
        if t not in data:
            raise DerivationFileError(f"the table [{t}] is required")
    for table, keys in schema.items():
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


#: the catalogue punches of ``[punch] kind``: the constructor, and what the punch is beyond its formula
#: (:attr:`Derivation.punch_traits`, in the words of :data:`thinlayer.errata.PUNCHES`)
_KINDS = {"elliptic_paraboloid": (Punch.elliptic_paraboloid, frozenset({"elliptic paraboloid"})),
          "paraboloid": (Punch.paraboloid, frozenset({"sphere"})),
          "fourth_degree": (Punch.fourth_degree, frozenset())}


def _punch_table(pu: dict) -> tuple[Punch | None, frozenset]:
    """The punch of ``[punch]`` and its traits: a catalogue ``kind`` or a polynomial ``expr``; its symbol names checked.

    ``kind = "flat"`` (the flat-ended cylinder) gives ``None``: its report is the section of ``[flat_punch]``.
    """
    if ("kind" in pu) == ("expr" in pu):
        raise DerivationFileError("[punch] needs exactly one of 'kind' (a catalogue punch) or 'expr' (a polynomial)")
    from .sections.tip import tip_kinds

    if pu.get("kind") == "flat" or pu.get("kind") in tip_kinds():  # the flat punch's or the tip's own section
        return None, frozenset()
    traits: frozenset = frozenset()
    if "kind" in pu:
        if pu["kind"] not in _KINDS:
            raise DerivationFileError(f"[punch] kind = {_short(pu['kind'])}: valid kinds are "
                                      f"{sorted([*_KINDS, 'flat', *tip_kinds()])}")
        extra = sorted(set(pu) - {"kind"})
        if extra:
            raise DerivationFileError(f"[punch] kind = {pu['kind']!r} takes no parameters here ({extra}): give their "
                                      "values in [contact] parameters")
        make, traits = _KINDS[pu["kind"]]
        punch = make()
    else:
        try:
            punch = Punch(pu["expr"])
        except (ValueError, TypeError, ArithmeticError, RecursionError) as exc:
            raise DerivationFileError(f"[punch]: {exc}") from exc
    try:
        check_symbol_names((q.name for q in punch.expr.free_symbols), "[punch]")
    except ReportTextError as exc:
        raise DerivationFileError(str(exc)) from exc
    return punch, traits


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
    punch, traits = _punch_table(data["punch"])
    units = _units_table(data.get("units"))
    context = ParseContext(layer, punch, corder, units, data)
    return Derivation(name, title, layer, punch, corder, units, parse_sections(data, context), traits)


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
        from .report import Document
        from .sections.errata import errata_document

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
    figures: Path | None = out / f"{der.name}-figures"
    figure_targets = figure_files(der, figures)  # the sections' figures (the validation plots)
    if not figure_targets:
        figures = None
    targets = [tex, *pdf_outputs(tex), *figure_targets]

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
