"""Code generation of the nearly incompressible models (issue 13, item 3): (I.7)-(I.9), (I.11).

Each generated numpy module is imported from its file, as a user would, and checked against identities that
do not go through the generated code's own expressions: the force is the integral of the generated pressure
(1.8), computed by scipy quadrature; the incompressible contact satisfies the volume identity (I.5)
``iint_omega (delta0 - Phi) dx = 0``; the sphere's force is ``2 pi mu R^2 delta0^3/H^3`` at ``c^2 = 4 R delta0``.
"""
from __future__ import annotations

import importlib.util
import math

import numpy as np
import pytest
from scipy import integrate

import thinlayer as tl
from thinlayer.asymptotics.incompressible import incompressible_axisymmetric, incompressible_ellipse, two_term_sphere
from thinlayer.export.codegen import generate


def _module(result, tmp_path):
    gc = generate(result, "python")
    (path,) = gc.write(tmp_path)
    spec = importlib.util.spec_from_file_location(f"generated_{gc.function_name}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return gc, getattr(mod, gc.function_name)


def test_incompressible_sphere(tmp_path):
    gc, f = _module(two_term_sphere(tl.IncompressibleLayer()), tmp_path)
    assert gc.arguments == ("rho", "c", "R", "H", "mu")
    R, H, mu, d0 = 10.0, 0.02, 1.3, 0.1
    c = 2 * math.sqrt(R * d0)
    delta0, force, _ = f(0.0, c, R, H, mu)
    assert delta0 == pytest.approx(d0, rel=1e-14)  # c^2 = 4 R delta0 (I.11)
    assert force == pytest.approx(2 * math.pi * mu * R**2 * d0**3 / H**3, rel=1e-13)
    quad = 2 * math.pi * integrate.quad(lambda r: r * f(r, c, R, H, mu)[2], 0, c, epsabs=0, epsrel=1e-12)[0]
    assert quad == pytest.approx(force, rel=1e-10)
    assert f(1.01 * c, c, R, H, mu)[2] == 0.0


def test_incompressible_ellipse(tmp_path):
    R1, R2 = 4.0, 1.0
    gc, f = _module(incompressible_ellipse(R1, R2), tmp_path)
    assert gc.arguments == ("x_1", "x_2", "delta_0", "H", "mu")
    d0, H, mu = 0.1, 0.05, 0.7
    force, a, b, _ = f(0.0, 0.0, d0, H, mu)
    # (I.5): iint_ellipse (delta0 - x1^2/(2R1) - x2^2/(2R2)) = pi a b (delta0 - a^2/(8 R1) - b^2/(8 R2)) = 0
    assert d0 == pytest.approx(a * a / (8 * R1) + b * b / (8 * R2), rel=1e-13)
    # (1.8): the force is the integral of the pressure (polar coordinates scaled to the ellipse)
    quad = integrate.dblquad(lambda s, t: a * b * s * f(a * s * math.cos(t), b * s * math.sin(t), d0, H, mu)[3],
                             0, 2 * math.pi, 0, 1, epsabs=0, epsrel=1e-10)[0]
    assert quad == pytest.approx(force, rel=1e-8)
    with np.errstate(all="raise"):  # branch-safe outside the contact
        assert f(2 * a, 0.0, d0, H, mu)[3] == 0.0


def test_incompressible_axisymmetric_quartic(tmp_path):
    punch = tl.Punch.fourth_degree(1, 1)
    gc, f = _module(incompressible_axisymmetric(punch), tmp_path)
    d0, H, mu = 0.5, 0.05, 1.0
    from scipy import optimize

    c = optimize.brentq(lambda c: f(0.0, c, d0, H, mu)[0], 0.1, 10.0, xtol=1e-15)
    ref = incompressible_axisymmetric(punch).evaluate(d0, H, mu)
    assert c == pytest.approx(ref.radius, rel=1e-12)
    force = f(0.0, c, d0, H, mu)[1]
    quad = 2 * math.pi * integrate.quad(lambda r: r * f(r, c, d0, H, mu)[2], 0, c, epsabs=0, epsrel=1e-12)[0]
    assert quad == pytest.approx(force, rel=1e-10)


def test_two_term_below_one_half_names_the_missing_function():
    with pytest.raises(NotImplementedError, match="besseli"):
        generate(two_term_sphere(tl.BondedLayer(0.45)), "c")


@pytest.mark.parametrize(("argv", "code", "text"), [
    (["incompressible", "--kind", "paraboloid", "--lang", "c"], 0, "two_term_sphere"),
    (["incompressible", "--kind", "elliptic_paraboloid", "--param", "R_1=4", "--param", "R_2=1", "--lang", "python"],
     0, "def incompressible_ellipse"),
    (["incompressible", "--kind", "fourth_degree", "--lang", "fortran"], 0, "incompressible_axisymmetric"),
    (["two-term", "--kind", "paraboloid", "--nu", "0.45", "--lang", "julia"], 0, "besseli"),
    (["two-term", "--kind", "paraboloid", "--nu", "0.45", "--lang", "c"], 2, "besseli"),
    (["two-term", "--kind", "elliptic_paraboloid", "--lang", "julia"], 2, "sphere"),
    (["two-term", "--kind", "paraboloid", "--nu", "0.2"], 2, "1/4 < nu < 1/2"),
    (["incompressible", "--kind", "paraboloid", "--nu", "0.3"], 2, "nu = 1/2"),
])
def test_cli_codegen_of_the_nearly_incompressible_models(capsys, argv, code, text):
    from thinlayer.export.cli import main

    assert main(["codegen", *argv]) == code
    out, err = capsys.readouterr()
    assert text in (out if code == 0 else err)
    if code:
        assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
