r"""Direct time-stepping solver of axisymmetric viscoelastic contact on the layer (issue 27 item 3): (V.1)-(V.9).

A rigid tip of revolution ``x3 = -Phi(r)`` is pressed into a layer (bonded or frictionless on a rigid base, any H)
or into the half-space made of a linear viscoelastic solid with a **Prony-series** relaxation modulus and a
**constant Poisson ratio** nu.  It is the independent reference for the hereditary laws (Lee-Radok, Ting): it never
uses an elastic force law, only the layer's kernel ``L(u)`` (2.3).

Derivation
----------
(V.1) *Which modulus relaxes.*  Young's modulus ``E(t) = E_inf + sum_i E_i exp(-t/tau_i)`` relaxes; nu is constant,
so every elastic constant is proportional to ``E(t)``: the shear modulus ``mu(t) = E(t)/(2(1 + nu))`` and the
layer's modulus ``vartheta(t) = mu(t)/(1 - nu) = E(t)/(2(1 - nu^2))`` (2.1) carry the same relaxation function.

(V.2) *The hereditary structure is a Volterra convolution of the elastic operator.*  Elastically (F.2) the surface
displacement of a pressure ``p`` is ``u = (1/vartheta) A p``, ``(A p)(r) = int_0^oo pbar(alpha) L(alpha H)
J0(alpha r) d alpha``; A depends on the geometry and on nu only.  By the correspondence principle (Laplace transform
in time, ``vartheta -> s vartheta_hat(s)``) and because nu, hence L and A, do not depend on time, the viscoelastic
relation between the surface fields is, at every r on the whole surface,

    A p(t) = int_0^t vartheta(t - s) d/ds u(s) ds    <=>    p(t) = int_0^t vartheta(t - s) d/ds pi(s) ds,
    u(t) = A pi(t),                                                                                      (V.2)

with ``pi`` the *elastic-equivalent pressure* (the pressure that would produce the present displacement ``u(t)``
on the layer at unit modulus).  ``pi`` and ``p`` are supported on the largest contact disc reached so far.

(V.3) *Abel (Copson) variables.*  Writing each radial pressure as in (F.3), ``pbar(alpha) = int_0^R phi(t)
cos(alpha t) dt`` (``phi`` for ``p``, ``Psi`` for ``pi``), and each displacement by its Abel transform,
``u(r) = (2/pi) int_0^r G(s) (r^2 - s^2)^{-1/2} ds``, the operator A becomes (F.4)-(F.6)

    G = (pi/2) (I - K) Psi,      (K f)(s) = int_0^R k(s, t) f(t) dt,
    k(s, t) = (2/pi) int_0^oo (1 - L(alpha H)) cos(alpha s) cos(alpha t) d alpha,

the flat punch's kernel (F.6) (K = 0 for the half-space).  Both transforms keep the supports: ``u = delta - Phi`` on
``r < c`` iff ``G = delta - h`` on ``s < c`` with the Abel load ``h`` of the tip (F.11), and ``p = 0`` on ``r > c``
iff ``phi = 0`` on ``t > c``.  (V.2) holds between ``phi`` and ``Psi`` pointwise in t.

(V.4) *Internal variables.*  For the Prony series ``phi = vartheta_inf Psi + sum_i vartheta_i Q_i`` with
``Q_i(t) = int_0^t exp(-(t - s)/tau_i) dPsi(s)``; over a step ``h_n = t_n - t_{n-1}`` with ``Psi`` linear in time
(exact exponential integration of the branch; implicit, second order in the step):

    Q_i^n = e_i Q_i^{n-1} + g_i (Psi^n - Psi^{n-1}),    e_i = exp(-h_n/tau_i),  g_i = (tau_i/h_n)(1 - e_i),
    phi^n = k_n Psi^n - eta^n,    k_n = vartheta_inf + sum_i vartheta_i g_i,
    eta^n = sum_i vartheta_i (g_i Psi^{n-1} - e_i Q_i^{n-1})                     (the history, known).      (V.4)

The first node is a step from rest (``g_i = e_i = 1``: the instantaneous modulus).

(V.5) *The step's contact problem.*  With ``Psi^n = (phi^n + eta^n)/k_n`` on ``[0, R]`` (``phi^n = 0`` beyond c) the
contact condition ``(I - K) Psi^n = (2/pi)(delta_n - h)`` on ``[0, c]`` becomes an elastic problem of modulus
``k_n`` with the history's displacement as a load:

    phi^n(s) - int_0^c k(s, t) phi^n(t) dt = (2 k_n/pi)(delta_n - h(s)) - ((I - K) eta^n)(s),   0 <= s <= c.   (V.5)

(V.6) *Contact set, smooth edge.*  The pressure is bounded at r = c iff ``phi^n(c) = 0`` (F.8), (F.13); (V.5) is linear
in ``delta_n``, so ``delta_n(c) = -phi_0(c)/phi_1(c)`` (the solutions for the two parts of the right-hand side), and
the radius follows from ``delta_n(c) = delta_n`` (depth control) or ``P(c) = P_n`` (force control) by Brent's method,
bracketed from the previous radius: loading and unloading alike.  No contact (``c = 0``, ``P = 0``) when the punch
is above the surface, ``delta_n < delta_n(0+)``.

(V.7) *Force.*  ``P = 2 pi int_0^c phi dt`` (F.3).

(V.8) *Unilateral conditions, checked each step.*  ``p(r) = -int_r^c phi'(t) (t^2 - r^2)^{-1/2} dt >= 0`` on the
contact (F.3) and the gap ``u(r) - (delta - Phi(r)) >= 0`` outside, ``u`` from ``G = (pi/2)(I - K) Psi`` by the Abel
integral (F.4).  The result records the worst values (relative); they are diagnostics of the construction, not
imposed.

(V.9) *Discretisation.*  ``nodes`` + 1 equidistant nodes ``s_j`` on ``[0, R]``, fields piecewise linear between them;
the step's unknowns are ``phi`` at the nodes inside c and at c itself (c is continuous, not a node), the integrals
are the trapezoidal rule on these points (Nystrom's method), the kernel ``k`` is evaluated by the flat punch's
quadrature (:func:`thinlayer.numerics.flat_punch.kernel_quadrature`, at ``lambda = R/H``).  R is 1.15 times the
elastic contact radius at the largest depth (found by the same discretisation), unless given.

(V.10) *The flat punch* (``Punch.flat(a)``: a fixed contact, the face ``r <= a``).  The disc is the face, ``R = a``;
(V.5) is solved on all of it without the edge condition (the pressure has the edge singularity of (F.8)):
``phi^n = delta_n phi_1 + phi_0`` and ``P = delta_n P_1 + P_0`` are linear in ``delta_n``.  Under depth control the
face is in contact while ``P >= 0``; where ``P`` would be negative the punch lifts off (no adhesion): ``phi^n = 0``,
``P = 0``, and the surface under the face, at depth ``-P_0/P_1`` (the zero-force depth, ``surface_depth``), recovers
by itself until the punch reaches it again.  Under force control ``delta_n = (P_n - P_0)/P_1``.  Nothing but the
kernel is used (no stiffness law): the independent reference of Ting's (T7) for the flat punch.

Measured (half-space, sphere, SLS ``E0/E_inf = 3``, ``tau = 0.2``, triangle to ``t_m = 0.5``, against the mpmath
closed forms of Lee-Radok and Ting): second order in time (1600 nodes, 51/101/201 steps: force error at t = 0.6
1.08e-4, 2.74e-5, 7.07e-6, order 1.97) and in space (801 steps, 100/200/400 nodes: 5.6e-5, 1.4e-5, 3.9e-6, order
1.97, 1.87 with the time error left in); 1.2e-4 at 101 steps x 200 nodes, and Richardson's value from
(201, 400) and (401, 800) within 1e-6 (tests/viscoelastic/test_timestep.py, SLOW).  On layers the Nystrom rule needs
about ``4 R/H + 60`` nodes (the cancellation of ``1 - k`` (F.6)); 200 nodes serve up to ``a/H ~ 10`` (bonded nu = 1/2
at ``a/H = 14.8``: a negative edge pressure of 3 % of the peak is flagged there).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._checks import InputError, InputTypeError, check_bounded, check_history, check_int, positive
from .._lazy import lazy_module
from ..display import RichDisplay
from ..errors import boundary
from ..layers.kernels import LayerKernel
from ..punch import is_polynomial_tip
from ._layer import numeric_layer_nu
from .flat_punch import check_numeric_layer, kernel_quadrature
from .revolution import abel_load

optimize, linalg, interpolate = (lazy_module(f"scipy.{m}") for m in ("optimize", "linalg", "interpolate"))

__all__ = ["MAX_NODES", "MAX_WORK", "ViscoelasticContactHistory", "prony_moduli", "solve_history"]

#: the most radial nodes
MAX_NODES = 4000
#: the most ``steps x nodes^2`` on a layer (a dense solve per Brent iteration): 1,000 steps x 200 nodes is 4e7
MAX_WORK = 2.0e9
#: the unilateral conditions (V.8) are checked at about this many radii per step (up to twice as many)
_CHECKS = 60
#: the largest domain radius over thickness R/H on a layer (the trapezoidal rule needs ~4 R/H + 60 nodes)
MAX_R_OVER_H = 100.0


def prony_moduli(material: Any, nu: float) -> tuple[float, np.ndarray, np.ndarray]:
    """``(vartheta_inf, vartheta_i, tau_i)`` of a Prony material at the constant Poisson ratio nu (V.1).

    ``vartheta = E/(2 (1 - nu^2))``; the material is read through its attributes ``E_inf`` and ``terms``.
    """
    terms = getattr(material, "terms", None)
    einf = getattr(material, "E_inf", None)
    if terms is None or einf is None:
        raise InputTypeError(f"material must be a Prony series (Prony(E_inf, [(E_i, tau_i), ...]) or "
                             f"StandardLinearSolid(E0, E_inf, tau)), got {material!r}")
    f = 1.0 / (2.0 * (1.0 - nu * nu))
    return float(einf) * f, np.array([e for e, _ in terms], dtype=float) * f, \
        np.array([t for _, t in terms], dtype=float)


# --------------------------------------------------------------------------- result
@dataclass(frozen=True, eq=False)
class ViscoelasticContactHistory(RichDisplay):
    """A viscoelastic contact history from the direct time-stepping solver (V.1)-(V.9).

    Attributes
    ----------
    times, depths, force, contact_radius : numpy.ndarray
        The history (read-only arrays); the prescribed one of depth and force is the input.
    min_pressure : numpy.ndarray
        Per step, the least contact pressure over the largest one (V.8): ``>= 0`` where the unilateral condition
        holds (small negative values near the edge are the discretisation's).
    min_gap : numpy.ndarray
        Per step, the least gap outside the contact over the depth (V.8), ``>= 0`` where it holds.
    nodes, domain_radius : int, float
        Radial nodes and the radius R of the discretised disc.
    valid : numpy.ndarray
        False where a unilateral condition fails by more than ``tolerance`` (the result is then not the contact
        solution); ``reason`` says why.
    """

    layer: LayerKernel
    H: float
    nu: float
    material: Any
    times: np.ndarray = field(repr=False)
    depths: np.ndarray = field(repr=False)
    force: np.ndarray = field(repr=False)
    contact_radius: np.ndarray = field(repr=False)
    min_pressure: np.ndarray = field(repr=False)
    min_gap: np.ndarray = field(repr=False)
    valid: np.ndarray = field(repr=False)
    reason: str
    control: str
    nodes: int
    domain_radius: float
    #: the flat punch (V.10): the depth of the surface under the face (the punch's depth in contact, the free recovery
    #: after lift-off); None for a smooth tip
    surface_depth: np.ndarray | None = field(default=None, repr=False)

    equation = "V.5"

    def force_at(self, t: Any) -> np.ndarray:
        """The force at times t (linear interpolation between the steps)."""
        return np.interp(np.asarray(t, dtype=float), self.times, self.force)

    def radius_at(self, t: Any) -> np.ndarray:
        """The contact radius at times t (linear interpolation between the steps)."""
        return np.interp(np.asarray(t, dtype=float), self.times, self.contact_radius)

    def latex(self) -> str:
        return (r"\phi^n - K_c\phi^n = \tfrac{2k_n}{\pi}(\delta_n - h) - (I - K)\eta^n,\ \phi^n(c_n) = 0"
                rf"\quad ({len(self.times)}\ \text{{steps}},\ {self.nodes}\ \text{{nodes}}) \tag{{V.5}}")

    def text_lines(self) -> list[str]:
        n_bad = int((~self.valid).sum())
        return [f"ViscoelasticContactHistory: {self.layer}, nu = {self.nu:.6g}, H = {self.H:.6g}   (V.1)-(V.9)",
                f"  {len(self.times)} steps ({self.control} control), {self.nodes} radial nodes on "
                f"[0, {self.domain_radius:.6g}]",
                f"  force up to {float(np.max(self.force, initial=0.0)):.10g}, contact radius up to "
                f"{float(np.max(self.contact_radius, initial=0.0)):.10g}",
                f"  {n_bad} steps NOT VALID: {self.reason}" if n_bad else f"  {self.reason}"]


# --------------------------------------------------------------------------- the tip
def _tip_functions(tip: Any) -> tuple[Any, Any, tuple]:
    """``(Phi, Phi', joins)`` of a numeric tip of revolution or of an axisymmetric polynomial punch."""
    if is_polynomial_tip(tip):
        import sympy as sp

        from .axisymmetric import r as rsym
        from .axisymmetric import radial_profile

        prof = radial_profile(tip)  # refuses free parameters and non-axisymmetric punches, in one line
        return (sp.lambdify(rsym, prof, "numpy"), sp.lambdify(rsym, sp.diff(prof, rsym), "numpy"), ())
    if not (getattr(tip, "axisymmetric", False) and hasattr(tip, "radial_slope")):
        raise InputTypeError(f"tip must be a thinlayer tip of revolution (Punch.paraboloid, .sphere, .cone, "
                             f".power_law, ...), got {tip!r}")
    if getattr(tip, "parameters", ()):
        raise InputError(f"the {tip.name} has free parameters: substitute numbers first (tip.subs({{...}}))")
    try:
        tip.radial_slope(np.array([0.5 * min(1.0, float(tip.support_radius))]))
    except ValueError as exc:
        raise InputError(f"the {tip.name} has no closed-form slope dPhi/dr: {exc}") from None
    return tip.radial_profile, tip.radial_slope, tuple(float(b) for b in tip.radial_breakpoints)


def _as_vector(f: Any) -> Any:
    def g(x: np.ndarray) -> np.ndarray:
        x = np.asarray(x, dtype=float)
        return np.broadcast_to(np.asarray(f(x), dtype=float), x.shape).astype(float)
    return g


# --------------------------------------------------------------------------- the discretisation
class _Grid:
    """Nodes, trapezoidal weights, the kernel's Nystrom matrix and the Abel matrix of the gap (V.8), (V.9)."""

    def __init__(self, layer: LayerKernel, H: float, R: float, M: int, slope: Any, joins: tuple) -> None:
        self.R, self.M = R, M
        self.x = np.linspace(0.0, 1.0, M + 1)
        self.hx = 1.0 / M
        self.w = np.full(M + 1, self.hx)
        self.w[[0, -1]] *= 0.5
        self.slope, self.joins = slope, joins
        self.load = abel_load(slope, joins, R * self.x)  # h(s_j) (F.11)
        xs = np.linspace(0.0, 1.0, 20 * M + 1)  # h at the trial radii: a cubic spline (exact for a paraboloid)
        self.load_at = interpolate.CubicSpline(xs, abel_load(slope, joins, R * xs))
        self.thick = bool(layer.has_thickness)
        self._lu: dict = {}
        if self.thick:
            t, wt = kernel_quadrature(layer, R / H)
            self.t, self.wt = t, wt
            self.C = np.cos(np.outer(self.x, t))  # (M + 1, nt)
            self.K = (self.C * wt) @ self.C.T  # k~(x_i, x_j), the scaled kernel of (F.6)

    def kernel_row(self, xc: float) -> tuple[np.ndarray, float]:
        """``k~(x_j, xc)`` at every node and ``k~(xc, xc)``."""
        cc = self.wt * np.cos(self.t * xc)
        return self.C @ cc, float(cc @ np.cos(self.t * xc))

    def factor(self, m: int) -> Any:
        """LU of ``I - K[:m, :m] diag(w0)``, ``w0`` the trapezoidal weights of ``[x_0, x_{m-1}]`` (cached, LRU)."""
        lu = self._lu.pop(m, None)
        if lu is None:
            w0 = np.full(m, self.hx)
            w0[0] = 0.5 * self.hx if m > 1 else 0.0
            if m > 1:
                w0[m - 1] = 0.5 * self.hx
            lu = (linalg.lu_factor(np.eye(m) - self.K[:m, :m] * w0[None, :]), w0)
        self._lu[m] = lu
        while len(self._lu) > 12:
            self._lu.pop(next(iter(self._lu)))
        return lu

    def bordered_solve(self, m: int, w: np.ndarray, kc: np.ndarray, kcc: float, b1: np.ndarray,
                       b0: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The Nystrom system of (V.5) on ``[x_0..x_{m-1}, xc]`` for the two right-hand sides, from the cached LU of
        its c-independent block: Sherman-Morrison for the partial panel's weight on node m-1, then the border (c).
        """
        (lu, w0) = self.factor(m)
        eps = w[m]  # (xc - x_{m-1})/2: the extra weight of node m-1 and the weight of c
        u = self.K[:m, m - 1]
        Y = linalg.lu_solve(lu, np.column_stack([b1[:m], b0[:m], u, kc]))
        yu = Y[:, 2]
        den = 1.0 - eps * yu[m - 1]
        Z = Y[:, [0, 1, 3]] + (eps / den) * np.outer(yu, Y[m - 1, [0, 1, 3]])  # (A0 - eps u e^T)^{-1} [b1, b0, kc]
        r = kc * w0
        r[m - 1] += eps * kc[m - 1]
        zk = eps * Z[:, 2]  # z = zb + phi_c zk
        scale = 1.0 - eps * kcc - float(r @ zk)
        out = []
        for j, b in ((0, b1), (1, b0)):
            phic = (b[m] + float(r @ Z[:, j])) / scale
            v = np.empty(m + 1)
            v[:m] = Z[:, j] + phic * zk
            v[m] = phic
            out.append(v)
        return out[0], out[1]

    def points(self, xc: float) -> tuple[int, np.ndarray]:
        """``(m, w)``: the m nodes strictly inside xc and the trapezoidal weights of ``[x_0..x_{m-1}, xc]``."""
        m = max(1, int(np.searchsorted(self.x, xc, side="left")))
        w = np.empty(m + 1)
        w[:m] = self.hx
        w[0] = 0.5 * self.hx
        last = xc - self.x[m - 1]
        if m == 1:
            w[0] = 0.5 * last
        else:
            w[m - 1] = 0.5 * self.hx + 0.5 * last
        w[m] = 0.5 * last
        return m, w


@dataclass
class _Step:
    """One step's data: modulus k_n, the history eta on the nodes and ``(I - K) eta``."""

    k: float
    eta: np.ndarray
    g: np.ndarray


def _solve_at(grid: _Grid, st: _Step, c: float) -> tuple[float, float, np.ndarray, np.ndarray, int, np.ndarray]:
    """``(delta(c), P(c), phi1, phi0, m, w)`` at the trial radius c (V.5)-(V.7): phi = delta phi1 + phi0 on
    ``[x_0..x_{m-1}, xc]``, with ``phi(c) = 0`` fixing delta.
    """
    xc = c / grid.R
    m, w = grid.points(xc)
    load_c = float(grid.load_at(xc))
    eta_c = float(np.interp(xc, grid.x, st.eta))
    b1 = np.full(m + 1, 2.0 * st.k / math.pi)
    b0 = np.empty(m + 1)
    b0[:m] = -(2.0 * st.k / math.pi) * grid.load[:m] - st.g[:m]
    if grid.thick:
        krow, kcc = grid.kernel_row(xc)
        b0[m] = -(2.0 * st.k / math.pi) * load_c - (eta_c - float(krow @ (grid.w * st.eta)))
        phi1, phi0 = grid.bordered_solve(m, w, krow[:m], kcc, b1, b0)
    else:
        b0[m] = -(2.0 * st.k / math.pi) * load_c - eta_c
        phi1, phi0 = b1, b0
    delta = -phi0[m] / phi1[m]
    phi = delta * phi1 + phi0
    phi[m] = 0.0
    P = 2.0 * math.pi * grid.R * float(w @ phi)
    return delta, P, phi1, phi0, m, w


def _pressure_min(grid: _Grid, phi: np.ndarray, m: int, xc: float) -> float:
    """Min p / max p on the contact (V.8), p at the midpoints of the panels, piecewise-linear phi."""
    pts = np.append(grid.x[:m], xc)
    if m < 2:
        return 0.0
    r = 0.5 * (pts[:-1] + pts[1:])
    r = r[:: max(1, r.size // _CHECKS)]  # at most ~2 _CHECKS points
    slope = np.diff(phi) / np.diff(pts)
    a, b = pts[None, :-1], pts[None, 1:]
    rr = r[:, None]
    lo = np.maximum(a, rr)
    with np.errstate(invalid="ignore", divide="ignore"):
        ac = np.where(b > rr, np.arccosh(np.maximum(b / rr, 1.0)) - np.arccosh(np.maximum(lo / rr, 1.0)), 0.0)
    p = -(ac @ slope) + phi[-1] / np.sqrt(xc * xc - r * r)  # the edge term: phi(c) = 0 but for the flat punch
    top = float(np.max(p))
    return float(np.min(p) / top) if top > 0 else 0.0


def _abel_matrix(x: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """``B_ij = int_0^{x_i} hat_j(s) (x_i^2 - s^2)^{-1/2} ds`` for the hat functions on the nodes, rows i (F.4)."""
    n = x.size
    B = np.zeros((rows.size, n))
    for row, i in enumerate(rows):
        if i == 0:
            continue
        r = x[i]
        a, b = x[:i], x[1:i + 1]
        # on [a, b]: hat_left = (b - s)/(b - a), hat_right = (s - a)/(b - a)
        I0 = np.arcsin(np.minimum(b / r, 1.0)) - np.arcsin(a / r)           # int ds/sqrt
        I1 = np.sqrt(np.maximum(r * r - a * a, 0.0)) - np.sqrt(np.maximum(r * r - b * b, 0.0))  # int s ds/sqrt
        L = b - a
        B[row, :i] += (b * I0 - I1) / L
        B[row, 1:i + 1] += (I1 - a * I0) / L
    return B


def _elastic_radius(grid: _Grid, delta: float) -> float:
    """The elastic contact radius at depth delta on the grid (one step from rest at unit modulus)."""
    st = _Step(1.0, np.zeros(grid.M + 1), np.zeros(grid.M + 1))
    f = lambda c: _solve_at(grid, st, c)[0] - delta  # noqa: E731
    hi = grid.R * (1.0 - 1e-12)
    if f(hi) < 0:
        raise InputError("the elastic contact radius at the largest depth exceeds the first domain estimate")
    return float(optimize.brentq(f, 1e-9 * grid.R, hi, xtol=1e-14 * grid.R))


# --------------------------------------------------------------------------- the solver
def _one_blas_thread() -> Any:
    """One BLAS thread while stepping (the systems are small: threads only contend, 10x slower at load 9 on 2
    cores, measured), when threadpoolctl is installed; otherwise nothing changes.
    """
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # pragma: no cover - optional
        import contextlib

        return contextlib.nullcontext()
    return threadpool_limits(1)


@boundary
def solve_history(layer: LayerKernel, tip: Any, H: Any, material: Any, times: Any, depths: Any = None, *,
                  forces: Any = None, nu: Any = None, nodes: int = 200, radius_max: Any = None,
                  tolerance: float = 0.02) -> ViscoelasticContactHistory:
    r"""Viscoelastic contact of a tip of revolution on the layer by direct time stepping (V.1)-(V.9).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)``, ``IncompressibleLayer()``, ``FrictionlessLayer()`` or ``HalfSpace()``.
    tip : Tip
        ``Punch.paraboloid(R)``, ``Punch.sphere(R)``, ``Punch.cone(angle)``, ... (a smooth contact edge).
    H : float
        Layer thickness (any number for ``HalfSpace``).
    material : Prony or StandardLinearSolid
        Young's relaxation modulus ``E(t)``; nu is constant (V.1).
    times : array_like
        Strictly increasing times; the history is at rest before ``times[0]``.
    depths, forces : array_like
        Exactly one: the depth (depth control) or the force (force control) at each time, linear between them.
    nu : float, optional
        Poisson ratio for layers that carry none.
    nodes : int
        Radial nodes on the disc ``[0, R]`` (V.9).
    radius_max : float, optional
        The disc radius R (default 1.15 times the elastic contact radius at the largest depth or, under force
        control, at the largest force with the relaxed modulus).
    tolerance : float
        A step whose relative unilateral violation (V.8) exceeds this is flagged not valid.

    Returns
    -------
    ViscoelasticContactHistory
        ``force``, ``contact_radius`` (and ``depths``) against ``times``; ``force_at(t)``, ``radius_at(t)``.

    Examples
    --------
    A sphere (paraboloid) ramped into the half-space of a standard linear solid, ``vartheta = E/(2(1 - nu^2))``:

    >>> import numpy as np
    >>> from thinlayer import HalfSpace, Punch, StandardLinearSolid
    >>> t = np.linspace(0.0, 1.0, 51)
    >>> out = solve_history(HalfSpace(), Punch.paraboloid(1.0), 1.0, StandardLinearSolid(1.0, 1.0, 0.5), t, 0.01 * t,
    ...                     nu=0.3, nodes=400)
    >>> vt = 1.0 / (2 * (1 - 0.3**2))                       # Hertz: c^2 = R delta, P = 8 vartheta c^3/(3 R)
    >>> round(float(out.contact_radius[-1]), 6), round(float(out.force[-1] / (8 * vt * 0.1**3 / 3)), 4)
    (0.1, 1.0)
    """
    with _one_blas_thread():
        return _solve_history(layer, tip, H, material, times, depths, forces, nu, nodes, radius_max, tolerance)


def _solve_history(layer: Any, tip: Any, H: Any, material: Any, times: Any, depths: Any, forces: Any, nu: Any,
                   nodes: Any, radius_max: Any, tolerance: Any) -> ViscoelasticContactHistory:
    layer = check_numeric_layer(layer)
    nu_v = numeric_layer_nu(layer, nu)
    HH = positive(H, "H") if layer.has_thickness else (1.0 if H is None else positive(H, "H"))
    vinf, vi, taui = prony_moduli(material, nu_v)
    face = float(tip.radius) if getattr(tip, "fixed_contact", False) else None  # the flat punch's face (V.10)
    if face is None:
        Phi, slope, joins = _tip_functions(tip)
        Phi, slope = _as_vector(Phi), _as_vector(slope)
    else:
        Phi = slope = _as_vector(lambda r: 0.0 * r)
        joins = ()
    M = check_int(nodes, "nodes", 8)
    check_bounded(M, "nodes", MAX_NODES, "second order in space: 400 nodes give ~1e-5 on the half-space")
    tol = positive(tolerance, "tolerance")
    if (depths is None) == (forces is None):
        raise InputError("give exactly one of depths (depth control) and forces (force control)")
    control = "depth" if depths is not None else "force"
    t, y = check_history(times, depths if depths is not None else forces, f"{control}s")
    if np.any(y < 0) or not np.max(y) > 0:
        raise InputError(f"{control}s must be >= 0 with at least one > 0")
    if layer.has_thickness:
        check_bounded(float(t.size) * M * M, f"the work estimate (steps x nodes^2 = {t.size} x {M}^2)", MAX_WORK,
                      "1,000 steps x 200 nodes take ~10 s; use fewer steps or nodes")
    # the disc [0, R]
    if face is not None:
        if radius_max is not None and not positive(radius_max, "radius_max") == face:
            raise InputError(f"radius_max of the flat punch is its radius a = {face:.6g} (the face is the contact)")
        R = face
    elif radius_max is not None:
        R = positive(radius_max, "radius_max")
    else:
        R = _domain(layer, HH, Phi, slope, joins, float(np.max(y)), control, vinf + 0.0 if vinf > 0 else None, M)
    if layer.has_thickness:
        check_bounded(R / HH, "R/H (the disc over the thickness)", MAX_R_OVER_H,
                      "the trapezoidal Nystrom rule needs ~4 R/H + 60 nodes; use the thin-layer laws there")
    grid = _Grid(layer, HH, R, M, slope, joins)
    rows = np.arange(0, M + 1, max(1, M // _CHECKS))  # the gap is checked at <= ~2 _CHECKS nodes (V.8)
    B = _abel_matrix(grid.x, rows)
    n_t, nb = t.size, vi.size
    Psi = np.zeros(M + 1)
    Q = np.zeros((nb, M + 1))
    force = np.zeros(n_t)
    radius = np.zeros(n_t)
    depth = np.zeros(n_t)
    pmin = np.zeros(n_t)
    gmin = np.zeros(n_t)
    c_prev = c_prev2 = 0.0
    surface = np.zeros(n_t)
    prof_nodes = Phi(R * grid.x)
    for n in range(n_t):
        if n == 0:
            g_i, e_i = np.ones(nb), np.ones(nb)
        else:
            hstep = t[n] - t[n - 1]
            e_i = np.exp(-hstep / taui)
            g_i = -np.expm1(-hstep / taui) * taui / hstep
        k = vinf + float(vi @ g_i)
        eta = vi @ (g_i[:, None] * Psi[None, :] - e_i[:, None] * Q) if nb else np.zeros(M + 1)
        gfield = eta - (grid.K @ (grid.w * eta) if grid.thick else 0.0)
        st = _Step(k, eta, gfield)
        target = y[n]
        which = 0 if control == "depth" else 1

        def f(c: float, st: _Step = st, target: float = target, which: int = which) -> float:
            return _solve_at(grid, st, c)[which] - target

        c_lo = 1e-9 * R
        if face is not None:  # (V.10): the face is the contact while the force is compressive
            d_n, P_n, c, phi_nodes, surface[n] = _face_step(grid, st, control, target)
            if c > 0:
                pmin[n] = _pressure_min(grid, np.append(phi_nodes[:M], phi_nodes[M]), M, 1.0)
        elif target <= 0 or f(c_lo) >= 0:  # the punch is above the surface: no contact
            c = 0.0
            phi_nodes = np.zeros(M + 1)
            d_n = target if control == "depth" else float(_solve_at(grid, st, c_lo)[0])
            P_n = 0.0
        else:
            guess = 2.0 * c_prev - c_prev2 if c_prev2 > 0 else max(c_prev, 1e-3 * R)
            c = _bracket_root(f, c_lo, guess, max(0.25 * abs(c_prev - c_prev2), 1e-5 * R), R)
            d_n, P_n, phi1, phi0, m, w = _solve_at(grid, st, c)
            phi = d_n * phi1 + phi0
            phi[m] = 0.0
            phi_nodes = np.zeros(M + 1)
            phi_nodes[:m] = phi[:m]
            pmin[n] = _pressure_min(grid, phi, m, c / R)
        Psi_new = (phi_nodes + eta) / k
        Q = e_i[:, None] * Q + g_i[:, None] * (Psi_new - Psi)[None, :]
        Psi = Psi_new
        force[n], radius[n], depth[n] = P_n, c, d_n
        if d_n > 0 and face is None:
            D = Psi - (grid.K @ (grid.w * Psi) if grid.thick else 0.0)  # (2/pi) G = (I - K) Psi (V.3)
            u = B @ D  # u = (2/pi) int G/sqrt(r^2 - s^2) ds = int D/sqrt (F.4), scaled by s = R x
            out = grid.x[rows] * R > c + 1.5 * R / M
            if out.any():
                gmin[n] = float(np.min(u[out] - (d_n - prof_nodes[rows][out]))) / d_n
        c_prev2, c_prev = c_prev, c
    if control == "force":
        depth = depth.copy()
    bad = (pmin < -tol) | (gmin < -tol)
    reasons = []
    if (pmin < -tol).any():
        reasons.append(f"the contact pressure is negative (min p/max p = {pmin.min():.3g}) from t = "
                       f"{t[np.argmax(pmin < -tol)]:.6g}: the contact set is not one disc with a smooth edge")
    if (gmin < -tol).any():
        reasons.append(f"the surface penetrates the tip outside the contact (gap/depth = {gmin.min():.3g}) from "
                       f"t = {t[np.argmax(gmin < -tol)]:.6g}")
    if face is None and (radius >= R * (1 - 1e-9)).any():
        raise InputError(f"the contact radius reached the disc radius R = {R:.6g}: give a larger radius_max")
    arrays = [t, depth, force, radius, pmin, gmin, ~bad, surface]
    for a in arrays:
        a.setflags(write=False)
    if face is not None:
        lost = np.flatnonzero((radius == 0) & (np.maximum.accumulate(radius) > 0))
        reasons.append("flat punch (V.10): the face is the contact while the force is compressive"
                       + (f"; lift-off at t = {t[lost[0]]:.6g}, the surface recovers freely (surface_depth)"
                          if lost.size else ""))
    return ViscoelasticContactHistory(layer, HH, nu_v, material, t, depth, force, radius, pmin, gmin, ~bad,
                                      "; ".join(reasons) or "p >= 0 on the contact and gap >= 0 outside at every step",
                                      control, M, R, surface if face is not None else None)


def _face_step(grid: _Grid, st: _Step, control: str, target: float) -> tuple[float, float, float, np.ndarray, float]:
    """One step of the flat punch (V.10): ``(depth, force, contact radius, phi at the nodes, surface depth)``.

    (V.5) on the whole face ``[0, a]`` without the edge condition: ``phi = delta phi_1 + phi_0``,
    ``P = delta P_1 + P_0`` (linear).  Depth control: contact while ``P >= 0``, else lift-off (``phi = 0``; the
    surface depth is the depth of zero force, ``-P_0/P_1``).  Force control: ``delta = (P - P_0)/P_1``.
    """
    _, _, phi1, phi0, m, w = _solve_at(grid, st, grid.R)
    P1 = 2.0 * math.pi * grid.R * float(w @ phi1)
    P0 = 2.0 * math.pi * grid.R * float(w @ phi0)
    free = -P0 / P1
    phi_nodes = np.zeros(grid.M + 1)
    if control == "depth":
        delta = target
        if target <= free or target <= 0:
            return delta, 0.0, 0.0, phi_nodes, free
    else:
        delta = (target - P0) / P1
    phi = delta * phi1 + phi0
    phi_nodes[:m] = phi[:m]
    phi_nodes[grid.M] = phi[m]
    return delta, max(delta * P1 + P0, 0.0), grid.R, phi_nodes, delta


def _bracket_root(f: Any, lo: float, guess: float, step: float, R: float) -> float:
    """The root of f (negative at lo) next to ``guess``: the secant method from ``guess`` and ``guess + step``
    (about 4 evaluations per step of a smooth history); if it leaves ``(lo, R)`` or stalls, a bracket grown from
    ``guess`` by ``step``, doubling, then Brent's method (f increases through its root).
    """
    hi_lim = R * (1.0 - 1e-12)
    x0 = min(max(guess, lo), hi_lim)
    x1 = min(x0 + max(step, 1e-9 * R), hi_lim)
    f0, f1 = f(x0), f(x1)
    for _ in range(12):
        if f1 == f0:
            break
        x2 = x1 - f1 * (x1 - x0) / (f1 - f0)
        if not (lo < x2 < hi_lim):
            break
        if abs(x2 - x1) <= 1e-14 * R:
            return float(x2)
        x0, f0, x1, f1 = x1, f1, x2, f(x2)
    return _brent_root(f, lo, guess, step, R)


def _brent_root(f: Any, lo: float, guess: float, step: float, R: float) -> float:
    """The bracketing fallback of :func:`_bracket_root`."""
    hi_lim = R * (1.0 - 1e-12)
    x = min(max(guess, lo), hi_lim)
    fx = f(x)
    if fx == 0.0:
        return x
    d = max(step, 1e-9 * R)
    if fx < 0:  # the root lies above x
        a = x
        while True:
            if a >= hi_lim:
                raise InputError(f"the contact radius reached the disc radius R = {R:.6g}: give a larger radius_max")
            b = min(a + d, hi_lim)
            if f(b) >= 0:
                break
            a, d = b, 2.0 * d
    else:
        b = x
        while True:
            a = max(b - d, lo)
            if a == lo or f(a) < 0:
                break
            b, d = a, 2.0 * d
    return float(optimize.brentq(f, a, b, xtol=1e-15 * R, rtol=1e-15, maxiter=200))


def _domain(layer: LayerKernel, H: float, Phi: Any, slope: Any, joins: tuple, top: float, control: str,
            vinf: float | None, M: int) -> float:
    """1.15 times the elastic radius at the largest depth (or force at the relaxed modulus), on a coarse grid."""
    if control == "depth":
        r = 1.0
        for _ in range(2000):  # the overlap radius Phi(r) = delta
            if float(Phi(np.array([r]))[0]) > top:
                break
            r *= 2.0
        a = float(optimize.brentq(lambda s: float(Phi(np.array([s]))[0]) - top, 0.0, r))
        R0 = (a + 6.0 * min(H, a)) if layer.has_thickness else 1.5 * a
        grid = _Grid(layer, H, R0, min(M, 96), slope, joins)
        return 1.15 * _elastic_radius(grid, top)
    if vinf is None:
        raise InputError("force control needs a relaxed modulus E_inf > 0 (else the contact grows without "
                         "bound); or give radius_max")
    # the relaxed modulus gives the largest contact: P = vinf * P1(c) at unit modulus
    st = None
    R0 = 1.0
    for _ in range(200):
        grid = _Grid(layer, H, R0, min(M, 96), slope, joins)
        st = _Step(1.0, np.zeros(grid.M + 1), np.zeros(grid.M + 1))
        if vinf * _solve_at(grid, st, R0 * (1 - 1e-9))[1] > top:
            break
        R0 *= 2.0
    c = float(optimize.brentq(lambda c: vinf * _solve_at(grid, st, c)[1] - top, 1e-9 * R0, R0 * (1 - 1e-9)))
    return 1.15 * c
