"""thinlayer's laws as nanite fit models, on real AFM curves (issue 25 item 1).

The curves are afmformats' own example data (tests/afm/data, MIT).  Every E of a thinlayer model is compared with the
E of nanite's own model (hertz_para, hertz_cone: an independent implementation) fitted by nanite to the same curve.
Skipped only when the extra ``thinlayer[afm]`` (nanite, afmformats) is not installed.
"""
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

nanite = pytest.importorskip("nanite", reason="the extra thinlayer[afm] is not installed (pip install -e .[afm])")

from thinlayer.afm import nanite_models  # noqa: E402
from thinlayer.afm.nanite_models import model_keys, model_module, register  # noqa: E402

pytestmark = pytest.mark.xdist_group("afm-laws")  # one worker builds the laws once for the afm tests
DATA = Path(__file__).resolve().parent / "data"
FILES = ["fmt-jpk-fd_spot3-0192.jpk-force", "fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data",
         "fmt-jpk-fd_qi-data-2021.04.13.jpk-qi-series"]
PRE = ["compute_tip_position", "correct_force_offset", "correct_tip_offset"]


@pytest.fixture(scope="module")
def curves():
    """The six real curves, preprocessed as nanite's documentation does (tip position, offsets)."""
    register()
    out = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for f in FILES:
            for idnt in nanite.load_group(DATA / f):
                idnt.apply_preprocessing(PRE)
                out.append((f, idnt))
    assert len(out) == 6
    return out


def _E(idnt, key, **values):
    """E fitted by nanite with ``key``; fresh parameters each time (nanite skips a fit whose parameters' hash it has
    seen, and lmfit Parameters are mutable)."""
    p = nanite.model.get_init_parms(key)
    for k, v in values.items():
        p[k].value = v
    idnt.fit_model(model_key=key, params_initial=p)
    assert idnt.fit_properties["success"]
    return idnt.fit_properties["params_fitted"]["E"].value


def test_the_modules_pass_nanites_own_checks():
    """nanite's NaniteFitModel checks a module (attributes, key order, argument names) and warns otherwise."""
    from nanite.model.core import NaniteFitModel

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for key in model_keys():
            md = NaniteFitModel(model_module(*key.split("_")[1:]))
            assert md.parameter_keys[:1] == ["E"] and "H" in md.parameter_keys
            assert md.valid_axes_x == ["tip position"]
    register()
    assert set(model_keys()) <= set(nanite.model.models_available)


def _thick_limit(curves, base):
    """The paraboloid: H = inf is Hertz (nanite's hertz_para) to 1e-12; the any-thickness law at H = 10 m (chi ~
    1e-6: the law's finite-H path) to 1e-6; at H = 1 mm the layer shows (E lower by more than 1e-3: the check can
    fail).  Returns nanite's E per curve."""
    out = []
    for name, idnt in curves:
        E_nanite = _E(idnt, "hertz_para")
        assert E_nanite > 0
        assert abs(_E(idnt, f"thinlayer_para_{base}", H=math.inf) / E_nanite - 1) < 1e-12, name
        assert abs(_E(idnt, f"thinlayer_para_{base}", H=10.0) / E_nanite - 1) < 1e-6, name
        assert _E(idnt, f"thinlayer_para_{base}", H=1e-3) / E_nanite < 1 - 1e-3, name
        out.append(E_nanite)
    return out


def test_thick_limit_equals_nanites_hertz_on_real_curves(curves):
    """Six real curves, the frictionless base (its law builds in ~1 s; the bonded one under THINLAYER_SLOW)."""
    assert len(set(np.round(np.log10(_thick_limit(curves, "frictionless")), 6))) == 6  # six different curves


@pytest.mark.slow
def test_thick_limit_bonded_on_real_curves(curves):
    _thick_limit(curves, "bonded")


@pytest.mark.slow
def test_cone_thick_limit_equals_nanites_hertz_cone(curves):
    """The cone against nanite's hertz_cone (Sneddon) on the same curves, nu = 0.45 (the bonded law's table; building
    the cone's law takes ~50 s cold)."""
    for name, idnt in curves[:2]:
        E_nanite = _E(idnt, "hertz_cone", nu=0.45)
        assert abs(_E(idnt, "thinlayer_cone_bonded", nu=0.45, H=10.0) / E_nanite - 1) < 1e-6, name
        assert abs(_E(idnt, "thinlayer_cone_frictionless", nu=0.45, H=10.0) / E_nanite - 1) < 1e-6, name


def test_cone_half_space_is_nanites_hertz_cone(curves):
    """H = inf: the cone is Sneddon's, nanite's hertz_cone, to 1e-12 (no law is built)."""
    for name, idnt in curves:
        E_nanite = _E(idnt, "hertz_cone", nu=0.45)
        assert abs(_E(idnt, "thinlayer_cone_bonded", nu=0.45, H=math.inf) / E_nanite - 1) < 1e-12, name


def test_flat_punch_thick_limit_is_sneddons():
    """The flat punch (no nanite model): H = inf is Sneddon's ``2 E a delta/(1 - nu^2)``; at a/H = 1e-6 kappa is 1 to
    1e-5 (kappa = 1 + O(a/H)); a thinner layer is stiffer."""
    mod = model_module("flat", "bonded")
    d = -np.linspace(0.0, 1e-6, 11)  # tip position: negative into the sample
    F = mod.model_func(d, 1e3, 5e-6, 0.45, math.inf)
    np.testing.assert_allclose(F, 2 * 1e3 * 5e-6 * (-d) / (1 - 0.45 ** 2), rtol=1e-15)
    np.testing.assert_allclose(mod.model_func(d, 1e3, 5e-6, 0.45, 5.0), F, rtol=1e-5)
    assert np.all(mod.model_func(d[1:], 1e3, 5e-6, 0.45, 5e-6) > 1.5 * F[1:])


def test_finite_thickness_on_a_real_curve(curves):
    """A finite H lowers E (the stiff base carries part of the load): at H = 50 x the depth the Dimitriadis
    (2002) first-order factor 1 + 1.133 chi (chi = sqrt(R delta)/H = 0.17 at the deepest point) bounds it."""
    name, idnt = curves[0]
    E_inf = _E(idnt, "thinlayer_para_frictionless", H=math.inf)
    depth = idnt.fit_properties["params_fitted"]["contact_point"].value - float(np.min(idnt["tip position"]))
    E_H = _E(idnt, "thinlayer_para_frictionless", H=50 * depth)
    chi = math.sqrt(10e-6 * depth) / (50 * depth)
    assert 1 / (1 + 1.133 * chi) < E_H / E_inf < 1 - 1e-2, (E_H / E_inf, chi)


def test_register_refuses_an_unknown_key():
    with pytest.raises(ValueError, match="unknown thinlayer nanite model 'thinlayer_pyr_bonded'"):
        register(["thinlayer_pyr_bonded"])
    with pytest.raises(ValueError, match="tip"):
        model_module("pyramid", "bonded")
    assert nanite_models.TIPS.keys() == {"para", "cone", "flat"}
