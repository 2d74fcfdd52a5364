r"""Thick layers under a polyhedral tip (a pyramid): the layer as a half-space problem with a shifted depth and a
perturbed profile, (T.10)-(T.13) (issue 24 item 3).  Equation tags continue :mod:`~thinlayer.asymptotics.thick_layer`'s.

Derivation
----------
(T.10) *The regular kernel acts through moments.*  With (T.1)-(T.2), ``L = 1 + (L - 1)`` and
``2 pi vartheta H K(s) = -sum_k (-1)^k b_k (s/(2H))^{2k}/(k!)^2`` (:func:`~thinlayer.asymptotics.thick_layer.
regular_kernel`), the contact condition on omega of ANY punch, axisymmetric or not, is

    (1/(2 pi vartheta)) iint p(y)/|x - y| dy = delta0 - Phi(x) - (1/(2 pi vartheta H)) iint p(y) k(|x - y|) dy,

``k(s) = 2 pi vartheta H K(s)``.  Expanding ``|x - y|^{2k} = (|x|^2 - 2 x.y + |y|^2)^k`` (sympy, :func:`kernel_action`),
the regular term is a polynomial in x whose coefficients are linear in the pressure's moments
``M_alpha = iint p y^alpha`` (``M_0 = P``):

    delta0 - Phi(x) - sum_beta x^beta C_beta(M)/(2 pi vartheta H).

So the layer is the half-space under the punch ``Phi_e = Phi + sum_{beta != 0} eps_beta x^beta`` at the depth
``delta_e = delta0 - C_0(M)/(2 pi vartheta H)``, ``eps_beta = C_beta(M)/(2 pi vartheta H)``.  Order by order:
``k = 0`` is the uniform shift ``delta_e = delta0 + b_0 P/(2 pi vartheta H)`` (the total force alone); ``k = 1``
(``H^-3``) adds ``-b_1 (P |x|^2 - 2 x.M_1 + M_2)/(8 pi vartheta H^3)``, ``M_2 = iint p |y|^2`` (the trace of the
second moments ``iint p y_i y_j``); ``k = 2`` (``H^-5``) the moments to order 4, ``iint p (x.y)^2`` the full
second-moment tensor.  The series in ``1/H`` converges for ``|x - y| < 2H`` (T.2).

(T.11) *The half-space answers to a perturbed profile, from one energy.*  For frictionless unilateral contact the
elastic energy at equilibrium ``W(delta0, eps)`` (punch ``Phi + sum eps_beta x^beta``) is stationary in the contact set,
so ``dW/d delta0 = P`` and ``dW/d eps_beta = -M_beta``: the force's answer to a profile perturbation is
``dP/d eps_beta = -dM_beta/d delta0`` (Maxwell's reciprocity).  A polyhedral tip is homogeneous of degree 1, so the
half-space solution is self-similar: with ``t = tan(alpha)`` (alpha the face angle; for any ``max`` of planes
``t = 1`` and the constants below are the tip's),

    P_hs = K vartheta t delta0^2,     M_alpha = mu_alpha vartheta t^{|alpha|+1} delta0^{|alpha|+2},
    W = vartheta t delta0^3 [K/3 - sum_beta e_beta mu_beta + (1/2) sum w_{beta gamma} e_beta e_gamma],
    e_beta = eps_beta t^{|beta|} delta0^{|beta| - 1}

(K, mu_alpha numbers of the tip's shape; the second-order responses ``w_{beta gamma}`` are NOT moments of the
half-space solution: they are left as unknown symbols).

(T.12) *The series.*  Substituting (T.11) into (T.10) and iterating to a fixed point in ``chi = delta0 t/H``
(:func:`polyhedral_thick_series`, exact in sympy):

    P = K vartheta t delta0^2 (1 + sum_{m>=1} f_m chi^m),

    f_1 = 2 beta,  f_2 = 5 beta^2,  f_3 = 14 beta^3 - 3 b_1 m_2/(4 pi),  ...,   beta = b_0 K/(2 pi),

(the shift alone gives the Catalan numbers ``F = (1 + beta chi F)^2``), ``m_2 = iint p |y|^2``, ``m_4 = iint p |y|^4``
in the units of (T.11).  For the regular pyramids (symmetry D_3, D_4: ``M_1 = 0``, ``iint p y_i y_j =
(m_2/2) delta_ij``) the coefficients through ``f_5`` hold K, m_2 and m_4 only.  The unknown ``w`` first appear in
``f_6``: **the series of the force is exact through chi^5 in three half-space numbers; its remainder is O(chi^6)**
(:attr:`PolyhedralThickSeries.exact_order`, derived, not assumed).  ``b_2`` enters at chi^5, ``b_3`` at chi^7.

(T.13) *The half-space numbers of the regular pyramids* (:data:`HALF_SPACE_CONSTANTS`) come from
:func:`thinlayer.numerics.solve_2d` on the half-space (nothing closed-form is known for a polygonal contact) by
refinement, see the constants' comment; their uncertainty is carried into the estimate.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import sympy as sp

from ..display import RichDisplay, fmt
from ..errors import InputError
from ..results import latex_equation
from .thick_layer import moment_symbols, regular_kernel

__all__ = [
    "HALF_SPACE_CONSTANTS",
    "PolyhedralThickSeries",
    "PyramidThickLaw",
    "PyramidThickValues",
    "pyramid_thick_law",
    "kernel_action",
    "polyhedral_thick_series",
    "symmetric_moments",
]

#: chi = delta0 tan(alpha)/H, the force constant K of (T.11), the coordinates of (T.10)
chi_sym = sp.Symbol("chi", positive=True)
K_sym = sp.Symbol("K", positive=True)
m2_sym = sp.Symbol("m_2", positive=True)
m4_sym = sp.Symbol("m_4", positive=True)
_x1, _x2, _y1, _y2 = sp.symbols("x1 x2 y1 y2", real=True)
_d = sp.Symbol("delta", positive=True)
#: largest order of :func:`polyhedral_thick_series` (order 7 needs b_3 and the moments to order 6: slow and unused)
MAX_POLYHEDRAL_ORDER = 6


def _mu(a: int, b: int) -> sp.Symbol:
    """``mu_{a,b}``: the half-space moment ``iint p y1^a y2^b`` in the units of (T.11) (``mu_{0,0} = K``)."""
    return K_sym if a == b == 0 else sp.Symbol(f"mu_{a}{b}", real=True)


def _monomials(top: int) -> list[tuple[int, int]]:
    return [(a, n - a) for n in range(top + 1) for a in range(n, -1, -1)]


@lru_cache(maxsize=8)
def kernel_action(kmax: int) -> dict[tuple[int, int], sp.Expr]:
    r"""``{beta: C_beta}`` of (T.10) with ``H = 1``: ``iint p(y) k(|x - y|) dy = sum_beta x^beta C_beta(M)``, ``C_beta``
    linear in the moments ``M_{a,b}`` (sympy Symbols ``M_ab``; ``M_00 = P``), through the kernel term ``b_kmax``.

    Examples
    --------
    >>> kernel_action(1)[(0, 0)]
    -M_00*b_0 + M_02*b_1/4 + M_20*b_1/4
    """
    s = sp.Symbol("s")
    rk = sp.expand(regular_kernel(kmax, s).subs(sp.Symbol("H", positive=True), 1))
    q = (_x1 - _y1) ** 2 + (_x2 - _y2) ** 2
    total = sp.expand(sp.Add(*[rk.coeff(s, 2 * k) * q**k for k in range(kmax + 1)]))
    out: dict[tuple[int, int], sp.Expr] = {}
    for (a1, a2, c1, c2), coef in sp.Poly(total, _x1, _x2, _y1, _y2).terms():
        out[(a1, a2)] = out.get((a1, a2), sp.Integer(0)) + coef * sp.Symbol(f"M_{c1}{c2}")
    return out


@lru_cache(maxsize=8)
def symmetric_moments(sides: int, top: int) -> dict[sp.Symbol, sp.Expr]:
    r"""The relations among the moments ``mu_{a,b}`` (``a + b <= top``) of a pressure with the regular pyramid's
    symmetry D_sides (rotation by ``2 pi/sides`` and the reflection ``x1 -> -x1``, :mod:`thinlayer.punch.pyramid`'s
    orientation): ``{mu: its value in the remaining ones}``, from ``iint p y^alpha = iint p (g y)^alpha`` solved by
    sympy degree by degree.

    Examples
    --------
    >>> symmetric_moments(4, 2)
    {mu_01: 0, mu_10: 0, mu_11: 0, mu_20: mu_02}
    """
    if sides not in (3, 4):
        raise InputError(f"sides must be 3 or 4, got {sides!r}")
    c, s = sp.cos(2 * sp.pi / sides), sp.sin(2 * sp.pi / sides)
    maps = [(c * _y1 - s * _y2, s * _y1 + c * _y2), (-_y1, _y2)]
    out: dict[sp.Symbol, sp.Expr] = {}
    for n in range(1, top + 1):
        mons = [(a, n - a) for a in range(n, -1, -1)]
        eqs = []
        for g1, g2 in maps:
            for a, b in mons:
                image = sp.Poly(sp.expand(g1**a * g2**b), _y1, _y2)
                eqs.append(sp.Add(*[cf * _mu(*m) for m, cf in image.terms()]) - _mu(a, b))
        unknowns = [_mu(a, b) for a, b in mons]
        sol = sp.solve(eqs, unknowns, dict=True)[0]
        out.update({k: sp.expand(v) for k, v in sol.items()})
    return out


@dataclass(frozen=True, eq=False)
class PolyhedralThickSeries(RichDisplay):
    r"""The force of a polyhedral tip on a thick layer (T.12): ``P = K vartheta t delta0^2 (1 + sum f_m chi^m)``.

    Attributes
    ----------
    order : int
        Highest power of ``chi = delta0 tan(alpha)/H`` derived.
    sides : int or None
        3 or 4 (the regular pyramid's symmetry applied, coefficients in ``K, m_2, m_4``), or None (any polyhedral tip:
        coefficients in the moments ``mu_ab``).
    coefficients : tuple of sympy.Expr
        ``(1, f_1, ..., f_order)`` in ``b_k`` (T.2), ``K``, the moments and the unknown second-order responses
        ``w_...`` of (T.11).
    exact_order : int
        The highest order whose coefficient is free of the unknown ``w``: the law is exact through ``chi^exact_order``
        and its remainder is ``O(chi^(exact_order + 1))``.
    """

    order: int
    sides: int | None
    coefficients: tuple = field(repr=False)
    exact_order: int
    equation = "T.12"

    @property
    def unknowns(self) -> tuple[sp.Symbol, ...]:
        """The second-order responses ``w`` the coefficients hold (those beyond :attr:`exact_order`)."""
        syms = set().union(*(c.free_symbols for c in self.coefficients))
        return tuple(q for q in syms if q.name == "w")

    def force_ratio(self) -> sp.Expr:
        r"""``P/(K vartheta t delta0^2)`` through ``chi^exact_order``."""
        return sp.Add(*[c * chi_sym**m for m, c in enumerate(self.coefficients[: self.exact_order + 1])])

    def latex(self) -> str:
        terms = [sp.latex(sp.factor(c) * chi_sym**m) for m, c in enumerate(self.coefficients[: self.exact_order + 1])]
        return latex_equation(r"\frac{P}{K \vartheta \tan\alpha\, \delta_0^2}",
                              " + ".join(terms) + rf" + O(\chi^{{{self.exact_order + 1}}})", "T.12")

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        what = f"{self.sides}-sided pyramid" if self.sides else "polyhedral tip"
        lines = [f"PolyhedralThickSeries ({what}), chi = delta0 tan(alpha)/H, exact through chi^{self.exact_order}"
                 f" (remainder O(chi^{self.exact_order + 1}))   (T.12)"]
        for m in range(1, min(self.order, self.exact_order) + 1):
            lines.append(f"  f_{m} = {fmt(sp.factor(self.coefficients[m]))}")
        return lines


@lru_cache(maxsize=8)
def _derive(order: int, sides: int | None = None, unknowns: bool = True) -> tuple[sp.Expr, ...]:
    """``(1, f_1, ..., f_order)`` for a general polyhedral tip (T.12), in ``b_k``, ``K``, ``mu_ab`` and ``w``.

    Exact arithmetic in the ring ``QQ[delta, g_k = b_k/pi, K, mu, w]`` (truncated in delta at each product), with
    ``t = H = vartheta = 1`` so that ``delta0 = chi``.  The fixed point of (T.10)-(T.11) from the half-space values.
    """
    from sympy.polys.domains import QQ
    from sympy.polys.rings import ring

    kmax = max((order - 1) // 2, 0)
    C = kernel_action(kmax)
    alphas = [al for al in _monomials(2 * kmax) if al != (0, 0)]
    pairs = [(bt, gm) for i, bt in enumerate(alphas) for gm in alphas[i:]]
    names = (["delta"] + [f"g_{k}" for k in range(kmax + 1)] + ["K"] + [_mu(*al).name for al in alphas]
             + ["w"])
    R, *gens = ring(names, QQ)
    d, g, K = gens[0], gens[1:kmax + 2], gens[kmax + 2]
    mu = dict(zip(alphas, gens[kmax + 3:kmax + 3 + len(alphas)]))
    if sides is not None:  # the pyramid's symmetry first: fewer moments, a far smaller fixed point
        rel = symmetric_moments(sides, 2 * kmax)
        musym = {_mu(*al): mu[al] for al in alphas}
        for al in alphas:
            if _mu(*al) in rel:
                v = sp.expand(rel[_mu(*al)])
                mu[al] = sum((R(QQ(int(sp.Rational(c).p), int(sp.Rational(c).q))) * musym[q]
                              for q, c in v.as_coefficients_dict().items() if q != 1), R(0))
    # the unknown responses w_{beta gamma} as distinct multiples of one marker w (distinct primes: no accidental
    # cancellation), enough to find the first order they enter, at a fraction of the cost of 105 symbols
    w = {}
    wgen = gens[-1]
    for (bt, gm), prime in zip(pairs, sp.primerange(2, 10**4)):
        w[(bt, gm)] = w[(gm, bt)] = wgen * int(prime) if unknowns else R(0)
    top = order + 2 + 2 * kmax

    def trunc(p, deg):
        return R({m: c for m, c in p.items() if m[0] <= deg})

    def mul(p, q):
        return trunc(p * q, top)

    # C_beta/(2 pi) as {beta: [(moment, ring coefficient)]}: b_k/(2 pi) = g_k/2
    bsyms = moment_symbols(kmax)
    lin = {}
    for bt, expr in C.items():
        terms = []
        for term in sp.Add.make_args(sp.expand(expr)):
            coef, rest = term.as_coeff_Mul()
            msym = [f for f in sp.Mul.make_args(rest) if f.name.startswith("M_")][0]
            bk = [f for f in sp.Mul.make_args(rest) if f in bsyms][0]
            al = (int(msym.name[2]), int(msym.name[3]))
            terms.append((al, R(QQ(int(sp.Rational(coef).p), int(sp.Rational(coef).q)) / 2) * g[bsyms.index(bk)]))
        lin[bt] = terms
    M = {(0, 0): K * d**2}
    M.update({al: mu[al] * d ** (sum(al) + 2) for al in alphas})
    for _ in range(order + 1):
        de = d - sum((c * M[al] for al, c in lin[(0, 0)]), R(0))
        eps = {bt: trunc(sum((c * M[al] for al, c in lin.get(bt, ())), R(0)), top) for bt in alphas}
        pw = [R(1), trunc(de, top)]
        for _j in range(2, 4 * kmax + 4):
            pw.append(mul(pw[-1], pw[1]))
        P = K * pw[2]
        new = {}
        for bt in alphas:
            n = sum(bt)
            P -= mul(eps[bt] * mu[bt] * (n + 2), pw[n + 1])
            acc = mu[bt] * pw[n + 2]
            for gm in alphas:
                acc -= mul(w[(bt, gm)] * eps[gm], pw[n + sum(gm) + 1])
            new[bt] = trunc(acc, top)
        for bt, gm in pairs:
            f = 1 if bt == gm else 2
            e = sum(bt) + sum(gm)
            P += mul(mul(eps[bt], eps[gm]) * w[(bt, gm)] * QQ(f * (e + 1), 2), pw[e])
        M = {(0, 0): trunc(P, order + 2), **new}
    out = []
    symbols = ([sp.Symbol("delta")] + [b / sp.pi for b in bsyms] + [K_sym] + [_mu(*al) for al in alphas]
               + [sp.Symbol("w", real=True)])
    for m in range(order + 1):
        term = R({mon: c for mon, c in M[(0, 0)].items() if mon[0] == m + 2})
        e = term.as_expr(*symbols).subs(symbols[0], 1)
        out.append(sp.expand(e / K_sym))
    return tuple(out)


def _exact_order(coefficients: tuple) -> int:
    for m, c in enumerate(coefficients):
        if any(q.name == "w" for q in c.free_symbols):
            return m - 1
    return len(coefficients) - 1


@lru_cache(maxsize=16)
def _series(order: int, sides: int | None) -> PolyhedralThickSeries:
    coefs = _derive(order, sides)
    if sides is not None:
        coefs = _invariants(coefs, sides)
    return PolyhedralThickSeries(order, sides, coefs, _exact_order(coefs))


def polyhedral_thick_series(order: int = 5, sides: int | None = None) -> PolyhedralThickSeries:
    r"""The thick-layer series (T.12) of a polyhedral tip's force, derived from the kernel (T.10) and the energy (T.11).

    Parameters
    ----------
    order : int
        Highest power of ``chi`` derived (1 .. :data:`MAX_POLYHEDRAL_ORDER`; order 6 shows where the unknown
        second-order responses enter).
    sides : int, optional
        3 or 4: apply the regular pyramid's symmetry (coefficients in ``K, m_2, m_4``).

    Examples
    --------
    >>> s = polyhedral_thick_series(3, sides=4)
    >>> s.coefficients[1], s.coefficients[2]
    (K*b_0/pi, 5*K**2*b_0**2/(4*pi**2))
    >>> s.exact_order
    3
    """
    if isinstance(order, bool) or not isinstance(order, int) or not 1 <= order <= MAX_POLYHEDRAL_ORDER:
        raise InputError(f"order must be an integer in [1, {MAX_POLYHEDRAL_ORDER}], got {order!r}")
    if sides is not None and sides not in (3, 4):
        raise InputError(f"sides must be 3, 4 or None (any polyhedral tip), got {sides!r}")
    return _series(order, sides)




# =============================================================================================
# (T.13): the regular pyramids' half-space numbers and the law
# =============================================================================================
#: (T.13) ``K``, ``m_2``, ``m_4`` (units of (T.11)) and the contact area ``|omega| = A t^2 delta0^2`` of the regular
#: pyramids on the half-space, with the uncertainty of each (absolute).  Measured with
#: :func:`thinlayer.numerics.solve_2d` (HalfSpace, tol 1e-11; the square ``[-1.25, 1.25]^2 t delta0`` for 4 sides,
#: ``[-1.8, 1.8] x [-1.3, 2.3] t delta0`` for 3) at n = 128, 256, 512, 1024 (2026-11-26, this branch):
#:
#:   4 sides  K   1.47562768 1.47535120 1.47526329 1.47524088  (order 1.97; Richardson 1.4752334)
#:            m_2 0.30620402 0.30590243 0.30579424 0.30576478  (order 1.88; 0.3057550)
#:            m_4 0.11989427 0.11957595 0.11945457 0.11942036  (order 1.83; 0.1194090)
#:            A   1.47689    1.47783    1.47872    1.47859     (the sub-cell contour, not monotone)
#:   3 sides  K   1.76473701 1.76482248 1.76482632 1.76482476  (converged to 2e-6, not monotone)
#:            m_2 0.67980314 0.68014577 0.68018162 0.68017815
#:            m_4 0.59304488 0.59419970 0.59438088 0.59438518
#:            A   1.77703    1.77390    1.77271    1.77203     (order 0.8; extrapolated 1.7711)
#:
#: The uncertainty is the last difference (m's) or the spread (A), at least; for K 2e-5 relative, the level at which
#: n = 256 direct solutions on the layer and on the half-space disagree with the series beyond its terms (tests).
#: The moments are the cell-averaged ones (``|y|^2 + Delta^2/6`` per cell); the first moments and ``iint p y1 y2`` are
#: below 1e-5 at n = 1024 (zero by symmetry; 8e-5 for 3 sides at n = 256, whose grid is not symmetric).
#: The equivalent cone (same area function, ``tan(alpha_eq)^2 = N tan(pi/N) tan(alpha)^2/pi``, Sneddon's
#: ``K = (4/pi) tan(alpha_eq)/tan(alpha)``) has K = 1.43673 (4 sides: -2.61 %) and 1.63751 (3 sides: -7.21 %).
HALF_SPACE_CONSTANTS: dict[int, dict[str, tuple[float, float]]] = {
    4: {"K": (1.475233, 3e-5), "m_2": (0.305755, 3e-5), "m_4": (0.119409, 3.5e-5), "A": (1.4785, 1.5e-3)},
    3: {"K": (1.764825, 3.5e-5), "m_2": (0.680178, 4e-6), "m_4": (0.594386, 5e-6), "A": (1.7711, 2.5e-3)},
}
#: the order of the law: the series (T.12) is exact through chi^5 (derived: f_6 holds the unknown responses)
LAW_ORDER = 5
#: the series converges while the contact's diameter is below 2H (T.2): chi < 1/sqrt(2) (4 sides, the diagonal
#: 2 sqrt(2) t delta0 of the level set) and 1/sqrt(3) (3 sides, its side 2 sqrt(3) t delta0); the estimate is inf
#: beyond 0.9 of it, as (T.8)
CHI_LIMIT = {4: 0.9 / math.sqrt(2.0), 3: 0.9 / math.sqrt(3.0)}


@lru_cache(maxsize=4)
def _law_coefficients(sides: int):
    """``f(b_0, b_1, b_2, K, m_2, m_4) -> [f_0 .. f_5]`` (numpy), from the derived series (T.12) of the pyramid."""
    b = moment_symbols(2)
    return sp.lambdify((*b, K_sym, m2_sym, m4_sym), list(_series_known(sides)), "math")


@lru_cache(maxsize=4)
def _series_known(sides: int) -> tuple[sp.Expr, ...]:
    """The coefficients ``f_0 .. f_5`` in ``b_k, K, m_2, m_4`` (the law's; no unknowns below order 6), kept in the
    disk cache (thinlayer._cache) as exact rational terms in ``g_k = b_k/pi`` (times K): a fresh process reads them
    instead of deriving them again (2 s).
    """
    from .._cache import cached

    b = moment_symbols(2)
    gens = (*(q / sp.pi for q in b), K_sym, m2_sym, m4_sym)

    def compute() -> tuple:
        coefs = _invariants(_derive(LAW_ORDER, sides, unknowns=False), sides)
        out = []
        for c in coefs:
            poly = sp.Poly(sp.expand(K_sym * c.xreplace({q: g_ * sp.pi for q, g_ in zip(b, sp.symbols("g_0:3"))})),
                           *sp.symbols("g_0:3"), K_sym, m2_sym, m4_sym)
            out.append(tuple((*mon, int(sp.Rational(cf).p), int(sp.Rational(cf).q)) for mon, cf in poly.terms()))
        return tuple(out)

    stored = cached("pyramid_thick_series", (sides, LAW_ORDER), compute)
    # stored times K (f_5 holds b_2 m_2^2/K)
    return tuple(sp.expand(sp.Add(*[sp.Rational(t[-2], t[-1]) * sp.Mul(*[g_**e for g_, e in zip(gens, t[:-2])])
                                    for t in c]) / K_sym) for c in stored)


def _invariants(coefs: tuple, sides: int) -> tuple[sp.Expr, ...]:
    rel = symmetric_moments(sides, 2 * max((len(coefs) - 2) // 2, 0))
    coefs = tuple(sp.expand(c.xreplace(rel)) for c in coefs)
    inv = {}
    for total, name in ((_mu(2, 0) + _mu(0, 2), m2_sym), (_mu(4, 0) + 2 * _mu(2, 2) + _mu(0, 4), m4_sym)):
        kept = sp.expand(total.xreplace(rel))
        pick = sorted(kept.free_symbols, key=lambda q: q.name)
        if pick:
            inv[pick[0]] = sp.solve(kept - name, pick[0])[0]
    return tuple(sp.expand(c.xreplace(inv)) for c in coefs)


@dataclass(frozen=True)
class PyramidThickValues:
    """Numbers of the pyramid's thick-layer law at one depth (T.12), with the relative estimates."""

    delta0: float
    force: float
    contact_area: float
    chi: float
    order: int
    force_error: float
    area_error: float


#: the area's (T.12) shift ``delta_e = delta0 (1 + (b_0 K/(2 pi)) chi F)`` leaves an O(chi^3) remainder (the profile
#: perturbation moves the contour); its constant measured against solve_2d (n = 256, chi = 0.05 .. 0.5, bonded
#: nu = 0.3, 0.45, frictionless, 4 sides) is 0.41 - 0.63 (chi >= 0.2; below, the direct area's own 3e-4): 3x margin
AREA_CHI3 = 2.0


@dataclass(frozen=True, eq=False)
class PyramidThickLaw:
    r"""The thick-layer law (T.12) of a regular pyramid on one layer: ``P = K vartheta t delta0^2 sum_m f_m chi^m``.

    Attributes
    ----------
    sides : int
    tan_alpha : float
        ``t``, the tangent of the face angle.
    coefficients : tuple of float
        ``f_0 .. f_5`` for this layer.
    """

    sides: int
    tan_alpha: float
    coefficients: tuple
    equation = "T.12"

    def terms(self, chi: float) -> list[float]:
        """The series' terms ``f_m chi^m``."""
        return [f * chi**m for m, f in enumerate(self.coefficients)]

    def estimate(self, chi: float) -> tuple[float, float]:
        """Relative estimates (force, contact area): the last two terms (T.8) plus the constants' uncertainty (T.13);
        inf from :data:`CHI_LIMIT` on.
        """
        if not chi < CHI_LIMIT[self.sides]:
            return math.inf, math.inf
        t = self.terms(chi)
        c = HALF_SPACE_CONSTANTS[self.sides]
        force = (abs(t[-1]) + abs(t[-2])) / abs(sum(t)) + c["K"][1] / c["K"][0]
        area = AREA_CHI3 * chi**3 + c["A"][1] / c["A"][0]
        return force, area

    def at_depth(self, delta0: float, H: float, vartheta: float) -> PyramidThickValues:
        """Force and contact area at a depth (T.12)."""
        c = HALF_SPACE_CONSTANTS[self.sides]
        t = self.tan_alpha
        chi = delta0 * t / H
        F = sum(self.terms(chi))
        P = c["K"][0] * vartheta * t * delta0 * delta0 * F
        beta = self.coefficients[1] / 2.0  # b_0 K/(2 pi)
        de = delta0 * (1.0 + beta * chi * F)
        eP, eA = self.estimate(chi)
        return PyramidThickValues(delta0, P, c["A"][0] * (t * de) ** 2, chi, LAW_ORDER, eP, eA)

    def at_force(self, force: float, H: float, vartheta: float) -> PyramidThickValues:
        """The depth for a force (the law is increasing in delta0 below :data:`CHI_LIMIT`; Brent's method)."""
        from scipy import optimize

        top = CHI_LIMIT[self.sides] * H / self.tan_alpha
        if not self.at_depth(top, H, vartheta).force > force:
            raise InputError(f"the force {force:.4g} needs chi = delta0 tan(alpha)/H >= {CHI_LIMIT[self.sides]:.3g}: "
                             "beyond the pyramid's thick-layer series (T.12); use the direct solver")
        lo = top
        while self.at_depth(lo, H, vartheta).force > force:
            lo *= 0.5
            if lo < 1e-300:
                raise InputError(f"the force {force:.4g} is below the range of the thick-layer series (T.12)")
        d = optimize.brentq(lambda x: self.at_depth(x, H, vartheta).force - force, lo, 2 * lo, xtol=1e-15 * lo,
                            rtol=4e-15)
        return self.at_depth(d, H, vartheta)


def pyramid_thick_law(layer: Any, tip: Any) -> PyramidThickLaw:
    r"""The thick-layer law (T.12) of a regular pyramid (3 or 4 sides, numeric face angle) on a layer of finite
    thickness with a numeric kernel (the moments ``b_0, b_1, b_2`` of (T.2)).

    Examples
    --------
    >>> from thinlayer import BondedLayer, Punch
    >>> law = pyramid_thick_law(BondedLayer(0.3), Punch.pyramid(35, 4))
    >>> round(law.coefficients[1], 4)      # f_1 = b_0 K/pi
    0.6465
    """
    from .thick_layer import thick_moments

    if getattr(tip, "kind", None) != "pyramid" or getattr(tip, "parameters", ()):
        raise InputError(f"the pyramid's thick-layer law (T.12) needs Punch.pyramid(angle, sides=3|4) with a numeric "
                         f"angle (Berkovich, Vickers), got {tip!r:.80}")
    b = [float(v) for v in thick_moments(layer, 2)]
    c = HALF_SPACE_CONSTANTS[tip.sides]
    f = _law_coefficients(tip.sides)(*b, c["K"][0], c["m_2"][0], c["m_4"][0])
    return PyramidThickLaw(tip.sides, math.tan(float(tip.alpha)), tuple(float(v) for v in f))
