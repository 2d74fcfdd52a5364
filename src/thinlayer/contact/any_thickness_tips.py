r"""Any thickness for the tips of revolution: the cone by its table from ``a/H -> 0`` to the thin layer, every tip of
revolution (exact sphere, blunted cone, power law, cone) by the equation (F.6) with its load (F.10)-(F.15).

The cone (and every power law ``C r^n`` at fixed n) is self-similar: with ``c_0``, ``P_0`` the half-space (Sneddon)
radius and force at the same depth (T.9; for the cone ``c_0 = (2/pi) delta0 tan(alpha)``, ``P_0 = (4/pi) vartheta
tan(alpha) delta0^2``),

    P = P_0 Pi(chi; nu),     c = c_0 Gamma(chi; nu),     chi = c_0/H,

for every angle (``C`` scales out).  The law of one (nu, base):

* ``chi <= CHI_SERIES``: the thick-layer series :func:`~thinlayer.asymptotics.thick_layer.thick_power_law_series`
  through chi^16, its estimate (T.8);
* ``CHI_SERIES < chi <= chi_max`` (about 29): a table of direct solutions (``data/any_thickness_tips.npz``, built by
  :mod:`thinlayer.contact._tips_table_build`), cubic splines of ``log(P/P_0)`` and ``log(c/c_0)`` in ``log chi``
  per curve; for the bonded layer, nu between the nodes in ``[0.3, 1/2]`` by a cubic spline across the curves in
  ``u = log(1 + sqrt(24 (1/2 - nu)) chi)`` (the incompressible/compressible crossover variable of (I.13), in which
  the curves are smooth at every chi).  The estimate is measured: the law against direct solutions off the nodes
  (stored with the table), 5 x the largest error near (chi, nu) (:func:`_measured`), at least 2e-6.  Measured
  worst: 9e-5 at nu = 0.4994, chi = 19.5 and 3e-5 at nu = 0.49999, chi = 13 (so the estimate exceeds 1e-4 there:
  near incompressibility beyond chi ~ 5); elsewhere below 1.5e-5.
* beyond ``chi_max`` (the thin layer), and for bonded nu < 0.3, the table does not answer.

Every tip of revolution with a closed-form slope (the exact sphere, the blunted cone, the power laws, and the cone
where its table does not answer or its estimate exceeds ``tol``): the thick-layer series (T.9) where its estimate is
below :data:`SERIES_TRUSTED`, else the second-kind equation (F.6) with the tip's load solved at the depth
(:func:`revolution_fields`, :mod:`thinlayer.numerics.revolution`, (F.10)-(F.15); ``c_0/H <= 30``, estimates
~1e-12 measured against the direct solver).  Beyond, ``solve(model="auto")`` goes on to the direct solver (the
thin-layer tip law, tried before, answers where its own estimate is within tol).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np

from .._checks import InputError, positive

__all__ = ["CHI_SERIES", "TIPS_TABLE_PATH", "ConeLaw", "NotTabulatedError", "cone_law", "cone_law_from", "cone_tangent",
           "numeric_tip", "revolution_fields", "tip_fields"]

TIPS_TABLE_PATH = Path(__file__).resolve().parent / "data" / "any_thickness_tips.npz"
#: below this chi the thick-layer series (its estimate < 1e-15 there)
CHI_SERIES = 0.06
#: order of the thick-layer series
SERIES_ORDER = 16
#: lowest nu of the bonded table
NU_MIN = 0.3
#: points of the law's fine grid in log chi
FINE = 600


class NotTabulatedError(InputError):
    """The any-thickness law does not cover this punch here (the message says why and what would)."""


@lru_cache(maxsize=1)
def _packaged() -> dict[str, np.ndarray]:
    if not TIPS_TABLE_PATH.exists():
        raise FileNotFoundError(f"the tips' any-thickness table {TIPS_TABLE_PATH} is missing: regenerate it with "
                                "python -m thinlayer.contact._tips_table_build")
    with np.load(TIPS_TABLE_PATH) as f:
        return {k: f[k] for k in f.files}


def _u(nu: float, chi: np.ndarray) -> np.ndarray:
    return np.log1p(math.sqrt(max(24.0 * (0.5 - nu), 0.0)) * chi)


def _curves_at(data: dict, rows: list[int], x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``y, z`` of the table's curves ``rows`` at ``x = log chi`` (cubic splines in log chi)."""
    from scipy.interpolate import CubicSpline

    ys, zs = [], []
    for i in rows:
        lx = np.log(data["chi"][i])
        ys.append(CubicSpline(lx, data["y"][i])(x))
        zs.append(CubicSpline(lx, data["z"][i])(x))
    return np.array(ys), np.array(zs)


def _raw(data: dict, nu: float, base: str, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The table's ``(y, z)`` at ``x = log chi`` for one (nu, base), before the series and the estimate."""
    from scipy.interpolate import CubicSpline

    if base == "frictionless":
        y, z = _curves_at(data, [0], x)
        return y[0], z[0]
    nus = [float(v) for v in data["nu"]]
    if nu in nus:
        y, z = _curves_at(data, [1 + nus.index(nu)], x)
        return y[0], z[0]
    Y, Z = _curves_at(data, list(range(1, 1 + len(nus))), x)
    chi = np.exp(x)
    out_y, out_z = np.empty_like(x), np.empty_like(x)
    for k in range(x.size):
        u = np.array([float(_u(v, chi[k])) for v in nus])
        uq = float(_u(nu, chi[k]))
        out_y[k] = CubicSpline(u, Y[:, k])(uq)
        out_z[k] = CubicSpline(u, Z[:, k])(uq)
    return out_y, out_z


@dataclass(frozen=True, eq=False)
class ConeLaw:
    r"""``P/P_0`` and ``c/c_0`` of the cone as functions of ``chi = c_0/H`` for one (nu, base), with the estimate.

    Attributes
    ----------
    nu, base
        Poisson ratio and ``"bonded"`` or ``"frictionless"``.
    chi_max : float
        The largest chi the law answers (the table's end; the thin layer beyond).
    """

    nu: float
    base: str
    chi_max: float
    splines: tuple = field(repr=False)  # log(P/P_0), log(c/c_0) and the two estimates, in log chi
    series: tuple = field(repr=False)
    equation = "T.9"

    def _check(self, chi: np.ndarray) -> float:
        """Refuse chi outside ``(0, chi_max]`` (NaN included); returns the smallest chi (two passes)."""
        lo, hi = (float(chi.min()), float(chi.max())) if chi.size else (1.0, 1.0)
        if not (lo > 0 and hi <= self.chi_max):
            if hi > self.chi_max:
                raise InputError(f"the cone's any-thickness law covers 0 < chi = c_0/H <= {self.chi_max:.4g}; got "
                                 f"chi up to {float(np.nanmax(chi)):.4g} (the thin layer: the tip law or the direct "
                                 "solver)")
            raise InputError(f"the cone's any-thickness law covers 0 < chi = c_0/H <= {self.chi_max:.4g}; got chi = "
                             f"{lo:.4g} (chi must be a positive number)")
        return lo

    def _pieces(self) -> tuple:
        """``(x0, h, knots, coefficients)`` of the four splines, on their common uniform knots (computed once)."""
        got = self.__dict__.get("_piece_cache")
        if got is None:
            knots = np.asarray(self.splines[0].x)
            got = (float(knots[0]), float(knots[1] - knots[0]), knots,
                   [np.ascontiguousarray(sp_.c) for sp_ in self.splines])
            object.__setattr__(self, "_piece_cache", got)
        return got

    def _splines_at(self, chi: np.ndarray, which: tuple) -> list[np.ndarray]:
        """The splines ``which`` at ``log chi`` (1-d): the interval from the uniform knots by one division (no binary
        search), the cubic by scipy's own sum of powers of ``s`` on gathered coefficients: the values of scipy's
        ``CubicSpline.__call__`` (tests/contact/test_any_thickness_tips.py).
        """
        x0, h, knots, coefs = self._pieces()
        x = np.log(chi)
        k = ((x - x0) / h).astype(np.intp)
        np.clip(k, 0, knots.size - 2, out=k)
        x -= np.take(knots, k, mode="clip")  # s, the offset in the interval
        s2 = x * x
        s3 = s2 * x
        out = []
        for j in which:  # scipy's order: c3 + c2 s + c1 s^2 + c0 s^3, left to right
            c = coefs[j]
            v = np.take(c[2], k, mode="clip")
            v *= x
            v += np.take(c[3], k, mode="clip")
            w = np.take(c[1], k, mode="clip")
            w *= s2
            v += w
            np.take(c[0], k, mode="clip", out=w)
            w *= s3
            v += w
            out.append(v)
        return out

    def ratios(self, chi: Any) -> tuple[np.ndarray, np.ndarray]:
        """``(P/P_0, c/c_0)`` at ``chi`` (vectorised: the series on the points below ``CHI_SERIES`` only)."""
        shape = np.shape(chi)
        chi = np.asarray(chi, dtype=float).reshape(-1)
        lo = self._check(chi)
        lp, lc = self._splines_at(chi, (0, 1))
        if lo <= CHI_SERIES:
            fc, rc, _ = self.series
            pv = np.polynomial.polynomial.polyval
            low = np.flatnonzero(chi <= CHI_SERIES)
            cl = chi[low]
            lp[low], lc[low] = np.log(pv(cl, fc)), np.log(pv(cl, rc))
        np.exp(lp, out=lp)
        np.exp(lc, out=lc)
        return lp.reshape(shape), lc.reshape(shape)

    def error_estimate(self, chi: Any) -> tuple[np.ndarray, np.ndarray]:
        """Relative estimates ``(force, contact radius)`` at ``chi``."""
        shape = np.shape(chi)
        chi = np.asarray(chi, dtype=float).reshape(-1)
        lo = self._check(chi)
        eP, ec = self._splines_at(chi, (2, 3))
        if lo <= CHI_SERIES:
            low = np.flatnonzero(chi <= CHI_SERIES)
            sP, sc = self.series[2](chi[low])
            eP[low], ec[low] = sP, sc
        return eP.reshape(shape), ec.reshape(shape)


def cone_law_from(data: dict, nu: float, base: str, with_estimate: bool = True) -> ConeLaw:
    """The cone's law of one (nu, base) from table arrays ``data`` (the packaged table or a fresh one)."""
    from scipy.interpolate import CubicSpline

    from ..asymptotics.thick_layer import thick_power_law_series
    from ..layers.kernels import BondedLayer, FrictionlessLayer, IncompressibleLayer

    rows = [0] if base == "frictionless" else list(range(1, 1 + data["nu"].size))
    chi_max = float(min(data["chi"][i][-1] for i in rows))
    x = np.linspace(math.log(CHI_SERIES), math.log(chi_max), FINE)
    y, z = _raw(data, nu, base, x)
    # evaluated by cubic splines through the fine values (h = 0.01): they differ from the curves' own splines by
    # ~h^4 |f^(4)|/384 < 1e-10, where a linear interpolation would add h^2 |f''|/8, up to 6e-5
    layer = FrictionlessLayer() if base == "frictionless" else IncompressibleLayer() if nu == 0.5 else BondedLayer(nu)
    ser = thick_power_law_series(1, SERIES_ORDER)
    fc, rc = ser.coefficients(layer)
    chi = np.exp(x)
    eP = np.zeros_like(x)
    ec = np.zeros_like(x)
    if with_estimate:
        eP, ec = _measured(data, nu, base, chi)
    splines = tuple(CubicSpline(x, v) for v in (y, z, eP, ec))
    return ConeLaw(float(nu), base, chi_max, splines, (fc, rc, lambda c: ser.error_estimate(c, layer)))


def _v(nu: Any) -> Any:
    """``max(sqrt(1/2 - nu), 0.003)``: the distance from incompressibility the nodes are spaced in."""
    return np.maximum(np.sqrt(np.maximum(0.5 - np.asarray(nu, dtype=float), 0.0)), 0.003)


def _measured(data: dict, nu: float, base: str, chi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """5 x the largest error of the validation points near (chi, nu): within a factor 2.5 in chi and, bonded, a
    factor 3 in ``v = sqrt(1/2 - nu)``; where none is near, 5 x the largest within a factor 4 in chi over all nu.
    At least 2e-6.  (The bonded points sit half-way between nu nodes, the worst place for the interpolation in nu.)
    """
    errs = _check_errors(data)
    kind = 0 if base == "frictionless" else 1
    rows = errs[errs[:, 0] == kind]
    if not rows.size:
        return np.full_like(chi, math.inf), np.full_like(chi, math.inf)
    dchi = np.abs(np.log(rows[None, :, 1]) - np.log(chi[:, None]))
    near_nu = np.abs(np.log(_v(rows[:, 4]) / _v(nu))) <= math.log(3.0) if kind else np.ones(len(rows), bool)
    local = (dchi <= math.log(2.5)) & near_nu[None, :]
    wide = dchi <= math.log(4.0)
    out = []
    for col in (2, 3):
        e_loc = np.where(local, rows[None, :, col], 0.0).max(axis=1)
        e_wide = np.where(wide, rows[None, :, col], 0.0).max(axis=1)
        out.append(np.maximum(5.0 * np.where(local.any(axis=1), e_loc, e_wide), 2e-6))
    return out[0], out[1]


def _check_errors(data: dict) -> np.ndarray:
    """Rows ``(kind, chi, force error, radius error, nu)``: the law without estimate against the validation points."""
    key = id(data)
    hit = _ERRORS.get(key)
    if hit is not None and hit[0] is data:
        return hit[1]
    # the law at a validation point is the table interpolated there (_raw): the law's own spline through its fine
    # grid differs from it by < 1e-10 (see cone_law_from), far below the errors measured; one _raw call per
    # (kind, nu) for all its points, instead of a whole law (8192 interpolations in nu) per point
    groups: dict[tuple[int, float], list] = {}
    for kind, nu, chi, P, c, _ in data["check"]:
        groups.setdefault((int(kind), float(nu)), []).append((float(chi), float(P), float(c)))
    rows = []
    for (kind, nu), pts in groups.items():
        base = "frictionless" if kind == 0 else "bonded"
        idx = [0] if base == "frictionless" else list(range(1, 1 + data["nu"].size))
        chi_max = float(min(data["chi"][i][-1] for i in idx))
        pts = [p for p in pts if CHI_SERIES < p[0] <= chi_max]
        if not pts:
            continue
        y, z = _raw(data, nu, base, np.log([p[0] for p in pts]))
        for (chi, P, c), yk, zk in zip(pts, y, z):
            rows.append((kind, chi, abs(math.exp(yk) / P - 1), abs(math.exp(zk) / c - 1), nu))
    out = np.array(rows) if rows else np.zeros((0, 5))
    _ERRORS[key] = (data, out)
    return out


_ERRORS: dict[int, tuple[dict, np.ndarray]] = {}


@lru_cache(maxsize=64)
def _cone_law_cached(nu: float, base: str) -> ConeLaw:
    return cone_law_from(_packaged(), nu, base)


def cone_law(nu: float, base: str = "bonded") -> ConeLaw:
    """The cone's any-thickness law of one (nu, base) (cached): bonded ``0.3 <= nu <= 1/2`` or frictionless.

    Examples
    --------
    >>> law = cone_law(0.5)
    >>> P, c = law.ratios([0.01, 1.0])
    >>> round(float(P[0]), 4)        # 1 + 2 (b_0/pi) chi + ... (T.9)
    1.0114
    """
    if base not in ("bonded", "frictionless"):
        raise InputError(f"base must be 'bonded' or 'frictionless', got {base!r}")
    nv = float(nu)
    if base == "bonded" and not NU_MIN <= nv <= 0.5:
        raise InputError(f"the cone's any-thickness table covers bonded layers with {NU_MIN} <= nu <= 1/2, got {nv}")
    return _cone_law_cached(nv if base == "bonded" else 0.3, base)


def _cone_angle(tip: Any) -> float | None:
    """``tan(alpha)`` when the tip is a cone ``r cot(alpha)`` (read from its profile, not its class), else None."""
    import sympy as sp

    from ..parse import RADIUS

    expr = getattr(tip, "radial_expr", None)
    if expr is None or getattr(tip, "parameters", ()):
        return None
    slope = sp.simplify(expr / RADIUS)
    if slope.free_symbols or not slope.is_positive:
        return None
    return 1.0 / float(slope)


def cone_tangent(tip: Any) -> float | None:
    """``tan(alpha)`` when the tip is a cone ``r cot(alpha)`` with a number for alpha (read from its profile), else
    None; cached per tip (the profile is simplified once).
    """
    try:
        return _cone_tangent_cached(tip)
    except TypeError:  # an unhashable tip
        return _cone_angle(tip)


@lru_cache(maxsize=64)
def _cone_tangent_cached(tip: Any) -> float | None:
    return _cone_angle(tip)


def numeric_tip(punch: Any, parameters: dict | None) -> Any:
    """A polynomial punch with numbers (``numeric_punch``), or a tip of revolution with its parameters given."""
    from ..asymptotics.solution import numeric_punch
    from ..punch import PunchError, Tip

    if not isinstance(punch, Tip) or punch.polynomial is not None:
        return numeric_punch(punch, parameters)
    tip = punch.subs(parameters) if parameters else punch
    if tip.parameters:
        raise PunchError(f"the {tip.name} has parameters {', '.join(map(str, tip.parameters))} without values; "
                         "pass parameters={...}")
    return tip


def tip_fields(layer: Any, tip: Any, delta0: Any, force: Any, H: float, mu: float, nu: float, base: str,
               tol: float, pressure: Any) -> dict[str, Any]:
    """The any-thickness answer for a tip of revolution as the fields of an Indentation (the caller adds layer,
    punch and material); :class:`~thinlayer.contact.any_thickness.NotTabulatedError` where it does not answer.

    In order: the cone's table (bonded ``0.3 <= nu <= 1/2`` or frictionless, within its chi and ``tol``); the
    thick-layer series (T.9) where its estimate is below :data:`SERIES_TRUSTED` (and ``tol``); else the equation
    (F.6) with the tip's load, solved at the depth (:func:`thinlayer.contact.revolution_law.revolution_fields`,
    ``c_0/H <= 30``).
    """
    answer = None
    tan_a = _cone_angle(tip)
    if tan_a is not None and (base == "frictionless" or NU_MIN <= nu <= 0.5):
        try:
            answer = _cone_table_fields(tip, tan_a, delta0, force, H, mu, nu, base)
        except NotTabulatedError:
            answer = None
        if answer is not None and max(answer[3].values()) > tol:
            answer = None
    if answer is None:
        from ..asymptotics.thick_tips import radial_thick_expansion

        ex = radial_thick_expansion(tip, SERIES_ORDER)
        try:
            v = ex.evaluate(layer, None if force is not None else delta0, H, mu, nu, force=force)
            est = {"force": v.force_error, "contact_area": 2 * v.radius_error, "contact_radius": v.radius_error}
            if max(est.values()) <= min(tol, SERIES_TRUSTED):
                answer = (v.delta0, v.force if force is None else positive(force, "force"), v.radius, est,
                          f"thick-layer series (T.9) through (c/H)^{ex.order} at c/H = {v.eps:.4g}")
        except ValueError:
            answer = None
    if answer is None:
        if base == "bonded" and not NU_MIN <= nu <= 0.5:
            raise NotTabulatedError(f"the any-thickness equation (F.6) for tips is validated for bonded layers with "
                                    f"{NU_MIN} <= nu <= 1/2 (and the frictionless base), got nu = {nu}")
        f = revolution_fields(layer, tip, delta0, force, H, mu, nu, tol)
        answer = (f["delta0"], f["force"], f["radius"], f["estimate"], f["reason"])
    d0, P, c, est, why = answer
    if max(est.values()) > tol:
        raise NotTabulatedError(f"the any-thickness estimate {max(est.values()):.3g} exceeds tol = {tol:.3g}")
    return dict(delta0=d0, force=P, contact_area=math.pi * c * c, contact_radius=c, reason=why,
                error_estimate=est, _pressure=pressure(d0, P, c), _extent=1.2 * c)


#: the thick-layer series answers a tip that is not a cone where its estimate (T.8) is below this (else the equation)
SERIES_TRUSTED = 1e-8


def _cone_table_fields(tip: Any, tan_a: float, delta0: Any, force: Any, H: float, mu: float, nu: float,
                       base: str) -> tuple:
    """``(delta0, P, c, estimates, reason)`` from the cone's table; :class:`NotTabulatedError` beyond it."""
    law = cone_law(nu, base)
    vt = mu / (1.0 - nu)

    def at(d: float) -> tuple[float, float, float, float, float]:
        c0 = 2.0 / math.pi * d * tan_a
        chi = c0 / H
        (Pr,), (cr,) = law.ratios(np.array([chi]))
        (eP,), (ec,) = law.error_estimate(np.array([chi]))
        return 4.0 / math.pi * vt * tan_a * d * d * Pr, c0 * cr, chi, eP, ec

    top = law.chi_max * H * math.pi / 2 / tan_a  # the deepest delta0 the law covers
    if force is not None:
        from scipy import optimize

        Pt = positive(force, "force")
        if at(top)[0] < Pt:
            raise NotTabulatedError(f"the force {Pt:.4g} needs chi = c_0/H > {law.chi_max:.3g}, beyond the cone's "
                                    "any-thickness table (the thin layer)")
        d0 = math.exp(optimize.brentq(lambda ld: math.log(at(math.exp(ld))[0] / Pt), math.log(top) - 80,
                                      math.log(top), xtol=1e-15, rtol=1e-15))
    else:
        d0 = positive(delta0, "delta0")
    if d0 > top * (1 + 1e-12):
        raise NotTabulatedError(f"chi = c_0/H = {2 / math.pi * d0 * tan_a / H:.4g} is beyond the cone's "
                                f"any-thickness table (chi <= {law.chi_max:.3g}): the thin layer")
    P, c, chi, eP, ec = at(min(d0, top))
    P = P if force is None else positive(force, "force")
    est = {"force": eP, "contact_area": 2 * ec, "contact_radius": ec}
    why = (f"any-thickness law for the cone at chi = c_0/H = {chi:.4g} "
           f"({'thick-layer series (T.9)' if chi <= CHI_SERIES else 'table of direct solutions'}; "
           f"estimates force {eP:.2g}, radius {ec:.2g})")
    return d0, P, c, est, why


def revolution_fields(layer: Any, tip: Any, delta0: Any, force: Any, H: float, mu: float, nu: float,
                      tol: float) -> dict[str, Any]:
    """``delta0, force, contact radius`` and the estimates of a tip of revolution at one depth (or force) (F.13);
    :class:`NotTabulatedError` beyond ``c_0/H = 30`` or where the estimate exceeds ``tol``.
    """
    from .._checks import WorkLimitError
    from ..numerics.revolution import MAX_C0_OVER_H, revolution_contact

    try:
        res = revolution_contact(layer, tip, delta0, H, force=force, mu=mu,
                                 nu=nu if layer.numeric_nu is None else None)
    except WorkLimitError as exc:
        raise NotTabulatedError(f"beyond the any-thickness equation's range (F.13), c_0/H <= {MAX_C0_OVER_H:g}: "
                                f"{exc}") \
            from None
    est = {"force": res.force_error, "contact_area": 2 * res.radius_error, "contact_radius": res.radius_error}
    if delta0 is None:
        est["delta0"] = res.delta0_error
    if max(est.values()) > tol:
        raise NotTabulatedError(f"the any-thickness estimate {max(est.values()):.3g} exceeds tol = {tol:.3g}")
    why = (f"any-thickness equation (F.6) with the tip's load (F.11)-(F.14) at c/H = {res.radius / H:.4g} "
           f"({res.nodes} nodes; estimates force {res.force_error:.2g}, radius {res.radius_error:.2g})")
    return {"delta0": res.delta0, "force": res.force, "radius": res.radius, "estimate": est, "reason": why}
