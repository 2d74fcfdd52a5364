"""The AR-sieve errors of fit_curve (issue 25 item 3): intervals that cover at their nominal 95 % under correlated
residuals (thinlayer.afm.bootstrap's module docstring: why the moving-block bootstrap did not).

Default: the method on a linear least-squares problem shaped like a force curve (a Hertz column after a contact point
and a baseline), 40 seeds of AR(1) noise: cheap, and it fails for the naive error (coverage ~0.6) and for an
estimate biased low by 20 %.  THINLAYER_SLOW=1: 400 seeds of fit_curve itself on AR(1) phi = 0.3, 0.7, 0.9, with the
binomial interval of the coverage.
"""
import math

import numpy as np
import pytest

from thinlayer.afm.bootstrap import ar_sieve, sieve_errors

pytestmark = pytest.mark.xdist_group("afm-laws")


def _ar1(phi, n, rng):
    """Unit-variance stationary AR(1): e_k = phi e_{k-1} + sqrt(1 - phi^2) w_k, e_0 ~ N(0, 1)."""
    from scipy import signal

    w = rng.normal(size=n)
    w[0] /= math.sqrt(1 - phi * phi)  # the stationary start
    return signal.lfilter([math.sqrt(1 - phi * phi)], [1.0, -phi], w)


def test_ar_sieve_recovers_an_ar1_and_its_autocovariance():
    """gamma_k = phi^k for a unit-variance AR(1) (the recursion against the closed form), phi within its error."""
    rng = np.random.default_rng(5)
    x = _ar1(0.8, 20000, rng)
    s = ar_sieve(x, max_order=1)
    assert s.order == 1 and abs(s.a[0] - 0.8) < 3 * math.sqrt((1 - 0.64) / 20000)
    g = s.autocovariance(50)
    assert np.allclose(g / g[0], s.a[0] ** np.arange(50), rtol=1e-12, atol=1e-15)
    y = _ar1(0.5, 3000, rng) + 0.3 * np.roll(_ar1(0.5, 3000, rng), 1)
    s3 = ar_sieve(y, max_order=3)  # Durbin-Levinson against scipy's Toeplitz solve of the Yule-Walker equations
    from scipy import linalg

    if s3.order:
        assert np.allclose(s3.a, linalg.solve_toeplitz(s3.acf[:-1], s3.acf[1:]), rtol=1e-10, atol=1e-12)
    w = ar_sieve(rng.normal(size=4000))  # white noise: AIC may keep a few lags, all negligible
    assert w.order <= 8 and np.all(np.abs(w.a) < 0.08)


def test_sieve_interval_covers_on_correlated_noise():
    """40 seeds, AR(1) phi = 0.7, 300 points: the interval theta +- 1.96 se_boot covers the true slope at >= 0.83
    (nominal 0.95; binomial sd 0.034), the naive one does not; the error is 2-3.5 times the naive one."""
    n, phi = 300, 0.7
    x = np.linspace(0, 1, n)
    J = np.column_stack([np.clip(x - 0.6, 0, None) ** 1.5, np.ones(n)])
    Jp = np.linalg.pinv(J)
    cover, naive, ratio = [], [], []
    for seed in range(40):
        rng = np.random.default_rng(seed)
        y = J @ np.array([2.0, 0.1]) + 0.01 * _ar1(phi, n, rng)
        theta = Jp @ y
        r = y - J @ theta
        se_naive = math.sqrt(r @ r / (n - 2) * np.linalg.inv(J.T @ J)[0, 0])
        out = sieve_errors(J, r, 40, rng)
        cover.append(abs(theta[0] - 2.0) < 1.96 * out.se_boot[0])
        naive.append(abs(theta[0] - 2.0) < 1.96 * se_naive)
        ratio.append(out.se_boot[0] / se_naive)
    assert np.mean(cover) >= 0.83
    assert np.mean(naive) < 0.8
    assert 2.0 < np.median(ratio) < 3.5  # the variance inflation sqrt((1 + phi)/(1 - phi)) = 2.38 and the t widening


def test_fit_curve_reports_the_sieve_errors():
    """One fit: the sieve is the default, its text says so, the interval is wider than the naive one."""
    from thinlayer.afm.curve_fit import fit_curve
    from thinlayer.afm.curves import curve_from_arrays

    rng = np.random.default_rng(3)
    n, R = 300, 10e-6
    z = np.linspace(2e-6, -0.8e-6, n)
    d = np.clip(0.3e-6 - z, 0, None)
    F = -4e-10 + 4 / 3 * 2000 / 0.75 * math.sqrt(R) * d ** 1.5 + 2e-11 * _ar1(0.7, n, rng)
    r = fit_curve(curve_from_arrays(z, F, axis="tip position"), punch=R, bootstrap=30, seed=1)
    assert r.bootstrap_method == "sieve" and r.ar_order >= 1
    assert 1.5 < r.E_se_boot / r.E_se < 4.0
    assert "AR-sieve" in str(r) and r.as_dict()["ar_order"] == r.ar_order
    with pytest.raises(ValueError, match="bootstrap_method"):
        fit_curve(curve_from_arrays(z, F, axis="tip position"), punch=R, bootstrap=3, bootstrap_method="naive")


@pytest.mark.slow
@pytest.mark.parametrize("phi", [0.3, 0.7, 0.9])
def test_fit_curve_coverage_400_seeds(phi):
    """fit_curve(bootstrap=100) on 400 synthetic curves (800 points, Hertz, AR(1) noise): the coverage of E +- 1.96
    E_se_boot is nominal: 0.95 within two binomial sd (0.011), i.e. >= 0.928."""
    from thinlayer.afm.curve_fit import fit_curve
    from thinlayer.afm.curves import curve_from_arrays

    n, R, E = 800, 10e-6, 2000.0
    z = np.linspace(2e-6, -0.8e-6, n)
    d = np.clip(0.3e-6 - z, 0, None)
    F0 = -4e-10 + 4 / 3 * E / 0.75 * math.sqrt(R) * d ** 1.5
    hits = []
    for seed in range(400):
        rng = np.random.default_rng(10_000 + seed)
        r = fit_curve(curve_from_arrays(z, F0 + 2e-11 * _ar1(phi, n, rng), axis="tip position"), punch=R,
                      bootstrap=100, seed=seed)
        hits.append(abs(r.E - E) < 1.96 * r.E_se_boot)
    cov = float(np.mean(hits))
    assert cov >= 0.95 - 2 * math.sqrt(0.95 * 0.05 / 400), cov
