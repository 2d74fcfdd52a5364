"""``thinlayer fit curve.csv --R ... --H ... --nu ...``: Young's modulus from a force-indentation curve.

:func:`add_fit_parser` adds the subcommand to the ``thinlayer`` parser, :func:`cmd_fit` runs it.  The CSV has
a depth column and a force column (default the first two; ``--columns`` picks others, by index or header
name; the depth is positive into the sample, ``--depth-sign -1`` flips a tip position, negative into it); a
header row, blank lines and ``#`` comments are skipped; comma, semicolon, tab or blanks separate the fields.
Every value is parsed as a finite number (never evaluated): a bad cell is a one-line error naming its row and
column.  ``--H`` omitted or ``inf`` is the half-space (Hertz).  The result goes to stdout (text, or ``--json``),
and with ``--out FILE`` to a file, which is never replaced unless ``--overwrite`` is given.

Instrument files (issue 25 item 3).  A file whose suffix afmformats reads (``.jpk-force``, ``.jpk-force-map``,
``.jpk-qi-data``, ``.jpk-qi-series``, ``.ibw``, ``.h5``, ...; ``.csv``, ``.txt`` and ``.tab`` stay with the CSV reader)
is read through :func:`thinlayer.afm.curves.load_curve` (``--segment``, ``--index``; tip position [m], negative into
the sample, force [N]: give ``--R`` and ``--H`` in metres) and fitted by :func:`thinlayer.afm.curve_fit.fit_curve`
with the contact point and the baseline as parameters (``--contact-point free|VALUE``, ``--baseline
offset|offset+slope``, ``--weighting none|nanite``, ``--fit-range LO HI`` with ``--range-kind
position|indentation``, ``--bootstrap N`` block-bootstrap refits).  A CSV takes the same options (then its depth
column is the axis, ``--depth-sign -1`` a tip position); without them it is fitted by :func:`thinlayer.fit` as
before.
"""
from __future__ import annotations

import argparse
import csv
import io
import json
import math
import re
import sys
import warnings
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError
from .cli_args import finite

__all__ = ["add_fit_parser", "cmd_fit", "read_curve"]

#: the largest CSV accepted (bytes), checked before reading
MAX_BYTES = 200 * 2**20

_SPLIT = re.compile(r"[,;\t ]+")


def _number(cell: str, row: int, col: int, path: str) -> float:
    s = cell.strip()
    try:
        val = float(s)
    except ValueError:
        raise InputError(f"{path}: row {row}, column {col}: {s[:40]!r} is not a number") from None
    if not math.isfinite(val):
        raise InputError(f"{path}: row {row}, column {col}: {s[:40]!r} is not a finite number")
    return val


def _fields(line: str) -> list[str]:
    if "," in line or ";" in line or "\t" in line:
        return [f for f in next(csv.reader([line], delimiter="," if "," in line else ";" if ";" in line else "\t"))]
    return _SPLIT.split(line.strip())


def read_curve(path: str | Path, columns: str = "0,1") -> tuple[np.ndarray, np.ndarray]:
    """``(delta, force)`` from a CSV file: two columns chosen by index or by header name (``"depth,force"``).

    Raises
    ------
    ValueError
        One line naming the file, and the row and column of a cell that is not a finite number.
    """
    p = Path(path)
    if not p.is_file():
        raise InputError(f"{path}: no such file")
    size = p.stat().st_size
    if size > MAX_BYTES:
        raise InputError(f"{path}: {size} bytes exceed the limit of {MAX_BYTES} bytes; subsample the curve")
    sel = [c.strip() for c in columns.split(",")]
    if len(sel) != 2 or not all(sel):
        raise InputError(f"--columns must name two columns, depth and force (indices or header names), got {columns!r}")
    from ..contact.fit import MAX_POINTS

    text = p.read_text(encoding="utf-8", errors="strict")
    lines = text.count("\n")
    if lines > MAX_POINTS + 1000:  # before splitting 10 million rows into fields (gigabytes of Python lists)
        raise InputError(f"{path}: {lines} lines, more than the {MAX_POINTS} points a fit accepts; subsample the "
                         "curve")
    rows = [(i + 1, _fields(line)) for i, line in enumerate(io.StringIO(text))
            if line.strip() and not line.lstrip().startswith("#")]
    if not rows:
        raise InputError(f"{path}: no data rows")
    first = rows[0][1]
    header = None
    try:
        [float(c) for c in first]
    except ValueError:
        header = [c.strip() for c in first]
        rows = rows[1:]
    idx = []
    for c in sel:
        if c.lstrip("-").isdigit():
            idx.append(int(c))
        elif header is not None and c in header:
            idx.append(header.index(c))
        else:
            raise InputError(f"{path}: no column {c!r}" + (f" (header: {', '.join(header)})" if header else
                                                             " (the file has no header: give indices)"))
    d, f = [], []
    for line_no, cells in rows:
        try:
            dv, fv = (_number(cells[j], line_no, j, str(path)) for j in idx)
        except IndexError:
            raise InputError(f"{path}: row {line_no} has {len(cells)} field(s), column {max(idx)} needed") from None
        d.append(dv)
        f.append(fv)
    return np.array(d), np.array(f)


def add_fit_parser(subparsers: Any, formatter_class: type) -> argparse.ArgumentParser:
    """Add ``fit`` to the ``thinlayer`` subcommands; the handler is :func:`cmd_fit` (``func`` default)."""
    s = subparsers.add_parser(
        "fit", formatter_class=formatter_class, help="Young's modulus from a force-indentation curve (any thickness)",
        description="Least-squares fit of E (optionally H and the contact point) to a force-indentation curve on\n"
                    "a layer (thinlayer.fit): a sphere (--R, the paraboloid of radius R; any thickness) or another\n"
                    "tip (--cone, --sphere, --blunted-cone, --power-law, --pyramid, --tip; the tip-law and direct "
                    "models).\nJSON keys: file, model, base, nu, R (null for a tip other than the paraboloid), tip, "
                    "E, E_se,\nH (null: the half-space), H_se, offset, offset_se, residual_rms, n_points, fitted, "
                    "condition, chi_max, flags\n(regime limits passed: delta/H beyond small strain, delta/R), "
                    "depth_sign.\nAn instrument file (or a CSV with a measured-curve option) is fitted with the "
                    "contact point z0 and the\nbaseline b0 + b1 (z - z0) free (thinlayer.fit_curve); its JSON "
                    "keys: E, H, z0, b0, b1, each with _se and\n_se_boot, covariance, fitted, chi_max, delta_max, "
                    "delta_over_H, delta_over_R, valid, validity, flags,\nbootstrap, block_length, phi, ...",
        epilog="examples:\n  thinlayer fit curve.csv --R 5e-6 --H 3e-6 --nu 0.5 --json\n"
               "  thinlayer fit curve.csv --columns depth,force --R 10 --H 2 --nu 0.3 --fit-offset --model hertz\n"
               "  thinlayer fit curve.csv --cone 70 --H 0.2 --nu 0.3\n"
               "  thinlayer fit curve.csv --blunted-cone 0.5 70 --H 0.2 --nu 0.3 --model tip-law --json")
    s.add_argument("csv", metavar="FILE", help="CSV file (a depth column and a force column, same length units as "
                   "--R, --H), or an instrument file afmformats reads (.jpk-force, .jpk-qi-data, .ibw, .h5, ...: "
                   "tip position in m, force in N)")
    s.add_argument("--R", type=finite, help="radius (> 0) of the sphere as a paraboloid r^2/(2R); or one tip below")
    s.add_argument("--tip", metavar="KIND:key=value,...", help="a tip of thinlayer.punch.TIPS with its values, e.g. "
                   "cone:half_angle=70, sphere:R=10")
    s.add_argument("--H", type=_thickness, default=None,
                   help="layer thickness (> 0; the starting value with --fit-H); omitted or inf: the half-space "
                        "(Hertz)")
    s.add_argument("--depth-sign", type=int, choices=(1, -1), default=1,
                   help="1 (default): the depth column is positive into the sample; -1: it is a tip position "
                        "(nanite, afmformats: negative into the sample), flipped")
    s.add_argument("--nu", type=finite, required=True, help="Poisson ratio in (-1, 1/2]")
    s.add_argument("--substrate-E", type=finite, default=None, metavar="E_S",
                   help="Young's modulus of the substrate (units of E): a FLAG when its compliance would change the "
                        "force by more than 1 %% (the laws take the base as rigid)")
    s.add_argument("--substrate-nu", type=finite, default=0.0, help="the substrate's Poisson ratio (default 0)")
    s.add_argument("--base", choices=("bonded", "frictionless"), default="bonded",
                   help="the base under the layer (default bonded)")
    s.add_argument("--model", choices=FIT_MODEL_CHOICES, default=None,
                   help="force model (default: any-thickness for --R, else the first model with a curve for the "
                        "tip, tip-law for the tips of revolution; direct: the axisymmetric solver, tabulated)")
    s.add_argument("--fit-H", action="store_true", help="also fit the thickness")
    s.add_argument("--fit-offset", action="store_true", help="also fit the contact point (depth offset)")
    s.add_argument("--work-of-adhesion", choices=("free",), default=None,
                   help="free: an adhesive (JKR) unloading curve, signed forces: fit E and the work of adhesion w "
                        "(the sphere, --R)")
    s.add_argument("--columns", default="0,1", help="depth and force columns: indices or header names (default 0,1)")
    s.add_argument("--out", type=Path, help="also write the result (text, or JSON with --json) to this file")
    s.add_argument("--overwrite", action="store_true", help="replace --out if it exists")
    s.add_argument("--json", action="store_true", help="machine-readable JSON output (keys above)")
    s.add_argument("--quiet", action="store_true", help="no 'wrote ...' message")
    c = s.add_argument_group("measured curves (instrument files; a CSV with any of these: the contact point and "
                             "baseline fitted, thinlayer.afm.curve_fit.fit_curve)")
    c.add_argument("--segment", choices=("approach", "retract"), default=None,
                   help="segment of an instrument file's curve (default approach)")
    c.add_argument("--index", type=int, default=0, help="curve of the file (a map holds many; default 0)")
    c.add_argument("--contact-point", type=_contact_point, default=None, metavar="free|VALUE",
                   help="the contact point: fitted (free, the default) or fixed at VALUE on the file's axis")
    c.add_argument("--baseline", choices=("offset", "offset+slope"), default=None,
                   help="baseline before contact: an offset (default) or an offset and a slope")
    c.add_argument("--weighting", choices=("none", "nanite"), default=None,
                   help="contact-point weighting: none (default) or nanite's linear ramp over --weight-cp")
    c.add_argument("--weight-cp", type=finite, default=None, help="width of nanite's weights (default 1e-6, the "
                   "axis's units)")
    c.add_argument("--fit-range", type=finite, nargs=2, default=None, metavar=("LO", "HI"),
                   help="fit only LO <= position <= HI (or LO <= indentation <= HI with --range-kind indentation)")
    c.add_argument("--range-kind", choices=("position", "indentation"), default=None,
                   help="what --fit-range bounds (default position)")
    c.add_argument("--bootstrap", type=int, default=None, metavar="N",
                   help="N AR-sieve bootstrap draws: errors whose 95 %% interval covers under correlated residuals")
    c.add_argument("--seed", type=int, default=None, help="seed of the bootstrap (default 0)")
    from .cli_args import add_tip_shortcuts

    add_tip_shortcuts(s)
    s.set_defaults(func=cmd_fit)
    return s


#: fit()'s models (the registry's entries with a force curve for fitting, by preference), written out so that
#: building the parser imports no scipy; a test keeps them equal to :data:`thinlayer.contact.fit.FIT_MODELS`
FIT_MODEL_CHOICES = ("tip-law", "any-thickness", "direct", "hertz", "dimitriadis2002", "garcia2018")


def _thickness(text: str) -> float:
    """``--H``: a finite number, or ``inf`` (the half-space)."""
    return math.inf if text.strip().lower() in ("inf", "+inf", "infinity") else finite(text)


def _contact_point(text: str) -> float | None:
    """``--contact-point``: ``free`` (None: fitted) or a finite number."""
    return None if text.strip().lower() == "free" else finite(text)


#: the options of a measured curve (dest, default); any of them given fits a CSV with fit_curve
_CURVE_OPTIONS = ("segment", "contact_point", "baseline", "weighting", "weight_cp", "fit_range", "range_kind",
                  "bootstrap", "seed")
#: plain-text suffixes: the CSV reader, even where afmformats has a format of its own
_TEXT = ("", ".csv", ".txt", ".tab", ".tsv", ".dat")


def _is_instrument(path: Path) -> bool:
    if path.suffix.lower() in _TEXT:
        return False
    from ..afm.curves import supported_suffixes

    return path.suffix.lower() in supported_suffixes()


def _fit_tip(args: argparse.Namespace):
    """The tip of ``--R`` (a paraboloid's radius, as a number), ``--tip`` or one tip option (exactly one)."""
    from .cli_args import BadInput, shortcuts_given, tip_from_shortcut

    given = [o for o, v in (("--R", args.R), ("--tip", args.tip)) if v is not None] + shortcuts_given(args)
    if len(given) != 1:
        raise BadInput("give exactly one of --R (a sphere as the paraboloid of radius R), --tip KIND:key=value,..., "
                       "--cone ANGLE, --pyramid ANGLE, --sphere R, --blunted-cone R ANGLE, --power-law C N"
                       + (f"; got {' and '.join(given)}" if given else ""))
    if args.R is not None:
        return args.R
    if args.tip is not None:
        from ..punch import tip_from_spec
        from .cli_args import tip_needs_values

        tip = tip_from_spec(args.tip)
        tip_needs_values(tip, args.tip)
        return tip
    return tip_from_shortcut(args)


def cmd_fit(args: argparse.Namespace) -> int:
    """Run ``thinlayer fit``; returns the exit code (0).  Bad input raises ValueError/TypeError (one line)."""
    from ..contact.fit import fit
    from ..errors import ValidityWarning
    from ..validation.output import atomic_write, refuse_existing

    if args.out is not None:
        refuse_existing([args.out], args.overwrite)
    punch = _fit_tip(args)
    path = Path(args.csv)
    given = [o for o in _CURVE_OPTIONS if getattr(args, o, None) is not None]
    if _is_instrument(path) or given:
        return _cmd_fit_curve(args, punch, path)
    delta, force = read_curve(args.csv, args.columns)
    if getattr(args, "work_of_adhesion", None) is not None:  # E and w of an adhesive curve (issue 26 item 5)
        from .adhesion_cli import adhesive_fit_text
        from .cli_args import print_text

        text = adhesive_fit_text(args, punch, delta, force)
        print_text(text)
        if args.out is not None:
            atomic_write(args.out, text + "\n")
        return 0
    with warnings.catch_warnings():  # a fit outside its model's range: the output says NOT VALID and why
        warnings.simplefilter("ignore", ValidityWarning)
        res = fit(delta, force, punch=punch, H=args.H, nu=args.nu, base=args.base, fit_H=args.fit_H,
                  fit_offset=args.fit_offset, model=args.model, depth_sign=args.depth_sign,
                  substrate_E=args.substrate_E, substrate_nu=args.substrate_nu)
    out = {"file": str(args.csv), **res.as_dict()}
    bad = [k for k, v in out.items() if isinstance(v, float) and not math.isfinite(v)]
    if bad:
        raise InputError(f"the fit's {bad[0]} is not a finite number: the data cannot determine the parameters")
    if args.json:
        text = json.dumps(out, indent=2, allow_nan=False)
    else:  # Unicode maths, in the command line's words
        from .solve_cli import cli_words, pretty

        what, size = res.tip_words, "χ_max" if res.paraboloid else "(c/H)_max"
        head = (f"fit of E by the {res.model} model: {what} on a {res.base} layer, ν = {res.nu:.6g}; "
                f"{res.n_points} points, {size} = {res.chi_max:.3g}")
        text = "\n".join([head, *(pretty(cli_words(ln)) for ln in res.text_lines()[1:])])
    from .cli_args import print_text

    print_text(text)
    if args.out is not None:
        atomic_write(args.out, text + "\n")
        if not args.quiet:
            print(f"wrote {args.out}", file=sys.stderr)
    return 0


def _cmd_fit_curve(args: argparse.Namespace, punch: Any, path: Path) -> int:
    """``thinlayer fit FILE`` of a measured curve: contact point and baseline fitted (thinlayer.afm.curve_fit)."""
    from ..afm.curve_fit import fit_curve
    from ..afm.curves import curve_from_arrays, load_curve
    from ..errors import ValidityWarning
    from ..validation.output import atomic_write

    if args.bootstrap is not None and args.bootstrap < 0:
        raise InputError(f"--bootstrap must be a number of refits >= 0, got {args.bootstrap}")
    if _is_instrument(path):
        for opt, bad in (("--columns", args.columns != "0,1"), ("--depth-sign", args.depth_sign != 1),
                         ("--fit-offset", args.fit_offset)):
            if bad:
                raise InputError(f"{opt} is for a CSV's columns; an instrument file's tip position is negative into "
                                 "the sample and its contact point is fitted (--contact-point free|VALUE)")
        curve = load_curve(path, args.segment or "approach", args.index)
    else:
        if args.segment not in (None, "approach") or args.index:
            raise InputError(f"{args.csv}: --segment and --index are for instrument files; a CSV holds one curve")
        z, force = read_curve(args.csv, args.columns)
        curve = curve_from_arrays(z, force, axis="depth" if args.depth_sign == 1 else "tip position",
                                  source=str(args.csv))
    with warnings.catch_warnings():  # outside its model's range: the output says NOT VALID and why
        warnings.simplefilter("ignore", ValidityWarning)
        res = fit_curve(curve, punch=punch, H=args.H, nu=args.nu, base=args.base, model=args.model,
                        fit_H=args.fit_H, baseline=args.baseline or "offset", contact_point=args.contact_point,
                        weighting=None if args.weighting in (None, "none") else args.weighting,
                        weight_cp=1e-6 if args.weight_cp is None else args.weight_cp,
                        fit_range=None if args.fit_range is None else tuple(args.fit_range),
                        range_kind=args.range_kind or "position", bootstrap=args.bootstrap or 0, seed=args.seed or 0,
                        substrate_E=args.substrate_E, substrate_nu=args.substrate_nu)
    out = {"file": str(args.csv), **res.as_dict()}
    if args.json:
        text = json.dumps(out, indent=2, allow_nan=False)
    else:
        from .solve_cli import cli_words, pretty

        text = "\n".join(pretty(cli_words(ln)) for ln in res.text_lines())
    from .cli_args import print_text

    print_text(text)
    if args.out is not None:
        atomic_write(args.out, text + "\n")
        if not args.quiet:
            print(f"wrote {args.out}", file=sys.stderr)
    return 0
