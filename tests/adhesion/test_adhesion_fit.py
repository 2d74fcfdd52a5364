"""fit_adhesive: E and w from an adhesive unloading curve (issue 26 item 5).

Default: data from JKR (1971) as printed (half-space, independent of the solver), with noise; SLOW: data made by
the direct JKR solver (J.1)-(J.5) on a bonded layer at radii that are not the fit table's nodes.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from thinlayer import BondedLayer, HalfSpace, Punch
from thinlayer.contact.adhesion_fit import fit_adhesive
from thinlayer.errors import InputError
from thinlayer.numerics.adhesion import adhesive_state

R, NU, E, W = 10.0, 0.3, 2.6, 0.01


def _jkr(a):
    es = E / (1 - NU**2)  # JKR (1971): delta = a^2/R - sqrt(2 pi w a/E*), P = 4E* a^3/(3R) - sqrt(8 pi w E* a^3)
    return a**2 / R - np.sqrt(2 * math.pi * W * a / es), 4 * es * a**3 / (3 * R) - np.sqrt(8 * math.pi * W * es * a**3)


def test_recovers_jkr_half_space_within_standard_errors():
    a = np.linspace(0.6, 1.5, 40)  # the stable branch under displacement control (d delta/da > 0 for a > 0.516)
    d, P = _jkr(a)
    noisy = P + 0.002 * np.random.default_rng(1).standard_normal(P.size)
    f = fit_adhesive(HalfSpace(), Punch.paraboloid(R), d, noisy, nu=NU, E0=2.0, w0=0.02, nodes=8, radii=(0.1, 2.0))
    assert abs(f.E - E) < 2 * f.E_error and abs(f.work_of_adhesion - W) < 2 * f.work_of_adhesion_error
    assert f.E_error < 0.01 * E and f.work_of_adhesion_error < 0.01 * W
    assert f.residual_rms < 0.003  # the noise (0.002) and nothing more: the model reproduces JKR


@pytest.mark.parametrize("kw, match", [({"depths": "0.1"}, "depths"), ({"E0": -1}, "E0"), ({"nodes": 2}, "nodes"),
                                       ({"forces": [1.0, 2.0]}, "forces")])
def test_bad_input_one_line(kw, match):
    args = {"depths": [0.01, 0.02, 0.03], "forces": [0.1, 0.2, 0.3], "nu": NU, "E0": 1.0, "w0": 0.01, **kw}
    with pytest.raises(InputError, match=match):
        fit_adhesive(HalfSpace(), Punch.paraboloid(R), **args)


@pytest.mark.slow
def test_recovers_direct_solver_data_on_a_layer():
    H = 0.1
    mu = E / (2 * (1 + NU))
    radii = np.linspace(0.75, 1.4, 12)
    states = [adhesive_state(BondedLayer(NU), Punch.paraboloid(R), c, H, mu, work_of_adhesion=W, energy_route=False)
              for c in radii]
    d = np.array([s.delta for s in states])
    P = np.array([s.force for s in states])
    assert np.all(np.diff(d) > 0)  # stable branch
    noisy = P + 0.003 * np.random.default_rng(2).standard_normal(P.size)
    f = fit_adhesive(BondedLayer(NU), Punch.paraboloid(R), d, noisy, H, nu=NU, E0=2.0, w0=0.02, nodes=14,
                     radii=(0.2, 2.0))
    assert abs(f.E - E) < 3 * f.E_error and abs(f.work_of_adhesion - W) < 3 * f.work_of_adhesion_error
    assert f.E_error < 0.02 * E
