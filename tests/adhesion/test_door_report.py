"""The [adhesion] table of derivation files and code generation of the thin-layer JKR law (issue 26 item 5).

The report itself (derivations/sphere_adhesive.toml, typeset with its figure) is checked with the catalogue in
tests/export/test_report_quality.py; here: the table's one-line errors, and the generated Python and C of (J.11)
and (J.15) against the engine's own evaluation of the law (lambdify of the derived expressions) to 1e-12.
"""
from __future__ import annotations

import ctypes
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from thinlayer.asymptotics.adhesion import thin_layer_jkr
from thinlayer.export.codegen import generate
from thinlayer.export.derivation import load_derivation
from thinlayer.export.sections.base import DerivationFileError

pytestmark = pytest.mark.xdist_group("adhesion-laws")

ROOT = Path(__file__).resolve().parents[2]
HEAD = '[derivation]\nname = "x"\ntitle = "x"\n[layer]\nmodel = "bonded"\nnu = "3/10"\n[punch]\nkind = "{kind}"\n'
C = np.array([0.6, 1.0, 3.0, 20.0])
H, R, W, MU = 0.1, 10.0, 0.01, 1.3


@pytest.mark.parametrize("kind, table, match", [
    ("paraboloid", "[adhesion]\nR = 1\n", "work_of_adhesion is required"),
    ("paraboloid", "[adhesion]\nwork_of_adhesion = -1\n", "work_of_adhesion"),
    ("paraboloid", "[adhesion]\nwork_of_adhesion = 0.1\nH_over_R = [0]\n", "H_over_R"),
    ("paraboloid", "[adhesion]\nwork_of_adhesion = 0.1\ncolour = 1\n", "unknown key"),
    ("elliptic_paraboloid", "[adhesion]\nwork_of_adhesion = 0.1\n", "paraboloid of revolution")])
def test_adhesion_table_errors_one_line(tmp_path, kind, table, match):
    path = tmp_path / "x.toml"
    path.write_text(HEAD.format(kind=kind) + table)
    with pytest.raises((DerivationFileError, ValueError), match=match) as exc:
        load_derivation(path)
    assert "\n" not in str(exc.value)


def test_shipped_file_reads_its_table():
    der = load_derivation(ROOT / "derivations" / "sphere_adhesive.toml")
    tab = der.sections["adhesion"]
    assert tab["work_of_adhesion"] == 0.05 and tab["R"] == 1.0 and tab["H_over_R"][0] == 0.01


def _python(law):
    gc = generate(law, "python")
    ns: dict = {}
    exec(compile(gc.source, "<generated>", "exec"), ns)  # the module thinlayer generated, not user input
    return gc, ns[gc.function_name]


@pytest.mark.parametrize("nu", [0.3, pytest.param(0.5, marks=pytest.mark.slow)])  # (J.15): 2 s of sympy
def test_generated_python_equals_the_law(nu):
    """(J.11) (nu = 0.3) and (J.15) (nu = 1/2): the generated numpy function against ThinLayerJKR.evaluate."""
    law = thin_layer_jkr(nu, 1)
    gc, fn = _python(law)
    assert gc.arguments == ("c", "H", "R", "w", "mu") and gc.outputs == ("delta0", "force")
    d, P = fn(C, H, R, W, MU)
    d0, P0 = law.evaluate(C, H, R, W, MU)
    np.testing.assert_allclose(d, d0, rtol=1e-12)
    np.testing.assert_allclose(P, P0, rtol=1e-12)
    assert ("(J.15)" if nu == 0.5 else "(J.11)") in gc.source


@pytest.mark.skipif(shutil.which("cc") is None and shutil.which("gcc") is None, reason="no C compiler")
def test_generated_c_compiles_and_equals_the_law(tmp_path):
    law = thin_layer_jkr(0.3, 1)
    gc = generate(law, "c")
    gc.write(tmp_path)
    lib = tmp_path / "libjkr.so"
    cc = shutil.which("cc") or shutil.which("gcc")
    subprocess.run([cc, "-std=c99", "-Wall", "-Werror", "-O2", "-fPIC", "-shared", "-o", str(lib),
                    str(tmp_path / gc.main_file), "-lm"], check=True, capture_output=True, stdin=subprocess.DEVNULL)
    f = getattr(ctypes.CDLL(str(lib)), gc.function_name)
    f.restype, f.argtypes = None, [ctypes.c_double] * 5 + [ctypes.POINTER(ctypes.c_double)]
    d0, P0 = law.evaluate(C, H, R, W, MU)
    for i, c in enumerate(C):
        out = (ctypes.c_double * 2)()
        f(float(c), H, R, W, MU, out)
        assert abs(out[0] / d0[i] - 1) < 1e-12 and abs(out[1] / P0[i] - 1) < 1e-12


def test_cli_codegen_jkr_refuses_without_nu(capsys):
    from thinlayer.export.cli import main

    assert main(["codegen", "jkr", "--lang", "c"]) == 2
    err = capsys.readouterr().err.strip()
    assert "--nu" in err and "\n" not in err
