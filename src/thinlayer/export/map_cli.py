"""``thinlayer fit-map MAP --R ... --nu ... --out DIR``: every curve of a force map fitted (issue 25 item 5).

:func:`add_map_parser` adds the subcommand to the ``thinlayer`` parser, :func:`cmd_fit_map` runs it through
:func:`thinlayer.afm.maps.fit_map` (imported on first use: the parser imports neither afmformats nor dask).  The
output folder receives ``map.csv`` (one row per pixel: E, its standard error, H, contact point, residual, status and
reason), ``E.png`` (the E map with its colour bar and µm axes), ``failures.txt`` (the failed and flagged pixels with
their reasons) and ``summary.json``; existing files are never replaced unless ``--overwrite`` is given (checked
before any curve is fitted).  Lengths in metres, forces in newtons, E in pascals (the instrument files' SI units).
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path
from typing import Any

from .cli_args import BadInput, finite

__all__ = ["OUTPUT_FILES", "add_map_parser", "cmd_fit_map"]

#: the files ``fit-map`` writes in ``--out``
OUTPUT_FILES = ("map.csv", "E.png", "failures.txt", "summary.json")


def _thickness(text: str) -> Any:
    """``--H``: a thickness (m), ``inf`` (the half-space) or ``height`` (topography minus the substrate)."""
    t = text.strip().lower()
    if t in ("inf", "+inf", "infinity"):
        return math.inf
    if t == "height":
        return "height"
    val = finite(text)
    if not val > 0:
        raise argparse.ArgumentTypeError(f"{text!r}: a thickness must be > 0 (or inf, or height)")
    return val


def add_map_parser(subparsers: Any, formatter_class: type) -> argparse.ArgumentParser:
    """Add ``fit-map`` to the ``thinlayer`` subcommands; the handler is :func:`cmd_fit_map`."""
    s = subparsers.add_parser(
        "fit-map", formatter_class=formatter_class, help="fit every curve of a force map (E, H, contact point maps)",
        description="Fit each approach curve of a force map (a .jpk-force-map, an afmformats HDF5 map, or a folder\n"
                    "of curves afmformats reads) for Young's modulus, the contact point free (thinlayer.fit_map).\n"
                    "Writes map.csv, E.png, failures.txt and summary.json into --out.  SI units: --R, --H in m.",
        epilog="examples:\n  thinlayer fit-map cells.jpk-force-map --R 5e-6 --nu 0.5 --out E-map\n"
               "  thinlayer fit-map film.h5 --R 5e-6 --H height --height-image topo.npy --nu 0.45 --out film\n"
               "  thinlayer fit-map curves/ --R 5e-6 --H 2e-6 --nu 0.5 --scheduler threads --out run1 --overwrite")
    s.add_argument("source", help="a map file (.jpk-force-map, afmformats .h5, ...) or a folder of curve files")
    s.add_argument("--R", type=finite, help="sphere radius (m), the paraboloid r^2/(2R); or --tip / a tip option")
    s.add_argument("--tip", metavar="KIND:key=value,...", help="a tip of thinlayer.punch.TIPS, e.g. cone:half_angle=70")
    s.add_argument("--H", type=_thickness, default=None,
                   help="layer thickness (m); omitted or inf: the half-space (Hertz); 'height': the topography "
                        "(--height-image, else each curve's contact height) minus the substrate level")
    s.add_argument("--height-image", type=Path, help="topography (m) as .npy or CSV, rows = y, columns = x "
                   "(with --H height)")
    s.add_argument("--substrate", type=finite, help="substrate height (m) for --H height (default: the median of "
                   "the lowest 5 %% of the topography)")
    s.add_argument("--nu", type=finite, required=True, help="Poisson ratio in (-1, 1/2]")
    s.add_argument("--base", choices=("bonded", "frictionless"), default="bonded",
                   help="the base under the layer (default bonded)")
    s.add_argument("--scheduler", default="auto", metavar="ADDR|auto|local|threads|serial",
                   help="run on dask.distributed: 'local' (a local cluster, one process per core), 'threads', or a "
                        "scheduler address tcp://host:8786; 'serial': in this process (default auto: local for 256 "
                        "curves or more when dask is installed, else serial)")
    s.add_argument("--workers", type=int, help="workers of a local cluster (default: one per core)")
    s.add_argument("--out", type=Path, required=True, help="output folder (created if missing)")
    s.add_argument("--overwrite", action="store_true", help="replace the output files if they exist")
    s.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")
    s.add_argument("--quiet", action="store_true", help="no summary on stdout")
    from .cli_args import add_tip_shortcuts

    add_tip_shortcuts(s)
    s.set_defaults(func=cmd_fit_map)
    return s


def _tip(args: argparse.Namespace) -> Any:
    from .cli_args import shortcuts_given, tip_from_shortcut

    given = [o for o, v in (("--R", args.R), ("--tip", args.tip)) if v is not None] + shortcuts_given(args)
    if len(given) != 1:
        raise BadInput("give exactly one of --R (a sphere's radius in m), --tip KIND:key=value,..., --cone ANGLE, "
                       "--pyramid ANGLE, --sphere R, --blunted-cone R ANGLE, --power-law C N"
                       + (f"; got {' and '.join(given)}" if given else ""))
    if args.R is not None:
        if not args.R > 0:
            raise BadInput(f"--R {args.R:g}: the sphere radius must be > 0 (m)")
        return args.R
    if args.tip is not None:
        from ..punch import tip_from_spec
        from .cli_args import tip_needs_values

        tip = tip_from_spec(args.tip)
        tip_needs_values(tip, args.tip)
        return tip
    return tip_from_shortcut(args)


def cmd_fit_map(args: argparse.Namespace) -> int:
    """Run ``thinlayer fit-map``; returns the exit code (0).  Bad input raises ValueError/TypeError (one line)."""
    from ..validation.output import atomic_write, refuse_existing

    punch = _tip(args)
    if not -1 < args.nu <= 0.5:
        raise BadInput(f"--nu {args.nu:g}: the Poisson ratio must be in (-1, 1/2]")
    if args.height_image is not None and args.H != "height":
        raise BadInput("--height-image is read with --H height (the topography minus the substrate level)")
    if args.substrate is not None and args.H != "height":
        raise BadInput("--substrate is used with --H height")
    if args.workers is not None and not 1 <= args.workers <= 256:
        raise BadInput(f"--workers {args.workers}: from 1 to 256")
    src = Path(args.source)
    if not src.exists():
        raise BadInput(f"{args.source}: no such file or folder")
    out = args.out
    if out.exists() and not out.is_dir():
        raise BadInput(f"--out {out}: exists and is not a folder")
    if not out.parent.is_dir():
        raise BadInput(f"--out {out}: its parent folder {out.parent} does not exist")
    paths = [out / name for name in OUTPUT_FILES]
    refuse_existing(paths, args.overwrite)
    from ..afm.distributed import check_scheduler
    from ..afm.maps import fit_map

    scheduler = check_scheduler(args.scheduler)
    H = None if args.H is not None and args.H == math.inf else args.H
    res = fit_map(src, punch=punch, H=H, nu=args.nu, base=args.base, progress=not args.no_progress,
                  scheduler=scheduler, height_image=args.height_image, substrate=args.substrate,
                  workers=args.workers)
    out.mkdir(exist_ok=True)
    atomic_write(paths[0], res.csv_text())
    res.to_png(paths[1], overwrite=True)  # refused above unless --overwrite
    atomic_write(paths[2], res.failures_text())
    summary = {"source": str(src), "shape": list(res.shape), "punch": res.punch, "nu": res.nu, "base": res.base,
               "fitter": res.fitter, "counts": res.counts(),
               "substrate_m": res.substrate if math.isfinite(res.substrate) else None,
               "E_median_Pa": _median(res), "files": list(OUTPUT_FILES)}
    atomic_write(paths[3], json.dumps(summary, indent=2, allow_nan=False) + "\n")
    if not args.quiet:
        print("\n".join(res.text_lines()))
        print(f"wrote {', '.join(str(p) for p in paths)}", file=sys.stderr)
    return 0


def _median(res: Any) -> float | None:
    import numpy as np

    E = res.E[np.isfinite(res.E)]
    return float(np.median(E)) if E.size else None
