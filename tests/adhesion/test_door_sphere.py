"""The sphere's JKR law at any thickness (J.16)-(J.18) (issue 26 item 3) and its row in solve().

Independent references: JKR (1971) as printed for the half-space limit; the direct JKR solver (J.1)-(J.6) of
thinlayer.numerics.adhesion (the exact kernel, its own Galerkin solution of the smooth part and its own flat-punch
solves); a central difference of the exact flat-punch stiffness (the compliance route) for Krein's g = f(1)^2.
Default: small slices; THINLAYER_SLOW=1: the grid of H/R with the direct pull-off (jkr_curve).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from thinlayer import BondedLayer, FrictionlessLayer, IncompressibleLayer, Punch, solve
from thinlayer.contact.adhesion_sphere import any_thickness_jkr, flat_release_factor
from thinlayer.errors import InputError
from thinlayer.numerics.adhesion import adhesive_state, jkr_curve
from thinlayer.numerics.flat_punch import flat_punch_kappa

# one worker builds the laws of BondedLayer(0.3) once for these tests and the acceptance grid
pytestmark = pytest.mark.xdist_group("adhesion-laws")

NU, R, W = 0.3, 1.0, 0.05
VT = 1.0 / (1 - NU)
SOLVE_KW = dict(force=-0.1, H=0.3, mu=1.0, work_of_adhesion=W)


def _paraboloid(r):
    return r * r / (2 * R)


def _scales(c, P, delta):
    """The scales of the relative estimates (contact/adhesion.py): max(|P|, pi w R), max(|delta|, c^2/R)."""
    return max(abs(P), math.pi * W * R), max(abs(delta), c * c / R)


def test_half_space_limit_is_jkr_1971():
    """(J.16) with H >> c: delta = c^2/R - sqrt(2 pi w c/E*), P = 4 E* c^3/(3R) - sqrt(8 pi w E* c^3), E* = 2 vartheta
    (JKR 1971 as printed); the layer's correction is O(c/H) = 1e-5 here, inside the law's estimate."""
    law = any_thickness_jkr(BondedLayer(NU))
    c = np.array([0.2, 0.5, 1.0])
    st = law.states(c, 1e5, R, W)
    Es = 2 * VT
    d_jkr = c**2 / R - np.sqrt(2 * math.pi * W * c / Es)
    P_jkr = 4 * Es * c**3 / (3 * R) - np.sqrt(8 * math.pi * W * Es * c**3)
    assert np.all(np.abs(st.delta - d_jkr) <= st.delta_error + 2e-5 * c**2 / R)
    assert np.all(np.abs(st.force - P_jkr) <= st.force_error + 2e-5 * math.pi * W * R)
    assert set(st.flat_models) == {"thick"}


def test_krein_g_equals_compliance_derivative():
    """(J.17): g = f(1)^2 of the exact solver (Krein (F.9)) equals d(lambda kappa)/d lambda by a central difference
    of the exact kappa (the compliance route, (J.4)); the interpolated table's g within its e_g of both; the thin
    form's g within its e_g at a/H = 60."""
    layer = BondedLayer(NU)
    for lam in (0.37, 1.5, 6.0):  # not table nodes
        kappa, g, ek, eg, models = flat_release_factor(layer, lam)
        assert models == ["table"] and eg[0] < 1e-5
        h = 0.02 * lam
        vals = [(lam + k * h) * flat_punch_kappa(layer, lam + k * h, error_estimate=False).kappa
                for k in (-2, -1, 1, 2)]
        fd = (vals[0] - 8 * vals[1] + 8 * vals[2] - vals[3]) / (12 * h)
        exact = flat_punch_kappa(layer, lam)
        assert abs(exact.edge_value**2 / fd - 1) < 1e-8  # Krein: f(1)^2 = (lambda kappa)'
        assert abs(g[0] / fd - 1) <= eg[0] and abs(kappa[0] / exact.kappa - 1) <= ek[0]
    kappa, g, _, eg, models = flat_release_factor(layer, 60.0)
    assert models == ["thin"]
    exact = flat_punch_kappa(layer, 60.0)
    assert abs(g[0] / exact.edge_value**2 - 1) <= eg[0]
    assert abs(kappa[0] / exact.kappa - 1) <= eg[0]


@pytest.mark.parametrize("layer, nu, H, c", [(BondedLayer(NU), None, 1.0, 0.5), (BondedLayer(NU), None, 0.1, 0.8),
                                             pytest.param(FrictionlessLayer(), NU, 0.05, 0.4, marks=pytest.mark.slow)])
def test_law_against_direct_solver(layer, nu, H, c):
    """(J.16)-(J.18) against the direct JKR solver: inside the estimate and within 1e-3 of the problem's scales."""
    law = any_thickness_jkr(layer, nu)
    st = law.states(c, H, R, W)
    ds = adhesive_state(layer, _paraboloid, c, H, 1.0, work_of_adhesion=W, nu=nu, energy_route=False)
    sP, sd = _scales(c, ds.force, ds.delta)
    assert abs(st.force[0] - ds.force) <= st.force_error[0] + ds.force_error
    assert abs(st.delta[0] - ds.delta) <= st.delta_error[0] + ds.delta_error
    assert abs(st.force[0] - ds.force) < 1e-3 * sP and abs(st.delta[0] - ds.delta) < 1e-3 * sd
    assert st.force_error[0] < 5e-3 * sP  # the estimate is usable (not vacuous)


def test_pull_off_is_the_direct_minimum():
    """The law's load-controlled pull-off radius is a minimum of the direct P(c), and the forces agree."""
    layer, H = BondedLayer(NU), 0.2
    law = any_thickness_jkr(layer)
    c, P_off, err = law.pull_off(H, R, W)
    P = [adhesive_state(layer, _paraboloid, c * f, H, 1.0, work_of_adhesion=W, energy_route=False).force
         for f in (0.97, 1.0, 1.03)]
    assert P[1] < P[0] and P[1] < P[2]
    assert abs(-P[1] - P_off) <= err + 1e-6 * P_off
    # between the thin-layer leading value 2 pi w R (J.12) and JKR's 1.5 pi w R on the half-space
    assert 1.5 * math.pi * W * R < P_off < 2 * math.pi * W * R


def test_solve_walks_to_the_law_when_the_thin_layer_law_refuses():
    """solve(work_of_adhesion=w) at c ~ H: thin-layer-jkr refuses (c < 5 H), the any-thickness row answers; its
    pull-off comes from the law (J.6), (J.16)."""
    ans = solve(BondedLayer(NU), Punch.paraboloid(R), **SOLVE_KW)
    assert ans.model == "any-thickness" and "thin-layer-jkr" in ans.reason
    assert ans.equations == ("J.16", "J.16") and ans.tensile and max(ans.error_estimate.values()) <= ans.tol
    po = ans.pull_off
    assert po.source.startswith("any-thickness") and po.load_force > 0.1 and po.displacement_force < po.load_force
    assert po.load_radius < ans.contact_radius < po.jump_in_load_radius  # stable branch, pulled: below P = 0


@pytest.mark.slow
def test_solve_law_agrees_with_direct_model():
    """The any-thickness answer and model='direct' (root-finding on direct JKR states) inside the estimates."""
    ans = solve(BondedLayer(NU), Punch.paraboloid(R), **SOLVE_KW)
    direct = solve(BondedLayer(NU), Punch.paraboloid(R), **SOLVE_KW, model="direct")
    est = ans.error_estimate
    assert abs(ans.contact_radius / direct.contact_radius - 1) <= est["contact_radius"] + \
        direct.error_estimate["contact_radius"]
    assert abs(ans.delta0 - direct.delta0) <= (est["depth"] + direct.error_estimate["depth"]) * \
        max(abs(direct.delta0), direct.contact_radius**2 / R)


def test_bad_layer_one_line():
    from thinlayer import HalfSpace
    with pytest.raises(InputError, match="rigid base") as exc:
        any_thickness_jkr(HalfSpace(), 0.3)
    assert "\n" not in str(exc.value)
    with pytest.raises(InputError, match="radius"):
        any_thickness_jkr(BondedLayer(NU)).states([-1.0], 1.0, R, W)


# --------------------------------------------------------------------------- the grid (THINLAYER_SLOW=1)
@pytest.mark.slow
@pytest.mark.parametrize("layer, nu", [(BondedLayer(NU), None), (IncompressibleLayer(), None),
                                       (FrictionlessLayer(), NU)])
def test_law_against_jkr_curve_on_H_over_R_grid(layer, nu):
    """Every H/R from 10 to 0.01: the law's curve within its estimate and 1e-3 of the direct curve; the pull-off
    force against the direct jkr_curve's."""
    law = any_thickness_jkr(layer, nu)
    for HR in (10.0, 1.0, 0.3, 0.1, 0.03, 0.01):
        H = HR * R
        radii = np.geomspace(0.08, 1.2, 9)
        cur = jkr_curve(layer, _paraboloid, radii, H, 1.0, work_of_adhesion=W, nu=nu)
        st = law.states(radii, H, R, W)
        for i, s in enumerate(cur.states):
            sP, sd = _scales(s.radius, s.force, s.delta)
            assert abs(st.force[i] - s.force) <= st.force_error[i] + s.force_error
            assert abs(st.delta[i] - s.delta) <= st.delta_error[i] + s.delta_error
            assert abs(st.force[i] - s.force) < 1e-3 * sP and abs(st.delta[i] - s.delta) < 1e-3 * sd
        c, P_off, err = law.pull_off(H, R, W)
        assert abs(P_off + cur.pull_off_load.force) <= err + cur.pull_off_load.force_error
        assert abs(P_off + cur.pull_off_load.force) < 1e-3 * P_off
