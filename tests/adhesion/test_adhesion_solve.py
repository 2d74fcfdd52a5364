"""solve(..., work_of_adhesion=w): the adhesive rows of the model registry (issue 26 item 5).

Independent references: Kendall's thin-film detachment force with its first correction (J.13) written out by hand
from A = (1/2 - nu)/(1 - nu)^2 (2.4) and h*(0.3) = 0.1221 (3.25) against the direct (exact-kernel) flat-punch
answer; the thin-layer JKR law (J.11) against the direct JKR solver (J.1)-(J.5) (THINLAYER_SLOW).
"""
from __future__ import annotations

import math

import pytest

from thinlayer import BondedLayer, FrictionlessLayer, Punch, solve
from thinlayer.asymptotics.solution import ValidityError
from thinlayer.errors import InputError

NU, H, W, R = 0.3, 0.1, 0.01, 10.0
VT = 1.0 / (1 - NU)
A = (0.5 - NU) / (1 - NU) ** 2


def test_flat_punch_detachment_kendall_thin_film():
    """(J.13): P_off = pi a_e^(3/2) a^(1/2) sqrt(2 vartheta w/(A H)), a_e = a + h* H; remainder O((H/a)^2)."""
    ans = solve(BondedLayer(NU), Punch.flat(1.0), delta0=-0.01, H=H, mu=1.0, work_of_adhesion=W)
    hand = math.pi * (1 + 0.1221 * H) ** 1.5 * math.sqrt(2 * VT * W / (A * H))
    assert abs(ans.pull_off.load_force / hand - 1) < 2e-3   # (H/a)^2 = 1e-2 times a small constant
    assert ans.pull_off.displacement_force == ans.pull_off.load_force  # Kendall: unstable under both controls
    assert ans.tensile and ans.signed_force == -ans.force and ans.force > 0
    assert "tensile (pulling) force" in str(ans)
    # linear at the fixed contact: P/delta = P_off/d_off
    assert abs(ans.force / 0.01 - ans.pull_off.load_force / -ans.pull_off.displacement_depth) < 1e-9 * ans.force
    with pytest.raises(ValidityError, match="come off"):
        solve(BondedLayer(NU), Punch.flat(1.0), force=-1.01 * hand, H=H, mu=1.0, work_of_adhesion=W)


def test_thin_layer_law_answers_tensile_with_branch():
    ans = solve(BondedLayer(NU), Punch.paraboloid(R), force=-0.3, H=H, mu=1.0, work_of_adhesion=W)
    assert ans.model == "thin-layer-jkr" and ans.branch == "stable" and ans.control == "load"
    assert ans.tensile and abs(ans.force - 0.3) < 1e-12
    assert max(ans.error_estimate.values()) <= ans.tol
    assert ans.contact_radius > 5 * H and "tensile (pulling) force" in str(ans)
    # leading order (J.12): the law's pull-off 2 pi w R exceeds the pull 0.3 here, so a stable state exists
    assert 0.3 < 2 * math.pi * W * R
    # compressive side: no tensile flag
    push = solve(BondedLayer(NU), Punch.paraboloid(R), force=2.0, H=H, mu=1.0, work_of_adhesion=W)
    assert not push.tensile and push.contact_radius > ans.contact_radius
    # the unstable state at this pull lies below c = 5 H: the law refuses when named
    with pytest.raises(ValidityError, match="c/H"):
        solve(BondedLayer(NU), Punch.paraboloid(R), force=-0.3, H=H, mu=1.0, work_of_adhesion=W,
              model="thin-layer-jkr", branch="unstable")


@pytest.mark.parametrize("kw, match", [({"work_of_adhesion": -1}, "work_of_adhesion"),
                                       ({"work_of_adhesion": "1+1"}, "work_of_adhesion"),
                                       ({"work_of_adhesion": W, "branch": "up"}, "branch"),
                                       ({"work_of_adhesion": W, "delta0": math.inf}, "delta0"),
                                       ({"work_of_adhesion": W, "model": "compressible"}, "model")])
def test_adhesive_bad_input_one_line(kw, match):
    args = {"delta0": 0.01, **kw}
    with pytest.raises(InputError, match=match) as exc:
        solve(BondedLayer(NU), Punch.paraboloid(R), H=H, mu=1.0, **args)
    assert "\n" not in str(exc.value)


def test_law_refused_on_frictionless_base_goes_direct_for_the_flat_punch():
    ans = solve(FrictionlessLayer(NU), Punch.flat(1.0), force=0.5, H=1.0, mu=1.0, work_of_adhesion=W)
    assert ans.model == "direct" and not ans.tensile and ans.force == 0.5 and ans.delta0 > 0


@pytest.mark.slow
def test_thin_layer_law_against_direct_solver():
    """The law's answer (J.11) and the direct JKR solver's differ by less than the law's estimates."""
    law = solve(BondedLayer(NU), Punch.paraboloid(R), force=-0.3, H=H, mu=1.0, work_of_adhesion=W)
    direct = solve(BondedLayer(NU), Punch.paraboloid(R), force=-0.3, H=H, mu=1.0, work_of_adhesion=W, model="direct")
    assert direct.model == "direct" and law.model == "thin-layer-jkr"
    assert abs(law.contact_radius / direct.contact_radius - 1) <= law.error_estimate["contact_radius"]
    assert abs(law.delta0 - direct.delta0) <= law.error_estimate["depth"] * max(abs(direct.delta0),
                                                                               direct.contact_radius**2 / R)
    po = direct.pull_off
    assert po.load_force > 0.3 and po.load_radius < direct.contact_radius
