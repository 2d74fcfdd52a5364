r"""Thin-layer JKR for the elliptic paraboloid on a compressible layer (J.25)-(J.29).

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

(J.29) *Remainder and estimate.*  The relative remainder of (J.25)-(J.28) is ``O(H kappa)``, ``kappa`` the contour's
curvature, from ``a1/a2^2`` to ``a2/a1^2`` along an ellipse (``a1 < a2``).  The first-order correction is *not*
included: for a disc it is the contour shift ``a_e = c + h* H`` and the factor ``1 + h* H/c`` of (J.10); along an
ellipse the curvature varies, ``p_out`` on the shifted contour is then no longer constant and the contour no longer
a level set, and the boundary layer of a curved edge is not derived here.  The estimate
(:meth:`EllipticJKR.state`) is twice the largest change that the disc's first-order correction makes when applied
with the curvature at either end of the ellipse (``g -> g/sqrt(1 + h* H kappa)``, the contact inside the level set
by ``h* H``): for ``R1 = R2`` it is twice the change from (J.11) order 0 to order 1, the sphere's estimate.
Measured against the direct solvers (``tests/adhesion/test_elliptic*.py``).

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
from .wiener_hopf import edge_shift_exact

__all__ = ["EllipticJKR", "EllipticJKRState", "elliptic_jkr"]

#: below this many layer thicknesses (the smaller contact semi-axis) the thin-layer law is flagged invalid
MIN_AXIS_OVER_H = 5.0

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
    """Thin-layer JKR for the elliptic paraboloid on a compressible layer (J.25)-(J.29), order 0.

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
        ``-2 pi w sqrt(R1 R2)`` (J.28), the minimum of ``P`` under load control.
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

    equation = "J.27"
    order = 0

    def _numbers(self, H: Any, R1: Any, R2: Any, work_of_adhesion: Any, mu: Any) -> tuple:
        Hv, r1, r2 = positive(H, "H"), positive(R1, "R1"), positive(R2, "R2")
        wv, vtv = check_work(work_of_adhesion), positive(mu, "mu") / (1 - self.nu)
        g = math.sqrt(2 * self.A * Hv * wv / vtv)
        return Hv, r1, r2, wv, vtv, g, self.m1 * Hv * Hv * (1 / r1 + 1 / r2)

    def _at_level(self, k: float, g: float, Hv: float, r1: float, r2: float, vtv: float) -> tuple:
        """(delta-independent) force and semi-axes at the level k with the contour pressure of g (J.27)."""
        P = math.pi * vtv * math.sqrt(r1 * r2) / (self.A * Hv) * (k * k - 2 * g * k)
        return P, math.sqrt(2 * r1 * k), math.sqrt(2 * r2 * k)

    def _state(self, delta_v: float, k: float, g: float, Hv, r1, r2, vtv) -> EllipticJKRState:
        P, a1, a2 = self._at_level(k, g, Hv, r1, r2, vtv)
        lo, hi = sorted((a1, a2))
        errs = np.zeros(3)
        for kappa in (lo / hi**2, hi / lo**2):  # the curvature at either end of the ellipse (J.29)
            gk = g / math.sqrt(1 + self.h * Hv * kappa)
            kk = k - g + gk  # the same depth
            if kk <= 0:
                errs[:] = math.inf
                break
            Pk, b1, b2 = self._at_level(kk, gk, Hv, r1, r2, vtv)
            errs = np.maximum(errs, np.abs([Pk - P, b1 - self.h * Hv - a1, b2 - self.h * Hv - a2]))
        errs *= 2.0
        valid = lo >= MIN_AXIS_OVER_H * Hv
        reason = (f"smaller semi-axis {lo:.4g} = {lo / Hv:.3g} H" + (" >= " if valid else " < ")
                  + f"{MIN_AXIS_OVER_H:g} H (thin-layer law, relative remainder O(H kappa), J.29)")
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

    def pull_off(self, H: Any, R1: Any, R2: Any, work_of_adhesion: Any, mu: Any = 1.0) -> EllipticJKRState:
        """The load-controlled pull-off state (J.28): ``P = -2 pi w sqrt(R1 R2)`` at ``k = g``."""
        Hv, r1, r2, _, vtv, g, dm = self._numbers(H, R1, R2, work_of_adhesion, mu)
        return self._state(dm, g, g, Hv, r1, r2, vtv)

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
        return [f"EllipticJKR: elliptic paraboloid on {type(self.layer).__name__} (nu = {self.nu:g}), order 0   "
                "(J.25)-(J.29)", f"  delta(k) = {self.depth}", f"  P(k) = {self.force}",
                f"  a1, a2 = {self.semi_axes[0]}, {self.semi_axes[1]}",
                f"  pull-off (load control) {self.pull_off_load}; A = {self.A:.12g}, h* = {self.h:.12g}, "
                f"m1 = {self.m1:.6g}"]


def elliptic_jkr(layer: LayerKernel, nu: Any = None) -> EllipticJKR:
    """Thin-layer JKR of the elliptic paraboloid on a compressible layer (J.25)-(J.29).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` with a number ``-1 < nu < 1/2``, or ``FrictionlessLayer()`` (``A = 1/2``).  Incompressible
        layers are refused (the contour is not a level set of ``Phi`` there: use the 2D solver).
    nu : float, optional
        Poisson ratio for layers that fix none (``FrictionlessLayer``): it sets ``vartheta = mu/(1 - nu)``.

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
    der = _derivation()
    if not -1.0 < nu < 0.5:
        raise InputError(f"nu must lie in (-1, 1/2) for the compressible thin-layer law, got {nu!r}")
    return EllipticJKR(layer, float(nu), float(A), float(edge_shift_exact(layer, dps=16)), float(layer.m(1)),
                       der["depth"], der["force"], der["axes"], der["contour_pressure"], der["pull_off"])
