"""Argument validators shared by every stage: one place for each rule.

Imports only :mod:`thinlayer.errors` (it is next to the bottom of the import table in
``tests/test_architecture.py``) and re-exports its exception classes.  Each check returns the normalised value
or raises an :class:`~thinlayer.errors.InputError`/:class:`~thinlayer.errors.InputTypeError` whose one-line
message names the argument and what would be valid.
"""
from __future__ import annotations

import math
import numbers
import re
from collections.abc import Callable
from fractions import Fraction
from typing import Any

import mpmath

from ._lazy import lazy_module, loaded_types
from .errors import (
    ComputationError,
    InputError,
    InputTypeError,
    NotDerivedError,
    ThinlayerError,
    WorkLimitError,
    boundary,
)

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it

__all__ = ["ComputationError", "InputError", "InputTypeError", "NotDerivedError", "ThinlayerError", "WorkLimitError",
           "array_size", "boundary", "check_array_size", "check_bounded", "check_choice", "check_int", "check_list",
           "check_order", "parse_nu",
           "positive"]



def check_order(n: Any, name: str) -> int:
    """A non-negative integer (an order of expansion, a moment index).

    >>> check_order(3, "order")
    3
    """
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        raise InputTypeError(f"{name} must be a non-negative integer, got {n!r}")
    if n < 0:
        raise InputError(f"{name} must be a non-negative integer, got {n}")
    return int(n)


def check_bounded(value: Any, name: str, limit: float, reason: str) -> Any:
    """``value`` if ``value <= limit``, else a one-line :class:`WorkLimitError` naming the input, the limit and why.

    Parameters
    ----------
    value : int or float
        The requested size (an order, a degree, a number of grid points, an estimate of bytes).
    name : str
        The input to change, as the user wrote it.
    limit : int or float
        The largest accepted value.
    reason : str
        Why the limit is there (with the measured cost of the largest accepted case).

    Examples
    --------
    >>> check_bounded(3, "order", 30, "symbolic coefficients")
    3
    """
    if not value <= limit:
        raise WorkLimitError(f"{name} = {value:g} exceeds the limit {limit:g}: {reason}"
                             if isinstance(value, float) else f"{name} = {value} exceeds the limit {limit}: {reason}")
    return value


def array_size(value: Any) -> int:
    """The number of values in an array-like, counted without converting it (a list of lists: its shape)."""
    size = getattr(value, "size", None)
    if isinstance(size, numbers.Integral) and hasattr(value, "shape"):
        return int(size)
    n = 1
    while isinstance(value, (list, tuple)):
        n *= len(value)
        if not value:
            break
        value = value[0]
    return n


def check_array_size(value: Any, name: str, limit: int, reason: str) -> Any:
    """``value`` if it holds at most ``limit`` values (counted before any conversion), else a WorkLimitError."""
    check_bounded(array_size(value), f"the number of values of {name}", limit, reason)
    return value


def check_int(value: Any, name: str, lo: int) -> int:
    """An integer ``>= lo`` (a count of points, modes, iterations)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < lo:
        raise InputError(f"{name} must be an integer >= {lo}, got {value!r}")
    return int(value)


def positive(value: Any, name: str) -> float:
    """A finite positive real number, as a float.

    >>> positive(2, "H")
    2.0
    """
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, mpmath.mpf, *loaded_types("sympy", "Number"))):
        raise InputTypeError(f"{name} must be a positive real number, got {value!r} ({type(value).__name__})")
    v = float(value)
    if not (math.isfinite(v) and v > 0):
        raise InputError(f"{name} must be a finite positive number, got {value!r}")
    return v


def work_of_adhesion(value: Any) -> float:
    """A work of adhesion: a finite number >= 0, as a float (the adhesion stages and solvers, (J.1)).

    >>> work_of_adhesion(0.5)
    0.5
    """
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(f"work_of_adhesion must be a finite number >= 0, got {value!r}") from None
    if not (math.isfinite(v) and v >= 0):
        raise InputError(f"work_of_adhesion must be a finite number >= 0, got {value!r}")
    return v


def positive_radii(radius: Any) -> Any:
    """Contact radii: a finite positive number or array, as a float numpy array."""
    import numpy as np

    try:
        a = np.asarray(radius, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"radius must be a positive number or array, got {radius!r}") from None
    if not np.all(np.isfinite(a)) or np.any(a <= 0):
        raise InputError("radius must be finite and > 0")
    return a


def check_history(times: Any, values: Any, name: str, min_size: int = 1) -> tuple[Any, Any]:
    """A load history: ``times`` strictly increasing and ``values`` (``name``: depths, forces), finite, 1-d, of one
    length (at least ``min_size``), as new float numpy arrays (the hereditary laws and the time-stepping solver).
    """
    import numpy as np

    try:
        t = np.array(times, dtype=float)
        v = np.array(values, dtype=float)
    except (TypeError, ValueError):
        raise InputTypeError(f"times and {name} must be sequences of numbers") from None
    if t.ndim != 1 or v.shape != t.shape or t.size < min_size:
        length = "of one length" if min_size <= 1 else f"of one length >= {min_size}"
        sep = " and " if min_size <= 1 else ", "
        raise InputError(f"times and {name} must be 1-d{sep}{length}, got shapes {t.shape} and {v.shape}")
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(v))):
        raise InputError(f"times and {name} must be finite (no nan or inf)")
    if np.any(np.diff(t) <= 0):
        raise InputError("times must be strictly increasing")
    return t, v


def check_choice(value: str, allowed: tuple[str, ...], name: str) -> str:
    """One of a fixed set of strings."""
    if value not in allowed:
        raise InputError(f"{name} must be one of {allowed}, got {value!r}")
    return value


def check_list(values: Any, check: Callable[[Any], Any], name: str) -> tuple:
    """A non-empty sequence (or a single value), each checked, duplicates dropped in order."""
    if isinstance(values, (numbers.Real, str)):
        values = (values,)
    try:
        vals = tuple(values)
    except TypeError as exc:
        raise InputTypeError(f"{name} must be a sequence of numbers, got {values!r}") from exc
    if not vals:
        raise InputError(f"{name} is empty: give at least one value")
    out: list = []
    for v in vals:
        c = check(v)
        if c not in out:
            out.append(c)
    return tuple(out)


def _exact_binary(x: float | mpmath.mpf) -> sp.Rational:
    """The exact rational value of a binary float."""
    if isinstance(x, mpmath.mpf):
        sign, man, exp, _ = x._mpf_
        return sp.Rational(int(man) * 2 ** max(exp, 0), 2 ** max(-exp, 0)) * (-1 if sign else 1)
    return sp.Rational(*float(x).as_integer_ratio())


#: a Poisson ratio written as text: a decimal number (exponent allowed) or a fraction of two integers
_NU_TEXT = re.compile(r"(?P<sign>[+-]?)(?P<int>\d*)(?:\.(?P<frac>\d*))?(?:[eE](?P<exp>[+-]?\d+))?"
                      r"(?:\s*/\s*(?P<den>[+-]?\d+))?")
#: the most digits of an exact Poisson ratio written as text (numerator or denominator, exponent included; the
#: derivation files allow 6 too): the exact coefficients grow with the digits -- order 200 took 2.7 s with 3/10,
#: 7 s with 6 digits, 12 s with 10 and 57 s with 30 (2 cores, load 4)
MAX_NU_DIGITS = 6


def as_fraction(x: Any) -> Fraction:
    """A rational, a float or an mpmath float as the exact Fraction it is (no sympy needed for a float)."""
    if isinstance(x, mpmath.mpf):
        sign, man, exp, _ = x._mpf_
        return Fraction(-int(man) if sign else int(man)) * Fraction(2) ** int(exp)
    if isinstance(x, float):
        return Fraction(*x.as_integer_ratio())
    if isinstance(x, (int, Fraction)):
        return Fraction(x)
    if getattr(x, "is_Rational", False):  # a sympy Rational or Integer
        return Fraction(int(x.p), int(x.q))
    return Fraction(*float(x).as_integer_ratio())  # a sympy Float (17 digits of a float)


def _exact_nu(text: str, example: str) -> sp.Rational:
    """The exact rational of a Poisson ratio written as text, its size checked before any big number is built.

    ``Fraction("1e-99999999")`` builds ``10**99999999`` (minutes); here the digits, exponent included, are counted
    from the text first.
    """
    t = text.strip()
    if len(t) > 100:
        raise WorkLimitError(f"nu={t[:30] + ' ...'!r} has {len(t)} characters, more than 100: give a float (e.g. 0.3) "
                             "or a short fraction (e.g. '3/10')")
    m = _NU_TEXT.fullmatch(t)
    if m is None or not (m["int"] or m["frac"]):
        shown = t if len(t) <= 40 else t[:30] + " ..."
        raise InputError(f"nu={shown!r} is not a number; give e.g. {example}")
    digits = len((m["int"] or "").lstrip("0")) + len(m["frac"] or "")
    exp = int(m["exp"]) if m["exp"] and len(m["exp"].lstrip("+-")) <= 6 else (0 if not m["exp"] else 10**6)
    size = max(digits + max(exp, 0), len(m["frac"] or "") - min(exp, 0), len((m["den"] or "").lstrip("+-0")))
    if size > MAX_NU_DIGITS:
        shown = "more than a million" if size >= 10**6 else f"about {size}"
        raise WorkLimitError(f"nu={t if len(t) <= 40 else t[:30] + ' ...'!r} has {shown} digits as an exact "
                             f"fraction, above the limit {MAX_NU_DIGITS}: exact coefficients grow with its digits; "
                             "give a float (e.g. 0.3) or a short fraction (e.g. '3/10')")
    try:
        return sp.Rational(Fraction(t))
    except (TypeError, ValueError, ZeroDivisionError) as exc:
        raise InputError(f"nu={t!r} is not a number; give e.g. {example}") from exc


def parse_nu(
    nu: Any,
    *,
    floats: str = "mpf",
    lower: Any = -1,
    upper: Any = Fraction(1, 2),
    upper_closed: bool = False,
    symbols: bool = True,
    example: str = "'3/10', 0.3",
    range_hint: str = "",
) -> Any:
    """The one Poisson-ratio parser: a Symbol, an exact Rational or a float, range-checked.

    Parameters
    ----------
    nu : Symbol, int, Fraction, sympy Rational, str, float or mpmath.mpf
        The Poisson ratio as given.  A string must be a plain number (``"3/10"``, ``"0.3"``).
    floats : {"mpf", "exact", "Float", "float"}
        What a float becomes: an mpmath float, its exact binary rational, a 17-digit sympy Float
        (0.5 becomes exactly 1/2) or a Python float.
    lower, upper : Any
        number
        The open lower and the upper end of the admissible range.
    upper_closed : bool
        Whether ``nu = upper`` is admissible.
    symbols : bool
        Whether a sympy Symbol is returned as it is (else it is an error).
    example : str
        Valid values quoted in the error message.
    range_hint : str
        Why the range is what it is, appended to the out-of-range message.

    Returns
    -------
    Symbol, Rational, mpmath.mpf, Float or float

    Examples
    --------
    >>> parse_nu("3/10"), parse_nu(0.5, floats="Float", upper_closed=True)
    (3/10, 1/2)
    """
    # the sympy classes, if sympy is loaded: a sympy object cannot exist otherwise (a float nu needs no sympy)
    Symbol, Basic, Rational, Float = loaded_types("sympy", "Symbol", "Basic", "Rational", "Float") or ((),) * 4
    if isinstance(nu, Symbol):
        if not symbols:
            raise InputTypeError(f"a numeric Poisson ratio is needed here (e.g. nu={example.split(',')[-1].strip()}), "
                            f"got the symbol {nu}")
        return nu
    if isinstance(nu, bool):
        raise InputTypeError("nu must be a number, got a bool")
    if isinstance(nu, Basic) and not nu.is_number:
        raise InputTypeError(f"nu must be None, a Symbol or a number, got the expression {nu!r}")
    if isinstance(nu, (Rational, numbers.Integral, Fraction)):
        val: Any = sp.Rational(nu)
    elif isinstance(nu, str):
        val = _exact_nu(nu, example)
    elif isinstance(nu, (float, Float, mpmath.mpf, numbers.Real)):
        f = mpmath.mpf(str(nu)) if isinstance(nu, Float) else mpmath.mpf(nu)
        if not mpmath.isfinite(f):
            raise InputError(f"nu must be finite, got {nu!r}")
        if floats == "exact":
            val = _exact_binary(f)
        elif floats == "Float":
            val = sp.Rational(1, 2) if f == 0.5 else sp.Float(float(f), 17)
        elif floats == "float":
            val = float(f)
        else:
            val = f
    else:
        raise InputTypeError(f"nu must be a Symbol, a rational or a float, got {type(nu).__name__}")
    lo, hi = as_fraction(lower), as_fraction(upper)  # exact, like the value: a binary float is an exact rational
    v = as_fraction(val)
    inside = (lo < v <= hi) if upper_closed else (lo < v < hi)
    if not inside:
        rel = "<=" if upper_closed else "<"
        raise InputError(f"Poisson ratio nu={nu!r} is outside the admissible range {lo} < nu {rel} {hi}"
                         + (f": {range_hint}" if range_hint else ""))
    return val

