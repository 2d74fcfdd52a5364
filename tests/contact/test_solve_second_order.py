"""``solve(..., order=2)``: the second-order laws (SO.9), (SO.10) and composite pressure (SO.7) at the front door,
checked against the direct axisymmetric solver (no asymptotics)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from thinlayer import BondedLayer, FrictionlessLayer, Punch, solve
from thinlayer.numerics import solve_axisymmetric

SPHERE = Punch.paraboloid(10)


@pytest.mark.parametrize("nu", [0.3, 0.45])
def test_second_order_force_and_area_beat_the_first_order_and_their_estimates(nu):
    """sphere R = 10, delta0 = 0.1 (a = 1.414), H = 0.05 and 0.1 (H/a = 0.035, 0.071)."""
    for H in (0.05, 0.1):
        two = solve(BondedLayer(nu), SPHERE, delta0=0.1, H=H, mu=1.0, order=2)
        one = solve(BondedLayer(nu), SPHERE, delta0=0.1, H=H, mu=1.0, model="compressible", tol=math.inf)
        d = solve_axisymmetric(BondedLayer(nu), SPHERE, 0.1, H, 1.0)
        assert two.model == "compressible" and two.detail.order == 2
        errP2, errP1 = abs(two.force / d.force - 1), abs(one.force / d.force - 1)
        errA2, errA1 = abs(two.contact_area / d.contact_area - 1), abs(one.contact_area / d.contact_area - 1)
        assert errP2 < errP1 / 10 and errA2 < errA1 / 5, (errP1, errP2, errA1, errA2)
        assert errP2 <= two.error_estimate["force"] and errA2 <= two.error_estimate["contact_area"]
        assert abs(two.contact_radius / d.radius - 1) <= two.error_estimate["contact_radius"]


def test_inverse_problem_at_second_order():
    ans = solve(BondedLayer(0.4), SPHERE, delta0=0.1, H=0.05, mu=2.0, order=2)
    back = solve(BondedLayer(0.4), SPHERE, force=ans.force, H=0.05, mu=2.0, order=2)
    assert back.delta0 == pytest.approx(0.1, rel=1e-12)


def test_frictionless_base_and_radial_monomial():
    q = Punch("(x_1**2 + x_2**2)**2")
    for layer, kw in ((FrictionlessLayer(), {"nu": 0.3}), (BondedLayer(0.3), {})):
        two = solve(layer, q, delta0=0.1, H=0.03, mu=1.0, order=2, **kw)
        one = solve(layer, q, delta0=0.1, H=0.03, mu=1.0, **kw)
        d = solve_axisymmetric(layer, q, 0.1, 0.03, 1.0, **kw)
        assert abs(two.force / d.force - 1) < abs(one.force / d.force - 1) / 4
        assert abs(two.force / d.force - 1) <= two.error_estimate["force"]


def test_pressure_at_second_order_is_closer_to_the_direct_one():
    layer = BondedLayer(0.3)
    two = solve(layer, SPHERE, delta0=0.1, H=0.05, mu=1.0, order=2)
    one = solve(layer, SPHERE, delta0=0.1, H=0.05, mu=1.0)
    d = solve_axisymmetric(layer, SPHERE, 0.1, 0.05, 1.0)
    r = np.linspace(0, 1.5, 3001)
    pd = d.pressure_at(r)
    e2 = np.abs(two.pressure(r, 0 * r) - pd).max() / pd.max()
    e1 = np.abs(one.pressure(r, 0 * r) - pd).max() / pd.max()
    assert e2 < e1 / 10, (e1, e2)  # measured 2.0e-3 -> 2.8e-5 of p_max
    assert two.detail.order_of_accuracy["force"][0].endswith("(SO.9)")


def test_bad_orders_get_one_clear_line():
    with pytest.raises(NotImplementedError, match="order <= 2"):
        solve(BondedLayer(0.3), SPHERE, delta0=0.1, H=0.05, mu=1.0, order=3, model="compressible")
    with pytest.raises(ValueError, match="exact boundary layer"):
        solve(BondedLayer(0.3), SPHERE, delta0=0.1, H=0.05, mu=1.0, order=2, boundary_layer="alexandrov")
    with pytest.raises(TypeError, match="belong to the compressible model"):
        solve(BondedLayer(0.49), SPHERE, delta0=0.1, H=0.05, mu=1.0, order=2, model="two-term")


def test_auto_falls_back_without_the_compressible_options():
    """order=2 is the compressible model's option: where that model is refused, auto goes on (any-thickness)."""
    ans = solve(BondedLayer(0.49), SPHERE, delta0=0.1, H=0.5, E=2.0, order=2)
    assert ans.model == "any-thickness" and "compressible:" in ans.reason


def test_second_order_text_and_latex_show_the_new_term():
    ans = solve(BondedLayer(0.3), SPHERE, delta0=0.1, H=0.05, mu=1.0, order=2)
    assert "second order" in str(ans.detail) and r"\tag{SO.9}" in ans.detail.latex()
