r"""A published viscoelastic bottom-effect model of the cone, as implemented, against the engine (issue 27 item 5).

Sources.  Efremov et al. (2017) (the Ting model of AFM force curves) and Garcia & Garcia (2018) (the cone's
bottom-effect coefficients) could not be read past their openings (:data:`READ_ATTEMPTS`); nor could the Garcia
group's later open-access papers that print bottom-effect power-law models (Garcia et al. 2020, Sanchez et al. 2021,
Moura et al. 2025: the stored pages end before their models).  What is compared here is therefore the form the first
author of Efremov et al. (2017) implements in his code, a secondary source: ``yu-efremov/ViscoIndent``
(commit c90ee84), files ``Ting_numerical.py`` and ``bottom_effect_correction.py``, whose documentation
(``ViscoIndent_Documentation.pdf``, rev. August 2022) cites Efremov et al. (2017) for the numerical Ting algorithm and
Garcia & Garcia (2018) for the coefficients.  Every quantity below is labelled "as implemented in ViscoIndent".

(PV.1) *The form as implemented* (cone of half-angle theta, ``X = delta tan(theta)/h``, relaxation modulus E(t),
``K_1 = 2 tan(theta)/(pi (1 - nu^2))``, ``B(X) = 1 + 0.721 X + 0.650 X^2 + 0.491 X^3 + 0.225 X^4`` for
``0.45 <= nu < 0.5``):

* approach (growing contact): ``P(t) = K_1 B(X(t)) int_0^t E(t - s) d/ds[delta(s)^2] ds``;
* retraction (Ting): ``P(t) = K_1 B(X(t_1)) int_0^{t_1} E(t - s) d/ds[delta(s)^2] ds`` with ``t_1 <= t_max`` the
  root of ``int_{t_1}^t E(t - s) d delta/ds ds = 0`` (the contact radius at t equals that at t_1).

The bottom-effect factor multiplies the half-space hereditary integral from outside, evaluated at the current depth
(approach) or at ``t_1`` (retraction).  (The stored code applies the coefficients only for ``0.45 <= nu < 0.5``; at
``nu = 0.5`` exactly its cone branch assigns no factor.  The comparison here takes the form at ``nu = 1/2``, where
the coefficients are meant to hold.)

(PV.2) *What the layer gives.*  For a constant Poisson ratio and a growing contact, Lee & Radok's construction holds
on the layer as on the half-space (the contact radius depends on the depth only, not on the modulus): with the
layer's elastic force ``K_1 E delta^2 R(X)`` (R = P/P_S of the engine's cone law)

    P(t) = K_1 int_0^t E(t - s) d/ds[delta(s)^2 R(X(s))] ds              (:func:`thinlayer.contact.hereditary`)

The factor belongs inside the integral.  Outside it, at the current depth, it gives every earlier increment the
current depth's correction and the recent increments, the least relaxed ones, too little: ``d(delta^2 R)`` grows
faster than ``R d(delta^2)`` by ``delta^2 dR``.  The force comes out too small on every growing history with a
relaxing modulus; for a slow ramp (``T >> tau``) the deficit is about ``(E_0 - E_inf)/E_inf (tau/T) X R'/R``.  It
vanishes for an elastic material and for a relaxation much faster or much slower than the ramp, and after a long
hold (only the elastic coefficient error is then left).

(PV.3) *Elastic limit of the retraction.*  For E constant the root is ``delta(t_1) = delta(t)`` and (PV.1) gives the
elastic ``K_1 E B(X) delta^2``: Ting's part reduces to the elastic series, whose error against the layer is that of
the quoted coefficients (:mod:`thinlayer.validation.published_tips`).  Whether Ting's construction itself holds on
the layer is the subject of issue 27 item 2 (the time-stepping direct solver); it is not assumed here.

(PV.4) *A power-law material on a ramp: the factor in closed form.*  For ``E(t) = E_0 (t/t_0)^(-alpha)``, a ramp
``X = v t`` and ``R(X) = sum_k c_k X^k`` (the derived series (PT.3)), ``int_0^t (t - s)^(-alpha) d/ds[s^(k+2)] ds =
(k+2) B(k+2, 1-alpha) t^(k+2-alpha)``, so (PV.2) is the half-space ramp force times

    R_alpha(X) = sum_k c_k w_k(alpha) X^k,   w_k = Gamma(k+3) Gamma(3-alpha) / (2 Gamma(k+3-alpha)),  w_0 = 1,

exact for the series, at every ramp speed (the power law has no time scale).  Outside the integral the factor is
``R(X)`` (all ``w_k = 1``): the force falls short by ``c_1 (w_1 - 1) X = -(4 b_0/pi^2) alpha/(3 - alpha) X`` at
first order.  With all four terms (:func:`power_law_ramp_ratio`, ``nu = 1/2``): ``-0.56 %``, ``-1.95 %``,
``-3.67 %`` at ``X = 0.1, 0.3, 0.5`` for ``alpha = 0.2``; ``-0.87 %``, ``-3.02 %``, ``-5.64 %`` for ``alpha = 0.3``
(a modulus fitted with the factor outside comes out high by about as much).  The engine's hereditary integral of the
power law (:func:`thinlayer.contact.hereditary.hereditary_integral`, product integration) agrees with the closed form
to ``7.4e-6`` and ``2.2e-6`` at 200 and 400 steps (``X = 0.3``, ``alpha = 0.2``; order ``2 - alpha``).  The same
holds for any tip with ``P_hs ~ delta^m`` and a series in ``delta^q``: ``w_k = Gamma(m + kq + 1) Gamma(m + 1 -
alpha)/(Gamma(m + 1) Gamma(m + kq + 1 - alpha))``.  For the sphere (``m = 3/2``, ``q = 1/2``, the series (T.7) in
``chi = sqrt(R delta)/h``, which ViscoIndent also multiplies from outside, with Garcia & Garcia's sphere coefficients)
the factor outside falls short by ``-0.60 %``, ``-2.16 %``, ``-3.99 %`` at ``chi = 0.1, 0.3, 0.5`` for ``alpha =
0.2``; the engine's integral agrees with the closed form to ``4.3e-6`` and ``1.3e-6`` at 200 and 400 steps.

Measured (:func:`loading_table`, ``route="law"``; SLS ``E(t) = E_inf + 4 E_inf exp(-t/tau)``, 45-degree cone,
incompressible layer bonded to the base, ramp ``X = X_max t/T`` on 400 steps then a hold of ``5 tau``; relative
differences against (PV.2) with the engine's any-thickness cone law; "structural": the layer's own R outside the
integral; "impl.": the form as implemented, quoted B outside; "elastic": ``B/R - 1`` at ``X_max``)::

     X_max  T/tau  structural  impl.(ramp)  impl.(hold)    elastic
      0.10   0.10   -5.07e-04    -1.22e-04    +3.69e-04  +3.85e-04
      0.10   1.00   -4.45e-03    -4.06e-03    +2.69e-04  +3.85e-04
      0.10  10.00   -1.19e-02    -1.16e-02    +2.46e-04  +3.85e-04
      0.30   0.10   -1.74e-03    -1.01e-03    +6.75e-04  +7.30e-04
      0.30   1.00   -1.52e-02    -1.45e-02    +3.29e-04  +7.30e-04
      0.30  10.00   -4.16e-02    -4.09e-02    +2.30e-04  +7.30e-04
      0.50   0.10   -3.21e-03    -4.31e-03    -1.21e-03  -1.11e-03
      0.50   1.00   -2.79e-02    -2.90e-02    -1.85e-03  -1.11e-03
      0.50  10.00   -7.72e-02    -7.82e-02    -2.07e-03  -1.11e-03

The same table with the derived series (PT.3) in place of the law (``route="series"``) differs from it by at most
``5e-4`` (``2e-6`` at ``X_max = 0.1``): the series' own truncation.  The hereditary integral of (PV.2) is
checked against mpmath quadrature of the closed-form integrand (the tests) and, in the errata registry, against an
exact evaluation (``-4.15 %`` at ``X_max = 0.3``, ``T = 10 tau``, the derived series).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from .._checks import InputError
from .._lazy import lazy_module
from .published_sources import READ_ATTEMPTS
from .published_tips import GARCIA_2018_CONE, derived_cone_coefficients, derived_cone_ratio

optimize = lazy_module("scipy.optimize")

__all__ = ["READ_ATTEMPTS", "VISCOINDENT", "QUOTED_RATIO", "ramp_hold", "triangle", "engine_ratio",
           "lee_radok", "factor_outside", "ting_as_implemented", "LoadingRow", "loading_table", "format_table",
           "power_law_weights", "power_law_ramp_ratio"]

#: the secondary source: the first author's code (files and commit read in the snapshot)
VISCOINDENT = ("yu-efremov/ViscoIndent, files Ting_numerical.py and bottom_effect_correction.py (commit c90ee84); "
               "documentation ViscoIndent_Documentation.pdf (rev. August 2022)")

#: B(X) as ViscoIndent applies it to a cone (Garcia & Garcia's coefficients as quoted, 0.45 <= nu < 0.5)
QUOTED_RATIO = GARCIA_2018_CONE.ratio


def _history(t: Any, X: Any) -> tuple[np.ndarray, np.ndarray]:
    t = np.asarray(t, dtype=float)
    X = np.asarray(X, dtype=float)
    if t.ndim != 1 or X.shape != t.shape or t.size < 3 or not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
        raise InputError("times must be 3 or more strictly increasing finite values, with one depth X each")
    if not np.all(np.isfinite(X)) or np.any(X < 0) or X[0] != 0:
        raise InputError("depths X = delta tan(theta)/h must be finite, >= 0, and start at 0 (first contact)")
    return t, X


def ramp_hold(X_max: float, T: float, hold: float, n: int = 400) -> tuple[np.ndarray, np.ndarray]:
    """A ramp ``X = X_max t/T`` on ``n`` steps, then a hold of length ``hold`` on ``n`` steps."""
    if not (0 < X_max <= 1.0 and T > 0 and hold >= 0 and 10 <= n <= 20000):
        raise InputError("ramp_hold needs 0 < X_max <= 1 (the thick range), T > 0, hold >= 0, 10 <= n <= 20000")
    t1 = np.linspace(0.0, T, n + 1)
    X1 = X_max * t1 / T
    if hold == 0:
        return t1, X1
    t2 = T + np.linspace(0.0, hold, n + 1)[1:]
    return np.concatenate([t1, t2]), np.concatenate([X1, np.full(n, X_max)])


def triangle(X_max: float, T: float, n: int = 400) -> tuple[np.ndarray, np.ndarray]:
    """Approach ``X = X_max t/T`` then retraction at the same speed, ``n`` steps each."""
    if not (0 < X_max <= 1.0 and T > 0 and 10 <= n <= 20000):
        raise InputError("triangle needs 0 < X_max <= 1 (the thick range), T > 0, 10 <= n <= 20000")
    t = np.linspace(0.0, 2 * T, 2 * n + 1)
    return t, X_max * (1.0 - np.abs(t - T) / T)


@lru_cache(maxsize=4)
def _law(nu: float):
    from ..contact.any_thickness_tips import TIPS_TABLE_PATH, cone_law_from

    with np.load(TIPS_TABLE_PATH) as z:
        data = {k: z[k] for k in z.files}
    return cone_law_from(data, nu, "bonded", with_estimate=False)


def engine_ratio(X: Any, nu: float = 0.5, route: str = "law") -> np.ndarray:
    """``R = P/P_S`` of the cone on the bonded layer at ``X``: the any-thickness law (``route="law"``, within 7.4e-5
    of the direct solver for X <= 1) or the derived series (PT.3) (``route="series"``, within 1e-6 for X <= 0.1).
    ``R(0) = 1``.
    """
    X = np.asarray(X, dtype=float)
    if route == "series":
        return np.asarray(derived_cone_ratio(X, nu))
    if route != "law":
        raise InputError(f"route must be 'law' or 'series', got {route!r}")
    out = np.ones_like(X)
    pos = X > 0
    out[pos] = _law(float(nu)).ratios(2.0 * X[pos] / math.pi)[0]
    return out


def lee_radok(material: Any, t: Any, X: Any, ratio=engine_ratio) -> np.ndarray:
    """(PV.2): ``P/K_1 = int_0^t E(t - s) d/ds[X^2 R(X)] ds`` (45 degrees, h = 1), by the engine's hereditary
    integral (:func:`thinlayer.contact.hereditary.hereditary_integral`, exact for piecewise-linear histories of
    ``X^2 R``).  Valid while the contact grows.
    """
    from ..contact.hereditary import hereditary_integral

    t, X = _history(t, X)
    return hereditary_integral(material, t, X * X * ratio(X))


def factor_outside(material: Any, t: Any, X: Any, ratio=QUOTED_RATIO) -> np.ndarray:
    """(PV.1), approach: ``P/K_1 = R(X(t)) int_0^t E(t - s) d/ds[X^2] ds``, the factor outside the integral
    (ViscoIndent's form with ``ratio=QUOTED_RATIO``; with the engine's ratio, the structural part alone).
    """
    from ..contact.hereditary import hereditary_integral

    t, X = _history(t, X)
    return ratio(X) * hereditary_integral(material, t, X * X)


def _integrated_modulus(material: Any, x: np.ndarray) -> np.ndarray:
    """``I(x) = int_0^x E(u) du`` of a Prony series (closed form, x >= 0)."""
    terms = getattr(material, "terms", None)
    if terms is None:
        raise InputError("ting_as_implemented takes a Prony series (or StandardLinearSolid)")
    out = material.E_inf * x
    for e, tau in terms:
        out = out + e * tau * -np.expm1(-x / tau)
    return out


def ting_as_implemented(material: Any, t: Any, X: Any, ratio=QUOTED_RATIO) -> tuple[np.ndarray, np.ndarray]:
    """(PV.1) over an approach-retraction history: ``(P/K_1, t_1)`` at every node (45 degrees, h = 1).

    ``X^2`` is taken linear in time between nodes (as :func:`lee_radok`); on retraction ``t_1`` is the exact root of
    ``int_{t_1}^t E(t - s) X'(s) ds = 0`` for the piecewise-linear ``X`` (Brent's method on the closed-form
    integrated modulus).  After the contact is lost (no root) the force is 0 and ``t_1 = nan``.  O(N^2), N <= 4001.
    """
    t, X = _history(t, X)
    if t.size > 4001:
        raise InputError(f"ting_as_implemented: at most 4001 nodes (O(N^2)), got {t.size}")
    m = int(np.argmax(X))
    if np.any(np.diff(X[: m + 1]) < 0) or np.any(np.diff(X[m:]) > 0):
        raise InputError("ting_as_implemented takes one approach then one retraction (X rising, then falling)")
    P = np.zeros_like(t)
    t1 = np.full_like(t, np.nan)
    P[: m + 1] = factor_outside(material, t[: m + 1], X[: m + 1], ratio)
    t1[: m + 1] = t[: m + 1]
    v = np.diff(X) / np.diff(t)  # slope of X on each step
    r = np.diff(X * X) / np.diff(t)  # slope of X^2 on each step (linear in time)
    for n in range(m + 1, t.size):
        tn = t[n]
        w = _integrated_modulus(material, tn - t[:n]) - _integrated_modulus(material, tn - t[1: n + 1])
        phi = np.concatenate([np.cumsum((v[:n] * w)[::-1])[::-1], [0.0]])  # phi_k = int_{t_k}^{t_n} E X'
        k = next((k for k in range(m - 1, -1, -1) if phi[k] >= 0.0), None)
        if k is None:  # no root: the contact is lost from here on
            break
        if v[k] <= 0:  # a step without approach speed: the root is its end
            root = t[k + 1]
        else:
            target = _integrated_modulus(material, np.array(tn - t[k + 1])) - phi[k + 1] / v[k]

            def gap(x: float) -> float:
                return float(_integrated_modulus(material, np.array(x)) - target)

            lo, hi = tn - t[k + 1], tn - t[k]
            x = hi if gap(hi) <= 0 else optimize.brentq(gap, lo, hi, xtol=1e-14 * max(hi, 1e-300), rtol=1e-15)
            root = tn - x
        j = int(np.searchsorted(t, root, side="right")) - 1
        j = min(j, m - 1)
        full = _integrated_modulus(material, tn - t[:j]) - _integrated_modulus(material, tn - t[1: j + 1])
        part = _integrated_modulus(material, np.array(tn - t[j])) - _integrated_modulus(material, np.array(tn - root))
        Xr = X[j] + v[j] * (root - t[j])
        P[n] = float(ratio(np.array(Xr))) * (float(np.dot(r[:j], full)) + r[j] * float(part))
        t1[n] = root
    return P, t1


@dataclass(frozen=True)
class LoadingRow:
    """One row of :func:`loading_table`: relative differences against (PV.2) (the engine's law inside)."""

    X_max: float
    T_over_tau: float
    structural_end_ramp: float  # engine's R outside / R inside - 1, at the end of the ramp
    quoted_end_ramp: float      # ViscoIndent's form (quoted B outside) / (PV.2) - 1, end of the ramp
    quoted_end_hold: float      # the same after a hold of 5 tau
    elastic: float              # B(X_max)/R(X_max) - 1: the elastic limit (coefficients only)


def loading_table(X_values=(0.1, 0.3, 0.5), T_over_tau=(0.1, 1.0, 10.0), E_ratio: float = 5.0, nu: float = 0.5,
                  route: str = "law", n: int = 400) -> tuple[LoadingRow, ...]:
    """(PV.1) against (PV.2) on ramp-holds of a standard linear solid ``E(t) = E_inf (1 + (E_ratio - 1) e^{-t/tau})``
    (tau = 1), for each ``X_max`` and ramp time ``T``.
    """
    from ..contact.materials import StandardLinearSolid

    if not E_ratio >= 1:
        raise InputError(f"E_ratio = E0/E_inf must be >= 1, got {E_ratio!r}")
    mat = StandardLinearSolid(float(E_ratio), 1.0, 1.0)

    def R(x):
        return engine_ratio(x, nu, route)

    rows = []
    for Xm in X_values:
        for T in T_over_tau:
            t, X = ramp_hold(float(Xm), float(T), 5.0, n)
            exact = lee_radok(mat, t, X, R)
            outside = factor_outside(mat, t, X, R)
            quoted = factor_outside(mat, t, X, QUOTED_RATIO)
            e = n  # index of the end of the ramp
            rows.append(LoadingRow(float(Xm), float(T), float(outside[e] / exact[e] - 1),
                                   float(quoted[e] / exact[e] - 1), float(quoted[-1] / exact[-1] - 1),
                                   float(QUOTED_RATIO(Xm) / R(np.array([Xm]))[0] - 1)))
    return tuple(rows)


def format_table(rows) -> str:
    """The rows of :func:`loading_table` as text."""
    lines = [f"{'X_max':>6} {'T/tau':>6} {'structural':>11} {'impl.(ramp)':>12} {'impl.(hold)':>12} {'elastic':>10}"]
    for r in rows:
        lines.append(f"{r.X_max:6.2f} {r.T_over_tau:6.2f} {r.structural_end_ramp:+11.2e} {r.quoted_end_ramp:+12.2e} "
                     f"{r.quoted_end_hold:+12.2e} {r.elastic:+10.2e}")
    return "\n".join(lines)


def power_law_weights(alpha: float, order: int = 4, m: float = 2.0, q: float = 1.0) -> np.ndarray:
    """(PV.4): ``w_k = Gamma(m + k q + 1) Gamma(m + 1 - alpha)/(Gamma(m + 1) Gamma(m + k q + 1 - alpha))``,
    ``k = 0..order`` (``w_0 = 1``), for a tip with ``P_hs ~ delta^m`` and a series in ``delta^q``: the cone
    (``m = 2``, ``q = 1``: ``Gamma(k+3) Gamma(3-alpha)/(2 Gamma(k+3-alpha))``) or the sphere (``m = 3/2``,
    ``q = 1/2``, the series in ``chi = sqrt(R delta)/h``).
    """
    if isinstance(alpha, bool) or not isinstance(alpha, (int, float)) or not 0 < alpha < 1:
        raise InputError(f"alpha (E ~ t^-alpha) must be a number in (0, 1), got {alpha!r}")
    p = m + q * np.arange(order + 1)
    lg = np.vectorize(math.lgamma)
    return np.exp(lg(p + 1.0) + math.lgamma(m + 1.0 - alpha) - math.lgamma(m + 1.0) - lg(p + 1.0 - alpha))


def power_law_ramp_ratio(X: Any, alpha: float, nu: float = 0.5, inside: bool = True, tip: str = "cone") -> np.ndarray:
    """(PV.4): the bottom-effect factor of the ramp force of a power-law material on the bonded layer, ``R_alpha``
    (``inside=True``, exact for the derived series) or, for comparison, the elastic ``R`` that the factor-outside
    form uses.  ``tip="cone"``: ``X = delta tan(theta)/h`` and the series (PT.3); ``tip="sphere"``: ``X = chi =
    sqrt(R delta)/h`` and the engine's thick-layer series (T.7).
    """
    if tip == "cone":
        coeffs, m, q = derived_cone_coefficients(nu), 2.0, 1.0
    elif tip == "sphere":
        from ..asymptotics.thick_layer import thick_sphere_series
        from ..layers.kernels import BondedLayer

        layer = BondedLayer(float(nu))  # BondedLayer(0.5) is the incompressible layer
        coeffs = np.array([float(v) for v in thick_sphere_series(4).coefficients(layer)[0]])
        m, q = 1.5, 0.5
    else:
        raise InputError(f"tip must be 'cone' or 'sphere', got {tip!r}")
    w = power_law_weights(alpha, coeffs.size - 1, m, q) if inside else np.ones(coeffs.size)
    return np.polynomial.polynomial.polyval(np.asarray(X, dtype=float), coeffs * w)
