r"""Identifiers of the generated code: sanitised sympy names, reserved words, name collisions.

sympy names such as ``x_1``, ``H_*``, ``delta_0^*``, ``\alpha`` or ``ν`` become identifiers valid in every
language (see :mod:`thinlayer.export.codegen`, *Names*); a reserved word gets a trailing ``_`` and two
names that end up the same raise :class:`NameCollisionError`.
"""
from __future__ import annotations

import keyword
import re
import unicodedata
from typing import Any

from sympy.printing.c import C99CodePrinter
from sympy.printing.rust import RustCodePrinter

from ..._checks import InputError

#: The languages :func:`~thinlayer.export.codegen.generate` knows, in the order ``generate_all`` uses.
LANGUAGES = ("c", "fortran", "rust", "julia", "octave", "python")

#: name of the output array of C and Fortran for several outputs
VECTOR_OUT = "out"

_CASE_INSENSITIVE = frozenset({"fortran"})
_MAX_LENGTH = {"fortran": 63}  # Fortran 2003 limit, accepted by every current compiler


class NameCollisionError(InputError):
    """Two different names of the generated code map to the same identifier of the language."""


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

LANGUAGE_LABEL = {"c": "C", "fortran": "Fortran", "rust": "Rust", "julia": "Julia", "octave": "Octave",
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
    r"""The identifier that generated code in ``language`` uses for a sympy name.

    Parameters
    ----------
    name : str
        A sympy symbol or output name.
    language : str
        One of :data:`LANGUAGES` (or ``"matlab"``).

    Returns
    -------
    str
        ASCII letters, digits and ``_``, starting with a letter; a reserved word gets a trailing ``_``.

    Examples
    --------
    >>> identifier("H_*", "c"), identifier("delta_0^*", "fortran"), identifier("lambda", "python")
    ('H_s', 'delta_0_s', 'lambda_')
    >>> identifier("\\alpha_{1}", "julia"), identifier("ν", "rust"), identifier("end", "octave")
    ('alpha_1', 'nu', 'end_')
    """
    language = check_language(language)
    ident = _sanitise(name)
    if _key(ident, language) in _RESERVED[language]:
        ident += "_"
    return ident


def check_language(language: Any) -> str:
    """The language name in :data:`LANGUAGES` (``"matlab"`` and ``"m"`` mean ``"octave"``).

    Parameters
    ----------
    language : str
        A language name, any case.

    Returns
    -------
    str
        One of :data:`LANGUAGES`.
    """
    lang = language.lower() if isinstance(language, str) else language
    if lang in ("matlab", "m"):
        lang = "octave"
    if lang not in LANGUAGES:
        raise InputError(f"unknown language {language!r}; valid languages are {', '.join(LANGUAGES)} "
                         f"('matlab' is an alias of 'octave')")
    return lang


def check_function_name(name: Any, language: str) -> str:
    """``name`` if it is a valid, non-reserved identifier of ``language`` within its length limit.

    Parameters
    ----------
    name : str
        The function name, used as given (it also names the generated files).
    language : str
        One of :data:`LANGUAGES`.

    Returns
    -------
    str
        ``name``.
    """
    if not isinstance(name, str) or not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", name):
        raise InputError(f"function name {name!r} is not a valid identifier: use ASCII letters, digits "
                         f"and '_', starting with a letter (it also names the generated files)")
    if _key(name, language) in _RESERVED[language]:
        raise InputError(f"function name {name!r} is reserved in {LANGUAGE_LABEL[language]} (a keyword or a "
                         f"name the generated code uses); choose another name")
    limit = _MAX_LENGTH.get(language)
    if limit and len(name) > limit:
        raise InputError(f"function name {name!r} has {len(name)} characters; {LANGUAGE_LABEL[language]} "
                         f"allows at most {limit}")
    return name


def check_collisions(entries: list[tuple[str, str]], language: str) -> None:
    """Raise :class:`NameCollisionError` if two entries ``(identifier, description)`` clash.

    Parameters
    ----------
    entries : list of (str, str)
        Every identifier of the generated code with a description for the message.
    language : str
        One of :data:`LANGUAGES`; Fortran ignores case.
    """
    groups: dict[str, list[tuple[str, str]]] = {}
    for ident, what in entries:
        groups.setdefault(_key(ident, language), []).append((ident, what))
    clashes = [g for g in groups.values() if len(g) > 1]
    if clashes:
        parts = ["; ".join(f"{what} -> {ident!r}" for ident, what in g) for g in clashes]
        case = " (Fortran ignores case)" if language in _CASE_INSENSITIVE else ""
        raise NameCollisionError(
            f"names collide in the generated {LANGUAGE_LABEL[language]} code{case}: " + " | ".join(parts)
            + ". Rename a symbol (expr.xreplace({old: Symbol(new)})), an output, or the function")
    limit = _MAX_LENGTH.get(language)
    if limit:
        long = [ident for ident, _ in entries if len(ident) > limit]
        if long:
            raise InputError(f"identifier(s) {long} longer than {limit} characters, the "
                             f"{LANGUAGE_LABEL[language]} limit")
