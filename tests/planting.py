"""Links planted where thinlayer writes, and runs killed on the way (issue 23, item 2): shared machinery.

Used by ``tests/export/test_symlink_safety.py`` and the acceptance table (``tests/acceptance/cases_files.py``).
The checks are independent of the program: the bytes of a sentinel file outside the output folder, the
list of files outside it, the exit code and the number of lines on stderr.
"""
from __future__ import annotations

import contextlib
import hashlib
import io
import os
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from children import CHILD

#: what the user's file outside the output folder holds
SENTINEL = b"the user's own file, outside --out\n"

#: a pdflatex that writes a small PDF and log at once, or (with THINLAYER_TEST_FLAG set) touches that flag
#: and sleeps until it is killed: a compile under way for as long as a test needs
FAKE_PDFLATEX = """#!/bin/sh
for a in "$@"; do last=$a; done
stem=${last%.tex}
if [ -n "$THINLAYER_TEST_FLAG" ]; then : > "$THINLAYER_TEST_FLAG"; exec sleep 600; fi
printf '%%PDF-1.4\\n%% fake PDF of %s\\n' "$stem" > "$stem.pdf"
echo "This is a fake pdflatex: $stem" > "$stem.log"
"""


def fake_tex(folder: Path) -> str:
    """A folder with :data:`FAKE_PDFLATEX` as ``pdflatex``; returns a PATH that finds it first."""
    folder.mkdir(parents=True, exist_ok=True)
    exe = folder / "pdflatex"
    exe.write_text(FAKE_PDFLATEX)
    exe.chmod(0o755)
    return f"{folder}{os.pathsep}{os.environ.get('PATH', '')}"


def derivation_file(folder: Path, title: str = "t", validation: bool = False, name: str = "inj") -> Path:
    f = folder / f"{name}-{hashlib.sha1(title.encode()).hexdigest()[:8]}.toml"
    extra = "[validation]\nnu=[0.3]\nH_over_a=[0.1]\nshapes=['sphere']\n" if validation else ""
    f.write_text(f'[derivation]\nname="{name}"\ntitle="{title}"\n[layer]\nnu="3/10"\n[punch]\nkind="paraboloid"\n'
                 + extra)
    return f


@dataclass
class Outside:
    """A folder outside ``--out`` with the sentinel; :meth:`changed` says what a run did to it."""

    root: Path
    before: dict = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.root.mkdir(parents=True, exist_ok=True)
        (self.root / "sentinel").write_bytes(SENTINEL)
        (self.root / "folder").mkdir(exist_ok=True)
        self.before = self.snapshot()

    @property
    def sentinel(self) -> Path:
        return self.root / "sentinel"

    def snapshot(self) -> dict:
        return {str(p.relative_to(self.root)): (p.read_bytes() if p.is_file() else None)
                for p in sorted(self.root.rglob("*"))}

    def changed(self) -> list[str]:
        """Files outside ``--out`` created, removed or changed since the start (empty: nothing lost)."""
        now = self.snapshot()
        return sorted(k for k in set(now) | set(self.before) if now.get(k, "gone") != self.before.get(k, "gone"))


def plant(path: Path, kind: str, outside: Outside) -> None:
    """A link at ``path``: ``"link"`` to the sentinel, ``"dangling"`` to a file that does not exist outside,
    ``"dir"`` to a folder outside (for a folder the run writes into)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    target = {"link": outside.sentinel, "dangling": outside.root / f"created-by-{path.name}",
              "dir": outside.root / "folder"}[kind]
    os.symlink(target, path)


def run_cli(argv: list[str]) -> tuple[int, str]:
    """``thinlayer <argv>`` in this process: ``(exit code, stderr)``."""
    from thinlayer.export.cli import main

    err, out = io.StringIO(), io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
        code = main(argv)
    return code, err.getvalue()


@contextlib.contextmanager
def environment(**values: str) -> Iterator[None]:
    old = {k: os.environ.get(k) for k in values}
    os.environ.update(values)
    try:
        yield
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


_STUDY: list = []


@contextlib.contextmanager
def quick_validation() -> Iterator[None]:
    """``validation_study`` answers at once with one small study computed once, and figures are saved as a few
    bytes of their format instead of being drawn (the files are what is tested, as with :data:`FAKE_PDFLATEX`;
    drawing the validation figures took ~7 s of CPU per run; tests/validation/test_study_plots.py checks them)."""
    import matplotlib.figure

    import thinlayer.validation as v
    import thinlayer.validation.runner as runner

    real_savefig = matplotlib.figure.Figure.savefig

    def fake_savefig(self, fname, *args, format=None, **kw):  # noqa: A002 - matplotlib's keyword
        data = b"%PDF-1.4\n% fake figure\n" if format == "pdf" else b"\x89PNG\r\n\x1a\n fake figure\n"
        if hasattr(fname, "write"):
            fname.write(data)
        else:
            Path(fname).write_bytes(data)

    real = runner.validation_study
    if not _STUDY:
        _STUDY.append(real(nus=[0.3], ratios=[0.1], shapes=["sphere"], progress=False))

    def quick(*_a, **_k):
        return _STUDY[0]

    had = "validation_study" in vars(v)
    old = vars(v).get("validation_study")
    runner.validation_study = quick
    v.validation_study = quick
    matplotlib.figure.Figure.savefig = fake_savefig
    try:
        yield
    finally:
        matplotlib.figure.Figure.savefig = real_savefig
        runner.validation_study = real
        if had:
            v.validation_study = old
        else:
            del v.validation_study


@dataclass(frozen=True)
class Writer:
    """A command that writes files into ``--out``: its arguments and every path it writes there."""

    name: str
    argv: Callable[[Path, Path], list[str]]  # (work folder, out folder) -> argv without --overwrite
    files: tuple[str, ...]  # relative to --out
    lock: str
    folder: str | None = None  # a folder inside --out it writes into


CODEGEN_FILES = tuple(f"kernel_coefficients.{x}" for x in ("c", "h", "f90", "fi", "rs", "jl", "m", "py"))
VALIDATION_FILES = ("validation.txt", "validation.tex", "validation.json",
                    *(f"validation_{f}.{x}" for f in ("errors", "pressure", "contours", "edge_shift")
                      for x in ("png", "pdf")))
REPORT_FIGURES = tuple(f"inj-figures/validation_{f}.pdf" for f in ("errors", "pressure", "contours", "edge_shift"))

WRITERS = (
    Writer("report --pdf", lambda w, o: ["report", str(derivation_file(w)), "--out", str(o), "--pdf"],
           ("inj.tex", "inj.pdf", "inj.log"), ".inj.lock"),
    Writer("report with figures", lambda w, o: ["report", str(derivation_file(w, validation=True)), "--out", str(o)],
           ("inj.tex", *REPORT_FIGURES), ".inj.lock", "inj-figures"),
    Writer("codegen (all languages)", lambda w, o: ["codegen", "coefficients", "--order", "1", "--lang", "all",
                                                    "--out", str(o)], CODEGEN_FILES, ".kernel_coefficients.lock"),
    Writer("codegen any-thickness", lambda w, o: ["codegen", "any-thickness", "--nu", "0.3", "--lang", "python,c",
                                                  "--out", str(o)],
           ("thinlayer_any_thickness.py", "thinlayer_any_thickness.c"), ".thinlayer_any_thickness.lock"),
    Writer("validate --plots", lambda w, o: ["validate", "--nu", "0.3", "--ratios", "0.1", "--shapes", "sphere",
                                             "--out", str(o), "--plots", "--quiet"], VALIDATION_FILES,
           ".validation.lock"),
    Writer("fit --out", lambda w, o: ["fit", str(_curve(w)), "--R", "1", "--H", "0.2", "--nu", "0.3", "--out",
                                      str(o / "fit.json"), "--json", "--quiet"], ("fit.json",), ""),
)


def _curve(folder: Path) -> Path:
    """A force-indentation curve of the half-space (Hertz, E = 2, nu = 0.3, R = 1) as CSV."""
    f = folder / "curve.csv"
    if not f.exists():
        e_star = 2.0 / (1 - 0.3**2)
        f.write_text("\n".join(f"{d:.6g},{4 / 3 * e_star * d**1.5:.9g}" for d in [0.001 * k for k in range(1, 41)])
                     + "\n")
    return f


def one_line(err: str) -> bool:
    return len(err.strip().splitlines()) == 1 and "Traceback" not in err


@dataclass
class Outcome:
    """What a run did: its exit code and stderr, what changed outside, what each planted path became."""

    code: int
    err: str
    outside_changed: list[str]
    planted_now: dict[str, str]
    seconds: float = 0.0

    def safe(self, refused_expected: bool | None = None) -> tuple[bool, str]:
        """Safe: nothing outside changed, and either a one-line refusal (exit 2) or every planted path replaced
        by a regular file inside ``--out`` (exit 0)."""
        if self.outside_changed:
            return False, f"outside --out changed: {self.outside_changed}"
        refused = self.code == 2 and one_line(self.err)
        wrote = self.code == 0 and all(v == "file" for v in self.planted_now.values())
        if refused_expected is True and not refused:
            return False, f"expected a one-line refusal, got exit {self.code}: {self.err.strip()[:200]!r}"
        if refused_expected is False and not wrote:
            return False, f"expected the links replaced, got exit {self.code}: {self.err.strip()[:200]!r} " \
                          f"{self.planted_now}"
        if not (refused or wrote):
            return False, f"exit {self.code}: {self.err.strip()[:200]!r}"
        return True, ""


def _state(path: Path) -> str:
    if path.is_symlink():
        return "link"
    if path.is_file():
        return "file"
    return "dir" if path.is_dir() else "missing"


#: outcomes of the attacks run in this process: tests/export/test_symlink_safety.py and the acceptance table
#: (tests/acceptance/cases_files.py) try the same inputs; they share one xdist group, and each input runs once
_OUTCOMES: dict[tuple, Outcome] = {}
#: one killed run per (stage, signal), see :func:`killed_run`
_KILLED: dict = {}


def attack(writer: Writer, rels: list[str], kind: str, overwrite: bool, work: Path) -> Outcome:
    """Plant ``kind`` links at ``rels`` of ``writer``'s ``--out``, run it (with ``--overwrite`` or not).

    The outcome (exit code, stderr, the independent checks of the sentinel and of the planted paths) of one input is
    kept for the process: a second caller with the same input gets the same run's outcome.
    """
    key = (writer.name, tuple(rels), kind, bool(overwrite))
    if key not in _OUTCOMES:
        _OUTCOMES[key] = _attack(writer, rels, kind, overwrite, work)
    return _OUTCOMES[key]


def _attack(writer: Writer, rels: list[str], kind: str, overwrite: bool, work: Path) -> Outcome:
    out = work / "out"
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    outside = Outside(work / "outside")
    for rel in rels:
        plant(out / rel, kind, outside)
    argv = writer.argv(work, out) + (["--overwrite"] if overwrite else [])
    with environment(PATH=fake_tex(work / "bin")), quick_validation():
        start = time.monotonic()
        code, err = run_cli(argv)
        seconds = time.monotonic() - start
    outcome = Outcome(code, err, outside.changed(), {r: _state(out / r) for r in rels}, seconds)
    shutil.rmtree(work / "outside")
    return outcome


def wait_for(cond: Callable[[], bool], timeout: float = 300.0) -> bool:
    """Poll ``cond`` until it holds or ``timeout`` seconds pass (a generous bound: the machine may be loaded)."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if cond():
            return True
        time.sleep(0.05)
    return cond()


_SLOW_FSYNC = """
import os, sys, time
from pathlib import Path
flag = Path(sys.argv[1])
def slow(fd):  # the .tex is being written: its temporary file exists, the rename has not happened
    flag.touch()
    time.sleep(600)
os.fsync = slow
from thinlayer.export.cli import main
sys.exit(main(sys.argv[2:]))
"""
#: the exit code of a run killed by each signal (the command line's own codes for SIGTERM and Ctrl-C)
EXIT_CODES = {signal.SIGTERM: 143, signal.SIGINT: 130, signal.SIGKILL: -signal.SIGKILL}


def report_files(out: Path) -> dict[str, bytes]:
    """The visible files of an output folder and their bytes."""
    return {p.name: p.read_bytes() for p in sorted(out.iterdir()) if p.is_file() and not p.name.startswith(".")}


def leftovers(out: Path) -> list[str]:
    """Temporary files and folders of runs in ``out`` (``.<target>.thinlayer-<pid>-<hex>.tmp``)."""
    return sorted(p.name for p in out.iterdir() if ".thinlayer-" in p.name)


@dataclass
class Killed:
    """A report run killed on the way, and the run after it."""

    stage: str
    sig: int
    pid: int
    code: int | None
    err: str
    before: dict
    after: dict
    left: list
    next_code: int
    next_err: str
    next_left: list
    next_files: dict
    next_lock: bool
    stop_seconds: float = 0.0  # from the signal to the end of the run

    def problems(self) -> list[str]:
        """What went wrong (empty: the earlier files kept, the temporary ones gone or cleaned by the next run)."""
        out = []
        if self.code != EXIT_CODES[self.sig]:
            out.append(f"exit {self.code} (expected {EXIT_CODES[self.sig]}): {self.err.strip()[-300:]!r}")
        if self.after != self.before:
            changed = sorted(k for k in set(self.after) | set(self.before) if self.after.get(k) != self.before.get(k))
            out.append(f"the earlier files changed: {changed}")
        if self.sig == signal.SIGKILL:
            kind = ".inj.pdf." if self.stage == "compile" else ".inj.tex."
            if not (len(self.left) == 1 and self.left[0].startswith(f"{kind}thinlayer-{self.pid}-")
                    and self.left[0].endswith(".tmp")):
                out.append(f"after SIGKILL expected one {kind}thinlayer-{self.pid}-*.tmp, found {self.left}")
        elif self.left or not one_line(self.err):
            out.append(f"left {self.left}, stderr {self.err.strip()[-300:]!r}")
        if self.next_code != 0 or self.next_left or self.next_lock:
            out.append(f"the next run: exit {self.next_code}, left {self.next_left}, lock kept {self.next_lock}, "
                       f"{self.next_err.strip()[-300:]!r}")
        elif b"another title" not in self.next_files.get("inj.tex", b""):
            out.append("the next run did not write the new .tex")
        return out


def killed_run(work: Path, stage: str, sig: int) -> Killed:
    """Write a report (tex, PDF, log), then kill a second run of it with ``sig`` while it is at ``stage``
    (``"compile"``: pdflatex running; ``"tex"``: the .tex's temporary file written, not yet renamed); then
    run it once more.

    As for :func:`attack`, the outcome of one ``(stage, sig)`` is kept for the process: the acceptance table
    (tests/acceptance/cases_files.py) and tests/export/test_symlink_safety.py share one run of each (they are one
    xdist group, ``file-attacks``).
    """
    key = (stage, int(sig))
    if key not in _KILLED:
        _KILLED[key] = _killed_run(work, stage, sig)
    return _KILLED[key]


def _killed_run(work: Path, stage: str, sig: int) -> Killed:
    out = work / "out"
    path = fake_tex(work / "bin")
    src = str(Path(__file__).resolve().parents[1] / "src")
    with environment(PATH=path):
        code, err = run_cli(["report", str(derivation_file(work, "first")), "--out", str(out), "--pdf"])
    if code != 0:
        raise RuntimeError(f"the first run failed: {err}")
    before = report_files(out)
    flag = work / "flag"
    env = {**os.environ, "PYTHONPATH": src, "PATH": path}
    # a second run that may replace them (an existing PDF is replaced only with --overwrite), killed on the way
    argv = ["report", str(derivation_file(work, "second: another title")), "--out", str(out), "--overwrite"]
    if stage == "compile":
        env["THINLAYER_TEST_FLAG"] = str(flag)
        cmd = [sys.executable, "-m", "thinlayer", *argv, "--pdf"]
    else:
        cmd = [sys.executable, "-c", _SLOW_FSYNC, str(flag), *argv]
    p = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True,
                         **CHILD)
    try:
        if not wait_for(lambda: flag.exists() or p.poll() is not None) or not flag.exists():
            p.kill()
            p.wait()
            return Killed(stage, sig, p.pid, None, "never reached the stage: " + p.stderr.read().decode()[-500:],
                          before, report_files(out), leftovers(out), -1, "", [], {}, False)
        p.send_signal(sig)
        start = time.monotonic()
        _, raw = p.communicate(timeout=300)
        stop = time.monotonic() - start
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
        with contextlib.suppress(ProcessLookupError):
            os.killpg(p.pid, signal.SIGKILL)  # a fake pdflatex left sleeping by SIGKILL
    after, left = report_files(out), leftovers(out)
    with environment(PATH=path):
        next_code, next_err = run_cli(argv + ["--pdf"])
    return Killed(stage, sig, p.pid, p.returncode, raw.decode(errors="replace"), before, after, left, next_code,
                  next_err, leftovers(out), report_files(out), (out / ".inj.lock").exists(), stop)
