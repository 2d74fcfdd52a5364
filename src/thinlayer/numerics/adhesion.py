r"""Adhesive (JKR) contact of an axisymmetric punch on a layer, solved directly with the exact kernel.

Equation tags ``J.n`` are this module's own.  Assumptions: frictionless contact, the layer bonded to (or lying
on) a rigid base as the layer kernel ``L(u)`` (2.3) says, JKR adhesion (a short-range attraction: the work of
adhesion ``w`` is spent at the contact edge only, the pressure is free to be tensile inside the contact).

Derivation (own)
----------------
(J.1) *Superposition at a fixed contact radius.*  At a prescribed contact radius ``c`` the problem (1.5)-(2.6)
with the equality ``u3 = delta - Phi`` on ``r < c`` is linear in ``delta``.  Its solutions form a line: the
smooth-edge solution of :func:`~thinlayer.numerics.axisymmetric.contact_for_radius` (depth ``delta_1(c)``, force
``P_1(c)``, pressure vanishing like ``(c - r)^{1/2}`` at the edge) plus a flat-ended punch of radius ``c``
pressed to the depth ``d = delta - delta_1(c)`` (:mod:`thinlayer.numerics.flat_punch`)::

    delta = delta_1(c) + d,      P = P_1(c) + S(c) d,      S(c) = 4 vartheta c kappa(c/H)       (F.1)

with ``vartheta = mu/(1 - nu)``.  Only the flat part is singular at the edge (F.8):
``p ~ (2 vartheta d/pi) f(1)/sqrt(c^2 - r^2) ~ (2 vartheta d f(1)/pi)/sqrt(2 c (c - r))``.

(J.2) *Stress-intensity factor* (mode I, ``sigma_zz = -p``, positive when the edge is pulled open)::

    K_I = lim_{r -> c} sqrt(2 pi (c - r)) sigma_zz = -2 vartheta d f(1)/sqrt(pi c).

(J.3) *Energy release rate from K_I.*  Near the edge the kernel is the half-space's (``L(u) -> 1``, (2.4)), and
for ``L = 1`` (2.1) is Boussinesq's ``u3 = (1/(2 pi vartheta)) iint p/|x - y|``, i.e. ``E* = E/(1 - nu^2) =
2 vartheta``.  Irwin's plane-strain relation ``G = K_I^2/(2 E*)`` therefore reads

    G = K_I^2/(4 vartheta) = vartheta d^2 f(1)^2/(pi c).

(J.4) *Energy release rate from the compliance* (the independent route).  At fixed ``delta`` the elastic energy
is ``U = U_1(c) + P_1(c) d + S(c) d^2/2`` up to terms stationary in ``c`` (the smooth-edge solution makes
``dU_1/dc`` equal to ``P_1 d delta_1/dc``), so the energy released per unit of contact area lost,
``dA = 2 pi c dc``, is

    G = (d^2/2) dS/dA = d^2 S'(c)/(4 pi c) = vartheta d^2 (lambda kappa)'(lambda)/(pi c),  lambda = c/H,

with the derivative taken numerically (a fourth-order central difference of the exact ``kappa``): it never uses
``f(1)``.  (J.3) and (J.4) agree by Krein's identity (F.9), ``(lambda kappa)' = f(1)^2``; the module checks it
at every state (``release_rate_energy`` against ``release_rate``).

(J.5) *JKR condition* ``G = w``.  The edge must be pulled (``K_I >= 0``, ``d <= 0``; a compressive edge
singularity would make the punch overlap the free surface), so

    d = -sqrt(pi c w/vartheta)/f(1),    delta(c) = delta_1(c) + d,    P(c) = P_1(c) + 4 vartheta c kappa d.

For ``L = 1`` (``kappa = f(1) = 1``) and the paraboloid this is the JKR (1971) result (checked symbolically in
``tests/adhesion``).

(J.6) *Pull-off and jump-in.*  Under load control the pull-off force is ``-min_c P(c)``; under displacement
control the contact is lost at ``min_c delta(c)`` (``d delta/dc = 0``), the force there is the pull-off force
of a rigid machine.  Jump-in on approach: the surfaces first touch at ``delta = 0`` (``Phi(0) = 0``); under
displacement control the contact jumps to the stable state with ``delta = 0`` (``d delta/dc > 0``), under load
control (zero load) to the stable state with ``P = 0`` (``dP/dc > 0``).

(J.13) *Flat punch (Kendall).*  A flat-ended cylinder of radius ``a`` keeps its contact radius until
``G = w``; then the edge crack runs inward unstably (``G ~ d^2 f(1)^2/c`` grows as ``c`` falls, under load and
under displacement control alike).  The detachment force is ``|P| = S(a) |d|`` with ``d`` of (J.5)::

    P_off = 4 vartheta a kappa sqrt(pi a w/vartheta)/f(1)

(half-space: ``sqrt(8 pi a^3 E* w)``, Kendall 1971; thin layer: :mod:`thinlayer.asymptotics.adhesion` (J.13)).

Errors
------
``delta_error`` and ``force_error`` add the direct solver's estimates (``delta0_error``, ``force_error`` of
:func:`~thinlayer.numerics.axisymmetric.contact_for_radius`, ``error`` of ``kappa``) and the disagreement of
the two routes for ``G`` (which bounds the error of ``f(1)``: ``d ~ G^{-1/2}``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._checks import InputError, positive
from .._checks import work_of_adhesion as check_work
from .._lazy import lazy_module
from ..display import RichDisplay
from ..layers.kernels import LayerKernel
from ._layer import numeric_layer_nu
from .axisymmetric import contact_for_radius
from .flat_punch import MAX_A_OVER_H, check_numeric_layer, flat_punch_kappa

optimize = lazy_module("scipy.optimize")  # scipy imported on first use

__all__ = ["AdhesiveState", "FlatDetachment", "JKRCurve", "adhesive_state", "flat_punch_detachment",
           "flat_release_rate_factor", "jkr_curve"]

#: relative step of the central difference of ``lambda kappa(lambda)`` (J.4)
_STEP = 0.02


# --------------------------------------------------------------------------- flat part
def flat_release_rate_factor(layer: LayerKernel, a_over_H: float, energy_route: bool = True
                             ) -> tuple[float, float, float, float]:
    """``(kappa, f(1)^2, (lambda kappa)', error of kappa)`` of the flat punch of radius ``c = lambda H`` (J.3), (J.4).

    ``(lambda kappa)'`` is the fourth-order central difference with step ``0.02 lambda`` (truncation about
    ``1e-9`` relative) of :func:`~thinlayer.numerics.flat_punch.flat_punch_kappa`; for a layer without
    thickness (the half-space) ``kappa = f(1) = 1`` and the derivative is 1 exactly.  ``energy_route=False``
    skips the four extra solves of the derivative (returned as ``nan``).
    """
    layer = check_numeric_layer(layer)
    if not layer.has_thickness:
        return 1.0, 1.0, 1.0, 0.0
    lam = positive(a_over_H, "a_over_H")
    st = flat_punch_kappa(layer, lam)
    if not energy_route:
        return st.kappa, st.edge_value**2, math.nan, st.error
    h = _STEP * lam
    if lam + 2 * h > MAX_A_OVER_H:
        raise InputError(f"a/H = {lam:g}: the energy route differentiates kappa up to a/H = {lam + 2 * h:g}, "
                         f"beyond the exact solver's limit {MAX_A_OVER_H:g}")
    g = [(lam + k * h) * flat_punch_kappa(layer, lam + k * h, error_estimate=False).kappa for k in (-2, -1, 1, 2)]
    deriv = (g[0] - 8 * g[1] + 8 * g[2] - g[3]) / (12 * h)
    return st.kappa, st.edge_value**2, deriv, st.error


# --------------------------------------------------------------------------- results
@dataclass(frozen=True)
class AdhesiveState(RichDisplay):
    """An adhesive contact state at a prescribed contact radius (J.1)-(J.5).

    Attributes
    ----------
    layer : LayerKernel
        The layer.
    H, mu, nu, vartheta : float
        Thickness (``nan`` for the half-space), shear modulus, Poisson ratio, ``mu/(1 - nu)``.
    radius : float
        Contact radius ``c``.
    delta, force : float
        float
        Depth and force of the state (J.1); the force is negative when the punch is pulled.
    work_of_adhesion : float
        ``w`` with ``G = w`` (J.5) (for a state built from a depth: the ``G`` of that state).
    delta_smooth, force_smooth : float
        float
        ``delta_1(c)``, ``P_1(c)`` of the smooth-edge (non-adhesive) solution at the same radius.
    flat_depth : float
        ``d = delta - delta_1(c)`` (J.1), ``<= 0`` on the JKR branch.
    kappa, edge_value : float
        float
        ``kappa(c/H)`` and ``f(1)`` of the flat punch (F.7), (F.8).
    stress_intensity : float
        ``K_I`` (J.2).
    release_rate, release_rate_energy : float
        float
        ``G`` from ``K_I`` (J.3) and from the compliance (J.4).
    delta_error, force_error : float
        float
        Absolute error estimates (module docstring).
    """

    layer: LayerKernel
    H: float
    mu: float
    nu: float
    vartheta: float
    radius: float
    delta: float
    force: float
    work_of_adhesion: float
    delta_smooth: float
    force_smooth: float
    flat_depth: float
    kappa: float
    edge_value: float
    stress_intensity: float
    release_rate: float
    release_rate_energy: float
    delta_error: float
    force_error: float

    equation = "J.5"

    @property
    def stiffness(self) -> float:
        """``S(c) = 4 vartheta c kappa`` (F.1): the slope ``dP/d delta`` at a fixed contact radius."""
        return 4.0 * self.vartheta * self.radius * self.kappa

    def latex(self) -> str:
        return (rf"c = {self.radius:.10g},\quad \delta = {self.delta:.10g},\quad P = {self.force:.10g},\quad "
                rf"G = \frac{{K_I^2}}{{4\vartheta}} = {self.release_rate:.10g} \tag{{J.5}}")

    def text_lines(self) -> list[str]:
        return [f"AdhesiveState: {self.layer}, H = {self.H:.6g}, mu = {self.mu:.6g}, nu = {self.nu:.6g}   (J.1)-(J.5)",
                f"  c = {self.radius:.10g}, w = {self.work_of_adhesion:.10g}",
                f"  delta = {self.delta:.12g} (+- {self.delta_error:.1e}), P = {self.force:.12g} "
                f"(+- {self.force_error:.1e})",
                f"  smooth edge: delta_1 = {self.delta_smooth:.12g}, P_1 = {self.force_smooth:.12g}; flat part "
                f"d = {self.flat_depth:.12g}",
                f"  K_I = {self.stress_intensity:.10g}; G (K_I) = {self.release_rate:.10g}, "
                f"G (compliance) = {self.release_rate_energy:.10g}"]


def _material(layer: Any, H: Any, mu: Any, nu: Any) -> tuple[LayerKernel, float | None, float, float]:
    layer = check_numeric_layer(layer)
    nu_val = numeric_layer_nu(layer, nu)
    mu_val = positive(mu, "mu")
    if layer.has_thickness:
        if H is None:
            raise InputError(f"{type(layer).__name__} needs the layer thickness H > 0")
        return layer, positive(H, "H"), mu_val, nu_val
    return layer, None, mu_val, nu_val


def adhesive_state(layer: LayerKernel, punch: Any, radius: float, H: float | None = None, mu: float = 1.0, *,
                   work_of_adhesion: float | None = None, delta: float | None = None, nu: float | None = None,
                   n: int | None = None, energy_route: bool = True) -> AdhesiveState:
    """The adhesive state of an axisymmetric punch at the contact radius ``c`` (J.1)-(J.5).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)``, ``FrictionlessLayer()``, ``IncompressibleLayer()`` or ``HalfSpace()``.
    punch : Punch, sympy.Expr or callable
        What :func:`~thinlayer.numerics.axisymmetric.contact_for_radius` takes (radial profile with Phi(0) = 0).
    radius : float
        Contact radius ``c > 0``.
    H : float, optional
        Layer thickness (omitted for the half-space).
    mu : float
        Shear modulus.
    work_of_adhesion, delta : float, optional
        float
        Exactly one: ``w >= 0`` (the JKR state, ``G = w``, J.5) or the depth (any state on the line (J.1);
        ``work_of_adhesion`` of the result is then its ``G``, and a depth above ``delta_1(c)`` is refused:
        its edge would be compressive and singular).
    nu : float, optional
        Poisson ratio for layers that fix none.
    n : int, optional
        Galerkin modes of the smooth-edge solution (refinement checks).
    energy_route : bool
        Also compute ``G`` by the compliance route (J.4) (four more flat-punch solves); without it
        ``release_rate_energy`` is ``nan`` and the error estimate leaves out the routes' disagreement.

    Returns
    -------
    AdhesiveState

    Examples
    --------
    The half-space and the paraboloid ``r^2/(2R)``: JKR (1971), ``delta = c^2/R - sqrt(2 pi w c/E*)``,
    ``E* = 2 mu/(1 - nu)``:

    >>> from thinlayer import HalfSpace
    >>> s = adhesive_state(HalfSpace(), lambda r: r**2 / 20.0, 1.0, work_of_adhesion=0.01, nu=0.0)
    >>> abs(s.delta - (0.1 - math.sqrt(2 * math.pi * 0.01 / 2.0))) < 1e-9
    True
    """
    layer, H_val, mu_val, nu_val = _material(layer, H, mu, nu)
    c = positive(radius, "radius")
    if (work_of_adhesion is None) == (delta is None):
        raise InputError("give exactly one of work_of_adhesion (the JKR state) and delta (a depth)")
    vt = mu_val / (1.0 - nu_val)
    lam = c / H_val if H_val is not None else 1.0
    smooth = contact_for_radius(layer, punch, c, H_val, mu_val, n, nu=None if layer.numeric_nu is not None
                                else nu_val)
    kappa, f1sq, dg, kerr = flat_release_rate_factor(layer, lam, energy_route)
    if work_of_adhesion is not None:
        w = check_work(work_of_adhesion)
        d = -math.sqrt(math.pi * c * w / vt / f1sq)  # (J.5)
    else:
        try:
            dval = float(delta)
        except (TypeError, ValueError):
            raise InputError(f"delta must be a finite number, got {delta!r}") from None
        if not math.isfinite(dval):
            raise InputError(f"delta must be finite, got {delta!r}")
        d = dval - smooth.delta0
        if d > 1e-12 * max(1.0, abs(smooth.delta0)):
            raise InputError(f"delta = {dval:g} exceeds the smooth-edge depth {smooth.delta0:g} at c = {c:g}: "
                             "the edge would be compressive and singular (no JKR state); give delta <= delta_1(c)")
        d = min(d, 0.0)
    f1 = math.sqrt(f1sq)
    K = -2.0 * vt * d * f1 / math.sqrt(math.pi * c)  # (J.2)
    G = K * K / (4.0 * vt)  # (J.3)
    G_energy = vt * d * d * dg / (math.pi * c)  # (J.4)
    S = 4.0 * vt * c * kappa
    rel_G = abs(G - G_energy) / G if G > 0 and energy_route else 0.0
    d_err = abs(d) * (0.5 * rel_G + kerr)
    delta_err = smooth.delta0_error + d_err
    force_err = abs(smooth.force) * smooth.force_error + abs(S * d) * kerr + S * d_err
    return AdhesiveState(layer, H_val if H_val is not None else math.nan, mu_val, nu_val, vt, c, smooth.delta0 + d,
                         smooth.force + S * d, G if work_of_adhesion is None else w, smooth.delta0, smooth.force,
                         d, kappa, f1, K, G, G_energy, delta_err, force_err)


# --------------------------------------------------------------------------- the JKR curve
@dataclass(frozen=True)
class JKRCurve(RichDisplay):
    """The JKR curve ``(c, delta(c), P(c))`` of a punch on a layer at a work of adhesion (J.5), (J.6).

    Attributes
    ----------
    radii, delta, force : numpy.ndarray
        numpy.ndarray
        Sampled contact radii and the JKR depth and force there (read-only).
    states : tuple of AdhesiveState
        The states themselves.
    pull_off_load : AdhesiveState
        The minimum of ``P(c)`` (load control, J.6); its ``-force`` is the pull-off force.
    pull_off_displacement : AdhesiveState or None
        The minimum of ``delta(c)`` (displacement control); None when ``delta(c)`` has no interior minimum on
        the sampled range (for the layer it may lie below the smallest radius given).
    jump_in_displacement, jump_in_load : AdhesiveState or None
        AdhesiveState or None
        The stable states with ``delta = 0`` and with ``P = 0`` (J.6); None where the sampled curve has none.
    """

    radii: np.ndarray = field(repr=False)
    delta: np.ndarray = field(repr=False)
    force: np.ndarray = field(repr=False)
    states: tuple = field(repr=False)
    pull_off_load: AdhesiveState | None
    pull_off_displacement: AdhesiveState | None
    jump_in_displacement: AdhesiveState | None
    jump_in_load: AdhesiveState | None
    work_of_adhesion: float

    equation = "J.6"

    def latex(self) -> str:
        parts = []
        if self.pull_off_load is not None:
            parts.append(rf"P_{{\mathrm{{off}}}}^{{\mathrm{{load}}}} = {-self.pull_off_load.force:.10g}")
        if self.pull_off_displacement is not None:
            parts.append(rf"P_{{\mathrm{{off}}}}^{{\mathrm{{disp}}}} = {-self.pull_off_displacement.force:.10g}")
        return r",\quad ".join(parts) + r" \tag{J.6}"

    def text_lines(self) -> list[str]:
        out = [f"JKRCurve: w = {self.work_of_adhesion:.6g}, {self.radii.size} radii in "
               f"[{self.radii[0]:.6g}, {self.radii[-1]:.6g}]   (J.5), (J.6)"]
        for name, st in (("pull-off, load control", self.pull_off_load),
                         ("pull-off, displacement control", self.pull_off_displacement),
                         ("jump-in, displacement control", self.jump_in_displacement),
                         ("jump-in, load control", self.jump_in_load)):
            out.append(f"  {name}: " + ("none on the sampled range" if st is None else
                                        f"c = {st.radius:.10g}, delta = {st.delta:.10g}, P = {st.force:.10g}"))
        return out


def _refine(fun, radii: np.ndarray, values: np.ndarray, kind: str):
    """The radius of an interior minimum (kind 'min') or of the last sign change upward (kind 'zero')."""
    if kind == "min":
        i = int(np.argmin(values))
        if i == 0 or i == values.size - 1:
            return None
        res = optimize.minimize_scalar(fun, bracket=(radii[i - 1], radii[i], radii[i + 1]),
                                       options={"xtol": 1e-10})
        return float(res.x)
    i_min = int(np.argmin(values))
    for j in range(i_min, values.size - 1):
        if values[j] <= 0.0 < values[j + 1]:
            return float(optimize.brentq(fun, radii[j], radii[j + 1], xtol=1e-13 * radii[j + 1], rtol=1e-13))
    return None


def jkr_curve(layer: LayerKernel, punch: Any, radii: Any, H: float | None = None, mu: float = 1.0, *,
              work_of_adhesion: float, nu: float | None = None, n: int | None = None) -> JKRCurve:
    """The JKR curve on the given contact radii, with pull-off and jump-in (J.5), (J.6).

    The extrema and zeros are located on the sampled radii and refined by Brent's method on
    :func:`adhesive_state` (each evaluation one direct solve); an extremum at the end of the sampled range is not
    reported (give a wider range).

    Parameters
    ----------
    layer, punch, H, mu, nu, n
        As for :func:`adhesive_state`.
    radii : array_like
        Increasing contact radii (at least 3, at most 400).
    work_of_adhesion : float
        ``w >= 0``.

    Returns
    -------
    JKRCurve
    """
    try:
        c = np.asarray(radii, dtype=float)
    except (TypeError, ValueError):
        raise InputError("radii must be 3 to 400 increasing positive contact radii (numbers)") from None
    if c.ndim != 1 or c.size < 3 or c.size > 400 or not np.all(np.isfinite(c)) or np.any(c <= 0) \
            or np.any(np.diff(c) <= 0):
        raise InputError("radii must be 3 to 400 increasing positive contact radii")
    w = check_work(work_of_adhesion)

    def state(ci: float) -> AdhesiveState:
        return adhesive_state(layer, punch, float(ci), H, mu, work_of_adhesion=w, nu=nu, n=n)

    states = tuple(state(ci) for ci in c)
    d = np.array([s.delta for s in states])
    P = np.array([s.force for s in states])
    found = []
    for vals, kind, attr in ((P, "min", "force"), (d, "min", "delta"), (d, "zero", "delta"), (P, "zero", "force")):
        x = _refine(lambda r, a=attr: getattr(state(r), a), c, vals, kind)
        found.append(None if x is None else state(x))
    for arr in (c, d, P):
        arr.setflags(write=False)
    return JKRCurve(c, d, P, states, *found, w)


# --------------------------------------------------------------------------- (J.13) the flat punch
@dataclass(frozen=True)
class FlatDetachment(RichDisplay):
    """Detachment of a flat-ended cylinder of radius ``a`` from a layer (J.13).

    Attributes
    ----------
    layer : LayerKernel
        The layer.
    radius, H, mu, nu, vartheta, work_of_adhesion : float
        float
        Punch radius ``a``, thickness (``nan`` for the half-space), shear modulus, Poisson ratio,
        ``mu/(1 - nu)``, ``w``.
    kappa, edge_value : float
        float
        ``kappa(a/H)`` and ``f(1)`` (F.7), (F.8).
    depth : float
        The (negative) depth at detachment, ``d`` of (J.5).
    force : float
        The detachment (pull-off) force, a magnitude ``>= 0``: the punch is pulled with ``-force``.
    error : float
        Relative error estimate (that of ``kappa`` plus the disagreement of (J.3) and (J.4)).
    """

    layer: LayerKernel
    radius: float
    H: float
    mu: float
    nu: float
    vartheta: float
    work_of_adhesion: float
    kappa: float
    edge_value: float
    depth: float
    force: float
    error: float

    equation = "J.13"

    def latex(self) -> str:
        return (rf"P_{{\mathrm{{off}}}} = \frac{{4 \vartheta a \kappa}}{{f(1)}}\sqrt{{\frac{{\pi a w}}{{\vartheta}}}}"
                rf" = {self.force:.10g} \tag{{J.13}}")

    def text_lines(self) -> list[str]:
        return [f"FlatDetachment: flat punch a = {self.radius:.6g} on {self.layer}, H = {self.H:.6g}   (J.13)",
                f"  w = {self.work_of_adhesion:.6g}: detachment force {self.force:.12g} (+- {self.error:.1e} "
                f"relative), depth {self.depth:.10g}",
                f"  kappa = {self.kappa:.12g}, f(1) = {self.edge_value:.12g}"]


def flat_punch_detachment(layer: LayerKernel, radius: float, H: float | None = None, mu: float = 1.0, *,
                          work_of_adhesion: float, nu: float | None = None) -> FlatDetachment:
    """The detachment force of a flat-ended cylinder on a layer (J.13), Kendall's problem at any ``a/H``.

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)``, ``FrictionlessLayer()``, ``IncompressibleLayer()`` or ``HalfSpace()``.
    radius : float
        Punch radius ``a``.
    H : float, optional
        Thickness (omitted for the half-space); ``a/H <= 190`` (the energy route's stencil).
    mu : float
        Shear modulus.
    work_of_adhesion : float
        ``w >= 0``.
    nu : float, optional
        Poisson ratio for layers that fix none.

    Returns
    -------
    FlatDetachment

    Examples
    --------
    >>> from thinlayer import HalfSpace
    >>> res = flat_punch_detachment(HalfSpace(), 1.0, work_of_adhesion=0.1, nu=0.0)
    >>> round(res.force / math.sqrt(8 * math.pi * 2.0 * 0.1), 12)
    1.0
    """
    layer, H_val, mu_val, nu_val = _material(layer, H, mu, nu)
    a = positive(radius, "radius")
    wv = check_work(work_of_adhesion)
    vt = mu_val / (1.0 - nu_val)
    kappa, f1sq, dg, kerr = flat_release_rate_factor(layer, a / H_val if H_val is not None else 1.0)
    d = -math.sqrt(math.pi * a * wv / vt / f1sq)
    err = kerr + 0.5 * abs(dg - f1sq) / f1sq
    return FlatDetachment(layer, a, H_val if H_val is not None else math.nan, mu_val, nu_val, vt, wv, kappa,
                          math.sqrt(f1sq), d, -4.0 * vt * a * kappa * d, err)
