"""Force maps (issue 25 item 5): thinlayer.afm.maps.fit_map on synthetic maps of known E, contact point and thickness,
and on a real JPK map (afmformats' test data).

The synthetic maps are afmformats HDF5 files (thinlayer.afm.map_data.write_synthetic_map) whose curves are Hertz's
closed form (the half-space: no law to build, cheap) plus Gaussian noise: the truth is the input, independent of the
fitter.  Small sizes (4 x 4 pixels, 300 points per curve).
"""
from __future__ import annotations

import csv
import dataclasses
import math

import numpy as np
import pytest

pytest.importorskip("afmformats")
pytest.importorskip("h5py")

from thinlayer.afm.map_data import MapGrid, read_map, write_synthetic_map  # noqa: E402
from thinlayer.afm.maps import CurveFit, fit_curve_basic, fit_map, substrate_level, thickness_from_height  # noqa: E402
from thinlayer.errors import InputError  # noqa: E402

R = 5e-6
NU = 0.5
#: the truth of the 4 x 4 map: E (Pa) varies over the map; pixel (0, 3) has nothing to indent (E = 0)
E_TRUE = np.array([[3e3, 4e3, 5e3, 0.0],
                   [6e3, 7e3, 8e3, 9e3],
                   [1e4, 1.1e4, 1.2e4, 3.5e3],
                   [4.5e3, 5.5e3, 6.5e3, 7.5e3]])
#: contact heights (m): a topography of 0 .. 150 nm
CONTACT = 1e-8 * np.arange(16.0).reshape(4, 4)
PIXEL = 1e-6
NOISE = 2e-12  # N; the peak force is ~ 1e-8 N


@pytest.fixture(scope="module")
def hertz_map(tmp_path_factory):
    path = tmp_path_factory.mktemp("maps") / "hertz.h5"
    write_synthetic_map(path, E_TRUE, math.inf, R=R, nu=NU, points=300, depth=0.2e-6, contact=CONTACT, noise=NOISE,
                        pixel=PIXEL, seed=1)
    return path


@pytest.fixture(scope="module")
def hertz_result(hertz_map):
    """The map fitted by the fast fitter (fit_curve_basic); the default fitter (fit_curve) in its own test."""
    return fit_map(hertz_map, punch=R, H=None, nu=NU, progress=False, fit_one=fit_curve_basic)


def test_read_map_places_each_curve_on_its_pixel(hertz_map):
    curves, grid = read_map(hertz_map)
    assert grid.shape == (4, 4) and len(curves) == 16
    assert sorted(c.index for c in curves) == [(i, j) for i in range(4) for j in range(4)]
    assert grid.extent_um == pytest.approx((0.0, 4.0, 0.0, 4.0))
    np.testing.assert_allclose(grid.x, [0.5, 1.5, 2.5, 3.5])
    c = next(c for c in curves if c.index == (1, 2))
    assert c.position == pytest.approx((2.5e-6, 1.5e-6))
    # the tip position is height (measured) + force/k (nanite's compute_tip_position): it starts 0.2 um above contact
    assert c.tip_position[0] == pytest.approx(CONTACT[1, 2] + 0.2e-6, abs=1e-15)


def test_fit_map_recovers_E_and_the_contact_point(hertz_result):
    r = hertz_result
    ok = E_TRUE > 0
    assert r.shape == (4, 4)
    assert np.all(r.status[ok] == "ok"), r.reasons[ok]
    np.testing.assert_allclose(r.E[ok], E_TRUE[ok], rtol=5e-3)
    np.testing.assert_allclose(r.contact_point[ok], CONTACT[ok], atol=3e-9)  # sampling step 1.3 nm
    assert np.all(r.E_se[ok] > 0) and np.all(r.E_se[ok] < 5e-3 * r.E[ok])
    assert np.all(np.isinf(r.H[ok]))
    # residual: the noise's standard deviation
    np.testing.assert_allclose(r.residual[ok], NOISE, rtol=0.25)


def test_the_default_fitter_is_fit_curve(hertz_map):
    """fit_map's default per-curve fitter: thinlayer.afm.curve_fit.fit_curve (contact point and baseline fitted), on
    curves passed as a list (two pixels of the map).
    """
    from thinlayer.afm.maps import default_fitter, fit_curve_full

    assert default_fitter() is fit_curve_full
    curves, _ = read_map(hertz_map)
    two = [c for c in curves if c.index in ((1, 1), (2, 2))]
    r = fit_map(two, punch=R, H=None, nu=NU, progress=False)
    assert r.fitter == "fit_curve_full" and r.shape == (3, 3) and r.counts()["empty"] == 7
    for i in (1, 2):
        assert r.E[i, i] == pytest.approx(E_TRUE[i, i], rel=5e-3)
        assert r.contact_point[i, i] == pytest.approx(CONTACT[i, i], abs=3e-9)


def test_a_failed_pixel_is_nan_with_its_reason(hertz_result):
    r = hertz_result
    assert r.status[0, 3] == "failed"
    for a in (r.E, r.E_se, r.contact_point, r.residual):
        assert math.isnan(a[0, 3])
    (row, col, name, reason), = r.failures
    assert (row, col) == (0, 3) and name.endswith("[3]")
    assert "contact" in reason and "\n" not in reason
    assert r.counts() == {"ok": 15, "flagged": 0, "failed": 1, "empty": 0}
    assert "failed" in r.failures_text() and "0, 3" in r.failures_text()


def test_map_result_is_immutable(hertz_result):
    with pytest.raises(ValueError):
        hertz_result.E[0, 0] = 1.0
    with pytest.raises(ValueError):
        hertz_result.status[0, 0] = "ok"
    with pytest.raises(dataclasses.FrozenInstanceError):
        hertz_result.E = None
    assert "15 ok" in str(hertz_result) and r"\tag{T.7}" in hertz_result.latex()


def test_csv_round_trips_and_files_are_never_replaced_unasked(hertz_result, tmp_path):
    from thinlayer.validation.output import OutputExistsError

    p = hertz_result.to_csv(tmp_path / "map.csv")
    rows = list(csv.DictReader(p.open()))
    assert len(rows) == 16
    for row in rows:
        i, j = int(row["row"]), int(row["column"])
        E = float(row["E_Pa"])
        assert (E == hertz_result.E[i, j]) or (math.isnan(E) and math.isnan(hertz_result.E[i, j]))
        assert row["status"] == hertz_result.status[i, j]
        assert float(row["x_um"]) == pytest.approx(j + 0.5)
    with pytest.raises(OutputExistsError):
        hertz_result.to_csv(p)
    hertz_result.to_csv(p, overwrite=True)
    with pytest.raises(InputError, match="quantity"):
        hertz_result.to_png(tmp_path / "x.png", quantity="nu")  # refused before matplotlib (the PNG: test_maps_cli)


def _record_H(curve, *, punch, H, nu, base):
    """A fitter that reports the thickness it was given (the per-pixel H plumbing, nothing fitted)."""
    return CurveFit(1.0, 0.0, H, 0.0, 0.0)


def test_substrate_level_is_robust_to_a_stray_low_pixel():
    topo = np.full((10, 10), 2e-6)
    topo[:3, :] = 1e-6                 # 30 % bare substrate at 1 um
    topo[5, 5] = -5e-6                 # one stray pixel far below
    assert substrate_level(topo) == 1e-6
    H, level = thickness_from_height(topo)
    assert level == 1e-6 and H[9, 9] == 1e-6 and H[0, 0] == 0.0
    assert thickness_from_height(topo, substrate=0.5e-6)[0][9, 9] == 1.5e-6


def test_per_pixel_thickness_from_a_height_image(hertz_map):
    topo = 1e-6 + 1e-7 * np.arange(16.0).reshape(4, 4)
    topo[0, 0] = 0.9e-6                               # the lowest pixel: the substrate, H <= 0 there
    r = fit_map(hertz_map, punch=R, H="height", height_image=topo, nu=NU, fit_one=_record_H, progress=False)
    level = substrate_level(topo)
    assert r.substrate == level == 0.9e-6
    want = topo - level
    np.testing.assert_array_equal(r.H[want > 0], want[want > 0])
    assert r.status[0, 0] == "failed" and "no layer here" in r.reasons[0, 0]


def test_per_pixel_thickness_from_the_maps_own_contact_heights(hertz_map):
    r = fit_map(hertz_map, punch=R, H="height", nu=NU, fit_one=_record_H, progress=False)
    # the substrate: the lowest contact height, pixel (0, 0) at 0 m, estimated where the force leaves 5 sigma of noise,
    # i.e. Hertz's depth (5 sigma / (4/3 E/(1-nu^2) sqrt R))^(2/3) = 6.3 nm below the true contact at E = 5 kPa
    assert -1.5e-8 < r.substrate <= 0.0
    ok = np.isfinite(r.H)
    assert ok.sum() == 14 and not ok[0, 3] and not ok[0, 0]  # (0, 3): no contact; (0, 0): the substrate, H <= 0
    np.testing.assert_allclose(r.H[ok], CONTACT[ok] - r.substrate, atol=1.5e-8)
    with pytest.raises(InputError, match="shape"):
        fit_map(hertz_map, punch=R, H="height", height_image=np.zeros((3, 4)), nu=NU, fit_one=_record_H,
                progress=False)


@pytest.mark.parametrize("kwargs, match", [
    ({"H": "thick"}, "'height'"),
    ({"H": -1.0}, "positive"),
    ({"H": np.ones((2, 2))}, "shape"),
    ({"nu": 0.7}, "nu"),
    ({"base": "glued"}, "base"),
    ({"scheduler": "nowhere"}, "scheduler"),
    ({"height_image": np.ones((4, 4))}, "H='height'"),
])
def test_bad_input_is_one_line(hertz_map, kwargs, match):
    args = {"punch": R, "H": None, "nu": NU, "progress": False, "fit_one": _record_H, **kwargs}
    with pytest.raises((InputError, TypeError), match=match) as exc:
        fit_map(hertz_map, **args)
    assert "\n" not in str(exc.value)


def test_a_missing_or_gridless_source_is_refused(tmp_path):
    with pytest.raises(InputError, match="no such file"):
        fit_map(tmp_path / "none.jpk-force-map", punch=R, nu=NU, progress=False)
    with pytest.raises(InputError, match="no curve file"):
        fit_map(tmp_path, punch=R, nu=NU, progress=False)


def test_a_pixel_outside_a_validity_limit_is_flagged_with_its_numbers(hertz_map):
    """delta/R = 0.2 um / 1.5 um = 0.13 > 0.1 (the paraboloid against the sphere): every contact pixel flagged, E
    kept.
    """
    r = fit_map(hertz_map, punch=1.5e-6, H=None, nu=NU, progress=False, fit_one=fit_curve_basic)
    flagged = r.status == "flagged"
    assert flagged.sum() == 15 and r.status[0, 3] == "failed"
    assert np.all(np.isfinite(r.E[flagged]))
    assert all("delta/R" in why for *_, why in r.flagged)
    assert "flagged: delta/R" in r.failures_text()


@pytest.mark.slow
def test_finite_thickness_map_with_flags(tmp_path):
    """Any thickness (T.7): E recovered on a 2 x 2 map of two thicknesses; delta/H = 0.2 is flagged, not hidden.
    Slow only by the law's first build (3 s CPU); the per-pixel H plumbing is tested by default with _record_H.
    """
    E = np.array([[4e3, 6e3], [5e3, 8e3]])
    H = np.array([[2e-6, 2e-6], [0.5e-6, 2e-6]])
    p = write_synthetic_map(tmp_path / "layer.h5", E, H, R=R, nu=NU, points=300, depth=0.1e-6, noise=1e-12)
    r = fit_map(p, punch=R, H=H, nu=NU, progress=False)
    np.testing.assert_allclose(r.E, E, rtol=5e-3)
    np.testing.assert_array_equal(r.H, H)
    assert r.status[1, 0] == "flagged" and "delta/H" in r.reasons[1, 0]
    assert (r.status == "ok").sum() == 3
    assert r.flagged[0][:2] == (1, 0)


JPK = "fmt-jpk-fd_map-data-reference-points.jpk-force-map"


def test_real_jpk_force_map(tmp_path):
    """afmformats' JPK map (spinal cord section, R = 18.64 um; nanite's tests/test_qmap.py): three curves on a 25 x 25
    grid.  nanite's own test fits them with its Sneddon sphere model (E = 57.6 Pa grey matter at pixel (4, 9),
    46.6 Pa white matter at (16, 16), 17.6 kPa background at (5, 20); a secondary source): the same order here.
    """
    from pathlib import Path

    path = Path(__file__).parent / "data" / JPK
    r = fit_map(path, punch=37.28e-6 / 2, H=None, nu=0.5, fit_one=fit_curve_basic, progress=False)
    assert r.shape == (25, 25) and r.counts()["empty"] == 622
    grey, white, background = r.E[4, 9], r.E[16, 16], r.E[5, 20]
    assert 20 < white < grey < 100, (grey, white)
    assert background > 100 * grey
    assert r.grid.extent_um == pytest.approx((-1409.765625, -909.765625, -1864.0625, -1364.0625))
    # delta/R ~ 0.25 on the soft tissue: flagged (the paraboloid against the sphere), the numbers kept
    assert r.status[4, 9] == "flagged" and "delta/R" in r.reasons[4, 9]
    assert isinstance(r.grid, MapGrid)
