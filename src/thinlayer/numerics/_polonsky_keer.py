"""The Polonsky-Keer conjugate-gradient iteration for the discrete contact conditions (1.5).

Private to :mod:`thinlayer.numerics.fft2d` (its module docstring, "Convolution and contact algorithm",
states the method and the stopping rule): ``p >= 0``, ``C p - w >= 0``, ``p (C p - w) = 0`` with the
rigid-body displacement prescribed or, in load control, the force (Polonsky & Keer, Wear 231 (1999) 206).
Work arrays are allocated once and the sums avoid BLAS.
"""
from __future__ import annotations

import math

import numpy as np

from ._influence import Convolver

_REFRESH = 20  # recompute u = C p by a fresh convolution at least this often


def _dot(a: np.ndarray, b: np.ndarray) -> float:
    """``sum(a * b)`` of two C-contiguous arrays without BLAS.

    numpy's ``@`` calls OpenBLAS, whose threads keep spinning after each product and take the cores the FFT
    workers need (issue 18 measured 12.6 s of CPU for 6.4 s of wall time at n = 1024); einsum's own loop uses none.
    """
    return float(np.einsum("ij,ij->", a, b))


class _PKState:
    """Work arrays of the Polonsky-Keer iteration, each allocated once (n x n); those of a step only when one is taken
    (a solve that is converged at its start, like the check on the whole grid in
    ``thinlayer.numerics.fft2d._iterate``, needs none).
    """

    def __init__(self, shape: tuple[int, int]):
        self.shape = shape
        self.g = np.empty(shape)
        self.gm = np.empty(shape)  # g on the contact set, 0 elsewhere
        self.Ic = np.empty(shape, dtype=bool)
        self.free = np.empty(shape, dtype=bool)

    def step_arrays(self) -> None:
        if not hasattr(self, "t"):
            self.t = np.zeros(self.shape)  # conjugate direction
            self.r = np.empty(self.shape)  # C t
            self.tmp = np.empty(self.shape)
            self.mask = np.empty(self.shape, dtype=bool)


def _pk_residual(st: _PKState, u: np.ndarray, w: np.ndarray, p: np.ndarray, force: float | None,
                 delta0: float | None) -> tuple[float, float]:
    """Gap ``st.g``, contact set ``st.Ic`` (and ``st.free``), ``st.gm`` (g on it); rigid-body displacement, residual."""
    g, Ic, free, gm = st.g, st.Ic, st.free, st.gm
    np.subtract(u, w, out=g)
    np.greater(p, 0.0, out=Ic)
    np.logical_not(Ic, out=free)
    if force is not None:
        count = int(np.count_nonzero(Ic))
        d0 = float(np.sum(g, where=Ic)) / count if count else math.nan  # the mean of u + Phi on the contact set
        g -= d0
        scale = abs(d0) if d0 != 0 else float(np.abs(u).max())
    else:
        d0, scale = delta0, delta0
    np.multiply(g, Ic, out=gm)
    worst_in = max(float(gm.max()), -float(gm.min()))
    res = max(worst_in, -float(np.min(g, where=free, initial=0.0))) / scale
    return d0, res


def _pk_step(st: _PKState, p: np.ndarray, t: np.ndarray, tau: float) -> tuple[bool, bool]:
    """``p -= tau t`` in place, clipped at zero, penetrating free cells pushed in; return (overlap, clipped)."""
    g, free, clipped, tmp = st.g, st.free, st.mask, st.tmp
    np.multiply(t, tau, out=tmp)
    p -= tmp
    np.less(p, 0.0, out=clipped)
    any_clip = bool(clipped.any())
    if any_clip:
        p[clipped] = 0.0
        clipped |= free  # free cells that penetrate (the clipped ones had p > 0 unless clipped now)
        overlap = clipped
    else:
        overlap = free
    overlap = overlap & (g < 0)
    has_ol = bool(overlap.any())
    if has_ol:
        p[overlap] -= tau * g[overlap]
    return has_ol, any_clip


def polonsky_keer(conv: Convolver, w: np.ndarray, cell: float, force: float | None, p0: np.ndarray,
                   tol: float, maxiter: int, delta0: float | None, u0: np.ndarray | None = None):
    """Polonsky-Keer CG for ``p >= 0, C p - w >= 0, p (C p - w) = 0`` (force mode: w up to a constant).

    Returns (p, u, g, iterations, residual, delta0, converged).  A stop is confirmed with a fresh
    convolution ``u = C p`` (the linear steps update u without one).  Work arrays are allocated once and the
    reductions avoid BLAS (:func:`_dot`); ``t`` vanishes off the contact set, so the sums over it need no gather.
    ``u0 = C p0`` when the caller has it (saves a convolution).
    """
    p = p0  # updated in place: the callers hand over their starting pressure
    st = _PKState(p.shape)
    u = conv(p) if u0 is None else u0
    G_old, conj, fresh = 1.0, False, True
    it = 0
    while True:
        d0, res = _pk_residual(st, u, w, p, force, delta0)
        if res <= tol or it >= maxiter:
            if fresh:
                return p, u, st.g, it, res, d0, res <= tol
            conv(p, out=u)  # confirm with a fresh convolution
            fresh = True
            continue
        it += 1
        st.step_arrays()
        gm, Ic, t, r = st.gm, st.Ic, st.t, st.r
        G = _dot(gm, gm)
        if conj:
            t *= G / G_old
            np.multiply(t, Ic, out=t)  # t = 0 off the contact set
            t += gm
        else:
            np.copyto(t, gm)
        G_old = G
        conv(t, out=r)
        den = _dot(r, t)
        if force is not None:
            count = int(np.count_nonzero(Ic))
            den -= float(np.sum(r, where=Ic)) / count * float(t.sum())  # r minus its mean on the contact set
        if not den > 0:  # t = 0 on the contact set: nothing left to do
            if fresh:
                return p, u, st.g, it, res, d0, res <= tol
            conv(p, out=u)
            fresh = True
            continue
        tau = _dot(gm, t) / den
        has_ol, any_clip = _pk_step(st, p, t, tau)
        conj = not has_ol
        factor = 1.0
        if force is not None:
            factor = force / (cell * float(p.sum()))
            p *= factor
        if has_ol or any_clip or it % _REFRESH == 0:
            conv(p, out=u)
            fresh = True
        else:  # the step was linear: update u without a convolution
            r *= tau
            u -= r
            if factor != 1.0:
                u *= factor
            fresh = False
