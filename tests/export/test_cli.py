"""The command line: every subcommand, --json keys, --latex, --help examples and exit codes."""
from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp

from thinlayer.export.cli import build_parser, main

#: the solve subcommand with its shear modulus (solve needs --mu or --E)
SOLVE_MU = ["solve", "--mu", "1"]

ROOT = Path(__file__).resolve().parents[2]


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_coefficients_json_against_sympy_series(capsys):
    code, out, _ = run(capsys, "coefficients", "--nu", "3/10", "--order", "2", "--json")
    assert code == 0
    data = json.loads(out)
    assert set(data) == {"nu", "model", "order", "A", "m", "M", "moments"}
    # independent route: sympy's series of L(s)/s (2.3) = A (1 + m_1 s^2 + m_2 s^4 + ...) (2.20)
    s = sp.Symbol("s")
    k = 3 - 4 * sp.Rational(3, 10)
    L = (2 * k * sp.sinh(2 * s) - 4 * s) / (2 * k * sp.cosh(2 * s) + 1 + k**2 + 4 * s**2)
    ser = sp.series(L / s, s, 0, 5).removeO()
    A = ser.coeff(s, 0)
    assert sp.Rational(data["A"]["expr"]) == A
    assert sp.Rational(data["m"][1]["expr"]) == ser.coeff(s, 2) / A
    assert sp.Rational(data["m"][2]["expr"]) == ser.coeff(s, 4) / A
    # (4.2): M is the reciprocal series: (1 + m1 z + m2 z^2)(1 + M1 z + M2 z^2) = 1 + O(z^3)
    m = [sp.Rational(x["expr"]) for x in data["m"]]
    M = [sp.Rational(x["expr"]) for x in data["M"]]
    assert m[1] + M[1] == 0 and m[2] + m[1] * M[1] + M[2] == 0
    assert data["moments"]["mu_0,0"]["value"] == pytest.approx(float(sp.pi**2 * A))


def test_coefficients_latex_and_text(capsys):
    code, out, _ = run(capsys, "coefficients", "--order", "1", "--latex")
    assert code == 0 and r"\tag{2.20}" in out
    code, out, _ = run(capsys, "coefficients", "--nu", "0.3", "--order", "1")
    assert code == 0 and "m₁ = 0.0714285714286" in out and "_1" not in out  # Unicode maths (issue 28.5), 1/14


def test_inner_json_and_latex(capsys):
    code, out, _ = run(capsys, "inner", "--kind", "paraboloid", "--nu", "3/10", "--json")
    assert code == 0
    data = json.loads(out)
    assert {"punch", "terms", "scaled_terms", "pressure", "arguments"} <= set(data)
    # p_1 = -(vartheta H/A) m_1 Laplacian(Phi) with vartheta = mu/(1 - nu), A = 20/49, m_1 = 1/14, Lap = 2/R
    H, mu, R = sp.symbols("H mu R", positive=True)
    p1 = sp.sympify(data["terms"][1]["expr"], locals={"H": H, "mu": mu, "R": R})
    assert sp.simplify(p1 + mu / sp.Rational(7, 10) * H / sp.Rational(20, 49) * sp.Rational(1, 14) * 2 / R) == 0
    code, out, _ = run(capsys, "inner", "--punch", "x_1**2/2 + x_2**4", "--latex")
    assert code == 0 and r"\tag{4.1}" in out


def test_solve_json_matches_api(capsys):
    from thinlayer import BondedLayer, Punch, solve

    code, out, _ = run(capsys, "solve", "--mu", "1", "--nu", "0.3", "--kind", "elliptic_paraboloid", "--param", "R_1=4",
                       "--param", "R_2=1", "--delta0", "0.5", "--H", "0.05", "--json")
    assert code == 0
    data = json.loads(out)
    sol = solve(BondedLayer(0.3), Punch.elliptic_paraboloid(4, 1), delta0=0.5, H=0.05, mu=1.0)
    assert data["force"] == pytest.approx(sol.force, rel=1e-14)
    assert data["contact_area"] == pytest.approx(sol.contact_area, rel=1e-14)
    assert data["edge_shift_exact"] == pytest.approx(0.1220706479, abs=1e-9)
    assert set(data["remainder"]) == {"force", "contact_area", "pressure_interior", "pressure_composite"}
    code, out, _ = run(capsys, "solve", "--mu", "1", "--nu", "0.3", "--punch", "x_1**2/8 + x_2**2/2", "--force",
                       str(sol.force), "--H", "0.05", "--json")
    assert code == 0 and json.loads(out)["delta0"] == pytest.approx(0.5, rel=1e-12)
    code, out, _ = run(capsys, "solve", "--mu", "1", "--nu", "0.3", "--punch", "x_1**2/8 + x_2**2/2", "--delta0", "0.5",
                       "--H", "0.05", "--latex")
    assert code == 0 and r"\tag{1.8}" in out


def test_errata_json(capsys):
    from thinlayer import errata

    code, out, _ = run(capsys, "errata", "--json")
    data = json.loads(out)
    assert code == 0 and len(data) == len(errata.ENTRIES)
    assert {"equation", "kind", "quantity", "printed", "derived", "evidence"} == set(data[0])


def test_report_json_and_alias(capsys, tmp_path):
    f = ROOT / "derivations" / "quartic_punch.toml"
    code, out, _ = run(capsys, "report", str(f), "--out", str(tmp_path), "--json")
    assert code == 0 and json.loads(out) == {"tex": str(tmp_path / "quartic_punch.tex"), "pdf": None}
    code, out, _ = run(capsys, "derive", str(f), "--out", str(tmp_path))
    assert code == 0 and "wrote" in out


@pytest.mark.parametrize("argv, reason", [
    ([*SOLVE_MU, "--nu", "0.7", "--kind", "paraboloid", "--param", "R=1", "--delta0", "0.1", "--H", "0.1"], "nu"),
    ([*SOLVE_MU, "--nu", "0.3", "--kind", "paraboloid", "--delta0", "0.1", "--H", "0.1"], "without values"),
    ([*SOLVE_MU, "--nu", "0.3", "--kind", "paraboloid", "--param", "R=1", "--delta0", "-1", "--H", "0.1"], "delta0"),
    ([*SOLVE_MU, "--nu", "0.3", "--kind", "paraboloid", "--param", "R=1", "--delta0", "0.1", "--H", "0"], "H"),
    ([*SOLVE_MU, "--nu", "0.3", "--kind", "paraboloid", "--param", "R", "--delta0", "0.1", "--H", "1"], "NAME=VALUE"),
    ([*SOLVE_MU, "--nu", "0.3", "--punch", "exp(x_1)", "--delta0", "0.1", "--H", "1"], "polynomial"),
    ([*SOLVE_MU, "--nu", "0.3", "--punch", "x_1**2", "--kind", "paraboloid", "--delta0", "0.1", "--H", "1"],
     "exactly one"),
    (["coefficients", "--nu", "abc"], "--nu"),
    (["coefficients", "--order", "0"], "--order"),
    (["report", "no/such/file.toml"], "does not exist"),
])
def test_bad_input_exit_code_2(capsys, argv, reason):
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and reason in err


def test_help_has_examples():
    ap = build_parser()
    assert "example" in ap.format_help()
    sub = ap._subparsers._group_actions[0].choices
    for name in ("report", "coefficients", "inner", "solve", "errata", "codegen"):
        text = sub[name].format_help()
        assert "example" in text and "--json" in text, name


def test_codegen_writes_files_and_refuses_overwrite(capsys, tmp_path):
    out = tmp_path / "gen"
    code, text, _ = run(capsys, "codegen", "force", "--kind", "paraboloid", "--lang", "c,python", "--out", str(out),
                        "--json")
    assert code == 0
    files = json.loads(text)["files"]
    assert sorted(Path(f).name for f in files) == ["force_law.c", "force_law.h", "force_law.py"]
    (out / "force_law.py").write_text("# mine\n")
    code, text, err = run(capsys, "codegen", "force", "--kind", "paraboloid", "--lang", "c,python", "--out", str(out))
    assert code == 2 and "exists" in err and (out / "force_law.py").read_text() == "# mine\n"
    code, *_ = run(capsys, "codegen", "force", "--kind", "paraboloid", "--lang", "python", "--out", str(out), "--force")
    assert code == 0 and "def force_law" in (out / "force_law.py").read_text()


def test_codegen_prints_and_validates(capsys):
    code, text, _ = run(capsys, "codegen", "coefficients", "--order", "1", "--lang", "python", "--json")
    assert code == 0
    data = json.loads(text)
    assert data[0]["outputs"] == ["A", "m_1", "M_1"] and data[0]["arguments"] == ["nu"]
    code, text, _ = run(capsys, "codegen", "composite", "--kind", "paraboloid", "--param", "R=2", "--nu", "0.3",
                        "--delta0", "0.25", "--H", "0.02", "--lang", "c")
    assert code == 0 and "double composite_pressure(double x_1, double x_2, double H, double mu)" in text
    for argv, reason in [(["codegen", "inner", "--kind", "paraboloid", "--lang", "cobol"], "--lang"),
                         (["codegen", "composite", "--kind", "paraboloid", "--param", "R=2", "--lang", "c"], "numeric"),
                         (["codegen", "composite", "--kind", "elliptic_paraboloid", "--param", "R_1=4", "--param",
                           "R_2=1", "--nu", "0.3", "--delta0", "0.25", "--H", "0.02"], "radial")]:
        code, out, err = run(capsys, *argv)
        assert code == 2 and reason in err, (argv, err)


def test_cli_and_no_overwrite(tmp_path, capsys):
    f = ROOT / "derivations" / "quartic_punch.toml"
    assert main(["derive", str(f), "--out", str(tmp_path)]) == 0
    assert main(["derive", str(f), "--out", str(tmp_path)]) == 0  # our own file: replaced
    mine = tmp_path / "quartic_punch.tex"
    mine.write_text("my notes\n")
    assert main(["derive", str(f), "--out", str(tmp_path)]) == 2
    assert "not written by thinlayer" in capsys.readouterr().err
    assert mine.read_text() == "my notes\n"
    assert main(["derive", str(f), "--out", str(tmp_path), "--force"]) == 0


def test_conventions_version_quiet_overwrite(capsys, tmp_path):
    # --version; --overwrite for files (the former --force still accepted there); --quiet drops 'wrote ...'
    from importlib.metadata import version

    assert main(["--version"]) == 0 and capsys.readouterr().out.strip() == f"thinlayer {version('thinlayer')}"
    out = tmp_path / "gen"
    argv = ["codegen", "force", "--kind", "paraboloid", "--lang", "python", "--out", str(out)]
    assert main(argv) == 0 and "wrote" in capsys.readouterr().out
    assert main(argv) == 2 and "pass --overwrite" in capsys.readouterr().err
    assert main([*argv, "--overwrite", "--quiet"]) == 0 and capsys.readouterr().out == ""
    assert main([*argv, "--force"]) == 0
    for cmd in ("report", "coefficients", "inner", "solve", "errata", "codegen", "validate"):
        text = build_parser()._subparsers._group_actions[0].choices[cmd].format_help()
        assert "--quiet" in text, cmd
        assert ("--overwrite" in text) == (cmd in ("report", "codegen", "validate", "solve")), cmd  # solve --output


def test_report_without_latex_prints_how_to_get_the_pdf(tmp_path, monkeypatch, capsys):
    # issue 17 item 1: a fresh machine with nothing but Python writes the report and says how to get the PDF (a
    # catalogue report that builds in ~2 s: the hint does not depend on the derivation; the sphere's takes ~15 s)
    import shutil as _shutil

    from thinlayer.export.cli import main as _main

    monkeypatch.setattr(_shutil, "which", lambda name, *a, **k: None)
    assert _main(["report", "frictionless_sphere", "--out", str(tmp_path / "a")]) == 0
    out = capsys.readouterr().out.splitlines()
    assert (tmp_path / "a" / "frictionless_sphere.tex").is_file()
    assert len(out) == 2 and out[0].startswith("wrote ") and out[1].startswith("no PDF: pdflatex is not installed")
    assert _main(["report", "frictionless_sphere", "--out", str(tmp_path / "b"), "--quiet"]) == 0
    assert capsys.readouterr().out == ""


def test_flat_punch_commands(capsys):
    # issue 14 item 5: kappa over a/H from the command line, and solve --flat; kappa(a/H) -> 1 (Boussinesq) as
    # a/H -> 0, the exact model's value agrees with the thin-layer law inside the law's estimate at a/H = 50
    import json as _json

    from thinlayer.export.cli import main as _main

    assert _main(["flat-punch", "--a-over-H", "1e-4", "50", "--nu", "3/10", "--model", "exact", "--json"]) == 0
    rows = _json.loads(capsys.readouterr().out)["rows"]
    assert abs(rows[0]["kappa"] - 1) < 1e-3 and rows[0]["model"] == "exact"
    assert _main(["flat-punch", "--a-over-H", "50", "--nu", "0.3", "--model", "thin", "--json"]) == 0
    thin = _json.loads(capsys.readouterr().out)["rows"][0]
    assert abs(thin["kappa"] / rows[1]["kappa"] - 1) <= thin["error_estimate"]
    assert _main(["solve", "--flat", "2", "--nu", "0.3", "--delta0", "0.01", "--H", "1e6", "--mu", "1", "--json"]) == 0
    out = _json.loads(capsys.readouterr().out)
    assert abs(out["force"] / (4 * 2 * 0.01 / 0.7) - 1) < 1e-5 and out["max_pressure"] is None
    for argv in (["flat-punch", "--a-over-H", "0", "--nu", "0.3"], ["flat-punch", "--a-over-H", "1", "--nu", "0.7"],
                 ["solve", "--flat", "-1", "--nu", "0.3", "--delta0", "0.01", "--H", "0.5", "--mu", "1"],
                 ["solve", "--flat", "1", "--kind", "paraboloid", "--nu", "0.3", "--delta0", "0.01", "--H", "0.5",
                  "--mu", "1"]):
        assert _main(argv) == 2, argv
        err = capsys.readouterr().err
        assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
