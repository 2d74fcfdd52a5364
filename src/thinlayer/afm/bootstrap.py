r"""Uncertainty of a force-curve fit under correlated residuals (issue 25 item 3): the studentised AR-sieve bootstrap,
and the moving-block bootstrap it replaces.

The residuals of a force curve are correlated (cantilever thermal motion, drift, the instrument's filters): the
naive standard error ``s^2 (J^T J)^{-1}`` assumes independent residuals and under-covers.

Studentised AR-sieve bootstrap (the default of ``fit_curve(bootstrap=N)``).  The residuals are fitted by an
autoregression AR(p) (Yule-Walker by the Durbin-Levinson recursion; the order by AIC up to ``10 log10 n``: the
sieve of Bühlmann 1997, *Bernoulli* 3, 123).  Its autocovariance ``gamma`` (the sample's up to lag p, the AR
recursion beyond) gives the sandwich covariance of the least-squares estimate,

    ``cov = J^+ Sigma J^{+T}``,  ``J^+ = (J^T J)^{-1} J^T``,  ``Sigma_{ij} = gamma_{|i - j|}``

(a HAC covariance with an AR-sieve spectral estimate at every frequency, not only at zero).  Its own error is not
small: the long-run variance of strongly correlated noise is poorly known from one curve (at phi = 0.9 and 800
points the standard error itself scatters by 15 %, and Yule-Walker's ``phi`` is biased low by about ``(1 + 3 phi)/n``,
8 % low in the standard error).  So ``N`` series are drawn from the fitted AR(p) with resampled innovations (the sieve
bootstrap); each gives the residuals of the fit linearised at the solution, ``(1 - J J^+) e*`` (one Gauss-Newton
step: exact for the parameters that enter linearly, within the noise's second order for the others), the AR(p) is
fitted to them again (order by AIC again) and gives the variance ``var*``.  The spread of ``var*`` about ``var``
measures the estimator in the bootstrap world:

* bias: ``var_c = var^2/mean(var*)`` (the bootstrap bias correction, Efron & Tibshirani 1993, ch. 10, on the
  ratio scale);
* scatter: ``var_c`` is taken as a scaled chi-square with Satterthwaite's ``dof = 2/var(log var*)`` degrees of freedom
  (Satterthwaite 1946), so the 95 % interval is ``theta +- t_{dof, 0.975} sqrt(var_c)``, a studentised interval.

The result reports ``se_boot = t_{dof, 0.975} sqrt(var_c)/1.96``: the standard error that makes ``theta +- 1.96
se_boot`` that interval.  Measured coverage: :data:`MEASURED_COVERAGE`.

Why the moving-block bootstrap under-covered (measured on AR(1) noise, 800 points, 300 seeds; the oracle
sandwich with the true covariance covers 0.94-0.95, so the estimate's distribution is normal enough): its variance
estimate is biased low by ``sum |k| gamma_k/(b g(0))`` (Künsch 1989), which at the Politis-White length is of the
order of its own scatter by construction (the length minimises the mean-square error, not the coverage): 6 %, 10 %,
16 % low in the standard error at phi = 0.3, 0.7, 0.9, with a scatter of 9-17 %; coverage 0.925, 0.86, 0.81 (80
seeds).  The AR-sieve sandwich removes most of the bias (2 %, 3 %, 8 % low; coverage 0.94, 0.92, 0.91 over 300
seeds); the bias correction and the studentisation cover the rest (tests/afm/test_bootstrap_coverage.py).

Moving-block bootstrap (``bootstrap_method="block"``, kept for comparison).  The moving-block bootstrap (Künsch 1989,
*Ann. Statist.* 17, 1217) resamples the residuals in blocks of ``b`` consecutive points, which keeps their
correlation up to lag ``b``; each resampled curve (the fitted model plus the resampled residuals) is fitted again,
and the spread of the refitted parameters is their standard error.

Block length.  :func:`block_length` fits an AR(1) to the residuals (``phi``: their lag-1 autocorrelation) and takes
the optimal moving-block length of Politis & White (2004, *Econometric Rev.* 23, 53; corrected by Patton, Politis &
White 2009, *Econometric Rev.* 28, 372), ``b = (2 G^2/D)^{1/3} n^{1/3}`` with ``D = (4/3) g(0)^2``, for the AR(1)
autocovariance ``gamma_k = sigma^2 phi^|k|``: ``G = sum |k| gamma_k = 2 sigma^2 phi/(1 - phi)^2``, ``g(0) = sum
gamma_k = sigma^2 (1 + phi)/(1 - phi)``, so

    ``b = 6^{1/3} (phi/(1 - phi^2))^{2/3} n^{1/3}``,

rounded up and kept in ``[1, n/4]`` (``b = 1``, the ordinary residual bootstrap, for ``phi <= 0``).  (The ``arch``
package implements the general Politis-White rule for a series; this is its AR(1) plug-in, for regression residuals,
which arch does not resample.)
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["ARSieve", "MEASURED_COVERAGE", "SieveErrors", "ar_sieve", "block_length", "block_resample",
           "lag1_autocorrelation", "sieve_errors"]


#: Coverage of ``E +- 1.96 E_se_boot`` measured with fit_curve(bootstrap=100) (nominal 0.95; binomial sd 0.011):
#: Hertz curves of 800 points with AR(1) noise, ``{phi: (coverage, seeds)}`` (the curves of
#: tests/afm/test_bootstrap_coverage.py's THINLAYER_SLOW=1 study, seeds 10000..10399, 2026-11-26; the naive interval
#: covered 0.835, 0.608, 0.368 of the same curves).  Residual resampling of the shipped JPK curve
#: (fmt-jpk-fd_spot3-0192, blocks of 200 of its own residuals, 100 curves): 0.95 +- 0.02 (naive 0.93).
MEASURED_COVERAGE = {0.3: (0.9525, 400), 0.7: (0.9575, 400), 0.9: (0.9425, 400)}


def lag1_autocorrelation(r: np.ndarray) -> float:
    """The lag-1 autocorrelation of ``r`` (mean removed); 0 for a constant series."""
    x = np.asarray(r, dtype=float) - float(np.mean(r))
    den = float(x @ x)
    return float(x[1:] @ x[:-1]) / den if den > 0 else 0.0


def block_length(r: np.ndarray) -> tuple[int, float]:
    """``(b, phi)``: the moving-block length for the residuals ``r`` and their lag-1 autocorrelation (module
    docstring: the Politis-White length under an AR(1) fit).
    """
    n = int(np.size(r))
    phi = min(lag1_autocorrelation(r), 0.99)
    if phi <= 0 or n < 8:
        return 1, phi
    b = math.ceil(6 ** (1 / 3) * (phi / (1 - phi * phi)) ** (2 / 3) * n ** (1 / 3))
    return int(min(max(b, 1), max(n // 4, 1))), phi


def block_resample(r: np.ndarray, b: int, rng: np.random.Generator) -> np.ndarray:
    """One moving-block resample of ``r``: ``ceil(n/b)`` blocks of ``b`` consecutive values, each starting at a
    uniformly drawn point of ``[0, n - b]``, joined and cut to ``n`` values.
    """
    r = np.asarray(r)
    n = r.size
    k = -(-n // b)
    starts = rng.integers(0, n - b + 1, size=k)
    idx = (starts[:, None] + np.arange(b)[None, :]).ravel()[:n]
    return r[idx]


@dataclass(frozen=True)
class ARSieve:
    """An AR(p) fitted to a series: ``x_t = sum_i a_i x_{t-i} + e_t``, ``var e = s2``; ``acf`` the sample
    autocovariance at lags ``0..p`` (which the Yule-Walker fit reproduces).
    """

    a: np.ndarray
    s2: float
    acf: np.ndarray

    @property
    def order(self) -> int:
        return int(self.a.size)

    def autocovariance(self, n: int) -> np.ndarray:
        """``gamma_0 .. gamma_{n-1}`` of the fitted process: the sample's to lag p, the AR recursion beyond."""
        from scipy import signal

        p = self.order
        g = np.zeros(n)
        m = min(n, p + 1)
        g[:m] = self.acf[:m]
        if p == 0 or n <= p + 1:
            return g
        zi = signal.lfiltic([1.0], np.r_[1.0, -self.a], self.acf[p:0:-1])
        g[p + 1:] = signal.lfilter([1.0], np.r_[1.0, -self.a], np.zeros(n - p - 1), zi=zi)[0]
        return g

    def innovations(self, x: np.ndarray) -> np.ndarray:
        """The centred innovations ``e_t``, ``t >= p``, of the series ``x`` (mean removed)."""
        from scipy import signal

        e = signal.lfilter(np.r_[1.0, -self.a], [1.0], x - x.mean())[self.order:]
        return e - e.mean()


def _acf(x: np.ndarray, lags: int) -> np.ndarray:
    """Biased sample autocovariances (divided by n, mean removed) at lags ``0..lags``; rows of a 2-d ``x``."""
    x = x - x.mean(axis=-1, keepdims=True)
    n = x.shape[-1]
    if x.ndim == 1 and lags <= 16:  # a few lags: dot products beat the FFT
        return np.array([x[:n - k] @ x[k:] for k in range(min(lags, n - 1) + 1)]) / n
    f = np.fft.rfft(x, 2 * n, axis=-1)
    return np.fft.irfft(f * np.conj(f), 2 * n, axis=-1)[..., :lags + 1] / n


def ar_sieve(x: np.ndarray, max_order: int | None = None) -> ARSieve:
    """The AR(p) of the sieve: Yule-Walker for ``p = 0 .. max_order`` (default ``10 log10 n``, at most ``n/4``),
    the order of least AIC ``n log s2_p + 2 p``.
    """
    x = np.asarray(x, dtype=float)
    n = x.size
    pmax = int(10 * math.log10(n)) if max_order is None else int(max_order)
    pmax = max(0, min(pmax, n // 4))
    ac = _acf(x, pmax)
    if not ac[0] > 0:
        return ARSieve(np.zeros(0), 0.0, ac[:1])
    # Durbin-Levinson: the Yule-Walker fits of every order p <= pmax in one pass (each solve_toeplitz of order p
    # gives the same coefficients, tests/afm/test_bootstrap_coverage.py), their innovation variances s2_p
    best = (n * math.log(ac[0]), np.zeros(0), float(ac[0]))
    a = np.zeros(0)
    v = float(ac[0])
    for p in range(1, pmax + 1):
        k = (ac[p] - a @ ac[p - 1:0:-1]) / v if p > 1 else ac[1] / v
        a = np.r_[a - k * a[::-1], k]
        v *= 1.0 - k * k
        if not v > 0:
            break
        aic = n * math.log(v) + 2 * p
        if aic < best[0]:
            best = (aic, a, v)
    _, a, s2 = best
    return ARSieve(np.asarray(a, dtype=float), s2, ac[:a.size + 1])


@dataclass(frozen=True)
class SieveErrors:
    """The AR-sieve errors of the parameters (module docstring), in the units of the Jacobian's columns.

    Attributes
    ----------
    se : numpy.ndarray
        The AR-sieve sandwich standard errors.
    bias : numpy.ndarray
        ``var/mean(var*)``: the bootstrap's bias factor of the variance (> 1: the sandwich is low).
    dof : numpy.ndarray
        Satterthwaite's degrees of freedom of the corrected variance, ``2/var(log var*)``.
    se_boot : numpy.ndarray
        ``sqrt(var bias) t_{dof, 0.975}/1.96``: ``theta +- 1.96 se_boot`` is the 95 % interval.
    order : int
        The AR order.
    """

    se: np.ndarray
    bias: np.ndarray
    dof: np.ndarray
    se_boot: np.ndarray
    order: int


def _sandwich_kernels(Jp: np.ndarray) -> np.ndarray:
    """``C[k, l] = sum_t Jp[k, t] Jp[k, t + l]`` (l >= 0), so that ``var_k = gamma_0 C[k, 0] + 2 sum_l gamma_l
    C[k, l]``.
    """
    n = Jp.shape[1]
    f = np.fft.rfft(Jp, 2 * n, axis=1)
    return np.fft.irfft(f * np.conj(f), 2 * n, axis=1)[:, :n]


def _variances(C: np.ndarray, g: np.ndarray) -> np.ndarray:
    return C[:, 0] * g[0] + 2.0 * (C[:, 1:] @ g[1:])


def sieve_errors(J: np.ndarray, r: np.ndarray, n_boot: int, rng: np.random.Generator,
                 level: float = 0.95) -> SieveErrors:
    """Studentised AR-sieve errors of a least-squares fit with Jacobian ``J`` (n x k) and residuals ``r`` (module
    docstring); ``n_boot`` series drawn from the fitted AR(p) with resampled innovations.  With ``n_boot = 0``: the
    sandwich errors alone.
    """
    from scipy import signal, stats

    J = np.asarray(J, dtype=float)
    r = np.asarray(r, dtype=float)
    n = r.size
    Jp = np.linalg.pinv(J)
    C = _sandwich_kernels(Jp)
    sieve = ar_sieve(r)
    var = np.maximum(_variances(C, sieve.autocovariance(n)), 0.0)
    se = np.sqrt(var)
    z = float(stats.norm.ppf(0.5 + level / 2))
    if n_boot < 1 or not np.all(se > 0):
        return SieveErrors(se, np.ones(se.size), np.full(se.size, math.inf), se, sieve.order)
    eps = sieve.innovations(r)
    p = sieve.order
    rho = float(np.max(np.abs(np.roots(np.r_[1.0, -sieve.a])))) if p else 0.0
    burn = max(100, 10 * p) if not 0 < rho < 1 else max(100, 10 * p, min(int(math.log(1e-8) / math.log(rho)), 20 * n))
    den = np.r_[1.0, -sieve.a]
    vb = np.empty((n_boot, se.size))
    for i in range(n_boot):
        e = signal.lfilter([1.0], den, rng.choice(eps, n + burn))[burn:] if p else rng.choice(eps, n)
        rb = e - J @ (Jp @ e)  # the residuals of the linearised refit
        sb = ar_sieve(rb)  # the order chosen again, as on the data
        vb[i] = _variances(C, sb.autocovariance(n))
    vb = np.maximum(vb, 1e-300)
    bias = var / vb.mean(axis=0)
    dof = 2.0 / np.maximum(np.var(np.log(vb), axis=0, ddof=1), 1e-12) if n_boot > 1 else np.full(se.size, math.inf)
    scale = stats.t.ppf(0.5 + level / 2, dof) / z
    return SieveErrors(se, bias, dof, se * np.sqrt(bias) * scale, p)
