"""sympy's code printers and code generators with the fixes thinlayer's expressions need.

See :mod:`thinlayer.export.codegen`, *Printer fixes*: strict C99 constants, standard Fortran types and
rank-1 output arrays, a Rust printer independent of sympy's version-specific number handling (and an
``erf`` helper, which Rust's std lacks), Julia's Euler number, and the numpy module's ``erf``.  Also the
preparation of the outputs: floats without rounding noise (:func:`clean_numbers`), even roots that are
safe outside their branch (:func:`guard_roots`) and common subexpressions as locals
(:func:`common_subexpressions`, written by every generator through :class:`_Locals`).
"""
from __future__ import annotations

import math
import textwrap
from collections.abc import Sequence

import sympy as sp
from sympy.printing.fortran import FCodePrinter
from sympy.printing.julia import JuliaCodePrinter
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.rust import RustCodePrinter
from sympy.utilities.codegen import C99CodeGen, FCodeGen, JuliaCodeGen, OctaveCodeGen, RustCodeGen


def clean_float(x: float, ulps: int = 4) -> sp.Float:
    """The shortest decimal within ``ulps`` units in the last place of ``x``, as a sympy Float.

    Rounding noise of a floating-point computation (``3.4999999999999996``, a 30-digit Float made from a
    double) is printed as the number it stands for (``3.5``); a number that needs all 17 digits keeps them.

    >>> clean_float(3.4999999999999996), clean_float(0.14519285684593675), clean_float(1 / 3)
    (3.50000000000000, 0.1451928568459367, 0.3333333333333333)
    """
    x = float(x)
    if x == 0 or not math.isfinite(x):
        return sp.Float(x)
    tol = ulps * math.ulp(x)
    for digits in range(1, 18):
        text = f"{x:.{digits}g}"
        if abs(float(text) - x) <= tol:
            return sp.Float(text, max(digits, 15))
    return sp.Float(repr(x), 17)


def clean_numbers(expr: sp.Expr) -> sp.Expr:
    """Every Float of ``expr`` by :func:`clean_float`; exact numbers (Rational, pi, sqrt(2)) stay exact."""
    floats = {f: clean_float(f) for f in expr.atoms(sp.Float)}
    return expr.xreplace(floats) if floats else expr


class NanIfNegative(sp.Function):
    """``x`` where ``x >= 0``, NaN elsewhere: the argument of an even root in branch-safe code.

    The real square root of a negative number is NaN in C, Fortran and Rust, but numpy warns ("invalid
    value encountered in sqrt") and Julia throws a DomainError.  numpy evaluates every branch of a
    ``Piecewise`` (``numpy.select``) and common subexpressions are computed before any branch is chosen,
    so the root of the boundary layer's ``v - h`` (3.24) is taken outside the contact too.  ``sqrt(NaN)``
    is NaN without a warning in both, the value is the same (NaN) and the chosen branch never sees it.
    """

    nargs = 1

    @classmethod
    def eval(cls, x):
        if x.is_nonnegative:
            return x
        return None


def guard_roots(expr: sp.Expr) -> sp.Expr:
    """Every even root ``b**(p/2)`` whose base may be negative as ``NanIfNegative(b)**(p/2)``."""
    def even_root(e):
        return (isinstance(e, sp.Pow) and e.exp.is_Rational and not e.exp.is_Integer and e.exp.q % 2 == 0
                and not e.base.is_nonnegative and not e.base.is_number)

    return expr.replace(even_root, lambda e: sp.Pow(NanIfNegative(e.base), e.exp))


def common_subexpressions(exprs: Sequence[sp.Expr], taken: Sequence[str], case_insensitive: bool = False
                          ) -> tuple[list[tuple[sp.Symbol, sp.Expr]], list[sp.Expr]]:
    """The outputs with their common subexpressions as locals (``sympy.cse``): ``(locals, outputs)``.

    The locals are real numbers named ``t0, t1, ...`` (another prefix when an argument, output or
    function is named like that); a boolean subexpression (a comparison of a ``Piecewise``) is put
    back in place, since the typed languages cannot store it in a ``double``.

    Parameters
    ----------
    exprs : sequence of sympy.Expr
        The outputs, in terms of the argument symbols.
    taken : sequence of str
        The identifiers the function already uses.
    case_insensitive : bool
        Whether the language ignores case (Fortran).

    Returns
    -------
    tuple
        The locals in evaluation order and the outputs in terms of arguments and locals.
    """
    def key(name: str) -> str:
        return name.lower() if case_insensitive else name

    used = {key(n) for n in taken}
    prefix = next(p for p in ("t", "tmp", "cse", "cse_tmp", "thinlayer_cse")
                  if not any(u.startswith(key(p)) and u[len(p):].isdigit() for u in used))
    names = sp.numbered_symbols(prefix, real=True)
    pairs, reduced = sp.cse(list(exprs), symbols=names, optimizations=None)
    kept: list[tuple[sp.Symbol, sp.Expr]] = []
    inline: dict = {}
    for sym, val in pairs:
        val = val.xreplace(inline)
        if isinstance(val, sp.logic.boolalg.Boolean) and not isinstance(val, sp.Expr):
            inline[sym] = val
        else:
            kept.append((sym, val))
    return kept, [e.xreplace(inline) for e in reduced]


def real_branches(expr: sp.Expr) -> sp.Expr:
    """Piecewise branches that are exact numbers become Floats (typed languages need one type)."""
    def fix(pw):
        return sp.Piecewise(*[(sp.Float(e, 17) if e.is_Number else e, c) for e, c in pw.args])
    return expr.replace(lambda e: isinstance(e, sp.Piecewise), fix)


class FortranPrinter(FCodePrinter):
    """Fortran printer: a column vector output is a rank-1 array ``out(i)``."""

    def _print_MatrixElement(self, expr):
        if expr.parent.shape[1] == 1:  # a column vector is a rank-1 array
            return f"{self._print(expr.parent)}({expr.i + 1})"
        return super()._print_MatrixElement(expr)


class RustPrinter(RustCodePrinter):
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


class JuliaPrinter(JuliaCodePrinter):
    """Julia printer: Euler's number as ``Base.MathConstants.e`` (``e`` is undefined in Julia 1.x)."""

    def _print_Exp1(self, expr):
        return "Base.MathConstants.e"

    def _print_NanIfNegative(self, expr):
        x = self._print(expr.args[0])
        return f"(({x} >= 0) ? ({x}) : (NaN))"


class NumPyModulePrinter(NumPyPrinter):
    """numpy printer for the standalone module: ``erf`` is the module's ``_erf`` (numpy has none)."""

    def _print_erf(self, expr):
        return f"_erf({self._print(expr.args[0])})"

    def _print_NanIfNegative(self, expr):
        x = self._print(expr.args[0])
        return f"numpy.where(numpy.greater_equal({x}, 0), {x}, numpy.nan)"


def _comment_block(lines: list[str], prefix: str) -> list[str]:
    return [(prefix + " " + ln).rstrip() + "\n" for ln in lines]


class _Locals:
    """A generator whose function body starts with the common subexpressions ``locals``.

    ``locals`` holds ``(symbol, value)`` pairs in evaluation order (:func:`common_subexpressions`); the
    routine is built with their symbols as ``global_vars`` (so that they are no arguments), which the
    generators below declare as nothing.  Each language writes one assignment per local (:meth:`_local`)
    after the constants it needs (``pi`` in C and Fortran), each constant declared once.
    """

    locals: tuple[tuple[sp.Symbol, sp.Expr], ...] = ()
    #: ``{local name: note}``: a comment line before the local (a named constant: where its number comes from)
    local_notes: dict = {}
    _comment_prefix = "//"
    _print_settings: dict = {"human": False, "strict": False}

    def _declare_globals(self, routine):
        return []

    def _local(self, text: str) -> str:
        return text + "\n"

    def _constant(self, name, value) -> str:
        raise NotImplementedError

    def _local_lines(self) -> tuple[list[str], list[str]]:
        """``(constant declarations, assignments)`` of the locals."""
        decl, code = [], []
        for sym, val in self.locals:
            constants, _, text = self._printer_method_with_settings("doprint", dict(self._print_settings), val,
                                                                    assign_to=sym)
            decl += [self._constant(n, v) for n, v in sorted(constants, key=str)]
            note = self.local_notes.get(sym.name)
            if note:
                code += [f"{self._comment_prefix} {ln}\n" for ln in textwrap.wrap(note, 100, break_on_hyphens=False)]
            code.append(self._local(text))
        return list(dict.fromkeys(decl)), code

    def _call_printer(self, routine):
        decl, code = self._local_lines()
        rest = [ln for ln in super()._call_printer(routine) if ln not in decl]
        return decl + code + rest


class CGen(_Locals, C99CodeGen):
    """C99 generator whose files start with thinlayer's header comment (:attr:`header_lines`)."""

    header_lines: tuple[str, ...] = ()

    def _get_header(self):
        lines = [ln.replace("*/", "* /") for ln in self.header_lines]  # a symbol named a*/b
        return ["/*\n"] + _comment_block(lines, " *") + [" */\n", "\n"]

    def _constant(self, name, value) -> str:
        return f"double const {name} = {value};\n"

    def _local(self, text: str) -> str:
        return f"const double {text}\n"


class FortranGen(_Locals, FCodeGen):
    """Fortran generator whose files start with thinlayer's header comment (:attr:`header_lines`)."""

    header_lines: tuple[str, ...] = ()
    _comment_prefix = "!"
    _print_settings = {"human": False, "source_format": "free", "standard": 95, "strict": False}

    def _get_header(self):
        return _comment_block(self.header_lines, "!") + ["\n"]

    def _constant(self, name, value) -> str:
        return f"double precision, parameter :: {name} = {value}\n"

    def _declare_locals(self, routine):
        return [f"double precision :: {self._get_symbol(s)}\n" for s, _ in self.locals]

    def _call_printer(self, routine):
        # every declaration before the first statement: the locals' constants and the results' constants
        decl, code = self._local_lines()
        rest = FCodeGen._call_printer(self, routine)
        more = [ln.replace("REAL*8", "double precision") for ln in rest if "::" in ln]
        return list(dict.fromkeys(decl + more)) + code + [ln for ln in rest if "::" not in ln]


class RustGen(_Locals, RustCodeGen):
    """Rust generator: thinlayer's header, a ``preamble`` (the erf helper) and ``pub fn``."""

    header_lines: tuple[str, ...] = ()
    preamble: tuple[str, ...] = ()

    def _get_header(self):
        return _comment_block(self.header_lines, "//") + ["\n"]

    def _constant(self, name, value) -> str:
        return f"const {name}: f64 = {value};\n"

    def _local(self, text: str) -> str:
        return f"let {text}\n"

    def _preprocessor_statements(self, prefix):
        return list(self.preamble)

    def _get_routine_opening(self, routine):
        return ["#[allow(non_snake_case, unused_parens, unused_variables)]\n",
                f"pub {self.get_prototype(routine)} {{\n"]


class JuliaGen(_Locals, JuliaCodeGen):
    """Julia generator: thinlayer's header and a ``preamble`` (``using SpecialFunctions``)."""

    header_lines: tuple[str, ...] = ()
    _comment_prefix = "#"
    preamble: tuple[str, ...] = ()

    def _get_header(self):
        return _comment_block(self.header_lines, "#") + ["\n"]

    def _preprocessor_statements(self, prefix):
        return list(self.preamble)

    def _constant(self, name, value) -> str:
        return f"{name} = {value}\n"


class OctaveGen(_Locals, OctaveCodeGen):
    """Octave/MATLAB generator whose file starts with thinlayer's header comment."""

    header_lines: tuple[str, ...] = ()
    _comment_prefix = "%"

    def _get_header(self):
        return _comment_block(self.header_lines, "%")

    def _constant(self, name, value) -> str:
        return f"  {name} = {value};  % constant\n"


# Error function for Rust, whose std has none.  Derived for thinlayer from two textbook identities
# (Abramowitz & Stegun 7.1.6 and 7.1.14); relative error < 2e-15, checked against mpmath in the tests.
RUST_ERF = """
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
