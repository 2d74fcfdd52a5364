"""Immutable result objects: every stage of the derivation returns one.

:class:`Result` is the one protocol they share: the paper's ``equation`` they reproduce, their
``latex()`` and their own ``text_lines()`` (what ``print`` shows, through
:class:`~thinlayer.display.RichDisplay`).  A :class:`SymbolicResult` also turns into numbers with
``lambdify()``, which the code generators (:mod:`thinlayer.export.codegen`) read the same way.

A result knows the paper's equation number it reproduces, prints itself as LaTeX and
turns into numeric functions through :func:`checked_lambdify`, which refuses any
expression with a free symbol that is not among the named arguments.
"""
from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Protocol, runtime_checkable

from ._lazy import lazy_function, lazy_module
from .errors import InputError, InputTypeError, boundary

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it
normal_latex = lazy_function("thinlayer.normal", "normal_latex")  # the printers subclass sympy's

BACKENDS = ("numpy", "mpmath", "math", "sympy")


@runtime_checkable
class Result(Protocol):
    """What every result of a stage offers: its equation, its LaTeX and its text."""

    equation: str

    def latex(self) -> str:
        """The result as tagged LaTeX (the equation number in a tag)."""
        ...

    def text_lines(self) -> list[str]:
        """The lines ``print(result)`` shows."""
        ...


@runtime_checkable
class SymbolicResult(Result, Protocol):
    """A result whose formulas become numeric functions (and generated code)."""

    def lambdify(self, *args: Any, **kwargs: Any) -> Callable:
        """The formulas as a numeric function (:func:`checked_lambdify`)."""
        ...

    def codegen_expressions(self) -> tuple[Sequence[sp.Symbol], Mapping[str, sp.Expr]]:
        """The argument symbols in call order and ``{output name: expression}``, for generated code."""
        ...


class MissingArgumentError(InputError):
    """An expression has free symbols that are not among the lambdify arguments."""


def _as_symbols(args: Sequence[sp.Symbol] | sp.Symbol) -> tuple[sp.Symbol, ...]:
    if isinstance(args, sp.Basic):
        args = (args,)
    args = tuple(args)
    for a in args:
        if not isinstance(a, sp.Symbol):
            raise InputTypeError(f"lambdify arguments must be sympy Symbols, got {a!r} ({type(a).__name__})")
    if len(set(args)) != len(args):
        raise InputError(f"lambdify arguments repeat a symbol: {args}")
    return args


@boundary
def checked_lambdify(
    args: Sequence[sp.Symbol] | sp.Symbol,
    exprs: sp.Expr | Iterable[sp.Expr],
    backend: str = "numpy",
) -> Callable:
    """``sympy.lambdify(args, exprs)`` that first checks every free symbol is an argument.

    Parameters
    ----------
    args : Sequence[sympy.Symbol] | sympy.Symbol
        The arguments of the numeric function, in call order.
    exprs : sympy.Expr | Iterable[sympy.Expr]
        One expression or a sequence of them (the function then returns a tuple).
    backend : str
        ``"numpy"`` (vectorised), ``"mpmath"`` (arbitrary precision, uses ``mpmath.mp.dps``),
        ``"math"`` or ``"sympy"``.

    Raises
    ------
    MissingArgumentError
        naming each free symbol missing from ``args``.
    """
    if backend not in BACKENDS:
        raise InputError(f"backend must be one of {BACKENDS}, got {backend!r}")
    args = _as_symbols(args)
    if isinstance(exprs, (str, bytes)):  # sympy.lambdify would paste a string into the generated code
        raise InputTypeError("exprs must be sympy expressions, not a string (read a formula with "
                             "thinlayer.parse.parse_expression)")
    single = isinstance(exprs, sp.Basic)
    items = [exprs] if single else list(exprs)
    bad = [e for e in items if not isinstance(e, sp.Basic)]
    if bad:
        raise InputTypeError(f"exprs must be sympy expressions, got {type(bad[0]).__name__} (read a formula with "
                             "thinlayer.parse.parse_expression)")
    free: set[sp.Symbol] = set()
    for e in items:
        free |= e.free_symbols if isinstance(e, sp.Basic) else set()
    missing = sorted(free - set(args), key=lambda q: q.name)
    if missing:
        names = ", ".join(m.name for m in missing)
        raise MissingArgumentError(
            f"the expression has free symbol(s) {names} missing from the arguments "
            f"({', '.join(a.name for a in args) or 'none'}); add them to the argument list "
            f"or substitute values first"
        )
    modules = {"numpy": "numpy", "mpmath": "mpmath", "math": "math", "sympy": "sympy"}[backend]
    f = sp.lambdify(args, items[0] if single else tuple(items), modules=modules, cse=True)
    if backend == "numpy" and single and not any(items[0].has(a) for a in args):
        # a constant expression must still broadcast like its arguments
        const = f

        def f(*xs, _c=const):  # type: ignore[no-redef]
            import numpy as np

            shape = np.broadcast(*[np.asarray(x) for x in xs]).shape if xs else ()
            return np.full(shape, float(_c(*xs))) if shape else _c(*xs)

    f.__doc__ = f"numeric function of ({', '.join(a.name for a in args)}) [{backend}]"
    return f


@dataclass(frozen=True)
class Equation:
    """A single named equation ``lhs = rhs`` with its number in the paper."""

    lhs: sp.Expr
    rhs: sp.Expr
    number: str

    def latex(self) -> str:
        return rf"{normal_latex(self.lhs)} = {normal_latex(self.rhs)} \tag{{{self.number}}}"


def latex_equation(lhs: sp.Expr | str, rhs: sp.Expr | str, number: str | None) -> str:
    r"""LaTeX of ``lhs = rhs`` with an optional ``\tag`` of the paper's equation number.

    A formula (not a string) is printed in the normal form (:func:`thinlayer.normal.normal_latex`).
    """
    l = lhs if isinstance(lhs, str) else normal_latex(lhs)
    r = rhs if isinstance(rhs, str) else normal_latex(rhs)
    tag = rf" \tag{{{number}}}" if number else ""
    return f"{l} = {r}{tag}"
