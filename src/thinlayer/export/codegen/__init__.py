r"""Code generation: C, Fortran, Rust, Julia, Octave/MATLAB and a standalone numpy module.

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
that lists both, with the sympy symbol behind each argument and what each argument and output is: its
meaning, units and the paper's equation (:mod:`~thinlayer.export.codegen.meanings`); the numpy function's
docstring lists them again (numpydoc).

Numbers of one layer are named constants, not arguments: a result's ``codegen_constants()`` gives them
(``{symbol: (number, note)}``), and the generated function defines each as a local with its note, e.g. the
force law of ``BondedLayer(0.3)``::

    h_s = 0.1220706478594777  # edge shift h*(nu=0.3), exact Wiener-Hopf solution (3.18), (3.25)

(the second-order law's ``r_3`` and ``h^*``, the flat punch's ``A``, ``m_1``, ``h^*``, ``c_1``, ``h`` and series
coefficients ``c_k`` alike).  With a symbolic nu, ``h^*`` stays an argument, described as
``thinlayer.edge_shift_exact(nu)``.

Common subexpressions (``sympy.cse``) are computed once, as locals ``t0, t1, ...`` at the top of the
function body in every language (sympy's own ``cse`` option covers C only).  Floats are printed
without rounding noise: each is the shortest decimal within four units in the last place of its
double (``3.4999999999999996`` is ``3.5``); exact numbers stay exact (``1.0/4.0`` in C).  An even
root whose argument may be negative (the boundary layer's ``sqrt(v - h)`` outside the contact) is
taken of ``NaN`` there in the numpy module and in Julia, which evaluate it before the branch is
chosen: numpy would warn "invalid value in sqrt", Julia would throw; the results are unchanged.

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
        def codegen_constants(self):        # optional: numbers of the layer the outputs name
            return {h_star: (0.1220706478594777, "edge shift h*(nu=0.3), exact Wiener-Hopf (3.25)")}

``codegen_expressions()`` returns ``(args, outputs)``: the argument symbols in call order and a
mapping from output name to sympy expression, in output order.  It takes precedence over every
other way of reading an object.  The outputs may hold the symbols of ``codegen_constants()``, which are
not arguments.

Modules
-------
:mod:`~thinlayer.export.codegen.names` (identifiers, reserved words, collisions),
:mod:`~thinlayer.export.codegen.spec` (reading a result into arguments and named outputs),
:mod:`~thinlayer.export.codegen.printers` (sympy's printers and generators with the fixes below),
:mod:`~thinlayer.export.codegen.files` (the header, the compiled-language files, the numpy module),
:mod:`~thinlayer.export.codegen.meanings` (what each argument and output is) and
:mod:`~thinlayer.export.codegen.generator` (:func:`generate`, :func:`generate_all`, :class:`GeneratedCode`).

Names
-----
sympy names such as ``x_1``, ``delta_0``, ``H_*``, ``delta_0^*``, ``\alpha`` or ``ν`` are turned
into identifiers valid in every language: ``*`` becomes ``s`` (``H_*`` -> ``H_s``,
``delta_0^*`` -> ``delta_0_s``), LaTeX braces and backslashes are dropped, Greek letters are
spelled out, font commands such as ``\mathcal{A}`` keep their argument, other characters become
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
* Rust: numbers, powers, products and sums are printed by
  :class:`~thinlayer.export.codegen.printers.RustPrinter`: sympy 1.13 prints integer literals
  (``-1/R`` does not compile), sympy 1.14 drops the parentheses of a sum inside a product (a wrong
  result) and rounds ``sqrt(2)`` to 14 digits.  Also fully qualified
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

from .generator import GeneratedCode, generate, generate_all
from .names import LANGUAGES, NameCollisionError, identifier
from .spec import CodegenResult

__all__ = [
    "LANGUAGES",
    "CodegenResult",
    "GeneratedCode",
    "NameCollisionError",
    "generate",
    "generate_all",
    "identifier",
]
