"""thinlayer's viscoelastic nanite models (issue 27 item 4): the approach of a constant-speed indentation, Lee-Radok.

Checked against: the elastic family (E0 = E_inf, tau -> 0), closed forms on the half-space (Hertz under a power law:
a Beta function; under a standard linear solid: quadrature of ``int exp(-(t - s)/tau) s^(1/2) ds``), the engine's
Lee-Radok door on the layer (:func:`thinlayer.viscoelastic_force`: the registry's law, the data's own time grid), and
nanite's own fit (``Indentation.fit_model``) of a noisy synthetic approach made by that door.
Skipped only when the extra ``thinlayer[afm]`` (nanite, afmformats) is not installed.
"""
import math
import warnings

import numpy as np
import pytest

nanite = pytest.importorskip("nanite", reason="the extra thinlayer[afm] is not installed (pip install -e .[afm])")

from thinlayer import BondedLayer, Punch, StandardLinearSolid, viscoelastic_force  # noqa: E402
from thinlayer.afm.nanite_models import model_keys, model_module, register, visco_model_keys, visco_model_module  # noqa: E402

pytestmark = pytest.mark.xdist_group("afm-laws")
R, NU, V = 10e-6, 0.5, 1e-6  # tip radius [m], Poisson ratio, indentation speed [m/s]
Z = -np.linspace(0.0, 2e-6, 301)[1:]  # tip position, contact point 0, to 2 um deep


def test_the_modules_pass_nanites_checks_and_are_listed():
    from nanite.model.core import NaniteFitModel

    with warnings.catch_warnings():
        warnings.simplefilter("error")  # nanite warns when the arguments are not in parameter_keys' order
        for key in visco_model_keys():
            md = NaniteFitModel(visco_model_module(*key.split("_")[1:]))
            assert md.valid_axes_x == ["tip position"] and "speed" in md.parameter_keys
            assert "approach" in md.model_doc and "constant" in md.model_doc
    register()
    assert set(visco_model_keys()) | set(model_keys()) <= set(nanite.model.models_available)
    assert "thinlayer_sls_para_bonded" in visco_model_keys() and "thinlayer_powerlaw_cone_frictionless" in \
        visco_model_keys()


@pytest.mark.parametrize("tip,base,size,H", [("para", "bonded", R, 5e-6), ("para", "frictionless", R, 5e-6),
                                             ("para", "bonded", R, math.inf), ("flat", "bonded", 5e-6, 5e-6),
                                             ("cone", "bonded", 25.0, math.inf), ("pyr4s", "bonded", 25.0, math.inf)])
def test_no_relaxation_is_the_elastic_model(tip, base, size, H):
    """E0 = E_inf: the elastic model with E = E_inf; tau = 1e-13 s (relaxed at once): the same to 1e-10."""
    el = model_module(tip, base).model_func(Z, 3e3, size, NU, H, 1e-7, 1e-10)
    vs = visco_model_module("sls", tip, base).model_func
    np.testing.assert_allclose(vs(Z, 3e3, 3e3, 0.2, V, size, NU, H, 1e-7, 1e-10), el, rtol=1e-10, atol=0)
    if tip == "para":
        np.testing.assert_allclose(vs(Z, 9e3, 3e3, 1e-13, V, size, NU, H, 1e-7, 1e-10), el, rtol=1e-10, atol=0)
        assert np.all(vs(Z, 9e3, 3e3, 0.5, V, size, NU, H, 1e-7, 1e-10)[10:] > 1.2 * el[10:])  # relaxing: stiffer


def test_half_space_closed_forms():
    """Hertz ``f = c delta^(3/2)``, ``c = 4 sqrt(R)/(3(1 - nu^2))``, at ``delta = v t``: under ``E0 (t/t0)^-a``,
    ``P = E0 c v^(3/2) (3/2) B(3/2, 1 - a) t^(3/2 - a)`` (t0 = 1); under a standard linear solid, ``P = c v^(3/2)
    [E_inf t^(3/2) + (3/2) E1 int_0^t exp(-(t - s)/tau) s^(1/2) ds]`` (quadrature)."""
    from scipy.integrate import quad
    from scipy.special import beta

    c, t = 4 * math.sqrt(R) / (3 * (1 - NU ** 2)), -Z / V
    pl = visco_model_module("powerlaw", "para", "bonded").model_func(Z, 3e3, 0.2, 1.0, V, R, NU, math.inf, 0.0, 0.0)
    exact = 3e3 * c * V ** 1.5 * 1.5 * beta(1.5, 0.8) * t ** 1.3
    assert np.max(np.abs(pl - exact)) < 2e-6 * exact.max()  # measured 8.4e-7 (the first nodes; 1e-7 deep)
    assert np.max(np.abs(pl / exact - 1)[100:]) < 1e-6
    sls = visco_model_module("sls", "para", "bonded").model_func(Z, 3e3, 1e3, 0.5, V, R, NU, math.inf, 0.0, 0.0)
    ref = np.array([c * V ** 1.5 * (1e3 * x ** 1.5 + 1.5 * 2e3 * quad(lambda s, x=x: math.exp(-(x - s) / 0.5)
                                                                       * math.sqrt(s), 0, x, epsrel=1e-12)[0])
                    for x in t[::20]])
    assert np.max(np.abs(sls[::20] - ref)) < 1e-7 * ref.max()  # measured 3.6e-8


def test_the_layer_equals_the_lee_radok_door():
    """H = 5 um (a/H up to ~1): the model against viscoelastic_force (the registry's any-thickness law (T.7), the
    hereditary integral on the data's own 300 times)."""
    t = -Z / V
    door = viscoelastic_force(BondedLayer(NU), Punch.paraboloid(R), 5e-6, StandardLinearSolid(9e3, 3e3, 0.5), t, -Z)
    P = visco_model_module("sls", "para", "bonded").model_func(Z, 9e3, 3e3, 0.5, V, R, NU, 5e-6, 0.0, 0.0)
    assert door.valid.all()
    assert np.max(np.abs(P - door.force)) < 1e-5 * door.force.max()


def _indentation(z, force):
    meta = {"spring constant": 0.05, "sensitivity": 1e-8, "imaging mode": "force-distance", "path": "synthetic",
            "enum": 0, "duration": float(abs(z[-1] - z[0]) / V), "z range": float(abs(z[-1] - z[0])),
            "point count": z.size, "speed approach": V, "speed retract": V, "rate approach": 100.0,
            "rate retract": 100.0}
    data = {"force": force, "tip position": z, "segment": np.zeros(z.size, dtype=bool), "time": (z[0] - z) / V}
    return nanite.Indentation(data=data, metadata=meta)


def test_nanite_fits_a_noisy_synthetic_approach():
    """The approach (0.5 um above contact to 2 um deep) made by viscoelastic_force (SLS 9/3 kPa, 0.5 s, H = 5 um,
    contact point 0.1 um, baseline 2 nN), 0.3 % noise; nanite fits E0, E_inf, tau, contact point, baseline with its
    own machinery: each within 3 of lmfit's standard errors."""
    register(["thinlayer_sls_para_bonded"])
    z = np.linspace(0.6e-6, -1.9e-6, 400)
    d = np.maximum(1e-7 - z, 0.0)
    door = viscoelastic_force(BondedLayer(NU), Punch.paraboloid(R), 5e-6, StandardLinearSolid(9e3, 3e3, 0.5),
                              (z[0] - z) / V, d)
    force = np.nan_to_num(door.force) + 2e-9
    force = force + np.random.default_rng(7).normal(0.0, 0.003 * force.max(), z.size)
    idnt = _indentation(z, force)
    p = nanite.model.get_init_parms("thinlayer_sls_para_bonded")
    for k, v in {"E0": 5e3, "E_inf": 2e3, "tau": 0.3, "H": 5e-6, "speed": V, "contact_point": 0.0}.items():
        p[k].value = v
    idnt.fit_model(model_key="thinlayer_sls_para_bonded", params_initial=p)
    assert idnt.fit_properties["success"]
    fitted = idnt.fit_properties["params_fitted"]
    for k, v in {"E0": 9e3, "E_inf": 3e3, "tau": 0.5, "contact_point": 1e-7, "baseline": 2e-9}.items():
        assert abs(fitted[k].value - v) <= 3 * fitted[k].stderr, (k, fitted[k].value, fitted[k].stderr)
        assert fitted[k].stderr < 0.25 * abs(v), k  # one speed: tau to ~20 %


def test_bad_keys_are_refused():
    with pytest.raises(ValueError, match="unknown thinlayer nanite model 'thinlayer_maxwell_para_bonded'"):
        register(["thinlayer_maxwell_para_bonded"])
    with pytest.raises(ValueError, match="material"):
        visco_model_module("maxwell", "para", "bonded")
