"""The model registry (issue 29 items 1 and 3): a new model is one registered class, checked at registration,
that solve() walks without any edit of solve.py; every model's unit-modulus ForceCurve equals solve() point by point.

Independent values: Hertz's half-space force ``P = (4/3) E/(1 - nu^2) R^{1/2} delta^{3/2}`` for the toy model,
Boussinesq's flat punch ``P = 4 mu a w0 kappa/(1 - nu)`` with kappa from :func:`flat_punch_stiffness`, and the
solve() answers (separate code paths: solve() runs the scalar models, the curves their vectorised laws).
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import thinlayer as tl
from thinlayer.contact import solve as solve_mod
from thinlayer.contact.indentation import Indentation
from thinlayer.contact.models import MODEL_REGISTRY, Model, model_names, register_model, unregister_model
from thinlayer.contact.models.base import entries_named
from thinlayer.contact.problem import Depth, Elastic, Frictionless, Problem
from thinlayer.errors import ThinlayerError


class ToyHertz(Model):
    """Hertz's half-space law for the sphere, with a zero estimate: a toy that "auto" must take first."""

    name = "toy-hertz"
    preference = -1
    asymptotic = True
    equations = ("H.1", "H.2")

    def applies(self, problem):
        return None if problem.tip.sphere_radius is not None else "the toy is for the sphere"

    def run(self, problem):
        R, d, nu, mu = problem.tip.sphere_radius, problem.delta0, problem.nu, problem.mu
        c = math.sqrt(R * d)
        P = 4.0 / 3.0 * 2.0 * mu / (1.0 - nu) * math.sqrt(R) * d**1.5
        return Indentation(layer=problem.layer, punch=problem.tip, delta0=d, force=P, H=problem.H, mu=mu, nu=nu,
                           contact_area=math.pi * c * c, contact_radius=c, semi_axes=None, model=self.name,
                           reason="", error_estimate={"force": 0.0, "contact_area": 0.0}, tol=problem.tol,
                           detail=None, _pressure=lambda x1, x2: 0.0 * x1, _extent=c, extras={"toy": True})


def test_a_registered_toy_model_is_used_without_editing_solve():
    source = Path(solve_mod.__file__).read_text()
    assert "toy" not in source and source.count('model == "') == 0 and len(source.splitlines()) < 300
    entry = register_model(ToyHertz)
    try:
        assert "toy-hertz" in model_names()
        ans = tl.solve(tl.BondedLayer(0.3), tl.Punch.paraboloid(10), delta0=0.1, H=0.05, E=2.6)
        mu = 2.6 / (2 * 1.3)
        assert ans.model == "toy-hertz" and ans.entry is entry and ans.extras == {"toy": True}
        assert ans.force == pytest.approx(4 / 3 * 2.6 / (1 - 0.09) * math.sqrt(10) * 0.1**1.5, rel=1e-14)
        assert ans.force == pytest.approx(16 / 3 * mu / (2 * 0.7) * math.sqrt(10) * 0.1**1.5, rel=1e-14)
        assert ans.reason == "toy-hertz: estimates force 0 %, contact area 0 % within tol 5 %"
        assert ans.equations == ("H.1", "H.2")
        named = tl.solve(tl.BondedLayer(0.3), tl.Punch.paraboloid(10), delta0=0.1, H=0.05, E=2.6, model="toy-hertz")
        assert named.force == ans.force
        # another punch: the toy does not apply; "auto" names it among the models tried and goes on
        other = tl.solve(tl.BondedLayer(0.3), tl.Punch.elliptic_paraboloid(4, 1), delta0=0.1, H=0.02, mu=1.0)
        assert other.model == "compressible" and other.reason.startswith("toy-hertz: the toy is for the sphere; ")
    finally:
        unregister_model(entry)
    assert entry not in MODEL_REGISTRY and "toy-hertz" not in model_names()
    assert tl.solve(tl.BondedLayer(0.3), tl.Punch.paraboloid(10), delta0=0.1, H=0.05, E=2.6).model == "compressible"


@pytest.mark.parametrize("attr, value, match", [
    ("equations", ("H.1",), "pair of strings"), ("preference", 1.5, "int"), ("preference", True, "int"),
    ("name", "", "non-empty"), ("name", "auto", "other than"), ("parameter_units", ("Pa",), "equal length"),
])
def test_the_contract_is_checked_at_registration(attr, value, match):
    bad = type("Bad", (ToyHertz,), {attr: value})
    n = len(MODEL_REGISTRY)
    with pytest.raises(ThinlayerError, match=match):
        register_model(bad)
    assert len(MODEL_REGISTRY) == n


def test_one_entry_per_name_and_applies():
    entry = register_model(ToyHertz)
    try:
        with pytest.raises(ThinlayerError, match="registered already"):
            register_model(ToyHertz)
    finally:
        unregister_model(entry)
    # "direct": three entries (flat punch exact, axisymmetric spectral, 2D FFT), each with its own applies
    assert [type(m).__name__ for m in entries_named("direct")] == ["FlatExact", "AxisymmetricDirect", "FFTDirect"]
    assert model_names() == solve_mod.MODELS == ("auto", "asymptotic", "compressible", "two-term", "incompressible",
                                                 "any-thickness", "direct")


def _problem(layer, tip, H, nu, tol=0.05):
    return Problem(layer, tip, Elastic(1.0, nu), Frictionless(), Depth(1.0), H, tol)


@pytest.mark.parametrize("name, layer, punch, H, depths", [
    ("compressible", tl.BondedLayer(0.3), tl.Punch.paraboloid(10), 0.02, [0.05, 0.1, 0.3]),
    ("compressible", tl.FrictionlessLayer(0.3), tl.Punch.elliptic_paraboloid(40, 10), 0.02, [0.05, 0.2]),
    ("two-term", tl.BondedLayer(0.45), tl.Punch.paraboloid(10), 0.005, [0.05, 0.1]),
    ("any-thickness", tl.BondedLayer(0.49), tl.Punch.paraboloid(10), 0.5, [0.01, 0.1, 2.0]),
])
def test_force_curve_equals_solve_point_by_point(name, layer, punch, H, depths):
    entry = entries_named(name)[0]
    curve = entry.force_curve(_problem(layer, punch, H, float(layer.numeric_nu), tol=1.0))
    d = np.array(depths)
    P, A = curve.force(d), curve.contact_area(d)
    for k, dv in enumerate(depths):
        ans = tl.solve(layer, punch, delta0=dv, H=H, mu=2.5, model=name, tol=1.0)
        assert 2.5 * P[k] == pytest.approx(ans.force, rel=1e-9)
        assert A[k] == pytest.approx(ans.contact_area, rel=1e-9)
    assert curve.valid(d).all() and curve.force(np.array([0.0, -1.0])).tolist() == [0.0, 0.0]


def test_any_thickness_curve_radius_and_its_inverse():
    curve = entries_named("any-thickness")[0].force_curve(_problem(tl.BondedLayer(0.49), tl.Punch.paraboloid(10),
                                                                   0.5, 0.49))
    d = np.geomspace(1e-4, 10.0, 7)
    c = curve.contact_radius(d)
    for dv, cv in zip(d, c):
        assert cv == pytest.approx(tl.solve(tl.BondedLayer(0.49), tl.Punch.paraboloid(10), delta0=float(dv), H=0.5,
                                            mu=1.0, model="any-thickness").contact_radius, rel=1e-12)
    assert curve.depth_for_radius(c) == pytest.approx(d, rel=1e-9)
    assert curve.force_for_radius(c) == pytest.approx(curve.force(d), rel=1e-8)


def test_flat_punch_curve_is_boussinesq_times_kappa():
    layer = tl.BondedLayer(0.3)
    kappa = tl.flat_punch_stiffness(layer, 2.0)
    problem = _problem(layer, tl.Punch.flat(1.0), 0.5, 0.3)
    exact = entries_named("direct")[0].force_curve(problem)
    d = np.array([0.01, 0.02])
    assert exact.force(d) == pytest.approx(4 * 1.0 * d * kappa / 0.7, rel=1e-9)
    assert exact.contact_radius(d).tolist() == [1.0, 1.0]
    thick = entries_named("thick-layer")[0].force_curve(problem)  # a/H = 2 is beyond the series' range
    assert not thick.valid(d).any() and np.isnan(thick.force(d)).all()


def test_direct_solvers_give_no_curve_and_the_estimate_marks_the_range():
    problem = _problem(tl.BondedLayer(0.3), tl.Punch.paraboloid(10), 0.02, 0.3, tol=0.01)
    assert entries_named("direct")[1].force_curve(problem) is None
    curve = entries_named("compressible")[0].force_curve(problem)
    d = np.array([1e-4, 0.1])  # 1e-4: the contact radius 0.045 is about 2 H: beyond the thin-layer range
    assert curve.valid(d).tolist() == [False, True] and math.isnan(curve.force(d)[0])
    assert curve.estimate(d)[0] > 0.01 >= curve.estimate(d)[1]
