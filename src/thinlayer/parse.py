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
and its position.  Work is bounded before it starts: the text's length, the nesting depth and each
exponent (an integer of magnitude at most :data:`MAX_EXPONENT`).

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
from collections.abc import Iterable, Mapping
from fractions import Fraction
from typing import Any

import mpmath
import sympy as sp

from . import symbols as S

__all__ = ["ExpressionError", "MAX_EXPONENT", "MAX_LENGTH", "as_expr", "parse_expression", "parse_number"]

#: longest formula read (characters)
MAX_LENGTH = 10_000
#: deepest nesting of parentheses, signs and powers
MAX_DEPTH = 100
#: largest magnitude of an exponent
MAX_EXPONENT = 1000

_ALLOWED = "numbers, the coordinates x_1, x_2, parameter names, + - * / ** and parentheses"
_TOKEN = re.compile(r"\s*(?:(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)|(?P<name>[A-Za-z][A-Za-z0-9_]*)"
                    r"|(?P<op>\*\*|[-+*/()]))")


class ExpressionError(ValueError):
    """A user's formula that the grammar does not accept."""


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
    def __init__(self, text: str, names: Mapping[str, sp.Symbol], allowed: frozenset[str] | None):
        self.toks = _tokens(text)
        self.i = 0
        self.names = dict(names)
        self.allowed = allowed
        self.depth = 0

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
        out = self.term()
        while (tok := self.peek()) is not None and tok[1] in "+-" and tok[0] == "op":
            self.take()
            rhs = self.term()
            out = out + rhs if tok[1] == "+" else out - rhs
        self.depth -= 1
        return out

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
            if not (exp.is_Integer and abs(int(exp)) <= MAX_EXPONENT):
                raise ExpressionError(f"the exponent {exp} after position {tok[2]} must be an integer of magnitude "
                                      f"at most {MAX_EXPONENT}")
            if base == 0 and exp < 0:
                raise ExpressionError(f"0 to a negative power at position {tok[2]}")
            return base**exp
        return base

    def atom(self) -> sp.Expr:
        kind, value, pos = self.take()
        if kind == "num":
            return sp.Integer(int(value)) if value.isdigit() else sp.Float(value)
        if kind == "name":
            nxt = self.peek()
            if nxt is not None and nxt[1] == "(":
                raise ExpressionError(f"{value}(...) at position {pos} is a function call, not a polynomial term: "
                                      f"a formula here is a polynomial with parameters ({_ALLOWED})")
            if value in self.names:
                return self.names[value]
            if self.allowed is not None and value not in self.allowed:
                valid = ", ".join(sorted(set(self.names) | self.allowed)) or "none"
                raise ExpressionError(f"unknown name {value!r} at position {pos}: the valid names are {valid}")
            return sp.Symbol(value)
        if value == "(":
            inner = self.expr()
            self.take(")")
            return inner
        raise ExpressionError(f"{value!r} at position {pos} is not allowed here: {_ALLOWED} are allowed")


def parse_expression(text: str, *, coordinates: bool = True, names: Iterable[str] | None = None,
                     what: str = "formula") -> sp.Expr:
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

    Returns
    -------
    sympy.Expr

    Raises
    ------
    ExpressionError
        The text is not a formula of the grammar; the message names the token and its position.
    """
    if not isinstance(text, str):
        raise TypeError(f"{what} must be a string here, got {type(text).__name__}")
    if len(text) > MAX_LENGTH:
        raise ExpressionError(f"cannot read the {what}: it has {len(text)} characters, more than {MAX_LENGTH}")
    coords = {"x_1": S.x1, "x_2": S.x2, "x1": S.x1, "x2": S.x2} if coordinates else {}
    allowed = None if names is None else frozenset(names)
    try:
        parser = _Parser(text, coords, allowed)
        if not parser.toks:
            raise ExpressionError("it is empty")
        out = parser.expr()
        if parser.peek() is not None:
            tok = parser.peek()
            raise ExpressionError(f"{tok[1]!r} at position {tok[2]} is not allowed here: {_ALLOWED} are allowed")
    except ExpressionError as exc:
        shown = text if len(text) <= 80 else text[:60] + " ... " + text[-15:]
        raise ExpressionError(f"cannot read {shown!r}: {exc}") from None
    except RecursionError:
        raise ExpressionError(f"cannot read the {what}: it nests too deeply") from None
    return out


def parse_number(value: Any, what: str) -> sp.Expr:
    """A number given as a string (``"3/10"``, ``"0.3"``, ``"1e-3"``), an int, a float or a sympy number.

    Exact where the input is exact: ``"3/10"`` and ``3`` give Rationals, ``"0.3"`` and ``0.3`` a Float.
    No names are allowed; the result must be finite.
    """
    if isinstance(value, bool):
        raise TypeError(f"{what} must be a number, got a bool")
    if isinstance(value, str):
        out = parse_expression(value, coordinates=False, names=(), what=what)
    else:
        out = as_expr(value, what)
    if not out.is_number or out.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        raise ExpressionError(f"{what} must be a finite number, got {value!r}")
    return out


def as_expr(value: Any, what: str = "value") -> sp.Expr:
    """A sympy object from a number or a sympy object; a string goes through :func:`parse_expression`.

    The one place where non-string values are converted to sympy: floats, ints, Fractions, mpmath numbers.
    """
    if isinstance(value, str):
        return parse_expression(value, what=what)
    if isinstance(value, sp.Basic):
        return value
    if isinstance(value, bool):
        raise TypeError(f"{what} must be a number or a sympy expression, got a bool")
    if isinstance(value, numbers.Integral):
        return sp.Integer(int(value))
    if isinstance(value, Fraction):
        return sp.Rational(value.numerator, value.denominator)
    if isinstance(value, mpmath.mpf):
        return sp.Float(value, mpmath.mp.dps)
    if isinstance(value, numbers.Real):
        f = float(value)
        if not math.isfinite(f):
            raise ValueError(f"{what} must be finite, got {value!r}")
        return sp.Float(f)
    raise TypeError(f"{what} must be a number, a string formula or a sympy expression, got {type(value).__name__}")
