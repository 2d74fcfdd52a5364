"""Generated code of the flat punch's asymptotic laws (issue 14 item 5): kappa(a/H) and its estimate.

The generated numpy module and C agree with the engine's own evaluation of the laws to 1e-13; the laws
themselves are checked against the exact Fredholm solution in tests/asymptotics/test_flat_punch_asymptotics.py.
The nearly incompressible thin law (F.15) needs Bessel functions: Julia and Octave only, one-line refusal elsewhere.
"""
from __future__ import annotations

import numpy as np
import pytest

import thinlayer as tl
from thinlayer.asymptotics.flat_punch import thick_flat_punch, thin_flat_punch
from thinlayer.export.codegen import generate

X = np.array([0.05, 0.3, 0.79, 2.0, 10.0, 60.0])


def _python(model):
    gc = generate(model, "python")
    ns: dict = {}
    exec(compile(gc.source, "<generated>", "exec"), ns)  # the module thinlayer generated, not user input
    return ns[gc.function_name]


@pytest.mark.parametrize("layer", [tl.IncompressibleLayer(), tl.FrictionlessLayer(), tl.BondedLayer(0.2)], ids=str)
def test_thin_law_generated_python(layer):
    model = thin_flat_punch(layer)
    kappa, est = _python(model)(X)
    np.testing.assert_allclose(kappa, model(X), rtol=1e-13)
    np.testing.assert_allclose(est, model.error_estimate(X), rtol=1e-13)


@pytest.mark.parametrize("layer", [tl.BondedLayer(0.3), tl.IncompressibleLayer(), tl.FrictionlessLayer()], ids=str)
def test_thick_series_generated_python_flags_its_range(layer):
    model = thick_flat_punch(layer)
    kappa, est = _python(model)(X)
    np.testing.assert_allclose(kappa, model(X), rtol=1e-13)
    inside = X < 0.8
    np.testing.assert_allclose(est[inside], model.error_estimate(X[inside]), rtol=1e-12)
    assert np.all(est[~inside] == 1.0)  # beyond the series' range: no accuracy claimed


def test_generated_c_compiles_and_agrees(tmp_path):
    from test_codegen import run_c

    for model in (thin_flat_punch(tl.IncompressibleLayer()), thick_flat_punch(tl.BondedLayer(0.3))):
        out = run_c(generate(model, "c"), [[x] for x in X], tmp_path)
        np.testing.assert_allclose(out[:, 0], model(X), rtol=1e-13)


def test_bessel_law_in_julia_octave_refused_elsewhere():
    model = thin_flat_punch(tl.BondedLayer(0.45))  # 1/4 < nu < 1/2: (F.15) with I_0, I_1
    assert "besseli" in generate(model, "julia").source
    with pytest.raises(NotImplementedError, match="besseli"):
        generate(model, "c")


def test_cli_codegen_flat_punch(capsys):
    from thinlayer.export.cli import main

    assert main(["codegen", "flat-punch", "--nu", "0.5", "--lang", "python"]) == 0
    assert "def flat_punch_kappa_thin(a_over_H)" in capsys.readouterr().out
    assert main(["codegen", "flat-punch", "--nu", "0.3", "--law", "thick", "--lang", "c"]) == 0
    assert "flat_punch_kappa_thick" in capsys.readouterr().out
    assert main(["codegen", "flat-punch", "--lang", "c"]) == 2
    assert "give --nu" in capsys.readouterr().err


def test_any_thickness_table_python_and_c_against_the_exact_solution(tmp_path):
    # issue 15 item 3 for the flat punch: the exact kappa tabulated (F.6)-(F.7), checked half-way between nodes
    import ctypes
    import shutil
    import subprocess

    from thinlayer.contact.flat_punch import SOURCE_POINTS, SOURCE_RANGE, flat_punch_source
    from thinlayer.numerics.flat_punch import flat_punch_kappa

    layer = tl.BondedLayer(0.45)
    grid = np.exp(np.linspace(np.log(SOURCE_RANGE[0]), np.log(SOURCE_RANGE[1]), SOURCE_POINTS))
    mids = np.sqrt(grid[1:] * grid[:-1])[::9]
    exact = np.array([flat_punch_kappa(layer, float(x)).kappa for x in mids])
    ns: dict = {}
    exec(compile(flat_punch_source(layer, "python"), "<generated>", "exec"), ns)
    assert np.max(np.abs(ns["kappa"](mids) / exact - 1)) < 2e-7
    assert np.isnan(ns["kappa"](250.0)) and np.isnan(ns["kappa"](-1.0))
    small = flat_punch_kappa(layer, 2e-4).kappa  # below the table: the thick series (F.18)
    assert abs(ns["kappa"](2e-4) / small - 1) < 1e-12
    gcc = shutil.which("gcc")
    if gcc is None:
        pytest.skip("gcc not found: apt-get install gcc to compile the generated C")
    (tmp_path / "k.c").write_text(flat_punch_source(layer, "c"))
    lib = tmp_path / "libk.so"
    subprocess.run([gcc, "-std=c99", "-pedantic", "-Wall", "-Wextra", "-Werror", "-O2", "-fPIC", "-shared", "-o",
                    str(lib), str(tmp_path / "k.c"), "-lm"], check=True, capture_output=True,
                   stdin=subprocess.DEVNULL)
    f = ctypes.CDLL(str(lib)).thinlayer_flat_punch_kappa
    f.restype, f.argtypes = ctypes.c_double, [ctypes.c_double]
    np.testing.assert_allclose([f(float(x)) for x in mids], ns["kappa"](mids), rtol=1e-14)
