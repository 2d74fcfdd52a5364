"""Code generation of the closed-form tip laws (issue 24 item 6): the cone, the exact sphere and the power law, in
C, Fortran, Rust (compiled and run) and the standalone numpy module, equal to the Python law to 1e-12; the blunted
cone has no closed form and says why."""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from test_codegen import RUNNERS, assert_close, run_python_module  # the runners of the existing codegen tests

from thinlayer import BondedLayer, FrictionlessLayer, Punch
from thinlayer.asymptotics.tip_law import tip_force_law
from thinlayer.export.codegen import generate

LAWS = {"cone": (BondedLayer(sp.Rational(3, 10)), Punch.cone(), [("alpha", 55.0, 80.0)]),
        "sphere": (BondedLayer(sp.Rational(9, 20)), Punch.sphere(), [("R", 5.0, 20.0)]),
        "power_law": (FrictionlessLayer(sp.Rational(2, 5)), Punch.power_law(1, sp.Rational(3, 2)), [])}


def _points(key):
    layer, tip, extra = LAWS[key]
    law = tip_force_law(layer, tip)
    args, _ = law.codegen_expressions()
    rng = np.random.default_rng(17)
    n = 8
    cols = {"delta_0": rng.uniform(0.2, 1.0, n), "H": rng.uniform(0.005, 0.02, n), "mu": rng.uniform(0.5, 2, n),
            "nu": rng.uniform(-0.5, 0.45, n)}
    for name, lo, hi in extra:
        cols[name] = rng.uniform(lo, hi, n)
    assert [a.name for a in args] == [*cols][:3] + [a.name for a in args[3:]]
    return law, args, np.column_stack([cols[a.name] for a in args])


#: the rigid overlap radius a(delta0) by elementary geometry, where the tip has one: the cone a = delta0 tan(alpha)
#: (alpha the half-angle in degrees), the sphere a = sqrt(2 R delta0 - delta0^2) (a chord of the circle)
OVERLAP = {"cone": lambda v: v["delta_0"] * math.tan(math.radians(v["alpha"])),
           "sphere": lambda v: math.sqrt(2.0 * v["R"] * v["delta_0"] - v["delta_0"] ** 2)}


def _reference(key, law, args, pts):
    """The Python law (P0 + P1 lambdified) and the radius a - h* H, with a by geometry (:data:`OVERLAP`) or from the
    tip's numeric level set (the power law)."""
    force = law.lambdify(args[:len(args)])
    h = float(next(iter(law.codegen_constants().values()))[0])
    rows = []
    for pt in pts:
        vals = dict(zip((a.name for a in args), pt))
        if key in OVERLAP:
            a = OVERLAP[key](vals)
        else:
            tip = law.tip.subs({k: v for k, v in vals.items() if k in {q.name for q in law.tip.parameters}})
            a = tip.level_set(vals["delta_0"]).radius
        rows.append([float(force(*pt)[0]), a - h * vals["H"]])
    return np.array(rows)


@pytest.fixture(scope="module")
def references():
    """Per law: its points and the reference values, computed once for the four languages; the module's tests share
    it, so they run in one xdist worker."""
    cache = {}

    def get(key):
        if key not in cache:
            law, args, pts = _points(key)
            cache[key] = (law, args, pts, _reference(key, law, args, pts))
        return cache[key]
    return get


@pytest.mark.parametrize("language", ["c", "fortran", "rust", "python"])
@pytest.mark.parametrize("key", list(LAWS))
def test_tip_law_code_equals_the_python_law(key, language, tmp_path, references):
    law, args, pts, reference = references(key)
    gc = generate(law, language)
    assert gc.function_name == "tip_force_law" and list(gc.outputs) == ["force", "contact_radius"]
    if language == "python":
        got, loaded = run_python_module(gc, pts, tmp_path)
        assert loaded == "[]"
    else:
        got = RUNNERS[language](gc, pts, tmp_path)
    assert_close(got, reference, f"{key} tip law in {language}")


def test_cone_code_takes_the_angle_in_degrees():
    law = tip_force_law(BondedLayer(sp.Rational(3, 10)), Punch.cone())
    gc = generate(law, "python")
    assert "alpha" in [str(a) for a in gc.arguments] and "pi" in gc.source and "/180" in gc.source.replace(" ", "")
    ns: dict = {}
    exec(compile(gc.source, "tip_force_law.py", "exec"), ns)  # the generated module (our own output, not input)
    f = ns["tip_force_law"]
    at70 = tip_force_law(BondedLayer(sp.Rational(3, 10)), Punch.cone(70)).evaluate(0.5, 0.01, 1.0, nu=0.3)
    assert f(0.5, 0.01, 1.0, 70.0)[0] == pytest.approx(sum(at70), rel=1e-12)
    assert math.isfinite(f(0.5, 0.01, 1.0, 70.0)[1])


def test_blunted_cone_has_no_closed_form_and_says_why():
    law = tip_force_law(BondedLayer(0.3), Punch.blunted_cone(0.5, 70))
    with pytest.raises(ValueError, match="root finding"):
        generate(law, "c")
