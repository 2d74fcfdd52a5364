"""The command line's text (issue 28 item 5) and sweeps (item 6): Unicode maths, each thing said once, the
rejected models only with --verbose, CLI options in messages, catalogue names vs paths, sweeps = single solves."""
from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

import pytest

from thinlayer.export.cli import main
from thinlayer.export.solve_cli import MAX_SWEEP, cli_words, parse_values, pretty

SPHERE = ["solve", "--nu", "0.3", "--kind", "paraboloid", "--param", "R=10", "--E", "2"]
#: nu = 0.49, H/a = 0.33: the compressible, two-term and incompressible models are rejected, any-thickness answers
REJECTING = ["solve", "--nu", "0.49", "--kind", "paraboloid", "--param", "R=10", "--delta0", "0.1", "--H", "0.5",
             "--mu", "1"]


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_solve_text_is_unicode_and_says_each_thing_once(capsys):
    code, out, err = run(capsys, "solve", "--nu", "0.3", "--punch", "x_1**2/8 + x_2**2/2", "--delta0", "0.5",
                         "--H", "0.05", "--mu", "1")
    assert code == 0 and err == ""
    assert "Φ = x₁²/8 + x₂²/2" in out and "ν = 0.3" in out and "δ₀ = 0.5" in out
    assert "**" not in out and "x_1" not in out and "+-" not in out and "Phi" not in out
    assert out.count("compressible") == 1  # the model, once (no 'model: compressible -- compressible: ...')
    for word in ("force", "contact area", "H/a", "ν ="):
        assert out.count(word) == 1, (word, out)


def test_rejected_models_only_with_verbose(capsys):
    code, out, _ = run(capsys, *REJECTING)
    assert code == 0 and "model: any-thickness" in out
    assert "  rejected " not in out and "unphysical" not in out and "3 models tried before it: --verbose" in out
    code, verbose, _ = run(capsys, *REJECTING, "--verbose")
    assert code == 0
    rejected = [ln for ln in verbose.splitlines() if ln.startswith("  rejected ")]
    assert [ln.split()[1] for ln in rejected] == ["compressible:", "two-term:", "incompressible:"]
    assert "--model direct" in verbose and "thinlayer.numerics" not in verbose  # CLI words, not Python
    assert "with its own contact size" in verbose  # its H/a differs from the answer's (0.354 vs 0.326)
    assert "λ² = (a/H)²/m₁" in verbose and "lambda" not in verbose


def test_inner_and_coefficients_text(capsys):
    code, out, _ = run(capsys, "inner", "--kind", "elliptic_paraboloid")
    assert code == 0
    assert "p₀  = 2μ (1 - ν)(δ₀ - x₂²/(2R₂) - x₁²/(2R₁))/(H (1 - 2ν))" in out
    assert "**" not in out and "lambdify" not in out and "InnerPressure" not in out
    code, out, _ = run(capsys, "coefficients", "--order", "1")
    assert code == 0 and "𝒜  = (1 - 2ν)/(2(1 - ν)²)" in out and "KernelCoefficients" not in out
    # the one base option: --base (the former --model of coefficients/inner kept as an alias)
    code, a, _ = run(capsys, "coefficients", "--base", "frictionless", "--order", "1", "--json")
    code2, b, _ = run(capsys, "coefficients", "--model", "frictionless", "--order", "1", "--json")
    assert code == code2 == 0 and json.loads(a) == json.loads(b) and json.loads(a)["A"]["expr"] == "1/2"


def test_solve_base_and_its_former_name(capsys):
    argv = [*SPHERE, "--delta0", "0.1", "--H", "0.1", "--json"]
    code, a, _ = run(capsys, *argv, "--base", "frictionless")
    code2, b, _ = run(capsys, *argv, "--layer", "frictionless")
    assert code == code2 == 0 and json.loads(a)["force"] == json.loads(b)["force"]
    assert json.loads(a)["layer"] == "frictionless"


@pytest.mark.parametrize("argv, words, python", [
    (["solve", "--nu", "0.3", "--kind", "paraboloid", "--delta0", "0.1", "--H", "0.1", "--mu", "1"],
     "give --param R=VALUE", "parameters="),
    ([*SPHERE, "--delta0", "0.1", "--H", "0.1", "--model", "two-term"], "--model auto or --model direct", "model='"),
    ([*SPHERE, "--delta0", "0.1", "--H", "1", "--model", "asymptotic"], "--tol 0.05", "model='"),
    ([*SPHERE, "--delta0", "0", "--H", "0.1"], "--delta0 must be", "thinlayer."),
])
def test_messages_speak_in_cli_options(capsys, argv, words, python):
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert words in err and python not in err, err


def test_cli_words_and_pretty():
    assert cli_words("use model='exact' (or 'auto')") == "use --model exact or --model auto"
    assert cli_words("order=2 needs it; use order=1 or model='direct'") == \
        "order=2 needs it; use --order 1 or --model direct"
    assert cli_words("build the composite with boundary_layer='alexandrov'") == \
        "build the composite with --boundary-layer alexandrov"
    assert pretty("P = -0.04 <= 0 (nu = 0.3); --nu, --delta0") == "P = -0.04 ≤ 0 (ν = 0.3); --nu, --delta0"


def test_report_path_or_catalogue_name(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # no derivations/ here
    code, out, err = run(capsys, "report", "derivations/sphere.toml", "--out", "o")
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert "does not exist" in err and "'thinlayer report sphere' is the catalogue's" in err
    assert not (tmp_path / "o").exists()  # no silent fall-back to the packaged copy
    code, out, err = run(capsys, "report", "nosuchname", "--out", "o")
    assert code == 2 and "no derivation of that name" in err and "sphere" in err
    code, out, _ = run(capsys, "report", "quartic_punch", "--out", "o", "--json")  # a bare name: the catalogue
    assert code == 0 and json.loads(out)["tex"] == str(Path("o") / "quartic_punch.tex")


# ---- sweeps ----------------------------------------------------------------------------------
def test_parse_values():
    assert parse_values("0.01:1:100")[0] == 0.01 and parse_values("0.01:1:100")[-1] == 1.0  # both ends included
    assert len(parse_values("0.01:1:100")) == 100
    assert parse_values("2:3:1") == [2.0] and parse_values("0.1,0.2,0.5") == [0.1, 0.2, 0.5]
    vals = parse_values("0:1:11")
    assert all(math.isclose(v, k / 10, abs_tol=1e-15) for k, v in enumerate(vals))


@pytest.mark.parametrize("sweep", [f"0.1:1:{MAX_SWEEP + 1}", "0.1:1:0", "0.1:1:2.5", "0.1:x:5", "1:2", "0.1:inf:3",
                                   ",".join(["0.1"] * (MAX_SWEEP + 1))])
def test_sweep_refused_before_solving(capsys, sweep, monkeypatch):
    import thinlayer.contact.solve as solve_module

    monkeypatch.setattr(solve_module, "solve", lambda *a, **k: pytest.fail("solve() ran"))
    code, out, err = run(capsys, *SPHERE, "--delta0", sweep, "--H", "0.1")
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1, err


def test_sweep_rows_equal_single_solves(capsys):
    from thinlayer import BondedLayer, Punch, solve

    code, out, _ = run(capsys, *SPHERE, "--delta0", "0.01:1:4", "--H", "0.1", "--format", "csv")
    assert code == 0
    rows = list(csv.DictReader(io.StringIO(out)))
    assert [float(r["delta0"]) for r in rows] == [0.01, 0.34, 0.67, 1.0]
    for r in rows:  # the API, one call per depth
        ans = solve(BondedLayer(0.3), Punch.paraboloid(10), delta0=float(r["delta0"]), H=0.1, E=2.0)
        assert float(r["force"]) == ans.force and float(r["contact_area"]) == ans.contact_area
        assert float(r["contact_radius"]) == ans.contact_radius and r["model"] == ans.model
        assert float(r["error_force"]) == pytest.approx(ans.error_estimate["force"], rel=1e-12)
    # a swept H, as JSON, and the inverse problem: each row is the single solve of its value
    code, out, _ = run(capsys, *SPHERE, "--force", "5", "--H", "0.05,0.5,2", "--json")
    data = json.loads(out)
    assert code == 0 and data["swept"] == "H" and len(data["rows"]) == 3
    for row in data["rows"]:
        ans = solve(BondedLayer(0.3), Punch.paraboloid(10), force=5.0, H=row["H"], E=2.0)
        assert row["delta0"] == ans.delta0 and row["model"] == ans.model
    assert [r["model"] for r in data["rows"]][0] != data["rows"][-1]["model"]  # thin and thick layers


def test_sweep_text_table_and_output_file(capsys, tmp_path):
    code, out, _ = run(capsys, *SPHERE, "--delta0", "0.1,0.2", "--H", "0.1")
    lines = out.splitlines()
    assert code == 0 and lines[0].startswith("paraboloid of revolution, Φ = (x₁² + x₂²)/(2R), R = 10")
    assert lines[2].split()[:4] == ["δ₀", "P", "|ω|", "c"] and len(lines) == 5
    f = tmp_path / "sweep.csv"
    code, out, _ = run(capsys, *SPHERE, "--delta0", "0.1:0.2:3", "--H", "0.1", "--output", str(f))
    assert code == 0 and out.startswith(f"wrote {f}") and len(f.read_text().splitlines()) == 4
    f.write_text("mine\n")
    code, out, err = run(capsys, *SPHERE, "--delta0", "0.1:0.2:3", "--H", "0.1", "--output", str(f))
    assert code == 2 and "--overwrite" in err and f.read_text() == "mine\n"
    code, *_ = run(capsys, *SPHERE, "--delta0", "0.1:0.2:3", "--H", "0.1", "--output", str(f), "--overwrite",
                   "--format", "json", "--quiet")
    assert code == 0 and len(json.loads(f.read_text())["rows"]) == 3


def test_sweep_stops_at_a_failing_value(capsys, tmp_path):
    f = tmp_path / "s.csv"
    code, out, err = run(capsys, *SPHERE, "--delta0", "0.1", "--H", "0.1,1,10", "--model", "compressible",
                         "--output", str(f))
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert "--H 1 (value 2 of 3)" in err and not f.exists()
