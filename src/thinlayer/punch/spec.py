"""``tip_from_spec("paraboloid:R=10")``: a tip from the text a user writes (CLI ``--tip``, derivation files, fit).

The form is ``KIND`` or ``KIND:key=value,key=value`` with ``KIND`` a key of :data:`~thinlayer.punch.TIPS` and the
keys its parameters (or their aliases).  Every value is read by the restricted grammar of :mod:`thinlayer.parse`
(numbers, parameter names, ``+ - * / **`` and parentheses; ``x_1, x_2`` in a formula), never evaluated as code.
"""
from __future__ import annotations

from typing import Any

from ..errors import InputTypeError, WorkLimitError
from ..parse import MAX_LENGTH, ExpressionError, parse_expression
from .base import PunchError, Tip, catalogue, tip_kind


class TipSpecError(PunchError):
    """A tip spec that names no registered kind, an unknown key, or a value the grammar does not read."""


def valid_forms() -> str:
    """The forms :func:`tip_from_spec` reads, one per registered kind, e.g. ``"paraboloid:R=<length>"``."""
    return ", ".join(row.form for row in catalogue().values())


def _split(text: str) -> list[str]:
    """Split ``key=value,key=value`` at the commas outside parentheses."""
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        depth += ch == "("
        depth -= ch == ")"
        if ch == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return parts


def tip_from_spec(spec: Any) -> Tip:
    """The tip a spec names: ``"paraboloid:R=10"``, ``"flat:a=1"``, ``"elliptic_paraboloid:R1=4,R2=1"``,
    ``"fourth_degree:R=1,K=2"``, ``"polynomial:expr=x_1**2 + 2*x_2**2"``.

    A parameter left out stays a symbol where the kind allows it (``"paraboloid"`` is ``Punch.paraboloid()``).

    Raises
    ------
    TipSpecError
        An unknown kind or key, a key given twice, a missing required key, or a value the restricted grammar
        does not read; the message lists the valid forms.
    """
    if not isinstance(spec, str):
        raise InputTypeError(f"a tip spec must be a string such as 'paraboloid:R=10', got {type(spec).__name__}")
    if len(spec) > MAX_LENGTH:
        raise TipSpecError(f"the tip spec has {len(spec)} characters, more than {MAX_LENGTH}")
    kind, _, rest = spec.strip().partition(":")
    kind = kind.strip()
    row = tip_kind(kind)  # a loaded kind (paraboloid, flat) without importing every tip module (issue 28 item 6)
    if row is None:
        raise TipSpecError(f"unknown tip kind {kind!r} in the tip spec {spec!r:.80}; valid forms: {valid_forms()}")
    keys = {k: p for p in row.parameters for k in (p.name, *p.aliases)}
    values: dict[str, Any] = {}
    for item in (_split(rest) if rest.strip() else []):
        key, eq, text = item.partition("=")
        key = key.strip()
        if not eq or key not in keys:
            what = f"unknown key {key!r}" if eq else f"{item.strip()!r} is not key=value"
            raise TipSpecError(f"{what} in the tip spec {spec!r:.80}; the form of {kind!r} is {row.form} "
                               f"(valid forms: {valid_forms()})")
        par = keys[key]
        if par.name in values:
            raise TipSpecError(f"the key {par.name!r} is given twice in the tip spec {spec!r:.80}")
        try:
            values[par.name] = parse_expression(text.strip(), coordinates=par.unit_kind == "expression",
                                                radial=par.unit_kind == "profile",
                                                what=f"the {par.description} {par.name}")
        except ExpressionError as exc:
            raise (type(exc) if isinstance(exc, WorkLimitError) else TipSpecError)(
                f"the tip spec {spec!r:.80}: {exc}") from None
    missing = [p.name for p in row.parameters if p.required and p.name not in values]
    if missing:
        raise TipSpecError(f"the tip spec {spec!r:.80} misses {', '.join(missing)}: the form of {kind!r} is {row.form}")
    return row.constructor(**values)
