"""Direct numerical solution of the axisymmetric unilateral contact problem (1.5)-(1.8).

This module is the *independent* route that validates the asymptotic expansions: it never
uses ``A``, ``m_n`` or any thin-layer series; it only evaluates the kernel L(u) (2.3).

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
many modes (an over-estimate of the error of the finer run).
"""
from __future__ import annotations

import math
import numbers
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import mpmath
import numpy as np
import sympy as sp
from scipy import integrate, optimize, special

from ..display import RichDisplay, fmt
from ..layers.kernels import HalfSpace, LayerKernel

__all__ = ["AxisymmetricContact", "contact_for_radius", "solve_axisymmetric", "surface_displacement"]

_U_MAX = 22.0  # L(u) - 1 = O(u^2 e^{-2u}) < 1e-16 beyond
_GAUSS = 16  # Gauss-Legendre points per panel
_MAX_MODES = 600


# --------------------------------------------------------------------------- input checks
def _positive(value: Any, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, sp.Number, mpmath.mpf)):
        raise TypeError(f"{name} must be a positive real number, got {value!r} ({type(value).__name__})")
    v = float(value)
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"{name} must be a finite positive number, got {value!r}")
    return v


def _is_incompressible(layer: Any) -> bool:
    """True for the incompressible bonded layer (kappa = 1), the one kernel that admits nu = 1/2."""
    from ..asymptotics.incompressible import (
        IncompressibleLayer,  # late import: incompressible.py imports this module
    )

    return isinstance(layer, IncompressibleLayer)


def _nu_and_layer(layer: Any, nu: Any) -> float:
    if not isinstance(layer, LayerKernel):
        raise TypeError(
            f"layer must be a thinlayer LayerKernel (BondedLayer(nu), FrictionlessLayer(), HalfSpace()), "
            f"got {layer!r} ({type(layer).__name__})")
    layer_nu = getattr(layer, "nu", None)
    if layer_nu is not None and isinstance(layer_nu, sp.Basic) and not layer_nu.is_number:
        raise ValueError("the direct solver needs a numeric Poisson ratio: build e.g. BondedLayer(0.3), "
                         f"not {layer!r}")
    if layer_nu is not None:
        lnu = float(layer_nu)
        if nu is not None and abs(float(nu) - lnu) > 1e-12:
            raise ValueError(f"nu={nu!r} disagrees with the layer's Poisson ratio {lnu}")
        nu_val = lnu
    else:
        if nu is None:
            raise ValueError(f"{type(layer).__name__} does not fix Poisson's ratio: pass nu= (-1 < nu < 1/2) "
                             "to define vartheta = mu/(1-nu)")
        if isinstance(nu, bool) or not isinstance(nu, (numbers.Real, sp.Number)):
            raise TypeError(f"nu must be a real number with -1 < nu < 1/2, got {nu!r}")
        nu_val = float(nu)
    if not (-1 < nu_val < 0.5 or (nu_val == 0.5 and _is_incompressible(layer))):
        raise ValueError(f"Poisson ratio nu={nu_val} outside the admissible range -1 < nu < 1/2 "
                         "(nu = 1/2 only with thinlayer.asymptotics.incompressible.IncompressibleLayer())")
    try:
        far = float(np.asarray(layer.L_numeric(np.array([2 * _U_MAX]), "numpy"))[0])
    except Exception as exc:  # GenericLayer and friends
        raise ValueError(f"layer {layer!r} cannot be evaluated numerically: {exc}") from exc
    if abs(far - 1.0) > 1e-12:
        raise ValueError(f"layer kernel must tend to the half-space value L = 1 at large u (2.4); "
                         f"L({2 * _U_MAX}) = {far}")
    return nu_val


def _profile(Phi_r: Any) -> Callable[[np.ndarray], np.ndarray]:
    """Turn a numpy callable or a one-symbol sympy expression into a vectorised Phi(r)."""
    if isinstance(Phi_r, sp.Basic):
        free = sorted(Phi_r.free_symbols, key=str)
        if len(free) > 1:
            raise ValueError(f"Phi_r must depend on the radius only; it has free symbols {free}: "
                             "substitute numbers for R, etc.")
        sym = free[0] if free else sp.Symbol("r")
        f = sp.lambdify(sym, Phi_r, "numpy")
    elif callable(Phi_r):
        f = Phi_r
    else:
        raise TypeError(f"Phi_r must be a callable Phi(r) (numpy-vectorised) or a sympy expression in r, "
                        f"got {Phi_r!r} ({type(Phi_r).__name__})")

    def phi(r: np.ndarray) -> np.ndarray:
        r = np.asarray(r, dtype=float)
        out = np.broadcast_to(np.asarray(f(r), dtype=float), r.shape)
        if not np.all(np.isfinite(out)):
            raise ValueError("Phi_r returned non-finite values on [0, c]")
        return out

    return phi


def _check_modes(n: Any) -> int | None:
    if n is None:
        return None
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)):
        raise TypeError(f"n (number of modes) must be an integer, got {n!r}")
    if not 4 <= n <= _MAX_MODES:
        raise ValueError(f"n (number of modes) must lie in [4, {_MAX_MODES}], got {n}")
    return int(n)


def _default_modes(c_over_H: float) -> int:
    return int(min(_MAX_MODES, math.ceil(8.0 * math.sqrt(max(c_over_H, 0.0))) + 12))


# --------------------------------------------------------------------------- basis
def _beta(n: np.ndarray) -> np.ndarray:
    """beta_n = Gamma(n + 1/2)/(sqrt(pi) n!) = P_n^{(0,-1/2)}(-1) (-1)^n."""
    return np.exp(special.gammaln(n + 0.5) - special.gammaln(n + 1.0)) / math.sqrt(math.pi)


def _basis_transform(n: int, b: np.ndarray) -> np.ndarray:
    """int_0^1 psi_n(x) J0(b x) x dx = beta_n j_{2n}(b) (unnormalised basis)."""
    return _beta(np.array(float(n))) * special.spherical_jn(2 * n, np.asarray(b, dtype=float))


def _half_space_diagonal(n: np.ndarray) -> np.ndarray:
    """d_n = int_0^oo (beta_n j_2n(t))^2 dt = beta_n^2 pi / (2 (4n + 1)) (Weber-Schafheitlin)."""
    return _beta(n) ** 2 * math.pi / (2.0 * (4.0 * n + 1.0))


@dataclass(frozen=True)
class _Discretisation:
    """Fixed modes and t-quadrature, valid for contact radii in [c_lo, c_hi]."""

    layer: LayerKernel
    H: float
    modes: int
    c_lo: float
    c_hi: float
    t: np.ndarray = field(repr=False)
    w: np.ndarray = field(repr=False)
    G: np.ndarray = field(repr=False)  # normalised transforms g~_n(t_k), shape (nt, modes)
    scale: np.ndarray = field(repr=False)  # sqrt(d_n)
    s: np.ndarray = field(repr=False)  # edge-singularity functional in the normalised basis
    xq: np.ndarray = field(repr=False)  # quadrature abscissae x_k = sin(theta_k) in [0, 1]
    Pq: np.ndarray = field(repr=False)  # w_k P_m(cos 2 theta_k) x_k / sqrt(d_m), shape (modes, nq)

    @classmethod
    def build(cls, layer: LayerKernel, H: float, modes: int, c_lo: float, c_hi: float) -> _Discretisation:
        n = np.arange(modes, dtype=float)
        scale = np.sqrt(_half_space_diagonal(n))
        if isinstance(layer, HalfSpace):
            t = w = np.zeros(0)
            G = np.zeros((0, modes))
        else:
            T = _U_MAX * c_hi / H
            ell = min(3.0, 0.5 * c_lo / H)
            npan = max(8, math.ceil(T / ell))
            xg, wg = special.roots_legendre(_GAUSS)
            edges = np.linspace(0.0, T, npan + 1)
            a, b = edges[:-1, None], edges[1:, None]
            t = (0.5 * (b - a) * xg + 0.5 * (a + b)).ravel()
            w = np.broadcast_to(0.5 * (b - a) * wg, (npan, _GAUSS)).ravel().copy()
            G = _beta(n) / scale * special.spherical_jn(2 * np.arange(modes)[None, :], t[:, None])
        s = (-1.0) ** n * _beta(n) / scale
        # F_m = int_0^1 psi_m(x) f(c x) x dx = int_0^{pi/2} P_m(cos 2 th) f(c sin th) sin th d th  (x = sin th):
        # a smooth integrand, Gauss-Legendre in th (more accurate than Gauss-Jacobi nodes from scipy)
        nq = 2 * modes + 48
        xg, wg = special.roots_legendre(nq)
        th = 0.25 * math.pi * (xg + 1.0)
        xq = np.sin(th)
        P = special.eval_jacobi(np.arange(modes)[:, None], 0.0, -0.5, np.cos(2 * th)[None, :])
        Pq = P * (0.25 * math.pi * wg * xq)[None, :] / scale[:, None]
        return cls(layer, H, modes, c_lo, c_hi, t, w, G, scale, s, xq, Pq)

    def matrix(self, c: float) -> np.ndarray:
        """Normalised Galerkin matrix I + C~(c) (half-space part is the identity)."""
        M = np.eye(self.modes)
        if self.t.size:
            lm1 = np.asarray(self.layer.L_numeric(self.t * (self.H / c), "numpy"), dtype=float) - 1.0
            # einsum (plain C loop) rather than BLAS: small products, immune to thread oversubscription
            M = M + np.einsum("km,kn->mn", self.G * (self.w * lm1)[:, None], self.G)
        return M

    def solve(self, c: float, phi: Callable[[np.ndarray], np.ndarray]):
        """Return (delta0(c), x~_1, x~_Phi): with S = 0, x~ = (vartheta/c)(delta0 x~_1 - x~_Phi)."""
        M = self.matrix(c)
        F1 = np.zeros(self.modes)
        F1[0] = 1.0 / self.scale[0]  # int psi_0 x dx = beta_0 j_0(0) = 1
        FPhi = self.Pq @ phi(c * self.xq)
        sol = np.linalg.solve(M, np.column_stack([F1, FPhi]))
        x1, xP = sol[:, 0], sol[:, 1]
        den = self.s @ x1
        if den == 0:
            raise ArithmeticError("degenerate edge condition")
        return float(self.s @ xP / den), x1, xP


# --------------------------------------------------------------------------- result
@dataclass(frozen=True)
class AxisymmetricContact(RichDisplay):
    """Direct numerical solution of the axisymmetric unilateral contact problem (1.5)-(1.8).

    Attributes
    ----------
    layer, nu, mu, vartheta, H:
        Layer model (kernel (2.3)), Poisson ratio, shear modulus, ``vartheta = mu/(1-nu)`` (2.1), thickness.
    delta0:
        Indentation depth (1.5).
    radius:
        Contact radius c (the pressure vanishes continuously at r = c).
    force:
        Total force P = 2 pi int_0^c p r dr (1.8).
    r, pressure:
        Sample radii on [0, c] (clustered at the edge) and p(r) there (read-only arrays).
    modes:
        Number of Galerkin modes.
    radius_error, force_error, delta0_error:
        Convergence estimates: |change| against a run with ~0.7x the modes (absolute for
        radius and delta0, relative for force); zero for the prescribed quantity.
    coefficients:
        Coefficients of p in the normalised flat-punch basis (``vartheta/c`` included).
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

    @property
    def equation(self) -> str:
        return "1.5-1.8"

    def pressure_at(self, r: Any) -> np.ndarray:
        """Contact pressure p(r) (zero outside the contact disc), accurate up to the edge."""
        return _pressure_function(np.asarray(self.coefficients), self.radius)(r)

    def latex(self) -> str:
        """One-line LaTeX summary of the solution with its convergence estimates."""
        return (rf"c = {self.radius:.10g}\,(\pm {self.radius_error:.1e}),\quad "
                rf"P = {self.force:.10g}\,(\pm {self.force_error:.1e}\,P),\quad "
                rf"\delta_0 = {self.delta0:.10g},\quad H = {self.H:g},\quad \nu = {self.nu:g}")

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        punch = getattr(self, "punch", None)
        what = f" of {punch.name} Phi = {fmt(punch.expr)}" if punch is not None else ""
        layer = str(self.layer) if "nu=" in str(self.layer) else f"{self.layer}, nu = {self.nu:.6g}"
        return [
            f"{type(self).__name__}: direct numerical solution{what}   (1.5)-(1.8)",
            f"  {layer}, mu = {self.mu:.6g}, H = {self.H:.6g}, delta0 = {self.delta0:.10g}",
            f"  contact radius c = {self.radius:.12g}  (+- {self.radius_error:.1e})",
            f"  force          P = {self.force:.12g}  (+- {self.force_error:.1e} P), {self.modes} modes",
        ]


def _pressure_function(coef: np.ndarray, c: float) -> Callable[[np.ndarray], np.ndarray]:
    """p(r) from the normalised coefficients, free of cancellation at the edge.

    ``p = sqrt(2) (1+y)^{-1/2} Q(y)`` with ``Q = sum_n x~_n P_n^{(0,-1/2)}(y)/sqrt(d_n)`` and ``y = 1 - 2 r^2/c^2``;
    the edge condition Q(-1) = 0 lets us write ``p = sqrt(2 (1+y)) R(y)`` with the polynomial
    ``R = Q/(1+y)``, built by Chebyshev interpolation at interior nodes (no division near y = -1).
    """
    N = coef.size
    n = np.arange(N)
    a = coef / np.sqrt(_half_space_diagonal(n.astype(float)))

    def Q(y: np.ndarray) -> np.ndarray:
        return special.eval_jacobi(n[:, None], 0.0, -0.5, np.asarray(y)[None, :]).T @ a

    Rcheb = np.polynomial.chebyshev.Chebyshev.interpolate(lambda yy: Q(yy) / (1.0 + yy), max(N - 2, 1))

    def p(r: np.ndarray) -> np.ndarray:
        x = np.abs(np.asarray(r, dtype=float)) / c
        out = np.zeros_like(x)
        inside = x < 1.0
        y = 1.0 - 2.0 * x[inside] ** 2
        out[inside] = np.sqrt(2.0 * (1.0 + y)) * Rcheb(y)
        return out

    return p


def _sample_radii(c: float, npts: int = 201) -> np.ndarray:
    return c * np.sin(np.linspace(0.0, 0.5 * math.pi, npts))


# --------------------------------------------------------------------------- drivers
def _intersection_radius(phi: Callable, delta0: float, scale_hint: float) -> float:
    """Radius where Phi(r) = delta0 (the rigid-body overlap), bracketed outward from scale_hint."""
    if phi(np.array([0.0]))[0] >= delta0:
        raise ValueError(f"Phi(0) = {phi(np.array([0.0]))[0]} >= delta0 = {delta0}: the punch does not "
                         "touch the layer; Phi must be normalised with Phi(0) = 0 and increase with r")
    hi = scale_hint
    for _ in range(200):
        if phi(np.array([hi]))[0] > delta0:
            break
        hi *= 2.0
    else:
        raise ValueError("Phi_r never reaches delta0: an unbounded, increasing profile (paraboloid, r^4, ...) "
                         "is needed for a finite contact disc")
    return optimize.brentq(lambda r: phi(np.array([r]))[0] - delta0, 0.0, hi, xtol=1e-14 * hi)


def _result(layer, nu, mu, H, delta0, c, disc, x1, xP, d0c, errs) -> AxisymmetricContact:
    vartheta = mu / (1.0 - nu)
    coef = (vartheta / c) * (delta0 * x1 - xP) if d0c is None else (vartheta / c) * (d0c * x1 - xP)
    force = 2.0 * math.pi * c**2 * coef[0] / disc.scale[0]  # (1.8): only psi_0 has nonzero mean
    r = _sample_radii(c)
    p = _pressure_function(coef, c)(r)
    r.setflags(write=False)
    p.setflags(write=False)
    return AxisymmetricContact(layer, nu, mu, vartheta, H, delta0, float(c), float(force), r, p, disc.modes,
                               float(errs[0]), float(errs[1]), float(errs[2]), tuple(float(v) for v in coef))


def contact_for_radius(layer: LayerKernel, Phi_r: Any, radius: float, H: float, mu: float = 1.0,
                       n: int | None = None, *, nu: float | None = None,
                       error_estimate: bool = True) -> AxisymmetricContact:
    """Solve the contact problem for a prescribed contact radius c: delta0 and P follow.

    Parameters
    ----------
    layer:
        Layer kernel (``BondedLayer(nu)`` with numeric nu, ``FrictionlessLayer()``, ``HalfSpace()``).
    Phi_r:
        Punch profile Phi(r) with Phi(0) = 0 (numpy callable or a sympy expression in one symbol).
    radius:
        Contact radius c > 0.
    H:
        Layer thickness (ignored by ``HalfSpace``).
    mu:
        Shear modulus.
    n:
        Number of Galerkin modes (default ``ceil(8 sqrt(c/H)) + 12``).
    nu:
        Poisson ratio, only for layers that do not carry one (``HalfSpace``, ``FrictionlessLayer``).
    error_estimate:
        Also solve with ~0.7 n modes and record the changes.

    Returns
    -------
    AxisymmetricContact
        With ``delta0`` such that p vanishes continuously at r = c (1.5).
    """
    c = _positive(radius, "radius")
    H = _positive(H, "H")
    mu = _positive(mu, "mu")
    nu_val = _nu_and_layer(layer, nu)
    phi = _profile(Phi_r)
    N = _check_modes(n) or _default_modes(c / H)
    runs = []
    for modes in ([N, max(4, round(0.7 * N))] if error_estimate else [N]):
        disc = _Discretisation.build(layer, H, modes, c, c)
        d0, x1, xP = disc.solve(c, phi)
        runs.append((disc, d0, x1, xP))
    disc, d0, x1, xP = runs[0]
    if not d0 > 0:
        raise ValueError(f"no indentation delta0 > 0 gives contact radius {c}: is Phi increasing with Phi(0) = 0?")
    vt = mu / (1.0 - nu_val)
    errs = (0.0, 0.0, 0.0)
    if error_estimate:
        dc, d0c, x1c, xPc = runs[1]
        Pf = 2 * math.pi * c * vt * (d0 * x1[0] - xP[0]) / disc.scale[0]
        Pc = 2 * math.pi * c * vt * (d0c * x1c[0] - xPc[0]) / dc.scale[0]
        errs = (0.0, abs(Pf - Pc) / abs(Pf), abs(d0 - d0c))
    return _result(layer, nu_val, mu, H, d0, c, disc, x1, xP, None, errs)


def _radius_for_depth(layer, phi, delta0, H, N, c_int):
    """Contact radius for a prescribed depth: Brent's method on delta0(c) - delta0."""
    lo, hi = 0.3 * c_int, c_int + 6.0 * min(H, c_int)
    for _ in range(60):
        disc = _Discretisation.build(layer, H, N, lo, hi)
        f_lo = disc.solve(lo, phi)[0] - delta0
        f_hi = disc.solve(hi, phi)[0] - delta0
        if f_lo < 0 < f_hi:
            break
        if f_lo >= 0:
            lo *= 0.5
        if f_hi <= 0:
            hi = hi * 1.5 + 2.0 * H
    else:
        raise ValueError("could not bracket the contact radius: is Phi convex and increasing (one contact disc)?")
    c = optimize.brentq(lambda cc: disc.solve(cc, phi)[0] - delta0, lo, hi, xtol=1e-15 * hi, rtol=1e-15,
                        maxiter=200)
    d0c, x1, xP = disc.solve(c, phi)
    return c, disc, d0c, x1, xP


def solve_axisymmetric(layer: LayerKernel, Phi_r: Any, delta0: float, H: float, mu: float = 1.0,
                       n: int | None = None, *, nu: float | None = None,
                       error_estimate: bool = True) -> AxisymmetricContact:
    """Direct solution of the unilateral contact problem (1.5)-(1.8) for an axisymmetric punch.

    A rigid punch ``x3 = -Phi(r)`` is pressed to depth ``delta0`` into a layer of thickness H
    on a rigid base (kernel L of the layer, (2.1), (2.3)).  The contact radius c is unknown and is
    found from the condition that the pressure vanishes continuously at the edge (see the module
    docstring for the spectral Galerkin method).  No asymptotic expansion is used.

    Parameters
    ----------
    layer:
        ``BondedLayer(nu)`` (numeric nu), ``FrictionlessLayer()`` or ``HalfSpace()``.
    Phi_r:
        Punch profile Phi(r), Phi(0) = 0, increasing and convex (numpy callable or sympy
        expression in one symbol), e.g. ``lambda r: r**2 / (2 * R)``.
    delta0:
        Indentation depth (> 0).
    H:
        Layer thickness (ignored by ``HalfSpace``).
    mu:
        Shear modulus.
    n:
        Number of Galerkin modes (default ``ceil(8 sqrt(c/H)) + 12``, from a first estimate of c).
    nu:
        Poisson ratio, only for layers that do not carry one (``HalfSpace``, ``FrictionlessLayer``).
    error_estimate:
        Also solve with ~0.7 n modes and record the changes of c and P.

    Returns
    -------
    AxisymmetricContact
        Frozen result with ``radius``, ``force`` (1.8), ``r``, ``pressure`` and error estimates.

    Examples
    --------
    Hertz's solution for the half-space (L = 1): c^2 = R delta0, P = 8 vartheta c^3 / (3 R).

    >>> from thinlayer import HalfSpace
    >>> res = solve_axisymmetric(HalfSpace(), lambda r: r**2 / 2, 0.01, H=1.0, nu=0.3)
    >>> round(res.radius**2 / 0.01, 10), round(res.force / (8 / 0.7 * res.radius**3 / 3), 10)
    (1.0, 1.0)
    """
    delta0 = _positive(delta0, "delta0")
    H = _positive(H, "H")
    mu = _positive(mu, "mu")
    nu_val = _nu_and_layer(layer, nu)
    phi = _profile(Phi_r)
    N_given = _check_modes(n)
    c_int = _intersection_radius(phi, delta0, H)
    N = N_given or _default_modes(c_int / H)
    c, disc, d0c, x1, xP = _radius_for_depth(layer, phi, delta0, H, N, c_int)
    if N_given is None and _default_modes(c / H) > N:  # first estimate of c was too small
        N = _default_modes(c / H)
        c, disc, d0c, x1, xP = _radius_for_depth(layer, phi, delta0, H, N, c_int)
    errs = (0.0, 0.0, 0.0)
    vt = mu / (1.0 - nu_val)
    if error_estimate:
        cc, discc, d0cc, x1c, xPc = _radius_for_depth(layer, phi, delta0, H, max(4, round(0.7 * N)), c_int)
        Pf = 2 * math.pi * c * vt * (d0c * x1[0] - xP[0]) / disc.scale[0]
        Pc = 2 * math.pi * cc * vt * (d0cc * x1c[0] - xPc[0]) / discc.scale[0]
        errs = (abs(c - cc), abs(Pf - Pc) / abs(Pf), 0.0)
    return _result(layer, nu_val, mu, H, delta0, c, disc, x1, xP, d0c, errs)


# --------------------------------------------------------------------------- displacement (check route)
def surface_displacement(result: AxisymmetricContact, r: Any) -> np.ndarray:
    """Surface displacement u3(r) produced by the computed pressure, by a route independent of the solver.

    The half-space part is evaluated in physical space with the ring kernel
    ``u(r) = (2/(pi vartheta)) int_0^c p(rho) rho K(m)/(r + rho) d rho``, ``m = 4 r rho/(r+rho)^2``
    (Boussinesq (2.1) with L = 1, averaged over a ring; K the complete elliptic integral), by adaptive
    quadrature; the layer correction ``(1/vartheta) int pbar(a) (L(aH) - 1) J0(a r) da`` by quadrature
    in a.  Inside the contact disc it must reproduce ``delta0 - Phi(r)`` (1.5); outside it must exceed it.

    Parameters
    ----------
    result:
        A solution from :func:`solve_axisymmetric` or :func:`contact_for_radius`.
    r:
        Radii (>= 0) where u3 is wanted.

    Returns
    -------
    numpy.ndarray
        u3 at ``r``.
    """
    if not isinstance(result, AxisymmetricContact):
        raise TypeError(f"result must be an AxisymmetricContact, got {type(result).__name__}")
    r = np.atleast_1d(np.asarray(r, dtype=float))
    if np.any(r < 0) or not np.all(np.isfinite(r)):
        raise ValueError("r must be finite and >= 0")
    c, vt = result.radius, result.vartheta
    p = _pressure_function(np.asarray(result.coefficients), c)

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
    if isinstance(result.layer, HalfSpace):
        return hs
    coef = np.asarray(result.coefficients)
    N = coef.size
    n = np.arange(N, dtype=float)
    scale = np.sqrt(_half_space_diagonal(n))
    T = _U_MAX * c / result.H
    ell = min(1.0, 0.5 * c / result.H, 0.5 * c / max(float(r.max()), c))
    npan = max(8, math.ceil(T / ell))
    xg, wg = special.roots_legendre(_GAUSS)
    edges = np.linspace(0.0, T, npan + 1)
    a_, b_ = edges[:-1, None], edges[1:, None]
    t = (0.5 * (b_ - a_) * xg + 0.5 * (a_ + b_)).ravel()
    w = np.broadcast_to(0.5 * (b_ - a_) * wg, (npan, _GAUSS)).ravel()
    # pbar(t/c) = c^2 sum_n coef_n beta_n j_2n(t)/sqrt(d_n);  da = dt / c
    pbar = c**2 * (special.spherical_jn(2 * np.arange(N)[None, :], t[:, None]) * (_beta(n) / scale)) @ coef
    lm1 = np.asarray(result.layer.L_numeric(t * result.H / c, "numpy"), dtype=float) - 1.0
    corr = (special.j0(np.outer(r, t) / c) @ (w * pbar * lm1)) / (c * vt)
    return hs + corr
