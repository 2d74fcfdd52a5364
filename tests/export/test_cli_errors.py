"""Every bad input to the command line is one line on stderr and exit 2 (issue 12, item 6)."""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

from thinlayer.export.cli import main

#: the solve subcommand with its shear modulus (solve needs --mu or --E)
SOLVE_MU = ["solve", "--mu", "1"]

ROOT = Path(__file__).resolve().parents[2]
SRC = str(ROOT / "src")
GOOD = "[derivation]\nname='x'\n[layer]\nnu='3/10'\n[punch]\nkind='paraboloid'\n"
SOLVE = [*SOLVE_MU, "--nu", "0.3", "--kind", "paraboloid", "--param", "R=1", "--delta0", "0.1"]

#: (name, derivation file content or None, argv with {file} and {tmp}) -> one line, exit 2
CASES = [
    ("nu 1/0", None, [*SOLVE_MU, "--nu", "1/0", "--kind", "paraboloid", "--param", "R=1", "--delta0", "0.1", "--H",
                      "0.01"]),
    ("nu nan", None, ["coefficients", "--nu", "nan"]),
    ("nu inf", None, ["coefficients", "--nu", "inf"]),
    ("nu 0.7", None, ["coefficients", "--nu", "0.7"]),
    ("nu code", None, ["coefficients", "--nu", "__import__('os').system('true')"]),
    ("order text", None, ["coefficients", "--order", "three"]),
    ("order 0", None, ["coefficients", "--order", "0"]),
    ("order huge", None, ["coefficients", "--order", "100000"]),
    ("H nan", None, [*SOLVE, "--H", "nan"]),
    ("H -inf", None, [*SOLVE, "--H=-inf"]),  # --H inf is the half-space (issue 25 item 4): tests/afm
    ("H negative", None, [*SOLVE, "--H", "-1"]),
    ("mu 1e308", None, [*SOLVE, "--H", "0.01", "--mu", "1e308", "--json"]),
    ("param nan", None, [*SOLVE_MU, "--nu", "0.3", "--kind", "paraboloid", "--param", "R=nan", "--delta0", "0.1",
                         "--H", "0.01"]),
    ("param no =", None, [*SOLVE_MU, "--nu", "0.3", "--kind", "paraboloid", "--param", "R", "--delta0", "0.1",
                          "--H", "0.01"]),
    ("punch code", None, ["inner", "--punch", "x_1**2 + __import__('os').system('touch pwned')"]),
    ("punch exp", None, ["inner", "--punch", "exp(x_1)"]),
    ("punch deep", None, ["inner", "--punch", "(" * 5000 + "x_1" + ")" * 5000]),
    ("unknown command", None, ["frobnicate"]),
    ("unknown option", None, ["errata", "--frob"]),
    ("lang cobol", None, ["codegen", "inner", "--kind", "paraboloid", "--lang", "cobol"]),
    ("codegen out under a file", None, ["codegen", "force", "--kind", "paraboloid", "--lang", "c", "--out",
                                        "{tmp}/afile/sub"]),
    ("missing file", None, ["report", "{tmp}/none.toml"]),
    ("folder as file", None, ["report", "{tmp}"]),
    ("binary file", b"\x00\xff\xfe[derivation]", ["report", "{file}"]),
    ("bad TOML", "[derivation\n", ["report", "{file}"]),
    ("unknown key", GOOD + "[coefficients]\norder=2\nordr=3\n", ["report", "{file}"]),
    ("layer nuu", GOOD.replace("nu='3/10'", "nuu='0.3'"), ["report", "{file}"]),
    ("coefficients = 3", "coefficients = 3\n" + GOOD, ["report", "{file}"]),
    ("kind list", GOOD.replace("kind='paraboloid'", "kind=['paraboloid']"), ["report", "{file}"]),
    ("title 5", GOOD.replace("name='x'", "name='x'\ntitle=5"), ["report", "{file}"]),
    ("title emoji", GOOD.replace("name='x'", "name='x'\ntitle='\U0001F600'"), ["report", "{file}"]),
    ("contact H 1e300", GOOD + "[contact]\ndelta0=0.1\nH=1e300\nparameters={R=1}\n", ["report", "{file}"]),
    ("R 1e-300", GOOD + "[contact]\ndelta0=0.1\nH=0.01\nparameters={R=1e-300}\n", ["report", "{file}"]),
    ("contact nu twice", GOOD + "[contact]\nnu=0.4\ndelta0=0.1\nH=0.01\nparameters={R=1}\n", ["report", "{file}"]),
    ("out under a file", GOOD, ["report", "{file}", "--out", "{tmp}/afile/sub"]),
    ("out is a file", GOOD, ["report", "{file}", "--out", "{tmp}/afile"]),
    ("tex is a folder", GOOD, ["report", "{file}", "--out", "{tmp}/texdir"]),
    ("validate plots without out", None, ["validate", "--plots"]),
    ("validate nu text", None, ["validate", "--nu", "0.3,x"]),
    ("validate ratios 1/0", None, ["validate", "--ratios", "1/0"]),
    ("validate existing out", None, ["validate", "--out", "{tmp}/done", "--quiet"]),
]


@pytest.mark.parametrize("name, content, argv", CASES, ids=[c[0] for c in CASES])
def test_bad_input_is_one_line_and_exit_2(tmp_path, capsys, name, content, argv):
    (tmp_path / "afile").write_text("a regular file\n")
    (tmp_path / "texdir" / "x.tex").mkdir(parents=True)
    (tmp_path / "done").mkdir()
    (tmp_path / "done" / "validation.txt").write_text("earlier results\n")
    f = tmp_path / "d.toml"
    if content is not None:
        f.write_bytes(content if isinstance(content, bytes) else content.encode())
    argv = [a.replace("{file}", str(f)).replace("{tmp}", str(tmp_path)) for a in argv]
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        code = main(argv)
    finally:
        os.chdir(cwd)
    out, err = capsys.readouterr()
    assert code == 2, (name, err)
    assert len(err.strip().splitlines()) == 1, (name, err)
    assert "Traceback" not in err and "Infinity" not in out and out == ""
    assert not (tmp_path / "pwned").exists()
    assert (tmp_path / "done" / "validation.txt").read_text() == "earlier results\n"


def test_at_least_30_cases():
    assert len(CASES) >= 30


def test_keyboard_interrupt_is_one_line_and_130(monkeypatch, capsys):
    import thinlayer.export.cli as cli

    def interrupted(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(cli, "_cmd_errata", interrupted)
    assert main(["errata"]) == 130
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "interrupted" in err and "Traceback" not in err


def _run(args: list[str], **kw) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": SRC}
    if "input" not in kw:  # the child never waits on the terminal, however pytest was launched
        kw["stdin"] = subprocess.DEVNULL
    return subprocess.run([sys.executable, "-m", "thinlayer", *args], capture_output=True, env=env, **kw)


def test_closed_pipe_ends_quietly():
    env = {**os.environ, "PYTHONPATH": SRC}
    p = subprocess.Popen([sys.executable, "-m", "thinlayer", "errata", "--json"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, env=env, stdin=subprocess.DEVNULL)
    first = p.stdout.read(10)
    p.stdout.close()  # the reader goes away, like `| head -c 10`
    err = p.stderr.read().decode()
    code = p.wait(timeout=60)
    assert first.startswith(b"[")
    assert code in (0, 141) and "Traceback" not in err and "BrokenPipe" not in err, err


def test_subprocess_bad_input_no_traceback():
    res = _run([*SOLVE_MU, "--nu", "0.3", "--kind", "paraboloid", "--param", "R=1", "--delta0", "0.1", "--H", "-1",
                "--json"])
    assert res.returncode == 2 and b"Traceback" not in res.stderr and res.stdout == b""
    assert len(res.stderr.decode().strip().splitlines()) == 1


def test_subprocess_huge_thickness_is_the_half_space():
    # H = 1e300: the thick end of the any-thickness law, Hertz: P = 4/3 E/(1 - nu^2) R^(1/2) d0^(3/2), c = sqrt(R d0)
    res = _run([*SOLVE_MU, "--nu", "0.3", "--kind", "paraboloid", "--param", "R=1", "--delta0", "0.1", "--H", "1e300",
                "--json"])
    assert res.returncode == 0 and b"Traceback" not in res.stderr and b"Warning" not in res.stderr, res.stderr
    out = json.loads(res.stdout)
    E = 2 * 1.0 * 1.3
    assert out["force"] == pytest.approx(4 / 3 * E / (1 - 0.3**2) * 0.1**1.5, rel=1e-12)
    assert out["contact_radius"] == pytest.approx(0.1**0.5, rel=1e-12)
    assert out["max_pressure"] == pytest.approx(1.5 * out["force"] / (math.pi * 0.1), rel=1e-9)
