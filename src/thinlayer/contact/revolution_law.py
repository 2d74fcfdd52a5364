r"""Any thickness for every tip of revolution (issue 24 item 3): the exact sphere, the blunted cone, the power law
and the cone, from ``c/H -> 0`` to the thin layer, by the second-kind equation (F.6) with the profile's load.

The route (:mod:`thinlayer.numerics.revolution`, (F.10)-(F.15)): Copson's representation of the pressure turns the
contact problem of a profile ``Phi(r)`` with contact radius ``c`` into the flat punch's equation (F.6) with the
right-hand side ``delta0 - h(c x)``, ``h(s) = s int_0^s Phi'(r)/sqrt(s^2 - r^2) dr`` (F.11); the edge condition
(pressure bounded at ``r = c``) gives ``delta0 = fPhi(1)/f1(1)`` (F.13) and the force ``P = 4 vartheta c (delta0
kappa - int fPhi)`` (F.14).  The kernel is smooth (``1 - L`` decays like ``u^2 e^{-2u}``), so the collocation
converges exponentially: measured against the direct spectral solver (:mod:`thinlayer.numerics.axisymmetric`), the
two agree to 1e-9 or better up to ``c/H = 40`` (tests/test_revolution_law.py).  Its estimate is the change against
0.7 times the nodes and coarser quadratures, carried to a prescribed depth (or force) through the measured slopes.

Two forms of the law:

* :func:`~thinlayer.contact.any_thickness_tips.revolution_fields` -- one depth (or force): the equation solved
  where it is asked (exact sphere and blunted cone, whose shape parameters ``R/H``, ``alpha`` do not scale out;
  any tip of revolution with a closed-form slope).  ``c_0/H <= 30`` (``c_0`` the half-space radius at the same
  depth); beyond, the thin-layer tip laws.
* :func:`power_law_law` -- the self-similar tips ``C r^n`` (the cone: ``n = 1``): ``P = P_0 Pi(chi)``, ``c = c_0
  Gamma(chi)``, ``chi = c_0/H`` (T.9) is one curve per (nu, base, n), tabulated once on :data:`GRID` and interpolated
  (cubic splines in ``log chi``; below ``CHI_SERIES`` the thick-layer series (T.9)); its estimate adds the measured
  interpolation error (the spline through every other node against the nodes left out, a quarter of it: a cubic
  spline's error falls like ``h^4``) to the solver's.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import numpy as np

from .._checks import InputError, positive
from .any_thickness_tips import CHI_SERIES, NotTabulatedError

__all__ = ["GRID", "MAX_CHI", "PowerLawLaw", "law_from_table", "power_law_law", "power_law_table",
           "self_similar_exponent"]

#: the largest ``c_0/H`` (half-space radius over thickness) the equation is solved at (0.5-2 s per depth there on a
#: loaded 2-core machine; the thin-layer tip laws beyond)
MAX_CHI = 30.0  # = thinlayer.numerics.revolution.MAX_C0_OVER_H
#: contact radii ``c/H`` of the self-similar table (geometric), continued with the same ratio until ``chi = c_0/H``
#: reaches 30 (``c/H <= 90``)
GRID = (0.04, 45.0, 41)
#: order of the thick-layer series below ``CHI_SERIES``
SERIES_ORDER = 16


def self_similar_exponent(tip: Any) -> tuple[float, float] | None:
    """``(C, n)`` when the tip's profile is ``C r^n`` with numbers C > 0, n >= 1 (read from its profile), else None."""
    import sympy as sp

    from ..parse import RADIUS

    expr = getattr(tip, "radial_expr", None)
    if expr is None or getattr(tip, "parameters", ()) or isinstance(expr, sp.Piecewise):
        return None
    C, n = sp.expand(expr).as_coeff_exponent(RADIUS)
    if C.free_symbols or n.free_symbols or sp.simplify(C * RADIUS**n - expr) != 0:
        return None
    C, n = float(C), float(n)
    return (C, n) if C > 0 and n >= 1 else None


@dataclass(frozen=True, eq=False)
class PowerLawLaw:
    r"""``P/P_0 = Pi(chi)`` and ``c/c_0 = Gamma(chi)`` of the tip ``C r^n`` for one (nu, base), ``chi = c_0/H`` (T.9).

    Attributes
    ----------
    n, nu, base
        Exponent, Poisson ratio, ``"bonded"`` or ``"frictionless"``.
    chi_max : float
        The largest chi of the table.
    k_n : float
        Sneddon's ``delta0 = C k_n c_0^n`` (T.9).
    """

    n: float
    nu: float
    base: str
    chi_max: float
    k_n: float
    splines: tuple = field(repr=False)
    series: tuple = field(repr=False)
    equation = "T.9"

    def _check(self, chi: np.ndarray) -> float:
        """Refuse chi outside ``(0, chi_max]`` (NaN included); returns the smallest chi (two passes over the data)."""
        lo, hi = (float(chi.min()), float(chi.max())) if chi.size else (1.0, 1.0)
        if not (lo > 0 and hi <= self.chi_max):
            if hi > self.chi_max:
                raise NotTabulatedError(f"the power-law tip's law covers 0 < chi = c_0/H <= {self.chi_max:.4g}; got "
                                        f"chi = {float(np.nanmax(chi)):.4g} (the thin layer: the tip law)")
            raise NotTabulatedError(f"the power-law tip's law covers 0 < chi = c_0/H <= {self.chi_max:.4g}; got chi "
                                    f"= {lo:.4g} (chi must be a positive number)")
        return lo

    @property
    def _slopes(self) -> tuple[np.ndarray, np.ndarray]:
        """``Y[k+1] - Y[k]``, ``Z[k+1] - Z[k]`` of the fine grid, computed once (the same floating-point values the
        interpolation ``Y[k] + w (Y[k+1] - Y[k])`` forms point by point).
        """
        got = self.__dict__.get("_slope_cache")
        if got is None:
            got = (np.diff(self.splines[2]), np.diff(self.splines[3]))
            object.__setattr__(self, "_slope_cache", got)
        return got

    def evaluate(self, chi: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``(P/P_0, c/c_0, force estimate, radius estimate)`` at ``chi`` in one pass: linear interpolation of the
        ratios on the fine uniform grid in ``log chi`` (its error ``h^2/8 max|y'' + y'^2|`` is in the estimate), the
        series below ``CHI_SERIES``.

        Vectorised without temporaries beyond the four outputs (issue 24 item 7: 1e6 points in <= 50 ms,
        benchmarks/bench_revolution.py): the slopes of the grid are stored once, the gathers are ``np.take`` with
        ``mode="clip"`` (the index is clipped already), arithmetic in place.  The values are bit-identical to the
        point-by-point formula ``Y[k] + w (Y[k+1] - Y[k])`` (tests/test_revolution_law.py).
        """
        shape = np.shape(chi)
        chi = np.asarray(chi, dtype=float).reshape(-1)  # 1-d (a view where it can be): in-place ops on arrays
        lo = self._check(chi)
        x0, h, Y, Z, EY, EZ = self.splines
        dY, dZ = self._slopes
        t = np.log(np.maximum(chi, CHI_SERIES) if lo < CHI_SERIES else chi)
        t -= x0
        t /= h
        k = t.astype(np.intp)
        np.minimum(k, Y.size - 2, out=k)
        t -= k  # the weight w of the upper node
        Pr = np.take(dY, k, mode="clip")
        Pr *= t
        Pr += np.take(Y, k, mode="clip")  # the ratios themselves: no exp per point
        cr = np.take(dZ, k, mode="clip")
        cr *= t
        cr += np.take(Z, k, mode="clip")
        eP, ec = np.take(EY, k, mode="clip"), np.take(EZ, k, mode="clip")
        if lo < CHI_SERIES:
            low = np.flatnonzero(chi < CHI_SERIES)  # integer indices: the assignments below touch these points only
            fc, rc, ser = self.series
            pv = np.polynomial.polynomial.polyval
            cl = chi[low]
            Pr[low], cr[low] = pv(cl, fc), pv(cl, rc)
            sP, sc = ser(cl)
            eP[low], ec[low] = sP, sc
        return Pr.reshape(shape), cr.reshape(shape), eP.reshape(shape), ec.reshape(shape)

    def ratios(self, chi: Any) -> tuple[np.ndarray, np.ndarray]:
        """``(P/P_0, c/c_0)`` at ``chi``."""
        return self.evaluate(chi)[:2]

    def error_estimate(self, chi: Any) -> tuple[np.ndarray, np.ndarray]:
        """Relative estimates ``(force, contact radius)`` at ``chi``."""
        return self.evaluate(chi)[2:]


#: intervals of the law's fine uniform grid in log chi (linear interpolation: h ~ 1.5e-3, error ~3e-7 |y''|)
FINE = 4096


def power_law_table(n: float, nu: float, base: str, grid: tuple) -> dict[str, np.ndarray]:
    """Direct solutions of (F.13) for ``r^n`` (H = 1, C = 1) at the contact radii of ``grid``: chi, log ratios, and
    the solver's estimates of them (the depth's error moves chi and both ratios).
    """
    from ..layers.kernels import BondedLayer, FrictionlessLayer, IncompressibleLayer
    from ..numerics.revolution import MAX_C_OVER_H_TIP, revolution_contact_for_radius
    from ..punch import Punch

    layer = FrictionlessLayer(nu) if base == "frictionless" else IncompressibleLayer() if nu == 0.5 else \
        BondedLayer(nu)
    tip = Punch.cone(45) if n == 1 else Punch.power_law(1, n)
    k = _k_n(n)
    rows = []
    radii = list(np.geomspace(*grid[:2], grid[2]))
    step = radii[1] / radii[0]
    while radii:
        s = radii.pop(0)
        res = revolution_contact_for_radius(layer, tip, float(s), 1.0, nu=nu if base == "frictionless" else None)
        c0 = (res.delta0 / k) ** (1.0 / n)
        P0 = 4.0 * res.vartheta * k * c0 ** (n + 1) * n / (n + 1)
        rows.append((c0, math.log(res.force / P0), math.log(s / c0), res.delta0_error, res.force_error))
        if not radii and c0 < MAX_CHI and s * step <= MAX_C_OVER_H_TIP and grid is GRID:
            radii.append(s * step)  # on to chi = 30 (c/c_0 grows with n and near nu = 1/2)
    a = np.array(rows)
    return {"chi": a[:, 0], "y": a[:, 1], "z": a[:, 2], "ed": a[:, 3], "eP": a[:, 4]}


def _k_n(n: float) -> float:
    """Sneddon's ``k_n`` (T.9), derived by :func:`~thinlayer.asymptotics.thick_layer.power_law_half_space`."""
    import sympy as sp

    from ..asymptotics.thick_layer import power_law_half_space

    nn = sp.Rational(n).limit_denominator(10**6) if n != int(n) else int(n)
    return float(power_law_half_space(nn))


def law_from_table(data: dict, n: float, nu: float, base: str) -> PowerLawLaw:
    """The law of one (n, nu, base) from the table's arrays, with its measured estimate."""
    import sympy as sp
    from scipy.interpolate import CubicSpline

    from ..asymptotics.thick_layer import thick_power_law_series
    from ..layers.kernels import BondedLayer, FrictionlessLayer, IncompressibleLayer

    x, y, z = np.log(data["chi"]), data["y"], data["z"]
    if x[0] > math.log(CHI_SERIES):
        raise InputError(f"the table must start below chi = {CHI_SERIES} (the series' end), at chi = "
                         f"{math.exp(x[0]):.3g}")
    Sy, Sz = CubicSpline(x, y), CubicSpline(x, z)
    # interpolation: the spline through every other node, at the nodes left out; a cubic spline's error falls like
    # h^4: the full spline's error is ~1/16 of it (a quarter taken), the largest of the two neighbouring intervals
    m_odd = (x.size - 1) // 2  # the nodes 2j + 1 that lie between two nodes of the coarse spline (no extrapolation)
    even = slice(0, 2 * m_odd + 1, 2)
    hy, hz = CubicSpline(x[even], y[even]), CubicSpline(x[even], z[even])
    odd = slice(1, 2 * m_odd, 2)
    iy, iz = np.abs(hy(x[odd]) - y[odd]) / 4, np.abs(hz(x[odd]) - z[odd]) / 4
    iy_n, iz_n = np.zeros_like(x), np.zeros_like(x)
    for j, (a, b) in enumerate(zip(iy, iz)):  # node 2j+1 is inside [x_2j, x_2j+2]
        for m in (2 * j, 2 * j + 1, 2 * j + 2):
            iy_n[m], iz_n[m] = max(iy_n[m], a), max(iz_n[m], b)
    iy_n[-1], iz_n[-1] = max(iy_n[-1], iy_n[-2]), max(iz_n[-1], iz_n[-2])
    # the solver's errors: the depth's relative error e_d moves chi by e_d/n, P_0 by (n + 1)/n e_d and c_0 by e_d/n
    sy, sz = np.abs(Sy(x, 1)), np.abs(Sz(x, 1))
    pty = data["eP"] + (n + 1) / n * data["ed"] + sy * data["ed"] / n
    ptz = data["ed"] / n + sz * data["ed"] / n
    ey = np.maximum.reduce([pty, np.roll(pty, 1), np.roll(pty, -1)]) + iy_n
    ez = np.maximum.reduce([ptz, np.roll(ptz, 1), np.roll(ptz, -1)]) + iz_n
    # a relative error e of P is |exp(e_log) - 1| <= 1.01 e_log for e_log < 0.01
    ey, ez = 1.01 * ey, 1.01 * ez
    # the fine uniform grid of the evaluation: values of the splines, the estimate of each fine cell the larger of the
    # two table nodes around it, plus the linear interpolation's h^2/8 max|y''| (y'' of the spline over the cell)
    xf = np.linspace(max(math.log(CHI_SERIES), x[0]), x[-1], FINE + 1)
    h = xf[1] - xf[0]
    node = np.clip(np.searchsorted(x, xf, side="right") - 1, 0, x.size - 2)
    ey_f, ez_f = np.maximum(ey[node], ey[node + 1]), np.maximum(ez[node], ez[node + 1])
    # the ratios e^y are interpolated linearly: relative error h^2/8 |y'' + y'^2|
    d2y, d2z = np.abs(Sy(xf, 2)) + Sy(xf, 1) ** 2, np.abs(Sz(xf, 2)) + Sz(xf, 1) ** 2
    lin_y = h * h / 8 * np.maximum(d2y, np.roll(d2y, -1))
    lin_z = h * h / 8 * np.maximum(d2z, np.roll(d2z, -1))
    ey_f, ez_f = np.maximum(ey_f, np.roll(ey_f, -1)) + lin_y, np.maximum(ez_f, np.roll(ez_f, -1)) + lin_z
    layer = FrictionlessLayer(nu) if base == "frictionless" else IncompressibleLayer() if nu == 0.5 else \
        BondedLayer(nu)
    ser = thick_power_law_series(sp.Rational(n).limit_denominator(10**6), SERIES_ORDER)
    fc, rc = ser.coefficients(layer)
    fine = (xf[0], h, np.exp(Sy(xf)), np.exp(Sz(xf)), ey_f, ez_f)
    return PowerLawLaw(n, nu, base, float(data["chi"][-1]), _k_n(n), fine,
                       (fc, rc, lambda c: ser.error_estimate(c, layer)))


@lru_cache(maxsize=16)
def _law_cached(n: float, nu: float, base: str) -> PowerLawLaw:
    if CHI_SERIES < GRID[0] * 0.5:
        raise InputError("the table must start below the series' end")
    return law_from_table(power_law_table(n, nu, base, GRID), n, nu, base)


def power_law_law(n: float, nu: float, base: str = "bonded") -> PowerLawLaw:
    """The any-thickness law of the tip ``C r^n`` (the cone: n = 1) for one (nu, base), built on first use (about 40
    solves of (F.13), a few seconds) and cached: bonded ``0.3 <= nu <= 1/2`` or frictionless, ``1 <= n <= 8``.

    Examples
    --------
    >>> law = power_law_law(1.5, 0.5)                         # doctest: +SKIP
    >>> law.ratios([0.01, 1.0])[0]                            # doctest: +SKIP
    """
    if base not in ("bonded", "frictionless"):
        raise InputError(f"base must be 'bonded' or 'frictionless', got {base!r}")
    nv, nn = float(nu), positive(n, "n")
    if base == "bonded" and not 0.3 <= nv <= 0.5:
        raise InputError(f"the power-law tip's law covers bonded layers with 0.3 <= nu <= 1/2, got {nv}")
    if not 1.0 <= nn <= 8.0:
        raise InputError(f"the power-law tip's law covers exponents 1 <= n <= 8, got {nn}")
    return _law_cached(nn, nv if base == "bonded" else 0.3, base)
