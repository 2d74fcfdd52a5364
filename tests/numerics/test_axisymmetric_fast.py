"""Issue 18 item 4: the faster axisymmetric solver (spherical Bessel functions by recurrences over the order, the
Galerkin matrix by a BLAS product) against mpmath, the previous evaluation and a high-resolution reference.
"""
from __future__ import annotations

import mpmath
import numpy as np
import pytest
from scipy import special

from thinlayer import BondedLayer, Punch
from thinlayer.numerics import _spectral, solve_axisymmetric
from thinlayer.numerics._spectral import spherical_jn_even


def _exact(n: int, t: float) -> float:
    try:
        return float(mpmath.sqrt(mpmath.pi / (2 * mpmath.mpf(t))) * mpmath.besselj(2 * n + mpmath.mpf(1) / 2, t))
    except ValueError:  # mpmath gives up far below the double range (high order, tiny t): the value is 0 there
        return 0.0 if 2 * n > 20 * max(t, 1.0) else float("nan")


@pytest.mark.parametrize("modes", [4, 30, 84, 300])
def test_spherical_jn_even_against_mpmath(modes):
    K = 2 * (modes - 1)
    rng = np.random.default_rng(modes)
    # tiny t, the turning region t ~ order (downward recurrence), and t >= K (upward)
    t = np.concatenate([[1e-3, 0.02, 0.5], rng.uniform(0.5, K + 5, 40), rng.uniform(K, min(40 * K + 50, 2000), 20)])
    J = spherical_jn_even(t, modes)
    assert J.shape == (t.size, modes) and np.all(np.isfinite(J))
    for i in range(t.size):
        for n in rng.choice(modes, size=min(modes, 6), replace=False):
            ex = _exact(int(n), float(t[i]))
            assert abs(J[i, n] - ex) <= 4e-16 + 1e-14 * abs(ex), (t[i], n)
    ref = special.spherical_jn(2 * np.arange(modes)[None, :], t[:, None])
    assert np.abs(J - ref).max() < 5e-15


def _previous_transforms(t, modes, scale):
    n = np.arange(modes, dtype=float)
    return _spectral.beta(n) / scale * special.spherical_jn(2 * np.arange(modes)[None, :], t[:, None])


def _previous_matrix(self, c):
    M = np.eye(self.modes)
    if self.t.size:
        lm1 = np.asarray(self.layer.L_numeric(self.t * (self.H / c), "numpy"), dtype=float) - 1.0
        M = M + np.einsum("km,kn->mn", self.G * (self.w * lm1)[:, None], self.G)
    return M


@pytest.mark.parametrize("c_over_H", [10.0, 40.0])
def test_same_solution_as_the_previous_evaluation(monkeypatch, c_over_H):
    layer, punch, H = BondedLayer(0.3), Punch.paraboloid(R=1000.0), 1.0
    d0 = c_over_H**2 / 2000.0
    new = solve_axisymmetric(layer, punch, d0, H)
    monkeypatch.setattr(_spectral, "_normalised_transforms", _previous_transforms)
    monkeypatch.setattr(_spectral.Discretisation, "matrix", _previous_matrix)
    old = solve_axisymmetric(layer, punch, d0, H)
    assert new.modes == old.modes
    # the same digits: far below the solver's own error estimate
    assert new.radius == pytest.approx(old.radius, rel=1e-12)
    assert new.force == pytest.approx(old.force, rel=1e-11)
    assert np.abs(new.pressure - old.pressure).max() <= 1e-11 * old.pressure.max()


def test_thin_layer_against_a_high_resolution_reference():
    # H/a = 0.0125 (the benchmark case): the default modes against 1.5 times as many
    layer, punch, H = BondedLayer(0.3), Punch.paraboloid(R=1000.0), 1.0
    d0 = 80.0**2 / 2000.0
    res = solve_axisymmetric(layer, punch, d0, H)
    ref = solve_axisymmetric(layer, punch, d0, H, n=int(1.5 * res.modes), error_estimate=False)
    assert res.force_error < 1e-10 and res.radius_error / res.radius < 1e-8
    assert res.force == pytest.approx(ref.force, rel=1e-10)
    assert res.radius == pytest.approx(ref.radius, rel=1e-9)
    r = np.linspace(0, 0.999 * res.radius, 400)
    assert np.abs(res.pressure_at(r) - ref.pressure_at(r)).max() <= 1e-7 * ref.pressure.max()
