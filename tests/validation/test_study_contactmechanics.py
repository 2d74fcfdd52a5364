"""The direct solvers and the asymptotics against contactmechanics (optional), an independent FFT solver.

Its ``PeriodicFFTElasticHalfSpace(thickness=H, poisson=nu)`` is the bonded layer; the expected values
are textbook formulas (Hertz) and thinlayer's own independent solvers.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from thinlayer import BondedLayer, FrictionlessLayer, Punch
from thinlayer.asymptotics.solution import compressible_solution as solve
from thinlayer.numerics import solve_2d, solve_axisymmetric


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
