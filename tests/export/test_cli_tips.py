"""The tip options of ``thinlayer solve`` and ``thinlayer fit`` (issue 24 item 6): ``--cone ANGLE``, ``--pyramid ANGLE
--sides N``, ``--sphere R``, ``--blunted-cone R ANGLE``, ``--power-law C N``, built through the tip registry."""
from __future__ import annotations

import json

import pytest

import thinlayer as tl
from thinlayer.export.cli import main
from thinlayer.punch import TIPS

SOLVE = ["solve", "--nu", "0.3", "--delta0", "1", "--H", "0.1", "--mu", "1", "--json"]


@pytest.mark.parametrize("option,tip", [(["--cone", "70"], tl.Punch.cone(70)),
                                        (["--blunted-cone", "0.5", "70"], tl.Punch.blunted_cone(0.5, 70)),
                                        (["--power-law", "1", "1.5"], tl.Punch.power_law(1, 1.5))])
def test_solve_tip_options_are_the_registry_tips(option, tip, capsys):
    assert main([*SOLVE, *option]) == 0
    out = json.loads(capsys.readouterr().out)
    ans = tl.solve(tl.BondedLayer(0.3), tip, delta0=1.0, H=0.1, mu=1.0)
    assert out["force"] == pytest.approx(ans.force, rel=1e-12) and out["model"] == ans.model == "tip-law"


def test_solve_sphere_option_is_the_exact_sphere(capsys):
    assert main(["solve", "--nu", "0.3", "--delta0", "0.3", "--H", "0.1", "--mu", "1", "--json", "--sphere", "10"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["force"] == pytest.approx(tl.solve(tl.BondedLayer(0.3), tl.Punch.sphere(10), delta0=0.3, H=0.1,
                                                  mu=1.0).force, rel=1e-12)


@pytest.mark.parametrize("option,words", [
    (["--cone", "90"], "--cone 90: the half-angle must lie strictly between 0 and 90"),
    (["--cone", "0"], "--cone 0: the half-angle"),
    (["--cone", "-5"], "--cone -5: the half-angle"),
    (["--sphere", "0"], "--sphere 0: the R must be a positive"),
    (["--sphere", "-2"], "--sphere -2: the R must be a positive"),
    (["--blunted-cone", "-1", "70"], "--blunted-cone -1 70"),
    (["--blunted-cone", "1", "95"], "--blunted-cone 1 95: the half-angle"),
    (["--power-law", "1", "0.5"], "--power-law 1 0.5"),
    (["--cone", "70", "--sphere", "3"], "got --cone and --sphere"),
    (["--cone", "70", "--tip", "paraboloid:R=1"], "got --tip and --cone"),
    (["--cone", "70", "--sides", "3"], "--sides goes with --pyramid only"),
    (["--cone", "abc"], "'abc' is not a number"),
])
def test_bad_tip_values_are_one_line_exit_2(option, words, capsys):
    assert main([*SOLVE, *option]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    assert words in err, err


@pytest.mark.parametrize("sides", [3, 4])
def test_pyramid_option_goes_through_the_registry(sides, capsys):
    """thinlayer solve --pyramid 35 --sides N: exit 0, the pyramid's thin-layer law (its solve() answer)."""
    assert "pyramid" in TIPS
    args = ["solve", "--nu", "0.3", "--delta0", "1", "--H", "0.05", "--mu", "1", "--json"]
    assert main([*args, "--pyramid", "35", "--sides", str(sides)]) == 0
    out = json.loads(capsys.readouterr().out)
    ans = tl.solve(tl.BondedLayer(0.3), tl.Punch.pyramid(35, sides), delta0=1.0, H=0.05, mu=1.0)
    assert out["model"] == ans.model == "tip-law"
    assert out["force"] == pytest.approx(ans.force, rel=1e-12) and out["force"] > 0
    assert main([*args, "--pyramid", "35"]) == 0  # --sides defaults to 4
    assert json.loads(capsys.readouterr().out)["force"] == pytest.approx(
        tl.solve(tl.BondedLayer(0.3), tl.Punch.pyramid(35, 4), delta0=1.0, H=0.05, mu=1.0).force, rel=1e-12)


def test_pyramid_with_five_sides_is_one_line_exit_2(capsys):
    assert main([*SOLVE, "--pyramid", "35", "--sides", "5"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    assert "--sides 5: a pyramid has 3 or 4 sides" in err, err


def test_fit_pyramid_option(tmp_path, capsys):
    """thinlayer fit --pyramid 35: E = 2.6 from a curve of the direct solver (solve_2d, bonded nu = 0.3,
    H/a = 0.1 .. 0.14) within the law's estimate, the tip named in words."""
    import numpy as np

    from thinlayer.numerics import solve_2d

    tip, H = tl.Punch.pyramid(35, 4), 0.07
    d = np.array([0.7, 0.85, 1.0])
    P = []
    for x in d:
        ext = 1.05 * float(np.abs(tip.polygon(x)).max()) + 2.5 * H
        P.append(solve_2d(tl.BondedLayer(0.3), tip, delta0=float(x), H=H, n=int(2 * ext / (H / 6)) + 1, extent=ext,
                          tol=1e-10).force)
    path = tmp_path / "curve.csv"
    path.write_text("".join(f"{float(a)!r},{float(b)!r}\n" for a, b in zip(d, P)))
    assert main(["fit", str(path), "--pyramid", "35", "--H", "0.07", "--nu", "0.3", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["model"] == "tip-law" and out["R"] is None and out["tip"] == "4-sided pyramid, face angle 35 deg"
    assert out["valid"] and abs(out["E"] / 2.6 - 1) <= out["model_error"] < 0.1, out
    assert main(["fit", str(path), "--pyramid", "35", "--H", "0.07", "--nu", "0.3"]) == 0
    text = capsys.readouterr().out
    assert "fit of E by the tip-law model: 4-sided pyramid, face angle 35 deg" in text, text


def test_fit_tip_options(tmp_path, capsys):
    """thinlayer fit --cone: the tip law's E on a curve of the direct solver (E = 3) within its estimate."""
    import numpy as np

    from thinlayer.numerics import solve_axisymmetric

    d = np.array([0.5, 0.7, 0.9, 1.1])
    P = [solve_axisymmetric(tl.BondedLayer(0.3), tl.Punch.cone(70), x, H=0.2, mu=3 / 2.6, error_estimate=False).force
         for x in d]
    path = tmp_path / "curve.csv"
    path.write_text("".join(f"{float(a)!r},{float(b)!r}\n" for a, b in zip(d, P)))
    assert main(["fit", str(path), "--cone", "70", "--H", "0.2", "--nu", "0.3", "--json", "--model", "tip-law"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["model"] == "tip-law" and out["R"] is None and out["tip"] == "cone half_angle = 70"
    assert abs(out["E"] / 3 - 1) <= out["model_error"] < 0.05
    # the default: the cone's any-thickness law (T.9), within its own estimate
    assert main(["fit", str(path), "--cone", "70", "--H", "0.2", "--nu", "0.3", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["model"] == "any-thickness" and abs(out["E"] / 3 - 1) <= out["model_error"] < 1e-3
    assert main(["fit", str(path), "--cone", "70", "--R", "3", "--H", "0.2", "--nu", "0.3"]) == 2
    assert "got --R and --cone" in capsys.readouterr().err
    assert main(["fit", str(path), "--H", "0.2", "--nu", "0.3"]) == 2
    assert main(["fit", str(path), "--cone", "70", "--H", "0.2", "--nu", "0.3", "--model", "hertz"]) == 2
    err = capsys.readouterr().err
    # two commands, one line each
    assert "models that fit it: tip-law, any-thickness, direct" in err and len(err.strip().splitlines()) == 2
