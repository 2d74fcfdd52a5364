"""Direct numerical solution of the axisymmetric unilateral contact problem (1.5)-(1.8).

This module is the *independent* route that validates the asymptotic expansions: it never
uses ``A``, ``m_n`` or any thin-layer series; it only evaluates the kernel L(u) (2.3).

The punch is a :class:`~thinlayer.punch.Punch` (or a polynomial in ``x1, x2``) whose ``Phi`` depends on
``x1^2 + x2^2`` only -- checked exactly, ``x1 dPhi/dx2 - x2 dPhi/dx1 = 0`` -- or directly its radial
profile ``Phi(r)`` (a numpy callable or a sympy expression in one symbol).

Formulation
-----------
For an axisymmetric pressure p(r) on the disc r < c, the two-dimensional Fourier integral
(2.1) reduces, with ``p_hat(alpha) = 2 pi pbar(alpha)`` and the angular integral
``int_0^{2 pi} exp(i alpha r cos t) dt = 2 pi J0(alpha r)``, to the Hankel form::

    u3(r) = (1/vartheta) int_0^oo pbar(a) L(a H) J0(a r) da,
    pbar(a) = int_0^c p(rho) J0(a rho) rho d rho,       vartheta = mu / (1 - nu).

(Check: for L = 1 this is Boussinesq's ``w = (1-nu)/(2 pi mu) iint p(y)/|x-y| dy``, because
``int_0^oo J0(a r) J0(a rho) da`` is the ring average of ``1/(2 pi |x-y|)``.)  Note that the
printed (2.1) carries a leading minus sign; with the sign convention of (1.5) (u3 >= delta0 - Phi,
p >= 0) the kernel must be positive, as (2.6) has it.

Discretisation (spectral Galerkin in the flat-punch basis)
----------------------------------------------------------
With x = r/c and y = 1 - 2 x^2 the pressure is expanded as::

    p(r) = sum_n x_n psi_n(x),     psi_n(x) = (1 - x^2)^{-1/2} P_n^{(0,-1/2)}(1 - 2 x^2),

whose Hankel transforms are (a Bateman-type Jacobi/Bessel integral; checked against mpmath
quadrature in the tests)::

    int_0^1 psi_n(x) J0(b x) x dx = beta_n j_{2n}(b),     beta_n = Gamma(n+1/2) / (sqrt(pi) n!),

j_k the spherical Bessel function.  Galerkin projection of u3 = delta0 - Phi on psi_m gives::

    (c/vartheta) sum_n K_mn x_n = F_m,   K_mn = int_0^oo beta_m beta_n j_2m(t) j_2n(t) L(t H/c) dt,
    F_m = int_0^1 psi_m(x) (delta0 - Phi(c x)) x dx.

Splitting ``L = 1 + (L - 1)``: the half-space part is diagonal by the Weber-Schafheitlin
integral ``int_0^oo j_2m j_2n dt = pi delta_mn / (2(4n+1))`` (the flat-punch / Popov
diagonalisation); the correction ``L(u) - 1 = O(u^2 e^{-2u})`` is smooth and exponentially
decaying and is integrated by composite Gauss-Legendre quadrature on [0, 22 c/H].

The basis represents both the bounded edge behaviour ``p ~ (c - r)^{1/2}`` and the flat-punch
singularity ``p ~ (c - r)^{-1/2}``, whose coefficient is ``S = sum_n x_n P_n^{(0,-1/2)}(-1)``.
The unknown contact radius is fixed by the condition that the pressure vanishes continuously
at the edge (smooth punch, complementarity (1.5)): S = 0.  Because the solution is linear in
delta0 at fixed c, ``delta0(c) = S[Phi] / S[1]`` in closed form; for a prescribed delta0 the
radius follows by a bracketing root search (Brent) on this monotone function.  As the kernel's
correction is analytic, the pressure is ``(1 - x^2)^{1/2}`` times a smooth function and the
method converges spectrally; the boundary layer of width ~H at the edge needs about
``8 sqrt(c/H)`` modes.  The error estimate is the change against a run with ~0.7 times as
many modes (an over-estimate of the error of the finer run).  For a tip of revolution (cone, blunted cone, power law,
exact sphere) the error falls like ``exp(-4 n H/c)`` (the layer's coupling of mode n), so a run at 0.7 N over-states
it by ``exp(1.2 N H/c)`` (>= 100x at the default modes); its estimate extrapolates three runs ``N, N - k, N - 2k``,
``k ~ 0.4 c/H``, with the rate they show (``_geometric_error``), and is never below the rounding floor 5e-13.
The discretisation itself lives in the private module ``thinlayer.numerics._spectral``.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import InputError, InputTypeError, check_bounded, positive
from .._lazy import lazy_module
from ..display import RichDisplay, fmt
from ..errors import boundary, boundary_methods
from ..layers.kernels import LayerKernel
from ..punch import Punch, PunchError, Tip, is_polynomial_tip
from ._layer import GAUSS, U_MAX, numeric_layer_nu, panel_count
from ._spectral import Discretisation, RadialLoad, correction_displacement, pressure_function, sample_radii

integrate, optimize, special = (lazy_module(f"scipy.{m}") for m in ("integrate", "optimize", "special"))  # on first use

__all__ = ["AxisymmetricContact", "AxisymmetricPunchContact", "contact_for_radius", "radial_profile",
           "solve_axisymmetric", "surface_displacement"]

_MAX_MODES = 600

#: the radius symbol of the radial profile Phi(r)
r = sp.Symbol("r", nonnegative=True)


#: the largest H/c the solver takes: the layer correction is below double precision long before (it solves
#: H/c = 1e100 to rounding; its Bessel recurrences overflow from H/c ~ 1e150)
MAX_H_OVER_C = 1e100


# --------------------------------------------------------------------------- result

@boundary_methods
@dataclass(frozen=True)
class AxisymmetricContact(RichDisplay):
    """Direct numerical solution of the axisymmetric unilateral contact problem (1.5)-(1.8).

    Attributes
    ----------
    layer : LayerKernel
        Layer model (kernel (2.3)).
    nu, mu, vartheta, H : float
        float
        Poisson ratio, shear modulus, ``vartheta = mu/(1-nu)`` (2.1), thickness.
    delta0 : float
        Indentation depth (1.5).
    radius : float
        Contact radius c (the pressure vanishes continuously at r = c).
    force : float
        Total force P = 2 pi int_0^c p r dr (1.8).
    r, pressure : numpy.ndarray
        numpy.ndarray
        Sample radii on [0, c] (clustered at the edge) and p(r) there (read-only arrays).
    modes : int
        Number of Galerkin modes.
    radius_error, force_error, delta0_error : float
        float
        Convergence estimates (absolute for radius and delta0, relative for force; zero for the prescribed
        quantity): for a polynomial punch the change against a run with ~0.7x the modes; for a tip of revolution
        the geometric extrapolation of three runs ``N, N - k, N - 2k`` (``_geometric_error``), never below the
        rounding floor :data:`ROUNDING_FLOOR` (relative).
    coefficients : tuple of float
        Coefficients of p in the normalised flat-punch basis (``vartheta/c`` included).
    punch : Punch or None
        The punch, when one was given (None for a bare radial profile ``Phi(r)``).
    """

    layer: LayerKernel
    nu: float
    mu: float
    vartheta: float
    H: float
    delta0: float
    radius: float
    force: float
    r: np.ndarray = field(repr=False)
    pressure: np.ndarray = field(repr=False)
    modes: int
    radius_error: float
    force_error: float
    delta0_error: float
    coefficients: tuple[float, ...] = field(repr=False)
    punch: Tip | None = None

    @property
    def equation(self) -> str:
        return "1.5-1.8"

    @property
    def contact_radius(self) -> float:
        """Contact radius c (= ``radius``; the name shared with :class:`~thinlayer.numerics.Contact2D`)."""
        return self.radius

    @property
    def contact_area(self) -> float:
        """Area of the contact disc, ``pi c^2``."""
        return math.pi * self.radius**2

    def pressure_at(self, r: Any) -> np.ndarray:
        """Contact pressure p(r) (zero outside the contact disc), accurate up to the edge."""
        return pressure_function(np.asarray(self.coefficients), self.radius)(r)

    def latex(self) -> str:
        """One-line LaTeX summary of the solution with its convergence estimates."""
        return (rf"c = {self.radius:.10g}\,(\pm {self.radius_error:.1e}),\quad "
                rf"P = {self.force:.10g}\,(\pm {self.force_error:.1e}\,P),\quad "
                rf"\delta_0 = {self.delta0:.10g},\quad H = {self.H:g},\quad \nu = {self.nu:g}")

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        what = f" of {self.punch.name} Φ = {fmt(self.punch.expr)}" if self.punch is not None else ""
        layer = str(self.layer) if "nu=" in str(self.layer) else f"{self.layer}, ν = {self.nu:.6g}"
        return [
            f"{type(self).__name__}: direct numerical solution{what}   (1.5)-(1.8)",
            f"  {layer}, μ = {self.mu:.6g}, H = {self.H:.6g}, δ₀ = {self.delta0:.10g}",
            f"  contact radius c = {self.radius:.12g}  (+- {self.radius_error:.1e})",
            f"  force          P = {self.force:.12g}  (+- {self.force_error:.1e} P), {self.modes} modes",
        ]


#: former name of the result of a :class:`~thinlayer.punch.Punch` (now the same class, with ``punch`` set)
AxisymmetricPunchContact = AxisymmetricContact


# --------------------------------------------------------------------------- the punch and its profile
def _as_punch(punch: Any) -> Punch:
    if isinstance(punch, (str, sp.Basic)):
        punch = Punch(punch)
    if not is_polynomial_tip(punch):
        raise InputTypeError(f"punch must be a thinlayer Punch (or a polynomial expression in x1, x2), "
                        f"got {punch!r} ({type(punch).__name__})")
    return punch


@boundary
def radial_profile(punch: Any) -> sp.Expr:
    """The profile ``Phi(r)`` of an axisymmetric punch, as a sympy expression in :data:`r`.

    Parameters
    ----------
    punch : Punch or str
        A :class:`~thinlayer.punch.Punch` with numeric parameters (or a polynomial in ``x1, x2``).

    Returns
    -------
    sympy.Expr
        ``Phi(r, 0)``.

    Raises
    ------
    ValueError
        If the punch has free parameters (named) or is not axisymmetric.

    Examples
    --------
    >>> from thinlayer import Punch
    >>> radial_profile(Punch.fourth_degree(R=2, K=1))
    r**4 + r**2/4
    """
    punch = _as_punch(punch)
    if punch.parameters:
        names = ", ".join(str(q) for q in punch.parameters)
        raise InputError(f"the punch '{punch.name}' Phi = {punch.expr} has free parameter(s) {names}: "
                         f"substitute numbers first, e.g. punch.subs({{'{punch.parameters[0]}': 1.0}})")
    phi = punch.expr
    if not punch.axisymmetric:
        angular = sp.expand(S.x1 * sp.diff(phi, S.x2) - S.x2 * sp.diff(phi, S.x1))
        raise InputError(f"the punch '{punch.name}' Phi = {punch.expr} is not axisymmetric "
                         f"(x1 dPhi/dx2 - x2 dPhi/dx1 = {angular} is not zero): use "
                         "thinlayer.numerics.solve_2d for a general punch")
    return sp.expand(phi.xreplace({S.x1: r, S.x2: sp.Integer(0)}))


def _is_punch(shape: Any) -> bool:
    """A Punch, a string, or a sympy expression in the plane coordinates ``thinlayer.symbols.x1, x2``."""
    if isinstance(shape, str) or is_polynomial_tip(shape):
        return True
    return isinstance(shape, sp.Basic) and shape.has(S.x1, S.x2)


def _vectorised(Phi_r: Any) -> Callable[[np.ndarray], np.ndarray]:
    """Turn a numpy callable or a one-symbol sympy expression into a vectorised Phi(r)."""
    if isinstance(Phi_r, sp.Basic):
        free = sorted(Phi_r.free_symbols, key=str)
        if len(free) > 1:
            raise InputError(f"Phi_r must depend on the radius only; it has free symbols {free}: "
                             "substitute numbers for R, etc.")
        f = sp.lambdify(free[0] if free else r, Phi_r, "numpy")
    elif callable(Phi_r):
        f = Phi_r
    else:
        raise InputTypeError(f"the punch must be a thinlayer Punch (or a polynomial in x1, x2) or a radial profile "
                        f"Phi_r: a numpy-vectorised callable Phi(r) or a sympy expression in r; "
                        f"got {Phi_r!r} ({type(Phi_r).__name__})")

    def phi(rr: np.ndarray) -> np.ndarray:
        rr = np.asarray(rr, dtype=float)
        with np.errstate(over="ignore", invalid="ignore"):  # refused below, in one line
            out = np.broadcast_to(np.asarray(f(rr), dtype=float), rr.shape)
        if not np.all(np.isfinite(out)):
            raise InputError(f"Phi_r returned non-finite values on [0, {float(np.max(rr)):.3g}] (beyond the double "
                             "range): express the lengths in other units")
        return out

    return phi


def _radial_tip(shape: Any) -> bool:
    """A tip of revolution that is not a polynomial (cone, sphere, ...): the solver asks it for its profile."""
    return (isinstance(shape, Tip) and shape.polynomial is None and shape.axisymmetric
            and not shape.fixed_contact)


def _tip_load(tip: Tip) -> RadialLoad:
    """The profile of a tip of revolution with its slope, joins, apex and rim (:class:`RadialLoad`)."""
    if not tip.is_numeric:
        names = ", ".join(q.name for q in tip.parameters)
        raise InputError(f"the {tip.name} has free parameter(s) {names}: substitute numbers first (tip.subs({{...}}))")
    try:
        tip.radial_slope(np.array([0.5]))
        slope = tip.radial_slope
    except PunchError:
        slope = None
    phi = _vectorised(tip.radial_profile)
    return RadialLoad(phi, slope, tuple(float(b) for b in tip.radial_breakpoints), tip.smoothness == "apex",
                      float(tip.support_radius))


def _profile(shape: Any) -> tuple[Punch | None, Callable[[np.ndarray], np.ndarray]]:
    """``(punch or None, vectorised Phi(r))`` of an axisymmetric punch or of a radial profile; a tip of revolution
    gives a :class:`~thinlayer.numerics._spectral.RadialLoad` (graded load, edge-functional tail).
    """
    if _radial_tip(shape):
        return shape, _tip_load(shape)
    if _is_punch(shape):
        punch = _as_punch(shape)
        return punch, _vectorised(radial_profile(punch))
    return None, _vectorised(shape)


# --------------------------------------------------------------------------- input checks
def _check_modes(n: Any) -> int | None:
    if n is None:
        return None
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)):
        raise InputTypeError(f"n (number of modes) must be an integer, got {n!r}")
    if not 4 <= n <= _MAX_MODES:
        raise InputError(f"n (number of modes) must lie in [4, {_MAX_MODES}], got {n}")
    return int(n)


#: Largest work estimate ``(t-quadrature points) x modes^2`` of one Galerkin matrix (see :func:`_check_work`).
#: Measured (paraboloid, nu = 0.3, default modes, with the error estimate): c/H = 100 (9.9e7) takes 0.20 s,
#: c/H = 128 (1.9e8) 0.29 s (3.2 s and 3.4 s before the recurrences of issue 18; c/H = 300 (1.0e9) took 21.6 s
#: and c/H = 1000 (8.1e9) 212 s then, the transforms growing like the work); the limit admits c/H <= ~130
#: with the default modes (about 9 MB for the transforms array).
MAX_WORK = 2.0e8


def _check_work(layer: Any, H: float, c_lo: float, c_hi: float, modes: int, what: str) -> None:
    """Refuse, before any matrix is built, a discretisation whose work estimate exceeds :data:`MAX_WORK`.

    The t-quadrature of :class:`~thinlayer.numerics._spectral.Discretisation` has ``GAUSS`` points on each of
    ``panel_count(U_MAX c_hi/H, min(3, c_lo/(2H)))`` panels; each Galerkin matrix costs that times modes^2
    (and its transforms array that times modes x 8 bytes: 9 MB at the limit).
    """
    if not layer.has_thickness:  # the half-space: no quadrature, at most 600 modes
        return
    nt = GAUSS * panel_count(U_MAX * c_hi / H, min(3.0, 0.5 * c_lo / H))
    work = float(nt) * modes * modes
    check_bounded(work, f"the work estimate ({nt} quadrature points x {modes}^2 modes)", MAX_WORK,
                  f"the contact radius ~{c_hi:.3g} is {c_hi / H:.3g} layer thicknesses (H = {H:.3g}) {what}; the "
                  f"direct solver is limited to about c/H <= 130 with the default modes (0.3 s measured at c/H = 128): "
                  f"increase H, "
                  f"decrease the contact size (delta0 or radius) or the modes n, or use the asymptotic "
                  f"thinlayer.solve, which is accurate for such thin layers")


def _default_modes(c_over_H: float, phi: Any = None, layer: Any = None, H: float = 1.0, c: float = 1.0) -> int:
    """``ceil(8 sqrt(c/H)) + 12`` modes; for a tip of revolution (:class:`RadialLoad`) at least ``ceil(4 c/H) + 24``
    within the work limit: its load has every mode, and the layer couples mode n by ``~exp(-4 n H/c)``
    (measured: the cone at c/H = 10 changes by 4e-9 from 80 to 160 modes, 8e-6 from 40 to 80).
    """
    n = int(min(_MAX_MODES, math.ceil(8.0 * math.sqrt(max(c_over_H, 0.0))) + 12))
    if isinstance(phi, RadialLoad) and layer is not None and layer.has_thickness:
        nt = GAUSS * panel_count(U_MAX * (c + 6.0 * min(H, c)) / H, min(3.0, 0.15 * c / H))
        fit = int(math.sqrt(MAX_WORK / nt))
        n = max(n, min(_MAX_MODES, math.ceil(4.0 * c_over_H) + 24, fit))
    return n


#: relative rounding floor of a tip-of-revolution run: the scatter of converged runs (n = 60 .. 400) about each other,
#: measured up to 2.6e-13 (blunted cone, force, c/H = 10); the estimate never reads below it
ROUNDING_FLOOR = 5e-13
#: the slowest geometric rate ``exp(-RATE_MIN n H/c)`` the estimate assumes for the truncation error (the layer couples
#: mode n by ~exp(-4 n H/c); measured 3.8-4.5 for c and delta0, about twice that for P at a prescribed depth)
RATE_MIN = 3.0
#: factor on the extrapolated error (covers a ratio that is still settling between the three runs)
SAFETY = 2.0


def _coarse_modes(N: int, layer: Any, H: float, c: float) -> tuple[int, int]:
    """The two coarser runs ``N - k``, ``N - 2k`` of the estimate for a tip of revolution, ``k ~ 0.4 c/H`` (the
    error of the layer's coupling falls by ~exp(-1.6) per step: a ratio well above rounding, read from the runs).
    """
    k = max(2, math.ceil(0.4 * c / H)) if layer.has_thickness else max(2, round(0.15 * N))
    k = max(1, min(k, (N - 4) // 2))
    return N - k, N - 2 * k


def _geometric_error(v: tuple[float, float, float], rho_k: float, settled: bool) -> float:
    r"""Relative truncation error of ``v[0]`` (finest) from three runs ``N, N - k, N - 2k`` (Aitken).

    With ``e(n) ~ A rho^n``: ``d1 = |v0 - v1|``, ``d2 = |v1 - v2|``, ``q = d1/d2 ~ rho^k`` and
    ``e(N) = d1 q/(1 - q)``.  The ratio is taken no smaller than ``rho_k`` (the slowest rate assumed, :data:`RATE_MIN`),
    the result is multiplied by :data:`SAFETY` and is never below the last change ``d1``.  Where the rate has not
    settled -- fewer than ``2 c/H`` modes (a mode resolves ``~c/n``, the layer's kernel varies on ``H``; measured: the
    blunted cone's error at c/H = 10 oscillates up to 16 modes), a ratio faster than ``exp(-10 k H/c)`` (no rate
    measured exceeds 7.3), or changes that do not shrink (rounding) -- the larger change is the estimate.  Never
    below :data:`ROUNDING_FLOOR`.
    """
    scale = abs(v[0])
    d1, d2 = abs(v[0] - v[1]) / scale, abs(v[1] - v[2]) / scale
    fastest = rho_k ** (10.0 / RATE_MIN)
    if not settled or not d1 < d2 or d1 < fastest * d2:
        est = max(d1, d2)
    else:
        q = max(d1 / d2, rho_k)
        est = max(SAFETY * d1 * q / (1.0 - q), d1)
    return max(est, ROUNDING_FLOOR)


def _material(layer: Any, H: Any, mu: Any, nu: Any) -> tuple[float, float, float]:
    """Checked ``(H, mu, nu)``; H may be omitted (None) only for a layer without thickness (half-space)."""
    nu_val = numeric_layer_nu(layer, nu)
    if H is None:
        if layer.has_thickness:
            raise InputError(f"{type(layer).__name__} needs the layer thickness H > 0")
        H = 1.0  # ignored by the half-space kernel
    return positive(H, "H"), positive(mu, "mu"), nu_val


# --------------------------------------------------------------------------- result assembly
def _force(c: float, vt: float, d0: float, x1: np.ndarray, xP: np.ndarray, disc: Discretisation) -> float:
    """``P = 2 pi c^2 x~_0/sqrt(d_0)`` (1.8): only psi_0 has nonzero mean."""
    return 2 * math.pi * c * vt * (d0 * x1[0] - xP[0]) / disc.scale[0]


def _result(layer, punch, nu, mu, H, delta0, c, disc, x1, xP, d0c, errs) -> AxisymmetricContact:
    vartheta = mu / (1.0 - nu)
    coef = (vartheta / c) * (delta0 * x1 - xP) if d0c is None else (vartheta / c) * (d0c * x1 - xP)
    force = 2.0 * math.pi * c**2 * coef[0] / disc.scale[0]  # (1.8): only psi_0 has nonzero mean
    radii = sample_radii(c)
    p = pressure_function(coef, c)(radii)
    radii.setflags(write=False)
    p.setflags(write=False)
    return AxisymmetricContact(layer, nu, mu, vartheta, H, delta0, float(c), float(force), radii, p, disc.modes,
                               float(errs[0]), float(errs[1]), float(errs[2]), tuple(float(v) for v in coef),
                               punch)


# --------------------------------------------------------------------------- prescribed radius
@boundary
def contact_for_radius(layer: LayerKernel, punch: Any, radius: float, H: float | None = None, mu: float = 1.0,
                       n: int | None = None, *, nu: float | None = None,
                       error_estimate: bool = True) -> AxisymmetricContact:
    """Solve the contact problem (1.5)-(1.8) for a prescribed contact radius c: delta0 and P follow.

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` with numeric nu, ``FrictionlessLayer()``, ``HalfSpace()``, the incompressible layer.
    punch : Punch, str, sympy.Expr or callable
        An axisymmetric :class:`~thinlayer.punch.Punch` with numeric parameters (or a polynomial in
        ``x1, x2``), or its radial profile Phi(r) with Phi(0) = 0 (numpy callable or a sympy
        expression in one symbol).
    radius : float
        Contact radius c > 0.
    H : float, optional
        Layer thickness (may be omitted, and is ignored, for ``HalfSpace``).
    mu : float
        Shear modulus.
    n : int, optional
        Number of Galerkin modes (default ``ceil(8 sqrt(c/H)) + 12``).
    nu : float, optional
        Poisson ratio, only for layers that do not carry one (``HalfSpace``, ``FrictionlessLayer``).
    error_estimate : bool
        Also solve with ~0.7 n modes and record the changes.

    Returns
    -------
    AxisymmetricContact
        With ``delta0`` such that p vanishes continuously at r = c (1.5).
    """
    punch, phi = _profile(punch)
    c = positive(radius, "radius")
    H, mu, nu_val = _material(layer, H, mu, nu)
    N = _check_modes(n) or _default_modes(c / H, phi, layer, H, c)
    _check_work(layer, H, c, c, N, "(the prescribed radius)")
    radial = isinstance(phi, RadialLoad) and N >= 6
    coarse = list(_coarse_modes(N, layer, H, c)) if radial else [max(4, round(0.7 * N))]
    runs = []
    for modes in ([N, *coarse] if error_estimate else [N]):
        disc = Discretisation.build(layer, H, modes, c, c)
        runs.append((disc, *disc.solve(c, phi)))
    disc, d0, x1, xP = runs[0]
    if not d0 > 0:
        raise InputError(f"no indentation delta0 > 0 gives contact radius {c}: is Phi increasing with Phi(0) = 0?")
    vt = mu / (1.0 - nu_val)
    errs = (0.0, 0.0, 0.0)
    if error_estimate:
        P = [_force(c, vt, *run[1:], run[0]) for run in runs]
        if radial:  # a tip of revolution: geometric extrapolation from three runs
            rho_k = math.exp(-RATE_MIN * (N - coarse[0]) * H / c) if layer.has_thickness else 0.0
            settled = not layer.has_thickness or N >= 2.0 * c / H
            errs = (0.0, _geometric_error(tuple(P), rho_k, settled),
                    _geometric_error(tuple(run[1] for run in runs), rho_k, settled) * abs(d0))
        else:
            errs = (0.0, abs(P[0] - P[1]) / abs(P[0]), abs(d0 - runs[1][1]))
    return _result(layer, punch, nu_val, mu, H, d0, c, disc, x1, xP, None, errs)


# --------------------------------------------------------------------------- prescribed depth
def _intersection_radius(phi: Callable, delta0: float, scale_hint: float) -> float:
    """Radius where Phi(r) = delta0 (the rigid-body overlap), bracketed outward from scale_hint."""
    if phi(np.array([0.0]))[0] >= delta0:
        raise InputError(f"Phi(0) = {phi(np.array([0.0]))[0]} >= delta0 = {delta0}: the punch does not "
                         "touch the layer; Phi must be normalised with Phi(0) = 0 and increase with r")
    hi = min(scale_hint, 1.0)  # (from H = 1e300 the first Phi(hi) would overflow)
    rim = getattr(phi, "rim", math.inf)
    if math.isfinite(rim):  # the exact sphere: the tip ends at r = R
        if not phi(np.array([rim]))[0] > delta0:
            raise InputError(f"delta0 = {delta0:g} reaches the rim of the tip (r = {rim:g}, Phi = "
                             f"{phi(np.array([rim]))[0]:g}): no contact disc inside it")
        return optimize.brentq(lambda rr: phi(np.array([rr]))[0] - delta0, 0.0, rim, xtol=1e-14 * rim)
    for _ in range(2200):
        if phi(np.array([hi]))[0] > delta0:
            break
        hi *= 2.0
    else:
        raise InputError("Phi_r never reaches delta0: an unbounded, increasing profile (paraboloid, r^4, ...) "
                         "is needed for a finite contact disc")
    return optimize.brentq(lambda rr: phi(np.array([rr]))[0] - delta0, 0.0, hi, xtol=1e-14 * hi)


def _radius_for_depth(layer, phi, delta0, H, N, c_int):
    """Contact radius for a prescribed depth: Brent's method on delta0(c) - delta0."""
    rim = getattr(phi, "rim", math.inf)
    lo, hi = 0.3 * c_int, min(c_int + 6.0 * min(H, c_int), (1 - 1e-9) * rim)
    for _ in range(60):
        disc = Discretisation.build(layer, H, N, lo, hi)
        f_lo = disc.solve(lo, phi)[0] - delta0
        f_hi = disc.solve(hi, phi)[0] - delta0
        if f_lo < 0 < f_hi:
            break
        if f_lo >= 0:
            lo *= 0.5
        if f_hi <= 0:
            hi = min(hi * 1.5 + 2.0 * H, (1 - 1e-9) * rim)
    else:
        raise InputError("could not bracket the contact radius: is Phi convex and increasing (one contact disc)?")
    c = optimize.brentq(lambda cc: disc.solve(cc, phi)[0] - delta0, lo, hi, xtol=1e-15 * hi, rtol=1e-15,
                        maxiter=200)
    d0c, x1, xP = disc.solve(c, phi)
    return c, disc, d0c, x1, xP


@boundary
def solve_axisymmetric(layer: LayerKernel, punch: Any, delta0: float, H: float | None = None, mu: float = 1.0,
                       n: int | None = None, *, nu: float | None = None,
                       error_estimate: bool = True) -> AxisymmetricContact:
    """Direct solution of the unilateral contact problem (1.5)-(1.8) for an axisymmetric punch.

    A rigid punch ``x3 = -Phi(r)`` is pressed to depth ``delta0`` into a layer of thickness H
    on a rigid base (kernel L of the layer, (2.1), (2.3)).  The contact radius c is unknown and is
    found from the condition that the pressure vanishes continuously at the edge (see the module
    docstring for the spectral Galerkin method).  No asymptotic expansion is used.

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` (numeric nu), ``FrictionlessLayer()``, ``HalfSpace()`` or the incompressible layer.
    punch : Punch, str, sympy.Expr or callable
        An axisymmetric :class:`~thinlayer.punch.Punch` with numeric parameters (or a polynomial in
        ``x1, x2``), e.g. ``Punch.paraboloid(R=100)``; or directly the radial profile Phi(r), Phi(0) = 0,
        increasing and convex (numpy callable or sympy expression in one symbol), e.g.
        ``lambda r: r**2 / (2 * R)``.
    delta0 : float
        Indentation depth (> 0).
    H : float, optional
        Layer thickness (may be omitted, and is ignored, for ``HalfSpace``).
    mu : float
        Shear modulus.
    n : int, optional
        Number of Galerkin modes (default ``ceil(8 sqrt(c/H)) + 12``, from a first estimate of c).
    nu : float, optional
        Poisson ratio, only for layers that do not carry one (``HalfSpace``, ``FrictionlessLayer``).
    error_estimate : bool
        Also solve with ~0.7 n modes and record the changes of c and P.

    Returns
    -------
    AxisymmetricContact
        Frozen result with ``radius`` (= ``contact_radius``), ``force`` (1.8), ``r``, ``pressure``,
        ``contact_area``, error estimates, and the ``punch`` when one was given.

    Raises
    ------
    thinlayer._checks.WorkLimitError
        Before any matrix is built, when the work estimate (quadrature points x modes^2, from the rigid
        overlap radius) exceeds :data:`MAX_WORK` = 2e8: about c/H <= 130 with the default modes (0.3 s measured
        at c/H = 128); c/H = 300 took 22 s and c/H = 1000 212 s before the limit, H = 1e-6 tried to allocate 166 GiB.

    Examples
    --------
    Hertz's solution for the half-space (L = 1): c^2 = R delta0, P = 8 vartheta c^3 / (3 R).

    >>> from thinlayer import HalfSpace, Punch
    >>> res = solve_axisymmetric(HalfSpace(), lambda r: r**2 / 2, 0.01, H=1.0, nu=0.3)
    >>> round(res.radius**2 / 0.01, 10), round(res.force / (8 / 0.7 * res.radius**3 / 3), 10)
    (1.0, 1.0)
    >>> res = solve_axisymmetric(HalfSpace(), Punch.paraboloid(R=2), 0.5, nu=0.3)
    >>> round(res.contact_radius, 10), round(res.contact_area, 10)
    (1.0, 3.1415926536)
    """
    punch, phi = _profile(punch)
    delta0 = positive(delta0, "delta0")
    H, mu, nu_val = _material(layer, H, mu, nu)
    N_given = _check_modes(n)
    c_int = _intersection_radius(phi, delta0, H)
    if H is not None and H > MAX_H_OVER_C * c_int:  # its Bessel recurrences overflow from H/c ~ 1e150
        raise InputError(f"H/c = {H / c_int:.3g} exceeds {MAX_H_OVER_C:.0e}: the layer's correction to the half-space "
                         "is far below double precision there; solve the half-space (thinlayer.HalfSpace(), with nu=)")
    N = N_given or _default_modes(c_int / H, phi, layer, H, c_int)
    _check_work(layer, H, 0.3 * c_int, c_int + 6.0 * min(H, c_int), N,
                f"(estimated from the rigid overlap Phi(c) = delta0 = {delta0:.3g})")
    c, disc, d0c, x1, xP = _radius_for_depth(layer, phi, delta0, H, N, c_int)
    if N_given is None and _default_modes(c / H, phi, layer, H, c) > N:  # first estimate of c was too small
        N = _default_modes(c / H, phi, layer, H, c)
        c, disc, d0c, x1, xP = _radius_for_depth(layer, phi, delta0, H, N, c_int)
    errs = (0.0, 0.0, 0.0)
    vt = mu / (1.0 - nu_val)
    if error_estimate and isinstance(phi, RadialLoad) and N >= 6:  # a tip of revolution: three runs, extrapolated
        coarse = _coarse_modes(N, layer, H, c)
        runs = [(c, _force(c, vt, d0c, x1, xP, disc))]
        for m in coarse:
            cm, discm, d0m, x1m, xPm = _radius_for_depth(layer, phi, delta0, H, m, c_int)
            runs.append((cm, _force(cm, vt, d0m, x1m, xPm, discm)))
        rho_k = math.exp(-RATE_MIN * (N - coarse[0]) * H / c) if layer.has_thickness else 0.0
        settled = not layer.has_thickness or N >= 2.0 * c / H
        errs = (_geometric_error(tuple(v[0] for v in runs), rho_k, settled) * c,
                _geometric_error(tuple(v[1] for v in runs), rho_k, settled), 0.0)
    elif error_estimate:
        cc, discc, d0cc, x1c, xPc = _radius_for_depth(layer, phi, delta0, H, max(4, round(0.7 * N)), c_int)
        Pf, Pc = _force(c, vt, d0c, x1, xP, disc), _force(cc, vt, d0cc, x1c, xPc, discc)
        errs = (abs(c - cc), abs(Pf - Pc) / abs(Pf), 0.0)
    return _result(layer, punch, nu_val, mu, H, delta0, c, disc, x1, xP, d0c, errs)


# --------------------------------------------------------------------------- displacement (check route)
@boundary
def surface_displacement(result: AxisymmetricContact, r: Any) -> np.ndarray:
    """Surface displacement u3(r) produced by the computed pressure, by a route independent of the solver.

    The half-space part is evaluated in physical space with the ring kernel
    ``u(r) = (2/(pi vartheta)) int_0^c p(rho) rho K(m)/(r + rho) d rho``, ``m = 4 r rho/(r+rho)^2``
    (Boussinesq (2.1) with L = 1, averaged over a ring; K the complete elliptic integral), by adaptive
    quadrature; the layer correction ``(1/vartheta) int pbar(a) (L(aH) - 1) J0(a r) da`` by quadrature
    in a.  Inside the contact disc it must reproduce ``delta0 - Phi(r)`` (1.5); outside it must exceed it.

    Parameters
    ----------
    result : AxisymmetricContact
        A solution from :func:`solve_axisymmetric` or :func:`contact_for_radius`.
    r : array_like
        Radii (>= 0) where u3 is wanted.

    Returns
    -------
    numpy.ndarray
        u3 at ``r``.
    """
    if not isinstance(result, AxisymmetricContact):
        raise InputTypeError(f"result must be an AxisymmetricContact, got {type(result).__name__}")
    r = np.atleast_1d(np.asarray(r, dtype=float))
    if np.any(r < 0) or not np.all(np.isfinite(r)):
        raise InputError("r must be finite and >= 0")
    c, vt = result.radius, result.vartheta
    p = pressure_function(np.asarray(result.coefficients), c)

    def ring(rho: float, rr: float) -> float:
        if rr == 0.0:
            return float(p(np.array([rho]))[0]) * (math.pi / 2)  # K(0) = pi/2, rho/(0+rho) = 1
        s = rr + rho
        m1 = ((rr - rho) / s) ** 2  # 1 - m, computed without cancellation
        return float(p(np.array([rho]))[0]) * rho * special.ellipkm1(m1) / s

    hs = np.empty_like(r)
    for i, rr in enumerate(r):
        pts = [rr] if 0 < rr < c else None
        val, _ = integrate.quad(ring, 0.0, c, args=(rr,), points=pts, limit=400, epsabs=0, epsrel=1e-12)
        hs[i] = 2.0 / (math.pi * vt) * val
    if not result.layer.has_thickness:
        return hs
    return hs + correction_displacement(result.layer, result.H, np.asarray(result.coefficients), c, vt, r)
