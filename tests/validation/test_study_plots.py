"""Figures of a validation study (thinlayer.validation.plots): files written, or the extra named."""
from __future__ import annotations

import json
import sys

import pytest


def test_plots_written(small_study, tmp_path):
    pytest.importorskip("matplotlib", reason="matplotlib (the optional 'plot' extra) is not installed")
    files = small_study.write(tmp_path / "out", plots=True)
    names = {f.name for f in files}
    for stem in ("validation_errors", "validation_pressure", "validation_contours", "validation_edge_shift"):
        assert {f"{stem}.png", f"{stem}.pdf"} <= names
    for f in files:
        assert f.stat().st_size > 0
        head = f.read_bytes()[:8]
        if f.suffix == ".png":
            assert head == b"\x89PNG\r\n\x1a\n"
        elif f.suffix == ".pdf":
            assert head.startswith(b"%PDF")
    assert json.loads((tmp_path / "out" / "validation.json").read_text())["rows"]


def test_plots_without_matplotlib_name_the_extra(small_study, tmp_path, monkeypatch):
    for mod in ("matplotlib", "matplotlib.figure", "matplotlib.backends.backend_agg"):
        monkeypatch.setitem(sys.modules, mod, None)  # import raises ImportError
    with pytest.raises(ImportError, match=r"thinlayer\[plot\]"):
        small_study.plots(tmp_path)
    assert not any(tmp_path.iterdir())
