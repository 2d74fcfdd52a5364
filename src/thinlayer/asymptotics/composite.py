r"""Composite (uniformly valid) contact pressure: inner expansion + boundary layer - common part.

For a point ``x`` near the contour Gamma_0 = {Phi = delta0} let ``n`` be its distance from
Gamma_0 along the gradient line of Phi (positive inside omega_0), ``v = n/H`` and ``g = |grad Phi|``
at the foot point on Gamma_0.  The inner expansion (2.26) near the edge is
``p_in = (vartheta/(A H)) (delta0 - Phi) = (vartheta g/A) v + O(H)``; the boundary layer (3.24) in
the same normalisation is ``(vartheta g/A) Qhat(v)`` with ``Qhat(v) ~ v`` as ``v -> oo`` and
``Qhat = 0`` for ``v <= h^*``.  Their common part is ``(vartheta g/A) v``, so

    p_c(x) = p_in(x) + (vartheta g/A) (Qhat(v) - v)      for v > h^*,     p_c = 0 otherwise,

and ``Qhat(v) - v`` decays exponentially into omega_0 (``e^{-sigma v}``), so away from the edge
``p_c = p_in`` exactly.  ``Qhat`` is either the exact Wiener--Hopf solution
(:func:`thinlayer.boundary_layer_exact`, kernel (2.3)) or Alexandrov's closed form (3.24).

Accuracy: the boundary layer is its leading term, so ``p_c`` is uniformly valid with an error
``O(p_max H/a)`` (a the contact half-width); away from the edge it is as accurate as the inner
expansion.  Near the edge the neglected ``O(H/a)`` terms (``p_1``, curvature of Gamma_0) may make
the sum slightly negative where ``g Qhat(v) < |p_1| A/vartheta``: with ``Qhat ~ 2 sqrt(A tau/pi)``
a zone ``tau < (pi/(4A)) (m_1 H Laplacian(Phi)/g)^2 = O((H/a)^2)`` (wider as nu -> 1/2, where m_1
grows); ``p_c`` is clipped at 0 there.

The foot point is found by Newton's method on ``Phi(x + t e) = delta0`` along
``e = grad Phi(x)/|grad Phi(x)|``, started from the root of the second-order Taylor polynomial
of ``Phi`` along the line (exact for a quadratic punch) and stopped point by point once the step
is below ``1e-13 H``; the gradient line meets Gamma_0 at a point whose distance differs from the
normal distance by ``O(n^2/R)``, inside the error above.  The boundary-layer correction is only
evaluated where ``|Qhat(v) - v| >= 1e-11`` (the tabulated exact solution's own rounding is
~5e-12 beyond): deeper inside ``p_c = p_in``.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .. import symbols as S
from .._checks import InputError, NotDerivedError, parse_nu, positive
from .._lazy import lazy_function, lazy_module
from ..display import RichDisplay, fmt
from ..errors import boundary, boundary_methods
from ..layers.kernels import LayerKernel
from ..punch import Punch
from .inner import InnerPressure, inner_pressure

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it
normal_latex = lazy_function("thinlayer.normal", "normal_latex")  # the printers subclass sympy's

__all__ = ["CompositePressure", "composite_pressure", "BOUNDARY_LAYERS"]

BOUNDARY_LAYERS = ("exact", "alexandrov")
_NEWTON_STEPS = 8
#: ``Qhat(v) - v`` is taken as 0 where the table's magnitude stays below this (the table's own noise: ~5e-12)
_TAIL = 1e-11
#: nodes of the interpolation table of Qhat(v) - v, uniform in sqrt(v - h)
_TABLE_NODES = 2**14 + 1


def _norm(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``sqrt(a^2 + b^2)``, vectorised: several times faster than ``numpy.hypot`` (punch gradients do not overflow)."""
    out = a * a
    out += b * b
    return np.sqrt(out, out=out)


@boundary_methods
@dataclass(frozen=True, eq=False)
class CompositePressure(RichDisplay):
    r"""Uniformly valid pressure ``p_c(x1, x2)`` (module docstring); call it like a numpy function.

    Attributes
    ----------
    inner : InnerPressure
        The :class:`~thinlayer.InnerPressure` used (``inner.order`` terms).
    boundary_layer : str
        ``"exact"`` or ``"alexandrov"``.
    h : float
        The edge shift used (3.25): the pressure vanishes for ``v = n/H <= h``.
    amplitude : float
        ``vartheta/A``: the boundary layer is ``amplitude * g * Qhat(v)``.
    band : float
        ``Qhat(v) - v`` is taken as 0 beyond ``v = band`` (below 1e-11 there).
    """

    layer: LayerKernel
    punch: Punch
    delta0: float
    H: float
    mu: float
    inner: InnerPressure
    boundary_layer: str
    h: float
    amplitude: float
    band: float
    _p_in: Callable = field(repr=False)
    _phi: Callable = field(repr=False)
    _Q: Callable = field(repr=False)
    _table: tuple = field(repr=False)
    _nu: Any = field(default=None, repr=False)
    _hess: Callable | None = field(default=None, repr=False)  # (Phi_11, Phi_12, Phi_22): the Newton start
    _quadratic: bool = field(default=False, repr=False)  # Phi of degree <= 2: the foot point in closed form

    def local(self, x1: Any, x2: Any) -> tuple[np.ndarray, np.ndarray]:
        """``(v, g)``: scaled distance ``n/H`` from Gamma_0 (inward positive) and ``|grad Phi|`` at the foot.

        Newton on the gradient line, to 1e-13 of ``H``; ``v = +inf`` where the gradient vanishes.
        """
        x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
        f, fx, fy = self._phi(x1, x2)
        return self._newton(x1, x2, f, fx, fy)

    def _newton(self, x1, x2, f, fx, fy):
        if self._quadratic:
            return self._foot_quadratic(x1, x2, f, fx, fy)
        gn = _norm(fx, fy)
        d0, tol, far = self.delta0, 1e-13 * self.H, 2 * self.band * self.H
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            ex, ey = fx / gn, fy / gn
            r = d0 - f
            if self._hess is None:
                t = r / gn
            else:  # root of f + gn t + c t^2/2 = delta0, c = e.Hess(Phi).e (exact for a quadratic Phi)
                hxx, hxy, hyy = self._hess(x1, x2)
                c = hxx * ex * ex + (2.0 * hxy) * ex * ey + hyy * ey * ey
                disc = gn * gn + 2.0 * c * r
                t = 2.0 * r / (gn + np.sqrt(disc))
                lin = ~np.isfinite(t)
                if lin.any():  # no real root of the quadratic model: the first-order distance
                    t[lin] = r[lin] / gn[lin]
            ok = np.isfinite(t)
            if not ok.all():
                t[~ok] = 0.0
            # Newton point by point: a point leaves once converged (or far outside the band, where the correction is
            # 0); g is |grad Phi| at its last evaluation, the foot point to within the last step
            act = None if ok.all() else np.flatnonzero(ok)
            g = gn if act is None else gn.copy()
            ta, exa, eya, xa, ya = (t, ex, ey, x1, x2) if act is None else (t[act], ex[act], ey[act], x1[act], x2[act])
            for _ in range(_NEWTON_STEPS):
                f, fx, fy = self._phi(xa + ta * exa, ya + ta * eya)
                step = (f - d0) / (fx * exa + fy * eya)
                ta = ta - step
                if act is None:
                    g, t = _norm(fx, fy), ta
                else:
                    g[act], t[act] = _norm(fx, fy), ta
                keep = np.abs(step) > tol
                keep &= np.abs(ta) < far
                if not keep.any():
                    break
                if not keep.all():
                    sel = np.flatnonzero(keep)
                    act = sel if act is None else act[sel]
                    ta, exa, eya, xa, ya = ta[sel], exa[sel], eya[sel], xa[sel], ya[sel]
        v = np.where(ok & np.isfinite(t), t / self.H, np.inf)
        return v, g

    def _foot_quadratic(self, x1, x2, f, fx, fy):
        """``(v, g)`` for a quadratic Phi: ``Phi(x + t e) = f + |grad f| t + c t^2/2`` exactly along the gradient line.

        ``t = 2 r/(|grad f| + sqrt(|grad f|^2 + 2 c r))``, ``r = delta0 - f``, and the gradient at the foot is
        ``grad f + (t/|grad f|) Hess grad f``.  Where the line does not reach Gamma_0 (negative discriminant, far
        outside) the first-order distance stands in.
        """
        hxx, hxy, hyy = self._hess(x1, x2)
        with np.errstate(divide="ignore", invalid="ignore"):
            if np.ndim(hxy) == 0 and hxy == 0:  # axes along the principal directions (most punches)
                hx, hy = fx * hxx, fy * hyy
            else:
                hx, hy = hxx * fx + hxy * fy, hxy * fx + hyy * fy
            g2 = fx * fx
            g2 += fy * fy
            gn = np.sqrt(g2)
            r = self.delta0 - f
            q = fx * hx
            q += fy * hy  # grad f . Hess . grad f
            q *= r
            q *= 2.0
            q /= g2
            q += g2
            np.sqrt(q, out=q)
            q += gn
            t = np.multiply(r, 2.0, out=r)
            t /= q  # 2 r/(|grad f| + sqrt(|grad f|^2 + 2 c r)),  c = q_0/|grad f|^2
            bad = ~np.isfinite(t)
            if bad.any():
                t[bad] = (self.delta0 - f[bad]) / gn[bad]
            s = np.divide(t, gn, out=q)
            hx = hx * s
            hx += fx
            hy = hy * s
            hy += fy
            g = _norm(hx, hy)
        v = np.where(np.isfinite(t), t / self.H, np.inf)
        return v, g

    def __call__(self, x1: Any, x2: Any) -> np.ndarray:
        """``p_c(x1, x2)``, vectorised over broadcastable arrays."""
        x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
        shape = x1.shape
        x1, x2 = x1.ravel(), x2.ravel()
        f, fx, fy = self._phi(x1, x2)
        with np.errstate(divide="ignore", invalid="ignore"):
            v_est = (self.delta0 - f) / (_norm(fx, fy) * self.H)
        p_in = self._p_in(x1, x2)
        p = np.where(v_est > 0, p_in, 0.0)
        # first-order distance first; the Newton foot point only near the edge (the first-order estimate may be far
        # off where grad Phi is small: the margin is that of the whole table, the Newton stops at the band)
        reach = self.h + float(self._table[0][-1]) ** 2
        near = np.flatnonzero((v_est < 1.25 * reach + 1) & (v_est > min(self.h, 0.0) - 1))
        if near.size:
            xn, yn = x1[near], x2[near]
            v, g = self._newton(xn, yn, f[near], fx[near], fy[near])
            corr = self._correction(v)
            p[near] = np.where(v > self.h, p_in[near] + self.amplitude * g * corr, 0.0)
        return np.maximum(p, 0.0).reshape(shape)

    def _correction(self, v: np.ndarray) -> np.ndarray:
        """``Qhat(v) - v`` for ``v > h`` (interpolated table), 0 beyond the band."""
        zt, ct = self._table
        dz = zt[1]
        w = np.sqrt(np.clip(v - self.h, 0.0, None)) / dz
        i = np.minimum(w.astype(np.intp), len(zt) - 2)
        w -= i
        out = ct[i] * (1 - w) + ct[i + 1] * w  # linear interpolation on the uniform sqrt grid
        return np.where(v < self.band, out, 0.0)

    codegen_name = "composite_pressure"
    equation = "3.24"

    def codegen_expressions(self):
        """``((x1, x2, H, mu), {"p": p_c})`` for :mod:`thinlayer.export.codegen` (radial punch, Alexandrov layer).

        For a radial punch ``Gamma_0`` is the circle ``r = a`` and ``v = (a - r)/H`` exactly, so with
        Alexandrov's closed form (3.24) the composite is an expression in ``x1, x2``; ``H`` and ``mu``
        stay arguments (``delta0``, ``nu`` and the punch are fixed numbers).
        """
        if self.boundary_layer != "alexandrov":
            raise NotDerivedError(
                "the exact boundary layer is a numerical (tabulated) function; generated code needs the closed "
                "form: build the composite with boundary_layer='alexandrov'")
        Phi = self.punch.expr
        rho = sp.Symbol("rho", positive=True)
        radial = Phi.subs({S.x1: rho, S.x2: 0})
        if sp.expand(Phi - radial.subs(rho, sp.sqrt(S.x1**2 + S.x2**2))) != 0:
            raise NotDerivedError(
                f"the punch {Phi} is not radial: the distance to Gamma_0 has no closed form; "
                "generated code is available for radial punches")
        from scipy.optimize import brentq

        from .boundary_layer import alexandrov_solution

        f = sp.lambdify(rho, radial - self.delta0)
        hi = 1.0
        while f(hi) < 0:
            hi *= 2
        a = sp.Float(brentq(f, 0.0, hi, xtol=1e-15, rtol=1e-15), 17)
        g = sp.Float(float(sp.diff(radial, rho).subs(rho, a)), 17)
        vs = sp.Symbol("v", real=True)
        Q = alexandrov_solution(self.layer).q(vs)
        v = (a - sp.sqrt(S.x1**2 + S.x2**2)) / S.H
        nu = {S.nu: self._nu} if self._nu is not None else {}
        p_in = self.inner.pressure.subs({S.delta0: self.delta0, **nu})
        amp = (self.layer.vartheta.subs(nu) / self.layer.A).subs(S.mu, 1)
        val = p_in + sp.Float(float(amp), 17) * S.mu * g * (Q.subs(vs, v) - v)
        pc = sp.Piecewise((0, v <= sp.Float(self.h, 17)), (0, val < 0), (val, True))
        return (S.x1, S.x2, S.H, S.mu), {"p": pc}

    def lambdify(self) -> Callable:
        """The numeric pressure function ``(x1, x2) -> p_c`` (this object: it is already vectorised)."""
        return self

    def latex(self) -> str:
        amplitude = normal_latex(sp.factor(self.layer.vartheta / self.layer.A))  # vartheta/A, one fraction
        kind = "exact (2.3)" if self.boundary_layer == "exact" else "Alexandrov (3.24)"
        return (
            r"p_c(\mathbf{x}) = p_{\mathrm{in}}(\mathbf{x}) + " + amplitude + r"\,|\nabla\Phi(s)|"
            r"\left(\hat Q\!\left(\frac{n}{H}\right) - \frac{n}{H}\right),\quad \hat Q = 0 \ \text{for}\ "
            rf"\frac{{n}}{{H}} \le h^* = {self.h:.10g}\ (\text{{{kind} boundary layer}})"
        )

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        kind = "exact (2.3)" if self.boundary_layer == "exact" else "Alexandrov (3.24)"
        return [
            f"CompositePressure: inner ({self.inner.order} terms) + {kind} boundary layer - common part"
            "   (2.26), (3.24)",
            f"  {self.punch.name}: Φ = {fmt(self.punch.expr)} on {self.layer}",
            f"  δ₀ = {self.delta0:.6g}, H = {self.H:.6g}, μ = {self.mu:.6g}",
            f"  h* = {self.h:.10g}, amplitude ϑ/𝒜 = {self.amplitude:.10g}, "
            f"boundary layer for n/H < {self.band:.4g}",
        ]


@boundary
def composite_pressure(layer: LayerKernel, punch: Punch, delta0: float, H: float, mu: float = 1.0,
                       terms: int = 2, boundary_layer: str = "exact", nu: Any = None) -> CompositePressure:
    """Uniformly valid contact pressure for a numeric layer and punch (module docstring).

    Parameters
    ----------
    layer : LayerKernel
        A :class:`~thinlayer.BondedLayer` with a numeric Poisson ratio, or a
        :class:`~thinlayer.FrictionlessLayer` (then give ``nu`` for ``vartheta = mu/(1 - nu)``).
    punch : Punch
        A :class:`~thinlayer.Punch` with numeric coefficients.
    delta0, H, mu : float
        Indentation, thickness, shear modulus (finite numbers > 0; a clear ValueError otherwise).
    terms : int
        Number of inner terms ``p_0 .. p_{terms-1}`` (2.26).
    boundary_layer : str
        ``"exact"`` (Wiener--Hopf, kernel (2.3); its table is built once per nu, ~2 s) or
        ``"alexandrov"`` (closed form (3.24)).
    """
    from .boundary_layer import alexandrov_solution
    from .wiener_hopf import boundary_layer_exact

    if boundary_layer not in BOUNDARY_LAYERS:
        raise InputError(f"boundary_layer must be one of {BOUNDARY_LAYERS}, got {boundary_layer!r}")
    delta0, H, mu = (positive(v, name) for v, name in ((delta0, "delta0"), (H, "H"), (mu, "mu")))
    inner = inner_pressure(layer, punch, order=terms)
    vals = {S.delta0: delta0, S.H: H, S.mu: mu}
    if nu is not None:
        vals[S.nu] = parse_nu(nu, floats="float", upper_closed=True, symbols=False)
    p_expr = inner.pressure.xreplace(vals)
    th = float(layer.vartheta.xreplace(vals))
    p_lam = sp.lambdify((S.x1, S.x2), p_expr, modules="numpy", cse=True)

    def p_in(a, b):
        q = p_lam(a, b)
        return q if np.ndim(q) else np.full(np.shape(a), float(q))

    Phi = punch.expr
    phi = sp.lambdify((S.x1, S.x2), (Phi, sp.diff(Phi, S.x1), sp.diff(Phi, S.x2)), modules="numpy", cse=True)
    hess = sp.lambdify((S.x1, S.x2), (sp.diff(Phi, S.x1, 2), sp.diff(Phi, S.x1, S.x2), sp.diff(Phi, S.x2, 2)),
                       modules="numpy", cse=True)

    def phi3(a, b):
        return tuple(q if np.ndim(q) else np.full(np.shape(a), float(q)) for q in phi(a, b))

    def hess3(a, b):
        return tuple(q if np.ndim(q) else float(q) for q in hess(a, b))  # constants broadcast as scalars

    if boundary_layer == "exact":
        sol = boundary_layer_exact(layer)
        h = float(sol.h)
        band = h + sol.tau_max
        Q = sol.pressure
    else:
        sol = alexandrov_solution(layer)
        h = float(sol.h)
        band = h + 40.0 / float(sol.params.B)  # erfc(sqrt(40)) ~ 1e-19
        Q = sol.q_numeric
    zt = np.linspace(0.0, np.sqrt(band - h), _TABLE_NODES)
    vt = h + zt * zt
    ct = np.asarray(Q(vt), dtype=float) - vt
    ct[0] = -h  # Qhat(h) = 0 (3.18)
    big = np.flatnonzero(np.abs(ct) >= _TAIL)
    if big.size and big[-1] + 1 < len(vt):  # the band ends where |Qhat - v| stays below _TAIL
        band = float(vt[big[-1] + 1])
    quadratic = punch.polynomial.total_degree() <= 2
    return CompositePressure(layer, punch, float(delta0), float(H), float(mu), inner, boundary_layer, h,
                             th / float(layer.A), float(band), p_in, phi3, Q, (zt, ct), nu, hess3, quadratic)
