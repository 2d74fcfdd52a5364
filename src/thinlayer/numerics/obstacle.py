r"""The thin-layer free-boundary problem (I.3)-(I.4) / (I.10) on a grid, for any punch.

The obstacle problem ``min sum (|grad_h p|^2/2 + k^2 p^2/2 - f p)`` over ``p >= 0`` with the 5-point
Laplacian, solved by the primal-dual active-set method with nested iteration
(:func:`solve_obstacle_grid`).  The model's coefficients ``c_0 = A``, ``c_1 = A m_1`` ((I.1) at
``nu = 1/2``) and ``vartheta`` come from the layer (``layer.taylor_coefficients(1)``,
``layer.vartheta``); the symbolic problem is :func:`thinlayer.asymptotics.incompressible.obstacle_problem`.
"""
from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import ComputationError, InputError, InputTypeError, check_bounded, parse_nu, positive
from ..errors import boundary, boundary_methods
from ..layers.kernels import BondedLayer, IncompressibleLayer, LayerKernel
from ..punch import is_polynomial_tip

__all__ = ["GridContact", "solve_obstacle_grid"]

QUARTER = sp.Rational(1, 4)
#: Largest nodes per side: sparse LU solves of (n - 2)^2 unknowns, nested.  Measured (2 cores, paraboloid):
#: n = 161 (the default) 2.1 s, n = 321 10 s (fill and time grow like n^3).
MAX_NODES = 321
RANGE_HINT = ("the incompressible/two-term models need m_1 > 0, so that -m_1 H^2 Delta + 1 is elliptic; "
              "for nu <= 1/4 use the compressible expansion (thinlayer.inner_pressure, thinlayer.solve)")


# =============================================================================================
# numerics on a grid: (I.3)-(I.4) and (I.10) for any punch
# =============================================================================================
@boundary_methods
@dataclass(frozen=True)
class GridContact:
    """Grid solution of the obstacle problem (I.3)-(I.4) / (I.10).

    Attributes
    ----------
    nu, delta0, H, mu : float
        Parameters.  ``k2`` is ``c_0/(c_1 H^2)`` (zero at nu = 1/2).
    x1, x2 : numpy.ndarray
        Grid coordinates (1-D, read-only); ``pressure[i, j]`` is ``p(x1[i], x2[j])``.
    pressure, contact : numpy.ndarray
        Pressure and contact set ``p > 0`` (read-only arrays).
    force : float
        ``P = sum p h1 h2`` (1.8).
    area : float
        Number of contact nodes times ``h1 h2`` (first-order accurate).
    iterations : int
        Active-set iterations on the finest grid.
    volume_residual : float
        ``int_omega f / int_omega |f|`` -- zero for the exact solution at nu = 1/2 (I.5).
    """

    nu: float
    delta0: float
    H: float
    mu: float
    k2: float
    x1: np.ndarray = field(repr=False)
    x2: np.ndarray = field(repr=False)
    pressure: np.ndarray = field(repr=False)
    contact: np.ndarray = field(repr=False)
    force: float = 0.0
    area: float = 0.0
    iterations: int = 0
    volume_residual: float = 0.0

    equation = "I.3"

    @property
    def h(self) -> tuple[float, float]:
        return float(self.x1[1] - self.x1[0]), float(self.x2[1] - self.x2[0])

    def moments(self) -> tuple[float, float, float, float, float]:
        """``(x1c, x2c, <dx1^2>, <dx1 dx2>, <dx2^2>)``: pressure-weighted centroid and second moments.

        For ``p = C (1 - x1^2/a^2 - x2^2/b^2)^2``, ``<x1^2> = a^2/8`` and ``<x2^2> = b^2/8``.
        """
        X1, X2 = np.meshgrid(self.x1, self.x2, indexing="ij")
        w = self.pressure / self.pressure.sum()
        c1, c2 = float((w * X1).sum()), float((w * X2).sum())
        d1, d2 = X1 - c1, X2 - c2
        return c1, c2, float((w * d1 * d1).sum()), float((w * d1 * d2).sum()), float((w * d2 * d2).sum())

    def extent(self) -> tuple[float, float, float, float]:
        """``(x1 min, x1 max, x2 min, x2 max)`` of the contact nodes, widened by half a cell."""
        i, j = np.nonzero(self.contact)
        h1, h2 = self.h
        return (float(self.x1[i.min()] - h1 / 2), float(self.x1[i.max()] + h1 / 2),
                float(self.x2[j.min()] - h2 / 2), float(self.x2[j.max()] + h2 / 2))

    def pressure_at(self, x1: Any, x2: Any) -> np.ndarray:
        """Bilinear interpolation of the grid pressure (zero outside the grid)."""
        from scipy.interpolate import RegularGridInterpolator

        f = RegularGridInterpolator((self.x1, self.x2), self.pressure, bounds_error=False, fill_value=0.0)
        x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
        return f(np.stack([x1.ravel(), x2.ravel()], axis=-1)).reshape(x1.shape)

    def lambdify(self) -> Callable:
        """The pressure as a numeric function ``p(x1, x2)`` (bilinear interpolation)."""
        return self.pressure_at

    def latex(self) -> str:
        h1, h2 = self.h
        return (rf"P = {self.force:.8g},\quad |\omega| = {self.area:.6g},\quad h = ({h1:.3g}, {h2:.3g}),\quad "
                rf"\nu = {self.nu:g},\quad \delta_0 = {self.delta0:g},\quad H = {self.H:g} \tag{{I.3}}")


def _numeric_phi(punch: Any, parameters: dict | None) -> Callable:
    if is_polynomial_tip(punch):
        pn = punch.subs(parameters) if parameters else punch
        if pn.parameters:
            raise InputError(f"the punch parameters {[q.name for q in pn.parameters]} need values (parameters=...)")
        f = sp.lambdify((S.x1, S.x2), pn.expr, "numpy")
        return lambda a, b: np.broadcast_to(np.asarray(f(a, b), dtype=float), np.broadcast(a, b).shape)
    if callable(punch):
        if parameters:
            raise InputError("parameters= only applies to a Punch")
        return lambda a, b: np.broadcast_to(np.asarray(punch(a, b), dtype=float), np.broadcast(a, b).shape)
    raise InputTypeError(f"punch must be a thinlayer.Punch or a callable Phi(x1, x2), got {type(punch).__name__}")


def _default_box(phi: Callable, delta0: float) -> tuple[float, float, float, float]:
    """Twice the bounding box of ``{Phi < delta0}`` (found along 256 rays from the origin)."""
    if not phi(np.array(0.0), np.array(0.0)) < delta0:
        raise InputError(f"Phi(0, 0) >= delta0 = {delta0}: the punch does not touch the layer at the origin; "
                         "give box=(x1min, x1max, x2min, x2max)")
    th = np.linspace(0, 2 * np.pi, 256, endpoint=False)
    c, s = np.cos(th), np.sin(th)
    hi = np.ones_like(th)
    for _ in range(200):
        grow = phi(hi * c, hi * s) < delta0
        if not grow.any():
            break
        hi = np.where(grow, hi * 2, hi)
    else:
        raise InputError("Phi does not reach delta0 along some rays: the contact region is unbounded")
    lo = np.zeros_like(th)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        inside = phi(mid * c, mid * s) < delta0
        lo, hi = np.where(inside, mid, lo), np.where(inside, hi, mid)
    x, y = hi * c, hi * s
    cx, cy = 0.5 * (x.max() + x.min()), 0.5 * (y.max() + y.min())
    wx, wy = x.max() - cx, y.max() - cy
    return cx - 2 * wx, cx + 2 * wx, cy - 2 * wy, cy + 2 * wy


def _pdas(A, b: np.ndarray, inactive: np.ndarray, maxit: int) -> tuple[np.ndarray, int]:
    """Primal-dual active set (semismooth Newton) for ``A p - b = lam >= 0, p >= 0, p lam = 0``."""
    from scipy.sparse.linalg import spsolve

    for it in range(1, maxit + 1):
        p = np.zeros_like(b)
        idx = np.nonzero(inactive)[0]
        if idx.size:
            p[idx] = spsolve(A[idx][:, idx].tocsc(), b[idx])
        lam = A @ p - b
        lam[idx] = 0.0
        new = ~((lam > 0) | (p < 0))  # active: lam - c p > 0 (p = 0 there, lam = 0 elsewhere)
        if np.array_equal(new, inactive):
            return np.maximum(p, 0.0), it
        inactive = new
    raise ComputationError(f"the active-set iteration did not converge in {maxit} steps")


def _grid_solve(phi, d0, th, c0, c1, H, mu, box, n, maxit, coarsest=41):
    import scipy.sparse as sps

    x1 = np.linspace(box[0], box[1], n)
    x2 = np.linspace(box[2], box[3], n)
    h1, h2 = x1[1] - x1[0], x2[1] - x2[0]
    m = n - 2
    X1, X2 = np.meshgrid(x1[1:-1], x2[1:-1], indexing="ij")
    f = th * mu * (d0 - phi(X1, X2)) / (c1 * H**3)
    k2 = c0 / (c1 * H**2)
    T1 = sps.diags([-np.ones(m - 1), 2 * np.ones(m), -np.ones(m - 1)], [-1, 0, 1]) / h1**2
    T2 = sps.diags([-np.ones(m - 1), 2 * np.ones(m), -np.ones(m - 1)], [-1, 0, 1]) / h2**2
    I = sps.identity(m)
    A = (sps.kron(T1, I) + sps.kron(I, T2) + k2 * sps.identity(m * m)).tocsr()
    b = f.ravel()
    if (n - 1) % 2 == 0 and (n - 1) // 2 + 1 >= coarsest:
        # nested iteration: the coarse solution's support is the initial inactive set
        pc, *_ = _grid_solve(phi, d0, th, c0, c1, H, mu, box, (n - 1) // 2 + 1, maxit, coarsest)
        from scipy.interpolate import RegularGridInterpolator

        xc1, xc2 = np.linspace(box[0], box[1], (n - 1) // 2 + 1), np.linspace(box[2], box[3], (n - 1) // 2 + 1)
        pi = RegularGridInterpolator((xc1, xc2), pc)(np.stack([X1.ravel(), X2.ravel()], axis=-1))
        inactive = pi > 0
    else:
        inactive = b > 0
    p, its = _pdas(A, b, inactive, maxit)
    P = np.zeros((n, n))
    P[1:-1, 1:-1] = p.reshape(m, m)
    return P, x1, x2, f, its, k2


def _layer_of_nu(nu: Any) -> tuple[LayerKernel, str]:
    """The layer of a bare Poisson ratio in (1/4, 1/2] (the deprecated form) and how to write it."""
    nv = parse_nu(nu, floats="Float", lower=QUARTER, upper_closed=True, symbols=False,
                  example="'49/100', 0.49 or 0.5", range_hint=RANGE_HINT)
    if nv == sp.Rational(1, 2):
        return IncompressibleLayer(), "IncompressibleLayer()"
    return BondedLayer(nv), f"BondedLayer({nu!r})"


def _model_floats(layer: Any) -> tuple[float, float, float, float]:
    """``(nu, c_0, c_1, vartheta/mu)`` of the model (I.3)/(I.10) for a numeric bonded layer, 1/4 < nu <= 1/2."""
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a thinlayer LayerKernel (IncompressibleLayer(), BondedLayer(nu)), "
                        f"got {layer!r}")
    if not layer.has_incompressible_model or layer.symbolic_coefficients or not layer.has_thickness:
        raise InputError(f"the grid model needs BondedLayer(nu) (1/4 < nu < 1/2) or IncompressibleLayer(), "
                         f"got {layer!r}")
    nv = layer.numeric_nu
    if nv is None:
        raise InputTypeError(f"a numeric Poisson ratio in (1/4, 1/2] is needed here (e.g. BondedLayer(0.49)), "
                        f"got the symbolic {layer!r}")
    parse_nu(nv, floats="float", lower=QUARTER, upper_closed=True, range_hint=RANGE_HINT)
    c0, c1 = (float(c) for c in layer.taylor_coefficients(1))
    return float(nv), c0, c1, float(layer.vartheta / S.mu)


def _old_call(layer: Any, punch: Any, delta0: Any, H: Any, mu: Any, nu: Any) -> tuple:
    """``(layer, punch, delta0, H, mu)`` from the deprecated ``solve_obstacle_grid(punch, delta0, H, mu, nu=...)``."""
    if isinstance(layer, LayerKernel):
        if nu is not None:
            raise InputTypeError("nu= belongs to the deprecated form solve_obstacle_grid(punch, delta0, H, nu=...); "
                            "pass the layer only: solve_obstacle_grid(BondedLayer(nu), punch, delta0, H)")
        if delta0 is None or H is None:
            raise InputTypeError("solve_obstacle_grid(layer, punch, delta0, H, mu=1.0): delta0 and H are required")
        return layer, punch, delta0, H, mu
    # the punch came first: (punch, delta0, H[, mu]) shifted by one place
    new_layer, new = _layer_of_nu(sp.Rational(1, 2) if nu is None else nu)
    warnings.warn(f"solve_obstacle_grid(punch, delta0, H, nu=...) is deprecated; call "
                  f"solve_obstacle_grid({new}, punch, delta0, H)", DeprecationWarning, stacklevel=3)
    return new_layer, layer, punch, delta0, (mu if H is None else H)


def _check_box(box: Any, phi: Callable, d0: float) -> tuple[float, float, float, float]:
    """The box ``(x1min, x1max, x2min, x2max)``, default twice the bounding box of ``{Phi < delta0}``."""
    if box is None:
        return _default_box(phi, d0)
    try:
        bx = tuple(float(v) for v in box)
    except (TypeError, ValueError) as exc:
        raise InputError(f"box must be (x1min, x1max, x2min, x2max), got {box!r}") from exc
    if len(bx) != 4 or not (bx[0] < bx[1] and bx[2] < bx[3]) or not all(map(math.isfinite, bx)):
        raise InputError(f"box must be (x1min, x1max, x2min, x2max) with min < max, got {box!r}")
    return bx


@boundary
def solve_obstacle_grid(layer: LayerKernel, punch: Any, delta0: float | None = None, H: float | None = None,
                        mu: float = 1.0, *, n: int = 161, box: Any = None, parameters: dict | None = None,
                        maxit: int = 500, nu: Any = None) -> GridContact:
    """Solve the free-boundary problem (I.3)-(I.4) (or (I.10) for ``1/4 < nu < 1/2``) on a grid.

    The obstacle problem ``min sum (|grad_h p|^2/2 + k^2 p^2/2 - f p)`` over ``p >= 0`` with the
    5-point Laplacian on ``n x n`` nodes (``p = 0`` on the box boundary) is solved exactly by the
    primal-dual active-set method (each step a sparse LU solve, scipy.sparse), started from the
    interpolated solution on the grid with ``(n - 1)/2 + 1`` nodes (nested iteration).  The error
    is ``O(h^2)`` (measured in the tests).

    Parameters
    ----------
    layer : LayerKernel
        ``IncompressibleLayer()`` for (I.3); ``BondedLayer(nu)`` with a numeric ``1/4 < nu < 1/2`` for
        the two-term model (I.10).
    punch : Punch or callable
        A :class:`~thinlayer.punch.Punch` (numeric, or with ``parameters``) or a callable
        ``Phi(x1, x2)`` (numpy-vectorised).
    delta0, H, mu
        float
        Indentation, thickness, shear modulus.
    n : int
        Nodes per side (odd, 21 <= n <= 321; checked before any work: n = 161 takes 2.1 s, n = 321 10 s).
    box : tuple of float, optional
        ``(x1min, x1max, x2min, x2max)``; default twice the bounding box of ``{Phi < delta0}``.
    parameters : dict, optional
        Values of the punch's parameters, e.g. ``{"R": 2.0}``.
    maxit : int
        Maximum active-set iterations.
    nu : number, optional
        Deprecated: the form ``solve_obstacle_grid(punch, delta0, H, mu, nu=...)`` of earlier releases
        (the punch first; a DeprecationWarning).

    Returns
    -------
    GridContact

    Raises
    ------
    ValueError
        When the contact set reaches the box boundary (enlarge ``box``).
    """
    layer, punch, delta0, H, mu = _old_call(layer, punch, delta0, H, mu, nu)
    d0, HH, mm = (positive(v, nm) for v, nm in ((delta0, "delta0"), (H, "H"), (mu, "mu")))
    nv, c0, c1, th = _model_floats(layer)
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 21 or n % 2 == 0:
        raise InputError(f"n (nodes per side) must be an odd integer >= 21, got {n!r}")
    check_bounded(int(n), "n (nodes per side)", MAX_NODES, "each active-set step is a sparse LU solve of (n-2)^2 "
                  "unknowns: n = 161 takes 2.1 s, n = 321 10 s, and the cost grows like n^3")
    if isinstance(maxit, bool) or not isinstance(maxit, int) or maxit < 1:
        raise InputError(f"maxit must be a positive integer, got {maxit!r}")
    phi = _numeric_phi(punch, parameters)
    bx = _check_box(box, phi, d0)
    P, x1, x2, f, its, k2 = _grid_solve(phi, d0, th, c0, c1, HH, mm, bx, int(n), maxit)
    contact = P > 0
    if contact[:3, :].any() or contact[-3:, :].any() or contact[:, :3].any() or contact[:, -3:].any():
        raise InputError(f"the contact region reaches the boundary of the box {bx}: pass a larger box=")
    if not contact.any():
        raise InputError("no contact: the pressure vanishes on the grid (is delta0 > min Phi?)")
    h1, h2 = x1[1] - x1[0], x2[1] - x2[0]
    fin = f[contact[1:-1, 1:-1]]
    vol = float(fin.sum() / np.abs(fin).sum())
    for arr in (x1, x2, P, contact):
        arr.setflags(write=False)
    return GridContact(nv, d0, HH, mm, k2, x1, x2, P, contact, float(P.sum() * h1 * h2),
                       float(contact.sum() * h1 * h2), its, vol)
