"""``thinlayer flat-punch``: the stiffness kappa(a/H) of a flat-ended cylinder, P = 4 mu a w0 kappa/(1 - nu) (F.1).

:func:`add_flat_parser` adds the subcommand to the ``thinlayer`` parser, :func:`cmd_flat` runs it.  One row per
value of ``--a-over-H``: kappa, the model that gave it (exact Fredholm solution (F.6)-(F.7), thin-layer law
(F.10)-(F.16) or thick series (F.18)) and its estimated relative error.  The force of one punch on one layer is
``thinlayer solve --tip flat:a=A ...``.
"""
from __future__ import annotations

import argparse
import json
import math
from typing import Any

from ..errors import InputError

__all__ = ["add_flat_parser", "cmd_flat"]

#: most values of a/H on one command line
MAX_VALUES = 200


def _ratio(text: str) -> float:
    try:
        val = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not (math.isfinite(val) and val > 0):
        raise argparse.ArgumentTypeError(f"{text!r} is not a positive finite number")
    return val


def add_flat_parser(subparsers: Any, formatter_class: type) -> argparse.ArgumentParser:
    """Add ``flat-punch`` to the ``thinlayer`` subcommands; the handler is :func:`cmd_flat`."""
    s = subparsers.add_parser(
        "flat-punch", formatter_class=formatter_class,
        help="stiffness kappa(a/H) of a flat-ended cylinder, P = 4 mu a w0 kappa/(1 - nu) (F.1)",
        description="The stiffness factor kappa(a/H) of a flat-ended cylinder of radius a on a layer of thickness H\n"
                    "(thinlayer.flat_punch_stiffness): exact (Fredholm equation (F.6)-(F.7)), thin-layer law\n"
                    "(F.10)-(F.16), thick series (F.18), or auto (the cheapest within --max-error).\n"
                    "JSON: {layer (the base), nu, model, rows: [{a_over_H, kappa, model, error_estimate}]}.",
        epilog="examples:\n  thinlayer flat-punch --a-over-H 0.5 2 10 --nu 0.3\n"
               "  thinlayer flat-punch --a-over-H 50 --nu 0.5 --model thin --json\n"
               "  thinlayer solve --tip flat:a=1 --nu 0.3 --H 0.5 --delta0 0.01 --E 2.6   # force of one punch")
    s.add_argument("--a-over-H", dest="a_over_H", type=_ratio, nargs="+", required=True,
                   help=f"punch radius over layer thickness (> 0; at most {MAX_VALUES} values)")
    s.add_argument("--nu", required=True, help="Poisson ratio in (-1, 1/2]: a number or an exact fraction")
    from .cli_args import base_arg

    base_arg(s, "the base under the layer: bonded (default) or frictionless", old="--layer")
    s.add_argument("--model", choices=("auto", "exact", "thin", "thick"), default="auto",
                   help="auto (default): thick series, then thin-layer law within --max-error, else exact")
    s.add_argument("--max-error", type=_ratio, default=1e-2,
                   help="largest estimated relative error of an asymptotic model (default 0.01)")
    s.add_argument("--json", action="store_true", help="machine-readable JSON output (keys above)")
    s.add_argument("--quiet", action="store_true", help="accepted for symmetry; the table is the output")
    s.set_defaults(func=cmd_flat)
    return s


def cmd_flat(args: argparse.Namespace) -> int:
    """Run ``thinlayer flat-punch``; returns 0.  Bad input raises ValueError/TypeError (one line, exit 2)."""
    from .._checks import parse_nu
    from ..contact.flat_punch import stiffness_table
    from ..layers.kernels import BondedLayer, FrictionlessLayer, IncompressibleLayer

    if len(args.a_over_H) > MAX_VALUES:
        raise InputError(f"--a-over-H: {len(args.a_over_H)} values, at most {MAX_VALUES} on one command line")
    nu = float(parse_nu(args.nu, floats="float", upper_closed=True, symbols=False, example="0.3, '3/10' or 0.5"))
    layer = FrictionlessLayer(nu) if args.base == "frictionless" else (
        IncompressibleLayer() if nu == 0.5 else BondedLayer(nu))
    if args.max_error > 1:
        raise InputError(f"--max-error {args.max_error:g}: a relative error in (0, 1]")
    kappa, est, used = stiffness_table(layer, args.a_over_H, args.model, max_error=args.max_error)
    rows = [{"a_over_H": float(a), "kappa": float(k), "model": m, "error_estimate": float(e)}
            for a, k, e, m in zip(args.a_over_H, kappa, est, used)]
    if args.json:
        print(json.dumps({"layer": args.base, "nu": nu, "model": args.model, "rows": rows}, indent=2,
                         allow_nan=False))
        return 0
    from .cli_args import print_text

    lines = [f"flat-ended cylinder on a {args.base} layer, ν = {nu:g}: P = 4μ a w₀ κ/(1 - ν)   (F.1)",
             f"  {'a/H':>10}  {'κ':>16}  {'model':<6}  estimate"]
    lines += [f"  {r['a_over_H']:>10.6g}  {r['kappa']:>16.10g}  {r['model']:<6}  {r['error_estimate']:.1e}"
              for r in rows]
    print_text("\n".join(lines))
    return 0
