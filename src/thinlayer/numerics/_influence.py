"""The layer's surface operator on a grid: influence coefficients and their aperiodic FFT convolution (1.5), (2.1).

Private to :mod:`thinlayer.numerics.fft2d` (its module docstring, sections "Influence coefficients" and
"Convolution and contact algorithm", derives the formulas): the coefficients ``C[k, l]`` (Love's square
plus the cell-integrated layer correction ``g_c``), the product ``u = C * p`` by FFT on a zero-padded
grid, and the memory bound that every grid size is checked against before any work.
"""
from __future__ import annotations

import math
import numbers
from collections.abc import Callable
from functools import lru_cache
from typing import Any

import numpy as np

from .._checks import InputError, InputTypeError, check_bounded, positive
from .._lazy import lazy_module
from ..errors import boundary
from ..layers.kernels import LayerKernel
from ._layer import U_MAX, gauss_panels, numeric_layer_nu, panel_count

sfft, interpolate, special = (lazy_module(f"scipy.{m}") for m in ("fft", "interpolate", "special"))  # on first use

_R_CUT = 50.0  # in units of H: the layer kernel 1/(2 pi r) + g_c(r) is below 1e-15/H beyond
_TABLE_STEP = 1.0 / 40.0  # spacing of the g_c table, in units of H
_CELL_GAUSS = 4  # Gauss-Legendre points per direction for the cell integral of g_c
_RHO_TABLE = 52  # the per-layer tables of H g_c(rho H) reach rho = 52 at most: past _R_CUT with room for two cells
_MAX_N = 4096
#: Largest estimated memory of one solve (bytes), :func:`memory_estimate`: it admits n <= 3600.
MAX_BYTES = 2 * 1024**3


def memory_estimate(n: int) -> int:
    """Bytes of the arrays of a solve on an n x n grid (an upper bound), checked against :data:`MAX_BYTES`.

    The check on the whole grid holds the most: the spectrum's quadrant ``16 (M/2 + 1)^2`` and the column
    buffer ``16 M (M/2 + 1)`` of the convolution, ``M <= 2 next_fast_len(n)`` the padded length, its row-block
    buffer and temporaries (4 x 8 MiB at most), at most 13 float and 4 boolean n x n arrays (Phi, the overlap, the
    coefficients, pressure, displacement, gap and the iteration's work arrays).  Measured peaks (tracemalloc,
    the sphere of ``benchmarks/bench_numerics.py``): 122 MiB at n = 1024 (estimate 249 MiB), 440 MiB at
    n = 2048 (estimate 717 MiB).
    """
    M = 2 * sfft.next_fast_len(n, real=True)  # the largest padding: a kernel that reaches across the grid
    h = M // 2
    setup = 8 * 4_000_000 * 2  # the J0 block of layer_correction_kernel and its argument
    return 16 * (h + 1) ** 2 + 16 * M * (h + 1) + 4 * Convolver._BLOCK_BYTES + (8 * 13 + 4) * n * n + setup


# --------------------------------------------------------------------------- influence coefficients
def _love_square(X: np.ndarray, Y: np.ndarray, h: float) -> np.ndarray:
    """``iint dy/|y|`` over the square ``|y1 - X| < h, |y2 - Y| < h`` (Love's closed form)."""

    def F(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        # a asinh(b/|a|) -> 0 as a -> 0: guard the division, the factor a makes the term vanish
        return (a * np.arcsinh(b / np.where(a == 0, 1.0, np.abs(a)))
                + b * np.arcsinh(a / np.where(b == 0, 1.0, np.abs(b))))

    return F(X + h, Y + h) - F(X - h, Y + h) - F(X + h, Y - h) + F(X - h, Y - h)


def _t_quadrature(rho_max: float) -> tuple[np.ndarray, np.ndarray]:
    """Composite 16-point Gauss-Legendre nodes on [0, U_MAX], one J0(t rho_max) period per panel."""
    return gauss_panels(U_MAX, panel_count(U_MAX, min(0.5, 2.0 * math.pi / max(rho_max, 1e-300))), 16)


@boundary
def layer_correction_kernel(layer: LayerKernel, H: float, r: Any) -> np.ndarray:
    """``g_c(r) = (1/(2 pi H)) int_0^oo (L(t) - 1) J0(t r/H) dt``: the layer's correction to Boussinesq.

    The surface Green's function of the layer (2.1) is ``1/(2 pi r) + g_c(r)`` (divided by
    vartheta).  ``g_c`` is smooth, ``g_c(r) -> -1/(2 pi r)`` as r/H -> oo.

    Parameters
    ----------
    layer : LayerKernel
        A layer kernel with numeric evaluation (``BondedLayer(0.3)``, ``FrictionlessLayer()``).
    H : float
        Layer thickness.
    r : array_like
        Radii >= 0.

    Returns
    -------
    numpy.ndarray
        g_c at ``r`` (zero for the half-space).
    """
    r = np.asarray(r, dtype=float)
    if not layer.has_thickness:  # the half-space: L = 1
        return np.zeros_like(r)
    rho = r.ravel() / H
    t, w = _t_quadrature(float(rho.max(initial=0.0)))
    wl = w * (np.asarray(layer.L_numeric(t, "numpy"), dtype=float) - 1.0)
    out = np.empty_like(rho)
    step = max(1, 4_000_000 // t.size)  # bound the J0 matrix to ~32 MB
    for s in range(0, rho.size, step):
        out[s:s + step] = special.j0(np.outer(rho[s:s + step], t)) @ wl
    return (out / (2.0 * math.pi * H)).reshape(r.shape)


def _uniform_spline(rr: np.ndarray, values: np.ndarray) -> Callable[[np.ndarray], np.ndarray]:
    """The cubic spline of ``g_c`` through uniform knots ``rr`` (``g_c'(0) = 0``, not-a-knot at the far end),
    evaluated without a search: the interval is ``floor(r/step)``.

    The same piecewise cubic as scipy's ``CubicSpline(r)`` for ``0 <= r <= last knot`` (a point on a knot may take
    the neighbouring piece: equal to rounding), several times faster on the ~10^6 points of a large grid.
    """
    spline = interpolate.CubicSpline(rr, values, bc_type=((1, 0.0), "not-a-knot"))
    x, c = spline.x, spline.c
    inv, last = (len(x) - 1) / (x[-1] - x[0]), len(x) - 2
    c0, c1, c2, c3 = (np.ascontiguousarray(c[k]) for k in range(4))

    def ev(r: np.ndarray) -> np.ndarray:
        i = np.minimum(((r - x[0]) * inv).astype(np.intp), last)
        dx = r - x[i]
        out = c0[i] * dx
        out += c1[i]
        out *= dx
        out += c2[i]
        out *= dx
        out += c3[i]
        return out

    return ev


def _g_c_spline(layer: LayerKernel, H: float, r_tab: float) -> Callable[[np.ndarray], np.ndarray]:
    """``g_c`` on ``[0, r_tab]`` as a cubic spline of knot spacing ``<= H/40`` (at least 64 intervals).

    ``g_c(r) = G(r/H)/H`` with ``G`` a function of the layer alone.  Where the spacing is ``H/40`` the spline is
    the layer's table of ``G`` on ``0 <= rho <= m`` (``m = ceil(r_tab/H)``, :func:`_layer_table`), scaled: its
    knot values are computed once per layer and process, whatever the grid.  A domain much smaller than H
    (``r_tab < 1.6 H``: a finer spacing) or wider than 52 H gets a table of its own.
    """
    m = math.ceil(r_tab / H)
    if _TABLE_STEP * H * 64 <= r_tab and m <= _RHO_TABLE:
        try:
            G = _layer_table(layer, m)
        except TypeError:  # a layer that cannot be a cache key
            G = None
        if G is not None:
            inv_H = 1.0 / H

            def g_c(r: np.ndarray) -> np.ndarray:
                out = G(r * inv_H)
                out *= inv_H
                return out

            return g_c
    npts = max(65, math.ceil(r_tab / (_TABLE_STEP * H)) + 1)
    rr = np.linspace(0.0, r_tab, npts)
    return _uniform_spline(rr, layer_correction_kernel(layer, H, rr))


@lru_cache(maxsize=64)
def _layer_table(layer: LayerKernel, m: int) -> Callable[[np.ndarray], np.ndarray]:
    """The layer's ``G(rho) = H g_c(rho H)`` as a cubic spline on the knots ``rho = 0, 1/40, ..., m``.

    The knot values come in unit intervals of rho (:func:`_layer_segment`), each by ``layer_correction_kernel``
    at ``H = 1`` with the J0 quadrature its own largest rho needs: the same values whatever grid asked first.
    """
    knots = np.concatenate([_layer_segment(layer, k) for k in range(m)] + [_layer_segment(layer, m)[:1]])
    rr = np.arange(knots.size) * _TABLE_STEP
    return _uniform_spline(rr, knots)


@lru_cache(maxsize=4096)
def _layer_segment(layer: LayerKernel, k: int) -> np.ndarray:
    """``G`` at the 40 knots ``rho = k, k + 1/40, ..., k + 39/40`` (read-only)."""
    per = round(1.0 / _TABLE_STEP)
    out = layer_correction_kernel(layer, 1.0, (k * per + np.arange(per)) * _TABLE_STEP)
    out.setflags(write=False)
    return out


@boundary
def influence_coefficients(layer: LayerKernel, H: float | None, spacing: float, n: int, *,
                           nu: float | None = None, mu: float = 1.0) -> np.ndarray:
    """Influence coefficients ``C[k, l]``: u3 at offset ``(k Delta, l Delta)`` from a cell under unit pressure.

    See the docstring of :mod:`thinlayer.numerics.fft2d` for the formula (Love's rectangle + cell-integrated
    layer correction).
    The kernel is even in both offsets, so the quadrant ``0 <= k, l < n`` defines it.

    Parameters
    ----------
    layer : LayerKernel
        Layer kernel; ``HalfSpace()`` gives Boussinesq's coefficients.
    H : float or None
        Layer thickness (ignored by ``HalfSpace``).
    spacing : float
        Cell size Delta.
    n : int
        Number of offsets per direction.
    nu, mu
        float
        Poisson ratio (only for layers that carry none) and shear modulus: ``vartheta = mu/(1 - nu)``.

    Returns
    -------
    numpy.ndarray
        Array of shape (n, n).

    Examples
    --------
    Self-influence of a square on the half-space: ``4 Delta asinh(1)/(2 pi vartheta)``.

    >>> import math
    >>> from thinlayer import HalfSpace
    >>> C = influence_coefficients(HalfSpace(), None, 1.0, 2, nu=0.3)
    >>> round(float(C[0, 0]) / (4 * math.asinh(1) * 0.7 / (2 * math.pi)), 12)
    1.0
    """
    nu_val = numeric_layer_nu(layer, nu)
    mu = positive(mu, "mu")
    d = positive(spacing, "spacing")
    n = check_n(n)
    vartheta = mu / (1.0 - nu_val)
    half = not layer.has_thickness
    if not half:
        H = positive(H, "H")
    # C is symmetric in (k, l): evaluate on k <= l only
    kk, ll = np.triu_indices(n)
    X, Y = kk * d, ll * d
    C = np.zeros((n, n))
    if half:
        vals = _love_square(X, Y, 0.5 * d) / (2.0 * math.pi)
    else:
        near = np.hypot(X, Y) <= _R_CUT * H + d  # beyond, the two parts cancel to rounding
        kk, ll, X, Y = kk[near], ll[near], X[near], Y[near]
        vals = _love_square(X, Y, 0.5 * d) / (2.0 * math.pi)
        g_c = _g_c_spline(layer, H, float(np.hypot(X, Y).max(initial=0.0)) + d)
        xg, wg = special.roots_legendre(_CELL_GAUSS)
        ya, wa = 0.5 * d * xg, 0.5 * d * wg
        for i in range(_CELL_GAUSS):
            ax2 = X + ya[i]
            ax2 *= ax2
            for j in range(_CELL_GAUSS):
                r2 = Y + ya[j]
                r2 *= r2
                r2 += ax2
                vals += wa[i] * wa[j] * g_c(np.sqrt(r2, out=r2))
    C[kk, ll] = vals
    C[ll, kk] = vals
    return C / vartheta


def check_n(n: Any) -> int:
    if isinstance(n, bool) or not isinstance(n, (numbers.Integral, np.integer)):
        raise InputTypeError(f"n (cells per side) must be an integer, got {n!r}")
    if not 2 <= n <= _MAX_N:
        raise InputError(f"n (cells per side) must lie in [2, {_MAX_N}], got {n}")
    need = memory_estimate(int(n))
    check_bounded(need / 1024**3, f"the memory estimate for n = {n} cells per side (GiB)", MAX_BYTES / 1024**3,
                  "the FFT convolution needs its spectrum and a padded (2n x n) complex buffer besides about 13 "
                  "n x n arrays; use a smaller n (n <= 3600 fits in 2 GiB)")
    return int(n)


# --------------------------------------------------------------------------- FFT convolution
def _reach(C: np.ndarray, axis: int) -> int:
    """The largest offset index along ``axis`` with a nonzero coefficient (the kernel is cut beyond ``_R_CUT`` H)."""
    idx = np.flatnonzero(np.any(C != 0.0, axis=1 - axis))
    return int(idx[-1]) if idx.size else 0


def _padded_size(N: int, reach: int) -> int:
    """Even FFT length M with ``M >= N + reach`` (and ``>= 2 reach + 1``): the aperiodic sum needs no more.

    A coefficient at offset k contributes to ``u_i`` from ``p_{i-k}``; on a period M nothing wraps into the
    N computed cells when ``M >= N + reach``, i.e. ``2N - 1`` for a kernel reaching across the grid and less
    for a thin layer on a wide grid (the coefficients vanish beyond ``_R_CUT`` H).
    """
    need = max(min(2 * N - 1, N + reach), 2 * reach + 1, 2)
    return 2 * sfft.next_fast_len((need + 1) // 2, real=True)


class Convolver:
    """Aperiodic convolution ``u = C * p`` on an N1 x N2 grid by FFT on the zero-padded M1 x M2 grid.

    ``C[k, l]`` (shape N1 x N2) is the kernel at offsets ``(+-k, +-l)``: even in both, so its spectrum is real
    and even, and its quadrant ``0 <= j <= M1/2, 0 <= k <= M2/2`` is the 2D DCT-I of the coefficients (no
    M1 x M2 array is built; kept complex, which multiplies faster); the rows ``j > M1/2`` of the rfft2 layout are
    those of ``M1 - j``.  Only the N1 non-zero input rows are transformed along x2 and only the N1 wanted output
    rows are transformed back, in blocks of rows through one zero-padded buffer; the x1 transforms run in place
    on the one M1 x (M2/2 + 1) complex buffer.
    """

    _BLOCK_BYTES = 8 << 20  # row blocks of the x2 transforms

    def __init__(self, C: np.ndarray, workers: int):
        N1, N2 = C.shape
        M1, M2 = _padded_size(N1, _reach(C, 0)), _padded_size(N2, _reach(C, 1))
        h1, h2 = M1 // 2, M2 // 2
        Kq = np.zeros((h1 + 1, h2 + 1))
        m1, m2 = min(N1, h1 + 1), min(N2, h2 + 1)
        Kq[:m1, :m2] = C[:m1, :m2]
        self.spec = sfft.dctn(Kq, type=1, workers=workers).astype(complex)  # the real spectrum's quadrant
        del Kq
        self.shape, self.padded, self.workers = (N1, N2), (M1, M2), workers
        self._cbuf = np.zeros((M1, h2 + 1), dtype=complex)
        self._rows = min(N1, max(8, self._BLOCK_BYTES // (16 * (h2 + 1))))
        self._rbuf = np.zeros((self._rows, M2))  # columns N2.. stay zero (padding)

    def __call__(self, p: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        (N1, N2), (M1, M2), w = self.shape, self.padded, self.workers
        h1, R, rb, cb = M1 // 2, self._rows, self._rbuf, self._cbuf
        for r0 in range(0, N1, R):  # only the N1 non-zero rows are transformed
            m = min(R, N1 - r0)
            rb[:m, :N2] = p[r0:r0 + m]
            cb[r0:r0 + m] = sfft.rfft(rb[:m], axis=1, workers=w)
        cb[N1:] = 0.0
        a = sfft.fft(cb, axis=0, overwrite_x=True, workers=w)  # in place
        a[: h1 + 1] *= self.spec
        a[h1 + 1:] *= self.spec[h1 - 1:0:-1]
        a = sfft.ifft(a, axis=0, overwrite_x=True, workers=w)
        if out is None:
            out = np.empty((N1, N2))
        for r0 in range(0, N1, R):
            out[r0:r0 + R] = sfft.irfft(a[r0:min(r0 + R, N1)], n=M2, axis=1, workers=w)[:, :N2]
        return out
