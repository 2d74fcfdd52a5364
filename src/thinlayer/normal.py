r"""One normal form for every printed formula: LaTeX (:func:`normal_latex`) and text (:func:`normal_text`).

Every ``latex()``, ``print(result)`` and report of thinlayer prints its formulas through this module, so a
quantity reads the same everywhere.  It is a way of *printing*: the sympy expressions a user computes with
are never changed.  The policy, applied to every product (at the top level and inside function arguments
alike):

* the numeric content of every sum is pulled out and joined with the product's coefficient into one
  fraction: ``(1/2 - nu)`` is written ``(1 - 2 nu)/2``, ``-4 nu^3/15 - ... - 1/20`` as
  ``-(3 - 30 nu + ...)/60``;
* a polynomial in one parameter (``nu``, ``kappa``) is written in ascending powers with a positive first
  coefficient: ``(1 - 2 nu)`` and ``(1 - nu)``, never ``(2 nu - 1)`` or ``(nu - 1)``; any other sum starts
  with a positive term when it has one, and is negated (the sign moved in front) when it has none; so no
  sum prints a double negative (``- -``, ``+ -``);
* equal factors are merged (``(1 - 2 nu) (1 - 2 nu)`` is ``(1 - 2 nu)^2``, and ``(1/2 - nu)/(1 - 2 nu)`` is
  ``1/2``); square roots are joined (``\sqrt{2 R_1 \delta_0}``, not ``\sqrt{2} \sqrt{R_1} \sqrt{\delta_0}``);
* no fraction inside a fraction: a sum whose terms are all fractions is brought to one fraction first
  (``1/R_1 + 1/R_2`` is ``(R_1 + R_2)/(R_1 R_2)``); a sum that still holds a fraction
  (``\delta_0 - x_1^2/(2 R)``) is set in parentheses after the fraction, not inside it, and so is a
  function, power of ``e`` or square root whose argument holds a fraction (``\frac{1}{\sqrt{\pi B}}
  e^{-B (v - h)} \sqrt{v - h}``, not ``e^{..}`` and ``\sqrt{..}`` inside the numerator); the argument itself
  is printed by the same policy, and a square root of a lone sum takes no parentheses;
* floating-point numbers to ``digits`` significant digits (``51``, not ``50.9999999999999534``), powers
  of ten as ``\cdot 10^{k}``; no term that is zero;
* a starred symbol survives powers: ``H_*`` squared is ``H_{*}^{2}`` in LaTeX and ``H*²`` (``H_s**2`` in
  ASCII) in text, ``h^*`` squared ``{h^{*}}^{2}``, never ``H_***2``;
* the complete elliptic integrals are named by the *modulus* ``k`` (DLMF 19.2): upright
  :math:`\mathrm{K}(k)`, :math:`\mathrm{E}(k)`, with ``k = sqrt(m)`` for sympy's ``elliptic_k(m)``,
  ``elliptic_e(m)`` (whose argument is the parameter ``m = k^2``); for the contact ellipse ``k = e``, its
  eccentricity (3.1).  Young's modulus is the italic symbol :math:`E`, never followed by an argument.
  In text they are ``K(k)`` and ``E(k)``: ``E(`` is always the elliptic integral.

The text form is Unicode maths (``(1 - 2ν)/(2(1 - ν)²)``, ``x₁²/8 + x₂²/2``) or, with ``unicode=False``, the
same normal form in sympy's syntax (``(1 - 2*nu)/(2*(1 - nu)**2)``); :func:`to_ascii` turns a Unicode line
into ASCII for a stream that cannot take Unicode.

:func:`normal_terms` returns the pieces a formula is printed from, so that a test can check that they
add up to the original expression.

This module imports nothing of thinlayer (rank 0 of ``tests/test_architecture.py``): the layers and the
stages print with it, and :mod:`thinlayer.export._normal` re-exports it for the reports.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import mpmath
import sympy as sp
from sympy.printing.conventions import split_super_sub
from sympy.printing.latex import LatexPrinter
from sympy.printing.pretty.pretty_symbology import greek_unicode
from sympy.printing.str import StrPrinter

__all__ = ["DIGITS", "TEXT_DIGITS", "NormalLatexPrinter", "NormalTextPrinter", "ReportPrinter", "Term",
           "float_latex", "join_signed", "normal_latex", "normal_term", "normal_terms", "normal_text", "ordered_terms",
           "symbol_text", "to_ascii"]

#: significant digits of a floating-point number in LaTeX (reports, ``latex()``)
DIGITS = 6
#: significant digits of a floating-point number in text (``print(result)``)
TEXT_DIGITS = 12
#: names of the one-parameter polynomials written in ascending powers: the Poisson ratio and kappa = 3 - 4 nu
_PARAMETERS = frozenset({"nu", "kappa"})
#: above this degree a polynomial sum is not factored for printing (factoring cost grows fast; the engine
#: factors its small coefficients itself)
_FACTOR_DEGREE = 8


def float_latex(x: float, digits: int = DIGITS) -> str:
    r"""A number to ``digits`` significant digits: ``51``, ``0.145193``, ``1.2 \cdot 10^{-5}``.

    >>> float_latex(50.9999999999999534), float_latex(-2.69257272589), float_latex(1.2e-5), float_latex(0.0)
    ('51', '-2.69257', '1.2 \\cdot 10^{-5}', '0')
    """
    x = float(x)
    if x == 0:
        return "0"
    text = f"{x:.{digits}g}"
    if "e" in text:
        mant, exp = text.split("e")
        k = int(exp)
        return (f"{mant} \\cdot " if mant not in ("1", "-1") else ("-" if mant == "-1" else "")) + f"10^{{{k}}}"
    return text


def _as_sympy(expr: Any) -> sp.Basic:
    """A sympy object, or an int/float/mpmath number converted; anything else is refused (never a string)."""
    if isinstance(expr, sp.Basic):
        return expr
    if isinstance(expr, bool) or isinstance(expr, str):
        raise TypeError(f"a formula to print must be a sympy expression or a number, got {type(expr).__name__}")
    if isinstance(expr, int):
        return sp.Integer(expr)
    if isinstance(expr, mpmath.mpf):
        return sp.Float(expr, mpmath.mp.dps)
    if isinstance(expr, float):
        return sp.Float(expr)
    if hasattr(expr, "numerator") and hasattr(expr, "denominator"):  # fractions.Fraction
        return sp.Rational(int(expr.numerator), int(expr.denominator))
    raise TypeError(f"a formula to print must be a sympy expression or a number, got {type(expr).__name__}")


def _parameter_poly(expr: sp.Expr) -> sp.Symbol | None:
    """The parameter (nu or kappa) when ``expr`` is a polynomial in it alone, else None."""
    free = expr.free_symbols
    if len(free) == 1:
        (v,) = free
        if getattr(v, "name", None) in _PARAMETERS and expr.is_polynomial(v):
            return v
    return None


def ordered_terms(add: sp.Expr) -> list[sp.Expr]:
    """The terms of a sum in print order: ascending powers of a one-parameter polynomial, else sympy's order
    with a positive term first when there is one.
    """
    return list(_ordered_terms(add))


@lru_cache(maxsize=4096)
def _ordered_terms(add: sp.Expr) -> tuple[sp.Expr, ...]:
    v = _parameter_poly(add)
    if v is not None:
        return tuple(sorted(sp.Add.make_args(add), key=lambda t: sp.degree(t, v)))
    terms = list(add.as_ordered_terms())
    first = next((i for i, t in enumerate(terms) if not t.could_extract_minus_sign()), 0)
    return tuple(terms[first:first + 1] + terms[:first] + terms[first + 1:])


def _all_fractions(add: sp.Expr) -> bool:
    """Every term of the sum has a symbolic denominator (``1/R_1 + 1/R_2``): bring it to one fraction."""
    return all(sp.fraction(t)[1].free_symbols for t in sp.Add.make_args(add))


def _printed_fraction(x: sp.Expr) -> bool:
    """Whether ``x`` is printed with a fraction in it (the exponent 1/2 of a square root is not one)."""
    if isinstance(x, sp.Rational):
        return not x.is_Integer
    if isinstance(x, sp.Pow):
        if x.exp.is_negative:
            return True
        if x.exp == sp.S.Half:
            return _printed_fraction(x.base)
    return any(_printed_fraction(a) for a in x.args)


def _holds_fraction(base: sp.Expr, e: sp.Expr) -> bool:
    """A factor ``base**e`` whose printed argument holds a fraction: ``e^{..}``, a function, a square root."""
    if base is sp.E:
        return _printed_fraction(e)
    if e == sp.S.Half and not base.is_Atom:
        return _printed_fraction(base)
    if base.is_Function and e.is_Integer:
        return any(_printed_fraction(a) for a in base.args)
    return False


def _normal_add(add: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """``(content, primitive)`` of a sum: content a signed number, primitive with a positive first term."""
    content, prim = add.as_content_primitive()
    if not isinstance(prim, sp.Add):
        return content, prim
    if ordered_terms(prim)[0].could_extract_minus_sign():
        content, prim = -content, sp.expand(-prim)
    return content, prim


@dataclass
class Term:
    """One product of the policy: ``coefficient * prod(num) / prod(den) * prod(outside)``.

    ``num`` and ``den`` map a base to its exponent (a number, or 1/2 for a square root); ``outside``
    holds sums that contain fractions, set after the fraction.
    """

    coefficient: sp.Expr
    num: dict = field(default_factory=dict)
    den: dict = field(default_factory=dict)
    outside: list = field(default_factory=list)

    def value(self) -> sp.Expr:
        """The product as a sympy expression (for checking that it equals the original)."""
        out = self.coefficient
        for b, e in self.num.items():
            out *= b**e
        for b, e in self.den.items():
            out /= b**e
        for b in self.outside:
            out *= b
        return out


def _symbolic_fraction(add: sp.Expr) -> bool:
    """A term of the sum has a symbol in its denominator (``delta_0 - x_1^2/(2 R)``)."""
    return any(sp.fraction(t)[1].free_symbols for t in sp.Add.make_args(add))


def _merge(term: Term, sub: Term) -> None:
    term.coefficient *= sub.coefficient
    for b, k in sub.num.items():
        term.num[b] = term.num.get(b, 0) + k
    for b, k in sub.den.items():
        term.den[b] = term.den.get(b, 0) + k
    term.outside += sub.outside


@lru_cache(maxsize=4096)
def _factored(base: sp.Expr) -> sp.Expr | None:
    """``factor(base)`` of a polynomial sum small enough to factor for printing (no floats; total degree at most
    8), else None.  Cached: the same few factors (``1 - 2 nu``, ``1 - nu``) recur in every coefficient.
    """
    if base.has(sp.Float) or len(base.free_symbols) > 6 or len(base.args) > 40 or not base.is_polynomial():
        return None  # (many symbols: sympy's dense factorisation took 90 s on a 30-parameter punch's report)
    gens = sorted(base.free_symbols, key=sp.default_sort_key)
    if gens and sp.Poly(base, *gens).total_degree() > _FACTOR_DEGREE:
        return None
    return sp.factor(base)


def _add_factor(term: Term, base: sp.Expr, e: sp.Expr) -> None:
    if isinstance(base, sp.Add) and e.is_Integer:
        if _symbolic_fraction(base):
            if _all_fractions(base):  # 1/R_1 + 1/R_2 -> (R_1 + R_2)/(R_1 R_2)
                _merge(term, normal_term(sp.together(base) ** e))
                return
            if e == 1:  # delta_0 - x_1^2/(2 R): after the fraction, its sign normalised only
                if ordered_terms(base)[0].could_extract_minus_sign():
                    term.coefficient, base = -term.coefficient, sp.expand(-base)
                term.outside.append(base)
                return
        factored = _factored(base)
        if factored is not None:
            if not isinstance(factored, sp.Add):  # reducible: each factor by the policy
                _merge(term, normal_term(factored**e))
                return
        content, prim = _normal_add(base)
        term.coefficient *= content**e
        base = prim
    if base.is_Number and e.is_Integer:
        term.coefficient *= base**e
        return
    if not e.is_negative and _holds_fraction(base, e):  # e^{-B (v - 1/(2B))}: after the fraction
        term.outside.append(sp.Pow(base, e, evaluate=False))  # as written: sqrt(x/12) is not re-split
        return
    if e.is_negative:
        term.den[base] = term.den.get(base, 0) - e
    else:
        term.num[base] = term.num.get(base, 0) + e


def normal_term(expr: sp.Expr) -> Term:
    """One product of ``expr`` split by the policy (module docstring) into a :class:`Term`."""
    coeff, rest = expr.as_coeff_Mul()
    term = Term(coeff)
    for f in sp.Mul.make_args(rest):
        base, e = f.as_base_exp()
        _add_factor(term, base, e)
    for d in (term.num, term.den):
        for b in [b for b, e in d.items() if e == 0]:
            del d[b]
    c = term.coefficient
    if not term.den and not (c.is_Rational and c.q != 1):  # no fraction bar: nothing to keep out of one
        for b in [b for b in term.outside if not isinstance(b, sp.Add)]:
            term.outside.remove(b)
            base, e = b.as_base_exp()
            term.num[base] = term.num.get(base, 0) + e
    common = set(term.num) & set(term.den)
    for b in common:  # a base on both sides (after normalising the signs of sums)
        k = term.num.pop(b) - term.den.pop(b)
        if k:
            (term.num if k > 0 else term.den)[b] = abs(k)
    return term


def normal_terms(expr: sp.Expr) -> list[Term]:
    """The terms of ``expr`` (a sum or one product) as :class:`Term` objects, in print order; zero terms dropped."""
    expr = _as_sympy(expr)
    terms = ordered_terms(expr) if isinstance(expr, sp.Add) else [expr]
    return [normal_term(t) for t in terms if t != 0]


def _negative(c: sp.Expr) -> bool:
    return bool(c.is_negative) or bool(c.is_Float and float(c) < 0)


def _split_coefficient(c: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """``(numerator, denominator)`` of a non-negative coefficient."""
    if c.is_Rational:
        return sp.Integer(c.p), sp.Integer(c.q)
    return c, sp.S.One


def _negated_polynomial(expr: sp.Expr) -> bool:
    """A one-parameter polynomial whose constant term is negative (``nu - 1``): printed ``-(1 - nu)``."""
    return _parameter_poly(expr) is not None and ordered_terms(expr)[0].could_extract_minus_sign()


def _positive_first(expr: sp.Expr) -> sp.Expr:
    """``expr`` or ``-expr``, whichever prints with a positive first term (the argument of ``|..|``)."""
    if isinstance(expr, sp.Add) and ordered_terms(expr)[0].could_extract_minus_sign():
        return sp.expand(-expr)
    return expr


def join_signed(parts: list[str], latex: bool = True) -> str:
    r"""Printed terms joined by ``+`` and ``-``: a term that starts with a minus is subtracted (no ``+ -``),
    an empty or zero term is left out.

    >>> join_signed(["1", "0.87\\,\\lambda", "- 0.34\\,\\lambda^{2}", "0"])
    '1 + 0.87\\,\\lambda - 0.34\\,\\lambda^{2}'
    >>> join_signed(["-x", "-2y", "3"], latex=False)
    '-x - 2y + 3'
    """
    out = ""
    for p in parts:
        p = p.strip()
        if not p or p == "0":
            continue
        negative = p.startswith("-")
        body = p[1:].lstrip() if negative else p
        if not out:
            out = ("- " if latex else "-") + body if negative else body
        else:
            out += (" - " if negative else " + ") + body
    return out or "0"


# ---------------------------------------------------------------------------------------------------
# LaTeX
# ---------------------------------------------------------------------------------------------------
class NormalLatexPrinter(LatexPrinter):
    """sympy's LaTeX printer with the normal form for sums, products, powers, floats and elliptic integrals."""

    def __init__(self, digits: int = DIGITS, **settings: Any):
        super().__init__(settings)
        self.digits = digits

    def _print_Float(self, expr):
        return float_latex(expr, self.digits)

    def _print_Add(self, expr, order=None):
        if _negated_polynomial(expr):  # nu - 1 on its own: -(1 - nu)
            return rf"- \left({self._print_Add(sp.expand(-expr))}\right)"
        out = ""
        for k, t in enumerate(normal_terms(expr)):
            body, negative = self._term(t)
            if k == 0:
                out = ("- " if negative else "") + body
            else:
                out += (" - " if negative else " + ") + body
        return out or "0"

    def _print_Mul(self, expr):
        body, negative = self._term(normal_term(expr))
        return ("- " if negative else "") + body

    def _print_Abs(self, expr, exp=None):
        tex = rf"\left|{self._print(_positive_first(expr.args[0]))}\right|"
        return tex if exp is None else rf"{tex}^{{{exp}}}"

    def _print_Pow(self, expr):
        b, e = expr.base, expr.exp
        if e.is_negative or (isinstance(b, sp.Add) and e.is_Integer) or (e == sp.S.Half and not b.is_Atom):
            return self._print_Mul(sp.Mul(sp.S.One, expr, evaluate=False))
        if isinstance(b, sp.Symbol) and e.is_Integer:
            return self._factor(b, e)
        return super()._print_Pow(expr)

    def _elliptic(self, letter: str, expr, exp=None) -> str:
        m = expr.args[0]
        k = self._print(sp.sqrt(m)) if m.is_number or m.is_Atom else rf"\sqrt{{{self._print(m)}}}"
        tex = rf"\mathrm{{{letter}}}\left({k}\right)"
        return tex if exp is None else rf"{tex}^{{{exp}}}"

    def _print_elliptic_k(self, expr, exp=None):
        return self._elliptic("K", expr, exp)

    def _print_elliptic_e(self, expr, exp=None):
        if len(expr.args) != 1:  # the incomplete integral E(phi | m): sympy's form
            return super()._print_elliptic_e(expr, exp)
        return self._elliptic("E", expr, exp)

    # ---- one term ------------------------------------------------------------------------------
    def _factor(self, base: sp.Expr, e: sp.Expr) -> str:
        if isinstance(base, sp.Add):
            inner = rf"\left({self._print(base)}\right)"
        elif isinstance(base, sp.Symbol):
            inner = self._print(base)
            if e != 1 and "^" in inner:  # h^{*} squared: {h^{*}}^{2}, never a double superscript
                inner = "{" + inner + "}"
        elif (isinstance(base, sp.Integer) or base.is_Function or isinstance(base, sp.NumberSymbol)
              or (isinstance(base, sp.Pow) and base.base.is_Symbol and e == 1)):
            inner = self._print(base)
        else:
            inner = rf"\left({self._print(base)}\right)"
        return inner if e == 1 else f"{inner}^{{{self._print(e)}}}"

    def _side(self, factors: dict, number: sp.Expr) -> str:
        roots = [b**(2 * e) if e != sp.S.Half else b for b, e in factors.items() if e.is_Rational and e.q == 2]
        plain = [(b, e) for b, e in factors.items() if not (e.is_Rational and e.q == 2)]
        if number == 1 and not roots and len(plain) == 1 and plain[0][1] == 1:  # a lone sum needs no parentheses
            return self._print(plain[0][0])
        parts = []
        if number != 1:
            parts.append(self._print(number))

        for b, e in sorted(plain, key=_factor_order):
            parts.append(self._factor(b, e))
        if roots:  # one radical: \sqrt{2 R_1 \delta_0}, \sqrt{B^2 + s^2}, \sqrt{\frac{3 (..)}{1 - 2 \nu}}
            parts.append(rf"\sqrt{{{self._print(sp.Mul(*roots))}}}")
        return " ".join(parts)

    def _outside(self, b: sp.Expr) -> str:
        """A factor set after the fraction: a sum in parentheses, a square root of its (normalised) argument."""
        if isinstance(b, sp.Add):
            return rf"\left({self._print(b)}\right)"
        if isinstance(b, sp.Pow) and b.exp == sp.S.Half:
            return rf"\sqrt{{{self._print(b.base)}}}"
        return self._print(b)

    def _term(self, t: Term) -> tuple[str, bool]:
        c = t.coefficient
        negative = _negative(c)
        cn, cd = _split_coefficient(-c if negative else c)
        num = self._side(t.num, cn)
        den = self._side(t.den, cd)
        outside = " ".join(self._outside(b) for b in t.outside)
        if not num:
            num = "1" if (den or not outside) else ""
        body = rf"\frac{{{num}}}{{{den}}}" if den else num
        if outside:
            body = (body + " " if body not in ("", "1") else "") + outside
        return body.strip(), negative


#: the name the reports used first
ReportPrinter = NormalLatexPrinter


def _factor_order(be: tuple) -> tuple:
    """Symbols, then powers of e, then sums (the order of factors in a product)."""
    return isinstance(be[0], sp.Add), be[0] is sp.E, sp.default_sort_key(be[0])


def normal_latex(expr: Any, digits: int = DIGITS) -> str:
    r"""LaTeX of ``expr`` in the normal form (module docstring).

    >>> import sympy as sp
    >>> nu, mu, H, m = sp.Symbol("nu", real=True), sp.Symbol("mu"), sp.Symbol("H"), sp.Symbol("m")
    >>> normal_latex((sp.Rational(1, 2) - nu) / (1 - nu) ** 2)
    '\\frac{1 - 2 \\nu}{2 \\left(1 - \\nu\\right)^{2}}'
    >>> normal_latex((nu - 1) / (2 * nu - 1))
    '\\frac{1 - \\nu}{1 - 2 \\nu}'
    >>> normal_latex(sp.Float("50.9999999999999534", 30) * mu / H)
    '\\frac{51 \\mu}{H}'
    >>> normal_latex(4 * sp.elliptic_e(sp.Rational(3, 4)) - sp.elliptic_k(m) + sp.Symbol("h^*") ** 2)
    '{h^{*}}^{2} - \\mathrm{K}\\left(\\sqrt{m}\\right) + 4 \\mathrm{E}\\left(\\frac{\\sqrt{3}}{2}\\right)'
    """
    return NormalLatexPrinter(digits).doprint(_as_sympy(expr))


# ---------------------------------------------------------------------------------------------------
# text
# ---------------------------------------------------------------------------------------------------
_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
_SUBSCRIPT = str.maketrans("0123456789aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ")
_SUBSCRIPTABLE = frozenset("0123456789aehijklmnoprstuvx")
_GREEK = {**greek_unicode, "vartheta": "ϑ", "varphi": "ϕ", "varepsilon": "ε", "epsilon": "ε", "lamda": "λ"}
_LATEX_FONT = re.compile(r"\\(?:mathcal|mathrm|mathbf|mathit|operatorname|boldsymbol)\{([^{}]*)\}")
_CALLIGRAPHIC = {"A": "𝒜", "L": "ℒ"}


def symbol_text(name: str, unicode: bool = True) -> str:
    r"""A symbol's name in text: Greek letters, sub- and superscripts in Unicode; a star kept off the power.

    In ASCII a starred name takes ``_s`` (``H_*`` -> ``H_s``, ``delta_0^*`` -> ``delta_0_s``: the names of
    :mod:`thinlayer.symbols` and of generated code), so that its square ``H_s**2`` is never ``H_***2``.

    >>> [symbol_text(n) for n in ["nu", "delta_0", "H_*", "delta_0^*", "x_1", "vartheta", "R_1^*", "m_12"]]
    ['ν', 'δ₀', 'H*', 'δ₀*', 'x₁', 'ϑ', 'R₁*', 'm₁₂']
    >>> [symbol_text(n, unicode=False) for n in ["nu", "H_*", "delta_0^*", "h^*", r"\mathcal{A}"]]
    ['nu', 'H_s', 'delta_0_s', 'h_s', 'A']
    """
    plain = _LATEX_FONT.sub(r"\1", name)
    if not unicode:
        plain = plain.replace("^*", "_s").replace("_*", "_s").replace("\\", "")
        return plain.replace("{", "").replace("}", "")
    font = _LATEX_FONT.fullmatch(name)
    if font and name.startswith(r"\mathcal") and font.group(1) in _CALLIGRAPHIC:
        return _CALLIGRAPHIC[font.group(1)]
    base, supers, subs = split_super_sub(plain.replace("\\", "").replace("{", "").replace("}", ""))
    star = "*" if "*" in supers or "*" in subs else ""
    supers = [s for s in supers if s != "*"]
    subs = [s for s in subs if s != "*"]
    out = _GREEK.get(base, base)
    for s in subs:
        s = _GREEK.get(s, s)
        out += s.translate(_SUBSCRIPT) if set(s) <= _SUBSCRIPTABLE else "_" + s
    for s in supers:
        out += s.translate(_SUPERSCRIPT) if s.lstrip("-").isdigit() else "^" + s
    return out + star


class NormalTextPrinter(StrPrinter):
    """The normal form as one line of text: Unicode maths, or sympy's syntax with ``unicode=False``.

    Products are juxtaposed in Unicode (``2ν``, ``3π R δ₀² μ/H``), starred symbols keep their star off the
    power (``H*²``), square roots are ``√``, the elliptic integrals ``K(k)``, ``E(k)`` of the modulus.
    """

    printmethod = "_thinlayer_text"  # no object's own str hook: the normal form decides

    def __init__(self, unicode: bool = True, digits: int = TEXT_DIGITS, **settings: Any):
        super().__init__(settings)
        self.unicode = unicode
        self.digits = digits

    # ---- atoms ---------------------------------------------------------------------------------
    def _print_Symbol(self, expr):
        return symbol_text(expr.name, self.unicode)

    _print_Dummy = _print_Symbol

    def _print_Pi(self, expr):
        return "π" if self.unicode else "pi"

    def _print_Exp1(self, expr):
        return "e" if self.unicode else "E"

    def _print_Infinity(self, expr):
        return "∞" if self.unicode else "oo"

    def _print_NegativeInfinity(self, expr):
        return "-∞" if self.unicode else "-oo"

    def _print_ImaginaryUnit(self, expr):
        return "i" if self.unicode else "I"

    def _print_Float(self, expr):
        return mpmath.nstr(mpmath.mpf(expr), self.digits)

    def _print_Rational(self, expr):
        return f"{expr.p}/{expr.q}" if expr.q != 1 else str(expr.p)

    def _print_Half(self, expr):
        return self._print_Rational(expr)

    # ---- functions -----------------------------------------------------------------------------
    def _print_exp(self, expr):
        return f"exp({self._print(expr.args[0])})"

    def _print_Abs(self, expr):
        return f"|{self._print(_positive_first(expr.args[0]))}|"

    def _elliptic(self, letter: str, expr) -> str:
        m = expr.args[0]
        if m.is_number or m.is_Atom:
            return f"{letter}({self._print(sp.sqrt(m))})"
        return f"{letter}({self._root([m])})"

    def _print_elliptic_k(self, expr):
        return self._elliptic("K", expr)

    def _print_elliptic_e(self, expr):
        if len(expr.args) != 1:
            return super()._print_Function(expr)
        return self._elliptic("E", expr)

    def _bessel(self, letter: str, expr) -> str:
        order = self._print(expr.args[0])
        if self.unicode and set(order) <= _SUBSCRIPTABLE:
            return f"{letter}{order.translate(_SUBSCRIPT)}({self._print(expr.args[1])})"
        return f"{expr.func.__name__}({order}, {self._print(expr.args[1])})"

    def _print_besseli(self, expr):
        return self._bessel("I", expr)

    def _print_besselj(self, expr):
        return self._bessel("J", expr)

    def _print_besselk(self, expr):
        return self._bessel("K", expr)

    # ---- sums, products, powers -----------------------------------------------------------------
    def _print_Add(self, expr, order=None):
        if _negated_polynomial(expr):  # nu - 1 on its own: -(1 - nu)
            return f"-({self._print_Add(sp.expand(-expr))})"
        out = ""
        for k, t in enumerate(normal_terms(expr)):
            body, negative = self._term(t)
            if k == 0:
                out = ("-" if negative else "") + body
            else:
                out += (" - " if negative else " + ") + body
        return out or "0"

    def _print_Mul(self, expr):
        body, negative = self._term(normal_term(expr))
        return ("-" if negative else "") + body

    def _print_Pow(self, expr, rational=False):
        b, e = expr.base, expr.exp
        if e.is_negative or (isinstance(b, sp.Add) and e.is_Integer) or e == sp.S.Half:
            return self._print_Mul(sp.Mul(sp.S.One, expr, evaluate=False))
        return self._factor(b, e)

    def _exponent(self, e: sp.Expr) -> str:
        if self.unicode and e.is_Integer and e > 0:
            return str(e).translate(_SUPERSCRIPT)
        text = self._print(e)
        if not ((e.is_Integer and e > 0) or isinstance(e, sp.Symbol)):
            text = f"({text})"
        return ("^" if self.unicode else "**") + text

    def _factor(self, base: sp.Expr, e: sp.Expr) -> str:
        """``base**e`` as one factor of a product: parenthesised when it is not an atom."""
        if base is sp.E:
            return f"exp({self._print(e)})"
        if e == sp.S.Half:
            return self._root([base])
        if isinstance(base, (sp.Symbol, sp.Integer, sp.NumberSymbol)) or base.is_Function:
            inner = self._print(base)
            if isinstance(base, sp.Integer) and base < 0:
                inner = f"({inner})"
        else:
            inner = f"({self._print(base)})"
        return inner if e == 1 else inner + self._exponent(e)

    def _root(self, bases: list) -> str:
        b = sp.Mul(*bases)
        inner = self._print(b)
        if not self.unicode:
            return f"sqrt({inner})"
        return "√" + (inner if isinstance(b, (sp.Symbol, sp.Integer, sp.NumberSymbol)) else f"({inner})")

    def _join(self, parts: list[str], number: str | None = None) -> str:
        """Factors of a product: juxtaposed in Unicode (``2ν``, ``π R``, ``(1 - ν)(1 - 2ν)``), ``*`` in ASCII.

        A number binds to what follows (``2ν``, ``3(1 - ν)``), two parenthesised sums to each other; any other
        pair is spaced, so that a function's argument never runs into a following group (``E(k) (1 - ν)``).
        """
        items = ([number] if number is not None else []) + parts
        if not self.unicode:
            return "*".join(items)
        out = ""
        for k, item in enumerate(items):
            if k == 0:
                out = item
                continue
            prev = items[k - 1]
            tight = (k == 1 and number is not None and prev.isdigit()) or (_is_group(prev) and _is_group(item))
            out += ("" if tight else " ") + item
        return out

    def _side(self, factors: dict, number: sp.Expr, outside: list | None = None) -> tuple[str, int]:
        """The text of one side of a fraction and how many factors it has (for parentheses)."""
        roots = [b**(2 * e) if e != sp.S.Half else b for b, e in factors.items() if e.is_Rational and e.q == 2]
        plain = [(b, e) for b, e in factors.items() if not (e.is_Rational and e.q == 2)]
        parts = [self._factor(b, e) for b, e in sorted(plain, key=_factor_order)]
        if roots:
            parts.append(self._root([sp.Mul(*roots)]))
        parts += [self._outside(b) for b in outside or []]
        count = len(parts) + (number != 1)
        if number != 1:
            return self._join(parts, self._print(number)), count
        return self._join(parts), count

    def _outside(self, b: sp.Expr) -> str:
        if isinstance(b, sp.Add):
            return f"({self._print(b)})"
        base, e = b.as_base_exp()
        return self._factor(base, e)

    def _term(self, t: Term) -> tuple[str, bool]:
        c = t.coefficient
        negative = _negative(c)
        cn, cd = _split_coefficient(-c if negative else c)
        num, n_num = self._side(t.num, cn, t.outside)
        den, n_den = self._side(t.den, cd)
        if not den:
            return num or "1", negative
        return f"{num or '1'}/({den})" if n_den > 1 else f"{num or '1'}/{den}", negative


def _is_group(text: str) -> bool:
    """``(..)`` or ``(..)ⁿ``: one parenthesised sum, perhaps to a power (not a function call ``f(..)``)."""
    stripped = text.rstrip("⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
    if not (stripped.startswith("(") and stripped.endswith(")")):
        return False
    depth = 0
    for i, ch in enumerate(stripped):
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if depth == 0 and i < len(stripped) - 1:
            return False
    return True


def normal_text(expr: Any, unicode: bool = True, digits: int = TEXT_DIGITS) -> str:
    """``expr`` as one line of text in the normal form (module docstring).

    >>> import sympy as sp
    >>> nu, x1, x2 = sp.Symbol("nu", real=True), sp.Symbol("x_1"), sp.Symbol("x_2")
    >>> A = (sp.Rational(1, 2) - nu) / (1 - nu) ** 2
    >>> normal_text(A), normal_text(A, unicode=False)
    ('(1 - 2ν)/(2(1 - ν)²)', '(1 - 2*nu)/(2*(1 - nu)**2)')
    >>> normal_text(x1**2 / 8 + x2**2 / 2), normal_text(sp.Symbol("H_*") ** 2 * sp.Symbol("xi_1"))
    ('x₁²/8 + x₂²/2', 'H*² ξ₁')
    >>> normal_text(8 * sp.elliptic_e(sp.Rational(3, 4))), normal_text(-sp.Symbol("a") * (1 - nu) / (nu - 1))
    ('8E(√3/2)', 'a')
    """
    return NormalTextPrinter(unicode, digits).doprint(_as_sympy(expr))


_ASCII = {**{v: k for k, v in greek_unicode.items() if len(v) == 1 and k != "lamda"}, "ϑ": "vartheta", "ϕ": "varphi",
          "ε": "epsilon", "𝒜": "A", "ℒ": "L", "√": "sqrt", "∞": "oo", "π": "pi", "−": "-", "·": "*",
          "∬": "iint", "∮": "oint", "∇": "grad", "Δ": "Delta", "≤": "<=", "≥": ">=", "≈": "~", "∼": "~",
          "±": "+-", "→": "->", "…": "...", "ℓ": "l"}
_SUB_BACK = {v: k for k, v in zip("0123456789aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ")}
_SUP_BACK = {v: k for k, v in zip("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")}


def to_ascii(text: str) -> str:
    """A Unicode line of :func:`normal_text` (or of a result's text) as ASCII: ``ν`` -> ``nu``, ``x₁²`` -> ``x_1^2``.

    For a stream that cannot take Unicode (:meth:`thinlayer.display.RichDisplay.__str__`).

    >>> to_ascii("(1 - 2ν)/(2(1 - ν)²),  Φ = x₁²/8 + √(2R δ₀)")
    '(1 - 2nu)/(2(1 - nu)^2),  Phi = x_1^2/8 + sqrt(2R delta_0)'
    """
    text = re.sub("[₀-₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ]+", lambda m: "_" + "".join(_SUB_BACK[c] for c in m.group()), text)
    text = re.sub("[⁰¹²³⁴⁵⁶⁷⁸⁹⁻]+", lambda m: "^" + "".join(_SUP_BACK[c] for c in m.group()), text)
    text = re.sub(r"√(\w+)", r"sqrt(\1)", text)
    out = "".join(_ASCII.get(c, c) for c in text)
    return out.encode("ascii", "replace").decode("ascii")
