"""The direct time-stepping solver (issue 27 item 3, numerics/viscoelastic (V.1)-(V.9)).

Independent references: the half-space closed forms of Lee-Radok and Ting for the sphere (Hertz) with a standard
linear solid under a triangular depth history, evaluated by mpmath (quadrature and bisection, 30 digits) from the
construction (T4), (T5) -- the solver never uses it; the elastic direct solver (numerics/revolution (F.13), (F.14)) for
the layer; the Lee-Radok law on the layer (hereditary.py with the any-thickness law) for a monotone ramp.
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
import pytest
from ting_reference import E0, EINF, NU, RT, TAU, TM, V, hertz_ting

from thinlayer import BondedLayer, FrictionlessLayer, HalfSpace, Punch
from thinlayer.contact.hereditary import viscoelastic_force
from thinlayer.contact.materials import KelvinVoigt, Prony, StandardLinearSolid
from thinlayer.errors import InputError, WorkLimitError
from thinlayer.numerics.revolution import revolution_contact
from thinlayer.numerics.viscoelastic import solve_history

SLS = StandardLinearSolid(E0, EINF, TAU)


def _history(n: int) -> tuple[np.ndarray, np.ndarray]:
    t = np.linspace(0.0, 1.0, n)
    return t, np.where(t <= TM, V * t, V * (2 * TM - t))


@lru_cache(maxsize=None)
def _half_space(n: int, nodes: int):
    t, d = _history(n)
    return solve_history(HalfSpace(), Punch.paraboloid(RT), 1.0, SLS, t, d, nu=NU, nodes=nodes)


CHECK_TIMES = (0.25, 0.5, 0.6, 0.7)


def _errors(out) -> list[float]:
    errs = []
    for tt in CHECK_TIMES:
        P, a = hertz_ting(tt)
        i = int(np.argmin(abs(out.times - tt)))
        assert out.times[i] == pytest.approx(tt, abs=1e-12)
        errs.append(abs(out.force[i] / P - 1.0))
        errs.append(abs(out.contact_radius[i] / a - 1.0))
    return errs


def test_half_space_lee_radok_and_ting_small():
    # Lee-Radok while loading (t <= 0.5), Ting while unloading (0.6, 0.7): measured 1.2e-4 at (101 steps, 200 nodes)
    out = _half_space(101, 200)
    assert max(_errors(out)) < 2.5e-4
    assert out.valid.all(), out.reason
    lost = out.times > 0.8  # Ting: contact lost at 0.78 (int_0^t E(t - s) d delta <= 0)
    assert hertz_ting(0.8) == (0.0, 0.0)
    assert np.all(out.force[lost] == 0.0) and np.all(out.contact_radius[lost] == 0.0)


@pytest.mark.slow
def test_half_space_refinement_to_1e_6():
    # both step and spacing halved: second order, and the Richardson value (4 P_fine - P_coarse)/3 within 1e-6
    runs = [_half_space(101 * 2**k - 2**k + 1, 200 * 2**k) for k in range(3)]
    errs = [np.array(_errors(r)) for r in runs]
    forces = [np.array([r.force[int(np.argmin(abs(r.times - tt)))] for tt in CHECK_TIMES]) for r in runs]
    ref = np.array([hertz_ting(tt)[0] for tt in CHECK_TIMES])
    order = np.log2(errs[1][::2] / errs[2][::2])
    assert np.all((order > 1.7) & (order < 2.4)), order
    rich = (4 * forces[2] - forces[1]) / 3
    assert np.max(np.abs(rich / ref - 1)) < 1e-6


def test_elastic_limit_on_layer_matches_elastic_solver():
    # E(t) constant: one elastic solve per step; against (F.13), (F.14) at the last depth (bonded nu = 0.3, c/H ~ 1.3)
    t = np.linspace(0.0, 1.0, 6)
    out = solve_history(BondedLayer(0.3), Punch.sphere(1.0), 0.1, Prony(2.0), t, 0.02 * t, nodes=120)
    ref = revolution_contact(BondedLayer(0.3), Punch.sphere(1.0), 0.02, 0.1, mu=2.0 / (2 * 1.3))
    assert out.force[-1] == pytest.approx(ref.force, rel=3e-4)
    assert out.contact_radius[-1] == pytest.approx(ref.radius, rel=1e-4)


def test_layer_ramp_matches_lee_radok_law():
    # monotone loading on a frictionless layer: Lee-Radok with the any-thickness elastic law (hereditary.py)
    t = np.linspace(0.0, 0.5, 21)
    d = 0.02 * t
    layer = FrictionlessLayer(0.3)
    out = solve_history(layer, Punch.paraboloid(RT), 0.1, SLS, t, d, nodes=120)
    lr = viscoelastic_force(layer, Punch.paraboloid(RT), 0.1, SLS, t, d)
    np.testing.assert_allclose(out.force[5:], lr.force[5:], rtol=5e-4)
    np.testing.assert_allclose(out.contact_radius[5:], lr.contact_radius[5:], rtol=2e-4)
    assert out.valid.all() and out.min_gap.min() >= 0


def test_force_control_inverts_depth_control():
    # the force of a depth-controlled ramp, prescribed back: the same depths (one discretisation, two controls)
    t, d = _history(41)
    out = solve_history(HalfSpace(), Punch.paraboloid(RT), 1.0, SLS, t[:21], d[:21], nu=NU, nodes=200)
    back = solve_history(HalfSpace(), Punch.paraboloid(RT), 1.0, SLS, t[:21], forces=out.force, nu=NU, nodes=200)
    # the discrete P(c) and delta(c) are each monotone only to the discretisation's error (measured 6e-5 here)
    np.testing.assert_allclose(back.depths[1:], d[1:21], rtol=2e-4)
    assert back.control == "force" and math.isclose(back.force[-1], out.force[-1])


def test_refusals_one_line():
    t = np.linspace(0, 1, 5)
    for kwargs, exc in [(dict(material=KelvinVoigt(1.0, 1.0)), TypeError),
                        (dict(depths=None), InputError),
                        (dict(nodes=5000), WorkLimitError),
                        (dict(depths=-t), InputError)]:
        args = dict(layer=HalfSpace(), tip=Punch.paraboloid(1.0), H=1.0, material=SLS, times=t, depths=0.01 * t, nu=0.3)
        args.update(kwargs)
        with pytest.raises(exc) as info:
            solve_history(**args)
        assert "\n" not in str(info.value)
    # the flat punch is solved on its face (V.10) (tests/viscoelastic/test_ting_tips.py); its disc is its radius
    with pytest.raises(InputError, match="radius a = 1") as info:
        solve_history(HalfSpace(), Punch.flat(1.0), 1.0, SLS, t, 0.01 * t, nu=0.3, radius_max=2.0)
    assert "\n" not in str(info.value)
