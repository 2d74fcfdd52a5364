"""Direct numerical solution of the two-dimensional unilateral contact problem (1.5)-(1.8).

A rigid punch ``x3 = -Phi(x1, x2)`` (any polynomial :class:`~thinlayer.punch.Punch`, or any numeric tip with a
vectorised profile: a pyramid, a cone, ...) is pressed
without friction into a layer of thickness H on a rigid base.  We seek ``p(x) >= 0`` on the
plane with

    u3(x) >= delta0 - Phi(x),     p (u3 - delta0 + Phi) = 0,     P = iint p dx   (1.5), (1.8),

    u3 = (1/vartheta) F^{-1}[ p_hat(alpha) L(|alpha| H) / |alpha| ],    vartheta = mu/(1 - nu),   (2.1)

with ``p_hat(alpha) = iint p e^{i alpha.x} dx`` (2.2) and ``F^{-1} f = (2 pi)^{-2} iint f e^{-i alpha.x} d alpha``.
(The printed (2.1) has a leading minus sign; with p >= 0 the kernel must be positive --
see :mod:`thinlayer.errata`.  For L = 1 this is Boussinesq's
``u3 = (1 - nu)/(2 pi mu) iint p(y)/|x - y| dy``.)  No asymptotic expansion is used: this is an
independent check of the thin-layer results, like :mod:`thinlayer.numerics.axisymmetric` for axisymmetric punches.

Influence coefficients
----------------------
The pressure is piecewise constant on an N x N grid of square cells of side Delta (centres
``x_i``), and (1.5) is collocated at the cell centres.  The displacement at a point offset by
``x = (k Delta, l Delta)`` from the centre of a cell carrying unit pressure is

    C(x) = (1/vartheta) iint_{cell} G(x - y) dy,      G = F^{-1}[L(|alpha| H)/|alpha|].

We split ``L = 1 + (L - 1)``.  The half-space part ``1/|alpha|`` has ``F^{-1} = 1/(2 pi r)``,
whose integral over a square is Love's closed form (exact)::

    iint_{|y1 - x1| < h, |y2 - x2| < h} dy / |y| = sum_{corners} +-F(X, Y),
    F(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|),     h = Delta/2

(the corner sum ``F(x1+h, x2+h) - F(x1-h, x2+h) - F(x1+h, x2-h) + F(x1-h, x2-h)``; the usual
``X log(Y + r) + Y log(X + r)`` differs from F by functions of X or of Y alone, which cancel,
and the asinh form has no cancellation).  The correction ``(L(|alpha| H) - 1)/|alpha|`` is
singular like ``-1/|alpha|`` at alpha = 0 -- its Fourier samples on a finite grid alias badly --
but in real space it is the smooth radial function

    g_c(r) = (1/(2 pi)) int_0^oo (L(s H) - 1) J0(s r) ds
           = (1/(2 pi H)) int_0^{22} (L(t) - 1) J0(t r/H) dt        (L - 1 = O(t^2 e^{-2t}), (2.4)),

analytic and even in r, with ``g_c(0)`` finite and ``g_c(r) = -1/(2 pi r) + O(e^{-gamma r/H})``:
since ``L(s)/s`` is even and analytic near the real axis (section 2), the full layer kernel
``1/(2 pi r) + g_c(r)`` decays exponentially on the scale H.  ``g_c`` is computed by composite
Gauss-Legendre quadrature in t (one J0 period per 16-point panel) on a table of radii with spacing
``<= H/40``, interpolated by a cubic spline, and integrated over each cell by a 4 x 4
Gauss-Legendre rule (``g_c`` varies on the scale H >= 5 Delta).  Hence

    C(k, l) = (1/vartheta) [ (1/(2 pi)) Love(k Delta, l Delta; Delta/2)
                             + sum_{a,b} w_a w_b g_c(|(k Delta + y_a, l Delta + y_b)|) ],

and ``C = 0`` where the whole cell lies beyond ``50 H``: there the layer kernel is below
``1e-15/H`` (checked in the tests), i.e. the two parts cancel to rounding.  For the half-space
(``HalfSpace``) only the Love term remains.

Convolution and contact algorithm
---------------------------------
``u_i = sum_j C(x_i - x_j) p_j`` is an aperiodic (linear) convolution, evaluated exactly by
FFT on a zero-padded grid of size ``M >= N + R`` (R the kernel's reach in cells, the offsets
beyond ``50 H`` being zero; ``M = 2N`` or so when the kernel reaches across the grid), even and
smooth (:func:`scipy.fft.next_fast_len`); nothing wraps around, so an isolated contact needs no
periodic images.  The even kernel's real spectrum is computed once, as the 2D DCT-I of the
coefficient quadrant, and only the non-zero input rows and the wanted output rows are
transformed along x2.  The complementarity problem (1.5) is solved by the Polonsky-Keer
conjugate-gradient method (Polonsky & Keer, Wear 231 (1999) 206), which minimises
``p.C p / 2 - p.(delta0 - Phi)`` over ``p >= 0`` -- with the rigid-body displacement delta0
prescribed (the mean-gap shift and force rescaling of the original algorithm dropped), or, with
``force=`` given, in its original load-controlled form.  With delta0 prescribed the pressure can
only be positive where the rigid overlap ``delta0 - Phi`` is (a penetrating cell has
``delta0 - Phi > u3 >= 0``), so the iteration runs on the bounding box of that overlap (a smaller
FFT) and is then checked -- and continued if needed -- on the whole grid with a fresh
convolution, which also gives the gap everywhere.  The iteration stops when the discrete
contact conditions hold to ``tol``:

    residual = max( max_{p > 0} |g|,  max_{p = 0} max(-g, 0) ) / delta0,    g = u3 - delta0 + Phi,

with the displacement recomputed by a fresh convolution at the end.  Its work arrays are
allocated once, and its sums avoid BLAS (``numpy.einsum``): OpenBLAS threads woken by ``@``
keep spinning on the cores the FFT workers need.

Contact area and contour
------------------------
The contact set is the union of cells with ``p > 0``; ``contact_area_cells`` is their number
times Delta^2.  A sub-cell estimate: contourpy traces the boundary between contact and
non-contact cell centres (marching squares, saddles included), and each vertex, lying on a grid
segment from a contact centre (pressure p_b) to a free centre (gap g_o), is moved to the point at
fraction t from the contact centre given by the local edge asymptotics of a smooth contact,
``p ~ P1 d^{1/2}`` inside and ``g ~ (4 P1/(3 E*)) s^{3/2}`` outside (E* = 2 vartheta; at distances
below H every layer acts like a half-space).  Eliminating P1: ``(1 - t)^{3/2} t^{-1/2} = rho``,
``rho = 3 E* g_o/(4 p_b Delta)``, whose root is ``t = 1 - (2 rho/sqrt 3) sinh(asinh(3 sqrt(3)/(2 rho))/3)``.
``contact_area`` is the area enclosed by these polygons (shoelace).

Accuracy and limitations
------------------------
* Measured (tests/numerics/test_fft2d.py): Hertz's force is reached with error ``c (Delta/a)^2``,
  c = 0.03-0.08, observed order 2.0-2.2; the contour vertices lie within 0.15 Delta of Hertz's
  circle/ellipse (rms 0.05 Delta), the equivalent contact radius within 0.02 Delta; the staircase
  area ``contact_area_cells`` is only first-order accurate.  On a thin layer (H/a = 0.1, Delta = H/10)
  force and radius agree with :mod:`thinlayer.numerics.axisymmetric` to 2e-5 and 1e-4.
* Pyramids (ridges, a polygonal contact; tests/numerics/test_pyramid_2d.py): the force converges at an observed
  order 1.5-3.9 (the square's edges fall at a different fraction of a cell on each grid), 2.4e-6 from the Richardson
  value at n = 512 and H/a = 0.1; away from the corners the contour lies within 0.16 cells (n = 256) of the square
  shifted by h^* H (3.25); single-cell islands can appear just beyond the corners on coarse grids.
* Only contact inside the computational square is modelled: the contact must stay two cells
  away from its boundary (checked, with an error); contact regions disconnected from the one
  around the tip and lying outside the square are not seen.  The default square is built from
  the overlap region ``Phi < delta0`` seen from the origin (or from the minimum found by descent
  from it); pass ``extent`` otherwise.
* The grid must resolve the layer (Delta <= H/5, checked) and the contact (warning below 8 cells
  across).  Memory: the spectrum quadrant, one padded complex buffer and about 13 n x n arrays;
  :func:`memory_estimate` (an upper bound: measured peaks 122 MiB at n = 1024 and 440 MiB at n = 2048
  for a sphere, a = 10 H) must stay below :data:`MAX_BYTES` = 2 GiB (n <= 3600), checked before any work.
* Polonsky-Keer is unpreconditioned CG: iterations grow slowly with N (about 60 for N = 1024 on a
  thin layer, 100 for N = 256 on the half-space, tol = 1e-10).
"""
from __future__ import annotations

import math
import numbers
import os
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import contourpy
import numpy as np
import sympy as sp

from .._checks import ComputationError, InputError, InputTypeError, positive
from .._lazy import lazy_module
from ..errors import boundary, boundary_methods
from ..layers.kernels import LayerKernel
from ..punch import Punch, Tip, is_polynomial_tip
from ._influence import MAX_BYTES, Convolver, check_n, influence_coefficients, layer_correction_kernel, memory_estimate
from ._layer import numeric_layer_nu
from ._polonsky_keer import polonsky_keer

optimize = lazy_module("scipy.optimize")  # scipy imported on first use

__all__ = [
    "CoarseGridWarning",
    "Contact2D",
    "ContactConvergenceError",
    "MAX_BYTES",
    "influence_coefficients",
    "layer_correction_kernel",
    "memory_estimate",
    "solve_2d",
]

_MIN_CELLS_PER_H = 5.0  # H must span at least this many cells
_EDGE_CELLS = 2  # the contact must stay this many cells away from the domain boundary
_MIN_CELLS_ACROSS = 8  # fewer cells across the contact -> CoarseGridWarning


class ContactConvergenceError(ComputationError, RuntimeError):
    """The Polonsky-Keer iteration did not reach the tolerance; ``.result`` holds the last iterate."""

    def __init__(self, message: str, result: Contact2D | None = None):
        super().__init__(message)
        self.result = result


class CoarseGridWarning(UserWarning):
    """The contact area is resolved by only a few cells: the result is of low accuracy."""


# --------------------------------------------------------------------------- result
@boundary_methods
@dataclass(frozen=True, eq=False)
class Contact2D:
    """Direct numerical solution of the two-dimensional contact problem (1.5)-(1.8).

    Attributes
    ----------
    layer, punch, nu, mu, vartheta, H
        LayerKernel, Punch, float, float, float, float or None
        Layer model (kernel L, (2.3)), punch (1.1), Poisson ratio, shear modulus,
        ``vartheta = mu/(1 - nu)`` (2.1), thickness (None for the half-space).
    delta0 : float
        Indentation depth (prescribed, or computed when the force was prescribed).
    force : float
        Total force ``P = iint p dx = Delta^2 sum p`` (1.8).
    contact_area : float
        Area enclosed by the sub-cell contact contour (see the module docstring).
    contact_area_cells : float
        Number of cells with p > 0 times Delta^2.
    contour : tuple of numpy.ndarray
        Tuple of closed polygons, each a (k, 2) array of (x1, x2) vertices (first = last).
    pressure : numpy.ndarray
        N x N array, ``pressure[i, j] = p(x1[i], x2[j])`` (cell values; read-only).
    gap : numpy.ndarray
        N x N array of ``u3 - delta0 + Phi`` at the cell centres (>= 0; 0 in contact).
    x1, x2 : numpy.ndarray
        numpy.ndarray
        Cell-centre coordinates (length N each).
    spacing : float
        Cell size Delta.
    iterations, residual, tol
        int, float, float
        Polonsky-Keer iterations, final residual (contact conditions, relative to delta0), tolerance.
    """

    layer: LayerKernel
    punch: Punch
    nu: float
    mu: float
    vartheta: float
    H: float | None
    delta0: float
    force: float
    contact_area: float
    contact_area_cells: float
    contour: tuple = field(repr=False)
    pressure: np.ndarray = field(repr=False)
    gap: np.ndarray = field(repr=False)
    x1: np.ndarray = field(repr=False)
    x2: np.ndarray = field(repr=False)
    spacing: float
    iterations: int
    residual: float
    tol: float

    @property
    def equation(self) -> str:
        return "1.5-1.8"

    @property
    def n(self) -> int:
        """Cells per side."""
        return self.x1.size

    @property
    def contact_radius(self) -> float:
        """Radius of the disc with the same area, ``sqrt(contact_area/pi)``."""
        return math.sqrt(self.contact_area / math.pi)

    @property
    def contact_mask(self) -> np.ndarray:
        """Boolean N x N array of the cells in contact (p > 0)."""
        return self.pressure > 0

    @property
    def max_pressure(self) -> float:
        return float(self.pressure.max())

    def latex(self) -> str:
        """One-line LaTeX summary."""
        return (rf"P = {self.force:.8g},\quad |\omega| = {self.contact_area:.8g},\quad "
                rf"\delta_0 = {self.delta0:.8g},\quad N = {self.n},\ \Delta = {self.spacing:.4g}")


# --------------------------------------------------------------------------- punch and domain
def _numeric_punch(punch: Any) -> tuple[Punch, Callable[[np.ndarray, np.ndarray], np.ndarray]]:
    if isinstance(punch, (str, sp.Basic)):
        punch = Punch(punch)
    if not isinstance(punch, Tip) or punch.fixed_contact:
        raise InputTypeError(f"punch must be a thinlayer tip (a Punch, a polynomial expression in x1, x2, or a tip "
                             f"such as Punch.pyramid(35)) whose contact grows with the depth, got {punch!r:.80} "
                             f"({type(punch).__name__})")
    if punch.parameters:
        names = ", ".join(str(q) for q in punch.parameters)
        raise InputError(f"the punch '{punch.name}' Phi = {punch.expr} has free parameter(s) {names}: "
                         f"substitute numbers first, e.g. punch.subs({{'{punch.parameters[0]}': 1.0}})")
    if not is_polynomial_tip(punch):  # any other tip: its own vectorised profile (a pyramid, a cone, ...)
        f = punch.profile
    else:
        coeffs = punch.polynomial.coeffs()
        if not all(c.is_real for c in coeffs):
            raise InputError(f"the punch '{punch.name}' Phi = {punch.expr} has non-real coefficients")
        f = punch.lambdify()

    def phi(X: np.ndarray, Y: np.ndarray) -> np.ndarray:
        return np.broadcast_to(np.asarray(f(X, Y), dtype=float), np.broadcast(X, Y).shape)

    return punch, phi


def _overlap_box(punch: Punch, phi: Callable, delta0: float) -> tuple[float, float, float, float]:
    """Bounding box of the rigid overlap {Phi < delta0}, seen along 72 rays from the punch tip."""
    o = np.zeros(2)
    if not phi(np.array(0.0), np.array(0.0)) < delta0:
        res = optimize.minimize(lambda z: float(phi(np.array(z[0]), np.array(z[1]))), o, method="BFGS")
        o = res.x
        val = float(phi(np.array(o[0]), np.array(o[1])))
        if not val < delta0:
            raise InputError(f"the punch '{punch.name}' Phi = {punch.expr} does not touch the layer: "
                             f"min Phi = {val:.6g} (at x = {o[0]:.6g}, {o[1]:.6g}, found by descent from the origin) "
                             f">= delta0 = {delta0:.6g}; increase delta0, or pass extent= if the contact lies "
                             "elsewhere")
    th = np.linspace(0.0, 2.0 * math.pi, 72, endpoint=False)
    pts = []
    for c, s in zip(np.cos(th), np.sin(th)):
        def along(r: float, c=c, s=s) -> float:
            return float(phi(np.array(o[0] + r * c), np.array(o[1] + r * s))) - delta0

        hi = 1e-6 * (1.0 + float(np.abs(o).max()))
        for _ in range(400):
            if along(hi) > 0:
                break
            hi *= 1.5
        else:
            raise InputError(f"the punch '{punch.name}' Phi = {punch.expr} stays below delta0 = {delta0:.6g} "
                             f"along the direction ({c:.3f}, {s:.3f}): the contact region is unbounded; "
                             "solve_2d needs a punch that rises above delta0 all around (or pass extent=)")
        r0 = optimize.brentq(along, 0.0, hi, xtol=1e-13 * hi)
        pts.append((o[0] + r0 * c, o[1] + r0 * s))
    pts = np.array(pts)
    radii = np.hypot(pts[:, 0] - o[0], pts[:, 1] - o[1])
    if radii.max() > 1e4 * radii.min():
        k = int(np.argmax(radii))
        raise InputError(f"the punch '{punch.name}' Phi = {punch.expr} leaves an unbounded (or extremely "
                         f"elongated) overlap region Phi < delta0 = {delta0:.6g}: it reaches delta0 at distance "
                         f"{radii.min():.3g} in one direction but {radii.max():.3g} along "
                         f"({math.cos(th[k]):.3f}, {math.sin(th[k]):.3f}); pass extent= to solve on a chosen square")
    return float(pts[:, 0].min()), float(pts[:, 0].max()), float(pts[:, 1].min()), float(pts[:, 1].max())


def _domain(extent: Any, punch: Punch, phi: Callable, delta0: float | None, H: float | None
            ) -> tuple[float, float, float]:
    """Return (x1 centre, x2 centre, half-width) of the computational square."""
    if extent is None:
        if delta0 is None:
            raise InputError("with a prescribed force the domain cannot be guessed: pass extent= "
                             "(half-width of a square centred at the origin, or (x1min, x1max, x2min, x2max))")
        a0, a1, b0, b1 = _overlap_box(punch, phi, delta0)
        size = max(a1 - a0, b1 - b0)
        margin = 0.15 * size if H is None else min(2.0 * H, 0.15 * size)
        return 0.5 * (a0 + a1), 0.5 * (b0 + b1), 0.54 * size + margin
    if isinstance(extent, (numbers.Real, sp.Number)) and not isinstance(extent, bool):
        return 0.0, 0.0, positive(extent, "extent (half-width)")
    try:
        a0, a1, b0, b1 = (float(v) for v in extent)
    except (TypeError, ValueError) as exc:
        raise InputTypeError(f"extent must be None, a half-width, or (x1min, x1max, x2min, x2max); got {extent!r}"
                        ) from exc
    w1, w2 = a1 - a0, b1 - b0
    if not (math.isfinite(w1) and math.isfinite(w2) and w1 > 0 and w2 > 0):
        raise InputError(f"extent {extent!r} is not a non-empty box (x1min, x1max, x2min, x2max)")
    if abs(w1 - w2) > 1e-9 * max(w1, w2):
        raise InputError(f"extent must be a square (the grid is N x N with square cells): "
                         f"widths {w1:.6g} (x1) and {w2:.6g} (x2) differ")
    return 0.5 * (a0 + a1), 0.5 * (b0 + b1), 0.5 * w1


# --------------------------------------------------------------------------- contour
def _edge_fraction(p_in: np.ndarray, g_out: np.ndarray, d: float, estar: float) -> np.ndarray:
    """Fraction t in [0, 1] from the contact centre to the edge: root of (1 - t)^{3/2} t^{-1/2} = rho."""
    with np.errstate(divide="ignore", invalid="ignore"):
        rho = 3.0 * estar * np.maximum(g_out, 0.0) / (4.0 * p_in * d)
        z = (2.0 * rho / math.sqrt(3.0)) * np.sinh(np.arcsinh(3.0 * math.sqrt(3.0) / (2.0 * rho)) / 3.0)
    z = np.where(rho > 0, z, 0.0)  # zero gap: the edge is at the free centre
    return np.clip(1.0 - np.nan_to_num(z, nan=0.5), 0.0, 1.0)


def _contour(p: np.ndarray, g: np.ndarray, x1: np.ndarray, x2: np.ndarray, d: float, estar: float
             ) -> tuple[tuple[np.ndarray, ...], float]:
    """Sub-cell contact contour (see module docstring) and the area it encloses."""
    inside = p > 0
    z = np.where(inside, 1.0, -1.0).T  # contourpy: z[j, i] at (x1[i], x2[j])
    lines = contourpy.contour_generator(x=x1, y=x2, z=z, line_type=contourpy.LineType.Separate).lines(0.0)
    out = []
    area = 0.0
    for line in lines:
        fi = (line[:, 0] - x1[0]) / d
        fj = (line[:, 1] - x2[0]) / d
        on_i = np.abs(fi - np.round(fi)) > 0.25  # vertex on a segment along x1 (fi half-integer)
        i0 = np.where(on_i, np.floor(fi), np.round(fi)).astype(int)
        j0 = np.where(on_i, np.round(fj), np.floor(fj)).astype(int)
        i1 = i0 + on_i
        j1 = j0 + ~on_i
        first_in = inside[i0, j0]
        ii, ji = np.where(first_in, i0, i1), np.where(first_in, j0, j1)
        io, jo = np.where(first_in, i1, i0), np.where(first_in, j1, j0)
        t = _edge_fraction(p[ii, ji], g[io, jo], d, estar)
        pts = np.column_stack([x1[ii] + t * (x1[io] - x1[ii]), x2[ji] + t * (x2[jo] - x2[ji])])
        pts.setflags(write=False)
        out.append(pts)
        xs, ys = pts[:, 0], pts[:, 1]
        area += 0.5 * float(np.dot(xs[:-1], ys[1:]) - np.dot(xs[1:], ys[:-1]))
    return tuple(out), abs(area)


# --------------------------------------------------------------------------- solver
@dataclass(frozen=True, eq=False)
class _Problem:
    """The checked input of :func:`solve_2d`, on its grid."""

    layer: LayerKernel
    punch: Punch
    nu: float
    mu: float
    vartheta: float
    H: float | None  # as given (may be None or ignored for the half-space)
    delta0: float | None
    force: float | None
    tol: float
    maxiter: int
    x1: np.ndarray = field(repr=False)
    x2: np.ndarray = field(repr=False)
    spacing: float
    Phi: np.ndarray = field(repr=False)
    C: np.ndarray = field(repr=False)  # influence coefficients (n x n quadrant)
    workers: int
    load: np.ndarray | None = field(default=None, repr=False)  # prescribed surface pressure q (hook, see solve_2d)

    @property
    def n(self) -> int:
        return self.x1.size


def _check_controls(delta0: Any, force: Any, n: Any, tol: Any, maxiter: Any):
    """Checked ``(delta0, force, n, tol, maxiter)``: exactly one of delta0 and force."""
    if (delta0 is None) == (force is None):
        raise InputError("give exactly one of delta0 (indentation depth) and force (total load P)")
    if delta0 is not None:
        delta0 = positive(delta0, "delta0")
    else:
        force = positive(force, "force")
    n = check_n(n)
    if isinstance(tol, bool) or not isinstance(tol, (numbers.Real, sp.Number)) or not 0 < float(tol) < 1:
        raise InputError(f"tol must be a number in (0, 1), got {tol!r}")
    if isinstance(maxiter, bool) or not isinstance(maxiter, (numbers.Integral, np.integer)) or maxiter < 1:
        raise InputError(f"maxiter must be a positive integer, got {maxiter!r}")
    return delta0, force, n, float(tol), int(maxiter)


def _grid(punch: Punch, phi: Callable, extent: Any, delta0: float | None, H_eff: float | None, n: int):
    """Cell centres ``x1, x2``, spacing and ``Phi`` at the centres; the grid must resolve H (Delta <= H/5)."""
    c1, c2, half_w = _domain(extent, punch, phi, delta0, H_eff)
    d = 2.0 * half_w / n
    if H_eff is not None and d > H_eff / _MIN_CELLS_PER_H:
        raise InputError(
            f"grid too coarse to resolve the layer: cell size Delta = {d:.4g} > H/{_MIN_CELLS_PER_H:g} = "
            f"{H_eff / _MIN_CELLS_PER_H:.4g} (H = {H_eff:.4g}, domain width {2 * half_w:.4g}, n = {n}); "
            f"use n >= {math.ceil(2 * half_w * _MIN_CELLS_PER_H / H_eff)} or a smaller extent")
    x1 = c1 - half_w + (np.arange(n) + 0.5) * d
    x2 = c2 - half_w + (np.arange(n) + 0.5) * d
    X1, X2 = np.meshgrid(x1, x2, indexing="ij")
    Phi = phi(X1, X2)
    if not np.all(np.isfinite(Phi)):
        raise InputError(f"the punch '{punch.name}' Phi = {punch.expr} is not finite on the grid")
    return x1, x2, d, Phi


def _setup(layer: Any, punch: Any, delta0: Any, H: Any, mu: Any, n: Any, extent: Any, tol: Any, maxiter: Any,
           force: Any, nu: Any, workers: Any, surface_load: Any = None) -> _Problem:
    """Check the input of :func:`solve_2d`, build the grid and the FFT convolution with the coefficients."""
    nu_val = numeric_layer_nu(layer, nu)
    mu = positive(mu, "mu")
    if not layer.has_thickness:  # the half-space: H is optional and ignored
        H = None if H is None else positive(H, "H")
        H_eff = None
    else:
        if H is None:
            raise InputError(f"{type(layer).__name__} needs the layer thickness H > 0")
        H = H_eff = positive(H, "H")
    delta0, force, n, tol, maxiter = _check_controls(delta0, force, n, tol, maxiter)
    workers = (os.cpu_count() or 1) if workers is None else int(workers)
    punch, phi = _numeric_punch(punch)
    x1, x2, d, Phi = _grid(punch, phi, extent, delta0, H_eff, n)
    C = influence_coefficients(layer, H_eff, d, n, nu=nu_val, mu=mu)
    load = None
    if surface_load is not None:
        if delta0 is None or extent is None:
            raise InputError("surface_load= needs delta0= and extent= (the load lives on the grid that extent and n "
                             "define; a prescribed force is not supported with it)")
        try:
            load = np.array(surface_load(x1, x2) if callable(surface_load) else surface_load, dtype=float)
        except (TypeError, ValueError):
            raise InputTypeError(f"surface_load must be a finite {n} x {n} array of numbers (or a callable of the cell "
                                 f"centres x1, x2 returning one), got {type(surface_load).__name__}") from None
        if load.shape != (n, n) or not np.all(np.isfinite(load)):
            raise InputError(f"surface_load must be a finite {n} x {n} array (or a callable of the cell centres "
                             f"x1, x2 returning one), got shape {load.shape}")
    return _Problem(layer, punch, nu_val, mu, mu / (1.0 - nu_val), H, delta0, force, tol, maxiter, x1, x2, d, Phi,
                    C, workers, load)


def _overlap_slices(w: np.ndarray) -> tuple[slice, slice]:
    """Index ranges of the bounding box of the rigid overlap ``w = delta0 - Phi > 0``."""
    rows, cols = np.flatnonzero(w.max(axis=1) > 0), np.flatnonzero(w.max(axis=0) > 0)
    return slice(int(rows[0]), int(rows[-1]) + 1), slice(int(cols[0]), int(cols[-1]) + 1)


def _iterate(prob: _Problem):
    """Initial pressure and the Polonsky-Keer iteration: ``(p, g, iterations, residual, delta0, converged)``.

    With delta0 prescribed the pressure can only be positive where the rigid overlap ``w = delta0 - Phi`` is
    (a penetrating cell has ``w > u >= 0``), so the iteration runs on the bounding box B of ``w > 0`` (a
    smaller FFT: the box plus the kernel's reach instead of twice the grid); its result is then checked (and,
    if a cell outside B penetrates, continued) on the whole grid with one fresh convolution, which also gives
    the gap everywhere.
    """
    cell, n, Phi = prob.spacing**2, prob.n, prob.Phi
    if prob.force is None:
        w = prob.delta0 - Phi
        if prob.load is not None:  # the prescribed surface load's displacement moves the obstacle (hook)
            w = w - Convolver(prob.C, prob.workers)(prob.load)
        if not (w > 0).any():
            raise InputError(f"Phi >= delta0 = {prob.delta0:.6g} at every cell centre: no contact on the grid "
                             f"(min Phi = {Phi.min():.6g}); refine the grid or increase delta0")
        box = _overlap_slices(w)
        wb = np.ascontiguousarray(w[box])
        nb1, nb2 = wb.shape
        conv = Convolver(prob.C[:nb1, :nb2], prob.workers)
        p0 = np.maximum(wb, 0.0)
        u0 = conv(p0)
        scale = float((p0 * wb).sum() / (p0 * u0).sum())  # best multiple of the overlap: a good start
        p0 *= scale
        u0 *= scale
        iters, maxiter = 0, prob.maxiter
        if wb.shape != w.shape:  # else the whole grid is the box: iterate on it directly
            pb, _, _, iters, _, _, _ = polonsky_keer(conv, wb, cell, None, p0, prob.tol, maxiter, prob.delta0, u0)
            p0 = np.zeros((n, n))
            p0[box] = pb
            maxiter -= iters
            u0 = conv = pb = None
        del wb
    else:
        w = -Phi
        p0 = np.full((n, n), prob.force / (cell * n * n))
        iters, maxiter, u0, conv = 0, prob.maxiter, None, None
    if conv is None:
        conv = Convolver(prob.C, prob.workers)
    p, _, g, more, res, d0, ok = polonsky_keer(conv, w, cell, prob.force, p0, prob.tol, maxiter, prob.delta0, u0)
    return p, g, iters + more, res, d0, ok


def _check_inside(inside: np.ndarray, x1: np.ndarray, x2: np.ndarray, d: float) -> None:
    """The contact must stay ``_EDGE_CELLS`` cells away from the boundary of the computational square."""
    n = x1.size
    ii, jj = np.nonzero(inside)
    near = min(ii.min(), jj.min(), n - 1 - ii.max(), n - 1 - jj.max())
    if near < _EDGE_CELLS:
        raise InputError(
            f"the contact reaches the boundary of the computational domain: contact cells span "
            f"x1 in [{x1[ii.min()]:.6g}, {x1[ii.max()]:.6g}], x2 in [{x2[jj.min()]:.6g}, {x2[jj.max()]:.6g}], "
            f"the domain is [{x1[0] - d / 2:.6g}, {x1[-1] + d / 2:.6g}] x [{x2[0] - d / 2:.6g}, "
            f"{x2[-1] + d / 2:.6g}] ({near} free cells to the edge, {_EDGE_CELLS} needed); enlarge extent")


def _package(prob: _Problem, p: np.ndarray, g: np.ndarray, iters: int, res: float, d0: float, ok: bool
             ) -> Contact2D:
    """The frozen :class:`Contact2D` (contour, force (1.8)); raise or warn on non-convergence or a coarse grid."""
    x1, x2, d, n = prob.x1, prob.x2, prob.spacing, prob.n
    cell = d * d
    P = cell * float(p.sum() if prob.load is None else (p + prob.load).sum())
    inside = p > 0
    if inside.any():
        _check_inside(inside, x1, x2, d)
    contour, area = _contour(p, g, x1, x2, d, 2.0 * prob.vartheta) if inside.any() else ((), 0.0)
    for arr in (p, g, x1, x2):
        arr.setflags(write=False)
    result = Contact2D(prob.layer, prob.punch, prob.nu, prob.mu, prob.vartheta, prob.H, float(d0), P, float(area),
                       cell * int(inside.sum()), contour, p, g, x1, x2, d, iters, float(res), prob.tol)
    if not ok:
        raise ContactConvergenceError(
            f"Polonsky-Keer iteration did not converge: residual {res:.3e} > tol {prob.tol:.1e} after {iters} "
            f"iterations (n = {n}); raise maxiter or tol. The last iterate is in .result", result)
    across = math.sqrt(4.0 * cell * inside.sum() / math.pi) / d
    if across < _MIN_CELLS_ACROSS:
        warnings.warn(f"the contact is only ~{across:.1f} cells across (n = {n}, Delta = {d:.4g}): expect "
                      f"errors of order Delta/diameter ~ {1 / max(across, 1):.0%}; refine n or reduce extent",
                      CoarseGridWarning, stacklevel=3)
    return result


@boundary
def solve_2d(layer: LayerKernel, punch: Any, delta0: float | None = None, H: float | None = None,
             mu: float = 1.0, n: int = 256, extent: Any = None, tol: float = 1e-10, maxiter: int = 5000,
             *, force: float | None = None, nu: float | None = None, workers: int | None = None,
             surface_load: Any = None) -> Contact2D:
    """Solve the unilateral contact problem (1.5)-(1.8) on an N x N grid (FFT + Polonsky-Keer CG).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` with numeric nu (2.3), ``FrictionlessLayer()`` or ``HalfSpace()``.
    punch : Tip or str or sympy.Expr
        A :class:`~thinlayer.punch.Punch` (or polynomial expression in ``x1, x2``), or any other tip whose contact
        grows with the depth (``Punch.pyramid(35)``, ``Punch.cone(70)``: its :meth:`profile`), with numbers for
        all parameters; the tip is taken at the origin when ``Phi(0) < delta0``.
    delta0 : float, optional
        Indentation depth (> 0).  Exactly one of ``delta0`` and ``force`` must be given.
    H : float, optional
        Layer thickness (> 0; not needed for ``HalfSpace``).  The grid must resolve it:
        ``Delta <= H/5``.
    mu : float
        Shear modulus.
    n : int
        Cells per side, at most ~3600: the memory estimate (:func:`memory_estimate`) must stay below 2 GiB
        (checked before any work; measured peaks 122 MiB at n = 1024, 440 MiB at n = 2048).
    extent : None, float or tuple of float
        Computational square: None (from the overlap region ``Phi < delta0`` plus a margin), a
        half-width (square centred at the origin), or ``(x1min, x1max, x2min, x2max)``.
    tol : float
        Tolerance of the contact conditions relative to delta0 (see module docstring).
    maxiter : int
        Maximum number of Polonsky-Keer iterations.
    force : float, optional
        Prescribed total force P (1.8) instead of delta0 (needs ``extent``).
    nu : float, optional
        Poisson ratio, only for layers that carry none (``HalfSpace``, ``FrictionlessLayer``).
    workers : int, optional
        Threads for :mod:`scipy.fft` (default: all CPUs).  The iteration itself calls no BLAS.
    surface_load : numpy.ndarray or callable, optional
        A prescribed surface pressure ``q`` (n x n cell values, tensile < 0, or a callable ``q(x1, x2)`` of the 1-D
        cell-centre coordinates) carried besides the contact pressure: the complementarity (1.5) then holds for
        ``p >= 0`` with ``u3 = C (p + q)``; ``pressure`` is p, ``gap`` the full gap and ``force`` the total
        ``Delta^2 sum (p + q)``.  The hook of cohesive laws (:func:`thinlayer.numerics.cohesive.maugis_dugdale_2d`);
        needs ``delta0`` and ``extent``.

    Returns
    -------
    Contact2D

    Raises
    ------
    ValueError
        On bad input, a grid too coarse for H, or a contact reaching the domain boundary.
    ContactConvergenceError
        If the tolerance is not reached within ``maxiter`` iterations.

    Examples
    --------
    Hertz's sphere on a half-space (a = sqrt(R delta0) = 1, P = 8 vartheta a^3/(3R)):

    >>> from thinlayer import HalfSpace, Punch
    >>> res = solve_2d(HalfSpace(), Punch.paraboloid(R=1), delta0=1.0, n=64, extent=1.25, nu=0.3)
    >>> abs(res.force / (8 / 0.7 / 3) - 1) < 0.01, abs(res.contact_radius - 1) < 0.01
    (True, True)
    """
    prob = _setup(layer, punch, delta0, H, mu, n, extent, tol, maxiter, force, nu, workers, surface_load)
    return _package(prob, *_iterate(prob))
