r"""Ting's method on the layer (issue 27 item 2): approach-retract histories, the contact shrinking, (T1)-(T6).

Statement (derived below, checked against the direct solver :func:`thinlayer.numerics.viscoelastic.solve_history`)
----------------------------------------------------------------------------------------------------------------
For a tip of revolution on the bonded or frictionless layer (or the half-space) of a linear viscoelastic solid with a
**constant Poisson ratio**, under a depth history whose contact radius grows to one maximum at ``t_m`` and then
shrinks, Ting's construction is **exact for the layer as for the half-space**, under conditions (C1)-(C3):

* ``t <= t_m`` (Lee-Radok): ``a(t) = a_e(delta(t))``, ``P(t) = int_0^t G(t - s) d/ds F(delta(s)) ds``;
* ``t > t_m``: ``t1(t) <= t_m`` solves ``int_{t1}^t E(t - s) d delta(s) = 0`` (T4), then
  ``a(t) = a_e(delta(t1))`` and ``P(t) = int_0^{t1} G(t - s) d/ds F(delta(s)) ds`` (T5);
  the contact is lost when ``int_0^t E(t - s) d delta(s) <= 0``.

``F`` and ``a_e`` are the layer's elastic force and contact radius at unit shear modulus (the model's
:class:`~thinlayer.contact.models.base.ForceCurve`), ``G = E/(2 (1 + nu))``.

Derivation
----------
(T1) With nu constant the layer's influence operator A (surface pressure -> surface displacement at unit modulus,
(F.2)) does not depend on time, and ``A p(t) = int vartheta(t - s) d u(s)`` on the whole surface (numerics/viscoelastic
(V.2)); equivalently ``u = A pi``, ``p = vartheta * d pi`` (Stieltjes convolution), ``pi = J * d p`` with J the creep
compliance of vartheta.

(T2) Let ``p_e(r; a)`` be the layer's elastic contact pressure of radius a at unit modulus and ``delta_e(a)`` its
depth: ``A p_e(.; a) = delta_e(a) - Phi(r)`` on ``r <= a``, ``p_e = 0`` on ``r > a``.  Nothing here is specific to
the half-space.

(T3) Ansatz: ``p(r, t) = int_0^{t1(t)} vartheta(t - s) d_s p_e(r; a(s))`` with ``a(t1(t)) = a(t)``, ``t1 <= t_m``.
It vanishes for ``r > a(t)`` (every ``a(s) <= a(t)`` there).  With ``Fi(r, s) = A p_e(.; a(s))(r)``,
``A p(s) = vartheta * dFi - int_{t1(s)}^s vartheta(s - tau) d_tau Fi``, so ``u = J * d(A p) = Fi(., t) - J * d D``,
``D(s) = int_{t1(s)}^s vartheta(s - tau) d_tau Fi(r, tau)``.  For ``r < a(t)`` and ``tau`` in ``[t1(s), s]``,
``s <= t``, the radius ``a(tau) >= a(t) > r``: ``Fi(r, tau) = delta_e(a(tau)) - Phi(r)`` and ``d_tau Fi`` does not
depend on r.  Hence ``u(r, t) = delta(t) - Phi(r)`` on the contact with

    delta(t) = delta_e(a(t)) - int_0^t J(t - s) d/ds [int_{t1(s)}^s vartheta(s - tau) d delta_e(a(tau))] ds.

(T4) Convolving with vartheta and using ``delta(s) = delta_e(a(s))`` for ``s <= t_m`` (loading): ``int_{t1}^t
vartheta(t - s) d delta(s) = 0`` -- Ting's condition (vartheta and E differ by a constant factor).

(T5) ``P = 2 pi int p r dr = int_0^{t1} vartheta(t - s) d P_e(a(s))``, ``P_e`` the elastic force at unit vartheta:
at unit shear modulus, ``P = int_0^{t1} G(t - s) dF(delta(s))``.

(T6) *Conditions.*  (T3)-(T5) satisfy the contact equations exactly on a layer; they are the solution of the
unilateral problem (unique) when
(C1) nu is constant (else A depends on time and (T1) fails: no exact result then);
(C2) ``p_e(r; a)`` does not decrease with a at any r (then ``p >= 0``); checked for the sphere and the cone (70 deg)
on bonded nu = 0.3, 1/2 and frictionless layers, ``c/H`` from 0.5 to 8 (tests/viscoelastic/test_ting.py,
test_ting_tips.py: the elastic direct solver's pressure at growing radii);
(C3) the gap stays open outside ``a(t)``: not proved here; measured by the direct solver at every step ((V.8)
``min_gap``), which also solves the problem without (T3).
Ting (1968) is needed for a radius with several maxima; those times are flagged here.

(T7) *The flat punch* (fixed contact, ``Punch.flat(a)``).  Its contact is the face ``r <= a`` as long as the force is
compressive, so Ting reduces to Lee-Radok with ``t1 = t`` at every time, for a falling depth too: with the contact
fixed the problem is linear, ``p(r, t) = p_e(r) Y(t)/delta_e`` with ``Y(t) = int_0^t E(t - s) dU(s)`` and ``U`` the
depth of the surface under the face, and ``P = S Y/(2 (1 + nu))``, ``S`` the elastic stiffness at unit shear modulus
(``P_e = S delta``, :func:`thinlayer.contact.flat_punch.flat_punch_stiffness`).  There is no adhesion, so the
force cannot turn tensile: when ``Y`` would fall below 0 the punch lifts off, the force is 0, and the surface under
the face (uniform, since the pressure has kept the shape ``p_e``: ``u = U`` on ``r <= a``) recovers freely, ``Y = 0``:
``U`` follows the creep recovery of the history before the lift-off and no longer the punch -- the depth history
decouples.  The punch touches again when its depth reaches ``U``.  Both phases are one complementarity per time,
``U = max(delta, U_free)`` with ``Y(U_free) = 0``, solved exactly for ``U`` linear in time between the nodes
(``surface_depth`` of the result).  (C2) holds (``p_e > 0`` on the face), (C3) has no content (nothing of the punch
lies outside the face).  Checked against the direct solver with a fixed contact face (numerics/viscoelastic (V.10)).

The cone: Ting's construction above, with the cone's elastic law at any thickness (T.9) (its table,
:func:`thinlayer.contact.any_thickness_tips.cone_law`); (C2) checked on three layers like the sphere's
(tests/viscoelastic/test_ting_tips.py).

Measured against the direct solver (sphere ``R = 1``, SLS ``E0/E_inf = 3``, ``tau = 0.2``, ``delta = 0.02 min(t,
1 - t)``; the solver at 201 steps x 200 nodes, Ting on 20,001 steps; largest relative force difference while
unloading at ``P > 0.1 P_max``, in brackets at 101 steps x 100 nodes)::

    a_max/H           0.1              ~1.3             ~6              ~11-15
    bonded nu = 1/2   3.2e-5 (1.3e-4)  4.7e-5 (1.8e-4)  8.8e-5 (3.6e-4)  1.3e-4 (a/H = 14.8, solver flags p < 0)
    bonded nu = 0.3   3.3e-5 (1.3e-4)  3.4e-5 (1.3e-4)  4.4e-5 (1.5e-4)  4.9e-5
    frictionless 0.3  3.3e-5 (1.3e-4)  3.3e-5 (1.3e-4)  4.0e-5 (1.5e-4)  4.8e-5

Cone (70 degrees) on the half-space: 7.9e-5 (101 x 100), 2.0e-5 (201 x 200) against Ting on 2,001 steps.
The acceptance grid (tests/viscoelastic/test_visco_acceptance.py: sphere, cone 70, flat punch x bonded nu = 1/2, 0.3,
frictionless x ``a_max/H`` ~ 0.1 to 10 x ramp-hold, approach-retract, oscillation; the solver at 60 and 120 steps per
unit time, nodes doubled too): every Ting cell within 1.7e-4 of the solver (a third of the solver's own refinement
change: its second-order error), and the Richardson value within 5.1e-5 (cone) and 3.6e-5 (sphere) of Ting; the
flat punch (T7), lift-off included, within 1.4e-7 by Richardson over the exact or thick-layer stiffness, and within
the thin-layer stiffness's own error (2.8e-4, estimate 8.5e-4) at a/H = 5.
The difference falls 4x when the solver's steps and nodes are doubled (its own second-order error): no error of
Ting's construction shows on the layer, thick to thin, at the solver's accuracy; the solver's ``min_pressure`` and
``min_gap`` stay >= 0 (C2, C3) wherever it resolves the layer.

Numerics: the branch variables of ``delta`` and ``F`` (linear in time between the nodes, as in
:mod:`thinlayer.contact.hereditary`) at the nodes, ``t1`` by bisection (vectorised over the times) on the monotone
``int_0^{t1} E(t - s) d delta``, exact within a step.
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._checks import check_array_size, check_history, parse_nu, positive
from ..asymptotics.solution import DEFAULT_TOL, numeric_punch
from ..errors import InputError, InputTypeError, boundary
from ..layers.kernels import LayerKernel
from ..punch import Tip, is_polynomial_tip
from .hereditary import MAX_STEPS, force_curve_for, hereditary_integral
from .materials import Material, Prony

__all__ = ["TingForce", "ting_force"]


@dataclass(frozen=True, eq=False)
class TingForce:
    r"""A force history by Ting's method (T3)-(T5): ``force``, ``contact_radius``, ``t1`` against ``times``.

    ``t1[n]`` is Ting's time (``= times[n]`` while the contact grows; NaN after contact is lost).  ``valid[n]`` is
    False where the construction does not apply (``reason``); the force is NaN there.
    """

    times: np.ndarray
    depths: np.ndarray
    force: np.ndarray
    contact_radius: np.ndarray
    t1: np.ndarray
    valid: np.ndarray
    reason: str
    model: str
    material: Material
    nu: float
    H: float

    #: the flat punch (T7): the depth of the surface under the punch (the punch's depth while in contact, the free
    #: recovery after lift-off); None for a tip whose contact grows and shrinks
    surface_depth: np.ndarray | None = None

    equation = "T5"

    def latex(self) -> str:
        return (r"P(t) = \frac{1}{2(1+\nu)}\int_0^{t_1(t)} E(t-s)\,\frac{d}{ds}F\big(\delta(s)\big)\,ds,\quad "
                r"\int_{t_1(t)}^{t} E(t-s)\,\dot\delta(s)\,ds = 0,\quad " + self.material.latex()
                + rf",\ \nu = {self.nu:.4g}\ \text{{({self.model})}} \tag{{T5}}")

    def __repr__(self) -> str:
        n_bad = int((~self.valid).sum())
        return f"<TingForce: {self.model} law, {len(self.times)} times" + (f", {n_bad} NOT VALID>" if n_bad else ">")

    def __str__(self) -> str:
        n_bad = int((~self.valid).sum())
        head = f"TingForce ({self.model} law, {len(self.times)} times, nu = {self.nu:.4g}, H = {self.H:.6g})"
        return (f"{head}: force up to {np.nanmax(self.force, initial=0.0):.6g}"
                + (f"; {n_bad} times NOT VALID: {self.reason}" if n_bad else ""))


def _branch(t: np.ndarray, f: np.ndarray, tau: float) -> np.ndarray:
    """``int_0^{t_n} exp(-(t_n - s)/tau) df(s)`` at the nodes (f linear between them, a step at t[0])."""
    return hereditary_integral(Prony(0.0, [(1.0, tau)]), t, f)


def _at(t: np.ndarray, f: np.ndarray, q: np.ndarray, taus: np.ndarray, k: np.ndarray,
        theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(f(t1), q_i(t1))`` at ``t1 = t_k + theta`` inside step k (exact for f linear in time)."""
    h = np.diff(t)
    kk = np.minimum(k, len(t) - 2)
    r = np.where(k < len(t) - 1, (f[kk + 1] - f[kk]) / h[kk], 0.0)
    e = np.exp(-theta[None, :] / taus[:, None])
    return f[k] + r * theta, e * q[:, k] + r[None, :] * taus[:, None] * (1.0 - e)


def _A(einf: float, E: np.ndarray, taus: np.ndarray, tn: np.ndarray, t1: np.ndarray, f1: np.ndarray,
       q1: np.ndarray) -> np.ndarray:
    """``int_0^{t1} E(t_n - s) df(s) = E_inf f(t1) + sum_i E_i exp(-(t_n - t1)/tau_i) q_i(t1)``."""
    return einf * f1 + (E[:, None] * np.exp(-(tn - t1)[None, :] / taus[:, None]) * q1).sum(axis=0)


@boundary
def ting_force(layer: LayerKernel, punch: Any, H: Any, material: Material, times: Any, depths: Any, *,
               nu: Any = None, tol: float = DEFAULT_TOL, model: str = "auto") -> TingForce:
    r"""Force and contact radius for an approach-retract depth history by Ting's method on the layer (T3)-(T5).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)``, ``FrictionlessLayer(nu)`` or ``HalfSpace()``.
    punch : Tip
        A tip with a vectorised elastic law and a smooth contact edge (``Punch.paraboloid(R)``, ``Punch.sphere(R)``,
        ``Punch.cone(angle)``).
    H : float
        Layer thickness.
    material : Prony or StandardLinearSolid
        Young's relaxation modulus; nu constant (C1).
    times, depths : array_like
        Depth history, linear in time between the nodes; the contact radius must have one maximum (the depth rises
        to its maximum, then falls or holds).
    nu, tol, model
        As for :func:`thinlayer.contact.hereditary.viscoelastic_force`.

    Examples
    --------
    A sphere pressed into and pulled out of a thin bonded layer of a standard linear solid:

    >>> import numpy as np
    >>> from thinlayer import BondedLayer, Punch, StandardLinearSolid
    >>> t = np.linspace(0.0, 1.0, 201)
    >>> d = 0.04 * np.minimum(t, 1.0 - t)
    >>> out = ting_force(BondedLayer(0.5), Punch.paraboloid(10.0), 1.0, StandardLinearSolid(3.0, 1.0, 0.1), t, d)
    >>> bool(out.valid.all()), bool(out.force[150] > 0), float(out.force[-1])
    (True, True, 0.0)
    """
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be BondedLayer(nu), FrictionlessLayer(nu) or HalfSpace(), got {layer!r}")
    if not isinstance(material, Prony):
        raise InputTypeError(f"material must be Prony(...) or StandardLinearSolid(...) (Ting's method here needs the "
                             f"Prony branches), got {material!r}")
    nu_v = float(parse_nu(layer.poisson_ratio(nu), floats="float", upper_closed=True, symbols=False,
                          example="0.3, '3/10' or 0.5"))
    HH = positive(H, "H")
    if isinstance(tol, bool) or not isinstance(tol, numbers.Real) or not tol > 0:
        raise InputError(f"tol must be a positive number (the elastic law's largest relative error), got {tol!r}")
    for name, v in (("times", times), ("depths", depths)):
        check_array_size(v, name, MAX_STEPS, "1e6 nodes take ~1 s; subsample the history")
    t, d = check_history(times, depths, "depths", min_size=2)
    tip = punch if isinstance(punch, Tip) and not is_polynomial_tip(punch) else numeric_punch(punch, {})
    if layer.numeric_nu is None or layer.incompressible_at(nu_v):
        layer = layer.with_nu(nu_v)
    curve = force_curve_for(layer, tip, HH, nu_v, float(tol), d, model)
    if tip.fixed_contact:
        return _flat_punch(t, d, curve, material, nu_v, HH, float(tol))
    u, inv = np.unique(d, return_inverse=True)
    F = curve.force(u)[inv]
    bad_law = ~np.isfinite(F)
    F = np.where(bad_law, 0.0, F)
    einf = material.E_inf
    E = np.array([e for e, _ in material.terms], dtype=float)
    taus = np.array([tau for _, tau in material.terms], dtype=float)
    if E.size == 0:  # elastic: one branch of zero modulus keeps the arrays two-dimensional
        E, taus = np.zeros(1), np.ones(1)
    qd = np.array([_branch(t, d, tau) for tau in taus])
    qF = np.array([_branch(t, F, tau) for tau in taus])
    Ed = hereditary_integral(material, t, d)  # int_0^t E(t - s) d delta: the target of (T4)
    m = int(np.argmax(d))
    g = 1.0 / (2.0 * (1.0 + nu_v))
    force = hereditary_integral(material, t, F) * g
    radius = curve.contact_radius(u)[inv]
    t1 = t.copy()
    reasons = []
    notting = np.zeros(t.size, dtype=bool)
    if np.any(np.diff(d[: m + 1]) < 0):
        k = int(np.argmax(np.diff(d[: m + 1]) < 0))
        notting[k + 1:] = True
        reasons.append(f"the depth falls at t = {t[k + 1]:.6g} before its maximum: the contact radius has several "
                       "maxima (Ting 1968, not covered)")
    after = np.arange(m + 1, t.size)
    if after.size:
        tn, T = t[after], Ed[after]
        lost = T <= 0.0
        # bisection over the steps k in [0, m): A(t_k) <= T < A(t_{k+1})
        lo, hi = np.zeros(after.size, dtype=int), np.full(after.size, m)
        zero = np.zeros(after.size)
        for _ in range(int(math.ceil(math.log2(m + 1))) + 1):
            mid = (lo + hi) // 2
            f1, q1 = _at(t, d, qd, taus, mid, zero)
            ok = _A(einf, E, taus, tn, t[mid], f1, q1) <= T
            lo, hi = np.where(ok, mid, lo), np.where(ok, hi, mid)
        k = lo
        h = np.where(k < t.size - 1, t[np.minimum(k + 1, t.size - 1)] - t[k], 0.0)
        a_, b_ = np.zeros(after.size), h.copy()
        for _ in range(60):  # within the step: A increases with t1 (the depth grows there)
            th = 0.5 * (a_ + b_)
            f1, q1 = _at(t, d, qd, taus, k, th)
            ok = _A(einf, E, taus, tn, t[k] + th, f1, q1) <= T
            a_, b_ = np.where(ok, th, a_), np.where(ok, b_, th)
        th = 0.5 * (a_ + b_)
        tt1 = t[k] + th
        d1, _ = _at(t, d, qd, taus, k, th)
        F1, qF1 = _at(t, F, qF, taus, k, th)
        P = g * _A(einf, E, taus, tn, tt1, F1, qF1)
        # a_e(delta(t1)); below the history's least positive depth (contact nearly lost), linear from 0: the law is
        # never asked beyond the depths it was built for (a direct model would solve at depth 1e-300)
        dpos = u[u > 0]
        small = d1 < dpos.min()
        c1 = curve.contact_radius(np.where(small, dpos.min(), d1))
        c1 = np.where(small, c1 * np.maximum(d1, 0.0) / dpos.min(), c1)
        force[after] = np.where(lost, 0.0, P)
        radius[after] = np.where(lost, 0.0, c1)
        t1[after] = np.where(lost, np.nan, tt1)
        # the radius must keep shrinking: t1 never increases (else it grows again: Ting 1968)
        run = np.minimum.accumulate(np.where(lost, np.inf, tt1))
        regrow = np.zeros(after.size, dtype=bool)
        regrow[1:] = ~lost[1:] & (tt1[1:] > run[:-1] + 1e-12 * (t[-1] - t[0]))
        regrow |= np.logical_or.accumulate(lost) & ~lost  # re-contact after a loss
        if regrow.any():
            first = after[int(np.argmax(regrow))]
            notting[first:] = True
            reasons.append(f"the contact grows again (or re-forms) at t = {t[first]:.6g} after its maximum at "
                           f"t = {t[m]:.6g}: Ting 1968's construction for several maxima is not covered")
    invalid_law = np.logical_or.accumulate(bad_law)
    if invalid_law.any():
        reasons.append(f"the {curve.model} law has no answer within tol = {tol:.3g} at depth "
                       f"{d[np.argmax(bad_law)]:.6g} (t = {t[np.argmax(bad_law)]:.6g})")
    valid = ~(notting | invalid_law)
    force = np.where(valid, force, np.nan)
    radius = np.where(valid, radius, np.nan)
    for arr in (t, d, force, radius, t1, valid):
        arr.setflags(write=False)
    return TingForce(t, d, force, radius, t1, valid, "; ".join(reasons) or "Ting (1966): one maximum of the contact "
                     "radius", curve.model, material, nu_v, HH)


def _flat_punch(t: np.ndarray, d: np.ndarray, curve: Any, material: Prony, nu: float, H: float,
                tol: float) -> TingForce:
    """The flat punch's history (T7): Lee-Radok on the fixed face while compressive, lift-off, free recovery,
    re-contact; ``U_n = max(delta_n, U_free)`` per step, exact for U linear in time between the nodes.
    """
    top = float(np.max(d))
    S = float(curve.force(np.array([top]))[0]) / top if top > 0 else 0.0  # P_e = S delta at unit shear modulus
    a = float(curve.contact_radius(np.array([top]))[0]) if top > 0 else math.nan
    if top > 0 and not (math.isfinite(S) and S > 0):
        raise InputError(f"the {curve.model} law gives no flat-punch stiffness within tol = {tol:.3g} (a/H = "
                         f"{a / H:.4g})")
    E = np.array([e for e, _ in material.terms], dtype=float)
    taus = np.array([tau for _, tau in material.terms], dtype=float)
    einf = material.E_inf
    n = t.size
    U = np.empty(n)
    Y = np.empty(n)
    q = np.zeros(E.size)
    u_prev = 0.0
    h = np.diff(t)
    for k in range(n):
        if k == 0:  # a step from rest: q_i = U_0
            e, gf = np.zeros(E.size), np.ones(E.size)
        else:
            e = np.exp(-h[k - 1] / taus)
            gf = -np.expm1(-h[k - 1] / taus) * taus / h[k - 1]
        qa = e * q - gf * u_prev
        # Y(U) = E_inf U + sum_i E_i (qa_i + gf_i U), increasing in U; the free surface has Y = 0 (T7)
        slope = einf + float(E @ gf)
        u_free = -float(E @ qa) / slope
        U[k] = max(float(d[k]), u_free)
        q = qa + gf * U[k]
        Y[k] = max(einf * U[k] + float(E @ q), 0.0)
        u_prev = U[k]
    contact = d >= U  # in contact where the punch reaches the surface (U = delta)
    contact &= d > 0
    force = S * Y / (2.0 * (1.0 + nu))
    force = np.where(contact, force, 0.0)
    radius = np.where(contact, a, 0.0)
    t1 = np.where(contact, t, np.nan)
    valid = np.ones(n, dtype=bool)
    lost = (~contact) & (np.maximum.accumulate(np.where(contact, 1, 0)) > 0)
    why = ("flat punch (T7): the contact is the punch's face while the force is compressive (Lee-Radok, exact); "
           + (f"lift-off at t = {t[np.argmax(lost)]:.6g} (the force would turn tensile; no adhesion): the force is 0 "
              "and the surface recovers freely (surface_depth)" if lost.any() else "no lift-off"))
    for arr in (t, d, force, radius, t1, valid, U):
        arr.setflags(write=False)
    return TingForce(t, d, force, radius, t1, valid, why, curve.model, material, nu, H, surface_depth=U)
