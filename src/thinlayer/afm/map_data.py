"""Force-map data: curves on a grid read through afmformats, and synthetic maps written in afmformats' HDF5 format.

* :func:`read_map` reads a map file (a JPK ``.jpk-force-map``, afmformats' own HDF5 export of a map, any file
  afmformats reads whose curves carry the grid's metadata) or a folder of curve files, and returns light, picklable
  :class:`MapCurve` records (approach segment only: tip position and force) and the :class:`MapGrid`.
  Instrument formats are read by afmformats only, never parsed here.  The tip position is nanite's
  (``compute_tip_position``, JPK's "Vertical Tip Position"): ``height (measured) + force/k`` (negative into the
  sample), taken from the ``"tip position"`` column when the file has one.
* :func:`write_synthetic_map` writes a map whose curves follow the any-thickness law (T.7) for given E and H maps,
  in afmformats' HDF5 format (afmformats and nanite read it back as a map): the test and benchmark data.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError

__all__ = ["MAX_CURVES", "MapCurve", "MapGrid", "read_map", "write_synthetic_map"]

#: the most curves a map may hold (checked before fitting: 256 x 256 pixels)
MAX_CURVES = 65536


@dataclass(frozen=True, eq=False)
class MapCurve:
    """One pixel's force curve (approach segment), small enough to send to a dask worker.

    Attributes
    ----------
    index : tuple of int
        ``(row, column)`` = ``(grid index y, grid index x)``.
    tip_position : numpy.ndarray
        Tip position (m), negative into the sample, in time order.
    force : numpy.ndarray
        Force (N).
    name : str
        The file and the curve's number in it.
    spring_constant : float
        Cantilever spring constant (N/m; NaN if not recorded).
    """

    index: tuple
    tip_position: np.ndarray
    force: np.ndarray
    name: str = ""
    spring_constant: float = math.nan
    position: tuple = (math.nan, math.nan)

    def approach(self) -> tuple[np.ndarray, np.ndarray]:
        """``(tip position, force)`` of the approach."""
        return self.tip_position, self.force


@dataclass(frozen=True)
class MapGrid:
    """A map's grid: ``shape = (ny, nx)``, pixel-centre coordinates ``x``, ``y`` (µm) and the ``extent_um``
    ``(x0, x1, y0, y1)`` of the image (``None`` and pixel numbers when the data carry no positions).
    """

    shape: tuple
    x: np.ndarray
    y: np.ndarray
    extent_um: tuple | None = None

    @classmethod
    def from_metadata(cls, meta: dict[str, Any]) -> MapGrid:
        """The grid of an afmformats map (``grid shape``, ``grid size``, ``grid center``: metres)."""
        nx, ny = int(meta["grid shape x"]), int(meta["grid shape y"])
        sx, sy = float(meta["grid size x"]) * 1e6, float(meta["grid size y"]) * 1e6
        cx, cy = float(meta["grid center x"]) * 1e6, float(meta["grid center y"]) * 1e6
        ext = (cx - sx / 2, cx + sx / 2, cy - sy / 2, cy + sy / 2)
        x = ext[0] + (np.arange(nx) + 0.5) * sx / nx  # pixel centres, as afmformats' AFMQMap
        y = ext[2] + (np.arange(ny) + 0.5) * sy / ny
        return cls((ny, nx), x, y, ext)

    @classmethod
    def from_curves(cls, curves: list[MapCurve]) -> MapGrid:
        """The smallest grid holding the curves' indices (no positions: axes in pixels)."""
        if not curves:
            raise InputError("the map has no curve")
        ny = 1 + max(c.index[0] for c in curves)
        nx = 1 + max(c.index[1] for c in curves)
        return cls((ny, nx), np.arange(nx, dtype=float), np.arange(ny, dtype=float), None)


def _tip_position(data: Any, meta: dict[str, Any]) -> tuple[np.ndarray, np.ndarray, float]:
    force = np.asarray(data["force"], dtype=float)
    k = float(meta.get("spring constant", math.nan))
    columns = data.columns
    if "tip position" in columns:
        z = np.asarray(data["tip position"], dtype=float)
    else:
        col = "height (measured)" if "height (measured)" in columns else "height (piezo)"
        if not math.isfinite(k) or k <= 0:
            raise InputError(f"{_name(meta)}: no spring constant recorded: the tip position (height + force/k) "
                             "cannot be computed")
        z = np.asarray(data[col], dtype=float) + force / k
    seg = np.asarray(data["segment"]) if "segment" in columns else np.zeros(force.size, dtype=int)
    appr = seg == 0
    return z[appr], force[appr], k


def _name(meta: dict[str, Any]) -> str:
    return f"{Path(str(meta.get('path', ''))).name}[{meta.get('enum', '?')}]"


def _load(path: Path) -> list[Any]:
    try:
        import afmformats
    except ImportError:  # pragma: no cover - the extra thinlayer[afm]
        raise InputError("reading force maps needs afmformats: pip install 'thinlayer[afm]'") from None
    try:
        return list(afmformats.load_data(path, modality="force-distance"))
    except (ValueError, KeyError, OSError, NotImplementedError) as exc:
        first = str(exc).splitlines()[0][:160] if str(exc) else type(exc).__name__
        raise InputError(f"{path.name}: afmformats cannot read it as force-distance data ({first})") from None


def _grid_index(meta: dict[str, Any]) -> tuple[int, int] | None:
    if "grid index x" in meta and "grid index y" in meta:
        return int(meta["grid index y"]), int(meta["grid index x"])
    return None


def read_map(source: str | Path) -> tuple[list[MapCurve], MapGrid]:
    """The curves of a map file or a folder of curve files, and the grid.

    A file: its curves must carry afmformats' grid metadata (``grid index x/y``, ``grid shape x/y``); a folder: every
    file in it that afmformats reads (by suffix, sorted by name), placed by its grid metadata, else by its ``position
    x/y`` (the sorted distinct positions make the grid), else refused.

    Raises
    ------
    InputError
        One line naming the file and what is missing.
    """
    p = Path(source)
    if p.is_dir():
        import afmformats

        suffixes = tuple(afmformats.supported_extensions)
        files = sorted(f for f in p.iterdir() if f.is_file() and f.name.endswith(suffixes))
        if not files:
            raise InputError(f"{p}: no curve file afmformats reads ({', '.join(sorted(set(suffixes)))})")
        data = [d for f in files for d in _load(f)]
    elif p.is_file():
        data = _load(p)
    else:
        raise InputError(f"{str(source)[:200]}: no such file or folder")
    if not data:
        raise InputError(f"{p.name}: no force-distance curve in it")
    if len(data) > MAX_CURVES:
        raise InputError(f"{p.name}: {len(data)} curves, more than {MAX_CURVES}: split the map")
    metas = [d.metadata for d in data]  # afmformats copies the metadata on each access: once per curve
    meta0 = metas[0]
    indices = [_grid_index(m) for m in metas]
    if all(i is not None for i in indices) and all(k in meta0 for k in ("grid shape x", "grid size x",
                                                                          "grid center x")):
        grid = MapGrid.from_metadata(meta0)
    elif p.is_dir() and all("position x" in m and "position y" in m for m in metas):
        xs = sorted({float(m["position x"]) for m in metas})
        ys = sorted({float(m["position y"]) for m in metas})
        indices = [(ys.index(float(m["position y"])), xs.index(float(m["position x"]))) for m in metas]
        grid = _grid_from_positions(np.array(xs) * 1e6, np.array(ys) * 1e6)
    else:
        raise InputError(f"{p.name}: the curves carry no grid (afmformats' 'grid index x/y') nor positions: not a "
                         "map; fit single curves with 'thinlayer fit'")
    curves = []
    for d, m, idx in zip(data, metas, indices):
        if not (0 <= idx[0] < grid.shape[0] and 0 <= idx[1] < grid.shape[1]):
            raise InputError(f"{_name(m)}: grid index {idx} outside the map's shape {grid.shape}")
        z, f, k = _tip_position(d, m)
        pos = (float(m.get("position x", math.nan)), float(m.get("position y", math.nan)))
        curves.append(MapCurve(idx, z, f, _name(m), k, pos))
    return curves, grid


def _grid_from_positions(xs: np.ndarray, ys: np.ndarray) -> MapGrid:
    def edges(v: np.ndarray) -> tuple[float, float]:
        step = float(np.median(np.diff(v))) if v.size > 1 else 1.0
        return float(v[0] - step / 2), float(v[-1] + step / 2)

    x0, x1 = edges(xs)
    y0, y1 = edges(ys)
    return MapGrid((ys.size, xs.size), xs, ys, (x0, x1, y0, y1))


def synthetic_curve(E: float, H: float, *, R: float, nu: float = 0.5, base: str = "bonded", points: int = 2000,
                    depth: float = 0.5e-6, contact: float = 0.0, noise: float = 0.0, slope: float = 0.0,
                    offset: float = 0.0, rng: np.random.Generator | None = None) -> tuple[np.ndarray, np.ndarray]:
    """``(tip position, force)`` of an approach: ``points`` evenly spaced tip positions from ``contact + depth``
    down to ``contact - depth`` (half off contact, half in), the force of the any-thickness law (T.7) (Hertz for
    ``H = inf``; no force for ``E = 0``) plus a baseline ``offset + slope * tip`` and Gaussian noise of standard
    deviation ``noise`` (N).
    """
    from ..contact.any_thickness import force_any_thickness

    z = np.linspace(contact + depth, contact - depth, points)
    d = contact - z
    dd = np.where(d > 0, d, 0.0)
    if E == 0:  # nothing to indent (a hole down to a soft nothing): the baseline and noise only
        P = np.zeros_like(z)
    elif math.isinf(H):
        P = 4.0 / 3.0 * E / (1 - nu * nu) * math.sqrt(R) * dd ** 1.5
    else:
        P = np.where(d > 0, force_any_thickness(np.where(d > 0, d, 1.0), R=R, H=H, E=E, nu=nu, base=base), 0.0)
    f = P + offset + slope * z
    if noise:
        f = f + (rng if rng is not None else np.random.default_rng(0)).normal(0.0, noise, points)
    return z, f


def write_synthetic_map(path: str | Path, E: Any, H: Any, *, R: float, nu: float = 0.5, base: str = "bonded",
                        points: int = 2000, depth: float = 0.5e-6, contact: Any = 0.0, noise: float = 0.0,
                        pixel: float = 1e-6, spring_constant: float = 0.05, seed: int = 0,
                        overwrite: bool = False) -> Path:
    """Write a force map in afmformats' HDF5 format: one approach curve per pixel of ``E`` (Pa) and ``H`` (m) maps.

    ``contact`` (m, scalar or map) is each pixel's contact height; ``pixel`` the grid step (m).  The columns are
    ``height (measured)`` (= tip position - force/k), ``force``, ``segment`` (0, the approach) and ``time``; the
    metadata carry the grid (``grid index``, ``grid shape``, ``grid size``, ``grid center``, ``position``) as
    afmformats' map readers do, so ``afmformats.AFMQMap`` and nanite read it as a map.
    """
    import afmformats
    import h5py

    from ..validation.output import refuse_existing

    path = Path(path)
    refuse_existing([path], overwrite, "pass overwrite=True to replace it")
    E = np.atleast_2d(np.asarray(E, dtype=float))
    H = np.broadcast_to(np.asarray(H, dtype=float), E.shape)
    C = np.broadcast_to(np.asarray(contact, dtype=float), E.shape)
    ny, nx = E.shape
    rng = np.random.default_rng(seed)
    tmp = path.with_name(path.name + ".part")
    with h5py.File(tmp, "w") as h5:
        for i in range(ny):
            for j in range(nx):
                z, f = synthetic_curve(float(E[i, j]), float(H[i, j]), R=R, nu=nu, base=base, points=points,
                                       depth=depth, contact=float(C[i, j]), noise=noise, rng=rng)
                meta = {"path": path, "enum": i * nx + j, "spring constant": spring_constant,
                        "grid index x": j, "grid index y": i, "grid shape x": nx, "grid shape y": ny,
                        "grid size x": nx * pixel, "grid size y": ny * pixel, "grid center x": nx * pixel / 2,
                        "grid center y": ny * pixel / 2, "position x": (j + 0.5) * pixel,
                        "position y": (i + 0.5) * pixel, "imaging mode": "force-distance",
                        "software": "thinlayer synthetic map", "point count": points, "segment count": 1,
                        "duration": 1.0, "sensitivity": 1e-8, "date": "2026-11-26", "time": "00:00:00",
                        "speed approach": 2 * depth, "rate approach": float(points)}
                data = {"force": f, "height (measured)": z - f / spring_constant,
                        "segment": np.zeros(points, dtype=np.uint8), "time": np.linspace(0.0, 1.0, points)}
                afmformats.AFMForceDistance(data, meta).export_data(h5, fmt="hdf5")
    tmp.replace(path)
    return path
