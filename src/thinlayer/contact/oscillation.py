r"""Small oscillations around an indentation depth (issue 27 item 2): the layer's dynamic stiffness, microrheology.

A depth history ``delta(t) = delta0 + eps sin(w t)`` around a held depth ``delta0``.  Lee-Radok's law (see
:mod:`thinlayer.contact.hereditary`), ``P(t) = 1/(2(1 + nu)) int E(t - s) d/ds F(delta(s)) ds`` with ``F`` the
layer's elastic force at unit shear modulus, linearised in ``eps`` (:func:`oscillation_law` does it in sympy):

.. math::  F(\delta_0 + \varepsilon\sin\omega s) = F(\delta_0) + S(\delta_0)\,\varepsilon\sin\omega s
           + O(\varepsilon^2), \qquad S(\delta_0) = F'(\delta_0),

and, once the transients have died out (steady state),

.. math::  P(t) - P_\mathrm{hold}(t) = \frac{S(\delta_0)}{2(1+\nu)}\,\varepsilon\,
           \operatorname{Im}\!\big[E^*(\omega)\,e^{i\omega t}\big] + O(\varepsilon^2),\qquad
           E^*(\omega) = i\omega\int_0^\infty E(u)\,e^{-i\omega u}\,du .

So the force oscillates with amplitude ``|K*| eps`` and leads the depth by the loss angle ``arg E*(w)``, where
``K*(w) = E*(w) S(delta0)/(2(1 + nu))`` is the dynamic stiffness.  The bottom-effect correction for
microrheology follows: ``E*(w) = 2(1 + nu) K*(w)/S(delta0)`` with the **layer's** ``S`` at that depth (any
thickness, any tip with a law), instead of the half-space's (Hertz: ``S = 4 sqrt(R delta0)/(1 - nu)`` at unit
shear modulus, which overestimates ``|E*|`` on a thin sample by ``S_layer/S_half-space``).

Conditions (stated on every result):

* ``eps << delta0``: the neglected terms are of relative order ``eps/delta0`` (a second harmonic and a shift of the
  mean force) and ``(eps/delta0)^2`` in the first harmonic; :data:`MAX_RELATIVE_AMPLITUDE` bounds what is returned
  unflagged;
* the contact radius oscillates too, by ``c'(delta0) eps`` (given on the result), so that the contact shrinks in
  half of every cycle where Lee-Radok is not exact (Ting's construction is).  To first order in ``eps`` the contact
  set may be frozen at ``c(delta0)``: a smooth punch's pressure vanishes at its edge, so the strip the edge sweeps
  carries a force of higher order, and ``S(delta0)`` equals the stiffness of a flat punch of the same contact (the
  identity ``dP/d delta = `` flat-punch stiffness of the current contact), for which the fixed-contact response
  above is exact.

Measured against the direct time-stepping solver (:func:`thinlayer.numerics.viscoelastic.solve_history`, which
moves the contact edge itself): sphere ``R = 10`` on a bonded incompressible layer ``H = 1`` (``c/H = 1.64``), SLS
``E0 = 3, E_inf = 1, tau = 0.1``, ``delta0 = 0.13``, ``w = 10``, first harmonic of the last of 3 periods after a
hold of ``10 tau`` (120 nodes, 100 steps per period; in brackets 200 nodes, 200 steps)::

    eps/delta0        0.001    0.005    0.02             0.05
    |K|/|K*| - 1     -0.34 %  -0.46 %  -1.34 % (-1.31 %)  -3.2 %
    phase - arg K*   -0.0024  -0.0028  -0.0055 (-0.0050)  -0.0126

A floor of ~0.3 % (the solver's time step; its phase error) and a part **linear** in ``eps/delta0``, about
``0.55 eps/delta0``: the moving contact edge costs the linear response a first-order relative error, not
``(eps/delta0)^2``.  Over the acceptance grid (tests/viscoelastic/test_visco_acceptance.py: sphere and cone 70 on
bonded nu = 1/2, 0.3 and frictionless layers, ``a/H`` from 0.1 to 10, ``eps/delta0 = 0.01``, ``w tau = 1``; the solver
refined by doubling steps and nodes, Richardson's value) the error of ``K*`` is 0.66 to 2.1 times the relative edge
motion ``|c'(delta0)| eps/c`` (largest on the thin bonded incompressible layer), and 3.5e-7 for the flat punch, whose
contact does not move (the linear response is exact there).  The result's ``estimate`` is
``EDGE_FACTOR |c'(delta0)| eps/c`` (:data:`EDGE_FACTOR` = 3) plus the stiffness's estimate.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from .._checks import InputError, positive
from ..asymptotics.solution import DEFAULT_TOL
from ..display import RichDisplay
from ..errors import boundary
from ..layers.kernels import LayerKernel
from .hereditary import check_setting, force_curve_for
from .materials import Material

__all__ = ["MAX_RELATIVE_AMPLITUDE", "ContactStiffness", "Oscillation", "OscillationLaw", "contact_stiffness",
           "oscillation", "oscillation_law"]

#: the estimate's factor on the relative edge motion ``|c'(delta0)| eps/c`` (measured at most 2.1: module docstring)
EDGE_FACTOR = 3.0
#: amplitudes ``eps/delta0`` above this are flagged (the linear response's neglected terms are of order eps/delta0)
MAX_RELATIVE_AMPLITUDE = 0.05


# =============================================================================================
# the derivation (sympy)
# =============================================================================================
@dataclass(frozen=True, eq=False)
class OscillationLaw(RichDisplay):
    r"""The linearised Lee-Radok law of a small oscillation, derived in sympy (module docstring).

    Attributes
    ----------
    linear_rate : sympy.Expr
        ``d/ds F(delta(s))`` to first order in ``eps``: ``S eps w cos(w s)``.
    branch_response : sympy.Expr
        ``int_0^inf E_1 exp(-u/tau) eps w cos(w (t - u)) du`` (one Prony branch, steady state), integrated by sympy.
    branch_modulus : sympy.Expr
        The branch's complex modulus read off it: ``E_1 i w tau/(1 + i w tau)``.
    sls_modulus : sympy.Expr
        The standard linear solid's ``E*(w) = E_inf + (E0 - E_inf) i w tau/(1 + i w tau)``.
    thin_sphere : sympy.Expr
        The dynamic stiffness ``K*`` of the sphere on a thin bonded compressible layer at leading order (1.8):
        ``E*(w) S0(delta0)/(2(1 + nu))``, ``S0 = dP0/d delta0``.
    thin_sphere_incompressible : sympy.Expr
        The same for ``nu = 1/2`` from (I.10)-(I.11).
    """

    symbols: dict
    linear_rate: Any
    branch_response: Any
    branch_modulus: Any
    sls_modulus: Any
    thin_sphere: Any
    thin_sphere_incompressible: Any

    equation = "Lee-Radok linearised; (1.8), (I.11)"

    def latex(self) -> str:
        import sympy as sp

        y = self.symbols
        return (r"K^*(\omega) = \frac{E^*(\omega)\,S(\delta_0)}{2(1+\nu)},\quad "
                + sp.latex(sp.Symbol("K^*_{thin}")) + " = " + sp.latex(self.thin_sphere) + r",\quad "
                + sp.latex(sp.Symbol(r"K^*_{thin}(\nu = 1/2)")) + " = "
                + sp.latex(self.thin_sphere_incompressible)
                + rf",\quad E^*_{{SLS}}({sp.latex(y['omega'])}) = " + sp.latex(self.sls_modulus))

    def text_lines(self) -> list[str]:
        return ["OscillationLaw: delta = delta0 + eps sin(w t), eps << delta0 (Lee-Radok linearised)",
                f"  dF/ds  = {self.linear_rate}",
                "  K*     = E*(w) S(delta0)/(2(1 + nu))",
                f"  K*_thin (bonded, (1.8))     = {self.thin_sphere}",
                f"  K*_thin (nu = 1/2, (I.11)) = {self.thin_sphere_incompressible}"]

    def __str__(self) -> str:
        return "\n".join(self.text_lines())


@lru_cache(maxsize=1)
def oscillation_law() -> OscillationLaw:
    r"""Linearise Lee-Radok for ``delta = delta0 + eps sin(w t)`` and give the thin-layer sphere's ``K*``.

    Steps (sympy): expand ``d/ds F(delta0 + eps sin w s)`` to first order in ``eps``; integrate one Prony branch
    ``E_1 exp(-u/tau)`` against it over the past (``u = t - s`` from 0 to infinity, the steady state); read off the
    branch's complex modulus as ``(I cos w t + R sin w t)`` coefficients of ``eps S (Re E* sin w t + Im E* cos w t)``;
    differentiate the leading thin-layer force of the paraboloid (1.8) and the incompressible one (I.10)-(I.11).

    >>> law = oscillation_law()
    >>> print(law.thin_sphere)
    2*pi*E^*(omega)*R*delta_0*(nu - 1)/(H*(nu + 1)*(2*nu - 1))
    >>> print(law.thin_sphere_incompressible)
    2*pi*E^*(omega)*R**2*delta_0**2/H**3
    """
    import sympy as sp

    from ..asymptotics.force_law import force_law
    from ..asymptotics.incompressible import two_term_sphere
    from ..layers.kernels import BondedLayer, IncompressibleLayer
    from ..punch import Punch

    t, s, u, w, eps, tau, E1, Einf, E0 = sp.symbols("t s u omega epsilon tau E_1 E_inf E_0", positive=True)
    t = sp.Symbol("t", real=True)
    d0 = sp.Symbol("delta_0", positive=True)
    S = sp.Symbol("S", positive=True)
    F = sp.Function("F")
    rate = sp.diff(F(d0 + eps * sp.sin(w * s)), s)
    linear = sp.diff(rate, eps).subs(eps, 0) * eps  # first order in eps: F'(delta0) eps w cos(w s)
    linear = linear.replace(lambda e: isinstance(e, (sp.Subs, sp.Derivative)), lambda e: S)
    # one branch over the past, s = t - u: int_0^inf E_1 exp(-u/tau) S eps w cos(w (t - u)) du
    #   = eps S Re[Z exp(i w t)],  Z = E_1 w int_0^inf exp(-b u) du,  b = 1/tau + i w  (Re b > 0: sympy integrates
    #   for b > 0 and the result continues analytically)
    bb = sp.Symbol("b", positive=True)
    anti = sp.integrate(sp.exp(-bb * u), u)  # the antiderivative (risch), then its limits
    Z = E1 * w * (sp.limit(anti, u, sp.oo) - anti.subs(u, 0)).subs(bb, 1 / tau + sp.I * w)
    resp = sp.expand(sp.expand_complex(eps * S * sp.re(Z * sp.exp(sp.I * w * t))))
    # eps S Im[E* exp(i w t)] = eps S (Re E* sin w t + Im E* cos w t): read E* off the response
    a = sp.cancel(resp.coeff(sp.sin(w * t)) / (eps * S))
    b = sp.cancel(resp.coeff(sp.cos(w * t)) / (eps * S))
    modulus = sp.cancel(a + sp.I * b)
    sls = sp.cancel(Einf + modulus.subs(E1, E0 - Einf))
    # the thin layer: P0 = mu f(delta0), mu = E/(2(1 + nu)); K* = E* f'(delta0)/(2(1 + nu))
    P0 = force_law(BondedLayer(), Punch.paraboloid()).P0
    sym = {x.name: x for x in P0.free_symbols}
    Estar = sp.Symbol("E^*(omega)")
    thin = sp.factor(sp.diff(P0, sym["delta_0"]).subs(sym["mu"], Estar / (2 * (1 + sym["nu"]))))
    thin_inc = _incompressible_stiffness(two_term_sphere(IncompressibleLayer()), Estar)
    return OscillationLaw({"t": t, "omega": w, "epsilon": eps, "tau": tau, "S": S, "E*": Estar, "E_1": E1,
                           "E_0": E0, "E_inf": Einf, **sym}, linear, resp, modulus, sls, thin, thin_inc)


def _incompressible_stiffness(sph: Any, Estar: Any) -> Any:
    """``E* S0/(2(1 + nu))`` at ``nu = 1/2`` from the sphere's ``P(c)``, ``delta0(c)`` (I.10)-(I.11)."""
    import sympy as sp

    P_c, d_c = sph.force_of_c, sph.delta0_of_c
    c = next(x for x in d_c.free_symbols if x.name == "c")
    free = {x.name: x for x in (P_c.free_symbols | d_c.free_symbols)}
    d0 = sp.Symbol("delta_0", positive=True)
    sol = [r for r in sp.solve(sp.Eq(d_c, d0), c) if r.is_positive is not False]
    P_d = P_c.subs(c, sol[0])
    return sp.factor(sp.diff(P_d, d0).subs(free["mu"], Estar / 3))  # 2(1 + nu) = 3


# =============================================================================================
# the numbers
# =============================================================================================
def _slope(curve: Any, d0: float) -> tuple[float, float, float, float, float]:
    """``(F, S = dF/d delta, c, dc/d delta, kink)`` at ``d0``: a fourth-order central difference of the law's own
    force (step ``1e-3 d0``: truncation ~1e-12, rounding ~1e-13 relative for a smooth law), so that ``S`` is the slope
    of the very force the hereditary integral uses.  ``kink`` is the relative difference of the second-order one-sided
    slopes (left and right, ~1e-6 for a smooth law): a law pieced together from branches can have a slope that
    jumps where they meet (the any-thickness law at chi = 1: 1e-4), and ``S`` is then known to that size only.
    """
    h = 1e-3 * d0
    x = d0 + h * np.array([-2.0, -1.0, 0.0, 1.0, 2.0])
    f = curve.force(x)
    F = float(f[2])
    c = float(curve.contact_radius(x[2:3])[0])
    S = float((f[0] - 8.0 * f[1] + 8.0 * f[3] - f[4]) / (12.0 * h))
    left = (3.0 * f[2] - 4.0 * f[1] + f[0]) / (2.0 * h)
    right = (-3.0 * f[2] + 4.0 * f[3] - f[4]) / (2.0 * h)
    rad = curve.contact_radius(x)
    dc = float((rad[0] - 8.0 * rad[1] + 8.0 * rad[3] - rad[4]) / (12.0 * h)) if np.all(np.isfinite(rad)) else math.nan
    return F, S, c, dc, float(abs(right - left) / abs(S))


def _half_space_stiffness(tip: Any, nu: float, c: float, d0: float) -> float:
    """The half-space's ``dP/d delta`` at unit shear modulus: ``4 a/(1 - nu)`` for the contact radius ``a`` of the
    half-space (Hertz ``a = sqrt(R delta0)``, the flat punch its radius); NaN for other tips.
    """
    if getattr(tip, "fixed_contact", False):
        return 4.0 * float(tip.radius) / (1.0 - nu)
    R = getattr(tip, "sphere_radius", None)
    if R is None:
        return math.nan
    return 4.0 * math.sqrt(float(R) * d0) / (1.0 - nu)


@dataclass(frozen=True, eq=False)
class ContactStiffness(RichDisplay):
    r"""The layer's contact stiffness ``S = dF/d delta`` at a depth, at unit shear modulus (any thickness).

    Attributes
    ----------
    delta0, H, nu : float
    stiffness : float
        ``S(delta0)`` at ``mu = 1`` (multiply by ``mu``, or by ``E/(2(1 + nu))``).
    half_space_stiffness : float
        The half-space's (Hertz for the sphere, ``4 a/(1 - nu)`` for the flat punch; NaN for other tips).
    force : float
        ``F(delta0)`` at ``mu = 1``.
    contact_radius, radius_slope : float
        ``c(delta0)`` and ``dc/d delta`` (0 for a flat punch).
    model : str
        The elastic law's model.
    estimate : float
        The relative error estimate of ``S``: the law's estimate at ``delta0`` plus twice the jump of its one-sided
        slopes there (a law pieced from branches, e.g. the any-thickness law at ``chi = 1``: measured against the
        flat-punch identity, the central slope there is off by up to 1.5 times the jump).
    """

    delta0: float
    H: float
    nu: float
    stiffness: float
    half_space_stiffness: float
    force: float
    contact_radius: float
    radius_slope: float
    model: str
    estimate: float

    equation = "S = dP/d delta (Lee-Radok linearised)"

    @property
    def bottom_effect(self) -> float:
        """``S_layer/S_half-space``: the factor by which a half-space reading overestimates ``|E*|``."""
        return self.stiffness / self.half_space_stiffness

    def complex_modulus(self, dynamic_stiffness: Any) -> np.ndarray:
        r"""Young's ``E*(w) = 2(1 + nu) K*(w)/S(delta0)`` from a measured ``K* = (Delta P/Delta delta)(w)``."""
        k = _complex_array(dynamic_stiffness, "dynamic_stiffness")
        return 2.0 * (1.0 + self.nu) * k / self.stiffness

    def half_space_complex_modulus(self, dynamic_stiffness: Any) -> np.ndarray:
        """What the half-space's stiffness would read from the same ``K*`` (uncorrected, for comparison)."""
        k = _complex_array(dynamic_stiffness, "dynamic_stiffness")
        if not math.isfinite(self.half_space_stiffness):
            raise InputError("the half-space stiffness is known for the paraboloid and the flat punch only")
        return 2.0 * (1.0 + self.nu) * k / self.half_space_stiffness

    def latex(self) -> str:
        return (rf"S(\delta_0 = {self.delta0:.6g}) = {self.stiffness:.8g}\,\mu,\quad "
                rf"S_{{\text{{half-space}}}} = {self.half_space_stiffness:.8g}\,\mu\ \text{{({self.model})}}")

    def text_lines(self) -> list[str]:
        return [f"ContactStiffness ({self.model} law, nu = {self.nu:.4g}, H = {self.H:.6g}) at delta0 = "
                f"{self.delta0:.6g}",
                f"  S = dP/d delta = {self.stiffness:.8g} mu  (half-space {self.half_space_stiffness:.8g} mu, ratio "
                f"{self.bottom_effect:.6g})",
                f"  contact radius c = {self.contact_radius:.8g}, dc/d delta = {self.radius_slope:.6g}",
                f"  relative error estimate of S {self.estimate:.2g}"]

    def __str__(self) -> str:
        return "\n".join(self.text_lines())


def _complex_array(x: Any, name: str) -> np.ndarray:
    try:
        a = np.asarray(x, dtype=complex)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a (complex) number or an array of them, got {x!r}") from None
    if not np.all(np.isfinite(a)):
        raise InputError(f"{name} must be finite (no nan or inf)")
    return a


@boundary
def contact_stiffness(layer: LayerKernel, punch: Any, H: Any, delta0: Any, *, nu: Any = None,
                      tol: float = DEFAULT_TOL, model: str = "auto") -> ContactStiffness:
    r"""The layer's stiffness ``S(delta0) = dF/d delta`` at unit shear modulus: the bottom-effect correction.

    ``E*(w) = 2(1 + nu) K*(w)/S(delta0)`` recovers the complex modulus from a measured dynamic stiffness
    (:meth:`ContactStiffness.complex_modulus`).

    >>> from thinlayer import BondedLayer, Punch
    >>> cs = contact_stiffness(BondedLayer(0.5), Punch.paraboloid(10.0), 1.0, 0.1)
    >>> cs.model, round(cs.bottom_effect, 2)         # the layer is 7.8 times stiffer than the half-space
    ('any-thickness', 7.78)
    """
    from .materials import Prony

    layer, tip, nu_v, HH = check_setting(layer, punch, H, Prony(1.0), nu, tol, model)
    d0 = positive(delta0, "delta0")
    curve = force_curve_for(layer, tip, HH, nu_v, float(tol), np.array([d0]), model)
    if not bool(curve.valid(np.array([d0]))[0]):
        raise InputError(f"the {curve.model} law has no answer within tol = {tol:.3g} at delta0 = {d0:.6g} "
                         f"(H = {HH:.6g}); raise tol or choose another depth")
    F, S, c, dc, kink = _slope(curve, d0)
    return ContactStiffness(d0, HH, nu_v, S, _half_space_stiffness(tip, nu_v, c, d0), F, c, dc, curve.model,
                            float(curve.estimate(np.array([d0]))[0]) + 2.0 * kink)


@dataclass(frozen=True, eq=False)
class Oscillation(RichDisplay):
    r"""The steady response to ``delta0 + eps sin(w t)``: ``P(t) = P_hold(t) + |K*| eps sin(w t + phase)``.

    Attributes
    ----------
    omega : numpy.ndarray
        Angular frequencies (read-only).
    dynamic_stiffness : numpy.ndarray
        ``K*(w) = E*(w) S(delta0)/(2(1 + nu))`` (complex, read-only).
    force_amplitude, phase : numpy.ndarray
        ``|K*| eps`` and ``arg K* = arg E*`` (the loss angle: the force leads the depth).
    radius_amplitude : float
        The contact radius's oscillation ``|c'(delta0)| eps``.
    stiffness : ContactStiffness
        The layer's ``S(delta0)``.
    material : Material
    amplitude : float
        ``eps``.
    valid : bool
        ``eps/delta0 <= MAX_RELATIVE_AMPLITUDE``; ``reason`` the conditions in one line.
    estimate : float
        Relative error estimate of ``K*``: ``EDGE_FACTOR |c'(delta0)| eps/c`` (the moving contact edge, measured
        against the direct solver over the acceptance grid: module docstring) plus the stiffness's estimate.
    """

    omega: np.ndarray
    dynamic_stiffness: np.ndarray
    force_amplitude: np.ndarray
    phase: np.ndarray
    radius_amplitude: float
    stiffness: ContactStiffness
    material: Material
    amplitude: float
    valid: bool
    reason: str
    estimate: float = math.nan

    equation = "K* = E* S/(2(1 + nu))"

    def latex(self) -> str:
        return (r"P(t) = P_\mathrm{hold}(t) + \varepsilon\,\operatorname{Im}\!\big[K^*(\omega)e^{i\omega t}\big],\ "
                r"K^*(\omega) = \frac{E^*(\omega)\,S(\delta_0)}{2(1+\nu)},\ "
                + rf"S = {self.stiffness.stiffness:.8g},\ " + self.material.latex())

    def text_lines(self) -> list[str]:
        out = [f"Oscillation around delta0 = {self.stiffness.delta0:.6g}, eps = {self.amplitude:.3g} "
               f"({self.stiffness.model} law, S = {self.stiffness.stiffness:.8g} mu)"
               + ("" if self.valid else "  NOT VALID"),
               "  omega          |K*|            phase (rad)"]
        out += [f"  {w:<14.6g} {abs(k):<15.8g} {p:.6g}" for w, k, p in zip(self.omega, self.dynamic_stiffness,
                                                                         self.phase)]
        out.append(f"  contact radius oscillates by ±{self.radius_amplitude:.3g}; {self.reason}")
        return out

    def __str__(self) -> str:
        return "\n".join(self.text_lines())

    def as_dict(self) -> dict:
        """Plain numbers for JSON."""
        return {"delta0": self.stiffness.delta0, "amplitude": self.amplitude, "H": self.stiffness.H,
                "nu": self.stiffness.nu, "model": self.stiffness.model, "stiffness": self.stiffness.stiffness,
                "half_space_stiffness": self.stiffness.half_space_stiffness, "omega": self.omega.tolist(),
                "dynamic_stiffness_real": self.dynamic_stiffness.real.tolist(),
                "dynamic_stiffness_imag": self.dynamic_stiffness.imag.tolist(),
                "force_amplitude": self.force_amplitude.tolist(), "phase": self.phase.tolist(),
                "radius_amplitude": self.radius_amplitude, "valid": self.valid, "estimate": self.estimate,
                "reason": self.reason}


@boundary
def oscillation(layer: LayerKernel, punch: Any, H: Any, material: Material, delta0: Any, omega: Any,
                amplitude: Any, *, nu: Any = None, tol: float = DEFAULT_TOL, model: str = "auto") -> Oscillation:
    r"""Force amplitude and phase of a small oscillation ``delta0 + eps sin(w t)`` on the layer (module docstring).

    Parameters
    ----------
    layer, punch, H, nu, tol, model
        As :func:`thinlayer.contact.hereditary.viscoelastic_force`.
    material : Material
        ``E(t)``; its :meth:`~thinlayer.contact.materials.Material.complex_modulus` gives ``E*(w)``.
    delta0 : float
        The held depth.
    omega : float or array_like
        Angular frequencies ``w >= 0``.
    amplitude : float
        ``eps > 0``; flagged (``valid=False``) above ``MAX_RELATIVE_AMPLITUDE delta0``.

    Examples
    --------
    >>> from thinlayer import BondedLayer, Punch, StandardLinearSolid
    >>> osc = oscillation(BondedLayer(0.5), Punch.paraboloid(10.0), 1.0, StandardLinearSolid(3.0, 1.0, 0.1),
    ...                   0.1, [1.0, 10.0], 1e-3)
    >>> osc.valid, [round(float(p), 4) for p in osc.phase]
    (True, [0.1918, 0.4636])
    """
    try:
        raw = np.asarray(omega)
        if raw.dtype.kind not in "iuf":
            raise TypeError
        w = np.array(raw, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InputError(f"omega must be a number or an array of numbers >= 0, got {omega!r}") from None
    if w.size == 0 or not np.all(np.isfinite(w)) or np.any(w < 0):
        raise InputError("omega must hold finite angular frequencies >= 0")
    eps = positive(amplitude, "amplitude")
    if not isinstance(material, Material):
        raise InputError(f"material must be Prony(...), StandardLinearSolid(...), KelvinVoigt(...) or PowerLaw(...), "
                         f"got {material!r}")
    st = contact_stiffness(layer, punch, H, delta0, nu=nu, tol=tol, model=model)  # the inputs checked first
    k = material.complex_modulus(w) * st.stiffness / (2.0 * (1.0 + st.nu))
    ratio = eps / st.delta0
    valid = ratio <= MAX_RELATIVE_AMPLITUDE
    estimate = EDGE_FACTOR * abs(st.radius_slope) * eps / st.contact_radius + st.estimate
    reason = (f"Lee-Radok linearised in eps/delta0 = {ratio:.3g} "
              + ("(<= " if valid else "(NOT VALID: > ") + f"{MAX_RELATIVE_AMPLITUDE:g}); the contact radius "
              "oscillates, frozen at c(delta0) to first order; the moving edge costs K* up to ~2 |c'| eps/c against "
              f"the direct solver (the acceptance grid): estimate {estimate:.2g}")
    amp = np.abs(k) * eps
    ph = np.angle(k)
    for a in (w, k, amp, ph):
        a.setflags(write=False)
    return Oscillation(w, k, amp, ph, abs(st.radius_slope) * eps, st, material, eps, bool(valid), reason,
                       float(estimate))
