r"""The moving-block bootstrap of a fit's residuals (issue 25 item 3): standard errors that hold for correlated noise.

The residuals of a force curve are correlated (cantilever thermal motion, drift, the instrument's filters): the
naive standard error ``s^2 (J^T J)^{-1}`` assumes independent residuals and under-covers.  The moving-block bootstrap
(Künsch 1989, *Ann. Statist.* 17, 1217) resamples the residuals in blocks of ``b`` consecutive points, which keeps
their correlation up to lag ``b``; each resampled curve (the fitted model plus the resampled residuals) is fitted
again, and the spread of the refitted parameters is their standard error.

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

import numpy as np

__all__ = ["block_length", "block_resample", "lag1_autocorrelation"]


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
