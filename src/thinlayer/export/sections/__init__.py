r"""The sections of a derivation's report: a registry, one module per section, in the order of :data:`SECTIONS`.

A section module declares

``KEY``
    the table of the derivation file it reads (``"contact"`` for ``[contact]``), or None;
``SCHEMA``
    its fragment of the file's schema, ``{key: (python types, what is valid)}`` (empty without a ``KEY``);
``parse(table, context)``
    the value of its table (None when the file has none; ``table`` is None then), checked and converted,
    raising :class:`~thinlayer.export.sections.base.DerivationFileError` naming the key and what is valid;
    ``context`` is a :class:`~thinlayer.export.sections.base.ParseContext` (the core tables, read);
``applies(derivation)``
    whether the report of ``derivation`` has this section;
``render(doc, derivation, context)``
    append the section to ``doc`` (a :class:`thinlayer.export.report.Document`); ``context`` is a
    :class:`~thinlayer.export.sections.base.RenderContext`;
``ORDER``
    an int, its place in the report (unique);

and optionally ``figure_files(derivation, folder)``, the figure files it writes into ``folder`` (they are checked
before anything is written).  :func:`register_section` checks this contract; the derivation file's schema
(:data:`thinlayer.export.derivation.SCHEMA`) is the core tables' and the registered sections' fragments, and the
parsed tables are ``Derivation.sections[KEY]``.  A new section is one module and one :func:`register_section`
call: :func:`thinlayer.export.report.derivation_document` renders every registered section that applies, in
``ORDER``.

>>> [s.__name__.rsplit(".", 1)[1] for s in SECTIONS][:3]
['intro', 'kernel', 'inner']
"""
from __future__ import annotations

import re
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from ...errors import InputError, InputTypeError
from .base import DerivationFileError, ParseContext, RenderContext

__all__ = ["CORE_TABLES", "SECTIONS", "SectionContractError", "DerivationFileError", "ParseContext", "RenderContext",
           "figure_files", "parse_sections", "register_section", "schema", "unregister_section"]

#: the derivation file's own tables, read by :mod:`thinlayer.export.derivation` (a section may not claim one)
CORE_TABLES = ("derivation", "layer", "coefficients", "punch", "units")
#: the attributes every section declares
REQUIRED = ("KEY", "SCHEMA", "parse", "applies", "render", "ORDER")
_TABLE_NAME = re.compile(r"[a-z][a-z0-9_]{0,39}")

#: the registered sections in report order (``ORDER``); kept sorted in place by :func:`register_section`
SECTIONS: list[Any] = []


class SectionContractError(InputTypeError):
    """A report section that does not declare what :func:`register_section` requires; the message says what."""


def _name(section: Any) -> str:
    return getattr(section, "__name__", None) or type(section).__name__


def _check_schema(name: str, key: str | None, fragment: Any) -> None:
    if not isinstance(fragment, Mapping):
        raise SectionContractError(f"section {name}: SCHEMA must be a mapping {{key: (types, what is valid)}}, "
                                   f"got {type(fragment).__name__}")
    if key is None and fragment:
        raise SectionContractError(f"section {name}: SCHEMA {sorted(fragment)} without a KEY (a table to read)")
    for k, spec in fragment.items():
        ok = (isinstance(k, str) and isinstance(spec, tuple) and len(spec) == 2 and isinstance(spec[0], tuple)
              and spec[0] and all(isinstance(t, type) for t in spec[0]) and isinstance(spec[1], str))
        if not ok:
            raise SectionContractError(f"section {name}: SCHEMA[{k!r}] must be ((python types, ...), 'what is "
                                       f"valid'), got {spec!r}")


def register_section(section: Any) -> Any:
    """Add a report section (a module or any object with the attributes of the contract) to :data:`SECTIONS`.

    Parameters
    ----------
    section : module or object
        With ``KEY``, ``SCHEMA``, ``parse``, ``applies``, ``render``, ``ORDER`` (see :mod:`thinlayer.export.sections`)
        and optionally ``figure_files``.

    Returns
    -------
    module or object
        ``section`` (so that the call can decorate a class).

    Raises
    ------
    SectionContractError
        an attribute missing or of the wrong kind, an ``ORDER`` or a ``KEY`` another section has, a ``KEY`` that
        is a core table (:data:`CORE_TABLES`) or no valid table name.
    """
    name = _name(section)
    missing = [a for a in REQUIRED if not hasattr(section, a)]
    if missing:
        raise SectionContractError(f"section {name} does not declare {', '.join(missing)}; a section declares "
                                   f"{', '.join(REQUIRED)}")
    order, key = section.ORDER, section.KEY
    if isinstance(order, bool) or not isinstance(order, int):
        raise SectionContractError(f"section {name}: ORDER = {order!r} must be an int (its place in the report)")
    for fn in ("parse", "applies", "render", "figure_files"):
        if hasattr(section, fn) and not callable(getattr(section, fn)):
            raise SectionContractError(f"section {name}: {fn} must be callable")
    if key is not None and not (isinstance(key, str) and _TABLE_NAME.fullmatch(key)):
        raise SectionContractError(f"section {name}: KEY = {key!r} must be None or a table name (lower-case "
                                   "letters, digits and '_', starting with a letter)")
    if key in CORE_TABLES:
        raise SectionContractError(f"section {name}: KEY = {key!r} is a core table of the derivation file "
                                   f"({', '.join(CORE_TABLES)})")
    _check_schema(name, key, section.SCHEMA)
    for other in SECTIONS:
        if other is section:
            raise SectionContractError(f"section {name} is registered already")
        if other.ORDER == order:
            raise SectionContractError(f"section {name}: ORDER = {order} is that of section {_name(other)}")
        if key is not None and other.KEY == key:
            raise SectionContractError(f"section {name}: KEY = {key!r} is read by section {_name(other)}")
    SECTIONS.append(section)
    SECTIONS.sort(key=lambda s: s.ORDER)
    return section


def unregister_section(section: Any) -> None:
    """Remove a section :func:`register_section` added (a plug-in's or a test's); an InputError if it is not there."""
    if not any(s is section for s in SECTIONS):
        raise InputError(f"section {_name(section)} is not registered")
    SECTIONS[:] = [s for s in SECTIONS if s is not section]


def schema() -> dict[str, dict[str, tuple[tuple[type, ...], str]]]:
    """The registered sections' fragments of the derivation file's schema, ``{table: {key: (types, what)}}``."""
    return {s.KEY: dict(s.SCHEMA) for s in SECTIONS if s.KEY is not None}


def parse_sections(tables: Mapping[str, Any], context: ParseContext) -> dict[str, Any]:
    """``{KEY: value}``: each section's table of ``tables`` (the parsed TOML) checked and converted, in ``ORDER``."""
    return {s.KEY: s.parse(tables.get(s.KEY), context) for s in SECTIONS if s.KEY is not None}


def figure_files(derivation: Any, folder: Path) -> list[Path]:
    """The figure files the report of ``derivation`` writes into ``folder`` (empty: a report without figures)."""
    out: list[Path] = []
    if not hasattr(derivation, "sections"):  # a document that is no derivation file (the errata)
        return out
    for s in SECTIONS:
        hook = getattr(s, "figure_files", None)
        if hook is not None and s.applies(derivation):
            out += hook(derivation, folder)
    return out


# the report's sections, each in its module (their ORDER makes the report's order, not the list below)
from . import (  # noqa: E402 - the registry above is what they register into
    adhesion,
    boundary_layer,
    contact,
    edge_shift,
    errata,
    flat_punch,
    incompressible,
    inner,
    intro,
    kernel,
    references,
    second_order,
    tip,
    two_term,
    validation,
    viscoelastic,
)

for _section in (intro, kernel, inner, boundary_layer, two_term, incompressible, edge_shift, tip, second_order,
                 contact, validation, flat_punch, adhesion, viscoelastic, errata, references):
    register_section(_section)
