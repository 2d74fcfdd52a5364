"""Figures of a validation study (thinlayer.validation.plots): files written, or the extra named."""
from __future__ import annotations

import json
import sys

import pytest


def test_plots_written(validate_cli_run):
    """``study.write(out, plots=True)``, as ``thinlayer validate --out validation --plots`` (the README's command, run
    once for the suite by conftest's ``validate_cli_run``) called it: every figure as PNG and PDF, and the JSON."""
    pytest.importorskip("matplotlib", reason="matplotlib (the optional 'plot' extra) is not installed")
    run = validate_cli_run(("validate", "--out", "validation", "--plots"))  # conftest.py's DEFAULT_VALIDATE
    assert run.code == 0, run.err[-2000:]
    out = run.folder / "validation"
    files = sorted(p for p in out.iterdir() if p.is_file())
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
    assert json.loads((out / "validation.json").read_text())["rows"]


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


# ---------------------------------------------------------------------------------------------
# what the figures say matches the data (issue 28, items 3 and 4)
# ---------------------------------------------------------------------------------------------
def test_pressure_colours_follow_h_over_a_in_every_panel(small_study):
    # issue 28: colours were given by position in a panel, so a panel with other H/a values wore the wrong ones.
    # Two shapes with different H/a: each line's H/a (its gid) must wear the legend's colour of that H/a.
    pytest.importorskip("matplotlib", reason="matplotlib (the optional 'plot' extra) is not installed")
    import dataclasses
    import re
    from types import SimpleNamespace

    import matplotlib
    from matplotlib.colors import to_hex

    from thinlayer.validation import plots

    sphere = [p for p in small_study.profiles if p.nu == 0.3 and p.axis == "r"]
    other = [dataclasses.replace(p, shape="elliptic", axis="x1") for p in sphere if p.H_over_a < 0.1]
    assert {p.H_over_a for p in sphere} != {p.H_over_a for p in other}
    fig = plots._pressure_figure(SimpleNamespace(profiles=sphere + other), ["sphere", "elliptic"],
                                 matplotlib.colormaps["viridis"])
    legend = {}
    for h, t in zip(fig.legends[0].legend_handles, fig.legends[0].get_texts()):
        m = re.fullmatch(r"\$H/a = ([\d.]+)\$", t.get_text())
        if m:
            legend[float(m.group(1))] = to_hex(h.get_color())
    assert len(set(legend.values())) == len(legend) >= 4  # one colour per H/a value, every value in the legend
    checked = 0
    for ax in fig.axes:
        for ln in ax.get_lines():
            m = re.match(r"H/a = ([\d.]+):", str(ln.get_gid()))
            assert m, f"{ax.get_title()}: a line without its H/a"
            assert to_hex(ln.get_color()) == legend[float(m.group(1))], (ax.get_title(), ln.get_gid())
            checked += 1
    assert checked == 2 * 2 * (len(sphere[:3]) + len(other[:3]))  # numeric and asymptotic, two panels per shape


def _inside(inner, outer, tol=0.5) -> bool:
    return (inner.x0 >= outer.x0 - tol and inner.x1 <= outer.x1 + tol and inner.y0 >= outer.y0 - tol
            and inner.y1 <= outer.y1 + tol)


def _labels_cross_frames(fig) -> list[str]:
    """Texts placed in a panel that reach over its frame, and tick labels of different panels that overlap."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    bad = []
    ticks = []
    for k, ax in enumerate(fig.axes):
        frame = ax.get_window_extent(renderer)
        for t in ax.texts:
            if t.get_text().strip() and not _inside(t.get_window_extent(renderer), frame):
                bad.append(f"{ax.get_title()!r}: {t.get_text()!r} crosses the frame")
        for labels, lim, i in ((ax.get_xticklabels(), ax.get_xlim(), 0), (ax.get_yticklabels(), ax.get_ylim(), 1)):
            lo, hi = sorted(lim)
            for lab in labels:  # the labels drawn: ticks inside the view
                if lab.get_visible() and lab.get_text().strip() and lo <= lab.get_position()[i] <= hi:
                    ticks.append((k, lab.get_text(), lab.get_window_extent(renderer)))
    for i, (ka, ta, a) in enumerate(ticks):
        for kb, tb, b in ticks[i + 1:]:
            if ka != kb and a.overlaps(b):
                bad.append(f"tick labels {ta!r} and {tb!r} of two panels overlap")
    return bad


def test_no_label_crosses_a_frame(small_study):
    pytest.importorskip("matplotlib", reason="matplotlib (the optional 'plot' extra) is not installed")
    for name, fig in _figures(small_study).items():
        assert _labels_cross_frames(fig) == [], name


def test_frame_check_can_fail():
    pytest.importorskip("matplotlib", reason="matplotlib (the optional 'plot' extra) is not installed")
    from thinlayer.validation.plots import _figure

    fig = _figure(figsize=(3, 2))
    ax = fig.subplots()
    ax.annotate("a long label that runs out of the panel", xy=(0.9, 0.5), xycoords="axes fraction")
    assert _labels_cross_frames(fig)


def test_figures_use_the_reports_fonts(small_study):
    # the report is set in Computer Modern: text in matplotlib's cmr10 (serif), mathematics in mathtext's "cm"
    pytest.importorskip("matplotlib", reason="matplotlib (the optional 'plot' extra) is not installed")
    from matplotlib.text import Text

    from thinlayer.validation.plots import STYLE

    assert STYLE["mathtext.fontset"] == "cm" and STYLE["font.family"] == "cmr10"
    for name, fig in _figures(small_study).items():
        texts = [t for t in fig.findobj(Text) if t.get_text().strip()]
        assert texts
        for t in texts:
            fp = t.get_fontproperties()
            assert fp.get_math_fontfamily() == "cm", (name, t.get_text())
            assert t.get_fontname() == "cmr10", (name, t.get_text(), t.get_fontname())
