r"""Any thickness for the regular pyramids (3 and 4 sides): the thick-layer series (T.12) and a table of direct
solutions, one law ``P/P_hs = Pi(chi)`` per (sides, nu, base) (issue 25 item 1, issue 24 item 3).

The pyramid is self-similar (:mod:`thinlayer.contact._pyramid_table_build`): with the half-space force (T.11)
``P_hs = K vartheta t delta0^2`` (``t = tan(alpha)``, alpha the face angle, K of (T.13)),

    P = P_hs Pi(chi; nu, base, sides),     chi = delta0 tan(alpha)/H     (the level set's inradius over H),

for every face angle.  The law of one (sides, nu, base):

* ``chi < CHI_NODES[0] = 0.05``: the series (T.12) of :func:`thinlayer.asymptotics.pyramid_thick.pyramid_thick_law`
  (exact through chi^5; its estimate there 2e-5, the half-space constant's uncertainty);
* ``0.05 <= chi <= CHI_MAX = 10``: a cubic spline in ``log chi`` of ``log Pi`` through the nodes
  :data:`~thinlayer.contact._pyramid_table_build.CHI_NODES`: the series' values below ``chi = 0.1``, direct solutions
  (:func:`thinlayer.numerics.solve_2d`, n = 256, the layer over the half-space on one grid) from 0.1 on; for a bonded
  nu between the table's nodes a cubic spline across the nodes in ``u = log(1 + sqrt(24 (1/2 - nu)) chi)`` (I.13),
  as the cone's table (:mod:`.any_thickness_tips`);
* beyond ``CHI_MAX`` (``H`` below a tenth of the inradius: the thin layer) and bonded ``nu < 0.3`` the law refuses.

Estimate (relative, force): the series' own (T.8) below 0.05; in the table :data:`TABLE_ERROR` (1.4e-3, 1.1e-3
bonded; 1e-4 frictionless), three times the largest error measured at the validation points stored with the table
(off the nodes in chi and nu: the interpolation; a finer grid, n = 384, at nodes: the resolution).  The resolution is
measured against n = 384 only, not a converged solution: solve_2d's own study (tests/numerics/test_pyramid_2d.py)
puts n = 256 within 4e-5 of the extrapolated force at H/a = 0.1, and the ratio to the half-space on the same grid
agrees with the series (T.12) to 5e-5 at chi = 0.135 and 0.26.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np

from .._checks import InputError

__all__ = ["CHI_MAX", "PYRAMID_TABLE_PATH", "PyramidLaw", "TABLE_ERROR", "pyramid_law", "table_errors"]

PYRAMID_TABLE_PATH = Path(__file__).resolve().parent / "data" / "any_thickness_pyramids.npz"
#: the largest chi the law answers (the table's end)
CHI_MAX = 10.0
#: lowest nu of the bonded table
NU_MIN = 0.3
#: the table's relative estimate (force) per (sides, base): 3 x the largest error measured at the validation points
#: (:func:`table_errors`, tests/afm/test_nanite_models.py), rounded up.  Measured (2026-11-26): off-node interpolation
#: bonded 8.5e-6 .. 4.5e-4 (4 sides; worst nu = 0.4855, chi = 8.7), 8.5e-6 .. 3.6e-4 (3 sides), frictionless
#: 1.2e-5 .. 1.9e-5; resolution (n = 384 against the table's n = 256 at nodes) 2.4e-5 and 9.3e-6.
TABLE_ERROR = {(4, "bonded"): 1.4e-3, (3, "bonded"): 1.1e-3, (4, "frictionless"): 1e-4, (3, "frictionless"): 1e-4}


@lru_cache(maxsize=1)
def _packaged() -> dict[str, np.ndarray]:
    if not PYRAMID_TABLE_PATH.exists():
        raise FileNotFoundError(f"the pyramids' any-thickness table {PYRAMID_TABLE_PATH} is missing: regenerate it "
                                "with python -m thinlayer.contact._pyramid_table_build")
    with np.load(PYRAMID_TABLE_PATH) as f:
        return {k: f[k] for k in f.files}


def _layer(nu: float, base: str):
    from ..layers.kernels import BondedLayer, FrictionlessLayer, IncompressibleLayer

    if base == "frictionless":
        return FrictionlessLayer(nu)
    return IncompressibleLayer() if nu == 0.5 else BondedLayer(float(nu))


def _u(nu: float, chi: np.ndarray) -> np.ndarray:
    return np.log1p(math.sqrt(max(24.0 * (0.5 - nu), 0.0)) * chi)


def _node_values(data: dict, sides: int, nu: float, base: str) -> np.ndarray:
    """``log Pi`` at the table's chi nodes for one (sides, nu, base): the stored curve, or across the nu nodes."""
    from scipy.interpolate import CubicSpline

    a = [int(s) for s in data["sides"]].index(sides)
    y = data["y"][a]
    if base == "frictionless":
        return y[0].copy()
    nus = [float(v) for v in data["nu"]]
    if nu in nus:
        return y[1 + nus.index(nu)].copy()
    chi = data["chi"]
    out = np.full(chi.size, np.nan)
    for k in range(chi.size):
        if np.isnan(y[1, k]):
            continue
        u = np.array([float(_u(v, chi[k])) for v in nus])
        order = np.argsort(u)
        out[k] = CubicSpline(u[order], y[1:, k][order])(float(_u(nu, chi[k])))
    return out


@dataclass(frozen=True, eq=False)
class PyramidLaw:
    r"""``Pi(chi) = P/P_hs`` of the regular pyramid for one (sides, nu, base), with its estimate.

    Attributes
    ----------
    sides : int
        3 or 4.
    nu, base
        Poisson ratio and ``"bonded"`` or ``"frictionless"``.
    K : float
        The half-space constant (T.13): ``P_hs = K vartheta tan(alpha) delta0^2``.
    series : tuple of float
        ``f_0 .. f_5`` of (T.12) for the layer.
    knots, coefficients : numpy.ndarray
        The cubic spline of ``log Pi`` in ``log chi`` (scipy's PPoly layout: ``coefficients[m, i]`` multiplies
        ``(x - knots[i])^(3 - m)``).
    """

    sides: int
    nu: float
    base: str
    K: float
    series: tuple
    knots: np.ndarray = field(repr=False)
    coefficients: np.ndarray = field(repr=False)
    _series_error: Any = field(repr=False, default=None)
    equation = "T.12"
    chi_max = CHI_MAX

    def _check(self, chi: np.ndarray) -> None:
        if np.any(chi > CHI_MAX) or np.any(~(chi >= 0)):
            raise InputError(f"the {self.sides}-sided pyramid's any-thickness law covers 0 <= chi = delta0 tan(alpha)/H"
                             f" <= {CHI_MAX:g}; got chi up to {float(np.nanmax(chi)):.4g} (a thinner layer: "
                             "thinlayer.solve's tip law or direct solver solve_2d)")

    def ratios(self, chi: Any) -> np.ndarray:
        """``P/P_hs`` at ``chi`` (1 at ``chi = 0``).  Vectorised: the interval from the knots' uniform step in
        ``log chi`` by one division, the cubic as a sum of powers of the offset on gathered coefficients, the series
        (T.12) on the points below the first knot only (the generated nanite module runs the same operations).
        """
        shape = np.shape(chi)
        chi = np.asarray(chi, dtype=float).reshape(-1)
        self._check(chi)
        knots, c = self.knots, self.coefficients
        x0, h = float(knots[0]), float(knots[1] - knots[0])
        x = np.log(np.maximum(chi, self.chi_low))  # below the first knot the series answers (below)
        k = ((x - x0) / h).astype(np.intp)
        np.clip(k, 0, knots.size - 2, out=k)
        x -= np.take(knots, k, mode="clip")
        s2 = x * x
        s3 = s2 * x
        v = np.take(c[2], k, mode="clip")
        v *= x
        v += np.take(c[3], k, mode="clip")
        w = np.take(c[1], k, mode="clip")
        w *= s2
        v += w
        np.take(c[0], k, mode="clip", out=w)
        w *= s3
        v += w
        np.exp(v, out=v)
        if chi.size and chi.min() < self.chi_low:
            low = np.flatnonzero(chi < self.chi_low)
            v[low] = np.polynomial.polynomial.polyval(chi[low], self.series)
        return v.reshape(shape)

    @property
    def chi_low(self) -> float:
        """The first knot's chi: the series (T.12) below it."""
        return float(np.exp(self.knots[0]))

    def error_estimate(self, chi: Any) -> np.ndarray:
        """The relative estimate of the force at ``chi`` (module docstring)."""
        chi = np.asarray(chi, dtype=float)
        self._check(chi)
        low = chi < self.chi_low
        ser = np.array([self._series_error(float(c))[0] for c in np.atleast_1d(chi)[np.atleast_1d(low)]])
        out = np.full(np.atleast_1d(chi).shape, TABLE_ERROR[(self.sides, self.base)])
        out[np.atleast_1d(low)] = ser
        return out.reshape(chi.shape)


def law_from(data: dict, sides: int, nu: float, base: str) -> PyramidLaw:
    """The law of one (sides, nu, base) from table arrays ``data`` (the packaged table or a fresh one)."""
    from scipy.interpolate import CubicSpline

    from ..asymptotics.pyramid_thick import HALF_SPACE_CONSTANTS, pyramid_thick_law
    from ..punch import Punch

    thick = pyramid_thick_law(_layer(nu, base), Punch.pyramid(45, sides))
    chi = np.asarray(data["chi"], dtype=float)
    y = _node_values(data, sides, nu, base)
    below = np.isnan(y)  # the series' values below CHI_SOLVED
    y[below] = np.log(np.polynomial.polynomial.polyval(chi[below], thick.coefficients))
    spline = CubicSpline(np.log(chi), y)
    return PyramidLaw(sides, float(nu), base, HALF_SPACE_CONSTANTS[sides]["K"][0], tuple(thick.coefficients),
                      np.asarray(spline.x), np.asarray(spline.c), thick.estimate)


@lru_cache(maxsize=64)
def _law_cached(sides: int, nu: float, base: str) -> PyramidLaw:
    return law_from(_packaged(), sides, nu, base)


def pyramid_law(sides: int, nu: float, base: str = "bonded") -> PyramidLaw:
    """The any-thickness law of the regular pyramid (cached): bonded ``0.3 <= nu <= 1/2`` or frictionless.

    Examples
    --------
    >>> law = pyramid_law(4, 0.5)
    >>> round(float(law.ratios(0.01)), 4)       # 1 + f_1 chi + ... (T.12)
    1.0084
    """
    if sides not in (3, 4) or isinstance(sides, bool):
        raise InputError(f"a regular pyramid has 3 or 4 sides, got {sides!r}")
    if base not in ("bonded", "frictionless"):
        raise InputError(f"base must be 'bonded' or 'frictionless', got {base!r}")
    nv = float(nu)
    if base == "bonded" and not NU_MIN <= nv <= 0.5:
        raise InputError(f"the pyramids' any-thickness table covers bonded layers with {NU_MIN} <= nu <= 1/2, got {nv}")
    if base == "frictionless" and not -1.0 < nv <= 0.5:
        raise InputError(f"nu must lie in (-1, 1/2], got {nv}")
    return _law_cached(int(sides), nv if base == "bonded" else 0.3, base)


def table_errors(data: dict | None = None) -> np.ndarray:
    """Rows ``(sides, kind, nu, chi, n, relative error)``: the law against the table's validation points."""
    data = _packaged() if data is None else data
    rows = []
    for sides, kind, nu, chi, n, y in data["check"]:
        law = law_from(data, int(sides), float(nu), "frictionless" if kind == 0 else "bonded")
        rows.append((sides, kind, nu, chi, n, abs(float(law.ratios(chi)) / math.exp(y) - 1)))
    return np.array(rows)
