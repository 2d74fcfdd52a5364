"""Guards a user trusts (issue 25 item 4): the depth's sign, the half-space, the regime flags; fit(), solve(), CLI."""
import json
import math
from pathlib import Path

import mpmath
import numpy as np
import pytest
import sympy as sp

from thinlayer import BondedLayer, FrictionlessLayer, Punch, fit, solve
from thinlayer.contact.any_thickness import force_any_thickness
from thinlayer.contact.guards import SIGN_CONVENTION, SMALL_STRAIN, SPHERE_RATIO, regime_flags
from thinlayer.export.cli import main

pytestmark = pytest.mark.xdist_group("afm-laws")  # one worker builds the laws once for the afm tests
DATA = Path(__file__).resolve().parent / "data"


def _hertz(d, R=10.0, E=1.0, nu=0.5):
    return 4.0 / 3.0 * E / (1 - nu**2) * math.sqrt(R) * np.asarray(d) ** 1.5


# ---- the numbers behind the flags, each by an independent route ---------------------------------------------------
def test_sphere_against_paraboloid_is_delta_over_10R():
    """Sneddon (1965) (6.8)-(6.9), the exact sphere on the half-space, solved by mpmath:
    delta = (a/2) ln((R + a)/(R - a)), P/E* = ((a^2 + R^2)/2) ln((R + a)/(R - a)) - a R; against Hertz at the same
    depth the force is lower by delta/(10 R) (what SPHERE_RATIO's 1 % rests on)."""
    mpmath.mp.dps = 30
    for dR in (1e-3, 1e-2, 0.1):
        a = mpmath.findroot(lambda a: a / 2 * mpmath.log((1 + a) / (1 - a)) - dR, mpmath.sqrt(dR))
        Ps = (a**2 + 1) / 2 * mpmath.log((1 + a) / (1 - a)) - a
        rel = float(Ps / (mpmath.mpf(4) / 3 * mpmath.mpf(dR) ** 1.5) - 1)
        assert rel == pytest.approx(-dR / 10, rel=5e-3), dR
    assert SPHERE_RATIO / 10 == pytest.approx(0.01)


def test_neo_hookean_strain_is_first_order():
    """Uniaxial neo-Hookean compression, nominal stress mu (lambda - lambda^-2) against the linear 3 mu (lambda - 1):
    the ratio is 1 + e + O(e^2) at nominal strain e = 1 - lambda (what SMALL_STRAIN's 10 % rests on)."""
    e = sp.symbols("e", positive=True)
    lam = 1 - e
    ratio = sp.series((lam - lam**-2) / (3 * (lam - 1)), e, 0, 2).removeO()
    assert sp.expand(ratio - (1 + e)) == 0
    assert SMALL_STRAIN == 0.1


# ---- fit(): the sign of the depth ---------------------------------------------------------------------------------
def test_tip_position_is_refused_unflipped_and_flipped_when_asked():
    d = np.linspace(0.0, 1.0, 60)
    F = _hertz(d)
    tip_position = 0.3 - d  # nanite's axis: negative into the sample, contact point at 0.3
    for x in (-d, tip_position):
        with pytest.raises(ValueError, match="positive into the sample") as exc:
            fit(x, F, punch=10.0, H=2.0, fit_offset=True)
        assert "\n" not in str(exc.value) and "depth_sign=-1" in str(exc.value)
    r = fit(-d, F, punch=10.0, H=None, depth_sign=-1)
    assert r.E == pytest.approx(1.0, rel=1e-12) and r.depth_sign == -1
    assert np.allclose(r.predict(-d), F, rtol=1e-12)
    with pytest.raises(ValueError, match="after depth_sign=-1"):
        fit(d, F, punch=10.0, H=2.0, depth_sign=-1)
    with pytest.raises(ValueError, match="depth_sign must be 1"):
        fit(d, F, punch=10.0, H=2.0, depth_sign=2)
    assert "negative into the sample" in SIGN_CONVENTION


def test_real_tip_position_unflipped_is_refused():
    """A real curve (afmformats' example, JPK): the tip position as recorded is refused, flipped it fits."""
    nanite = pytest.importorskip("nanite", reason="the extra thinlayer[afm] is not installed (pip install -e .[afm])")
    idnt = nanite.load_group(DATA / "fmt-jpk-fd_spot3-0192.jpk-force")[0]
    idnt.apply_preprocessing(["compute_tip_position", "correct_force_offset", "correct_tip_offset"])
    app = np.asarray(idnt["segment"]) == 0
    x, F = np.asarray(idnt["tip position"])[app], np.asarray(idnt["force"])[app]
    with pytest.raises(ValueError, match="falls as the depth grows|no positive depth"):
        fit(x, F, punch=10e-6, H=None, nu=0.5)
    r = fit(x, F, punch=10e-6, H=None, nu=0.5, depth_sign=-1)
    assert r.E > 0 and r.depth_sign == -1


# ---- the half-space -----------------------------------------------------------------------------------------------
def test_fit_half_space_is_hertz():
    d = np.linspace(0.01, 1.0, 50)
    for H in (None, math.inf):
        r = fit(d, 2.5 * _hertz(d), punch=10.0, H=H)
        assert r.E == pytest.approx(2.5, rel=1e-12) and r.model == "hertz" and math.isinf(r.H)
        assert r.as_dict()["H"] is None and "H      = inf (the half-space)" in str(r)
    with pytest.raises(TypeError, match="fit_H=True"):
        fit(d, _hertz(d), punch=10.0, H=None, fit_H=True)
    with pytest.raises(ValueError, match="paraboloid"):
        fit(d, _hertz(d), punch=Punch.cone(70), H=math.inf)


def test_solve_half_space_is_the_thick_limit_of_the_law():
    """solve(H=None or inf) is Hertz; the any-thickness law (T.7) at chi = 1e-9 gives the same force to 1e-8 (the
    frictionless base's law: the one the flag test builds too)."""
    for H in (None, math.inf):
        ans = solve(BondedLayer(0.5), Punch.paraboloid(10), delta0=0.1, H=H, E=1.0)
        assert ans.model == "half-space" and ans.force == pytest.approx(float(_hertz(0.1)), rel=1e-14)
        assert ans.contact_radius == pytest.approx(1.0, rel=1e-14) and ans.flags == ()
        law = force_any_thickness(0.1, 10.0, 1e9, E=1.0, nu=0.5, base="frictionless")
        assert ans.force == pytest.approx(float(law), rel=1e-8)
        assert ans.max_pressure == pytest.approx(2 * (4 / 3) / (math.pi * 10) * 1.0, rel=1e-6)  # p0 = 2E*a/(pi R)
        assert ans.as_dict()["H"] is None
    inv = solve(BondedLayer(0.5), Punch.paraboloid(10), force=ans.force, H=None, E=1.0)
    assert inv.delta0 == pytest.approx(0.1, rel=1e-12)
    with pytest.raises(ValueError, match="paraboloid"):
        solve(BondedLayer(0.5), Punch.cone(70), delta0=0.1, H=None, E=1.0)


# ---- the regime flags ---------------------------------------------------------------------------------------------
def test_flags_in_fit_and_solve():
    assert regime_flags(0.05, 1.0, 1.0) == ()
    d = np.linspace(0.02, 2.0, 40)
    r = fit(d, force_any_thickness(d, 10.0, 0.5, E=1.0, nu=0.5, base="frictionless"), punch=10.0, H=0.5,
            base="frictionless")
    assert len(r.flags) == 2 and r.flags[0].startswith("delta/H = 4 > 0.1") and "delta/R = 0.2" in r.flags[1]
    assert str(r).count("FLAG:") == 2 and r.as_dict()["flags"] == list(r.flags)
    small = fit(d[:10] * 0.01, _hertz(d[:10] * 0.01), punch=10.0, H=1.0, base="frictionless")
    assert small.flags == () and "FLAG" not in str(small)
    ans = solve(FrictionlessLayer(0.5), Punch.paraboloid(10), delta0=2.0, H=1.0, E=1.0, model="any-thickness")
    assert len(ans.flags) == 2 and "delta/H = 2 > 0.1" in ans.flags[0] and "FLAG: delta/H" in str(ans)
    assert ans.as_dict()["flags"] == list(ans.flags)


# ---- the command line ---------------------------------------------------------------------------------------------
def test_cli_depth_sign_and_half_space(tmp_path, capsys):
    d = np.linspace(0.0, 1.0, 40)
    path = tmp_path / "tip_position.csv"
    path.write_text("tip position,force\n" + "".join(f"{-float(a)!r},{float(b)!r}\n" for a, b in zip(d, _hertz(d))))
    assert main(["fit", str(path), "--R", "10", "--nu", "0.5"]) == 2
    err = capsys.readouterr().err
    assert "positive into the sample" in err and "--depth-sign -1" in err and "Traceback" not in err
    assert main(["fit", str(path), "--R", "10", "--nu", "0.5", "--depth-sign", "-1", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["E"] == pytest.approx(1.0, rel=1e-12) and out["H"] is None and out["depth_sign"] == -1
    assert main(["fit", str(path), "--R", "10", "--nu", "0.5", "--depth-sign", "-1", "--H", "0.5"]) == 0
    text = capsys.readouterr().out
    assert "FLAG: δ/H = 2 > 0.1" in text or "FLAG: delta/H = 2 > 0.1" in text
    assert main(["solve", "--nu", "0.5", "--tip", "paraboloid:R=10", "--delta0", "0.1", "--H", "inf", "--E", "1",
                 "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["model"] == "half-space" and out["H"] is None and out["force"] == pytest.approx(float(_hertz(0.1)))


# ---- a substrate not much stiffer than the layer (issue 25 item 4) -------------------------------------------------
def test_substrate_estimate_is_the_series_compliance():
    """kappa E*_l/E*_s: with kappa = 1 (the half-space limit a/H -> 0) the substrate's share of a flat punch's
    indentation, P/(2 E*_s a) over P/(2 E*_l a) (Boussinesq for both), is E*_l/E*_s exactly."""
    from thinlayer.contact.guards import substrate_estimate

    El, nul, Es, nus = 3.0, 0.5, 50.0, 0.25
    assert substrate_estimate(1.0, El, nul, Es, nus) == pytest.approx((El / (1 - nul**2)) / (Es / (1 - nus**2)),
                                                                      rel=1e-15)
    assert substrate_estimate(2.0, El, nul, Es) > substrate_estimate(2.0, El, nul, Es, 0.3)  # nu_s = 0: largest


def test_substrate_flag_in_solve_fit_and_the_cli(tmp_path, capsys):
    from thinlayer.contact.flat_punch import flat_punch_stiffness
    from thinlayer.contact.guards import SUBSTRATE_ERROR

    tip = Punch.paraboloid(10)
    soft = solve(BondedLayer(0.5), tip, delta0=0.01, H=0.3, E=1e3, substrate_E=2e4)
    stiff = solve(BondedLayer(0.5), tip, delta0=0.01, H=0.3, E=1e3, substrate_E=7e10)  # a gel on glass
    assert [f for f in stiff.flags if f.startswith("substrate")] == []
    (flag,) = [f for f in soft.flags if f.startswith("substrate")]
    kappa = float(flat_punch_stiffness(BondedLayer(0.5), soft.contact_radius / 0.3))
    assert f"= {kappa * (1e3 / 0.75) / 2e4:.2g} > {SUBSTRATE_ERROR:g}" in flag and "FLAG: substrate" in str(soft)
    assert solve(BondedLayer(0.5), tip, delta0=0.01, H=None, E=1e3, substrate_E=1.0).flags == ()  # the half-space
    ell = solve(BondedLayer(0.3), Punch.elliptic_paraboloid(4, 1), delta0=0.5, H=0.05, E=2.6, substrate_E=2.6)
    assert ell.contact_radius is None and any(f.startswith("substrate") for f in ell.flags)  # equal-area radius
    d = np.linspace(0.002, 0.05, 30)
    P = force_any_thickness(d, 10.0, 0.3, E=1e3, nu=0.5)
    assert any(f.startswith("substrate") for f in fit(d, P, punch=10.0, H=0.3, substrate_E=2e4).flags)
    assert not any(f.startswith("substrate") for f in fit(d, P, punch=10.0, H=0.3, substrate_E=7e10).flags)
    for bad, match in ((-1.0, "substrate_E must be a positive"), ("x", "substrate_E must be a positive")):
        with pytest.raises(ValueError, match=match) as exc:
            solve(BondedLayer(0.5), tip, delta0=0.01, H=0.3, E=1e3, substrate_E=bad)
        assert "\n" not in str(exc.value)
    with pytest.raises(ValueError, match="substrate_nu must be a number in"):
        fit(d, P, punch=10.0, H=0.3, substrate_E=2e4, substrate_nu=0.7)
    with pytest.raises(TypeError, match="non-adhesive"):
        solve(BondedLayer(0.5), tip, delta0=0.01, H=0.3, E=1e3, substrate_E=2e4, work_of_adhesion=0.01)
    assert main(["solve", "--nu", "0.5", "--tip", "paraboloid:R=10", "--delta0", "0.01", "--H", "0.3", "--E",
                 "1000", "--substrate-E", "20000"]) == 0
    assert "FLAG: substrate" in capsys.readouterr().out
    path = tmp_path / "curve.csv"
    path.write_text("depth,force\n" + "".join(f"{float(a)!r},{float(b)!r}\n" for a, b in zip(d, P)))
    assert main(["fit", str(path), "--R", "10", "--nu", "0.5", "--H", "0.3", "--substrate-E", "2e4"]) == 0
    assert "FLAG: substrate" in capsys.readouterr().out
    # an instrument file (thinlayer.fit_curve): the real JPK curve (E ~ 15 kPa, 0.24 um deep) on a 1 um layer
    jpk = str(DATA / "fmt-jpk-fd_spot3-0192.jpk-force")
    assert main(["fit", jpk, "--R", "10e-6", "--nu", "0.5", "--H", "1e-6", "--substrate-E", "2e5"]) == 0
    assert "FLAG: substrate" in capsys.readouterr().out
    assert main(["fit", jpk, "--R", "10e-6", "--nu", "0.5", "--H", "1e-6", "--substrate-E", "7e10"]) == 0
    assert "FLAG: substrate" not in capsys.readouterr().out
