"""Tests of the criterion (I.13) (:mod:`thinlayer.asymptotics.incompressible.regime`).

The criterion against its closed forms; its agreement with the direct solver is in
``tests/validation/test_comparison.py``.
"""
from __future__ import annotations

import pytest

from thinlayer import BondedLayer
from thinlayer.asymptotics.incompressible import IncompressibleLayer, regime, two_term_sphere


def _layer(nu):
    return IncompressibleLayer() if nu == 0.5 else BondedLayer(nu)


def test_regime_criterion():
    assert [regime(_layer(nu), 0.05).model for nu in (0.3, 0.45, 0.49, 0.5)] == \
        ["compressible", "compressible", "two-term", "incompressible"]
    assert regime(BondedLayer(0.2), 0.05).model == "compressible"  # m_1 < 0: no breakdown below nu = 1/4
    # near 1/2: lambda^2 ~ 3 (1 - 2 nu) (a/H)^2 (I.13)
    rg = regime(BondedLayer(0.49999), 0.1)
    assert rg.lambda2 == pytest.approx(3 * 2e-5 * 100, rel=1e-3)
    # the incompressible model's force error (3/16) lambda^2, from the two-term sphere at small k c
    a = two_term_sphere(BondedLayer(0.499999)).evaluate(0.2, 1000.0, 1.0, edge_correction=False)
    b = two_term_sphere(IncompressibleLayer()).evaluate(0.2, 1000.0, 1.0, edge_correction=False)
    x2 = b.radius**2 / float(BondedLayer(0.499999).m(1))  # (k c)^2 with H = 1
    # divide out the O(1 - 2 nu) change of the prefactor vartheta/c_1 of f (I.10)
    ta, tb = two_term_sphere(BondedLayer(0.499999)), two_term_sphere(IncompressibleLayer())
    pref = float((ta.vartheta / ta.c1) / (tb.vartheta / tb.c1))
    assert a.force / (b.force * pref) - 1 == pytest.approx(-3 / 16 * x2, rel=0.01)
    f = rg.lambdify()
    assert f(0.49999, 0.1)[0] == pytest.approx(rg.lambda2, rel=1e-10)
    assert "tag{I.13}" in rg.latex()
    with pytest.raises(ValueError, match="nu"):
        regime(BondedLayer(0.6), 0.1)
    with pytest.raises(ValueError, match="H_over_a"):
        regime(BondedLayer(0.49), 0.0)


def test_regime_deprecated_nu_form_still_works():
    # regime(nu, H_over_a) of earlier releases: the same criterion, with a DeprecationWarning naming the new call
    with pytest.warns(DeprecationWarning, match=r"regime\(BondedLayer\(0.49\), H_over_a\)"):
        old = regime(0.49, 0.05)
    assert old == regime(BondedLayer(0.49), 0.05)
    with pytest.warns(DeprecationWarning, match=r"regime\(IncompressibleLayer\(\), H_over_a\)"):
        assert regime(0.5, 0.05) == regime(IncompressibleLayer(), 0.05)
    with pytest.raises(ValueError, match="nu"):
        regime(0.6, 0.1)
    with pytest.raises(TypeError, match="numeric"):
        regime(BondedLayer(), 0.1)
