"""Sneddon's (1965) half-space relations of the cone, the exact sphere and the power law (issue 24 item 5).

Sources.  Sneddon, Int. J. Engng Sci. 3 (1965) 47-57: only the first page (title, abstract, introduction) could be
read (a scan at paperzz.com/doc/8681378 and pdfcoffee.com/sneddon-1965-pdf-free.html); the pages with the special
cases could not, nor could Johnson (1985) or Popov & Hess.  The closed forms are therefore compared as a secondary
source writes them: AFM-analysis/nanite (``thinlayer.validation.sneddon.QUOTED``, ``E/(1 - nu^2) = 2 vartheta``).
For the power law no printed form was read: it is compared with the Gamma-function form derived by hand in
``thinlayer.validation.sneddon`` only.  The engine's side is the general solution (S1), (S2) integrated by sympy
(``sneddon_symbolic``), by mpmath quadrature, and the direct axisymmetric solver.
"""
import math

import mpmath
import pytest
import sympy as sp

from thinlayer import BondedLayer, HalfSpace, Punch
from thinlayer.numerics.axisymmetric import contact_for_radius
from thinlayer.validation.sneddon import QUOTED, half_space_by_quadrature, sneddon_power_law, sneddon_symbolic

NU = 0.3
VT = 1 / (1 - NU)
E_STAR = 2 * VT  # E/(1 - nu^2) = 2 mu (1 + nu)/(1 - nu^2) = 2 vartheta
r, c, R, kappa, delta = sp.symbols("r c R kappa delta", positive=True)


# --------------------------------------------------------------------------- the quoted closed forms
def quoted_cone_force(half_angle_deg, d):
    # QUOTED["cone"]: F = 2 tan(alpha)/pi * E/(1 - nu^2) * delta^2
    return 2 * math.tan(math.radians(half_angle_deg)) / math.pi * E_STAR * d * d


def quoted_sphere(R_, a):
    # QUOTED["sphere"]: F = E/(1-nu^2) ((R^2 + a^2)/2 ln((R+a)/(R-a)) - a R),  delta = a/2 ln((R+a)/(R-a))
    lg = mpmath.log((R_ + a) / (R_ - a))
    return float(a / 2 * lg), float(E_STAR * ((R_**2 + a**2) / 2 * lg - a * R_))


def test_quoted_sources_are_named():
    assert set(QUOTED) == {"sphere", "cone"}  # nothing quoted for the power law: none was read
    for where, formula in QUOTED.values():
        assert where.startswith("AFM-analysis/nanite, file nanite/model/") and "E/(1-nu**2)" in formula


# --------------------------------------------------------------------------- cone
def test_cone_symbolic_general_solution_equals_the_quoted_form():
    # (S1), (S2) integrated by sympy for Phi' = cot(alpha) = kappa, vartheta = 1
    d, P = sneddon_symbolic(kappa + 0 * r, r, c)
    assert d == sp.pi * c * kappa / 2 and P == sp.pi * c**2 * kappa  # ladder: ==
    c_of_delta = sp.solve(sp.Eq(d, delta), c)[0]
    quoted = 2 * (1 / kappa) / sp.pi * 2 * delta**2  # E/(1 - nu^2) = 2 vartheta = 2
    diff = P.subs(c, c_of_delta) - quoted
    assert sp.expand(diff) == 0  # ladder: expand
    assert sp.simplify(diff) == 0
    # mpmath: quadrature of (S1), (S2) against the quoted force at the same depth
    cot = 1 / mpmath.tan(mpmath.radians(70))
    q = half_space_by_quadrature(lambda s: cot, 0.8, VT)
    assert q.force == pytest.approx(quoted_cone_force(70, q.delta0), rel=1e-13)


# --------------------------------------------------------------------------- exact sphere
def test_sphere_series_identity_with_the_quoted_form():
    # Phi' = r/sqrt(R^2 - r^2) = sum_k C(-1/2, k) (-1)^k r^(2k+1)/R^(2k+1): (S1), (S2) integrated term by term by
    # sympy (each term a power law) must equal the Taylor series of the quoted closed forms in c/R, 8 terms
    N = 8
    d_ser, p_ser = 0, 0
    for k in range(N):
        a_k = sp.binomial(sp.Rational(-1, 2), k) * (-1) ** k / R ** (2 * k + 1)
        d_k, p_k = sneddon_symbolic(a_k * r ** (2 * k + 1), r, c)
        d_ser, p_ser = d_ser + d_k, p_ser + p_k
    lg = sp.log((R + c) / (R - c))
    qd, qP = c / 2 * lg, 2 * ((R**2 + c**2) / 2 * lg - c * R)  # quoted, with E/(1 - nu^2) = 2, vartheta = 1
    td = sp.series(qd, c, 0, 2 * N + 1).removeO()
    tP = sp.series(qP, c, 0, 2 * N + 2).removeO()
    assert sp.expand(td - d_ser) == 0
    assert sp.expand(tP - p_ser) == 0
    assert d_ser.coeff(c, 2) == 1 / R and p_ser.coeff(c, 3) == sp.Rational(8, 3) / R  # Hertz leads


@pytest.mark.parametrize("c_over_R", [0.4, 0.95])
def test_sphere_quadrature_equals_the_quoted_form(c_over_R):
    q = half_space_by_quadrature(lambda s: s / mpmath.sqrt(1 - s * s), c_over_R, VT, dps=30)
    d, P = quoted_sphere(1, c_over_R)
    assert q.delta0 == pytest.approx(d, rel=1e-12)
    assert q.force == pytest.approx(P, rel=1e-12)


# --------------------------------------------------------------------------- power law (no printed form read)
@pytest.mark.parametrize("n", [3, 4])  # sympy integrates sin^m t for integer m only (n = 3/2 did not finish)
def test_power_law_symbolic_equals_the_gamma_form(n):
    C = sp.Rational(13, 10)
    d, P = sneddon_symbolic(C * n * r ** (n - 1), r, c)
    closed = sneddon_power_law(1.3, float(n), 0.8, 1.0)
    assert float(d.subs(c, sp.Rational(4, 5))) == pytest.approx(closed.delta0, rel=1e-14)
    assert float(P.subs(c, sp.Rational(4, 5))) == pytest.approx(closed.force, rel=1e-14)
    # the derived structure P = 4 vartheta c delta0 n/(n + 1)
    assert sp.simplify(P - 4 * c * d * n / (n + 1)) == 0


# --------------------------------------------------------------------------- the direct solver
TIPS = [(Punch.cone(70), lambda cr: (mpmath.pi / 2 * cr / mpmath.tan(mpmath.radians(70)), None), "cone"),
        (Punch.sphere(2), lambda cr: quoted_sphere(2, cr), "sphere"),
        (Punch.power_law(1.3, 1.5), lambda cr: (sneddon_power_law(1.3, 1.5, cr, VT).delta0, None), "power")]


@pytest.mark.parametrize("tip,quoted,name", TIPS, ids=[t[2] for t in TIPS])
def test_direct_solver_half_space_and_large_H_equal_the_quoted_forms(tip, quoted, name):
    cr = 0.8
    d_q, P_q = quoted(cr)
    if P_q is None:
        P_q = quoted_cone_force(70, float(d_q)) if name == "cone" else sneddon_power_law(1.3, 1.5, cr, VT).force
    for layer, H in ((HalfSpace(), None), (BondedLayer(NU), 1e9)):
        res = contact_for_radius(layer, tip, cr, H=H, nu=NU if H is None else None, n=40, error_estimate=False)
        assert res.delta0 == pytest.approx(float(d_q), rel=1e-8), (name, H)
        assert res.force == pytest.approx(float(P_q), rel=1e-8), (name, H)


@pytest.mark.parametrize("tip,quoted,name", TIPS, ids=[t[2] for t in TIPS])
def test_first_layer_correction_is_the_rigid_shift_of_T2(tip, quoted, name):
    # at H = 1e3 c the depth differs from the half-space's by -b_0 P/(2 pi vartheta H) (T.2): the layer's limit is
    # approached at the derived rate, the next term being O((c/H)^2) relative to the shift (here ~ 4e-4)
    from thinlayer.asymptotics.thick_layer import thick_moments

    b0 = float(thick_moments(BondedLayer(NU), 0)[0])
    half = contact_for_radius(HalfSpace(), tip, 0.8, nu=NU, n=40, error_estimate=False)
    layer = contact_for_radius(BondedLayer(NU), tip, 0.8, H=1e3, n=40, error_estimate=False)
    shift = -b0 * half.force / (2 * math.pi * VT * 1e3)
    assert layer.delta0 - half.delta0 == pytest.approx(shift, rel=2e-3)
    assert abs(layer.delta0 - half.delta0 - shift) < 1e-3 * abs(shift)
