"""Timing of the main job: the LaTeX report of the paper's derivation (issue 5: under 10 s without PDF).

``run()`` returns ``(name, seconds, target)`` rows; nothing runs at import.
"""
from __future__ import annotations

from pathlib import Path

from _timing import main, once


def run() -> list[tuple[str, float, str]]:
    from thinlayer.export.derivation import load_derivation, report_latex

    root = Path(__file__).resolve().parents[1] / "derivations"
    rows = []
    for name in ("elliptic_paraboloid", "quartic_punch"):
        der = load_derivation(root / f"{name}.toml")
        rows.append((f"report {name}.toml (LaTeX, no PDF), first run", once(report_latex, der), "< 10 s"))
    errata = load_derivation("errata")  # the whole errata registry (issue 28)
    rows.append(("report errata (LaTeX, no PDF)", once(report_latex, errata), "< 10 s"))
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
