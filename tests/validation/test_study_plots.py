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


# ---------------------------------------------------------------------------------------------
# readable in print (issue 17, item 6)
# ---------------------------------------------------------------------------------------------
def _figures(study):
    from thinlayer.validation import plots

    colour = {nu: f"C{k}" for k, nu in enumerate(sorted({r.nu for r in study.rows}))}
    import matplotlib

    cmap = matplotlib.colormaps["viridis"]
    return {"errors": plots._errors_figure(study, colour),
            "pressure": plots._pressure_figure(study, ["sphere"], cmap),
            "contours": plots._contours_figure(study, ["sphere"]),
            "edge_shift": plots._edge_shift_figure(study, colour)}


def test_slope_lines_are_labelled_with_the_slope_drawn(small_study):
    pytest.importorskip("matplotlib", reason="matplotlib (the optional 'plot' extra) is not installed")
    import numpy as np

    fig = _figures(small_study)["errors"]
    seen = []
    for ax in fig.axes:
        lines = [ln for ln in ax.get_lines() if str(ln.get_gid()).startswith("slope")]
        labels = [t.get_text() for t in ax.texts if t.get_gid() == "slope label"]
        assert len(lines) == 1 and len(labels) == 1, (ax.get_title(), labels)
        x, y = (np.asarray(v, float) for v in lines[0].get_data())
        drawn = np.diff(np.log(y)) / np.diff(np.log(x))  # measured from the line itself
        assert np.allclose(drawn, drawn[0])
        assert labels[0].split()[:2] == ["slope", f"{round(drawn[0]):d}"], (labels[0], drawn[0])
        assert abs(drawn[0] - round(drawn[0])) < 1e-9
        seen.append(round(drawn[0]))
    assert len(set(seen)) > 1  # the panels really differ (3, 2, 1): one legend for all would mislead


def test_figures_are_readable_in_print_and_say_what_they_show(small_study):
    pytest.importorskip("matplotlib", reason="matplotlib (the optional 'plot' extra) is not installed")
    from matplotlib.text import Text

    for name, fig in _figures(small_study).items():
        w, _ = fig.get_size_inches()
        assert w <= 7.0, f"{name}: {w} in wide; scaled to a 6.7 in text width its fonts shrink"
        sizes = [t.get_fontsize() for t in fig.findobj(Text) if t.get_text().strip()]
        assert sizes and min(sizes) >= 7.5, f"{name}: text of {min(sizes)} pt"
        title = fig._suptitle.get_text() if fig._suptitle is not None else ""
        assert title or all(ax.get_title() for ax in fig.axes), f"{name}: no title says what it shows"
        legends = fig.legends + [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
        assert legends, f"{name}: no legend"
        for leg in legends:
            for h, t in zip(leg.legend_handles, leg.get_texts()):
                visible_line = h.get_linestyle() not in ("None", "none", "", " ") and h.get_linewidth() > 0
                visible_marker = getattr(h, "get_marker", lambda: "None")() not in ("None", "none", "", " ", None)
                assert visible_line or visible_marker, f"{name}: legend entry {t.get_text()!r} shows nothing"
        fig.canvas.draw()  # overlapping texts: titles of neighbouring panels must not collide
        boxes = [ax.title.get_window_extent() for ax in fig.axes if ax.get_title()]
        for i, a in enumerate(boxes):
            for b in boxes[i + 1:]:
                assert not a.overlaps(b), f"{name}: panel titles overlap"
