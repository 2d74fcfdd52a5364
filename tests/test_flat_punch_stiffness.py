"""The flat-punch front door :mod:`thinlayer.contact.flat_punch`: models, their agreement, errors, published tables.

The exact model is the reference (its own tests: ``tests/numerics/test_flat_punch.py``); the thin and thick models
must agree with it within their error estimates, ``"auto"`` must pick the cheapest admissible one, and the values
attributed to Hayes et al. (1972) must either agree to their printed digits or be listed in the errata registry.
"""
from __future__ import annotations

from decimal import Decimal

import numpy as np
import pytest

from thinlayer import BondedLayer, FrictionlessLayer, HalfSpace, errata
from thinlayer._checks import WorkLimitError
from thinlayer.contact.flat_punch import FLAT_PUNCH_MODELS, flat_punch_contact, flat_punch_stiffness
from thinlayer.layers.kernels import IncompressibleLayer

#: Complete tables attributed to Hayes, Keer, Herrmann & Mockros (1972), J. Biomech. 5:541-551, Table 1
#: (kappa of a flat-ended punch on a bonded layer), as found in code that reproduces them (the original could not
#: be accessed): source -> (nu, a/h values, printed kappa).
PUBLISHED = {
    "MohammadHosseinEbrahimi/Equilibrium-and-instantaneous-moduli, equilibrium_instantaneous.m":
        ("0.3", "0.2 0.4 0.6 0.8 1.0 1.2 1.4 1.6 1.8 2.0",
         "1.207 1.472 1.784 2.124 2.480 2.845 3.214 3.586 3.960 4.336"),
    "ImanKafian/CartilageStaticElasticModuliEstimation, cartilage_static_elastic_mod_estimator.py":
        ("0.5", "0.2 0.4 0.6 0.8 1.0 1.2 1.4 1.6 1.8 2.0",
         "1.281 1.683 2.211 2.855 3.609 4.469 5.441 6.528 7.735 9.069"),
    "elkadi/mach4ml, R/Hayes_correction.R":
        ("0.5", "0.2 0.4 0.6 0.8 1.0 1.5 2.0 2.5 3.0 3.5 4.0 5 6 7 8",
         "1.281 1.683 2.211 2.855 3.609 5.970 9.069 13 17.86 23.74 30.75 48.47 71.75 101.27 137.7"),
    "Corneliox/Indenter_LabView2Python, youngs_modulus.py":
        ("0.45", "0.2 0.4 0.6 0.8 1.0 1.5 2.0 2.5 3.0 3.5 4.0 5.0 6.0 7.0 8.0",
         "1.252 1.599 2.031 2.532 3.085 4.638 6.380 8.265 10.26 12.32 14.45 18.80 23.23 27.69 32.15"),
}


def half_unit(text: str) -> float:
    return 0.5 * 10.0 ** Decimal(text).as_tuple().exponent


# --------------------------------------------------------------------------- models
def test_scalar_in_float_out_array_in_array_out():
    layer = BondedLayer(0.3)
    k = flat_punch_stiffness(layer, 2.0)
    assert isinstance(k, float) and k == pytest.approx(4.35324429, rel=1e-8)
    arr = flat_punch_stiffness(layer, np.array([[5.0, 10.0], [20.0, 40.0]]), "thin")
    assert arr.shape == (2, 2)
    assert flat_punch_stiffness(layer, [0.1, 0.2], "thick").shape == (2,)


@pytest.mark.parametrize("layer", [BondedLayer(-0.5), BondedLayer(0.3), BondedLayer(0.45), FrictionlessLayer(),
                                   IncompressibleLayer()], ids=str)
def test_thin_and_thick_agree_with_exact_within_their_estimates(layer):
    thin_x = np.array([20.0, 50.0])
    ex = flat_punch_stiffness(layer, thin_x)
    th = flat_punch_stiffness(layer, thin_x, "thin", max_error=1e-2)
    assert np.all(np.abs(th / ex - 1) < 1e-2)
    thick_x = np.array([0.1, 0.3, 0.5])
    ex = flat_punch_stiffness(layer, thick_x)
    tk = flat_punch_stiffness(layer, thick_x, "thick", max_error=1e-2)
    assert np.all(np.abs(tk / ex - 1) < 1e-2)


def test_auto_takes_the_cheapest_admissible_model():
    layer = BondedLayer(0.3)
    assert flat_punch_contact(layer, 0.2, 1.0, w0=1e-3).model == "thick"
    assert flat_punch_contact(layer, 2.0, 1.0, w0=1e-3).model == "exact"
    assert flat_punch_contact(layer, 30.0, 1.0, w0=1e-3).model == "thin"
    assert flat_punch_contact(layer, 2.0, 1.0, w0=1e-3, max_error=1e-1).model == "thin"
    # beyond the exact solver's limit the thin model still answers, with its small error
    assert flat_punch_contact(layer, 500.0, 1.0, w0=1e-3).model == "thin"
    x = np.array([0.1, 1.0, 2.0, 30.0, 500.0])
    k = flat_punch_stiffness(layer, x, "auto", max_error=1e-6)
    ref = [flat_punch_stiffness(layer, v) for v in x[:4]]
    assert k[:4] == pytest.approx(ref, rel=1e-6)


def test_half_space_only_exactly():
    assert flat_punch_stiffness(HalfSpace(), 1.0) == 1.0
    assert flat_punch_stiffness(HalfSpace(), 1.0, "auto") == 1.0
    with pytest.raises(ValueError, match="finite thickness"):
        flat_punch_stiffness(HalfSpace(), 1.0, "thin")


def test_force_and_depth_are_inverse():
    """P = 4 mu a w0 kappa/(1 - nu) (F.1), and back."""
    layer = BondedLayer(0.3)
    res = flat_punch_contact(layer, radius=2.0, H=1.0, w0=0.01, mu=3.0, model="exact")
    assert res.force == pytest.approx(4 * 3.0 * 2.0 * 0.01 * res.kappa / 0.7, rel=1e-15)
    back = flat_punch_contact(layer, radius=2.0, H=1.0, force=res.force, mu=3.0, model="exact")
    assert back.w0 == pytest.approx(0.01, rel=1e-14)
    assert res.stiffness == pytest.approx(res.force / res.w0, rel=1e-14)
    assert "FlatPunchResult" in str(res) and r"\tag{F.1}" in res.latex()
    fr = flat_punch_contact(FrictionlessLayer(), 2.0, 1.0, w0=0.01, nu=0.25, model="exact")
    assert fr.nu == 0.25 and fr.force == pytest.approx(4 * 2.0 * 0.01 * fr.kappa / 0.75, rel=1e-15)


# --------------------------------------------------------------------------- errors
@pytest.mark.parametrize("call, match", [
    (lambda: flat_punch_stiffness(BondedLayer(0.3), 2.0, "thin"),
     r"thin-layer model .* at a/H = 2 has an estimated relative error 1\.3e-02 > max_error = 0\.01"),
    (lambda: flat_punch_stiffness(BondedLayer(0.3), 0.9, "thick"), "thick-layer series .* at a/H = 0.9"),
    (lambda: flat_punch_stiffness(BondedLayer(0.3), 300.0), "exact model is limited to a/H <= 200"),
    (lambda: flat_punch_stiffness(BondedLayer(0.3), 1.0, "fem"), "model must be one of"),
    (lambda: flat_punch_stiffness(BondedLayer(0.3), 0.0), "a_over_H must be finite and positive, got 0.0"),
    (lambda: flat_punch_stiffness(BondedLayer(0.3), [1.0, np.nan], "thin"), "finite and positive, got nan"),
    (lambda: flat_punch_stiffness(BondedLayer(0.3), [], "thin"), "a_over_H is empty"),
    (lambda: flat_punch_stiffness(BondedLayer(0.3), "1.0"), "a_over_H must be a positive number"),
    (lambda: flat_punch_stiffness(BondedLayer(0.3), True), "got a bool"),
    (lambda: flat_punch_stiffness(BondedLayer(0.3), 1.0, max_error=2.0), r"max_error is a relative error in \(0, 1\]"),
    (lambda: flat_punch_stiffness(BondedLayer(), 1.0), "numeric kernel"),
    (lambda: flat_punch_contact(BondedLayer(0.3), 1.0, 1.0), "exactly one of w0"),
    (lambda: flat_punch_contact(FrictionlessLayer(), 1.0, 1.0, w0=1.0), "pass nu="),
    (lambda: flat_punch_contact(BondedLayer(0.3), -1.0, 1.0, w0=1.0), "radius must be a finite positive number"),
])
def test_errors_are_one_line(call, match):
    with pytest.raises((ValueError, TypeError), match=match) as exc:
        call()
    assert "\n" not in str(exc.value)


def test_exact_model_refuses_huge_arrays_before_work():
    with pytest.raises(WorkLimitError, match="number of a/H values"):
        flat_punch_stiffness(BondedLayer(0.3), np.full(5000, 1.0))
    assert flat_punch_stiffness(BondedLayer(0.3), np.full(5000, 30.0), "thin").shape == (5000,)
    assert set(FLAT_PUNCH_MODELS) == {"exact", "thin", "thick", "auto"}


# --------------------------------------------------------------------------- published values
@pytest.mark.parametrize("source", PUBLISHED, ids=lambda s: s.split("/")[0])
def test_published_values_agree_or_are_in_the_errata(source):
    """Each printed kappa agrees with the exact one to its digits, or its row is in the errata registry (entry
    "Hayes 1972" of that source); the printed values are never high, and their deficit grows with a/h."""
    nu, ahs, vals = PUBLISHED[source]
    layer = BondedLayer(float(nu))
    listed = {}
    for e in errata.get("Hayes 1972"):
        if source.split("/")[0] in e.quantity:
            listed = {a: p for a, p in zip(e.printed.split(r",\ "), e.printed.split(r",\ "))}
    assert listed, f"no errata entry names {source}"
    deficits = []
    for a, v in zip(ahs.split(), vals.split()):
        k = flat_punch_stiffness(layer, float(a))
        off = abs(float(v) - k) > half_unit(v)
        assert off == (rf"\kappa({a}) = {v}" in listed), (a, v, k)
        assert float(v) < k + half_unit(v)
        deficits.append(1 - float(v) / k)
    assert deficits[-1] > deficits[1] > 0
    assert deficits[0] < 3e-4  # a/h = 0.2: the normalisation P = 4 mu a w0 kappa/(1 - nu) is the same
