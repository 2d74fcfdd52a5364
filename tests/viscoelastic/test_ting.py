"""Ting's method on the layer (issue 27 item 2, contact/ting.py (T1)-(T6)).

Independent references: the half-space closed form by mpmath (ting_reference.py); the direct time-stepping solver
(numerics/viscoelastic), which never uses Ting's construction, on bonded and frictionless layers; the elastic direct
solver's pressure (numerics/axisymmetric) for condition (C2).
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np
import pytest
from ting_reference import E0, EINF, NU, RT, TAU, TM, V, hertz_ting

from thinlayer import BondedLayer, FrictionlessLayer, HalfSpace, Punch
from thinlayer.contact.materials import PowerLaw, StandardLinearSolid
from thinlayer.contact.ting import ting_force
from thinlayer.numerics.axisymmetric import contact_for_radius
from thinlayer.numerics.viscoelastic import solve_history

SLS = StandardLinearSolid(E0, EINF, TAU)
TIMES = (0.25, 0.5, 0.6, 0.7)


def _history(n: int) -> tuple[np.ndarray, np.ndarray]:
    t = np.linspace(0.0, 1.0, n)
    return t, np.where(t <= TM, V * t, V * (2 * TM - t))


@lru_cache(maxsize=None)
def _ting_half_space(n: int):
    return ting_force(HalfSpace(), Punch.paraboloid(RT), 1.0, SLS, *_history(n), nu=NU)


def _errors(out) -> np.ndarray:
    errs = []
    for tt in TIMES:
        P, a = hertz_ting(tt)
        i = int(np.argmin(abs(out.times - tt)))
        assert out.times[i] == pytest.approx(tt, abs=1e-12)
        errs += [abs(out.force[i] / P - 1), abs(out.contact_radius[i] / a - 1)]
    return np.array(errs)


def test_half_space_closed_form_and_order():
    # (T4), (T5) against mpmath: F linear in time between nodes gives second order (measured 3.2e-6 at 1001 nodes)
    coarse, fine = _errors(_ting_half_space(501)), _errors(_ting_half_space(1001))
    assert fine.max() < 5e-6
    assert np.all(fine[1::2] < 1e-12)  # the radius a_e(delta(t1)) is exact where t1 is (bisection to rounding)
    order = np.log2(coarse[:4:2] / fine[:4:2])  # while loading; unloading errors change sign between the grids
    assert np.all((order > 1.8) & (order < 2.2)), order
    assert np.all(coarse[4::2] < 4e-5)
    out = _ting_half_space(1001)
    assert out.valid.all() and np.all(out.force[out.times > 0.8] == 0) and np.isnan(out.t1[-1])


def test_agrees_with_direct_solver_on_bonded_layer():
    # bonded nu = 0.5, a_max/H = 1.5: Ting is exact there (C1)-(C3); the solver (41 steps, 80 nodes) carries its
    # own discretisation error, measured 1e-3 at this size; Ting on a fine time grid
    layer, H = BondedLayer(0.5), 0.1
    t, d = _history(41)
    s = solve_history(layer, Punch.paraboloid(RT), H, SLS, t, d, nodes=80)
    tf, df = _history(4001)
    tg = ting_force(layer, Punch.paraboloid(RT), H, SLS, tf, df)
    P, a = np.interp(t, tf, tg.force), np.interp(t, tf, tg.contact_radius)
    unload = (t > TM) & (P > 0.1 * P.max())
    assert unload.sum() >= 5
    np.testing.assert_allclose(s.force[unload], P[unload], rtol=3e-3)
    np.testing.assert_allclose(s.contact_radius[unload], a[unload], rtol=2e-3)
    assert s.valid.all() and s.min_gap.min() > -1e-3 and s.min_pressure.min() > -1e-3  # (C2), (C3) at this size


@pytest.mark.parametrize("layer", [BondedLayer(0.3), BondedLayer(0.5), FrictionlessLayer(0.3)], ids=str)
def test_condition_c2_pressure_grows_with_radius(layer):
    # (C2): the elastic pressure p_e(r; a) of the sphere does not decrease with a at any r (c/H from 0.5 to 8)
    r = np.linspace(0.0, 7.99, 161)
    prev = np.zeros_like(r)
    for c in (0.5, 1.0, 2.0, 4.0, 8.0):
        p = contact_for_radius(layer, Punch.paraboloid(10.0), c, 1.0, error_estimate=False).pressure_at(r)
        assert np.all(p >= prev - 1e-12 * p.max())
        prev = p


def test_reloading_and_materials_flagged():
    t = np.linspace(0.0, 1.5, 151)
    d = 0.02 * np.where(t <= 0.5, t, np.where(t <= 1.0, 1.0 - t, t - 1.0)) + 0.002
    out = ting_force(HalfSpace(), Punch.paraboloid(RT), 1.0, SLS, t, d, nu=NU)
    assert out.valid[:60].all() and not out.valid[-1] and "Ting 1968" in out.reason and np.isnan(out.force[-1])
    with pytest.raises(TypeError) as info:
        ting_force(HalfSpace(), Punch.paraboloid(RT), 1.0, PowerLaw(1.0, 1.0, 0.2), t, d, nu=NU)
    assert "\n" not in str(info.value)


@pytest.mark.slow
@pytest.mark.parametrize("layer,H", [(BondedLayer(0.5), 0.025), (BondedLayer(0.3), 0.1),
                                     (FrictionlessLayer(0.3), 0.025)],
                         ids=["bonded-0.5-thin", "bonded-0.3", "frictionless-thin"])
def test_ting_exact_on_layer_to_solver_accuracy(layer, H):
    # (T6): Ting's construction is exact on the layer; the difference to the direct solver is the solver's own
    # second-order error: it falls ~4x when steps and nodes are doubled (measured: bonded 0.5 at a_max/H = 6.9,
    # 3.6e-4 -> 8.8e-5), and (C2)-(C3) hold at every step (min_pressure, min_gap >= 0)
    tf, df = _history(20001)
    tg = ting_force(layer, Punch.paraboloid(RT), H, SLS, tf, df)
    diffs = []
    for n, nodes in ((101, 100), (201, 200)):
        t, d = _history(n)
        s = solve_history(layer, Punch.paraboloid(RT), H, SLS, t, d, nodes=nodes)
        P = np.interp(t, tf, tg.force)
        unload = (t > TM) & (P > 0.1 * P.max())
        diffs.append(np.max(np.abs(s.force[unload] / P[unload] - 1)))
        contact = s.force > 0
        assert s.valid.all() and s.min_pressure[contact].min() >= 0 and s.min_gap[contact].min() >= 0
    assert 3.0 < diffs[0] / diffs[1] < 5.5, diffs
    assert diffs[1] < 1e-4


@pytest.mark.slow
def test_cone_half_space_ting_against_solver():
    # the cone (70 deg, Sneddon's law through the direct model's curve): Ting on 2,001 steps against the solver,
    # the difference falling ~4x from (101, 100) to (201, 200) (measured 7.9e-5 -> 2.0e-5)
    tf, df = _history(2001)
    tg = ting_force(HalfSpace(), Punch.cone(70.0), 1.0, SLS, tf, df, nu=NU)
    diffs = []
    for n, nodes in ((101, 100), (201, 200)):
        t, d = _history(n)
        s = solve_history(HalfSpace(), Punch.cone(70.0), 1.0, SLS, t, d, nu=NU, nodes=nodes)
        P = np.interp(t, tf, tg.force)
        unload = (t > TM) & (P > 0.1 * P.max())
        diffs.append(np.max(np.abs(s.force[unload] / P[unload] - 1)))
        assert s.valid.all()
    assert 3.0 < diffs[0] / diffs[1] < 5.5 and diffs[1] < 5e-5, diffs
