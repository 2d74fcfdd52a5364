r"""The leading contact area omega_0 = {delta0 - Phi(x1, x2) > 0} and its contour Gamma_0 (3.1)-(3.14).

The principal term (2.29) of the inner expansion is proportional to ``delta0 - Phi``; it is
positive exactly on

.. math:: \omega_0 = \{x : \delta_0 - \Phi(x_1, x_2) > 0\},

the main approximation of the contact area (section 4).  Its boundary
:math:`\Gamma_0 = \{\Phi = \delta_0\}` carries the local coordinates (3.4) of the boundary layer.

Everything here is in the *dimensional* coordinates ``x = (x1, x2)`` of (1.1).  The paper works in
the scaled coordinates (2.8) ``x = H_* xi`` with the scaled data (1.2) ``delta0 = eps delta0^*``,
``Phi(x) = eps Phi^*(xi)``.  Then arc length and normal distance scale as ``s = H_* s^*``,
``n = H_* n^*``, the unit tangent and normal are unchanged, the curvature radius is
``rho = H_* rho^*``, and from

    delta0 - Phi(f + n n0) = eps (delta0^* - Phi^*(f^* + n^* n0)) = eps H_*^2 (b1^* n^* + b2^* n^{*2})

(the factor ``H_*^2`` is the one pulled out of ``Phi^*`` in (2.13), which makes (3.13) read
``pi^2 vartheta H_* (eps v b1^* + eps^2 v^2 b2^*)`` with (2.25)) one finds

    b1(s) = eps H_* b1^*(s^*) = H b1^*(s^*),     b2(s) = eps b2^*(s^*) = (H / H_*) b2^*(s^*),

where ``b1, b2`` are the dimensional coefficients of :class:`ContactContour`
(``delta0 - Phi(f + n n0) = b1 n + b2 n^2 + O(n^3)``, ``b1 = -grad Phi . n0``,
``2 b2 = -n0^T Hess(Phi) n0``).  For the elliptic paraboloid they reproduce (3.14) term by term.

For the elliptic paraboloid (1.1) the contour is the ellipse with semi-axes
``a = sqrt(2 delta0 R1)``, ``b = sqrt(2 delta0 R2)`` and ``e^2 = 1 - R2/R1`` (3.1); in the scaled
coordinates the semi-axis is ``sqrt(2 delta0^* R1^*)/H_*`` (the printed (3.1) has ``R_1`` in
place of ``R_1^*``; see :meth:`EllipseContour.scaled_semi_axes`).

Method of :func:`contact_contour`:

0. the natural frame (scale-free search): steps 1-3 run on ``Phi(A u)/delta0 = 1`` with
   ``x = A u``, ``A`` built from the principal lengths ``l_j = sqrt(2 delta0/lambda_j)`` of a
   positive definite quadratic part (eigen-decomposition of its Hessian; lengths of the other
   degrees cap them), else from the smallest length at which one degree's terms reach delta0;
   so coefficients from 1e-70 to 1e30 and rotated, elongated regions are found on O(1) grids;
1. a box that contains the whole set ``{Phi < delta0}`` (a rigorous radius when the leading
   homogeneous part of Phi is positive definite, otherwise a box grown from the smallest natural
   length until its edge lies in ``{Phi > delta0}``, confirmed on boxes up to 256 times larger
   and at the largest natural length);
2. the critical points of Phi in the box (Newton on ``grad Phi = 0`` from the grid minima of
   ``|grad Phi|^2``): the minimum of Phi, critical points on the level set (not smooth), maxima
   inside the region (holes), minima outside it (further components);
3. the closed level lines ``Phi = delta0`` on a grid fitted to the region (``contourpy``);
4. a smooth (low-pass trigonometric) reference curve through the polygon, then Newton along its
   normals onto ``Phi = delta0``: the curve is an analytic periodic function of the reference
   parameter, represented spectrally; arc length by spectral integration of the speed, resampled
   at equal arc length and again projected onto the level set.  When that fails its checks
   (contours with features much smaller than the grid), the unit tangent field
   ``(-Phi_x2, Phi_x1)/|grad Phi|`` is integrated in arc length instead (scipy DOP853);
5. the final trigonometric (FFT) interpolant ``f(s)`` and its accuracy: the level residual and
   ``| |f'| - 1 |`` at points halfway between the nodes, the Fourier tail and the turning number
   ``(1/2pi) oint kappa ds = 1``.

Steps 4-5 run on ``Phi(ell u)/delta0 = 1`` with ``ell`` the size of the region, so their tolerances
do not depend on the units.  That is the whole representation up to the aspect ratio (longest /
shortest principal axis of omega_0, from its second moments) ``ASPECT_DIRECT = 3``.

Elongated contours.  The arc-length Fourier series of an ellipse of aspect ratio ``r`` decays like
``exp(-2 pi k rho/L)`` with tip radius ``rho = b^2/a`` and ``L ~ 4a``: about ``18 r^2`` nodes (16384
for ``r = 30``, 1.8e61 for ``r = 1e30``).  Above ``ASPECT_DIRECT`` steps 4-5 therefore run in the
round frame ``x = W w``, ``W = A S`` (``A`` of step 0, ``S = (4 M)^(1/2)`` with ``M`` the central second
moments of the region polygon in ``u``; :func:`round_frame`), where omega_0 is about the unit disk,
so ``w(sigma)``, the arc-length (``sigma``) Fourier series of the round image, needs as many nodes as
a circle-like contour whatever ``r``.  Everything in x follows from the linear map and its Jacobian:

    x(sigma) = W w(sigma),   ds = |W w'(sigma)| dsigma,   |omega_0| = det W |W^-1 omega_0|,
    d^m f/ds^m = (|x'(sigma)|^-1 d/dsigma)^m x(sigma)     (tangent (3.9), normal (3.3), curvature),

the centroid is ``W`` times that of the image.  The speed ``|W w'|`` is smooth but nearly a kink at
each tip (branch points at distance about ``1/r`` from the real sigma axis), so the trapezoidal rule
in sigma would need about ``r`` nodes for the perimeter; the arc length ``s(sigma)`` is built on
Chebyshev panels bisected towards the tips instead (``_ArcLength`` in :mod:`._contour_elongated`: a few
dozen panels per tip whatever ``r``, at most 4096), inverted by safeguarded Newton.  Area integrals keep the trapezoidal
rule in the smooth parameter sigma (``f'(s) ds = x'(sigma) dsigma``); line integrals ``oint g ds``
use Gauss-Legendre on the panels.  ``Phi(W w)/delta0`` is expanded in exact rational arithmetic
(:func:`transformed`), so a rotated elongated quadratic form, whose three terms cancel to one part in
``r^2``, gives the contour of the coefficients as given.

Limits: aspect ratio at most ``ASPECT_MAX = 1e100`` (a ValueError naming the ratio beyond it: the tip
curvature, about ``r^2/L``, and the powers of the frame lengths approach the double range).  A tip
shorter than about 1e-16 of the perimeter (an ellipse with ``r > 1e8``: ``rho = L/(4 r^2)``) lies
between adjacent doubles ``s``: the evaluators are accurate at every representable ``s``, but the peak of
the curvature there is not sampled, and line integrals of the curvature itself are not resolved.
Functions evaluated in x (``phi``, ``g``, ``b1``, ``b2``, ``contains``) of a *rotated* elongated punch lose
about ``r^2`` (``phi``) or ``r`` (gradient) units in the last place to the same cancellation.
Components, holes and critical points smaller than the search grids can be missed
(structures are found from grid cells, grid minima of ``|grad Phi|^2`` and zooms around every
minimum below delta0); when the leading homogeneous part of Phi is only semidefinite, the
boundedness of ``{Phi < delta0}`` is checked on box edges (exact minimum of the 1-D polynomial
on each edge) up to 256 times the first guess and at the largest natural length.
"""
from __future__ import annotations

import math
import numbers
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from functools import lru_cache
from typing import ClassVar

import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import ComputationError, InputError, InputTypeError
from ..display import RichDisplay, fmt
from ..errors import boundary, boundary_methods
from ..normal import normal_latex
from ..parse import as_expr, sympy_value
from ._contour_elongated import FramedCurve
from ._contour_region import (
    ASPECT_DIRECT,
    ASPECT_MAX,
    Frame,
    Poly2,
    as_polynomial,
    region,
    round_frame,
    short,
    too_elongated,
    transformed,
)
from ._contour_spectral import NMAX, nodes_by_ode, nodes_by_reference, sym_coeffs, tail, trig_eval, trim, uniform_eval

__all__ = ["ContactContour", "ContourAccuracy", "EllipseContour", "contact_contour", "ellipse_contour"]


# ---------------------------------------------------------------------------------------------
# input validation
# ---------------------------------------------------------------------------------------------
def _as_delta0(delta0) -> float:
    if isinstance(delta0, bool):
        raise InputTypeError(f"delta0 must be a positive real number, got the bool {delta0!r}")
    if isinstance(delta0, sp.Basic):
        if delta0.free_symbols:
            names = ", ".join(sorted(str(q) for q in delta0.free_symbols))
            raise InputError(
                f"delta0 = {delta0} has free symbol(s) {names}; the contour needs a numeric delta0 > 0 "
                "(substitute values first)"
            )
        val = complex(sp.N(delta0))
        if val.imag != 0:
            raise InputError(f"delta0 must be a positive real number, got {delta0}")
        val = val.real
    elif isinstance(delta0, (numbers.Real, Fraction, np.floating, np.integer)):
        val = float(delta0)
    else:
        raise InputTypeError(f"delta0 must be a positive real number, got {delta0!r} ({type(delta0).__name__})")
    if not math.isfinite(val) or val <= 0:
        raise InputError(f"delta0 (the indentation depth) must be a finite number > 0, got {delta0}")
    return val


# ---------------------------------------------------------------------------------------------
# self-checks of the spectral contour (step 5)
# ---------------------------------------------------------------------------------------------
def _accuracy(P, delta0, Z, L) -> ContourAccuracy:
    N = len(Z)
    Zhat = np.fft.fft(Z)
    h = L / (2 * N)
    zm = uniform_eval(Zhat, L, shift=h)
    d1 = uniform_eval(Zhat, L, shift=h, deriv=1)
    f, gx, gy, *_ = P.all(zm.real, zm.imag)
    dist = float(np.max(np.abs(f - delta0) / np.hypot(gx, gy))) / L
    speed = float(np.max(np.abs(np.abs(d1) - 1.0)))
    d1n = uniform_eval(Zhat, L, deriv=1)
    d2n = uniform_eval(Zhat, L, deriv=2)
    kap = (np.conj(d1n) * d2n).imag
    turning = float(np.sum(kap) * L / N / (2 * np.pi))
    return ContourAccuracy(dist, speed, tail(Zhat), turning)


def _acceptable(acc: ContourAccuracy, strict: float) -> bool:
    return (abs(acc.turning_number - 1.0) <= 1e-6 and acc.level_distance <= strict
            and acc.speed_error <= strict)


# ---------------------------------------------------------------------------------------------
# results
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ContourAccuracy:
    """Self-checks of the spectral contour (all measured between the nodes).

    For an elongated contour they are those of its round image ``w`` (``x = W w``, module docstring),
    whose arc length sigma is the parameter of the Fourier series.

    Attributes
    ----------
    level_distance : float
        max |Phi(f(s)) - delta0| / |grad Phi|, the distance of the interpolant from Gamma_0,
        relative to the perimeter.
    speed_error : float
        max | |f'(s)| - 1 | (arc-length parametrisation).
    spectral_tail : float
        largest Fourier coefficient in the upper half of the band, relative to the largest one.
    turning_number : float
        (1/2 pi) oint kappa ds; 1 for a simple closed CCW curve (closure of the tangent).
    """

    level_distance: float
    speed_error: float
    spectral_tail: float
    turning_number: float


@boundary_methods
@dataclass(frozen=True, eq=False)
class ContactContour(RichDisplay):
    r"""The leading contact area omega_0 = {delta0 - Phi > 0} and its contour Gamma_0 (3.3)-(3.14).

    Made by :func:`contact_contour`; dimensional coordinates.  ``s`` is the arc length along
    Gamma_0 in ``[0, perimeter)`` (periodic), counterclockwise, ``omega_0`` on the left.
    All evaluators are vectorised over ``s`` (any shape); vector-valued ones return arrays with a
    trailing axis of length 2.  An elongated contour (aspect ratio above 3) is held as
    ``x = W w(sigma)`` with its arc length ``s(sigma)`` (module docstring); the evaluators are the
    same functions of ``s``.

    Attributes
    ----------
    Phi, delta0
        The punch (sympy, in ``thinlayer.symbols.x1, x2``) and the indentation.
    perimeter, area, centroid
        Length of Gamma_0, area and centroid of omega_0.
    nodes : numpy.ndarray
        ``(N, 2)`` points of Gamma_0 at ``s_j = j perimeter / N``.
    min_point, min_value
        Where Phi is smallest and its value (the first point of contact).
    accuracy : ContourAccuracy
        :class:`ContourAccuracy` (of the round image ``w`` for an elongated contour).
    """

    #: the paper's equation this result reproduces
    equation: ClassVar[str] = "3.3"

    Phi: sp.Expr
    delta0: float
    perimeter: float
    area: float
    centroid: tuple[float, float]
    nodes: np.ndarray = field(repr=False)
    min_point: tuple[float, float]
    min_value: float
    accuracy: ContourAccuracy
    _k: np.ndarray = field(repr=False)
    _c: np.ndarray = field(repr=False)
    _poly: Poly2 = field(repr=False)
    _star_center: tuple[float, float] | None = field(repr=False)
    _framed: FramedCurve | None = field(default=None, repr=False)

    # ---- the curve (3.3) ------------------------------------------------------------------
    def _z(self, s, m=0):
        if self._framed is not None:
            return self._framed.z(s, m)
        return trig_eval(self._k, self._c, self.perimeter, s, m)

    @staticmethod
    def _pair(z):
        return np.stack([z.real, z.imag], axis=-1)

    def f(self, s) -> np.ndarray:
        """The point ``f(s) = (f1(s), f2(s))`` of Gamma_0 (3.3), natural parametrisation."""
        return self._pair(self._z(s))

    def derivative(self, s, order: int = 1) -> np.ndarray:
        """``d^order f / ds^order`` (spectral)."""
        if not isinstance(order, (int, np.integer)) or order < 0:
            raise InputError(f"order must be an integer >= 0, got {order!r}")
        return self._pair(self._z(s, int(order)))

    def tangent(self, s) -> np.ndarray:
        """Unit tangent ``f'(s) = (cos psi, sin psi)`` (3.9)."""
        return self._pair(self._z(s, 1))

    def normal(self, s) -> np.ndarray:
        """Inward unit normal ``n0(s) = (-f2'(s), f1'(s))`` (3.3)."""
        d = self._z(s, 1)
        return self._pair(1j * d)

    def curvature(self, s) -> np.ndarray:
        """Signed curvature ``kappa = f1' f2'' - f2' f1''`` (> 0 where omega_0 is convex)."""
        d1 = self._z(s, 1)
        d2 = self._z(s, 2)
        return (np.conj(d1) * d2).imag

    def rho(self, s) -> np.ndarray:
        """Curvature radius ``rho(s) = 1/(f2'' f1' - f1'' f2')`` (after (3.6)); inf at inflections."""
        k = self.curvature(s)
        with np.errstate(divide="ignore"):
            return 1.0 / k

    def local_to_cartesian(self, s, n) -> np.ndarray:
        """``x = f(s) + n n0(s)`` (3.4): ``n`` is the signed distance along the inward normal."""
        s, n = np.broadcast_arrays(np.asarray(s, dtype=float), np.asarray(n, dtype=float))
        z = self._z(s) + n * 1j * self._z(s, 1)
        return self._pair(z)

    def g(self, s) -> np.ndarray:
        """``|grad Phi|`` on Gamma_0 at ``f(s)``."""
        p = self.f(s)
        gx, gy = self._poly.grad(p[..., 0], p[..., 1])
        return np.hypot(gx, gy)

    def b1(self, s) -> np.ndarray:
        """``b1(s) = -grad Phi(f(s)) . n0(s)``: ``delta0 - Phi(f + n n0) = b1 n + b2 n^2 + O(n^3)``.

        Dimensional form of (3.14): ``b1 = eps H_* b1^* = H b1^*`` (module docstring).  On the
        level set ``n0 = -grad Phi/|grad Phi|``, so ``b1 = g > 0``.
        """
        p = self.f(s)
        nn = self.normal(s)
        gx, gy = self._poly.grad(p[..., 0], p[..., 1])
        return -(gx * nn[..., 0] + gy * nn[..., 1])

    def b2(self, s) -> np.ndarray:
        """``b2(s) = -n0^T Hess(Phi) n0 / 2`` (dimensional form of (3.14): ``b2 = eps b2^*``)."""
        p = self.f(s)
        nn = self.normal(s)
        _, _, _, hxx, hxy, hyy = self._poly.all(p[..., 0], p[..., 1])
        n1, n2 = nn[..., 0], nn[..., 1]
        return -0.5 * (hxx * n1 * n1 + 2 * hxy * n1 * n2 + hyy * n2 * n2)

    def b_star(self, s, epsilon: float, H_s: float) -> tuple[np.ndarray, np.ndarray]:
        """The starred coefficients of (3.13)-(3.14): ``b1^* = b1/(eps H_*)``, ``b2^* = b2/eps``.

        ``s`` is the dimensional arc length (``s^* = s/H_*``).  Derived in the module docstring from
        (1.2), (2.8), (2.13): ``delta0 - Phi = eps H_*^2 (b1^* n^* + b2^* n^{*2})`` with ``n = H_* n^*``.
        """
        for nm, v in (("epsilon", epsilon), ("H_s", H_s)):
            if isinstance(v, bool) or not isinstance(v, numbers.Real) or not v > 0:
                raise InputError(f"{nm} must be a number > 0, got {v!r}")
        return self.b1(s) / (epsilon * H_s), self.b2(s) / epsilon

    # ---- the region --------------------------------------------------------------------
    def phi(self, x1, x2) -> np.ndarray:
        """Phi(x1, x2), vectorised."""
        return self._poly.value(x1, x2)

    def contains(self, x1, x2) -> np.ndarray:
        """``delta0 - Phi(x1, x2) > 0``: membership of omega_0 (the whole set is one region)."""
        return self._poly.value(x1, x2) < self.delta0

    @property
    def is_star_shaped(self) -> bool:
        """Whether omega_0 is star-shaped about its centroid or its lowest point (used by integrate)."""
        return self._star_center is not None

    def integrate(self, F: Callable, n_radial: int = 40, n_angular: int | None = None) -> float:
        r"""``\iint_{omega_0} F(x1, x2) dx1 dx2`` for a vectorised numpy function ``F(x1, x2)``.

        Star-shaped omega_0 (about a centre c): ``x = c + lambda (f(s) - c)``,
        ``dA = lambda (f - c) x f'(s) dlambda ds``; trapezoidal rule in the periodic ``s`` (spectral)
        and Gauss-Legendre in ``u`` with ``lambda = 1 - (1 - u)^2``, which also makes integrands
        like ``sqrt(delta0 - Phi)`` or ``1/sqrt(delta0 - Phi)`` smooth at the edge.  F is only
        evaluated inside omega_0.  Otherwise Green's theorem ``iint F = oint G dx2`` with
        ``G(x1, x2) = int_{c1}^{x1} F(t, x2) dt``; then F must be smooth on the horizontal segments
        from ``x1 = c1`` to the contour (e.g. a polynomial).  An elongated contour (round frame
        ``x = W w(sigma)``, see :func:`contact_contour`) uses the same formulas in its smooth
        parameter sigma instead of ``s`` (``f'(s) ds = x'(sigma) dsigma``), with
        ``(f - c) x x'(sigma) = det W (w - w_c) x w'(sigma)``; ``n_angular`` then counts sigma nodes.
        """
        if not callable(F):
            raise InputTypeError(f"F must be a vectorised function F(x1, x2), got {F!r}")
        if not isinstance(n_radial, (int, np.integer)) or n_radial < 2:
            raise InputError(f"n_radial must be an integer >= 2, got {n_radial!r}")
        N = len(self.nodes)
        M = int(n_angular) if n_angular is not None else max(2 * N, 128)
        if M < 8:
            raise InputError(f"n_angular must be >= 8, got {n_angular!r}")
        if self._framed is None:
            s = self.perimeter * np.arange(M) / M
            z, dz, step = self._z(s), self._z(s, 1), self.perimeter / M
        else:
            z, dz, step, wz, dwz = self._framed.samples(M)
        u, wu = _gauss_legendre(int(n_radial))
        u = 0.5 * (u + 1.0)
        wu = 0.5 * wu
        if self._star_center is not None:
            c = complex(*self._star_center)
            lam = 1.0 - (1.0 - u) ** 2
            dlam = 2.0 * (1.0 - u)
            r = z - c
            if self._framed is None:
                jac = (np.conj(r) * dz).imag  # (f - c) x f'
            else:  # det W (w - w_c) x w': no cancellation between the long and the short axis
                cw = complex(*self._framed.to_w(self._star_center))
                jac = self._framed.det * (np.conj(wz - cw) * dwz).imag
            pts = c + lam[:, None] * r[None, :]
            vals = np.asarray(F(pts.real, pts.imag), dtype=float) * np.ones(pts.shape)
            inner = (vals * (lam * dlam * wu)[:, None]).sum(axis=0)
            return float(np.sum(inner * jac) * step)
        c1 = self.centroid[0]
        x1 = z.real
        pts_x = c1 + u[:, None] * (x1 - c1)[None, :]
        pts_y = np.broadcast_to(z.imag[None, :], pts_x.shape)
        vals = np.asarray(F(pts_x, pts_y), dtype=float) * np.ones(pts_x.shape)
        G = (x1 - c1) * (vals * wu[:, None]).sum(axis=0)
        return float(np.sum(G * dz.imag) * step)

    def boundary_integral(self, g: Callable, of: str = "x", n: int | None = None) -> float:
        """``oint_{Gamma_0} g ds`` by the trapezoidal rule in arc length (spectral for smooth g).

        ``of="x"``: ``g(x1, x2)`` a vectorised function of the point; ``of="s"``: ``g(s)``
        (e.g. ``contour.b1``).  An elongated contour (round frame, see :func:`contact_contour`):
        ``oint g ds = oint g |x'(sigma)| dsigma`` by Gauss-Legendre on the panels that resolve the
        speed ``|x'(sigma)|`` near the tips (``n``: at least that many nodes).
        """
        if not callable(g):
            raise InputTypeError(f"g must be a vectorised function, got {g!r}")
        if of not in ("x", "s"):
            raise InputError(f"of must be 'x' (g(x1, x2)) or 's' (g(s)), got {of!r}")
        M = int(n) if n is not None else max(2 * len(self.nodes), 128)
        if M < 8:
            raise InputError(f"n must be >= 8, got {n!r}")
        if self._framed is not None:
            sig, wts, sq = self._framed.arc.quadrature(M if n is not None else 0)
            jac = self._framed.speed(sig) * wts
            if of == "s":
                vals = np.asarray(g(sq), dtype=float) * np.ones(len(sq))
            else:
                p = self._framed.x(sig)
                vals = np.asarray(g(p.real, p.imag), dtype=float) * np.ones(len(sq))
            return float(np.sum(vals * jac))
        s = self.perimeter * np.arange(M) / M
        if of == "s":
            vals = np.asarray(g(s), dtype=float) * np.ones(M)
        else:
            p = self.f(s)
            vals = np.asarray(g(p[:, 0], p[:, 1]), dtype=float) * np.ones(M)
        return float(np.sum(vals) * self.perimeter / M)

    def latex(self) -> str:
        """LaTeX summary: the contour equation and its measured size."""
        return (
            r"\Gamma_0:\ " + normal_latex(self.Phi) + rf" = {normal_latex(sp.Float(self.delta0, 12), digits=12)}"
            rf",\quad |\Gamma_0| = {self.perimeter:.12g},\quad |\omega_0| = {self.area:.12g}"
        )

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        acc = self.accuracy
        return [
            f"ContactContour: Γ₀ = {{{fmt(self.Phi)} = {fmt(self.delta0)}}}   (3.3)-(3.14)",
            f"  perimeter |Γ₀| = {fmt(self.perimeter)}, area |ω₀| = {fmt(self.area)}",
            f"  centroid ({fmt(self.centroid[0])}, {fmt(self.centroid[1])}), {len(self.nodes)} nodes",
            (f"  accuracy: distance from Gamma_0 {acc.level_distance:.1e}, arc-length speed {acc.speed_error:.1e}, "
            f"turning number {acc.turning_number:.12g}"),
        ]


# ---------------------------------------------------------------------------------------------
# the stage function
# ---------------------------------------------------------------------------------------------
@boundary
def contact_contour(Phi, delta0, n: int | None = None, tol: float = 1e-12) -> ContactContour:
    r"""The leading contact area ``omega_0 = {delta0 - Phi > 0}`` and its contour Gamma_0 (3.1)-(3.14).

    Parameters
    ----------
    Phi
        The punch shape, a sympy polynomial in ``thinlayer.symbols.x1, x2`` with numeric
        coefficients (or a :class:`thinlayer.Punch` with numeric parameters, or a string).
    delta0
        The indentation depth, a number > 0.
    n : int | None
        Number of equally spaced arc-length nodes of the trigonometric interpolant (even,
        >= 16); then no accuracy is enforced (read ``.accuracy``).  Default: adaptive, doubling
        until the Fourier tail is below ``tol`` and the self-checks pass to 1e-9.  For an elongated
        contour (aspect ratio above 3) the interpolant is that of the round image ``w`` (module
        docstring); ``.nodes`` still holds ``n`` points at equal arc length of Gamma_0.
    tol : float
        Target relative size of the Fourier tail (adaptive mode).

    Returns
    -------
    ContactContour

    Raises
    ------
    ValueError
        delta0 <= 0; Phi not a polynomial in x1, x2 or with other free symbols; no contact
        (delta0 <= min Phi, the minimum is named); an unbounded region; several components
        or a hole; a level set through a critical point of Phi (not smooth); an aspect ratio
        (longest/shortest principal axis of omega_0) above ``ASPECT_MAX = 1e100``, beyond the
        double range.  Overall scale and elongation are free: the region search runs in the
        natural frame of Phi at delta0 and an elongated contour is represented in its round frame
        (module docstring), so ``1e-70 (x1^2 + 4 x2^2)``, ``1e30 (x1^2 + 4 x2^2)`` and
        ``1e-30 x1^2 + 1e30 x2^2`` (aspect ratio 1e30) work alike.

    Examples
    --------
    >>> import math
    >>> from thinlayer.symbols import x1, x2
    >>> c = contact_contour(x1**2/(2*4) + x2**2/(2*1), 0.5)   # a = 2, b = 1
    >>> round(c.area / math.pi, 10)
    2.0
    """
    d0 = _as_delta0(delta0)
    expr, terms = _polynomial(Phi)
    if n is not None and (not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 16 or n % 2):
        raise InputError(f"n (number of contour nodes) must be an even integer >= 16, got {n!r}")
    if not (isinstance(tol, (int, float)) and 0 < tol < 1):
        raise InputError(f"tol must be a number in (0, 1), got {tol!r}")
    P = Poly2(terms)
    if P.deg < 2 and P.deg >= 1:
        raise InputError(f"the contact area {{delta0 - Phi > 0}} is unbounded: Phi = {expr} is linear "
                         "(a half-plane); the punch must rise in every direction")
    poly, _, best, aspect, fr, curve_u = region(P, d0, expr)
    if not aspect <= ASPECT_MAX:
        raise too_elongated(expr, d0, aspect)
    if aspect <= ASPECT_DIRECT:
        # the spectral work in x = ell u, Phi = d0 Phi~ (ell the size of the region): arc length scales by ell
        ell = float(np.max(np.abs(poly)))
        frame, polys, det = Frame(ell * np.eye(2), ell, d0), poly / ell, ell * ell
    else:
        # elongated: the spectral work in the round frame x = W w (step 0 of the module docstring)
        frame, polys, det = round_frame(curve_u, fr)
        kap = float(np.max(np.abs(polys)))
        frame, polys, det = Frame(frame.A * kap, frame.ell * kap, d0), polys / kap, det * kap * kap
    Ps = transformed(P, frame)
    res = nodes_by_reference(Ps, 1.0, polys, n, tol)
    acc = _accuracy(Ps, 1.0, *res) if res is not None else None
    if acc is None or (n is None and not _acceptable(acc, 1e-9)):
        alt = nodes_by_ode(Ps, 1.0, polys, n, tol)
        if alt is not None:
            acc_alt = _accuracy(Ps, 1.0, *alt)
            if acc is None or acc_alt.speed_error < acc.speed_error:
                res, acc = alt, acc_alt
    if acc is None or (not _acceptable(acc, 1e-6) if n is None else abs(acc.turning_number - 1) > 1e-3):
        raise ComputationError(
            f"the spectral contour of Phi = {expr} at delta0 = {short(d0)} is inaccurate ({acc}): the contour "
            f"has features too small for {NMAX} arc-length nodes; try a larger n"
        )
    if aspect <= ASPECT_DIRECT:
        return _direct_contour(expr, d0, P, res[0] * ell, res[1] * ell, best, acc)
    return _framed_contour(expr, d0, P, Ps, frame.A, det, res[0], res[1], best, acc)


def _polynomial(Phi) -> tuple[sp.Expr, list[tuple[int, int, float]]]:
    """:func:`as_polynomial`, kept per punch (the contour of another depth needs the same terms)."""
    try:
        expr, terms = _polynomial_cached(Phi)
    except TypeError:  # unhashable input: no cache
        return as_polynomial(Phi)
    return expr, list(terms)


@lru_cache(maxsize=256)
def _polynomial_cached(Phi) -> tuple[sp.Expr, tuple[tuple[int, int, float], ...]]:
    expr, terms = as_polynomial(Phi)
    return expr, tuple(terms)


@lru_cache(maxsize=32)
def _gauss_legendre(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss--Legendre nodes and weights on [-1, 1] (read-only arrays, computed once per n)."""
    u, w = np.polynomial.legendre.leggauss(n)
    u.flags.writeable = False
    w.flags.writeable = False
    return u, w


def _direct_contour(expr, d0, P, Z, L, best, acc) -> ContactContour:
    """Gamma_0 by its arc-length Fourier series in x (aspect ratio up to ``ASPECT_DIRECT``)."""
    N = len(Z)
    Zhat = np.fft.fft(Z)
    k, c = sym_coeffs(Zhat)
    # area and centroid by Green's theorem (trapezoidal in s, spectral)
    dZ = uniform_eval(Zhat, L, deriv=1)
    x, y, dx, dy = Z.real, Z.imag, dZ.real, dZ.imag
    ds = L / N
    area = 0.5 * float(np.sum(x * dy - y * dx)) * ds
    cx = 0.5 * float(np.sum(x * x * dy)) * ds / area
    cy = -0.5 * float(np.sum(y * y * dx)) * ds / area
    # a centre about which omega_0 is star-shaped (for integrate)
    star = None
    for cand in ((cx, cy), (best[1], best[2])):
        r = Z - complex(*cand)
        cross = (np.conj(r) * dZ).imag
        if P.value(*cand) < d0 and cross.min() > 1e-3 * cross.max():
            star = (float(cand[0]), float(cand[1]))
            break
    return ContactContour(
        Phi=expr, delta0=d0, perimeter=float(L), area=area, centroid=(cx, cy),
        nodes=np.column_stack([x, y]), min_point=(best[1], best[2]), min_value=best[0],
        accuracy=acc, _k=k, _c=c, _poly=P, _star_center=star,
    )


def _framed_contour(expr, d0, P, Pw, W, det, Zw, Lw, best, acc) -> ContactContour:
    """Gamma_0 as ``x = W w(sigma)`` (elongated): w by its arc-length Fourier series in the round frame.

    Area and centroid by Green's theorem in w (spectral) and the map: ``|omega_0| = det W |w(omega_0)|``,
    the centroid is ``W`` times the centroid in w; star-shapedness is affine invariant, so it is
    tested in w.  The perimeter is ``fc.arc.length`` (``_ArcLength`` in :mod:`._contour_elongated`: the
    Jacobian ``|W w'|`` on panels).
    """
    N = len(Zw)
    Zhat = np.fft.fft(Zw)
    k, c = trim(*sym_coeffs(Zhat))
    fc = FramedCurve(W, det, k, c, Lw, Pw)
    dZ = uniform_eval(Zhat, Lw, deriv=1)
    x, y, dx, dy = Zw.real, Zw.imag, dZ.real, dZ.imag
    ds = Lw / N
    area_w = 0.5 * float(np.sum(x * dy - y * dx)) * ds
    cw = (0.5 * float(np.sum(x * x * dy)) * ds / area_w, -0.5 * float(np.sum(y * y * dx)) * ds / area_w)
    cen = fc.apply(complex(*cw))
    star = None
    for cand_x, cand_w in (((cen.real, cen.imag), cw), ((best[1], best[2]), tuple(fc.to_w((best[1], best[2]))))):
        cross = (np.conj(Zw - complex(*cand_w)) * dZ).imag
        if P.value(*cand_x) < d0 and cross.min() > 1e-3 * cross.max():
            star = (float(cand_x[0]), float(cand_x[1]))
            break
    L = fc.arc.length
    nodes = fc.z(L * np.arange(N) / N)
    return ContactContour(
        Phi=expr, delta0=d0, perimeter=L, area=det * area_w, centroid=(float(cen.real), float(cen.imag)),
        nodes=np.column_stack([nodes.real, nodes.imag]), min_point=(best[1], best[2]), min_value=best[0],
        accuracy=acc, _k=k, _c=c, _poly=P, _star_center=star, _framed=fc,
    )


# ---------------------------------------------------------------------------------------------
# the elliptic paraboloid in closed form (3.1)
# ---------------------------------------------------------------------------------------------
@boundary_methods
@dataclass(frozen=True)
class EllipseContour(RichDisplay):
    r"""Closed form of Gamma_0 for the elliptic paraboloid (1.1), (3.1).

    ``Phi = x1^2/(2 R1) + x2^2/(2 R2) = delta0`` is ``x1^2/a^2 + x2^2/b^2 = 1`` with
    ``a = sqrt(2 delta0 R1)`` (along x1), ``b = sqrt(2 delta0 R2)`` (along x2).  With the paper's
    ``R1 >= R2``, ``a`` is the major semi-axis and ``e^2 = 1 - b^2/a^2 = 1 - R2/R1`` (3.1).
    """

    #: the paper's equation this result reproduces
    equation: ClassVar[str] = "3.1"

    R1: sp.Expr
    R2: sp.Expr
    delta0: sp.Expr
    a: sp.Expr
    b: sp.Expr
    e2: sp.Expr
    area: sp.Expr
    perimeter: sp.Expr

    def curvature_radius(self, x1, x2) -> sp.Expr:
        """Curvature radius at a point of the ellipse: ``a^2 b^2 (x1^2/a^4 + x2^2/b^4)^(3/2)``."""
        x1, x2 = sympy_value(x1, "x1"), sympy_value(x2, "x2")
        return self.a**2 * self.b**2 * (x1**2 / self.a**4 + x2**2 / self.b**4) ** sp.Rational(3, 2)

    def scaled_semi_axes(self) -> tuple[sp.Expr, sp.Expr]:
        """Semi-axes in the scaled coordinates xi = x/H_* (2.8) with the data (1.2), (3.1).

        Substitutes ``delta0 = eps delta0^*``, ``R_j = R_j^*/eps`` into ``a/H_*``, ``b/H_*``;
        eps cancels: ``a^* = sqrt(2 delta0^* R1^*)/H_*`` (printed (3.1) shows ``R_1``).
        Needs symbolic ``R1, R2, delta0``.
        """
        for nm, v in (("R1", self.R1), ("R2", self.R2), ("delta0", self.delta0)):
            if not isinstance(v, sp.Symbol):
                raise InputTypeError(f"scaled_semi_axes needs a symbolic {nm} (a sympy Symbol), got {v}")
        eps = S.epsilon
        rep = {self.delta0: eps * S.delta0_s, self.R1: S.starred(self.R1) / eps,
               self.R2: S.starred(self.R2) / eps}
        return tuple(sp.simplify(v.xreplace(rep) / S.H_s) for v in (self.a, self.b))

    def latex(self) -> str:
        return (
            rf"a = {normal_latex(self.a)},\quad b = {normal_latex(self.b)},\quad "
            rf"e^2 = {normal_latex(self.e2)} \tag{{3.1}} \\" + "\n"
            rf"|\omega_0| = {normal_latex(self.area)},\quad |\Gamma_0| = {normal_latex(self.perimeter)}"
            + (r",\quad \mathrm{E}(k) = \int_0^{\pi/2}\sqrt{1 - k^2 \sin^2\theta}\,d\theta,\ k = e"
               if self.perimeter.has(sp.elliptic_e) else "")
        )

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return [
            "EllipseContour: x₁²/a² + x₂²/b² = 1   (3.1)",
            f"  a  = {fmt(self.a)}",
            f"  b  = {fmt(self.b)}",
            f"  e² = {fmt(self.e2)}",
            f"  area |ω₀| = {fmt(self.area)}, perimeter |Γ₀| = {fmt(self.perimeter)}"
            + ("   (E(k): complete elliptic integral of the second kind, modulus k = e)"
               if self.perimeter.has(sp.elliptic_e) else ""),
        ]


@boundary
def ellipse_contour(R1=None, R2=None, delta0=None) -> EllipseContour:
    """Closed-form contour of the elliptic paraboloid (1.1): semi-axes and eccentricity (3.1).

    Parameters
    ----------
    R1, R2
        Principal radii of curvature (numbers > 0 or symbols; default the symbols ``R_1, R_2``
        of :meth:`thinlayer.Punch.elliptic_paraboloid`).  The paper takes ``R1 >= R2``; numeric
        ``R1 < R2`` gives ``e^2 = 1 - R1/R2`` (major axis along x2).
    delta0
        Indentation (default the symbol ``thinlayer.symbols.delta0``).

    Examples
    --------
    >>> ellipse_contour().a
    sqrt(2)*sqrt(R_1)*sqrt(delta_0)
    >>> ellipse_contour(4, 1, sp.Rational(1, 2)).e2
    3/4
    """
    r1 = sp.Symbol("R_1", positive=True) if R1 is None else as_expr(R1)
    r2 = sp.Symbol("R_2", positive=True) if R2 is None else as_expr(R2)
    d0 = S.delta0 if delta0 is None else as_expr(delta0)
    for nm, v in (("R1", r1), ("R2", r2), ("delta0", d0)):
        if v.is_number and not (v.is_real and v > 0):
            raise InputError(f"{nm} must be positive, got {v}")
    a = sp.sqrt(2 * d0 * r1)
    b = sp.sqrt(2 * d0 * r2)
    if (r1 - r2).is_number and (r1 - r2) < 0:
        e2 = 1 - r1 / r2
        major = b
    else:
        e2 = 1 - r2 / r1
        major = a
    per = 4 * major * sp.elliptic_e(e2)
    return EllipseContour(r1, r2, d0, a, b, e2, sp.pi * a * b, per)
