"""The cases of the validation study (thinlayer.validation.cases): the elliptic case and the input checks.

The expected values are the paper's claims ((1.8), (3.25)); the 2D error estimate is checked against
the independent axisymmetric solver.
"""
from __future__ import annotations

import math

import pytest

from thinlayer import BondedLayer, Punch
from thinlayer.numerics import solve_2d, solve_axisymmetric
from thinlayer.validation import (
    check_nu,
    check_nus,
    check_ratio,
    check_ratios,
    check_shapes,
    elliptic_grid,
    validate_elliptic,
    validate_sphere,
    validation_study,
)


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




def test_public_checks():
    assert check_nu(0.3) == 0.3 and isinstance(check_nu(0), float)
    assert check_nus([0.3, 0.2, 0.3]) == (0.3, 0.2)
    assert check_ratio(0.2) == 0.2 and check_ratios(0.1) == (0.1,)
    assert check_shapes("sphere") == ("sphere",)
    with pytest.raises(ValueError, match="admissible range"):
        check_nus([0.3, 0.5], "nu")
    with pytest.raises(ValueError, match=r"outside the validated range \[0.0125, 0.2\]"):
        check_ratios([0.1, 0.3], "H_over_a")
    with pytest.raises(ValueError, match="unknown shape 'cube'"):
        check_shapes(["sphere", "cube"])
    with pytest.raises(ValueError, match="empty"):
        check_shapes(())
