r"""The JKR limit of the grid's Maugis-Dugdale states: a 2D direct reference for adhesion of any punch (D.12).

(D.12) *JKR as the large-lambda limit.*  At a fixed depth the Maugis-Dugdale force, contact semi-axes and depth of
the grid solver (:func:`~thinlayer.numerics.cohesive.maugis_dugdale_2d`, (D.10)) tend to JKR's like ``lambda^-2``
(the cohesive zone's width is ``O(lambda^-2)``; measured with the axisymmetric solver (D.3)-(D.9) on the sphere,
bonded nu = 0.3, H/R = 0.1 and 1: ``lambda^2 (P_MD - P_JKR)`` changes by 2 % from lambda = 10 to 20, and the
contact radius's ``lambda^2 (c_MD - c_JKR)`` by 3 % from lambda = 2 to 5).  Richardson's value of two lambdas
``l1 < l2``::

    X_JKR = (l2^2 X(l2) - l1^2 X(l1))/(l2^2 - l1^2).

The zone must be resolved by the grid (a cell is far wider than the zone at lambda = 10 on affordable grids), so the
lambdas stay small (default 2 and 3), and the extrapolation's remainder is not small: its estimate is the
extrapolation step ``|X_JKR - X(l2)|`` (measured on the sphere with the axisymmetric solver at lambda = 2, 3: the true
remainder is 0.17-0.31 of it for the force, 0.04 for the radius, away from pull-off: see (D.13)), plus the grid's: the
change of the extrapolated value from ``m = coarse n`` to ``n`` cells times ``m/(n - m)`` (first-order convergence;
until 2026-11-26 the changes at each lambda carried through the Richardson weights, which add what the extrapolation
cancels).  Checked against the axisymmetric JKR solver (J.1)-(J.5) on the sphere (bonded nu = 0.3, n = 128/64, with
(D.13); tests/adhesion/test_elliptic_reference.py, SLOW): H/R = 0.1, force off by 2.3e-4 (estimate 6.6e-4, 1.2 % of
the force; the analog's own remainder is 1.7e-4), radius 6e-4 (estimate 0.020); H/R = 1, force 4.9e-3 (estimate
1.3e-2, 11 %), radius 2.5e-3 (estimate 0.021).  The semi-axes' estimate is dominated by the extrapolation step, which
overstates the radius's remainder about 25 times on the sphere: a third lambda (4 or 5, on a finer grid) would
tighten it (not done).  Cost: 0.5-3 min of CPU per state at n = 128-320.

(D.13) *The extrapolation's remainder, measured on the axisymmetric analog.*  The step is no bound near pull-off on a
thin layer: there the Dugdale stress ``sigma0`` at lambda = 2, 3 is below the tension the JKR edge carries on the
layer, ``sqrt(2 vartheta w/(A H))`` (J.26), the Maugis-Dugdale states are DMT-like (a wide zone, a small contact) and
``lambda^-2`` is not yet their law.  Measured with the exact-kernel solvers on the paraboloid of the mean radius
``R = sqrt(R1 R2)`` at the acceptance cells' depths (Richardson minus the JKR direct solver (J.1)-(J.5), relative;
in brackets the step)::

    layer, H, w, delta             lambda = 2, 3: radius     force              lambda = 6, 8: radius   force
    bonded 0.3, 0.04, 0.02, -0.0076     -14.0 % (17.5 %)   +1.7 % (0.10 %)        +0.52 %          -0.017 %
    frictionless, 0.04, 0.02, -0.0113    -7.6 % (21 %)     +1.9 % (0.30 %)        +0.37 %          -0.013 %
    bonded 0.3, 0.05, 0.02, 0.0044 (R=2) -11.2 % (9.9 %)   +1.4 % (0.09 %)        +0.39 %          -0.010 %
    bonded 0.3, 0.04, 0.005, 0.0108      -0.8 % (7.4 %)    +1.3 % (0.66 %)   (4, 5): +0.6 %         +0.04 %

so the step understates the force's remainder up to 16 times and (R = 2) the radius's.  Hence the analog: the same
Richardson on the axisymmetric Maugis-Dugdale solver (D.3)-(D.9) (no grid) against the JKR direct solver at the same
depth, both on ``r^2/(2R)`` (:func:`axisymmetric_analog`, 3-8 s of CPU); twice its relative remainder, carried to
this punch (the force relative to ``max(|P|, pi w R)``, each semi-axis relative to itself: on a thin layer the edge's
Maugis-Dugdale error is local, the same along the contour), bounds the extrapolation's part of the estimate when it
exceeds the step.  For the sphere it is the remainder itself.  On thin layers the cells choose lambdas whose
``sigma0`` exceeds that edge tension (about 1.2 times: lambda = 4, 5 at w = 0.005 and 6, 7 at w = 0.02 above), on
grids that resolve the zone (two cells or more at the larger lambda).  There the grid's error dominates: on the
sphere of the first row (lambda = 6, 7, n = 256, coarse 192; tests/adhesion/test_elliptic_reference.py, SLOW) the
reference is 3.2 % low in radius and 2.9 % in force (less tension) against the JKR direct solver, inside its estimate
(0.016 against 0.0088 in radius, 0.020 against 0.0048 in force): the grid's changes at lambda = 6 and 7 differ (the
zone is 5 and 2.6 cells wide) and Richardson's weights (2.8, 3.8) amplify the difference.

The contact semi-axes are read off the sub-cell contour (:class:`~thinlayer.numerics.fft2d.Contact2D`) where it
crosses the axes ``x2 = 0`` and ``x1 = 0`` (a punch symmetric about both axes, apex at the origin).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._checks import InputError, check_int, positive
from .._lazy import lazy_module
from ..display import RichDisplay
from ..layers.kernels import LayerKernel
from ._layer import numeric_layer_nu
from .adhesion import adhesive_state
from .cohesive import maugis_dugdale, maugis_dugdale_2d, maugis_lambda, mean_radius

optimize = lazy_module("scipy.optimize")

__all__ = ["JKRLimit2D", "axisymmetric_analog", "jkr_limit_2d"]


@dataclass(frozen=True)
class JKRLimit2D(RichDisplay):
    """JKR state at a prescribed depth from the Maugis-Dugdale states of the grid (D.12).

    Attributes
    ----------
    delta0, force, a1, a2 : float
        float
        Depth, force (negative: pulled) and contact semi-axes along ``x1``, ``x2`` (Richardson in ``lambda^-2``).
    force_error, a1_error, a2_error : float
        float
        Absolute estimates: the extrapolation's (the step, or twice the analog's remainder (D.13)) plus the grid's
        (the extrapolated value's change under refinement).
    lambdas : tuple of float
        Maugis's lambdas used (of the apex's mean radius of curvature).
    rows : tuple of dict
        Per lambda and grid: ``{"lambda", "n", "force", "a1", "a2"}``.
    analog : dict
        The axisymmetric analog (D.13) (empty when not computed): ``{"R", "force", "radius", "force_jkr",
        "radius_jkr"}``: the same Richardson on the mean-curvature paraboloid and the exact JKR state there.
    """

    delta0: float
    force: float
    a1: float
    a2: float
    force_error: float
    a1_error: float
    a2_error: float
    lambdas: tuple
    rows: tuple
    analog: dict = field(default_factory=dict)

    equation = "D.12"

    def latex(self) -> str:
        return (rf"P = {self.force:.8g} \pm {self.force_error:.2g},\quad a_1 = {self.a1:.6g},\ a_2 = {self.a2:.6g}"
                r" \tag{D.12}")

    def text_lines(self) -> list[str]:
        return [f"JKRLimit2D: delta0 = {self.delta0:.8g}, P = {self.force:.8g} +- {self.force_error:.2g}   (D.12)",
                f"  a1 = {self.a1:.8g} +- {self.a1_error:.2g}, a2 = {self.a2:.8g} +- {self.a2_error:.2g}; "
                f"lambda = {', '.join(f'{v:g}' for v in self.lambdas)}"]


def _axis_crossing(contour: tuple, axis: int) -> float:
    """The largest coordinate ``|x_axis|`` where a contour polygon crosses the other axis (linear interpolation)."""
    best = 0.0
    other = 1 - axis
    for line in contour:
        y, x = line[:, other], line[:, axis]
        s = np.nonzero(np.sign(y[:-1]) != np.sign(y[1:]))[0]
        for i in s:
            t = y[i] / (y[i] - y[i + 1]) if y[i] != y[i + 1] else 0.0
            best = max(best, abs(x[i] + t * (x[i + 1] - x[i])))
    if best == 0.0:
        raise InputError("the contact contour does not cross the axes: the punch must have its apex at the origin")
    return best


def _jkr_radius_at_depth(layer: LayerKernel, R: float, delta0: float, H: float | None, mu: float, w: float,
                         nu: float | None, guess: float) -> float:
    """The stable JKR root of ``delta(c) = delta0`` of the paraboloid ``r^2/(2R)`` ((J.5): ``delta`` rises there)."""
    def f(c: float) -> float:
        return adhesive_state(layer, lambda r: r * r / (2.0 * R), c, H, mu, work_of_adhesion=w, nu=nu,
                              energy_route=False).delta - delta0

    hi, f_hi = guess, f(guess)
    for _ in range(40):
        if f_hi > 0:
            break
        hi, f_hi = 1.3 * hi, f(1.3 * hi)
    lo, f_lo = hi / 1.3, f(hi / 1.3)
    for _ in range(40):
        if f_lo < 0:
            return float(optimize.brentq(f, lo, hi, xtol=1e-12 * hi, rtol=1e-12))
        if f_lo >= f_hi:  # delta no longer falls with c: past the displacement-controlled pull-off
            break
        hi, f_hi, lo = lo, f_lo, lo / 1.3
        f_lo = f(lo)
    raise InputError(f"the axisymmetric analog (R = {R:.6g}) has no JKR state at delta0 = {delta0:.6g} "
                     "(below its displacement-controlled pull-off)")


def axisymmetric_analog(layer: LayerKernel, R: float, delta0: float, H: float | None, mu: float, *, w: float,
                        lambdas: tuple, nu: float | None = None) -> dict:
    """(D.13) The Richardson of (D.12) on the paraboloid ``r^2/(2R)`` with the exact kernel, and the exact JKR state.

    The Maugis-Dugdale states of the axisymmetric solver (D.3)-(D.9) at the two lambdas (no grid) and the JKR direct
    solver (J.1)-(J.5) at the same depth: the difference is the extrapolation's own remainder for that paraboloid.

    Returns
    -------
    dict
        ``{"R", "force", "radius"}`` (Richardson's values), ``{"force_jkr", "radius_jkr"}`` (JKR's).
    """
    from ..punch import Punch  # rank 2, below the numerics

    l1, l2 = lambdas
    vt = positive(mu, "mu") / (1.0 - numeric_layer_nu(layer, nu))
    lam_h0 = maugis_lambda(R, 2.0 * vt, w, 1.0)
    vals = []
    for lam in (l1, l2):
        st = maugis_dugdale(layer, Punch.paraboloid(R=R), H, mu, w=w, h0=lam_h0 / lam, delta0=delta0, nu=nu,
                            error_estimate=False)
        vals.append((st.force, st.radius))
    wt1, wt2 = l1 * l1 / (l2 * l2 - l1 * l1), l2 * l2 / (l2 * l2 - l1 * l1)
    P, c = (wt2 * vals[1][i] - wt1 * vals[0][i] for i in (0, 1))
    c_jkr = _jkr_radius_at_depth(layer, R, delta0, H, mu, w, nu, max(c, vals[1][1]))
    js = adhesive_state(layer, lambda r: r * r / (2.0 * R), c_jkr, H, mu, work_of_adhesion=w, nu=nu,
                        energy_route=False)
    return {"R": R, "force": P, "radius": c, "force_jkr": js.force, "radius_jkr": c_jkr}


def jkr_limit_2d(layer: LayerKernel, punch: Any, delta0: float, H: float | None = None, mu: float = 1.0, *,
                 w: float, extent: float, n: int = 128, lambdas: tuple = (2.0, 3.0), nu: float | None = None,
                 refine: bool = True, analog: bool = True, max_iterations: int = 200,
                 coarse: float = 0.5) -> JKRLimit2D:
    """JKR at the depth ``delta0`` as the large-lambda limit of :func:`maugis_dugdale_2d` (D.12).

    Parameters
    ----------
    layer, punch, H, mu, nu
        As for :func:`~thinlayer.numerics.cohesive.maugis_dugdale_2d` (a punch with its apex at the origin,
        symmetric about both axes, e.g. ``Punch.elliptic_paraboloid(R1, R2)``).
    delta0 : float
        Depth (negative when pulled).
    w : float
        Work of adhesion.
    extent : float
        Half-width of the square: it must hold the cohesive zone at the smallest lambda.
    n : int
        Cells per side of the finest grid (the grid estimate also solves on ``round(coarse n)``).
    lambdas : tuple of float
        Two Maugis lambdas (of the mean apex curvature), increasing.
    refine : bool
        Also solve on ``m = round(coarse n)`` cells for the grid's part of the estimate (otherwise it is left out:
        say so): the change of the extrapolated value from ``m`` to ``n`` cells times ``m/(n - m)`` (the error at
        ``n`` for first-order convergence in the cell size; the errors at the two lambdas are correlated, and the
        extrapolated value cancels most of them).
    analog : bool
        Measure the extrapolation's remainder on the axisymmetric analog (D.13) and let twice it (carried to this
        punch) bound the extrapolation's part of the estimate when it exceeds the step.  Without it the estimate is
        the step alone, measured to be untrue near pull-off on thin layers (module docstring).
    max_iterations : int
        Of the fixed point on the zone in each grid solve (:func:`maugis_dugdale_2d`).
    coarse : float
        The coarser grid's fraction of ``n`` (0.5: ``n/2``; 0.75 keeps a narrow zone resolved on the coarse grid).

    Returns
    -------
    JKRLimit2D
    """
    wv = positive(w, "w (work of adhesion)")
    n = check_int(n, "n (cells per side)", 16)
    try:
        l1, l2 = (positive(v, "lambda") for v in lambdas)
    except (TypeError, ValueError):
        raise InputError(f"lambdas must be two positive numbers, increasing, got {lambdas!r:.60}") from None
    if not l1 < l2:
        raise InputError(f"lambdas must increase, got {lambdas!r}")
    if not 0.2 <= coarse <= 0.9:
        raise InputError(f"coarse must be a fraction of n in [0.2, 0.9], got {coarse!r:.30}")
    m_c = max(8, round(coarse * n))
    grids = (n, m_c) if refine else (n,)
    rows, vals = [], {}
    vt = positive(mu, "mu") / (1.0 - numeric_layer_nu(layer, nu))
    lam_h0 = maugis_lambda(mean_radius(punch), 2.0 * vt, wv, 1.0)  # lambda is proportional to 1/h0 (D.8)
    for lam in (l1, l2):
        h0 = lam_h0 / lam
        for m in grids:
            st = maugis_dugdale_2d(layer, punch, delta0, H, mu, w=wv, h0=h0, extent=extent, n=m, nu=nu,
                                   max_iterations=max_iterations)
            row = {"lambda": st.maugis_lambda, "n": m, "force": st.force,
                   "a1": _axis_crossing(st.contact.contour, 0), "a2": _axis_crossing(st.contact.contour, 1)}
            rows.append(row)
            vals[(lam, m)] = row
    wt1, wt2 = l1 * l1 / (l2 * l2 - l1 * l1), l2 * l2 / (l2 * l2 - l1 * l1)
    out, err = {}, {}
    for key in ("force", "a1", "a2"):
        x1, x2 = vals[(l1, n)][key], vals[(l2, n)][key]
        out[key] = wt2 * x2 - wt1 * x1
        err[key] = abs(out[key] - x2)
    found: dict = {}
    if analog:  # (D.13): the extrapolation's own remainder on the mean-curvature paraboloid, twice, carried over
        R = mean_radius(punch)
        found = axisymmetric_analog(layer, R, float(delta0), H, mu, w=wv, lambdas=(l1, l2), nu=nu)
        scale = math.pi * wv * R
        rel_P = abs(found["force"] - found["force_jkr"]) / max(abs(found["force_jkr"]), scale)
        rel_c = abs(found["radius"] / found["radius_jkr"] - 1.0)
        err["force"] = max(err["force"], 2.0 * rel_P * max(abs(out["force"]), scale))
        for key in ("a1", "a2"):
            err[key] = max(err[key], 2.0 * rel_c * out[key])
    if refine:
        for key in ("force", "a1", "a2"):
            rich_c = wt2 * vals[(l2, m_c)][key] - wt1 * vals[(l1, m_c)][key]
            err[key] += abs(out[key] - rich_c) * m_c / (n - m_c)
    return JKRLimit2D(float(delta0), out["force"], out["a1"], out["a2"], err["force"], err["a1"], err["a2"],
                      (l1, l2), tuple(rows), found)
