r"""Figures of a validation study (matplotlib, the optional ``plot`` extra; no pyplot state is touched).

Sized for print: at most :data:`WIDTH` inches wide with 8-9 pt text (:data:`STYLE`), each with a title
that says what it shows, one legend below the panels whose every entry shows its line or marker, and
reference lines labelled with the slope they are drawn with.  Four figures, one function each: the
relative errors against ``H/a`` (log-log, with the claimed
slopes), the pressure profiles (numerical against composite, with an edge zoom), the contact contours
(numerical, Gamma_0 moved in by h^* H with the exact and Alexandrov's h^* (3.25), Gamma_0), and the
sphere's edge shift ``(a_0 - c)/H`` against ``H/a`` with its extrapolation to 0.
"""
from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from .._checks import InputError
from .cases import CLAIMED_ORDERS, SHAPES

if TYPE_CHECKING:  # pragma: no cover
    from .analysis import ValidationStudy

__all__ = ["figure_files", "plot_study"]

#: the figures, by the end of their file names (the edge-shift figure only when the study has spheres)
FIGURES = ("errors", "pressure", "contours", "edge_shift")

_MARKER = {"sphere": "o", "elliptic": "s"}


#: sizes for print: a figure is at most :data:`WIDTH` inches wide (the text width of an A4 page with 2 cm
#: margins is 6.7 in), so that a report includes it at about its natural size and 8-9 pt text stays 8-9 pt
WIDTH = 6.7
#: the resolution of the PNG files (dots per inch)
DPI = 130
STYLE = {"font.size": 9, "axes.titlesize": 9, "axes.labelsize": 9, "xtick.labelsize": 8, "ytick.labelsize": 8,
         "legend.fontsize": 8, "figure.titlesize": 10, "lines.markersize": 4.5,
         # the report's fonts: Computer Modern for text (cmr10, shipped with matplotlib, named directly so that it
         # holds when the figure is drawn outside this style) and for mathtext; the linear axes' tick labels are
         # plain cmr10 text whose minus sign (cmr10 has none) falls back to DejaVu Serif's (:func:`_plain_ticks`)
         "font.family": "cmr10",
         "mathtext.fontset": "cm", "axes.formatter.use_mathtext": True, "axes.unicode_minus": False}


def _figure(*args, **kw):
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError as exc:
        raise ImportError("the validation plots need matplotlib, the optional 'plot' extra: "
                          "pip install 'thinlayer[plot]' (or pip install matplotlib)") from exc
    kw.setdefault("dpi", DPI)  # the files' resolution: text is measured for the layout at the resolution it is drawn at
    fig = Figure(*args, **kw)
    FigureCanvasAgg(fig)
    return fig


#: the tick labels' fonts: cmr10, and for the minus sign (U+2212, not in cmr10) DejaVu Serif (shipped with matplotlib)
TICK_FONTS = ["cmr10", "DejaVu Serif"]


def _plain_ticks(fig) -> None:
    """The linear axes' tick labels as plain text in :data:`TICK_FONTS` with a Unicode minus, not mathtext.

    They look the same (mathtext sets the digits in cmr10 too) and cost a tenth: each distinct label is otherwise
    parsed by mathtext's pyparsing grammar at each resolution it is drawn at (measured: 45 % of a figure's time).
    """
    from matplotlib.ticker import ScalarFormatter

    class _Minus(ScalarFormatter):
        @staticmethod
        def fix_minus(s):
            return s.replace("-", "\N{MINUS SIGN}")

    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            if type(axis.get_major_formatter()) is ScalarFormatter:
                axis.set_major_formatter(_Minus(useMathText=False))
                ax.tick_params(axis="x" if axis is ax.xaxis else "y", labelfontfamily=TICK_FONTS)


def _styled(build):
    """Run a figure builder with :data:`STYLE` (a local rc context: no global matplotlib state changes)."""
    def run(*args, **kw):
        import matplotlib

        with matplotlib.rc_context(STYLE):
            fig = build(*args, **kw)
            if fig is not None:
                _plain_ticks(fig)
            return fig
    run.__doc__ = build.__doc__
    return run


def _save(fig, directory: Path, name: str, formats: tuple[str, ...]) -> list[Path]:
    import io

    from .output import atomic_write

    out = []
    for fmt in formats:
        buf = io.BytesIO()
        fig.savefig(buf, format=fmt, dpi=DPI, bbox_inches="tight")
        out.append(atomic_write(directory / f"{name}.{fmt}", buf.getvalue()))
    return out


def figure_files(directory: Path, stem: str, formats: Sequence[str]) -> list[Path]:
    """Every file :func:`plot_study` may write into ``directory`` (checked before any is written).

    Parameters
    ----------
    directory : Path
        The folder.
    stem : str
        The start of the file names.
    formats : sequence of str
        The file formats.

    Returns
    -------
    list of Path
    """
    return [Path(directory) / f"{stem}_{f}.{fmt}" for f in FIGURES for fmt in formats]


def _log_axes(ax, ticks: Sequence[float]) -> None:
    from matplotlib.ticker import FixedLocator, NullFormatter, NullLocator

    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.xaxis.set_major_locator(FixedLocator(sorted(set(ticks))))
    ax.xaxis.set_major_formatter(lambda v, _pos: f"{v:g}")
    ax.xaxis.set_minor_locator(NullLocator())
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.yaxis.set_minor_formatter(NullFormatter())  # labelled decades only: minor labels crowd a narrow panel


def plot_study(study: ValidationStudy, directory: Path, stem: str, formats: tuple[str, ...], force: bool = False
               ) -> list[Path]:
    """Write the figures of ``study`` into ``directory`` as ``<stem>_errors.<fmt>`` etc.; return the files.

    Parameters
    ----------
    study : ValidationStudy
        The study, with at least one row.
    directory : Path
        The folder (created if missing).
    stem : str
        The start of the file names.
    formats : tuple of str
        Among ``"png"``, ``"pdf"``, ``"svg"``.
    force : bool
        Whether existing figure files may be replaced (checked before any is written).

    Returns
    -------
    list of Path

    Raises
    ------
    ImportError
        matplotlib is not installed (raised before any file is touched).
    OutputExistsError
        a figure file exists and ``force`` is not given (nothing is written then).
    """
    bad = [f for f in formats if f not in ("png", "pdf", "svg")]
    if bad or not formats:
        raise InputError(f"plot formats must be among png, pdf, svg; got {formats!r}")
    if not study.rows:
        raise InputError("the study has no rows to plot")
    _figure()  # raises the ImportError naming the extra before any file is touched
    from .output import refuse_existing

    refuse_existing(figure_files(directory, stem, formats), force)
    directory.mkdir(parents=True, exist_ok=True)
    from matplotlib import colormaps

    cmap = colormaps["viridis"]
    nus = sorted({r.nu for r in study.rows})
    colour = {v: cmap(0.85 * i / max(len(nus) - 1, 1)) for i, v in enumerate(nus)}
    shapes = [s for s in SHAPES if any(r.shape == s for r in study.rows)]
    import matplotlib

    with matplotlib.rc_context(STYLE):  # drawn and saved in the style they were built in
        files = _save(_errors_figure(study, colour), directory, f"{stem}_errors", formats)
        files += _save(_pressure_figure(study, shapes, cmap), directory, f"{stem}_pressure", formats)
        files += _save(_contours_figure(study, shapes), directory, f"{stem}_contours", formats)
        fig = _edge_shift_figure(study, colour)
        if fig is not None:
            files += _save(fig, directory, f"{stem}_edge_shift", formats)
    return files


def _legend_below(fig, handles: list, ncol: int) -> None:
    """One legend for the whole figure, below the panels (never over the data)."""
    fig.legend(handles=handles, loc="outside lower center", ncol=ncol, frameon=False)


def _key(**kw):
    """A legend entry drawn as given (a line, a marker or both): every entry shows what it names."""
    from matplotlib.lines import Line2D

    return Line2D([], [], **kw)


@_styled
def _errors_figure(study: ValidationStudy, colour: dict[float, Any]):
    """Relative error vs H/a (log-log), one panel per quantity, each with a reference line of its claimed slope.

    The reference line is labelled on its own panel with the slope it is drawn with.
    """
    panels = (("force", "force $P$", r"$|P_0+P_1-P|/P$"),
              ("contact_area", r"contact area $|\omega|$", r"$|\,|\omega|_{\rm as}-|\omega|\,|/|\omega|$"),
              ("pressure", "pressure $p$", r"$\max|p_c-p|/p_{\max}$"))
    groups = study.groups()
    ratios = [r.H_over_a for r in study.rows]
    fig = _figure(figsize=(WIDTH, 3.1), layout="constrained")
    axes = fig.subplots(1, 3)
    hollow = False
    for ax, (q, title, measure) in zip(axes, panels):
        allx, ally = [], []
        for (shape, nu), rows in groups.items():
            x = np.array([r.H_over_a for r in rows])
            y = np.array([abs(r.errors()[q]) for r in rows])
            res = np.array([r.resolved(q) for r in rows])
            ax.plot(x, y, "-", color=colour[nu], lw=1, alpha=0.7)
            ax.plot(x[res], y[res], _MARKER[shape], color=colour[nu])
            if (~res).any():
                hollow = True
                ax.plot(x[~res], y[~res], _MARKER[shape], mfc="none", color=colour[nu])
            allx += list(x)
            ally += list(y[y > 0])
        if allx and ally:
            _claimed_slope(ax, q, allx, ally)
        _log_axes(ax, ratios)
        ax.set_xlabel("$H/a$")
        ax.set_title(f"{title}: {measure}", fontsize=8.5)
        ax.grid(True, which="major", alpha=0.3)
    axes[0].set_ylabel("relative error")
    keys = [_key(color=colour[nu], marker=_MARKER[shape], ls="-", label=f"{shape}, $\\nu = {nu:g}$")
            for shape, nu in groups]
    keys.append(_key(color="k", ls="--", label="claimed slope (labelled)"))
    if hollow:
        keys.append(_key(color="0.3", marker="o", mfc="none", ls="none", label="not resolved by the numerics"))
    _legend_below(fig, keys, min(len(keys), 4))
    fig.suptitle("Asymptotic solution against the direct numerical solution: relative errors")
    return fig


def _claimed_slope(ax, quantity: str, allx: list[float], ally: list[float]) -> float:
    """A dashed line of the claimed slope through the middle of the points, labelled with that slope."""
    claimed, kind = CLAIMED_ORDERS[quantity]
    xs = np.array([min(allx), max(allx)])
    y0 = float(np.exp(np.median(np.log(ally))))
    x0 = float(np.exp(np.mean(np.log(xs))))
    ys = y0 * (xs / x0) ** claimed
    ax.plot(xs, ys, "k--", lw=1.2, gid=f"slope {claimed}")
    text = f"slope {claimed} " + ("(bound, dashed)" if kind == "bound" else "(dashed)")
    # inside the panel's lower right corner (the errors rise to the right: that corner is free), never across its frame
    ax.text(0.97, 0.04, text, transform=ax.transAxes, fontsize=8, ha="right", va="bottom", gid="slope label")
    return float(claimed)


def _profiles(study: ValidationStudy, shape: str) -> tuple[float, list]:
    """The profiles a pressure panel shows: nu = 0.3 if there (else the first), the three largest H/a."""
    profs = [p for p in study.profiles if p.shape == shape and p.axis in ("r", "x1")]
    nu_pick = 0.3 if any(p.nu == 0.3 for p in profs) else profs[0].nu
    return nu_pick, sorted((p for p in profs if p.nu == nu_pick), key=lambda p: -p.H_over_a)[:3]


@_styled
def _pressure_figure(study: ValidationStudy, shapes: list[str], cmap: Any):
    """Pressure profiles (nu = 0.3 if there, the three largest H/a): whole contact and edge zoom."""
    fig = _figure(figsize=(WIDTH, 2.7 * len(shapes) + 0.7), layout="constrained")
    axes = np.atleast_2d(fig.subplots(len(shapes), 2))
    picked = {shape: _profiles(study, shape) for shape in shapes}
    # one colour per H/a value, the same in every panel and in the legend (never by position in a panel)
    ratios = sorted({p.H_over_a for _, profs in picked.values() for p in profs}, reverse=True)
    colour = {e: cmap(0.8 * k / max(len(ratios) - 1, 1)) for k, e in enumerate(ratios)}
    for row_ax, shape in zip(axes, shapes):
        nu_pick, profs = picked[shape]
        for p in profs:
            col = colour[p.H_over_a]
            x = p.x / p.half_width
            pm = float(np.max(p.numeric))
            for ax in row_ax:
                ax.plot(x, p.numeric / pm, "-", color=col, lw=1.5, gid=f"H/a = {p.H_over_a:g}: numerical")
                ax.plot(x, p.asymptotic / pm, "--", color=col, lw=1.2, gid=f"H/a = {p.H_over_a:g}: asymptotic")
        lab = "r/a_0" if shape == "sphere" else "x_1/a_1"
        row_ax[0].set_xlim(0 if shape == "sphere" else -1.1, 1.1)
        row_ax[0].set_title(f"{shape}, $\\nu = {nu_pick:g}$: whole contact")
        row_ax[1].set_xlim(0.85, 1.05)
        row_ax[1].set_ylim(-0.02, 0.45)
        row_ax[1].set_title("near the edge (boundary layer, width $\\sim H$)")
        for ax in row_ax:
            ax.set_xlabel(f"${lab}$")
            ax.grid(True, alpha=0.3)
        row_ax[0].set_ylabel(r"$p/p_{\max}$")
    keys = [_key(color=colour[e], lw=3, label=f"$H/a = {e:g}$") for e in ratios]
    handles = [*keys, _key(color="k", ls="-", label="numerical"),
               _key(color="k", ls="--", label="composite asymptotic")]
    _legend_below(fig, handles, len(handles))
    fig.suptitle("Contact pressure: direct numerical solution and composite asymptotic expansion")
    return fig


@_styled
def _contours_figure(study: ValidationStudy, shapes: list[str]):
    """Contact contours at the largest H/a, with a zoom at the x1 tip on the scale of the edge shift."""
    fig = _figure(figsize=(WIDTH, 3.0 * len(shapes) + 0.9), layout="constrained")
    axes = np.atleast_2d(fig.subplots(len(shapes), 2))
    handles = []
    for row_ax, shape in zip(axes, shapes):
        cs = [c for c in study.contours if c.shape == shape]
        nu_pick = 0.3 if any(c.nu == 0.3 for c in cs) else cs[0].nu
        c = max((c for c in cs if c.nu == nu_pick), key=lambda c: c.H_over_a)
        row0 = next(r for r in study.rows if r.shape == shape and r.nu == nu_pick and r.H_over_a == c.H_over_a)
        for ax in row_ax:
            for poly in c.numeric:
                ax.plot(poly[:, 0], poly[:, 1], "-", color="C0", lw=1.6)
            ax.plot(c.asymptotic[:, 0], c.asymptotic[:, 1], "--", color="C3", lw=1.3)
            ax.plot(c.alexandrov[:, 0], c.alexandrov[:, 1], "-.", color="C2", lw=1.1)
            ax.plot(c.leading[:, 0], c.leading[:, 1], ":", color="k", lw=1)
            ax.grid(True, alpha=0.3)
            ax.set_xlabel("$x_1$")
        row_ax[0].set_ylabel("$x_2$")
        row_ax[0].set_aspect("equal")
        a1, H = float(np.max(c.leading[:, 0])), row0.H
        tip = [a1 - row0.edge_shift_exact * H, a1 - row0.edge_shift_alexandrov * H, a1,
               row0.semi_axes_numeric[0]]
        lo, hi = min(tip), max(tip)
        pad = 0.6 * (hi - lo)
        row_ax[1].set_xlim(lo - pad, hi + pad)
        row_ax[1].set_ylim(-0.15 * H * 20 ** 0.5, 0.15 * H * 20 ** 0.5)
        row_ax[1].xaxis.set_major_locator(_ticks(3))
        row_ax[0].set_title(f"{shape}, $\\nu = {nu_pick:g}$, $H/a = {c.H_over_a:g}$")
        row_ax[1].set_title(f"zoom at the $x_1$ tip ($H = {H:.3g}$)")
        if not handles:
            handles = [_key(color="C0", ls="-", lw=1.6, label="numerical"),
                       _key(color="C3", ls="--", label=f"$\\Gamma_0$ moved in by $h^*H$, exact $h^* = "
                                                        f"{row0.edge_shift_exact:.4f}$"),
                       _key(color="C2", ls="-.", label=f"Alexandrov's $h^* = {row0.edge_shift_alexandrov:.4f}$ (3.25)"),
                       _key(color="k", ls=":", label=r"leading contour $\Gamma_0$")]
    _legend_below(fig, handles, 2)
    fig.suptitle("Contact contour: numerical, and the leading contour moved in by the edge shift")
    return fig


def _ticks(n: int):
    from matplotlib.ticker import MaxNLocator

    return MaxNLocator(n)


@_styled
def _edge_shift_figure(study: ValidationStudy, colour: dict[float, Any]):
    """The edge shift ``(a_0 - c)/H`` against H/a with h^* exact and Alexandrov's; None without sphere rows."""
    sph = {nu: rows for (shape, nu), rows in study.groups().items() if shape == "sphere"}
    if not sph:
        return None
    fig = _figure(figsize=(0.75 * WIDTH, 3.6), layout="constrained")
    ax = fig.subplots()
    for nu, rows in sph.items():
        x = np.array([r.H_over_a for r in rows])
        ax.plot(x, [r.edge_shift_numeric for r in rows], "o-", color=colour[nu],
                label=f"numerical, $\\nu = {nu:g}$")
        ax.axhline(rows[0].edge_shift_exact, color=colour[nu], lw=1, ls="--",
                   label=f"exact $h^* = {rows[0].edge_shift_exact:.4f}$")
        ax.axhline(rows[0].edge_shift_alexandrov, color=colour[nu], lw=1, ls=":",
                   label=f"Alexandrov's $h^* = {rows[0].edge_shift_alexandrov:.4f}$")
    for k, ch in enumerate(study.edge_shift_checks()):
        ax.plot([0.0], [ch.extrapolated], "*", color=colour[ch.nu], ms=10, ls="none",
                label="extrapolated to $H/a = 0$" if k == 0 else None)
    ax.set_xlim(left=-0.005)
    ax.set_xlabel("$H/a$")
    ax.set_ylabel("edge shift $(a_0 - c)/H$")
    ax.set_title("Sphere: edge shift of the contact radius")
    ax.grid(True, alpha=0.3)
    fig.legend(loc="outside lower center", ncol=2, frameon=False)
    return fig
