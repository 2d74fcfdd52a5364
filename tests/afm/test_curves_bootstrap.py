"""The moving-block bootstrap of fit_curve (issue 25 item 3, ``bootstrap_method="block"``; the default AR-sieve errors
are tested in test_bootstrap_coverage.py).

Synthetic approach curves (Hertz written out here) with AR(1) noise of known ``phi``: the
naive standard error is too small by about ``sqrt((1 + phi)/(1 - phi))`` (the variance inflation of a smooth
regressor under AR(1) noise) and under-covers; the moving-block bootstrap's error matches the spread of E over seeds
and covers.  The block-length rule is checked against the Politis-White formula summed as series.
"""
import math

import numpy as np
import pytest

from thinlayer.afm.bootstrap import block_length, block_resample, lag1_autocorrelation
from thinlayer.afm.curve_fit import fit_curve
from thinlayer.afm.curves import curve_from_arrays
from thinlayer.contact.any_thickness import force_any_thickness

pytestmark = pytest.mark.xdist_group("afm-laws")
R = 10e-6  # nanite's default tip radius of hertz_para


def _synthetic(seed, H=None, n=600, noise=2e-11, slope=5e-5, ar=0.0):
    """A tip-position approach curve: baseline b0 + b1 (z - z0), then the law (Hertz written out here, or (T.7))."""
    rng = np.random.default_rng(seed)
    z = np.linspace(2e-6, -0.8e-6, n)  # approach: the tip position falls into the sample
    z0, E, b0 = 0.3e-6, 2000.0, -4e-10
    d = np.clip(z0 - z, 0, None)
    if H is None:
        P = 4 / 3 * E / (1 - 0.25) * math.sqrt(R) * d ** 1.5
    else:
        P = force_any_thickness(d, R, H, E=E, nu=0.5)
    e = rng.normal(0, noise, n)
    for k in range(1, n):
        e[k] = ar * e[k - 1] + math.sqrt(1 - ar * ar) * e[k]
    return z, b0 + slope * (z - z0) + P + e, dict(E=E, z0=z0, b0=b0, b1=slope)


def _ar1(phi, n, seed):
    rng = np.random.default_rng(seed)
    e = rng.normal(size=n)
    for k in range(1, n):
        e[k] = phi * e[k - 1] + math.sqrt(1 - phi * phi) * e[k]
    return e


def test_block_length_is_politis_white_for_ar1():
    """b = (2 G^2/D)^{1/3} n^{1/3}, D = (4/3) g(0)^2, with G = sum |k| phi^|k| and g(0) = sum phi^|k| summed here as
    series (Politis & White 2004, Patton et al. 2009), at the phi the residuals show."""
    n = 20000
    r = _ar1(0.6, n, 1)
    b, phi = block_length(r)
    assert phi == pytest.approx(0.6, abs=0.02) and phi == lag1_autocorrelation(r)
    k = np.arange(1, 2000)
    G = 2 * np.sum(k * phi ** k)
    g0 = 1 + 2 * np.sum(phi ** k)
    assert b == math.ceil((2 * G ** 2 / (4 / 3 * g0 ** 2)) ** (1 / 3) * n ** (1 / 3))
    assert block_length(np.random.default_rng(2).normal(size=500))[0] <= 2  # white noise: (nearly) single points
    assert block_length(_ar1(0.99, 100, 3))[0] <= 25  # at most n/4


def test_block_resample_takes_runs_of_consecutive_points():
    r = np.arange(103.0)
    out = block_resample(r, 10, np.random.default_rng(0))
    assert out.size == 103
    steps = np.diff(out).reshape(-1)
    assert np.all(steps[np.arange(steps.size) % 10 != 9] == 1)  # within a block: consecutive


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_bootstrap_widens_the_error_for_correlated_noise_only(seed):
    """AR(1) noise, phi = 0.7: the bootstrap error is 1.5 to 3.5 times the naive one (theory: 2.38); white noise:
    0.7 to 1.4 times."""
    z, F, _ = _synthetic(1000 + seed, n=600, ar=0.7, slope=0.0)
    r = fit_curve(curve_from_arrays(z, F, axis="tip position"), punch=R, bootstrap=50, seed=seed,
                  bootstrap_method="block")
    assert 1.5 < r.E_se_boot / r.E_se < 3.5 and r.phi > 0.5 and r.block_length > 5
    z, F, _ = _synthetic(2000 + seed, n=600, ar=0.0, slope=0.0)
    w = fit_curve(curve_from_arrays(z, F, axis="tip position"), punch=R, bootstrap=50, seed=seed,
                  bootstrap_method="block")
    assert 0.7 < w.E_se_boot / w.E_se < 1.4 and w.block_length <= 2
    assert "block bootstrap" in str(r) and r.as_dict()["E_se_boot"] == r.E_se_boot


@pytest.mark.slow
def test_coverage_over_seeds():
    """60 seeds, phi = 0.7, n = 800, 100 refits each (measured: naive coverage 0.70, bootstrap 0.88 of the nominal
    0.95; the bootstrap error's mean 2.27 against the spread of E 2.34; the naive error 1.06)."""
    errs, naive, boot = [], [], []
    for seed in range(60):
        z, F, truth = _synthetic(1000 + seed, n=800, ar=0.7, slope=0.0)
        r = fit_curve(curve_from_arrays(z, F, axis="tip position"), punch=R, bootstrap=100, seed=seed,
                      bootstrap_method="block")
        errs.append(r.E - truth["E"])
        naive.append(r.E_se)
        boot.append(r.E_se_boot)
    errs, naive, boot = map(np.array, (errs, naive, boot))
    spread = float(np.sqrt(np.mean(errs ** 2)))
    assert np.mean(np.abs(errs) < 1.96 * naive) < 0.8  # the naive error under-covers
    assert np.mean(np.abs(errs) < 1.96 * boot) > 0.83  # the bootstrap covers (nominal 0.95, binomial sd 0.03)
    assert 0.8 < np.mean(boot) / spread < 1.25 and np.mean(naive) / spread < 0.6
