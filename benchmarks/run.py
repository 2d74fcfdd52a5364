"""Run the benchmark modules (benchmarks/bench_*.py) and print one table.

``python benchmarks/run.py`` runs every module; ``python benchmarks/run.py core numerics`` the modules whose name
contains one of the words; ``python benchmarks/run.py --group core`` exactly ``bench_core.py``; ``--list`` names
the groups; ``--strict`` exits with status 1 when a row fails its target.  Each row prints the measured value, the
target, the ratio to a peer measured side by side where one exists, and pass/FAIL.
"""
from __future__ import annotations

import argparse
import importlib.util
import sys
from pathlib import Path

from _timing import print_header, print_rows, print_summary


def _modules(names: list[str], groups: list[str]) -> list[Path]:
    here = Path(__file__).parent
    mods = sorted(here.glob("bench_*.py"))
    if groups:
        wanted = {g.removeprefix("bench_").removesuffix(".py") for g in groups}
        unknown = wanted - {m.stem.removeprefix("bench_") for m in mods}
        if unknown:
            raise SystemExit(f"unknown group(s) {sorted(unknown)}; --list names them")
        mods = [m for m in mods if m.stem.removeprefix("bench_") in wanted]
    if names:
        mods = [m for m in mods if any(n in m.stem for n in names)]
    return mods


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("names", nargs="*", help="run the modules whose name contains one of these words")
    ap.add_argument("-g", "--group", action="append", default=[],
                    help="run exactly this group (bench_<group>.py); may be repeated")
    ap.add_argument("--list", action="store_true", help="list the groups and exit")
    ap.add_argument("--strict", action="store_true", help="exit with status 1 when a row fails its target")
    args = ap.parse_args(argv)
    mods = _modules(args.names, args.group)
    if args.list:
        for m in mods:
            print(m.stem.removeprefix("bench_"))
        return 0
    print_header()
    rows = []
    for path in mods:
        spec = importlib.util.spec_from_file_location(path.stem, path)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        rows += print_rows(mod.run())
    print_summary(rows)
    return 1 if args.strict and any(r.verdict() == "FAIL" for r in rows) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
