"""LaTeX safety and no output lost (issue 12, items 2 and 4)."""
from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
import sympy as sp
from children import CHILD

from thinlayer.export.derivation import load_derivation, report_latex, write_report
from thinlayer.export.report import ReportTextError, check_symbol_names, compile_pdf
from thinlayer.validation.output import OutputExistsError, atomic_write

ROOT = Path(__file__).resolve().parents[2]
SRC = str(ROOT / "src")
HAVE_TEX = shutil.which("pdflatex") is not None
INJECTIONS = [r"\input{/etc/hostname}", r"\include{/etc/hostname}", r"\write18{touch pwned}",
              r"\immediate\write18{touch pwned}", r"\newread\f\openin\f=/etc/hostname", r"^^5cinput{/etc/hostname}",
              r"a } b \ c", r"$x$ % comment", r"\catcode`\^=7"]


def _derivation(tmp_path, title: str, extra: str = "") -> Path:
    f = tmp_path / "d.toml"
    esc = title.replace("\\", "\\\\").replace('"', '\\"')
    f.write_text(f'[derivation]\nname="inj"\ntitle="{esc}"\n[layer]\nnu="3/10"\n[punch]\nkind="paraboloid"\n{extra}')
    return f


@pytest.mark.parametrize("title", INJECTIONS)
def test_title_injection_is_escaped(tmp_path, title):
    text = report_latex(load_derivation(_derivation(tmp_path, title)))
    line = next(ln for ln in text.splitlines() if ln.startswith(r"\title{"))
    body = line[len(r"\title{"):-1]
    # independent check: no LaTeX-active character survives unescaped in the title
    stripped = body
    # (and the break points thinlayer puts into a long run without a space, issue 23)
    for esc in (r"\textbackslash{}", r"\textasciicircum{}", r"\{", r"\}", r"\$", r"\%", r"\_", r"\&", r"\#",
                r"\allowbreak{}"):
        stripped = stripped.replace(esc, "")
    assert not set(stripped) & set("\\{}$%^&#_"), line


@pytest.mark.parametrize("name", [r"\input{/etc/hostname}", "a$b", "a%b", "a{b", "a}b", "a\\b", "x y"])
def test_raw_symbol_names_rejected(name):
    with pytest.raises(ReportTextError, match="not allowed in a report"):
        check_symbol_names([name])


def test_symbol_name_injection_through_the_api_is_rejected(tmp_path):
    from thinlayer import Punch
    from thinlayer.export.derivation import Derivation

    der = load_derivation(_derivation(tmp_path, "t"))
    bad = sp.Symbol(r"\input{/etc/hostname}", positive=True)
    from thinlayer import symbols as S

    punch = Punch((S.x1 ** 2 + S.x2 ** 2) / (2 * bad))
    evil = Derivation(der.name, der.title, der.layer, punch, 2)
    with pytest.raises(ReportTextError, match="not allowed"):
        report_latex(evil)


@pytest.mark.skipif(not HAVE_TEX, reason="needs pdflatex")
def test_pdf_with_every_injection_and_greek_title(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    title = "\u03a3\u03bd \u00e9 " + " ".join(INJECTIONS[:4] + INJECTIONS[5:7])
    tex = write_report(load_derivation(_derivation(tmp_path, title)), tmp_path / "out", pdf=True)
    log = tex.with_suffix(".log").read_text()
    host = Path("/etc/hostname").read_text().strip() if Path("/etc/hostname").exists() else None
    assert tex.with_suffix(".pdf").stat().st_size > 10_000
    assert "(/etc/hostname" not in log and not list(tmp_path.rglob("pwned"))
    if host:
        assert host not in tex.read_text()


@pytest.mark.skipif(not HAVE_TEX, reason="needs pdflatex")
@pytest.mark.parametrize("body", [r"\input{/etc/hostname}", r"\immediate\write18{touch pwned}ok",
                                  r"\newwrite\f\immediate\openout\f=../escaped.tex\immediate\write\f{x}ok"])
def test_latex_run_is_sandboxed(tmp_path, body):
    """A hand-made .tex (not from thinlayer) still cannot read outside, run commands or write outside."""
    work = tmp_path / "w"
    work.mkdir()
    tex = work / "evil.tex"
    tex.write_text("\\documentclass{article}\\begin{document}" + body + "\\end{document}\n")
    root = tmp_path / "tmproot"
    root.mkdir()
    try:
        compile_pdf(tex, temp_root=root)
    except RuntimeError as exc:
        assert "\n" not in str(exc)
    assert not list(tmp_path.rglob("pwned")) and not list(tmp_path.rglob("escaped.tex"))
    log = tex.with_suffix(".log")
    if log.exists():
        assert "(/etc/hostname" not in log.read_text()
    assert list(root.iterdir()) == []


def test_emoji_title_is_one_line(tmp_path):
    from thinlayer.export.derivation import DerivationFileError

    with pytest.raises(DerivationFileError) as exc:
        load_derivation(_derivation(tmp_path, "ball \U0001F3C0"))
    assert "\n" not in str(exc.value) and "U+1F3C0" in str(exc.value)


# ------------------------------------------------------------------------------------------------
# no output lost
# ------------------------------------------------------------------------------------------------
def test_hand_edited_generated_tex_is_kept(tmp_path):
    der = load_derivation(_derivation(tmp_path, "t"))
    tex = write_report(der, tmp_path / "o")
    write_report(der, tmp_path / "o")  # unchanged generated file: replaced
    text = tex.read_text()
    assert text.startswith("% generated by thinlayer sha256=")
    edited = text.replace(r"\section{", r"\section{My notes. ", 1)
    tex.write_text(edited)
    with pytest.raises(OutputExistsError, match="edited after thinlayer wrote it"):
        write_report(der, tmp_path / "o")
    assert tex.read_text() == edited
    write_report(der, tmp_path / "o", force=True)
    assert tex.read_text() == text


@pytest.mark.parametrize("existing", ["inj.pdf", "inj.log"])
def test_existing_pdf_and_log_are_kept(tmp_path, existing):
    der = load_derivation(_derivation(tmp_path, "t"))
    out = tmp_path / "o"
    out.mkdir()
    (out / existing).write_text("mine\n")
    with pytest.raises(OutputExistsError, match=existing):
        write_report(der, out, pdf=True)
    assert (out / existing).read_text() == "mine\n" and not (out / "inj.tex").exists()


def test_umask_respected_and_atomic(tmp_path, monkeypatch):
    old = os.umask(0o027)
    try:
        p = atomic_write(tmp_path / "a.txt", "x")
        tex = write_report(load_derivation(_derivation(tmp_path, "t")), tmp_path / "o")
    finally:
        os.umask(old)
    assert p.stat().st_mode & 0o777 == 0o640 and tex.stat().st_mode & 0o777 == 0o640

    def broken(*_a):
        raise OSError("disk full")

    monkeypatch.setattr(os, "replace", broken)
    with pytest.raises(OSError, match="disk full"):
        atomic_write(p, "new")
    assert p.read_text() == "x" and [q.name for q in tmp_path.iterdir() if q.name.endswith(".tmp")] == []


def test_codegen_files_atomic_and_kept(tmp_path):
    from thinlayer import BondedLayer, kernel_coefficients
    from thinlayer.export.codegen import generate

    code = generate(kernel_coefficients(BondedLayer(), 1), "python")
    (tmp_path / code.main_file).write_text("mine\n")
    with pytest.raises(FileExistsError):
        code.write(tmp_path)
    assert (tmp_path / code.main_file).read_text() == "mine\n"
    old = os.umask(0o022)
    try:
        code.write(tmp_path, force=True)
    finally:
        os.umask(old)
    assert (tmp_path / code.main_file).stat().st_mode & 0o777 == 0o644


def test_validate_refuses_existing_outputs_before_running(tmp_path, capsys):
    from thinlayer.export.cli import main

    for name in ("validation.json", "validation_errors.png"):
        d = tmp_path / name
        d.mkdir()
        (d / name).write_text("old\n")
        assert main(["validate", "--out", str(d), "--plots", "--quiet"]) == 2
        assert "exists; pass --overwrite" in capsys.readouterr().err and (d / name).read_text() == "old\n"


def _fake_tex(tmp_path) -> dict:
    """PATH with a pdflatex that sleeps (the compile is under way as long as needed)."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    fake = bin_dir / "pdflatex"
    fake.write_text("#!/bin/sh\nsleep 60\n")
    fake.chmod(0o755)
    root = tmp_path / "tmproot"
    root.mkdir()
    return {**os.environ, "PYTHONPATH": SRC, "PATH": f"{bin_dir}{os.pathsep}{os.environ['PATH']}",
            "TMPDIR": str(root)}


def _wait_for(cond, timeout=60.0) -> bool:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if cond():
            return True
        time.sleep(0.05)
    return False


def _compiling(out: Path):
    """Whether a report named ``inj`` is being compiled in its private folder inside ``out``."""
    return lambda: any(out.glob(".inj.pdf.thinlayer-*.tmp/inj.tex"))


def _temporaries(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.rglob("*thinlayer-*") if p.name.endswith(".tmp")) if folder.exists() else []


@pytest.mark.parametrize("sig, code", [(signal.SIGTERM, 143), (signal.SIGINT, 130)])
def test_signal_mid_compile_removes_temporary_folder(tmp_path, sig, code):
    env = _fake_tex(tmp_path)
    root = Path(env["TMPDIR"])
    f = _derivation(tmp_path, "t")
    p = subprocess.Popen([sys.executable, "-m", "thinlayer", "report", str(f), "--out", str(tmp_path / "o"), "--pdf"],
                         env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, **CHILD)
    assert _wait_for(_compiling(tmp_path / "o")), "the compile never started"
    p.send_signal(sig)
    _, err = p.communicate(timeout=60)
    assert p.returncode == code, err
    assert b"Traceback" not in err and len(err.decode().strip().splitlines()) == 1
    assert list(root.iterdir()) == []  # the temporary folder is gone
    assert _temporaries(tmp_path / "o") == []
    assert not (tmp_path / "o" / "inj.pdf").exists() and not (tmp_path / "o" / ".inj.lock").exists()


def test_concurrent_runs_of_one_name_cannot_mix(tmp_path):
    env = _fake_tex(tmp_path)
    root = Path(env["TMPDIR"])
    f = _derivation(tmp_path, "t")
    argv = [sys.executable, "-m", "thinlayer", "report", str(f), "--out", str(tmp_path / "o"), "--pdf"]
    first = subprocess.Popen(argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, **CHILD)
    try:
        assert _wait_for(_compiling(tmp_path / "o"))
        second = subprocess.run(argv, env=env, capture_output=True, timeout=120, stdin=subprocess.DEVNULL)
        err = second.stderr.decode()
        assert second.returncode == 1 and "another thinlayer run is writing" in err
        assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    finally:
        first.terminate()
        first.communicate(timeout=60)
    assert list(root.iterdir()) == []
    assert _temporaries(tmp_path / "o") == []
