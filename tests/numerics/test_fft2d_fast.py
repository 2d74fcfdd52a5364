"""Issue 18 item 3: the faster solve_2d (padding by the kernel's reach, DCT spectrum, iteration on the overlap box,
no BLAS in the loop) gives the results of the whole-grid solve, and its memory estimate bounds what it uses.
"""
from __future__ import annotations

import tracemalloc

import numpy as np
import pytest
from scipy import signal

from thinlayer import BondedLayer, HalfSpace, Punch
from thinlayer.numerics import _polonsky_keer, fft2d, solve_2d
from thinlayer.numerics._influence import Convolver as _Convolver
from thinlayer.numerics.fft2d import influence_coefficients

SPHERE = dict(punch=Punch.paraboloid(R=100.0), delta0=0.5, H=1.0)  # overlap radius 10 H


def _direct(C: np.ndarray, p: np.ndarray) -> np.ndarray:
    """The aperiodic sum by scipy.signal.convolve2d with the full even kernel (an independent route)."""
    N1, N2 = p.shape
    K = C[np.ix_(np.abs(np.arange(1 - N1, N1)), np.abs(np.arange(1 - N2, N2)))]  # K[i + N1 - 1, ...] = C(|i|, ...)
    full = signal.convolve2d(p, K, mode="full")
    return full[N1 - 1: 2 * N1 - 1, N2 - 1: 2 * N2 - 1]


@pytest.mark.parametrize("shape", [(70, 70), (64, 45), (23, 81)])
def test_reach_padded_rectangular_convolution_equals_direct_sum(shape):
    # Delta = H: the kernel reaches 51 cells, less than the grid -> padding N + 51 instead of 2N - 1
    n = max(shape)
    C = influence_coefficients(BondedLayer(0.3), 1.0, 1.0, n)[: shape[0], : shape[1]]
    conv = _Convolver(C, 1)
    if min(shape) == 70:
        assert conv.padded[0] < 2 * 70 - 1
    p = np.random.default_rng(3).uniform(0, 1, shape)
    ref = _direct(C, p)
    out = np.empty(shape)
    assert conv(p, out=out) is out
    assert np.allclose(out, ref, rtol=0, atol=1e-14 * np.abs(ref).max())


def test_half_space_kernel_reaches_across_the_grid():
    C = influence_coefficients(HalfSpace(), None, 0.1, 40, nu=0.3)
    conv = _Convolver(C, 2)
    assert conv.padded[0] >= 2 * 40 - 1
    p = np.random.default_rng(4).uniform(0, 1, (40, 40))
    ref = _direct(C, p)
    assert np.allclose(conv(p), ref, rtol=0, atol=1e-14 * np.abs(ref).max())


def _whole_grid(monkeypatch):
    """Make the iteration run on the whole grid from the start (the previous algorithm)."""
    monkeypatch.setattr(fft2d, "_overlap_slices", lambda w: (slice(0, w.shape[0]), slice(0, w.shape[1])))


def test_box_iteration_equals_whole_grid_iteration(monkeypatch):
    layer = BondedLayer(0.3)
    box = solve_2d(layer, **SPHERE, n=160)
    _whole_grid(monkeypatch)
    whole = solve_2d(layer, **SPHERE, n=160)
    assert box.residual <= 1e-10 and whole.residual <= 1e-10
    assert box.force == pytest.approx(whole.force, rel=1e-9)
    assert np.abs(box.pressure - whole.pressure).max() <= 1e-8 * whole.max_pressure
    assert np.abs(box.gap - whole.gap).max() <= 1e-8 * SPHERE["delta0"]
    assert box.contact_area == pytest.approx(whole.contact_area, rel=1e-9)


def test_too_small_box_is_continued_on_the_whole_grid(monkeypatch):
    # a box that misses part of the overlap: the check on the whole grid finds penetrating cells and iterates on
    layer = BondedLayer(0.3)
    ref = solve_2d(layer, **SPHERE, n=160)
    monkeypatch.setattr(fft2d, "_overlap_slices", lambda w: (slice(40, 120), slice(30, 130)))
    res = solve_2d(layer, **SPHERE, n=160)
    assert res.residual <= 1e-10
    assert res.force == pytest.approx(ref.force, rel=1e-9)
    assert np.abs(res.pressure - ref.pressure).max() <= 1e-8 * ref.max_pressure


def test_force_mode_unchanged_by_the_box():
    # force prescribed: the whole grid from the start, and the same solution as the depth it finds
    layer = BondedLayer(0.3)
    by_depth = solve_2d(layer, **SPHERE, n=128)
    by_force = solve_2d(layer, SPHERE["punch"], H=1.0, n=128, force=by_depth.force, extent=by_depth.x1[-1]
                        + by_depth.spacing / 2)
    assert by_force.delta0 == pytest.approx(SPHERE["delta0"], rel=1e-6)


def test_dot_without_blas_matches_numpy():
    rng = np.random.default_rng(5)
    a, b = rng.normal(size=(300, 200)), rng.normal(size=(300, 200))
    assert _polonsky_keer._dot(a, b) == pytest.approx(float(np.vdot(a, b)), rel=1e-12)


@pytest.mark.parametrize("n", [128, 256])
def test_memory_estimate_bounds_the_measured_peak(n):
    layer = BondedLayer(0.3)
    solve_2d(layer, **SPHERE, n=128)  # imports and caches first
    tracemalloc.start()
    try:
        res = solve_2d(layer, **SPHERE, n=n)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert res.residual <= 1e-10
    assert peak <= fft2d.memory_estimate(n)
