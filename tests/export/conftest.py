"""Shared fixtures of the report tests: each catalogue report is built once per session (the sphere's takes ~15 s).

The tests that use them are put into one xdist group (tests/conftest.py): under ``-n 2 --dist loadgroup`` they run
in one worker, so each report is built once, not once per worker.  The fixtures hand out paths and
text; no test may edit what they built.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from thinlayer.export.derivation import load_derivation, report_latex, write_report
from thinlayer.export.report import latex_available

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def catalogue_report(tmp_path_factory):
    """``name -> Path`` of ``<name>.tex`` as ``write_report`` writes derivations/<name>.toml, with its validation
    figures, and with the PDF and its log when pdflatex is installed (built on first use, then shared)."""
    built: dict[str, Path] = {}

    def get(name: str) -> Path:
        if name not in built:
            out = tmp_path_factory.mktemp(f"report-{name}")
            built[name] = write_report(load_derivation(ROOT / "derivations" / f"{name}.toml"), out,
                                       pdf=latex_available())
        return built[name]

    return get


@pytest.fixture(scope="session")
def sphere_latex() -> str:
    """``report_latex`` of derivations/sphere.toml without a figure folder (validation tables, no plots)."""
    return report_latex(load_derivation(ROOT / "derivations" / "sphere.toml"))
