r"""Half-space limits of the tips of revolution: Sneddon's (1965) general formulas, derived here (Abel/Copson route).

Derivation
----------
For the half-space (``L = 1`` in (2.1)) write the pressure on the contact disc ``r < c`` through an auxiliary
function ``g`` (the Abel/Copson route of Copson 1947 and Sneddon 1965, Int. J. Engng Sci. 3, 47-57):

    p(r) = g(c)/sqrt(c^2 - r^2) - int_r^c g'(t)/sqrt(t^2 - r^2) dt.

Each term is a superposition of flat-punch pressures ``1/sqrt(t^2 - r^2)`` on the discs ``r < t``; a flat punch of
radius t loaded by ``P_t = 2 pi t`` (that pressure) sinks uniformly by ``P_t/(4 vartheta t) = pi/(2 vartheta)``
inside its disc and by ``(1/vartheta) arcsin(t/r)`` outside it (Boussinesq; the stiffness ``4 vartheta t`` is the
``2 E* a`` of (F.10) with ``E* = 2 vartheta``).  Summing, for ``r < c``:

    u3(r) = (1/vartheta) int_0^r g(t)/sqrt(r^2 - t^2) dt            (after an integration by parts in t).

The contact condition ``u3 = delta0 - Phi(r)`` (1.5) is an Abel equation for g; its inverse is

    g(t) = (2 vartheta/pi) d/dt int_0^t r (delta0 - Phi(r))/sqrt(t^2 - r^2) dr = (2 vartheta/pi) (delta0 - D(t)),
    D(t) = t int_0^1 Phi'(t x)/sqrt(1 - x^2) dx                       (Phi(0) = 0; x = r/t, one integration by parts).

The pressure vanishes continuously at the edge (smooth contact, (1.5)) iff ``g(c) = 0``:

    delta0(c) = D(c) = int_0^1 c Phi'(c x)/sqrt(1 - x^2) dx.                                            (S1)

The force (1.8) ``P = 2 pi int_0^c p r dr = -2 pi int_0^c t g'(t) dt = 2 pi int_0^c g(t) dt``, so

    P(c) = 4 vartheta int_0^c (delta0 - D(t)) dt = 4 vartheta c int_0^1 x^2 c Phi'(c x)/sqrt(1 - x^2) dx,   (S2)

the second form by exchanging the integrals (``int_0^c D dt = int_0^c Phi'(s) sqrt(c^2 - s^2) ds``).  With
``vartheta = mu/(1 - nu)`` (2.1).  Check: the paraboloid ``r^2/(2R)`` gives Hertz, ``delta0 = c^2/R``,
``P = 8 vartheta c^3/(3R)``.

Closed forms (each evaluated from (S1), (S2) by hand; the tests compare them with mpmath quadrature of (S1), (S2)
and with the direct solver, independently):

* cone ``r cot(alpha)``: ``delta0 = (pi/2) c cot(alpha)``, ``P = pi vartheta c^2 cot(alpha)``
  (``int_0^1 dx/sqrt(1-x^2) = pi/2``, ``int_0^1 x^2 dx/sqrt(1-x^2) = pi/4`` with
  ``E/(1 - nu^2) = 2 vartheta``; Sneddon 1965, the conical punch);
* exact sphere ``R - sqrt(R^2 - r^2)``: ``Phi' = r/sqrt(R^2 - r^2)``,
  ``delta0 = (c/2) ln((R + c)/(R - c))``, ``P = vartheta ((c^2 + R^2) ln((R + c)/(R - c)) - 2 c R)``
  (Sneddon 1965, the spherical punch; Segedin 1957);
* power law ``C r^n``: ``int_0^1 x^{n-1}/sqrt(1 - x^2) dx = sqrt(pi) Gamma(n/2)/(2 Gamma((n+1)/2))``, so
  ``delta0 = C n c^n sqrt(pi) Gamma(n/2)/(2 Gamma((n+1)/2))`` and, with ``D(t) = delta0 (t/c)^n``,
  ``P = 4 vartheta c delta0 n/(n + 1)`` (Sneddon 1965's punch ``C r^n``; Galin 1946).

(S3) *An independent check: Boussinesq's Green function.*  The derivation above passes through the Abel inversion and
Copson's representation.  :func:`boussinesq_check` checks its result by a route that uses neither: the pressure

    p(r) = -int_r^c g'(t)/sqrt(t^2 - r^2) dt = (2 vartheta/pi) int_0^{arccosh(c/r)} D'(r cosh u) du   (g(c) = 0)

is put into Boussinesq's point-load solution ``u3(x) = (1/(2 pi vartheta)) iint p(y)/|x - y| dy`` (``(1 - nu)/(2 pi
mu)`` of (2.1) with ``L = 1``), whose ring average is ``int_0^{2 pi} d phi/|x - y| = 4 K(m)/(r + s)``,
``m = 4 r s/(r + s)^2`` (K the complete elliptic integral of the first kind), and the displacement is compared with
the contact condition ``u3 = delta0 - Phi(r)`` (1.5) at radii inside the contact; the force is ``2 pi int_0^c p s ds``.
With ``D'(t)`` of each tip (cone ``(pi/2) cot(alpha)``, power law ``n D(t)/t``, exact sphere
``(1/2) ln((R + t)/(R - t)) + t R/(R^2 - t^2)``) mpmath quadrature gives ``u3 - (delta0 - Phi)`` below ``1e-9 delta0``
and the force of (S2) to ``1e-10`` (``tests/validation/test_sneddon_independent.py``): the half-space limits used
against the direct solver rest on this check, not on any quoted formula.

Equation numbers of Sneddon's paper are not quoted: the formulas here are derived, not transcribed, and each is
checked against quadrature and the direct solver.  Only the first page of Sneddon (1965) could be read by this
project; :data:`QUOTED` holds the closed forms as a secondary source (nanite's models) writes them, and
:func:`sneddon_symbolic` derives (S1), (S2) with sympy for the comparison
(``tests/validation/test_sneddon_printed.py``).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import mpmath

__all__ = ["HalfSpaceIndentation", "BoussinesqCheck", "boussinesq_check", "half_space_by_quadrature", "sneddon_cone",
           "sneddon_power_law", "sneddon_sphere", "sneddon_symbolic", "QUOTED"]

#: Sneddon's half-space closed forms as a secondary source writes them (the publication's own pages with these
#: formulas could not be read): ``(file, formula)``, with ``E/(1 - nu^2) = 2 vartheta``, ``a`` the contact radius.
#: Nothing is quoted for the power law ``C r^n``: no source read prints it.
QUOTED = {
    "sphere": ("AFM-analysis/nanite, file nanite/model/model_sneddon_spherical.pyx (docstring of hertz_spherical)",
               "F = E/(1-nu**2)*((R^2+a^2)/2*ln((R+a)/(R-a))-a*R);  delta = a/2*ln((R+a)/(R-a))"),
    "cone": ("AFM-analysis/nanite, file nanite/model/model_conical_indenter.py (docstring of hertz_conical)",
             "F = 2*tan(alpha)/pi * E/(1-nu**2) * delta^2"),
}


@dataclass(frozen=True)
class HalfSpaceIndentation:
    """``delta0`` and ``P`` of a tip on the half-space at contact radius ``c`` (``vartheta = mu/(1-nu)``)."""

    c: float
    delta0: float
    force: float
    source: str


def sneddon_cone(half_angle_deg: float, c: float, vartheta: float = 1.0) -> HalfSpaceIndentation:
    """Cone (S1), (S2): ``delta0 = pi c cot(alpha)/2``, ``P = pi vartheta c^2 cot(alpha)``; angle in degrees."""
    cot = 1 / mpmath.tan(mpmath.radians(half_angle_deg))
    return HalfSpaceIndentation(c, float(mpmath.pi * c * cot / 2), float(mpmath.pi * vartheta * c * c * cot),
                                "(S1), (S2) in closed form (Sneddon 1965)")


def sneddon_sphere(R: float, c: float, vartheta: float = 1.0) -> HalfSpaceIndentation:
    """Exact sphere (S1), (S2): ``delta0 = (c/2) ln((R+c)/(R-c))``,
    ``P = vartheta ((c^2+R^2) ln((R+c)/(R-c)) - 2cR)``.
    """
    if not 0 < c < R:
        raise ValueError(f"the contact radius c = {c} must lie in (0, R = {R})")
    with mpmath.workdps(40):
        R_, c_ = mpmath.mpf(R), mpmath.mpf(c)
        lg = mpmath.log((R_ + c_) / (R_ - c_))
        return HalfSpaceIndentation(c, float(c_ * lg / 2), float(vartheta * ((c_**2 + R_**2) * lg - 2 * c_ * R_)),
                                    "(S1), (S2) in closed form (Sneddon 1965)")


def sneddon_power_law(C: float, n: float, c: float, vartheta: float = 1.0) -> HalfSpaceIndentation:
    """Power law ``C r^n`` (S1), (S2): Gamma-function form (module docstring)."""
    d = C * n * c**n * math.sqrt(math.pi) * math.exp(math.lgamma(n / 2) - math.lgamma((n + 1) / 2)) / 2
    return HalfSpaceIndentation(c, d, 4 * vartheta * c * d * n / (n + 1),
                                "(S1), (S2) in closed form (Sneddon 1965)")


def half_space_by_quadrature(slope: Callable, c: float, vartheta: float = 1.0, breaks=(),
                             dps: int = 30) -> HalfSpaceIndentation:
    """(S1), (S2) by mpmath quadrature (``x = sin th`` removes the endpoint singularity), split at ``breaks`` (radii
    where Phi'' jumps).  ``slope(r)`` is ``Phi'(r)`` as an mpmath-callable function.
    """
    with mpmath.workdps(dps):
        cuts = [mpmath.mpf(0)] + [mpmath.asin(mpmath.mpf(b) / c) for b in breaks if 0 < b < c] + [mpmath.pi / 2]
        d = mpmath.quad(lambda t: c * slope(c * mpmath.sin(t)), cuts)
        p = mpmath.quad(lambda t: mpmath.sin(t) ** 2 * c * slope(c * mpmath.sin(t)), cuts)
        return HalfSpaceIndentation(c, float(d), float(4 * vartheta * c * p), "quadrature of (S1), (S2)")


def sneddon_symbolic(slope, r, c):
    """(S1), (S2) by sympy: ``(delta0(c), P(c))`` for ``Phi'(r) = slope`` (a sympy expression in ``r``), vartheta = 1.

    ``delta0 = int_0^1 c Phi'(c x)/sqrt(1 - x^2) dx``, ``P = 4 c int_0^1 x^2 c Phi'(c x)/sqrt(1 - x^2) dx``: the
    general axisymmetric solution of the module docstring, integrated by sympy (not by hand) after ``x = sin t``.
    """
    import sympy as sp

    t = sp.Symbol("t", positive=True)
    f = sp.expand(c * slope.subs(r, c * sp.sin(t)))
    d = sp.integrate(f, (t, 0, sp.pi / 2))
    p = 4 * c * sp.integrate(sp.expand(sp.sin(t) ** 2 * f), (t, 0, sp.pi / 2))
    return sp.simplify(d), sp.simplify(p)


@dataclass(frozen=True)
class BoussinesqCheck:
    """(S3): the derived half-space solution put back into Boussinesq's Green function.

    Attributes
    ----------
    radii : tuple of float
        Radii inside the contact where the displacement was computed.
    residuals : tuple of float
        ``(u3(r) - (delta0 - Phi(r)))/delta0`` at each radius (zero for the exact solution).
    force : float
        ``2 pi int_0^c p(s) s ds`` of the pressure (S3).
    edge_pressure : float
        ``p(0.999 c)/p(c/2)``: small for a pressure that vanishes continuously at the edge (1.5).
    """

    radii: tuple[float, ...]
    residuals: tuple[float, ...]
    force: float
    edge_pressure: float


def boussinesq_check(depth_slope: Callable, profile: Callable, delta0: float, c: float, radii=(0.3, 0.9),
                     vartheta: float = 1.0, dps: int = 12) -> BoussinesqCheck:
    """(S3) by mpmath quadrature: the pressure of ``D'(t)`` in Boussinesq's solution, against ``delta0 - Phi(r)``.

    Parameters
    ----------
    depth_slope : callable
        ``D'(t)`` for ``0 < t <= c`` (mpmath-callable), D of (S1).
    profile : callable
        ``Phi(r)``.
    delta0, c : float
        Depth and contact radius of the solution under test.
    radii : tuple of float
        Radii as fractions of c, in (0, 1).
    """
    with mpmath.workdps(dps):
        c_ = mpmath.mpf(c)

        def pressure(s):
            top = mpmath.acosh(max(c_ / s, mpmath.mpf(1)))
            return 2 * vartheta / mpmath.pi * mpmath.quad(lambda u: depth_slope(s * mpmath.cosh(u)), [0, top],
                                                          maxdegree=5)

        def u3(r):
            def ring(s):  # 4 s K(m)/(r + s), m <= 1 (rounding kept below the log singularity at s = r)
                return pressure(s) * 4 * s / (r + s) * mpmath.ellipk(min(4 * r * s / (r + s) ** 2, 1 - mpmath.eps))
            return mpmath.quad(ring, [0, r, c_]) / (2 * mpmath.pi * vartheta)

        rr = tuple(float(f) * c for f in radii)
        res = tuple(float((u3(mpmath.mpf(r)) - (delta0 - profile(mpmath.mpf(r)))) / delta0) for r in rr)
        force = float(2 * mpmath.pi * mpmath.quad(lambda s: pressure(s) * s, [0, c_]))
        edge = float(pressure(mpmath.mpf(0.999) * c_) / pressure(c_ / 2))
        return BoussinesqCheck(rr, res, force, edge)
