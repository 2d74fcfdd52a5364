"""What the subcommands of ``thinlayer`` share: the one-line bad-input error, the punch and base options, the
layer of a Poisson ratio, the punch parameters, and text output that falls back to ASCII.

Imported by :mod:`thinlayer.export.cli` and the subcommand modules (``solve_cli``, ``fit_cli``, ``flat_cli``);
it imports none of them.
"""
from __future__ import annotations

import argparse
import math
import sys
from typing import Any

__all__ = ["BASES", "BadInput", "KINDS", "NOTE", "SHORTCUTS", "TIP_KINDS", "add_punch_args", "add_tip_shortcuts",
           "base_arg", "finite", "nonfinite", "print_text", "punch_from_args", "punch_params", "shortcuts_given",
           "solve_layer", "tip_from_shortcut", "tip_needs_values"]


def finite(text: str) -> float:
    """An argparse type: a finite float."""
    try:
        val = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(val):
        raise argparse.ArgumentTypeError(f"{text!r} is not a finite number")
    return val


class BadInput(ValueError):
    """Raised for invalid command-line values (exit code 2)."""


def nonfinite(obj: Any, path: str = "") -> str | None:
    """The key path of the first non-finite number in a JSON-like object, or None."""
    if isinstance(obj, float) and not math.isfinite(obj):
        return path or "value"
    if isinstance(obj, dict):
        items: Any = obj.items()
    elif isinstance(obj, (list, tuple)):
        items = enumerate(obj)
    else:
        return None
    for k, v in items:
        bad = nonfinite(v, f"{path}.{k}" if path else str(k))
        if bad:
            return bad
    return None


#: the catalogue names of the deprecated ``--kind NAME`` (each a kind of ``--tip``)
KINDS = ("elliptic_paraboloid", "paraboloid", "fourth_degree")
#: the kinds of ``--tip``: the keys of :data:`thinlayer.punch.TIPS`, written out so that building the parser imports
#: no sympy (``thinlayer --help`` stays fast); a test keeps them equal to the registry's keys
TIP_KINDS = ("blunted_cone", "cone", "flat", "paraboloid", "elliptic_paraboloid", "fourth_degree", "polynomial",
             "power_law", "revolution", "sphere", "pyramid", "polyhedral")
#: the attribute of the parsed arguments holding the deprecation note of ``--kind``/``--flat`` (printed by
#: :func:`thinlayer.export.cli.main` on stderr after a command that succeeded)
NOTE = "deprecation_note"


def _kind_note(kind: str, params: list[str] | None) -> str:
    """``--kind NAME [--param K=V ...]`` in the words of ``--tip``: ``"--kind paraboloid is deprecated; use --tip
    paraboloid:R=10"`` (a ``--param`` name that is an alias of the kind's key, ``R_1``, is written as the key).
    """
    from ..punch import tip_kind

    row = tip_kind(kind)
    keys = {k: p.name for p in (row.parameters if row else ()) for k in (p.name, *p.aliases)}
    items = []
    for it in params or []:
        k, _, v = it.partition("=")
        items.append(f"{keys.get(k.strip(), k.strip())}={v.strip()}")
    spec = kind + (":" + ",".join(items) if items else "")
    return f"--kind {kind} is deprecated; use --tip {spec}"


def tip_needs_values(tip, spec: str) -> None:
    """Refuse a ``--tip`` spec that leaves parameters symbolic where numbers are needed (``solve``, ``codegen
    composite``): one line naming the spec's keys, ``write --tip paraboloid:R=VALUE`` (``--param`` is refused with
    ``--tip``, so the library's "give --param" would send the user in a circle).
    """
    if not tip.parameters:
        return
    from ..punch import tip_kind

    row = tip_kind(tip.kind)
    keys = {a: p.name for p in (row.parameters if row else ()) for a in (p.name, *p.aliases)}
    missing = [keys.get(str(s), str(s)) for s in tip.parameters]
    fix = spec.strip() + ("," if ":" in spec else ":") + ",".join(f"{k}=VALUE" for k in missing)
    raise BadInput(f"--tip {spec}: {', '.join(missing)} without a value; write --tip {fix}")


def punch_from_args(args, allow_flat: bool = False):
    """The punch of ``--tip KIND:key=value,...``, ``--punch EXPR``, ``--kind NAME`` (with ``--param``; deprecated) or,
    where ``allow_flat``, ``--flat A`` (deprecated).

    Without ``allow_flat`` (``inner``, ``codegen``) the tip must be a polynomial (:attr:`Tip.polynomial`): the
    symbolic stages (2.26)-(3.25) take only those.  A deprecated option sets the note :data:`NOTE` on ``args``.

    Returns the punch, or ``(punch, flat)`` with ``allow_flat`` (``flat``: a tip with a fixed contact, the
    flat-ended cylinder, was asked for).
    """
    from ..punch import Punch

    flat_a = getattr(args, "flat", None) if allow_flat else None
    spec = getattr(args, "tip", None)
    given = [o for o, v in (("--tip", spec), ("--punch", args.punch), ("--kind", args.kind), ("--flat", flat_a))
             if v is not None] + shortcuts_given(args)
    if len(given) != 1:
        choices = ("--tip KIND:key=value,... (thinlayer.punch.TIPS), --punch EXPR (a polynomial in x_1, x_2), "
                   f"--kind NAME ({', '.join(KINDS)})") + (" and --flat A" if allow_flat else "")
        if hasattr(args, "cone"):
            choices = choices.replace(" and --flat A", ", --flat A") + ", " + SHORTCUT_FORMS
        raise BadInput(f"give exactly one of {choices}" + (f"; got {' and '.join(given)}" if given else ""))
    if shortcuts_given(args):
        tip = tip_from_shortcut(args)
        return (tip, False) if allow_flat else tip
    if spec is not None:
        from ..punch import tip_from_spec

        if args.param:
            raise BadInput("--tip KIND:key=value,... holds the tip's values: leave out --param")
        if allow_flat:  # solve: a quadric with plain numbers takes the numeric route, no sympy (issue 28 item 6)
            kind, _, rest = spec.strip().partition(":")
            numeric = _numeric_kind(kind.strip(), [i for i in rest.split(",") if i.strip()])
            if numeric is not None:
                return numeric, False
        tip = tip_from_spec(spec)
        if allow_flat:  # solve: numbers
            tip_needs_values(tip, spec)
            return tip, bool(tip.fixed_contact)
        if tip.polynomial is None:
            raise BadInput(f"--tip {spec}: the {tip.name} is not a polynomial in x_1, x_2, and the symbolic stages "
                           "(2.26)-(3.25) need one (e.g. --tip paraboloid, --tip polynomial:expr='x_1**2/2 + x_2**4')")
        return tip
    if flat_a is not None:
        from ..punch import FlatPunch

        if args.param:
            raise BadInput("--flat A is the flat-ended cylinder of radius A: leave out --param")
        setattr(args, NOTE, f"--flat {flat_a:g} is deprecated; use --tip flat:a={flat_a:g}")
        return FlatPunch(flat_a), True
    if args.kind is not None:
        setattr(args, NOTE, _kind_note(args.kind, args.param))
        numeric = _numeric_kind(args.kind, args.param) if allow_flat else None
        if numeric is not None:  # solve: the punch with its numbers, no symbolic radii (issue 28 item 6)
            return numeric, False
    punch = getattr(Punch, args.kind)() if args.kind is not None else Punch(args.punch)
    return (punch, False) if allow_flat else punch


def _numeric_kind(kind: str, items: list[str] | None):
    """``Punch.<kind>(**numbers)`` when ``--param`` gives every radius of a catalogue kind as a plain number, else
    None (the symbolic punch and ``parameters=`` then, as before).
    """
    from ..punch import Punch, tip_kind

    row = tip_kind(kind)
    if row is None or kind not in ("paraboloid", "elliptic_paraboloid"):
        return None
    try:
        given = punch_params(items)
    except ValueError:
        return None
    names = {k: p.name for p in row.parameters for k in (p.name, *p.aliases)}
    values = {names.get(k): v for k, v in given.items()}
    if None in values or len(values) != len(given) or set(values) != {p.name for p in row.parameters}:
        return None
    punch = getattr(Punch, kind)(**values)
    return punch if punch.formula_text is not None else None


#: the tip options of ``solve`` and ``fit``: option -> (TIPS key, metavars); values go to the kind's parameters in
#: the registry's order (a parameter named or aliased ``sides`` takes ``--sides``)
SHORTCUTS = {"--cone": ("cone", ("ANGLE",)), "--pyramid": ("pyramid", ("ANGLE",)), "--sphere": ("sphere", ("R",)),
             "--blunted-cone": ("blunted_cone", ("R", "ANGLE")), "--power-law": ("power_law", ("C", "N"))}
SHORTCUT_FORMS = ", ".join(f"{o} {' '.join(m)}" for o, (_, m) in SHORTCUTS.items())


def _dest(option: str) -> str:
    return option[2:].replace("-", "_")


def add_tip_shortcuts(p: argparse.ArgumentParser) -> None:
    """``--cone ANGLE``, ``--pyramid ANGLE --sides N``, ``--sphere R``, ``--blunted-cone R ANGLE``, ``--power-law C
    N``: the tips of :data:`thinlayer.punch.TIPS` by their usual names (angles in degrees).
    """
    g = p.add_argument_group("tips (one of them, or --tip; angles are half-angles in degrees, 0 < ANGLE < 90)")
    helps = {"--cone": "cone of half-angle ANGLE degrees (AFM cones: 70 or so)",
             "--pyramid": "pyramid of face half-angle ANGLE degrees with --sides faces (3 or 4; default 4)",
             "--sphere": "the exact sphere of radius R (the cap, not the paraboloid)",
             "--blunted-cone": "cone of half-angle ANGLE degrees with a spherical apex of radius R (tangent join)",
             "--power-law": "Phi = C r^N (N >= 1)"}
    for option, (_, metavars) in SHORTCUTS.items():
        g.add_argument(option, type=finite, nargs=len(metavars), metavar=metavars if len(metavars) > 1 else
                       metavars[0], help=helps[option])
    g.add_argument("--sides", type=int, default=None, help="faces of --pyramid: 3 or 4 (default 4)")


def shortcuts_given(args) -> list[str]:
    """The tip options of :data:`SHORTCUTS` on the command line."""
    return [o for o in SHORTCUTS if getattr(args, _dest(o), None) is not None]


def tip_from_shortcut(args):
    """The tip of the one option of :data:`SHORTCUTS` given, built through the registry :data:`thinlayer.punch.TIPS`
    (one line naming the option for a bad value, or a kind not registered yet).
    """
    from ..punch import TIPS

    (option,) = shortcuts_given(args)
    kind, _ = SHORTCUTS[option]
    values = getattr(args, _dest(option))
    values = [int(v) if float(v).is_integer() else v for v in (values if isinstance(values, list) else [values])]
    shown = f"{option} {' '.join(f'{v:g}' for v in values)}"
    sides = getattr(args, "sides", None)
    if sides is not None and option != "--pyramid":
        raise BadInput(f"--sides goes with --pyramid only (got {shown})")
    row = TIPS.get(kind)
    if row is None:
        raise BadInput(f"{shown}: this thinlayer has no {kind} tip yet (thinlayer.punch.TIPS: "
                       f"{', '.join(TIPS)})")
    named = [p for p in row.parameters if "sides" not in (p.name, *p.aliases)]
    kwargs = {p.name: v for p, v in zip(named, values)}
    if option == "--pyramid":
        side = next((p for p in row.parameters if "sides" in (p.name, *p.aliases)), None)
        if sides is not None and sides not in (3, 4):
            raise BadInput(f"--sides {sides}: a pyramid has 3 or 4 sides")
        if side is not None:
            kwargs[side.name] = 4 if sides is None else sides
    try:
        return row.constructor(**kwargs)
    except (ValueError, TypeError) as exc:
        raise BadInput(f"{shown}: {exc}") from None


def punch_params(items: list[str] | None) -> dict[str, float]:
    out = {}
    for it in items or []:
        if "=" not in it:
            raise BadInput(f"--param {it!r}: write NAME=VALUE, e.g. --param R_1=4")
        k, v = it.split("=", 1)
        try:
            val = float(v)
        except ValueError as exc:
            raise BadInput(f"--param {it!r}: {v!r} is not a number") from exc
        if not math.isfinite(val):
            raise BadInput(f"--param {it!r}: {v!r} is not a finite number")
        out[k.strip()] = val
    return out


def print_text(text: str) -> None:
    """Print Unicode text, or its ASCII form (:func:`thinlayer.normal.to_ascii`) on a stream that cannot take it."""
    enc = getattr(sys.stdout, "encoding", None) or "utf-8"
    try:
        text.encode(enc)
    except (UnicodeEncodeError, LookupError):
        from ..normal import to_ascii

        text = to_ascii(text)
    print(text)


def add_punch_args(p: argparse.ArgumentParser, flat: bool = False) -> None:
    """``--tip`` (the tip registry), ``--punch``, ``--param`` and the deprecated ``--kind`` (and, with ``flat``,
    ``--flat``), hidden from ``--help`` like every former spelling.
    """
    where = "" if flat else "; here a polynomial tip (the symbolic stages need one)"
    p.add_argument("--tip", metavar="KIND:key=value,...",
                   help=f"a tip of the registry thinlayer.punch.TIPS, KIND one of {', '.join(TIP_KINDS)}; a value "
                        "left out stays a symbol (--tip paraboloid: the paraboloid of radius R), e.g. "
                        f"paraboloid:R=10, cone:half_angle=70, flat:a=1, sphere:R=2{where}")
    p.add_argument("--punch", help="the punch Phi as a polynomial in x_1, x_2, e.g. 'x_1**2/8 + x_2**2/2'")
    p.add_argument("--kind", choices=KINDS, help=argparse.SUPPRESS)  # deprecated: --tip KIND
    p.add_argument("--param", action="append", metavar="NAME=VALUE",
                   help="a value for a parameter of --punch (repeatable), e.g. --param R=4")
    if flat:
        p.add_argument("--flat", type=finite, metavar="A", help=argparse.SUPPRESS)  # deprecated: --tip flat:a=A


#: the bases of a layer (``--base``)
BASES = ("bonded", "frictionless")


def base_arg(p: argparse.ArgumentParser, help: str, old: str | None = None) -> None:
    """``--base bonded|frictionless`` (one name in every subcommand); ``old``: the former spelling, kept hidden."""
    p.add_argument("--base", choices=BASES, default="bonded", help=help)
    if old:
        p.add_argument(old, dest="base", choices=BASES, help=argparse.SUPPRESS)


def solve_layer(kind: str, nu: str):
    """The layer of ``thinlayer solve``: bonded (nu up to 1/2, 1/2 the incompressible layer) or frictionless."""
    from ..layers.kernels import BondedLayer, FrictionlessLayer

    try:
        val: Any = nu if "/" in nu else float(nu)
    except ValueError as exc:
        raise BadInput(f"--nu {nu!r}: use an exact fraction such as 3/10, or a number in (-1, 1/2]") from exc
    try:
        return FrictionlessLayer(val) if kind == "frictionless" else BondedLayer(val)
    except (ValueError, TypeError, ArithmeticError) as exc:
        raise BadInput(f"--nu {nu}: {exc}") from exc
