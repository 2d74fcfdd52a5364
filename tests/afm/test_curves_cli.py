"""``thinlayer fit FILE`` on measured curves (issue 25 item 3): instrument files and CSV, in-process (capsys)."""
import json

import numpy as np
import pytest

pytest.importorskip("nanite", reason="the extra thinlayer[afm] is not installed (pip install -e .[afm])")

from test_curves import FILES, _nanite  # noqa: E402 - nanite's own fits, shared (lru_cache)
from test_curves_bootstrap import R, _synthetic  # noqa: E402

from thinlayer.export.cli import main  # noqa: E402

pytestmark = pytest.mark.xdist_group("afm-laws")
SPOT = str(__import__("pathlib").Path(__file__).resolve().parent / "data" / FILES[0][0])


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_instrument_file_json_equals_nanite_and_bootstrap(capsys):
    out = _json(capsys, ["fit", SPOT, "--R", str(R), "--nu", "0.5", "--weighting", "nanite", "--bootstrap", "20",
                         "--json"])
    assert out["E"] / _nanite(*FILES[0])[0] == pytest.approx(1.0, abs=1e-4)  # nanite's hertz_para, same curve
    assert out["H"] is None and out["model"] == "hertz" and out["fitted"] == ["E", "z0", "b0"]
    assert out["bootstrap"] == 20 and out["E_se_boot"] > 0 and out["block_length"] >= 1
    assert out["file"] == SPOT and out["segment"] == "approach" and len(out["covariance"]) == 3
    assert main(["fit", SPOT, "--R", str(R), "--nu", "0.5", "--H", "3e-6", "--segment", "retract",
                 "--baseline", "offset+slope", "--fit-range", "1.79e-5", "2.3e-5"]) == 0
    text = capsys.readouterr().out
    assert "retract" in text and "baseline slope" in text and "δ/H" in text


def test_csv_with_curve_options_fits_contact_point_and_baseline(tmp_path, capsys):
    z, F, truth = _synthetic(5, n=300)
    path = tmp_path / "curve.csv"
    path.write_text("position,force\n" + "\n".join(f"{float(a)!r},{float(b)!r}" for a, b in zip(z, F)))
    out = _json(capsys, ["fit", str(path), "--R", str(R), "--nu", "0.5", "--depth-sign", "-1", "--baseline",
                         "offset+slope", "--json"])
    assert abs(out["E"] - truth["E"]) < 3.5 * out["E_se"] and abs(out["z0"] - truth["z0"]) < 3.5 * out["z0_se"]
    assert out["axis"] == "tip position"
    fixed = _json(capsys, ["fit", str(path), "--R", str(R), "--nu", "0.5", "--depth-sign", "-1", "--contact-point",
                           repr(truth["z0"]), "--json"])
    assert fixed["z0"] == truth["z0"] and fixed["z0_se"] == 0 and "z0" not in fixed["fitted"]
    plain = tmp_path / "plain.csv"  # without the options: fit() as before (depths, no baseline)
    d = np.linspace(0.01, 1.0, 30)
    plain.write_text("\n".join(f"{float(a)!r},{float(4 / 3 / 0.75 * 2.0 * np.sqrt(5.0) * a ** 1.5)!r}" for a in d))
    old = _json(capsys, ["fit", str(plain), "--R", "5", "--nu", "0.5", "--json"])
    assert old["E"] == pytest.approx(2.0, rel=1e-9) and "offset" in old and "z0" not in old


@pytest.mark.parametrize("argv, match", [
    (["--segment", "retract"], "are for instrument files"),
    (["--bootstrap", "-1"], "--bootstrap must be"),
    (["--baseline", "cubic"], "invalid choice"),
    (["--contact-point", "abc"], "is not a number"),
])
def test_bad_input_on_a_csv_exits_2_with_one_line(tmp_path, capsys, argv, match):
    path = tmp_path / "c.csv"
    path.write_text("0.1,1\n0.2,2\n0.3,3\n0.4,4\n0.5,5\n0.6,6\n0.7,7\n")
    assert main(["fit", str(path), "--R", "1", "--nu", "0.5", *argv]) == 2
    err = capsys.readouterr().err
    assert match in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err


def test_bad_input_on_instrument_files_exits_2_with_one_line(tmp_path, capsys):
    bad = tmp_path / "bad.jpk-force"
    bad.write_text("garbage")
    for argv, match in [([str(tmp_path / "none.jpk-force")], "no such file"),
                        ([str(bad)], "afmformats cannot read it"),
                        ([SPOT, "--depth-sign", "-1"], "--depth-sign is for a CSV"),
                        ([SPOT, "--index", "4"], "beyond the file's 1 curve")]:
        assert main(["fit", *argv, "--R", str(R), "--nu", "0.5"]) == 2
        err = capsys.readouterr().err
        assert match in err and len(err.strip().splitlines()) == 1, err
