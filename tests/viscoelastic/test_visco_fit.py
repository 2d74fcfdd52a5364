"""fit_viscoelastic (issue 27 item 4): parameters and uncertainties recovered from synthetic data.

The data come from the hereditary integral (:func:`thinlayer.viscoelastic_force`, checked against closed forms and
quadrature in test_lee_radok.py and test_door_solve.py) or from the complex modulus (test_door_oscillation.py), with
Gaussian noise; the check is the statistical one: the true values lie within the stated errors (3.5 sigma per seed
by default; the 2-sigma coverage over 40 seeds under THINLAYER_SLOW=1).
"""
from __future__ import annotations

import numpy as np
import pytest

from thinlayer import BondedLayer, Punch, solve, viscoelastic_force
from thinlayer.contact.materials import PowerLaw, StandardLinearSolid
from thinlayer.contact.oscillation import oscillation
from thinlayer.contact.visco_fit import fit_viscoelastic
from thinlayer.errors import ThinlayerError

L, TIP, H = BondedLayer(0.5), Punch.paraboloid(10.0), 1.0
TRUE = {"E0": 3.0, "E_inf": 1.0, "tau": 0.3}
SLS = StandardLinearSolid(3.0, 1.0, 0.3)


def _approach_retract(speed: float, n: int = 81):
    """Approach to 0.1 at ``speed``, retract at the same speed: (t, d, P), the retraction by Ting's method (the door
    routes a Prony depth history there; Ting is checked against the direct solver in test_ting.py)."""
    T = 0.1 / speed
    t = np.linspace(0.0, 2 * T, n)
    d = np.where(t <= T, speed * t, 0.1 - speed * (t - T))
    return t, d, solve(L, TIP, H=H, material=SLS, history=(t, d)).force


@pytest.fixture(scope="module")
def curves():
    return [_approach_retract(0.1), _approach_retract(0.5)]


def _noisy(curves, seed, rel=0.003):
    rng = np.random.default_rng(seed)
    top = max(np.nanmax(P) for _, _, P in curves)
    return [(t, d, np.where(np.isfinite(P), P, 0.0) + rng.normal(0.0, rel * top, t.size)) for t, d, P in curves]


def _within(res, truth, k):
    return all(abs(res.values[n] - v) <= k * res.errors[n] for n, v in truth.items())


def test_exact_data_recovered(curves):
    res = fit_viscoelastic(L, TIP, H, curves=[curves[1]])
    for n, v in TRUE.items():
        assert res.values[n] == pytest.approx(v, rel=1e-6)
    assert res.n_excluded == 0 and "1 with its retraction by Ting's method" in res.reason
    # a power law has no Ting here: its retraction is left out and counted
    pl = PowerLaw(2.0, 1.0, 0.2)
    t, d, _ = curves[1]
    P = viscoelastic_force(L, TIP, H, pl, t, d).force
    res = fit_viscoelastic(L, TIP, H, material="power-law", curves=[(t, d, np.where(np.isfinite(P), P, 0.0))])
    assert res.values["alpha"] == pytest.approx(0.2, rel=1e-6)
    assert res.n_excluded == d.size - int(np.argmax(d)) - 1 and "left out" in res.reason


@pytest.mark.parametrize("seed", [0, pytest.param(1, marks=pytest.mark.slow), pytest.param(2, marks=pytest.mark.slow)])
def test_approach_retract_two_speeds_within_errors(curves, seed):
    res = fit_viscoelastic(L, TIP, H, curves=_noisy(curves, seed))
    assert _within(res, TRUE, 3.5), (res.values, res.errors)
    assert all(0 < res.errors[n] < 0.2 * TRUE[n] for n in TRUE)


@pytest.mark.slow
def test_two_sigma_coverage_over_seeds(curves):
    hits = sum(_within(fit_viscoelastic(L, TIP, H, curves=_noisy(curves, s)), {n: v}, 2.0)
               for s in range(40) for n, v in TRUE.items())
    assert 0.85 * 120 <= hits <= 120, hits


def test_power_law_ramp_hold_within_errors():
    pl = PowerLaw(2.0, 1.0, 0.2)
    t = np.linspace(0.0, 1.0, 301)
    d = 0.1 * np.minimum(t / 0.5, 1.0)
    P = np.array(viscoelastic_force(L, TIP, H, pl, t, d).force)
    rng = np.random.default_rng(5)
    res = fit_viscoelastic(L, TIP, H, material="power-law", curves=[(t, d, P + rng.normal(0, 0.003 * P.max(),
                                                                                            t.size))])
    assert _within(res, {"E0": 2.0, "alpha": 0.2}, 3.5), (res.values, res.errors)
    assert "alpha" in res.latex() and res.as_dict()["values"]["alpha"] == res.values["alpha"]


def test_oscillation_within_errors_and_bottom_effect():
    w = np.geomspace(0.1, 100.0, 12)
    osc = oscillation(L, TIP, H, SLS, 0.13, w, 1e-3)
    rng = np.random.default_rng(3)
    K = osc.dynamic_stiffness * (1 + rng.normal(0, 0.01, w.size) + 1j * rng.normal(0, 0.01, w.size))
    res = fit_viscoelastic(L, TIP, H, oscillation=(w, K), delta0=0.13)
    assert _within(res, TRUE, 3.5), (res.values, res.errors)
    # the same measurement read on a thick sample (H = 1e3: the half-space's stiffness) overestimates the moduli by
    # the bottom effect S_layer/S_half-space and leaves tau alone
    thick = fit_viscoelastic(L, TIP, 1e3, oscillation=(w, K), delta0=0.13)
    ratio = osc.stiffness.bottom_effect
    assert thick.values["E0"] / res.values["E0"] == pytest.approx(ratio, rel=2e-3)
    assert thick.values["tau"] == pytest.approx(res.values["tau"], rel=1e-6)


@pytest.mark.parametrize("kwargs,match", [
    (dict(), "exactly one"),
    (dict(curves="data"), "list"),
    (dict(curves=[([0.0, 1.0], [0.0, 0.1])]), "triple"),
    (dict(curves=[([0.0, 1.0], [0.0, 0.1], [0.0, 0.1])], material="maxwell"), "material"),
    (dict(oscillation=([1.0, 2.0], [1.0, 2.0])), "delta0"),
    (dict(curves=[([0.0, 1.0], [0.0, 0.1], [0.0, 0.1])], guess={"E0": "3"}), "guess"),
    (dict(curves=[([1.0, 0.0], [0.0, 0.1], [0.0, 0.1])]), "increasing"),
])
def test_bad_input_one_line(kwargs, match):
    with pytest.raises(ThinlayerError, match=match) as exc:
        fit_viscoelastic(L, TIP, H, **kwargs)
    assert "\n" not in str(exc.value)
