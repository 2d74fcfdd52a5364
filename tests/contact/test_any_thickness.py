"""The any-thickness law of the sphere: against the direct solver, the thick series (T.7) and the thin models.

The table is data (direct solutions), so the law is checked against direct solutions it was not built from
(off-node chi and nu), against the two asymptotic limits derived independently (Hertz; the compressible and
incompressible thin-layer forces (1.8), (I.11)), and its generation is re-run at a coarse size.
"""
import math
import os

import numpy as np
import pytest

from thinlayer import BondedLayer, FrictionlessLayer, Punch
from thinlayer.asymptotics.incompressible import two_term_sphere
from thinlayer.asymptotics.thick_layer import thick_sphere_series
from thinlayer.contact._table_build import SMALL, build_table, direct_ratios
from thinlayer.contact.any_thickness import (
    CHI_HI,
    CHI_LO,
    TABLE_PATH,
    NotTabulatedError,
    anchor,
    any_thickness_fields,
    any_thickness_law,
    build_law,
    force_any_thickness,
)
from thinlayer.contact.solve import Indentation
from thinlayer.layers.kernels import IncompressibleLayer
from thinlayer.numerics import solve_axisymmetric

SLOW = os.environ.get("THINLAYER_SLOW") == "1"


def direct(nu, base, chi):
    return direct_ratios(nu, base, chi)[:2]


# --------------------------------------------------------------------------- the pieces
@pytest.mark.parametrize("nu", [0.3, 0.42, 0.499, 0.5])
def test_two_term_anchor_is_the_two_term_model(nu):
    """The anchor's own (I.11) (bisection on c) against thinlayer.asymptotics.incompressible.two_term_sphere."""
    layer = IncompressibleLayer() if nu == 0.5 else BondedLayer(nu)
    model = two_term_sphere(layer)
    chi = np.array([0.3, 3.0, 40.0])
    w, g = anchor(chi, nu, "bonded")
    for x, wi, gi in zip(chi, w, g):
        v = model.evaluate(x * x, 1.0, 1.0, 1.0, edge_correction=False)
        assert wi == pytest.approx(v.force / (8 / 3 / (1 - nu) * x**3), rel=1e-12)
        assert gi == pytest.approx(v.radius / x, rel=1e-12)


def test_table_is_packaged_and_regenerates(tmp_path):
    """Coarse re-run of the generator on chi in [0.2, 2]; the packaged law agrees with its direct solutions."""
    assert TABLE_PATH.exists()
    out = tmp_path / "coarse.npz"
    data = build_table((2, 2, SMALL[2]), out, validate=False, chi_range=(CHI_LO, 2.0))
    with np.load(out) as f:
        assert set(f.files) >= {"chi", "low_y", "high_y", "fric_y", "high_nu"}
        assert np.array_equal(f["low_y"], data["low_y"])
    with pytest.raises(FileExistsError):
        build_table((2, 2, 2), out, validate=False, chi_range=(CHI_LO, 0.3))
    # every coarse node is an off-node point of the packaged table
    for i, x in enumerate(data["chi"]):
        for nu, y in zip(data["low_nu"], data["low_y"][i]):
            law = any_thickness_law(float(nu))
            w, _ = anchor(np.array([x]), float(nu), "bonded")
            P_direct = math.exp(y) * (1 + w[0])
            assert law.ratios(x)[0] == pytest.approx(P_direct, rel=max(3 * float(law.error_estimate(x)[0]), 1e-6))


# --------------------------------------------------------------------------- accuracy
@pytest.mark.parametrize("nu,base,chi", [
    (0.5, "bonded", 0.11), (0.5, "bonded", 0.7), (0.5, "bonded", 7.3), (0.4987, "bonded", 2.2),
    (0.47, "bonded", 13.0), (0.33, "bonded", 0.9), (0.12, "bonded", 3.3), (-0.6, "bonded", 1.7),
    (0.3, "frictionless", 0.45), (0.3, "frictionless", 5.5),
])
def test_law_against_direct_solver(nu, base, chi):
    P, c = direct(nu, base, chi)
    law = any_thickness_law(nu, base)
    Pl, cl = law.ratios(chi)
    eP, ec = law.error_estimate(chi)
    assert abs(Pl / P - 1) <= max(eP, 1e-9) and eP <= 1e-3
    assert abs(cl / c - 1) <= max(ec, 1e-9) and ec <= 1e-3


def test_limits():
    """chi -> 0: Hertz and the series (T.7); chi -> oo: the thin-layer forces (1.8), (I.11) and radii."""
    for nu, base in ((0.5, "bonded"), (0.3, "bonded"), (0.3, "frictionless")):
        law = any_thickness_law(nu, base)
        layer = FrictionlessLayer() if base == "frictionless" else IncompressibleLayer() if nu == 0.5 \
            else BondedLayer(nu)
        fc, rc = thick_sphere_series(16).coefficients(layer)
        for x in (1e-4, 0.003, 0.15):
            P, c = law.ratios(x)
            eP, ec = law.error_estimate(x)
            assert abs(P / np.polynomial.polynomial.polyval(x, fc) - 1) < min(eP, 1e-6)
            assert abs(c / np.polynomial.polynomial.polyval(x, rc) - 1) < min(ec, 1e-6)
        P, c = law.ratios(1e5)
        if nu == 0.5:  # P = 2 pi mu R^2 delta^3/H^3 (I.11), c = 2 sqrt(R delta)
            assert P * 16 / 3 == pytest.approx(2 * math.pi * 1e15, rel=1e-4)
            assert c == pytest.approx(2.0, rel=1e-4)
        else:  # P = pi vartheta R delta^2/(A H) (1.8), c = sqrt(2 R delta)
            A = 0.5 if base == "frictionless" else (0.5 - nu) / (1 - nu) ** 2
            assert P * 8 / 3 == pytest.approx(math.pi * 1e5 / A, rel=1e-4)
            assert c == pytest.approx(math.sqrt(2.0), rel=1e-4)


def test_monotone_and_smooth():
    chi = np.geomspace(1e-3, 1e6, 4000)
    for nu, base in ((0.5, "bonded"), (0.499, "bonded"), (0.2, "bonded"), (0.3, "frictionless")):
        P, c = any_thickness_law(nu, base).ratios(chi)
        assert np.all(np.diff(P * chi**3) > 0)  # the force grows with the depth
        assert np.all(np.isfinite(c)) and np.all((c > 0.99) & (c < 2.01))


def test_force_vectorised_and_units():
    d = np.array([[-1.0, 0.0, 0.01], [0.1, 1.0, 10.0]])
    P = force_any_thickness(d, R=2.0, H=0.5, E=3.0, nu=0.45)
    assert P.shape == d.shape and P[0, 0] == 0 and P[0, 1] == 0
    mu = 3.0 / (2 * 1.45)
    ratio, _ = any_thickness_law(0.45).ratios(np.sqrt(2.0 * d[1]) / 0.5)
    assert np.allclose(P[1], 8 / 3 * mu / 0.55 * math.sqrt(2.0) * d[1] ** 1.5 * ratio, rtol=1e-12)
    assert np.allclose(force_any_thickness(d, 2.0, 0.5, mu=mu, nu=0.45), P, rtol=1e-14)
    with pytest.raises(ValueError, match="nu must lie"):
        force_any_thickness(d, 1.0, 1.0, mu=1.0, nu=0.6)
    with pytest.raises(ValueError, match="base must be"):
        force_any_thickness(d, 1.0, 1.0, mu=1.0, base="glued")
    with pytest.raises(TypeError, match="exactly one"):
        force_any_thickness(d, 1.0, 1.0, mu=1.0, E=2.0)
    with pytest.raises(ValueError, match="finite"):
        force_any_thickness([np.nan], 1.0, 1.0, mu=1.0)


# --------------------------------------------------------------------------- the front-door fields
def test_fields_build_an_indentation_and_invert():
    layer, punch = BondedLayer(0.45), Punch.paraboloid(10)
    ans = Indentation(**any_thickness_fields(layer, punch, delta0=0.3, H=1.2, E=2.0))
    res = solve_axisymmetric(layer, punch, 0.3, H=1.2, mu=2.0 / 2.9)
    assert ans.model == "any-thickness" and ans.force == pytest.approx(res.force, rel=1e-3)
    assert ans.contact_radius == pytest.approx(res.radius, rel=1e-3)
    assert ans.error_estimate["force"] <= 1e-3 and "chi" in ans.reason
    assert ans.pressure(0.0, 0.0) == pytest.approx(float(res.pressure_at(np.array([0.0]))[0]), rel=1e-8)
    back = any_thickness_fields(layer, punch, force=ans.force, H=1.2, E=2.0)
    assert back["delta0"] == pytest.approx(0.3, rel=1e-10)
    assert "any-thickness" in str(ans)


def test_fields_for_other_punches_and_errors():
    punch = Punch("x_1**2/2 + x_2**2/2 + (x_1**2 + x_2**2)**2")
    f = any_thickness_fields(BondedLayer(0.3), punch, delta0=0.01, H=5.0, mu=1.0)
    res = solve_axisymmetric(BondedLayer(0.3), punch, 0.01, H=5.0, mu=1.0)
    assert f["force"] == pytest.approx(res.force, rel=1e-7) and "thick-layer series" in f["reason"]
    with pytest.raises(NotTabulatedError, match="model='auto'"):
        any_thickness_fields(BondedLayer(0.3), punch, delta0=1.0, H=0.5, mu=1.0)
    with pytest.raises(NotTabulatedError):
        any_thickness_fields(BondedLayer(0.3), Punch.elliptic_paraboloid(2, 1), delta0=0.1, H=1.0, mu=1.0)
    with pytest.raises(TypeError, match="exactly one of delta0"):
        any_thickness_fields(BondedLayer(0.3), Punch.paraboloid(1), H=1.0, mu=1.0)
    with pytest.raises(TypeError, match="BondedLayer"):
        any_thickness_fields(BondedLayer(), Punch.paraboloid(1), delta0=0.1, H=1.0, mu=1.0)


def test_packaged_validation_points_are_within_1e3():
    """The validation points stored with the table (direct solutions off the nodes, all nu and chi)."""
    with np.load(TABLE_PATH) as f:
        err = f["check_err"]
        chk = f["check"]
    assert err.shape[0] == chk.shape[0] >= 150
    assert err[:, 2].max() < 1e-3 and err[:, 3].max() < 1e-3


@pytest.mark.skipif(not SLOW, reason="slow: set THINLAYER_SLOW=1 (about 60 direct solutions)")
def test_law_against_direct_solver_dense():
    rng = np.random.default_rng(7)
    worst = 0.0
    for _ in range(60):
        base = "frictionless" if rng.uniform() < 0.2 else "bonded"
        nu = float(0.5 - 0.6 * rng.uniform() ** 3) if base == "bonded" else 0.3
        chi = float(np.exp(rng.uniform(math.log(0.05), math.log(60.0))))
        P, c = direct(nu, base, chi)
        law = build_law({k: v for k, v in np.load(TABLE_PATH).items()}, nu, base)
        Pl, cl = law.ratios(chi)
        eP, ec = law.error_estimate(chi)
        worst = max(worst, abs(Pl / P - 1), abs(cl / c - 1))
        assert abs(Pl / P - 1) <= max(eP, 1e-9) and abs(cl / c - 1) <= max(ec, 1e-9)
    assert worst < 1e-3
    assert CHI_HI == 64.0


# --------------------------------------------------------------------------- standalone code
def test_generated_numpy_module_and_c(tmp_path):
    import ctypes
    import importlib.util
    import shutil
    import subprocess

    from thinlayer.contact.any_thickness import any_thickness_source

    nu, R, H, mu = 0.47, 3.0, 0.8, 1.7
    law = any_thickness_law(nu)
    d = np.array([1e-9, 1e-4, 0.01, 0.3, 2.0, 50.0, 4e3, 1e18])
    chi = np.sqrt(R * d) / H
    Pr, cr = law.ratios(chi)
    P_law = 8 / 3 * mu / (1 - nu) * math.sqrt(R) * d**1.5 * Pr
    c_law = np.sqrt(R * d) * cr
    py = tmp_path / "at_law.py"
    py.write_text(any_thickness_source(nu, language="python"))
    spec = importlib.util.spec_from_file_location("at_law", py)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    assert np.allclose(mod.force(d, R, H, mu), P_law, rtol=1e-6)
    assert np.allclose(mod.radius(d, R, H, mu), c_law, rtol=1e-6)
    assert mod.force(np.array([-1.0, 0.0]), R, H, mu).tolist() == [0.0, 0.0]
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        pytest.skip("no C compiler")
    src = tmp_path / "at_law.c"
    src.write_text(any_thickness_source(nu, language="c"))
    lib = tmp_path / "at_law.so"
    subprocess.run([cc, "-std=c99", "-O2", "-Wall", "-Werror", "-shared", "-fPIC", str(src), "-o", str(lib), "-lm"],
                   check=True, capture_output=True, stdin=subprocess.DEVNULL)
    so = ctypes.CDLL(str(lib))
    for name in ("thinlayer_any_thickness_force", "thinlayer_any_thickness_radius"):
        getattr(so, name).restype = ctypes.c_double
        getattr(so, name).argtypes = [ctypes.c_double] * 4
    Pc = np.array([so.thinlayer_any_thickness_force(x, R, H, mu) for x in d])
    cc_ = np.array([so.thinlayer_any_thickness_radius(x, R, H, mu) for x in d])
    assert np.allclose(Pc, mod.force(d, R, H, mu), rtol=1e-12) and np.allclose(cc_, c_law, rtol=1e-6)
