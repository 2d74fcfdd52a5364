"""Tests of the grid solver of the free-boundary problem (I.3)-(I.4), (I.10) (:mod:`thinlayer.numerics.obstacle`).

Against the closed forms of the incompressible model (ellipse (I.6)-(I.8), radial quadrature (I.9)), the
two-term sphere (I.11), and the discrete equations themselves; convergence rates measured.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from thinlayer import BondedLayer, Punch
from thinlayer.asymptotics.incompressible import (
    IncompressibleLayer,
    incompressible_axisymmetric,
    incompressible_ellipse,
    two_term_sphere,
)
from thinlayer.numerics.obstacle import solve_obstacle_grid

slow = pytest.mark.slow
INC = IncompressibleLayer()


def rate(e1: float, e2: float, ratio: float = 2.0) -> float:
    """Observed order of convergence from errors at step sizes h and h/ratio."""
    return math.log(abs(e1) / abs(e2)) / math.log(ratio)


# =========================================================================== grid solver
@pytest.fixture(scope="module")
def grid_ellipse():
    ev = incompressible_ellipse(2, 1).evaluate(0.1, 0.1, 1.0)
    runs = {n: solve_obstacle_grid(INC, Punch.elliptic_paraboloid(2, 1), 0.1, 0.1, 1.0, n=n) for n in (41, 81, 161)}
    return ev, runs


def test_grid_reproduces_the_ellipse_with_second_order_convergence(grid_ellipse):
    ev, runs = grid_ellipse
    errP = {n: g.force / ev.force - 1 for n, g in runs.items()}
    errp = {}
    for n, g in runs.items():
        X1, X2 = np.meshgrid(g.x1, g.x2, indexing="ij")
        pex = ev.C * np.maximum(1 - X1**2 / ev.a**2 - X2**2 / ev.b**2, 0) ** 2
        errp[n] = np.abs(g.pressure - pex).max() / ev.C
    assert abs(errP[161]) < 5e-4 and errp[161] < 5e-4
    assert rate(errP[81], errP[161]) > 1.7 and rate(errp[81], errp[161]) > 1.7  # O(h^2)
    g = runs[161]
    # semi-axes: from the pressure moments (<x1^2> = a^2/8 for the (1 - X)^2 profile) and from the contact set
    _, _, m11, m12, m22 = g.moments()
    assert math.sqrt(8 * m11) == pytest.approx(ev.a, rel=5e-4)
    assert math.sqrt(8 * m22) == pytest.approx(ev.b, rel=5e-4)
    assert abs(m12) < 1e-12
    x1a, x1b, _, x2b = g.extent()
    h1, h2 = g.h
    assert abs(x1b - ev.a) < 1.5 * h1 and abs(-x1a - ev.a) < 1.5 * h1 and abs(x2b - ev.b) < 1.5 * h2
    assert g.area == pytest.approx(ev.area, rel=0.03)
    assert abs(g.volume_residual) < abs(runs[81].volume_residual) < 0.1  # (I.5), first order on the grid


def test_grid_quartic_against_the_radial_quadrature():
    punch = Punch.fourth_degree(R=1, K=1)
    ref = incompressible_axisymmetric(Punch.fourth_degree()).evaluate(0.1, 0.01, 1.0, {"R": 1.0, "K": 1.0})
    e = {n: solve_obstacle_grid(INC, punch, 0.1, 0.01, n=n).force / ref.force - 1 for n in (81, 161)}
    assert abs(e[161]) < 5e-4 and rate(e[81], e[161]) > 1.7


def test_grid_general_punch_converges_and_satisfies_the_conditions():
    punch = Punch("x_1**2/2 + x_2**2/4 + x_1**3/3 + x_1*x_2/5")
    g = {n: solve_obstacle_grid(INC, punch, 0.1, 0.01, n=n) for n in (41, 81, 161)}
    d1, d2 = g[41].force - g[81].force, g[81].force - g[161].force
    assert rate(d1, d2) > 1.6  # Richardson: O(h^2)
    s = g[161]
    assert np.all(s.pressure >= 0) and s.pressure[0, :].max() == 0
    # discrete (I.3) on the contact nodes away from the free boundary
    P = s.pressure
    h1, h2 = s.h
    L = ((P[2:, 1:-1] - 2 * P[1:-1, 1:-1] + P[:-2, 1:-1]) / h1**2
         + (P[1:-1, 2:] - 2 * P[1:-1, 1:-1] + P[1:-1, :-2]) / h2**2)
    X1, X2 = np.meshgrid(s.x1[1:-1], s.x2[1:-1], indexing="ij")
    f = 3.0 / 0.01**3 * (0.1 - (X1**2 / 2 + X2**2 / 4 + X1**3 / 3 + X1 * X2 / 5))
    inner = s.contact[1:-1, 1:-1]
    assert np.max(np.abs(-L - f)[inner]) < 1e-8 * np.abs(f).max()
    # outside: u_3 = -(H^3/3 mu) Delta_h p >= delta0 - Phi (complementarity (1.5)), discretely
    assert np.all((-L - f)[~inner] >= -1e-8 * np.abs(f).max())
    assert s.pressure_at(0.0, 0.0) > 0 and s.lambdify()(10.0, 10.0) == 0


def test_grid_two_term_matches_the_bessel_sphere():
    # nu = 0.49, R = 1, delta0 = 0.02, H = 0.01: k c ~ 5, both terms of (I.10) matter
    ts = two_term_sphere(BondedLayer("49/100")).evaluate(0.02, 1.0, 0.01)
    e = {n: solve_obstacle_grid(BondedLayer("49/100"), Punch.paraboloid(R=1), 0.02, 0.01, n=n).force / ts.force - 1
         for n in (81, 161)}
    assert abs(e[161]) < 1e-3 and rate(e[81], e[161]) > 1.7


def test_grid_input_errors():
    pun = Punch.paraboloid(R=1)
    with pytest.raises(ValueError, match="odd"):
        solve_obstacle_grid(INC, pun, 0.1, 0.1, n=40)
    with pytest.raises(ValueError, match="box"):
        solve_obstacle_grid(INC, pun, 0.1, 0.1, n=41, box=(-0.3, 0.3, -0.3, 0.3))
    with pytest.raises(ValueError, match="parameters"):
        solve_obstacle_grid(INC, Punch.paraboloid(), 0.1, 0.1, n=41)
    with pytest.raises(ValueError, match="delta0"):
        solve_obstacle_grid(INC, pun, -0.1, 0.1, n=41)
    with pytest.raises(ValueError, match="1/4 < nu"):
        solve_obstacle_grid(BondedLayer(0.2), pun, 0.1, 0.1, n=41)
    with pytest.raises(TypeError, match="Punch"):
        solve_obstacle_grid(INC, "x^2", 0.1, 0.1, n=41)
    g = solve_obstacle_grid(INC, lambda a, b: (a * a + b * b) / 2, 0.1, 0.1, n=41)  # a callable punch
    assert g.force == pytest.approx(2 * math.pi * 0.1**3 / 0.1**3, rel=0.02)  # 2 pi mu R^2 delta0^3/H^3, R = 1
    with pytest.raises(ValueError):
        g.pressure[0, 0] = 1.0
    assert "tag{I.3}" in g.latex()

@slow
def test_grid_fine_ellipse():
    ev = incompressible_ellipse(2, 1).evaluate(0.1, 0.1, 1.0)
    e = [solve_obstacle_grid(INC, Punch.elliptic_paraboloid(2, 1), 0.1, 0.1, n=n).force / ev.force - 1
         for n in (161, 321)]
    assert abs(e[1]) < 1e-4 and rate(*e) > 1.7


def test_grid_deprecated_nu_form_still_works():
    # solve_obstacle_grid(punch, delta0, H, mu, nu=...) of earlier releases: same numbers, a DeprecationWarning
    pun = Punch.paraboloid(R=1)
    with pytest.warns(DeprecationWarning, match=r"solve_obstacle_grid\(IncompressibleLayer\(\), punch"):
        old = solve_obstacle_grid(pun, 0.1, 0.1, n=41)
    assert old.force == solve_obstacle_grid(INC, pun, 0.1, 0.1, n=41).force
    with pytest.warns(DeprecationWarning, match=r"BondedLayer\('49/100'\)"):
        old = solve_obstacle_grid(pun, 0.02, 0.01, 1.0, nu="49/100", n=41)
    new = solve_obstacle_grid(BondedLayer("49/100"), pun, 0.02, 0.01, 1.0, n=41)
    assert (old.force, old.nu, old.k2) == (new.force, new.nu, new.k2)
    with pytest.raises(ValueError, match="1/4 < nu"):
        solve_obstacle_grid(pun, 0.1, 0.1, nu=0.2, n=41)
    with pytest.raises(TypeError, match="deprecated"):
        solve_obstacle_grid(INC, pun, 0.1, 0.1, nu=0.5, n=41)
    with pytest.raises(TypeError, match="numeric"):
        solve_obstacle_grid(BondedLayer(), pun, 0.1, 0.1, n=41)
