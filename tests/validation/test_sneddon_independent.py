"""Half-space limits of the cone, the exact sphere and the power law, checked without any quoted formula (issue 24
item 5).

The derived half-space solution ((S1), (S2) of :mod:`thinlayer.validation.sneddon`, Abel/Copson route) is put back into
Boussinesq's point-load solution by mpmath quadrature ((S3), :func:`~thinlayer.validation.sneddon.boussinesq_check`):
the displacement must equal ``delta0 - Phi(r)`` inside the contact (1.5) and the pressure must vanish at the edge.  The
force so obtained is the reference for the closed forms of the module and for the direct axisymmetric solver's
half-space limit (to 1e-8); nanite's docstrings (``QUOTED``, a secondary source) take no part here.
"""
import math
from functools import lru_cache

import mpmath
import pytest

from thinlayer import HalfSpace, Punch
from thinlayer.numerics.axisymmetric import contact_for_radius
from thinlayer.validation.sneddon import (
    boussinesq_check,
    half_space_by_quadrature,
    sneddon_cone,
    sneddon_power_law,
    sneddon_sphere,
)

NU = 0.3
VT = 1 / (1 - NU)
C_R = 0.8  # contact radius
ALPHA, C_POW, N_POW, R_SPH = 70.0, 1.3, 1.5, 2.0


def _cone():
    cot = 1 / mpmath.tan(mpmath.radians(ALPHA))
    ref = sneddon_cone(ALPHA, C_R, VT)
    return ref, (lambda t: mpmath.pi / 2 * cot), (lambda r: r * cot), (lambda s: cot), Punch.cone(ALPHA), ()


def _power():
    ref = sneddon_power_law(C_POW, N_POW, C_R, VT)
    d0, c = ref.delta0, C_R
    return (ref, (lambda t: N_POW * d0 * t ** (N_POW - 1) / c**N_POW), (lambda r: C_POW * r**N_POW),
            (lambda s: C_POW * N_POW * s ** (N_POW - 1)), Punch.power_law(C_POW, N_POW), ())


def _sphere():
    R = R_SPH
    ref = sneddon_sphere(R, C_R, VT)
    return (ref, (lambda t: mpmath.log((R + t) / (R - t)) / 2 + t * R / (R * R - t * t)),
            (lambda r: R - mpmath.sqrt(R * R - r * r)), (lambda s: s / mpmath.sqrt(R * R - s * s)),
            Punch.sphere(R), ())


TIPS = {"cone": _cone, "power": _power, "sphere": _sphere}


@lru_cache(maxsize=None)
def _checked(name):
    ref, dslope, phi, slope, punch, breaks = TIPS[name]()
    radii = (0.3, 0.9) if name == "cone" else (0.6,)  # the nested quadrature costs ~0.5 s CPU per radius
    return ref, boussinesq_check(dslope, phi, ref.delta0, C_R, radii, vartheta=VT), slope, punch, breaks


@pytest.mark.parametrize("name", list(TIPS))
def test_derived_solution_satisfies_boussinesq_contact_condition(name):
    # (S3): u3 of the derived pressure by Boussinesq's Green function equals delta0 - Phi inside the contact (1.5)
    ref, chk, *_ = _checked(name)
    assert max(abs(x) for x in chk.residuals) < 1e-9, chk.residuals
    assert 0 < chk.edge_pressure < 0.06  # p > 0 and p -> 0 like sqrt(c - r) at the edge (1.5)
    # the force (1.8) of that pressure is the closed form (S2) of the module and the quadrature of (S2)
    assert chk.force == pytest.approx(ref.force, rel=1e-10)


@pytest.mark.parametrize("name", list(TIPS))
def test_half_space_quadrature_and_direct_solver_equal_the_boussinesq_force(name):
    ref, chk, slope, punch, breaks = _checked(name)
    q = half_space_by_quadrature(slope, C_R, VT, breaks=breaks)
    assert q.delta0 == pytest.approx(ref.delta0, rel=1e-12)
    assert q.force == pytest.approx(chk.force, rel=1e-10)
    # the direct axisymmetric solver on the half-space (Galerkin modes, no closed form) at the same contact radius
    res = contact_for_radius(HalfSpace(), punch, C_R, nu=NU, n=40, error_estimate=False)
    assert res.force == pytest.approx(chk.force, rel=1e-8)
    assert res.delta0 == pytest.approx(ref.delta0, rel=1e-8)
    assert math.isfinite(res.force) and res.force > 0
