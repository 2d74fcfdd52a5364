"""Read a user's formula without running it: a small grammar, never ``eval`` or ``sympify``.

``sympy.sympify`` evaluates its input as Python (``"__import__('os').system(...)"`` runs), so every
string a user gives thinlayer -- a punch, a parameter value, a derivation file's ``expr`` -- is read
here instead.  The grammar is that of a polynomial with parameters::

    expr  := term (("+" | "-") term)*
    term  := unary (("*" | "/") unary)*
    unary := ("+" | "-") unary | power
    power := atom ("**" unary)?              (right-associative, binds tighter than a sign, as in Python)
    atom  := number | name | "(" expr ")"

A number is a decimal integer or float (``2``, ``0.3``, ``1e-71``); a name is a letter followed by
letters, digits and underscores.  The coordinates become ``thinlayer.symbols.x1, x2`` and every other
name a plain sympy Symbol of that name -- ``E``, ``I``, ``S``, ``N``, ``Q``, ``beta``, ``gamma`` and
``lambda`` included (never Euler's number, the imaginary unit or a sympy function).  Anything else
(a call, an attribute, a string, ``^``, ``[``, ``=``, ...) is an :class:`ExpressionError` naming the token
and its position.

A formula in the coordinates may also take the maximum or minimum of linear forms (a polyhedral tip,
:meth:`thinlayer.Punch.from_expr`)::

    atom  := ... | ("max" | "min") "(" expr ("," expr)* ")"

each argument a linear form ``a*x1 + b*x2 + c`` in the coordinates (coefficients numbers or parameters) or a
max/min/sum/multiple of such, at most :data:`MAX_ARGUMENTS` arguments per call; the same bounds as every formula.

A radial profile ``Phi(r)`` of a tip of revolution (``parse_expression(text, radial=True)``,
:meth:`thinlayer.Punch.revolution`) is read by the same grammar with three additions and the same bounds::

    atom  := number | name | "(" expr ")" | ("sqrt" | "abs") "(" expr ")" | ("max" | "min") "(" expr ("," expr)* ")"
    power := atom ("**" unary)?        (the exponent a number: an integer or an exact rational p/q, |p|, q <= 1000)

The name ``r`` is the radius (``thinlayer.parse.RADIUS``, a nonnegative Symbol), the coordinates ``x_1, x_2`` are
not names there, ``sqrt``, ``abs``, ``max`` and ``min`` are the only calls (any other call, attribute or keyword stays
an error; each argument of max/min a linear form ``a*r + c`` or a max/min/sum/multiple of such, at most
:data:`MAX_ARGUMENTS`), and a decimal exponent is exact (``r**1.5`` is ``r**(3/2)``).

Work is bounded before it starts, by cost and not by shape (each limit a :class:`~thinlayer.errors.WorkLimitError`
naming it and why): the text's length (:data:`MAX_LENGTH`), the nesting depth, each exponent (an integer of
magnitude at most :data:`MAX_EXPONENT`), each number literal (an integer of at most :data:`MAX_DIGITS` digits; a
decimal of at most :data:`MAX_FLOAT_DIGITS` significant digits inside the normal double range, so ``1e999999`` and
``1e-999999`` are refused at the token), every exact intermediate number (at most :data:`MAX_BITS` bits: the size
of a power is estimated as ``bits(base) |exponent|`` before it is computed, so ``((9**1000)**1000)**30`` is refused
at once), and the expansion of the whole formula estimated from its tree (:func:`expression_cost`): total degree
in all symbols (:data:`MAX_TOTAL_DEGREE`), number of terms (:data:`MAX_TERMS`: ``(a1 + ... + an)**k`` has
``C(n + k - 1, k)`` terms, products multiply) and distinct parameter names (:data:`MAX_PARAMETERS`).

Examples
--------
>>> parse_expression("x_1**2/(2*R_1) + E*x_2**2")
E*x_2**2 + x_1**2/(2*R_1)
>>> parse_expression("x_1**2 + __import__('os')")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
thinlayer.parse.ExpressionError: cannot read ...: '__import__' at position 9 is not allowed: a name starts ...
"""
from __future__ import annotations

import math
import numbers
import re
import sys
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import mpmath

from . import symbols as S
from ._lazy import lazy_module
from .errors import InputError, InputTypeError, WorkLimitError, boundary, boundary_methods

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it

__all__ = ["Cost", "ExpressionError", "MAX_BITS", "MAX_DIGITS", "MAX_EXPONENT", "MAX_FLOAT_DIGITS", "MAX_LENGTH",  # noqa: F822
           "MAX_PARAMETERS", "MAX_TERMS", "MAX_TOTAL_DEGREE", "RADIUS", "as_expr", "check_cost", "expression_cost",
           "piecewise_linear_form",
           "parse_expression", "parse_number", "sympy_value"]

#: longest formula read (characters)
MAX_LENGTH = 10_000
#: deepest nesting of parentheses, signs and powers
MAX_DEPTH = 100
#: largest magnitude of an exponent
MAX_EXPONENT = 1000
#: most digits of an integer literal (about MAX_BITS bits)
MAX_DIGITS = 3000
#: most significant digits of a decimal literal (its precision)
MAX_FLOAT_DIGITS = 50
#: largest exact number, numerator or denominator, anywhere in a formula (bits): Python prints integers of at
#: most 4300 digits, and a power's size is estimated before it is computed
MAX_BITS = 10_000
#: largest total degree in all symbols after expansion (``x_1**1000`` is one term and cheap; (a + b)**1000 is not)
MAX_TOTAL_DEGREE = 1000
#: most terms after expansion: sympy expands 2000 terms in ~0.1 s; ``(x_1 + x_2 + a + b + c)**40`` has 135751
MAX_TERMS = 2000
#: most distinct parameter names (coordinates excluded); Punch.general(20) has 230 and its inner expansion
#: takes 4 s with a symbolic nu
MAX_PARAMETERS = 250

_ALLOWED = "numbers, the coordinates x_1, x_2, parameter names, + - * / ** and parentheses"
#: most arguments of one max(...) or min(...)
MAX_ARGUMENTS = 64
#: the piecewise-linear calls of a formula in x1, x2: max/min of linear forms (polyhedral tips)
_PIECEWISE_FUNCTIONS = {"max": "Max", "min": "Min"}  # name -> the sympy function's name (sympy loads lazily)
_ALLOWED_RADIAL = ("numbers, the radius r, parameter names, + - * / **, parentheses, sqrt(...), abs(...) and "
                   "max(...)/min(...) of linear forms in r")
#: the radius of a radial profile Phi(r) read with ``radial=True``
_LAZY_SYMBOLS = {"RADIUS": ("r", {"nonnegative": True})}  # RADIUS: a nonnegative Symbol, made on first use


def __getattr__(name: str) -> Any:
    """``RADIUS`` (the radius ``r`` of a radial profile), a sympy Symbol made on first use (PEP 562)."""
    if name in _LAZY_SYMBOLS:
        text, assumptions = _LAZY_SYMBOLS[name]
        return sp.Symbol(text, **assumptions)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


#: the calls a radial profile may make, and what they build
_RADIAL_FUNCTIONS = {"sqrt": "sqrt", "abs": "Abs"}  # name -> the sympy function's name
_TOKEN = re.compile(r"\s*(?:(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)|(?P<name>[A-Za-z][A-Za-z0-9_]*)"
                    r"|(?P<op>\*\*|[-+*/(),]))")


class ExpressionError(InputError):
    """A user's formula that the grammar does not accept."""


class FormulaTooLargeError(ExpressionError, WorkLimitError):
    """A formula whose numbers or expansion would exceed a documented limit (refused before the work)."""


_CAP = 10**15  # estimates saturate here (far above every limit)


@boundary_methods
@dataclass(frozen=True)
class Cost:
    """Upper bounds of what expanding a formula produces, read off its tree without expanding it.

    Attributes
    ----------
    degree : int
        Total degree in all symbols.
    terms : int
        Number of terms: a sum adds, a product multiplies, ``(t_1 + ... + t_n)**k`` has at most
        ``C(n + k - 1, k)`` (and at most the number of monomials of its degree in its symbols).
    bits : int
        Size of the largest exact coefficient (bits of numerator or denominator).
    """

    degree: int
    terms: int
    bits: int


def _bits(q: sp.Rational) -> int:
    return max(int(q.p).bit_length(), int(q.q).bit_length())


def _power_cost(base: Cost, k: int, nsym: int) -> Cost:
    k = abs(k)
    degree = min(base.degree * k, _CAP)
    if base.terms <= 1 or k == 0:
        terms = 1
    else:
        n = base.terms
        # C(n + k - 1, k): computed in logs first, so that a huge estimate costs nothing
        log_terms = math.lgamma(n + k) - math.lgamma(k + 1) - math.lgamma(n)
        terms = _CAP if log_terms > math.log(_CAP) else math.comb(n + k - 1, k)
        if nsym:  # at most the monomials of degree <= degree in nsym symbols
            log_mono = math.lgamma(degree + nsym + 1) - math.lgamma(nsym + 1) - math.lgamma(degree + 1)
            if log_mono < math.log(_CAP):
                terms = min(terms, math.comb(degree + nsym, nsym))
    bits = base.bits * k + (k * max(base.terms, 1).bit_length() if base.terms > 1 else 0)
    return Cost(degree, min(terms, _CAP), min(bits, _CAP))


@boundary
def expression_cost(expr: sp.Basic) -> Cost:
    """Estimate of the expansion of ``expr`` (:class:`Cost`), from its tree: linear in the tree's size.

    Examples
    --------
    >>> from sympy.abc import a, b, c, d
    >>> expression_cost((a + b + c + d)**1000).terms      # C(1003, 3)
    167668501
    """
    if not isinstance(expr, sp.Basic):
        raise InputTypeError(f"expression_cost needs a sympy expression, got {type(expr).__name__} (read a formula "
                             "with parse_expression)")
    memo: dict = {}

    def walk(e: sp.Basic) -> Cost:
        got = memo.get(e)
        if got is not None:
            return got
        if e.is_Number:
            out = Cost(0, 1, _bits(e) if e.is_Rational else 0)
        elif e.is_Symbol:
            out = Cost(1, 1, 0)
        elif isinstance(e, sp.Add):
            parts = [walk(a) for a in e.args]
            out = Cost(max(p.degree for p in parts), min(sum(p.terms for p in parts), _CAP),
                       max(p.bits for p in parts) + 1)
        elif isinstance(e, sp.Mul):
            parts = [walk(a) for a in e.args]
            terms = 1
            for p in parts:
                terms = min(terms * p.terms, _CAP)
            out = Cost(min(sum(p.degree for p in parts), _CAP), terms, min(sum(p.bits for p in parts), _CAP))
        elif isinstance(e, sp.Pow) and e.exp.is_Integer:
            out = _power_cost(walk(e.base), int(e.exp), len(e.base.free_symbols))
        elif isinstance(e, sp.Pow) and e.exp.is_Rational:  # a root: as costly as the power of its numerator
            out = _power_cost(walk(e.base), max(abs(int(e.exp.p)), 1), len(e.base.free_symbols))
        else:  # a function or any other node: one term, its arguments' cost
            parts = [walk(a) for a in e.args if isinstance(a, sp.Basic)]
            out = Cost(max([1 if e.free_symbols else 0] + [p.degree for p in parts]), 1,
                       max([0] + [p.bits for p in parts]))
        memo[e] = out
        return out

    return walk(expr)


@boundary
def check_cost(expr: sp.Basic, what: str = "formula", *, cost: Cost | None = None) -> sp.Basic:
    """``expr`` if expanding it stays within the limits (module docstring), else a one-line error naming the limit.

    Applied to every parsed formula, and by :class:`~thinlayer.Punch` to a sympy expression it is given.  Also
    checks that every float in it lies in the normal double range.
    """
    if not isinstance(expr, sp.Basic):
        raise InputTypeError(f"check_cost needs a sympy expression, got {type(expr).__name__} (read a formula with "
                             "parse_expression)")
    try:
        c = cost if cost is not None else expression_cost(expr)
    except RecursionError:
        raise FormulaTooLargeError(f"the {what} nests too deeply to be read") from None
    names = {q for q in expr.free_symbols if q.name not in _COORDINATE_NAMES}
    checks = (
        (c.bits, MAX_BITS, "holds an exact number of {} bits", "exact arithmetic and printing slow down with the "
                                                               "size; Python prints at most 4300 digits"),
        (c.degree, MAX_TOTAL_DEGREE, "has total degree {} in all symbols once expanded",
         "polynomial arithmetic grows with the degree"),
        (c.terms, MAX_TERMS, "expands to {} terms", "expanding and deriving grow with the number of terms "
                                                    "(2000 terms expand in about 0.1 s)"),
        (len(names), MAX_PARAMETERS, "has {} distinct parameter names", "the inner expansion of Punch.general(20), "
                                                                       "230 parameters, takes 4 s with a symbolic nu"),
    )
    for value, limit, label, why in checks:
        if value > limit:
            shown = f"more than {_CAP:.0e}" if value >= _CAP else f"{value}"
            raise FormulaTooLargeError(f"the {what} {label.format(shown)}, above the limit {limit}: {why}; give a "
                                       "smaller formula or numbers for some parameters")
    for f in expr.atoms(sp.Float):
        if float(f) != 0.0 and not (sys.float_info.min <= abs(float(f)) <= sys.float_info.max):
            raise FormulaTooLargeError(f"the {what} holds the number {sp.sstr(f, full_prec=False)}, outside the "
                                       f"double range {sys.float_info.min:.4g} <= |x| <= {sys.float_info.max:.4g}: "
                                       "rescale the units")
    return expr


_COORDINATE_NAMES = frozenset({"x_1", "x_2", "x1", "x2"})


def piecewise_linear_form(e: sp.Expr, coords: tuple) -> bool:
    """Whether ``e`` is a linear form in ``coords`` or a max/min/sum/multiple of such (the grammar's max/min rule).

    ``e`` is a sympy expression (a string is read by :func:`parse_expression` first), ``coords`` a tuple of sympy
    Symbols.
    """
    if not isinstance(e, sp.Basic):
        raise InputTypeError(f"piecewise_linear_form takes a sympy expression (parse a string with "
                             f"parse_expression first), got {type(e).__name__}")
    if not isinstance(coords, tuple) or not all(isinstance(c, sp.Symbol) for c in coords):
        raise InputTypeError(f"piecewise_linear_form takes a tuple of sympy Symbols as coords, got {coords!r:.60}")
    return _piecewise_linear(e, coords)


def _piecewise_linear(e: sp.Expr, coords: tuple | None = None) -> bool:
    """Whether ``e`` is a linear form in the coordinates x1, x2 (or the radius ``r`` when given as ``coords``) or a
    max/min/sum/multiple of such.
    """
    coords = (S.x1, S.x2) if coords is None else coords
    if not e.has(*coords):
        return True
    if e in coords:
        return True
    if isinstance(e, (sp.Max, sp.Min, sp.Add)):
        return all(_piecewise_linear(a, coords) for a in e.args)
    if isinstance(e, sp.Mul):
        moving = [f for f in e.args if f.has(*coords)]
        return len(moving) == 1 and _piecewise_linear(moving[0], coords)
    return False
_DECIMAL = re.compile(r"(\d*)\.?(\d*)(?:[eE]([+-]?\d+))?")


def _tokens(text: str) -> list[tuple[str, str, int]]:
    out = []
    pos = 0
    while pos < len(text):
        if text[pos:].strip() == "":
            break
        m = _TOKEN.match(text, pos)
        if m is None or m.end() == pos:
            start = pos + len(text[pos:]) - len(text[pos:].lstrip())
            bad = re.match(r"[A-Za-z0-9_]+|\S", text[start:]).group(0)
            hint = "write x**2 for a power" if bad == "^" else (
                "a name starts with a letter" if bad[0] == "_" else _ALLOWED + " are allowed")
            raise ExpressionError(f"{bad!r} at position {start} is not allowed: {hint}")
        kind = m.lastgroup
        out.append((kind, m.group(kind), m.start(kind)))
        pos = m.end()
    return out


class _Parser:
    def __init__(self, text: str, names: Mapping[str, sp.Symbol], allowed: frozenset[str] | None,
                 radial: bool = False):
        self.radial = radial
        self.toks = _tokens(text)
        self.i = 0
        self.names = dict(names)
        self.allowed = allowed
        self.depth = 0
        self.seen: set[str] = set()

    def peek(self) -> tuple[str, str, int] | None:
        return self.toks[self.i] if self.i < len(self.toks) else None

    def take(self, value: str | None = None) -> tuple[str, str, int]:
        tok = self.peek()
        if tok is None:
            raise ExpressionError("the formula ends too early" + (f": {value!r} expected" if value else ""))
        if value is not None and tok[1] != value:
            raise ExpressionError(f"{tok[1]!r} at position {tok[2]}: {value!r} expected")
        self.i += 1
        return tok

    def deeper(self) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise ExpressionError(f"the formula nests deeper than {MAX_DEPTH} levels")

    def expr(self) -> sp.Expr:
        self.deeper()
        terms = [self.term()]
        while (tok := self.peek()) is not None and tok[1] in "+-" and tok[0] == "op":
            self.take()
            rhs = self.term()
            terms.append(rhs if tok[1] == "+" else -rhs)
        self.depth -= 1
        return sp.Add(*terms)  # at once: adding one term at a time costs O(n^2)

    def term(self) -> sp.Expr:
        out = self.unary()
        while (tok := self.peek()) is not None and tok[1] in ("*", "/"):
            self.take()
            rhs = self.unary()
            if tok[1] == "/":
                if rhs == 0:
                    raise ExpressionError(f"division by zero at position {tok[2]}")
                out = out / rhs
            else:
                out = out * rhs
            if out.is_Rational and _bits(out) > MAX_BITS:  # each factor is bounded, so the product is cheap
                raise FormulaTooLargeError(f"the number at position {tok[2]} has {_bits(out)} bits, above the limit "
                                           f"{MAX_BITS}: exact arithmetic and printing slow down with the size")
        return out

    def unary(self) -> sp.Expr:
        tok = self.peek()
        if tok is not None and tok[0] == "op" and tok[1] in "+-":
            self.take()
            self.deeper()
            val = self.unary()
            self.depth -= 1
            return -val if tok[1] == "-" else val
        return self.power()

    def power(self) -> sp.Expr:
        base = self.atom()
        tok = self.peek()
        if tok is not None and tok[1] == "**":
            self.take()
            self.deeper()
            exp = self.unary()
            self.depth -= 1
            if self.radial and exp.is_Float:  # a decimal is exact: 1.5 is 3/2
                exp = sp.Rational(str(exp))
            if self.radial and exp.is_Rational and not exp.is_Integer:
                if abs(int(exp.p)) > MAX_EXPONENT or int(exp.q) > MAX_EXPONENT:
                    raise ExpressionError(f"the exponent {exp} after position {tok[2]} must be a rational p/q with "
                                          f"|p|, q at most {MAX_EXPONENT}")
                if base == 0 and exp < 0:
                    raise ExpressionError(f"0 to a negative power at position {tok[2]}")
                cost = _power_cost(expression_cost(base), int(exp.p), len(base.free_symbols))
                if cost.bits > MAX_BITS or cost.terms > MAX_TERMS or cost.degree > MAX_TOTAL_DEGREE:
                    check_cost(base**0, cost=cost, what=f"power at position {tok[2]}")
                return base**exp
            if not (exp.is_Integer and abs(int(exp)) <= MAX_EXPONENT):
                what = "an integer or a rational p/q" if self.radial else "an integer"
                raise ExpressionError(f"the exponent {exp} after position {tok[2]} must be {what} of magnitude "
                                      f"at most {MAX_EXPONENT}")
            if base == 0 and exp < 0:
                raise ExpressionError(f"0 to a negative power at position {tok[2]}")
            # the cost of the power, estimated before sympy computes it (an exact number's power is computed
            # at once: ((9**1000)**1000)**30 would be a number of 95 million bits)
            cost = _power_cost(expression_cost(base), int(exp), len(base.free_symbols))
            if cost.bits > MAX_BITS or cost.terms > MAX_TERMS or cost.degree > MAX_TOTAL_DEGREE:
                check_cost(base**0, cost=cost, what=f"power at position {tok[2]}")
            return base**exp
        return base

    def piecewise_linear(self, value: str, pos: int) -> sp.Expr:
        """``max(f_1, ..., f_m)`` / ``min(...)`` of linear forms in x1, x2, or in the radius r for a radial profile
        (the ``(`` is next).
        """
        self.take("(")
        self.deeper()
        args = [self.expr()]
        while (tok := self.peek()) is not None and tok[1] == ",":
            self.take()
            args.append(self.expr())
            if len(args) > MAX_ARGUMENTS:
                raise FormulaTooLargeError(f"{value}(...) at position {pos} has more than {MAX_ARGUMENTS} arguments")
        self.depth -= 1
        self.take(")")
        coords = (self.names["r"],) if self.radial else None
        for k, a in enumerate(args):
            if not _piecewise_linear(a, coords):
                what = "r (a*r + c" if self.radial else "x1, x2 (a*x1 + b*x2 + c"
                raise ExpressionError(f"argument {k + 1} of {value}(...) at position {pos}, {sp.sstr(a):.60}, is not "
                                      f"a linear form in {what}, or max/min of such)")
        # unevaluated: sympy's Max compares its arguments pairwise under assumptions (slow for 64 symbolic forms)
        return getattr(sp, _PIECEWISE_FUNCTIONS[value])(*args, evaluate=False)

    def atom(self) -> sp.Expr:
        kind, value, pos = self.take()
        if kind == "num":
            return _number(value, pos)
        if kind == "name":
            nxt = self.peek()
            if nxt is not None and nxt[1] == "(" and value in _PIECEWISE_FUNCTIONS:
                return self.piecewise_linear(value, pos)
            if nxt is not None and nxt[1] == "(" and self.radial and value in _RADIAL_FUNCTIONS:
                self.take("(")
                self.deeper()
                inner = self.expr()
                self.depth -= 1
                self.take(")")
                return getattr(sp, _RADIAL_FUNCTIONS[value])(inner)
            if nxt is not None and nxt[1] == "(" and self.radial:
                raise ExpressionError(f"{value}(...) at position {pos} is a call: a radial profile may call only "
                                      f"sqrt(...), abs(...), max(...) and min(...) ({_ALLOWED_RADIAL})")
            if nxt is not None and nxt[1] == "(":
                raise ExpressionError(f"{value}(...) at position {pos} is a function call, not a polynomial term: "
                                      f"a formula here is a polynomial with parameters ({_ALLOWED}), or max(...)/"
                                      "min(...) of linear forms")
            if value in self.names:
                return self.names[value]
            if self.radial and value in _COORDINATE_NAMES:
                raise ExpressionError(f"{value!r} at position {pos}: a radial profile is a formula in the radius r, "
                                      "not in the coordinates x_1, x_2")
            if self.allowed is not None and value not in self.allowed:
                valid = ", ".join(sorted(set(self.names) | self.allowed)) or "none"
                raise ExpressionError(f"unknown name {value!r} at position {pos}: the valid names are {valid}")
            self.seen.add(value)
            if len(self.seen) > MAX_PARAMETERS:  # refused while reading: a sum of 300 names costs 0.7 s to build
                raise FormulaTooLargeError(f"{value!r} at position {pos} is the parameter name number "
                                           f"{len(self.seen)}, above the limit {MAX_PARAMETERS}: the inner "
                                           "expansion of Punch.general(20), 230 parameters, takes 4 s with a "
                                           "symbolic nu")
            return sp.Symbol(value)
        if value == "(":
            inner = self.expr()
            self.take(")")
            return inner
        raise ExpressionError(f"{value!r} at position {pos} is not allowed here: {_ALLOWED} are allowed")


def _number(text: str, pos: int) -> sp.Number:
    """A number token, its size checked before it is built (``sp.Float("1e999999")`` takes a minute)."""
    if text.isdigit():
        digits = len(text.lstrip("0"))
        if digits > MAX_DIGITS:
            raise FormulaTooLargeError(f"the integer at position {pos} has {digits} digits, above the limit "
                                       f"{MAX_DIGITS}: exact arithmetic slows down with the size")
        return sp.Integer(int(text))
    m = _DECIMAL.fullmatch(text)
    mantissa = (m[1] + m[2]).strip("0")
    if len(mantissa) > MAX_FLOAT_DIGITS:
        raise FormulaTooLargeError(f"the number at position {pos} has {len(mantissa)} significant digits, above the "
                                   f"limit {MAX_FLOAT_DIGITS}")
    value = float(text)  # fast for any exponent: inf or 0 beyond the double range
    shown = text if len(text) <= 30 else text[:25] + "..."
    if not math.isfinite(value):
        raise ExpressionError(f"the number {shown} at position {pos} is beyond the double range (|x| <= "
                              f"{sys.float_info.max:.4g}): rescale the units")
    if mantissa and abs(value) < sys.float_info.min:
        raise ExpressionError(f"the number {shown} at position {pos} is below the double range "
                              f"({sys.float_info.min:.4g} <= |x| <= {sys.float_info.max:.4g}; write 0 for zero): "
                              "rescale the units")
    return sp.Float(text) if mantissa else sp.Float(0)


@boundary
def parse_expression(text: str, *, coordinates: bool = True, names: Iterable[str] | None = None,
                     what: str = "formula", radial: bool = False) -> sp.Expr:
    """A user's formula as a sympy expression, read by the restricted grammar (never evaluated as code).

    Parameters
    ----------
    text : str
        The formula, e.g. ``"x_1**2/(2*R_1) + x_2**2/(2*R_2)"``.
    coordinates : bool
        Whether ``x_1``, ``x_2`` (also written ``x1``, ``x2``) are the coordinates (1.1).
    names : iterable of str, optional
        The parameter names allowed; None allows any name.
    what : str
        What the formula is, for the error message (``"punch"``, ``"R_1"``, ...).
    radial : bool
        Read a radial profile ``Phi(r)``: the name ``r`` is :data:`RADIUS`, ``sqrt(...)``, ``abs(...)`` and rational
        exponents are allowed, the coordinates are not (module docstring).

    Returns
    -------
    sympy.Expr

    Raises
    ------
    ExpressionError
        The text is not a formula of the grammar; the message names the token and its position.
    """
    if not isinstance(text, str):
        raise InputTypeError(f"{what} must be a string here, got {type(text).__name__}")
    if len(text) > MAX_LENGTH:
        raise ExpressionError(f"cannot read the {what}: it has {len(text)} characters, more than {MAX_LENGTH}")
    coords = {"x_1": S.x1, "x_2": S.x2, "x1": S.x1, "x2": S.x2} if coordinates and not radial else {}
    if radial:
        coords = {"r": __getattr__("RADIUS")}
    allowed = None if names is None else frozenset(names)
    try:
        parser = _Parser(text, coords, allowed, radial)
        if not parser.toks:
            raise ExpressionError("it is empty")
        out = parser.expr()
        if parser.peek() is not None:
            tok = parser.peek()
            raise ExpressionError(f"{tok[1]!r} at position {tok[2]} is not allowed here: {_ALLOWED} are allowed")
        check_cost(out, what)
    except ExpressionError as exc:
        shown = text if len(text) <= 80 else text[:60] + " ... " + text[-15:]
        raise type(exc)(f"cannot read {shown!r}: {exc}") from None
    except RecursionError:
        raise ExpressionError(f"cannot read the {what}: it nests too deeply") from None
    return out


@boundary
def parse_number(value: Any, what: str) -> sp.Expr:
    """A number given as a string (``"3/10"``, ``"0.3"``, ``"1e-3"``), an int, a float or a sympy number.

    Exact where the input is exact: ``"3/10"`` and ``3`` give Rationals, ``"0.3"`` and ``0.3`` a Float.
    No names are allowed; the result must be finite.
    """
    if isinstance(value, bool):
        raise InputTypeError(f"{what} must be a number, got a bool")
    if isinstance(value, str):
        out = parse_expression(value, coordinates=False, names=(), what=what)
    else:
        out = as_expr(value, what)
    if not out.is_number or out.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        raise ExpressionError(f"{what} must be a finite number, got {value!r}")
    return out


@boundary
def sympy_value(value: Any, what: str, *, symbol: bool = False) -> sp.Basic:
    """An argument that takes a sympy expression: a sympy object as given, a number converted, a string read by
    the grammar (:func:`parse_expression`, never evaluated); ``symbol=True`` requires a sympy Symbol.

    sympy's own functions (``sp.diff``, ``sp.sinh``, ``.subs``) sympify a string, which runs it as Python: every
    method that hands an argument to them converts it here first.
    """
    if symbol:
        if isinstance(value, sp.Symbol):
            return value
        raise InputTypeError(f"{what} must be a sympy Symbol, got {value!r:.60} ({type(value).__name__})")
    if isinstance(value, sp.Basic):
        return value
    return as_expr(value, what)


@boundary
def as_expr(value: Any, what: str = "value") -> sp.Expr:
    """A sympy object from a number or a sympy object; a string goes through :func:`parse_expression`.

    The one place where non-string values are converted to sympy: floats, ints, Fractions, mpmath numbers.
    """
    if isinstance(value, str):
        return parse_expression(value, what=what)
    if isinstance(value, sp.Basic):
        return value
    if isinstance(value, bool):
        raise InputTypeError(f"{what} must be a number or a sympy expression, got a bool")
    if isinstance(value, numbers.Integral):
        return sp.Integer(int(value))
    if isinstance(value, Fraction):
        return sp.Rational(value.numerator, value.denominator)
    if isinstance(value, mpmath.mpf):
        return sp.Float(value, mpmath.mp.dps)
    if isinstance(value, numbers.Real):
        f = float(value)
        if not math.isfinite(f):
            raise InputError(f"{what} must be finite, got {value!r}")
        return sp.Float(f)
    raise InputTypeError(f"{what} must be a number, a string formula or a sympy expression, got {type(value).__name__}")
