r"""Fitting a measured force curve: E (and H) with the contact point and the baseline as parameters (issue 25 item 3).

:func:`fit_curve` fits, to a :class:`~thinlayer.afm.curves.Curve` (tip position ``z`` [m], force ``F`` [N]),

    ``F(z) = b0 + b1 (z - z0) + E P(delta; H)``,  ``delta = z0 - z`` (a tip position; ``z - z0`` for a depth axis),

``P`` being the unit-modulus force of :func:`thinlayer.fit`'s law (:func:`thinlayer.contact.fit.fit_law`: the
any-thickness law (T.7) of the paraboloid by default, Hertz for ``H`` None/inf, the tip laws for other tips) and zero
before contact (``delta <= 0``).  ``b0`` is the baseline force at the contact point, ``b1`` its slope
(``baseline="offset+slope"``; 0 with ``"offset"``).  The parameters ``(log E, z0, b0[, b1][, log H])`` are found by
:func:`scipy.optimize.least_squares` with the analytic Jacobian, started from a robust estimate:

1. the baseline: a Theil-Sen line (``"offset"``: the median) through the farthest 40 % of the points from the sample,
   the noise ``sigma`` the scaled median absolute deviation of its residual;
2. the contact point: the deepest point whose force is within ``3 sigma`` of that baseline (where the residual
   departs), then the best of 100 trial contact points at and before it (40 within one indentation depth of it, 60
   back to the start of the curve), each with ``E``, ``b0``, ``b1`` solved
   linearly (the model is linear in them): a profile of the residual over ``z0``.

Solvers.  ``solver="lm"`` (the default, the reference) scores the 100 trial contact points on every point and runs
Levenberg-Marquardt on all parameters from the best.  ``solver="varpro"`` (the default of force maps,
:func:`thinlayer.afm.maps.fit_curve_full`) solves the same least squares by variable projection: the force is linear in
``E``, ``b0``, ``b1``, so for a contact point they are one linear solve (the baseline's columns span the same space
whatever ``z0``: projected out once), the trials are scored all at once on at most 128 block means of the curve, and
Gauss-Newton steps on the projected residual (Kaufman's approximation) in ``z0`` alone converge in 3-5 evaluations of
the law on the points in contact; the standard errors are then computed as ``"lm"``'s, from the full Jacobian at the
solution.  Measured against ``"lm"``: E, z0, b0 within 2.2e-5 of a standard error on the 2,000-point curves of
benchmarks/bench_maps.py, within 1.2e-3 on a 300-point map pixel where Levenberg-Marquardt stops earlier along the E-z0
valley (variable projection's residual is the lower); 3.9 ms of CPU per curve on a layer against 47 ms, 2.5 ms on the
half-space against 41 ms (benchmarks/bench_maps.py, load 8-10; tests/afm/test_maps_fast.py).  Weighted fits, a fitted H
and an indentation range are left to ``"lm"``.

Contact-point weighting.  ``weighting="nanite"`` multiplies each residual by ``min(|z - z0|/weight_cp, 1)``
(nanite's ``compute_contact_point_weights``, its default ``weight_cp = 1e-6`` m), which lets the points next to the
contact point count less; the weights move with ``z0`` (their derivative is in the Jacobian), as in nanite.
Measured on the real JPK curve ``fmt-jpk-fd_spot3-0192.jpk-force`` (afmformats' example, approach, 2,000 points,
R = 10 um, nu = 1/2, H = inf, offset baseline): E = 14,742 Pa unweighted and 15,345 Pa weighted (+4.1 %, nine times
the unweighted standard error of 67 Pa); on the first curve of the QI map ``fmt-jpk-fd_2020.02.07-16.29.05.036
.jpk-qi-data`` (300 points, a few in contact) E = 992 Pa unweighted and 16.3 Pa weighted (a factor 61: unweighted,
the last steep points are taken for the contact; weighted, a soft contact 0.5 um earlier fits better).  With the
weights the fit is nanite's ``hertz_para`` fit with its own contact-point model on the same curve: the same E within
2e-5 on afmformats' six example curves, and the same standard error (564 Pa on the JPK curve: the weights' derivative
is in both Jacobians); ``tests/afm/test_curves.py`` holds these numbers.  Which to choose is a modelling decision the
data do not make: the spread between the two is an uncertainty no standard error of one fit shows.

Uncertainty.  Beside the naive standard errors (``s^2 (J^T J)^{-1}``, independent residuals) ``bootstrap=N`` gives
the studentised AR-sieve errors (:mod:`thinlayer.afm.bootstrap`: an AR(p) fitted to the residuals gives the sandwich
covariance; ``N`` series drawn from it correct its bias and give its degrees of freedom): ``E +- 1.96 E_se_boot`` is
the 95 % interval.  Its coverage on AR(1) noise (800 points, 400 seeds each,
:data:`thinlayer.afm.bootstrap.MEASURED_COVERAGE`): 0.953, 0.958, 0.943 at phi = 0.3, 0.7, 0.9, where the naive error
covers 0.835, 0.61, 0.37.  ``bootstrap_method="block"`` keeps the moving-block bootstrap with refits (it under-covers:
0.86 at phi = 0.7, 0.81 at 0.9).

The result says the regime as :func:`thinlayer.fit` does: ``chi_max`` (or ``(c/H)_max``), ``delta/H``, ``delta/R``,
the model's error against the any-thickness law and whether it is valid, and the guard flags.
"""
from __future__ import annotations

import functools
import math
import numbers
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._checks import InputError, InputTypeError, check_choice, positive
from ..display import RichDisplay
from ..errors import ComputationError, ValidityWarning, boundary, boundary_methods
from .bootstrap import block_length, block_resample, sieve_errors
from .curves import Curve

__all__ = ["BASELINES", "CurveFit", "MAX_BOOTSTRAP", "SOLVERS", "WEIGHTINGS", "fit_curve"]

BASELINES = ("offset", "offset+slope")
WEIGHTINGS = (None, "nanite")
#: ``"lm"``: the trial contact points on every point, then Levenberg-Marquardt on all parameters (the reference);
#: ``"varpro"``: the trial points on block means, then variable projection over the contact point (module docstring)
SOLVERS = ("lm", "varpro")
#: the most block means the trial contact points of ``solver="varpro"`` are scored on
TRIAL_POINTS = 128
#: the most bootstrap refits asked for in one call (about 2 ms each on a 2,000-point curve)
MAX_BOOTSTRAP = 5000
#: a condition number of the column-scaled Jacobian above this means the data cannot separate the parameters
MAX_CONDITION = 1e10
_PHYS = ("E", "z0", "b0", "b1", "H")


@boundary_methods
@dataclass(frozen=True, eq=False)
class CurveFit(RichDisplay):
    """The result of :func:`fit_curve`.

    Attributes
    ----------
    E, E_se, E_se_boot : float
        Young's modulus [Pa for a file], its naive standard error and its block-bootstrap standard error (NaN
        without ``bootstrap``).
    H, H_se, H_se_boot : float
        Thickness (fitted, or as given with ``H_se = 0``; inf: the half-space).
    z0, z0_se, z0_se_boot : float
        Contact point on the curve's axis (given: ``z0_se = 0``).
    b0, b0_se, b0_se_boot, b1, b1_se, b1_se_boot : float
        Baseline ``b0 + b1 (z - z0)``: the force at the contact point and the slope (0 with ``"offset"``).
    fitted : tuple of str
        The fitted parameters, the order of ``covariance`` (of ``E, z0, b0, b1, H``, physical units).
    residual_rms : float
    residuals : numpy.ndarray
        ``model - force`` at the fitted points, in the curve's order.
    block_length, phi : int, float
        The bootstrap's block length and the residuals' lag-1 autocorrelation it was chosen from.
    chi_max, delta_max, valid, model_error, validity, flags
        The regime and the model's check, as :class:`thinlayer.contact.fit.FitResult`.
    """

    E: float
    E_se: float
    H: float
    H_se: float
    z0: float
    z0_se: float
    b0: float
    b0_se: float
    b1: float
    b1_se: float
    residual_rms: float
    residuals: np.ndarray = field(repr=False)
    covariance: np.ndarray = field(repr=False)
    fitted: tuple = ()
    n_points: int = 0
    model: str = "any-thickness"
    base: str = "bonded"
    nu: float = 0.5
    R: float = math.nan
    tip_words: str = ""
    chi_max: float = math.nan
    delta_max: float = math.nan
    valid: bool = True
    model_error: float = 0.0
    validity: str = ""
    flags: tuple = ()
    baseline: str = "offset"
    weighting: str | None = None
    weight_cp: float = 1e-6
    axis: str = "tip position"
    direction: int = -1
    units: tuple = ("m", "N")
    source: str = ""
    segment: str = ""
    fit_range: tuple | None = None
    range_kind: str = "position"
    condition: float = math.nan
    bootstrap: int = 0
    block_length: int = 0
    phi: float = math.nan
    boot_failures: int = 0
    E_se_boot: float = math.nan
    H_se_boot: float = math.nan
    z0_se_boot: float = math.nan
    b0_se_boot: float = math.nan
    b1_se_boot: float = math.nan
    law: Any = field(default=None, repr=False)
    bootstrap_method: str = ""
    ar_order: int = 0
    equation = "T.7"

    def predict(self, z: Any) -> np.ndarray:
        """The fitted force at the positions ``z`` (the curve's axis): baseline plus the law after contact."""
        zz = np.asarray(z, dtype=float)
        if zz.dtype.kind != "f" or not np.all(np.isfinite(zz)):
            raise InputError("predict(): z must be finite numbers on the curve's axis")
        delta = self.direction * (zz - self.z0)
        P, _, _ = self.law.shape(delta, self.H, slopes=False)
        return self.b0 + self.b1 * (zz - self.z0) + self.E * P

    def as_dict(self) -> dict[str, Any]:
        """The numbers as a JSON-ready dictionary (NaN and inf as None)."""
        out: dict[str, Any] = {"source": self.source, "segment": self.segment, "model": self.model,
                               "base": self.base, "nu": self.nu, "R": None if math.isnan(self.R) else self.R,
                               "tip": self.tip_words, "axis": self.axis, "units": list(self.units)}
        for k in ("E", "E_se", "E_se_boot", "H", "H_se", "H_se_boot", "z0", "z0_se", "z0_se_boot", "b0", "b0_se",
                  "b0_se_boot", "b1", "b1_se", "b1_se_boot", "residual_rms", "chi_max", "delta_max", "model_error",
                  "condition", "phi", "weight_cp"):
            v = float(getattr(self, k))
            out[k] = v if math.isfinite(v) else None
        out.update({"delta_over_H": (self.delta_max / self.H) if math.isfinite(self.H) else 0.0,
                    "delta_over_R": None if math.isnan(self.R) else self.delta_max / self.R,
                    "n_points": self.n_points, "fitted": list(self.fitted), "baseline": self.baseline,
                    "weighting": self.weighting, "fit_range": None if self.fit_range is None else list(self.fit_range),
                    "range_kind": self.range_kind, "bootstrap": self.bootstrap, "block_length": self.block_length,
                    "bootstrap_method": self.bootstrap_method, "ar_order": self.ar_order,
                    "boot_failures": self.boot_failures, "valid": self.valid, "validity": self.validity,
                    "flags": list(self.flags),
                    "covariance": [[float(v) for v in row] for row in self.covariance]})
        return out

    def text_lines(self) -> list[str]:
        zu, fu = self.units
        mu = f" {zu}" if zu else ""
        Eu = " Pa" if (zu, fu) == ("m", "N") else ""
        size = "chi_max" if not math.isnan(self.R) else "(c/H)_max"
        lines = [f"CurveFit ({self.model} model, {self.base} base, nu = {self.nu:.6g}, {self.tip_words}) of "
                 f"{self.source}" + (f", {self.segment}" if self.segment else "")
                 + f": {self.n_points} points, {size} = {self.chi_max:.3g}"]
        if not self.valid:
            lines.append(f"  NOT VALID: {self.validity}")
        boot = self.bootstrap > 0

        def pm(name, v, se, seb, unit):
            kind = "AR-sieve" if self.bootstrap_method == "sieve" else "block"
            tail = f" ({kind} bootstrap +- {seb:.2g})" if boot and math.isfinite(seb) else ""
            return f"  {name:<6} = {v:.8g} +- {se:.2g}{unit}{tail}"

        lines.append(pm("E", self.E, self.E_se, self.E_se_boot, Eu))
        if "H" in self.fitted:
            lines.append(pm("H", self.H, self.H_se, self.H_se_boot, mu))
        elif math.isinf(self.H):
            lines.append("  H      = inf (the half-space)")
        else:
            lines.append(f"  H      = {self.H:.8g}{mu} (given)")
        if "z0" in self.fitted:
            lines.append(pm("z0", self.z0, self.z0_se, self.z0_se_boot, mu) + "   (contact point)")
        else:
            lines.append(f"  z0     = {self.z0:.8g}{mu} (given contact point)")
        lines.append(pm("b0", self.b0, self.b0_se, self.b0_se_boot, f" {fu}" if fu else "")
                     + "   (baseline at the contact point)")
        if "b1" in self.fitted:
            lines.append(pm("b1", self.b1, self.b1_se, self.b1_se_boot, f" {fu}/{zu}" if fu else "")
                         + "   (baseline slope)")
        d = f"  delta_max = {self.delta_max:.4g}{mu}"
        if math.isfinite(self.H):
            d += f", delta/H = {self.delta_max / self.H:.3g}"
        if not math.isnan(self.R):
            d += f", delta/R = {self.delta_max / self.R:.3g}"
        lines.append(d)
        lines.append(f"  residual rms = {self.residual_rms:.4g}{(' ' + fu) if fu else ''}, lag-1 autocorrelation "
                     f"{self.phi:.3g}")
        if boot and self.bootstrap_method == "sieve":
            lines.append(f"  bootstrap: {self.bootstrap} AR-sieve draws, AR({self.ar_order}) of the residuals, "
                         "studentised (+- 1.96 x the bootstrap error is the 95 % interval)")
        elif boot:
            lines.append(f"  bootstrap: {self.bootstrap} moving-block resamples of the residuals, block length "
                         f"{self.block_length} (AR(1) Politis-White rule)"
                         + (f", {self.boot_failures} refits failed" if self.boot_failures else ""))
        if self.weighting:
            lines.append(f"  contact-point weighting: {self.weighting} (weight_cp = {self.weight_cp:.3g}{mu})")
        lines += [f"  FLAG: {f}" for f in self.flags]
        lines.append(f"  model error  = {100 * self.model_error:.2g} % ({self.validity})")
        return lines

    def latex(self) -> str:
        return (rf"E = {self.E:.6g} \pm {self.E_se:.2g},\quad z_0 = {self.z0:.6g},\quad H = {self.H:.6g},\quad "
                rf"\text{{{self.model}}},\ \nu = {self.nu:.4g}")


def _plain(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _fit_law(punch: Any, H: Any, nu: Any, base: Any, model: Any) -> Any:
    """:func:`thinlayer.contact.fit.fit_law`, kept per (sphere radius, half-space or not, nu, base, model): the law
    does not depend on the value of a finite H (a map fits thousands of curves with one law).
    """
    from ..contact.fit import fit_law

    if _plain(punch) and _plain(nu) and isinstance(base, str) and (model is None or isinstance(model, str)):
        if H is None or (_plain(H) and H == math.inf):
            return _law_kept(float(punch), True, float(nu), base, model)
        if _plain(H) and math.isfinite(H) and H > 0:
            return _law_kept(float(punch), False, float(nu), base, model)
    return fit_law(punch, H, nu, base, model)


@functools.lru_cache(maxsize=32)
def _law_kept(R: float, half: bool, nu: float, base: str, model: str | None) -> Any:
    from ..contact.fit import fit_law

    return _ForceOnly.of(fit_law(R, None if half else 1.0, nu, base, model))


def _real(v: Any, name: str) -> float:
    if isinstance(v, bool) or not isinstance(v, numbers.Real) or not math.isfinite(float(v)):
        raise InputError(f"{name} must be a finite number, got {v!r:.60}")
    return float(v)


def _range(fit_range: Any, range_kind: str) -> tuple[float, float] | None:
    check_choice(range_kind, ("position", "indentation"), "range_kind")
    if fit_range is None:
        return None
    if isinstance(fit_range, (str, bytes)) or not hasattr(fit_range, "__len__") or len(fit_range) != 2:
        raise InputError(f"fit_range must be two numbers (lo, hi) on the {range_kind} axis, got {fit_range!r:.60}")
    lo, hi = (_real(v, "fit_range") for v in fit_range)
    if not lo < hi:
        raise InputError(f"fit_range must have lo < hi, got ({lo:g}, {hi:g})")
    return lo, hi


@boundary
def fit_curve(curve: Curve, punch: Any = None, H: Any = None, nu: Any = 0.5, base: str = "bonded", *,
              model: str | None = None, fit_H: bool = False, baseline: str = "offset", contact_point: Any = None,
              weighting: str | None = None, weight_cp: float = 1e-6, fit_range: Any = None,
              range_kind: str = "position", bootstrap: int = 0, seed: int = 0,
              bootstrap_method: str = "sieve", solver: str = "lm", substrate_E: Any = None,
              substrate_nu: Any = 0.0) -> CurveFit:
    r"""Fit E (and H), the contact point and the baseline to a measured force curve (module docstring).

    Parameters
    ----------
    curve : Curve
        From :func:`thinlayer.afm.curves.load_curve` (tip position [m], force [N]) or
        :func:`~thinlayer.afm.curves.curve_from_arrays`.
    punch, H, nu, base, model
        As :func:`thinlayer.fit`: the sphere radius (or a tip), the thickness (None/inf: the half-space), the
        Poisson ratio, the base, the force model.
    fit_H : bool
        Also fit the thickness (``H`` is its starting value).
    baseline : str
        ``"offset"`` (``b0``) or ``"offset+slope"`` (``b0 + b1 (z - z0)``).
    contact_point : float, optional
        None (default): fitted; a number: fixed there (on the curve's axis).
    weighting : str, optional
        None (equal weights) or ``"nanite"`` (contact-point weights over ``weight_cp``, module docstring).
    fit_range : (float, float), optional
        Points kept: ``lo <= z <= hi`` (``range_kind="position"``), or ``lo <= delta <= hi`` (``"indentation"``:
        relative to the fitted contact point, negative before contact, e.g. ``(-2e-6, 1e-6)``).
    bootstrap : int
        Number of bootstrap draws (0: none; at most :data:`MAX_BOOTSTRAP`): of the AR-sieve (module docstring), or of
        moving-block refits with ``bootstrap_method="block"``.
    seed : int
        Seed of the bootstrap's random numbers.
    bootstrap_method : str
        ``"sieve"`` (default: studentised AR-sieve, its interval covers) or ``"block"`` (moving-block refits).
    solver : str
        ``"lm"`` (default, the reference) or ``"varpro"`` (the same least-squares problem solved by variable
        projection over the contact point, module docstring; used for the contact point free or fixed, no weighting,
        ``fit_H=False`` and a position range, else ``"lm"``).
    substrate_E, substrate_nu : float, optional
        The substrate's Young's modulus (units of E) and Poisson ratio (default 0): a flag when its compliance would
        change the force by more than 1 % (as :func:`thinlayer.fit`; :func:`thinlayer.contact.guards.substrate_flags`).

    Returns
    -------
    CurveFit

    Raises
    ------
    ValueError
        One line: force falling into the sample (the axis convention), no contact in the data, too few points, a
        range that keeps none, data that cannot separate the parameters.

    Examples
    --------
    >>> import numpy as np
    >>> from thinlayer.afm.curves import curve_from_arrays
    >>> z = np.linspace(-1.0, 1.0, 201)                        # a depth axis, contact at z0 = -0.2
    >>> F = 0.5 + 3.0 * 4 / 3 / 0.75 * np.sqrt(10.0) * np.clip(z + 0.2, 0, None) ** 1.5
    >>> r = fit_curve(curve_from_arrays(z, F), punch=10.0, H=None)
    >>> round(r.E, 6), round(r.z0, 6), round(r.b0, 6)
    (3.0, -0.2, 0.5)
    """
    from ..contact.fit import check_separable

    if not isinstance(curve, Curve):
        raise InputTypeError(f"fit_curve() needs a Curve (thinlayer.afm.curves.load_curve or curve_from_arrays), "
                             f"got {type(curve).__name__}")
    law = _fit_law(punch, H, nu, base, model)
    if law.half_space and fit_H:
        raise InputTypeError("fit_curve(fit_H=True) needs H= (the starting value of the thickness); H=None or inf is "
                             "the half-space")
    check_separable(law.tip, fit_H)
    H0 = math.inf if law.half_space else float(H)
    check_choice(baseline, BASELINES, "baseline")
    check_choice(solver, SOLVERS, "solver")
    if weighting not in WEIGHTINGS:
        raise InputError(f"weighting must be None or 'nanite', got {weighting!r:.60}")
    wcp = positive(weight_cp, "weight_cp")
    rng_ = _range(fit_range, range_kind)
    if isinstance(bootstrap, bool) or not isinstance(bootstrap, numbers.Integral) or not \
            0 <= bootstrap <= MAX_BOOTSTRAP:
        raise InputError(f"bootstrap must be a whole number of refits in [0, {MAX_BOOTSTRAP}], got {bootstrap!r:.60}")
    check_choice(bootstrap_method, ("sieve", "block"), "bootstrap_method")
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral):
        raise InputTypeError(f"seed must be a whole number, got {seed!r:.60}")
    fixed = None if contact_point is None else _real(contact_point, "contact_point")
    s = curve.direction
    x_all, f_all = s * curve.z, curve.force
    keep = np.ones(x_all.size, dtype=bool)
    if rng_ is not None and range_kind == "position":
        keep = (curve.z >= rng_[0]) & (curve.z <= rng_[1])
    law = _ForceOnly.of(law)
    opts = dict(law=law, slope=baseline == "offset+slope", fit_H=fit_H, weighting=weighting, wcp=wcp)
    boot_kind = bootstrap_method
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):
        x, f = x_all[keep], f_all[keep]
        _orientation(x, f, curve)
        xc0 = None if fixed is None else s * fixed
        fast = None
        if solver == "varpro" and weighting is None and not fit_H and not (rng_ is not None and
                                                                           range_kind == "indentation"):
            fast = _varpro(x, f, H0, xc0, **opts)
        if fast is not None:
            res = _result(curve, x, f, fast, H0, xc0, rng_, range_kind, baseline, int(bootstrap), int(seed), boot_kind,
                          **opts)
            return _checked(res, substrate_E, substrate_nu)
        start = _initial(x, f, H0, xc0, **opts)
        if rng_ is not None and range_kind == "indentation":
            for _ in range(6):  # the window follows the contact point
                sel = (x_all - start[0] >= rng_[0]) & (x_all - start[0] <= rng_[1])
                if sel.sum() < 6:
                    raise InputError(f"fit_range {rng_} in indentation keeps {int(sel.sum())} points around the "
                                     f"contact point: widen it")
                x, f = x_all[sel], f_all[sel]
                new = _solve(x, f, start, H0, xc0, **opts)
                moved = np.any(sel != keep)
                keep, start = sel, new[0]
                if not moved:
                    break
        sol = _solve(x, f, start, H0, xc0, **opts)
        res = _result(curve, x, f, sol, H0, xc0, rng_, range_kind, baseline, int(bootstrap), int(seed), boot_kind,
                      **opts)
    return _checked(res, substrate_E, substrate_nu)


def _checked(res: CurveFit, substrate_E: Any = None, substrate_nu: Any = 0.0) -> CurveFit:
    vals = (res.E, res.E_se, res.z0, res.b0, res.residual_rms)
    if not all(math.isfinite(v) for v in vals):
        raise ComputationError(f"fit_curve(): the fitted numbers are not finite (E = {res.E!r}): the data's numbers "
                               "leave the double range")
    if substrate_E is not None:  # as fit()
        from dataclasses import replace

        from ..contact.guards import fit_substrate_flags

        extra = fit_substrate_flags(res.base, res.nu, res.R, res.chi_max, res.E, substrate_E, substrate_nu)
        if extra:
            res = replace(res, flags=res.flags + extra)
    if not res.valid:
        warnings.warn(f"fit_curve(): E = {res.E:.4g} is NOT VALID: {res.validity}", ValidityWarning, stacklevel=4)
    return res


def _orientation(x: np.ndarray, f: np.ndarray, curve: Curve) -> None:
    if x.size < 6:
        raise InputError(f"{x.size} points in the fit range: too few for E, the contact point and the baseline")
    # the sign of the correlation of position and force: the sign of their covariance (no need to normalise it)
    if np.ptp(x) > 0 and np.ptp(f) > 0 and float(np.dot(x - x.mean(), f - f.mean())) < 0:
        how = ("the file's tip position is negative into the sample" if curve.segment else
               "axis='depth' is positive into the sample, axis='tip position' (CLI --depth-sign -1) negative")
        raise InputError(f"fit_curve(): the force falls as the tip moves into the sample ({how}): is this the "
                         f"right segment or axis?")


def _median(a: np.ndarray) -> float:
    """``float(np.median(a))`` of a 1D float array, bit for bit (the same partition, the same mean of the two middle
    values, NaN when ``a`` has one), without np.median's generic machinery (a fit takes five).
    """
    n = a.size
    if n == 0:
        return float(np.median(a))
    k = n // 2
    p = np.partition(a, [k - 1, k, -1] if n % 2 == 0 else [k, -1])
    if np.isnan(p[-1]):
        return math.nan
    return float((p[k - 1] + p[k]) / 2.0) if n % 2 == 0 else float(p[k])


def _weights(x: np.ndarray, xc: float, weighting: str | None, wcp: float) -> np.ndarray:
    if weighting is None:
        return np.ones_like(x)
    return np.minimum(np.abs(x - xc) / wcp, 1.0)


def _trials(x, f, slope, xc_fixed):
    """``(x sorted, f in that order, the trial contact points)`` (module docstring, steps 1-2)."""
    order = np.argsort(x, kind="stable")
    xs, fs = x[order], f[order]
    n = xs.size
    n0 = max(int(0.4 * n), 5)
    for _ in range(2):
        sub = np.linspace(0, n0 - 1, min(n0, 400)).astype(int)
        if slope:
            from scipy import stats  # seconds to import: only for the sloped baseline

            sl, ic = stats.theilslopes(fs[sub], xs[sub])[:2]
        else:
            sl, ic = 0.0, _median(fs[:n0])
        r = fs - (ic + sl * xs)
        dev = r[:n0] - _median(r[:n0])
        sigma = 1.4826 * _median(np.abs(dev)) or float(np.std(r[:n0])) or 1e-12 * float(np.max(np.abs(fs)))
        below = np.nonzero(r <= 3 * sigma)[0]
        i_dep = int(below[-1]) if below.size else 0
        if i_dep >= n0 or n0 <= 5:
            break
        n0 = max(int(0.8 * i_dep), 5)  # contact within the first 40 %: a shorter baseline
    if xc_fixed is None and i_dep >= n - 2:
        raise InputError(f"no contact in the data: no point's force departs from the baseline by more than 3 sigma "
                         f"(sigma = {sigma:.3g}); is this the approach segment, does the range hold the contact?")
    if xc_fixed is not None:
        grid = np.array([xc_fixed])
    else:
        x_dep, span = xs[i_dep], xs[-1] - xs[i_dep]
        grid = np.concatenate([np.linspace(max(xs[0], x_dep - span), x_dep + 0.1 * span, 40),
                               np.linspace(xs[n // 20], x_dep, 60)])  # near the departure, and all the way back
    return xs, fs, grid


def _initial(x, f, H0, xc_fixed, *, law, slope, fit_H, weighting, wcp):
    """``(xc, E, b0, bx, H)``: the robust start (module docstring, steps 1-2)."""
    xs, fs, grid = _trials(x, f, slope, xc_fixed)
    best = None
    for xc in grid:
        P, _, _ = law.shape(xs - xc, H0, slopes=False)
        if not np.any(P > 0):
            continue
        cols = [P, np.ones_like(xs)] + ([xs - xc] if slope else [])
        w = _weights(xs, xc, weighting, wcp)
        A = np.column_stack(cols) * w[:, None]
        norms = np.linalg.norm(A, axis=0)
        norms[norms == 0] = 1.0
        coef, *_ = np.linalg.lstsq(A / norms, fs * w, rcond=None)  # columns scaled: P/E is ~1e-13 in SI units
        coef = coef / norms
        if not coef[0] > 0:
            continue
        rss = float(np.sum((A @ coef - fs * w) ** 2))
        if best is None or rss < best[0]:
            best = (rss, xc, coef)
    if best is None:
        raise InputError("no contact point gives a positive modulus: the force does not grow into the sample after "
                         "any trial contact point (check the segment, the axis and the range)")
    _, xc, coef = best
    return (float(xc), float(coef[0]), float(coef[1]), float(coef[2]) if slope else 0.0, H0)


def _solve(x, f, start, H0, xc_fixed, *, law, slope, fit_H, weighting, wcp, solved=False):
    """Least squares from ``start`` (nanite's weights, when asked, move with the contact point).  Returns
    ``(params (xc, E, b0, bx, H), jacobian, scaled residuals, names, column scales, weights, the law's force at the
    solution)``; ``solved``: ``start`` is the solution already (:func:`_varpro`), only the Jacobian and the residuals
    are computed there (from one evaluation of the law).
    """
    from scipy import optimize

    xc, E, b0, bx, HH = start
    free_xc = xc_fixed is None
    names = ["E"] + (["z0"] if free_xc else []) + ["b0"] + (["b1"] if slope else []) + (["H"] if fit_H else [])
    xscale = float(np.ptp(x)) or 1.0
    fscale = float(np.max(np.abs(f - _median(f)))) or float(np.max(np.abs(f))) or 1.0
    xref = xc

    def unpack(p):
        i = 1
        E_ = math.exp(p[0])
        xc_ = xref + p[i] * xscale if free_xc else xc_fixed
        i += free_xc
        b0_ = p[i] * fscale
        i += 1
        bx_ = p[i] * fscale / xscale if slope else 0.0
        i += slope
        H_ = math.exp(p[i]) if fit_H else H0
        return xc_, E_, b0_, bx_, H_

    def resid(p, shape=None):
        xc_, E_, b0_, bx_, H_ = unpack(p)
        P, _, _ = law.shape(x - xc_, H_, slopes=False) if shape is None else shape
        return (b0_ + bx_ * (x - xc_) + E_ * P - f) * _weights(x, xc_, weighting, wcp) / fscale

    def jac(p, shape=None):
        xc_, E_, b0_, bx_, H_ = unpack(p)
        d = x - xc_
        P, gd, gH = law.shape(d, H_, slopes=True) if shape is None else shape
        EP = E_ * P
        w = _weights(x, xc_, weighting, wcp)
        cols = [EP * w]
        if free_xc:
            dPd = np.where(d > 0, EP * gd / np.where(d > 0, d, 1.0), 0.0)
            col = (-bx_ - dPd) * w
            if weighting:  # the weights follow the contact point: d w/d xc = -sign(d)/weight_cp inside the ramp
                col = col + (b0_ + bx_ * d + EP - f) * np.where(np.abs(d) < wcp, -np.sign(d) / wcp, 0.0)
            cols.append(col * xscale)
        cols.append(np.full_like(x, fscale) * w)
        if slope:
            cols.append(d * fscale / xscale * w)
        if fit_H:
            cols.append(EP * gH * w)
        return np.column_stack(cols) / fscale

    p0 = [math.log(E)] + ([0.0] if free_xc else []) + [b0 / fscale] + ([bx * xscale / fscale] if slope else []) \
        + ([math.log(HH)] if fit_H else [])
    if solved:
        px = np.array(p0, dtype=float)
    else:
        sol = optimize.least_squares(resid, p0, jac=jac, method="lm", xtol=1e-12, ftol=1e-12, gtol=1e-12,
                                     max_nfev=400)
        px, fun = sol.x, sol.fun
    xc, E, b0, bx, HH = unpack(px)
    shape = law.shape(x - xc, HH, slopes=True)  # once at the solution: its force is the same with or without slopes
    if solved:
        fun = resid(px, shape)
    w = _weights(x, xc, weighting, wcp)
    J = jac(px, shape)
    T = np.array([E] + ([xscale] if free_xc else []) + [fscale] + ([fscale / xscale] if slope else [])
                 + ([HH] if fit_H else []))
    return (xc, E, b0, bx, HH), J, fun, names, T, w, shape[0]


class _ForceOnly:
    """A :class:`~thinlayer.contact.fit.FitLaw` whose ``shape`` evaluates the law at the depths in contact only,
    through the curve's force-only path when it has one (:meth:`thinlayer.contact.models.any_thickness.SphereCurve.
    force_slopes`: no contact radius, no error estimate): the same numbers bit for bit as the law's own ``shape``
    (tests/afm/test_maps_fast.py); every other attribute is the law's.
    """

    def __init__(self, law: Any) -> None:
        self._law = law
        self._curves: dict[float, Any] = {}
        self._scale = 1.0 / (2.0 * (1.0 + law.nu))  # E/mu, as the law's shape divides

    @classmethod
    def of(cls, law: Any) -> Any:
        """``law`` itself for the half-space (a closed form already) or a law without curves, else the wrapper."""
        if isinstance(law, cls) or law.half_space or not hasattr(law.shape, "curve"):
            return law
        return cls(law)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):  # not set yet (copy, pickle): never the law's private names
            raise AttributeError(name)
        return getattr(self._law, name)

    def __reduce__(self):
        return _ForceOnly, (self._law,)

    def _curve(self, H: float) -> Any:
        curve = self._curves.get(H)
        if curve is None:
            if len(self._curves) > 64:
                self._curves.clear()
            curve = self._curves[H] = self._law.shape.curve(H)
        return curve

    def in_contact(self, delta: np.ndarray, H: float):
        """``shape(delta, H)`` at depths that are all ``> 0`` (the points past a contact point): the same numbers bit
        for bit, without the masks (:func:`_varpro` takes it 3-4 times per curve).
        """
        both = getattr(self._curve(H), "force_slopes", None)
        if both is None:
            return self._law.shape(delta, H, True)
        p, a, b = both(np.asarray(delta, dtype=float), True)
        return p * self._scale, a, b

    def shape(self, delta: np.ndarray, H: float, slopes: bool = True):
        curve = self._curve(H)
        both = getattr(curve, "force_slopes", None)
        if both is None:
            return self._law.shape(delta, H, slopes)
        delta = np.asarray(delta, dtype=float)
        pos = delta > 0
        P = np.zeros(delta.shape)
        gd = gH = None
        if slopes:
            gd, gH = np.zeros(delta.shape), np.zeros(delta.shape)
        if pos.any():
            p, a, b = both(delta[pos], slopes)
            P[pos] = p * self._scale
            if slopes:
                gd[pos], gH[pos] = a, b
        return P, gd, gH


def _varpro(x, f, H0, xc_fixed, *, law, slope, fit_H, weighting, wcp):
    """``solver="varpro"``: the least-squares problem of :func:`_solve` (unweighted, H given) by variable projection.

    The force ``b0 + b1 (x - xc) + E P(x - xc)`` is linear in ``E``, ``b0``, ``b1``: for a contact point they are one
    linear least-squares solve, and only ``xc`` is searched.  The trial contact points of :func:`_initial` are scored
    on at most :data:`TRIAL_POINTS` block means of the sorted curve (all trials at once); from the best, Gauss-Newton
    steps on the projected functional (Kaufman's variable projection: the step in ``xc`` from its Jacobian column with
    the linear columns projected out), halved while the residual grows, until the step's predicted gain in the sum of
    squares is below 1e-8 of its mean square (the step below 1e-4 of z0's standard error).  Returns what
    :func:`_solve` returns (its Jacobian and residuals at the solution) or None where the answer
    is not a positive modulus (the caller then runs :func:`_solve`, which says why).
    """
    xs, fs, grid = _trials(x, f, slope, xc_fixed)
    n = xs.size
    span = float(xs[-1] - xs[0]) or 1.0
    fmid = _median(fs)
    fsc = float(np.max(np.abs(fs - fmid))) or 1.0
    g = (fs - fmid) / fsc  # the force centred and scaled: sums of squares without cancellation
    u = (xs - xs[0]) / span
    # the baseline's columns span {1, x} (or {1}) whatever the contact point: one orthonormal basis Q for all
    Q, Rq = np.linalg.qr(np.column_stack([np.ones(n), u]) if slope else np.ones((n, 1)))
    g_perp = g - Q @ (Q.T @ g)

    # --- the trials on block means --------------------------------------------------------------------------------
    if xc_fixed is None:
        k = -(-n // TRIAL_POINTS)
        m = (n // k) * k
        xb = xs[n - m:].reshape(-1, k).mean(axis=1)
        gb = g[n - m:].reshape(-1, k).mean(axis=1)
        Qb, _ = np.linalg.qr(np.column_stack([np.ones(m // k), xb - xb[0]]) if slope else np.ones((m // k, 1)))
        gbp = gb - Qb @ (Qb.T @ gb)
        D = xb[None, :] - grid[:, None]
        pos = D > 0
        P = np.zeros(D.shape)
        if pos.any():
            P[pos] = law.shape(D[pos], H0, slopes=False)[0]
        Pp = P - (P @ Qb) @ Qb.T  # each trial's force column, the baseline projected out
        spg, spp = Pp @ gbp, np.einsum("ij,ij->i", Pp, Pp)
        with np.errstate(all="ignore"):
            rss = float(gbp @ gbp) - spg * spg / spp
        rss[~(np.isfinite(rss) & (spg > 0) & (spp > 0))] = np.inf  # a positive modulus and a finite force
        best = int(np.argmin(rss))
        if not math.isfinite(rss[best]):
            return None
        xc = float(grid[best])
    else:
        xc = float(xc_fixed)

    # --- variable projection on every point -----------------------------------------------------------------------
    contact = isinstance(law, _ForceOnly)

    def linear(xc_):
        i = int(np.searchsorted(xs, xc_, side="right"))
        d = xs[i:] - xc_
        if not d.size:
            return None
        Pc, gd, _ = law.in_contact(d, H0) if contact else law.shape(d, H0, slopes=True)  # d > 0: xs[i:] > xc_
        Pp = -Q @ (Q[i:].T @ Pc)
        Pp[i:] += Pc
        spp = float(Pp @ Pp)
        E_ = float(Pp @ g_perp) / spp
        if not (math.isfinite(E_) and E_ > 0):
            return None
        r = E_ * Pp - g_perp
        return float(r @ r), E_, r, Pp, spp, i, d, Pc, gd

    cur = linear(xc)
    if cur is None:
        return None
    if xc_fixed is None:
        for _ in range(60):
            rss, E_, r, Pp, spp, i, d, Pc, gd = cur
            Jx = np.zeros(n)  # d model/d xc: -E dP/d delta in contact (the baseline's part is projected out)
            Jx[i:] = -E_ * Pc * gd / d
            Jp = Jx - Q @ (Q.T @ Jx)
            Jp -= (float(Pp @ Jp) / spp) * Pp  # Kaufman's Jacobian: the column with the linear ones projected out
            jj = float(Jp @ Jp)
            if not jj > 0:
                break
            step = -float(Jx[i:] @ r[i:]) / jj  # r is orthogonal to Q and to Pp: Jp . r = Jx . r
            new = None
            while step * step * jj > 1e-8 * rss / n:  # the step's gain: the step above 1e-4 of z0's standard error
                new = linear(xc + step)
                if new is not None and new[0] <= rss:
                    break
                new = None
                step *= 0.5
            if new is None:  # converged: no step worth taking lowers the residual
                break
            xc, cur = xc + step, new
    _, E_, r, Pp, spp, i, d, Pc, gd = cur
    Pf = np.zeros(n)
    Pf[i:] = Pc
    coef = np.linalg.solve(Rq, Q.T @ (g - E_ * Pf))  # the baseline a + c u in g's units
    uc = (xc - xs[0]) / span
    E = E_ * fsc
    b0 = (coef[0] + (coef[1] * uc if slope else 0.0)) * fsc + fmid
    bx = coef[1] * fsc / span if slope else 0.0
    if not (math.isfinite(E) and E > 0 and math.isfinite(b0) and math.isfinite(bx)):
        return None
    return _solve(x, f, (xc, E, b0, bx, H0), H0, xc_fixed, law=law, slope=slope, fit_H=fit_H, weighting=weighting,
                  wcp=wcp, solved=True)


def _result(curve, x, f, sol, H0, xc_fixed, rng_, range_kind, baseline, n_boot, seed, boot_kind, *, law, slope,
            fit_H, weighting, wcp) -> CurveFit:
    (xc, E, b0, bx, HH), J, r, names, T, w, P = sol
    s = curve.direction
    p = len(names)
    if x.size < p + 1:
        raise InputError(f"{x.size} points cannot determine {p} parameters ({', '.join(names)}) with an error estimate")
    colnorm = np.linalg.norm(J, axis=0)
    if np.any(colnorm == 0):
        raise InputError(f"the data do not determine {names[int(np.argmin(colnorm))]}: the model does not depend on "
                         "it at these points (does the range hold points before and after contact?)")
    sv = np.linalg.svd(J / colnorm, compute_uv=False)
    cond = float(sv[0] / sv[-1]) if sv[-1] > 0 else math.inf
    if cond > MAX_CONDITION:
        raise InputError(f"the data cannot separate {', '.join(names)} (singular Jacobian, condition {cond:.2g}): give "
                         "the contact point, a simpler baseline or H")
    s2 = float(r @ r) / (x.size - p)
    cov = np.linalg.inv(J.T @ J) * s2 * np.outer(T, T)
    se = dict(zip(names, np.sqrt(np.diag(cov))))
    # physical signs: z0 = s xc, b1 = s bx (the covariance of a sign flip changes the off-diagonal signs only)
    flip = np.array([s if nm in ("z0", "b1") else 1 for nm in names], dtype=float)
    cov = cov * np.outer(flip, flip)
    model_f = b0 + bx * (x - xc) + E * P  # P: the law's force at the solution (:func:`_solve`)
    resid = model_f - f
    b, phi = block_length(resid)
    boot = dict.fromkeys(_PHYS, math.nan)
    failures = 0
    order = 0
    if n_boot and boot_kind == "sieve":
        sv_ = sieve_errors(J, r, n_boot, np.random.default_rng(seed))
        order = sv_.order
        for k, nm in enumerate(names):
            boot[nm] = float(sv_.se_boot[k] * T[k])
    elif n_boot:
        rng = np.random.default_rng(seed)
        draws = []
        opts = dict(law=law, slope=slope, fit_H=fit_H, weighting=weighting, wcp=wcp)
        for _ in range(n_boot):
            fb = model_f - block_resample(resid, b, rng)
            try:
                pb = _solve(x, fb, (xc, E, b0, bx, HH), H0, xc_fixed, **opts)[0]
            except (ValueError, ArithmeticError, np.linalg.LinAlgError):
                failures += 1
                continue
            draws.append((pb[1], s * pb[0], pb[2], s * pb[3], pb[4]))
        if len(draws) >= 2:
            arr = np.array(draws)
            for k, nm in enumerate(_PHYS):
                boot[nm] = float(np.std(arr[:, k], ddof=1))
    chi_max, valid, err, why, flags = law.validity(x - xc, HH)
    dmax = max(float(np.max(x - xc)), 0.0)
    tip_words = (f"sphere R = {law.R:.6g}" if not math.isnan(law.R)
                 else getattr(law.tip, "description", None) or law.tip.name)
    se = {k: float(v) for k, v in se.items()}
    return CurveFit(
        float(E), se["E"], float(HH), se.get("H", 0.0), float(s * xc), se.get("z0", 0.0), float(b0), se["b0"],
        float(s * bx), se.get("b1", 0.0),
        float(np.sqrt(np.mean(resid ** 2))), _ro(resid), _ro(cov), tuple(names), int(x.size), law.model, law.base,
        law.nu, law.R, tip_words, chi_max, dmax, bool(valid), float(err), why, tuple(flags), baseline, weighting, wcp,
        curve.axis, s, tuple(curve.units), curve.source, curve.segment, rng_, range_kind, cond, n_boot, b, phi,
        failures, boot["E"], boot["H"] if fit_H else math.nan,
        boot["z0"] if xc_fixed is None else math.nan, boot["b0"], boot["b1"] if slope else math.nan, law,
        boot_kind if n_boot else "", order)


def _ro(a: np.ndarray) -> np.ndarray:
    out = np.array(a, dtype=float)
    out.setflags(write=False)
    return out
