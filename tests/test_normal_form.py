"""One normal form for every printed formula (issue 28, item 5): ``latex()``, ``print(result)``, reports.

The normal form is a way of printing; the values a user computes with are checked by the ladder
(``==``, ``cancel`` of the difference, a numeric mpmath check) against independent routes.
"""
from __future__ import annotations

import io
import re
import sys

import mpmath
import pytest
import sympy as sp

import thinlayer as tl
from thinlayer import symbols as S
from thinlayer.asymptotics.second_order import second_order_law
from thinlayer.normal import normal_latex, normal_terms, normal_text, to_ascii

nu = S.nu


# ---- the values behind the printed forms ----------------------------------------------------------
def test_A_is_returned_factored_and_equals_the_kernel_limit():
    """(2.4): A = lim L(s)/s = (1 - 2 nu)/(2 (1 - nu)^2), printed without (1/2 - nu)."""
    A = tl.BondedLayer().A
    closed = sp.Mul(sp.S.Half, 1 - 2 * nu, (1 - nu) ** -2)
    assert A == closed  # structurally: the factored form is the value
    kappa = 3 - 4 * nu  # (2.3), (2.4): A = 4 (kappa - 1)/(kappa + 1)^2
    assert sp.cancel(A - 4 * (kappa - 1) / (kappa + 1) ** 2) == 0
    for v in ("0.3", "-0.4", "0.49"):  # the kernel (2.3) itself, by mpmath: L(s)/s at s -> 0
        with mpmath.workdps(50):
            k = 3 - 4 * mpmath.mpf(v)
            s = mpmath.mpf("1e-15")
            L = (2 * k * mpmath.sinh(2 * s) - 4 * s) / (2 * k * mpmath.cosh(2 * s) + 1 + k**2 + 4 * s**2)
            assert abs(L / s - mpmath.mpf(sp.N(A.subs(nu, sp.Rational(v)), 50))) < 1e-25
    assert str(A) == "(1 - 2*nu)/(2*(1 - nu)**2)"
    assert normal_text(A) == "(1 - 2ν)/(2(1 - ν)²)"
    assert normal_latex(A) == r"\frac{1 - 2 \nu}{2 \left(1 - \nu\right)^{2}}"


def test_moment_has_no_half_beside_one_minus_two_nu():
    """(2.21): mu_40 = pi^2 A m_2 4! -- the factor 1 - 2 nu of A cancels the one of m_2."""
    layer = tl.BondedLayer()
    mu40 = layer.moment(4, 0)
    assert "1/2 - nu" not in str(mu40) and not mu40.has(1 - 2 * nu)
    expected = sp.pi**2 * layer.A * layer.m(2) * 24
    assert sp.cancel(mu40 - expected) == 0
    num = tl.BondedLayer(sp.Rational(3, 10)).moment(4, 0)  # exact layer: an independent evaluation
    assert mu40.subs(nu, sp.Rational(3, 10)) == num
    assert abs(sp.N(mu40.subs(nu, sp.Float("0.3", 40)), 30) - sp.N(num, 30)) < 1e-25
    text, tex = normal_text(mu40), normal_latex(mu40)
    assert "1 - 2ν" not in text and r"\frac{1}{2}" not in tex
    assert text == "-π² (3 - 30ν + 76ν² + 16ν³)/(5(1 - ν)⁴)"


def test_normal_terms_add_up_for_the_api_expressions():
    layer = tl.BondedLayer()
    ip = tl.inner_pressure(layer, tl.Punch.elliptic_paraboloid())
    law = tl.force_law(layer, tl.Punch.elliptic_paraboloid())
    exprs = [layer.A, layer.m(2), layer.M(2), layer.moment(4, 2), *ip.terms, *ip.scaled_terms, law.P0, law.P1,
             law.contact_area, tl.alexandrov_solution(layer).params.B]
    for e in exprs:
        total = sp.Add(*[t.value() for t in normal_terms(e)])
        d = sp.cancel(sp.expand(total - e))
        if d != 0:
            d = sp.simplify(total - e)
        assert d == 0, e


# ---- starred symbols survive powers ----------------------------------------------------------------
def test_starred_symbols_print_unambiguously():
    ip = tl.inner_pressure(tl.BondedLayer(), tl.Punch.elliptic_paraboloid())
    for t in ip.scaled_terms:
        text, ascii_, tex = normal_text(t), normal_text(t, unicode=False), normal_latex(t)
        assert "***" not in text and "***" not in ascii_ and "}^{*}^{" not in tex
    p0 = ip.scaled_terms[0]  # (2.27): H_*^2 xi^2/(2 R^*)
    assert "H_***2" in str(p0)  # sympy's own str of the symbol H_* is ambiguous ...
    assert "H*² ξ₂²/(2R₂*)" in normal_text(p0) and "H_s**2*xi_2**2/(2*R_2_s)" in normal_text(p0, unicode=False)
    assert r"\frac{H_{*}^{2} \xi_{2}^{2}}{2 R^{*}_{2}}" in normal_latex(p0)  # ... the normal form is not
    assert "***" not in str(ip) and "H*²" in str(ip)
    h = sp.Symbol("h^*", real=True)
    assert normal_latex(sp.pi * h**2) == r"\pi {h^{*}}^{2}"  # never the double superscript h^{*}^{2}
    assert normal_text(h**2) == "h*²" and normal_text(h**2, unicode=False) == "h_s**2"
    d0s = S.delta0_s
    assert normal_text(d0s**2) == "δ₀*²" and normal_text(d0s**2, unicode=False) == "delta_0_s**2"


# ---- no double negatives -----------------------------------------------------------------------------
def _printed(res) -> list[str]:
    return [res.latex(), str(res)]


def _results():
    L = tl.BondedLayer()
    par, ell = tl.Punch.paraboloid(), tl.Punch.elliptic_paraboloid()
    return [
        tl.kernel_coefficients(L, 3), tl.moment_expansion(L, 3), tl.inner_pressure(L, ell),
        tl.force_law(L, ell), tl.force_law(tl.BondedLayer("1/10"), par),  # m_1 < 0
        tl.force_law(tl.BondedLayer("1/4"), par),  # m_1 = 0: no "+ 0" term, no "(1 + 0)"
        tl.force_law(tl.BondedLayer("3/10"), tl.Punch.elliptic_paraboloid(4, 1)),
        second_order_law(tl.BondedLayer("1/10"), par), second_order_law(tl.BondedLayer("3/10"), par),
        tl.alexandrov_solution(L), tl.alexandrov_solution(tl.BondedLayer(0)),
        tl.ellipse_contour(4, 1, sp.Rational(1, 2)),
        tl.thin_layer_operator(tl.IncompressibleLayer(), 3), tl.thin_layer_operator(tl.BondedLayer("9/20"), 2),
        tl.obstacle_problem(tl.BondedLayer("9/20"), par), tl.two_term_sphere(tl.BondedLayer("9/20")),
        tl.asymptotics.flat_punch.thick_flat_punch(tl.BondedLayer(0.3), 4),  # c_4 < 0
        tl.asymptotics.thick_layer.thick_sphere_series(4),
    ]


@pytest.fixture(scope="module")
def results():
    import thinlayer.asymptotics.flat_punch  # noqa: F401 (the modules the list reaches by attribute)
    import thinlayer.asymptotics.thick_layer  # noqa: F401

    return _results()


def test_no_double_negatives_and_no_zero_terms(results):
    bad = re.compile(r"-\s*-|\+\s*-|\(1 \+ 0\)|\\left\(1 \+ 0\\right\)|\+ 0\\oint|\+ 0 ")
    for res in results:
        for text in _printed(res):
            assert not bad.search(text), (type(res).__name__, bad.search(text).group(), text[:300])
            assert r"\frac{1}{2} - \nu" not in text and "1/2 - ν" not in text and "(1/2 - nu)" not in text


def test_text_is_unicode_maths_in_the_normal_form(results):
    for res in results:
        text = str(res)
        assert "**" not in text and "*pi" not in text and "sqrt(" not in text, (type(res).__name__, text)
        assert len(repr(res)) <= 110 and "\n" not in repr(res)  # the short repr of a result with text_lines
    law = tl.force_law(tl.BondedLayer("3/10"), tl.Punch.elliptic_paraboloid(4, 1))
    assert "  Φ  = x₁²/8 + x₂²/2" in str(law).splitlines()
    assert "  P₀ = 7π δ₀² μ/H" in str(law).splitlines()


def test_polynomials_in_nu_ascend_with_a_positive_first_term(results):
    for res in results:
        tex = res.latex()
        assert not re.search(r"\\left\((-\s*)?\d*\s*\\nu(\^\{\d+\})? - 1\\right\)", tex), tex  # (nu - 1), (2 nu - 1)
        assert not re.search(r"\((\d*)ν - 1\)", str(res)), str(res)


def test_ascii_fallback_when_the_stream_cannot_take_unicode(monkeypatch):
    law = tl.force_law(tl.BondedLayer("3/10"), tl.Punch.elliptic_paraboloid(4, 1))
    monkeypatch.setattr(sys, "stdout", io.TextIOWrapper(io.BytesIO(), encoding="ascii"))
    text = str(law)
    text.encode("ascii")  # no UnicodeEncodeError
    assert "Phi  = x_1^2/8 + x_2^2/2" in text and "E(sqrt(3)/2)" in text
    assert to_ascii("h*² (1 - 2ν)") == "h*^2 (1 - 2nu)"  # the star never meets a ** (no h***2)


# ---- the complete elliptic integrals and Young's modulus ---------------------------------------------
def test_elliptic_integrals_are_named_by_their_modulus():
    """``E(k)``, ``K(k)`` with k the modulus (DLMF 19.2.4, 19.2.5): k^2 = m, sympy's parameter."""
    for m in (sp.Rational(3, 4), sp.Rational(1, 3), sp.Symbol("m", positive=True)):
        k = sp.sqrt(m)
        assert normal_latex(sp.elliptic_e(m)) == rf"\mathrm{{E}}\left({normal_latex(k)}\right)"
        assert normal_latex(sp.elliptic_k(m)) == rf"\mathrm{{K}}\left({normal_latex(k)}\right)"
        assert normal_text(sp.elliptic_e(m)) == f"E({normal_text(k)})"
    # the modulus convention, by quadrature: E(k) = int_0^{pi/2} sqrt(1 - k^2 sin^2 t) dt, K(k) likewise
    with mpmath.workdps(40):
        k = mpmath.sqrt(3) / 2
        E_k = mpmath.quad(lambda t: mpmath.sqrt(1 - k**2 * mpmath.sin(t) ** 2), [0, mpmath.pi / 2])
        K_k = mpmath.quad(lambda t: 1 / mpmath.sqrt(1 - k**2 * mpmath.sin(t) ** 2), [0, mpmath.pi / 2])
        assert abs(E_k - mpmath.mpf(sp.N(sp.elliptic_e(sp.Rational(3, 4)), 40))) < 1e-30
        assert abs(K_k - mpmath.mpf(sp.N(sp.elliptic_k(sp.Rational(3, 4)), 40))) < 1e-30
        # the perimeter of the contact ellipse a = 2, b = 1 (3.1): 4 a E(e), e the eccentricity
        arc = mpmath.quad(lambda t: mpmath.sqrt(4 * mpmath.sin(t) ** 2 + mpmath.cos(t) ** 2), [0, mpmath.pi / 2])
        assert abs(4 * arc - 8 * E_k) < 1e-30
    c = tl.ellipse_contour(4, 1, sp.Rational(1, 2))
    assert "8E(√3/2)" in str(c) and r"8 \mathrm{E}\left(\frac{\sqrt{3}}{2}\right)" in c.latex()


def test_no_printed_E_paren_but_the_elliptic_integral():
    """Young's modulus E never takes an argument; ``E(`` (text) and ``\\mathrm{E}`` (LaTeX) are the integral."""
    E_young, m = sp.Symbol("E", positive=True), sp.Symbol("m", positive=True)
    both = E_young * (1 - nu) * sp.elliptic_e(m)
    tex, text = normal_latex(both), normal_text(both)
    assert re.findall(r"(?<!\\mathrm\{)E\b", tex) == ["E"]  # one italic E: the modulus, no argument
    assert r"\mathrm{E}\left(\sqrt{m}\right)" in tex
    assert text == "E E(√m) (1 - ν)"  # E( is the integral; the modulus is spaced off whatever follows it
    printed = []
    L = tl.BondedLayer()
    for res in (tl.force_law(L, tl.Punch.elliptic_paraboloid()),
                tl.force_law(tl.BondedLayer("3/10"), tl.Punch.elliptic_paraboloid(4, 1)),
                second_order_law(tl.BondedLayer("3/10"), tl.Punch.elliptic_paraboloid(4, 1)),
                tl.ellipse_contour(), tl.ellipse_contour(4, 1, sp.Rational(1, 2))):
        tex, text = res.latex(), str(res)
        printed.append(tex + text)
        assert not re.search(r"(?<!\\mathrm\{)(?<![A-Za-z\\])[EK]\\left\(", tex), tex  # sympy's E\left(m\right)
        if re.search(r"(?<![A-Za-z_])[EK]\(", text):  # an E( or K( in the text: the note says what it is
            assert "complete elliptic integral" in text and "modulus k" in text, text
    assert any("mathrm{E}" in p for p in printed) and any("mathrm{K}" in p for p in printed)
