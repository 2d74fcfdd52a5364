r"""Units of a derivation file's ``[units]`` table: a small grammar, their dimensions and their LaTeX.

A unit is parsed by a tokenizer and a recursive descent (nothing is evaluated)::

    unit     := product ['/' product]
    product  := factor {('*' | '.' | ' ') factor}
    factor   := primary ['^' integer]
    primary  := symbol | '(' unit ')'
    integer  := ['-' | '+'] digit            (1 to 9, not 0)
    symbol   := [prefix] base

with the SI bases :data:`BASES` (``m``, ``g``, ``s``, ``N``, ``Pa``) and the prefixes :data:`PREFIXES`
(``G M k c m u µ n p``; ``u`` and ``µ`` are both micro): ``mm``, ``um``, ``µm``, ``nm``, ``kg``, ``ms``,
``mN``, ``µN``, ``nN``, ``kPa``, ``MPa``, ``GPa``, ``N/mm^2``, ``kg m/s^2``, ``kg/(m*s^2)``, ``N.m^-2``.
Spaces next to an operator are ignored.  Equal symbols are merged (``m m`` is ``m^2``) and the unit is
kept as a product of symbols with integer exponents, so that a power of it combines the exponents
(:meth:`Unit.power`: the area of ``m^2`` is ``\mathrm{m}^{4}``, never ``\mathrm{m}^{2}^{2}``).

Its dimension (mass, length, time) and its size (a power of ten of kg, m, s) let the derivation file's
schema check that a length is a length, a force a force and a stress a stress, and that the three are
one consistent system (stress = force / length^2), so that no number of the report carries a wrong unit.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["BASES", "PREFIXES", "Unit", "UnitError", "UnitLatex", "dimension_name", "parse_unit", "unit_latex",
           "unit_power"]


class UnitError(ValueError):
    """A unit outside the grammar of :mod:`thinlayer.export.units` (the message says where and why)."""


#: base symbol -> (dimension (kg, m, s), power of ten of its size in kg, m, s)
BASES: dict[str, tuple[tuple[int, int, int], int]] = {
    "m": ((0, 1, 0), 0), "g": ((1, 0, 0), -3), "s": ((0, 0, 1), 0), "N": ((1, 1, -2), 0), "Pa": ((1, -1, -2), 0)}
#: prefix -> power of ten (``u``, the micro sign U+00B5 and the Greek mu U+03BC are all micro)
PREFIXES: dict[str, int] = {"G": 9, "M": 6, "k": 3, "c": -2, "m": -3, "u": -6, "\u00b5": -6, "\u03bc": -6, "n": -9,
                            "p": -12}
#: the longest unit text and the most factors
MAX_TEXT, MAX_FACTORS = 40, 8
#: what a unit is, for the errors
FORMS = ("a unit is SI symbols (m, g, s, N, Pa) with an optional prefix (G M k c m u/\u00b5 n p), joined by '*', "
         "'.' or spaces, with at most one '/', integer powers '^2' or '^-1' and parentheses, e.g. 'mm', 'um', "
         "'MPa', 'N/mm^2', 'kg m/s^2'")
_MICRO = "\u00b5"
_TOKEN = re.compile(r"(?P<sym>[A-Za-z\u00b5\u03bc]+)|(?P<int>[0-9]+)|(?P<op>[*./^()+-])|(?P<space>\s+)")


def _symbol(word: str) -> tuple[str, str]:
    """``(prefix, base)`` of a symbol: the whole word if it is a base, else a prefix and a base."""
    if word in BASES:
        return "", word
    if word[:1] in PREFIXES and word[1:] in BASES:
        return (_MICRO if PREFIXES[word[0]] == -6 else word[0]), word[1:]
    raise UnitError(f"unknown unit symbol {word!r}")


def _tokens(text: str) -> list[tuple[str, str]]:
    out, pos = [], 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:
            raise UnitError(f"the character {text[pos]!r} is not allowed")
        kind = m.lastgroup or ""
        out.append((kind, " " if kind == "space" else m.group()))
        pos = m.end()
    # a space is a product only between two operands: next to an operator, or at an end, it is nothing
    keep = []
    for k, (kind, val) in enumerate(out):
        if kind == "space":
            before = out[k - 1][1] if k else "^"
            after = out[k + 1][1] if k + 1 < len(out) else ")"
            if before in "*./^(+-" or after in "*./^)":
                continue
            val = "*"
            kind = "op"
        keep.append((kind, val))
    return keep


class _Parser:
    """Recursive descent over the tokens; each rule returns ``{(prefix, base): exponent}``."""

    def __init__(self, tokens: list[tuple[str, str]]):
        self.tokens, self.pos, self.depth = tokens, 0, 0

    def peek(self) -> str | None:
        return self.tokens[self.pos][1] if self.pos < len(self.tokens) else None

    def take(self) -> tuple[str, str]:
        if self.pos >= len(self.tokens):
            raise UnitError("it ends too early")
        tok = self.tokens[self.pos]
        self.pos += 1
        return tok

    def unit(self) -> dict:
        out = self.product()
        if self.peek() == "/":
            self.take()
            out = _combine(out, self.product(), -1)
            if self.peek() == "/":
                raise UnitError("a second '/' is ambiguous: write N/(m s) or N m^-1 s^-1")
        return out

    def product(self) -> dict:
        out = self.factor()
        while self.peek() in ("*", "."):
            self.take()
            out = _combine(out, self.factor(), 1)
        return out

    def factor(self) -> dict:
        base = self.primary()
        if self.peek() != "^":
            return base
        self.take()
        kind, val = self.take()
        sign = 1
        if val in "+-" and kind == "op":
            sign = -1 if val == "-" else 1
            kind, val = self.take()
        if kind != "int" or not 1 <= int(val) <= 9:
            raise UnitError(f"after '^' comes an integer from 1 to 9 (or -1 to -9), not {val!r}")
        return {k: sign * int(val) * e for k, e in base.items()}

    def primary(self) -> dict:
        kind, val = self.take()
        if kind == "sym":
            return {_symbol(val): 1}
        if val == "(":
            self.depth += 1
            if self.depth > 4:
                raise UnitError("parentheses nest too deeply")
            inner = self.unit()
            if self.peek() != ")":
                raise UnitError("a '(' is not closed")
            self.take()
            self.depth -= 1
            return inner
        raise UnitError(f"expected a unit symbol or '(', got {val!r}")


def _combine(a: dict, b: dict, sign: int) -> dict:
    out = dict(a)
    for k, e in b.items():
        out[k] = out.get(k, 0) + sign * e
    return out


def _factor_latex(prefix: str, base: str, exponent: int) -> str:
    body = (r"\mu\mathrm{" + base + "}") if prefix == _MICRO else rf"\mathrm{{{prefix}{base}}}"
    if exponent == 1:
        return body
    return (f"{{{body}}}" if prefix == _MICRO else body) + f"^{{{exponent}}}"


def _factor_text(prefix: str, base: str, exponent: int) -> str:
    return f"{prefix}{base}" + ("" if exponent == 1 else f"^{exponent}")


@dataclass(frozen=True)
class Unit:
    r"""A parsed unit: a product of symbols with integer exponents (:func:`parse_unit`).

    Attributes
    ----------
    factors : tuple
        ``((prefix, base, exponent), ...)`` in the order of first appearance, no zero exponent.
    """

    factors: tuple[tuple[str, str, int], ...]

    @property
    def dimension(self) -> tuple[int, int, int]:
        """Exponents of kg, m and s."""
        d = [0, 0, 0]
        for _, base, e in self.factors:
            for i, x in enumerate(BASES[base][0]):
                d[i] += e * x
        return d[0], d[1], d[2]

    @property
    def decade(self) -> int:
        """Its size as a power of ten of the SI unit of its dimension (``mm``: -3, ``MPa``: 6, ``g``: -3)."""
        return sum(e * (PREFIXES.get(p, 0) + BASES[b][1]) for p, b, e in self.factors)

    def power(self, n: int) -> Unit:
        """The unit to the integer power ``n`` (exponents multiplied: never a superscript on a superscript)."""
        return Unit(tuple((p, b, e * n) for p, b, e in self.factors))

    def text(self) -> str:
        """The unit in the grammar's normal form, e.g. ``N/mm^2``, ``kg m/s^2``, ``s^-1``."""
        num = [f for f in self.factors if f[2] > 0]
        den = [(p, b, -e) for p, b, e in self.factors if e < 0]
        if not num:
            return " ".join(_factor_text(*f) for f in self.factors)
        top = " ".join(_factor_text(*f) for f in num)
        if not den:
            return top
        bottom = " ".join(_factor_text(*f) for f in den)
        return f"{top}/" + (f"({bottom})" if len(den) > 1 else bottom)

    def latex(self, n: int = 1) -> str:
        r"""The unit (to the power ``n``) in math mode: ``\mathrm{N}/\mathrm{mm}^{2}``, ``\mu\mathrm{m}``.

        Factors are joined by a thin space; a denominator of several factors is set in parentheses,
        a unit with no positive exponent as a product of negative powers.
        """
        u = self.power(n) if n != 1 else self
        num = [f for f in u.factors if f[2] > 0]
        den = [(p, b, -e) for p, b, e in u.factors if e < 0]
        if not num:
            return r"\,".join(_factor_latex(*f) for f in u.factors)
        top = r"\,".join(_factor_latex(*f) for f in num)
        if not den:
            return top
        bottom = r"\,".join(_factor_latex(*f) for f in den)
        return f"{top}/" + (f"({bottom})" if len(den) > 1 else bottom)


def parse_unit(text: object) -> Unit:
    r"""Parse a unit by the grammar of :mod:`thinlayer.export.units` (never evaluated).

    Parameters
    ----------
    text : object
        The user's unit, a string of at most :data:`MAX_TEXT` characters.

    Returns
    -------
    Unit
        Equal symbols merged, in the order of first appearance.

    Raises
    ------
    UnitError
        one line saying what is wrong; the caller adds :data:`FORMS`.

    Examples
    --------
    >>> parse_unit("N/mm^2").latex(), parse_unit("m^2").latex(2), parse_unit("um").latex(2)
    ('\\mathrm{N}/\\mathrm{mm}^{2}', '\\mathrm{m}^{4}', '{\\mu\\mathrm{m}}^{2}')
    """
    if not isinstance(text, str):
        raise UnitError(f"expected a string, got {type(text).__name__}")
    if not text.strip() or len(text) > MAX_TEXT:
        raise UnitError(f"expected 1 to {MAX_TEXT} characters, got {len(text)}")
    parser = _Parser(_tokens(text.strip()))
    raw = parser.unit()
    if parser.pos != len(parser.tokens):
        raise UnitError(f"unexpected {parser.peek()!r}")
    factors = tuple((p, b, e) for (p, b), e in raw.items() if e != 0)
    if not factors:
        raise UnitError("the symbols cancel: that is a pure number, not a unit")
    if len(factors) > MAX_FACTORS:
        raise UnitError(f"at most {MAX_FACTORS} different symbols")
    return Unit(factors)


def unit_latex(text: str) -> str:
    r"""A unit (:func:`parse_unit`) as math: ``\mathrm{N}/\mathrm{mm}^{2}``.

    >>> unit_latex("N/mm^2"), unit_latex("kg m")
    ('\\mathrm{N}/\\mathrm{mm}^{2}', '\\mathrm{kg}\\,\\mathrm{m}')
    """
    return parse_unit(text).latex()


class UnitLatex(str):
    r"""The LaTeX of a parsed unit (a ``str``, as the report prints it) that can also raise it to a power.

    >>> u = UnitLatex(parse_unit("mm")); u, u.power(2)
    ('\\mathrm{mm}', '\\mathrm{mm}^{2}')
    """

    unit: Unit

    def __new__(cls, unit: Unit) -> UnitLatex:
        obj = super().__new__(cls, unit.latex())
        obj.unit = unit
        return obj

    def power(self, n: int) -> str:
        """The LaTeX of the unit to the power ``n``, exponents combined."""
        return self.unit.latex(n)


def unit_power(unit: str, n: int) -> str:
    r"""The LaTeX of a unit of ``[units]`` to the power ``n``: exponents combined for a parsed unit
    (:class:`UnitLatex`); any other LaTeX string is set in parentheses when it is more than one symbol.

    >>> unit_power(UnitLatex(parse_unit("N/m^2")), 2), unit_power(r"\mathrm{m}", 3)
    ('\\mathrm{N}^{2}/\\mathrm{m}^{4}', '\\mathrm{m}^{3}')
    """
    if n == 1:
        return str(unit)
    if isinstance(unit, UnitLatex):
        return unit.power(n)
    if re.fullmatch(r"\\mathrm\{[A-Za-z]+\}", unit):
        return f"{unit}^{{{n}}}"
    return rf"\left({unit}\right)^{{{n}}}"


_NAMES = {(0, 1, 0): "a length", (0, 2, 0): "an area", (0, 3, 0): "a volume", (1, 1, -2): "a force",
          (1, -1, -2): "a stress", (1, 0, 0): "a mass", (0, 0, 1): "a time", (1, 2, -2): "an energy"}


def dimension_name(dim: tuple[int, int, int]) -> str:
    """``"a length"``, ``"a force"``, ... or the dimension in kg, m and s."""
    if dim in _NAMES:
        return _NAMES[dim]
    text = " ".join(f"{s}^{e}" if e != 1 else s for s, e in zip(("kg", "m", "s"), dim) if e)
    return f"of dimension {text}" if text else "a pure number"
