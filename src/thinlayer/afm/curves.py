r"""Measured force curves: instrument files read through afmformats, or arrays (issue 25 item 3).

:func:`load_curve` reads one segment (``"approach"`` or ``"retract"``) of one curve of an instrument file through
afmformats (imported on first use: the extra ``thinlayer[afm]``) and returns an immutable :class:`Curve`:

* ``z`` is the **tip position** [m], negative into the sample (afmformats' and nanite's axis): the afmformats
  column ``"tip position"`` when the file has one, else ``height (measured) + force / spring constant`` (nanite's
  ``compute_tip_position``, JPK's "Vertical Tip Position", unsmoothed);
* ``force`` [N] as the file records it (afmformats converts to SI units: metres, newtons);
* the indentation is ``delta = z0 - z`` after the contact point ``z0`` (``direction = -1``).

:func:`curve_from_arrays` makes a :class:`Curve` of two arrays (a CSV's columns, read by the CLI's reader
:func:`thinlayer.export.fit_cli.read_curve`): a depth axis, positive into the sample (``direction = +1``:
``delta = z - z0``), or a tip position (``direction = -1``), in the caller's units.

The fit of such a curve, with the contact point and a baseline as parameters, is
:func:`thinlayer.afm.curve_fit.fit_curve`.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .._checks import InputError, InputTypeError, check_array_size, check_choice
from ..display import RichDisplay
from ..errors import boundary, boundary_methods

__all__ = ["Curve", "SEGMENTS", "curve_from_arrays", "load_curve", "supported_suffixes"]

#: the segments of a force-distance curve, in afmformats' numbering (0: approach, 1: retract)
SEGMENTS = ("approach", "retract")
#: more points than this are refused (:data:`thinlayer.contact.fit.MAX_POINTS`, the fit's own limit)
MAX_POINTS = 1_000_000
#: the largest instrument file read (bytes), checked before afmformats opens it (a force map is read curve by
#: curve by thinlayer.afm.maps, not here)
MAX_BYTES = 2 * 2**30


@boundary_methods
@dataclass(frozen=True, eq=False)
class Curve(RichDisplay):
    """One segment of a measured force curve.

    Attributes
    ----------
    z : numpy.ndarray
        The position axis (``axis``): the tip position [m] for an instrument file.
    force : numpy.ndarray
        The force [N] for an instrument file.
    axis : str
        ``"tip position"`` (negative into the sample) or ``"depth"`` (positive into the sample).
    direction : int
        ``-1``: the indentation is ``delta = z0 - z`` (a tip position); ``+1``: ``delta = z - z0`` (a depth).
    units : tuple of str
        Units of ``z`` and ``force`` (``("m", "N")`` from a file; ``("", "")``: the caller's units).
    segment : str
        ``"approach"`` or ``"retract"`` (``""`` for arrays).
    source : str
        The file (and ``index`` its curve) or ``"arrays"``.
    index : int
    spring_constant, sensitivity : float
        Cantilever spring constant [N/m] and deflection sensitivity [m/V] from the file (NaN if not recorded).
    metadata : tuple of (str, str)
        afmformats' metadata, as text.
    """

    z: np.ndarray = field(repr=False)
    force: np.ndarray = field(repr=False)
    axis: str = "tip position"
    direction: int = -1
    units: tuple = ("m", "N")
    segment: str = "approach"
    source: str = "arrays"
    index: int = 0
    spring_constant: float = math.nan
    sensitivity: float = math.nan
    metadata: tuple = field(default=(), repr=False)

    @property
    def n_points(self) -> int:
        return int(self.z.size)

    def text_lines(self) -> list[str]:
        zu, fu = (f" [{u}]" if u else "" for u in self.units)
        lines = [f"Curve: {self.source}" + (f" #{self.index}, {self.segment}" if self.segment else "")
                 + f", {self.n_points} points",
                 f"  {self.axis}{zu} from {float(self.z.min()):.6g} to {float(self.z.max()):.6g} "
                 f"({'negative' if self.direction < 0 else 'positive'} into the sample)",
                 f"  force{fu} from {float(self.force.min()):.6g} to {float(self.force.max()):.6g}"]
        if math.isfinite(self.spring_constant):
            lines.append(f"  spring constant = {self.spring_constant:.6g} N/m")
        if math.isfinite(self.sensitivity):
            lines.append(f"  sensitivity = {self.sensitivity:.6g} m/V")
        return lines

    def latex(self) -> str:
        return rf"\text{{{self.n_points} points, {self.axis}}}"


def supported_suffixes() -> tuple[str, ...]:
    """The file suffixes afmformats reads (``.jpk-force``, ``.jpk-force-map``, ``.ibw``, ``.h5``, ...)."""
    import afmformats

    return tuple(afmformats.formats.supported_extensions)


@boundary
def load_curve(path: str | Path, segment: str = "approach", index: int = 0) -> Curve:
    """Read one segment of one force curve of an instrument file through afmformats.

    Parameters
    ----------
    path : str or Path
        A file afmformats reads (:func:`supported_suffixes`: JPK ``.jpk-force``, ``.jpk-force-map``,
        ``.jpk-qi-data``, ``.jpk-qi-series``, Igor ``.ibw``, NT-MDT ``.txt``, HDF5 ``.h5``, ``.tab``, ...).
    segment : str
        ``"approach"`` (default) or ``"retract"``.
    index : int
        The curve in the file (a map holds many; default the first).

    Returns
    -------
    Curve
        Tip position [m] (negative into the sample) and force [N], with the file's spring constant and sensitivity.

    Raises
    ------
    ValueError
        One line: no such file, a segment or index the file does not have, a file afmformats cannot read (with the
        formats it reads), or no tip position (neither the column nor height, force and spring constant).
    """
    if not isinstance(path, (str, Path)):
        raise InputTypeError(f"load_curve(): path must be a file name (str or Path), got {type(path).__name__}")
    check_choice(segment, SEGMENTS, "segment")
    if isinstance(index, bool) or not isinstance(index, (int, np.integer)) or index < 0:
        raise InputError(f"load_curve(): index must be a curve number >= 0, got {index!r}")
    p = Path(path)
    if not p.is_file():
        raise InputError(f"{path}: no such file")
    suffixes = supported_suffixes()
    if p.suffix.lower() not in suffixes:
        raise InputError(f"{path}: afmformats reads no {p.suffix or 'suffix-less'} file; it reads "
                         f"{', '.join(suffixes)} (a CSV of depth and force: thinlayer fit FILE.csv)")
    size = p.stat().st_size
    if size > MAX_BYTES:
        raise InputError(f"{path}: {size} bytes exceed the limit of {MAX_BYTES} bytes")
    import afmformats
    import afmformats.errors

    try:
        with warnings.catch_warnings():  # afmformats warns about metadata it does not know; the data are read
            warnings.simplefilter("ignore")
            group = afmformats.load_data(p)
    except (Exception, afmformats.errors.AFMFileFormatError, afmformats.errors.MissingMetaDataError) as exc:  # noqa: BLE001
        # any failure of the reader is the file's (afmformats' own errors derive from BaseException): one line
        text = " ".join(str(exc).split())[:160]
        raise InputError(f"{path}: afmformats cannot read it ({type(exc).__name__}: {text}); it reads "
                         f"{', '.join(suffixes)}") from None
    if index >= len(group):
        raise InputError(f"{path}: index {index} is beyond the file's {len(group)} curve(s) (0 to {len(group) - 1})")
    data = group[index]
    columns = list(data.columns)
    meta = dict(data.metadata)
    seg_id = SEGMENTS.index(segment)
    if "segment" in columns:
        mask = np.asarray(data["segment"]) == seg_id
        if not mask.any():
            raise InputError(f"{path}: curve {index} has no {segment} segment")
    elif segment == "approach":
        mask = np.ones(len(data["force"]), dtype=bool)
    else:
        raise InputError(f"{path}: curve {index} has no segments; only its approach can be read")
    force = np.asarray(data["force"], dtype=float)
    k = float(meta.get("spring constant", math.nan))
    if "tip position" in columns:
        z = np.asarray(data["tip position"], dtype=float)
    elif "height (measured)" in columns and math.isfinite(k) and k > 0:
        z = np.asarray(data["height (measured)"], dtype=float) + force / k
    else:
        raise InputError(f"{path}: no tip position: the file has neither a 'tip position' column nor 'height "
                         f"(measured)' with a spring constant (columns: {', '.join(columns)})")
    z, force = z[mask], force[mask]
    check_array_size(z, "the curve", MAX_POINTS, "subsample the curve")
    good = np.isfinite(z) & np.isfinite(force)
    if good.sum() < 3:
        raise InputError(f"{path}: curve {index}, {segment}: fewer than 3 finite points")
    sens = float(meta.get("sensitivity", math.nan))
    text_meta = tuple((str(key), str(v)[:200]) for key, v in meta.items())
    return Curve(_frozen(z[good]), _frozen(force[good]), "tip position", -1, ("m", "N"), segment, str(path),
                 int(index), k, sens, text_meta)


@boundary
def curve_from_arrays(z: Any, force: Any, axis: str = "depth", units: tuple = ("", ""),
                      source: str = "arrays") -> Curve:
    """A :class:`Curve` of two arrays: ``axis="depth"`` (positive into the sample, ``delta = z - z0``) or
    ``"tip position"`` (negative into the sample, ``delta = z0 - z``).
    """
    check_choice(axis, ("depth", "tip position"), "axis")
    for name, v in (("z", z), ("force", force)):
        check_array_size(v, name, MAX_POINTS, "subsample the curve")
    try:
        zz = np.asarray(z, dtype=float).ravel()
        ff = np.asarray(force, dtype=float).ravel()
    except (TypeError, ValueError, OverflowError):
        raise InputError("z and force must be sequences of numbers") from None
    if zz.size != ff.size:
        raise InputError(f"z and force must have the same length, got {zz.size} and {ff.size}")
    if zz.size < 3:
        raise InputError(f"a curve needs at least 3 points, got {zz.size}")
    if not (np.all(np.isfinite(zz)) and np.all(np.isfinite(ff))):
        raise InputError("z and force must be finite (no nan or inf); drop the bad rows first")
    if not (isinstance(units, tuple) and len(units) == 2 and all(isinstance(u, str) for u in units)):
        raise InputTypeError(f"units must be two strings (of z and force), got {units!r:.60}")
    return Curve(_frozen(zz), _frozen(ff), axis, -1 if axis == "tip position" else 1, units, "", str(source)[:200])


def _frozen(a: np.ndarray) -> np.ndarray:
    out = np.array(a, dtype=float)
    out.setflags(write=False)
    return out
