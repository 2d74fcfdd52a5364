"""Command line: ``thinlayer derive FILE [--out DIR] [--pdf] [--force]``."""
from __future__ import annotations

import argparse
import sys

from .derivation import DerivationFileError, load_derivation, write_report


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="thinlayer", description="thin elastic layer contact asymptotics")
    sub = ap.add_subparsers(dest="cmd", required=True)
    d = sub.add_parser("derive", help="carry out a derivation file and export its LaTeX report")
    d.add_argument("file", help="a derivation file, e.g. derivations/elliptic_paraboloid.toml")
    d.add_argument("--out", default="build", help="output folder (default: build)")
    d.add_argument("--pdf", action="store_true", help="also compile the report with pdflatex")
    d.add_argument("--force", action="store_true", help="overwrite a .tex file thinlayer did not write")
    args = ap.parse_args(argv)
    try:
        der = load_derivation(args.file)
        tex = write_report(der, args.out, pdf=args.pdf, force=args.force)
    except (DerivationFileError, FileExistsError, RuntimeError) as exc:
        print(f"thinlayer: {exc}", file=sys.stderr)
        return 2
    print(f"wrote {tex}" + (f" and {tex.with_suffix('.pdf')}" if args.pdf else ""))
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
