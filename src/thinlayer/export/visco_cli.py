"""``thinlayer visco``: viscoelastic layers from the command line (issue 27 item 4).

Three subcommands, each a door of :mod:`thinlayer.contact`:

* ``thinlayer visco solve --material SPEC --history FILE.csv [--control force]``: force (or depth) and contact radius
  against time (``solve(material=..., history=...)``); the CSV holds ``time,depth`` (or ``time,force``);
* ``thinlayer visco fit --material sls|power-law --curves A.csv [B.csv ...]`` (``time,depth,force`` each) or
  ``--oscillation FILE.csv --delta0 D`` (``omega,K_real,K_imag``): the material's parameters with errors;
  ``--fit-H`` fits the thickness too (``--H`` is its start), ``--contact-point`` reads ``time,position,force`` (the
  tip position, negative into the sample) and fits each curve's contact point and baseline;
* ``thinlayer visco oscillation --material SPEC --delta0 D --amplitude EPS --omega W ...``: amplitude and phase of
  the force, and the layer's stiffness ``S(delta0)`` (the bottom-effect correction).

``SPEC`` is ``KIND:key=value,...`` read by a small key=value parser (numbers through ``float``; nothing is
evaluated): ``sls:E0=3,Einf=1,tau=0.2``, ``prony:Einf=1,E1=2,tau1=0.5,E2=1,tau2=5``, ``power-law:E0=1,alpha=0.2,t0=1``,
``kv:E=1,eta=0.5``.  A CSV may start with one header row; ``#`` starts a comment.  Bad values exit 2 with one line.
"""
from __future__ import annotations

import argparse
import csv
import json
import math
import sys
from typing import Any

import numpy as np

from .cli_args import BadInput, finite

__all__ = ["MATERIAL_KINDS", "add_visco_parser", "cmd_visco", "parse_material", "read_columns"]

#: the material kinds of ``--material KIND:key=value,...`` and their keys
MATERIAL_KINDS = {"sls": ("E0", "Einf", "tau"), "prony": ("Einf", "E<i>", "tau<i>"),
                  "power-law": ("E0", "alpha", "t0"), "kv": ("E", "eta")}
#: the most rows of a CSV file
MAX_ROWS = 2_000_000


def parse_material(spec: str) -> Any:
    """The material of ``KIND:key=value,...`` (one-line :class:`BadInput` naming what would be valid)."""
    from ..contact.materials import KelvinVoigt, PowerLaw, Prony, StandardLinearSolid

    hint = "; e.g. sls:E0=3,Einf=1,tau=0.2, prony:Einf=1,E1=2,tau1=0.5, power-law:E0=1,alpha=0.2,t0=1, kv:E=1,eta=0.5"
    kind, sep, rest = spec.strip().partition(":")
    kind = kind.strip().lower()
    if kind not in MATERIAL_KINDS or not sep:
        raise BadInput(f"--material {spec!r}: KIND:key=value,... with KIND one of {', '.join(MATERIAL_KINDS)}{hint}")
    vals: dict[str, float] = {}
    for item in (i for i in rest.split(",") if i.strip()):
        key, eq, text = item.partition("=")
        key = key.strip()
        if not eq or not key:
            raise BadInput(f"--material {spec!r}: {item.strip()!r} is not key=value{hint}")
        try:
            v = float(text)
        except ValueError:
            raise BadInput(f"--material {spec!r}: {key} = {text.strip()!r} is not a number") from None
        if not math.isfinite(v):
            raise BadInput(f"--material {spec!r}: {key} must be finite")
        if key in vals:
            raise BadInput(f"--material {spec!r}: {key} given twice")
        vals[key] = v
    try:
        if kind == "prony":
            einf = vals.pop("Einf", 0.0)
            idx = sorted({k[1:] for k in vals if k.startswith("E")} | {k[3:] for k in vals if k.startswith("tau")})
            terms = []
            for i in idx:
                if f"E{i}" not in vals or f"tau{i}" not in vals:
                    raise BadInput(f"--material {spec!r}: term {i} needs both E{i} and tau{i}")
                terms.append((vals.pop(f"E{i}"), vals.pop(f"tau{i}")))
            _no_extra(spec, vals)
            return Prony(einf, terms)
        need = [k for k in MATERIAL_KINDS[kind] if k not in vals and not (kind == "power-law" and k == "t0")]
        if need:
            raise BadInput(f"--material {spec!r}: {', '.join(need)} missing (keys: {', '.join(MATERIAL_KINDS[kind])})")
        if kind == "sls":
            m = StandardLinearSolid(vals.pop("E0"), vals.pop("Einf"), vals.pop("tau"))
        elif kind == "power-law":
            m = PowerLaw(vals.pop("E0"), vals.pop("t0", 1.0), vals.pop("alpha"))
        else:
            m = KelvinVoigt(vals.pop("E"), vals.pop("eta"))
        _no_extra(spec, vals)
        return m
    except BadInput:
        raise
    except (ValueError, TypeError) as exc:
        raise BadInput(f"--material {spec!r}: {exc}") from None


def _no_extra(spec: str, vals: dict) -> None:
    if vals:
        raise BadInput(f"--material {spec!r}: unknown key(s) {', '.join(sorted(vals))}")


def read_columns(path: str, names: tuple[str, ...]) -> list[np.ndarray]:
    """The numeric columns of a CSV file (one optional header row, ``#`` comments), one line on a bad file."""
    rows: list[list[float]] = []
    with open(path, newline="", encoding="utf-8") as fh:
        for k, row in enumerate(csv.reader(line for line in fh if line.strip() and not line.lstrip().startswith("#"))):
            try:
                vals = [float(x) for x in row]
            except ValueError:
                if k == 0 and not rows:
                    continue  # the header
                raise BadInput(f"{path}: data row {k + 1} holds a value that is not a number: {','.join(row)[:80]!r}")\
                    from None
            if len(vals) != len(names):
                raise BadInput(f"{path}: data row {k + 1} has {len(vals)} columns; expected {len(names)} "
                               f"({', '.join(names)})")
            rows.append(vals)
            if len(rows) > MAX_ROWS:
                raise BadInput(f"{path}: more than {MAX_ROWS} rows; subsample the file")
    if len(rows) < 2:
        raise BadInput(f"{path}: at least 2 rows of {', '.join(names)} are needed")
    a = np.array(rows)
    if not np.all(np.isfinite(a)):
        raise BadInput(f"{path}: every value must be finite (no nan or inf)")
    return [a[:, j] for j in range(len(names))]


def _common(p: argparse.ArgumentParser) -> None:
    from .cli_args import add_punch_args, add_tip_shortcuts, base_arg

    add_punch_args(p, flat=True)
    add_tip_shortcuts(p)
    p.add_argument("--nu", required=True, help="Poisson ratio in (-1, 1/2], constant in time")
    p.add_argument("--H", type=finite, required=True, help="layer thickness (> 0)")
    base_arg(p, "the base under the layer: bonded (default) or frictionless")
    p.add_argument("--model", default="auto", help="the elastic law at unit modulus (default auto)")
    p.add_argument("--tol", type=finite, default=0.05, help="the elastic law's largest relative error (0.05)")
    p.add_argument("--json", action="store_true", help="JSON output")


def add_visco_parser(subparsers: Any, formatter_class: type) -> argparse.ArgumentParser:
    """Add ``visco`` (with ``solve``, ``fit``, ``oscillation``) to the ``thinlayer`` subcommands."""
    v = subparsers.add_parser("visco", formatter_class=formatter_class,
                              help="viscoelastic layers: force histories, fits, oscillations (Lee-Radok)",
                              description=__doc__.split("\n\n", 1)[1],
                              epilog="examples:\n  thinlayer visco oscillation --tip paraboloid:R=10 --nu 0.5 --H 1 "
                                     "--material sls:E0=3,Einf=1,tau=0.1 --delta0 0.13 --amplitude 1e-3 --omega 1 10"
                                     "\n  thinlayer visco oscillation --tip paraboloid:R=10 --nu 0.5 --H 1 "
                                     "--material power-law:E0=2,alpha=0.2 --delta0 0.13 --amplitude 1e-3 --omega 1 "
                                     "--json\n(thinlayer visco solve --help and thinlayer visco fit --help: the CSV "
                                     "files they read)")
    sub = v.add_subparsers(dest="visco_cmd", required=True, metavar="SUBCOMMAND")
    s = sub.add_parser("solve", formatter_class=formatter_class, help="force (or depth) against time",
                       epilog="example:\n  thinlayer visco solve --tip paraboloid:R=10 --nu 0.5 --H 1 "
                              "--material sls:E0=3,Einf=1,tau=0.2 --history ramp.csv")
    _common(s)
    s.add_argument("--material", required=True, metavar="KIND:key=value,...", help="the material (module doc)")
    s.add_argument("--history", required=True, metavar="FILE.csv", help="time,depth (or time,force) rows")
    s.add_argument("--control", choices=("depth", "force"), default="depth",
                   help="the history's second column: depth (default) or force")
    s.add_argument("--format", choices=("text", "csv"), default="text", help="text table (default) or CSV")
    s.set_defaults(func=cmd_visco)
    f = sub.add_parser("fit", formatter_class=formatter_class, help="material parameters from curves or oscillation",
                       epilog="examples:\n  thinlayer visco fit --tip paraboloid:R=10 --nu 0.5 --H 1 --material sls "
                              "--curves slow.csv fast.csv\n  thinlayer visco fit --tip paraboloid:R=10 --nu 0.5 --H 1 "
                              "--material sls --curves slow.csv fast.csv --fit-H --contact-point"
                              "\n  thinlayer visco fit --tip paraboloid:R=10 --nu 0.5 --H 1 "
                              "--material sls --oscillation kstar.csv --delta0 0.13")
    _common(f)
    f.add_argument("--material", choices=("sls", "power-law"), default="sls", help="the material to fit")
    f.add_argument("--t0", type=finite, default=1.0, help="the power law's reference time (default 1)")
    f.add_argument("--curves", nargs="+", metavar="FILE.csv", help="time,depth,force rows, one file per curve")
    f.add_argument("--oscillation", metavar="FILE.csv", help="omega,K_real,K_imag rows (the dynamic stiffness)")
    f.add_argument("--delta0", type=finite, help="with --oscillation: the depth it oscillates around")
    f.add_argument("--fit-H", action="store_true", help="with --curves: fit the thickness too (--H is the start)")
    f.add_argument("--contact-point", action="store_true",
                   help="with --curves: the CSVs hold time,position,force (tip position, negative into the sample); "
                        "fit each curve's contact point and baseline")
    f.set_defaults(func=cmd_visco)
    o = sub.add_parser("oscillation", formatter_class=formatter_class, help="small oscillation: |K*|, phase, S",
                       epilog="example:\n  thinlayer visco oscillation --tip paraboloid:R=10 --nu 0.5 --H 1 "
                              "--material sls:E0=3,Einf=1,tau=0.1 --delta0 0.1 --amplitude 1e-3 --omega 1 10 100")
    _common(o)
    o.add_argument("--material", required=True, metavar="KIND:key=value,...", help="the material (module doc)")
    o.add_argument("--delta0", type=finite, required=True, help="the held depth")
    o.add_argument("--amplitude", type=finite, required=True, help="the depth amplitude eps (<< delta0)")
    o.add_argument("--omega", type=finite, nargs="+", required=True, help="angular frequencies (>= 0)")
    o.set_defaults(func=cmd_visco)
    return v


def _setting(args: argparse.Namespace) -> tuple[Any, Any]:
    from .cli_args import punch_from_args, solve_layer

    layer = solve_layer(args.base, args.nu)
    punch, _ = punch_from_args(args, allow_flat=True)
    if args.param:
        raise BadInput("--param goes with --punch EXPR; give the tip's values in --tip KIND:key=value")
    return layer, punch


def _fmt(x: float) -> str:
    return "NOT VALID" if not math.isfinite(x) else f"{x:.8g}"


def cmd_visco(args: argparse.Namespace) -> int:
    """Run ``thinlayer visco solve|fit|oscillation``."""
    layer, punch = _setting(args)
    if args.visco_cmd == "solve":
        from ..contact.solve import solve

        material = parse_material(args.material)
        t, v = read_columns(args.history, ("time", args.control))
        ans = solve(layer, punch, H=args.H, material=material, history=(t, v), control=args.control,
                    model=args.model, tol=args.tol)
        if args.json:
            sys.stdout.write(json.dumps(ans.as_dict(), allow_nan=False) + "\n")
        elif args.format == "csv":
            w = csv.writer(sys.stdout, lineterminator="\n")
            w.writerow(["time", "depth", "force", "contact_radius", "valid"])
            for row in zip(ans.times, ans.depths, ans.force, ans.contact_radius, ans.valid):
                w.writerow([f"{x:.10g}" for x in row[:4]] + [int(row[4])])
        else:
            print(str(ans))
            print(f"{'time':>14} {'depth':>14} {'force':>14} {'contact radius':>14}")
            for tt, d, p, c in zip(ans.times, ans.depths, ans.force, ans.contact_radius):
                print(f"{tt:>14.8g} {_fmt(d):>14} {_fmt(p):>14} {_fmt(c):>14}")
            print(f"model: {ans.reason}")
        return 0
    if args.visco_cmd == "oscillation":
        from ..contact.oscillation import oscillation

        osc = oscillation(layer, punch, args.H, parse_material(args.material), args.delta0, args.omega,
                          args.amplitude, tol=args.tol, model=args.model)
        if args.json:
            sys.stdout.write(json.dumps(osc.as_dict(), allow_nan=False) + "\n")
        else:
            print(str(osc))
            print(str(osc.stiffness))
        return 0
    from ..contact.visco_fit import fit_viscoelastic

    if (args.curves is None) == (args.oscillation is None):
        raise BadInput("give exactly one of --curves FILE.csv ... and --oscillation FILE.csv (with --delta0)")
    if args.curves is not None:
        if args.delta0 is not None:
            raise BadInput("--delta0 goes with --oscillation")
        axis = "position" if args.contact_point else "depth"
        data = [tuple(read_columns(p, ("time", axis, "force"))) for p in args.curves]
        res = fit_viscoelastic(layer, punch, args.H, material=args.material, curves=data, t0=args.t0,
                               tol=args.tol, model=args.model, fit_H=args.fit_H, contact_point=args.contact_point)
    else:
        if args.fit_H or args.contact_point:
            raise BadInput("--fit-H and --contact-point go with --curves: an oscillation around one depth cannot "
                           "separate H from the modulus")
        if args.delta0 is None:
            raise BadInput("--oscillation needs --delta0, the depth it oscillates around")
        w, kr, ki = read_columns(args.oscillation, ("omega", "K_real", "K_imag"))
        res = fit_viscoelastic(layer, punch, args.H, material=args.material, oscillation=(w, kr + 1j * ki),
                               delta0=args.delta0, t0=args.t0, tol=args.tol, model=args.model)
    if args.json:
        sys.stdout.write(json.dumps(res.as_dict(), allow_nan=False) + "\n")
    else:
        print(str(res))
    return 0
