"""The output spec of a result: its argument symbols in call order and its named output expressions.

:func:`read_spec` reads every input :func:`~thinlayer.export.codegen.generate` accepts (the
:class:`CodegenResult` protocol, kernel coefficients (2.20), (4.2), an inner pressure (2.26), plain sympy
expressions) into one :class:`Spec`; :func:`check_free_symbols` makes sure the arguments cover the outputs.
"""
from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol, runtime_checkable

import sympy as sp

from ..._checks import InputError
from ...parse import as_expr
from ...results import MissingArgumentError


@runtime_checkable
class CodegenResult(Protocol):
    """What a result type implements to plug into :func:`generate`: the code-generation part of
    :class:`thinlayer.results.SymbolicResult`, which every symbolic stage result implements.

    ``codegen_expressions()`` returns the argument symbols in call order and a mapping
    ``{output name: sympy expression}`` in output order.  Optional attributes: ``codegen_name``
    (the default function name), ``equation`` (the paper's equation number), ``punch`` (whose
    parameters are described as such) and ``codegen_constants()``: ``{symbol: (number, note)}``, the numbers
    of one layer (``h^*``, ``r_3``, ``A``, ...) that the outputs hold as named symbols; the generated code
    defines each as a named constant with its note (where the number comes from) instead of an argument.
    """

    def codegen_expressions(self) -> tuple[Sequence[sp.Symbol], Mapping[str, sp.Expr]]:
        ...


@dataclass(frozen=True)
class Spec:
    """What to generate: argument symbols in call order, ``(output name, expression)`` pairs in output
    order, the default function name and the source quoted in the generated header.
    """

    args: tuple[sp.Symbol, ...]
    outputs: tuple[tuple[str, sp.Expr], ...]
    name: str
    source: str
    #: ``(symbol, number, note)``: named constants folded into the generated function (not arguments)
    constants: tuple[tuple[sp.Symbol, sp.Expr, str], ...] = ()
    #: names of the punch's parameters (described as such in the generated header)
    punch_parameters: tuple[str, ...] = field(default=())
    #: the result's equation of the paper, if it has one
    equation: str | None = None


def _snake(name: str) -> str:
    return re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()


# Bad input of any kind raises ValueError (issue 5 asks for it), also for a wrong type: hence noqa TRY004.
def _as_expr(x: Any, what: str) -> sp.Expr:
    if isinstance(x, (bool, str)):
        raise InputError(f"{what} is {x!r} ({type(x).__name__}); pass a sympy expression "  # noqa: TRY004
                         f"(strings are not parsed: use thinlayer.parse.parse_expression)")
    if isinstance(x, (int, float)):
        return as_expr(x)
    if not isinstance(x, sp.Expr):
        raise InputError(f"{what} is a {type(x).__name__}, not a sympy expression")  # noqa: TRY004
    if x.has(sp.I) or any(a.is_real is False for a in x.atoms(sp.Symbol)):
        raise InputError(f"{what} is complex ({x}); generated code works with real doubles")
    if x.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        raise InputError(f"{what} contains an infinity or NaN: {x}")
    return x


def _as_args(args: Any) -> tuple[sp.Symbol, ...]:
    if isinstance(args, sp.Basic):
        args = (args,)
    if isinstance(args, (str, bytes)) or not isinstance(args, Sequence):
        msg = f"args must be a sequence of sympy Symbols in call order, got {args!r}"
        raise InputError(msg)  # noqa: TRY004
    args = tuple(args)
    for a in args:
        if not isinstance(a, sp.Symbol):
            msg = f"every argument must be a sympy Symbol, got {a!r} ({type(a).__name__})"
            raise InputError(msg)  # noqa: TRY004
        if a.is_real is False:
            raise InputError(f"argument {a} is declared non-real; generated code takes real doubles")
    if len(set(args)) != len(args):
        raise InputError(f"args repeat a symbol: {', '.join(a.name for a in args)}")
    return args


def _outputs_from(obj: Any, what: str) -> tuple[tuple[str, sp.Expr], ...]:
    if isinstance(obj, Mapping):
        if not obj:
            raise InputError(f"{what}: no outputs given")
        outs = []
        for k, v in obj.items():
            if not isinstance(k, str):
                raise InputError(f"{what}: output names must be strings, got {k!r}")  # noqa: TRY004
            outs.append((k, _as_expr(v, f"output {k!r}")))
        return tuple(outs)
    if isinstance(obj, (list, tuple)):
        if not obj:
            raise InputError(f"{what}: no expressions given")
        return tuple((f"value_{i}", _as_expr(v, f"expression {i}")) for i, v in enumerate(obj))
    return (("value", _as_expr(obj, what)),)


def _describe(obj: Any) -> str:
    eq = getattr(obj, "equation", None)
    return f"{type(obj).__name__}" + (f", paper eq. ({eq})" if eq else "")


def _protocol_spec(result: Any, hook: Any, args: Any) -> Spec:
    """The spec of a :class:`CodegenResult`: its ``codegen_expressions()``."""
    got = hook()
    if not (isinstance(got, tuple) and len(got) == 2 and isinstance(got[1], Mapping)):
        raise InputError(f"{type(result).__name__}.codegen_expressions() must return "
                         f"(args, {{name: expr}}), got {type(got).__name__}")
    r_args, outs = got
    name = getattr(result, "codegen_name", None) or _snake(type(result).__name__)
    source = getattr(result, "codegen_source", None) or _describe(result)
    consts = getattr(result, "codegen_constants", None)
    constants = []
    for sym, (value, note) in (consts() if callable(consts) else {}).items():
        value = _as_expr(value, f"constant {sym}")
        if not isinstance(sym, sp.Symbol) or value.free_symbols:
            raise InputError(f"{type(result).__name__}.codegen_constants(): {sym!r} must be a Symbol with a number, "
                             f"got {value}")
        constants.append((sym, value, str(note)))
    punch = getattr(result, "punch", None)
    params = tuple(q.name for q in getattr(punch, "parameters", ()) or ())
    eq = getattr(result, "equation", None)
    return Spec(_as_args(r_args if args is None else args),
                _outputs_from(dict(outs), type(result).__name__), name, source, tuple(constants), params,
                eq if isinstance(eq, str) else None)


def read_spec(result: Any, args: Any) -> Spec:
    """The arguments and named outputs of anything :func:`~thinlayer.export.codegen.generate` accepts.

    Parameters
    ----------
    result : CodegenResult, KernelCoefficients, InnerPressure, sympy expression, sequence or mapping
        What to generate code for; a :class:`CodegenResult` takes precedence over every other reading.
    args : sequence of sympy.Symbol or None
        Argument symbols in call order; None for the result's own order (required for plain expressions).

    Returns
    -------
    Spec
        Arguments, ``(output name, expression)`` pairs, default function name and a source description.
    """
    if isinstance(result, (str, bytes)):
        msg = (f"cannot generate code from the string {result!r}: strings are not parsed; pass a sympy "
               f"expression (thinlayer.parse.parse_expression reads a formula)")
        raise InputError(msg)  # noqa: TRY004
    hook = getattr(result, "codegen_expressions", None)
    if callable(hook):
        return _protocol_spec(result, hook, args)
    if isinstance(result, (sp.Basic, int, float, Mapping, list, tuple)) and not isinstance(result, bool):
        if args is None:
            raise InputError("args is required for a plain expression: the argument symbols in call order")
        return Spec(_as_args(args), _outputs_from(result, "expression"), "f", "sympy expression(s)")
    raise InputError(
        f"cannot generate code from a {type(result).__name__}; pass an InnerPressure, a KernelCoefficients, "
        f"an object with codegen_expressions(), a sympy expression, a list of them or a {{name: expr}} "
        f"mapping (the last three with args=[symbols])")


def check_free_symbols(spec: Spec) -> None:
    """Raise ``MissingArgumentError`` when an output has a free symbol that is not an argument.

    Parameters
    ----------
    spec : Spec
        The arguments and outputs to check.
    """
    free: set = set()
    for _, e in spec.outputs:
        free |= e.free_symbols
    missing = sorted(free - set(spec.args) - {c for c, _, _ in spec.constants}, key=lambda q: q.name)
    if missing:
        raise MissingArgumentError(
            f"the expression has free symbol(s) {', '.join(m.name for m in missing)} missing from the "
            f"arguments ({', '.join(a.name for a in spec.args) or 'none'}); add them to args or substitute "
            f"values first")
