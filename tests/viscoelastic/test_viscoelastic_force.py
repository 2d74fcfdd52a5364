"""viscoelastic_force(): the front door of the Lee-Radok law (issue 27 item 3): flags, refusals, read-only results."""
from __future__ import annotations

import numpy as np
import pytest

from thinlayer import BondedLayer, FrictionlessLayer, Punch
from thinlayer.contact.hereditary import viscoelastic_force
from thinlayer.contact.materials import KelvinVoigt, PowerLaw, Prony, StandardLinearSolid
from thinlayer.errors import InputError, InputTypeError

SLS = StandardLinearSolid(3.0, 1.0, 0.2)


def _approach_retract(n=201):
    t = np.linspace(0.0, 2.0, 2 * n - 1)
    d = 0.05 * np.minimum(t, 2.0 - t)
    return t, d


def test_elastic_limit_is_the_elastic_force():
    # E(t) = E constant: P = E F(delta)/(2 (1 + nu)) at every time, whatever the history
    t, d = _approach_retract()
    out = viscoelastic_force(BondedLayer(0.3), Punch.paraboloid(10.0), 1.0, Prony(2.6, []), t[:201], d[:201])
    from thinlayer import solve

    ref = solve(BondedLayer(0.3), Punch.paraboloid(10.0), delta0=0.05, H=1.0, E=2.6, model="any-thickness")
    assert out.force[-1] == pytest.approx(ref.force, rel=1e-9)
    assert out.contact_radius[-1] == pytest.approx(ref.contact_radius, rel=1e-9)


def test_a_shrinking_contact_is_flagged_not_answered():
    t, d = _approach_retract()
    out = viscoelastic_force(BondedLayer(0.3), Punch.paraboloid(10.0), 1.0, SLS, t, d)
    k = int(np.argmax(d))
    assert out.valid[: k + 1].all() and not out.valid[k + 1:].any()
    assert np.isnan(out.force[k + 1:]).all() and np.isnan(out.contact_radius[k + 1:]).all()
    assert "Ting's method is needed" in out.reason and "NOT VALID" in str(out)
    assert np.all(out.force[out.valid] >= 0)


def test_ramp_hold_relaxes_to_the_relaxed_modulus():
    t = np.linspace(0.0, 5.0, 5001)
    d = 0.05 * np.minimum(t, 1.0)
    out = viscoelastic_force(FrictionlessLayer(0.3), Punch.paraboloid(10.0), 1.0, SLS, t, d)
    relaxed = viscoelastic_force(FrictionlessLayer(0.3), Punch.paraboloid(10.0), 1.0, Prony(1.0, []), t, d)
    assert out.valid.all()
    assert np.all(np.diff(out.force[1001:]) < 0)  # relaxation during the hold
    # after 20 tau the SLS force is the relaxed elastic one to exp(-20) ~ 2e-9 (relative, times E0/E_inf)
    assert out.force[-1] == pytest.approx(relaxed.force[-1], rel=1e-8)
    assert out.force[1000] > 1.5 * relaxed.force[1000]


def test_flat_punch_force_follows_the_material_and_lift_off_is_flagged():
    t, d = _approach_retract()
    out = viscoelastic_force(BondedLayer(0.3), Punch.flat(1.0), 1.0, KelvinVoigt(1.0, 0.3), t, d)
    assert out.model == "direct"
    assert np.all(out.contact_radius[1:200] == 1.0)
    bad = ~out.valid
    assert bad.any() and "lifts off" in out.reason and np.isnan(out.force[bad]).all()


@pytest.mark.parametrize("material", [KelvinVoigt(1.0, 0.3), PowerLaw(1.0, 1.0, 0.4)])
def test_a_step_under_an_infinite_instantaneous_modulus_is_flagged(material):
    t = np.linspace(0.0, 1.0, 11)
    out = viscoelastic_force(BondedLayer(0.3), Punch.paraboloid(10.0), 1.0, material, t, np.full(11, 0.02))
    assert not out.valid[0] and np.isnan(out.force[0]) and "infinite force" in out.reason
    assert out.valid[1:].all() and np.all(np.isfinite(out.force[1:]))


def test_result_is_read_only_and_the_users_arrays_are_untouched():
    t = np.linspace(0.0, 1.0, 11)
    d = 0.01 * t
    out = viscoelastic_force(BondedLayer(0.3), Punch.paraboloid(10.0), 1.0, SLS, t, d)
    assert t.flags.writeable and d.flags.writeable
    with pytest.raises(ValueError):
        out.force[0] = 1.0
    with pytest.raises(AttributeError):
        out.reason = "x"
    assert out.latex().startswith(r"P(t) = \frac{1}{2(1+\nu)}")
    assert repr(out) == "<ViscoelasticForce: any-thickness law, 11 times>"


@pytest.mark.parametrize("kwargs, kind, words", [
    (dict(times=[0.0, 1.0, 1.0], depths=[0.0, 0.1, 0.2]), InputError, "strictly increasing"),
    (dict(times=[0.0, 1.0], depths=[0.0]), InputError, "one length"),
    (dict(times=[0.0, float("nan")], depths=[0.0, 0.1]), InputError, "finite"),
    (dict(times=[0.0, 1.0], depths=[0.0, 0.1], material=3.0), InputTypeError, "material must be"),
    (dict(times=[0.0, 1.0], depths=[0.0, 0.1], H=-1.0), InputError, "H"),
    (dict(times=[0.0, 1.0], depths=[0.0, 0.1], layer="bonded"), InputTypeError, "layer must be"),
    (dict(times=[0.0, 1.0], depths=[0.0, 0.1], tol=0), InputError, "tol"),
])
def test_bad_input_is_one_line(kwargs, kind, words):
    args = dict(layer=BondedLayer(0.3), punch=Punch.paraboloid(10.0), H=1.0, material=SLS)
    args.update(kwargs)
    with pytest.raises(kind) as exc:
        viscoelastic_force(**args)
    assert words in str(exc.value) and "\n" not in str(exc.value)


def test_depths_outside_the_elastic_law_are_flagged_with_everything_after():
    # the elliptic paraboloid has the thin-layer law only: a ramp from zero starts where its estimate exceeds tol
    t = np.linspace(0.0, 1.0, 21)
    out = viscoelastic_force(BondedLayer(0.3), Punch.elliptic_paraboloid(4, 1), 0.05, SLS, t, 0.1 * t)
    assert out.model == "compressible" and not out.valid[1:].any() and "estimate exceeds tol" in out.reason
    # the same punch stepped to a depth where the law holds, then ramped: valid throughout
    out = viscoelastic_force(BondedLayer(0.3), Punch.elliptic_paraboloid(4, 1), 0.05, SLS, t, 0.05 + 0.1 * t)
    assert out.valid.all() and np.all(np.diff(out.force) > 0)


def test_runaway_histories_are_refused_before_any_work():
    from thinlayer.contact.hereditary import MAX_STEPS
    from thinlayer.errors import WorkLimitError

    n = MAX_STEPS + 1
    with pytest.raises(WorkLimitError, match="subsample the history"):
        viscoelastic_force(BondedLayer(0.3), Punch.paraboloid(10.0), 1.0, SLS, range(n), range(n))
    with pytest.raises(WorkLimitError, match="subsample the history"):
        viscoelastic_force(BondedLayer(0.3), Punch.paraboloid(10.0), 1.0, SLS, np.zeros(n), np.zeros(n))


def test_power_law_before_contact_is_exactly_zero_and_valid():
    """A power-law ramp that starts at rest (depth 0 until t = 0.3): the hereditary integral is exactly 0 before the
    first change of the elastic force, so no pre-contact point is flagged as a lift-off (before the fix the FFT's
    round-off left forces of -1e-17 there, flagged 'the punch lifts off'); the first force in contact is positive."""
    import numpy as np

    from thinlayer import BondedLayer, Punch, viscoelastic_force
    from thinlayer.contact.materials import PowerLaw

    t = np.linspace(0.0, 1.0, 2001)
    d = 0.05 * np.maximum(t - 0.3, 0.0)
    out = viscoelastic_force(BondedLayer(0.5), Punch.paraboloid(10.0), 1.0, PowerLaw(E0=3.0, alpha=0.2, t0=1.0), t, d)
    assert out.valid.all(), out.reason if hasattr(out, "reason") else out
    assert (out.force[t <= 0.3] == 0.0).all()
    assert (out.force[t > 0.3] > 0.0).all()
