"""Code generation: C, Fortran, Rust, Julia, Octave/MATLAB and a standalone numpy module.

Turns any result of thinlayer (the inner pressure (2.26), the kernel coefficients (2.20), (4.2),
or any later result that follows the protocol below) or plain sympy expressions into source code
for numerical work outside Python::

    generate(result, language, name=None, args=None) -> GeneratedCode

The compiled and scripting languages go through sympy's own machinery: the code generators of
:mod:`sympy.utilities.codegen` (``C99CodeGen``, ``FCodeGen``, ``RustCodeGen``, ``JuliaCodeGen``,
``OctaveCodeGen``) with small printer subclasses that fix what the stock printers get wrong for
thinlayer's expressions (see *Printer fixes*).  The standalone Python module is printed with
sympy's ``NumPyPrinter`` and imports only ``numpy`` (and ``math`` when it needs ``erf``).

Languages and calling conventions
---------------------------------
=========== ====================== =========================================================
language    files                  function
=========== ====================== =========================================================
``c``       ``name.c``, ``name.h`` C99. One output: ``double name(double a, ...)``.  Several:
                                   ``void name(double a, ..., double *out)``, ``out[0..n-1]``.
``fortran`` ``name.f90``,          Fortran 95 (+ the Fortran 2008 intrinsic ``erf``), ``double
            ``name.fi``            precision``.  One output: a function; several: ``subroutine
                                   name(a, ..., out)`` with ``out(1:n)``.  ``name.fi`` is the
                                   interface block, for ``include 'name.fi'`` in a caller.
``rust``    ``name.rs``            ``pub fn name(a: f64, ...) -> f64`` (a tuple of ``f64`` for
                                   several outputs).  ``erf`` is emitted as a private helper
                                   (Rust's ``std`` has none), only when it is needed.
``julia``   ``name.jl``            ``function name(a, ...)`` returning the output(s); scalar,
                                   broadcast with ``name.(a, ...)``.  ``using SpecialFunctions``
                                   is added when the code calls ``erf``.
``octave``  ``name.m``             ``function [o1, o2] = name(a, ...)``, element-wise operators:
                                   vectorised.  Runs in Octave and MATLAB.
``python``  ``name.py``            ``def name(a, ...)``, numpy, vectorised; returns one array or
                                   a tuple.  No sympy import.
=========== ====================== =========================================================

All functions take ``double``/``f64`` arguments in the order of :attr:`GeneratedCode.arguments`;
outputs come in the order of :attr:`GeneratedCode.outputs`.  Every file starts with a comment
that lists both, with the sympy symbol behind each argument.  Code is generated without common
subexpression elimination (sympy's Julia, Octave and Rust generators do not support it); the
expressions of thinlayer are short enough.

What can be generated
---------------------
* an :class:`~thinlayer.asymptotics.inner.InnerPressure` (or any object with ``.pressure`` and ``.arguments``):
  one function of ``.arguments`` with one output ``p``, the dimensional pressure;
* a :class:`~thinlayer.layers.coefficients.KernelCoefficients` of a symbolic layer: **one vector-valued
  function** of the layer parameter (nu, or kappa) with the outputs ``A, m_1..m_N, M_1..M_N``
  (N = ``order``; m_0 = M_0 = 1 are left out);
* any object with a method ``codegen_expressions()`` (the protocol below);
* a sympy expression, a sequence of them (outputs ``value_0, value_1, ...``) or a mapping
  ``{output name: expression}``; these need ``args``.

Result protocol (for later result types, e.g. composite pressure, force law)::

    class ForceLaw:
        codegen_name = "force_law"          # optional: default function name
        equation = "1.8"                    # optional: quoted in the generated header
        def codegen_expressions(self):
            return (delta0, H, mu, nu, R_1, R_2), {"P": force_expr}

``codegen_expressions()`` returns ``(args, outputs)``: the argument symbols in call order and a
mapping from output name to sympy expression, in output order.  It takes precedence over every
other way of reading an object.

Names
-----
sympy names such as ``x_1``, ``delta_0``, ``H_*``, ``delta_0^*``, ``\\alpha`` or ``ν`` are turned
into identifiers valid in every language: ``*`` becomes ``s`` (``H_*`` -> ``H_s``,
``delta_0^*`` -> ``delta_0_s``), LaTeX braces and backslashes are dropped, Greek letters are
spelled out, font commands such as ``\\mathcal{A}`` keep their argument, other characters become
``_``.  An identifier that is a reserved word of the language or a name the generated code needs
(``for``, ``end``, ``lambda``, ``exp``, ``pi``, ...) gets a trailing ``_``.
If two different symbols end up with the same identifier (Fortran ignores case, so ``R`` and ``r``
clash there), :class:`NameCollisionError` names them.  The function name is used as given and
must be a valid, non-reserved identifier.

Printer fixes
-------------
* C: ``pi`` and ``E`` become ``double const`` locals (sympy's ``math_macros`` off), so the code is
  strict C99 (``M_PI`` is POSIX, not C).
* Fortran: ``double precision`` instead of the non-standard ``REAL*8``; a vector output is a
  rank-1 array; integer branches of ``Piecewise`` are printed as reals (``merge`` needs one type).
* Rust: numbers, powers, products and sums are printed by :class:`_RustPrinter`: sympy 1.13
  prints integer literals (``-1/R`` does not compile), sympy 1.14 drops the parentheses of a sum
  inside a product (a wrong result) and rounds ``sqrt(2)`` to 14 digits.  Also fully qualified
  ``std::f64::consts``, the ``erf`` helper, real ``Piecewise`` branches and ``pub fn``.
* Julia: Euler's number as ``Base.MathConstants.e`` (sympy prints ``e``, undefined in Julia 1.x);
  real ``Piecewise`` branches.
* Python: ``erf`` is ``numpy.vectorize(math.erf)`` (numpy has no erf; scipy is not imported).

The tests compile the C with ``gcc -std=c99 -pedantic -Wall -Wextra -Werror``, the Fortran with
``gfortran -std=f2008 -Wall -Werror`` and the Rust with ``rustc -D warnings`` (1.63 and later).
The Rust ``erf`` helper agrees with mpmath to 2e-15 relative.

Limitations: Octave's ``Piecewise`` is sympy's mask product ``(c).*(a) + (~c).*(b)``, which
evaluates every branch everywhere, so a branch that is NaN, infinite or complex outside its
condition spoils the result there; the numpy module's ``numpy.select`` evaluates all branches
too but picks the right one.  Julia's ``?:`` ``Piecewise`` is scalar (broadcast the call).

Examples
--------
>>> import sympy as sp
>>> from thinlayer import BondedLayer, Punch, inner_pressure
>>> from thinlayer.export.codegen import generate
>>> ip = inner_pressure(BondedLayer(sp.Rational(3, 10)), Punch.elliptic_paraboloid())
>>> code = generate(ip, "c")
>>> code.function_name, code.arguments, code.outputs
('inner_pressure', ('x_1', 'x_2', 'delta_0', 'H', 'mu', 'R_1', 'R_2'), ('p',))
>>> sorted(code.files)
['inner_pressure.c', 'inner_pressure.h']
>>> print(code.files["inner_pressure.h"].splitlines()[-2])
double inner_pressure(double x_1, double x_2, double delta_0, double H, double mu, double R_1, double R_2);
>>> Hs = sp.Symbol("H_*", positive=True)
>>> generate(sp.sqrt(Hs) / 2, "rust", name="half_root", args=[Hs]).arguments
('H_s',)
"""
from __future__ import annotations

import keyword
import re
import unicodedata
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any, Protocol, runtime_checkable

import sympy as sp
from sympy.printing.c import C99CodePrinter
from sympy.printing.fortran import FCodePrinter
from sympy.printing.julia import JuliaCodePrinter
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.octave import OctaveCodePrinter
from sympy.printing.rust import RustCodePrinter
from sympy.utilities.codegen import (
    C99CodeGen,
    FCodeGen,
    JuliaCodeGen,
    OctaveCodeGen,
    OutputArgument,
    RustCodeGen,
)

from ..layers.coefficients import KernelCoefficients
from ..layers.kernels import GenericLayer
from ..results import MissingArgumentError

__all__ = [
    "LANGUAGES",
    "CodegenResult",
    "GeneratedCode",
    "NameCollisionError",
    "generate",
    "generate_all",
    "identifier",
]

#: The languages :func:`generate` knows, in the order :func:`generate_all` uses.
LANGUAGES = ("c", "fortran", "rust", "julia", "octave", "python")

_PROJECT = "thinlayer"
_CASE_INSENSITIVE = frozenset({"fortran"})
_MAX_LENGTH = {"fortran": 63}  # Fortran 2003 limit, accepted by every current compiler
_VECTOR_OUT = "out"  # name of the output array of C and Fortran for several outputs


class NameCollisionError(ValueError):
    """Two different names of the generated code map to the same identifier of the language."""


@runtime_checkable
class CodegenResult(Protocol):
    """What a result type implements to plug into :func:`generate`.

    ``codegen_expressions()`` returns the argument symbols in call order and a mapping
    ``{output name: sympy expression}`` in output order.  Optional attributes: ``codegen_name``
    (the default function name) and ``equation`` (the paper's equation number).
    """

    def codegen_expressions(self) -> tuple[Sequence[sp.Symbol], Mapping[str, sp.Expr]]:
        ...


# ----------------------------------------------------------------------------------------------
# reserved identifiers
# ----------------------------------------------------------------------------------------------

# math functions and constants the printers may emit: an argument with such a name would shadow them
_MATH = frozenset({
    "exp", "expm1", "log", "log1p", "log2", "log10", "sqrt", "cbrt", "pow", "erf", "erfc", "gamma",
    "lgamma", "abs", "fabs", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh",
    "asinh", "acosh", "atanh", "floor", "ceil", "min", "max", "sign", "hypot", "fmin", "fmax", "pi", "e",
    "E"
})

_C_WORDS = frozenset(C99CodePrinter().reserved_words) | frozenset({
    "_Bool", "_Complex", "_Imaginary", "main", "NAN", "INFINITY", "HUGE_VAL", "M_PI", "M_E", "NULL"
})
_FORTRAN_WORDS = frozenset({
    "program", "function", "subroutine", "module", "use", "end", "implicit", "none", "intent", "in", "out",
    "inout", "real", "integer", "double", "precision", "complex", "logical", "character", "dimension",
    "parameter", "merge", "if", "then", "else", "elseif", "do", "while", "call", "return", "contains",
    "interface", "kind", "dble", "huge", "tiny", "epsilon", "mod", "modulo", "int", "nint", "aint", "anint",
    "include", "result", "allocatable", "pointer", "target", "save", "data", "format", "go",
    "goto", "stop", "continue", "cycle", "exit", "select", "case", "where", "forall", "true", "false",
    "and", "or", "not", "eq", "ne", "lt", "le", "gt", "ge"
})
_RUST_WORDS = frozenset(RustCodePrinter().reserved_words) | frozenset({
    "f64", "f32", "i32", "i64", "u32", "u64", "usize", "isize", "bool", "std", "core", "Some", "None", "Ok",
    "Err", "PI", "E", "INFINITY", "NEG_INFINITY", "NAN", "union"
})
_JULIA_WORDS = frozenset({
    "baremodule", "begin", "break", "catch", "const", "continue", "do", "else", "elseif", "end", "export",
    "false", "finally", "for", "function", "global", "if", "import", "let", "local", "macro", "module",
    "quote", "return", "struct", "true", "try", "using", "while", "abstract", "mutable", "primitive",
    "type", "where", "in", "isa", "outer", "im", "Inf", "NaN", "Base", "Core", "Main", "MathConstants",
    "SpecialFunctions"
})
_OCTAVE_WORDS = frozenset({
    "__FILE__", "__LINE__", "break", "case", "catch", "classdef", "continue", "do", "else", "elseif", "end",
    "end_try_catch", "end_unwind_protect", "endclassdef", "endenumeration", "endevents", "endfor",
    "endfunction", "endif", "endmethods", "endparfor", "endproperties", "endswitch", "endwhile",
    "enumeration", "events", "for", "function", "global", "if", "methods", "otherwise", "parfor",
    "persistent", "properties", "return", "switch", "try", "until", "unwind_protect",
    "unwind_protect_cleanup", "while", "spmd", "endspmd", "arguments", "endarguments", "i", "j", "I", "J",
    "Inf", "inf", "NaN", "nan", "NA", "eps", "ans", "true", "false", "varargin", "varargout", "nargin",
    "nargout"
})
_PYTHON_WORDS = frozenset(keyword.kwlist) | frozenset(keyword.softkwlist) | {"numpy", "math", "_erf"}

_RESERVED: dict[str, frozenset] = {
    "c": _C_WORDS | _MATH,
    "fortran": frozenset(w.lower() for w in _FORTRAN_WORDS | _MATH),
    "rust": _RUST_WORDS | _MATH,
    "julia": _JULIA_WORDS | _MATH,
    "octave": _OCTAVE_WORDS | _MATH,
    "python": _PYTHON_WORDS,
}

_LANGUAGE_LABEL = {"c": "C", "fortran": "Fortran", "rust": "Rust", "julia": "Julia", "octave": "Octave",
                   "python": "Python"}


def _key(ident: str, language: str) -> str:
    return ident.lower() if language in _CASE_INSENSITIVE else ident


_FONT_COMMAND = r"\\(?:mathcal|mathrm|mathbf|mathit|mathsf|boldsymbol|bm|operatorname|text)\{([^{}]*)\}"


def _sanitise(name: str) -> str:
    """A name made of ASCII letters, digits and ``_`` that starts with a letter."""
    s = re.sub(_FONT_COMMAND, r"\1", name)  # \mathcal{A} -> A
    s = s.replace("\\", "").replace("{", "").replace("}", "").replace("*", "s").replace("'", "p")
    chars = []
    for ch in s:
        if ord(ch) < 128:
            chars.append(ch)
            continue
        m = re.fullmatch(r"GREEK (SMALL|CAPITAL) LETTER (\w+)", unicodedata.name(ch, ""))
        if m:
            word = m.group(2).lower()
            chars.append(word if m.group(1) == "SMALL" else word.capitalize())
        else:
            chars.append("_")
    s = re.sub(r"[^A-Za-z0-9_]", "_", "".join(chars))
    s = re.sub(r"_+", "_", s).strip("_")
    if not s or not s[0].isalpha():
        s = "v_" + s if s else "v"
    return s


def identifier(name: str, language: str) -> str:
    """The identifier that generated code in ``language`` uses for a sympy name.

    >>> identifier("H_*", "c"), identifier("delta_0^*", "fortran"), identifier("lambda", "python")
    ('H_s', 'delta_0_s', 'lambda_')
    >>> identifier("\\\\alpha_{1}", "julia"), identifier("ν", "rust"), identifier("end", "octave")
    ('alpha_1', 'nu', 'end_')
    """
    language = _check_language(language)
    ident = _sanitise(name)
    if _key(ident, language) in _RESERVED[language]:
        ident += "_"
    return ident


def _check_language(language: Any) -> str:
    lang = language.lower() if isinstance(language, str) else language
    if lang in ("matlab", "m"):
        lang = "octave"
    if lang not in LANGUAGES:
        raise ValueError(f"unknown language {language!r}; valid languages are {', '.join(LANGUAGES)} "
                         f"('matlab' is an alias of 'octave')")
    return lang


def _check_function_name(name: Any, language: str) -> str:
    if not isinstance(name, str) or not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", name):
        raise ValueError(f"function name {name!r} is not a valid identifier: use ASCII letters, digits "
                         f"and '_', starting with a letter (it also names the generated files)")
    if _key(name, language) in _RESERVED[language]:
        raise ValueError(f"function name {name!r} is reserved in {_LANGUAGE_LABEL[language]} (a keyword or a "
                         f"name the generated code uses); choose another name")
    limit = _MAX_LENGTH.get(language)
    if limit and len(name) > limit:
        raise ValueError(f"function name {name!r} has {len(name)} characters; {_LANGUAGE_LABEL[language]} "
                         f"allows at most {limit}")
    return name


def _check_collisions(entries: list[tuple[str, str]], language: str) -> None:
    """Raise :class:`NameCollisionError` if two entries ``(identifier, description)`` clash."""
    groups: dict[str, list[tuple[str, str]]] = {}
    for ident, what in entries:
        groups.setdefault(_key(ident, language), []).append((ident, what))
    clashes = [g for g in groups.values() if len(g) > 1]
    if clashes:
        parts = ["; ".join(f"{what} -> {ident!r}" for ident, what in g) for g in clashes]
        case = " (Fortran ignores case)" if language in _CASE_INSENSITIVE else ""
        raise NameCollisionError(
            f"names collide in the generated {_LANGUAGE_LABEL[language]} code{case}: " + " | ".join(parts)
            + ". Rename a symbol (expr.xreplace({old: Symbol(new)})), an output, or the function")
    limit = _MAX_LENGTH.get(language)
    if limit:
        long = [ident for ident, _ in entries if len(ident) > limit]
        if long:
            raise ValueError(f"identifier(s) {long} longer than {limit} characters, the "
                             f"{_LANGUAGE_LABEL[language]} limit")


# ----------------------------------------------------------------------------------------------
# reading the input: arguments and named outputs
# ----------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class _Spec:
    args: tuple[sp.Symbol, ...]
    outputs: tuple[tuple[str, sp.Expr], ...]
    name: str
    source: str


def _snake(name: str) -> str:
    return re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()


# Bad input of any kind raises ValueError (issue 5 asks for it), also for a wrong type: hence noqa TRY004.
def _as_expr(x: Any, what: str) -> sp.Expr:
    if isinstance(x, (bool, str)):
        raise ValueError(f"{what} is {x!r} ({type(x).__name__}); pass a sympy expression "  # noqa: TRY004
                         f"(strings are not parsed: use sympy.sympify yourself)")
    if isinstance(x, (int, float)):
        return sp.sympify(x)
    if not isinstance(x, sp.Expr):
        raise ValueError(f"{what} is a {type(x).__name__}, not a sympy expression")  # noqa: TRY004
    if x.has(sp.I) or any(a.is_real is False for a in x.atoms(sp.Symbol)):
        raise ValueError(f"{what} is complex ({x}); generated code works with real doubles")
    if x.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        raise ValueError(f"{what} contains an infinity or NaN: {x}")
    return x


def _as_args(args: Any) -> tuple[sp.Symbol, ...]:
    if isinstance(args, sp.Basic):
        args = (args,)
    if isinstance(args, (str, bytes)) or not isinstance(args, Sequence):
        msg = f"args must be a sequence of sympy Symbols in call order, got {args!r}"
        raise ValueError(msg)  # noqa: TRY004
    args = tuple(args)
    for a in args:
        if not isinstance(a, sp.Symbol):
            msg = f"every argument must be a sympy Symbol, got {a!r} ({type(a).__name__})"
            raise ValueError(msg)  # noqa: TRY004
        if a.is_real is False:
            raise ValueError(f"argument {a} is declared non-real; generated code takes real doubles")
    if len(set(args)) != len(args):
        raise ValueError(f"args repeat a symbol: {', '.join(a.name for a in args)}")
    return args


def _outputs_from(obj: Any, what: str) -> tuple[tuple[str, sp.Expr], ...]:
    if isinstance(obj, Mapping):
        if not obj:
            raise ValueError(f"{what}: no outputs given")
        outs = []
        for k, v in obj.items():
            if not isinstance(k, str):
                raise ValueError(f"{what}: output names must be strings, got {k!r}")  # noqa: TRY004
            outs.append((k, _as_expr(v, f"output {k!r}")))
        return tuple(outs)
    if isinstance(obj, (list, tuple)):
        if not obj:
            raise ValueError(f"{what}: no expressions given")
        return tuple((f"value_{i}", _as_expr(v, f"expression {i}")) for i, v in enumerate(obj))
    return (("value", _as_expr(obj, what)),)


def _describe(obj: Any) -> str:
    eq = getattr(obj, "equation", None)
    return f"{type(obj).__name__}" + (f", paper eq. ({eq})" if eq else "")


def _spec(result: Any, args: Any) -> _Spec:
    if isinstance(result, (str, bytes)):
        msg = (f"cannot generate code from the string {result!r}: strings are not parsed; pass a sympy "
               f"expression (sympy.sympify it yourself)")
        raise ValueError(msg)  # noqa: TRY004
    hook = getattr(result, "codegen_expressions", None)
    if callable(hook):
        got = hook()
        if not (isinstance(got, tuple) and len(got) == 2 and isinstance(got[1], Mapping)):
            raise ValueError(f"{type(result).__name__}.codegen_expressions() must return "
                             f"(args, {{name: expr}}), got {type(got).__name__}")
        r_args, outs = got
        name = getattr(result, "codegen_name", None) or _snake(type(result).__name__)
        return _Spec(_as_args(r_args if args is None else args),
                     _outputs_from(dict(outs), type(result).__name__), name, _describe(result))
    if isinstance(result, KernelCoefficients):
        p = result.layer.parameter
        if isinstance(result.layer, GenericLayer):
            msg = ("the coefficients of a GenericLayer are the symbols A, m_n themselves; pass the "
                   "expressions you need (e.g. M_expr(k)) with args=[m_1, ...]")
            raise ValueError(msg)  # noqa: TRY004
        if p is None:
            raise ValueError("these kernel coefficients have no symbolic parameter (a numeric or "
                             "parameter-free layer): they are numbers already; use e.g. "
                             "kernel_coefficients(BondedLayer(), n)")
        outs = [("A", result.A_expr)] + [(f"m_{n}", result.m_expr(n)) for n in range(1, result.order + 1)]
        outs += [(f"M_{k}", result.M_expr(k)) for k in range(1, result.order + 1)]
        return _Spec(_as_args((p,) if args is None else args),
                     tuple((k, _as_expr(v, k)) for k, v in outs), "kernel_coefficients",
                     f"{_describe(result)} and (4.2), {result.layer!r}, order {result.order}")
    if hasattr(result, "pressure") and hasattr(result, "arguments"):
        r_args = result.arguments if args is None else args
        return _Spec(_as_args(r_args), (("p", _as_expr(result.pressure, "pressure")),),
                     _snake(type(result).__name__), _describe(result))
    if isinstance(result, (sp.Basic, int, float, Mapping, list, tuple)) and not isinstance(result, bool):
        if args is None:
            raise ValueError("args is required for a plain expression: the argument symbols in call order")
        return _Spec(_as_args(args), _outputs_from(result, "expression"), "f", "sympy expression(s)")
    raise ValueError(
        f"cannot generate code from a {type(result).__name__}; pass an InnerPressure, a KernelCoefficients, "
        f"an object with codegen_expressions(), a sympy expression, a list of them or a {{name: expr}} "
        f"mapping (the last three with args=[symbols])")


def _check_free_symbols(spec: _Spec) -> None:
    free: set = set()
    for _, e in spec.outputs:
        free |= e.free_symbols
    missing = sorted(free - set(spec.args), key=lambda q: q.name)
    if missing:
        raise MissingArgumentError(
            f"the expression has free symbol(s) {', '.join(m.name for m in missing)} missing from the "
            f"arguments ({', '.join(a.name for a in spec.args) or 'none'}); add them to args or substitute "
            f"values first")


# ----------------------------------------------------------------------------------------------
# printers and code generators: sympy's, with the fixes listed in the module docstring
# ----------------------------------------------------------------------------------------------

def _real_branches(expr: sp.Expr) -> sp.Expr:
    """Piecewise branches that are exact numbers become Floats (typed languages need one type)."""
    def fix(pw):
        return sp.Piecewise(*[(sp.Float(e, 17) if e.is_Number else e, c) for e, c in pw.args])
    return expr.replace(lambda e: isinstance(e, sp.Piecewise), fix)


class _FPrinter(FCodePrinter):
    def _print_MatrixElement(self, expr):
        if expr.parent.shape[1] == 1:  # a column vector is a rank-1 array
            return f"{self._print(expr.parent)}({expr.i + 1})"
        return super()._print_MatrixElement(expr)


class _RustPrinter(RustCodePrinter):
    """sympy's Rust printer made independent of its version-specific number handling.

    Every number is an ``f64`` literal (Rust does not mix integers and floats: ``-1/R`` does not
    compile, as sympy 1.13 prints it), powers are printed here (``powi`` with an ``i32``
    exponent), pure-number subexpressions are evaluated to full precision (sympy 1.14 rounds
    ``sqrt(2)`` to 14 digits), and products and sums bypass sympy 1.14's casting layer, which
    drops the parentheses of a sum (``7*mu*(d - x)/H`` came out as ``7*mu*d - x/H``).
    """

    def _print_Mul(self, expr):
        return super(RustCodePrinter, self)._print_Mul(expr)

    def _print_Add(self, expr, order=None):
        return super(RustCodePrinter, self)._print_Add(expr, order)

    def _print_TypeCast(self, expr):  # sympy 1.14's _print_Relational casts an integer-valued side
        inner = self._print(expr.expr)
        return f"({inner})" if isinstance(expr.expr, (sp.Add, sp.Piecewise)) else inner

    def _print_Float(self, expr, _type=False):
        return repr(float(expr)) + ("_f64" if _type else "")  # shortest literal that round-trips

    def _print_Integer(self, expr, _type=False):
        return f"{int(expr)}.0" + ("_f64" if _type else "")

    def _print_Rational(self, expr, _type=False):
        return f"{int(expr.p)}.0/{int(expr.q)}.0"

    def _number(self, expr):
        return self._print_Float(sp.Float(expr.evalf(20), 17))

    def _print_NumberSymbol(self, expr, _type=False):
        return self._number(expr)

    def _print_Pi(self, expr, _type=False):
        return "std::f64::consts::PI"

    def _print_Exp1(self, expr, _type=False):
        return "std::f64::consts::E"

    def _receiver(self, expr):
        """``expr`` as the receiver of a method call: ``x``, ``(x + 1.0)``, ``(2.0_f64)``."""
        if expr.is_Symbol:
            return self._print(expr)
        if expr.is_number:
            return f"({self._number(expr)}_f64)"
        return f"({self._print(expr)})"

    def _print_Pow(self, expr):
        base, e = expr.base, expr.exp
        if expr.is_number:
            return self._number(expr)
        b = self._receiver(base)
        if e == -1:
            return f"{b}.recip()"
        if e == sp.S.Half:
            return f"{b}.sqrt()"
        if e == -sp.S.Half:
            return f"{b}.sqrt().recip()"
        if e == sp.Rational(1, 3):
            return f"{b}.cbrt()"
        if e.is_Integer and abs(int(e)) < 2**31:
            return f"{b}.powi({int(e)})"
        if base == sp.E:
            return f"{self._receiver(e)}.exp()"
        return f"{b}.powf({self._print(e)})"

    def _print_Function(self, expr):
        if expr.is_number:
            return self._number(expr)
        return super()._print_Function(expr)

    def _print_erf(self, expr):
        if expr.is_number:
            return self._number(expr)
        return f"erf({self._print(expr.args[0])})"


class _JuliaPrinter(JuliaCodePrinter):
    def _print_Exp1(self, expr):
        return "Base.MathConstants.e"


class _NumPyPrinter(NumPyPrinter):
    def _print_erf(self, expr):
        return f"_erf({self._print(expr.args[0])})"


def _comment_block(lines: list[str], prefix: str) -> list[str]:
    return [(prefix + " " + ln).rstrip() + "\n" for ln in lines]


class _CCodeGen(C99CodeGen):
    header_lines: tuple[str, ...] = ()

    def _get_header(self):
        lines = [ln.replace("*/", "* /") for ln in self.header_lines]  # a symbol named a*/b
        return ["/*\n"] + _comment_block(lines, " *") + [" */\n", "\n"]


class _FCodeGen(FCodeGen):
    header_lines: tuple[str, ...] = ()

    def _get_header(self):
        return _comment_block(self.header_lines, "!") + ["\n"]


class _RustCodeGen(RustCodeGen):
    header_lines: tuple[str, ...] = ()
    preamble: tuple[str, ...] = ()

    def _get_header(self):
        return _comment_block(self.header_lines, "//") + ["\n"]

    def _preprocessor_statements(self, prefix):
        return list(self.preamble)

    def _get_routine_opening(self, routine):
        return ["#[allow(non_snake_case, unused_parens, unused_variables)]\n",
                f"pub {self.get_prototype(routine)} {{\n"]


class _JuliaCodeGen(JuliaCodeGen):
    header_lines: tuple[str, ...] = ()
    preamble: tuple[str, ...] = ()

    def _get_header(self):
        return _comment_block(self.header_lines, "#") + ["\n"]

    def _preprocessor_statements(self, prefix):
        return list(self.preamble)


class _OctaveCodeGen(OctaveCodeGen):
    header_lines: tuple[str, ...] = ()

    def _get_header(self):
        return _comment_block(self.header_lines, "%")


# Error function for Rust, whose std has none.  Derived for thinlayer from two textbook identities
# (Abramowitz & Stegun 7.1.6 and 7.1.14); relative error < 2e-15, checked against mpmath in the tests.
_RUST_ERF = """
/// erf(x) in double precision (Rust's std has no erf).
/// |x| < 2: erf(x) = 2/sqrt(pi) exp(-x^2) sum_n 2^n x^(2n+1) / (1*3*...*(2n+1)), positive terms (A&S 7.1.6);
/// 2 <= |x| < 6: 1 - erfc(x), erfc(x) = exp(-x^2)/sqrt(pi) / (x + (1/2)/(x + 1/(x + (3/2)/(x + ...))))
/// (A&S 7.1.14) by the modified Lentz method; |x| >= 6: +-1 to double precision.
fn erf(x: f64) -> f64 {
if x.is_nan() {
return x;
}
let a = x.abs();
let r = if a < 2.0 {
let a2 = a * a;
let mut term = a;
let mut sum = a;
let mut n = 0.0_f64;
loop {
n += 1.0;
term *= 2.0 * a2 / (2.0 * n + 1.0);
sum += term;
if term <= sum * 1e-17 {
break;
}
}
std::f64::consts::FRAC_2_SQRT_PI * (-a2).exp() * sum
} else if a < 6.0 {
let mut f = a;
let mut c = a;
let mut d = 0.0_f64;
let mut n = 0.0_f64;
loop {
n += 1.0;
d = 1.0 / (a + 0.5 * n * d);
c = a + 0.5 * n / c;
let delta = c * d;
f *= delta;
if (delta - 1.0).abs() <= f64::EPSILON || n > 500.0 {
break;
}
}
1.0 - 0.5 * std::f64::consts::FRAC_2_SQRT_PI * (-a * a).exp() / f
} else {
1.0
};
r.copysign(x)
}
"""


# ----------------------------------------------------------------------------------------------
# result object
# ----------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class GeneratedCode:
    """Source files for one function in one language (immutable).

    Attributes
    ----------
    language:
        One of :data:`LANGUAGES`.
    function_name:
        Name of the generated function (and the stem of the file names).
    arguments:
        Argument identifiers in call order.
    outputs:
        Output names in order: the returned tuple (Rust, Julia, Octave, Python) or the slots of
        the output array ``out`` (C: ``out[0]``.., Fortran: ``out(1)``..) when there are several.
    symbols:
        The sympy symbols behind :attr:`arguments`, in the same order.
    files:
        Read-only mapping ``{file name: source text}``, main source file first.
    """

    language: str
    function_name: str
    arguments: tuple[str, ...]
    outputs: tuple[str, ...]
    symbols: tuple[sp.Symbol, ...]
    files: Mapping[str, str] = field(repr=False, hash=False)

    @property
    def main_file(self) -> str:
        """Name of the main source file (``name.c``, ``name.f90``, ``name.py``, ...)."""
        return next(iter(self.files))

    @property
    def source(self) -> str:
        """Text of the main source file."""
        return self.files[self.main_file]

    def write(self, directory: str | Path, force: bool = False) -> list[Path]:
        """Write every file into ``directory`` (created if missing) and return their paths.

        Existing files are not overwritten unless ``force=True``: a :class:`FileExistsError`
        naming the first such file is raised before anything is written.
        """
        d = Path(directory)
        paths = [d / fn for fn in self.files]
        if not force:
            for p in paths:
                if p.exists():
                    raise FileExistsError(f"{p} exists; pass force=True to overwrite it")
        d.mkdir(parents=True, exist_ok=True)
        for p, text in zip(paths, self.files.values()):
            p.write_text(text, encoding="utf-8")
        return paths


# ----------------------------------------------------------------------------------------------
# entry points
# ----------------------------------------------------------------------------------------------

def generate(result: Any, language: str, name: str | None = None, args: Sequence[sp.Symbol] | None = None
             ) -> GeneratedCode:
    """Source code of ``result`` as a function in ``language``.

    Parameters
    ----------
    result:
        An :class:`~thinlayer.asymptotics.inner.InnerPressure` (output ``p``: the dimensional pressure (2.26)),
        a :class:`~thinlayer.layers.coefficients.KernelCoefficients` of a symbolic layer (outputs
        ``A, m_1..m_N, M_1..M_N`` of (2.20), (4.2) as functions of nu), an object with
        ``codegen_expressions()`` (:class:`CodegenResult`), a sympy expression, a list of them, or
        a mapping ``{output name: expression}``.
    language:
        One of :data:`LANGUAGES` (``"matlab"`` is accepted for ``"octave"``).
    name:
        Function name; default from the result (``inner_pressure``, ``kernel_coefficients``,
        ``codegen_name`` of a protocol object, ``f`` for plain expressions).
    args:
        Argument symbols in call order.  Default: the result's own argument order; required for
        plain expressions.  Every free symbol of the outputs must be among them.

    Raises
    ------
    ValueError
        unknown language, unusable input or function name; :class:`NameCollisionError` when
        two names map to one identifier; ``MissingArgumentError`` for a free symbol not in args.
    NotImplementedError
        if an expression holds a function the language's printer cannot print.
    """
    language = _check_language(language)
    spec = _spec(result, args)
    _check_free_symbols(spec)
    fname = _check_function_name(spec.name if name is None else name, language)

    arg_ids = tuple(identifier(s.name, language) for s in spec.args)
    out_ids = tuple(identifier(k, language) for k, _ in spec.outputs)
    several = len(spec.outputs) > 1
    entries = [(fname, "function name")]
    entries += [(i, f"argument {s.name}") for i, s in zip(arg_ids, spec.args)]
    if language in ("c", "fortran"):
        if several:
            entries.append((_VECTOR_OUT, "output array"))
        elif language == "c":
            entries.append((f"{fname}_result", "C return variable"))
        if len(set(out_ids)) != len(out_ids):
            _check_collisions([(i, f"output {k!r}") for i, (k, _) in zip(out_ids, spec.outputs)], language)
    else:
        entries += [(i, f"output {k!r}") for i, (k, _) in zip(out_ids, spec.outputs)]
    _check_collisions(entries, language)

    # sympy symbols named by the identifiers: real, keeping the sign information
    new_syms = []
    for s, i in zip(spec.args, arg_ids):
        assumptions = {"real": True}
        for k in ("positive", "negative", "nonnegative", "nonpositive", "nonzero"):
            if getattr(s, "is_" + k):
                assumptions[k] = True
        new_syms.append(sp.Symbol(i, **assumptions))
    rename = dict(zip(spec.args, new_syms))
    exprs = [e.xreplace(rename) for _, e in spec.outputs]

    header = _header(spec, language, fname, arg_ids, out_ids, several)
    if language == "python":
        files = _python_module(fname, new_syms, arg_ids, out_ids, exprs, header)
    else:
        files = _compiled(language, fname, new_syms, out_ids, exprs, header, several)
    return GeneratedCode(language, fname, arg_ids, out_ids, tuple(spec.args), MappingProxyType(files))


def generate_all(result: Any, languages: Sequence[str] = LANGUAGES, name: str | None = None,
                 args: Sequence[sp.Symbol] | None = None) -> dict[str, GeneratedCode]:
    """:func:`generate` for several languages: ``{language: GeneratedCode}``.

    >>> import sympy as sp
    >>> from thinlayer import BondedLayer, kernel_coefficients
    >>> codes = generate_all(kernel_coefficients(BondedLayer(), 1))
    >>> sorted(codes), codes["octave"].outputs
    (['c', 'fortran', 'julia', 'octave', 'python', 'rust'], ('A', 'm_1', 'M_1'))
    """
    return {lang: generate(result, lang, name=name, args=args) for lang in languages}


# ----------------------------------------------------------------------------------------------
# assembling the files
# ----------------------------------------------------------------------------------------------

def _header(spec: _Spec, language: str, fname: str, arg_ids, out_ids, several: bool) -> list[str]:
    lines = [f"Generated by thinlayer.export.codegen from {spec.source}.",
             "Do not edit: regenerate from the derivation instead.", ""]
    lines.append(f"{fname}({', '.join(arg_ids)}) -> {', '.join(out_ids)}")
    lines.append("Arguments in call order (identifier: sympy symbol):")
    lines += [f"  {i}: {s.name}" for i, s in zip(arg_ids, spec.args)]
    if several and language in ("c", "fortran"):
        if language == "c":
            slots = [f"out[{k}] = {o}" for k, o in enumerate(out_ids)]
        else:
            slots = [f"out({k + 1}) = {o}" for k, o in enumerate(out_ids)]
        lines.append(f"Outputs, in the array out of length {len(out_ids)}:")
        lines += ["  " + s for s in slots]
    else:
        lines.append("Outputs: " + ", ".join(out_ids))
    if language == "python":
        lines.append("Vectorised: the arguments broadcast like numpy arrays.")
    elif language == "octave":
        lines.append("Vectorised: element-wise operators; arguments of equal sizes (or scalars).")
    elif language == "julia":
        lines.append(f"Scalar; broadcast over arrays with {fname}.(...).")
    return lines


def _unsupported(printer, exprs, language: str) -> None:
    bad: set = set()
    for e in exprs:
        _, not_supported, _ = _doprint_raw(printer, e)
        bad |= {str(getattr(x, "func", x)) for x in not_supported}
    if bad:
        raise NotImplementedError(
            f"{_LANGUAGE_LABEL[language]} code cannot express {', '.join(sorted(bad))}: no such function in "
            f"sympy's {_LANGUAGE_LABEL[language]} printer")


def _doprint_raw(printer, expr):
    """``(constants, not_supported, code)`` of sympy's code printers (their ``human=False`` mode)."""
    keys = [k for k in ("human", "strict") if k in printer._settings]  # no 'strict' before sympy 1.13
    old = {k: printer._settings[k] for k in keys}
    printer._settings.update({k: False for k in keys})
    try:
        return printer.doprint(expr)
    finally:
        printer._settings.update(old)


def _compiled(language, fname, syms, out_ids, exprs, header, several) -> dict[str, str]:
    if language in ("fortran", "rust", "julia"):
        exprs = [_real_branches(e) for e in exprs]
    uses_erf = any(e.has(sp.erf) for e in exprs)
    if language == "c":
        gen = _CCodeGen(project=_PROJECT, printer=C99CodePrinter({"math_macros": {}}),
                        preprocessor_statements=["#include <math.h>"])
    elif language == "fortran":
        gen = _FCodeGen(project=_PROJECT, printer=_FPrinter({"source_format": "free", "standard": 95}))
    elif language == "rust":
        gen = _RustCodeGen(project=_PROJECT, printer=_RustPrinter())
        gen.preamble = (*_RUST_ERF.lstrip("\n").splitlines(keepends=True), "\n") if uses_erf else ()
    elif language == "julia":
        gen = _JuliaCodeGen(project=_PROJECT, printer=_JuliaPrinter())
        gen.preamble = ("using SpecialFunctions  # erf\n", "\n") if uses_erf else ()
    else:
        gen = _OctaveCodeGen(project=_PROJECT, printer=OctaveCodePrinter())
    gen.header_lines = tuple(header)
    _unsupported(gen.printer, exprs, language)

    seq = list(syms)
    if language in ("c", "fortran"):
        if several:
            out = sp.MatrixSymbol(_VECTOR_OUT, len(exprs), 1)
            body: Any = sp.Eq(out, sp.ImmutableMatrix(exprs), evaluate=False)
            seq.append(out)
        else:
            body = exprs[0]
    else:  # named results: Rust, Julia and Octave return them (a tuple when there are several)
        body = [sp.Eq(sp.Symbol(o, real=True), e, evaluate=False) for o, e in zip(out_ids, exprs)]
    routine = gen.routine(fname, body, seq, None)
    if language == "fortran" and several:
        for a in routine.arguments:  # the output column (1:n, 1:1) becomes a rank-1 array (1:n)
            if isinstance(a, OutputArgument):
                a.dimensions = a.dimensions[:1]
    files = dict(gen.write([routine], fname, header=True, empty=False))
    if language == "fortran":
        files = {(fn[:-1] + "fi" if fn.endswith(".h") else fn): text.replace("REAL*8", "double precision")
                 for fn, text in files.items()}
    return {fn: re.sub(r"\n{3,}", "\n\n", text).strip("\n") + "\n" for fn, text in files.items()}


def _python_module(fname, syms, arg_ids, out_ids, exprs, header) -> dict[str, str]:
    printer = _NumPyPrinter({"fully_qualified_modules": True})
    _unsupported(printer, exprs, "python")
    body = []
    for o, e in zip(out_ids, exprs):
        code = printer.doprint(e)
        if not e.free_symbols and arg_ids:  # a constant still broadcasts like the arguments
            code = f"{code} + numpy.zeros(numpy.broadcast({', '.join(arg_ids)}).shape)"
        body.append(f"    {o} = {code}")
    modules = set(printer.module_imports) - {"numpy"}
    if modules:
        raise NotImplementedError(f"the numpy printer needs module(s) {sorted(modules)}; the standalone "
                                  f"module may import numpy and math only")
    uses_erf = any(e.has(sp.erf) for e in exprs)
    # a raw docstring: a symbol name like \xi in it is no escape sequence
    doc = ['r"""' + header[0], *[ln.replace('"""', "'''") for ln in header[1:]], '"""']
    lines = [ln.rstrip() for ln in doc]
    lines += ["import numpy"]
    if uses_erf:
        lines += ["import math", "", "_erf = numpy.vectorize(math.erf, otypes=[float])"]
    lines += ["", "", f"def {fname}({', '.join(arg_ids)}):",
              f'    """{fname}({", ".join(arg_ids)}) -> {", ".join(out_ids)}; see the module docstring."""']
    lines += body
    lines.append(f"    return {', '.join(out_ids)}")
    return {f"{fname}.py": "\n".join(lines) + "\n"}
