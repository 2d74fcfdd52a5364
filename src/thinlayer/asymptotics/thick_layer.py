r"""Thick layers (contact small against H): the layer as a regular perturbation of the half-space (T.1)-(T.8).

The opposite limit of the paper's: ``a/H -> 0``.  The expansion holds for any axisymmetric polynomial punch,
to any order in ``c/H``, for every layer whose kernel ``L(u)`` (2.3) tends to 1 (bonded, frictionless base,
incompressible).  Equation tags ``T.n`` are this module's own.

Derivation
----------
(T.1) *Split the kernel.*  With ``L = 1 + (L - 1)`` the displacement (2.1) of an axisymmetric pressure is
Boussinesq's plus a regular part,

    u_3(x) = (1/(2 pi vartheta)) iint p(y)/|x - y| dy + iint p(y) K(|x - y|) dy,
    K(s) = (1/(2 pi vartheta)) int_0^oo (L(alpha H) - 1) J_0(alpha s) d alpha,

(the angular integral of (2.1) gives ``2 pi J_0``; ``L = 1`` gives Boussinesq's ``1/(2 pi vartheta s)``).

(T.2) *The regular kernel in powers of s/H.*  ``L(u) - 1`` tends to ``-1`` at ``u = 0`` and decays like
``u^2 e^{-2u}`` (2.4), so every moment converges and ``J_0(z) = sum_k (-1)^k (z/2)^{2k}/(k!)^2`` may be
integrated term by term:

    K(s) = -(1/(2 pi vartheta H)) sum_{k>=0} (-1)^k b_k (s/(2H))^{2k}/(k!)^2,
    b_k = int_0^oo u^{2k} (1 - L(u)) du.

Only even moments appear (``J_0`` is even) and no logarithm: ``K`` is analytic in the strip
``|Im s| < 2H`` (``|J_0(z)| <= e^{|Im z|}``), so the series converges for ``s < 2H``, i.e. for contact radii
``c < H`` (``|x - y| <= 2c``).  The ``b_k`` are numbers for each layer (:func:`thick_moments`, mpmath
quadrature at any precision): functions of nu for the bonded layer; one set of numbers for the frictionless
base, whose kernel ``(cosh 2u - 1)/(sinh 2u + 2u)`` does not depend on nu.

(T.3) *Ring average.*  For an axisymmetric pressure only the angular mean of ``|x - y|^{2k}`` matters:

    <(r^2 + rho^2 - 2 r rho cos t)^k> = sum_{l} C(k, 2l) C(2l, l) (r^2 + rho^2)^{k-2l} (r rho)^{2l},

a polynomial in ``r^2, rho^2``; the regular displacement is a polynomial in ``r^2`` whose coefficients are
the moments ``mu_j = iint p |y|^{2j} dy``.

(T.4) *Half-space solution of a polynomial displacement* (Sneddon; Galin's theorem).  If the displacement on
the disc ``r < c`` is ``w(r) = sum_i w_i r^{2i}``, its one-dimensional equivalent is
``w_1(x) = sum_i kappa_i w_i x^{2i}``, ``kappa_i = 4^i (i!)^2/(2i)!``, and with ``E^* = 2 vartheta``

    p(r) = -(2 vartheta/pi) int_r^c w_1'(x) (x^2 - r^2)^{-1/2} dx,     w_1(c) = 0   (smooth edge),
    mu_j = 4 vartheta (2j + 1) B_j int_0^c w_1(x) x^{2j} dx,   B_j = 4^{j+1} j! (j+1)!/(2 (2j+2)!),

``mu_0 = P`` (1.8); ``p`` is ``sqrt(c^2 - r^2)`` times a polynomial in ``r^2``.

(T.5) *Order by order in eps = c/H.*  With ``rho = r/c``, ``delta = c sum_m delta~^(m) eps^m``,
``mu_j = vartheta c^{2j+2} sum_m M_j^(m) eps^m``, the order-m displacement is

    w~^(m)(rho) = delta~^(m)
                  + (1/(2 pi)) sum_{2k+1 <= m} (-1)^k b_k/(4^k (k!)^2) sum_{i,j} A^(k)_{ij} rho^{2i} M_j^(m-2k-1)

(``A^(k)`` the ring coefficients (T.3)); the edge condition of (T.4) fixes ``delta~^(m)``, and (T.4) gives the
moments ``M_j^(m)``: an explicit recursion, linear in the punch, exact in rationals and ``b_k/pi``
(:func:`thick_layer_expansion`).  The kernel moment ``b_k`` enters first at order ``eps^{2k+1}``.

(T.6) *Pressure.*  Each order is ``vartheta sqrt(1 - rho^2)/pi`` times a polynomial in ``rho^2`` (T.4).

(T.7) *The sphere in the indentation variable* ``chi = sqrt(R delta0)/H``: with ``delta0 = (c^2/R) D(eps)``
and ``P = (8 vartheta c^3/(3R)) F(eps)``, ``chi = eps sqrt(D)`` is reverted (Lagrange) and

    P/P_Hertz = F/D^{3/2} = 1 + sum_n beta_n chi^n,    c/sqrt(R delta0) = D^{-1/2} = 1 + sum_n gamma_n chi^n,

``P_Hertz = (8/3) vartheta R^{1/2} delta0^{3/2}`` (:func:`thick_sphere_series`), e.g.
``beta_1 = 2 b_0/pi``, ``beta_2 = 14 b_0^2/(3 pi^2)``, ``beta_3 = 8 (200 b_0^3 - 9 pi^2 b_1)/(135 pi^3)``.
The flat punch of radius ``c`` (no edge condition, ``w_1(c) != 0``) gives
``P = 4 vartheta c delta0 (1 + sum_n f_n eps^n)`` (:func:`thick_flat_punch_series`).

(T.9) *Any tip of revolution: the shape enters through its half-space moments.*  In (T.5) the punch appears at
order 0 only: the orders m >= 1 are the half-space answers to the polynomial displacements of the regular kernel,
and those are linear in the order-0 moments ``M_j^(0)``.  For a profile ``Phi(r)`` the order 0 is Sneddon's
half-space solution, ``w_1(x) = delta0 - g(x)``, ``g(x) = x int_0^1 Phi'(x t) (1 - t^2)^{-1/2} dt``; the edge
condition gives ``delta0 = g(c)`` and (T.4) the moments ``M_j^(0) = 4 (2j + 1) B_j int_0^c (g(c) - g(x)) x^{2j} dx``
(in units of ``c^{2j+2}``).  So ``delta0 = c sum_m eps^m (delta~^(0) [m = 0] + sum_j M_j^(0) D_j^(m))`` and
``P = vartheta c^2 sum_m eps^m (M_0^(0) [m = 0] + sum_j M_j^(0) P_j^(m))`` with the shape-free responses
``D_j^(m), P_j^(m)`` of the unit seed ``M_j^(0) = 1`` (:func:`seed_response`).  The power law ``C r^n``
(cone: ``n = 1``, ``C = cot alpha``) is self-similar: ``g = C k_n x^n``, ``k_n = sqrt(pi) n Gamma(n/2)/(2
Gamma((n+1)/2))`` (:func:`power_law_half_space`; ``k_1 = pi/2``, ``k_2 = 2``), and in units of ``C k_n c^{n-1}``
the seed is ``delta~^(0) = 1``, ``M_j^(0) = 4 B_j n/(n + 2j + 1)``: exact rationals for every rational n.  With
``c_0`` the half-space radius at the same depth (``delta0 = C k_n c_0^n``) and ``chi = c_0/H``, (T.7) becomes

    P/P_0 = F/D^{(n+1)/n},   c/c_0 = D^{-1/n},   chi = eps D^{1/n},
    P_0 = 4 vartheta C k_n c_0^{n+1} n/(n + 1)

(:func:`thick_power_law_series`; ``n = 2`` is the sphere's (T.7) unchanged).  The exact sphere and the blunted cone are
not self-similar: their moments depend on ``c/R`` and are computed by quadrature per contact radius
(:mod:`thinlayer.asymptotics.thick_tips`).

(T.8) *Error estimate.*  The terms of a series truncated after ``eps^N`` (or ``chi^N``) are summed up to the
last one; the estimate is ``|t_N| + |t_{N-1}|`` relative (the next term of a series that converges at least
geometrically is below the larger of the last two; the sum of both covers a ratio up to 1/2 and the
alternation seen for the sphere).  Beyond ``eps = 0.9`` (the series converges for ``c < H``) it is inf.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import mpmath
import numpy as np
import sympy as sp
from sympy.polys.domains import QQ
from sympy.polys.rings import ring

from .. import symbols as S
from .._cache import cached
from .._checks import InputError, InputTypeError, check_bounded, check_order, positive
from ..display import RichDisplay, fmt
from ..layers.kernels import LayerKernel
from ..normal import join_signed, normal_latex
from ..parse import as_expr
from ..punch import Punch, is_polynomial_tip
from ..results import checked_lambdify, latex_equation

__all__ = [
    "MAX_THICK_ORDER",
    "PUBLISHED_SERIES",
    "ThickLayerExpansion",
    "ThickSeries",
    "ThickValues",
    "moment_symbols",
    "regular_kernel",
    "thick_flat_punch_series",
    "thick_layer_expansion",
    "power_law_half_space",
    "seed_response",
    "thick_moments",
    "thick_power_law_series",
    "thick_sphere_series",
]

#: largest order in eps = c/H (or chi): order 24 of a degree-8 punch takes about a second
MAX_THICK_ORDER = 40
#: the series converges for c < H (T.2); beyond this eps the estimate is inf
EPS_LIMIT = 0.9

#: contact radius, radial coordinate, sphere radius, chi = sqrt(R delta0)/H of (T.7)
c_sym = sp.Symbol("c", positive=True)
r_sym = sp.Symbol("r", nonnegative=True)
R_sym = sp.Symbol("R", positive=True)
chi_sym = sp.Symbol("chi", positive=True)

#: Published thick-layer series for the sphere, ``P/P_Hertz = 1 + sum_n coef_n chi^n``, ``chi = sqrt(R delta0)/h``
#: (and the flat punch in ``a/h``), as printed; compared with (T.7) in ``tests/asymptotics/test_thick_layer.py``
#: and the errata registry.
PUBLISHED_SERIES: dict[str, dict[str, Any]] = {
    "dimitriadis2002-bonded": {
        "source": "Dimitriadis et al., Biophys. J. 82 (2002) 2798, sphere on a bonded layer, nu = 1/2",
        "shape": "sphere", "base": "bonded", "nu": 0.5, "coefficients": (1.133, 1.283, 0.769, 0.0975)},
    "dimitriadis2002-nonbonded": {
        "source": "Dimitriadis et al., Biophys. J. 82 (2002) 2798, sphere on a non-bonded layer, nu = 1/2",
        "shape": "sphere", "base": "frictionless", "nu": 0.5, "coefficients": (0.884, 0.781, 0.386, 0.0048)},
    "garcia2018-sphere": {
        "source": "Garcia & Garcia, Biophys. J. 114 (2018) 2923, paraboloid on a bonded layer, nu = 1/2",
        "shape": "sphere", "base": "bonded", "nu": 0.5, "coefficients": (1.133, 1.497, 1.469, 0.755)},
    "garcia2018-flat": {
        "source": "Garcia & Garcia, Biophys. J. 114 (2018) 2923, flat punch on a bonded layer, nu = 1/2 (in a/h)",
        "shape": "flat", "base": "bonded", "nu": 0.5, "coefficients": (1.133, 1.283, 0.598, -0.291)},
}


def moment_symbols(order: int) -> tuple[sp.Symbol, ...]:
    """The kernel moments ``b_0 .. b_order`` of (T.2) as sympy symbols."""
    return tuple(sp.Symbol(f"b_{k}", positive=True) for k in range(check_order(order, "order") + 1))


# =============================================================================================
# (T.2): the kernel moments
# =============================================================================================
def _check_layer(layer: Any) -> LayerKernel:
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a thinlayer layer, e.g. BondedLayer(0.3), FrictionlessLayer() or "
                        f"IncompressibleLayer(); got {layer!r}")
    if not layer.has_thickness or layer.symbolic_coefficients or layer.parameter is not None:
        raise InputError(f"the thick-layer moments (T.2) need a layer of finite thickness with a numeric kernel: "
                         f"BondedLayer(0.3), FrictionlessLayer() or IncompressibleLayer(); got {layer!r}")
    return layer.kernel_key  # a frictionless kernel does not depend on nu: one cache entry


@lru_cache(maxsize=64)
def _moments_cached(layer: LayerKernel, order: int, dps: int) -> tuple[mpmath.mpf, ...]:
    """The moments (T.2), kept on disk per layer, order and precision (thinlayer._cache): seconds per nu."""
    nu = getattr(layer, "nu", None)
    if isinstance(nu, mpmath.mpf):  # a float nu: its exact binary value
        nu = ("mpf", *(int(v) for v in nu.man_exp))
    key = (repr(layer), layer.base, nu, getattr(layer, "dps", None), order, dps)
    return cached("thick_moments", key, lambda: _moments_computed(layer, order, dps))


def _moments_computed(layer: LayerKernel, order: int, dps: int) -> tuple[mpmath.mpf, ...]:
    """All ``b_k`` from one composite Gauss-Legendre rule (``1 - L`` evaluated once per node).

    ``L`` is analytic in the strip ``|Im u| < 0.79`` at least (the nearest pole of (2.3), at nu = 1/2, sits near
    ``0.79 i``; far out they approach ``Im u = pi/2``): panels of width 1/2 up to u = 4, then 2, hold the
    Gauss-Legendre error below ``10^-(dps+5)`` with 24 nodes (48 beyond 25 digits, 96 beyond 50).  The rule stops
    where ``u^{2k+2} e^{-2u}`` has fallen ``10^{dps+5}`` below its peak; ``1 - L`` there loses ``0.87 u`` digits
    to cancellation, which the working precision adds.
    """
    from mpmath.calculus.quadrature import GaussLegendre

    k = order
    U = 4.0
    peak = (2 * k + 2) * math.log(k + 1.0) - 2 * (k + 1.0)
    while (2 * k + 2) * math.log(U) - 2 * U > peak - (dps + 5) * math.log(10) or U < k + 4:
        U += 2.0
    edges = [0.5 * i for i in range(9)] + [4.0 + 2 * i for i in range(1, int((U - 4) / 2) + 1)]
    degree = 4 if dps <= 25 else 5 if dps <= 50 else 6
    with mpmath.workdps(dps + 10 + int(0.87 * U)):
        gl = GaussLegendre(mpmath.mp).calc_nodes(degree, mpmath.mp.prec)
        sums = [mpmath.mpf(0)] * (order + 1)
        for a, b in zip(edges[:-1], edges[1:]):
            half, mid = mpmath.mpf(b - a) / 2, mpmath.mpf(a + b) / 2
            for x, w in gl:
                u = mid + half * x
                f = w * half * (1 - layer.L_numeric(u, "mpmath"))
                u2 = u * u
                for j in range(order + 1):
                    sums[j] += f
                    f *= u2
        return tuple(+v for v in sums)


def thick_moments(layer: LayerKernel, order: int, dps: int = 30) -> tuple[mpmath.mpf, ...]:
    r"""The kernel moments ``b_k = int_0^oo u^{2k} (1 - L(u)) du``, ``k = 0..order`` (T.2), by mpmath quadrature.

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` (numeric nu), ``IncompressibleLayer()`` or ``FrictionlessLayer()`` (whose kernel,
        hence whose moments, do not depend on nu).
    order : int
        Largest ``k``.
    dps : int
        Decimal digits (the quadrature runs 10 digits above).

    Returns
    -------
    tuple of mpmath.mpf

    Examples
    --------
    >>> from thinlayer import BondedLayer, FrictionlessLayer
    >>> [mpmath.nstr(b, 10) for b in thick_moments(BondedLayer(0.5), 1)]
    ['1.770216773', '3.831077156']
    >>> mpmath.nstr(thick_moments(FrictionlessLayer(), 0)[0], 10)
    '1.167576837'
    """
    layer = _check_layer(layer)
    n = check_order(order, "order")
    check_bounded(n, "order", MAX_THICK_ORDER, "the moments beyond k = 40 are never needed by (T.5) at order <= 40")
    if isinstance(dps, bool) or not isinstance(dps, int) or not 5 <= dps <= 200:
        raise InputError(f"dps must be an integer in [5, 200], got {dps!r}")
    return _moments_cached(layer, n, dps)[: n + 1]


def regular_kernel(order: int, s: sp.Expr = S.s) -> sp.Expr:
    r"""``2 pi vartheta H K(s)`` of (T.2) through ``(s/H)^{2 order}``, in the symbols ``b_k`` and ``H``.

    Examples
    --------
    >>> regular_kernel(1)
    -b_0 + b_1*s**2/(4*H**2)
    """
    b = moment_symbols(order)
    return sp.Add(*[-(-1) ** k * b[k] * (s / (2 * S.H)) ** (2 * k) / sp.factorial(k) ** 2 for k in range(order + 1)])


# =============================================================================================
# (T.3)-(T.5): the recursion, exact in QQ[g_0, g_1, ...], g_k = b_k/pi
# =============================================================================================
def _kappa(i: int):
    return QQ(4**i * math.factorial(i) ** 2, math.factorial(2 * i))


def _B(j: int):
    return QQ(4 ** (j + 1) * math.factorial(j) * math.factorial(j + 1), 2 * math.factorial(2 * j + 2))


@lru_cache(maxsize=None)
def _ring_average(k: int) -> dict[tuple[int, int], Any]:
    """``{(i, j): A_ij}`` with ``<|x - y|^{2k}>_angle = sum A_ij r^{2i} rho^{2j}`` (T.3)."""
    out: dict[tuple[int, int], Any] = {}
    for l in range(k // 2 + 1):
        c = QQ(math.comb(k, 2 * l) * math.comb(2 * l, l))
        for a in range(k - 2 * l + 1):  # (X + Y)^{k-2l} (XY)^l, X = r^2, Y = rho^2
            key = (a + l, k - 2 * l - a + l)
            out[key] = out.get(key, QQ(0)) + c * math.comb(k - 2 * l, a)
    return out


@lru_cache(maxsize=8)
def _poly_ring(nk: int):
    return ring([f"g_{k}" for k in range(max(nk, 1))], QQ)


def _add_layer_response(w: dict, m: int, K: int, g: list, Ms: list, zero: Any) -> None:
    """Add to ``w`` (coefficients of ``rho^{2i}``) the layer's displacement of order ``m`` (T.5): the kernel
    terms ``b_k`` (``g[k]``) acting on the moments ``Ms[m - 2k - 1]`` of the earlier orders.
    """
    for k in range(K + 1):
        if 2 * k + 1 > m:
            break
        fac = QQ((-1) ** k, 2 * 4**k * math.factorial(k) ** 2) * g[k]
        Mp = Ms[m - 2 * k - 1]
        for (i, j), a in _ring_average(k).items():
            w[i] = w.get(i, zero) + fac * a * Mp[j]


def _moments(w: dict, J: int, zero: Any) -> list:
    """The pressure moments ``M_0 .. M_{J-1}`` (T.5) of the half-space pressure that makes the displacement ``w``."""
    return [4 * (2 * j + 1) * _B(j) * sum((_kappa(i) * wi * QQ(1, 2 * i + 2 * j + 1) for i, wi in w.items()), zero)
            for j in range(J)]


@lru_cache(maxsize=256)
def _recursion(n: int, order: int, edge: bool) -> tuple[tuple, tuple, tuple]:
    """``(delta~^(m), M_0^(m), w~^(m))`` for the unit monomial ``rho^{2n}`` (T.5), m = 0..order.

    With ``edge`` (smooth punch) the edge condition of (T.4) fixes ``delta~^(m)``; without it (flat punch of
    radius c, ``n = 0`` only) ``delta~ = 1`` and ``delta~^(m) = 0`` for m >= 1.
    """
    K = max((order - 1) // 2, 0)
    Rg, *g = _poly_ring(K + 1)
    zero, one = Rg(0), Rg(1)
    ds, Ps, ws, Ms = [], [], [], []
    J = K + 1  # moments M_0..M_K are needed
    for m in range(order + 1):
        w: dict[int, Any] = {}
        if m == 0:
            w[n] = -one if edge else zero
            if not edge:
                w[0] = one
        _add_layer_response(w, m, K, g, Ms, zero)
        if edge:
            d = -sum((_kappa(i) * wi for i, wi in w.items()), zero)
            w[0] = w.get(0, zero) + d
        else:
            d = one if m == 0 else zero
        Mm = _moments(w, J, zero)
        ds.append(d)
        ws.append(tuple(sorted(w.items())))
        Ms.append(Mm)
        Ps.append(Mm[0])
    return tuple(ds), tuple(Ps), tuple(ws)


@lru_cache(maxsize=64)
def _seed_response(order: int) -> tuple[tuple[tuple, tuple], ...]:
    """``((D_j^(m), P_j^(m)) for j = 0..K)``, m = 0..order: (T.5) for the unit seed ``M_j^(0) = 1`` (T.9).

    The order-0 entries are 0 (the shape's own order 0 is added by the caller).
    """
    K = max((order - 1) // 2, 0)
    Rg, *g = _poly_ring(K + 1)
    zero = Rg(0)
    J = K + 1
    out = []
    for j0 in range(J):
        Ms = [[Rg(1) if j == j0 else zero for j in range(J)]]
        ds, Ps = [zero], [zero]
        for m in range(1, order + 1):
            w: dict[int, Any] = {}
            _add_layer_response(w, m, K, g, Ms, zero)
            d = -sum((_kappa(i) * wi for i, wi in w.items()), zero)
            w[0] = w.get(0, zero) + d
            Mm = _moments(w, J, zero)
            ds.append(d)
            Ps.append(Mm[0])
            Ms.append(Mm)
        out.append((tuple(ds), tuple(Ps)))
    return tuple(out)


def seed_response(order: int, layer: LayerKernel) -> tuple[np.ndarray, np.ndarray]:
    r"""``(D, P)``, arrays ``[j, m]`` of the responses of (T.9) for one layer: the depth and force terms of order
    ``m`` (units ``c`` and ``vartheta c^2``) produced by a unit half-space moment ``M_j^(0) = 1`` (``j <= K``,
    ``2K + 1 <= order``).  Exact in ``b_k/pi`` (:func:`thick_moments`), rounded to floats at the end.
    """
    n = _check_thick_order(order)
    return _numeric_response(n, layer)


@lru_cache(maxsize=64)
def _numeric_response(order: int, layer: LayerKernel) -> tuple[np.ndarray, np.ndarray]:
    K = max((order - 1) // 2, 0)
    resp = _seed_response(order)
    with mpmath.workdps(25):
        gv = [b / mpmath.pi for b in thick_moments(layer, K, dps=20)]
        D = np.array([[float(_to_number(p, gv)) for p in ds] for ds, _ in resp])
        P = np.array([[float(_to_number(p, gv)) for p in ps] for _, ps in resp])
    D.setflags(write=False)
    P.setflags(write=False)
    return D, P


def _to_expr(p: Any, b: tuple[sp.Symbol, ...]) -> sp.Expr:
    """A ring element in ``g_k = b_k/pi`` as a sympy expression in the ``b_k``."""
    out = sp.Integer(0)
    for mon, coef in p.terms():
        term = sp.Rational(int(coef.numerator), int(coef.denominator))
        for k, e in enumerate(mon):
            if e:
                term *= (b[k] / sp.pi) ** e
        out += term
    return out


def _to_number(p: Any, gv: list) -> mpmath.mpf:
    out = mpmath.mpf(0)
    for mon, coef in p.terms():
        term = mpmath.mpf(int(coef.numerator)) / int(coef.denominator)
        for k, e in enumerate(mon):
            if e:
                term *= gv[k] ** e
        out += term
    return out


# =============================================================================================
# (T.4)-(T.6): any axisymmetric polynomial punch
# =============================================================================================
def _radial_coefficients(punch: Punch) -> dict[int, sp.Expr]:
    """``{n: phi_n}`` of ``Phi = sum_n phi_n r^{2n}`` (checked axisymmetric, ``Phi(0) = 0``)."""
    if not punch.axisymmetric:
        raise InputError(f"the thick-layer expansion (T.5) is for axisymmetric punches; Phi = {punch.expr} is not "
                         "(x1 dPhi/dx2 - x2 dPhi/dx1 != 0)")
    out: dict[int, sp.Expr] = {}
    for (deg, j), coef in punch.polynomial.terms():  # Phi(x1, 0): the terms free of x2
        if j:
            continue
        if deg == 0:
            raise InputError(f"the punch Phi = {punch.expr} has Phi(0) = {coef}; normalise it with Phi(0) = 0")
        out[deg // 2] = coef
    return out


@dataclass(frozen=True)
class ThickValues:
    """Numbers of the thick-layer expansion at one depth: radius, force and their error estimates (T.8)."""

    delta0: float
    radius: float
    force: float
    eps: float
    order: int
    force_error: float
    radius_error: float


@dataclass(frozen=True, eq=False)
class ThickLayerExpansion(RichDisplay):
    r"""The thick-layer expansion (T.5) of an axisymmetric polynomial punch: ``delta0(c)``, ``P(c)``, ``p(r)``.

    Attributes
    ----------
    punch : Punch
        The punch (its coefficients may be symbols).
    order : int
        Highest power of ``eps = c/H`` kept.
    profile : dict
        ``{n: phi_n}`` with ``Phi = sum_n phi_n r^{2n}``.
    delta_terms, force_terms : tuple of sympy.Expr
        ``delta0 = sum_m delta_terms[m] (c/H)^m``, ``P = sum_m force_terms[m] (c/H)^m`` (in ``c``, ``b_k``, the punch's
        parameters and ``vartheta``).
    pressure_terms : tuple of sympy.Expr
        ``p(r) = sum_m pressure_terms[m] (c/H)^m`` for ``r < c`` (T.6).
    """

    punch: Punch
    order: int
    profile: dict = field(repr=False)
    delta_terms: tuple = field(repr=False)
    force_terms: tuple = field(repr=False)
    pressure_terms: tuple = field(repr=False)
    equation = "T.5"

    @property
    def moments(self) -> tuple[sp.Symbol, ...]:
        """The kernel moments the expansion depends on: ``b_0 .. b_K``, ``2K + 1 <= order``."""
        return moment_symbols(max((self.order - 1) // 2, 0))

    @property
    def delta0_of_c(self) -> sp.Expr:
        """``delta0(c)`` through ``(c/H)^order``."""
        return sp.Add(*[t * (c_sym / S.H) ** m for m, t in enumerate(self.delta_terms)])

    @property
    def force_of_c(self) -> sp.Expr:
        """``P(c)`` through ``(c/H)^order`` (1.8)."""
        return sp.Add(*[t * (c_sym / S.H) ** m for m, t in enumerate(self.force_terms)])

    @property
    def pressure_of_c(self) -> sp.Expr:
        """``p(r)`` for ``r < c`` through ``(c/H)^order`` (T.6)."""
        return sp.Add(*[t * (c_sym / S.H) ** m for m, t in enumerate(self.pressure_terms)])

    def numeric(self, layer: LayerKernel, parameters: dict | None = None) -> Callable:
        """``f(c, H, mu, nu) -> (delta0, P, delta terms, P terms)``: numpy function of the expansion for one layer.

        ``parameters`` gives the punch's free parameters (e.g. ``{"R": 10}``).
        """
        K = max((self.order - 1) // 2, 0)
        bvals = thick_moments(layer, K)
        subs = {b: sp.Float(v, 20) for b, v in zip(self.moments, bvals)}
        for name, val in (parameters or {}).items():
            subs[sp.Symbol(name, positive=True)] = val
            subs[sp.Symbol(name)] = val
        subs[S.vartheta] = S.mu / (1 - S.nu)
        dts = [as_expr(t).xreplace(subs) for t in self.delta_terms]
        pts = [as_expr(t).xreplace(subs) for t in self.force_terms]
        free = set().union(*(e.free_symbols for e in dts + pts)) - {c_sym, S.mu, S.nu}
        if free:
            raise InputError(f"the punch's parameters {sorted(map(str, free))} need values: parameters={{...}}")
        fd = checked_lambdify((c_sym, S.mu, S.nu), dts, "numpy")
        fp = checked_lambdify((c_sym, S.mu, S.nu), pts, "numpy")

        def f(c, H, mu, nu):
            e = c / H
            dt = [float(v) * e**m for m, v in enumerate(fd(c, mu, nu))]
            pt = [float(v) * e**m for m, v in enumerate(fp(c, mu, nu))]
            return sum(dt), sum(pt), dt, pt

        return f

    def evaluate(self, layer: LayerKernel, delta0: float, H: float, mu: float = 1.0, nu: float | None = None,
                 parameters: dict | None = None) -> ThickValues:
        """Contact radius and force for a prescribed depth: Brent's method on ``delta0(c)``; estimate (T.8).

        Raises
        ------
        ValueError
            When no ``c < 0.9 H`` reaches ``delta0`` (the series converges for ``c < H``): the layer is not thick.
        """
        from scipy import optimize

        d0, HH, mm = positive(delta0, "delta0"), positive(H, "H"), positive(mu, "mu")
        nv = float(layer.poisson_ratio(nu))
        f = self.numeric(layer, parameters)
        # the first crossing of delta0(c) = delta0 on a geometric scan of c < 0.9 H (the truncated series is
        # increasing there for a convex punch; beyond the first crossing it may not be)
        cs = EPS_LIMIT * HH * np.geomspace(1e-6, 1.0, 241)
        vals = np.array([f(cc, HH, mm, nv)[0] for cc in cs])
        above = np.flatnonzero(vals >= d0)
        if not above.size or above[0] == 0:
            raise InputError(f"the thick-layer expansion needs a contact radius c < {EPS_LIMIT} H; delta0 = {d0:.4g} "
                             f"needs more (H = {HH:.4g}): use the any-thickness law or the direct solver")
        lo, hi = cs[above[0] - 1], cs[above[0]]
        c = optimize.brentq(lambda cc: f(cc, HH, mm, nv)[0] - d0, lo, hi, xtol=1e-15 * hi, rtol=1e-14)
        d, P, dt, pt = f(c, HH, mm, nv)
        eps = c / HH
        ferr = _tail(pt, P, eps)
        # radius: d delta/dc ~ (2 n) delta/c: the depth's tail divided by the local exponent
        rerr = _tail(dt, d, eps) / 2.0
        return ThickValues(d0, c, P, eps, self.order, ferr, rerr)

    def latex(self) -> str:
        return " \\\\\n".join([latex_equation(r"\delta_0", normal_latex(self.delta0_of_c), "T.5"),
                               latex_equation("P", normal_latex(self.force_of_c), "T.5")])

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        lines = [f"ThickLayerExpansion of {self.punch.name} Φ = {fmt(self.punch.expr)}, "
                 f"through (c/H)^{self.order}   (T.5)"]
        for m in range(min(self.order, 3) + 1):
            lines.append(f"  (c/H)^{m}:  δ₀ {fmt(sp.simplify(self.delta_terms[m]))},  "
                         f"P {fmt(sp.simplify(self.force_terms[m]))}")
        return lines


def _tail(terms: list[float], total: float, eps: float) -> float:
    """Error estimate (T.8): ``|t_N| + |t_{N-1}|`` relative to the total; inf beyond ``eps = 0.9``."""
    if eps >= EPS_LIMIT or not total:
        return math.inf
    last = [abs(t) for t in terms[-2:]]
    return float(sum(last) / abs(total))


def _check_thick_order(order: Any) -> int:
    n = check_order(order, "order")
    check_bounded(n, "order", MAX_THICK_ORDER, "order 24 of a degree-8 punch already takes about a second")
    return n


@lru_cache(maxsize=32)
def _expansion(punch: Punch, order: int) -> ThickLayerExpansion:
    prof = _radial_coefficients(punch)
    K = max((order - 1) // 2, 0)
    b = moment_symbols(K)
    dterms = [sp.Integer(0)] * (order + 1)
    pterms = [sp.Integer(0)] * (order + 1)
    prterms = [sp.Integer(0)] * (order + 1)
    rho = r_sym / c_sym
    sig = sp.sqrt(1 - rho**2)
    for n, phi in prof.items():
        ds, Ps, ws = _recursion(n, order, True)
        scale = phi * c_sym ** (2 * n)  # f~_n c: delta = c delta~, f~_n = phi_n c^{2n-1}
        for m in range(order + 1):
            dterms[m] += scale * _to_expr(ds[m], b)
            pterms[m] += S.vartheta * c_sym * scale * _to_expr(Ps[m], b)
            prterms[m] += S.vartheta * scale / c_sym * _pressure_poly(ws[m], b, rho, sig)
    return ThickLayerExpansion(punch, order, prof, tuple(sp.expand(t) for t in dterms),
                               tuple(sp.expand(t) for t in pterms), tuple(prterms))


def _pressure_poly(w: tuple, b: tuple, rho: sp.Expr, sig: sp.Expr) -> sp.Expr:
    """``p~(rho) = -(4/pi) sum_i i kappa_i w_i sum_l C(i-1, l) rho^{2(i-1-l)} sigma^{2l+1}/(2l+1)`` (T.4), (T.6)."""
    out = sp.Integer(0)
    for i, wi in w:
        if i == 0:
            continue
        kap = sp.Rational(int(_kappa(i).numerator), int(_kappa(i).denominator))
        inner = sp.Add(*[sp.binomial(i - 1, l) * rho ** (2 * (i - 1 - l)) * sig ** (2 * l + 1) / (2 * l + 1)
                         for l in range(i)])
        out += -4 / sp.pi * i * kap * _to_expr(wi, b) * inner
    return out


def thick_layer_expansion(punch: Any, order: int = 8) -> ThickLayerExpansion:
    r"""The thick-layer expansion (T.5) of an axisymmetric polynomial punch to ``(c/H)^order``.

    Parameters
    ----------
    punch : Punch or str
        An axisymmetric polynomial punch with ``Phi(0) = 0`` (its coefficients may be symbols).
    order : int
        Highest power of ``c/H`` (default 8; at most :data:`MAX_THICK_ORDER`).

    Returns
    -------
    ThickLayerExpansion
        ``delta0_of_c``, ``force_of_c``, ``pressure_of_c`` symbolic in the moments ``b_k`` (T.2);
        ``evaluate(layer, delta0, H, mu)`` for numbers.

    Examples
    --------
    Hertz at order 0; the first correction moves the depth by the constant ``b_0 P/(2 pi vartheta H)``:

    >>> from thinlayer import Punch
    >>> ex = thick_layer_expansion(Punch.paraboloid(), order=1)
    >>> ex.delta_terms
    (c**2/R, -4*b_0*c**2/(3*pi*R))
    >>> ex.force_terms[0]
    8*c**3*vartheta/(3*R)
    """
    if isinstance(punch, str):
        punch = Punch(punch)
    if not is_polynomial_tip(punch):
        raise InputTypeError(f"punch must be a thinlayer Punch (or a polynomial string in x_1, x_2), got {punch!r}")
    return _expansion(punch, _check_thick_order(order))


# =============================================================================================
# (T.7): the sphere and the flat punch in one variable
# =============================================================================================
def _pow_series(a: list, alpha: Any, N: int, one: Any) -> list:
    """``a^alpha`` for ``a_0 = 1`` (J. C. P. Miller's recurrence ``n b_n = sum_k ((alpha+1) k - n) a_k b_{n-k}``)."""
    out = [one]
    for n in range(1, N + 1):
        acc = one * 0
        for k in range(1, n + 1):
            acc += ((alpha + 1) * k - n) * a[k] * out[n - k]
        out.append(acc * QQ(1, n))
    return out


def _mul(a: list, b: list, N: int) -> list:
    return [sum((a[j] * b[n - j] for j in range(n + 1)), a[0] * 0) for n in range(N + 1)]


def _compose(f: list, e: list, N: int) -> list:
    """``f(e(chi))`` for ``e_0 = 0``."""
    out = [f[0] * 0 for _ in range(N + 1)]
    power = [f[0] * 0 + (1 if n == 0 else 0) for n in range(N + 1)]
    for j in range(N + 1):
        for n in range(N + 1):
            out[n] += f[j] * power[n]
        power = _mul(power, e, N)
    return out


def _revert(S_: list, N: int) -> list:
    """``eps(chi)`` with ``chi = eps S(eps)``, ``S_0 = 1``: Lagrange, ``[chi^n] eps = [eps^{n-1}] S^{-n}/n``."""
    one = S_[0]
    out = [one * 0]
    for n in range(1, N + 1):
        out.append(_pow_series(S_, QQ(-n), n - 1, one)[n - 1] * QQ(1, n))
    return out


@dataclass(frozen=True, eq=False)
class ThickSeries(RichDisplay):
    r"""One-variable thick-layer series (T.7): ``P/P_0 = 1 + sum_n force[n] x^n``, ``c/c_0 = 1 + sum_n radius[n] x^n``.

    For the sphere ``x = chi = sqrt(R delta0)/H``, ``P_0 = (8/3) vartheta R^{1/2} delta0^{3/2}``,
    ``c_0 = sqrt(R delta0)``; for the flat punch ``x = c/H``, ``P_0 = 4 vartheta c delta0`` (no radius series).

    Attributes
    ----------
    shape : str
        ``"sphere"``, ``"flat"`` or ``"power law n = ..."`` (T.9; ``x = chi = c_0/H``, ``c_0`` and ``P_0`` the
        half-space radius and force at the same depth).
    order : int
    force, radius : tuple of sympy.Expr
        Coefficients (index 0 is 1), polynomials in ``b_k/pi``.
    """

    shape: str
    order: int
    force: tuple
    radius: tuple
    _ring_force: tuple = field(repr=False)
    _ring_radius: tuple = field(repr=False)
    equation = "T.7"

    def coefficients(self, layer: LayerKernel, dps: int = 20) -> tuple[np.ndarray, np.ndarray]:
        """``(force, radius)`` coefficients as float arrays for one layer (moments by :func:`thick_moments`)."""
        return _numeric_coefficients(self, layer, dps)

    def force_ratio(self, x: Any, layer: LayerKernel) -> np.ndarray:
        """``P/P_0`` at ``x`` (chi for the sphere, c/H for the flat punch)."""
        return np.polynomial.polynomial.polyval(np.asarray(x, dtype=float), self.coefficients(layer)[0])

    def radius_ratio(self, x: Any, layer: LayerKernel) -> np.ndarray:
        """``c/sqrt(R delta0)`` at ``chi`` (sphere)."""
        return np.polynomial.polynomial.polyval(np.asarray(x, dtype=float), self.coefficients(layer)[1])

    def error_estimate(self, x: Any, layer: LayerKernel) -> tuple[np.ndarray, np.ndarray]:
        """Relative estimates (T.8) of ``P`` and ``c``: the last two terms."""
        x = np.asarray(x, dtype=float)
        fc, rc = self.coefficients(layer)
        N = self.order
        pv = np.polynomial.polynomial.polyval
        ef = (np.abs(fc[N] * x**N) + np.abs(fc[N - 1] * x ** (N - 1))) / np.abs(pv(x, fc))
        er = (np.abs(rc[N] * x**N) + np.abs(rc[N - 1] * x ** (N - 1))) / np.abs(pv(x, rc))
        return ef, er

    def latex(self) -> str:
        x = sp.Symbol("c") / S.H if self.shape == "flat" else chi_sym
        def series(coefficients: tuple) -> str:  # ascending powers of the variable, each term in the normal form
            return join_signed([normal_latex(t * x**n) for n, t in enumerate(coefficients)])

        lines = [latex_equation(r"P/P_0", series(self.force), "T.7")]
        if self.shape != "flat":
            lines.append(latex_equation("c/c_0", series(self.radius), "T.7"))
        return " \\\\\n".join(lines)

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        var = "χ = √(R δ₀)/H" if self.shape == "sphere" else "c/H" if self.shape == "flat" else "χ = c₀/H"
        lines = [f"ThickSeries ({self.shape}) in {var}, through order {self.order}   (T.7)"]
        for n in range(1, min(self.order, 4) + 1):
            lines.append(f"  P: [{n}] {fmt(self.force[n])}")
        return lines


@lru_cache(maxsize=64)
def _numeric_coefficients(series: ThickSeries, layer: LayerKernel, dps: int) -> tuple[np.ndarray, np.ndarray]:
    K = max((series.order - 1) // 2, 0)
    with mpmath.workdps(dps + 5):
        gv = [b / mpmath.pi for b in thick_moments(layer, K, dps=max(dps, 20))]
        fc = np.array([float(_to_number(p, gv)) for p in series._ring_force])
        rc = np.array([float(_to_number(p, gv)) for p in series._ring_radius])
    fc.setflags(write=False)
    rc.setflags(write=False)
    return fc, rc


@lru_cache(maxsize=16)
def _sphere_series(order: int) -> ThickSeries:
    N = order
    ds, Ps, _ = _recursion(1, N, True)
    D = [d * QQ(1, 2) for d in ds]  # delta0/(c^2/R): delta~ = (c/(2R)) sum ds eps^m
    F = [p * QQ(3, 16) for p in Ps]  # P/(8 vartheta c^3/(3R))
    one = D[0]
    Sx = _pow_series(D, QQ(1, 2), N, one)  # chi = eps sqrt(D)
    e = _revert(Sx, N)
    ratio = _mul(F, _pow_series(D, QQ(-3, 2), N, one), N)
    fo = _compose(ratio, e, N)
    ro = _compose(_pow_series(D, QQ(-1, 2), N, one), e, N)
    b = moment_symbols(max((N - 1) // 2, 0))
    return ThickSeries("sphere", N, tuple(sp.expand(_to_expr(p, b)) for p in fo),
                       tuple(sp.expand(_to_expr(p, b)) for p in ro), tuple(fo), tuple(ro))


def power_law_half_space(n: Any) -> sp.Expr:
    r"""``k_n`` of the half-space power law (T.9): ``delta0 = C k_n c^n`` for ``Phi = C r^n``.

    ``g(x) = x int_0^1 Phi'(x t)(1 - t^2)^{-1/2} dt = C n x^n int_0^1 t^{n-1} (1 - t^2)^{-1/2} dt = C k_n x^n``,
    the integral ``B(n/2, 1/2)/2`` (derived here by sympy).

    Examples
    --------
    >>> power_law_half_space(1), power_law_half_space(2)
    (pi/2, 2)
    """
    t = sp.Symbol("t", positive=True)
    if isinstance(n, bool) or not isinstance(n, (int, float, sp.Expr)):
        raise InputError(f"n must be a number or a sympy expression (the tip's exponent), got {n!r}")
    nn = sp.Integer(n) if isinstance(n, int) else sp.Float(n) if isinstance(n, float) else n  # from the Tip
    integral = sp.integrate(t ** (nn - 1) / sp.sqrt(1 - t**2), (t, 0, 1))
    return sp.simplify(sp.gammasimp(nn * integral))


@lru_cache(maxsize=32)
def _power_law_series(n: sp.Rational, order: int) -> ThickSeries:
    N = order
    q = QQ(int(n.p), int(n.q))
    resp = _seed_response(N)
    Rg = _poly_ring(max((N - 1) // 2, 0) + 1)[0]
    seed = [4 * _B(j) * q / (q + 2 * j + 1) for j in range(len(resp))]  # M_j^(0), units C k_n c^{n-1}
    D = [Rg(1)] + [sum((seed[j] * resp[j][0][m] for j in range(len(resp))), Rg(0)) for m in range(1, N + 1)]
    F = [Rg(1)] + [sum((seed[j] * resp[j][1][m] for j in range(len(resp))), Rg(0)) * (1 / seed[0])
                   for m in range(1, N + 1)]
    one = D[0]
    e = _revert(_pow_series(D, 1 / q, N, one), N)  # chi = eps D^{1/n}
    fo = _compose(_mul(F, _pow_series(D, -(q + 1) / q, N, one), N), e, N)
    ro = _compose(_pow_series(D, -1 / q, N, one), e, N)
    b = moment_symbols(max((N - 1) // 2, 0))
    return ThickSeries(f"power law n = {n}", N, tuple(sp.expand(_to_expr(p, b)) for p in fo),
                       tuple(sp.expand(_to_expr(p, b)) for p in ro), tuple(fo), tuple(ro))


def thick_power_law_series(n: Any, order: int = 12) -> ThickSeries:
    r"""The power-law tip ``C r^n`` (the cone: ``n = 1``) on a thick layer (T.9): ``P/P_0`` and ``c/c_0`` in powers of
    ``chi = c_0/H``, ``c_0 = (delta0/(C k_n))^{1/n}`` the half-space radius, ``P_0 = 4 vartheta C k_n c_0^{n+1}
    n/(n + 1)`` (Sneddon).  ``n = 2`` is :func:`thick_sphere_series`.

    Examples
    --------
    >>> s = thick_power_law_series(1, 3)
    >>> s.force[1], s.radius[1]
    (2*b_0/pi, b_0/pi)
    """
    v = sp.Rational(n) if isinstance(n, (int, sp.Rational)) and not isinstance(n, bool) else None
    if isinstance(n, str):
        from ..parse import parse_number

        v = sp.Rational(parse_number(n, "the exponent n"))
    if v is None or not 1 <= v <= 1000:
        raise InputError(f"n must be a rational number with 1 <= n <= 1000 (an int, a sympy Rational or a string "
                         f"such as '3/2'), got {n!r}")
    N = _check_thick_order(order)
    if N < 2:
        raise InputError(f"order must be at least 2 (the estimate (T.8) needs two terms), got {order}")
    return _power_law_series(v, N)


def thick_sphere_series(order: int = 12) -> ThickSeries:
    r"""The sphere (paraboloid) on a thick layer: ``P/P_Hertz`` and ``c/sqrt(R delta0)`` in powers of chi (T.7).

    Examples
    --------
    >>> s = thick_sphere_series(4)
    >>> s.force[1], s.force[2]
    (2*b_0/pi, 14*b_0**2/(3*pi**2))
    >>> from thinlayer.layers.kernels import IncompressibleLayer
    >>> [round(float(v), 4) for v in s.coefficients(IncompressibleLayer())[0][1:]]
    [1.127, 1.4817, 1.47, 1.0047]
    """
    n = _check_thick_order(order)
    if n < 2:
        raise InputError(f"order must be at least 2 (the estimate (T.8) needs two terms), got {order}")
    return _sphere_series(n)


@lru_cache(maxsize=16)
def _flat_series(order: int) -> ThickSeries:
    _, Ps, _ = _recursion(0, order, False)
    fo = [p * QQ(1, 4) for p in Ps]  # P~ = 4 at order 0 (delta~ = 1)
    b = moment_symbols(max((order - 1) // 2, 0))
    return ThickSeries("flat", order, tuple(sp.expand(_to_expr(p, b)) for p in fo),
                       tuple(sp.Integer(0) for _ in fo), tuple(fo), tuple(p * 0 for p in fo))


def thick_flat_punch_series(order: int = 12) -> ThickSeries:
    r"""The flat punch of radius ``c`` on a thick layer: ``P/(4 vartheta c delta0) = 1 + sum_n f_n (c/H)^n`` (T.7).

    Examples
    --------
    >>> thick_flat_punch_series(3).force[:3]
    (1, 2*b_0/pi, 4*b_0**2/pi**2)
    """
    n = _check_thick_order(order)
    if n < 2:
        raise InputError(f"order must be at least 2 (the estimate (T.8) needs two terms), got {order}")
    return _flat_series(n)
