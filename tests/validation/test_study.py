"""Validation study (issue 4, items 3-6): asymptotics against the independent direct solvers.

The expected values here are the paper's claims (orders of the remainders, (1.8) and (3.25)), the
exact h^* against Alexandrov's, and textbook formulas (Hertz); never numbers taken from a run of
the engine.  The full study (every nu, nine H/a, the 2D elliptic case everywhere) is ``slow``.
"""
from __future__ import annotations

import argparse
import dataclasses
import json
import math
import sys

import numpy as np
import pytest

from thinlayer import BondedLayer, FrictionlessLayer, Punch, solve
from thinlayer.numerics import solve_2d, solve_axisymmetric
from thinlayer.validation.study import (
    CLAIMED_ORDERS,
    StudyEvent,
    ValidationStudy,
    add_cli,
    elliptic_grid,
    speed_comparison,
    validate_elliptic,
    validate_sphere,
    validation_study,
)

SMALL_NUS = (0.3, 0.45)
SMALL_RATIOS = (0.1, 0.05, 0.025, 0.0125)


@pytest.fixture(scope="module")
def small_study() -> ValidationStudy:
    """Sphere, nu in {0.3, 0.45}, H/a = 0.1 ... 0.0125 (axisymmetric numerics, ~8 s)."""
    return validation_study(nus=SMALL_NUS, ratios=SMALL_RATIOS, shapes=("sphere",), progress=False)


def _fit(study, shape, nu, quantity):
    (f,) = [f for f in study.observed_orders() if (f.shape, f.nu, f.quantity) == (shape, nu, quantity)]
    return f


# ---------------------------------------------------------------------------------------------
# observed orders against the claimed ones
# ---------------------------------------------------------------------------------------------
def test_small_study_has_every_case(small_study):
    got = {(r.nu, round(r.H_over_a, 12)) for r in small_study.rows}
    assert got == {(nu, eps) for nu in SMALL_NUS for eps in SMALL_RATIOS}
    assert not small_study.interrupted and not small_study.skipped
    for r in small_study.rows:
        # the spectral solver is converged far below every asymptotic error measured
        assert r.force_numeric_error < 1e-9 and r.area_numeric_error < 1e-8
        assert all(r.resolved(q) for q in CLAIMED_ORDERS)
        # the contact area of the disc is pi c^2 (Hertz-like radius from the same run)
        assert r.area_numeric == pytest.approx(math.pi * r.semi_axes_numeric[0] ** 2, rel=1e-14)


@pytest.mark.parametrize("nu", SMALL_NUS)
def test_force_remainder_is_third_order(small_study, nu):
    # (1.8): P = P_0 + P_1 + O(P_0 (H/a)^3)
    fit = _fit(small_study, "sphere", nu, "force")
    assert fit.points == len(SMALL_RATIOS)
    assert 2.6 <= fit.observed <= 3.4
    assert fit.matches


@pytest.mark.parametrize("nu", SMALL_NUS)
def test_area_remainder_is_second_order(small_study, nu):
    # (3.25): |omega| = |omega_0| - h^* H |Gamma_0| + O(|omega_0| (H/a)^2)
    fit = _fit(small_study, "sphere", nu, "contact_area")
    assert 1.6 <= fit.observed <= 2.4
    assert fit.matches


@pytest.mark.parametrize("nu", SMALL_NUS)
def test_composite_pressure_within_its_bound(small_study, nu):
    # composite pressure: O(p_max H/a) uniformly -- a bound, so the slope is at least 1
    fit = _fit(small_study, "sphere", nu, "pressure")
    assert fit.observed >= 1.0
    for r in small_study.rows:
        if r.nu == nu:
            assert r.pressure_error < 1.0 * r.H_over_a  # |p_c - p| <= C p_max H/a with C = 1


@pytest.mark.parametrize("nu", SMALL_NUS)
def test_first_corrections_matter(small_study, nu):
    # without P_1 the force error is O((H/a)^2); without the edge shift the area error is O(H/a)
    assert 1.6 <= _fit(small_study, "sphere", nu, "force_leading").observed <= 2.4
    assert 0.4 <= _fit(small_study, "sphere", nu, "contact_area_leading").observed <= 1.4
    # in the asymptotic range (at nu = 0.45, near incompressibility, m_1 is large and H/a = 0.1 is
    # still pre-asymptotic: there the corrected errors are only 2-3 times smaller)
    for r in small_study.rows:
        if r.nu == nu and r.H_over_a <= 0.05:
            assert abs(r.force_error) < abs(r.force_leading_error) / 3
            assert abs(r.area_error) < abs(r.area_leading_error) / 3


# ---------------------------------------------------------------------------------------------
# the edge shift h^* (3.25) from the contact radius of the numerics
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("nu", SMALL_NUS)
def test_edge_shift_confirmed_by_numerics(small_study, nu):
    (check,) = [c for c in small_study.edge_shift_checks() if c.nu == nu]
    assert check.ratios == (0.0125, 0.025, 0.05)  # the smallest three ratios
    # Tolerance 1e-3: the Richardson extrapolation (quadratic through three ratios a factor 2 apart)
    # leaves a remainder ~ c3 * 0.0125 * 0.025 * 0.05, and its estimate (quadratic minus linear
    # extrapolation) is below 1e-3 here; 1e-3 is still 20 times smaller than |h*_exact - h*_Alexandrov|
    # (>= 0.023 at these nu), so the check separates the two edge shifts.
    assert check.error_estimate < 1e-3
    assert abs(check.extrapolated - check.exact) < 1e-3
    assert abs(check.extrapolated - check.alexandrov) > 0.02
    assert abs(check.exact - check.alexandrov) > 20 * 1e-3
    assert check.confirms_exact and check.rejects_alexandrov and check.status == "ok"
    # the raw values approach h^* monotonically from one side (correction linear in H/a)
    d = np.array(check.h_numeric) - check.exact
    assert np.all(np.sign(d) == np.sign(d[0])) and np.all(np.abs(d[:-1]) < np.abs(d[1:]))


def test_study_passes_and_tables(small_study):
    assert small_study.passed
    text = small_study.table()
    assert "observed order" in text and "edge shift" in text and "MISMATCH" not in text
    tex = small_study.latex()
    assert tex.count(r"\begin{tabular}") == 3 and tex.count(r"\end{tabular}") == 3
    assert tex.count(r"\\") >= len(small_study.rows)
    d = json.loads(small_study.to_json())
    assert len(d["rows"]) == len(small_study.rows) and d["passed"] is True
    row = d["rows"][0]
    assert row["force_error"] == pytest.approx(small_study.rows[0].force_error)
    assert {"shape", "nu", "H_over_a", "force_numeric", "force_asymptotic", "edge_shift_numeric",
            "pressure_error", "resolved"} <= set(row)


def test_results_are_frozen(small_study):
    row = small_study.rows[0]
    with pytest.raises(dataclasses.FrozenInstanceError):
        row.force_numeric = 1.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        small_study.rows = ()
    with pytest.raises(TypeError):
        small_study.settings["nus"] = [0.1]
    prof = small_study.profiles[0]
    with pytest.raises(ValueError):
        prof.numeric[0] = 1.0


# ---------------------------------------------------------------------------------------------
# the elliptic paraboloid R1/R2 = 4 against the 2D FFT solver
# ---------------------------------------------------------------------------------------------
def test_elliptic_case_against_2d_numerics():
    study = validate_elliptic(0.3, (0.1,))
    (r,) = study.rows
    n, nc, _ = elliptic_grid(0.1)
    assert f"n={n}" in r.solver and f"n={nc}" in r.solver
    assert r.H_over_a == pytest.approx(0.1)
    # the 2D error estimate (two grids, order 2) is well below the asymptotic error being measured
    assert r.force_numeric_error < abs(r.force_error) / 10
    # remainder of (1.8): |err| <= C (H/a)^3 with a constant of order one (C = 2)
    assert abs(r.force_error) < 2 * 0.1**3
    # without P_1 the error is larger: P_1 is a genuine correction for the ellipse too
    assert abs(r.force_leading_error) > 2 * abs(r.force_error)
    # area: |omega_0| - h^* H |Gamma_0| is within O((H/a)^2), |omega_0| alone is not
    assert abs(r.area_error) < 0.1**2
    assert abs(r.area_leading_error) > 10 * abs(r.area_error)
    # the contact semi-axes sit at a_i - h^* H, not at a_i (2D contour error ~0.15 cell = 0.02 H)
    for s, s_asym, s0 in zip(r.semi_axes_numeric, r.semi_axes_asymptotic, r.semi_axes_leading):
        assert abs(s - s_asym) < 0.05 * r.H
        assert s0 - s > 0.5 * r.edge_shift_exact * r.H
    assert r.pressure_error < 0.1  # O(p_max H/a)
    assert study.contours[0].numeric and study.profiles[0].axis == "x1"


def test_2d_error_estimate_is_honest_on_the_sphere():
    # The elliptic rows estimate the 2D force error from two grids (H/8 and H/5 cells).  On the sphere the
    # axisymmetric solver gives the true error: the estimate from the same pair of resolutions must match it.
    layer, punch, H = BondedLayer(0.3), Punch.paraboloid(R=1.0), 0.1
    ref = solve_axisymmetric(layer, punch, 0.5, H)
    W = 1.01 + 2 * H
    n, nc = 16 * math.ceil(2 * W * 8 / H / 16), 16 * math.ceil(2 * W * 5 / H / 16)
    fine = solve_2d(layer, punch, delta0=0.5, H=H, n=n, extent=W)
    coarse = solve_2d(layer, punch, delta0=0.5, H=H, n=nc, extent=W)
    est = abs(fine.force - coarse.force) / fine.force
    true = abs(fine.force / ref.force - 1)
    assert 0.5 * est < true < 1.5 * est  # the estimate is of the right size ...
    assert true < 1e-4  # ... and both are far below the asymptotic force error (6e-4 here)


# ---------------------------------------------------------------------------------------------
# plots, progress, interruption
# ---------------------------------------------------------------------------------------------
def test_plots_written(small_study, tmp_path):
    pytest.importorskip("matplotlib", reason="matplotlib (the optional 'plot' extra) is not installed")
    files = small_study.write(tmp_path / "out", plots=True)
    names = {f.name for f in files}
    for stem in ("validation_errors", "validation_pressure", "validation_contours", "validation_edge_shift"):
        assert {f"{stem}.png", f"{stem}.pdf"} <= names
    for f in files:
        assert f.stat().st_size > 0
        head = f.read_bytes()[:8]
        if f.suffix == ".png":
            assert head == b"\x89PNG\r\n\x1a\n"
        elif f.suffix == ".pdf":
            assert head.startswith(b"%PDF")
    assert json.loads((tmp_path / "out" / "validation.json").read_text())["rows"]


def test_plots_without_matplotlib_name_the_extra(small_study, tmp_path, monkeypatch):
    for mod in ("matplotlib", "matplotlib.figure", "matplotlib.backends.backend_agg"):
        monkeypatch.setitem(sys.modules, mod, None)  # import raises ImportError
    with pytest.raises(ImportError, match=r"thinlayer\[plot\]"):
        small_study.plots(tmp_path)
    assert not any(tmp_path.iterdir())


def test_progress_lines_on_stderr(capsys):
    validate_sphere(0.3, (0.1, 0.05), progress=True)
    err = capsys.readouterr().err
    assert "validate: [1/2] sphere nu=0.3 H/a=0.1" in err and "[2/2]" in err


def test_progress_bar_with_tqdm_on_a_terminal(monkeypatch):
    import io
    import types

    from thinlayer.validation.study import _Progress

    calls = []

    class FakeTqdm:
        def __init__(self, total, file, unit, desc):
            calls.append(("init", total))

        def set_postfix_str(self, s):
            calls.append(("label", s))

        def update(self, k):
            calls.append(("update", k))

        def close(self):
            calls.append(("close",))

    class Tty(io.StringIO):
        def isatty(self):
            return True

    monkeypatch.setitem(sys.modules, "tqdm", types.SimpleNamespace(tqdm=FakeTqdm))
    stream = Tty()
    prog = _Progress(True, 2, stream)
    prog.start(0, "sphere nu=0.3 H/a=0.1", False)
    prog.done(0, "sphere nu=0.3 H/a=0.1", 0.1)
    prog.close(False, 1)
    assert calls == [("init", 2), ("label", "sphere nu=0.3 H/a=0.1"), ("update", 1), ("close",)]
    assert stream.getvalue() == ""  # the bar replaces the lines
    # not a terminal: plain lines, no bar
    plain = io.StringIO()
    prog = _Progress(True, 2, plain)
    prog.done(0, "x", 0.1)
    assert prog.bar is None and plain.getvalue().startswith("validate: [1/2] x")


@pytest.mark.parametrize("stage, at, done", [("start", 2, 2), ("done", 0, 1)])
def test_keyboard_interrupt_keeps_rows(stage, at, done, tmp_path):
    events: list[StudyEvent] = []

    def hook(ev: StudyEvent):
        events.append(ev)
        if ev.stage == stage and ev.index == at:
            raise KeyboardInterrupt

    study = validate_sphere(0.3, (0.2, 0.1, 0.05), callback=hook)
    assert study.interrupted
    assert len(study.rows) == done
    assert [r.H_over_a for r in study.rows] == pytest.approx([0.2, 0.1][:done])
    assert [p[2] for p in study.pending] == pytest.approx([0.2, 0.1, 0.05][done:])
    assert events[0].stage == "start" and events[0].total == 3
    assert "INTERRUPTED" in study.table()
    files = study.write(tmp_path)  # the rows done are saved
    d = json.loads(files[-1].read_text())
    assert d["interrupted"] is True and len(d["rows"]) == done


def test_other_callback_errors_propagate():
    def hook(ev):
        raise RuntimeError("boom")

    with pytest.raises(RuntimeError, match="boom"):
        validate_sphere(0.3, (0.1,), callback=hook)


# ---------------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("ratios", [(0.3,), (0.01,), (0.1, 0.5), (-0.1,)])
def test_ratio_out_of_range(ratios):
    with pytest.raises(ValueError, match=r"outside the validated range \[0.0125, 0.2\]"):
        validation_study(nus=(0.3,), ratios=ratios, shapes=("sphere",), progress=False)


@pytest.mark.parametrize("nu", [0.5, -1.0, 0.7])
def test_nu_out_of_range(nu):
    with pytest.raises(ValueError, match="admissible range"):
        validate_sphere(nu, (0.1,))


def test_bad_types_and_names():
    with pytest.raises(ValueError, match="unknown shape 'cube'"):
        validation_study(shapes=("sphere", "cube"), progress=False)
    with pytest.raises(TypeError, match="nu must be a real number"):
        validate_sphere("0.3", (0.1,))
    with pytest.raises(TypeError, match="H/a must be a real number"):
        validate_sphere(0.3, ("a",))
    with pytest.raises(ValueError, match="empty"):
        validate_sphere(0.3, ())
    with pytest.raises(ValueError, match="cells_per_H"):
        validate_elliptic(0.3, (0.1,), cells_per_H=4)
    with pytest.raises(ValueError, match="max_n"):
        validate_elliptic(0.3, (0.1,), max_n=0)
    with pytest.raises(ValueError, match="unknown quantity"):
        ValidationStudy(()).observed_orders(("stiffness",))


def test_grid_too_large_is_skipped_with_reason():
    study = validate_elliptic(0.3, (0.0125,), max_n=512)
    assert not study.rows
    ((shape, nu, eps, why),) = study.skipped
    assert (shape, nu, eps) == ("elliptic", 0.3, 0.0125) and "max_n = 512" in why
    assert "skipped" in study.table()


# ---------------------------------------------------------------------------------------------
# the command
# ---------------------------------------------------------------------------------------------
def _parser():
    ap = argparse.ArgumentParser(prog="thinlayer")
    sub = ap.add_subparsers(dest="cmd", required=True)
    add_cli(sub, argparse.RawDescriptionHelpFormatter)
    return ap


def test_cli_writes_files_and_json(tmp_path, capsys):
    args = _parser().parse_args(["validate", "--shapes", "sphere", "--nu", "0.3", "--ratios", "0.1,0.05,0.025",
                                 "--out", str(tmp_path), "--json", "--quiet"])
    assert args.func(args) == 0
    out = json.loads(capsys.readouterr().out)
    assert [r["H_over_a"] for r in out["rows"]] == pytest.approx([0.1, 0.05, 0.025])
    assert {p.name for p in tmp_path.iterdir()} == {"validation.txt", "validation.tex", "validation.json"}


def test_cli_bad_input():
    ap = _parser()
    for argv, msg in ((["validate", "--plots"], "--plots needs --out"),
                      (["validate", "--nu", "0.3,x"], "'x' is not a number"),
                      (["validate", "--ratios", "0.9", "--quiet"], "validated range")):
        args = ap.parse_args(argv)
        with pytest.raises(ValueError, match=msg):
            args.func(args)


def test_speed_comparison_reaches_equal_accuracy():
    sc = speed_comparison(0.3, 0.1, repeat=1)
    assert sc.fft2d_n is not None and sc.fft2d_error <= sc.asymptotic_error
    assert sc.axisymmetric_modes is not None and sc.axisymmetric_error <= sc.asymptotic_error
    assert sc.seconds_solve > 0 and sc.seconds_force_law > 0 and sc.ratio_fft2d > 0


# ---------------------------------------------------------------------------------------------
# contactmechanics (optional): its PeriodicFFTElasticHalfSpace(thickness=H, poisson=nu)
# ---------------------------------------------------------------------------------------------
def _cm():
    return pytest.importorskip(
        "ContactMechanics",
        reason="the optional package contactmechanics is not installed (pip install contactmechanics); "
               "the comparison with its finite-thickness FFT solver is skipped")


def _cm_solve(substrate_cls, n, L, R, delta0, **kw):
    """Sphere on a contactmechanics substrate: force P (its heights are -Phi, offset delta0)."""
    from ContactMechanics.Optimization import constrained_conjugate_gradients

    dx = L / n
    x = (np.arange(n) - (n / 2 - 0.5)) * dx
    X, Y = np.meshgrid(x, x, indexing="ij")
    sub = substrate_cls((n, n), physical_sizes=(L, L), **kw)
    res = constrained_conjugate_gradients(sub, -(X**2 + Y**2) / (2 * R), offset=delta0, pentol=1e-10 * delta0,
                                          forcetol=1e-12, thermotol=1e-12, maxiter=5000)
    assert res.success, res.message
    return float(np.sum(res.jac))  # compressive point forces are positive in .jac


def test_contactmechanics_normalisation_hertz():
    # contactmechanics' "young" of the free half-space is the contact modulus E* = E/(1 - nu^2)
    # (Johnson); Hertz: P = (4/3) E* a^3/R, a^2 = R delta0.  This pins its convention, independently of thinlayer.
    CM = _cm()
    mu, nu, R, d0 = 1.0, 0.3, 1.0, 0.01
    Estar = 2 * mu / (1 - nu)  # = E/(1 - nu^2) with E = 2 mu (1 + nu)
    a = math.sqrt(R * d0)
    P = _cm_solve(lambda shape, physical_sizes: CM.FreeFFTElasticHalfSpace(shape, Estar, physical_sizes),
                  128, 2.5 * a, R, d0)
    assert P == pytest.approx(4 / 3 * Estar * a**3 / R, rel=1e-3)


def test_contactmechanics_thick_bonded_layer():
    # H = 2a: contactmechanics' layer on a rigid flat (Young's modulus E = 2 mu (1 + nu)) against the
    # axisymmetric solver of thinlayer -- and not the frictionless base, nor the half-space
    CM = _cm()
    nu, R, d0, H = 0.3, 1.0, 0.5, 2.0
    P = _cm_solve(lambda shape, physical_sizes: CM.PeriodicFFTElasticHalfSpace(
        shape, 2 * (1 + nu), physical_sizes, thickness=H, poisson=nu), 256, 24.0, R, d0)
    bonded = solve_axisymmetric(BondedLayer(nu), Punch.paraboloid(R=R), d0, H).force
    frictionless = solve_axisymmetric(FrictionlessLayer(), Punch.paraboloid(R=R), d0, H, nu=nu).force
    hertz = 4 / 3 * (2 / (1 - nu)) * math.sqrt(R * d0) ** 3 / R
    assert P == pytest.approx(bonded, rel=3e-3)  # 2D discretisation, Delta = a/10.7
    assert abs(frictionless / bonded - 1) > 0.05 and abs(hertz / bonded - 1) > 0.3


def test_contactmechanics_thin_layer_against_asymptotics():
    # H/a = 0.1, the benchmark problem at 256^2 on the same grid as solve_2d's default square
    CM = _cm()
    nu, R, H, d0 = 0.3, 1000.0, 1.0, 0.05
    layer, punch = BondedLayer(nu), Punch.paraboloid(R=R)
    ours = solve_2d(layer, punch, delta0=d0, H=H, n=256)
    L = ours.spacing * ours.n
    P_cm = _cm_solve(lambda shape, physical_sizes: CM.PeriodicFFTElasticHalfSpace(
        shape, 2 * (1 + nu), physical_sizes, thickness=H, poisson=nu), 256, L, R, d0)
    ref = solve_axisymmetric(layer, punch, d0, H).force
    asym = solve(layer, punch, delta0=d0, H=H).force
    assert P_cm == pytest.approx(ref, rel=5e-5)
    assert P_cm == pytest.approx(ours.force, rel=5e-5)
    # the asymptotic force differs from contactmechanics by its own remainder, O((H/a)^3) = O(1e-3)
    assert abs(asym / P_cm - 1) < 0.1**3
    assert asym / P_cm - 1 == pytest.approx(asym / ref - 1, abs=5e-5)


# ---------------------------------------------------------------------------------------------
# the full study
# ---------------------------------------------------------------------------------------------
@pytest.mark.slow
def test_full_study():
    study = validation_study(full=True, progress=True)
    assert not study.interrupted
    assert len({r.nu for r in study.rows}) == 5
    fits = [f for f in study.observed_orders(("force", "contact_area", "pressure")) if f.observed is not None]
    assert fits and all(f.matches for f in fits), [f for f in fits if not f.matches]
    checks = study.edge_shift_checks()
    assert len(checks) == 5 and all(c.status == "ok" for c in checks)
    assert {r.shape for r in study.rows} == {"sphere", "elliptic"}
