"""No link followed to write, nothing lost to a killed run (issue 23, item 2).

For every path a command writes into its output folder (the report's .tex, .pdf, .log and figures, each file
of generated code, the validation tables and figures, the fit's result, and the lock files) a link is planted
there -- to a sentinel file outside the folder, or dangling to a name outside it -- and the command is run
with and without ``--overwrite``.  Independent checks: the sentinel's bytes and the list of files outside
the output folder are unchanged, and the run either refuses in one line with exit code 2 or replaced the
link itself by a regular file inside the folder.  Runs killed (SIGTERM, SIGINT, SIGKILL) while the PDF
compiles or while the .tex is written leave the earlier .tex, .pdf and .log byte for byte; SIGTERM and
SIGINT leave no temporary file; SIGKILL leaves one hidden ``.<name>.thinlayer-<pid>-<hex>.tmp`` entry
in the output folder, which the next run of that name removes.
"""
from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from children import CHILD
from planting import (
    EXIT_CODES,
    WRITERS,
    Outside,
    attack,
    derivation_file,
    killed_run,
    plant,
    quick_validation,
    run_cli,
)

from thinlayer.validation import output as O

#: the acceptance table (tests/test_safe_input_acceptance.py) tries the same inputs: one worker runs both, and
#: planting.attack runs each input once
pytestmark = pytest.mark.xdist_group("file-attacks")

ROOT = Path(__file__).resolve().parents[2]
SRC = str(ROOT / "src")
TARGETS = [(w, rel) for w in WRITERS for rel in w.files]


def _id(pair) -> str:
    w, rel = pair
    return f"{w.name}:{rel}".replace(" ", "_")


@pytest.fixture(scope="module", autouse=True)
def _study():
    with quick_validation():  # the one small study, computed once for the module
        yield


# ------------------------------------------------------------------------------------------------
# links planted at what a run writes
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("kind", ["link", "dangling"])
@pytest.mark.parametrize("target", TARGETS, ids=[_id(t) for t in TARGETS])
def test_a_link_at_a_target_is_refused_without_overwrite(tmp_path, target, kind):
    writer, rel = target
    res = attack(writer, [rel], kind, overwrite=False, work=tmp_path)
    ok, why = res.safe(refused_expected=True)
    assert ok, why
    assert "symbolic link" in res.err and "--overwrite" in res.err, res.err
    assert res.planted_now == {rel: "link"}  # the user's link is left as it was


@pytest.mark.parametrize("kind", ["link", "dangling"])
@pytest.mark.parametrize("writer", WRITERS, ids=[w.name.replace(" ", "_") for w in WRITERS])
def test_with_overwrite_the_links_themselves_are_replaced(tmp_path, writer, kind):
    res = attack(writer, list(writer.files), kind, overwrite=True, work=tmp_path)
    ok, why = res.safe(refused_expected=False)
    assert ok, why
    out = tmp_path / "out"
    assert all((out / r).is_file() and not (out / r).is_symlink() and (out / r).stat().st_size > 0
               for r in writer.files)


LOCKED = [w for w in WRITERS if w.lock]


@pytest.mark.parametrize("overwrite", [False, True])
@pytest.mark.parametrize("kind", ["link", "dangling"])
@pytest.mark.parametrize("writer", LOCKED, ids=[w.name.replace(" ", "_") for w in LOCKED])
def test_a_link_at_the_lock_file_is_refused(tmp_path, writer, kind, overwrite):
    res = attack(writer, [writer.lock], kind, overwrite=overwrite, work=tmp_path)
    ok, why = res.safe(refused_expected=True)
    assert ok, why
    assert "symbolic link" in res.err and writer.lock in res.err, res.err
    assert not any((tmp_path / "out" / f).exists() for f in writer.files if not f.startswith("inj-figures/"))


@pytest.mark.parametrize("overwrite", [False, True])
@pytest.mark.parametrize("kind", ["dir", "dangling"])
def test_a_linked_figure_folder_is_refused(tmp_path, kind, overwrite):
    writer = next(w for w in WRITERS if w.folder)
    res = attack(writer, [writer.folder], kind, overwrite=overwrite, work=tmp_path)
    ok, why = res.safe(refused_expected=True)
    assert ok, why
    assert "symbolic link" in res.err and "inj-figures" in res.err


def test_a_hard_link_or_a_special_file_at_the_lock_is_refused(tmp_path):
    outside = Outside(tmp_path / "outside")
    out = tmp_path / "out"
    out.mkdir()
    os.link(outside.sentinel, out / ".inj.lock")
    f = derivation_file(tmp_path)
    code, err = run_cli(["report", str(f), "--out", str(out), "--overwrite"])
    assert code == 2 and "hard link" in err and len(err.strip().splitlines()) == 1, err
    assert outside.changed() == [] and not (out / "inj.tex").exists()
    (out / ".inj.lock").unlink()
    os.mkfifo(out / ".inj.lock")
    code, err = run_cli(["report", str(f), "--out", str(out)])
    assert code == 2 and "special file" in err, err


def test_a_fifo_at_the_tex_is_refused_without_hanging(tmp_path):
    """check_writable reads an existing .tex for its mark: a FIFO there must not block the run."""
    out = tmp_path / "out"
    out.mkdir()
    os.mkfifo(out / "inj.tex")
    f = derivation_file(tmp_path)
    env = {**os.environ, "PYTHONPATH": SRC}
    res = subprocess.run([sys.executable, "-m", "thinlayer", "report", str(f), "--out", str(out)], env=env,
                         capture_output=True, text=True, timeout=300, **CHILD)
    assert res.returncode == 2 and "exists" in res.stderr and len(res.stderr.strip().splitlines()) == 1
    res = subprocess.run([sys.executable, "-m", "thinlayer", "report", str(f), "--out", str(out), "--overwrite"],
                         env=env, capture_output=True, text=True, timeout=300, **CHILD)
    assert res.returncode == 0 and (out / "inj.tex").is_file(), res.stderr


def test_an_output_folder_that_is_a_link_is_the_users_choice(tmp_path):
    """--out itself may be a link the user made: it is followed (documented in thinlayer.validation.output)."""
    real = tmp_path / "real"
    real.mkdir()
    os.symlink(real, tmp_path / "out")
    code, err = run_cli(["report", str(derivation_file(tmp_path)), "--out", str(tmp_path / "out")])
    assert code == 0, err
    assert (real / "inj.tex").is_file() and not (real / "inj.tex").is_symlink()


def _tokens(monkeypatch, first: str) -> None:
    """The first temporary name drawn is ``first``'s token; the later ones are random."""
    import secrets

    draws = iter([first])
    monkeypatch.setattr(O.secrets, "token_hex", lambda n: next(draws, None) or secrets.token_bytes(n).hex())


@pytest.mark.parametrize("kind", ["link", "dangling"])
def test_a_link_at_the_next_temporary_name_is_never_used(tmp_path, monkeypatch, kind):
    outside = Outside(tmp_path / "outside")
    out = tmp_path / "out"
    out.mkdir()
    token = "0123456789abcdef"
    for name in (f".a.txt.thinlayer-{os.getpid()}-{token}.tmp", f".r.pdf.thinlayer-{os.getpid()}-{token}.tmp"):
        plant(out / name, kind, outside)
    _tokens(monkeypatch, token)
    O.atomic_write(out / "a.txt", "new\n")
    assert (out / "a.txt").read_text() == "new\n" and outside.changed() == []
    _tokens(monkeypatch, token)
    folder = O.private_folder(out, "r.pdf")
    assert folder.is_dir() and not folder.is_symlink() and token not in folder.name
    assert folder.stat().st_mode & 0o777 == 0o700 and outside.changed() == []
    folder.rmdir()
    assert sorted(p.name for p in out.iterdir() if not p.is_symlink()) == ["a.txt"]


def test_stale_temporaries_of_dead_runs_only_are_removed(tmp_path):
    dead = subprocess.Popen([sys.executable, "-c", "pass"], **CHILD)
    dead.wait(timeout=120)
    stale = tmp_path / f".x.tex.thinlayer-{dead.pid}-{'a' * 16}.tmp"
    stale_dir = tmp_path / f".x.pdf.thinlayer-{dead.pid}-{'b' * 16}.tmp"
    live = tmp_path / f".x.tex.thinlayer-{os.getpid()}-{'c' * 16}.tmp"
    other = tmp_path / f".y.tex.thinlayer-{dead.pid}-{'d' * 16}.tmp"
    mine = tmp_path / ".x.tex.notes.tmp"
    for p in (stale, live, other, mine):
        p.write_text("x")
    stale_dir.mkdir()
    (stale_dir / "x.tex").write_text("x")
    removed = O.remove_stale([tmp_path / "x.tex", tmp_path / "x.pdf"])
    assert sorted(removed) == sorted([stale, stale_dir])
    assert live.exists() and other.exists() and mine.exists() and not stale.exists() and not stale_dir.exists()


# ------------------------------------------------------------------------------------------------
# killed runs
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT, signal.SIGKILL])
@pytest.mark.parametrize("stage", ["compile", "tex"])
def test_a_killed_run_leaves_the_earlier_files(tmp_path, stage, sig):
    k = killed_run(tmp_path, stage, sig)
    assert set(k.before) == {"inj.tex", "inj.pdf", "inj.log"}
    assert k.code == EXIT_CODES[sig], k.err
    assert k.after == k.before  # the earlier .tex, .pdf and .log, byte for byte
    if sig == signal.SIGKILL:  # one hidden, clearly named temporary entry of the dead run
        kind = ".inj.pdf." if stage == "compile" else ".inj.tex."
        assert len(k.left) == 1 and k.left[0].startswith(f"{kind}thinlayer-{k.pid}-") and k.left[0].endswith(".tmp")
    else:
        assert k.left == [] and len(k.err.strip().splitlines()) == 1, (k.left, k.err)
    # the next run of the name works, removes what a killed run left, and writes the new report
    assert k.next_code == 0, k.next_err
    assert k.next_left == [] and not k.next_lock
    assert k.next_files["inj.tex"] != k.before["inj.tex"] and b"another title" in k.next_files["inj.tex"]
    assert k.problems() == []
