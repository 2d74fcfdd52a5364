"""``thinlayer fit``: the CSV reader, the JSON output, one-line errors and output safety."""
import argparse
import json

import numpy as np
import pytest

from thinlayer.contact.any_thickness import force_any_thickness
from thinlayer.export.fit_cli import add_fit_parser, cmd_fit, read_curve
from thinlayer.validation.output import OutputExistsError


def parse(argv):
    ap = argparse.ArgumentParser(prog="thinlayer")
    sub = ap.add_subparsers(dest="cmd", required=True)
    add_fit_parser(sub, argparse.RawDescriptionHelpFormatter)
    return ap.parse_args(["fit", *argv])


@pytest.fixture
def curve(tmp_path):
    d = np.linspace(0.02, 1.0, 40)
    P = force_any_thickness(d, 5.0, 1.5, E=2.0, nu=0.5)
    path = tmp_path / "curve.csv"
    lines = ["# AFM curve, um and nN", "depth,force"] + [f"{float(a)!r},{float(b)!r}" for a, b in zip(d, P)] + [""]
    path.write_text("\n".join(lines))
    return path


def test_fit_json(curve, capsys):
    args = parse([str(curve), "--R", "5", "--H", "1.5", "--nu", "0.5", "--json"])
    assert args.func is cmd_fit
    assert cmd_fit(args) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["E"] == pytest.approx(2.0, rel=1e-9) and out["model"] == "any-thickness" and out["n_points"] == 40
    assert out["file"] == str(curve)


def test_columns_by_name_and_whitespace(tmp_path, capsys):
    path = tmp_path / "c.txt"
    d = np.linspace(0.05, 1.0, 10)
    P = force_any_thickness(d, 2.0, 1.0, E=1.0, nu=0.3)
    rows = [f"{i} {float(p)!r} {float(x)!r}" for i, (x, p) in enumerate(zip(d, P))]
    path.write_text("time force depth\n" + "\n".join(rows))
    assert cmd_fit(parse([str(path), "--columns", "depth,force", "--R", "2", "--H", "1", "--nu", "0.3"])) == 0
    assert "E      = 1" in capsys.readouterr().out
    assert np.allclose(read_curve(path, "2,1")[0], d)


def test_bad_cells_and_missing_data(tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("0.1,1.0\n0.2,__import__('os')\n")
    with pytest.raises(ValueError, match="row 2, column 1"):
        read_curve(path)
    path.write_text("0.1,1.0\n0.2,inf\n")
    with pytest.raises(ValueError, match="not a finite number"):
        read_curve(path)
    path.write_text("# nothing\n")
    with pytest.raises(ValueError, match="no data rows"):
        read_curve(path)
    with pytest.raises(ValueError, match="no such file"):
        read_curve(tmp_path / "missing.csv")
    path.write_text("a,b\n0.1,0.0\n0.2,0.0\n0.3,0.0\n")
    with pytest.raises(ValueError, match="no column 'depth'"):
        read_curve(path, "depth,force")
    with pytest.raises(ValueError, match="no positive force"):
        cmd_fit(parse([str(path), "--R", "1", "--H", "1", "--nu", "0.3"]))


def test_out_is_never_overwritten_silently(curve, tmp_path, capsys):
    out = tmp_path / "fit.json"
    out.write_text("keep me")
    with pytest.raises(OutputExistsError):
        cmd_fit(parse([str(curve), "--R", "5", "--H", "1.5", "--nu", "0.5", "--json", "--out", str(out)]))
    assert out.read_text() == "keep me"
    cmd_fit(parse([str(curve), "--R", "5", "--H", "1.5", "--nu", "0.5", "--json", "--out", str(out), "--overwrite"]))
    assert json.loads(out.read_text())["E"] == pytest.approx(2.0, rel=1e-9)
