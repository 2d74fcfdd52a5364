"""Numerically stable evaluation of layer kernels L(u) and L(u)/u in numpy and mpmath.

Kept apart from the symbolic core (:mod:`thinlayer.layers.kernels`), which dispatches here.

Bonded layer (2.3).  Dividing numerator and denominator by ``kappa e^{2u}`` and writing
``E = e^{-2u}``, ``S(x) = sinh x - x``::

    L(u) = [2 kappa S(2u) E + 4u (kappa - 1) E] / [kappa (1 + E^2) + (1 + kappa^2 + 4u^2) E]

Every term is non-negative for kappa > 1 (nu < 1/2), so there is no cancellation, and
nothing overflows: ``S(2u) E`` is ``(1 - E^2)/2 - 2u E`` for ``2u >= 2`` and a Taylor
series (times E) below.  ``L(u)/u`` uses the same form with ``S(2u)/u`` from the series,
so it tends to ``A`` without a 0/0 as u -> 0.

Frictionless base: ``L(u) = (cosh 2u - 1)/(sinh 2u + 2u) = (1 - E)^2/(1 - E^2 + 4uE)`` with
``1 - E = -expm1(-2u)``: again free of cancellation.

Extremes: every u >= 0 is admissible, including ``1e300`` and ``inf`` (L = 1, L/u = 0 there).  The
products ``u E`` and ``u^2 E`` are taken as 0 once ``E = e^{-2u}`` underflows (u > 372, where they are
below 1e-318), so ``u^2`` never overflows (it would above 1.3e154) and ``inf * 0`` never occurs.  A nan or
a negative u is refused by both backends with the same ValueError (:func:`check_u`).
"""
from __future__ import annotations

import math

import gmpy2
import mpmath
import numpy as np
from mpmath.libmp import dps_to_prec

from .._checks import InputError
from .._mpfr import to_mpf, to_mpfr

# Taylor coefficients of S(x)/x^3 = sum_k x^(2k) / (2k+3)!, enough for x <= 2 to 1e-19.
_S_TERMS = 14
_S_COEFFS = np.array([1.0 / math.factorial(2 * k + 3) for k in range(_S_TERMS)][::-1])
_SERIES_CUT = 2.0


def _u_message(bad) -> str:
    return f"u must be a real number >= 0 (inf allowed), got u = {float(bad)!r}"


def check_u(u):
    """``u`` as a float array (numpy backend): every entry >= 0 (inf allowed); nan or u < 0 is a ValueError.

    The message is the same as :func:`check_u_mpmath`'s for the same bad value.
    """
    u = np.asarray(u, dtype=float)
    bad = np.isnan(u) | (u < 0)
    if np.any(bad):
        raise InputError(_u_message(u[bad].flat[0]))
    return u


def check_u_mpmath(u) -> mpmath.mpf:
    """``u`` as an mpmath number (mpmath backend): >= 0 (inf allowed); nan or u < 0 is a ValueError."""
    if isinstance(u, np.ndarray):
        if u.ndim != 0:
            raise InputError(f"the mpmath backend takes one number u, got an array of shape {u.shape}")
        u = u.item()
    u = mpmath.mpf(u)
    if mpmath.isnan(u) or u < 0:
        raise InputError(_u_message(u))
    return u


def _times_E(a: np.ndarray, E: np.ndarray) -> np.ndarray:
    """``a * E`` with the product 0 where E underflowed (a may be huge or inf there)."""
    with np.errstate(over="ignore", invalid="ignore"):
        return np.where(E > 0, a * E, 0.0)


def _sinh_minus_x_over_x3(x: np.ndarray) -> np.ndarray:
    """(sinh x - x)/x^3 for 0 <= x <= 2 by its Taylor series (Horner in x^2)."""
    return np.polyval(_S_COEFFS, x * x)


def _scaled_sinh_minus_x(x: np.ndarray) -> np.ndarray:
    """(sinh x - x) e^{-x} for x >= 0, accurate to rounding everywhere."""
    x = np.asarray(x, dtype=float)
    small = x < _SERIES_CUT
    out = np.empty_like(x)
    xs = x[small]
    out[small] = xs**3 * _sinh_minus_x_over_x3(xs) * np.exp(-xs)
    xl = x[~small]
    E = np.exp(-xl)
    out[~small] = -0.5 * np.expm1(-2 * xl) - _times_E(xl, E)
    return out


def bonded_numpy(u, kappa: float, over_u: bool = False):
    """L(u) (or L(u)/u) of the bonded layer (2.3), vectorised over u >= 0 (inf included: L = 1, L/u = 0)."""
    u = check_u(u)
    with np.errstate(over="ignore", under="ignore"):  # e^{-2u} -> 0 and -2u -> -inf are intended
        return _bonded_numpy(u, kappa, over_u)


def _bonded_numpy(u: np.ndarray, kappa: float, over_u: bool):
    scalar = u.ndim == 0
    u = np.atleast_1d(u)
    E = np.exp(-2 * u)
    uE = _times_E(u, E)
    den = kappa * (1 + E * E) + (1 + kappa**2) * E + 4 * _times_E(np.where(E > 0, u, 0.0) ** 2, E)
    if over_u:
        # S(2u)/u = 8 u^2 * S(x)/x^3 for small x; for large u divide the scaled form by u
        x = 2 * u
        small = x < _SERIES_CUT
        su = np.empty_like(u)
        su[small] = 8 * u[small] ** 2 * _sinh_minus_x_over_x3(x[small]) * E[small]
        su[~small] = _scaled_sinh_minus_x(x[~small]) / u[~small]
        num = 2 * kappa * su + 4 * (kappa - 1) * E
    else:
        num = 2 * kappa * _scaled_sinh_minus_x(2 * u) + 4 * (kappa - 1) * uE
    out = num / den
    return out[0] if scalar else out


def frictionless_numpy(u, over_u: bool = False):
    """L(u) (or L(u)/u) of a layer on a frictionless base, vectorised over u >= 0 (inf included)."""
    u = check_u(u)
    with np.errstate(over="ignore", under="ignore"):
        return _frictionless_numpy(u, over_u)


def _frictionless_numpy(u: np.ndarray, over_u: bool):
    E = np.exp(-2 * u)
    a = -np.expm1(-2 * u)
    den = -np.expm1(-4 * u) + 4 * _times_E(u, E)
    with np.errstate(invalid="ignore", divide="ignore"):
        # below u = 1: L/u = (a/u)^2/(den/u), with a/u -> 2 and den/u -> 8 at u = 0 (L/u -> 1/2; no
        # underflow of a^2 for tiny u); above: L = a^2/den directly (-> 1, and L/u -> 0, at u = inf)
        us = np.where((u > 0) & (u < 1), u, 1.0)
        ratio = np.where(u == 0, 0.5, (a / us) ** 2 / (den / us))
        big = u >= 1
        L_big = a * a / np.where(big, den, 1.0)
        if over_u:
            return np.where(big, L_big / np.where(big, u, 1.0), ratio)
        return np.where(big, L_big, u * ratio)


def _extra_digits(u) -> int:
    """Guard digits for L(u) at small u: ``3 log10(1/u) + 5`` (the cancellation in ``sinh x - x``), 5 for u >= 1."""
    u = abs(mpmath.mpf(u))
    if u == 0:
        return 0
    if u >= 1:
        return 5
    f = float(u)  # a double's log10 where u is one (the count is a guard, not a result)
    lg = math.log10(f) if f > 1e-300 else float(mpmath.log10(u))
    return max(0, int(-3 * lg) + 5)


def _mpfr(extra: int) -> gmpy2.context:
    """An MPFR context at mpmath's working precision plus ``extra`` digits, with MPFR's whole exponent range."""
    return gmpy2.context(precision=dps_to_prec(mpmath.mp.dps + extra), emin=gmpy2.get_emin_min(),
                         emax=gmpy2.get_emax_max())


def bonded_mpmath(u, kappa, over_u: bool = False):
    """L(u) (or L(u)/u) of the bonded layer (2.3) in mpmath at the current precision.

    Uses the scaled form of the module docstring; the small-u cancellation in
    ``sinh x - x`` is absorbed by temporarily raising the working precision.  The arithmetic runs in MPFR (gmpy2)
    at mpmath's precision plus those guard digits and is rounded once to mpmath's precision: the same bits as in
    mpmath's own arithmetic (tests/layers/test_extremes.py), about four times faster.
    """
    u = check_u_mpmath(u)
    kappa = mpmath.mpf(kappa)
    if u == 0:
        return 4 * (kappa - 1) / (kappa + 1) ** 2 if over_u else mpmath.mpf(0)
    if mpmath.isinf(u):
        return mpmath.mpf(0) if over_u else mpmath.mpf(1)
    U, K = to_mpfr(u), to_mpfr(kappa)
    with _mpfr(_extra_digits(u)):  # MPFR at mpmath's precision + guard digits: one rounding to mpmath's at the end
        x = 2 * U
        E = gmpy2.exp(-x)
        S = (gmpy2.sinh(x) - x) * E if x < 40 else (1 - E * E) / 2 - x * E
        num = 2 * K * S + 4 * U * (K - 1) * E
        den = K * (1 + E * E) + (1 + K * K + 4 * U * U) * E
        val = num / den
        if over_u:
            val = val / U
    return to_mpf(val)


def frictionless_mpmath(u, over_u: bool = False):
    """L(u) (or L(u)/u) of the layer on a frictionless base, in mpmath."""
    u = check_u_mpmath(u)
    if u == 0:
        return mpmath.mpf(1) / 2 if over_u else mpmath.mpf(0)
    if mpmath.isinf(u):
        return mpmath.mpf(0) if over_u else mpmath.mpf(1)
    U = to_mpfr(u)
    with _mpfr(_extra_digits(u)):
        E = gmpy2.exp(-2 * U)
        a = -gmpy2.expm1(-2 * U)
        val = a * a / (-gmpy2.expm1(-4 * U) + 4 * U * E)
        if over_u:
            val = val / U
    return to_mpf(val)
