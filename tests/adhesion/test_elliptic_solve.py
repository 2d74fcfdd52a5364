"""solve(Punch.elliptic_paraboloid(R1, R2), ..., work_of_adhesion=w): the registry rows of
thinlayer.contact.models.adhesion_elliptic (issue 26 item 6).

Independent checks: the load-controlled pull-off is DMT's/Winkler's closed form 2 pi w sqrt(R1 R2) (J.28); the state
at a given force, fed back as a depth, returns that force (the law's two inversions agree); the force at a given
depth is the mpmath quadrature of the outer pressure (2.29) over the contact ellipse (J.27).  The 2D reference route
costs minutes: only its refusals run here (its numbers are test_elliptic_acceptance.py's, THINLAYER_SLOW=1).
"""
import math

import pytest

import thinlayer
from thinlayer import BondedLayer, IncompressibleLayer, Punch
from thinlayer.asymptotics.solution import ValidityError
from thinlayer.errors import InputError

pytestmark = pytest.mark.xdist_group("adhesion-laws")
ELL = Punch.elliptic_paraboloid(1, 2)
KW = dict(H=0.04, mu=0.35, work_of_adhesion=0.02)


def test_force_given_then_depth_given_round_trip():
    """Load control (stable branch) -> depth -> displacement control gives the force back; the equal-area radius."""
    a = thinlayer.solve(BondedLayer(0.3), ELL, force=-0.1, tol=0.1, **KW)
    assert a.model == "thin-layer-jkr" and a.tensile and a.control == "load" and a.equations == ("J.31", "J.30")
    s = a.detail
    assert abs(a.contact_radius - math.sqrt(s.a1 * s.a2)) < 1e-15 and s.a1 < s.a2
    b = thinlayer.solve(BondedLayer(0.3), ELL, delta0=a.delta0, tol=0.1, **KW)
    assert abs(b.signed_force + 0.1) < 1e-10 and b.control == "displacement"
    assert "thin-layer-jkr" in b.reason and all(v <= b.tol for v in b.error_estimate.values())


def test_pull_off_against_the_closed_form_of_order_zero():
    """(J.28) 2 pi w sqrt(R1 R2) (DMT's, Winkler's): the first-order pull-off differs from it by O(H kappa), inside
    the first-order state's own estimate plus that difference's (twice the change, J.31), and by more than rounding."""
    a = thinlayer.solve(BondedLayer(0.3), ELL, force=0.05, tol=0.1, **KW)
    off = a.pull_off
    closed = 2 * math.pi * 0.02 * math.sqrt(2)
    assert 1e-3 < abs(off.load_force / closed - 1) < 0.05
    assert off.displacement_force is None  # no thin-layer value under displacement control (J.28)
    assert off.jump_in_load_radius > off.load_radius > 5 * 0.04


def test_unstable_branch_and_out_of_validity_are_refused_by_the_law():
    with pytest.raises(ValidityError, match="thin-layer-jkr: smaller semi-axis .* < 5 H"):
        thinlayer.solve(BondedLayer(0.3), ELL, force=-0.1, branch="unstable", model="asymptotic", **KW)
    with pytest.raises(ValidityError, match="no unstable branch"):
        thinlayer.solve(BondedLayer(0.3), ELL, delta0=0.01, branch="unstable", model="thin-layer-jkr", **KW)
    with pytest.raises(ValidityError, match="pulls harder than the .*load-controlled pull-off"):
        thinlayer.solve(BondedLayer(0.3), ELL, force=-0.2, model="thin-layer-jkr", **KW)
    with pytest.raises(ValidityError, match="compressible layers"):
        thinlayer.solve(IncompressibleLayer(), ELL, delta0=0.01, model="thin-layer-jkr", **KW)


def test_direct_route_refuses_in_one_line_before_work():
    with pytest.raises(ValidityError, match="at a given depth .delta0=. only"):
        thinlayer.solve(IncompressibleLayer(), ELL, force=0.1, model="direct", **KW)
    with pytest.raises(ValidityError, match="at most n = 512") as exc:
        thinlayer.solve(IncompressibleLayer(), ELL, delta0=0.01, model="direct", n=1024, **KW)
    assert "\n" not in str(exc.value)


def test_other_punches_are_refused_by_both_kinds_of_row():
    with pytest.raises(InputError, match="paraboloid of revolution"):
        thinlayer.solve(BondedLayer(0.3), Punch("x_1**4 + x_2**2"), delta0=0.01, model="thin-layer-jkr", **KW)
