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

__all__ = ["BASES", "BadInput", "KINDS", "add_punch_args", "base_arg", "finite", "nonfinite", "print_text",
           "punch_from_args", "punch_params", "solve_layer"]


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


KINDS = ("elliptic_paraboloid", "paraboloid", "fourth_degree")


def punch_from_args(args, allow_flat: bool = False):
    """The punch of ``--punch EXPR``, ``--kind NAME`` (with ``--param``) or, where ``allow_flat``, ``--flat A``.

    Returns the punch, or ``(punch, flat)`` with ``allow_flat`` (``flat``: the flat-ended cylinder was asked for).
    """
    from ..punch import Punch

    flat_a = getattr(args, "flat", None) if allow_flat else None
    spec = getattr(args, "tip", None) if allow_flat else None
    given = [o for o, v in (("--tip", spec), ("--punch", args.punch), ("--kind", args.kind), ("--flat", flat_a))
             if v is not None]
    if len(given) != 1:
        choices = ("--tip KIND:key=value,... (thinlayer.punch.TIPS), " if allow_flat else "") + (
            "--punch EXPR (a polynomial in x_1, x_2), --kind NAME " + f"({', '.join(KINDS)})") + (
            " and --flat A" if allow_flat else "")
        raise BadInput(f"give exactly one of {choices}" + (f"; got {' and '.join(given)}" if given else ""))
    if spec is not None:
        from ..punch import tip_from_spec

        if args.param:
            raise BadInput("--tip KIND:key=value,... holds the tip's values: leave out --param")
        tip = tip_from_spec(spec)
        return tip, bool(getattr(tip, "fixed_contact", False))
    if flat_a is not None:
        from ..punch import FlatPunch

        if args.param:
            raise BadInput("--flat A is the flat-ended cylinder of radius A: leave out --param")
        return FlatPunch(flat_a), True
    punch = getattr(Punch, args.kind)() if args.kind is not None else Punch(args.punch)
    return (punch, False) if allow_flat else punch


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
    p.add_argument("--punch", help="the punch Phi as a polynomial in x_1, x_2, e.g. 'x_1**2/8 + x_2**2/2'")
    p.add_argument("--kind", choices=KINDS, help="a catalogue punch with symbolic parameters instead of --punch")
    p.add_argument("--param", action="append", metavar="NAME=VALUE",
                   help="a value for a punch parameter (repeatable), e.g. --param R_1=4 --param R_2=1")
    if flat:
        p.add_argument("--tip", metavar="KIND:key=value,...",
                       help="a tip of the registry thinlayer.punch.TIPS, e.g. paraboloid:R=10, cone:half_angle=70, "
                            "flat:a=1, sphere:R=2 (instead of --kind/--param, --punch, --flat)")
        p.add_argument("--flat", type=finite, metavar="A",
                       help="a flat-ended cylinder of radius A instead of --kind/--punch (--delta0 is its depth w0)")


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
