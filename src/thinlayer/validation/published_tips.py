r"""Published bottom-effect corrections of a cone on a bonded layer, as quoted, against the engine (issue 24 item 5).

AFM users correct Sneddon's cone ``P_S = 4 vartheta tan(theta) delta^2/pi`` (``= 8 E tan(theta) delta^2/(3 pi)`` at
``nu = 1/2``, ``vartheta = mu/(1 - nu)``) for a layer of thickness h bonded to a rigid base by a series in
``X = delta tan(theta)/h``:

    P/P_S = 1 + sum_n c_n X^n.

Two published series are implemented here as they are quoted (:data:`GAVARA_2012`, :data:`GARCIA_2018_CONE`).
Neither publication's equations could be read by this project, in three rounds of searching: :data:`READ_ATTEMPTS`
(:mod:`thinlayer.validation.published_sources`) lists every address tried and what it held (for Gavara & Chadwick
the opening of the PubMed Central author manuscript PMC3492504, up to the end of its first paragraph, and the
publisher's abstract page; for Garcia & Garcia no stored copy at all, only reference lists citing it).  The
coefficients are those that two public code repositories attribute to the publications, and every value here is
labelled "as quoted in" those repositories (a secondary source), never as the paper's own print; no equation number
or page of either paper is cited, because none was seen.

Derivation (PT.1)-(PT.4): the same series, derived
------------------------------------------------------
(PT.1) *Regular kernel through b_1.*  By (T.2) the layer's displacement is Boussinesq's plus
``-(1/(2 pi vartheta H)) iint p(y) (b_0 - b_1 |x - y|^2/(4 H^2)) dy`` and terms of ``b_2`` (relative order
``(c/H)^5``).  The ring average of ``|x - y|^2`` is ``r^2 + rho^2`` (T.3), so with ``P = iint p`` and
``mu_1 = iint p |y|^2`` the contact condition ``u_3 = delta - Phi`` on ``r < c`` (1.5) is the half-space problem of
the punch and depth

    Phi_e(r) = Phi(r) + q r^2,   q = b_1 P/(8 pi vartheta H^3),
    delta_e  = delta + b_0 P/(2 pi vartheta H) - b_1 mu_1/(8 pi vartheta H^3).

(PT.2) *Half-space relations* (Sneddon's (S1), (S2) of :mod:`thinlayer.validation.sneddon`, with ``g = (2 vartheta/pi)
(delta_e - D(t))``): ``delta_e = D(c)``, ``D(t) = t int_0^1 Phi_e'(t x)/sqrt(1 - x^2) dx``,
``P = 4 vartheta int_0^c (D(c) - D(t)) dt``, ``mu_1 = 8 vartheta int_0^c (D(c) - D(t)) t^2 dt`` (the Abel/Copson
pressure integrated against ``r^2``).  P is linear in q, so q follows exactly; sympy evaluates every integral.

(PT.3) *Series.*  Eliminating c (series reversion in ``X``) gives for the cone ``Phi = r cot(theta)``

    P/P_S = 1 + (4 b_0/pi^2) X + (20 b_0^2/pi^4) X^2 + (4 (28 b_0^3 - pi^2 b_1)/pi^6) X^3
              + (56 b_0 (12 b_0^3 - pi^2 b_1)/pi^8) X^4 + O(X^5),

exact in ``b_0, b_1`` (``b_2`` enters at ``X^5``).  The ratio depends on ``X`` only: with ``Phi = r cot(theta)`` the
problem at ``(delta, theta)`` is ``cot(theta)`` times the problem at ``(delta tan(theta), 45 deg)``.  At ``nu = 1/2``
(``b_0 = 1.770217``, ``b_1 = 3.831077``): ``1 + 0.71744 X + 0.64340 X^2 + 0.48893 X^3 + 0.30043 X^4``.  The same
route on the paraboloid reproduces the engine's own (T.7) sphere series term by term (the tests), and the direct
solver confirms the cone's series (remainder ``O(X^5)``).

On a layer lying without friction on the base (``base="frictionless"``, a kernel without nu: ``b_0 = 1.167577``,
``b_1 = 1.581526``) the same route gives ``1 + 0.47320 X + 0.27990 X^2 + 0.12048 X^3 + 0.02406 X^4``; the direct solver
leaves ``-6.4e-9``, ``-2.2e-7``, ``-7.9e-6`` at ``X = 0.05``, ``0.1``, ``0.2`` (``X^5``).  No published non-bonded cone
series was read; the bonded ``nu = 1/2`` series as quoted (Garcia & Garcia) makes the correction 1.57 times too large
on such a layer at ``X = 0.1``.

(PT.4) *Convergence.*  The series of (T.2) converges for ``c < H``; for the cone ``c = 2 X H/pi (1 + ...)``, so
``X`` up to about 1.4.  The comparisons run over ``X <= 1``.

Measured (:func:`comparison_table`, ``nu = 1/2``, the direct solver's own estimate below ``1e-10``; relative
difference of each route's force from the direct solver's)::

       X     c/H  direct P/P_S  derived(PT.3)  gavara2012-becc  garcia2018-cone
   0.010  0.0064    1.00723925      -1.01e-11        +1.42e-03        +3.60e-05
   0.020  0.0128    1.01461016      -3.17e-10        +1.27e-02        +7.27e-05
   0.050  0.0324    1.03754362      -2.97e-08        +1.03e-01        +1.87e-04
   0.100  0.0661    1.07869813      -8.76e-07        +4.30e-01        +3.85e-04
   0.200  0.1378    1.17364337      -2.28e-05        +1.64e+00        +7.20e-04
   0.300  0.2160    1.28893950      -1.29e-04        +3.40e+00        +7.29e-04
   0.500  0.3943    1.60021146      -4.67e-04        +7.65e+00        -1.11e-03
   0.750  0.6554    2.19015008      +5.10e-03        +1.26e+01        -2.49e-03
   1.000  0.9432    3.04437376      +3.48e-02        +1.61e+01        +1.40e-02

Beyond the thick range, on compressible layers (:func:`thin_layer_table`), the cone's thin-layer law ``P_0 + P_1``
against the direct solver: ``nu = 0.3``: ``-0.25``, ``-4.0e-2``, ``-2.1e-3``, ``-2.0e-4``, ``-2.2e-5`` at ``X = 1, 2,
5, 10, 20``; ``nu = 0.45``: ``-1.2e1``, ``-2.0``, ``-0.11``, ``-9.3e-3``, ``-8.6e-4`` (the thin law of a nearly
incompressible layer needs a far thinner layer).  There the published series (for ``nu = 1/2``, thick layers) are off
by factors 20 to 1000; at ``nu = 0.45`` and ``X = 1`` Garcia & Garcia's is ``+19 %`` off (their ``nu = 1/2``).

(PT.5) *Any self-similar tip, through X^2: the pyramid.*  The constant part ``b_0`` of (T.2) shifts the displacement
uniformly, whatever the contact's shape: the layer at depth delta is the half-space at ``delta + b_0 P/(2 pi vartheta
H)``, the ``b_1`` part entering at relative order ``(c/H)^3``.  For a tip whose half-space force is ``P_hs = K
delta^m`` (cone, pyramid: m = 2) the ratio ``y = P/P_hs`` therefore solves ``y = (1 + eps y)^m``, ``eps = b_0
P_hs(delta)/(2 pi vartheta H delta)``:

    y = 1 + m eps + (3 m^2 - m)/2 eps^2 + O(eps^3)            (:func:`homogeneous_tip_series`, sympy)

The cone (``K = 4 vartheta tan(theta)/pi``, ``eps = 2 b_0 X/pi^2``) gives back the first two terms of (PT.3).  A
regular pyramid of face angle alpha has ``P_hs = k vartheta tan(alpha) delta^2`` (k does not depend on alpha or nu,
by scaling), so ``P/P_hs = 1 + (b_0 k/pi) X + 5 (b_0 k/(2 pi))^2 X^2 + O(X^3)``, ``X = delta tan(alpha)/h``.  k is
measured by the 2D solver on the half-space (:func:`pyramid_half_space_coefficient`): 1.47582, 1.47539, 1.47528 at
n = 128, 256, 512 for four faces (cf. Sneddon's cone, ``4/pi = 1.27324``).  At ``nu = 1/2`` the pyramid's
coefficients are ``0.8313``, ``0.8638`` with k at n = 512 (the cone's ``0.7174``, ``0.6434``).  Checked against
the 2D solver on a bonded layer (``nu = 0.3``, X = 0.1, 0.05, both forces on one grid): the remainder after the two
terms is ``2.9e-4`` and ``3.4e-5`` at n = 256, falling like ``X^3`` (``THINLAYER_SLOW``); at n = 128 ``2.8e-4`` and
``-2.8e-5`` (a grid floor of about ``5e-5``), where the cone's two terms leave ``1.0e-2`` and ``4.7e-3``.  Two
repositories (pyAF, ViscoIndent) apply the cone's coefficients to pyramids with ``X = delta tan(angle)/h``
(:data:`GARCIA_2018_PYRAMID_AS_APPLIED`): read with the face angle their first coefficient ``0.721`` is 13 % below
the pyramid's ``0.8313``, read with the edge angle (``tan = sqrt(2) tan(alpha)``, ``0.721 sqrt(2) = 1.020``) 23 %
above; the errata registry holds the entry.  The half-space prefactors the repositories put in front
(:data:`PYRAMID_PREFACTORS_AS_IMPLEMENTED`, ``P = c E tan(angle) delta^2/(1 - nu^2)``): ViscoIndent's ``1.406/2`` and
PyFMRheo's ``1/sqrt(2)`` are 4.7 % and 4.1 % below the engine's ``k/2 = 0.73764`` read with the face angle, 35 %
above read with the edge angle (:func:`pyramid_prefactor_differences`; neither file names a publication for it, so
no errata entry).

Against the engine's any-thickness cone law (:func:`law_comparison`;
:func:`thinlayer.contact.any_thickness_tips.cone_law`, ``chi = c_0/H = 2X/pi``, within its estimate, at most
``7.4e-5`` for ``X <= 1``, of the direct solver) on 400 points of ``0.005 <= X <= 1`` at ``nu = 1/2``, the largest
relative differences are: Garcia & Garcia as quoted ``3.8e-4``, ``7.9e-4``, ``-1.09e-3``, ``+1.40e-2`` over
``X <= 0.1``, ``0.3``, ``0.5``, ``1``; Gavara & Chadwick as quoted ``+0.43``, ``+3.4``, ``+7.6``, ``+16``; the
derived four terms (PT.3) ``-9.5e-7``, ``-1.3e-4``, ``-4.7e-4``, ``+3.5e-2`` (``THINLAYER_SLOW`` test: building the
law costs about 3 s).

The tables put each published series beside the direct axisymmetric solver
(:func:`thinlayer.numerics.axisymmetric.solve_axisymmetric`, no asymptotics), the derived series (PT.3) and, for
compressible layers at large ``X``, the thin-layer law of the cone (:mod:`thinlayer.asymptotics.tip_law`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import numpy as np
import sympy as sp

from .._checks import InputError
from .published_sources import READ_ATTEMPTS  # every address tried, three rounds (shared registry)

__all__ = ["READ_ATTEMPTS", "PublishedCorrection", "GAVARA_2012", "GARCIA_2018_CONE", "PUBLISHED", "ComparisonRow",
           "cone_series", "paraboloid_series", "derived_cone_coefficients", "derived_cone_ratio", "direct_cone_ratio",
           "comparison_table",
           "format_table", "PYRAMID_STATUS", "ThinRow", "thin_layer_table", "GARCIA_2018_PYRAMID_AS_APPLIED",
           "homogeneous_tip_series", "pyramid_half_space_coefficient", "pyramid_series", "direct_pyramid_ratio",
           "LawComparison", "law_comparison", "PYRAMID_PREFACTORS_AS_IMPLEMENTED", "pyramid_prefactor_differences"]

#: the quoting repositories (a secondary source: the publications' own equations were not read)
PYAF = "sebastienjanel/pyAF, file src/compute_tools/stiffness_correction.py"
PYFMRHEO = "jlopezalo/PyFMRheo, file src/pyfmrheo/models/correction_factors.py"

#: what became of the pyramid of Garcia & Garcia (2018): the publication was not read (READ_ATTEMPTS); the repositories
#: that cite it apply the cone's coefficients to pyramids (GARCIA_2018_PYRAMID_AS_APPLIED), compared with (PT.5)
PYRAMID_STATUS = ("compared through X^2 only (PT.5): pyAF and ViscoIndent apply the cone's coefficients to pyramids; "
                  "the pyramid's own first two coefficients follow from its half-space force (2D solver) and b_0")


@dataclass(frozen=True)
class PublishedCorrection:
    r"""A published bottom-effect series ``P/P_S = 1 + sum_n c_n X^n``, ``X = delta tan(theta)/h``, as quoted.

    Attributes
    ----------
    key : str
        Short name.
    source : str
        Citation key of the publication (:mod:`thinlayer.references`).
    quoted_from : tuple of str
        The secondary sources the coefficients were read in (repository, file).
    quoted : str
        The formula as the secondary sources write it (LaTeX).
    coefficients : tuple of float
        ``c_1, c_2, ...`` of ``X^n``, from the quoted form.
    nu : float
        Poisson ratio the series is for (both assume an incompressible layer).
    stated_range : str
        What is known of the range the publication states (its text was not read).
    """

    key: str
    source: str
    quoted_from: tuple[str, ...]
    quoted: str
    coefficients: tuple[float, ...]
    nu: float
    stated_range: str

    def ratio(self, X: Any) -> np.ndarray:
        """``1 + sum_n c_n X^n`` at ``X = delta tan(theta)/h``."""
        X = np.asarray(X, dtype=float)
        return np.polynomial.polynomial.polyval(X, (1.0, *self.coefficients))

    def force(self, delta: Any, h: float, half_angle_deg: float, E: float) -> np.ndarray:
        """The published force ``8 E tan(theta) delta^2/(3 pi) (1 + sum_n c_n X^n)`` (``nu = 1/2``)."""
        t = math.tan(math.radians(half_angle_deg))
        d = np.asarray(delta, dtype=float)
        return 8 * E * t * d * d / (3 * math.pi) * self.ratio(d * t / h)


_A0 = 1.7795  # the alpha_0 both quoted series are written with (Dimitriadis et al. 2002's fitted value)

#: Gavara & Chadwick (2012), "bottom effect cone correction", as quoted in pyAF (a commented-out "old
#: Chadwick/Dimitriadis correction") and in PyFMRheo (``bec_gavara_cone``): both write
#: ``1 + 1.7795 (2 tan(theta)/pi^2) (delta/h) + 16 (1.7795)^2 tan^2(theta) (delta/h)^2``.
GAVARA_2012 = PublishedCorrection(
    "gavara2012-becc", "gavara2012", (PYAF, PYFMRHEO),
    r"1 + 1.7795\,\frac{2\tan\theta}{\pi^2}\,\frac{\delta}{h} + 16\,(1.7795)^2\tan^2\theta\,\frac{\delta^2}{h^2}",
    (2 * _A0 / math.pi**2, 16 * _A0**2), 0.5,
    "not read (READ_ATTEMPTS: the publication's text was not available); the title of its figure 2 on the "
    "publisher's page reads "
    "'Indentations larger than 10% of the sample thickness result in a very large overestimaton of the elastic "
    "modulus' (sic)")

#: Garcia & Garcia (2018), conical tip on a bonded layer, as quoted in PyFMRheo (``conical_model_factors``) and
#: in pyAF (the current "Sneddon (Cone and Pyramid)" correction): ``1 + 0.721 X + 0.650 X^2 + 0.491 X^3 + 0.225 X^4``.
GARCIA_2018_CONE = PublishedCorrection(
    "garcia2018-cone", "garcia2018", (PYFMRHEO, PYAF),
    r"1 + 0.721\,X + 0.650\,X^2 + 0.491\,X^3 + 0.225\,X^4,\ X = \frac{\delta\tan\theta}{h}",
    (0.721, 0.650, 0.491, 0.225), 0.5,
    "not read (READ_ATTEMPTS: no copy of the publication was available)")

PUBLISHED = (GAVARA_2012, GARCIA_2018_CONE)

VISCOINDENT = "yu-efremov/ViscoIndent, file bottom_effect_correction.py (commit 0709d3af)"

#: the cone's series of Garcia & Garcia as two repositories apply it to a pyramid (pyAF: "Sneddon (Cone and Pyramid)";
#: ViscoIndent: ``modelprobe in ['pyramid', 'cone']``), with X = delta tan(angle)/h; not in :data:`PUBLISHED` (the
#: tables are the cone's): compared in (PT.5)
GARCIA_2018_PYRAMID_AS_APPLIED = PublishedCorrection(
    "garcia2018-pyramid", "garcia2018", (PYAF, VISCOINDENT),
    r"1 + 0.721\,X + 0.650\,X^2 + 0.491\,X^3 + 0.225\,X^4,\ X = \frac{\delta\tan\alpha}{h}",
    (0.721, 0.650, 0.491, 0.225), 0.5,
    "not read (READ_ATTEMPTS: no copy of the publication was available); the repositories use the cone's series "
    "for pyramids")


# ---------------------------------------------------------------------------------------------
# (PT.1)-(PT.3): the series, derived
# ---------------------------------------------------------------------------------------------
_r, _t, _x, _c, _q = sp.symbols("r t x c q", positive=True)
_b0, _b1 = sp.symbols("b_0 b_1", positive=True)
ORDER = 4  # b_2 enters at order 5


def _relations(slope: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """``(delta(c), P(c))`` of (PT.1)-(PT.2) for ``Phi'(r) = slope``, for the kernel truncated after ``b_1``.

    ``q = b_1 P/(8 pi vartheta H^3)`` and ``P`` (linear in q) are iterated twice from ``q = 0``: the neglected part
    is of relative order ``(c/H)^6``, beyond :data:`ORDER`; the results are polynomials in c.  Units
    ``H = vartheta = 1`` (c stands for c/H, P for P/(vartheta H^2)).
    """
    phi_e = slope + 2 * _q * _r  # Phi_e' (PT.1), in units H = vartheta = 1
    D = sp.expand(_t * sp.integrate(sp.expand(phi_e.subs(_r, _t * _x)) / sp.sqrt(1 - _x**2), (_x, 0, 1)))  # (PT.2)
    Dc = D.subs(_t, _c)
    P = sp.expand(4 * sp.integrate(Dc - D, (_t, 0, _c)))
    mu1 = sp.expand(8 * sp.integrate((Dc - D) * _t**2, (_t, 0, _c)))
    q = sp.Integer(0)
    for _ in range(2):
        q = sp.expand(_b1 * P.subs(_q, q) / (8 * sp.pi))
    delta = Dc - _b0 * P / (2 * sp.pi) + _b1 * mu1 / (8 * sp.pi)
    return sp.expand(delta.subs(_q, q)), sp.expand(P.subs(_q, q))


def _trunc(expr: sp.Expr, var: sp.Symbol, n: int) -> sp.Expr:
    """The polynomial ``expr`` in ``var`` without its powers above ``n``."""
    e = sp.expand(expr)
    return sp.Add(*[e.coeff(var, k) * var**k for k in range(n + 1)])


def _compose(poly: sp.Expr, var: sp.Symbol, e: sp.Expr, X: sp.Symbol, n: int) -> sp.Expr:
    """``poly(e(X))`` to ``X^n`` (``e`` without constant term), truncating every power on the way."""
    p = sp.expand(poly)
    out, power = sp.Integer(0), sp.Integer(1)
    for k in range(n + 1):
        ak = p.coeff(var, k)
        if ak != 0:
            out += ak * power
        power = _trunc(power * e, X, n)
    return _trunc(out, X, n)


def _revert(of_eps: sp.Expr, eps: sp.Symbol, X: sp.Symbol, lead: sp.Expr, order: int) -> sp.Expr:
    """``eps(X)`` to ``X^(order+1)`` from ``X = of_eps(eps)``, a polynomial starting ``eps/lead``."""
    rest = sp.expand(of_eps - eps / lead)
    e = lead * X
    for _ in range(order):  # fixed point: each pass fixes one more power
        e = sp.expand(lead * (X - _compose(rest, eps, e, X, order + 1)))
    return e


def _sqrt_series(u: sp.Expr, var: sp.Symbol, n: int) -> sp.Expr:
    """``sqrt(1 + u)`` to ``var^n`` for a polynomial ``u`` without constant term."""
    return _trunc(sum(sp.binomial(sp.Rational(1, 2), k) * u**k for k in range(n + 1)), var, n)


@lru_cache(maxsize=4)
def cone_series(order: int = ORDER) -> tuple[tuple[sp.Expr, ...], tuple[sp.Expr, ...]]:
    r"""(PT.3): ``P/P_S`` and ``c/c_S`` of a cone on a thick layer in powers of ``X = delta tan(theta)/H``.

    ``P_S = 4 vartheta tan(theta) delta^2/pi``, ``c_S = 2 delta tan(theta)/pi`` (Sneddon).  Coefficients symbolic in
    the kernel moments ``b_0, b_1`` of (T.2).

    Returns
    -------
    (force, radius) : tuple of tuple of sympy.Expr
        Index n is the coefficient of ``X^n`` (index 0 is 1).

    Examples
    --------
    >>> force, radius = cone_series(2)
    >>> force
    (1, 4*b_0/pi**2, 20*b_0**2/pi**4)
    """
    order = _check_order(order)
    # theta = 45 deg: the ratio depends on X only (module docstring); c stands for eps = c/H
    delta, P = _relations(sp.Integer(1) + 0 * _r)
    X = sp.Symbol("X", positive=True)
    e = _revert(_trunc(delta, _c, order + 1), _c, X, 2 / sp.pi, order)  # X = delta tan(theta)/H = delta here
    # P/P_S, P_S = 4 vartheta tan(theta) delta^2/pi = 4 X^2/pi
    fr = sp.expand(_compose(P, _c, e, X, order + 2) * sp.pi / 4)
    rr = sp.expand(e * sp.pi / 2)
    return (tuple(sp.factor(fr.coeff(X, n + 2)) for n in range(order + 1)),
            tuple(sp.factor(rr.coeff(X, n + 1)) for n in range(order + 1)))


@lru_cache(maxsize=4)
def paraboloid_series(order: int = ORDER) -> tuple[sp.Expr, ...]:
    r"""The route (PT.1)-(PT.3) on the paraboloid ``r^2/(2R)``: ``P/P_Hertz`` in ``chi = sqrt(R delta)/H``.

    A check of the route against the engine's own thick-layer series (T.7), which it must reproduce term by term.
    """
    order = _check_order(order)
    # R = 1 (H = 1): chi = sqrt(delta) = c sqrt(delta/c^2), delta/c^2 = 1 + u(c)
    delta, P = _relations(_r)
    chi = sp.Symbol("chi", positive=True)
    u = _trunc(sp.expand(delta / _c**2) - 1, _c, order + 1)
    e = _revert(_trunc(sp.expand(_c * _sqrt_series(u, _c, order + 1)), _c, order + 1), _c, chi, 1, order)
    # P/P_Hertz, P_Hertz = (8/3) vartheta sqrt(R) delta^(3/2) = (8/3) chi^3
    fr = sp.expand(_compose(P, _c, e, chi, order + 3) * 3 / 8)
    return tuple(sp.factor(fr.coeff(chi, n + 3)) for n in range(order + 1))


def _check_order(order: Any) -> int:
    if isinstance(order, bool) or not isinstance(order, int) or not 1 <= order <= ORDER:
        raise InputError(f"order must be an integer in [1, {ORDER}] (b_2 enters at order 5), got {order!r}")
    return order


_BASES = ("bonded", "frictionless")


def _layer(nu: float, base: str = "bonded"):
    from ..layers.kernels import BondedLayer, FrictionlessLayer, IncompressibleLayer

    if isinstance(nu, bool) or not isinstance(nu, (int, float)) or not 0 <= nu <= 0.5:
        raise InputError(f"nu must be a number in [0, 0.5], got {nu!r}")
    if base not in _BASES:
        raise InputError(f"base must be 'bonded' or 'frictionless' (the layer's base), got {base!r}")
    if base == "frictionless":  # the kernel does not depend on nu; vartheta = mu/(1 - nu) does
        return FrictionlessLayer(nu=float(nu))
    return IncompressibleLayer() if nu == 0.5 else BondedLayer(float(nu))


def _moments(nu: float, base: str = "bonded") -> dict:
    from ..asymptotics.thick_layer import thick_moments

    b = thick_moments(_layer(nu, base), 1)
    return {_b0: float(b[0]), _b1: float(b[1])}


def derived_cone_coefficients(nu: float = 0.5, order: int = ORDER, base: str = "bonded") -> np.ndarray:
    """(PT.3) in numbers: ``(1, beta_1, ..., beta_order)`` of ``P/P_S = sum_n beta_n X^n`` for the layer."""
    return np.array([float(c.subs(_moments(nu, base))) for c in cone_series(order)[0]])


def derived_cone_ratio(X: Any, nu: float = 0.5, order: int = ORDER, base: str = "bonded") -> np.ndarray:
    """(PT.3) evaluated: ``P/P_S`` of the cone on a layer bonded to (or lying without friction on, ``base =
    "frictionless"``, independent of nu) a rigid base, at ``X = delta tan(theta)/H``.
    """
    return np.polynomial.polynomial.polyval(np.asarray(X, dtype=float), derived_cone_coefficients(nu, order, base))


def direct_cone_ratio(X: float, nu: float = 0.5, half_angle_deg: float = 45.0, n: int | None = None,
                      base: str = "bonded") -> tuple[float, float, float]:
    """``(P/P_S, c/H, estimated relative error of P)`` by the direct axisymmetric solver (H = mu = 1).

    Cached per ``(X, nu, angle, n, base)`` within a process (a solve takes seconds).
    """
    if isinstance(X, bool) or not isinstance(X, (int, float)) or not 0 < X <= 50:
        raise InputError(f"X = delta tan(theta)/h must be a number in (0, 50], got {X!r}")
    _layer(nu, base)
    return _direct(float(X), float(nu), float(half_angle_deg), n, base)


@lru_cache(maxsize=64)
def _direct(X: float, nu: float, half_angle_deg: float, n: int | None, base: str = "bonded"
            ) -> tuple[float, float, float]:
    from ..numerics.axisymmetric import solve_axisymmetric
    from ..punch import Punch

    t = math.tan(math.radians(half_angle_deg))
    d = X / t
    res = solve_axisymmetric(_layer(nu, base), Punch.cone(half_angle_deg), d, H=1.0, mu=1.0, n=n)
    ps = 4 / (1.0 - nu) * t * d * d / math.pi  # vartheta = mu/(1 - nu)
    return res.force / ps, res.radius, res.force_error / res.force


@dataclass(frozen=True)
class ComparisonRow:
    """One row of :func:`comparison_table`: ``X``, contact radius, the direct ratio and each route's difference."""

    X: float
    c_over_H: float
    direct: float
    direct_error: float
    derived: float
    published: tuple[tuple[str, float], ...]  # (key, ratio)

    def difference(self, key: str) -> float:
        """Relative difference of the published force against the direct solver."""
        return dict(self.published)[key] / self.direct - 1


def comparison_table(X_values=(0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0), nu: float = 0.5,
                     published=PUBLISHED, half_angle_deg: float = 45.0) -> tuple[ComparisonRow, ...]:
    """Each published series and the derived one (PT.3) against the direct solver over ``X`` (rows)."""
    rows = []
    for X in X_values:
        ratio, c, err = direct_cone_ratio(X, nu, half_angle_deg)
        rows.append(ComparisonRow(float(X), c, ratio, err, float(derived_cone_ratio(X, nu)),
                                  tuple((p.key, float(p.ratio(X))) for p in published)))
    return tuple(rows)


def format_table(rows, published=PUBLISHED) -> str:
    """The table as text: ``X``, ``c/H``, direct ``P/P_S``, and the relative difference of each route."""
    head = f"{'X':>6} {'c/H':>7} {'direct P/P_S':>13} {'derived(PT.3)':>14}" + "".join(
        f" {p.key:>16}" for p in published)
    lines = [head]
    for r in rows:
        lines.append(f"{r.X:6.3f} {r.c_over_H:7.4f} {r.direct:13.8f} {r.derived / r.direct - 1:+14.2e}"
                     + "".join(f" {r.difference(p.key):+16.2e}" for p in published))
    return "\n".join(lines)


@dataclass(frozen=True)
class ThinRow:
    """One row of :func:`thin_layer_table`: a compressible layer at large ``X``, where the thin-layer law holds."""

    X: float
    nu: float
    c_over_H: float
    direct: float
    thin_law: float  # (P_0 + P_1)/P_S of the thin-layer law (1.8)
    published: tuple[tuple[str, float], ...]


def thin_layer_table(X_values=(2.0, 5.0, 10.0), nu: float = 0.45, published=PUBLISHED,
                     half_angle_deg: float = 45.0) -> tuple[ThinRow, ...]:
    """Beyond the thick-layer range, on a compressible bonded layer: direct solver, the cone's thin-layer law
    ``P_0 + P_1`` (:func:`thinlayer.asymptotics.tip_law.tip_force_law`) and each published series (all as
    ``P/P_S``).  The published series are for ``nu = 1/2`` and a thick layer: this shows what they give outside.
    """
    from ..asymptotics.tip_law import tip_force_law
    from ..punch import Punch

    if nu >= 0.5:
        raise InputError(f"the thin-layer law (1.8) of the cone is for compressible layers (nu < 1/2), got nu = {nu}")
    law = tip_force_law(_layer(nu), Punch.cone(half_angle_deg))
    t = math.tan(math.radians(half_angle_deg))
    rows = []
    for X in X_values:
        ratio, c, _ = direct_cone_ratio(X, nu, half_angle_deg)
        d = X / t
        ps = 4 / (1 - nu) * t * d * d / math.pi
        p0, p1 = law.evaluate(d, 1.0, 1.0)
        quoted = tuple((p.key, float(p.ratio(X))) for p in published)
        rows.append(ThinRow(float(X), nu, c, ratio, (p0 + p1) / ps, quoted))
    return tuple(rows)


# ---------------------------------------------------------------------------------------------
# (PT.5): any self-similar tip through X^2; the pyramid
# ---------------------------------------------------------------------------------------------
_eps = sp.Symbol("epsilon", positive=True)


@lru_cache(maxsize=8)
def homogeneous_tip_series(m: int = 2, order: int = 2) -> tuple[sp.Expr, ...]:
    r"""(PT.5): ``P/P_hs = sum_j y_j eps^j`` for a tip with ``P_hs = K delta^m``, ``eps = b_0 P_hs/(2 pi vartheta H
    delta)``: the fixed point of ``y = (1 + eps y)^m`` to ``eps^order`` (order <= 2: ``b_1`` enters at 3).

    Examples
    --------
    >>> homogeneous_tip_series(2)
    (1, 2, 5)
    """
    if isinstance(m, bool) or not isinstance(m, int) or not 1 <= m <= 8:
        raise InputError(f"m (P_hs ~ delta^m) must be an integer in [1, 8], got {m!r}")
    if isinstance(order, bool) or not isinstance(order, int) or not 1 <= order <= 2:
        raise InputError(f"order must be 1 or 2 (b_1 enters at order 3), got {order!r}")
    y = sp.Integer(1)
    for _ in range(order):
        y = _trunc(sp.expand((1 + _eps * y) ** m), _eps, order)
    return tuple(sp.expand(y).coeff(_eps, j) for j in range(order + 1))


def _sides(sides: Any) -> int:
    if isinstance(sides, bool) or sides not in (3, 4):
        raise InputError(f"sides must be 3 or 4, got {sides!r}")
    return int(sides)


@lru_cache(maxsize=8)
def pyramid_half_space_coefficient(sides: int = 4, n: int = 128) -> float:
    """``k = P_hs/(vartheta tan(alpha) delta^2)`` of a regular pyramid on the half-space, by the 2D solver
    (:func:`thinlayer.numerics.fft2d.solve_2d`, n x n cells, alpha = 45 deg, delta = 1; k depends on neither).
    """
    from ..layers.kernels import HalfSpace
    from ..numerics.fft2d import solve_2d
    from ..punch import Punch

    res = solve_2d(HalfSpace(), Punch.pyramid(45, _sides(sides)), delta0=1.0, n=n, nu=0.3, extent=_extent(sides))
    return res.force * (1 - 0.3)  # vartheta = 1/(1 - nu), tan 45 = 1, delta = 1


def _extent(sides: int) -> float:
    return 1.5 if sides == 4 else 2.2  # corners at 1/cos(pi/N): 1.414, 2.0 (delta tan(alpha) = 1)


#: the half-space prefactor ``c`` of ``P = c E tan(angle) delta^2/(1 - nu^2)`` that two repositories use for a 4-sided
#: pyramid (a secondary source; neither file cites a publication for it, ViscoIndent's documentation calls its model
#: "Bilodeau"): ``{repository, file: c}``.  The engine's is ``k/2`` with ``k`` of
#: :func:`pyramid_half_space_coefficient` (face angle: ``P = k vartheta tan(alpha) delta^2``, ``vartheta = E/(2 (1 -
#: nu^2))``).
PYRAMID_PREFACTORS_AS_IMPLEMENTED = {
    "yu-efremov/ViscoIndent, Ting_numerical.py (commit c90ee84): K1 = 1.406/2 tan(angle)": 1.406 / 2,
    "jlopezalo/PyFMRheo, src/pyfmrheo/models/geom_coeffs.py: 1/sqrt(2) tan(angle)": 1 / math.sqrt(2),
}


def pyramid_prefactor_differences(n: int = 128) -> dict[str, tuple[float, float]]:
    """Each implemented prefactor against the engine's ``k/2`` (2D solver, ``n x n``): ``(relative difference with the
    angle read as the face angle, with the angle read as the edge angle, tan larger by sqrt(2))``.

    Measured: ``k/2 = 0.73764`` (n = 512); ViscoIndent ``-4.7 %`` (face) or ``+34.8 %`` (edge), PyFMRheo ``-4.1 %``
    or ``+35.6 %``.
    """
    half = pyramid_half_space_coefficient(4, n) / 2
    return {key: (c / half - 1, c * math.sqrt(2) / half - 1) for key, c in PYRAMID_PREFACTORS_AS_IMPLEMENTED.items()}


def pyramid_series(nu: float = 0.5, sides: int = 4, n: int = 128) -> tuple[float, float]:
    """(PT.5): the pyramid's ``(c_1, c_2)`` of ``P/P_hs = 1 + c_1 X + c_2 X^2``, ``X = delta tan(alpha)/h``."""
    b0 = float(_moments(nu)[_b0])
    k = pyramid_half_space_coefficient(sides, n)
    y = homogeneous_tip_series(2, 2)
    e = b0 * k / (2 * math.pi)  # eps = e X
    return float(y[1]) * e, float(y[2]) * e * e


@lru_cache(maxsize=16)
def direct_pyramid_ratio(nu: float, H: float, sides: int = 4, n: int = 128) -> float:
    """``P/P_hs`` of the pyramid (45 deg, delta = 1, X = 1/H) on a bonded layer (``nu < 1/2``) by the 2D solver,
    both forces on the same grid.
    """
    from ..layers.kernels import BondedLayer
    from ..numerics.fft2d import solve_2d
    from ..punch import Punch

    if isinstance(nu, bool) or not isinstance(nu, (int, float)) or not 0 <= nu < 0.5:
        raise InputError(f"nu must be a number in [0, 0.5) (the 2D solver takes no incompressible layer), got {nu!r}")
    res = solve_2d(BondedLayer(float(nu)), Punch.pyramid(45, _sides(sides)), delta0=1.0, H=float(H), n=n,
                   extent=_extent(sides))
    return res.force * (1 - nu) / pyramid_half_space_coefficient(sides, n)


# ---------------------------------------------------------------------------------------------
# the published series against the engine's any-thickness cone law
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LawComparison:
    """:func:`law_comparison`: the law's ``P/P_S`` on a grid of ``X`` and each series' relative difference from it."""

    X: np.ndarray = field(repr=False)
    law: np.ndarray = field(repr=False)
    differences: tuple[tuple[str, np.ndarray], ...] = field(repr=False)

    def worst(self, key: str, X_max: float) -> tuple[float, float]:
        """``(difference, X)`` of the largest ``|difference|`` of series ``key`` over ``X <= X_max``."""
        d = dict(self.differences)[key]
        m = self.X <= X_max
        i = int(np.argmax(np.abs(d[m])))
        return float(d[m][i]), float(self.X[m][i])


def law_comparison(X: Any = None, nu: float = 0.5, published=(*PUBLISHED,)) -> LawComparison:
    """Each published series and the derived one (PT.3, key ``"derived"``) against the any-thickness cone law
    (:func:`thinlayer.contact.any_thickness_tips.cone_law_from`, the packaged table, without its estimate), on
    ``X = delta tan(theta)/h`` (default 400 points in ``[0.005, 1]``).
    """
    from ..contact.any_thickness_tips import TIPS_TABLE_PATH, cone_law_from

    X = np.linspace(0.005, 1.0, 400) if X is None else np.asarray(X, dtype=float)
    if X.ndim != 1 or X.size == 0 or not np.all((X > 0) & (X <= 1.5)):
        raise InputError("X must be a non-empty 1D array of values in (0, 1.5] (the thick range, c < H)")
    _layer(nu)
    with np.load(TIPS_TABLE_PATH) as z:
        data = {k: z[k] for k in z.files}
    law = cone_law_from(data, float(nu), "bonded", with_estimate=False).ratios(2 * X / math.pi)[0]
    diffs = [(p.key, p.ratio(X) / law - 1) for p in published]
    diffs.append(("derived", derived_cone_ratio(X, nu) / law - 1))
    return LawComparison(X, law, tuple(diffs))
