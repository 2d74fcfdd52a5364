"""The entry points :func:`generate` and :func:`generate_all`, and their result :class:`GeneratedCode`."""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

import sympy as sp

from .files import argument_notes, compiled_files, header_lines, output_notes, python_module
from .names import LANGUAGES, VECTOR_OUT, check_collisions, check_function_name, check_language, identifier
from .spec import Spec, check_free_symbols, read_spec


@dataclass(frozen=True)
class GeneratedCode:
    """Source files for one function in one language (immutable).

    Attributes
    ----------
    language : str
        One of :data:`LANGUAGES`.
    function_name : str
        Name of the generated function (and the stem of the file names).
    arguments : tuple of str
        Argument identifiers in call order.
    outputs : tuple of str
        Output names in order: the returned tuple (Rust, Julia, Octave, Python) or the slots of
        the output array ``out`` (C: ``out[0]``.., Fortran: ``out(1)``..) when there are several.
    symbols : tuple of sympy.Symbol
        The sympy symbols behind :attr:`arguments`, in the same order.
    files : Mapping[str, str]
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
        naming the first such file is raised before anything is written.  Each file is written
        atomically (temporary file, fsync, rename) with the mode the umask gives.

        Parameters
        ----------
        directory : str or Path
            The folder to write into.
        force : bool
            Whether existing files may be overwritten.

        Returns
        -------
        list of Path
            The files written, main source file first.
        """
        from ...validation.output import atomic_write, refuse_existing

        d = Path(directory)
        paths = [d / fn for fn in self.files]
        refuse_existing(paths, force, "pass force=True to overwrite it")
        d.mkdir(parents=True, exist_ok=True)
        return [atomic_write(p, text) for p, text in zip(paths, self.files.values())]


def generate(result: Any, language: str, name: str | None = None, args: Sequence[sp.Symbol] | None = None
             ) -> GeneratedCode:
    """Source code of ``result`` as a function in ``language``.

    Parameters
    ----------
    result : InnerPressure, KernelCoefficients, CodegenResult, sympy expression, sequence or mapping
        An :class:`~thinlayer.asymptotics.inner.InnerPressure` (output ``p``: the dimensional pressure (2.26)),
        a :class:`~thinlayer.layers.coefficients.KernelCoefficients` of a symbolic layer (outputs
        ``A, m_1..m_N, M_1..M_N`` of (2.20), (4.2) as functions of nu), an object with
        ``codegen_expressions()`` (:class:`~thinlayer.export.codegen.spec.CodegenResult`), a sympy
        expression, a list of them, or a mapping ``{output name: expression}``.
    language : str
        One of :data:`LANGUAGES` (``"matlab"`` is accepted for ``"octave"``).
    name : str, optional
        Function name; default from the result (``inner_pressure``, ``kernel_coefficients``,
        ``codegen_name`` of a protocol object, ``f`` for plain expressions).
    args : sequence of sympy.Symbol, optional
        Argument symbols in call order.  Default: the result's own argument order; required for
        plain expressions.  Every free symbol of the outputs must be among them.

    Returns
    -------
    GeneratedCode
        The files, the argument and output identifiers.

    Raises
    ------
    ValueError
        unknown language, unusable input or function name; :class:`NameCollisionError` when
        two names map to one identifier; ``MissingArgumentError`` for a free symbol not in args.
    NotImplementedError
        if an expression holds a function the language's printer cannot print.
    """
    language = check_language(language)
    spec = read_spec(result, args)
    check_free_symbols(spec)
    fname = check_function_name(spec.name if name is None else name, language)

    arg_ids = tuple(identifier(s.name, language) for s in spec.args)
    out_ids = tuple(identifier(k, language) for k, _ in spec.outputs)
    const_ids = tuple(identifier(c.name, language) for c, _, _ in spec.constants)
    several = len(spec.outputs) > 1
    _check_names(spec, language, fname, arg_ids, out_ids, const_ids)

    new_syms = _real_symbols(spec.args, arg_ids)
    new_consts = [sp.Symbol(i, real=True, positive=bool(v > 0), negative=bool(v < 0))  # its sign is known
                  for i, (_, v, _) in zip(const_ids, spec.constants)]
    rename = dict(zip(spec.args, new_syms)) | dict(zip((c for c, _, _ in spec.constants), new_consts))
    exprs = [e.xreplace(rename) for _, e in spec.outputs]
    constants = [(s, v, note) for s, (_, v, note) in zip(new_consts, spec.constants)]

    header = header_lines(spec, language, fname, arg_ids, out_ids, several, const_ids)
    if language == "python":
        files = python_module(fname, new_syms, arg_ids, out_ids, exprs, header, constants,
                              argument_notes(spec, arg_ids), output_notes(out_ids, spec))
    else:
        files = compiled_files(language, fname, new_syms, out_ids, exprs, header, several, constants)
    return GeneratedCode(language, fname, arg_ids, out_ids, tuple(spec.args), MappingProxyType(files))


def _check_names(spec: Spec, language: str, fname: str, arg_ids: tuple[str, ...],
                 out_ids: tuple[str, ...], const_ids: tuple[str, ...] = ()) -> None:
    """No two names of the generated function (function, arguments, constants, outputs, C/Fortran locals) collide."""
    several = len(spec.outputs) > 1
    entries = [(fname, "function name")]
    entries += [(i, f"argument {s.name}") for i, s in zip(arg_ids, spec.args)]
    entries += [(i, f"constant {c.name}") for i, (c, _, _) in zip(const_ids, spec.constants)]
    if language in ("c", "fortran"):
        if several:
            entries.append((VECTOR_OUT, "output array"))
        elif language == "c":
            entries.append((f"{fname}_result", "C return variable"))
        if len(set(out_ids)) != len(out_ids):
            check_collisions([(i, f"output {k!r}") for i, (k, _) in zip(out_ids, spec.outputs)], language)
    else:
        entries += [(i, f"output {k!r}") for i, (k, _) in zip(out_ids, spec.outputs)]
    check_collisions(entries, language)


def _real_symbols(args: tuple[sp.Symbol, ...], arg_ids: tuple[str, ...]) -> list[sp.Symbol]:
    """Symbols named by the identifiers: real, keeping the sign information of ``args``."""
    new_syms = []
    for s, i in zip(args, arg_ids):
        assumptions = {"real": True}
        for k in ("positive", "negative", "nonnegative", "nonpositive", "nonzero"):
            if getattr(s, "is_" + k):
                assumptions[k] = True
        new_syms.append(sp.Symbol(i, **assumptions))
    return new_syms


def generate_all(result: Any, languages: Sequence[str] = LANGUAGES, name: str | None = None,
                 args: Sequence[sp.Symbol] | None = None) -> dict[str, GeneratedCode]:
    """:func:`generate` for several languages: ``{language: GeneratedCode}``.

    Parameters
    ----------
    result : object
        Anything :func:`generate` accepts.
    languages : sequence of str
        The languages, default every one of :data:`LANGUAGES`.
    name : str, optional
        Function name (default from the result).
    args : sequence of sympy.Symbol, optional
        Argument symbols in call order (default: the result's own).

    Returns
    -------
    dict
        ``{language: GeneratedCode}`` in the order of ``languages``.

    Examples
    --------
    >>> import sympy as sp
    >>> from thinlayer import BondedLayer, kernel_coefficients
    >>> codes = generate_all(kernel_coefficients(BondedLayer(), 1))
    >>> sorted(codes), codes["octave"].outputs
    (['c', 'fortran', 'julia', 'octave', 'python', 'rust'], ('A', 'm_1', 'M_1'))
    """
    return {lang: generate(result, lang, name=name, args=args) for lang in languages}
