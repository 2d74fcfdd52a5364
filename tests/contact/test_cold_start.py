"""Cold start of the daily path (issue 28 item 6): a numeric solve() loads neither sympy nor scipy, and its numbers
are the symbolic route's.

* a fresh process that solves the sphere with its per-nu constants on disk imports neither sympy nor scipy;
* the numeric route of a quadric punch (``thinlayer.asymptotics.solution.compressible_constants`` from the disk
  cache, the punch's level set in floats) equals the symbolic route (the force law (1.8) derived by sympy and
  evaluated by mpmath, (3.25) with the Wiener--Hopf h*) to 1e-12 relative, forward and inverse, on a grid of nu,
  bases, punches, depths and thicknesses;
* a damaged cache entry of those constants is ignored and rebuilt.

Timing targets are in ``benchmarks/bench_cold_start.py``, not here.
"""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import thinlayer as tl
from thinlayer import _cache
from thinlayer.asymptotics import solution as sol_mod
from thinlayer.asymptotics.solution import compressible_constants, compressible_solution

SOLVE = ("import sys, thinlayer as tl\n"
         "ans = tl.solve(tl.BondedLayer(0.3), tl.Punch.paraboloid(10), delta0=0.1, H=0.05, mu=1.0)\n"
         "print(repr(ans.force), repr(ans.contact_area), ans.model, 'sympy' in sys.modules, 'scipy' in sys.modules)\n")


def _run(code: str, env: dict) -> list[str]:
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=600,
                         stdin=subprocess.DEVNULL)
    assert out.returncode == 0, out.stderr
    return out.stdout.split()


def test_a_numeric_solve_with_constants_on_disk_imports_neither_sympy_nor_scipy(tmp_path):
    env = {**os.environ, "THINLAYER_CACHE_DIR": str(tmp_path)}
    env.pop("THINLAYER_CACHE", None)
    first = _run(SOLVE, env)  # the first run ever of nu = 0.3 derives the constants (sympy) and stores them
    assert list(tmp_path.rglob("compressible_constants*.json")), "the constants were not stored"
    again = _run(SOLVE, env)
    assert again[3:] == ["False", "False"], f"sympy/scipy imported by a numeric solve(): {again}"
    assert again[2] == "compressible"
    # the same numbers as the run that derived them, and as the paper's law (1.8): P0 (1 - 2 m1 H^2/(R delta0))
    assert again[:2] == first[:2]
    P0 = math.pi * (1 / 0.7) * 10 * 0.1**2 / (0.2 / 0.49 * 0.05)
    assert float(again[0]) == pytest.approx(P0 * (1 - 2 / 14 * 0.05**2 / (10 * 0.1)), rel=1e-13)


def test_a_damaged_constants_entry_is_ignored_and_rebuilt(tmp_path, monkeypatch):
    monkeypatch.setenv("THINLAYER_CACHE_DIR", str(tmp_path))
    monkeypatch.delenv("THINLAYER_CACHE", raising=False)
    layer = tl.BondedLayer(0.27)
    monkeypatch.setattr(sol_mod, "_CONSTANTS", {})
    good = compressible_constants(layer)
    path = _cache.entry_path("compressible_constants", layer.constants_key)
    assert path.exists()
    path.write_text('{"format": 1, "value": {"t": [{"f": "0x1.0p+0"}]}')  # truncated JSON, a wrong value inside
    monkeypatch.setattr(sol_mod, "_CONSTANTS", {})
    assert compressible_constants(layer) == good
    json.loads(path.read_text())  # rewritten whole
    assert good["m1"] == pytest.approx(float(layer.m(1)), rel=1e-15)


# ---------------------------------------------------------------------------------------------
# the numeric route against the symbolic one
# ---------------------------------------------------------------------------------------------
LAYERS = [tl.BondedLayer(0), tl.BondedLayer(0.3), tl.BondedLayer(0.45), tl.BondedLayer(0.49),
          tl.FrictionlessLayer(0.3)]
PUNCHES = [(tl.Punch.paraboloid, (10,)), (tl.Punch.elliptic_paraboloid, (4, 1.5))]
CASES = [(0.1, 0.05), (0.3, 0.02), (0.05, 0.01)]  # (delta0, H): H/a from 0.014 to 0.05
KEYS = ("force", "force_leading", "contact_area", "contact_area_leading", "contact_area_alexandrov", "edge_shift",
        "edge_shift_alexandrov", "half_width", "delta0")


def _both(monkeypatch, layer, make, args, **kw):
    monkeypatch.setattr(sol_mod, "NUMERIC_QUADRIC", True)
    fast = compressible_solution(layer, make(*args), tol=math.inf, **kw)
    assert fast._law is None, "the numeric route was not taken"
    monkeypatch.setattr(sol_mod, "NUMERIC_QUADRIC", False)
    slow = compressible_solution(layer, make(*args), tol=math.inf, **kw)
    assert slow._law is not None
    return fast, slow


@pytest.mark.parametrize("layer", LAYERS, ids=repr)
@pytest.mark.parametrize("make, args", PUNCHES, ids=["paraboloid", "elliptic"])
def test_numeric_route_equals_the_symbolic_route(monkeypatch, layer, make, args):
    for d0, H in CASES:
        fast, slow = _both(monkeypatch, layer, make, args, delta0=d0, H=H, mu=1.3)
        for key in KEYS:
            assert getattr(fast, key) == pytest.approx(getattr(slow, key), rel=1e-12, abs=1e-300), (key, d0, H)
        for key in ("force", "contact_area"):
            assert fast.error_estimate[key] == pytest.approx(slow.error_estimate[key], rel=1e-12), (key, d0, H)
        # the inverse problem (force=): the depth back, by both routes
        fi, si = _both(monkeypatch, layer, make, args, force=slow.force, H=H, mu=1.3)
        assert fi.delta0 == pytest.approx(si.delta0, rel=1e-12)
        assert fi.delta0 == pytest.approx(d0, rel=1e-12)
        # leading order alone (order=0), forward
        f0, s0 = _both(monkeypatch, layer, make, args, delta0=d0, H=H, mu=1.3, order=0)
        assert f0.force == pytest.approx(s0.force, rel=1e-12)
        assert f0.error_estimate["force"] == pytest.approx(s0.error_estimate["force"], rel=1e-12)
    # the result keeps its symbolic side: the law (derived on first access), LaTeX and the pressure
    assert fast.law.kind == "quadratic" and fast.law.P0 == slow.law.P0
    assert fast.latex() == slow.latex()
    x = np.array([0.0, 0.3])
    assert np.allclose(fast.pressure(x, 0 * x), slow.pressure(x, 0 * x), rtol=1e-12)


def test_solve_takes_the_numeric_route_and_keeps_latex_and_pressure(monkeypatch):
    layer, punch = tl.BondedLayer(0.3), tl.Punch.elliptic_paraboloid(4, 1.5)
    monkeypatch.setattr(sol_mod, "NUMERIC_QUADRIC", True)
    fast = tl.solve(layer, punch, delta0=0.1, H=0.02, mu=1.0)
    monkeypatch.setattr(sol_mod, "NUMERIC_QUADRIC", False)
    slow = tl.solve(layer, tl.Punch("x_1**2/8 + x_2**2/3"), delta0=0.1, H=0.02, mu=1.0)
    assert fast.model == slow.model == "compressible"
    assert fast.detail._law is None and slow.detail._law is not None
    for key in ("force", "contact_area", "delta0"):
        assert getattr(fast, key) == pytest.approx(getattr(slow, key), rel=1e-12)
    assert fast.semi_axes == pytest.approx(slow.semi_axes, rel=1e-12)
    assert fast.error_estimate == pytest.approx(slow.error_estimate, rel=1e-12)
    assert fast.max_pressure == pytest.approx(slow.max_pressure, rel=1e-9)
    assert r"\Phi" in fast.detail.latex()


def test_a_catalogue_punch_with_numbers_answers_as_the_symbolic_one():
    for fast, slow in [(tl.Punch.paraboloid(10), tl.Punch("(x_1**2 + x_2**2)/20", name="paraboloid of revolution")),
                       (tl.Punch.paraboloid(2.5), tl.Punch("(x_1**2 + x_2**2)/(2*2.5)",
                                                           name="paraboloid of revolution")),
                       (tl.Punch.elliptic_paraboloid(4, 1.5),
                        tl.Punch("x_1**2/8 + x_2**2/3.0", name="elliptic paraboloid"))]:
        assert fast._spec is not None and slow._spec is None
        assert fast.quadric == slow.quadric
        assert fast.sphere_radius == slow.sphere_radius
        assert fast.axisymmetric == slow.axisymmetric
        assert fast.parameters == slow.parameters == ()
        x1, x2 = np.array([0.1, -2.0, 3.0]), np.array([0.5, 1.0, -0.25])
        assert np.allclose(fast.profile(x1, x2), slow.profile(x1, x2), rtol=1e-15)
        assert fast.level_set(0.2) == slow.level_set(0.2)
        assert fast == slow and hash(fast) == hash(slow)  # Phi built on first use: the same expression
        assert fast.degree == 2 and fast.polynomial == slow.polynomial
        assert str(fast) == str(slow)


CLI = ("import sys\n"
       "from thinlayer.export.cli import main\n"
       "rc = main(['solve', '--nu', '0.3', {tip}, '--delta0', '0.1', '--H', '0.05', '--mu', '1'])\n"
       "print('MODULES', rc, 'sympy' in sys.modules, 'scipy' in sys.modules)\n")


@pytest.mark.parametrize("tip", ["'--kind', 'paraboloid', '--param', 'R=10'", "'--tip', 'paraboloid:R=10'"],
                         ids=["kind-param", "tip-spec"])
def test_thinlayer_solve_of_the_sphere_imports_neither_sympy_nor_scipy(tmp_path, tip):
    env = {**os.environ, "THINLAYER_CACHE_DIR": str(tmp_path)}
    env.pop("THINLAYER_CACHE", None)
    code = CLI.format(tip=tip)
    first = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=600,
                           stdin=subprocess.DEVNULL)
    again = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=600,
                           stdin=subprocess.DEVNULL)
    assert first.returncode == again.returncode == 0, again.stderr
    assert again.stdout.splitlines()[-1] == "MODULES 0 False False", again.stdout
    assert again.stdout == first.stdout.replace(first.stdout.splitlines()[-1], again.stdout.splitlines()[-1])
    lines = again.stdout.splitlines()
    assert lines[0] == "paraboloid of revolution, Φ = (x₁² + x₂²)/(2R), R = 10"
    assert "P = 21.983295" in again.stdout and "model: compressible" in again.stdout


def test_a_tip_spec_with_numbers_answers_as_the_symbolic_punch(capsys):
    """``--tip elliptic_paraboloid:R1=10,R2=5`` (numeric route) prints the numbers of ``--punch`` with the same Phi
    (the symbolic route through sympy) and names both radii."""
    from thinlayer.export.cli import main

    common = ["solve", "--nu", "0.3", "--delta0", "0.1", "--H", "0.05", "--mu", "1"]
    assert main([*common, "--tip", "elliptic_paraboloid:R1=10,R2=5"]) == 0
    fast = capsys.readouterr().out.splitlines()
    assert main([*common, "--punch", "x_1**2/20 + x_2**2/10"]) == 0
    slow = capsys.readouterr().out.splitlines()
    assert fast[0] == "elliptic paraboloid, Φ = x₂²/(2R₂) + x₁²/(2R₁), R₁ = 10, R₂ = 5"
    assert fast[1:] == slow[1:]


def test_the_printed_catalogue_formulas_are_the_printers():
    from thinlayer.export.solve_cli import RADIUS_TEXT
    from thinlayer.normal import normal_text, symbol_text
    from thinlayer.punch.polynomial import CATALOGUE_TEXT

    assert CATALOGUE_TEXT["paraboloid"] == normal_text(tl.Punch.paraboloid().expr)
    assert CATALOGUE_TEXT["elliptic"] == normal_text(tl.Punch.elliptic_paraboloid().expr)
    assert tl.Punch.paraboloid(3).formula_text == CATALOGUE_TEXT["paraboloid"]
    assert tl.Punch.paraboloid().formula_text is None
    for name in ("R1", "R_1", "R2", "R_2", "R", "radius"):
        assert RADIUS_TEXT.get(name, name) == symbol_text(name)


def test_the_cache_folder_version_is_the_installed_version():
    """The cache folder's version is read off the dist-info folder's name (no import of importlib.metadata); it is
    the version importlib.metadata reports."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        installed = version("thinlayer")
    except PackageNotFoundError:
        installed = "source"
    assert (_cache._dist_info_version() or _cache._metadata_version()) == installed
