"""The flat-ended cylinder at the front door (issue 14 item 5): ``solve(layer, Punch.flat(a), ...)``.

Independent routes: Boussinesq's half-space force ``P = 4 mu a w0/(1 - nu)`` (kappa -> 1 as H -> oo), the
exact Fredholm solution (F.6)-(F.7) for the thin-layer law and the thick series, a refined exact solution for
the exact answer, and the pressure integrated over the disc by quadrature for the force.
"""
from __future__ import annotations

import json
import math

import mpmath
import pytest

import thinlayer as tl
from thinlayer.asymptotics.solution import ValidityError

LAYERS = [tl.BondedLayer(0.3), tl.BondedLayer(0.45), tl.BondedLayer("1/2"), tl.FrictionlessLayer(0.3)]


@pytest.mark.parametrize("layer", LAYERS, ids=str)
@pytest.mark.parametrize("H", [0.01, 0.5, 20.0])
def test_auto_inside_its_estimate_of_the_exact_solution(layer, H):
    ans = tl.solve(layer, tl.Punch.flat(1.0), delta0=0.01, H=H, mu=1.0)
    assert ans.model in ("thin-layer", "thick-layer", "direct") and ans.force > 0
    assert ans.contact_radius == 1.0 and ans.contact_area == pytest.approx(math.pi, rel=1e-15)
    assert 0 < ans.error_estimate["force"] <= 0.05
    cmp = ans.compare_direct()
    assert cmp.direct.model == "direct"
    for key, value, direct, diff, est in cmp.rows:
        assert diff <= est + cmp.direct.error_estimate[key], (key, value, direct, diff, est)


def test_half_space_limit_is_boussinesq():
    for nu in (0.0, 0.3, 0.49):
        ans = tl.solve(tl.BondedLayer(nu), tl.Punch.flat(2.0), delta0=0.01, H=1e6, mu=1.5)
        assert ans.force == pytest.approx(4 * 1.5 * 2.0 * 0.01 / (1 - nu), rel=1e-5)


def test_inverse_round_trip_and_models():
    layer = tl.BondedLayer(0.3)
    for model in ("auto", "direct", "any-thickness", "asymptotic"):
        ans = tl.solve(layer, tl.Punch.flat(1.0), force=2.0, H=0.5, E=2.6, model=model)
        back = tl.solve(layer, tl.Punch.flat(1.0), delta0=ans.delta0, H=0.5, E=2.6, model=model)
        assert back.force == pytest.approx(2.0, rel=1e-12) and back.model == ans.model
    assert tl.solve(layer, tl.Punch.flat(1.0), delta0=0.01, H=0.5, mu=1, model="any-thickness").model == "direct"


def test_pressure_integrates_to_the_force():
    ans = tl.solve(tl.BondedLayer(0.3), tl.Punch.flat(1.0), delta0=0.01, H=0.5, mu=1.0, model="direct")
    # r = sin(t): the (1 - r^2)^(-1/2) edge singularity becomes bounded
    P = 2 * math.pi * float(mpmath.quad(lambda t: float(ans.pressure(math.sin(t), 0.0)) * math.sin(t) * math.cos(t),
                                        [0, math.pi / 4, math.pi / 2 - 1e-9]))
    assert P == pytest.approx(ans.force, rel=1e-5)
    assert float(ans.pressure(1.01, 0.0)) == 0.0
    assert ans.max_pressure == math.inf  # singular edge (F.8); JSON gets null, never Infinity
    json.dumps(ans.as_dict(), allow_nan=False)


def test_text_and_latex_name_the_flat_punch():
    ans = tl.solve(tl.BondedLayer(0.3), tl.Punch.flat(1.0), delta0=0.01, H=0.5, mu=1.0)
    assert "flat-ended cylinder, radius a = 1" in str(ans) and "thin-layer" in str(ans)
    assert r"\tag{F.1" in ans.latex()


def test_refusals_are_one_line():
    layer = tl.BondedLayer(0.3)
    with pytest.raises(ValueError, match="model of smooth punches") as exc:
        tl.solve(layer, tl.Punch.flat(1.0), delta0=0.01, H=0.5, mu=1.0, model="compressible")
    assert "\n" not in str(exc.value)
    with pytest.raises(ValidityError, match="tol"):
        tl.solve(layer, tl.Punch.flat(1.0), delta0=0.01, H=1.0, mu=1.0, model="asymptotic", tol=1e-6)
    with pytest.raises(TypeError, match="no parameters"):
        tl.solve(layer, tl.Punch.flat(1.0), delta0=0.01, H=0.5, mu=1.0, parameters={"R": 1})
    for bad in (-1, 0, "x_1", "1/0", "__import__('os')", float("nan")):
        with pytest.raises(tl.PunchError):
            tl.Punch.flat(bad)
