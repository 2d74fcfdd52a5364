"""The second-order laws (SO.9), (SO.10) on the command line and in code generation (issue 16, item 4).

``thinlayer codegen force --order 2``: the generated C (compiled with gcc) and numpy code against
:meth:`SecondOrderLaw.evaluate` (mpmath edge integrals, an independent route from the generated closed forms) to
1e-12 relative, for the sphere and the radial monomial ``r^4``; the elliptic paraboloid (complete elliptic
integrals) is one clear line and exit code 2.  ``thinlayer solve --order 2`` against ``thinlayer.solve(...,
order=2)``; bad orders are one line and exit code 2.
"""
from __future__ import annotations

import ctypes
import importlib.util
import json
import math
import shutil
import subprocess

import pytest

from thinlayer import BondedLayer, FrictionlessLayer, Punch
from thinlayer.asymptotics.second_order import second_order_law
from thinlayer.export.cli import _codegen_result, build_parser, main
from thinlayer.export.codegen import generate

RTOL = 1e-12
#: (delta0, H, mu[, R]) points: thin to moderately thin layers, two moduli
SPHERE_POINTS = [(0.5, 0.05, 1.0, 1.0), (0.1, 0.01, 2.5, 10.0), (0.3, 0.08, 0.7, 3.0), (2.0, 0.3, 1.0, 5.0)]
QUARTIC_POINTS = [(0.5, 0.05, 1.0), (0.1, 0.01, 2.5), (1.7, 0.08, 0.7)]


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def run_c(gc, points, tmp):
    """Compile the generated C (strict flags) as a shared library and call it at ``points``."""
    gcc = shutil.which("gcc")
    if gcc is None:
        pytest.skip("gcc not found: install it with `apt-get install gcc` to compile the generated C code")
    gc.write(tmp)
    lib = tmp / f"lib{gc.function_name}.so"
    subprocess.run([gcc, "-std=c99", "-pedantic", "-Wall", "-Wextra", "-Werror", "-O2", "-fPIC", "-shared", "-o",
                    str(lib), str(tmp / gc.main_file), "-lm"], check=True, capture_output=True, text=True,
                   stdin=subprocess.DEVNULL)
    f = getattr(ctypes.CDLL(str(lib)), gc.function_name)
    f.restype = None
    f.argtypes = [ctypes.c_double] * len(gc.arguments) + [ctypes.POINTER(ctypes.c_double)]
    rows = []
    for pt in points:
        out = (ctypes.c_double * len(gc.outputs))()
        f(*map(float, pt), out)
        rows.append(tuple(out))
    return rows


def _generate(capsys, tmp_path, argv, lang):
    out = tmp_path / lang
    code, text, err = run(capsys, "codegen", "force", "--order", "2", *argv, "--lang", lang, "--out", str(out),
                          "--json")
    assert code == 0, err
    return out, json.loads(text)["files"]


def _reference(layer, punch, pt):
    v = second_order_law(layer, punch).evaluate(pt[0], pt[1], pt[2], parameters={"R": pt[3]} if len(pt) > 3 else {})
    return v.force, v.area


CASES = {
    "sphere-0.3": (["--kind", "paraboloid", "--nu", "3/10"], BondedLayer("3/10"), Punch.paraboloid(), SPHERE_POINTS),
    "sphere-0.45": (["--kind", "paraboloid", "--nu", "0.45"], BondedLayer(0.45), Punch.paraboloid(), SPHERE_POINTS),
    "r4-0.3": (["--punch", "(x_1**2 + x_2**2)**2", "--nu", "3/10"], BondedLayer("3/10"),
               Punch("(x_1**2 + x_2**2)**2"), QUARTIC_POINTS),
}


@pytest.mark.parametrize("key", list(CASES))
def test_generated_numpy_matches_evaluate(key, capsys, tmp_path):
    argv, layer, punch, points = CASES[key]
    out, files = _generate(capsys, tmp_path, argv, "python")
    (path,) = files
    spec = importlib.util.spec_from_file_location("gen_second_order", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    for pt in points:
        P, A = mod.force_law_second_order(*pt)
        Pr, Ar = _reference(layer, punch, pt)
        assert float(P) == pytest.approx(Pr, rel=RTOL) and float(A) == pytest.approx(Ar, rel=RTOL), (key, pt)


@pytest.mark.parametrize("key", list(CASES))
def test_generated_c_matches_evaluate(key, capsys, tmp_path):
    argv, layer, punch, points = CASES[key]
    args = build_parser().parse_args(["codegen", "force", "--order", "2", *argv])
    gc = generate(_codegen_result(args), "c")
    assert gc.function_name == "force_law_second_order" and list(gc.outputs) == ["force", "contact_area"]
    got = run_c(gc, points, tmp_path / "build")
    for pt, (P, A) in zip(points, got):
        Pr, Ar = _reference(layer, punch, pt)
        assert P == pytest.approx(Pr, rel=RTOL) and A == pytest.approx(Ar, rel=RTOL), (key, pt)
    # the CLI writes the same C file
    out, files = _generate(capsys, tmp_path, argv, "c")
    assert (out / "force_law_second_order.c").read_text() == gc.files["force_law_second_order.c"]


def test_second_order_differs_from_first_by_p2(capsys, tmp_path):
    # the generated law is the second order, not the first: P - P_first = P_2 = (12 r_3 (H/a)^3) P_0 for the sphere
    from thinlayer.asymptotics.second_order import edge_constants

    out, (path,) = _generate(capsys, tmp_path, CASES["sphere-0.3"][0], "python")
    spec = importlib.util.spec_from_file_location("gen_so2", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    delta0, H, mu, R = 0.5, 0.05, 1.0, 1.0
    v = second_order_law(BondedLayer("3/10"), Punch.paraboloid()).evaluate(delta0, H, mu, parameters={"R": R})
    P, _ = mod.force_law_second_order(delta0, H, mu, R)
    a = math.sqrt(2 * R * delta0)
    c = edge_constants(BondedLayer("3/10"))
    assert (float(P) - v.force_first) / v.P0 == pytest.approx(12 * c.r3 * (H / a) ** 3, rel=1e-10)


def test_frictionless_base(capsys, tmp_path):
    out, (path,) = _generate(capsys, tmp_path, ["--kind", "paraboloid", "--base", "frictionless"], "python")
    spec = importlib.util.spec_from_file_location("gen_so3", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    P, A = mod.force_law_second_order(0.5, 0.05, 1.0, 1.0, 0.3)  # delta0, H, mu, R, nu
    v = second_order_law(FrictionlessLayer(), Punch.paraboloid()).evaluate(0.5, 0.05, 1.0, parameters={"R": 1.0},
                                                                            nu=0.3)
    assert float(P) == pytest.approx(v.force, rel=RTOL) and float(A) == pytest.approx(v.area, rel=RTOL)


@pytest.mark.parametrize("argv, reason", [
    (["--kind", "elliptic_paraboloid", "--nu", "0.3"], "elliptic integrals"),
    (["--kind", "paraboloid"], "numeric --nu"),
    (["--kind", "paraboloid", "--nu", "symbolic"], "numeric --nu"),
    (["--punch", "x_1**2/2 + x_2**4", "--nu", "0.3"], "no closed-form"),
    (["--kind", "paraboloid", "--nu", "0.3", "--order", "3"], "--order 3"),
])
def test_codegen_refusals_are_one_line(capsys, argv, reason):
    full = ["codegen", "force", "--order", "2", *argv]
    code, out, err = run(capsys, *full)
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1 and reason in err, err


# ---------------------------------------------------------------------------------------------
# thinlayer solve --order 2
# ---------------------------------------------------------------------------------------------
SOLVE = ["solve", "--mu", "1", "--nu", "0.3", "--kind", "paraboloid", "--param", "R=10", "--delta0", "0.1", "--H",
         "0.05"]


def test_solve_order_2_matches_the_api(capsys):
    from thinlayer import solve

    code, out, err = run(capsys, *SOLVE, "--order", "2", "--json")
    assert code == 0, err
    data = json.loads(out)
    ans = solve(BondedLayer(0.3), Punch.paraboloid(10), delta0=0.1, H=0.05, mu=1.0, order=2)
    assert data["force"] == pytest.approx(ans.force, rel=1e-14)
    assert data["contact_area"] == pytest.approx(ans.contact_area, rel=1e-14)
    assert data["order"] == 2
    # the second-order law itself, by its own evaluation: P = P0 + P1 + P2
    v = second_order_law(BondedLayer(0.3), Punch.paraboloid()).evaluate(0.1, 0.05, 1.0, parameters={"R": 10})
    assert data["force"] == pytest.approx(v.force, rel=1e-12)
    assert data["force_second_correction"] == pytest.approx(v.P2, rel=1e-12)
    code, out1, _ = run(capsys, *SOLVE, "--json")
    first = json.loads(out1)
    assert "order" not in first and first["force"] != data["force"]
    assert first["force"] == pytest.approx(v.force_first, rel=1e-12)
    code, out2, _ = run(capsys, *SOLVE, "--order", "1", "--json")
    assert json.loads(out2) == first


@pytest.mark.parametrize("value", ["3", "x", "0", "2.0", ""])
def test_solve_bad_order_is_one_line(capsys, value):
    code, out, err = run(capsys, *SOLVE, "--order", value)
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert "--order" in err and "1 or 2" in err


def test_solve_order_2_with_a_flat_punch_is_refused(capsys):
    code, out, err = run(capsys, "solve", "--flat", "1", "--nu", "0.3", "--delta0", "0.01", "--H", "0.5", "--E",
                         "2.6", "--order", "2")
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1 and "--order" in err
