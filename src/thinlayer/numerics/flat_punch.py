r"""Flat-ended cylindrical punch on a layer: the exact stiffness by a Fredholm equation of the second kind.

A rigid flat-ended cylinder of radius ``a`` is pressed to the depth ``w0`` into a layer of thickness ``H``
(kernel ``L(u)`` of the layer, (2.1), (2.3)).  The contact is the whole disc ``r < a`` (the pressure has the
square-root singularity of a sharp edge), and the force is written, after Hayes et al. (1972), as

    P = 4 mu a w0 kappa(a/H) / (1 - nu) = 4 vartheta a w0 kappa,      vartheta = mu/(1 - nu)         (F.1)

so that ``kappa = 1`` is Boussinesq's flat punch on the half-space (``P = 8 mu a w0/(2(1 - nu))``).  This
module computes ``kappa`` from the exact kernel; it never uses ``A``, ``m_n`` or any asymptotic stage.

Derivation (the Hankel/Abel reduction of Lebedev-Ufliand and Hayes et al., redone here)
-------------------------------------------------------------------------------------
(F.2) *Displacement.*  For an axisymmetric pressure the two-dimensional Fourier integral (2.1) becomes the
Hankel form of :mod:`thinlayer.numerics.axisymmetric`::

    u3(r) = (1/vartheta) int_0^oo pbar(alpha) L(alpha H) J0(alpha r) d alpha,
    pbar(alpha) = int_0^a p(rho) J0(alpha rho) rho d rho.

(F.3) *Copson's representation.*  Write ``pbar(alpha) = int_0^a phi(t) cos(alpha t) dt``.  Since
``int_0^oo sin(alpha t) J0(alpha rho) d alpha = (t^2 - rho^2)^{-1/2}`` for ``rho < t`` and ``0`` for ``rho > t``,
an integration by parts gives a pressure that vanishes for ``r > a`` and

    p(r) = phi(a)/sqrt(a^2 - r^2) - int_r^a phi'(t)/sqrt(t^2 - r^2) dt,     P = 2 pi pbar(0) = 2 pi int_0^a phi dt:

``phi(a)`` is the strength of the edge singularity.

(F.4) *Abel reduction.*  With ``J0(alpha r) = (2/pi) int_0^r cos(alpha s) (r^2 - s^2)^{-1/2} ds`` the
displacement is ``u3(r) = (2/pi) int_0^r G(s) (r^2 - s^2)^{-1/2} ds`` with
``G(s) = (1/vartheta) int_0^oo L(alpha H) cos(alpha s) int_0^a phi(t) cos(alpha t) dt d alpha``.  The
punch condition ``u3 = w0`` on ``r < a`` is an Abel equation for G, whose unique solution is
``G(s) = w0`` on ``0 <= s < a`` (because ``(2/pi) int_0^r (r^2 - s^2)^{-1/2} ds = 1``).

(F.5) *Second kind.*  Split ``L = 1 - (1 - L)``: the part 1 inverts by the Fourier cosine theorem,
``int_0^oo cos(alpha s) int_0^a phi(t) cos(alpha t) dt d alpha = (pi/2) phi(s)``, and the rest decays like
``u^2 e^{-2u}`` (2.4).  With ``s = a x``, ``t = a y``, ``phi(a y) = (2 vartheta w0/pi) f(y)`` and
``lambda = a/H``::

    f(x) - int_0^1 k(x, y) f(y) dy = 1,     0 <= x <= 1,                                              (F.6)
    k(x, y) = (2 lambda/pi) int_0^oo (1 - L(u)) cos(lambda u x) cos(lambda u y) du
            = (2/pi) int_0^oo (1 - L(t/lambda)) cos(t x) cos(t y) dt,

and the force (F.3) is ``P = 4 vartheta a w0 int_0^1 f dx``: comparing with (F.1),

    kappa(lambda) = int_0^1 f(x) dx.                                                                  (F.7)

The operator ``1 - k`` has the symbol ``L(|omega|/lambda) > 0`` on the even extension of ``f`` to
``(-1, 1)`` (the kernel is ``(1/2)(F(x - y) + F(x + y))`` with ``F`` the cosine transform of ``1 - L``), so (F.6)
is uniquely solvable for every layer.  For ``L = 1`` (the half-space) ``f = 1`` and ``kappa = 1``.

(F.8) *Pressure and edge value.*  From (F.3): ``p(r) = (2 vartheta w0/(pi a)) [f(1)/sqrt(1 - x^2) -
int_x^1 f'(y)/sqrt(y^2 - x^2) dy]``, ``x = r/a``; the coefficient of the edge singularity is ``f(1)``.
Differentiating (F.6) with respect to the interval length (the kernel depends on ``x - y`` and ``x + y``
only) gives Krein's identity

    d(lambda kappa)/d lambda = f(1)^2,                                                               (F.9)

a check of the solver that uses nothing else (tested).

Discretisation (two methods, both on (F.6))
-------------------------------------------
``method="collocation"`` (default).  The unknown ``f`` is the even polynomial ``sum_m a_m P_2m(x)`` through its
values at the ``n`` positive nodes of the ``2n``-point Gauss-Legendre rule (``a = T f`` with
``T_mj = (4m + 1) w_j P_2m(y_j)``, exact by Gauss quadrature).  The kernel acts on it in closed form, since
``int_0^1 P_2m(y) cos(t y) dy = (-1)^m j_2m(t)`` (``j`` the spherical Bessel function)::

    (k f)(x_i) = sum_m a_m (2/pi) int_0^oo (1 - L(t/lambda)) cos(t x_i) (-1)^m j_2m(t) dt,

and (F.6) is collocated at the nodes.  The ``t``-integral is a composite 16-point Gauss-Legendre rule on
``[0, 22 lambda]`` (``1 - L < 1e-16`` beyond ``u = 22``, (2.4)) with panels no longer than ``min(2 pi, lambda/2)``
(the oscillation and the scale ``H`` of ``1 - L``); ``L`` is evaluated by the layer's stable numerics
(:meth:`~thinlayer.layers.kernels.LayerKernel.L_numeric`), so nothing overflows at large ``lambda``;
``j_2m(t)`` by scipy below ``t = 1.5 (2n - 2) + 30`` and by the (there stable) upward recurrence above.  ``f`` is
smooth with an edge layer of width ``1/lambda`` at ``x = 1``, where the Gauss nodes cluster like ``1/n^2``: the
error falls like ``exp(-c n/sqrt(lambda))``, and the default ``n = ceil(4 sqrt(lambda)) + 12`` gives ``kappa`` to
about 1e-11.  Rounding sets a floor: ``1 - k = 1 - (1 - L)`` has the symbol ``L(1/lambda)`` on the lowest mode,
which is ``(2/3) lambda^-3`` at ``nu = 1/2``; there the error grows to 2e-10 at ``lambda = 50`` and 5e-8 at 200
(the estimate includes this floor, :func:`_rounding_floor`).  ``kappa = a_0``.

``method="nystrom"`` (check route).  Nystrom's method with ``n`` Gauss-Legendre nodes on ``[0, 1]`` and the
kernel in product form ``k(x_i, y_j) = sum_k W_k (1 - L(t_k/lambda)) cos(t_k x_i) cos(t_k y_j)``: no Bessel
functions and no polynomial interpolant.  The kernel has the width ``1/lambda`` everywhere, and the near
cancellation of ``1 - k`` (symbol ``L(omega/lambda) ~ A omega/lambda``) amplifies the quadrature error, so it
needs ``n ~ 4 lambda + 60`` (limited to ``lambda <= 60``).

The error estimate is the change against a run with ``0.7 n`` nodes.  The two methods agree with each other and
with the Galerkin solver of :mod:`thinlayer.numerics.axisymmetric` (pressure basis, no Abel reduction) to 1e-10
(tests).

A punch of revolution with the same kernel: :mod:`thinlayer.numerics.revolution` (F.10)-(F.15).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import numpy as np

from .._checks import InputError, InputTypeError, check_bounded, check_choice, check_int, positive
from .._lazy import lazy_module
from ..display import RichDisplay
from ..layers.kernels import LayerKernel
from ._layer import U_MAX, numeric_layer_nu
from ._spectral import spherical_jn_even

special = lazy_module("scipy.special")  # scipy imported on first use

__all__ = ["CHUNK", "MAX_A_OVER_H", "MAX_NODES", "METHODS", "FlatPunchContact", "FlatPunchStiffness", "check_nodes",
           "check_numeric_layer", "collocation_operator", "default_nodes", "even_bessel_transforms", "flat_punch_kappa",
           "kernel_quadrature", "rounding_floor", "solve_flat_punch"]

#: Largest a/H accepted.  Measured (default nodes, with the error estimate, nu = 0.3 and 1/2): a/H = 20 takes
#: 0.01 s, a/H = 50 0.02 s, a/H = 200 0.12 s (0.7 s on a loaded machine; the t-rule has 1.1e4 nodes there).
#: Beyond, the thin-layer asymptotics are better than 1e-7 for nu <= 0.45 and 5e-5 up to nu = 1/2.
MAX_A_OVER_H = 200.0
#: the Nystrom check route needs ~4 a/H + 60 nodes: limited to this a/H
MAX_A_OVER_H_NYSTROM = 60.0
#: largest number of nodes
MAX_NODES = 400
METHODS = ("collocation", "nystrom")
_GAUSS = 16
_PANEL = 2 * math.pi
_CHUNK = 4096
#: t-nodes per chunk of the kernel sums
CHUNK = _CHUNK


# --------------------------------------------------------------------------- results
@dataclass(frozen=True)
class FlatPunchStiffness(RichDisplay):
    """The exact stiffness ``kappa(a/H)`` of a flat-ended cylindrical punch (F.1), (F.7).

    Attributes
    ----------
    layer : LayerKernel
        The layer (its kernel ``L(u)``, (2.3)).
    a_over_H : float
        Punch radius over layer thickness, ``lambda``.
    kappa : float
        ``P (1 - nu)/(4 mu a w0)``; 1 for the half-space.
    error : float
        Relative change of ``kappa`` against a run with 0.7 times the nodes (an over-estimate of the error);
        0 when no estimate was asked for.
    nodes : int
        Number of collocation (or Nystrom) nodes.
    method : str
        ``"collocation"`` or ``"nystrom"`` (see the module docstring).
    edge_value : float
        ``f(1)``: the edge singularity ``p ~ (2 vartheta w0/pi) f(1)/sqrt(a^2 - r^2)`` (F.8).
    """

    layer: LayerKernel
    a_over_H: float
    kappa: float
    error: float
    nodes: int
    method: str
    edge_value: float
    _rep: tuple = field(repr=False, compare=False)

    equation = "F.7"

    def _check_x(self, x: Any) -> np.ndarray:
        x = np.asarray(x, dtype=float)
        if not np.all(np.isfinite(x)) or np.any((x < 0) | (x > 1)):
            raise InputError("x must lie in [0, 1] (x = r/a)")
        return x

    def f(self, x: Any) -> np.ndarray:
        """``f(x)`` of (F.6) on ``0 <= x <= 1``: the collocation polynomial (~1e-7 near the edge), or Nystrom's."""
        x = self._check_x(x)
        return _f_eval(self, np.atleast_1d(x), derivative=False).reshape(x.shape)

    def f_prime(self, x: Any) -> np.ndarray:
        """``f'(x)`` on ``[0, 1]``."""
        x = self._check_x(x)
        return _f_eval(self, np.atleast_1d(x), derivative=True).reshape(x.shape)

    def pressure(self, x: Any) -> np.ndarray:
        """The pressure ``p(r)`` in units of ``vartheta w0/a`` at ``x = r/a`` (F.8); 0 for ``x >= 1``.

        ``int_x^1 f'(y)/sqrt(y^2 - x^2) dy`` with ``y^2 = x^2 + (1 - x^2) s^2`` is
        ``sqrt(1 - x^2) int_0^1 f'(y)/y ds``, a smooth integrand (``f`` is even, ``f'(y)/y -> f''(0)``):
        Gauss-Legendre in ``s``.
        """
        x = np.abs(np.atleast_1d(np.asarray(x, dtype=float)))
        if not np.all(np.isfinite(x)):
            raise InputError("x must be finite")
        out = np.zeros_like(x)
        inside = x < 1.0
        xi = x[inside]
        if xi.size:
            s, ws = special.roots_legendre(max(64, 2 * self.nodes))
            s, ws = 0.5 * (s + 1.0), 0.5 * ws
            c = np.sqrt(1.0 - xi * xi)
            y = np.sqrt(xi[:, None] ** 2 + (c[:, None] * s[None, :]) ** 2)  # > 0: s > 0 at every Gauss node
            fp = _f_eval(self, y.ravel(), derivative=True).reshape(y.shape)
            out[inside] = (2.0 / math.pi) * (self.edge_value / c - c * ((fp / y) @ ws))
        return out

    def latex(self) -> str:
        return (rf"\kappa({self.a_over_H:.6g}) = {self.kappa:.12g}\ (\pm {self.error:.1e}),\quad "
                rf"f(1) = {self.edge_value:.10g} \tag{{F.7}}")

    def text_lines(self) -> list[str]:
        return [f"FlatPunchStiffness: {self.layer}, a/H = {self.a_over_H:.6g}   (F.1), (F.7)",
                f"  kappa = {self.kappa:.12g}  (+- {self.error:.1e} relative, {self.nodes} {self.method} nodes)",
                f"  edge value f(1) = {self.edge_value:.12g}"]


@dataclass(frozen=True)
class FlatPunchContact(RichDisplay):
    """A flat-ended cylindrical punch pressed into a layer: force, depth, stiffness and pressure (F.1), (F.8).

    Attributes
    ----------
    stiffness : FlatPunchStiffness
        ``kappa`` with its error estimate.
    radius, H, mu, nu, vartheta : float
        float
        Punch radius ``a``, thickness, shear modulus, Poisson ratio, ``vartheta = mu/(1 - nu)``.
    w0, force : float
        float
        Indentation depth and force, ``P = 4 vartheta a w0 kappa`` (F.1).
    """

    stiffness: FlatPunchStiffness
    radius: float
    H: float
    mu: float
    nu: float
    vartheta: float
    w0: float
    force: float

    equation = "F.1"

    @property
    def kappa(self) -> float:
        """The stiffness factor ``kappa(a/H)`` (F.1)."""
        return self.stiffness.kappa

    @property
    def stiffness_value(self) -> float:
        """``dP/dw0 = 4 vartheta a kappa``."""
        return 4.0 * self.vartheta * self.radius * self.kappa

    @property
    def edge_intensity(self) -> float:
        """``lim sqrt(a - r) p(r) = 2 vartheta w0 f(1)/(pi sqrt(2 a))`` (F.8)."""
        return 2.0 * self.vartheta * self.w0 * self.stiffness.edge_value / (math.pi * math.sqrt(2.0 * self.radius))

    def pressure_at(self, r: Any) -> np.ndarray:
        """Contact pressure ``p(r)`` (zero for ``r >= a``; singular like ``(a - r)^{-1/2}`` at the edge)."""
        r = np.asarray(r, dtype=float)
        return (self.vartheta * self.w0 / self.radius) * self.stiffness.pressure(r / self.radius).reshape(r.shape)

    def latex(self) -> str:
        return (rf"P = 4\vartheta a w_0 \kappa = {self.force:.10g},\quad w_0 = {self.w0:.10g},\quad "
                rf"\kappa = {self.kappa:.10g} \tag{{F.1}}")

    def text_lines(self) -> list[str]:
        return [f"FlatPunchContact: flat-ended cylinder on {self.stiffness.layer}   (F.1)",
                f"  a = {self.radius:.6g}, H = {self.H:.6g}, mu = {self.mu:.6g}, nu = {self.nu:.6g}",
                f"  w0 = {self.w0:.10g}, P = {self.force:.10g}",
                f"  kappa(a/H = {self.radius / self.H:.6g}) = {self.kappa:.12g}  (+- {self.stiffness.error:.1e})"]


# --------------------------------------------------------------------------- inputs
def check_numeric_layer(layer: Any) -> LayerKernel:
    """``layer`` if its kernel ``L(u)`` can be evaluated numerically and tends to 1 (2.4); one-line error otherwise."""
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a thinlayer LayerKernel (BondedLayer(nu), FrictionlessLayer(), "
                        f"IncompressibleLayer(), HalfSpace()), got {layer!r} ({type(layer).__name__})")
    try:
        far = float(np.asarray(layer.L_numeric(np.array([2 * U_MAX]), "numpy"))[0])
    except ValueError as exc:
        raise InputError(f"the flat-punch stiffness needs a layer with a numeric kernel L(u): {exc}") from None
    if abs(far - 1.0) > 1e-12:
        raise InputError(f"layer kernel must tend to the half-space value L = 1 at large u (2.4); L(44) = {far}")
    return layer


def default_nodes(a_over_H: float, method: str = "collocation") -> int:
    """Nodes for ~1e-10: ``ceil(4 sqrt(a/H)) + 12`` (collocation), ``ceil(4 a/H) + 60`` (Nystrom)."""
    if method == "nystrom":
        return int(math.ceil(4.0 * a_over_H)) + 60
    return int(math.ceil(4.0 * math.sqrt(a_over_H))) + 12


def _check_nodes(n: Any) -> int | None:
    if n is None:
        return None
    n = check_int(n, "n (nodes)", 4)
    return check_bounded(n, "n (nodes)", MAX_NODES, "the default nodes give 1e-10 up to a/H = 200 "
                                                    "(collocation: 69 nodes there)")


def _check_a_over_H(a_over_H: Any, method: str) -> float:
    lam = positive(a_over_H, "a_over_H")
    if method == "nystrom":
        return check_bounded(lam, "a_over_H", MAX_A_OVER_H_NYSTROM,
                             "the Nystrom check route needs ~4 a/H + 60 nodes; use method='collocation'")
    return check_bounded(lam, "a_over_H", MAX_A_OVER_H,
                         "the exact solver takes 0.12 s at a/H = 200; for thinner layers use the thin-layer "
                         "asymptotics (thinlayer.asymptotics.flat_punch), better than 5e-5 there")


# --------------------------------------------------------------------------- quadrature and transforms
@lru_cache(maxsize=64)
def _t_rule(layer: LayerKernel, lam: float) -> tuple[np.ndarray, np.ndarray]:
    """Nodes ``t_k`` and weights ``(2/pi) W_k (1 - L(t_k/lambda))`` of the kernel's t-integral (F.6)."""
    if not layer.has_thickness:
        return np.zeros(0), np.zeros(0)
    T = U_MAX * lam
    npan = max(8, math.ceil(T / min(_PANEL, 0.5 * lam)))
    xg, wg = special.roots_legendre(_GAUSS)
    edges = np.linspace(0.0, T, npan + 1)
    a, b = edges[:-1, None], edges[1:, None]
    t = (0.5 * (b - a) * xg + 0.5 * (a + b)).ravel()
    w = np.broadcast_to(0.5 * (b - a) * wg, (npan, _GAUSS)).ravel()
    wg_ = (2.0 / math.pi) * w * (1.0 - np.asarray(layer.L_numeric(t / lam, "numpy"), dtype=float))
    t.setflags(write=False)
    wg_.setflags(write=False)
    return t, wg_


def even_bessel_transforms(t: np.ndarray, n: int) -> np.ndarray:
    """``(-1)^m j_2m(t) = int_0^1 P_2m(y) cos(t y) dy`` for ``m < n``, shape ``(len(t), n)``.

    The recurrences over the order of :func:`thinlayer.numerics._spectral.spherical_jn_even` (upward where every
    order oscillates, Miller's downward recurrence below), 6-8x faster than scipy's ``spherical_jn`` on a whole
    rule and as accurate against mpmath (3e-16 absolute); scipy's ``spherical_jn`` below ``t = 1e-3``, where the
    downward recurrence's rescaling would be slow to catch up.
    """
    t = np.asarray(t, dtype=float)
    m = np.arange(n)
    out = np.empty((t.size, n))
    tiny = t < 1e-3
    out[tiny] = special.spherical_jn(2 * m[None, :], t[tiny][:, None])
    if not tiny.all():
        out[~tiny] = spherical_jn_even(t[~tiny], n)
    return out * ((-1.0) ** m)[None, :]


def _nodes(n: int) -> tuple[np.ndarray, np.ndarray]:
    """The n positive nodes of the 2n-point Gauss-Legendre rule and their weights (a rule on [0, 1] for even f)."""
    xg, wg = special.roots_legendre(2 * n)
    return xg[n:].copy(), wg[n:].copy()


# --------------------------------------------------------------------------- the two methods
def collocation_operator(layer: LayerKernel, lam: float,
                         n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(y, T, I - B T, E)``: the nodes, the values-to-Legendre map, the collocated operator ``1 - k`` of (F.6) and
    the edge row ``E_m = (k P_2m)(1)`` (Sloan's iterate at ``x = 1``).
    """
    y, w = _nodes(n)
    m = np.arange(n)
    T = (4 * m[:, None] + 1) * special.eval_legendre(2 * m[:, None], y[None, :]) * w[None, :]
    t, wt = _t_rule(layer, lam)
    B = np.zeros((n, n))
    E = np.zeros(n)
    for s in range(0, t.size, _CHUNK):
        tt, ww = t[s:s + _CHUNK], wt[s:s + _CHUNK]
        J = even_bessel_transforms(tt, n)
        B += (np.cos(np.outer(y, tt)) * ww) @ J
        E += (np.cos(tt) * ww) @ J
    return y, T, np.eye(n) - B @ T, E


def _collocation(layer: LayerKernel, lam: float, n: int) -> tuple[float, np.ndarray]:
    """``(kappa, a)``: (F.6) collocated at n nodes, ``f = sum_m a_m P_2m`` (module docstring)."""
    _, T, M, _ = collocation_operator(layer, lam, n)
    f = np.linalg.solve(M, np.ones(n))
    a = T @ f
    return float(a[0]), a


def kernel_quadrature(layer: LayerKernel, lam: float) -> tuple[np.ndarray, np.ndarray]:
    """Nodes ``t_k`` and weights ``(2/pi) W_k (1 - L(t_k/lambda))`` of the kernel's t-integral (F.6), cached."""
    return _t_rule(layer, lam)


def rounding_floor(layer: LayerKernel, lam: float) -> float:
    """The collocation's relative rounding floor (:func:`_rounding_floor`)."""
    return _rounding_floor(layer, lam)


def check_nodes(n: Any) -> int | None:
    """``n`` checked (4 <= n <= 400) or None."""
    return _check_nodes(n)


def _rounding_floor(layer: LayerKernel, lam: float) -> float:
    """Relative rounding floor of the collocation: ``eps sqrt(#t-nodes)/L(1/lambda)``.

    ``1 - k`` is ``1 - (1 - L)``: on the lowest mode (frequency ~1 in x) its symbol is ``L(1/lambda)``, while the
    kernel sums carry rounding errors of ``eps sqrt(#t-nodes)``.  Calibrated at ``nu = 1/2``, ``a/H = 200``
    (``L(0.005) = 8e-8``): floor 3e-7 against an observed scatter of 5e-8 over the number of nodes.
    """
    t, _ = _t_rule(layer, lam)
    Lmin = float(np.asarray(layer.L_numeric(np.array([1.0 / lam]), "numpy"))[0])
    return float(np.finfo(float).eps * math.sqrt(max(t.size, 1)) / Lmin)


def _sloan_edge(layer: LayerKernel, lam: float, a: np.ndarray) -> float:
    """``f(1) = 1 + (k f)(1)`` from (F.6) with the collocation polynomial inside the integral (Sloan's iterate).

    More accurate at the edge than the polynomial itself, whose value there is good to ~1e-7 only (the edge
    layer); ``f(1)`` enters Krein's identity (F.9) and the edge intensity.
    """
    t, wt = _t_rule(layer, lam)
    val = 1.0
    for s in range(0, t.size, _CHUNK):
        tt, ww = t[s:s + _CHUNK], wt[s:s + _CHUNK]
        val += float((np.cos(tt) * ww) @ (even_bessel_transforms(tt, a.size) @ a))
    return val


def _nystrom_matrix(t: np.ndarray, wg: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """``k(x_i, y_j) = sum_k wg_k cos(t_k x_i) cos(t_k y_j)`` (F.6), accumulated in chunks of t."""
    K = np.zeros((x.size, y.size))
    for s in range(0, t.size, _CHUNK):
        tt, ww = t[s:s + _CHUNK], wg[s:s + _CHUNK]
        Cx = np.cos(np.outer(x, tt))
        Cy = Cx if y is x else np.cos(np.outer(y, tt))
        K += (Cx * ww) @ Cy.T
    return K


def _nystrom(layer: LayerKernel, lam: float, n: int) -> tuple[float, np.ndarray, np.ndarray]:
    """``(kappa, x, w f)``: Nystrom solution of (F.6) with n Gauss-Legendre nodes on [0, 1]."""
    xg, wg = special.roots_legendre(n)
    x, w = 0.5 * (xg + 1.0), 0.5 * wg
    t, wt = _t_rule(layer, lam)
    sw = np.sqrt(w)
    K = _nystrom_matrix(t, wt, x, x)
    # symmetric form: (I - W^1/2 K W^1/2) (W^1/2 f) = W^1/2 1
    f = np.linalg.solve(np.eye(n) - sw[:, None] * K * sw[None, :], sw) / sw
    return float(w @ f), x, w * f


def _f_eval(st: FlatPunchStiffness, x: np.ndarray, derivative: bool) -> np.ndarray:
    """The solution's f (or f') at points x in [0, 1]."""
    if st.method == "collocation":
        (a,) = st._rep
        c = np.zeros(2 * a.size - 1)
        c[::2] = a  # sum_m a_m P_2m as a Legendre series
        if derivative:
            c = np.polynomial.legendre.legder(c)
        return np.polynomial.legendre.legval(x, c) if c.size else np.zeros_like(x)
    y, wf = st._rep  # Nystrom interpolation: f = 1 + int k f
    t, wt = _t_rule(st.layer, st.a_over_H)
    out = np.zeros(x.size) if derivative else np.ones(x.size)
    for s in range(0, t.size, _CHUNK):
        tt, ww = t[s:s + _CHUNK], wt[s:s + _CHUNK]
        inner = ww * (np.cos(np.outer(tt, y)) @ wf)
        out += (-np.sin(np.outer(x, tt)) @ (tt * inner)) if derivative else np.cos(np.outer(x, tt)) @ inner
    return out


# --------------------------------------------------------------------------- public functions
def flat_punch_kappa(layer: LayerKernel, a_over_H: float, n: int | None = None, *, method: str = "collocation",
                     error_estimate: bool = True) -> FlatPunchStiffness:
    """The stiffness ``kappa(a/H)`` of a flat-ended cylindrical punch from the exact kernel (F.6), (F.7).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` with numeric nu, ``IncompressibleLayer()``, ``FrictionlessLayer()`` (kappa does not
        depend on nu there) or ``HalfSpace()`` (kappa = 1).
    a_over_H : float
        Punch radius over layer thickness, ``0 < a/H <= 200`` (``<= 60`` with ``method="nystrom"``).
    n : int, optional
        Nodes (default :func:`default_nodes`: ``ceil(4 sqrt(a/H)) + 12`` collocation nodes, about 1e-10).
    method : str
        ``"collocation"`` (default) or ``"nystrom"`` (the check route; see the module docstring).
    error_estimate : bool
        Also solve with 0.7 n nodes and record the relative change.

    Returns
    -------
    FlatPunchStiffness
        ``kappa`` with ``P = 4 mu a w0 kappa/(1 - nu)`` (F.1), its error estimate and the edge value ``f(1)``.

    Raises
    ------
    thinlayer._checks.WorkLimitError
        Before any work, for ``a/H > 200`` (0.12 s measured at 200; the thin-layer asymptotics are better than
        5e-5 beyond) or more than 400 nodes.

    Examples
    --------
    >>> from thinlayer import BondedLayer, HalfSpace
    >>> flat_punch_kappa(HalfSpace(), 1.0).kappa
    1.0
    >>> round(flat_punch_kappa(BondedLayer(0.3), 1.0).kappa, 9)
    2.483524629
    """
    layer = check_numeric_layer(layer)
    check_choice(method, METHODS, "method")
    lam = _check_a_over_H(a_over_H, method)
    N = _check_nodes(n) or default_nodes(lam, method)
    if not layer.has_thickness:  # the half-space: f = 1, kappa = 1 exactly
        return FlatPunchStiffness(layer, lam, 1.0, 0.0, 1, "collocation", 1.0, (np.array([1.0]),))
    coarse = max(4, round(0.7 * N))
    if method == "collocation":
        kappa, a = _collocation(layer, lam, N)
        rep: tuple = (a,)
        edge = _sloan_edge(layer, lam, a)
        err = max(abs(kappa - _collocation(layer, lam, coarse)[0]) / abs(kappa), _rounding_floor(layer, lam)) \
            if error_estimate else 0.0
    else:
        kappa, x, wf = _nystrom(layer, lam, N)
        rep = (x, wf)
        err = abs(kappa - _nystrom(layer, lam, coarse)[0]) / abs(kappa) if error_estimate else 0.0
        edge = 0.0
    for arr in rep:
        arr.setflags(write=False)
    st = FlatPunchStiffness(layer, lam, kappa, float(err), N, method, edge, rep)
    if method == "nystrom":
        st = FlatPunchStiffness(layer, lam, kappa, float(err), N, method,
                                float(_f_eval(st, np.array([1.0]), derivative=False)[0]), rep)
    return st


def solve_flat_punch(layer: LayerKernel, radius: float, H: float | None = None, *, w0: float | None = None,
                     force: float | None = None, mu: float = 1.0, nu: float | None = None,
                     n: int | None = None) -> FlatPunchContact:
    """A flat-ended cylinder of radius ``a`` on a layer: the force for a depth, or the depth for a force (F.1).

    The problem is linear: ``P = 4 vartheta a w0 kappa(a/H)``, ``vartheta = mu/(1 - nu)``, with the exact
    ``kappa`` of :func:`flat_punch_kappa`.  Give exactly one of ``w0`` and ``force``.

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)``, ``IncompressibleLayer()``, ``FrictionlessLayer(nu)`` or ``HalfSpace()``.
    radius : float
        Punch radius ``a > 0``.
    H : float, optional
        Layer thickness (omitted, and ignored, for ``HalfSpace``).
    w0, force : float, optional
        float
        Indentation depth or total force (> 0): exactly one of them.
    mu : float
        Shear modulus.
    nu : float, optional
        Poisson ratio, for layers that do not fix one (``FrictionlessLayer()``, ``HalfSpace()``).
    n : int, optional
        Collocation nodes (see :func:`flat_punch_kappa`).

    Returns
    -------
    FlatPunchContact
        ``force``, ``w0``, ``kappa``, ``stiffness_value`` (dP/dw0), ``pressure_at(r)``.

    Examples
    --------
    Boussinesq's flat punch, ``P = 2 E* a w0`` with ``E* = 2 mu/(1 - nu)``:

    >>> from thinlayer import HalfSpace
    >>> res = solve_flat_punch(HalfSpace(), 2.0, w0=0.01, mu=1.0, nu=0.25)
    >>> round(res.force / (2 * (2 / 0.75) * 2.0 * 0.01), 12)
    1.0
    """
    layer = check_numeric_layer(layer)
    a = positive(radius, "radius")
    nu_val = numeric_layer_nu(layer, nu)
    mu_val = positive(mu, "mu")
    if H is None:
        if layer.has_thickness:
            raise InputError(f"{type(layer).__name__} needs the layer thickness H > 0")
        H_val = a  # ignored by the half-space kernel
    else:
        H_val = positive(H, "H")
    if (w0 is None) == (force is None):
        raise InputError("give exactly one of w0 (indentation depth) and force (total force)")
    st = flat_punch_kappa(layer, a / H_val, n)
    vt = mu_val / (1.0 - nu_val)
    if w0 is not None:
        w = positive(w0, "w0")
        P = 4.0 * vt * a * w * st.kappa
    else:
        P = positive(force, "force")
        w = P / (4.0 * vt * a * st.kappa)
    return FlatPunchContact(st, a, H_val, mu_val, nu_val, vt, w, P)
