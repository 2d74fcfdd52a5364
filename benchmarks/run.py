"""Run the benchmark modules (benchmarks/bench_*.py) and print one table.

``python benchmarks/run.py`` runs every module; ``python benchmarks/run.py core numerics`` the modules whose name
contains one of the words; ``python benchmarks/run.py --group core`` exactly ``bench_core.py``; ``--list`` names
the groups; ``--strict`` exits with status 1 when a row fails its target; ``--readme`` also writes the table, in
Markdown, between the ``<!-- benchmarks:begin -->`` and ``<!-- benchmarks:end -->`` lines of README.md.  Each
row prints the measured value, the target, the ratio to a peer measured side by side where one exists, and
pass/FAIL.
"""
from __future__ import annotations

import argparse
import importlib.util
import sys
from pathlib import Path

from _timing import environment, markdown_table, print_header, print_rows, print_summary

README = Path(__file__).resolve().parents[1] / "README.md"
BEGIN, END = "<!-- benchmarks:begin -->", "<!-- benchmarks:end -->"


def write_readme(rows: list, command: str) -> None:
    """Replace the README's performance table (between BEGIN and END) with these rows."""
    import datetime

    text = README.read_text()
    if BEGIN not in text or END not in text:
        raise SystemExit(f"README.md has no {BEGIN} ... {END} block")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    stamp = datetime.date.today().isoformat()
    block = (f"{BEGIN}\n_`{command}` on {stamp}; {environment()}._\n\n{markdown_table(rows)}\n{END}")
    README.write_text(head + block + tail)


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
    ap.add_argument("--readme", action="store_true", help="also write the table into README.md (its benchmarks block)")
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
    if args.readme:
        write_readme(rows, " ".join(["python3 benchmarks/run.py", *(a for a in argv if a != "--readme")]))
    return 1 if args.strict and any(r.verdict() == "FAIL" for r in rows) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
