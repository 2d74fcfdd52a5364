r"""One normalisation policy for every formula of a report, implemented once (:func:`normal_latex`).

The policy, applied to every product (at the top level and inside function arguments alike):

* the numeric content of every sum is pulled out and joined with the product's coefficient into one
  fraction: ``(1/2 - nu)`` is written ``(1 - 2 nu)/2``, ``-4 nu^3/15 - ... - 1/20`` as
  ``-(3 - 30 nu + ...)/60``;
* a polynomial in one parameter (``nu``, ``kappa``) is written in ascending powers with a positive first
  coefficient: ``(1 - 2 nu)`` and ``(1 - nu)``, never ``(2 nu - 1)`` or ``(nu - 1)``; any other sum starts
  with a positive term when it has one, and is negated (the sign moved in front) when it has none;
* equal factors are merged (``(1 - 2 nu) (1 - 2 nu)`` is ``(1 - 2 nu)^2``); square roots are joined
  (``\sqrt{2 R_1 \delta_0}``, not ``\sqrt{2} \sqrt{R_1} \sqrt{\delta_0}``);
* no fraction inside a fraction: a sum whose terms are all fractions is brought to one fraction first
  (``1/R_1 + 1/R_2`` is ``(R_1 + R_2)/(R_1 R_2)``); a sum that still holds a fraction
  (``\delta_0 - x_1^2/(2 R)``) is set in parentheses after the fraction, not inside it, and so is a
  function, power of ``e`` or square root whose argument holds a fraction (``\frac{1}{\sqrt{\pi B}}
  e^{-B (v - h)} \sqrt{v - h}``, not ``e^{..}`` and ``\sqrt{..}`` inside the numerator); the argument itself
  is printed by the same policy, and a square root of a lone sum takes no parentheses;
* floating-point numbers to ``digits`` significant digits (``51``, not ``50.9999999999999534``), powers
  of ten as ``\cdot 10^{k}``; no term that is zero.

:func:`normal_terms` returns the pieces the LaTeX is printed from, so that a test can check that they
add up to the original expression.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp
from sympy.printing.latex import LatexPrinter

from .. import symbols as S
from ..parse import as_expr

#: significant digits of a floating-point number in a report
DIGITS = 6
#: sums factored for print at most this large (a 30-parameter punch took 90 s in sp.factor before the bound)
MAX_FACTOR_SYMBOLS = 6
MAX_FACTOR_TERMS = 40
_PARAMETERS = (S.nu, S.kappa)


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


def _parameter_poly(expr: sp.Expr) -> sp.Symbol | None:
    """The parameter (nu or kappa) when ``expr`` is a polynomial in it alone, else None."""
    free = expr.free_symbols
    if len(free) == 1:
        (v,) = free
        if v in _PARAMETERS and expr.is_polynomial(v):
            return v
    return None


def ordered_terms(add: sp.Expr) -> list[sp.Expr]:
    """The terms of a sum in print order: ascending powers of a one-parameter polynomial, else sympy's order
    with a positive term first when there is one.
    """
    v = _parameter_poly(add)
    if v is not None:
        return sorted(sp.Add.make_args(add), key=lambda t: sp.degree(t, v))
    terms = list(add.as_ordered_terms())
    first = next((i for i, t in enumerate(terms) if not t.could_extract_minus_sign()), 0)
    return terms[first:first + 1] + terms[:first] + terms[first + 1:]


def _has_fraction(e: sp.Expr) -> bool:
    return any(isinstance(a, sp.Pow) and a.exp.is_negative for a in sp.preorder_traversal(e)) or \
        any(isinstance(a, sp.Rational) and not a.is_Integer for a in sp.preorder_traversal(e))


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
        # factor only small sums: sympy's dense multivariate factorisation costs minutes at 30 parameters
        if (not base.has(sp.Float) and len(base.free_symbols) <= MAX_FACTOR_SYMBOLS
                and len(base.args) <= MAX_FACTOR_TERMS and base.is_polynomial()):
            factored = sp.factor(base)
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
        term.outside.append(base**e)
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
        (term.num if k > 0 else term.den)[b] = abs(k)
        if k == 0:
            (term.num if k > 0 else term.den).pop(b)
    return term


def normal_terms(expr: sp.Expr) -> list[Term]:
    """The terms of ``expr`` (a sum or one product) as :class:`Term` objects, in print order; zero terms dropped."""
    expr = as_expr(expr)
    terms = ordered_terms(expr) if isinstance(expr, sp.Add) else [expr]
    return [normal_term(t) for t in terms if t != 0]


class ReportPrinter(LatexPrinter):
    """sympy's LaTeX printer with the report's policy for sums, products, powers and floats."""

    def __init__(self, digits: int = DIGITS, **settings):
        super().__init__(settings)
        self.digits = digits

    def _print_Float(self, expr):
        return float_latex(expr, self.digits)

    def _print_Add(self, expr, order=None):
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

    def _print_Pow(self, expr):
        b, e = expr.base, expr.exp
        if e.is_negative or (isinstance(b, sp.Add) and e.is_Integer) or (e == sp.S.Half and not b.is_Atom):
            return self._print_Mul(sp.Mul(sp.S.One, expr, evaluate=False))
        return super()._print_Pow(expr)

    # ---- one term ------------------------------------------------------------------------------
    def _factor(self, base: sp.Expr, e: sp.Expr) -> str:
        if isinstance(base, sp.Add):
            inner = rf"\left({self._print(base)}\right)"
        elif (isinstance(base, (sp.Symbol, sp.Integer)) or base.is_Function or isinstance(base, sp.NumberSymbol)
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
        def order(be: tuple) -> tuple:  # symbols, then powers of e, then sums
            return isinstance(be[0], sp.Add), be[0] is sp.E, sp.default_sort_key(be[0])

        for b, e in sorted(plain, key=order):
            parts.append(self._factor(b, e))
        if len(roots) == 1 and isinstance(roots[0], sp.Add):  # \sqrt{B^2 + s^2}, no parentheses
            parts.append(rf"\sqrt{{{self._print(roots[0])}}}")
        elif roots:
            parts.append(rf"\sqrt{{{' '.join(self._factor(b, 1) for b in roots)}}}")
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
        negative = bool(c.is_negative) or (c.is_Float and float(c) < 0)
        c = -c if negative else c
        if c.is_Rational:
            cn, cd = sp.Integer(c.p), sp.Integer(c.q)
        else:
            cn, cd = c, sp.S.One
        num = self._side(t.num, cn)
        den = self._side(t.den, cd)
        outside = " ".join(self._outside(b) for b in t.outside)
        if not num:
            num = "1" if (den or not outside) else ""
        body = rf"\frac{{{num}}}{{{den}}}" if den else num
        if outside:
            body = (body + " " if body not in ("", "1") else "") + outside
        return body.strip(), negative


def normal_latex(expr: sp.Expr, digits: int = DIGITS) -> str:
    r"""LaTeX of ``expr`` under the report's normalisation policy (module docstring).

    >>> import sympy as sp
    >>> from thinlayer import symbols as S
    >>> normal_latex((sp.Rational(1, 2) - S.nu) / (1 - S.nu) ** 2)
    '\\frac{1 - 2 \\nu}{2 \\left(1 - \\nu\\right)^{2}}'
    >>> normal_latex((S.nu - 1) / (2 * S.nu - 1))
    '\\frac{1 - \\nu}{1 - 2 \\nu}'
    >>> normal_latex(sp.Float("50.9999999999999534", 30) * S.mu / S.H)
    '\\frac{51 \\mu}{H}'
    """
    return ReportPrinter(digits).doprint(as_expr(expr))
