r"""Force maps (issue 25 item 5): every curve of a map fitted, E, H, contact point and quality as 2D arrays.

:func:`fit_map` reads a map (a ``.jpk-force-map``, any file afmformats reads with several curves on a grid, or a
folder of curve files, :mod:`thinlayer.afm.map_data`), fits each pixel's approach curve with a per-curve fitter
(``fit_one``) and returns an immutable :class:`MapResult`: the maps of E (Pa), its standard error, H, the contact
point (tip position, m) and the residual, each pixel's status, and the failures with their reasons.  A failed pixel
is NaN with its reason, never a number; a pixel fitted outside its model's validity keeps its numbers, flagged
(``status`` ``"flagged"`` and the reason).

The curves are fitted by :func:`thinlayer.afm.distributed.map_batch`: serially, or on dask.distributed
(``scheduler="local"``, an address ``"tcp://..."``), with the same results.

Thickness per pixel (``H``): one number for the whole map; ``None``/``inf`` for the half-space (Hertz); a 2D array
(one thickness per pixel); or ``"height"``: the topography minus the substrate level, the topography being a
height image (``height_image=``: an array or a ``.npy``/text file, in metres) or, without one, the height of each
curve's contact point estimated before the fit (:func:`estimate_contact`, where the force leaves 5 noise deviations:
a few nm below the true contact on soft samples, e.g. 6 nm for Hertz at E = 5 kPa, R = 5 µm, noise 2 pN), minus the
substrate level (:func:`thickness_from_height`).

The per-curve fitter.  ``fit_one(curve, punch=, H=, nu=, base=)`` takes a :class:`~thinlayer.afm.map_data.MapCurve`
and returns an object with ``E`` and optionally ``E_se``, ``H``, ``contact_point`` (or ``z0``), ``residual_rms``,
``valid``, ``validity``, ``flags``.  The default (:func:`default_fitter`) is :func:`fit_curve_full`:
:func:`thinlayer.afm.curve_fit.fit_curve`, with the contact point and the baseline offset as fit parameters, solved by
variable projection (``solver="varpro"``: the reference Levenberg-Marquardt's numbers within 1e-3 of a standard
error, 3.9 ms of CPU per 2,000-point curve on a layer, 2.5 ms on the half-space, one process at load 8-10).  With
``scheduler="auto"`` (default) a map of 256 curves or more runs on a local dask cluster (one process per core); the
any-thickness law is built here once and sent to the workers
(:func:`thinlayer.contact.models.any_thickness.adopt_law`), the curves travel packed (:class:`_PixelBlock`) and each
worker fits the first curve once while they travel (imports and caches paid then).
:func:`fit_curve_basic` is a simpler, faster fitter (baseline line fitted to the first quarter of the approach and
subtracted, the contact point started where the corrected force leaves the noise, then :func:`thinlayer.fit` with
the contact point free).
"""
from __future__ import annotations

import csv
import functools
import io
import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..display import RichDisplay
from ..errors import InputError, InputTypeError, ThinlayerError, ValidityWarning
from .distributed import check_scheduler, map_batch
from .map_data import MapCurve, MapGrid, read_map

__all__ = ["BASELINE_FRACTION", "CurveFit", "MapResult", "default_fitter", "fit_curve_basic", "fit_map",
           "fit_curve_full", "substrate_level", "thickness_from_height"]

#: the first part of the approach (by points) taken as off contact for the baseline of :func:`fit_curve_basic`
BASELINE_FRACTION = 0.25
#: a corrected force above this many noise standard deviations counts as in contact (contact-point estimate)
CONTACT_SIGMAS = 5.0
#: the fraction of the lowest pixels whose median is the substrate level (:func:`substrate_level`)
SUBSTRATE_FRACTION = 0.05
#: statuses of a pixel
STATUSES = ("ok", "flagged", "failed", "empty")


@dataclass(frozen=True)
class CurveFit:
    """One curve's fit (:func:`fit_curve_basic`): what a map keeps of it.

    Attributes
    ----------
    E, E_se : float
        Young's modulus (Pa) and its standard error (from the fit's Jacobian).
    H : float
        The thickness used (``inf``: the half-space).
    contact_point : float
        The fitted contact point as a tip position (m, the instrument's axis: negative into the sample).
    residual_rms : float
        Root-mean-square force residual (N).
    valid : bool
        Whether the model holds over the curve (:func:`thinlayer.fit`'s ``valid``).
    validity : str
        Why not, one line (empty when valid).
    flags : tuple of str
        Regime limits passed (``delta/H`` beyond small strain, ``delta/R``).
    n_points : int
        Points fitted.
    """

    E: float
    E_se: float
    H: float
    contact_point: float
    residual_rms: float
    valid: bool = True
    validity: str = ""
    flags: tuple = ()
    n_points: int = 0


def _baseline(z: np.ndarray, f: np.ndarray) -> tuple[np.ndarray, float]:
    """``(force minus the baseline line, noise sigma)``: the line fitted to the first :data:`BASELINE_FRACTION`."""
    n = max(3, int(BASELINE_FRACTION * z.size))
    zb, fb = z[:n], f[:n]
    if np.ptp(zb) > 0:
        slope, offset = np.polyfit(zb - zb.mean(), fb, 1)
        base = offset + slope * (z - zb.mean())
    else:
        base = np.full_like(f, float(np.median(fb)))
    res = fb - base[:n]
    sigma = 1.4826 * float(np.median(np.abs(res - np.median(res))))  # MAD: spikes do not inflate it
    return f - base, sigma


def estimate_contact(z: np.ndarray, f: np.ndarray) -> tuple[int, np.ndarray]:
    """``(index of the contact point, baseline-corrected force)`` of an approach curve (tip position ``z``).

    Walking back from the largest force, the contact is the last point whose corrected force is within
    :data:`CONTACT_SIGMAS` noise deviations of the baseline (or, noise-free, at most 1e-3 of the peak force).  A curve
    whose last 5 % (an approach ends pressed in) stays within that noise band has no contact: refused in one line.
    """
    fc, sigma = _baseline(z, f)
    top = int(np.argmax(fc))
    if not fc[top] > 0:
        raise InputError("the approach curve has no force above its baseline: no contact to fit")
    tail = float(np.median(fc[-max(5, fc.size // 20):]))  # an approach ends pressed in: its last points the highest
    if not tail > CONTACT_SIGMAS * sigma:
        raise InputError(f"no contact: the force at the end of the approach is not above the noise ({tail:.3g} N "
                         f"above the baseline, noise {sigma:.3g} N; {CONTACT_SIGMAS:g} noise deviations needed)")
    thresh = max(CONTACT_SIGMAS * sigma, 1e-3 * float(fc[top]))
    below = np.nonzero(fc[:top + 1] <= thresh)[0]
    if below.size == 0:
        raise InputError("the curve starts in contact (no baseline before the force rises): no contact point")
    return int(below[-1]), fc


#: the most points :func:`fit_curve_basic` fits: a longer fit window is averaged in blocks of consecutive points
MAX_FIT_POINTS = 500


def _blocks(z: np.ndarray, f: np.ndarray, most: int | None) -> tuple[np.ndarray, np.ndarray]:
    """Means of blocks of ``k = ceil(n/most)`` consecutive points (the first ``n mod k`` points, baseline, left out)."""
    n = z.size
    if most is None or n <= most:
        return z, f
    k = -(-n // most)
    m = (n // k) * k
    return z[n - m:].reshape(-1, k).mean(axis=1), f[n - m:].reshape(-1, k).mean(axis=1)


def fit_curve_basic(curve: MapCurve, *, punch: Any, H: Any = None, nu: float = 0.5, base: str = "bonded",
                    model: str | None = None, max_points: int | None = MAX_FIT_POINTS) -> CurveFit:
    """Fit one approach curve: baseline subtracted, contact point estimated, then :func:`thinlayer.fit` with the
    contact point free (E, and the contact point; H as given).

    The baseline (offset and slope in the tip position) is the line through the first quarter of the approach, which
    a force curve records off the sample; the contact point starts where the corrected force leaves the noise
    (:func:`estimate_contact`) and is then a parameter of the least-squares fit over the points from the end of the
    baseline window on (before contact the model's force is zero).  The depth is the tip position's distance below
    the contact point (the instrument's axis is negative into the sample).  A window of more than ``max_points``
    points (default :data:`MAX_FIT_POINTS`; ``None``: all) is fitted as the means of blocks of consecutive points
    (positions and forces averaged): the fit costs per point, and a block mean keeps the information of its points
    (its noise is the points' over sqrt(k)); on the benchmark's 2,000-point curves (blocks of 3) E moves by less than
    the fit's standard error (benchmarks/bench_maps.py prints the largest change).

    Returns
    -------
    CurveFit
    """
    from ..contact.fit import fit

    z, f = curve.approach()
    i0, fc = estimate_contact(z, f)
    n0 = max(3, int(BASELINE_FRACTION * z.size))
    z0 = float(z[i0])
    zw, fw = _blocks(z[n0:], fc[n0:], max_points)
    depth = z0 - zw  # positive into the sample
    if model is None and isinstance(punch, (int, float)) and H is not None and math.isfinite(H):
        model = "any-thickness"  # the sphere's law at any thickness, named: fit() need not search the registry
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)  # kept in the result: the pixel is flagged
        r = fit(depth, fw, punch=punch, H=H, nu=nu, base=base, fit_offset=True, model=model)
    if not r.offset > float(np.min(depth)):
        raise InputError(f"the fitted contact point lies above every fitted point (tip position {z0 - r.offset:.4g} "
                         "m): no baseline before contact, the curve cannot place the contact")
    return CurveFit(r.E, r.E_se, r.H, z0 - r.offset, r.residual_rms, bool(r.valid),
                    "" if r.valid else r.validity, tuple(r.flags), r.n_points)


def fit_curve_full(curve: MapCurve, *, punch: Any, H: Any = None, nu: float = 0.5, base: str = "bonded",
                   **options: Any) -> Any:
    """Fit one pixel by :func:`thinlayer.afm.curve_fit.fit_curve` (E, the contact point ``z0`` and the baseline
    offset as parameters, its robust start; ``options`` passed on, e.g. ``weighting="nanite"``, ``baseline=
    "offset+slope"``; no bootstrap unless asked: a map is thousands of fits).
    """
    from .curve_fit import fit_curve
    from .curves import curve_from_arrays

    c = curve_from_arrays(curve.tip_position, curve.force, axis="tip position", units=("m", "N"), source=curve.name)
    options.setdefault("solver", "varpro")
    if options.get("model") is None and isinstance(punch, (int, float)) and H is not None and math.isfinite(H):
        options["model"] = "any-thickness"  # the sphere's law at any thickness, named: no search of the registry
    return fit_curve(c, punch=punch, H=H, nu=nu, base=base, **options)


def default_fitter() -> Callable[..., Any]:
    """:func:`fit_curve_full` (``thinlayer.afm.curve_fit.fit_curve``) when that module is there, else
    :func:`fit_curve_basic`.
    """
    try:
        from . import curve_fit  # noqa: F401 - only whether it exists
    except ImportError:  # pragma: no cover - a thinlayer without thinlayer.afm.curve_fit
        return fit_curve_basic
    return fit_curve_full


@dataclass(frozen=True)
class _Pixel:
    """One pixel's numbers and status (what a worker returns: small and picklable)."""

    index: tuple
    E: float = math.nan
    E_se: float = math.nan
    H: float = math.nan
    contact_point: float = math.nan
    residual_rms: float = math.nan
    status: str = "failed"
    reason: str = ""


class _PixelBlock:
    """A chunk of a map's ``(curve, H)`` items packed for a dask worker: all its curves' tip positions in one array,
    their forces in another, the indices, names and thicknesses in a list.  Iterating gives back the chunk's items,
    in order, each curve's arrays slices of the two: the same numbers, pickled as 2 buffers instead of 2 per curve
    (:func:`thinlayer.afm.distributed.map_batch`'s ``pack``).
    """

    def __init__(self, items: list[tuple[MapCurve, Any]]) -> None:
        self.meta = [(c.index, c.name, c.spring_constant, c.position, H) for c, H in items]
        arrays = [(c.tip_position, c.force) for c, _ in items]
        if items and all(isinstance(a, np.ndarray) and a.dtype == np.float64 and a.ndim == 1 and a.size == z.size
                         for z, f in arrays for a in (z, f)):
            self.stops = [int(n) for n in np.cumsum([z.size for z, _ in arrays])]
            self.z = np.concatenate([z for z, _ in arrays])
            self.f = np.concatenate([f for _, f in arrays])
            self.items = None
        else:  # not 1D float arrays of one length per curve: the items themselves, as they are
            self.z = self.f = None
            self.items = list(items)

    def __len__(self) -> int:
        return len(self.meta)

    def __iter__(self):
        if self.z is None:
            yield from self.items
            return
        start = 0
        for stop, (index, name, k, pos, H) in zip(self.stops, self.meta):
            yield MapCurve(index, self.z[start:stop], self.f[start:stop], name, k, pos), H
            start = stop


def _number(obj: Any, *names: str) -> float:
    for n in names:
        v = getattr(obj, n, None)
        if v is not None:
            try:
                return float(v)
            except (TypeError, ValueError):
                continue
    return math.nan


def _fit_pixel(item: tuple[MapCurve, Any], *, fit_one: Callable[..., Any], punch: Any, nu: float,
               base: str, law: Any = None) -> _Pixel:
    """Fit one pixel, turning a refusal into a failed pixel with its reason (one line).  ``law``: the any-thickness
    law the parent built, adopted by this (worker) process instead of building its own.
    """
    if law is not None:
        from ..contact.models.any_thickness import adopt_law

        adopt_law(law)
    curve, H = item
    if H is not None and not (isinstance(H, float) and math.isinf(H)) and not (H > 0):
        return _Pixel(curve.index, status="failed",
                      reason=f"no layer here: the thickness from the height image is {H:.3g} m (<= 0)")
    try:
        r = fit_one(curve, punch=punch, H=H, nu=nu, base=base)
    except (ThinlayerError, ValueError, TypeError, ArithmeticError, np.linalg.LinAlgError) as exc:
        return _Pixel(curve.index, status="failed", reason=" ".join(str(exc).split())[:300] or type(exc).__name__)
    E = _number(r, "E")
    if not (math.isfinite(E) and E > 0):
        return _Pixel(curve.index, status="failed", reason=f"the fit returned E = {E!r}, not a positive number")
    valid = bool(getattr(r, "valid", True))
    flags = tuple(getattr(r, "flags", ()) or ())
    why = [] if valid else [str(getattr(r, "validity", "") or "outside the model's validity")]
    why += [str(f) for f in flags]
    return _Pixel(curve.index, E, _number(r, "E_se"), _number(r, "H"), _number(r, "contact_point", "z0"),
                  _number(r, "residual_rms", "residual"), "flagged" if why else "ok", "; ".join(why))


def substrate_level(height: np.ndarray, fraction: float = SUBSTRATE_FRACTION) -> float:
    """The substrate's height in a topography: the median of the lowest ``fraction`` of its finite pixels.

    Robust to a few pixels below the substrate (noise, a dust hole): one stray pixel moves a median of the lowest
    5 % by at most one rank, where the minimum would follow it.  Give the level yourself (``substrate=``) when the
    map has no bare substrate.
    """
    h = np.asarray(height, dtype=float)
    h = h[np.isfinite(h)]
    if h.size == 0:
        raise InputError("the height image has no finite pixel: no substrate level")
    k = max(1, int(math.ceil(fraction * h.size)))
    return float(np.median(np.partition(h, k - 1)[:k]))


def thickness_from_height(height: np.ndarray, substrate: float | None = None) -> tuple[np.ndarray, float]:
    """``(H map, substrate level)``: the topography minus the substrate level (given, or :func:`substrate_level`)."""
    h = np.asarray(height, dtype=float)
    level = substrate_level(h) if substrate is None else float(substrate)
    if not math.isfinite(level):
        raise InputError(f"substrate must be a finite height, got {substrate!r}")
    return h - level, level


def _load_height(image: Any, shape: tuple[int, int]) -> np.ndarray:
    if isinstance(image, (str, Path)):
        p = Path(image)
        if not p.is_file():
            raise InputError(f"height image {str(image)[:200]}: no such file")
        try:
            arr = np.load(p, allow_pickle=False) if p.suffix == ".npy" else np.loadtxt(p, delimiter=_delim(p),
                                                                                      ndmin=2)
        except (ValueError, OSError) as exc:
            raise InputError(f"height image {p.name}: not a 2D table of numbers ({str(exc).splitlines()[0][:100]})")\
                from None
    else:
        arr = image
    try:
        arr = np.asarray(arr, dtype=float)
    except (TypeError, ValueError):
        raise InputError("height_image must be a 2D array of heights (m) or a .npy/CSV file of one") from None
    if arr.shape != shape:
        raise InputError(f"the height image has shape {arr.shape}, the map {shape} (rows = y, columns = x)")
    return arr


def _delim(p: Path) -> str | None:
    head = p.read_text(errors="replace")[:2000]
    return "," if "," in head else ";" if ";" in head else None


@dataclass(frozen=True, eq=False)
class MapResult(RichDisplay):
    """The fitted map: 2D arrays (rows = y, columns = x; read-only), statuses and failures.

    Attributes
    ----------
    E, E_se : numpy.ndarray
        Young's modulus (Pa) and its standard error per pixel; NaN where the fit failed or no curve was measured.
    H : numpy.ndarray
        The thickness used per pixel (m; ``inf`` for the half-space).
    contact_point : numpy.ndarray
        The fitted contact point (tip position, m).
    residual : numpy.ndarray
        Root-mean-square force residual (N).
    status : numpy.ndarray
        ``"ok"``, ``"flagged"`` (numbers kept, outside a validity limit: ``reasons``), ``"failed"`` (NaN) or
        ``"empty"`` (no curve at this pixel).
    reasons : numpy.ndarray
        Why a pixel is flagged or failed, one line ("" otherwise).
    grid : MapGrid
        Shape, pixel coordinates and extent (µm) of the map.
    names : numpy.ndarray
        Each pixel's curve (file and index).
    source, fitter, punch, base : str
    nu : float
    substrate : float
        The substrate level used for ``H="height"`` (NaN otherwise).
    """

    E: np.ndarray
    E_se: np.ndarray
    H: np.ndarray
    contact_point: np.ndarray
    residual: np.ndarray
    status: np.ndarray
    reasons: np.ndarray
    grid: MapGrid
    names: np.ndarray = field(repr=False)
    source: str = ""
    fitter: str = ""
    punch: str = ""
    nu: float = 0.5
    base: str = "bonded"
    substrate: float = math.nan
    equation = "T.7"

    @property
    def shape(self) -> tuple[int, int]:
        """``(rows, columns)`` = ``(ny, nx)``."""
        return self.E.shape

    @property
    def failures(self) -> tuple[tuple[int, int, str, str], ...]:
        """``(row, column, curve, reason)`` of every failed pixel."""
        return tuple((int(i), int(j), str(self.names[i, j]), str(self.reasons[i, j]))
                     for i, j in zip(*np.nonzero(self.status == "failed")))

    @property
    def flagged(self) -> tuple[tuple[int, int, str, str], ...]:
        """``(row, column, curve, reason)`` of every pixel fitted outside a validity limit."""
        return tuple((int(i), int(j), str(self.names[i, j]), str(self.reasons[i, j]))
                     for i, j in zip(*np.nonzero(self.status == "flagged")))

    def counts(self) -> dict[str, int]:
        """How many pixels have each status."""
        return {s: int(np.sum(self.status == s)) for s in STATUSES}

    def text_lines(self) -> list[str]:
        c = self.counts()
        fitted = np.isfinite(self.E)
        lines = [f"MapResult {self.shape[0]} x {self.shape[1]} pixels from {self.source} ({self.fitter}; {self.punch}, "
                 f"{self.base} base, nu = {self.nu:.6g})",
                 "  pixels: " + ", ".join(f"{c[s]} {s}" for s in STATUSES)]
        if fitted.any():
            q = np.percentile(self.E[fitted], [5, 50, 95])
            lines.append(f"  E: median {q[1]:.4g} Pa (5-95 %: {q[0]:.4g} - {q[2]:.4g} Pa)")
        return lines

    def latex(self) -> str:
        fitted = np.isfinite(self.E)
        med = float(np.median(self.E[fitted])) if fitted.any() else math.nan
        n = int(fitted.sum())
        return rf"\tilde E = {med:.6g}\ \mathrm{{Pa}}\quad ({n}\ \text{{pixels}})\tag{{{self.equation}}}"

    # ---- files -----------------------------------------------------------------------------------------------------
    COLUMNS = ("row", "column", "x_um", "y_um", "E_Pa", "E_se_Pa", "H_m", "contact_point_m", "residual_rms_N",
               "status", "reason", "curve")

    def csv_text(self) -> str:
        """One row per pixel (:attr:`COLUMNS`), every number written with 17 significant digits (round-trips)."""
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(self.COLUMNS)
        ny, nx = self.shape
        for i in range(ny):
            for j in range(nx):
                w.writerow([i, j, _g(self.grid.x[j]), _g(self.grid.y[i]), _g(self.E[i, j]), _g(self.E_se[i, j]),
                            _g(self.H[i, j]), _g(self.contact_point[i, j]), _g(self.residual[i, j]),
                            self.status[i, j], self.reasons[i, j], self.names[i, j]])
        return buf.getvalue()

    def failures_text(self) -> str:
        """The failed and flagged pixels, one line each (``row, column, curve: status: reason``)."""
        lines = [f"{i}, {j}, {name}: failed: {why}" for i, j, name, why in self.failures]
        lines += [f"{i}, {j}, {name}: flagged: {why}" for i, j, name, why in self.flagged]
        return "\n".join(lines) + ("\n" if lines else "")

    def to_csv(self, path: str | Path, *, overwrite: bool = False) -> Path:
        """Write :meth:`csv_text` to ``path`` (refused if it exists, unless ``overwrite``)."""
        from ..validation.output import atomic_write, refuse_existing

        refuse_existing([path], overwrite, "pass overwrite=True to replace it")
        return atomic_write(path, self.csv_text())

    def to_png(self, path: str | Path, *, quantity: str = "E", overwrite: bool = False, dpi: int = 120) -> Path:
        """A PNG of one map (``"E"``, ``"H"``, ``"contact_point"``, ``"residual"``) with a colour bar in its unit and
        axes in µm from the map's grid (pixels when the grid has no positions); failed pixels grey, flagged ones
        hatched.
        """
        from ..validation.output import atomic_write, refuse_existing

        maps = {"E": (self.E, "E", "Pa"), "H": (self.H, "H", "m"), "contact_point": (self.contact_point,
                "contact point", "m"), "residual": (self.residual, "residual rms", "N")}
        if quantity not in maps:
            raise InputError(f"quantity must be one of {', '.join(maps)}, got {quantity!r}")
        refuse_existing([path], overwrite, "pass overwrite=True to replace it")
        data, label, unit = maps[quantity]
        png = _render_png(self, np.where(np.isfinite(data), data, np.nan), label, unit, dpi)
        return atomic_write(path, png)


def _g(v: float) -> str:
    return repr(float(v)) if math.isfinite(v) or math.isinf(v) else "nan"


_PREFIX = [(1e9, "G"), (1e6, "M"), (1e3, "k"), (1.0, ""), (1e-3, "m"), (1e-6, "µ"), (1e-9, "n"), (1e-12, "p")]


def _scaled(data: np.ndarray, unit: str) -> tuple[np.ndarray, str]:
    finite = data[np.isfinite(data)]
    if finite.size == 0:
        return data, unit
    top = float(np.max(np.abs(finite))) or 1.0
    for s, p in _PREFIX:
        if top >= s:
            return data / s, p + unit
    return data / 1e-12, "p" + unit


def _render_png(res: MapResult, data: np.ndarray, label: str, unit: str, dpi: int) -> bytes:
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    vals, u = _scaled(data, unit)
    fig = Figure(figsize=(5.6, 4.6), dpi=dpi)
    ax = fig.add_subplot()
    g = res.grid
    cmap = matplotlib.colormaps["viridis"].with_extremes(bad="0.75")
    extent = g.extent_um if g.extent_um is not None else (-0.5, g.shape[1] - 0.5, g.shape[0] - 0.5, -0.5)
    origin = "lower" if g.extent_um is not None else "upper"
    im = ax.imshow(vals, origin=origin, extent=extent, cmap=cmap, interpolation="nearest")
    flagged = np.argwhere(res.status == "flagged")
    if flagged.size:  # one hatched square per flagged pixel
        from matplotlib.collections import PatchCollection
        from matplotlib.patches import Rectangle

        dx = (extent[1] - extent[0]) / g.shape[1]
        dy = (extent[3] - extent[2]) / g.shape[0]
        y0 = extent[2] if origin == "lower" else extent[3]
        boxes = [Rectangle((extent[0] + j * dx, y0 + i * dy), dx, dy) for i, j in flagged]
        with matplotlib.rc_context({"hatch.linewidth": 1.5, "hatch.color": "white"}):
            ax.add_collection(PatchCollection(boxes, facecolor="none", edgecolor="white", hatch="///", linewidth=0))
    ax.set_xlabel("x (µm)" if g.extent_um is not None else "x (pixel)")
    ax.set_ylabel("y (µm)" if g.extent_um is not None else "y (pixel)")
    c = res.counts()
    ax.set_title(f"{label}: {res.punch}, {res.base} base, ν = {res.nu:.3g}\n"
                 f"{c['ok']} ok, {c['flagged']} flagged (hatched), {c['failed']} failed and {c['empty']} empty (grey)",
                 fontsize=9)
    ratio = abs((extent[3] - extent[2]) / (extent[1] - extent[0]))  # the bar as tall as the image
    bar = fig.colorbar(im, ax=ax, fraction=0.046 * min(ratio, 1.0), pad=0.04)
    bar.set_label(f"{label} ({u})")
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    return buf.getvalue()


def _punch_words(punch: Any) -> str:
    if isinstance(punch, (int, float)) and not isinstance(punch, bool):
        return f"sphere R = {float(punch):.4g} m"
    return str(getattr(punch, "description", None) or getattr(punch, "name", punch))


def _check_thickness(H: Any, height_image: Any) -> None:
    """One line for an ``H`` (or a ``height_image`` without ``H="height"``) that :func:`fit_map` cannot use."""
    if isinstance(H, str):
        if H != "height":
            raise InputError(f"H must be a thickness (m), None or inf (the half-space), a 2D array or 'height' (the "
                             f"topography minus the substrate), got {H[:40]!r}")
        return
    if height_image is not None:
        raise InputError("height_image is used with H='height' (the topography minus the substrate level)")
    if isinstance(H, (int, float)) and not isinstance(H, bool) and not (H > 0):
        raise InputError(f"H must be a positive thickness, None or inf (the half-space), got {H!r}")


def _thickness_map(H: Any, height_image: Any, substrate: Any, curves: list[MapCurve], grid: MapGrid,
                   ) -> tuple[np.ndarray | None, Any, float]:
    """``(per-pixel H or None, the single H, substrate level)``."""
    if isinstance(H, str):
        if H != "height":
            raise InputError(f"H must be a thickness (m), None or inf (the half-space), a 2D array or 'height' (the "
                             f"topography minus the substrate), got {H[:40]!r}")
        if height_image is not None:
            topo = _load_height(height_image, grid.shape)
        else:  # the map's own topography: each curve's contact height, estimated before the fit
            topo = np.full(grid.shape, np.nan)
            for c in curves:
                try:
                    z, f = c.approach()
                    topo[c.index] = z[estimate_contact(z, f)[0]]
                except (ThinlayerError, ValueError):
                    continue
        Hmap, level = thickness_from_height(topo, substrate)
        return Hmap, None, level
    if height_image is not None:
        raise InputError("height_image is used with H='height' (the topography minus the substrate level)")
    if H is None:
        return None, None, math.nan
    if isinstance(H, (int, float)) and not isinstance(H, bool):
        if math.isinf(H) and H > 0:
            return None, None, math.nan
        if not (math.isfinite(H) and H > 0):
            raise InputError(f"H must be a positive thickness, None or inf (the half-space), got {H!r}")
        return None, float(H), math.nan
    try:
        arr = np.asarray(H, dtype=float)
    except (TypeError, ValueError):
        raise InputTypeError(f"H must be a number, None, 'height' or a 2D array, got {type(H).__name__}") from None
    if arr.shape != grid.shape:
        raise InputError(f"the H map has shape {arr.shape}, the force map {grid.shape} (rows = y, columns = x)")
    return arr, None, math.nan


def _law_to_send(scheduler: Any, punch: Any, nu: float, base: str, Hs: list) -> Any:
    """The any-thickness law of the sphere, built here once and sent with the work, when the pixels run in other
    processes (a dask scheduler) and some pixel has a finite thickness: each worker adopts it instead of building
    its own (about 3 s CPU of symbolic series and tables per process, benchmarks/bench_maps.py).
    """
    if scheduler in (None, "serial", "threads") or not isinstance(punch, (int, float)) or isinstance(punch, bool):
        return None
    if not any(H is not None and math.isfinite(H) and H > 0 for H in Hs):
        return None
    from ..contact.any_thickness import any_thickness_law

    try:
        return any_thickness_law(nu, base)
    except (ThinlayerError, ValueError, TypeError):  # the pixels say why, one by one
        return None


def fit_map(source: Any, *, punch: Any, H: Any = None, nu: float = 0.5, base: str = "bonded",
            fit_one: Callable[..., Any] | None = None, progress: bool = True, scheduler: Any = "auto",
            height_image: Any = None, substrate: float | None = None, workers: int | None = None,
            timeout: float | None = None, timings: dict[str, float] | None = None) -> MapResult:
    """Fit every curve of a force map: E, H, contact point and quality per pixel (issue 25 item 5).

    Parameters
    ----------
    source : str, Path or list of MapCurve
        A map file afmformats reads (``.jpk-force-map``, an afmformats HDF5 of a map, ...), a folder of curve files,
        or curves already read (:func:`thinlayer.afm.map_data.read_map`).
    punch : float or Tip
        The sphere radius ``R`` (m; the paraboloid) or a tip (:mod:`thinlayer.punch`).
    H : None, float, "height" or 2D array
        The layer thickness (m): one value, ``None``/``inf`` (the half-space), a thickness per pixel, or
        ``"height"``: the topography minus the substrate level (module docstring).
    nu : float
        Poisson ratio.
    base : str
        ``"bonded"`` or ``"frictionless"``.
    fit_one : callable, optional
        The per-curve fitter (module docstring); default :func:`default_fitter`.
    progress : bool
        A progress bar on stderr.
    scheduler : None, str or distributed.Client
        Where the curves are fitted (:func:`thinlayer.afm.distributed.map_batch`): ``"auto"`` (default) a local dask
        cluster of one process per core for 256 curves or more (when dask.distributed is installed), else serially;
        None serially, ``"local"`` on a local dask cluster, ``"tcp://host:8786"`` on a cluster.
    height_image : array or path, optional
        The topography (m) for ``H="height"``.
    substrate : float, optional
        The substrate level (m) for ``H="height"`` (default: :func:`substrate_level`).
    workers : int, optional
        Workers of a local cluster started here.
    timeout : float, optional
        Seconds to wait for a dask cluster's results (:func:`~thinlayer.afm.distributed.map_batch`).
    timings : dict, optional
        Filled with where the time of a dask run went (:func:`~thinlayer.afm.distributed.map_batch`'s ``timings``).

    Returns
    -------
    MapResult
    """
    scheduler = check_scheduler(scheduler)
    if base not in ("bonded", "frictionless"):
        raise InputError(f"base must be 'bonded' or 'frictionless', got {base!r}")
    if isinstance(nu, bool) or not isinstance(nu, (int, float)) or not -1 < nu <= 0.5:
        raise InputError(f"nu must be a number in (-1, 1/2], got {nu!r}")
    if punch is None:
        raise InputTypeError("fit_map() needs punch= (the sphere radius R in m, or a tip)")
    _check_thickness(H, height_image)  # before reading the map: bad input costs nothing
    if isinstance(source, (list, tuple)):
        curves = list(source)
        grid = MapGrid.from_curves(curves)
        where = f"{len(curves)} curves"
    else:
        curves, grid = read_map(source)
        where = Path(source).name
    Hmap, H1, level = _thickness_map(H, height_image, substrate, curves, grid)
    fitter = default_fitter() if fit_one is None else fit_one
    items = [(c, float(Hmap[c.index]) if Hmap is not None else H1) for c in curves]
    if scheduler == "auto":
        from .distributed import auto_scheduler

        scheduler = auto_scheduler(len(items))
    work = functools.partial(_fit_pixel, fit_one=fitter, punch=punch, nu=float(nu), base=base,
                             law=_law_to_send(scheduler, punch, nu, base, [H for _, H in items]))
    pixels = map_batch(work, items, scheduler=scheduler, progress=progress, label="curves", workers=workers,
                       timeout=timeout, pack=_PixelBlock, warm=True, timings=timings)
    shape = grid.shape
    arrays = {k: np.full(shape, np.nan) for k in ("E", "E_se", "H", "contact_point", "residual")}
    status = np.full(shape, "empty", dtype=object)
    reasons = np.full(shape, "", dtype=object)
    names = np.full(shape, "", dtype=object)
    for c, p in zip(curves, pixels):
        if status[c.index] != "empty":
            raise InputError(f"two curves at the same pixel {c.index} ({names[c.index]} and {c.name}): is the map's "
                             "grid right?")
        for k, v in (("E", p.E), ("E_se", p.E_se), ("H", p.H), ("contact_point", p.contact_point),
                     ("residual", p.residual_rms)):
            arrays[k][c.index] = v
        status[c.index], reasons[c.index], names[c.index] = p.status, p.reason, c.name
    for a in (*arrays.values(), status, reasons, names):
        a.setflags(write=False)
    return MapResult(arrays["E"], arrays["E_se"], arrays["H"], arrays["contact_point"], arrays["residual"], status,
                     reasons, grid, names, where, getattr(fitter, "__qualname__", type(fitter).__name__),
                     _punch_words(punch), float(nu), base, level)
