"""Acceptance grid of the front door (issue 13): :func:`thinlayer.solve` against the direct solver.

Every cell of {bonded nu = 0, 0.3, 0.45, 0.49, 0.5; frictionless base} x {sphere, elliptic paraboloid
R1/R2 = 4, a non-symmetric quartic} x {H/a = 0.05, 0.2, 0.5}: ``solve(model="auto")`` is compared with the
direct solver run independently on the same problem (:meth:`Indentation.compare_direct`: the axisymmetric
spectral solver for the sphere, the 2D FFT solver otherwise; 1.4 times the modes or cells when the answer
itself is direct).  The relative difference of the force, the contact area and (sphere) the contact radius
must lie inside the estimate that solve() states, plus the reference's own estimate.  The model that
``"auto"`` chooses is checked in each test against the one found by another route (``model="asymptotic"``, which
refuses exactly where ``"auto"`` goes on to the any-thickness law (T.7), then to the direct solver).  That route
runs inside the test, not at collection: at collection it ran once per xdist worker, before any test.

Six cells are validation at resolution and run only with ``THINLAYER_SLOW=1`` (:data:`SLOW_CELLS`): the elliptic
paraboloid and the quartic at H/a = 0.05 for nu = 1/2 and 0.49 (direct answers whose independent check needs 768^2
to 1080^2 cells: 18 s CPU for the two nu = 0.49 cells, half of the default run's time) and for nu = 0.45 (the
two-dimensional compressible answer at 2.4 s each).  The default run keeps the same assertions for the same punches
(issue 28 item 7, a five-minute suite): on the direct solver for nu = 0.45, 0.49 and 1/2 at H/a = 0.2 and 0.5 (the
model "auto" picks for a nearly incompressible layer), and for the compressible answer at H/a = 0.05 for nu = 0,
0.3 and the frictionless base, each checked against the direct solver run at H/a = 0.05.
"""
from __future__ import annotations

import math

import pytest

import thinlayer as tl
from thinlayer.asymptotics.solution import ValidityError

LAYERS = {
    "nu=0": lambda: tl.BondedLayer(0),
    "nu=0.3": lambda: tl.BondedLayer(0.3),
    "nu=0.45": lambda: tl.BondedLayer(0.45),
    "nu=0.49": lambda: tl.BondedLayer(0.49),
    "nu=0.5": lambda: tl.BondedLayer(0.5),
    "frictionless": lambda: tl.FrictionlessLayer(0.3),
}
#: punch, depth and the half-width a of the rigid overlap {Phi < delta0} (2|omega_0|/|Gamma_0|), which sets H
PUNCHES = {
    "sphere": (tl.Punch.paraboloid(10), 0.1),
    "ellipse4": (tl.Punch.elliptic_paraboloid(40, 10), 0.1),
    "quartic": (tl.Punch("x_1**2/2 + x_2**2 + x_1**3/5 + x_1*x_2/10 + x_1**4 + x_2**4"), 0.3),
}
RATIOS = (0.05, 0.2, 0.5)
#: (layer, punch, H/a) of the cells that only THINLAYER_SLOW=1 runs (see the module's docstring)
SLOW_CELLS = {(nu, punch, 0.05) for nu in ("nu=0.45", "nu=0.49", "nu=0.5") for punch in ("ellipse4", "quartic")}


def _half_width(punch: tl.Punch, delta0: float) -> float:
    c = tl.contact_contour(punch.expr, delta0)
    return 2 * c.area / c.perimeter


def _model(layer, punch, delta0, H) -> str:
    try:
        return tl.solve(layer, punch, delta0=delta0, H=H, mu=1.0, model="asymptotic").model
    except ValidityError:
        pass
    try:  # "auto" tries the any-thickness law (T.7) before the direct solver
        return tl.solve(layer, punch, delta0=delta0, H=H, mu=1.0, model="any-thickness").model
    except ValueError:
        return "direct"


def _cells():
    out = []
    half_width = {pname: _half_width(punch, d0) for pname, (punch, d0) in PUNCHES.items()}  # once per punch
    for lname, make in LAYERS.items():
        for pname, (punch, d0) in PUNCHES.items():
            a = half_width[pname]
            for ratio in RATIOS:
                marks = [pytest.mark.slow] if (lname, pname, ratio) in SLOW_CELLS else []
                out.append(pytest.param(make, punch, d0, ratio * a, id=f"{lname}-{pname}-Ha{ratio}", marks=marks))
    return out


@pytest.mark.parametrize(("make", "punch", "delta0", "H"), _cells())
def test_solve_agrees_with_the_direct_solver_inside_its_estimate(make, punch, delta0, H):
    model = _model(make(), punch, delta0, H)
    ans = tl.solve(make(), punch, delta0=delta0, H=H, E=2.6)
    assert ans.model == model
    assert math.isfinite(ans.force) and ans.force > 0 and ans.contact_area > 0
    assert all(0 < e <= 0.05 for e in ans.error_estimate.values()), ans.error_estimate  # tol = 5 %
    cmp = ans.compare_direct()
    assert cmp.direct.model == "direct" and len(cmp.rows) >= 2
    for key, value, direct, diff, est in cmp.rows:
        allowed = est + cmp.direct.error_estimate.get(key, 0.0)
        assert diff <= allowed, f"{key}: {value} vs direct {direct}: difference {diff:.3g} > estimate {allowed:.3g}"
    # the pressure integrates to the force (1.8) for the closed-form and the direct answers alike
    if punch is PUNCHES["sphere"][0]:
        import numpy as np
        from scipy import integrate

        c = ans.contact_radius
        P = 2 * np.pi * integrate.quad(lambda r: r * float(ans.pressure(r, 0.0)), 0, c, limit=200)[0]
        assert P == pytest.approx(ans.force, rel=max(3 * ans.error_estimate["force"], 1e-3))
        assert ans.max_pressure == pytest.approx(float(ans.pressure(0.0, 0.0)), rel=1e-6)


@pytest.mark.parametrize(("nu", "model"), [(0.45, "two-term"), (0.49, "two-term"), (0.5, "incompressible")])
@pytest.mark.parametrize("ratio", [0.01, 0.03])
def test_nearly_incompressible_models_inside_their_estimate(nu, model, ratio):
    # (I.10)-(I.12): estimates 2 h H/c (force, area) and 2 (h H/c)^2 (corrected radius), against the direct solver
    punch = tl.Punch.paraboloid(10)
    H = ratio * math.sqrt(20 * 0.1)
    ans = tl.solve(tl.BondedLayer(nu), punch, delta0=0.1, H=H, mu=1.0, model=model, tol=0.2)
    assert ans.model == model
    cmp = ans.compare_direct()
    assert {k for k, *_ in cmp.rows} == {"force", "contact_area", "contact_radius"}
    for key, value, direct, diff, est in cmp.rows:
        assert diff <= est, f"{key}: {value} vs {direct}: {diff:.3g} > {est:.3g}"


def test_incompressible_ellipse_inside_its_estimate():
    # (I.6)-(I.8) at nu = 1/2 against the 2D direct solver, H/a = 0.05
    punch = tl.Punch.elliptic_paraboloid(40, 10)
    ans = tl.solve(tl.BondedLayer("1/2"), punch, delta0=0.1, H=0.12, mu=1.0, model="incompressible", tol=0.5)
    assert ans.model == "incompressible" and ans.semi_axes is not None
    cmp = ans.compare_direct()
    for key, value, direct, diff, est in cmp.rows:
        assert diff <= est + cmp.direct.error_estimate[key], f"{key}: {value} vs {direct}: {diff:.3g} > {est:.3g}"
