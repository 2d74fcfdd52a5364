"""Every code block of the README runs: Python blocks are executed, shell blocks run line by line.

Two lines are not run here, each for a stated reason: the README's test command (``python3 -m pytest``,
this very suite; CI runs it, and ``test_ci_runs_the_readme_test_command`` checks that it is the same command) and
the full benchmark table (minutes; run with ``THINLAYER_SLOW=1``).
A ``thinlayer ...`` command runs in this process through ``thinlayer.export.cli.main(argv)``, the function the
``thinlayer`` script calls (the installed script itself runs in tests/export/test_wheel.py, ``python -m thinlayer``
in tests/export/test_cli_errors.py): no interpreter start per line, and the per-process caches (h*, the
Wiener-Hopf tables) are shared with the report tests of the same xdist group.
A ``text`` block is a picture of the source tree and is compared with the tree instead.
"""
from __future__ import annotations

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text()
BLOCKS = re.findall(r"^```(\w+)\n(.*?)^```", README, flags=re.S | re.M)
SLOW = os.environ.get("THINLAYER_SLOW") == "1"


def _blocks(lang: str) -> list[str]:
    return [body for kind, body in BLOCKS if kind == lang]


def test_the_readme_has_code():
    assert _blocks("python") and _blocks("bash")


@pytest.mark.parametrize("k", range(len(_blocks("python"))))
def test_python_block_runs(k, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code = _blocks("python")[k]
    exec(compile(code, f"README python block {k + 1}", "exec"), {"__name__": "__readme__"})


def _shell_lines() -> list[str]:
    out = []
    for body in _blocks("bash"):
        for line in body.splitlines():
            line = line.split("  #")[0].strip()
            if line:
                out.append(line)
    return out


def _why_not_run(line: str) -> str | None:
    if "-m pytest" in line:
        return "the README's test command is this suite itself (CI runs it)"
    if "benchmarks/run.py" in line and not SLOW:
        return "the full benchmark table takes minutes: THINLAYER_SLOW=1 runs it"
    return None


def _group(line: str) -> list:
    if " report " in line:
        return [pytest.mark.xdist_group("catalogue-reports")]
    if line.startswith("thinlayer validate "):
        return [pytest.mark.xdist_group("validation-study")]
    return []


def _params() -> list:
    """The shell lines; a ``report`` line runs in the worker of the report tests (their caches are warm there), a
    ``validate`` line in the worker of the validation tests (tests/validation/conftest.py: one run of the default
    study serves both)."""
    return [pytest.param(line, marks=_group(line)) for line in _shell_lines()]


@pytest.mark.parametrize("line", _params())
def test_shell_line_runs(line, tmp_path, monkeypatch, capsys, request):
    if line.startswith("thinlayer validate ") and "&&" not in line:
        # run once, shared with tests/validation's small_study (root conftest's validate_cli_run): the same
        # main(argv) in a fresh folder, its exit code checked here as for every other line
        run = request.getfixturevalue("validate_cli_run")(shlex.split(line)[1:])
        assert run.code == 0, f"{line!r} failed ({run.code}):\n{run.out[-2000:]}\n{run.err[-2000:]}"
        return
    reason = _why_not_run(line)
    if reason:
        pytest.skip(reason)
    from thinlayer.export.cli import main

    # a copy of what the commands read (derivation files, benchmarks), so outputs land in tmp_path
    for folder in ("derivations", "benchmarks"):
        shutil.copytree(ROOT / folder, tmp_path / folder)
    monkeypatch.chdir(tmp_path)
    env = dict(os.environ)
    for part in line.split("&&"):
        argv = shlex.split(part)
        if argv[:4] == ["python3", "-m", "pip", "install"]:
            continue  # the package is installed already (CI installs it with the test extra)
        if "--pdf" in argv and shutil.which("pdflatex") is None and shutil.which("latexmk") is None:
            argv.remove("--pdf")
        if argv[0] == "thinlayer":
            code = main(argv[1:])
            out = capsys.readouterr()
            assert code == 0, f"{line!r} failed ({code}):\n{out.out[-2000:]}\n{out.err[-2000:]}"
            continue
        if argv[0] == "python3":
            argv[0] = sys.executable
        res = subprocess.run(argv, cwd=tmp_path, env=env, capture_output=True, text=True, timeout=600,
                             stdin=subprocess.DEVNULL)
        assert res.returncode == 0, f"{line!r} failed ({res.returncode}):\n{res.stdout[-2000:]}\n{res.stderr[-2000:]}"


def test_ci_runs_the_readme_test_command():
    """.ci/run runs exactly the README's test command (the line with ``-m pytest``), nothing else of pytest."""
    (readme_cmd,) = [ln for ln in _shell_lines() if "-m pytest" in ln]
    test_cmd = readme_cmd.split("&&")[-1].strip()
    ci = [ln.strip() for ln in (ROOT / ".ci" / "run").read_text().splitlines()
          if ln.strip() and not ln.lstrip().startswith("#")]
    assert [ln for ln in ci if "pytest" in ln and "pip install" not in ln] == [test_cmd]
    assert "-n 2" in test_cmd  # two workers (pytest-xdist, in the test extra): the suite's time on two cores


def test_tree_picture_matches_the_package():
    """The "where things live" map names every folder and top-level module of src/thinlayer."""
    (tree,) = _blocks("text")
    src = ROOT / "src" / "thinlayer"
    names = [p.name + ("/" if p.is_dir() else "") for p in src.iterdir()
             if not p.name.startswith("__") and p.name != "py.typed" and not p.name.endswith(".egg-info")
             and (p.is_dir() or p.suffix == ".py")]
    missing = [n for n in names if n not in tree]
    assert not missing, f"the README's map misses {missing}"
    for word in re.findall(r"\b([a-z_]+)/", tree):
        found = word in ("src", "thinlayer") or any(p.is_dir() for p in src.rglob(word))
        assert found, f"the map names a folder {word}/ that does not exist"


def test_performance_table_is_current_output_of_run_py():
    """The README's performance table is what ``benchmarks/run.py --readme`` writes: its header, one row per
    benchmark (the suite has over 100), and no row that missed its target (issue 18 item 6)."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    try:
        from _timing import MARKDOWN_HEADER
    finally:
        sys.path.pop(0)
    text = (ROOT / "README.md").read_text()
    block = text.split("<!-- benchmarks:begin -->", 1)[1].split("<!-- benchmarks:end -->", 1)[0]
    assert "python3 benchmarks/run.py" in block.splitlines()[1]
    assert MARKDOWN_HEADER in block
    rows = [ln for ln in block.splitlines() if ln.startswith("| ") and not ln.startswith("| benchmark |")]
    assert len(rows) >= 100, len(rows)
    verdicts = [ln.rstrip(" |").rsplit("|", 1)[1].strip() for ln in rows]
    ok = ("pass", "n/a", "info")
    assert set(verdicts) <= set(ok), [r for r, v in zip(rows, verdicts) if v not in ok]
    assert verdicts.count("pass") >= 100
