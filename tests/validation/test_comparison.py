"""The thin-layer models against the direct solver (:mod:`thinlayer.validation.comparison`).

The direct solver :func:`thinlayer.numerics.solve_axisymmetric` knows only L(u); the incompressible
model (I.8), (I.9), the edge correction (I.12), the two-term model (I.11) and the criterion (I.13) are
measured against it.
"""
from __future__ import annotations

import math
from dataclasses import FrozenInstanceError

import pytest
import sympy as sp

from thinlayer import BondedLayer, FrictionlessLayer, Punch
from thinlayer.asymptotics.incompressible import (
    IncompressibleLayer,
    incompressible_axisymmetric,
    two_term_edge_shift,
)
from thinlayer.numerics import solve_axisymmetric
from thinlayer.validation.comparison import compare_sphere_models

slow = pytest.mark.slow


def rate(e1: float, e2: float, ratio: float = 2.0) -> float:
    """Observed order of convergence from errors at step sizes h and h/ratio."""
    return math.log(abs(e1) / abs(e2)) / math.log(ratio)


# =========================================================================== against the direct solver
def test_direct_solver_accepts_the_incompressible_layer_only():
    res = solve_axisymmetric(IncompressibleLayer(), lambda r: r * r / 2000, 0.025, 1.0)
    assert res.nu == 0.5 and res.vartheta == pytest.approx(2.0)
    with pytest.raises(ValueError, match="disagrees"):
        solve_axisymmetric(IncompressibleLayer(), lambda r: r * r / 2000, 0.025, 1.0, nu=0.3)
    with pytest.raises(ValueError, match="nu"):
        solve_axisymmetric(FrictionlessLayer(), lambda r: r * r / 2000, 0.025, 1.0, nu=0.5)


@pytest.fixture(scope="module")
def direct_sphere():
    """Direct solutions at nu = 1/2 with the model radius a = 2 sqrt(R delta0) = (a/H) H, H = 1, R = 1000."""
    out = {}
    for aH in (10, 20, 40):
        d0 = aH**2 / 4000.0
        out[aH] = (d0, solve_axisymmetric(IncompressibleLayer(), lambda r: r * r / 2000.0, d0, 1.0))
    return out


def test_direct_force_converges_to_the_incompressible_law(direct_sphere):
    # (I.8) with R1 = R2: P = 2 pi mu R^2 delta0^3/H^3; measured error ~ 21 (H/a)^2
    e = {aH: res.force / (2 * math.pi * 1000.0**2 * d0**3) - 1 for aH, (d0, res) in direct_sphere.items()}
    assert e[10] > e[20] > e[40] > 0
    assert e[40] < 0.02
    assert 1.7 < rate(e[20], e[40]) < 2.3 and 1.6 < rate(e[10], e[20]) < 2.3


def test_direct_radius_converges_with_the_edge_shift(direct_sphere):
    # c = a - h(1/2) H + O(H^2/a), a = 2 sqrt(R delta0) (I.7), h from (I.12)
    h = float(two_term_edge_shift())
    shift = {aH: (aH - res.radius) for aH, (d0, res) in direct_sphere.items()}
    dev = {aH: h - s for aH, s in shift.items()}
    assert abs(dev[40]) < 0.12 and rate(dev[20], dev[40]) > 0.8  # (a - c)/H -> h at rate H/a
    assert 2 * shift[40] - shift[20] == pytest.approx(h, abs=0.02)  # Richardson extrapolation
    assert 0.8 < rate(1 - direct_sphere[20][1].radius / 20, 1 - direct_sphere[40][1].radius / 40) < 1.2


def test_direct_quartic_punch_against_the_radial_solution():
    rad = incompressible_axisymmetric(Punch.fourth_degree())
    errs = []
    for H in (0.04, 0.02):
        v = rad.evaluate(0.1, H, 1.0, {"R": 1.0, "K": 1.0})
        res = solve_axisymmetric(IncompressibleLayer(), lambda r: r**2 / 2 + r**4, 0.1, H)
        errs.append(res.force / v.force - 1)
    assert abs(errs[1]) < 0.04 and 1.6 < rate(*errs) < 2.4


@slow
def test_direct_sphere_fine_layers():
    e, sh = [], []
    for aH in (40, 80):
        d0 = aH**2 / 4000.0
        res = solve_axisymmetric(IncompressibleLayer(), lambda r: r * r / 2000.0, d0, 1.0)
        e.append(res.force / (2 * math.pi * 1000.0**2 * d0**3) - 1)
        sh.append(aH - res.radius)
    assert e[1] < 0.005 and 1.8 < rate(*e) < 2.2
    assert 2 * sh[1] - sh[0] == pytest.approx(float(two_term_edge_shift()), abs=0.01)

@pytest.fixture(scope="module")
def nearly_incompressible():
    """Sphere, R = 1000, H = 1, delta0 = 0.2 (sqrt(2 R delta0) = 20 H), in every model and the direct solver."""
    return {nu: compare_sphere_models(BondedLayer(nu), 1000.0, 0.2, 1.0, direct=True) for nu in (0.45, 0.49, 0.499)}


def test_two_term_beats_both_limits_where_they_fail(nearly_incompressible):
    err = {nu: m.errors() for nu, m in nearly_incompressible.items()}
    for e in err.values():
        assert abs(e["two_term"][0]) < 0.02  # force within 2 % across the transition
        assert abs(e["two_term"][1]) < 0.005  # radius with the edge correction (I.12)
    # nu = 0.45 (lambda^2 ~ 180): compressible expansion fine, incompressible model off by a factor
    assert abs(err[0.45]["compressible"][0]) < 0.01 and err[0.45]["incompressible"][0] > 10
    # nu = 0.49 (lambda^2 ~ 26): the compressible correction is 15 %; the two-term model is 5x better
    assert abs(err[0.49]["two_term"][0]) < 0.2 * abs(err[0.49]["compressible"][0])
    assert abs(err[0.49]["two_term"][0]) < 0.01 * abs(err[0.49]["incompressible"][0])
    # nu = 0.499 (lambda^2 ~ 2.4): both limits fail
    assert abs(err[0.499]["compressible"][0]) > 1 and abs(err[0.499]["incompressible"][0]) > 0.3
    assert abs(err[0.499]["two_term"][0]) < 0.05 * min(abs(err[0.499]["compressible"][0]),
                                                        abs(err[0.499]["incompressible"][0]))


def test_regime_criterion_against_direct(nearly_incompressible):
    # the compressible correction 4 m_1 (H/a)^2 (the sphere's 2 m_1 H^2/(R delta0)) and (3/16) lambda^2
    for nu, m in nearly_incompressible.items():
        rg = m.regime
        m1 = float(BondedLayer(sp.Rational(str(nu))).m(1))
        assert rg.lambda2 == pytest.approx(1 / (m1 * rg.H_over_a**2), rel=1e-12)
        assert rg.compressible_correction * rg.lambda2 == pytest.approx(4.0, rel=1e-12)
        # the recommended model is within 2 % of the direct solution
        best = {"compressible": "compressible", "incompressible": "incompressible", "two-term": "two_term"}
        assert abs(m.errors()[best[rg.model]][0]) < 0.02


def test_sphere_models_api(nearly_incompressible):
    m = nearly_incompressible[0.49]
    assert m.lambdify()("direct") == m.direct
    assert "two-term" in m.latex()
    with pytest.raises(FrozenInstanceError):
        m.nu = 0.3
    nod = compare_sphere_models(IncompressibleLayer(), 1000.0, 0.2, 1.0)
    assert nod.compressible is None and nod.direct is None
    with pytest.raises(ValueError, match="direct"):
        nod.errors()


@slow
@pytest.mark.parametrize("nu", [0.4999, 0.49999])
def test_two_term_near_the_incompressible_limit(nu):
    m = compare_sphere_models(BondedLayer(nu), 1000.0, 0.2, 1.0, direct=True)
    e = m.errors()
    assert abs(e["two_term"][0]) < 0.03 and abs(e["two_term"][1]) < 0.005
    assert abs(e["compressible"][0]) > 10


def test_compare_sphere_models_deprecated_nu_form_still_works():
    # compare_sphere_models(nu, ...) of earlier releases: the same numbers, with a DeprecationWarning
    with pytest.warns(DeprecationWarning, match=r"compare_sphere_models\(IncompressibleLayer\(\), R, delta0, H\)"):
        old = compare_sphere_models(0.5, 1000.0, 0.2, 1.0)
    new = compare_sphere_models(IncompressibleLayer(), 1000.0, 0.2, 1.0)
    assert (old.nu, old.incompressible, old.two_term, old.regime) == (new.nu, new.incompressible, new.two_term,
                                                                       new.regime)
    with pytest.raises(TypeError, match="numeric"):
        compare_sphere_models(BondedLayer(), 1000.0, 0.2, 1.0)
