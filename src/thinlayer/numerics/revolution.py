r"""A punch of revolution on a layer: the flat punch's second-kind equation (F.6) with the profile's load (F.10)-(F.15).

Derivation (Copson's representation, as in :mod:`thinlayer.numerics.flat_punch`, with a profile ``Phi(r)``)
-----------------------------------------------------------------------------------------------------------
(F.10) With the contact radius ``c`` and ``pbar(alpha) = int_0^c phi(t) cos(alpha t) dt`` the displacement is
``u3(r) = (2/pi) int_0^r G(s) (r^2 - s^2)^{-1/2} ds`` (F.4), and the punch condition ``u3 = delta0 - Phi(r)`` on
``r < c`` is an Abel equation for G whose solution is

    G(s) = d/ds int_0^s r (delta0 - Phi(r))/sqrt(s^2 - r^2) dr = delta0 - h(s),                                (F.11)
    h(s) = s int_0^s Phi'(r)/sqrt(s^2 - r^2) dr = s int_0^{pi/2} Phi'(s sin theta) d theta      (Phi(0) = 0).

(F.12) Splitting ``L = 1 - (1 - L)`` as in (F.5), with ``s = c x``, ``phi(c x) = (2 vartheta/pi) f(x)``,
``lambda = c/H``: ``f - k f = delta0 - h(c x)`` on ``[0, 1]``, the kernel k of (F.6).  By linearity
``f = delta0 f1 - fPhi`` with ``f1`` the flat punch's solution (right-hand side 1) and ``fPhi`` that of ``h(c x)``.
The right-hand side ``g`` need not be smooth (a cone's ``h`` is ``|x|`` in the even extension, a blunted cone's has a
``(x - x_b)^{3/2}`` join): ``u = f - g`` solves ``(1 - k) u = k g`` and is smooth (k is analytic in x), so u is
collocated as in (F.6), and ``k g`` needs only the cosine transform ``int_0^1 g(y) cos(t y) dy`` (a composite
Gauss-Legendre rule graded toward the apex and the joins).

(F.13) *Edge condition.*  The pressure ``p = (2 vartheta/(pi c)) [f(1)/sqrt(1 - x^2) - ...]`` (F.8) is bounded at
``r = c`` when ``f(1) = 0``: ``delta0 = fPhi(1)/f1(1)``, both edge values by Sloan's iterate.

(F.14) *Force.*  ``P = 2 pi int_0^c phi dt = 4 vartheta c (delta0 int_0^1 f1 - int_0^1 fPhi)``, with
``int_0^1 f1 = kappa(c/H)`` (F.7).  Half-space (k = 0): Sneddon's ``delta0 = h(c)``, ``P = 4 vartheta
int_0^c (h(c) - h(s)) ds``.

(F.15) *Check.*  At fixed ``delta0`` the force is stationary in c (``f(1) = 0``), so ``dP/d delta0 = 4 vartheta c
kappa(c/H)``: the flat punch's stiffness at the contact radius (tested by finite differences).

Discretisation and estimate: the collocation of (F.6) with :func:`tip_nodes` nodes (the error falls like
``exp(-8 n H/c)``, measured), the y-rule and a 40-point theta-rule per piece; the estimate is the change against
0.7 times the nodes with 12-point y-panels and a 28-point theta-rule, never below the rounding floor of (F.6).
Measured against the direct spectral solver (:mod:`thinlayer.numerics.axisymmetric`): agreement to 1e-9 or better up
to ``c/H = 40`` for the cone, the exact sphere, the blunted cone and ``r^1.5``, bonded nu = 0.45, 1/2 and frictionless.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from .._checks import InputError, InputTypeError, check_bounded, positive
from .._lazy import lazy_module
from ..display import RichDisplay
from ..layers.kernels import LayerKernel
from ._layer import U_MAX
from .flat_punch import (
    CHUNK,
    MAX_NODES,
    check_nodes,
    check_numeric_layer,
    collocation_operator,
    kernel_quadrature,
    rounding_floor,
)

special = lazy_module("scipy.special")  # scipy imported on first use

__all__ = ["MAX_C0_OVER_H", "MAX_C_OVER_H_TIP", "RevolutionContact", "abel_load", "revolution_contact",
           "revolution_contact_for_radius",
           "tip_nodes"]

#: Gauss-Legendre points per piece of the theta-rule of (F.11) and per panel of the y-rule of (F.12)
_THETA, _YGAUSS = 40, 16
#: geometric grading of the y-rule at the apex and at the profile's joins: ratio and number of panels
_GRADE, _GRADED = 0.2, 10
#: the largest c/H of a punch of revolution at a prescribed radius (the y-rule has ~3 U_MAX c/H panels, 290 nodes
#: there; about 1 s per solve with its estimate)
MAX_C_OVER_H_TIP = 90.0
#: the estimates never read below this: the level to which the equation is verified against the direct spectral solver
#: (whose own rounding floor is 5e-13; the collocation's rounding is ~1e-14 at small c/H)
VERIFIED_FLOOR = 1e-12
#: the largest half-space radius over thickness ``c_0/H`` at a prescribed depth or force (c is up to 1.4 c_0 there)
MAX_C0_OVER_H = 30.0


@lru_cache(maxsize=16)
def _legendre(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights, cached (abel_load is called once per trial radius by the time stepper)."""
    return special.roots_legendre(n)


def abel_load(slope: Any, breakpoints: tuple, s: Any, nodes: int = _THETA) -> np.ndarray:
    r"""``h(s) = s int_0^s Phi'(r)/sqrt(s^2 - r^2) dr = s int_0^{pi/2} Phi'(s sin theta) d theta`` (F.11).

    ``slope`` is the vectorised ``Phi'(r)``; the theta-range is split where ``s sin theta`` crosses a join of the
    profile (``breakpoints``), and its first piece is split at a quarter and graded (``theta ~ z^4``) toward the
    apex, where ``Phi'`` may behave like ``r^{n - 1}`` with a real ``n >= 1``.
    """
    s = np.atleast_1d(np.asarray(s, dtype=float))
    xg, wg = _legendre(nodes)
    z, wz = 0.5 * (xg + 1.0), 0.5 * wg
    with np.errstate(divide="ignore", invalid="ignore"):
        cuts = [np.arcsin(np.clip(np.where(s > 0, b / np.where(s > 0, s, 1.0), 1.0), 0.0, 1.0))
                for b in sorted(float(b) for b in breakpoints if b > 0)]
    first = cuts[0] if cuts else np.full(s.shape, 0.5 * math.pi)
    edges = [np.zeros_like(s), 0.25 * first, *cuts, np.full(s.shape, 0.5 * math.pi)]
    total = np.zeros_like(s)
    for j in range(len(edges) - 1):
        a, b = edges[j][:, None], edges[j + 1][:, None]
        if j == 0:  # graded toward the apex
            th, wt = a + (b - a) * z**4, (b - a) * 4.0 * z**3 * wz
        else:
            th, wt = a + (b - a) * z, (b - a) * wz
        vals = np.asarray(slope((s[:, None] * np.sin(th)).ravel()), dtype=float).reshape(th.shape)
        total += (vals * wt).sum(axis=1)
    return s * total


def _y_rule(lam: float, joins: tuple, gauss: int) -> tuple[np.ndarray, np.ndarray]:
    """Composite Gauss-Legendre rule on [0, 1] for ``int_0^1 g(y) cos(t y) dy`` up to ``t = U_MAX lambda`` (F.12):
    panels no longer than ``8/t_max``, graded geometrically toward 0 and toward the joins ``y_b``.
    """
    L = min(1.0, 8.0 / (U_MAX * max(lam, 1e-300)))
    edges = set(np.linspace(0.0, 1.0, max(2, math.ceil(1.0 / L)) + 1).tolist())
    for p in (0.0, *joins):
        edges.add(p)
        for k in range(1, _GRADED + 1):
            for q in (p - L * _GRADE**k, p + L * _GRADE**k):
                if 0.0 < q < 1.0:
                    edges.add(q)
    e = np.array(sorted(edges))
    xg, wg = special.roots_legendre(gauss)
    a, b = e[:-1, None], e[1:, None]
    return (0.5 * (b - a) * xg + 0.5 * (a + b)).ravel(), (0.5 * (b - a) * wg).ravel()


def _tip_parts(layer: LayerKernel, lam: float, n: int, c: float, slope: Any, joins: tuple,
               coarse: bool) -> tuple[float, float, float, float]:
    """``(f1(1), int f1, fPhi(1), int fPhi)`` of (F.13): the flat punch's and the profile's solutions of (F.6)."""
    y, T, M, E = collocation_operator(layer, lam, n)
    yq, wq = _y_rule(lam, tuple(b / c for b in joins if 0 < b < c), 12 if coarse else _YGAUSS)
    g = abel_load(slope, joins, c * yq, 28 if coarse else _THETA)
    t, wt = kernel_quadrature(layer, lam)
    kg, kg1 = np.zeros((n, 2)), np.zeros(2)
    for s in range(0, t.size, CHUNK):
        tt, ww = t[s:s + CHUNK], wt[s:s + CHUNK]
        C = np.cos(np.outer(tt, yq)) * wq
        ghat = np.stack([C.sum(axis=1), C @ g], axis=1)  # cosine transforms of 1 and of g (F.12)
        kg += (np.cos(np.outer(y, tt)) * ww) @ ghat
        kg1 += (np.cos(tt) * ww) @ ghat
    u = np.linalg.solve(M, kg)  # u = f - g is smooth: (1 - k) u = k g
    au = T @ u
    edge = np.array([1.0, float(abel_load(slope, joins, np.array([c]), 28 if coarse else _THETA)[0])]) + kg1 + E @ au
    integral = np.array([1.0, float(wq @ g)]) + au[0]
    return float(edge[0]), float(integral[0]), float(edge[1]), float(integral[1])


@dataclass(frozen=True)
class RevolutionContact(RichDisplay):
    """A punch of revolution on a layer from the second-kind equation (F.6) with the profile's load (F.10)-(F.14).

    Attributes
    ----------
    layer : LayerKernel
        The layer.
    radius, H, mu, nu, vartheta : float
        float
        Contact radius ``c``, thickness, shear modulus, Poisson ratio, ``vartheta = mu/(1 - nu)``.
    delta0, force : float
        float
        Depth and force (F.13), (F.14).
    delta0_error, force_error, radius_error : float
        float
        Relative estimates: the change against a run with 0.7 times the nodes and coarser quadratures, at least the
        rounding floor; at a prescribed depth propagated through the measured slopes (``radius_error`` 0 at a
        prescribed radius, ``delta0_error`` 0 at a prescribed depth).
    kappa : float
        The flat-punch stiffness ``kappa(c/H)`` (F.7): ``dP/d delta0 = 4 vartheta c kappa`` (F.15).
    nodes : int
        Collocation nodes.
    """

    layer: LayerKernel
    radius: float
    H: float
    mu: float
    nu: float
    vartheta: float
    delta0: float
    force: float
    delta0_error: float
    force_error: float
    radius_error: float
    kappa: float
    nodes: int

    equation = "F.13"

    @property
    def contact_radius(self) -> float:
        """``c``."""
        return self.radius

    def latex(self) -> str:
        return (rf"c = {self.radius:.10g},\quad \delta_0 = {self.delta0:.10g},\quad P = {self.force:.10g}"
                rf"\,(\pm {self.force_error:.1e}\,P) \tag{{F.13}}")

    def text_lines(self) -> list[str]:
        return [f"RevolutionContact: {self.layer}, nu = {self.nu:.6g}, H = {self.H:.6g}   (F.10)-(F.14)",
                f"  c = {self.radius:.12g} (+- {self.radius_error:.1e}), delta0 = {self.delta0:.12g} "
                f"(+- {self.delta0_error:.1e}), P = {self.force:.12g} (+- {self.force_error:.1e})",
                f"  {self.nodes} collocation nodes, kappa(c/H) = {self.kappa:.10g}"]


def tip_nodes(c_over_H: float) -> int:
    """``ceil(3 c/H) + 20`` collocation nodes for a tip of revolution (at most 400).

    Measured (cone, incompressible layer): the error of ``delta0`` and ``P`` falls like ``exp(-8 n H/c)`` (u = f - g
    of (F.13) carries the load's edge layer), 1e-11 at ``n = 50`` for ``c/H = 20``, 2.5e-10 at 80 for 35; the default
    gives about 1e-12.
    """
    return int(min(MAX_NODES, math.ceil(3.0 * c_over_H) + 20))


def _tip_slope(tip: Any) -> tuple[Any, tuple, float]:
    """``(Phi', joins, rim)`` of a numeric tip of revolution (one-line errors otherwise)."""
    if not (getattr(tip, "axisymmetric", False) and hasattr(tip, "radial_slope")):
        raise InputTypeError(f"punch must be a thinlayer tip of revolution (Punch.cone, .sphere, .blunted_cone, "
                             f".power_law, .revolution), got {tip!r}")
    if getattr(tip, "parameters", ()):
        raise InputError(f"the {tip.name} has free parameters: substitute numbers first (tip.subs({{...}}))")
    try:
        tip.radial_slope(np.array([0.5 * min(1.0, float(tip.support_radius))]))
    except ValueError as exc:
        raise InputError(f"the {tip.name} has no closed-form slope dPhi/dr: {exc}") from None
    return tip.radial_slope, tuple(float(b) for b in tip.radial_breakpoints), float(tip.support_radius)


def _tip_at(layer: LayerKernel, tip_data: tuple, c: float, H: float, n: int | None,
            coarse: bool = False) -> tuple[float, float, float, int]:
    """``(delta0, P/vartheta, kappa, nodes)`` at the contact radius c (F.13), (F.14)."""
    slope, joins, _ = tip_data
    lam = c / H if layer.has_thickness else 0.0
    N = n or tip_nodes(lam)
    if coarse:
        N = max(4, round(0.7 * N))
    if lam == 0.0:
        return _tip_at_half(tip_data, c)
    e1, i1, ep, ip = _tip_parts(layer, lam, N, c, slope, joins, coarse)
    d0 = ep / e1  # the edge condition f(1) = 0 (F.13)
    return d0, 4.0 * c * (d0 * i1 - ip), i1, N


def revolution_contact_for_radius(layer: LayerKernel, tip: Any, radius: float, H: float | None = None, *,
                                  mu: float = 1.0, nu: float | None = None, n: int | None = None,
                                  error_estimate: bool = True) -> RevolutionContact:
    """A tip of revolution at a prescribed contact radius ``c``: ``delta0`` and ``P`` from (F.13), (F.14).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)``, ``IncompressibleLayer()``, ``FrictionlessLayer()`` or ``HalfSpace()``.
    tip : Tip
        A numeric tip of revolution with a closed-form slope (``Punch.cone``, ``.sphere``, ``.blunted_cone``,
        ``.power_law``).
    radius : float
        Contact radius ``c``, ``c/H <= 60`` (below the exact sphere's rim).
    H : float, optional
        Layer thickness (ignored for ``HalfSpace``).
    mu, nu : float
        float
        Shear modulus; Poisson ratio for layers that carry none.
    n : int, optional
        Collocation nodes (default :func:`default_nodes`).
    error_estimate : bool
        Also solve with 0.7 n nodes and coarser quadratures and record the changes.

    Examples
    --------
    Sneddon's cone on the half-space, ``delta0 = (pi/2) c cot(alpha)``:

    >>> from thinlayer import HalfSpace, Punch
    >>> res = revolution_contact_for_radius(HalfSpace(), Punch.cone(45), 1.0, nu=0.0)
    >>> round(res.delta0 / (math.pi / 2), 12), round(res.force / math.pi, 12)  # P = (4/pi) tan(alpha) delta0^2
    (1.0, 1.0)
    """
    from ._layer import numeric_layer_nu as _nu

    layer = check_numeric_layer(layer)
    data = _tip_slope(tip)
    c = positive(radius, "radius")
    if c >= data[2]:
        raise InputError(f"the contact radius {c:g} reaches the rim of the tip (r = {data[2]:g})")
    nu_val = _nu(layer, nu)
    mu_val = positive(mu, "mu")
    HH = positive(H, "H") if H is not None else (c if not layer.has_thickness else None)
    if HH is None:
        raise InputError(f"{type(layer).__name__} needs the layer thickness H > 0")
    if layer.has_thickness:
        check_bounded(c / HH, "c/H", MAX_C_OVER_H_TIP, "beyond, the thin-layer tip laws are accurate (solve())")
    vt = mu_val / (1.0 - nu_val)
    d0, Pv, kappa, N = _tip_at(layer, data, c, HH, check_nodes(n))
    ed = eP = 0.0
    if error_estimate:
        d0c, Pvc, _, _ = _tip_at(layer, data, c, HH, N, coarse=True)
        floor = max(rounding_floor(layer, c / HH) if layer.has_thickness else 0.0, VERIFIED_FLOOR)
        ed = max(abs(d0c / d0 - 1.0), floor)
        eP = max(abs(Pvc / Pv - 1.0), floor)
    return RevolutionContact(layer, c, HH, mu_val, nu_val, vt, d0, vt * Pv, ed, eP, 0.0, kappa, N)


def revolution_contact(layer: LayerKernel, tip: Any, delta0: float | None = None, H: float | None = None, *,
                       force: float | None = None, mu: float = 1.0, nu: float | None = None,
                       error_estimate: bool = True) -> RevolutionContact:
    """A tip of revolution pressed to the depth ``delta0`` (or by the force ``force``): the contact radius from
    ``delta0(c) = delta0`` (or ``P(c) = force``), (F.13), (F.14), by the secant method in ``log c``.

    The estimates at the found radius (the change against 0.7 times the nodes and coarser quadratures, relative
    ``e_d``, ``e_P`` at fixed c) are carried to the prescribed depth through the slopes ``s_d = dlog delta0/dlog c``
    and ``s_P = dlog P/dlog c`` measured by one more solve at ``1.0001 c``: ``radius_error = e_d/s_d``,
    ``force_error = e_P + (s_P/s_d) e_d`` (at a prescribed force: ``e_P/s_P`` and ``delta0_error = e_d + (s_d/s_P)
    e_P``).

    Examples
    --------
    >>> from thinlayer import HalfSpace, Punch
    >>> res = revolution_contact(HalfSpace(), Punch.cone(45), math.pi / 2, nu=0.0)
    >>> round(res.radius, 12)
    1.0
    """
    from ._layer import numeric_layer_nu as _nu

    layer = check_numeric_layer(layer)
    data = _tip_slope(tip)
    nu_val = _nu(layer, nu)
    mu_val = positive(mu, "mu")
    vt = mu_val / (1.0 - nu_val)
    if (delta0 is None) == (force is None):
        raise InputError("give exactly one of delta0 (indentation depth) and force (total force)")
    if layer.has_thickness and H is None:
        raise InputError(f"{type(layer).__name__} needs the layer thickness H > 0")
    HH = positive(H, "H") if H is not None else 1.0
    if delta0 is not None:
        target, which = positive(delta0, "delta0"), 0
        a = _overlap(tip, target, data[2])
    else:
        target, which = positive(force, "force") / vt, 1
        a = None
    c, N = _radius_for(layer, data, target, which, HH, a)
    d0, Pv, kappa, _ = _tip_at(layer, data, c, HH, N)
    ec = eP = ed = 0.0
    if error_estimate:
        d0c, Pvc, _, _ = _tip_at(layer, data, c, HH, N, coarse=True)
        floor = max(rounding_floor(layer, c / HH) if layer.has_thickness else 0.0, VERIFIED_FLOOR)
        e_d, e_P = max(abs(d0c / d0 - 1.0), floor), max(abs(Pvc / Pv - 1.0), floor)
        d1, P1, _, _ = _tip_at(layer, data, c * 1.0001, HH, N)  # the slopes, same nodes
        s_d, s_P = math.log(d1 / d0) / math.log(1.0001), math.log(P1 / Pv) / math.log(1.0001)
        if which == 0:
            ec, eP = e_d / s_d, e_P + s_P / s_d * e_d
        else:
            ec, ed = e_P / s_P, e_d + s_d / s_P * e_P
    if which == 0:  # at the prescribed values exactly (the root is found to ~1e-15)
        d0, Pv = target, Pv * target / d0
    else:
        Pv = target
    return RevolutionContact(layer, c, HH, mu_val, nu_val, vt, d0, vt * Pv, ed, eP, ec, kappa, N)


def _overlap(tip: Any, delta0: float, rim: float) -> float:
    """The radius ``a`` of the rigid overlap ``Phi(a) = delta0`` (Brent on the tip's profile)."""
    from scipy import optimize

    prof = tip.radial_profile
    hi = rim * (1 - 1e-12) if math.isfinite(rim) else 1.0
    if math.isfinite(rim):
        if not float(prof(np.array([hi]))[0]) > delta0:
            raise InputError(f"delta0 = {delta0:g} reaches the rim of the tip (r = {rim:g})")
    else:
        for _ in range(2200):
            if float(prof(np.array([hi]))[0]) > delta0:
                break
            hi *= 2.0
    return float(optimize.brentq(lambda r: float(prof(np.array([r]))[0]) - delta0, 0.0, hi, xtol=1e-15 * hi))


def _radius_for(layer: LayerKernel, data: tuple, target: float, which: int, H: float,
                a: float | None) -> tuple[float, int]:
    """``(c, nodes)`` with ``delta0(c)`` (which = 0) or ``P(c)/vartheta`` (which = 1) equal to ``target`` (F.13),
    (F.14): the secant method on the logarithms from the half-space radius, Brent's method on the iterates' bracket
    if it stalls.  Refuses ``c/H`` beyond :data:`MAX_C_OVER_H_TIP` before the layer's first solve.
    """
    from scipy import optimize

    slope, joins, rim = data
    top = math.log((1.0 - 1e-9) * rim) if math.isfinite(rim) else math.inf

    def value(c: float, lay: LayerKernel | None, N: int) -> float:
        if lay is None:  # the half-space (Sneddon): f = g
            d0, Pv, _, _ = _tip_at_half(data, c)
        else:
            d0, Pv, _, _ = _tip_at(lay, data, c, H, N)
        return math.log((d0, Pv)[which] / target)

    lo = math.log(0.2 * a) if a is not None else min(0.0, top - 1.0)
    hi = min(math.log(1.2 * a), top) if a is not None else min(0.0, top - 1.0)
    while a is None and value(math.exp(hi), None, 4) < 0 and hi < min(top, 700.0):
        hi = min(hi + 2.0, top)
    while a is None and value(math.exp(lo), None, 4) > 0 and lo > -700.0:
        lo -= 2.0
    lc0 = optimize.brentq(lambda lc: value(math.exp(lc), None, 4), lo, hi, xtol=1e-12)
    if not layer.has_thickness:
        return math.exp(lc0), 4
    check_bounded(math.exp(lc0) / H, "c_0/H (the half-space contact radius over the thickness)", MAX_C0_OVER_H,
                  "beyond, the thin-layer tip laws are accurate (solve())")
    N = tip_nodes(1.5 * math.exp(lc0) / H)  # c/c0 < 1.4 measured: one set of nodes for all iterates

    def F(lc: float) -> float:
        return value(math.exp(lc), layer, N)

    x0, f0 = lc0, F(lc0)
    x1 = min(lc0 + 0.1 * (1 if f0 < 0 else -1), top)
    f1 = F(x1)
    pts = [(x0, f0), (x1, f1)]
    for _ in range(40):
        if abs(f1) < 1e-15 or f1 == f0:
            break
        x2 = x1 - f1 * (x1 - x0) / (f1 - f0)
        x2 = min(max(x2, x1 - 1.0), x1 + 1.0, top)
        x0, f0, x1 = x1, f1, x2
        f1 = F(x1)
        pts.append((x1, f1))
        if abs(x1 - x0) < 1e-14:
            break
    else:
        neg = max((p for p in pts if p[1] < 0), default=None)
        pos = min((p for p in pts if p[1] > 0), default=None)
        if neg is None or pos is None:
            raise InputError("no contact radius found (is the tip's profile increasing and convex?)")
        x1 = optimize.brentq(F, neg[0], pos[0], xtol=1e-14)
    return math.exp(x1), N


def _tip_at_half(data: tuple, c: float) -> tuple[float, float, float, int]:
    """The half-space (Sneddon) values at c: ``f = g`` in (F.13), (F.14)."""
    slope, joins, _ = data
    yq, wq = _y_rule(1.0, tuple(b / c for b in joins if 0 < b < c), _YGAUSS)
    d0 = float(abel_load(slope, joins, np.array([c]))[0])
    return d0, 4.0 * c * (d0 - float(wq @ abel_load(slope, joins, c * yq))), 1.0, 4
