r"""Figures of a validation study (matplotlib, the optional ``plot`` extra; no pyplot state is touched).

Four figures, one function each: the relative errors against ``H/a`` (log-log, with the claimed
slopes), the pressure profiles (numerical against composite, with an edge zoom), the contact contours
(numerical, Gamma_0 moved in by h^* H with the exact and Alexandrov's h^* (3.25), Gamma_0), and the
sphere's edge shift ``(a_0 - c)/H`` against ``H/a`` with its extrapolation to 0.
"""
from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from .cases import CLAIMED_ORDERS, SHAPES

if TYPE_CHECKING:  # pragma: no cover
    from .analysis import ValidationStudy

__all__ = ["figure_files", "plot_study"]

#: the figures, by the end of their file names (the edge-shift figure only when the study has spheres)
FIGURES = ("errors", "pressure", "contours", "edge_shift")

_MARKER = {"sphere": "o", "elliptic": "s"}


def _figure(*args, **kw):
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError as exc:
        raise ImportError("the validation plots need matplotlib, the optional 'plot' extra: "
                          "pip install 'thinlayer[plot]' (or pip install matplotlib)") from exc
    fig = Figure(*args, **kw)
    FigureCanvasAgg(fig)
    return fig


def _save(fig, directory: Path, name: str, formats: tuple[str, ...]) -> list[Path]:
    import io

    from .output import atomic_write

    out = []
    for fmt in formats:
        buf = io.BytesIO()
        fig.savefig(buf, format=fmt, dpi=130, bbox_inches="tight")
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
        raise ValueError(f"plot formats must be among png, pdf, svg; got {formats!r}")
    if not study.rows:
        raise ValueError("the study has no rows to plot")
    _figure()  # raises the ImportError naming the extra before any file is touched
    from .output import refuse_existing

    refuse_existing(figure_files(directory, stem, formats), force)
    directory.mkdir(parents=True, exist_ok=True)
    from matplotlib import colormaps

    cmap = colormaps["viridis"]
    nus = sorted({r.nu for r in study.rows})
    colour = {v: cmap(0.85 * i / max(len(nus) - 1, 1)) for i, v in enumerate(nus)}
    shapes = [s for s in SHAPES if any(r.shape == s for r in study.rows)]
    files = _save(_errors_figure(study, colour), directory, f"{stem}_errors", formats)
    files += _save(_pressure_figure(study, shapes, cmap), directory, f"{stem}_pressure", formats)
    files += _save(_contours_figure(study, shapes), directory, f"{stem}_contours", formats)
    fig = _edge_shift_figure(study, colour)
    if fig is not None:
        files += _save(fig, directory, f"{stem}_edge_shift", formats)
    return files


def _errors_figure(study: ValidationStudy, colour: dict[float, Any]):
    """Error vs H/a, one panel per claimed quantity, with the claimed slope."""
    panels = (("force", r"force  $|P_0+P_1-P|/P$"),
              ("contact_area", r"contact area  $|\,|\omega|_{\rm asym}-|\omega|\,|/|\omega|$"),
              ("pressure", r"pressure  $\max|p_c-p|/p_{\max}$ (elliptic: $\geq 3$ cells inside)"))
    groups = study.groups()
    ratios = [r.H_over_a for r in study.rows]
    fig = _figure(figsize=(15, 4.6), layout="constrained")
    axes = fig.subplots(1, 3)
    for ax, (q, title) in zip(axes, panels):
        allx, ally = [], []
        for (shape, nu), rows in groups.items():
            x = np.array([r.H_over_a for r in rows])
            y = np.array([abs(r.errors()[q]) for r in rows])
            res = np.array([r.resolved(q) for r in rows])
            ax.plot(x, y, "-", color=colour[nu], lw=1, alpha=0.7)
            ax.plot(x[res], y[res], _MARKER[shape], color=colour[nu], ms=5, label=f"{shape} ν={nu:g}")
            if (~res).any():
                ax.plot(x[~res], y[~res], _MARKER[shape], mfc="none", color=colour[nu], ms=5)
            allx += list(x)
            ally += list(y[y > 0])
        if allx and ally:
            _claimed_slope(ax, q, allx, ally)
        _log_axes(ax, ratios)
        ax.set_xlabel("$H/a$")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="major", alpha=0.3)
    axes[0].set_ylabel("relative error of the asymptotics")
    axes[-1].legend(fontsize=7, loc="lower right")
    fig.suptitle("asymptotic vs direct numerical solution (hollow markers: not resolved by the numerics)",
                 fontsize=10)
    return fig


def _claimed_slope(ax, quantity: str, allx: list[float], ally: list[float]) -> None:
    """A dashed line of the claimed slope through the middle of the points."""
    claimed, kind = CLAIMED_ORDERS[quantity]
    xs = np.array([min(allx), max(allx)])
    y0 = float(np.exp(np.median(np.log(ally))))
    x0 = float(np.exp(np.mean(np.log(xs))))
    ax.plot(xs, y0 * (xs / x0) ** claimed, "k--", lw=1.2,
            label=f"slope {claimed}" + (" (claimed bound)" if kind == "bound" else " (claimed)"))


def _pressure_figure(study: ValidationStudy, shapes: list[str], cmap: Any):
    """Pressure profiles (nu = 0.3 if there, the three largest H/a), whole contact and edge zoom."""
    fig = _figure(figsize=(12, 4.0 * len(shapes)), layout="constrained")
    axes = np.atleast_2d(fig.subplots(len(shapes), 2))
    for row_ax, shape in zip(axes, shapes):
        profs = [p for p in study.profiles if p.shape == shape and p.axis in ("r", "x1")]
        nu_pick = 0.3 if any(p.nu == 0.3 for p in profs) else profs[0].nu
        profs = sorted((p for p in profs if p.nu == nu_pick), key=lambda p: -p.H_over_a)[:3]
        for k, p in enumerate(profs):
            col = cmap(0.8 * k / max(len(profs) - 1, 1))
            x = p.x / p.half_width
            pm = float(np.max(p.numeric))
            for ax in row_ax:
                ax.plot(x, p.numeric / pm, "-", color=col, lw=1.5, label=f"numerical H/a={p.H_over_a:g}")
                ax.plot(x, p.asymptotic / pm, "--", color=col, lw=1.2, label=f"composite H/a={p.H_over_a:g}")
        lab = "r/a_0" if shape == "sphere" else "x_1/a_1"
        row_ax[0].set_xlim(0 if shape == "sphere" else -1.1, 1.1)
        row_ax[0].set_title(f"{shape}, ν={nu_pick:g}: pressure along ${lab}$", fontsize=10)
        row_ax[1].set_xlim(0.85, 1.05)
        row_ax[1].set_ylim(-0.02, 0.45)
        row_ax[1].set_title("edge zoom (boundary layer of width ~H)", fontsize=10)
        for ax in row_ax:
            ax.set_xlabel(f"${lab}$")
            ax.set_ylabel(r"$p/p_{\max}$")
            ax.grid(True, alpha=0.3)
        row_ax[0].legend(fontsize=7)
    return fig


def _contours_figure(study: ValidationStudy, shapes: list[str]):
    """Contact contours at the largest H/a, with a zoom at the x1 tip on the scale of the edge shift."""
    fig = _figure(figsize=(12, 4.4 * len(shapes)), layout="constrained")
    axes = np.atleast_2d(fig.subplots(len(shapes), 2))
    for row_ax, shape in zip(axes, shapes):
        cs = [c for c in study.contours if c.shape == shape]
        nu_pick = 0.3 if any(c.nu == 0.3 for c in cs) else cs[0].nu
        c = max((c for c in cs if c.nu == nu_pick), key=lambda c: c.H_over_a)
        row0 = next(r for r in study.rows if r.shape == shape and r.nu == nu_pick and r.H_over_a == c.H_over_a)
        for ax in row_ax:
            for k, poly in enumerate(c.numeric):
                ax.plot(poly[:, 0], poly[:, 1], "-", color="C0", lw=1.6, label="numerical" if k == 0 else None)
            ax.plot(c.asymptotic[:, 0], c.asymptotic[:, 1], "--", color="C3", lw=1.3,
                    label=f"$\\Gamma_0$ moved in by $h^*H$, exact $h^*$={row0.edge_shift_exact:.4f}")
            ax.plot(c.alexandrov[:, 0], c.alexandrov[:, 1], "-.", color="C2", lw=1.1,
                    label=f"Alexandrov $h^*$={row0.edge_shift_alexandrov:.4f}")
            ax.plot(c.leading[:, 0], c.leading[:, 1], ":", color="k", lw=1, label=r"$\Gamma_0$")
            ax.grid(True, alpha=0.3)
            ax.set_xlabel("$x_1$")
            ax.set_ylabel("$x_2$")
        row_ax[0].set_aspect("equal")
        a1, H = float(np.max(c.leading[:, 0])), row0.H
        tip = [a1 - row0.edge_shift_exact * H, a1 - row0.edge_shift_alexandrov * H, a1,
               row0.semi_axes_numeric[0]]
        lo, hi = min(tip), max(tip)
        pad = 0.6 * (hi - lo)
        row_ax[1].set_xlim(lo - pad, hi + pad)
        row_ax[1].set_ylim(-0.15 * H * 20 ** 0.5, 0.15 * H * 20 ** 0.5)
        row_ax[0].set_title(f"{shape}, ν={nu_pick:g}, H/a={c.H_over_a:g}: contact contour", fontsize=10)
        row_ax[1].set_title(f"zoom at the $x_1$ tip (H = {H:.3g}; 2D contour error ~0.1 cell)", fontsize=10)
        row_ax[1].legend(fontsize=7, loc="lower left")
    return fig


def _edge_shift_figure(study: ValidationStudy, colour: dict[float, Any]):
    """The edge shift ``(a_0 - c)/H`` against H/a with h^* exact and Alexandrov's; None without sphere rows."""
    sph = {nu: rows for (shape, nu), rows in study.groups().items() if shape == "sphere"}
    if not sph:
        return None
    fig = _figure(figsize=(7.5, 5), layout="constrained")
    ax = fig.subplots()
    for nu, rows in sph.items():
        x = np.array([r.H_over_a for r in rows])
        ax.plot(x, [r.edge_shift_numeric for r in rows], "o-", color=colour[nu], ms=4,
                label=f"ν={nu:g}: $(a_0-c)/H$")
        ax.axhline(rows[0].edge_shift_exact, color=colour[nu], lw=1, ls="--")
        ax.axhline(rows[0].edge_shift_alexandrov, color=colour[nu], lw=1, ls=":")
    for ch in study.edge_shift_checks():
        ax.plot([0.0], [ch.extrapolated], "*", color=colour[ch.nu], ms=10)
    ax.set_xlim(left=-0.005)
    ax.set_xlabel("$H/a$")
    ax.set_ylabel("edge shift")
    ax.set_title("sphere: $(a_0 - c)/H$ from the axisymmetric numerics; dashed exact $h^*$, dotted Alexandrov's,\n"
                 "stars: Richardson extrapolation to $H/a = 0$", fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    return fig
