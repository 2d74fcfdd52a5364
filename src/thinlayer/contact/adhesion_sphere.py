r"""One adhesive (JKR) law for the sphere at any thickness, from the half-space to the thin layer (issue 26 item 3).

Equation tags ``J.16``-``J.18`` continue those of :mod:`thinlayer.numerics.adhesion` (J.1)-(J.6) and
:mod:`thinlayer.asymptotics.adhesion` (J.7)-(J.15).  Assumptions: the paraboloid ``Phi = r^2/(2R)``, frictionless
contact, a layer bonded to (``-1 < nu <= 1/2``) or lying on (frictionless base) a rigid base, JKR adhesion.

(J.16) *The state at the contact radius c from two laws the engine has.*  The superposition (J.1) makes the JKR
state at ``c`` the smooth-edge (non-adhesive) state at ``c`` plus a flat punch of radius ``c`` pressed to
``d <= 0``::

    delta = delta_1(c) + d,      P = P_1(c) + S(c) d,      S(c) = 4 vartheta c kappa(c/H).

``delta_1(c)``, ``P_1(c)`` come from the sphere's any-thickness law (T.7) of
:mod:`thinlayer.contact.any_thickness`: with ``chi = sqrt(R delta_1)/H`` the law gives ``c/H = chi Gamma(chi)``
(increasing in chi; inverted by Newton's method in ``log chi``), ``delta_1 = chi^2 H^2/R`` and
``P_1 = (8/3) vartheta R^{1/2} delta_1^{3/2} Pi(chi)``.  ``kappa`` is the flat punch's stiffness at ``lambda = c/H``
(:mod:`thinlayer.contact.flat_punch`: the thin-layer form (F.12)/(F.14)/(F.15) where its estimate is within
``1e-5``, else the exact solver (F.6)-(F.7), its values interpolated in ``log lambda`` on ``[0.05, 60]`` (Chebyshev,
40 nodes, once per layer), the thick-layer series (F.18) below ``lambda = 0.05``).

(J.17) *The energy release rate from the compliance of the flat punch.*  At a fixed depth the elastic energy is
``U = U_1(c) + P_1 d + S d^2/2`` up to terms stationary in ``c``; releasing the area ``dA = 2 pi c dc`` releases
``G dA = (d^2/2) dS``::

    G = d^2 S'(c)/(4 pi c) = vartheta d^2 g(lambda)/(pi c),      g(lambda) = d(lambda kappa)/d lambda,

and ``G = w`` gives ``d = -sqrt(pi c w/(vartheta g))`` (the tensile root: the edge is pulled open).  ``g`` is
derived per model: the series (F.18) differentiated term by term, ``g = sum (k + 1) c_k lambda^k``; the thin forms
differentiated (a central difference of ``lambda kappa``, step ``1e-4 lambda``: truncation ``~1e-9``; for (F.12)
``g = pi (lambda + h*)/(2A)``, which is (J.10)); the exact solver by Krein's identity (F.9) ``g = f(1)^2`` (the
derivative of ``lambda kappa`` without differencing; ``tests/adhesion/test_door_sphere.py`` checks it against a
central difference of the exact ``kappa``).  Half-space limit (``lambda -> 0``): ``kappa = g = 1``, JKR (1971).

(J.18) *Error estimate* (absolute, from the ingredients' own).  The any-thickness law's relative estimates
``(e_P, e_c)`` hold at a given depth; at a given contact radius they become ``e_delta = e_c/s_c`` and
``e_P1 = e_P + s_P e_delta`` with ``s_c = d log c/d log delta_1`` and ``s_P = d log P_1/d log delta_1`` (both from
the law).  The flat part's relative estimates ``e_kappa`` (its model's) and ``e_g`` (the same bound: a relative
remainder ``K lambda^{-p}`` of kappa gives ``p K lambda^{-p}/(p + 1)`` or less in g for the thin forms,
the next terms of the differentiated series (F.18), ``4 e_kappa`` for the exact solver, the Chebyshev tail
for the interpolated exact values)
enter through ``d ~ g^{-1/2}``::

    err delta = e_delta delta_1 + |d| e_g/2,      err P = e_P1 P_1 + S |d| (e_kappa + e_g/2).

Pull-off (load control): the minimum of ``P(c)``, located on a grid in ``log c`` and refined by golden section;
under displacement control the minimum of ``delta(c)`` (J.6).  Measured against the direct JKR solver
(:func:`~thinlayer.numerics.adhesion.jkr_curve`) in ``tests/adhesion/test_door_sphere.py`` and
``tests/adhesion/test_acceptance.py``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from .._checks import InputError, positive, positive_radii
from .._checks import work_of_adhesion as check_work
from .._lazy import lazy_function
from ..display import RichDisplay
from .any_thickness import any_thickness_law

thick_flat_punch = lazy_function("thinlayer.asymptotics.flat_punch", "thick_flat_punch")
thin_flat_punch = lazy_function("thinlayer.asymptotics.flat_punch", "thin_flat_punch")
check_numeric_layer = lazy_function("thinlayer.numerics.flat_punch", "check_numeric_layer")
flat_punch_kappa = lazy_function("thinlayer.numerics.flat_punch", "flat_punch_kappa")

__all__ = ["AnyThicknessJKR", "JKRStates", "any_thickness_jkr", "flat_release_factor"]

#: the flat part's thin form is used where its relative estimate is within this (else the exact solver's values)
FLAT_TARGET = 1e-5
#: the exact flat-punch solver's limit in a/H (beyond it the thin forms are better than 5e-5)
MAX_EXACT = 200.0
#: the chi grid of the inversion c/H = chi Gamma(chi)
_GRID = np.geomspace(1e-6, 1e7, 2601)


# --------------------------------------------------------------------------- (J.17) the flat part
#: the exact solver's values are interpolated (Chebyshev in log lambda, TABLE_NODES nodes) on [TABLE_LO, <= TABLE_HI]
TABLE_LO, TABLE_HI, TABLE_NODES = 0.05, 60.0, 40
#: order of the thick-layer series (F.18) below TABLE_LO (estimate below 1e-7 there; 0.4 s to build per layer)
THICK_ORDER = 6


@lru_cache(maxsize=4096)
def _exact_flat(layer: Any, lam: float) -> tuple[float, float, float, float]:
    st = flat_punch_kappa(layer, lam)
    err = max(st.error, 1e-12)
    return st.kappa, st.edge_value**2, err, 4.0 * err


@lru_cache(maxsize=16)
def _flat_table(layer: Any) -> tuple[float, float, np.ndarray, np.ndarray, float, float]:
    """``(t_lo, t_hi, coefficients of log kappa, of log g, e_kappa, e_g)``: Chebyshev interpolants in
    ``t = log lambda`` of the exact solver's ``kappa`` and ``g = f(1)^2`` (Krein (F.9)) on ``[TABLE_LO, hi]``,
    ``hi`` where the thin form's estimate reaches FLAT_TARGET (at most TABLE_HI).  The estimates: four times the
    sum of the last four coefficients' magnitudes (measured: 10 to 100 times the true interpolation error at points
    between the nodes) plus the solver's own estimate at the largest node (the solver's error grows with lambda).
    One exact solve per node, once per layer (about 0.5 s).
    """
    th = thin_flat_punch(layer)
    x = np.geomspace(TABLE_LO, TABLE_HI, 400)
    ok = th.error_estimate(x) <= FLAT_TARGET
    hi = float(x[int(np.argmax(ok))]) if np.any(ok) else TABLE_HI
    a, b = math.log(TABLE_LO), math.log(hi)
    k = np.arange(TABLE_NODES)
    xn = np.cos((2 * k + 1) * np.pi / (2 * TABLE_NODES))
    # the solver's own estimate (a second solve with 0.7 times the nodes) at the largest lambda, where it is largest
    sols = [flat_punch_kappa(layer, math.exp(0.5 * (a + b) + 0.5 * (b - a) * v), error_estimate=bool(v == xn.max()))
            for v in xn]
    solver = max(max(st.error for st in sols), 1e-12)
    ck = np.polynomial.chebyshev.chebfit(xn, np.log([st.kappa for st in sols]), TABLE_NODES - 1)
    cg = np.polynomial.chebyshev.chebfit(xn, np.log([st.edge_value**2 for st in sols]), TABLE_NODES - 1)
    ek = 4 * float(np.abs(ck[-4:]).sum()) + solver
    eg = 4 * float(np.abs(cg[-4:]).sum()) + 4 * solver
    for arr in (ck, cg):
        arr.setflags(write=False)
    return a, b, ck, cg, ek, eg


def flat_release_factor(layer: Any, a_over_H: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray,
                                                                 list[str]]:
    """``(kappa, g, e_kappa, e_g, models)`` of the flat punch at ``lambda = a/H`` (J.17), vectorised.

    ``g = d(lambda kappa)/d lambda`` (``= f(1)^2`` by Krein (F.9)); ``e_kappa``, ``e_g`` relative estimates; the
    model of each value: ``"thick"`` (F.18) below TABLE_LO, ``"thin"`` (F.12)/(F.14)/(F.15), ``"table"`` (the
    exact solver's values interpolated, :func:`_flat_table`) or ``"exact"`` (F.6)-(F.7) solved at that value
    (between TABLE_HI and the thin form's range).
    """
    layer = check_numeric_layer(layer)
    lam = np.atleast_1d(np.asarray(a_over_H, dtype=float))
    if not np.all(np.isfinite(lam)) or np.any(lam <= 0):
        raise InputError("a/H must be finite and > 0")
    if not layer.has_thickness:
        return np.ones_like(lam), np.ones_like(lam), np.zeros_like(lam), np.zeros_like(lam), ["exact"] * lam.size
    kappa, g, ek, eg = (np.full(lam.shape, np.nan) for _ in range(4))
    models = np.full(lam.shape, "exact", dtype=object)
    th = thin_flat_punch(layer)
    e = th.error_estimate(lam)
    use = (e <= FLAT_TARGET) | (lam > MAX_EXACT)
    if np.any(use):
        x = lam[use]
        step = 1e-4 * x
        kappa[use], ek[use], eg[use] = th(x), e[use], e[use]
        g[use] = ((x + step) * th(x + step) - (x - step) * th(x - step)) / (2 * step)
        models[use] = "thin"
    low = np.isnan(kappa) & (lam < TABLE_LO)
    if np.any(low):
        tk = thick_flat_punch(layer, THICK_ORDER)
        x = lam[low]
        cs = np.asarray(tk.coefficients)
        dcs = cs * np.arange(1, cs.size + 1)  # d/dlambda of sum c_k lambda^{k+1}
        N = cs.size - 1
        gx = np.polynomial.polynomial.polyval(x, dcs)
        kappa[low], g[low], ek[low] = tk(x), gx, tk.error_estimate(x)
        eg[low] = (np.abs(dcs[N] * x**N) + np.abs(dcs[N - 1] * x ** (N - 1))) / np.abs(gx)
        models[low] = "thick"
    mid = np.isnan(kappa) & (lam <= TABLE_HI)
    if np.any(mid):
        a, b, ck, cg, e_k, e_g = _flat_table(layer)
        t = np.log(lam[mid])
        inside = t <= b
        xs = (2 * t[inside] - (a + b)) / (b - a)
        idx = np.flatnonzero(mid)[inside]
        kappa[idx] = np.exp(np.polynomial.chebyshev.chebval(xs, ck))
        g[idx] = np.exp(np.polynomial.chebyshev.chebval(xs, cg))
        ek[idx], eg[idx] = e_k, e_g
        models[idx] = "table"
    for i in np.flatnonzero(np.isnan(kappa)):
        kappa[i], g[i], ek[i], eg[i] = _exact_flat(layer, float(lam[i]))
    return kappa, g, ek, eg, list(models)


# --------------------------------------------------------------------------- the states
@dataclass(frozen=True)
class JKRStates(RichDisplay):
    """JKR states of the sphere at given contact radii by the any-thickness law (J.16)-(J.18); arrays.

    Attributes
    ----------
    radius, delta, force : numpy.ndarray
        numpy.ndarray
        Contact radii and the JKR depth and (signed, tensile negative) force there.
    delta_error, force_error : numpy.ndarray
        numpy.ndarray
        Absolute error estimates (J.18).
    delta_smooth, force_smooth, flat_depth : numpy.ndarray
        numpy.ndarray
        ``delta_1(c)``, ``P_1(c)`` and ``d`` of (J.16).
    kappa, release_factor : numpy.ndarray
        numpy.ndarray
        ``kappa(c/H)`` and ``g(c/H)`` (J.17).
    flat_models : tuple of str
        The flat part's model at each radius.
    """

    radius: np.ndarray
    delta: np.ndarray
    force: np.ndarray
    delta_error: np.ndarray
    force_error: np.ndarray
    delta_smooth: np.ndarray
    force_smooth: np.ndarray
    flat_depth: np.ndarray
    kappa: np.ndarray
    release_factor: np.ndarray
    flat_models: tuple

    equation = "J.16"

    def latex(self) -> str:
        return (r"\delta = \delta_1(c) + d,\quad P = P_1(c) + 4\vartheta c\,\kappa\, d,\quad "
                r"d = -\sqrt{\frac{\pi c w}{\vartheta\, g(c/H)}} \tag{J.16}")

    def text_lines(self) -> list[str]:
        out = [f"JKRStates: {self.radius.size} contact radii   (J.16)-(J.18)"]
        for i in range(min(self.radius.size, 8)):
            out.append(f"  c = {self.radius[i]:.8g}: delta = {self.delta[i]:.10g} (+- {self.delta_error[i]:.1e}), "
                       f"P = {self.force[i]:.10g} (+- {self.force_error[i]:.1e}), flat part {self.flat_models[i]}")
        return out


@dataclass(frozen=True, eq=False)
class AnyThicknessJKR(RichDisplay):
    """The sphere's JKR law at any thickness for one layer (J.16)-(J.18).

    Attributes
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)``, ``IncompressibleLayer()`` or ``FrictionlessLayer()``.
    nu : float
        The Poisson ratio in ``vartheta = mu/(1 - nu)``.
    base : str
        ``"bonded"`` or ``"frictionless"``.
    """

    layer: Any
    nu: float
    base: str

    equation = "J.16"

    @property
    def _law(self):
        return any_thickness_law(self.nu, self.base)

    def _chi_of_radius(self, lam: np.ndarray) -> np.ndarray:
        """``chi`` with ``chi Gamma(chi) = lambda`` (Newton in log chi from the grid)."""
        lg, sl = _grid(self.nu, self.base)
        t = np.log(lam)
        x = np.interp(t, lg, np.log(_GRID))
        for _ in range(4):
            y = x + np.log(self._law.ratios(np.exp(x))[1])
            x = x - (y - t) / np.interp(x, np.log(_GRID), sl)
        return np.exp(x)

    def smooth(self, radius: Any, H: Any, R: Any, mu: Any = 1.0) -> tuple[np.ndarray, ...]:
        """``(delta_1, P_1, err delta_1, err P_1)``: the non-adhesive sphere at contact radius ``c`` (J.16), (J.18)."""
        c = positive_radii(radius)
        Hv, Rv, vt = positive(H, "H"), positive(R, "R"), positive(mu, "mu") / (1.0 - self.nu)
        law = self._law
        chi = self._chi_of_radius(c / Hv)
        Pr, _ = law.ratios(chi)
        eP, ec = law.error_estimate(chi)
        x = np.log(chi)
        _, dlp = law.log_force_ratio(x)
        lg, sl = _grid(self.nu, self.base)
        s_c = 0.5 * np.interp(x, np.log(_GRID), sl)  # d log c/d log delta = (1/2) d log(chi Gamma)/d log chi
        s_P = 1.5 + 0.5 * dlp
        delta1 = (chi * Hv) ** 2 / Rv
        P1 = 8.0 / 3.0 * vt * math.sqrt(Rv) * delta1**1.5 * Pr
        e_d = ec / s_c
        return delta1, P1, e_d * delta1, (eP + s_P * e_d) * P1

    def states(self, radius: Any, H: Any, R: Any, work_of_adhesion: Any, mu: Any = 1.0) -> JKRStates:
        """The JKR states at the contact radii ``c`` (J.16)-(J.18), vectorised."""
        c = np.atleast_1d(positive_radii(radius))
        Hv, wv, vt = positive(H, "H"), check_work(work_of_adhesion), positive(mu, "mu") / (1.0 - self.nu)
        d1, P1, ed1, eP1 = self.smooth(c, Hv, R, mu)
        kappa, g, ek, eg, models = flat_release_factor(self.layer, c / Hv)
        d = -np.sqrt(math.pi * c * wv / (vt * g))  # (J.17): G = w, tensile root
        S = 4.0 * vt * c * kappa
        delta, P = d1 + d, P1 + S * d
        e_delta = ed1 + 0.5 * np.abs(d) * eg
        e_P = eP1 + S * np.abs(d) * (ek + 0.5 * eg)
        arrays = [c, delta, P, e_delta, e_P, d1, P1, d, kappa, g]
        for a in arrays:
            a.setflags(write=False)
        return JKRStates(*arrays, tuple(models))

    def evaluate(self, radius: Any, H: Any, R: Any, work_of_adhesion: Any, mu: Any = 1.0) -> tuple[np.ndarray,
                                                                                                     np.ndarray]:
        """``(delta, P)`` at the contact radii (J.16)."""
        st = self.states(radius, H, R, work_of_adhesion, mu)
        shape = np.shape(radius)
        return st.delta.reshape(shape), st.force.reshape(shape)

    def error_estimate(self, radius: Any, H: Any, R: Any, work_of_adhesion: Any,
                       mu: Any = 1.0) -> tuple[np.ndarray, np.ndarray]:
        """Absolute estimates ``(delta, P)`` of :meth:`evaluate` (J.18)."""
        st = self.states(radius, H, R, work_of_adhesion, mu)
        shape = np.shape(radius)
        return st.delta_error.reshape(shape), st.force_error.reshape(shape)

    def _minimum(self, which: int, H: float, R: float, w: float, mu: float) -> tuple[float, float, float]:
        """``(c, value, error)`` at the minimum of ``delta(c)`` (which 0) or ``P(c)`` (which 1) (J.6)."""
        a0 = (9 * math.pi * w * R * R / (4 * mu / (1 - self.nu))) ** (1 / 3)  # half-space JKR radius at P = 0
        lo = min(1e-3 * a0, 0.01 * H)  # on a thin layer the minimum of delta(c) lies at c = O(H) (J.12)
        grid = np.geomspace(lo, 10 * a0, 31 + int(8 * math.log10(1e-3 * a0 / lo)))

        def f(x: float) -> float:
            return float(self.evaluate(np.array([x]), H, R, w, mu)[which][0])

        vals = self.evaluate(grid, H, R, w, mu)[which]
        i = int(np.argmin(vals))
        if i == 0 or i == grid.size - 1:
            raise InputError(f"the minimum of the JKR curve lies outside c in [{grid[0]:.4g}, {grid[-1]:.4g}]")
        a, b = math.log(grid[i - 1]), math.log(grid[i + 1])
        gr = (math.sqrt(5) - 1) / 2
        x1, x2 = b - gr * (b - a), a + gr * (b - a)
        f1, f2 = f(math.exp(x1)), f(math.exp(x2))
        while b - a > 1e-6:  # in log c: the value at the minimum to ~1e-12 relative
            if f1 < f2:
                b, x2, f2 = x2, x1, f1
                x1 = b - gr * (b - a)
                f1 = f(math.exp(x1))
            else:
                a, x1, f1 = x1, x2, f2
                x2 = a + gr * (b - a)
                f2 = f(math.exp(x2))
        cm = math.exp(0.5 * (a + b))
        st = self.states(np.array([cm]), H, R, w, mu)
        err = (st.delta_error if which == 0 else st.force_error)[0]
        return cm, float((st.delta if which == 0 else st.force)[0]), float(err)

    def pull_off(self, H: Any, R: Any, work_of_adhesion: Any, mu: Any = 1.0) -> tuple[float, float, float]:
        """``(c, P_off, error)`` under load control: ``P_off = -min P(c)`` (J.6), a tensile magnitude."""
        Hv, Rv, wv, mv = positive(H, "H"), positive(R, "R"), positive(work_of_adhesion, "work_of_adhesion"), \
            positive(mu, "mu")
        c, P, e = self._minimum(1, Hv, Rv, wv, mv)
        return c, -P, e

    def pull_off_displacement(self, H: Any, R: Any, work_of_adhesion: Any, mu: Any = 1.0) -> tuple[float, float,
                                                                                                     float, float]:
        """``(c, P_off, delta, error of P)`` under displacement control: at ``min delta(c)`` (J.6)."""
        Hv, Rv, wv, mv = positive(H, "H"), positive(R, "R"), positive(work_of_adhesion, "work_of_adhesion"), \
            positive(mu, "mu")
        c, dmin, _ = self._minimum(0, Hv, Rv, wv, mv)
        st = self.states(np.array([c]), Hv, Rv, wv, mv)
        return c, -float(st.force[0]), dmin, float(st.force_error[0])

    def latex(self) -> str:
        return (r"\delta = \delta_1(c) + d,\quad P = P_1(c) + 4\vartheta c\,\kappa(c/H)\, d,\quad "
            r"G = \frac{d^2 S'(c)}{4\pi c} = \frac{\vartheta d^2 g(c/H)}{\pi c} = w \tag{J.17}")

    def text_lines(self) -> list[str]:
        return [f"AnyThicknessJKR: the sphere on {self.layer} ({self.base} base, nu = {self.nu:g}) at any thickness"
                "   (J.16)-(J.18)",
                "  delta = delta_1(c) + d, P = P_1(c) + 4 vartheta c kappa(c/H) d, d = -sqrt(pi c w/(vartheta g(c/H)))",
                "  delta_1, P_1: the any-thickness law (T.7); kappa, g = (lambda kappa)': the flat punch "
                "(F.12)-(F.15), (F.6)"]


@lru_cache(maxsize=64)
def _grid(nu: float, base: str) -> tuple[np.ndarray, np.ndarray]:
    """``log(chi Gamma(chi))`` on the chi grid and its slope in ``log chi`` (increasing: the inversion's start)."""
    lg = np.log(_GRID * any_thickness_law(nu, base).ratios(_GRID)[1])
    sl = np.gradient(lg, np.log(_GRID))
    for a in (lg, sl):
        a.setflags(write=False)
    return lg, sl


def any_thickness_jkr(layer: Any, nu: Any = None) -> AnyThicknessJKR:
    """The sphere's JKR law at any thickness for ``layer`` (J.16)-(J.18).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)``, ``IncompressibleLayer()`` or ``FrictionlessLayer()`` (a layer on a rigid base).
    nu : float, optional
        Poisson ratio for a layer that fixes none (the frictionless base).

    Returns
    -------
    AnyThicknessJKR

    Examples
    --------
    A thick layer (H = 1000 R-scale lengths) is the half-space: JKR (1971), ``delta = c^2/R - sqrt(2 pi w c/E*)``,
    ``E* = 2 mu/(1 - nu)``:

    >>> from thinlayer import BondedLayer
    >>> law = any_thickness_jkr(BondedLayer(0.3))
    >>> d, P = law.evaluate(1.0, H=1e4, R=10.0, work_of_adhesion=0.01)
    >>> Es = 2 / 0.7
    >>> abs(float(d) - (0.1 - math.sqrt(2 * math.pi * 0.01 / Es))) < 1e-4
    True
    """
    layer = check_numeric_layer(layer)
    base = layer.base_label
    if base not in ("bonded", "frictionless"):
        raise InputError(f"the any-thickness JKR law needs a layer on a rigid base (BondedLayer, IncompressibleLayer,"
                         f" FrictionlessLayer), got {layer!r}")
    nu_val = float(layer.poisson_ratio(nu))
    if not -1.0 < nu_val <= 0.5 or (base == "frictionless" and nu_val >= 0.5):
        raise InputError(f"nu must lie in (-1, 1/2] (bonded) or (-1, 1/2) (frictionless base), got {nu!r}")
    return AnyThicknessJKR(layer, nu_val, base)
