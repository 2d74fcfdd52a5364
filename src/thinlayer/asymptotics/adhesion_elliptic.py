r"""Thin-layer JKR for the elliptic paraboloid on a compressible layer (J.25)-(J.31).

Equation tags continue the J series of :mod:`thinlayer.asymptotics.adhesion` ((J.7)-(J.15); (J.16)-(J.18) are the
any-thickness sphere law of :mod:`thinlayer.contact.adhesion_sphere`).  Assumptions: frictionless contact, a
compressible layer (``A > 0``) bonded to a rigid base (kernel (2.3)) or lying on it without friction (``A = 1/2``),
JKR adhesion (short range: the work of adhesion ``w`` is spent at the contact edge), both contact semi-axes large
against ``H``.  The punch is ``Phi = x1^2/(2 R1) + x2^2/(2 R2)`` (1.1).

(J.25) *Outer pressure.*  At leading order the outer (inner-expansion) pressure is local, (2.29) with its ``m_1``
term (:func:`~thinlayer.asymptotics.inner.inner_pressure`)::

    p_out = (vartheta/(A H)) (delta - m_1 H^2 (1/R1 + 1/R2) - Phi(x)).

(J.26) *The contour is a level set.*  The adhesive edge layer (J.8)-(J.9) holds at every point of a smooth contour
whose curvature is small against ``1/H``: ``G = A H p_out(Gamma_0)^2/(2 vartheta)`` with a relative remainder
``O(H kappa)``.  ``G = w`` all along the contour fixes ``p_out`` there to the tensile root
``p_out = -sqrt(2 vartheta w/(A H))``, a constant; ``p_out`` is an affine function of ``Phi`` alone, so the contour
is the level set ``Phi = k``, an ellipse with the punch's aspect ratio::

    k = delta - m_1 H^2 (1/R1 + 1/R2) + g,     g = sqrt(2 A H w/vartheta),     a_i = sqrt(2 R_i k).

(J.27) *Force.*  ``P = iint_{Phi < k} p_out dx`` (``x1 = a1 rho cos theta``, ``x2 = a2 rho sin theta``)::

    P = (pi vartheta sqrt(R1 R2)/(A H)) (k^2 - 2 g k) = pi vartheta a1 a2 (a1^2/(4 R1) - g)/(A H).

With ``R1 = R2 = R`` and ``m_1 = 0`` this is the sphere's (J.11) at order 0 (``c^2 = 2 R k``): checked in sympy.

(J.28) *Pull-off.*  Under load control ``dP/dk = 0`` at ``k = g``: ``P_off = -2 pi w sqrt(R1 R2)`` (DMT's and
Winkler's value with the mean radius of curvature), at ``delta = m_1 H^2 (1/R1 + 1/R2)`` and ``a_i = sqrt(2 R_i g)``;
the law holds there when ``sqrt(2 R_i g) >> H``.  Under displacement control ``d delta/dk = 1 > 0``: the depth
decreases with the contact to ``k -> 0``, where the semi-axes are ``O(H)`` and the law no longer holds (no
thin-layer value, as for the sphere (J.12)).

(J.29) *Remainder and estimate (order 0).*  The relative remainder of (J.25)-(J.28) is ``O(H kappa)``, ``kappa`` the
contour's curvature, from ``a1/a2^2`` to ``a2/a1^2`` along an ellipse (``a1 < a2``).  The estimate
(:meth:`EllipticJKR.state`) is twice the largest change that the disc's first-order correction makes when applied
with the curvature at either end of the ellipse (``g -> g/sqrt(1 + h* H kappa)``, the contact inside the level set
by ``h* H``), plus (force) ``dP/d delta`` times ``2 |m_1| H^2/R_1`` (the depth's next term, as in
:meth:`~thinlayer.asymptotics.adhesion.ThinLayerJKR.error_estimate`) and (semi-axes) ``2 |m_1| H^2/a_i`` ((SO.5)).

(J.30) *First order: the curved edge.*  The correction of the edge layer by the contour's curvature is local at first
order: in the edge's coordinates ``(n, s)`` the operator gains terms ``kappa n`` (linear in the local ``kappa``); the
tangential variation of ``p_out`` along the contour enters at ``O(H^2)`` (the layer is symmetric under ``s -> -s``),
and the slope term ``p_s H`` times ``H kappa`` is ``O((H/c)^2)`` against ``p_e``.  The disc fixes the coefficient,
(J.10): ``G = A H p_out(Gamma_0)^2 (1 + h* H kappa)/(2 vartheta)`` with ``Gamma_0`` the contact edge moved outward by
``h* H`` (J.8) and ``kappa`` the edge's curvature.  ``G = w`` along the contour::

    Phi(Gamma_0(theta)) = rho(theta) = delta' + g/sqrt(1 + h* H kappa(theta)),  delta' = delta - m_1 H^2 (1/R1 + 1/R2),

in the coordinates ``x_i = sqrt(2 R_i rho) (cos theta, sin theta)`` (Jacobian ``sqrt(R1 R2)``); ``Gamma_0`` is no
longer a level set where ``kappa`` varies.  ``kappa`` is taken from the ellipse through ``Gamma_0``'s ends moved
inward by ``h* H`` (``kappa_Gamma = kappa_0/(1 - h* H kappa_0)``), by a fixed point; the difference from
``Gamma_0``'s own curvature is ``O(H)`` relative, i.e. ``O((H kappa)^2)`` in ``G``.  The contact semi-axes are
``a_1 = sqrt(2 R1 rho(0)) - h* H``, ``a_2 = sqrt(2 R2 rho(pi/2)) - h* H``, and the force, as (J.11)'s at order 1 (the
edge layer's pressure integrates to the outer pressure extended to ``Gamma_0``, (J.8)),

    P = iint_{inside Gamma_0} p_out dx = (vartheta sqrt(R1 R2)/(A H)) int_0^{2 pi} rho (delta' - rho/2) d theta,

by the periodic trapezoid rule in ``theta`` (exponentially convergent).  With ``R1 = R2`` the fixed point is exact
and this is (J.11) at order 1 (checked to rounding, tests/adhesion/test_elliptic_law.py).  The pull-off under load
control is the minimum of ``P`` over the depth (golden section), no longer ``2 pi w sqrt(R1 R2)`` exactly.

(J.31) *Remainder and estimate (order 1).*  Relative ``O((H kappa)^2)``.  The estimate is twice the change from
order 0 times ``H kappa_max`` (``kappa_max = a2/a1^2``), plus the ``m_1`` terms of (J.29) and, in the force,
``dP/d delta`` times ``4 |r_3| H^3/(a_1 R_1)`` (the third-order depth term measured for the sphere, (J.24)).
Measured against the axisymmetric direct solver at ``R1 = R2`` (``R = sqrt 2``, ``mu = 0.35``; bonded nu = -0.1, 0.3,
0.45 and frictionless; ``H = 0.04`` with ``w = 0.005, 0.02`` and ``H = 0.01`` with ``w = 0.02``; ``c/H = 5, 8, 10, 20,
40``): the true error over the estimate is at most 0.60 (order 0, radius and force) and 0.76 (order 1); order 1's
radius error is 0.03-0.3 of its estimate (nu <= 0.3), e.g. bonded nu = 0.3, H = 0.04, w = 0.02 at c/H = 8: order 0
``c`` +1.8e-2, ``P`` -1.6e-2 relative; order 1 ``c`` -1.2e-3, ``P`` -7.7e-4.  The elliptic cells against the 2D
reference: tests/adhesion/test_elliptic_acceptance.py.

Incompressible layers (``nu = 1/2``): the outer problem is the Laplacian (I.2), ``p_out`` is not a function of
``Phi`` alone, and the contour is not a level set; the law is refused there (the 2D solver answers).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import InputError, InputTypeError, positive
from .._checks import work_of_adhesion as check_work
from ..display import RichDisplay
from ..layers.kernels import GenericLayer, LayerKernel
from ..punch import Punch
from .adhesion import thin_layer_jkr
from .inner import inner_pressure
from .second_order import edge_constants
from .wiener_hopf import edge_shift_exact

__all__ = ["EllipticJKR", "EllipticJKRState", "elliptic_jkr"]

#: below this many layer thicknesses (the smaller contact semi-axis) the thin-layer law is flagged invalid
MIN_AXIS_OVER_H = 5.0
#: nodes of the periodic trapezoid rule in theta of the first-order law (J.31) (measured: 128 -> 256 changes the
#: force by < 1e-15 relative at a1 = 5 H, R2/R1 = 4)
THETA_NODES = 256

k_s = sp.Symbol("k", positive=True)  # the level Phi = k of the contact contour
w_s = sp.Symbol("w", positive=True)
vt, H_s, delta = S.vartheta, S.H, S.delta0
A_s = GenericLayer.A_symbol


# --------------------------------------------------------------------------- the symbolic derivation
def _ladder(lhs: sp.Expr, rhs: sp.Expr, what: str) -> None:
    """``lhs == rhs`` by the ladder: ``==``, then cancel/expand of the difference, then simplify."""
    if lhs == rhs:
        return
    diff = lhs - rhs
    if sp.cancel(sp.expand(diff)) == 0 or sp.simplify(diff) == 0:
        return
    raise ArithmeticError(f"{what}: {lhs} != {rhs}")


@lru_cache(maxsize=1)
def _derivation() -> dict[str, Any]:
    """(J.25)-(J.28) in sympy from the engine's outer pressure (2.29); each step checked (raises otherwise)."""
    punch = Punch.elliptic_paraboloid()
    Phi = punch.expr
    R1, R2 = sorted((s for s in Phi.free_symbols if s.name in ("R_1", "R_2")), key=lambda s: s.name)
    p_out = inner_pressure(GenericLayer(), punch).pressure  # (2.29), with the m_1 term
    (m1,) = [s for s in p_out.free_symbols if s.name == "m_1"]
    # (J.25): p_out + vartheta Phi/(A H) does not depend on x: p_out is affine in Phi alone
    const = sp.expand(p_out + vt * Phi / (A_s * H_s))
    if sp.diff(const, S.x1) != 0 or sp.diff(const, S.x2) != 0:
        raise ArithmeticError("(J.25): the outer pressure is not a function of Phi alone")
    # (J.26): G = A H p^2/(2 vartheta) = w (J.9), the tensile root
    p = sp.Symbol("p", real=True)
    roots = sp.solve(sp.Eq(A_s * H_s * p**2 / (2 * vt), w_s), p)
    (p_c,) = [rt for rt in roots if rt.is_negative]
    g = sp.sqrt(2 * A_s * H_s * w_s / vt)
    _ladder(p_c, -vt * g / (A_s * H_s), "(J.26) the contour pressure")
    level = sp.expand((const - p_c) * A_s * H_s / vt)  # Phi = k on the contour
    dm = m1 * H_s**2 * (1 / R1 + 1 / R2)
    _ladder(level, sp.expand(delta - dm + g), "(J.26) the level k")
    (depth,) = sp.solve(sp.Eq(level, k_s), delta)  # delta(k)
    axes = []
    for var, other in ((S.x1, S.x2), (S.x2, S.x1)):
        (ai,) = [rt for rt in sp.solve(sp.Eq(Phi.subs(other, 0), k_s), var) if rt.is_positive]
        axes.append(ai)
    a1, a2 = axes
    # (J.27): the force over the ellipse Phi < k
    rho, th = sp.symbols("rho theta", positive=True)
    integrand = sp.expand(p_out.subs(delta, depth).subs({S.x1: a1 * rho * sp.cos(th), S.x2: a2 * rho * sp.sin(th)})
                          * a1 * a2 * rho)
    force = sp.simplify(sp.integrate(sp.integrate(integrand, (rho, 0, 1)), (th, 0, 2 * sp.pi)))
    closed = sp.pi * vt * sp.sqrt(R1 * R2) / (A_s * H_s) * (k_s**2 - 2 * g * k_s)
    _ladder(force, closed, "(J.27) the force")
    _ladder(sp.expand(force), sp.expand(sp.pi * vt * a1 * a2 * (a1**2 / (4 * R1) - g) / (A_s * H_s)),
            "(J.27) the force in the semi-axes")
    # (J.28): load control, dP/dk = 0
    (k_off,) = sp.solve(sp.diff(force, k_s), k_s)
    _ladder(k_off, g, "(J.28) the pull-off level")
    P_off = force.subs(k_s, k_off)
    _ladder(P_off, -2 * sp.pi * w_s * sp.sqrt(R1 * R2), "(J.28) the pull-off force")
    if sp.diff(depth, k_s) != 1:
        raise ArithmeticError("(J.28): delta(k) does not increase with k")
    # R1 = R2: the sphere's (J.11) at order 0, c^2 = 2 R k (an independent identity)
    sph = thin_layer_jkr(0.3, 0)
    names = {s.name: s for s in sph.force.free_symbols | sph.depth.free_symbols}
    c, R = names["c"], names["R"]
    to_sphere = {R1: R, R2: R, m1: 0, k_s: c**2 / (2 * R), w_s: names["w"], A_s: names[A_s.name]}
    _ladder(sp.expand(force.subs(to_sphere)), sp.expand(sph.force), "(J.27) against the sphere's (J.11)")
    _ladder(sp.expand(depth.subs(to_sphere)), sp.expand(sph.depth), "(J.26) against the sphere's (J.11)")
    return {"R1": R1, "R2": R2, "m1": m1, "p_out": p_out, "contour_pressure": p_c, "level": level, "depth": depth,
            "axes": (a1, a2), "force": force, "pull_off_level": k_off, "pull_off": P_off}


# --------------------------------------------------------------------------- results
@dataclass(frozen=True)
class EllipticJKRState(RichDisplay):
    """A thin-layer JKR state of the elliptic paraboloid (J.26)-(J.29), at a given depth or at pull-off.

    Attributes
    ----------
    delta, force : float
        float
        Depth and force (negative: the punch is pulled).
    a1, a2 : float
        float
        Contact semi-axes along ``x1`` and ``x2`` (J.26).
    level : float
        ``k``: the contour is ``Phi = k``.
    force_error, a1_error, a2_error : float
        float
        Absolute error estimates (J.29).
    valid : bool
        False when the smaller semi-axis is below ``MIN_AXIS_OVER_H`` layer thicknesses (see ``reason``).
    reason : str
        Why the state is (or is not) inside the law's validity.
    """

    delta: float
    force: float
    a1: float
    a2: float
    level: float
    force_error: float
    a1_error: float
    a2_error: float
    valid: bool
    reason: str

    equation = "J.27"

    def latex(self) -> str:
        return (rf"P = {self.force:.8g} \pm {self.force_error:.2g},\quad a_1 = {self.a1:.6g},\ a_2 = {self.a2:.6g},"
                rf"\quad \delta = {self.delta:.6g} \tag{{J.27}}")

    def text_lines(self) -> list[str]:
        return [f"EllipticJKRState: delta = {self.delta:.8g}, P = {self.force:.8g} +- {self.force_error:.2g}   (J.27)",
                f"  a1 = {self.a1:.8g} +- {self.a1_error:.2g}, a2 = {self.a2:.8g} +- {self.a2_error:.2g}, "
                f"level k = {self.level:.8g}", f"  {'valid' if self.valid else 'OUTSIDE the law'}: {self.reason}"]


@dataclass(frozen=True)
class EllipticJKR(RichDisplay):
    """Thin-layer JKR for the elliptic paraboloid on a compressible layer (J.25)-(J.31), order 0 or 1.

    Attributes
    ----------
    layer : LayerKernel
        The layer (compressible: ``A > 0``).
    nu, A, h, m1 : float
        float
        Poisson ratio, ``A`` (2.4), exact edge shift ``h*`` (3.18), ``m_1`` (2.20).
    depth, force : sympy.Expr
        sympy.Expr
        ``delta(k)`` and ``P(k)`` (J.26), (J.27) in ``k, R_1, R_2, w, H, vartheta, A, m_1``.
    semi_axes : tuple of sympy.Expr
        ``(a1(k), a2(k))``.
    contour_pressure : sympy.Expr
        ``p_out`` on the contour, ``-sqrt(2 vartheta w/(A H))`` (J.26).
    pull_off_load : sympy.Expr
        ``-2 pi w sqrt(R1 R2)`` (J.28), the minimum of ``P`` under load control (order 0).
    order : int
        0: (J.26)-(J.28), relative remainder ``O(H kappa)``; 1: the edge layer's curvature correction (J.30),
        (J.31), relative remainder ``O((H kappa)^2)``.
    r3 : float
        ``r_3`` (SO.4) of the layer: the third-order depth term of order 1's estimate (J.31) (0 at order 0).
    """

    layer: LayerKernel
    nu: float
    A: float
    h: float
    m1: float
    depth: sp.Expr
    force: sp.Expr
    semi_axes: tuple
    contour_pressure: sp.Expr
    pull_off_load: sp.Expr
    order: int = 0
    r3: float = 0.0

    equation = "J.27"

    def _numbers(self, H: Any, R1: Any, R2: Any, work_of_adhesion: Any, mu: Any) -> tuple:
        Hv, r1, r2 = positive(H, "H"), positive(R1, "R1"), positive(R2, "R2")
        wv, vtv = check_work(work_of_adhesion), positive(mu, "mu") / (1 - self.nu)
        g = math.sqrt(2 * self.A * Hv * wv / vtv)
        return Hv, r1, r2, wv, vtv, g, self.m1 * Hv * Hv * (1 / r1 + 1 / r2)

    def _at_level(self, k: float, g: float, Hv: float, r1: float, r2: float, vtv: float) -> tuple:
        """(delta-independent) force and semi-axes at the level k with the contour pressure of g (J.27)."""
        P = math.pi * vtv * math.sqrt(r1 * r2) / (self.A * Hv) * (k * k - 2 * g * k)
        return P, math.sqrt(2 * r1 * k), math.sqrt(2 * r2 * k)

    def _first_order(self, dprime: float, g: float, Hv: float, r1: float, r2: float, vtv: float) -> tuple | None:
        """(J.30), (J.31) at ``delta' = delta - m_1 H^2 (1/R1 + 1/R2)``: ``(P, a1, a2, rho)`` or None (no contact).

        The shifted contour ``Gamma_0`` is ``Phi = rho(theta)`` in the coordinates ``x_i = sqrt(2 R_i rho) (cos, sin)
        theta`` (Jacobian ``sqrt(R1 R2)``); ``kappa`` is that of the ellipse through ``Gamma_0``'s ends, moved inward
        by ``h* H`` (a fixed point: exact for a disc); the force by the periodic trapezoid rule in ``theta``.
        """
        hH = self.h * Hv
        th = 2.0 * math.pi * np.arange(THETA_NODES) / THETA_NODES
        s2, c2 = np.sin(th) ** 2, np.cos(th) ** 2
        rho0 = dprime + g
        if not rho0 > 0:
            return None
        b1, b2 = math.sqrt(2 * r1 * rho0), math.sqrt(2 * r2 * rho0)
        for _ in range(200):
            kap0 = b1 * b2 / (b1 * b1 * s2 + b2 * b2 * c2) ** 1.5  # the ellipse's curvature at theta
            if not (hH * kap0 < 1).all():
                return None
            rho = dprime + g / np.sqrt(1.0 + hH * kap0 / (1.0 - hH * kap0))  # (J.30), kappa of Gamma (inward by h*H)
            if not (rho > 0).all():
                return None
            n1, n2 = math.sqrt(2 * r1 * rho[0]), math.sqrt(2 * r2 * rho[THETA_NODES // 4])
            done = abs(n1 - b1) <= 1e-15 * n1 and abs(n2 - b2) <= 1e-15 * n2
            b1, b2 = n1, n2
            if done:
                break
        P = vtv * math.sqrt(r1 * r2) / (self.A * Hv) * 2.0 * math.pi * float(np.mean(rho * (dprime - 0.5 * rho)))
        return P, b1 - hH, b2 - hH, rho

    def _state(self, delta_v: float, k: float, g: float, Hv, r1, r2, vtv) -> EllipticJKRState:
        P, a1, a2 = self._at_level(k, g, Hv, r1, r2, vtv)
        lo, hi = sorted((a1, a2))
        errs = np.zeros(3)
        if self.order == 1:  # (J.31): twice the change from order 0, times H kappa_max
            first = self._first_order(k - g, g, Hv, r1, r2, vtv)
            if first is None or min(first[1:3]) <= 0:
                raise InputError(f"delta0 = {delta_v:.6g}: the first-order law (J.30) leaves no contact here (the "
                                 "contact is a few H wide or less: outside the thin-layer law)")
            P1, b1, b2, _ = first
            lo, hi = sorted((b1, b2))
            errs = 2.0 * Hv * hi / (lo * lo) * np.abs([P1 - P, b1 - a1, b2 - a2])
            P, a1, a2 = P1, b1, b2  # the level k of order 0 is kept (the reference level)
        else:
            for kappa in (lo / hi**2, hi / lo**2):  # the curvature at either end of the ellipse (J.29)
                gk = g / math.sqrt(1 + self.h * Hv * kappa)
                kk = k - g + gk  # the same depth
                if kk <= 0:
                    errs[:] = math.inf
                    break
                Pk, b1, b2 = self._at_level(kk, gk, Hv, r1, r2, vtv)
                errs = np.maximum(errs, np.abs([Pk - P, b1 - self.h * Hv - a1, b2 - self.h * Hv - a2]))
            errs *= 2.0
        # the outer pressure's next term (2.31) moves the depth by ~ m_1 H^2/R (as in ThinLayerJKR.error_estimate):
        # at a given depth the force moves by dP/d delta times twice that (dP/dk of (J.27), k = delta' + g)
        slope_ = abs(2.0 * math.pi * vtv * math.sqrt(r1 * r2) / (self.A * Hv) * (k - g))
        # and, as ThinLayerJKR's order 2 measures (J.24), the next depth term ~ 2.6 r_3 H^3/(c R): 4 r_3 H^3/(c R)
        errs[0] += slope_ * (2.0 * abs(self.m1) * Hv * Hv * max(1 / r1, 1 / r2)
                             + 4.0 * abs(self.r3) * Hv**3 / (lo * min(r1, r2)))
        # the smooth edge's second-order shift m_1 H^2/a (SO.5), twice, in each semi-axis
        errs[1:] += 2.0 * abs(self.m1) * Hv * Hv / np.array([a1, a2])
        valid = lo >= MIN_AXIS_OVER_H * Hv
        tail = "O(H kappa), J.29" if self.order == 0 else "O((H kappa)^2), J.31"
        reason = (f"smaller semi-axis {lo:.4g} = {lo / Hv:.3g} H" + (" >= " if valid else " < ")
                  + f"{MIN_AXIS_OVER_H:g} H (thin-layer law, relative remainder {tail})")
        return EllipticJKRState(delta_v, P, a1, a2, k, float(errs[0]), float(errs[1]), float(errs[2]), valid, reason)

    def state(self, delta0: Any, H: Any, R1: Any, R2: Any, work_of_adhesion: Any, mu: Any = 1.0
              ) -> EllipticJKRState:
        """The JKR state at the depth ``delta0`` (J.26), (J.27), with its estimate (J.29) and validity flag.

        ``vartheta = mu/(1 - nu)``; a depth at which the law leaves no contact (``k <= 0``) is refused.
        """
        if isinstance(delta0, (bool, str)) or not isinstance(delta0, (int, float, np.floating, np.integer)):
            raise InputTypeError(f"delta0 must be a real number (negative when pulled), got {delta0!r:.60}")
        d0 = float(delta0)
        if not math.isfinite(d0):
            raise InputError(f"delta0 must be finite, got {delta0!r}")
        Hv, r1, r2, _, vtv, g, dm = self._numbers(H, R1, R2, work_of_adhesion, mu)
        k = d0 - dm + g
        if not k > 0:
            raise InputError(f"delta0 = {d0:.6g} is below the thin-layer law's contact range (delta0 > "
                             f"{dm - g:.6g}, where the contact shrinks to nothing; there the law does not hold)")
        return self._state(d0, k, g, Hv, r1, r2, vtv)

    def state_at_force(self, force: Any, H: Any, R1: Any, R2: Any, work_of_adhesion: Any, mu: Any = 1.0,
                       branch: str = "stable") -> EllipticJKRState:
        """The JKR state at the force ``P`` (negative when pulled) under load control (J.27), (J.28).

        ``P(k)`` is the parabola (J.27): ``k = g +- sqrt(g^2 + A H P/(pi vartheta sqrt(R1 R2)))``, the ``+`` root on
        the stable branch (``dP/dk > 0``), the ``-`` root on the unstable one.  A pull beyond ``2 pi w sqrt(R1 R2)``
        (J.28) has no state (refused, one line).
        """
        if isinstance(force, (bool, str)) or not isinstance(force, (int, float, np.floating, np.integer)) \
                or not math.isfinite(float(force)):
            raise InputTypeError(f"force must be a finite real number (negative when pulled), got {force!r:.60}")
        if branch not in ("stable", "unstable"):
            raise InputError(f"branch must be 'stable' or 'unstable', got {branch!r:.40}")
        Hv, r1, r2, wv, vtv, g, dm = self._numbers(H, R1, R2, work_of_adhesion, mu)
        if self.order == 1:
            dp = self._first_order_at_force(float(force), branch, g, Hv, r1, r2, vtv)
            return self._state(dp + dm, dp + g, g, Hv, r1, r2, vtv)
        disc = g * g + self.A * Hv * float(force) / (math.pi * vtv * math.sqrt(r1 * r2))
        if disc < 0:
            raise InputError(f"force = {float(force):.6g} pulls harder than the load-controlled pull-off force "
                             f"{2 * math.pi * wv * math.sqrt(r1 * r2):.6g} = 2 pi w sqrt(R1 R2) (J.28): no contact")
        k = g + math.sqrt(disc) if branch == "stable" else g - math.sqrt(disc)
        if not k > 0:
            raise InputError(f"force = {float(force):.6g} has no state on the unstable branch of the thin-layer law "
                             "(the contact would shrink to nothing)")
        return self._state(k - g + dm, k, g, Hv, r1, r2, vtv)

    def pull_off(self, H: Any, R1: Any, R2: Any, work_of_adhesion: Any, mu: Any = 1.0) -> EllipticJKRState:
        """The load-controlled pull-off state (J.28): ``P = -2 pi w sqrt(R1 R2)`` at ``k = g`` (order 0); the minimum
        of the first-order force (J.31) over the depth (order 1, golden section to 1e-12 g).
        """
        Hv, r1, r2, _, vtv, g, dm = self._numbers(H, R1, R2, work_of_adhesion, mu)
        if self.order == 1:
            dp = self._first_order_pull_off(g, Hv, r1, r2, vtv)
            return self._state(dp + dm, dp + g, g, Hv, r1, r2, vtv)
        return self._state(dm, g, g, Hv, r1, r2, vtv)

    def _force1(self, dprime: float, g: float, Hv, r1, r2, vtv) -> float:
        """The first-order force (J.31) at ``delta'``; ``+inf`` where the law leaves no contact."""
        f = self._first_order(dprime, g, Hv, r1, r2, vtv)
        return math.inf if f is None or min(f[1:3]) <= 0 else f[0]

    def _first_order_pull_off(self, g: float, Hv, r1, r2, vtv) -> float:
        """``delta'`` at the minimum of the first-order force (order 0's is ``delta' = 0``)."""
        a, b = -0.6 * g, 2.0 * g
        q = (math.sqrt(5) - 1) / 2
        x1, x2 = b - q * (b - a), a + q * (b - a)
        f1, f2 = self._force1(x1, g, Hv, r1, r2, vtv), self._force1(x2, g, Hv, r1, r2, vtv)
        while b - a > 1e-12 * g:
            if f1 < f2:
                b, x2, f2 = x2, x1, f1
                x1 = b - q * (b - a)
                f1 = self._force1(x1, g, Hv, r1, r2, vtv)
            else:
                a, x1, f1 = x1, x2, f2
                x2 = a + q * (b - a)
                f2 = self._force1(x2, g, Hv, r1, r2, vtv)
        if not math.isfinite(min(f1, f2)):
            raise InputError("the first-order law (J.30) has no contact near its pull-off here (the contact is a few "
                             "H wide: outside the thin-layer law)")
        return 0.5 * (a + b)

    def _first_order_at_force(self, target: float, branch: str, g: float, Hv, r1, r2, vtv) -> float:
        """``delta'`` where the first-order force (J.31) is ``target`` on the branch (bisection to 1e-13 g)."""
        x_off = self._first_order_pull_off(g, Hv, r1, r2, vtv)
        P_off = self._force1(x_off, g, Hv, r1, r2, vtv)
        if target < P_off:
            raise InputError(f"force = {target:.6g} pulls harder than the first-order law's load-controlled pull-off "
                             f"force {-P_off:.6g} (J.31): no contact")
        step = g
        if branch == "stable":
            lo, hi = x_off, x_off + step
            while self._force1(hi, g, Hv, r1, r2, vtv) < target:
                step *= 2.0
                hi = x_off + step
        else:
            if target >= 0:
                raise InputError(f"force = {target:.6g} has no state on the unstable branch (a pull, negative, is "
                                 "needed there)")
            lo, hi = x_off - 0.5 * g, x_off
            for _ in range(60):
                v = self._force1(lo, g, Hv, r1, r2, vtv)
                if v > target:
                    break
                lo = 0.5 * (lo + x_off) if not math.isfinite(v) else lo - 0.5 * (hi - lo)
            else:
                raise InputError(f"force = {target:.6g} has no state on the unstable branch of the first-order law")
            if not math.isfinite(self._force1(lo, g, Hv, r1, r2, vtv)):
                raise InputError(f"force = {target:.6g} has no state on the unstable branch of the first-order law "
                                 "(the contact would be a few H wide)")
        rising = branch == "stable"
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            above = self._force1(mid, g, Hv, r1, r2, vtv) > target
            if above == rising:
                hi = mid
            else:
                lo = mid
            if hi - lo <= 1e-13 * g:
                break
        return 0.5 * (lo + hi)

    def lambdify(self):
        """``(k, H, R1, R2, w, vartheta) -> (delta, P, a1, a2)`` with this layer's ``A`` and ``m_1``."""
        der = _derivation()
        num = {A_s: self.A, der["m1"]: self.m1}
        args = (k_s, H_s, der["R1"], der["R2"], w_s, vt)
        return sp.lambdify(args, [e.subs(num) for e in (self.depth, self.force, *self.semi_axes)], "numpy")

    def latex(self) -> str:
        a1, a2 = self.semi_axes
        return (rf"\delta = {sp.latex(self.depth)},\quad P = {sp.latex(self.force)},\quad a_1 = {sp.latex(a1)},\ "
                rf"a_2 = {sp.latex(a2)},\quad P_{{\mathrm{{off}}}} = {sp.latex(self.pull_off_load)} \tag{{J.27}}")

    def text_lines(self) -> list[str]:
        return [f"EllipticJKR: elliptic paraboloid on {type(self.layer).__name__} (nu = {self.nu:g}), order "
                f"{self.order}   (J.25)-(J.29)" + (", first order (J.30), (J.31)" if self.order else ""),
                f"  delta(k) = {self.depth}", f"  P(k) = {self.force}",
                f"  a1, a2 = {self.semi_axes[0]}, {self.semi_axes[1]}",
                f"  pull-off (load control) {self.pull_off_load}; A = {self.A:.12g}, h* = {self.h:.12g}, "
                f"m1 = {self.m1:.6g}"]


def elliptic_jkr(layer: LayerKernel, nu: Any = None, order: int = 0) -> EllipticJKR:
    """Thin-layer JKR of the elliptic paraboloid on a compressible layer (J.25)-(J.31).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` with a number ``-1 < nu < 1/2``, or ``FrictionlessLayer()`` (``A = 1/2``).  Incompressible
        layers are refused (the contour is not a level set of ``Phi`` there: use the 2D solver).
    nu : float, optional
        Poisson ratio for layers that fix none (``FrictionlessLayer``): it sets ``vartheta = mu/(1 - nu)``.
    order : int
        0 (J.26)-(J.29) or 1, with the edge layer's curvature correction (J.30), (J.31).

    Returns
    -------
    EllipticJKR

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> law = elliptic_jkr(BondedLayer(0.3))
    >>> s = law.pull_off(H=0.01, R1=1, R2=4, work_of_adhesion=0.1, mu=1)
    >>> round(s.force / (-2 * math.pi * 0.1 * 2), 12), s.valid
    (1.0, True)
    """
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a thinlayer layer (BondedLayer(nu), FrictionlessLayer()), got "
                             f"{type(layer).__name__}")
    A = layer.A
    if layer.numeric_nu is not None:
        nu = layer.numeric_nu
    elif nu is None:
        raise InputError("this layer fixes no Poisson ratio: pass nu= (a number in (-1, 1/2)) for vartheta")
    try:
        nu = float(nu)
    except (TypeError, ValueError):
        raise InputError(f"nu must be a number in (-1, 1/2), got {nu!r:.40}") from None
    if not layer.has_thickness or A is None or not float(A) > 0:
        raise InputError(f"the elliptic thin-layer JKR law (J.25)-(J.29) is for compressible layers (A > 0) with a "
                         f"thickness, got {type(layer).__name__} (A = {A}); at nu = 1/2 the outer problem is the "
                         "Laplacian (I.2) and the contour is not a level set: use the 2D solver")
    if order not in (0, 1) or isinstance(order, bool):
        raise InputError(f"order must be 0 or 1, got {order!r:.40}")
    der = _derivation()
    if not -1.0 < nu < 0.5:
        raise InputError(f"nu must lie in (-1, 1/2) for the compressible thin-layer law, got {nu!r}")
    return EllipticJKR(layer, float(nu), float(A), float(edge_shift_exact(layer, dps=16)), float(layer.m(1)),
                       der["depth"], der["force"], der["axes"], der["contour_pressure"], der["pull_off"], order,
                       _r3(layer) if order == 1 else 0.0)


@lru_cache(maxsize=16)
def _r3(layer: LayerKernel) -> float:
    """``r_3`` (SO.4) of the layer: order 1's estimate only (order 0's is larger by O(c/H))."""
    return float(edge_constants(layer, dps=16).r3)
