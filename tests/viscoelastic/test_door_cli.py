"""``thinlayer visco solve|fit|oscillation`` (issue 27 item 4), run in-process through ``thinlayer.export.cli.main``.

The numbers are compared with the library doors they print (tested against independent references in
test_door_solve.py, test_visco_fit.py, test_door_oscillation.py); here: the files read, the formats, the exit codes.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from thinlayer import BondedLayer, Punch, viscoelastic_force
from thinlayer.contact.materials import StandardLinearSolid
from thinlayer.export.cli import main

SET = ["--tip", "paraboloid:R=10", "--nu", "0.5", "--H", "1"]
SLS = "sls:E0=3,Einf=1,tau=0.2"


@pytest.fixture()
def ramp(tmp_path: Path) -> Path:
    t = np.linspace(0.0, 1.0, 41)
    f = tmp_path / "ramp.csv"
    f.write_text("time,depth\n# a ramp\n" + "".join(f"{a:.17g},{0.1 * a:.17g}\n" for a in t))
    return f


def test_solve_text_csv_json(ramp, capsys):
    assert main(["visco", "solve", *SET, "--material", SLS, "--history", str(ramp), "--format", "csv"]) == 0
    rows = capsys.readouterr().out.strip().splitlines()
    assert rows[0] == "time,depth,force,contact_radius,valid" and len(rows) == 42
    t = np.linspace(0.0, 1.0, 41)
    ref = viscoelastic_force(BondedLayer(0.5), Punch.paraboloid(10.0), 1.0, StandardLinearSolid(3, 1, 0.2), t, 0.1 * t)
    assert float(rows[-1].split(",")[2]) == pytest.approx(ref.force[-1], rel=1e-9)
    assert main(["visco", "solve", *SET, "--material", SLS, "--history", str(ramp), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["control"] == "depth" and out["force"][-1] == pytest.approx(ref.force[-1], rel=1e-12)
    assert main(["visco", "solve", *SET, "--material", SLS, "--history", str(ramp)]) == 0
    assert "lee-radok" in capsys.readouterr().out


def test_fit_curves_and_oscillation(tmp_path, capsys):
    t = np.linspace(0.0, 1.0, 201)
    d = 0.1 * t
    P = viscoelastic_force(BondedLayer(0.5), Punch.paraboloid(10.0), 1.0, StandardLinearSolid(3, 1, 0.2), t, d).force
    f = tmp_path / "c.csv"
    f.write_text("".join(f"{a:.17g},{b:.17g},{c:.17g}\n" for a, b, c in zip(t, d, P)))
    assert main(["visco", "fit", *SET, "--material", "sls", "--curves", str(f), "--json"]) == 0
    vals = json.loads(capsys.readouterr().out)["values"]
    assert vals["E0"] == pytest.approx(3.0, rel=1e-6) and vals["tau"] == pytest.approx(0.2, rel=1e-6)
    assert main(["visco", "oscillation", *SET, "--material", SLS, "--delta0", "0.13", "--amplitude", "1e-3",
                 "--omega", "0.5", "5", "50", "--json"]) == 0
    osc = json.loads(capsys.readouterr().out)
    g = tmp_path / "k.csv"
    g.write_text("omega,K_real,K_imag\n" + "".join(f"{w:.17g},{a:.17g},{b:.17g}\n" for w, a, b in zip(
        osc["omega"], osc["dynamic_stiffness_real"], osc["dynamic_stiffness_imag"])))
    assert main(["visco", "fit", *SET, "--oscillation", str(g), "--delta0", "0.13"]) == 0
    text = capsys.readouterr().out
    assert "E0     = 3" in text and "oscillation" in text


@pytest.mark.parametrize("extra,match", [
    (["solve", "--material", "sls:E0=3,Einf=__import__('os').system('touch {m}'),tau=1"], "not a number"),
    (["solve", "--material", "maxwell:E=1"], "KIND:key=value"),
    (["solve", "--material", "sls:E0=1,Einf=3,tau=1"], "must not exceed"),
    (["solve", "--material", "prony:Einf=1,E1=2"], "tau1"),
    (["solve", "--material", "kv:E=1,eta=1,zeta=2"], "unknown key"),
    (["solve", "--material", SLS, "--history", "{bad}"], "not a number"),
    (["solve", "--material", SLS, "--history", "{missing}"], "No such file"),
    (["fit", "--curves", "{ramp}"], "columns"),
    (["fit", "--oscillation", "{ramp}"], "--delta0"),
    (["fit"], "exactly one"),
])
def test_bad_input_exit_2_one_line(extra, match, ramp, tmp_path, capsys):
    marker = tmp_path / "marker"
    bad = tmp_path / "bad.csv"
    bad.write_text("time,depth\n0,0\n1,zz\n")
    args = [a.format(m=marker, bad=bad, missing=tmp_path / "none.csv", ramp=ramp) for a in extra]
    args = [args[0], *SET, *args[1:]]
    if args[0] == "solve" and "--history" not in args:
        args += ["--history", str(ramp)]
    assert main(["visco", *args]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and match in err and "Traceback" not in err
    assert not marker.exists()
