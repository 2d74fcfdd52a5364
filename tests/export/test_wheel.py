"""The wheel: every module and the derivation catalogue ship in it, and its CLI runs outside the repository.

The wheel is built from a copy of the project (``pip wheel --no-deps``, with the build backend of
pyproject.toml), installed into a temporary virtual environment (``--system-site-packages`` so that
sympy, numpy, ... need no download) and checked to be the one imported: ``thinlayer.__file__`` lies in
that environment, not in the repository's ``src``.  Then ``thinlayer report frictionless_sphere`` (a catalogue
name; one that builds in ~2 s: the sphere's report takes ~15 s and the lookup does not depend on the derivation)
runs in a temporary folder.  About 25 s on two cores, so it runs in the normal suite.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CATALOGUE = sorted((ROOT / "derivations").glob("*.toml"))


def _run(cmd: list[str], cwd: Path, timeout: float = 300, env: dict | None = None) -> subprocess.CompletedProcess:
    res = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout, env=env,
                         stdin=subprocess.DEVNULL)
    what = f"{' '.join(cmd)} failed ({res.returncode})"
    assert res.returncode == 0, f"{what}:\n{res.stdout[-2000:]}\n{res.stderr[-2000:]}"
    return res


def _build_backend_installed() -> bool:
    """Whether this environment has the build requirements of pyproject.toml (``setuptools>=N`` and ``wheel``: the
    test extra installs them), so that pip builds with them instead of installing them into an isolated environment
    first (~6 s of CPU, and a download on a machine without pip's cache)."""
    import importlib.util
    import re
    from importlib.metadata import PackageNotFoundError, version

    try:
        import tomllib
    except ImportError:  # Python 3.10: tomli, a dependency there
        import tomli as tomllib

    requires = tomllib.loads((ROOT / "pyproject.toml").read_text())["build-system"]["requires"]
    need = {m.group(1): int(m.group(2) or 0) for r in requires for m in [re.match(r"(\w+)(?:>=(\d+))?", r)] if m}
    try:
        have = {name: int(version(name).split(".")[0]) for name in need}
    except (PackageNotFoundError, ValueError):
        return False
    return all(have[n] >= v for n, v in need.items()) and importlib.util.find_spec("setuptools") is not None


@pytest.fixture(scope="module")
def wheel(tmp_path_factory) -> Path:
    """A wheel built from a copy of the project (the repository's own folder gets no build/ left behind)."""
    copy = tmp_path_factory.mktemp("project")
    ignore = shutil.ignore_patterns("__pycache__", "*.egg-info", "*.pyc")
    for name in ("pyproject.toml", "README.md"):
        shutil.copy(ROOT / name, copy / name)
    for name in ("src", "derivations"):
        shutil.copytree(ROOT / name, copy / name, ignore=ignore)
    out = tmp_path_factory.mktemp("dist")
    isolation = ["--no-build-isolation"] if _build_backend_installed() else []
    _run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", *isolation, "--wheel-dir", str(out), str(copy)],
         copy)
    (whl,) = out.glob("thinlayer-*.whl")
    return whl


def test_wheel_holds_every_module_and_the_catalogue(wheel):
    names = set(zipfile.ZipFile(wheel).namelist())
    src = ROOT / "src"
    modules = {p.relative_to(src).as_posix() for p in (src / "thinlayer").rglob("*.py") if "__pycache__" not in p.parts}
    assert modules and not modules - names, f"modules missing from the wheel: {sorted(modules - names)}"
    assert CATALOGUE, "the repository has no derivations/*.toml"
    with zipfile.ZipFile(wheel) as z:
        for f in CATALOGUE:
            packed = f"thinlayer/derivations/{f.name}"
            assert packed in names, f"{packed} is missing from the wheel"
            assert z.read(packed) == f.read_bytes(), f"{packed} differs from derivations/{f.name}"


def test_installed_wheel_reports_a_catalogue_derivation_outside_the_repository(wheel, tmp_path):
    env_dir = tmp_path / "venv"
    # no pip of its own (ensurepip costs ~5 s of CPU): this process's pip installs into it (pip --python)
    _run([sys.executable, "-m", "venv", "--without-pip", "--system-site-packages", str(env_dir)], tmp_path)
    py = env_dir / "bin" / "python"
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    # --ignore-installed: the repository's editable install is visible through the system site-packages
    _run([sys.executable, "-m", "pip", "--python", str(py), "install", "--quiet", "--no-deps", "--ignore-installed",
          str(wheel)], tmp_path, env=env)
    where = _run([str(py), "-c", "import thinlayer; print(thinlayer.__file__)"], tmp_path, env=env).stdout.strip()
    assert Path(where).resolve().is_relative_to(env_dir.resolve()), f"imported {where}, not the wheel's copy"
    assert not Path(where).resolve().is_relative_to(ROOT.resolve())
    work = tmp_path / "elsewhere"
    work.mkdir()
    res = _run([str(env_dir / "bin" / "thinlayer"), "report", "frictionless_sphere", "--out", "out"], work, env=env)
    tex = work / "out" / "frictionless_sphere.tex"
    assert tex.is_file(), res.stdout + res.stderr
    text = tex.read_text()
    assert r"\begin{document}" in text and r"\end{document}" in text
    # a bare name is the catalogue's (frictionless_sphere above; the README's first command names
    # elliptic_paraboloid, which the wheel holds byte for byte: the test above; its report is tested in
    # tests/test_readme.py and tests/test_newcomer.py); a path that does not exist is an error, never a silent
    # fall-back to the packaged copy (issue 28 item 5)
    res = subprocess.run([str(env_dir / "bin" / "thinlayer"), "report", "derivations/sphere.toml", "--out", "out"],
                         cwd=work, capture_output=True, text=True, timeout=300, env=env, stdin=subprocess.DEVNULL)
    assert res.returncode == 2 and "does not exist" in res.stderr and len(res.stderr.strip().splitlines()) == 1
    assert not (work / "out" / "sphere.tex").exists()
