"""Command line: ``thinlayer {report,coefficients,inner,solve,codegen,errata,validate} ...``.

Every subcommand prints readable text by default, ``--json`` for machine-readable output (keys
documented in each subcommand's ``--help``) and, where a formula is the answer, ``--latex``.
Exit codes: 0 success, 2 bad input (a one-line reason on stderr), 1 any other failure (one line too),
130 interrupted by Ctrl-C, 143 terminated by SIGTERM (temporary folders are removed on both), 141
when the reader of the output went away (``thinlayer errata --json | head``: no message).  No
traceback is ever printed, and a result that is not finite (or a force or area that is not positive)
is an error, never a JSON number such as ``Infinity``.
"""
from __future__ import annotations

import argparse
import functools
import json
import os
import signal
import sys
from pathlib import Path
from typing import Any

from .cli_args import (  # noqa: F401 - BadInput and the shared helpers, importable from here as before
    BASES,
    KINDS,
    NOTE,
    TIP_KINDS,
    BadInput,
    add_punch_args,
    base_arg,
    finite,
    nonfinite,
    print_text,
    punch_from_args,
    punch_params,
    solve_layer,
    tip_needs_values,
)

EXIT_OK, EXIT_FAILURE, EXIT_BAD_INPUT = 0, 1, 2
EXIT_INTERRUPTED, EXIT_BROKEN_PIPE, EXIT_TERMINATED = 130, 141, 143


class Terminated(BaseException):
    """SIGTERM arrived: unwinds like Ctrl-C so that ``finally`` blocks remove temporary folders."""


class _Parser(argparse.ArgumentParser):
    """An argument parser whose errors are one line on stderr (exit code 2), without the usage block."""

    def error(self, message: str):
        self.exit(EXIT_BAD_INPUT, f"{self.prog}: {message.splitlines()[0]} (see {self.prog} --help)\n")


def _order(text: str) -> int:
    """An argparse type: an integer."""
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None


# ---------------------------------------------------------------------------------------------
# shared argument parsing
# ---------------------------------------------------------------------------------------------
def _layer(nu: str, model: str = "bonded"):
    from ..layers.kernels import BondedLayer, FrictionlessLayer

    if model == "frictionless":
        return FrictionlessLayer()
    if nu in (None, "symbolic"):
        return BondedLayer()
    try:
        val: Any = nu if "/" in nu else float(nu)
    except ValueError as exc:
        raise BadInput(f"--nu {nu!r}: use 'symbolic', an exact fraction such as 3/10, or a number") from exc
    try:
        return BondedLayer(val)
    except (ValueError, TypeError, ArithmeticError) as exc:
        raise BadInput(f"--nu {nu}: {exc}") from exc


def _num(x: Any) -> float | None:
    try:
        return float(x)
    except (TypeError, ValueError):
        return None


def _expr_json(e: Any) -> dict:
    """``{"expr": sympy string, "latex": LaTeX (the normal form of thinlayer.normal), "value": float or null}``."""
    from ..normal import normal_latex
    from ..parse import as_expr

    e = as_expr(e)
    return {"expr": str(e), "latex": normal_latex(e), "value": _num(e) if e.is_number else None}


def _print(obj: Any, as_json: bool) -> None:
    if as_json:
        bad = nonfinite(obj)
        if bad:
            raise BadInput(f"the result {bad} is not a finite number: the inputs are outside the range this "
                           "model can answer")
        print(json.dumps(obj, indent=2, allow_nan=False))
    else:
        print(obj)


def _add_overwrite(p: argparse.ArgumentParser, help: str) -> None:
    """``--overwrite`` (files); ``--force`` is still accepted for it, hidden: in ``solve`` it is the total force."""
    p.add_argument("--overwrite", action="store_true", help=help)
    p.add_argument("--force", dest="overwrite", action="store_true", help=argparse.SUPPRESS)


def _add_output_args(p: argparse.ArgumentParser, latex: bool = True) -> None:
    p.add_argument("--quiet", action="store_true", help="no 'wrote ...' messages (errors still go to stderr)")
    p.add_argument("--json", action="store_true", help="machine-readable JSON output (keys above)")
    if latex:
        p.add_argument("--latex", action="store_true", help="print the LaTeX of the result")


# ---------------------------------------------------------------------------------------------
# subcommands
# ---------------------------------------------------------------------------------------------
def _cmd_report(args) -> int:
    from .derivation import load_derivation, write_report

    der = load_derivation(_derivation_path(args.file))
    tex = write_report(der, args.out, pdf=args.pdf, force=args.overwrite)
    pdf = tex.with_suffix(".pdf") if args.pdf else None
    if args.json:
        _print({"tex": str(tex), "pdf": str(pdf) if pdf else None}, True)
    else:
        if not args.quiet:
            print(f"wrote {tex}" + (f" and {pdf}" if pdf else ""))
            from .report import latex_available, pdf_hint

            if not args.pdf and not latex_available():
                print(pdf_hint(tex))
    return EXIT_OK


def _derivation_path(name: str) -> str | Path:
    """``report FILE``: a bare name (no folder, no suffix) names the catalogue, anything else must exist."""
    from .derivation import DOCUMENTS, catalogue

    path = Path(name)
    bare = path.name == name and not path.suffix and name not in (".", "..")
    if bare:
        cat = catalogue()
        if name in cat:
            return cat[name]
        if name in DOCUMENTS or path.exists():
            return name
        raise BadInput(f"{name}: no derivation of that name; the catalogue has {', '.join([*cat, *DOCUMENTS])} "
                       "(or give the path of a .toml file)")
    if not path.exists() and not path.is_symlink():
        stem = path.stem if path.suffix == ".toml" else ""
        hint = f"; 'thinlayer report {stem}' is the catalogue's" if stem in catalogue() else ""
        raise BadInput(f"{name}: the file does not exist{hint}")
    return path


def _cmd_coefficients(args) -> int:
    from ..layers.coefficients import kernel_coefficients
    from ..layers.moments import kernel_moment

    if args.order < 1 or args.order > 60:
        raise BadInput(f"--order {args.order}: an integer from 1 to 60")
    layer = _layer(args.nu, args.base)
    co = kernel_coefficients(layer, args.order)
    if args.latex:
        print(co.latex())
        return EXIT_OK
    moments = {}
    for n in range(min(args.order, 3) + 1):
        for k in range(n + 1):
            moments[f"mu_{2 * k},{2 * n - 2 * k}"] = _expr_json(kernel_moment(layer, 2 * k, 2 * n - 2 * k))
    out = {"nu": args.nu, "model": args.base, "order": args.order, "A": _expr_json(co.A),
           "m": [_expr_json(x) for x in co.m], "M": [_expr_json(x) for x in co.M], "moments": moments}
    # m[n], M[n] for n = 0..order (m_0 = M_0 = 1)
    if args.json:
        _print(out, True)
    else:  # the normal form in Unicode maths (m_0 = M_0 = 1 are left out)
        nu = "symbolic" if layer.numeric_nu is None and args.base == "bonded" else args.nu
        head = f"coefficients of the {args.base} layer's kernel" + (f", ν = {nu}" if args.base == "bonded" else "")
        print_text("\n".join([f"{head}   (2.4), (2.20), (4.2)", *co.text_lines()[1:]]))
    return EXIT_OK


def _cmd_inner(args) -> int:
    from ..asymptotics.inner import inner_pressure

    layer = _layer(args.nu, args.base)
    punch = punch_from_args(args)
    if args.param:
        punch = punch.subs(punch_params(args.param))
    ip = inner_pressure(layer, punch, args.order)
    if args.latex:
        print(ip.latex())
    elif args.json:
        _print({"punch": str(punch.expr), "nu": args.nu, "order": ip.order,
                "arguments": [a.name for a in ip.arguments],
                "terms": [_expr_json(t) for t in ip.terms],
                "scaled_terms": [_expr_json(t) for t in ip.scaled_terms],
                "pressure": _expr_json(ip.pressure)}, True)
    else:  # the normal form in Unicode maths; the lambdify() line is Python's business, not the shell's
        nu = "symbolic" if layer.numeric_nu is None and args.base == "bonded" else args.nu
        head = (f"inner pressure (2.26): {punch.name} on the {args.base} layer"
                + (f", ν = {nu}" if args.base == "bonded" else "") + f", {ip.order} term{'s' * (ip.order > 1)}")
        lines = [ln for ln in ip.text_lines()[1:] if "lambdify" not in ln]
        print_text("\n".join([head, *lines]))
    return EXIT_OK


def _cmd_errata(args) -> int:
    from .. import errata

    if args.latex:
        print(errata.latex_table())
    elif args.json:
        _print([{"equation": e.equation, "kind": e.kind, "quantity": e.quantity, "printed": e.printed,
                 "derived": e.derived, "evidence": e.evidence} for e in errata.ENTRIES], True)
    else:
        for e in errata.ENTRIES:
            print(f"({e.equation}) [{e.kind}] {e.quantity}\n    printed: {e.printed}\n    derived: {e.derived}")
    return EXIT_OK


def _codegen_result(args):
    """The result object named by ``thinlayer codegen RESULT``."""
    if args.result == "coefficients":
        from ..layers.coefficients import kernel_coefficients

        if args.nu not in (None, "symbolic"):
            raise BadInput("coefficients are generated as functions of nu: leave out --nu")
        return kernel_coefficients(_layer("symbolic"), args.order or 3)
    punch = punch_from_args(args) if args.result not in ("flat-punch", "jkr") else None
    if args.result == "inner":
        from ..asymptotics.inner import inner_pressure

        if args.param:
            punch = punch.subs(punch_params(args.param))
        return inner_pressure(_layer(args.nu or "symbolic"), punch, args.order)
    if args.result == "force":
        from ..asymptotics.force_law import force_law

        if args.param:
            punch = punch.subs(punch_params(args.param))
        if args.order not in (None, 1, 2):
            raise BadInput(f"force: --order {args.order}: 1 (the force law (1.8) and area (3.25), the default) or 2 "
                           "(the second-order laws (SO.9), (SO.10))")
        if args.order == 2:
            return _second_order_law(args, punch)
        return force_law(_layer(args.nu or "symbolic"), punch)
    if args.result in ("incompressible", "two-term"):
        return _nearly_incompressible_result(args, punch)
    if args.result == "flat-punch":
        return _flat_punch_law(args)
    if args.result == "jkr":  # the thin-layer JKR law (J.11), (J.15) of one bonded layer (issue 26 item 5)
        from ..asymptotics.adhesion import thin_layer_jkr

        if args.nu in (None, "symbolic") or args.base != "bonded":
            raise BadInput("jkr: the thin-layer JKR law (J.11) is generated for one bonded layer: give --nu "
                           "(-1 < nu < 1/2, or 1/2: (J.15))")
        from fractions import Fraction

        try:
            nu = float(Fraction(args.nu.strip()))
        except (ValueError, ZeroDivisionError):
            raise BadInput(f"jkr: --nu {args.nu!r} is not a number or a fraction such as 3/10") from None
        if args.order not in (None, 0, 1):
            raise BadInput(f"jkr: --order {args.order}: 0 or 1 (the law's order in H/c, default 1)")
        return thin_layer_jkr(nu, 1 if args.order is None else args.order)
    from ..asymptotics.solution import compressible_solution as solve  # composite: numeric parameters

    if args.nu in (None, "symbolic") or args.delta0 is None or args.H is None:
        raise BadInput("composite needs numeric --nu, --delta0 and --H (and --param values)")
    if args.tip is not None:
        tip_needs_values(punch, args.tip)
    sol = solve(_layer(args.nu), punch, delta0=args.delta0, H=args.H, mu=args.mu,
                parameters=punch_params(args.param), boundary_layer="alexandrov")
    return sol.composite


def _second_order_law(args, punch):
    """``codegen force --order 2``: the force (SO.9) and area (SO.10) of one layer (numeric nu: h^*, r_3 numbers)."""
    from ..asymptotics.second_order import second_order_law

    if args.nu in (None, "symbolic") and args.base == "bonded":
        raise BadInput("force --order 2: give a numeric --nu, e.g. --nu 3/10 (the constants h*, m_1, r_3 of the "
                       "second-order laws are numbers per nu), or --base frictionless")
    layer = _layer(args.nu or "symbolic", "frictionless" if args.base == "frictionless" else "bonded")
    law = second_order_law(layer, punch)
    try:
        law.codegen_expressions()  # refuses a law without closed form (elliptic integrals, a numerical contour)
    except ValueError as exc:
        raise BadInput(f"force --order 2: {exc}") from exc
    return law


def _flat_punch_law(args):
    """``codegen flat-punch``: kappa(a/H) and its estimate of one layer, thin-layer law or thick series."""
    from ..asymptotics.flat_punch import thick_flat_punch, thin_flat_punch

    if args.nu in (None, "symbolic") and args.base == "bonded":
        raise BadInput("flat-punch: give --nu (the laws are generated for one layer), or --base frictionless")
    layer = solve_layer(args.base, args.nu if args.nu not in (None, "symbolic") else "0")
    return thin_flat_punch(layer) if args.law == "thin" else thick_flat_punch(layer)


def _nearly_incompressible_result(args, punch):
    """``codegen incompressible`` (nu = 1/2: (I.11), (I.6)-(I.8), (I.9)) or ``codegen two-term`` (sphere, (I.11))."""
    from ..asymptotics.incompressible import (
        incompressible_axisymmetric,
        incompressible_ellipse,
        two_term_sphere,
    )
    from ..layers.kernels import IncompressibleLayer

    if args.param:
        punch = punch.subs(punch_params(args.param))
    radii = _paraboloid_radii(punch)
    sphere = radii is not None and radii[0] == radii[1]
    if args.result == "two-term":
        if not sphere:
            raise BadInput("two-term: the two-term model (I.10)-(I.11) is derived for the sphere: --tip paraboloid")
        layer = _layer(args.nu or "symbolic")
        nu = layer.numeric_nu
        if nu is not None and not 0.25 < nu < 0.5:
            raise BadInput(f"two-term: --nu {args.nu} is outside 1/4 < nu < 1/2 where the model holds "
                           "('codegen incompressible' for nu = 1/2)")
        return two_term_sphere(layer)
    if args.nu not in (None, "1/2", "0.5"):
        raise BadInput(f"incompressible: the model is nu = 1/2; leave out --nu (got {args.nu})")
    if sphere:
        return two_term_sphere(IncompressibleLayer())
    if radii is not None:
        return incompressible_ellipse(*radii)
    try:
        return incompressible_axisymmetric(punch)
    except (ValueError, TypeError) as exc:
        raise BadInput(f"incompressible: {exc}") from exc


def _paraboloid_radii(punch) -> tuple | None:
    """``(R1, R2)`` when the tip's polynomial is ``x1^2/(2 R1) + x2^2/(2 R2)`` (R1, R2 numbers or parameters: the
    paraboloid ``R1 = R2 = R`` or the elliptic paraboloid with its axes along x1, x2); else None.  Read from the
    tip's :attr:`~thinlayer.punch.Tip.polynomial`, not its name.
    """
    poly = punch.polynomial
    terms = dict(poly.terms()) if poly is not None else {}
    if set(terms) != {(2, 0), (0, 2)}:
        return None
    return 1 / (2 * terms[(2, 0)]), 1 / (2 * terms[(0, 2)])


#: what ``thinlayer codegen`` generates (the choices of RESULT)
CODEGEN_RESULTS = ("inner", "force", "coefficients", "composite", "incompressible", "two-term", "any-thickness",
                   "flat-punch", "nanite", "jkr")
#: the languages of the codegen registry, :data:`thinlayer.export.codegen.LANGUAGES`: written out so that building
#: the parser imports no sympy printer (``thinlayer --help`` stays fast); a test keeps them equal
LANGUAGES = ("c", "fortran", "rust", "julia", "octave", "python")
#: the languages of the tabulated laws (any-thickness, flat-punch --law any-thickness): a numpy module and C
TABULATED_LANGUAGES = ("python", "c")


def _cmd_codegen_any_thickness(args) -> int:
    """``codegen any-thickness`` (the sphere's law (T.7)) or ``codegen flat-punch --law any-thickness`` (the
    flat punch's exact kappa, tabulated) of one (nu, base) as a numpy module or a C file.
    """
    from ..parse import parse_number

    langs = ([x.strip() for x in args.lang.split(",") if x.strip()] if args.lang != "all"
             else list(TABULATED_LANGUAGES))
    bad = [x for x in langs if x not in TABULATED_LANGUAGES]
    if bad or not langs:
        raise BadInput(f"--lang {args.lang!r}: the any-thickness laws are generated in "
                       f"{' and '.join(TABULATED_LANGUAGES)} (numpy module, C file)")
    flat = args.result == "flat-punch"
    if args.nu in (None, "symbolic") and not (flat and args.base == "frictionless"):
        raise BadInput(f"{args.result}: give --nu, a number in (-1, 1/2] (the law is tabulated per nu)")
    if flat:
        from ..contact.flat_punch import flat_punch_source
        from ..layers.kernels import IncompressibleLayer

        layer = solve_layer(args.base, args.nu if args.nu not in (None, "symbolic") else "0")
        if layer.incompressible_at(layer.numeric_nu):
            layer = IncompressibleLayer()
        name = args.name or "thinlayer_flat_punch"
        sources = {lang: flat_punch_source(layer, lang) for lang in langs}
    else:
        from ..contact.any_thickness import any_thickness_source

        nu = float(parse_number(args.nu, "--nu"))
        name = args.name or "thinlayer_any_thickness"
        sources = {lang: any_thickness_source(nu, args.base, lang) for lang in langs}
    if args.out is None:
        if args.json:
            _print([{"language": lang, "source": src} for lang, src in sources.items()], True)
        else:
            for src in sources.values():
                print(src)
        return EXIT_OK
    from ..validation.output import atomic_write, output_lock, refuse_existing

    out_dir = Path(args.out)
    targets = {lang: out_dir / f"{name}.{'py' if lang == 'python' else 'c'}" for lang in langs}
    refuse_existing(targets.values(), args.overwrite)
    with output_lock(out_dir, name, targets.values()):
        refuse_existing(targets.values(), args.overwrite)
        written = [str(atomic_write(targets[lang], src)) for lang, src in sources.items()]
    if args.json:
        _print({"files": written}, True)
    elif not args.quiet:
        print("wrote " + ", ".join(written))
    return EXIT_OK


def _cmd_codegen(args) -> int:
    from .codegen import LANGUAGES, generate

    if args.result == "any-thickness" or (args.result == "flat-punch" and args.law == "any-thickness"):
        return _cmd_codegen_any_thickness(args)
    if args.result == "nanite":
        from .nanite_codegen import cmd_codegen_nanite

        return cmd_codegen_nanite(args)

    langs = list(LANGUAGES) if args.lang == "all" else [x.strip() for x in args.lang.split(",") if x.strip()]
    bad = [x for x in langs if x not in (*LANGUAGES, "matlab")]
    if bad or not langs:
        raise BadInput(f"--lang {args.lang!r}: choose from {', '.join(LANGUAGES)} (comma-separated) or 'all'")
    result = _codegen_result(args)
    codes = [generate(result, lang, name=args.name) for lang in langs]
    if args.out is None:
        if args.json:
            _print([{"language": c.language, "function": c.function_name, "arguments": list(c.arguments),
                     "outputs": list(c.outputs), "files": dict(c.files)} for c in codes], True)
        else:
            for c in codes:
                print(c.source)
        return EXIT_OK
    from ..validation.output import output_lock, refuse_existing

    out_dir = Path(args.out)
    targets = [out_dir / fname for c in codes for fname in c.files]
    refuse_existing(targets, args.overwrite)  # every file checked before any is written
    written = []
    with output_lock(out_dir, codes[0].function_name, targets):
        refuse_existing(targets, args.overwrite)
        for c in codes:
            written += [str(p) for p in c.write(out_dir, force=True)]
    if args.json:
        _print({"files": written}, True)
    else:
        if not args.quiet:
            print("wrote " + ", ".join(written))
    return EXIT_OK


# ---------------------------------------------------------------------------------------------
# the parser
# ---------------------------------------------------------------------------------------------
def _add_report(sub: Any, fmt: type) -> None:
    r = sub.add_parser("report", aliases=["derive"], formatter_class=fmt,
                       help="carry out a derivation file and write its LaTeX report (and PDF)",
                       description="Carry out a derivation file (derivations/*.toml) and write <out>/<name>.tex.\n"
                                   "JSON keys: tex, pdf (null without --pdf).",
                       epilog="examples:\n"
                              "  thinlayer report sphere --out thinlayer-out --pdf --overwrite   # a catalogue name\n"
                              "  thinlayer report derivations/quartic_punch.toml --out thinlayer-out   # a file\n"
                              "  thinlayer report errata --out thinlayer-out     # the whole errata registry")
    r.add_argument("file", help="a catalogue name (sphere, elliptic_paraboloid, ...: the derivation files shipped "
                                "with thinlayer), the path of a derivation file (it must exist), or errata (the whole "
                                "errata registry as one document)")
    r.add_argument("--out", default="thinlayer-out",
                   help="output folder, created if missing (default: thinlayer-out)")
    r.add_argument("--pdf", action="store_true",
                   help="also compile the report (pdflatex; shell escape off, reading and writing only in its "
                        "temporary folder)")
    _add_overwrite(r,
                   help="overwrite existing files: a .tex that was not written by thinlayer or was edited since, "
                        "a PDF, a log, figures (default: refuse, before anything is written)")
    _add_output_args(r, latex=False)
    r.set_defaults(func=_cmd_report)


def _add_coefficients(sub: Any, fmt: type) -> None:
    c = sub.add_parser("coefficients", formatter_class=fmt, help="A, m_n (2.20), M_k (4.2) and kernel moments (2.21)",
                       description="Coefficients of the layer kernel's expansions.\n"
                                   "JSON keys: nu, model, order, A, m (list m_0..m_order), M (list M_0..M_order), "
                                   "moments "
                                   "({'mu_i,j': ...}); every value is {expr, latex, value (float or null)}.",
                       epilog="examples:\n  thinlayer coefficients --nu 3/10 --order 4 --json\n"
                              "  thinlayer coefficients --order 2 --latex     # symbolic nu")
    c.add_argument("--nu", default="symbolic", help="'symbolic' (default), an exact fraction like 3/10, or a number")
    base_arg(c, "base of the layer: bonded (default) or frictionless", old="--model")
    c.add_argument("--order", type=_order, default=3, help="number of coefficients m_1..m_order (default 3)")
    _add_output_args(c)
    c.set_defaults(func=_cmd_coefficients)


def _add_inner(sub: Any, fmt: type) -> None:
    i = sub.add_parser("inner", formatter_class=fmt, help="inner expansion of the contact pressure (2.26), (4.1)",
                       description="Inner expansion p_0 + p_1 + ... for a punch.\n"
                                   "JSON keys: punch, nu, order, arguments, terms, scaled_terms, pressure "
                                   "(each {expr, latex, value}).",
                       epilog="examples:\n  thinlayer inner --tip elliptic_paraboloid --latex\n"
                              "  thinlayer inner --punch 'x_1**2/2 + x_2**4' --nu 3/10 --json")
    i.add_argument("--nu", default="symbolic", help="'symbolic' (default), an exact fraction, or a number")
    base_arg(i, "base of the layer: bonded (default) or frictionless", old="--model")
    i.add_argument("--order", type=_order, default=None, help="number of terms (default: degree//2 + 1)")
    add_punch_args(i)
    _add_output_args(i)
    i.set_defaults(func=_cmd_inner)


def _add_errata(sub: Any, fmt: type) -> None:
    e = sub.add_parser("errata", formatter_class=fmt, help="the misprints found by re-deriving the paper",
                       description="The errata registry.\nJSON: a list of {equation, kind, quantity, printed, "
                                   "derived, evidence}.",
                       epilog="example:\n  thinlayer errata --json")
    _add_output_args(e)
    e.set_defaults(func=_cmd_errata)


def _add_codegen(sub: Any, fmt: type) -> None:
    g = sub.add_parser("codegen", formatter_class=fmt, help="generate C, Fortran, Rust, Julia, Octave or Python code",
                       description="Generate functions from a result: 'inner' (pressure (2.26)), 'force' (force "
                                   "law (1.8) and contact area; --order 2: the second-order laws (SO.9), (SO.10)\n"
                                   "of one nu, sphere or radial monomial c r^2k), 'coefficients' (A, m_n, M_k of "
                                   "nu), 'composite' "
                                   "(composite pressure, radial punch, Alexandrov boundary layer, numeric "
                                   "parameters), 'incompressible' (nu = 1/2: force, contact size, pressure of "
                                   "the sphere (I.11),\nthe elliptic paraboloid (I.6)-(I.8), an axisymmetric punch "
                                   "(I.9)), 'two-term' (the sphere near nu = 1/2 (I.11);\nBessel functions: Julia "
                                   "and Octave), 'any-thickness' (the sphere at any H/a (T.7), one nu: numpy module "
                                   "or C), 'flat-punch' (kappa(a/H) of a flat punch, --law thin|thick, one nu),\n"
                                   "'nanite' (a standalone nanite model module at any thickness, one nu and base: "
                                   "--tip sphere, cone or pyramid with --sides 3|4), 'jkr' (the thin-layer JKR law of "
                                   "the sphere (J.11), delta0 and force at the contact radius c, one bonded nu; "
                                   "--order 0 or 1).\n"
                                   "Without --out the code is printed. JSON keys: a list of "
                                   "{language, function, arguments, outputs, files}; with --out: {files}.",
                       epilog="examples:\n  thinlayer codegen inner --tip elliptic_paraboloid --nu 3/10 --lang c\n"
                              "  thinlayer codegen force --tip paraboloid --lang all --out gen\n"
                              "  thinlayer codegen force --order 2 --tip paraboloid --nu 3/10 --lang c,python\n"
                              "  thinlayer codegen coefficients --order 2 --lang fortran,rust --json\n"
                              "  thinlayer codegen composite --tip paraboloid:R=2 --nu 0.3 "
                              "--delta0 0.25 --H 0.02 --lang python\n"
                              "  thinlayer codegen incompressible --tip elliptic_paraboloid --lang c,python\n"
                              "  thinlayer codegen two-term --tip paraboloid --nu 0.45 --lang julia\n"
                              "  thinlayer codegen any-thickness --nu 0.45 --lang python,c --out gen\n"
                              "  thinlayer codegen nanite --tip sphere --base frictionless --nu 0.45 --out gen")
    g.add_argument("result", choices=CODEGEN_RESULTS, help="what to generate")
    g.add_argument("--law", choices=("thin", "thick", "any-thickness"), default="thin",
                   help="flat-punch: the thin-layer law (F.12)-(F.16), the thick series (F.18), or the exact kappa "
                        "tabulated for 0.001 <= a/H <= 200 (python, c) (default thin)")
    base_arg(g, "base of the layer (any-thickness, flat-punch, force --order 2; default bonded)")
    g.add_argument("--lang", default="c", help=f"comma-separated languages of thinlayer.export.codegen.LANGUAGES "
                                               f"({', '.join(LANGUAGES)}) or 'all' (default c; any-thickness and "
                                               f"flat-punch --law any-thickness: {', '.join(TABULATED_LANGUAGES)})")
    g.add_argument("--out", help="write the files into this folder (created) instead of printing")
    _add_overwrite(g, help="overwrite existing files in --out (default: refuse, before anything is written)")
    g.add_argument("--name", help="function name (default from the result)")
    g.add_argument("--nu", default=None, help="Poisson ratio: 'symbolic' (default), a fraction or a number")
    g.add_argument("--order", type=_order, default=None,
                   help="inner terms / number of coefficients; force: 1 (default) or 2 (second order)")
    g.add_argument("--delta0", type=finite, help="indentation (composite)")
    g.add_argument("--H", type=finite, help="layer thickness (composite)")
    g.add_argument("--mu", type=finite, default=1.0, help="shear modulus (composite, default 1)")
    g.add_argument("--sides", type=int, choices=(3, 4), default=None, help="nanite --tip pyramid: 3 or 4 faces "
                                                                           "(default 4)")
    add_punch_args(g)
    _add_output_args(g, latex=False)
    g.set_defaults(func=_cmd_codegen)


def _version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("thinlayer")
    except PackageNotFoundError:  # run from a source tree that was never installed
        return "unknown (not installed)"


def build_parser() -> argparse.ArgumentParser:
    """The ``thinlayer`` argument parser: one subcommand per stage of the work.

    Returns
    -------
    argparse.ArgumentParser
        With the subcommands report (alias derive), coefficients, inner, solve, errata, codegen and
        validate (from :mod:`thinlayer.validation`); each sets ``func``, its handler.
    """
    from ..validation import add_cli as add_validate

    fmt = argparse.RawDescriptionHelpFormatter
    ap = _Parser(
        prog="thinlayer", formatter_class=fmt,
        description="Symbolic asymptotics of a rigid punch pressed into a thin elastic layer.",
        epilog="examples:\n"
               "  thinlayer report elliptic_paraboloid --out thinlayer-out --pdf --overwrite\n"
               "  thinlayer coefficients --nu 3/10 --order 4 --json\n"
               "  thinlayer solve --nu 0.3 --tip elliptic_paraboloid:R1=4,R2=1 "
               "--delta0 0.5 --H 0.05 --E 2.6\n\n"
               "exit codes: 0 success, 2 bad input (one-line reason on stderr), 1 other failure,\n"
               "130 Ctrl-C, 143 SIGTERM, 141 output pipe closed")
    ap.add_argument("--version", action="version", version=f"thinlayer {_version()}")
    sub = ap.add_subparsers(dest="cmd", required=True, metavar="COMMAND")
    from .fit_cli import add_fit_parser
    from .flat_cli import add_flat_parser
    from .map_cli import add_map_parser
    from .solve_cli import add_solve_parser

    for add in (_add_report, _add_coefficients, _add_inner, add_solve_parser, _add_errata, _add_codegen):
        add(sub, fmt)
    add_validate(sub, fmt)
    add_fit_parser(sub, fmt)
    add_flat_parser(sub, fmt)
    add_map_parser(sub, fmt)
    from .visco_cli import add_visco_parser

    add_visco_parser(sub, fmt)
    return ap


@functools.lru_cache(maxsize=1)
def _parser() -> argparse.ArgumentParser:
    """:func:`build_parser` once per process (15 ms of argparse per call; parsing leaves the parser unchanged)."""
    return build_parser()


def _one_line(exc: BaseException) -> str:
    text = str(exc).strip()
    if isinstance(exc, OSError) and exc.strerror:
        text = f"{exc.strerror}: {exc.filename}" if exc.filename else exc.strerror
    if isinstance(exc, KeyError):
        text = f"missing {text}"
    line = text.splitlines()[0] if text else type(exc).__name__
    return line if len(line) <= 500 else line[:480] + " ..."


def _on_sigterm(signum, frame):  # pragma: no cover - exercised in a subprocess
    raise Terminated()


def main(argv: list[str] | None = None) -> int:
    """Run the command line and return its exit code.

    Parameters
    ----------
    argv : list of str, optional
        The arguments after ``thinlayer`` (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        0 success, 2 bad input, 1 any other failure (each a one-line reason on stderr), 130 Ctrl-C,
        143 SIGTERM, 141 closed output pipe.
    """
    ap = _parser()
    try:
        args = ap.parse_args(argv)
    except SystemExit as exc:  # --help (0) or a one-line argparse error (2)
        return exc.code if isinstance(exc.code, int) else EXIT_BAD_INPUT
    old = None
    if hasattr(signal, "SIGTERM"):
        try:
            old = signal.signal(signal.SIGTERM, _on_sigterm)
        except ValueError:  # not the main thread: leave the handler alone
            old = None
    try:
        func = args.func  # by its module's current name: a handler replaced after the parser was built is called
        home = sys.modules.get(getattr(func, "__module__", ""), None)
        code = getattr(home, getattr(func, "__name__", ""), func)(args)
        sys.stdout.flush()
        note = getattr(args, NOTE, None)
        if code == EXIT_OK and note:  # a deprecated option: one line after the output (error runs keep one line)
            _err(f"note: {note}")
        return code
    except BrokenPipeError:
        _silence_stdout()
        return EXIT_BROKEN_PIPE
    except KeyboardInterrupt:
        _err("interrupted (Ctrl-C); temporary files removed, nothing half-written")
        return EXIT_INTERRUPTED
    except Terminated:
        _err("terminated (SIGTERM); temporary files removed, nothing half-written")
        return EXIT_TERMINATED
    except RecursionError as exc:
        _err(f"the input nests too deeply ({_one_line(exc)})")
        return EXIT_BAD_INPUT
    except (ValueError, TypeError, ArithmeticError, NotImplementedError, KeyError, OSError) as exc:
        from .solve_cli import cli_words

        _err(cli_words(_one_line(exc)))
        return EXIT_BAD_INPUT
    except MemoryError:
        _err("out of memory: choose a smaller order, degree or grid")
        return EXIT_FAILURE
    except Exception as exc:  # noqa: BLE001 - the last line of defence: one line, never a traceback
        _err(f"{_one_line(exc)}" if isinstance(exc, RuntimeError) else
             f"internal error ({type(exc).__name__}: {_one_line(exc)}); please report it")
        return EXIT_FAILURE
    finally:
        if old is not None:
            signal.signal(signal.SIGTERM, old)


def _err(msg: str) -> None:
    try:
        print(f"thinlayer: {msg}", file=sys.stderr, flush=True)
    except (BrokenPipeError, OSError):  # pragma: no cover - stderr gone too
        pass


def _silence_stdout() -> None:
    """After a closed pipe: point stdout at /dev/null so that the flush at exit raises nothing."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError, AttributeError):  # pragma: no cover - stdout is no real file (tests)
        pass


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
