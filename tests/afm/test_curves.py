"""Measured curves (issue 25 item 3): instrument files through afmformats, contact point and baseline fitted.

Independent references: nanite (its own tip-position preprocessing and its own ``hertz_para`` fit with its
contact-point model, on the same real curves: afmformats' example data in tests/afm/data), and synthetic curves made
with known parameters from the any-thickness law (T.7) and Hertz's law written out
(tests/afm/test_curves_bootstrap.py).
"""
import json
import math
import warnings
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

nanite = pytest.importorskip("nanite", reason="the extra thinlayer[afm] is not installed (pip install -e .[afm])")

from test_curves_bootstrap import R, _synthetic  # noqa: E402 - the synthetic curves (no nanite needed)

from thinlayer.afm.curve_fit import fit_curve  # noqa: E402
from thinlayer.afm.curves import Curve, curve_from_arrays, load_curve  # noqa: E402

pytestmark = pytest.mark.xdist_group("afm-laws")  # one worker builds the laws once for the afm tests
DATA = Path(__file__).resolve().parent / "data"
SPOT = DATA / "fmt-jpk-fd_spot3-0192.jpk-force"
QI = DATA / "fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data"
FILES = [("fmt-jpk-fd_spot3-0192.jpk-force", 0), ("fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data", 0),
         ("fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data", 1), ("fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data", 2),
         ("fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data", 3), ("fmt-jpk-fd_qi-data-2021.04.13.jpk-qi-series", 0)]
PRE = ["compute_tip_position", "correct_force_offset", "correct_tip_offset"]


@lru_cache(maxsize=None)
def _nanite(name: str, index: int):
    """nanite's own route: its preprocessing (tip position, offsets) and its hertz_para fit with its contact-point
    model (weights over 1 um, its default).  Returns (E, the tip-position column, the force, E's standard error)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        idnt = nanite.load_group(DATA / name)[index]
        raw = np.array(idnt["height (measured)"] + idnt["force"] / idnt.metadata["spring constant"])
        idnt.apply_preprocessing(PRE)
        p = nanite.model.get_init_parms("hertz_para")
        idnt.fit_model(model_key="hertz_para", params_initial=p)
        assert idnt.fit_properties["success"]
        seg = np.asarray(idnt["segment"]) == 0
        E = idnt.fit_properties["params_fitted"]["E"]
        return E.value, raw[seg], np.array(idnt["force"])[seg], E.stderr


# ---- load_curve ----------------------------------------------------------------------------------------------------
def test_load_curve_reads_the_tip_position_as_nanite_computes_it():
    c = load_curve(SPOT)
    assert isinstance(c, Curve) and c.segment == "approach" and c.n_points == 2000 and c.units == ("m", "N")
    assert c.axis == "tip position" and c.direction == -1
    assert c.spring_constant == pytest.approx(0.043493666407368466, rel=1e-15)  # the file's, via afmformats
    _, tip, _, _ = _nanite(SPOT.name, 0)
    assert np.allclose(c.z, tip, rtol=0, atol=1e-18)  # nanite's compute_tip_position on the same file
    with pytest.raises(ValueError):
        c.z[0] = 0.0  # immutable
    r = load_curve(SPOT, segment="retract")
    assert r.segment == "retract" and r.n_points == 2000 and r.z[0] < r.z[-1]  # the tip moves away
    assert "2000 points" in str(c) and "negative into the sample" in str(c)


def test_load_curve_refusals(tmp_path):
    bad = tmp_path / "bad.jpk-force"
    bad.write_text("not a JPK file")
    other = tmp_path / "curve.xyz"
    other.write_text("1 2\n")
    for args, kw, match in [((tmp_path / "none.jpk-force",), {}, "no such file"),
                            ((SPOT,), {"segment": "dwell"}, "segment must be one of"),
                            ((SPOT,), {"index": 3}, "beyond the file's 1 curve"),
                            ((bad,), {}, "afmformats cannot read it .* it reads .*jpk-force"),
                            ((other,), {}, "reads no .xyz file; it reads .*ibw")]:
        with pytest.raises(ValueError, match=match) as exc:
            load_curve(*args, **kw)
        assert "\n" not in str(exc.value)


# ---- fit_curve on real curves: nanite's hertz_para is the reference ----------------------------------------------
def test_thick_limit_equals_nanite_hertz_para_on_real_curves():
    """With nanite's contact-point weights, the half-space fit (Hertz, contact point and offset free) is nanite's
    hertz_para fit: the same E on all six curves (measured: within 2e-5; nanite's leastsq stops at its own
    tolerance) and the same standard error (lmfit's, from its numerical Jacobian)."""
    for name, i in FILES:
        E_nanite, _, _, se_nanite = _nanite(name, i)
        r = fit_curve(load_curve(DATA / name, index=i), punch=R, H=None, weighting="nanite")
        assert r.E / E_nanite == pytest.approx(1.0, abs=1e-4), (name, i)
        assert r.E_se / se_nanite == pytest.approx(1.0, abs=0.02), (name, i)  # lmfit's covariance, same weights
        assert r.fitted == ("E", "z0", "b0") and r.model == "hertz"


def test_weighting_effect_on_a_real_curve():
    """The numbers in curve_fit's docstring and the README: weighting moves E by 4 % on the JPK spot curve and by a
    factor 61 on the first QI curve (few points in contact: unweighted, the fit takes the last steep points as the
    contact; weighted, a soft contact 0.5 um earlier).  The weighted E is nanite's (checked above)."""
    spot = load_curve(SPOT)
    E0 = fit_curve(spot, punch=R).E
    E1 = fit_curve(spot, punch=R, weighting="nanite").E
    assert E0 == pytest.approx(14742, rel=1e-3) and E1 == pytest.approx(15345, rel=1e-3)
    qi = load_curve(QI)
    assert fit_curve(qi, punch=R).E / fit_curve(qi, punch=R, weighting="nanite").E == pytest.approx(60.8, rel=0.02)


def test_finite_thickness_on_a_real_curve_lowers_E_and_flags():
    spot = load_curve(SPOT)
    thick = fit_curve(spot, punch=R, H=None)
    thin = fit_curve(spot, punch=R, H=2e-6)
    assert thin.E < thick.E and thin.model == "any-thickness" and thin.valid
    assert thin.chi_max == pytest.approx(math.sqrt(R * thin.delta_max) / 2e-6, rel=1e-12)
    assert not thin.flags  # delta/H = 0.07 < 0.1, delta/R = 0.013 < 0.1
    deep = fit_curve(spot, punch=R, H=0.5e-6)
    assert any("delta/H" in f for f in deep.flags)
    d = json.loads(json.dumps(thin.as_dict(), allow_nan=False))
    assert d["delta_over_H"] == pytest.approx(thin.delta_max / 2e-6) and d["H"] == 2e-6 and d["fitted"][1] == "z0"


# ---- synthetic curves with known parameters ------------------------------------------------------------------------
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_synthetic_curve_recovers_E_z0_baseline_within_errors(seed):
    """z-test: each parameter within 3.5 standard errors of the truth (white noise: the naive errors hold)."""
    z, F, truth = _synthetic(seed, H=3e-6)
    r = fit_curve(curve_from_arrays(z, F, axis="tip position"), punch=R, H=3e-6, baseline="offset+slope")
    for k, v in truth.items():
        se = getattr(r, f"{k}_se")
        assert abs(getattr(r, k) - v) < 3.5 * se, (k, getattr(r, k), v, se)
    assert r.E_se / r.E < 0.05  # the test can fail: the errors are small enough to mean something


@pytest.mark.slow
def test_synthetic_z_scores_over_20_seeds():
    """Over 20 seeds the z-scores of E, z0, b0, b1 have a spread near 1 (0.6 to 1.5) and none beyond 4."""
    zs = {k: [] for k in ("E", "z0", "b0", "b1")}
    for seed in range(20):
        z, F, truth = _synthetic(100 + seed, H=3e-6)
        r = fit_curve(curve_from_arrays(z, F, axis="tip position"), punch=R, H=3e-6, baseline="offset+slope")
        for k in zs:
            zs[k].append((getattr(r, k) - truth[k]) / getattr(r, f"{k}_se"))
    for k, v in zs.items():
        v = np.array(v)
        assert np.all(np.abs(v) < 4) and 0.6 < np.sqrt(np.mean(v ** 2)) < 1.5, (k, v)


def test_fit_H_contact_point_fixed_and_ranges():
    z, F, truth = _synthetic(7, H=1e-6, noise=5e-12, slope=0.0)
    c = curve_from_arrays(z, F, axis="tip position")
    r = fit_curve(c, punch=R, H=2e-6, fit_H=True)
    assert abs(r.H - 1e-6) < 3.5 * r.H_se and "H" in r.fitted
    fixed = fit_curve(c, punch=R, H=1e-6, contact_point=truth["z0"])
    assert fixed.z0 == truth["z0"] and fixed.z0_se == 0 and "z0" not in fixed.fitted
    assert abs(fixed.E - truth["E"]) < 3.5 * fixed.E_se
    part = fit_curve(c, punch=R, H=1e-6, fit_range=(-0.5e-6, 1e-6))
    assert part.n_points == int(np.sum((z >= -0.5e-6) & (z <= 1e-6)))
    ind = fit_curve(c, punch=R, H=1e-6, fit_range=(-1e-6, 0.4e-6), range_kind="indentation")
    assert ind.n_points < z.size and abs(ind.E - truth["E"]) < 3.5 * ind.E_se
    assert np.allclose(fixed.predict(z), F, atol=5 * 5e-12)  # the model at the data, within the noise
    assert "contact point" in str(r) and r.latex().startswith("E = ")


def test_fit_curve_refusals():
    z, F, _ = _synthetic(1)
    c = curve_from_arrays(z, F, axis="tip position")
    for kw, match in [({"baseline": "cubic"}, "baseline must be one of"), ({"weighting": "x"}, "weighting must be"),
                      ({"fit_range": (1.0, 0.0)}, "lo < hi"), ({"bootstrap": -1}, "bootstrap must be"),
                      ({"H": None, "fit_H": True}, "needs H="), ({"fit_range": (5.0, 6.0)}, "too few")]:
        with pytest.raises((ValueError, TypeError), match=match) as exc:
            fit_curve(c, punch=R, **kw)
        assert "\n" not in str(exc.value)
    with pytest.raises(ValueError, match="force falls as the tip moves into the sample"):
        fit_curve(curve_from_arrays(z, F, axis="depth"), punch=R)  # the tip position taken for a depth
    noise = next(e for e in (np.random.default_rng(s).normal(0, 1e-11, z.size) for s in range(50))
                 if np.corrcoef(-z, e)[0, 1] > 0)  # noise that does not fall into the sample: past the sign check
    with pytest.raises(ValueError, match="no contact"):
        fit_curve(curve_from_arrays(z, noise, axis="tip position"), punch=R)
    with pytest.raises(TypeError, match="needs a Curve"):
        fit_curve((z, F), punch=R)
