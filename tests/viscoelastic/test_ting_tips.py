"""Ting for the cone and the flat punch on layers (issue 27 item 2; contact/ting.py (T6), (T7)).

Independent references: the flat punch on the half-space in closed form (the hereditary integral of the standard
linear solid, the lift-off time by mpmath's root, the free recovery by mpmath quadrature of the creep compliance
``J(t) = 1/E_inf - (1/E_inf - 1/E0) exp(-t E_inf/(E0 tau))``); the direct time-stepping solver on the flat punch's
face (numerics/viscoelastic (V.10)), which uses the layer's kernel only; the elastic direct solver's pressure
(numerics/axisymmetric) for condition (C2) of the cone.
"""
from __future__ import annotations

import math
from functools import lru_cache

import mpmath
import numpy as np
import pytest

from thinlayer import BondedLayer, FrictionlessLayer, HalfSpace, Punch, solve
from thinlayer.contact.materials import StandardLinearSolid
from thinlayer.contact.ting import ting_force
from thinlayer.numerics.axisymmetric import contact_for_radius
from thinlayer.numerics.viscoelastic import solve_history

E0, EINF, TAU, V, TM, NU = 3.0, 1.0, 0.2, 0.02, 0.5, 0.3
SLS = StandardLinearSolid(E0, EINF, TAU)


def _triangle(n: int, end: float = 1.5) -> tuple[np.ndarray, np.ndarray]:
    t = np.linspace(0.0, end, n)
    return t, V * np.maximum(np.minimum(t, 2 * TM - t), 0.0)


def _Y(s):
    """``int_0^s E(s - u) delta'(u) du`` of the triangle (up to 2 TM), closed form (mpmath)."""
    def ramp(x):
        return EINF * x + (E0 - EINF) * TAU * (1 - mpmath.exp(-x / TAU)) if x > 0 else mpmath.mpf(0)
    return V * (ramp(s) - 2 * ramp(s - TM))


def _dY(s):
    out = V * (EINF + (E0 - EINF) * mpmath.exp(-s / TAU))
    return out - 2 * V * (EINF + (E0 - EINF) * mpmath.exp(-(s - TM) / TAU)) if s > TM else out


@lru_cache(maxsize=None)
def _lift_off() -> float:
    with mpmath.workdps(25):
        return float(mpmath.findroot(_Y, (mpmath.mpf(TM) + mpmath.mpf("1e-9"), mpmath.mpf(2 * TM)),
                                     solver="illinois", tol=1e-30))


def _recovery(t: float) -> float:
    """The surface under the face after lift-off: ``U(t) = int_0^{t_L} J(t - s) Y'(s) ds`` (Y = 0 from t_L on)."""
    tL = _lift_off()
    with mpmath.workdps(25):
        def J(x):
            return 1 / mpmath.mpf(EINF) - (1 / mpmath.mpf(EINF) - 1 / mpmath.mpf(E0)) * mpmath.exp(
                -x * EINF / (E0 * TAU))
        return float(mpmath.quad(lambda s: J(t - s) * _dY(s), [0, TM, tL]))


def test_flat_punch_half_space_closed_form():
    # (T7): Lee-Radok on the face while compressive (P = 4 a Y/((1 - nu) 2 (1 + nu)), S = 4 a/(1 - nu) at mu = 1),
    # lift-off where Y = 0 (mpmath root), then the free creep recovery of the surface; exact for U linear in time
    t, d = _triangle(3001)
    out = ting_force(HalfSpace(), Punch.flat(1.0), 1.0, SLS, t, d, nu=NU)
    S = 4.0 / (1.0 - NU)
    tL = _lift_off()
    assert 0.78 < tL < 0.79
    for tt in (0.25, 0.5, 0.7):
        i = int(round(tt / 5e-4))
        assert out.force[i] == pytest.approx(S * float(_Y(mpmath.mpf(tt))) / (2 * (1 + NU)), rel=2e-6)
        assert out.contact_radius[i] == 1.0 and out.surface_depth[i] == d[i]
    first = int(np.argmax(out.force[t > TM] == 0)) + int(np.sum(t <= TM))
    assert t[first - 1] < tL <= t[first]  # lift-off in the step of the closed form's root
    for tt in (0.9, 1.2, 1.5):
        i = int(round(tt / 5e-4))
        assert out.force[i] == 0 and out.contact_radius[i] == 0
        assert out.surface_depth[i] == pytest.approx(_recovery(tt), rel=1e-6)  # above the punch: U > delta
        assert out.surface_depth[i] > d[i]
    assert "lift-off" in out.reason and out.valid.all()


def test_flat_punch_incompressible_layer_against_solver():
    # bonded nu = 1/2, a/H = 1: Ting (T7) against the solver on the face (V.10) at (31, 16) and (61, 32): the
    # difference falls ~4x (the solver's second order: measured 1.0e-3 -> 2.6e-4); the same lift-off step, the
    # same free surface after it (a/H = 5 and the other layers: test_visco_acceptance.py)
    tf, df = _triangle(3001)
    tg = ting_force(BondedLayer(0.5), Punch.flat(1.0), 1.0, SLS, tf, df)
    diffs = []
    for n, nodes in ((31, 16), (61, 32)):
        t, d = _triangle(n)
        s = solve_history(BondedLayer(0.5), Punch.flat(1.0), 1.0, SLS, t, d, nodes=nodes)
        P, U = np.interp(s.times, tf, tg.force), np.interp(s.times, tf, tg.surface_depth)
        on = P > 0.05 * P.max()
        diffs.append(np.max(np.abs(s.force[on] / P[on] - 1)))
        assert np.array_equal(s.force == 0, P == 0)
        assert np.max(np.abs(s.surface_depth - U)) < 5e-3 * V
        assert s.valid.all() and s.min_pressure.min() >= 0
    assert 3.0 < diffs[0] / diffs[1] < 5.0 and diffs[1] < 1e-3, diffs


def test_flat_punch_recontact():
    # retract to a held depth above the lifted surface: the surface recovers down to the punch and touches again;
    # Ting (T7) and the solver agree on both times and on the force after re-contact
    t = np.linspace(0.0, 4.0, 81)
    d = np.where(t <= 0.5, 0.04 * t, np.maximum(0.02 - 0.04 * (t - 0.5), 0.012))
    tg = ting_force(BondedLayer(0.5), Punch.flat(1.0), 1.0, SLS, t, d)
    s = solve_history(BondedLayer(0.5), Punch.flat(1.0), 1.0, SLS, t, d, nodes=24)
    off = np.flatnonzero(tg.force == 0)
    assert off.size and off[-1] < t.size - 1 and tg.force[-1] > 0  # lifts off, then touches again
    assert np.array_equal(s.force == 0, tg.force == 0)
    assert s.force[-1] == pytest.approx(tg.force[-1], rel=2e-3)


@pytest.mark.parametrize("layer", [BondedLayer(0.3), BondedLayer(0.5), FrictionlessLayer(0.3)], ids=str)
def test_cone_condition_c2_pressure_grows_with_radius(layer):
    # (C2) for the cone (70 deg): the elastic pressure p_e(r; a) does not decrease with a at any r (c/H 0.5 to 8)
    r = np.linspace(0.0, 7.99, 161)
    prev = np.zeros_like(r)
    for c in (0.5, 1.0, 2.0, 4.0, 8.0):
        p = contact_for_radius(layer, Punch.cone(70.0), c, 1.0, error_estimate=False).pressure_at(r)
        assert np.all(p >= prev - 1e-12 * p.max())
        assert p[r < 0.9 * c].min() > 0
        prev = p


def test_front_door_cone_and_flat_punch():
    # solve(Punch.cone(70), material=..., history=...): Ting over the cone's any-thickness law (T.9), loading and
    # unloading, the contact lost before the end; the flat punch: (T7), lift-off
    # (model="auto" on the bonded incompressible layer first asks the two-term row, ~2 s: the grid's cells do)
    t = np.linspace(0.0, 1.0, 401)
    d = 0.1 * np.minimum(t, 1.0 - t)
    cone = solve(BondedLayer(0.5), Punch.cone(70.0), H=0.1, material=SLS, history=(t, d), model="any-thickness")
    assert cone.model == "any-thickness" and cone.valid.all() and "Ting" in cone.reason
    direct = ting_force(BondedLayer(0.5), Punch.cone(70.0), 0.1, SLS, t, d, model="any-thickness")
    np.testing.assert_array_equal(cone.force, direct.force)
    c_max = 2 / math.pi * 0.05 * math.tan(math.radians(70.0))
    assert cone.contact_radius.max() / 0.1 > c_max / 0.1  # the bonded incompressible layer: c > c_0 (Sneddon)
    assert cone.force[-1] == 0 and np.all(np.diff(cone.contact_radius[200:]) <= 0)
    flat = solve(BondedLayer(0.5), Punch.flat(1.0), H=1.0, material=SLS, history=(t, d))
    assert flat.valid.all() and "lift-off" in flat.reason and flat.force[-1] == 0
    assert np.all(flat.contact_radius[flat.force > 0] == 1.0)
