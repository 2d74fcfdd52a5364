"""Run every benchmark module (benchmarks/bench_*.py) and print one table: ``python benchmarks/run.py``."""
from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

from _timing import print_header, print_rows


def main(names: list[str]) -> int:
    here = Path(__file__).parent
    mods = sorted(here.glob("bench_*.py"))
    if names:
        mods = [m for m in mods if any(n in m.stem for n in names)]
    print_header()
    for path in mods:
        spec = importlib.util.spec_from_file_location(path.stem, path)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        print_rows(mod.run())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
