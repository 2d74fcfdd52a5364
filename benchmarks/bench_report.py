"""Timing of the main job: the LaTeX report of the paper's derivation (issue 5: under 10 s without PDF).

``run()`` returns ``(name, seconds, target)`` rows; nothing runs at import.
"""
from __future__ import annotations

import time
from pathlib import Path


def run() -> list[tuple[str, float, str]]:
    from thinlayer.export.derivation import load_derivation, report_latex

    root = Path(__file__).resolve().parents[1] / "derivations"
    rows = []
    for name in ("elliptic_paraboloid", "quartic_punch"):
        der = load_derivation(root / f"{name}.toml")
        t0 = time.perf_counter()
        report_latex(der)
        rows.append((f"report {name}.toml (LaTeX, no PDF), first run", time.perf_counter() - t0, "< 10 s"))
    return rows


if __name__ == "__main__":  # pragma: no cover
    for name, sec, target in run():
        print(f"{name:60s} {sec:8.3f} s   (target {target})")
