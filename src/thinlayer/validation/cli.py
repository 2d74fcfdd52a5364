r"""The command ``thinlayer validate``: the study's table as text, LaTeX and JSON, and its figures.

``--plots`` writes the figures (matplotlib, the ``plot`` extra) as PNG and PDF.  Ctrl-C stops the
study cleanly: the rows done are printed and written, and the exit code is 130.
"""
from __future__ import annotations

import argparse
import sys
from fractions import Fraction
from pathlib import Path
from typing import Any

from ..errors import InputError

__all__ = ["EXIT_INTERRUPTED", "add_cli", "cli"]

#: exit code after Ctrl-C (128 + SIGINT), partial results written
EXIT_INTERRUPTED = 130
#: the default of --shapes: every shape of :data:`thinlayer.validation.cases.SHAPES` (a test keeps them equal);
#: written out so that building the parser imports neither the cases nor the solvers
DEFAULT_SHAPES = "sphere,elliptic"


def add_cli(subparsers: Any, formatter_class: Any = None) -> Any:
    """Add the ``validate`` subcommand to an argparse ``subparsers``; its handler is :func:`cli`.

    Parameters
    ----------
    subparsers : argparse subparsers action
        What ``ArgumentParser.add_subparsers()`` returned.
    formatter_class : type, optional
        The help formatter of the subcommand (e.g. ``argparse.RawDescriptionHelpFormatter``).

    Returns
    -------
    argparse.ArgumentParser
        The ``validate`` parser.
    """
    kw = {} if formatter_class is None else {"formatter_class": formatter_class}
    p = subparsers.add_parser(
        "validate", help="validation study: asymptotic vs direct numerical solutions (table, plots)",
        description="Compare the asymptotic force, contact area, edge shift and composite pressure with the\n"
                    "direct numerical solvers (sphere: axisymmetric spectral; elliptic paraboloid R1/R2 = 4: 2D FFT)\n"
                    "and fit the observed order of each remainder. Prints the table (or JSON) on stdout, progress\n"
                    "on stderr. Ctrl-C stops cleanly: the rows done are printed and written (exit code 130).\n"
                    "JSON keys: rows, observed_orders, edge_shift_checks, skipped, interrupted, pending, settings,\n"
                    "seconds, passed. Exit code 1 if an observed order or the h* check does not match.",
        epilog="examples:\n  thinlayer validate\n  thinlayer validate --out build/validation --plots\n"
               "  thinlayer validate --shapes sphere --nu 0.3,0.45 --ratios 0.1,0.05,0.025 --json\n"
               "  thinlayer validate --full --out build/validation --plots     # several minutes",
        **kw)
    p.add_argument("--full", action="store_true",
                   help="the full study: nine H/a values, the elliptic case for every nu (2D grids up to 2304^2)")
    p.add_argument("--out", metavar="DIR", help="write validation.txt/.tex/.json (and plots) into DIR")
    p.add_argument("--overwrite", action="store_true",
                   help="replace existing validation.txt/.tex/.json and figures in --out (default: refuse)")
    p.add_argument("--force", dest="overwrite", action="store_true", help=argparse.SUPPRESS)  # the former name
    p.add_argument("--plots", action="store_true", help="also write PNG and PDF figures into --out (needs matplotlib)")
    p.add_argument("--json", action="store_true", help="print JSON instead of the text table")
    p.add_argument("--nu", metavar="LIST", help="comma-separated Poisson ratios (default 0,0.2,0.3,0.4,0.45)")
    p.add_argument("--ratios", metavar="LIST", help="comma-separated H/a values in [0.0125, 0.2]")
    p.add_argument("--shapes", metavar="LIST", default=DEFAULT_SHAPES, help="sphere and/or elliptic (default both)")
    p.add_argument("--max-n", type=int, default=None, help="largest 2D grid (default 1024; --full 2304)")
    p.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    p.set_defaults(func=cli)
    return p


def _floats(text: str | None, name: str) -> tuple[float, ...] | None:
    if text is None:
        return None
    out = []
    for item in text.split(","):
        item = item.strip()
        if not item:
            continue
        try:
            out.append(float(Fraction(item)) if "/" in item else float(item))
        except (ValueError, ZeroDivisionError) as exc:
            raise InputError(f"--{name} {text!r}: {item!r} is not a number") from exc
    if not out:
        raise InputError(f"--{name} {text!r}: give comma-separated numbers")
    return tuple(out)


def cli(args: Any) -> int:
    """Run ``thinlayer validate``.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed arguments of the ``validate`` parser (:func:`add_cli`).

    Returns
    -------
    int
        The exit code: 0 ok, 1 an observed order or the h^* check does not match, 130 interrupted.
    """
    if args.plots and not args.out:
        raise InputError("--plots needs --out DIR (the folder for the PNG and PDF files)")
    if args.out:  # refuse before the study runs, not after minutes of work
        from .output import refuse_existing
        from .plots import figure_files

        d = Path(args.out)
        targets = [d / f"validation{x}" for x in (".txt", ".tex", ".json")]
        refuse_existing(targets + (figure_files(d, "validation", ("png", "pdf")) if args.plots else []),
                        getattr(args, "overwrite", False))
    from .runner import validation_study

    shapes = tuple(s.strip() for s in args.shapes.split(",") if s.strip())
    study = validation_study(nus=_floats(args.nu, "nu"), ratios=_floats(args.ratios, "ratios"), shapes=shapes,
                             full=args.full, max_n=args.max_n, progress=not args.quiet)
    print(study.to_json() if args.json else study.table(), flush=True)
    if args.out:
        if not study.rows:
            print("thinlayer: no case finished: nothing written", file=sys.stderr)
        else:
            files = study.write(args.out, plots=args.plots, force=getattr(args, "overwrite", False))
            print("wrote " + ", ".join(str(f) for f in files), file=sys.stderr)
    if study.interrupted:
        return EXIT_INTERRUPTED
    return 0 if study.passed else 1
