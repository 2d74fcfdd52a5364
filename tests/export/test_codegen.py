"""Code generation (issue 5, item 3): C, Fortran, Rust, Julia, Octave and a standalone numpy module.

Identifiers and collisions are tested in ``test_codegen_names.py``, bad inputs in ``test_codegen_spec.py``.

The generated C, Fortran and Rust are compiled (gcc, gfortran, rustc), run at about ten argument
points and compared with ``checked_lambdify(..., "numpy")`` to 1e-12 relative.  A missing compiler
skips its tests and names the Debian package that provides it.  The standalone Python module is
imported in a subprocess in which ``import sympy`` fails.

Julia and Octave output is compared with the golden files in ``tests/golden/``.  They were reviewed
by eye when written; they only freeze the output (a change in sympy's printers or in thinlayer shows
up as a diff), they are not an independent check of correctness.  ``sympy_version.txt`` records the
sympy that wrote them; under another sympy minor release a difference skips the test with a reason
instead of failing it (sympy 1.12 and 1.13 print these cases identically to 1.14).
When a change is intended, regenerate them and review the diff::

    THINLAYER_UPDATE_GOLDEN=1 python3 -m pytest -q tests/export/test_codegen.py

If ``octave`` happens to be installed, the Octave output is also run; Julia is never run here.
"""
from __future__ import annotations

import ctypes
import difflib
import importlib.util
import os
import shutil
import subprocess
import sys
import textwrap
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import mpmath
import numpy as np
import pytest
import sympy as sp

from thinlayer import (
    BondedLayer,
    Punch,
    checked_lambdify,
    inner_pressure,
    kernel_coefficients,
)
from thinlayer.export.codegen import LANGUAGES, generate, generate_all

GOLDEN = Path(__file__).resolve().parents[1] / "golden"
UPDATE = os.environ.get("THINLAYER_UPDATE_GOLDEN") == "1"
RTOL = 1e-12

COMPILERS = {"c": ("gcc", "gcc"), "fortran": ("gfortran", "gfortran"), "rust": ("rustc", "rustc")}
LABEL = {"c": "C", "fortran": "Fortran", "rust": "Rust"}


def need(language: str) -> str:
    exe, package = COMPILERS[language]
    path = shutil.which(exe)
    if path is None:
        pytest.skip(f"{exe} not found: install it with `apt-get install {package}` to compile the "
                    f"generated {LABEL[language]} code")
    return path


# ---------------------------------------------------------------------------------------------
# the cases: a result, its argument points, the reference values
# ---------------------------------------------------------------------------------------------

@dataclass
class Case:
    key: str
    result: object
    args: tuple
    exprs: tuple
    points: np.ndarray  # (n_points, n_args)
    kwargs: dict

    def generate(self, language):
        return generate(self.result, language, **self.kwargs)

    def reference(self) -> np.ndarray:
        """(n_points, n_outputs) from the numpy lambdification, point by point (math.erf is scalar)."""
        f = checked_lambdify(self.args, list(self.exprs), "numpy")
        with np.errstate(invalid="ignore"):  # numpy.select evaluates sqrt(v - h) for v < h too
            return np.array([[float(v) for v in f(*pt)] for pt in self.points])


def _inner_case() -> Case:
    # (2.26) for the elliptic paraboloid (1.1), nu = 3/10: the two non-zero terms p_0, p_1
    ip = inner_pressure(BondedLayer(sp.Rational(3, 10)), Punch.elliptic_paraboloid())
    assert ip.nonzero_terms == 2
    rng = np.random.default_rng(5)
    n = 10
    R1, R2 = rng.uniform(5, 20, n), rng.uniform(5, 20, n)
    delta0, H, mu = rng.uniform(0.05, 0.2, n), rng.uniform(0.05, 0.2, n), rng.uniform(0.5, 2, n)
    # points well inside the contact area, delta0 - Phi > delta0/2, so p is not near a zero
    s = rng.uniform(0, 0.5, n)
    ang = rng.uniform(0, 2 * np.pi, n)
    x1, x2 = np.sqrt(2 * s * delta0 * R1) * np.cos(ang), np.sqrt(2 * s * delta0 * R2) * np.sin(ang)
    pts = np.column_stack([x1, x2, delta0, H, mu, R1, R2])
    return Case("inner_pressure", ip, ip.arguments, (ip.pressure,), pts, {})


def _coefficient_case() -> Case:
    # A(nu), m_1..m_3 (2.20) and M_1..M_3 (4.2) with symbolic nu (includes A, m_1, M_1)
    kc = kernel_coefficients(BondedLayer(), 3)
    exprs = (kc.A_expr, *[kc.m_expr(n) for n in (1, 2, 3)], *[kc.M_expr(k) for k in (1, 2, 3)])
    nus = np.array([-0.9, -0.55, -0.3, -0.1, 0.05, 0.15, 0.27, 0.33, 0.41, 0.48])
    return Case("kernel_coefficients", kc, (kc.layer.parameter,), exprs, nus[:, None], {})


V, HH, B = sp.symbols("v h B", positive=True)


def _special_case() -> Case:
    # the shape of Alexandrov's boundary-layer solution (3.24): Piecewise, erf, exp, sqrt, pi
    tau = V - HH
    q = sp.Piecewise((V * sp.erf(sp.sqrt(B * tau)) + sp.sqrt(tau / (sp.pi * B)) * sp.exp(-B * tau), V > HH),
                     (0, True))
    rng = np.random.default_rng(7)
    h = rng.uniform(0.1, 0.5, 10)
    v = h + np.array([-0.3, -0.01, 1e-6, 0.01, 0.1, 0.4, 1.0, 2.5, 4.0, 9.0])
    pts = np.column_stack([v, h, rng.uniform(0.2, 3, 10)])
    kwargs = {"args": [V, HH, B], "name": "boundary_layer_q"}
    return Case("boundary_layer_q", q, (V, HH, B), (q,), pts, kwargs)


def _force_law_case() -> Case:
    # (1.8) and (3.25) for the paraboloid of revolution, symbolic nu: force, |omega_0|, |omega|
    from thinlayer import force_law

    law = force_law(BondedLayer(), Punch.paraboloid())
    args, outs = law.codegen_expressions()
    assert [a.name for a in args] == ["delta_0", "H", "mu", "R", "h^*", "nu"]
    rng = np.random.default_rng(11)
    n = 10
    pts = np.column_stack([rng.uniform(0.05, 0.2, n), rng.uniform(0.005, 0.02, n), rng.uniform(0.5, 2, n),
                           rng.uniform(5, 20, n), rng.uniform(-0.5, 0.2, n), rng.uniform(-0.9, 0.45, n)])
    return Case("force_law", law, tuple(args), tuple(outs.values()), pts, {})


def _composite_case() -> Case:
    # composite pressure with Alexandrov's boundary layer (3.24) for a sphere: radial, closed form
    from thinlayer.asymptotics.solution import compressible_solution as solve

    sol = solve(BondedLayer(0.3), Punch.paraboloid(2), delta0=0.25, H=0.02, boundary_layer="alexandrov")
    comp = sol.composite
    args, outs = comp.codegen_expressions()
    r = np.array([0.0, 0.3, 0.6, 0.9, 0.97, 0.99, 0.996, 0.9985, 1.0, 1.2])  # edge at 1 - h* H = 0.9971
    th = np.linspace(0.1, 6, r.size)
    pts = np.column_stack([r * np.cos(th), r * np.sin(th), np.full(r.size, 0.02), np.full(r.size, 1.0)])
    return Case("composite_pressure", comp, tuple(args), (outs["p"],), pts, {})


class _LazyCases(Mapping):
    """The cases by key, each built on first use (not at collection, where every xdist worker would build all)."""

    def __init__(self, builders):
        self._builders, self._built = builders, {}

    def __getitem__(self, key):
        if key not in self._built:
            case = self._builders[key]()
            assert case.key == key, (case.key, key)
            self._built[key] = case
        return self._built[key]

    def __iter__(self):
        return iter(self._builders)

    def __len__(self):
        return len(self._builders)


CASES = _LazyCases({"inner_pressure": _inner_case, "kernel_coefficients": _coefficient_case,
                    "boundary_layer_q": _special_case, "force_law": _force_law_case,
                    "composite_pressure": _composite_case})


def assert_close(got, ref, what):
    got, ref = np.asarray(got, float), np.asarray(ref, float)
    assert got.shape == ref.shape, (what, got.shape, ref.shape)
    np.testing.assert_allclose(got, ref, rtol=RTOL, atol=0, err_msg=what)


def test_reference_points_are_away_from_zeros():
    # a relative comparison is only meaningful where the values are not cancellation-small
    ip = CASES["inner_pressure"]
    p = ip.reference()[:, 0]
    p0 = checked_lambdify(ip.args, ip.result.terms[0], "numpy")(*ip.points.T)
    assert np.all(p0 > 0)
    assert np.all(p > 0.4 * p0)
    kc = CASES["kernel_coefficients"].reference()
    assert np.all(np.abs(kc) > 1e-4)
    q = CASES["boundary_layer_q"].reference()[:, 0]
    assert np.sum(q == 0) == 2 and np.all(q[2:] > 0)  # v < h gives 0, the rest is positive


# ---------------------------------------------------------------------------------------------
# compiling and running
# ---------------------------------------------------------------------------------------------

def _fmt(pt) -> str:
    return " ".join(repr(float(x)) for x in pt)


def run_c(gc, points, tmp: Path) -> np.ndarray:
    gcc = need("c")
    gc.write(tmp)
    lib = tmp / f"lib{gc.function_name}.so"
    flags = ["-std=c99", "-pedantic", "-Wall", "-Wextra", "-Werror", "-O2", "-fPIC", "-shared"]
    subprocess.run([gcc, *flags, "-o", str(lib), str(tmp / gc.main_file), "-lm"],
                   check=True, capture_output=True, text=True, stdin=subprocess.DEVNULL)
    f = getattr(ctypes.CDLL(str(lib)), gc.function_name)
    nin, nout = len(gc.arguments), len(gc.outputs)
    if nout == 1:
        f.restype, f.argtypes = ctypes.c_double, [ctypes.c_double] * nin
        return np.array([[f(*map(float, pt))] for pt in points])
    f.restype, f.argtypes = None, [ctypes.c_double] * nin + [ctypes.POINTER(ctypes.c_double)]
    rows = []
    for pt in points:
        out = (ctypes.c_double * nout)()
        f(*map(float, pt), out)
        rows.append(list(out))
    return np.array(rows)


def run_fortran(gc, points, tmp: Path) -> np.ndarray:
    gfortran = need("fortran")
    gc.write(tmp)
    name, nin, nout = gc.function_name, len(gc.arguments), len(gc.outputs)
    call = ", ".join(f"a({i + 1})" for i in range(nin))
    if nout == 1:
        decl, body = "", f"write(*, '(ES26.17E3)') {name}({call})"
    else:
        decl = f"double precision :: out({nout})"
        body = f"call {name}({call}, out)\n    write(*, '(*(ES26.17E3, 1X))') out"
    driver = textwrap.dedent(f"""\
        program driver
        implicit none
        include '{name}.fi'
        double precision :: a({nin})
        {decl}
        integer :: ios
        do
            read(*, *, iostat=ios) a
            if (ios /= 0) exit
            {body}
        end do
        end program driver
        """)
    (tmp / "driver.f90").write_text(driver)
    exe = tmp / "driver_f"
    subprocess.run([gfortran, "-std=f2008", "-Wall", "-Werror", "-O2", "-o", str(exe),
                    str(tmp / gc.main_file), str(tmp / "driver.f90")],
                   check=True, capture_output=True, text=True, cwd=tmp, stdin=subprocess.DEVNULL)
    out = subprocess.run([str(exe)], input="\n".join(map(_fmt, points)) + "\n", check=True,
                         capture_output=True, text=True).stdout
    return np.array([[float(t) for t in line.split()] for line in out.splitlines()])


def run_rust(gc, points, tmp: Path) -> np.ndarray:
    rustc = need("rust")
    gc.write(tmp)
    name, nin, nout = gc.function_name, len(gc.arguments), len(gc.outputs)
    call = ", ".join(f"v[{i}]" for i in range(nin))
    if nout == 1:
        show = 'println!("{:e}", r);'
    else:
        parts = ", ".join(f'format!("{{:e}}", r.{k})' for k in range(nout))
        show = 'println!("{}", [' + parts + '].join(" "));'
    main = textwrap.dedent(f"""\
        mod {name};
        use std::io::BufRead;
        fn main() {{
            for line in std::io::stdin().lock().lines() {{
                let v: Vec<f64> = line.unwrap().split_whitespace().map(|t| t.parse().unwrap()).collect();
                let r = {name}::{name}({call});
                {show}
            }}
        }}
        """)
    (tmp / "main.rs").write_text(main)
    exe = tmp / "driver_rs"
    subprocess.run([rustc, "--edition", "2021", "-D", "warnings", "-o", str(exe), str(tmp / "main.rs")],
                   check=True, capture_output=True, text=True, cwd=tmp, stdin=subprocess.DEVNULL)
    out = subprocess.run([str(exe)], input="\n".join(map(_fmt, points)) + "\n", check=True,
                         capture_output=True, text=True).stdout
    return np.array([[float(t) for t in line.split()] for line in out.splitlines()])


RUNNERS = {"c": run_c, "fortran": run_fortran, "rust": run_rust}


@pytest.mark.parametrize("language", ["c", "fortran", "rust"])
@pytest.mark.parametrize("key", list(CASES))
def test_compiled_code_matches_numpy_lambdify(key, language, tmp_path):
    case = CASES[key]
    gc = case.generate(language)
    try:
        got = RUNNERS[language](gc, case.points, tmp_path)
    except subprocess.CalledProcessError as e:
        pytest.fail(f"{language} build/run failed:\n{e.stderr}\n--- generated ---\n{gc.source}")
    assert_close(got, case.reference(), f"{key} in {language}")


def test_rust_erf_helper_accuracy(tmp_path):
    # Rust's std has no erf: the generated helper against mpmath, to a few ulp
    x = sp.Symbol("x", real=True)
    gc = generate(sp.erf(x), "rust", name="erf_check", args=[x])
    assert "fn erf(x: f64) -> f64" in gc.source
    assert "fn erf(" not in generate(sp.exp(x), "rust", args=[x]).source  # only when needed
    xs = np.concatenate([np.linspace(-7, 7, 561), [0.0, 1e-300, -1e-20, 1e-8, 0.3, 1.9999999, 2.0, 2.0000001,
                                                   5.9999, 6.0, 27.0, -3.5]])
    got = run_rust(gc, xs[:, None], tmp_path)[:, 0]
    with mpmath.workdps(40):
        ref = np.array([float(mpmath.erf(mpmath.mpf(float(v)))) for v in xs])
    np.testing.assert_allclose(got, ref, rtol=2e-15, atol=0)
    assert got[np.argmax(xs == 0.0)] == 0.0


def test_c_and_fortran_keep_erf_and_constants_standard():
    case = CASES["boundary_layer_q"]
    c = case.generate("c").source
    assert "erf(" in c and "M_PI" not in c and "double const pi = 3.14159265358979" in c  # strict C99
    f = case.generate("fortran").source
    assert "erf(" in f and "REAL*8" not in f and "double precision, parameter :: pi" in f
    assert max(len(line) for line in f.splitlines()) <= 132  # free-form line limit


# ---------------------------------------------------------------------------------------------
# the standalone numpy module
# ---------------------------------------------------------------------------------------------

def run_python_module(gc, points, tmp: Path) -> tuple[np.ndarray, str]:
    """Import the module in a fresh interpreter where sympy and thinlayer cannot be imported."""
    gc.write(tmp)
    np.save(tmp / "in.npy", np.asarray(points, float))
    script = textwrap.dedent(f"""\
        import sys
        sys.modules["sympy"] = None      # any `import sympy` now raises ImportError
        sys.modules["thinlayer"] = None
        import importlib.util
        import numpy
        spec = importlib.util.spec_from_file_location("{gc.function_name}", r"{tmp / gc.main_file}")
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        pts = numpy.load(r"{tmp / 'in.npy'}")
        res = mod.{gc.function_name}(*pts.T)            # one vectorised call
        res = res if isinstance(res, tuple) else (res,)
        assert all(numpy.shape(r) == (len(pts),) for r in res), [numpy.shape(r) for r in res]
        numpy.save(r"{tmp / 'out.npy'}", numpy.column_stack(res))
        print(sorted(m for m in sys.modules if m.split(".")[0] in ("sympy", "thinlayer", "scipy", "mpmath")
                     and sys.modules[m] is not None))
        """)
    proc = subprocess.run([sys.executable, "-c", script], check=False, capture_output=True, text=True,
                          cwd=tmp, stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, proc.stderr + "\n--- generated ---\n" + gc.source
    return np.load(tmp / "out.npy"), proc.stdout.strip()


def load_module(gc, tmp: Path):
    """Import a generated Python module in this process (from a file, like a user would)."""
    (path,) = gc.write(tmp)
    spec = importlib.util.spec_from_file_location(f"generated_{gc.function_name}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.parametrize("key", list(CASES))
def test_standalone_numpy_module_without_sympy(key, tmp_path):
    case = CASES[key]
    gc = case.generate("python")
    got, loaded = run_python_module(gc, case.points, tmp_path)
    assert loaded == "[]"  # neither sympy, thinlayer, scipy nor mpmath got imported
    imports = [ln for ln in gc.source.splitlines() if ln.startswith(("import ", "from "))]
    assert set(imports) <= {"import numpy", "import math"}
    assert_close(got, case.reference(), f"{key} in the numpy module")


def test_numpy_module_broadcasts_constant_outputs(tmp_path):
    x, y = sp.symbols("x y", real=True)
    gc = generate({"s": x + y, "three": sp.Integer(3)}, "python", name="pair", args=[x, y])
    s, three = load_module(gc, tmp_path).pair(np.arange(4.0), 1.0)
    assert np.array_equal(s, [1, 2, 3, 4]) and np.array_equal(three, [3, 3, 3, 3])


# ---------------------------------------------------------------------------------------------
# Julia and Octave: golden files
# ---------------------------------------------------------------------------------------------

def _minor(version: str) -> str:
    return ".".join(version.split(".")[:2])


@pytest.mark.parametrize("language", ["julia", "octave"])
@pytest.mark.parametrize("key", list(CASES))
def test_golden_files(key, language):
    gc = CASES[key].generate(language)
    (fn, text), = gc.files.items()
    path = GOLDEN / fn
    stamp = GOLDEN / "sympy_version.txt"  # sympy's printers change between releases
    if UPDATE:
        GOLDEN.mkdir(exist_ok=True)
        path.write_text(text)
        stamp.write_text(sp.__version__ + "\n")
        pytest.skip(f"THINLAYER_UPDATE_GOLDEN=1: rewrote {path}; review the diff before committing")
    assert path.exists(), f"missing golden file {path}; create it with THINLAYER_UPDATE_GOLDEN=1, review it"
    golden = path.read_text()
    written = stamp.read_text().strip()
    if text != golden and _minor(written) != _minor(sp.__version__):
        pytest.skip(f"{fn} differs from the golden file written with sympy {written}; this is sympy "
                    f"{sp.__version__}, whose printers may differ: regenerate with THINLAYER_UPDATE_GOLDEN=1 "
                    f"under this sympy to compare")
    if text != golden:
        diff = "".join(difflib.unified_diff(golden.splitlines(True), text.splitlines(True), str(path),
                                            "generated"))
        pytest.fail(f"generated {language} differs from {path}:\n{diff}\nIf the change is intended, rerun "
                    f"with THINLAYER_UPDATE_GOLDEN=1 python3 -m pytest tests/export/test_codegen.py; review the "
                    f"diff")


def test_golden_files_say_what_they_are():
    jl = (GOLDEN / "boundary_layer_q.jl").read_text()
    assert "using SpecialFunctions" in jl and "Base.MathConstants" not in jl and " e " not in jl
    m = (GOLDEN / "kernel_coefficients.m").read_text()
    assert m.startswith("function [A, m_1, m_2, m_3, M_1, M_2, M_3] = kernel_coefficients(nu)")
    assert "(h < v) ?" in jl  # scalar Piecewise in Julia, documented


def test_julia_euler_number_is_defined_in_julia_1():
    x = sp.Symbol("x", real=True)
    assert "Base.MathConstants.e" in generate(sp.E * x, "julia", args=[x]).source


def test_octave_output_runs_if_octave_is_installed(tmp_path):
    octave = shutil.which("octave")
    if octave is None:
        pytest.skip("octave not installed (optional: `apt-get install octave`); golden files check the text")
    for case in CASES.values():
        gc = case.generate("octave")
        gc.write(tmp_path)
        pts = case.points
        if case.key == "boundary_layer_q":
            # Octave's mask-product Piecewise evaluates sqrt(v - h) everywhere: only v > h (documented)
            pts = pts[case.points[:, 0] > case.points[:, 1]]
        cols = ", ".join(f"[{', '.join(repr(float(v)) for v in pts[:, j])}]'" for j in range(pts.shape[1]))
        outs = ", ".join(f"o{k}" for k in range(len(gc.outputs)))
        script = f"[{outs}] = {gc.function_name}({cols}); printf('%.17g\\n', [{outs}]');"
        proc = subprocess.run([octave, "--no-gui", "--no-window-system", "-q", "--eval", script], check=False,
                              cwd=tmp_path, capture_output=True, text=True, timeout=120,
                              stdin=subprocess.DEVNULL)
        assert proc.returncode == 0, proc.stderr
        got = np.array([float(t) for t in proc.stdout.split()]).reshape(len(pts), len(gc.outputs))
        ref = Case(case.key, case.result, case.args, case.exprs, pts, case.kwargs).reference()
        assert_close(got, ref, f"{case.key} in Octave")


# ---------------------------------------------------------------------------------------------
# API, names in the code, protocol
# ---------------------------------------------------------------------------------------------

def test_generated_code_api_and_files():
    ip = CASES["inner_pressure"].result
    codes = generate_all(ip)
    assert tuple(codes) == LANGUAGES
    files = {lang: sorted(gc.files) for lang, gc in codes.items()}
    assert files == {"c": ["inner_pressure.c", "inner_pressure.h"],
                     "fortran": ["inner_pressure.f90", "inner_pressure.fi"],
                     "rust": ["inner_pressure.rs"], "julia": ["inner_pressure.jl"],
                     "octave": ["inner_pressure.m"], "python": ["inner_pressure.py"]}
    for gc in codes.values():
        assert gc.function_name == "inner_pressure" and gc.outputs == ("p",)
        assert gc.arguments == ("x_1", "x_2", "delta_0", "H", "mu", "R_1", "R_2")
        assert gc.symbols == ip.arguments
    with pytest.raises(TypeError):
        codes["c"].files["x.c"] = ""  # read-only mapping
    kc = generate(CASES["kernel_coefficients"].result, "c")
    assert "void kernel_coefficients(double nu, double *out)" in kc.files["kernel_coefficients.h"]
    assert "out[6] = M_3" in kc.source  # the header documents the slots


def test_scaled_names_are_sanitised_and_documented(tmp_path):
    # the scaled pressure (2.26) has H_*, delta_0^*, R_1^*: H_s, delta_0_s, R_1_s in every language
    ip = inner_pressure(BondedLayer(sp.Rational(3, 10)), Punch.elliptic_paraboloid())
    args = ip.scaled_arguments
    for lang in LANGUAGES:
        gc = generate(ip.scaled_pressure, lang, name="scaled_pressure", args=args)
        assert gc.arguments[:6] == ("xi_1", "xi_2", "delta_0_s", "H_s", "Lambda", "vartheta"), lang
        assert "H_s: H_*" in gc.source and "delta_0_s: delta_0^*" in gc.source
    gc = generate(ip.scaled_pressure, "python", name="scaled_pressure", args=args)
    pts = np.array([[0.1, 0.2, 1.0, 1.0, 10.0, 1.0, 20.0, 15.0], [0.3, -0.1, 0.8, 1.2, 20.0, 2.0, 9.0, 7.0]])
    got, _ = run_python_module(gc, pts, tmp_path)
    assert_close(got, ip.lambdify(args, scaled=True)(*pts.T)[:, None], "scaled pressure")


def test_awkward_symbol_names_survive_the_comments(tmp_path):
    # a LaTeX name in the Python docstring (\\xi is an escape) and a C comment terminator in a name
    xi, odd = sp.Symbol("\\xi", real=True), sp.Symbol("q*/2", positive=True)
    gc = generate(xi * odd, "python", name="awkward", args=[xi, odd])
    assert gc.arguments == ("xi", "qs_2")  # "*" -> "s", "/" -> "_"
    assert load_module(gc, tmp_path / "py").awkward(2.0, 3.0) == 6.0
    got = run_c(generate(xi * odd, "c", name="awkward", args=[xi, odd]), [[2.0, 3.0]], tmp_path / "c")
    assert got[0, 0] == 6.0


def test_keyword_symbols_are_renamed_in_the_code(tmp_path):
    lam, end = sp.symbols("lambda end", positive=True)
    gc = generate(lam * end, "python", name="prod", args=[lam, end])
    assert gc.arguments == ("lambda_", "end")
    assert load_module(gc, tmp_path).prod(3.0, 4.0) == 12.0
    assert generate(lam * end, "octave", name="prod", args=[lam, end]).arguments == ("lambda", "end_")


def test_write_refuses_to_overwrite(tmp_path):
    gc = generate(CASES["kernel_coefficients"].result, "fortran")
    paths = gc.write(tmp_path / "new")
    assert sorted(p.name for p in paths) == ["kernel_coefficients.f90", "kernel_coefficients.fi"]
    (tmp_path / "new" / "kernel_coefficients.fi").write_text("edited")
    with pytest.raises(FileExistsError, match="kernel_coefficients.f90"):
        gc.write(tmp_path / "new")
    assert (tmp_path / "new" / "kernel_coefficients.fi").read_text() == "edited"  # nothing written
    gc.write(tmp_path / "new", force=True)
    assert (tmp_path / "new" / "kernel_coefficients.fi").read_text() == gc.files["kernel_coefficients.fi"]


class ForceLawLike:
    """A stand-in for a later result type that implements the codegen protocol."""

    equation = "1.8"
    codegen_name = "force_law"

    def codegen_expressions(self):
        d, R = sp.symbols("delta_0 R", positive=True)
        return (d, R), {"P": sp.pi * R * d**2, "a": sp.sqrt(2 * R * d)}


def test_codegen_protocol(tmp_path):
    obj = ForceLawLike()
    gc = generate(obj, "python")
    assert (gc.function_name, gc.arguments, gc.outputs) == ("force_law", ("delta_0", "R"), ("P", "a"))
    assert "ForceLawLike, paper eq. (1.8)" in gc.source
    got, _ = run_python_module(gc, [[0.1, 2.0], [0.2, 3.0]], tmp_path)
    assert_close(got, [[np.pi * 2 * 0.01, 0.4 ** 0.5], [np.pi * 3 * 0.04, 1.2 ** 0.5]], "protocol")
    jl = generate(obj, "julia", name="force")
    assert jl.function_name == "force" and "return P, a" in jl.source
    d, R = obj.codegen_expressions()[0]
    assert generate(obj, "c", args=[R, d]).arguments == ("R", "delta_0")  # args reorders


def test_composite_codegen_matches_the_numeric_composite(tmp_path):
    # the closed form (radial punch, Alexandrov layer) against CompositePressure.__call__, which uses the
    # Newton foot point and the interpolated Q table (accurate to ~1e-8 of the boundary-layer scale)
    case = CASES["composite_pressure"]
    got = run_c(case.generate("c"), case.points, tmp_path)[:, 0] if shutil.which("gcc") else case.reference()[:, 0]
    ref = case.result(case.points[:, 0], case.points[:, 1])
    assert np.all((got > 0) == (ref > 0))
    np.testing.assert_allclose(got, ref, rtol=1e-7, atol=1e-9 * ref.max())


def test_composite_codegen_needs_closed_form():
    from thinlayer.asymptotics.solution import compressible_solution as solve

    exact = solve(BondedLayer(0.3), Punch.paraboloid(2), delta0=0.25, H=0.02).composite
    with pytest.raises(NotImplementedError, match="alexandrov"):
        generate(exact, "c")
    ellip = solve(BondedLayer(0.3), Punch.elliptic_paraboloid(4, 1), delta0=0.25, H=0.02,
                  boundary_layer="alexandrov").composite
    with pytest.raises(NotImplementedError, match="radial"):
        generate(ellip, "c")
