"""The fast map fitter (issue 25 item 5): the force-only path of the any-thickness law, ``fit_curve(solver="varpro")``
against the reference ``solver="lm"``, and the map's validity flags.

Independent references: the law's full evaluation (``ForceCurve.force`` and ``slopes``, which also compute the contact
radius and the error estimate) for the force-only path, bit for bit; the Levenberg-Marquardt fit of the same least
squares (``solver="lm"``, the fitter tests/afm/test_curves.py holds against nanite) for variable projection.  The
synthetic curves are Hertz written out and the law (T.7) of thinlayer.afm.map_data.synthetic_curve; the real curve is
afmformats' JPK example (tests/afm/data).
"""
from __future__ import annotations

import functools
import math
import pickle
import warnings
from pathlib import Path

import numpy as np
import pytest

from thinlayer.afm.curve_fit import fit_curve
from thinlayer.afm.curves import curve_from_arrays
from thinlayer.afm.map_data import MapCurve, synthetic_curve
from thinlayer.afm.maps import fit_curve_full, fit_map
from thinlayer.contact import any_thickness as at
from thinlayer.contact.models import any_thickness as models_at
from thinlayer.contact.models.any_thickness import SphereCurve, sphere_curve
from thinlayer.errors import InputTypeError, ValidityWarning

pytestmark = pytest.mark.xdist_group("afm-laws")  # one worker builds the laws once for the afm tests
R = 5e-6
SPOT = Path(__file__).resolve().parent / "data" / "fmt-jpk-fd_spot3-0192.jpk-force"
#: |varpro - lm| / (lm's standard error) allowed (issue 25's brief: SE/100).  Measured: at most 2.2e-5 on the
#: benchmark's curves, 1.2e-3 on the map's pixel (1, 2) below, where Levenberg-Marquardt stops early along the E-z0
#: valley (its residual sum of squares 2.136960546e-21, variable projection's 2.136960536e-21: lower)
TOL_SE = 1e-2


# ---- the force-only path ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("R_, H", [(5e-6, 2e-6), (1.0, 1e-120), (1.0, 1e120), (1e50, 1e-100)])
def test_force_only_path_equals_the_full_evaluation_bit_for_bit(R_, H):
    """SphereCurve.force_slopes against force() and slopes() of the same curve, over chi from the thick series through
    the table to the thin limit and beyond the double range (NaN where the force is not a positive double, both)."""
    c = sphere_curve("any-thickness", R_, H, 0.5, "bonded", math.inf)
    assert isinstance(c, SphereCurve)
    for d in (np.geomspace(1e-249 / R_, 1e249 / R_, 801), np.linspace(1e-9, 1.5e-7, 777), np.array([2e-7])):
        P, gd, gH = c.force_slopes(d)
        assert np.array_equal(P, c.force(d), equal_nan=True)
        gd0, gH0 = c.slopes(d)
        assert np.array_equal(gd, gd0) and np.array_equal(gH, gH0)
        assert np.array_equal(c.force_slopes(d, slopes=False)[0], P, equal_nan=True)
    P = c.force_slopes(np.geomspace(1e-249 / R_, 1e249 / R_, 801))[0]
    assert np.isfinite(P).sum() > 200  # the comparison covers finite forces, not only NaN


def test_force_only_path_falls_back_outside_its_range_and_with_a_tolerance():
    c = sphere_curve("any-thickness", 1.0, 1.0, 0.5, "bonded", math.inf)
    d = np.geomspace(1e-300, 1e300, 601)  # R delta beyond 1e+-250: the area is computed to mask the force
    assert np.array_equal(c.force_slopes(d)[0], c.force(d), equal_nan=True)
    tol = sphere_curve("any-thickness", 1.0, 1.0, 0.5, "bonded", 1e-4)  # a finite tol: the estimate decides
    d = np.geomspace(1e-6, 1e6, 301)
    assert np.array_equal(tol.force_slopes(d)[0], tol.force(d), equal_nan=True)
    assert np.isnan(tol.force(d)).any() and np.isfinite(tol.force(d)).any()


def test_the_fit_shape_equals_the_laws_shape_bit_for_bit():
    """fit_curve's law evaluates the contact points only, through the force-only path: the law's own shape()."""
    from thinlayer.afm.curve_fit import _fit_law
    from thinlayer.contact.fit import fit_law

    mine, ref = _fit_law(R, 2e-6, 0.5, "bonded", None), fit_law(R, 2e-6, 0.5, "bonded", None)
    delta = np.linspace(-2e-7, 3e-7, 1001)  # before and after contact
    for H in (2e-6, 0.3e-6):
        for slopes in (False, True):
            a, b = mine.shape(delta, H, slopes), ref.shape(delta, H, slopes)
            for u, v in zip(a, b):
                assert (u is None and v is None) or np.array_equal(u, v)


# ---- variable projection against Levenberg-Marquardt -------------------------------------------------------------
def _close(a, b, keys=("E", "z0", "b0")):
    for k in keys:
        se = getattr(b, f"{k}_se")
        assert se > 0 and abs(getattr(a, k) - getattr(b, k)) <= TOL_SE * se, (k, getattr(a, k), getattr(b, k), se)
    for k in ("E_se", "z0_se", "b0_se"):
        assert getattr(a, k) == pytest.approx(getattr(b, k), rel=1e-3)
    assert (a.valid, a.flags, a.fitted, a.n_points) == (b.valid, b.flags, b.fitted, b.n_points)


@pytest.mark.parametrize("E, H, contact, slope, baseline", [
    (3e3, math.inf, 0.0, 0.0, "offset"),
    (8e3, math.inf, 0.2e-6, 2e-4, "offset+slope"),
    (5e3, 2e-6, -0.1e-6, 0.0, "offset"),
    (1.2e4, 2e-6, 0.25e-6, -1e-4, "offset+slope"),
    (4e3, 0.5e-6, 0.0, 0.0, "offset"),               # delta/H = 0.3: flagged, by both
])
def test_varpro_equals_lm_on_synthetic_curves(E, H, contact, slope, baseline):
    z, F = synthetic_curve(E, H, R=R, points=2000, depth=0.15e-6, contact=contact, noise=2e-12, slope=slope,
                           offset=3e-11, rng=np.random.default_rng(7))
    c = curve_from_arrays(z, F, axis="tip position")
    Hs = None if math.isinf(H) else H
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)  # delta/H = 0.3: flagged in the result, compared below
        ref = fit_curve(c, punch=R, H=Hs, baseline=baseline)
        a = fit_curve(c, punch=R, H=Hs, baseline=baseline, solver="varpro")
    _close(a, ref, ("E", "z0", "b0") + (("b1",) if baseline != "offset" else ()))
    assert abs(a.E / E - 1) < 0.01  # and both near the truth
    if H == 0.5e-6:
        assert any("delta/H" in f for f in a.flags)


def test_varpro_equals_lm_with_the_contact_point_given():
    z, F = synthetic_curve(6e3, 2e-6, R=R, points=600, depth=0.15e-6, noise=2e-12, rng=np.random.default_rng(3))
    c = curve_from_arrays(z, F, axis="tip position")
    ref = fit_curve(c, punch=R, H=2e-6, contact_point=1e-9)
    a = fit_curve(c, punch=R, H=2e-6, contact_point=1e-9, solver="varpro")
    _close(a, ref, ("E", "b0"))
    assert a.z0 == ref.z0 == 1e-9 and a.fitted == ("E", "b0")


def test_varpro_equals_lm_on_the_real_jpk_curve():
    """afmformats' JPK curve (2,000 approach points, R = 10 um; E = 14,742 Pa unweighted, tests/afm/test_curves.py):
    the half-space and a layer H = 2 um."""
    pytest.importorskip("afmformats")
    from thinlayer.afm.curves import load_curve

    spot = load_curve(SPOT)
    for H in (None, 2e-6):
        ref = fit_curve(spot, punch=10e-6, H=H)
        a = fit_curve(spot, punch=10e-6, H=H, solver="varpro")
        _close(a, ref)
        if H is None:
            assert a.E == pytest.approx(14742, rel=1e-3)


def test_varpro_leaves_weighted_and_thickness_fits_to_lm():
    """Nanite's moving weights and a fitted H are not variable projection's: the same answer as solver='lm'."""
    z, F = synthetic_curve(5e3, 1e-6, R=R, points=300, depth=0.15e-6, noise=2e-12, rng=np.random.default_rng(5))
    c = curve_from_arrays(z, F, axis="tip position")
    for kw in ({"weighting": "nanite", "H": 1e-6}, {"fit_H": True, "H": 2e-6}):
        a, b = fit_curve(c, punch=R, solver="varpro", **kw), fit_curve(c, punch=R, **kw)
        assert (a.E, a.z0, a.H) == (b.E, b.z0, b.H)


# ---- the map -------------------------------------------------------------------------------------------------------
def _map_curves():
    """3 x 3 pixels: the half-space on a layer's top (R = 5 um), a thin layer (delta/H flagged), nothing to indent."""
    rng = np.random.default_rng(11)
    E = [[3e3, 6e3, 9e3], [4e3, 0.0, 7e3], [5e3, 8e3, 1.1e4]]
    H = [[2e-6, 2e-6, 0.5e-6], [2e-6, 2e-6, 2e-6], [0.5e-6, 2e-6, 2e-6]]
    curves = [MapCurve((i, j), *synthetic_curve(E[i][j], H[i][j], R=R, points=300, depth=0.15e-6,
                                                contact=1e-8 * (i - j), noise=2e-12, rng=rng), name=f"c{i}{j}")
              for i in range(3) for j in range(3)]
    return curves, np.array(H)


def test_map_validity_flags_unchanged_by_the_fast_fitter():
    curves, H = _map_curves()
    fast = fit_map(curves, punch=R, H=H, progress=False)
    ref = fit_map(curves, punch=R, H=H, progress=False, fit_one=functools.partial(fit_curve_full, solver="lm"))
    assert fast.fitter == "fit_curve_full"
    assert np.array_equal(fast.status, ref.status) and np.array_equal(fast.reasons, ref.reasons)
    assert fast.counts() == {"ok": 6, "flagged": 2, "failed": 1, "empty": 0}
    assert all("delta/H" in why for *_, why in fast.flagged)
    ok = np.isfinite(ref.E)
    assert np.all(np.abs(fast.E[ok] - ref.E[ok]) <= TOL_SE * ref.E_se[ok])
    assert np.all(np.abs(fast.contact_point[ok] - ref.contact_point[ok]) <= 1e-12)


# ---- the law sent to dask workers ------------------------------------------------------------------------------------
def test_a_worker_adopts_the_law_its_parent_sent(monkeypatch):
    law = at.any_thickness_law(0.5, "bonded")
    sent = pickle.loads(pickle.dumps(law))
    for k in ("log_force", "log_radius", "dlog_force", "est_force", "est_radius", "series", "series_radius"):
        assert np.array_equal(getattr(sent, k), getattr(law, k))
    monkeypatch.setattr(at, "ADOPTED_LAWS", {})
    monkeypatch.setattr(models_at, "ADOPTED_LAWS", at.ADOPTED_LAWS)
    models_at.adopt_law(sent)
    assert at.any_thickness_law(0.5, "bonded") is sent
    with pytest.raises(InputTypeError, match="AnyThicknessLaw"):
        models_at.adopt_law("not a law")


def test_local_clusters_start_as_dask_says_unless_asked(monkeypatch):
    """dask's configured start method when it is not dask's default, else forkserver where the platform has it."""
    import multiprocessing

    from thinlayer.afm.distributed import start_method

    monkeypatch.delenv("THINLAYER_DASK_START", raising=False)
    dask = pytest.importorskip("dask")
    pytest.importorskip("distributed")  # its defaults in dask's config
    configured = dask.config.get("distributed.worker.multiprocessing-method", "spawn")
    has_forkserver = "forkserver" in multiprocessing.get_all_start_methods()
    assert start_method() == (configured if configured != "spawn" else "forkserver" if has_forkserver else "spawn")
    with dask.config.set({"distributed.worker.multiprocessing-method": "fork"}):
        assert start_method() == "fork"
    monkeypatch.setenv("THINLAYER_DASK_START", "fork")
    assert start_method() == "fork"
    monkeypatch.setenv("THINLAYER_DASK_START", "spawn")
    with dask.config.set({"distributed.worker.multiprocessing-method": "forkserver"}):
        assert start_method() == "spawn"


def test_auto_scheduler_is_a_local_cluster_for_a_large_map_only():
    from thinlayer.afm.distributed import AUTO_BATCH, auto_scheduler, check_scheduler

    assert check_scheduler("auto") == "auto" and auto_scheduler(AUTO_BATCH - 1) is None
    pytest.importorskip("distributed")
    import os

    assert auto_scheduler(AUTO_BATCH) == ("local" if len(os.sched_getaffinity(0)) > 1 else None)
