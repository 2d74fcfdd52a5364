r"""JKR on a nearly incompressible thin layer through the two-term model (J.19)-(J.23).

Equation tags continue the J series of :mod:`thinlayer.asymptotics.adhesion` ((J.7)-(J.15)) after the any-thickness
sphere law (J.16)-(J.18) of :mod:`thinlayer.contact.adhesion_sphere`.  Assumptions:
frictionless contact, the layer bonded to a rigid base (no slip), ``1/4 < nu < 1/2`` (``m_1 > 0``), JKR adhesion
(short-range: ``w`` is spent at the contact edge, tension inside the contact), ``c >> H``; the ratio
``lambda^2 = (c/H)^2/m_1 ~ 3 (1 - 2 nu)(c/H)^2`` (I.13) is free: the law is uniform from the compressible
(``lambda >> 1``, (J.11)) to the incompressible (``lambda << 1``, (J.15)) layer.

(J.19) *The two-term flat punch.*  The outer problem is the two-term operator (I.10),
``(H/vartheta)(A p - A m_1 H^2 Delta p) = d`` on the disc, with the Dirichlet condition ``p = 0`` at the model
edge ``a_e = c + h H`` (``h = h(nu)`` of (I.12); the edge of a flat punch is fixed, (F.15)).  With
``k^2 = 1/(m_1 H^2)`` the regular solution is ``p = (vartheta d/(A H))(1 - I_0(k r)/I_0(k a_e))`` and, since
``int_0^{a_e} I_0(k r) r dr = a_e I_1(k a_e)/k``::

    S = dP/dd = (pi vartheta a_e^2/(A H)) (1 - 2 rho(x)/x),   rho = I_1/I_0,   x = k a_e,              (J.19)

that is ``kappa = S/(4 vartheta c)``, (F.15).

(J.20) *Energy release rate.*  By (J.4) ``G = d^2 S'(c)/(4 pi c)``; ``rho' = 1 - rho/x - rho^2`` makes the terms in
``rho/x`` cancel, ``dS/da_e = 2 pi vartheta a_e rho^2/(A H)``::

    G = vartheta d^2 a_e rho(x)^2/(2 A H c) = vartheta d^2 a_e^3/(2 c_1 H^3 c sigma(x)^2),   sigma = x/rho,   (J.20)

``c_1 = A m_1``.  ``x -> oo`` (``rho -> 1 - 1/(2x)``): ``a_e rho^2 = c + h^* H + O(H^2/c)`` with
``h = h^* + sqrt(m_1)`` (I.12), the compressible (J.10); ``x -> 0`` (``sigma -> 2``): the incompressible (J.15).

(J.21) *The smooth part* is the two-term sphere (I.11) at the model edge ``a_e``:
``delta_1 = a_e^2 (1 - 2 psi(x))/(2R)``, ``P_1 = pi vartheta a_e^6 chi(x)/(R c_1 H^3)``.

(J.22) *JKR,* ``G = w`` with the tensile root (J.5)::

    d = -sigma(x) sqrt(2 c_1 H^3 w c/(vartheta a_e^3)),   delta = delta_1 + d,   P = P_1 + S d,          (J.22)

finite at ``nu = 1/2`` (``c_1 = 2/3``, ``sigma(0) = 2``, ``S = 3 pi vartheta a_e^4/(16 H^3)``).

(J.23) *Pull-off* under load control: ``-min_c P(c)`` (numerical minimum).  In the limits ``2 pi w R``
(compressible, (J.12)) and ``3 pi w R`` (incompressible, (J.15)); at nu = 0.49 it is ``2.36 pi w R`` at
``R = 1000 H`` (``c_p = 12 H``, ``lambda^2 = 9.6``), within 6.2e-3 of the direct solver's (5.1e-4 at ``R = 10^4 H``).

The derivation is carried out in sympy by :func:`two_term_jkr_derivation` and checked on the ladder
(``==``, expand/cancel, simplify) with mpmath values beside; the limits are series identities (``x -> 0``: the
Maclaurin series of ``I_0, I_1``; ``x -> oo``: Hankel's expansion, DLMF 10.40.1).  Measured against the direct
solver (``tests/adhesion/test_two_term_jkr.py``; ``R = c^2/(2H)``, ``w`` such that ``d = -delta_1/4``), relative
errors of ``delta`` and ``P``:

    ======  ====  =======  =================  =================  =================
    nu      c/H   lambda^2 two-term (J.22)    compressible (J.11) incompressible (J.15)
    ======  ====  =======  =================  =================  =================
    0.45     5     11.5    2.4e-2   5.9e-2    0.19    0.20       3.9e-2  1.4
    0.45    40     733     3.5e-5   1.6e-4    3.6e-3  4.1e-4     0.30    41
    0.49     5     1.63    0.10     7.7e-2    1.0     1.6        0.17    0.49
    0.49    10     6.51    1.6e-2   3.9e-2    0.40    0.48       4.4e-2  0.80
    0.49    20     26.0    1.6e-3   6.6e-3    0.11    5.9e-2     0.18    2.5
    0.49    40     104     1.6e-4   7.4e-4    2.8e-2  6.2e-3     0.26    9.0
    0.499    5     0.15    0.19     7.9e-2    (c + h* H < 0)     0.22    0.28
    0.499   20     2.42    9.9e-3   1.7e-2    0.95    1.6        2.3e-2  0.30
    0.499   40     9.68    1.2e-3   3.8e-3    0.33    0.32       0.11    0.98
    ======  ====  =======  =================  =================  =================

The two-term law's remainder falls like ``(H/c)^3`` in ``delta`` (slopes 3.06, 3.3, 3.06 between c/H = 20 and 40
at nu = 0.45, 0.49, 0.499) and in ``P`` (3.05, 3.16; 2.1 at nu = 0.499, still in the crossover), where (J.11)
and (J.15) fail by tens of percent.  :meth:`TwoTermJKR.error_estimate` (``2 (h H/c)^2`` relative, an envelope) is
at most 0.73 of the true error on this grid.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import InputError, positive, positive_radii
from .._checks import work_of_adhesion as check_work
from ..display import RichDisplay
from ..layers.kernels import BondedLayer, IncompressibleLayer
from ..normal import normal_latex
from .adhesion import A, R, c, thin_layer_jkr, w
from .flat_punch import psi as flat_psi
from .incompressible import two_term_edge_shift, two_term_sphere

__all__ = ["TwoTermJKR", "TwoTermJKRDerivation", "two_term_jkr", "two_term_jkr_derivation"]

vt, H, d = S.vartheta, S.H, sp.Symbol("d", real=True)
m1, c1 = sp.symbols("m_1 c_1", positive=True)
k, x, r = sp.symbols("k x r", positive=True)
a_e = sp.Symbol("a_e", positive=True)
u = sp.Symbol("u", positive=True)  # 1/x, Hankel's variable
rho_f, sigma_f, psi_f, chi_f, psiF_f = (sp.Function(n) for n in ("rho", "sigma", "psi", "chi", "psi_F"))
h_star = sp.Symbol("h^*", real=True)


def _ladder(lhs: sp.Expr, rhs: sp.Expr, what: str) -> str:
    """``lhs == rhs`` by ``==``, then cancel(expand) of the difference, then simplify; the rung that held."""
    if lhs == rhs:
        return "=="
    diff = sp.cancel(sp.expand(lhs - rhs))
    if diff == 0:
        return "expand/cancel"
    if sp.simplify(diff) == 0:
        return "simplify"
    raise ArithmeticError(f"{what}: {lhs} != {rhs}")


def _hankel(nu_order: int, n: int) -> sp.Expr:
    """``sqrt(2 pi x) e^{-x} I_nu(x) ~ sum_k (-1)^k a_k(nu) u^k``, ``u = 1/x`` (DLMF 10.40.1), n terms."""
    mu4 = 4 * nu_order**2
    out, a = sp.Integer(0), sp.Integer(1)
    for kk in range(n):
        out += (-1) ** kk * a * u**kk
        a = a * (mu4 - (2 * kk + 1) ** 2) / ((kk + 1) * 8)
    return out


def _trunc(expr: sp.Expr, var: sp.Symbol, n: int) -> sp.Expr:
    """``expr`` (a polynomial in ``var``) without the powers ``>= n``."""
    return sum((term for term in sp.Add.make_args(sp.expand(expr)) if sp.degree(term, var) < n), sp.Integer(0))


def _trunc_inv(q: sp.Expr, var: sp.Symbol, n: int) -> sp.Expr:
    """``1/q`` to ``O(var^n)`` for a polynomial ``q`` with ``q(0) = 1`` (the geometric series of ``1 - q``)."""
    if sp.expand(q).subs(var, 0) != 1:
        raise ArithmeticError(f"{q} does not start with 1")
    s, out, term = 1 - q, sp.Integer(1), sp.Integer(1)
    for _ in range(1, n):
        term = _trunc(term * s, var, n)
        out += term
    return _trunc(out, var, n)


@dataclass(frozen=True)
class TwoTermJKRDerivation(RichDisplay):
    """The steps (J.19)-(J.22) in sympy, with the rungs of the checks that held.

    Attributes
    ----------
    pressure : sympy.Expr
        ``p(r)`` of the two-term flat punch (J.19) in ``r, k, a_e, d, A, H, vartheta``.
    stiffness : sympy.Expr
        ``S`` (J.19) in ``rho(x)``, ``x = k a_e``.
    release_rate : sympy.Expr
        ``G`` (J.20) in ``d, a_e, c, sigma(x)``.
    depth, force : sympy.Expr
        sympy.Expr
        ``delta(c)`` and ``P(c)`` of (J.22) in ``a_e, x`` and the functions ``psi, chi, sigma`` of ``x``.
    checks : tuple of (str, str)
        ``(what, rung)`` of every symbolic check.
    """

    pressure: sp.Expr
    stiffness: sp.Expr
    release_rate: sp.Expr
    depth: sp.Expr
    force: sp.Expr
    checks: tuple

    equation = "J.19-J.22"

    def steps(self) -> list[tuple[str, str]]:
        """``(tag, LaTeX)`` of every step."""
        X = sp.Symbol("x")
        f = {fn(x): sp.Function(fn.__name__)(X) for fn in (rho_f, sigma_f, psi_f, chi_f, psiF_f)}
        return [("J.19", rf"p = {normal_latex(self.pressure)},\quad S = {normal_latex(self.stiffness.subs(f))}"
                         r",\quad \rho = \frac{I_1}{I_0},\ x = k a_e,\ k^2 = \frac{1}{m_1 H^2} \tag{J.19}"),
                ("J.20", rf"G = \frac{{d^2 S'(c)}}{{4\pi c}} = {normal_latex(self.release_rate.subs(f))},"
                         r"\quad \sigma = \frac{x}{\rho} \tag{J.20}"),
                ("J.22", rf"\delta = {normal_latex(self.depth.subs(f))},\quad P = {normal_latex(self.force.subs(f))},"
                         r"\quad a_e = c + h H \tag{J.22}")]

    def latex(self) -> str:
        return "\n".join(rf"\[ {tex} \]" for _, tex in self.steps())

    def text_lines(self) -> list[str]:
        return ["TwoTermJKRDerivation: JKR through the two-term model (I.10)   (J.19)-(J.22)",
                f"  S = {self.stiffness}", f"  G = {self.release_rate}", f"  delta = {self.depth}",
                f"  P = {self.force}", *(f"  check {what}: {rung}" for what, rung in self.checks)]


@lru_cache(maxsize=1)
def two_term_jkr_derivation() -> TwoTermJKRDerivation:
    """Carry out (J.19)-(J.22) in sympy and check the limits (J.10)/(J.11) and (J.15) (a few seconds, cached)."""
    checks = []
    # (J.19) the flat punch in the two-term model: (H/vartheta)(A p - A m_1 H^2 Delta p) = d, p(a_e) = 0
    B = sp.Symbol("B")
    p = vt * d / (A * H) + B * sp.besseli(0, k * r)
    op = H / vt * (A * p - A * m1 * H**2 * (sp.diff(p, r, 2) + sp.diff(p, r) / r))
    checks.append(("(I.10) solved", _ladder(sp.simplify(op.subs(m1, 1 / (k * H) ** 2)), d, "(J.19) the ODE")))
    p = p.subs(B, sp.solve(p.subs(r, a_e), B)[0])
    P = 2 * sp.pi * sp.integrate(sp.expand(p * r), (r, 0, a_e))
    S_c = sp.diff(P, d)
    S_rho = sp.pi * vt * a_e**2 / (A * H) * (1 - 2 * rho_f(x) / x)
    back = {rho_f(x): sp.besseli(1, k * a_e) / sp.besseli(0, k * a_e), x: k * a_e}
    checks.append(("(J.19) S", _ladder(S_c, S_rho.subs(back), "(J.19) the stiffness")))
    # (J.20) G = d^2 S'(c)/(4 pi c), a_e = c + h H (dS/dc = dS/da_e)
    dS = sp.diff(S_c, a_e)
    G_rho = vt * d**2 * a_e * rho_f(x) ** 2 / (2 * A * H * c)
    checks.append(("(J.20) G", _ladder(sp.simplify(sp.expand_func(d**2 * dS / (4 * sp.pi * c))),
                                       sp.expand_func(G_rho.subs(back)), "(J.20) the release rate")))
    G = vt * d**2 * a_e**3 / (2 * c1 * H**3 * c * sigma_f(x) ** 2)  # rho = x/sigma, x^2 = a_e^2/(m_1 H^2)
    checks.append(("(J.20) in sigma", _ladder(G.subs({sigma_f(x): x / rho_f(x)}).subs(x, a_e / (sp.sqrt(m1) * H))
                                              .subs(c1, A * m1), G_rho.subs(x, a_e / (sp.sqrt(m1) * H)), "(J.20)")))
    # mpmath: dS/da_e against a numerical derivative, one point
    num = {vt: 1.3, A: 0.2, H: 1.0, k: 0.7, d: -0.1, c: 3.0}
    f = sp.lambdify(a_e, S_c.subs(num), "mpmath")
    exact = sp.lambdify(a_e, (2 * sp.pi * vt * a_e * (sp.besseli(1, k * a_e) / sp.besseli(0, k * a_e)) ** 2
                              / (A * H)).subs(num), "mpmath")
    if abs(mpmath.diff(f, 4.0) / exact(4.0) - 1) > 1e-12:
        raise ArithmeticError("(J.20): dS/da_e differs from 2 pi vartheta a_e rho^2/(A H) numerically")
    # (J.22) G = w, the tensile root; the smooth part (J.21)
    d_jkr = -sigma_f(x) * sp.sqrt(2 * c1 * H**3 * w * c / (vt * a_e**3))
    checks.append(("(J.22) G = w", _ladder(G.subs(d, d_jkr), w, "(J.22)")))
    S_psi = sp.pi * vt * a_e**4 * psiF_f(x) / (8 * c1 * H**3)  # (J.19) with 1 - 2 rho/x = x^2 psi_F/8 (F.15)
    depth = a_e**2 * (1 - 2 * psi_f(x)) / (2 * R) + d_jkr
    force = sp.pi * vt * a_e**6 * chi_f(x) / (R * c1 * H**3) + S_psi * d_jkr
    # limit x -> 0 (k -> 0 at fixed c_1): (J.15).  Maclaurin series of rho, psi, chi, psi_F
    X = sp.Symbol("X", positive=True)
    I0s, I1s = (sum(((X / 2) ** (2 * j + n) / (sp.factorial(j) * sp.factorial(j + n)) for j in range(5)),
                    sp.Integer(0)) for n in (0, 1))
    for n, ser_n in ((0, I0s), (1, I1s)):  # the Maclaurin series of I_n, against sympy's own expansion
        if sp.expand(sp.series(sp.besseli(n, X), X, 0, 10).removeO() - ser_n) != 0:
            raise ArithmeticError(f"the Maclaurin series of I_{n}")

    def at0(num: sp.Expr, den: sp.Expr) -> sp.Expr:  # the value at X = 0 of a ratio of truncated series
        return sp.cancel(sp.expand(num) / sp.expand(den)).subs(X, 0)

    psi0 = at0(X * I0s - 2 * I1s, X**2 * I1s)  # psi of (I.11) = (X I_0/I_1 - 2)/X^2
    ser = {sigma_f(x): at0(X * I0s, I1s), psiF_f(x): at0(8 * (X * I0s - 2 * I1s), X**3 * I0s),
           chi_f(x): at0(X**2 * I1s - 4 * X * I0s + 8 * I1s, 4 * X**4 * I1s), psi_f(x): psi0}
    if (ser[sigma_f(x)], ser[psiF_f(x)], ser[chi_f(x)], psi0) != (2, 1, sp.Rational(1, 96), sp.Rational(1, 4)):
        raise ArithmeticError(f"the values at x = 0 of sigma, psi_F (F.15), chi, psi (I.11): {ser}")
    inc = thin_layer_jkr(0.5, 1)
    c1v = sp.Rational(2, 3)  # (I.1)
    dep0 = depth.subs(ser)
    for_0 = force.subs(ser)
    checks.append(("x -> 0: (J.15) delta", _ladder(dep0.subs(c1, c1v), inc.depth_display,
                                                   "(J.15) depth")))
    checks.append(("x -> 0: (J.15) P", _ladder(for_0.subs(c1, c1v), inc.force_display,
                                               "(J.15) force")))
    # limit x -> oo: Hankel's expansion of rho = I_1/I_0 in u = 1/x; a_e = c + (h* + sqrt(m_1)) H (I.12)
    rho_u = _trunc(_hankel(1, 4) * _trunc_inv(_hankel(0, 4), u, 3), u, 3)
    r40 = mpmath.besseli(1, 40) / mpmath.besseli(0, 40)  # mpmath: the expansion's remainder at x = 40 is O(u^3)
    if abs(float(rho_u.subs(u, sp.Rational(1, 40))) - float(r40)) > 40.0**-3:
        raise ArithmeticError("Hankel's expansion of I_1/I_0 fails at x = 40")
    eps = sp.Symbol("epsilon", positive=True)  # H -> eps H: the order in H/c
    big = {u: sp.sqrt(m1) * eps * H / a_e}
    to_c = {a_e: c + (h_star + sp.sqrt(m1)) * eps * H}

    def vanishes_to(expr: sp.Expr, n: int) -> bool:  # expr(eps) = O(eps^(n+1)): its first n + 1 Taylor terms
        return all(sp.cancel(sp.diff(expr, eps, j).subs(eps, 0)) == 0 for j in range(n + 1))

    comp = thin_layer_jkr(0.3, 1)  # (J.10), (J.11): symbolic in A, h*
    # G: a_e rho^2 = c + h* H + O(H^2/c), i.e. G / G_(J.10) = 1 + O((H/c)^2)
    G_ratio = (G_rho.subs(rho_f(x), rho_u).subs(H, eps * H).subs(big).subs(to_c)
               / comp.release_rate.subs(H, eps * H))
    if not vanishes_to(G_ratio - 1, 1):
        raise ArithmeticError("x -> oo: G is not (J.10) to O(H)")
    checks.append(("x -> oo: (J.10) G", "expand/cancel"))
    psi_u = _trunc(u * _trunc_inv(rho_u, u, 3) - 2 * u**2, u, 3)  # psi = (x/rho - 2)/x^2
    dep_big = (a_e**2 * (1 - 2 * psi_u) / (2 * R)).subs(big).subs(to_c)
    d1_ref = (c + h_star * eps * H) ** 2 / (2 * R) + m1 * (eps * H) ** 2 / R  # (J.11) and the m_1 term of (SO.10)
    if not vanishes_to(dep_big - d1_ref, 2):
        raise ArithmeticError("x -> oo: delta_1 is not (J.11) + m_1 H^2/R to O(H^2)")
    checks.append(("x -> oo: (J.11) delta_1 to O(H^2)", "expand/cancel"))
    return TwoTermJKRDerivation(p, S_rho, G, depth, force, tuple(checks))


# --------------------------------------------------------------------------- numbers
def _rho(xv: np.ndarray) -> np.ndarray:
    """``I_1(x)/I_0(x)``, stable for every ``x >= 0`` (scaled Bessel functions; ``x/2`` below 1e-8)."""
    from scipy import special

    xv = np.asarray(xv, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):
        big = special.ive(1, xv) / special.ive(0, xv)
    return np.where(xv < 1e-8, xv / 2, np.where(np.isinf(xv), 1.0, big))


@dataclass(frozen=True)
class TwoTermJKR(RichDisplay):
    """Thin-layer JKR for the paraboloid ``r^2/(2R)`` on a nearly incompressible bonded layer (J.19)-(J.23).

    Attributes
    ----------
    nu : float
        Poisson ratio, ``1/4 < nu <= 1/2``.
    A, m1, c1 : float
        float
        ``A`` (2.4), ``m_1`` (2.20) and ``c_1 = A m_1`` (I.1); at nu = 1/2 ``A = 0``, ``m_1 = inf``, ``c_1 = 2/3``.
    h : float
        Edge correction ``h(nu)`` (I.12).
    """

    nu: float
    A: float
    m1: float
    c1: float
    h: float

    equation = "J.22"

    @property
    def derivation(self) -> TwoTermJKRDerivation:
        """The symbolic steps (J.19)-(J.22) (:func:`two_term_jkr_derivation`, cached; seconds of sympy)."""
        return two_term_jkr_derivation()

    def _parts(self, radius: Any, H: Any, R: Any, work_of_adhesion: Any, mu: Any):
        cv = positive_radii(radius)
        Hv, Rv, wv = positive(H, "H"), positive(R, "R"), check_work(work_of_adhesion)
        vtv = positive(mu, "mu") / (1 - self.nu)
        ae = cv + self.h * Hv
        xv = self._x(ae, Hv)
        sigma = self._sigma(xv)
        layer = BondedLayer(self.nu) if self.A > 0 else IncompressibleLayer()
        d1, P1 = two_term_sphere(layer).lambdify()(ae, Rv, Hv, positive(mu, "mu"))  # (I.11) at a_e (J.21)
        Sv = np.pi * vtv * ae**4 * flat_psi(xv) / (8 * self.c1 * Hv**3)  # (J.19)
        dj = -sigma * np.sqrt(2 * self.c1 * Hv**3 * wv * cv / (vtv * ae**3))  # (J.22)
        return np.asarray(d1, float), np.asarray(P1, float), Sv, dj

    def _x(self, a_e: np.ndarray, H: float) -> np.ndarray:
        return a_e / (math.sqrt(self.m1) * H) if self.A > 0 else np.zeros_like(a_e)

    def stiffness(self, radius: Any, H: Any, mu: Any = 1.0) -> np.ndarray:
        """``S = dP/dd`` of the two-term flat punch of contact radius ``c`` (J.19), vectorised in ``c``."""
        cv, Hv = positive_radii(radius), positive(H, "H")
        ae = cv + self.h * Hv
        return np.pi * positive(mu, "mu") / (1 - self.nu) * ae**4 * flat_psi(self._x(ae, Hv)) / (8 * self.c1 * Hv**3)

    def release_rate(self, radius: Any, flat_depth: Any, H: Any, mu: Any = 1.0) -> np.ndarray:
        """``G = vartheta d^2 a_e^3/(2 c_1 H^3 c sigma(x)^2)`` (J.20), vectorised in ``c``."""
        cv, Hv = positive_radii(radius), positive(H, "H")
        ae = cv + self.h * Hv
        sig = self._sigma(self._x(ae, Hv))
        return (positive(mu, "mu") / (1 - self.nu) * np.asarray(flat_depth, float) ** 2 * ae**3
                / (2 * self.c1 * Hv**3 * cv * sig**2))

    @staticmethod
    def _sigma(xv: np.ndarray) -> np.ndarray:
        rho = _rho(xv)
        return np.where(xv < 1e-8, 2.0, xv / np.where(rho > 0, rho, 1.0))

    def evaluate(self, radius: Any, H: Any, R: Any, work_of_adhesion: Any, mu: Any = 1.0
                 ) -> tuple[np.ndarray, np.ndarray]:
        """``(delta, P)`` of (J.22), vectorised in the contact radius ``c``; ``vartheta = mu/(1 - nu)``."""
        d1, P1, Sv, dj = self._parts(radius, H, R, work_of_adhesion, mu)
        return d1 + dj, P1 + Sv * dj

    def error_estimate(self, radius: Any, H: Any, R: Any, work_of_adhesion: Any, mu: Any = 1.0
                       ) -> tuple[np.ndarray, np.ndarray]:
        """Absolute error estimates ``(delta, P)``: ``2 (h H/c)^2`` times the flat part ``|d|`` and the smooth depth,
        ``2 (h H/c)^2 |P|`` plus ``2 (h H/c)^2 S |d|`` (the first neglected order of (I.11), (J.19) is
        ``(H/c)^2`` relative).  An envelope of the remainders measured against the direct solver
        (``tests/adhesion/test_two_term_jkr.py``), not a derived bound.
        """
        cv = positive_radii(radius)
        d1, P1, Sv, dj = self._parts(cv, H, R, work_of_adhesion, mu)
        e = 2 * (self.h * positive(H, "H") / cv) ** 2
        return e * (np.abs(d1) + np.abs(dj)), e * (np.abs(P1) + np.abs(Sv * dj))

    def pull_off(self, H: Any, R: Any, work_of_adhesion: Any, mu: Any = 1.0) -> tuple[float, float]:
        """``(c, -min P)`` under load control (J.23): a grid, then golden-section refinement."""
        from scipy import optimize

        Hv, Rv, wv = positive(H, "H"), positive(R, "R"), positive(work_of_adhesion, "work_of_adhesion")
        grid = Hv * np.geomspace(1e-1, 1e5, 601)
        P = self.evaluate(grid, Hv, Rv, wv, mu)[1]
        i = int(np.argmin(P))
        lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
        res = optimize.minimize_scalar(lambda cc: float(self.evaluate(cc, Hv, Rv, wv, mu)[1]), bounds=(lo, hi),
                                       method="bounded", options={"xatol": 1e-12 * hi})
        return float(res.x), -float(res.fun)

    def latex(self) -> str:
        return self.derivation.latex()

    def text_lines(self) -> list[str]:
        return [f"TwoTermJKR: paraboloid on a bonded layer, nu = {self.nu:g}, two-term model   (J.19)-(J.23)",
                f"  delta = {self.derivation.depth}", f"  P = {self.derivation.force}",
                f"  a_e = c + h H, x = a_e/(sqrt(m_1) H); A = {self.A:.12g}, m_1 = {self.m1:.12g}, "
                f"c_1 = {self.c1:.12g}, h = {self.h:.12g}"]


def two_term_jkr(nu: Any) -> TwoTermJKR:
    """JKR of the paraboloid on a nearly incompressible bonded layer through the two-term model (J.19)-(J.23).

    Parameters
    ----------
    nu : float
        Poisson ratio, ``1/4 < nu <= 1/2`` (the two-term model needs ``m_1 > 0``).  Valid for ``c >> H`` at any
        ``lambda^2 = (c/H)^2/m_1`` (I.13).

    Returns
    -------
    TwoTermJKR

    Examples
    --------
    The JKR state at the contact radius ``c = 10 H`` of a sphere ``R = 50 H`` on a layer with nu = 0.49
    (``lambda^2 = 6.5``: neither (J.11) nor (J.15) holds); its flat part satisfies ``G = w`` (J.20):

    >>> law = two_term_jkr(0.49)
    >>> delta, P = law.evaluate(10.0, H=1.0, R=50.0, work_of_adhesion=0.05)
    >>> d = float(delta) - float(law.evaluate(10.0, 1.0, 50.0, 0.0)[0])
    >>> round(float(law.release_rate(10.0, d, H=1.0)), 12)
    0.05
    """
    try:
        val = float(nu)
    except (TypeError, ValueError):
        raise InputError(f"nu must be a number in (1/4, 1/2], got {nu!r}") from None
    if not 0.25 < val <= 0.5:
        raise InputError(f"nu must lie in (1/4, 1/2] (the two-term model needs m_1 > 0), got {nu!r}")
    if val == 0.5:
        return TwoTermJKR(val, 0.0, math.inf, 2.0 / 3.0, float(two_term_edge_shift(dps=16)))
    lay = BondedLayer(val)
    Av, m1v = float(lay.A), float(lay.m(1))
    return TwoTermJKR(val, Av, m1v, Av * m1v, float(two_term_edge_shift(lay, dps=16)))
