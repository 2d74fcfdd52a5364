"""``thinlayer solve``: force, contact size and pressure of one contact, or of a sweep, as text, JSON or CSV.

:func:`add_solve_parser` adds the subcommand to the ``thinlayer`` parser, :func:`cmd_solve` runs it.

* **Text** is Unicode maths (``Φ = x₁²/8 + x₂²/2``, ``ν``, ``δ₀``): the punch and the layer once, the numbers
  with their estimates once, the model with its equations and why it holds.  The models tried before it
  and why each was rejected are printed only with ``--verbose``.
* **Sweeps.** ``--delta0``, ``--force`` and ``--H`` each take one number, ``START:STOP:COUNT`` (COUNT values
  evenly spaced from START to STOP, *both ends included*, like ``numpy.linspace``) or a comma list
  (``0.1,0.2,0.5``).  One option is swept at a time, with at most :data:`MAX_SWEEP` values; a longer sweep is
  refused before anything is solved.  Every value is one :func:`thinlayer.solve` call in this process; the
  first value that fails stops the command with one line naming the value, and nothing is written.
* **Files.** ``--format csv|json`` (or ``--json``) and ``--output FILE``; an existing file is replaced only
  with ``--overwrite`` (checked before the first solve, written atomically at the end).
"""
from __future__ import annotations

import argparse
import csv
import io
import json
import math
import re
import sys
from pathlib import Path
from typing import Any

__all__ = ["MAX_SWEEP", "add_solve_parser", "cmd_solve", "parse_values", "pretty", "cli_words"]

#: the most values of one sweep (refused before the first solve)
MAX_SWEEP = 1000
#: the options that may be swept
SWEPT = ("delta0", "force", "H")
#: the --model choices: the public names of the model registry (thinlayer.contact.models.model_names(), which
#: imports the models), written out so that ``thinlayer --help`` imports none; a test keeps them equal
MODEL_CHOICES = ("auto", "asymptotic", "compressible", "tip-law", "two-term", "incompressible", "any-thickness",
                 "direct")
#: every name a reason may start a segment with (the models of solve() and the flat punch's)
_REASON_NAMES = ("compressible", "tip-law", "two-term", "incompressible", "any-thickness", "direct", "thin-layer",
                 "thick-layer", "exact")
#: the CSV columns, in order (``semi_axis_1``/``_2`` split ``semi_axes``)
CSV_COLUMNS = ("delta0", "force", "contact_area", "contact_radius", "semi_axis_1", "semi_axis_2", "max_pressure",
               "H", "H_over_a", "mu", "E", "nu", "layer", "model", "error_force", "error_contact_area",
               "error_contact_radius", "tol")


# ---------------------------------------------------------------------------------------------
# values and sweeps
# ---------------------------------------------------------------------------------------------
def _number(text: str, what: str) -> float:
    try:
        val = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{what}{text.strip()!r} is not a number") from None
    if not math.isfinite(val):
        raise argparse.ArgumentTypeError(f"{what}{text.strip()!r} is not a finite number")
    return val


def parse_values(text: str) -> float | list[float]:
    """One number, or the values of a sweep: ``START:STOP:COUNT`` (both ends included) or ``A,B,C``.

    Raises
    ------
    argparse.ArgumentTypeError
        One line: a value that is not a finite number, a count that is not an integer from 1 to
        :data:`MAX_SWEEP`, or a list longer than :data:`MAX_SWEEP`.

    Examples
    --------
    >>> parse_values("0.5"), parse_values("0:1:5"), parse_values("0.1, 0.2")
    (0.5, [0.0, 0.25, 0.5, 0.75, 1.0], [0.1, 0.2])
    """
    if ":" in text:
        parts = text.split(":")
        if len(parts) != 3:
            raise argparse.ArgumentTypeError(f"{text!r}: write START:STOP:COUNT, e.g. 0.01:1:100")
        start, stop = _number(parts[0], "START "), _number(parts[1], "STOP ")
        try:
            count = int(parts[2])
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r}: COUNT {parts[2].strip()!r} is not an integer") from None
        if not 1 <= count <= MAX_SWEEP:
            raise argparse.ArgumentTypeError(f"{text!r}: COUNT {count} values; a sweep has 1 to {MAX_SWEEP} values")
        if count == 1:
            return [start]
        step = (stop - start) / (count - 1)
        return [start + k * step for k in range(count - 1)] + [stop]
    if "," in text:
        items = [t for t in text.split(",") if t.strip()]
        if not items:
            raise argparse.ArgumentTypeError(f"{text!r}: give comma-separated numbers")
        if len(items) > MAX_SWEEP:
            raise argparse.ArgumentTypeError(f"{len(items)} values; a sweep has at most {MAX_SWEEP} values")
        return [_number(t, "") for t in items]
    return _number(text, "")


def _solve_order(text: str) -> int:
    """``--order``: 1 (the first-order laws (1.8), (3.25)) or 2 (the second order (SO.9), (SO.10))."""
    if text.strip() not in ("1", "2"):
        raise argparse.ArgumentTypeError(f"must be 1 or 2 (the order of the thin-layer laws), got {text!r}")
    return int(text)


def _tolerance(text: str) -> float:
    """``--tol``: a relative tolerance in (0, 1]."""
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a number in (0, 1], got {text!r}") from None
    if not (0 < v <= 1):
        raise argparse.ArgumentTypeError(f"must be a number in (0, 1], got {text!r}")
    return v


# ---------------------------------------------------------------------------------------------
# text: Unicode maths, and the library's keywords as command-line options
# ---------------------------------------------------------------------------------------------
_SUP = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
_PRETTY = [
    (re.compile(r"sqrt\(R delta0\)"), "√(Rδ₀)"),
    (re.compile(r"sqrt\(R delta\)"), "√(Rδ)"),
    (re.compile(r"(?<![-\w])delta\b"), "δ"),
    (re.compile(r"\bchi_max\b"), "χ_max"),
    (re.compile(r"(?<![-\w])(?:delta0|delta_0)\b"), "δ₀"),
    (re.compile(r"(?<![-\w])nu\b"), "ν"),
    (re.compile(r"(?<![-\w])mu\b"), "μ"),
    (re.compile(r"\bchi\b"), "χ"),
    (re.compile(r"\blambda\^2"), "λ²"),
    (re.compile(r"\blambda\b"), "λ"),
    (re.compile(r"\bkappa\b"), "κ"),
    (re.compile(r"\bvartheta\b"), "ϑ"),
    (re.compile(r"\b([mMPwr])([0-9])\b"), lambda m: m.group(1) + "₀₁₂₃₄₅₆₇₈₉"[int(m.group(2))]),
    (re.compile(r"\^\(?(-?[0-9]+)\)?"), lambda m: m.group(1).translate(_SUP)),
    (re.compile(r" <= "), " ≤ "),
    (re.compile(r" >= "), " ≥ "),
    (re.compile(r"\+-"), "±"),
    (re.compile(r"(?<=\d) x (?=\w)"), " × "),
]


def pretty(text: str) -> str:
    """A line of the library's ASCII text in Unicode maths: ``nu`` -> ``ν``, ``delta0`` -> ``δ₀``, ``<=`` -> ``≤``.

    Command-line options (``--nu``, ``--delta0``) are left alone.

    >>> pretty("nu = 0.49 < 1/2; chi = sqrt(R delta0)/H = 2; lambda^2 = (a/H)^2/m1, --nu")
    'ν = 0.49 < 1/2; χ = √(Rδ₀)/H = 2; λ² = (a/H)²/m₁, --nu'
    """
    for pat, rep in _PRETTY:
        text = pat.sub(rep, text)
    return text


def _model_list(m: re.Match) -> str:
    names = re.findall(r"'([\w-]+)'", m.group(0))
    return " or ".join(f"--model {n}" for n in names)


#: a parenthesis of Python names after a Python name, e.g. ``(regime(), solve_obstacle_grid)`` (none with ``=``)
_PY_NOTE = r"(?: \([^()=]*(?:\(\)[^()=]*)*\))?"
_WORDS = [
    (re.compile(r"^solve\(\): "), ""),
    (re.compile(r"pass parameters=\{([^}]*)\} or Punch\.subs\(\.\.\.\)"),
     lambda m: "give " + " ".join(f"--param {n}=VALUE" for n in re.findall(r"'(\w+)'", m.group(1)))),
    (re.compile(r"\(?parameters=\{\.\.\.\}\)?"), "(--param NAME=VALUE)"),
    (re.compile(r"model=(['\"])[\w-]+\1(?:(?:,| or|, or) (?:model=)?'[\w-]+')*(?: \(or '[\w-]+'\))?"),
     lambda m: _model_list(m)),
    (re.compile(r"\bboundary_layer='(\w+)'"), r"--boundary-layer \1"),
    (re.compile(r"\buse order=(\d)"), r"use --order \1"),
    (re.compile(r"\bbase='(\w+)'"), r"--base \1"),
    (re.compile(r"\bpass nu= "), "give --nu "),
    (re.compile(r"\bgive n= explicitly, or\b"), "give"),
    (re.compile(r"the direct numerical solver thinlayer\.[\w.]+" + _PY_NOTE),
     "the direct numerical solver (--model direct)"),
    (re.compile(r"the two-term/incompressible model thinlayer\.[\w.]+" + _PY_NOTE),
     "the two-term or incompressible model (--model two-term, --model incompressible)"),
    (re.compile(r"^(delta0|force|H|mu|E|tol|nu|order) must be"), r"--\1 must be"),
    (re.compile(r"\btol =? ?([0-9.]+(?:e-?\d+)?) %"), lambda m: f"--tol {float(m.group(1)) / 100:g}"),
]


def cli_words(text: str) -> str:
    """A library message in the command line's words: ``model='auto'`` -> ``--model auto``, ``parameters={'R':
    ...}`` -> ``--param R=VALUE``, ``delta0 must be`` -> ``--delta0 must be``, ``tol 5 %`` -> ``--tol 0.05``.

    >>> cli_words("solve(): the two-term model's estimates exceed tol 5 %; use model='auto' or model='direct'")
    "the two-term model's estimates exceed --tol 0.05; use --model auto or --model direct"
    >>> cli_words("the punch has parameters R without values; pass parameters={'R': ...} or Punch.subs(...)")
    'the punch has parameters R without values; give --param R=VALUE'
    """
    for pat, rep in _WORDS:
        text = pat.sub(rep, text)
    return text


def _segments(reason: str) -> list[str]:
    """A reason of solve() cut into its models: ``["compressible: ...", "two-term: ...", "direct: ..."]``."""
    names = "|".join(map(re.escape, _REASON_NAMES))
    return [s for s in re.split(rf"; (?=(?:{names}): )", reason) if s]


def _own_reason(segment: str, model: str, tol: float) -> str:
    """The chosen model's reason without what the lines above already say (its estimates, a/H)."""
    text = segment.split(": ", 1)[1] if segment.startswith(f"{model}: ") else segment
    text = re.sub(r"^estimates? .*? within tol [0-9.e+-]+ %", f"every estimate within --tol {tol:g}", text)
    text = re.sub(r",? estimate \([A-Z]?\.?\d+\) [0-9.e+-]+", "", text)  # 'estimate (F.16) 0.013'
    text = re.sub(r"[;,] estimates? [^)]*", "", text)  # '(table; estimates force 7e-05, radius 7.2e-05)'
    text = re.sub(r" at a/H = [0-9.e+-]+", "", text)
    text = text.replace(f"{model} law", "law").replace(f"{model} series", "series")
    return text.strip()


def _own_size(segment: str) -> str:
    """A rejected model's H/a is measured with its own contact size: say so (it differs from the answer's)."""
    return re.sub(r"\bH/a = ([0-9.e+-]+)", r"H/a = \1 with its own contact size", segment, count=1)


def _g(x: float, digits: int = 8) -> str:
    return f"{x:.{digits}g}"


def _pct(x: float | None) -> str:
    if x is None or not math.isfinite(x):
        return ""
    return f"± {100 * x:.2g} %"


def expr_missing(punch: Any) -> bool:
    """Whether a tip has no formula to print (its description says what it is)."""
    return getattr(punch, "expr", None) is None


#: the names of the catalogue radii as :func:`thinlayer.normal.symbol_text` prints them (a test holds them equal)
RADIUS_TEXT = {"R1": "R₁", "R_1": "R₁", "R2": "R₂", "R_2": "R₂"}


def _punch_text(punch: Any, params: dict[str, float] | None = None) -> str:
    """The punch once: its name and Φ in Unicode maths with its parameters' values, or its own description."""
    formula = getattr(punch, "formula_text", None)
    if formula is not None:  # a catalogue punch with numbers: its symbolic Phi, printed without sympy
        given = params or getattr(punch, "formula_values", None) or {}  # --param, or the numbers of --tip
        values = "".join(f", {RADIUS_TEXT.get(k, k)} = {_g(v)}" for k, v in given.items())
        return f"{punch.name}, Φ = {formula}{values}"
    from ..normal import normal_text, symbol_text

    desc = getattr(punch, "description", None)
    if isinstance(desc, str) and desc and (getattr(punch, "fixed_contact", False) or expr_missing(punch)):
        return pretty(desc)
    expr = getattr(punch, "expr", None)
    if expr is None:
        return str(punch.name)
    if getattr(punch, "polynomial", True) is None:  # a tip of revolution that is no polynomial: Φ(r)
        try:
            return f"{punch.name}, Φ(r) = {normal_text(getattr(punch, 'radial_expr', expr))}"
        except Exception:  # noqa: BLE001 - a form the printer does not know: the tip's own words
            return pretty(str(desc).replace("Phi", "Φ"))
    values = "".join(f", {symbol_text(k)} = {_g(v)}" for k, v in (params or {}).items())
    return f"{punch.name}, Φ = {normal_text(expr)}{values}"


def _layer_text(ans: Any, base: str) -> str:
    return (f"{base} layer, ν = {_g(ans.nu, 6)}, H = {_g(ans.H, 6)}, μ = {_g(ans.mu, 6)} (E = {_g(ans.E, 6)})")


def text_lines(ans: Any, base: str, given: str, verbose: bool = False, punch_line: str | None = None) -> list[str]:
    """The text of one answer: punch, layer, numbers with estimates, model; ``verbose``: the models tried."""
    est = ans.error_estimate
    tf, ta = ans.equations
    depth = f"  depth          δ₀ = {_g(ans.delta0)}" + ("   (given)" if given == "delta0" else "")
    force = f"  force           P = {_g(ans.force)}   {_pct(est.get('force'))}" + ("   (given)" if given == "force"
                                                                                      else f"   ({tf})")
    lines = [punch_line or _punch_text(ans.punch), _layer_text(ans, base), depth, force,
             f"  contact area  |ω| = {_g(ans.contact_area)}   {_pct(est.get('contact_area'))}   ({ta})"]
    if ans.contact_radius is not None:
        lines.append(f"  contact radius  c = {_g(ans.contact_radius)}   {_pct(est.get('contact_radius'))}")
    if ans.semi_axes is not None:
        lines.append(f"  semi-axes  a₁, a₂ = {_g(ans.semi_axes[0])}, {_g(ans.semi_axes[1])}")
    lines.append(f"  H/a = {ans.H_over_a:.3g}")
    segs = _segments(ans.reason)
    own = _own_reason(segs[-1] if segs else ans.reason, ans.model, ans.tol)
    tried = segs[:-1]
    lines.append(f"model: {ans.model}" + (f", {pretty(cli_words(own))}" if own else ""))
    if verbose:
        lines += [f"  rejected {pretty(cli_words(_own_size(s)))}" for s in tried] or [
            "  (no model was tried before it)"]
    elif tried:
        lines.append(f"  ({len(tried)} model{'s' if len(tried) > 1 else ''} tried before it: --verbose says why "
                     "each was rejected)")
    lines += [f"FLAG: {pretty(cli_words(f))}" for f in ans.flags]
    return [ln.rstrip() for ln in lines]


# ---------------------------------------------------------------------------------------------
# rows, CSV and JSON
# ---------------------------------------------------------------------------------------------
def _row(ans: Any, base: str, detail: bool, max_pressure: bool = True) -> dict[str, Any]:
    """The JSON object of one answer (``detail``: the compressible model's own terms too; without
    ``max_pressure`` that key is null: sampling the pressure takes about a second per answer).
    """
    if max_pressure:
        out = ans.as_dict()
    else:
        out = {"model": ans.model, "reason": ans.reason, "force": ans.force, "delta0": ans.delta0,
               "contact_area": ans.contact_area, "contact_radius": ans.contact_radius,
               "semi_axes": list(ans.semi_axes) if ans.semi_axes else None, "max_pressure": None,
               "H": ans.H if math.isfinite(ans.H) else None, "mu": ans.mu, "E": ans.E, "nu": ans.nu,
               "H_over_a": ans.H_over_a if math.isfinite(ans.H_over_a) else None,
               "error_estimate": dict(ans.error_estimate), "tol": ans.tol, "flags": list(ans.flags)}
    out["layer"] = base
    if detail and ans.model == "compressible":  # the expansion's own terms (1.8), (3.25)
        sol = ans.detail
        v = sol.values
        out.update({"force_leading": v.P0, "force_correction": v.P1, "contact_area_leading": v.area0,
                    "perimeter": v.perimeter, "edge_shift_exact": sol.edge_shift,
                    "edge_shift_alexandrov": sol.edge_shift_alexandrov,
                    "remainder": {k: {"statement": t, "relative_size": e}
                                  for k, (t, e) in sol.order_of_accuracy.items()}})
        if getattr(sol, "order", 1) == 2:
            out.update({"order": 2, "force_second_correction": float(sol.P2)})
    return out


def _csv_row(d: dict[str, Any]) -> list[Any]:
    axes = d.get("semi_axes") or [None, None]
    est = d.get("error_estimate") or {}
    flat = {**d, "semi_axis_1": axes[0], "semi_axis_2": axes[1], "error_force": est.get("force"),
            "error_contact_area": est.get("contact_area"), "error_contact_radius": est.get("contact_radius")}
    return ["" if flat.get(c) is None else (repr(flat[c]) if isinstance(flat[c], float) else flat[c])
            for c in CSV_COLUMNS]


def to_csv(rows: list[dict[str, Any]]) -> str:
    """The rows as CSV: a header of :data:`CSV_COLUMNS`, numbers to full precision (``repr``)."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(CSV_COLUMNS)
    for d in rows:
        w.writerow(_csv_row(d))
    return buf.getvalue()


def _table(answers: list[Any], swept: str) -> list[str]:
    head = ["δ₀", "P", "|ω|", "c", *(["H"] if swept == "H" else []), "H/a", "model", "± P"]
    rows = []
    for a in answers:
        rows.append([_g(a.delta0), _g(a.force), _g(a.contact_area),
                     "" if a.contact_radius is None else _g(a.contact_radius),
                     *([_g(a.H, 6)] if swept == "H" else []), f"{a.H_over_a:.3g}", a.model,
                     f"{100 * a.error_estimate['force']:.2g} %"])
    widths = [max(len(r[k]) for r in [head, *rows]) for k in range(len(head))]
    fmt_row = lambda r: "  ".join(c.ljust(w) if h == "model" else c.rjust(w)  # noqa: E731
                                  for c, w, h in zip(r, widths, head)).rstrip()
    return [fmt_row(head), *map(fmt_row, rows)]


# ---------------------------------------------------------------------------------------------
# the subcommand
# ---------------------------------------------------------------------------------------------
def add_solve_parser(sub: Any, fmt: type) -> argparse.ArgumentParser:
    """Add ``solve`` to the ``thinlayer`` subcommands; the handler is :func:`cmd_solve`."""
    from .cli_args import add_punch_args, add_tip_shortcuts, base_arg

    s = sub.add_parser(
        "solve", formatter_class=fmt, help="force, contact size and pressure for numeric parameters (or a sweep)",
        description="Force, contact area and contact radius by the model that holds (thinlayer.solve):\n"
                    "the compressible expansion, the two-term or incompressible model near nu = 1/2, the\n"
                    "any-thickness law of the sphere, or the direct numerical solver.\n"
                    "Sweeps: --delta0, --force or --H as START:STOP:COUNT (COUNT values from START to STOP, both\n"
                    f"ends included) or a comma list; one option swept, at most {MAX_SWEEP} values.\n"
                    "JSON keys (--json or --format json): model, reason, force, delta0, contact_area, "
                    "contact_radius,\nsemi_axes, max_pressure, H, mu, E, nu, H_over_a, error_estimate (relative), "
                    "tol, layer; with the\ncompressible model also force_leading, force_correction, "
                    "contact_area_leading, perimeter,\nedge_shift_exact, edge_shift_alexandrov, remainder; with "
                    "--order 2 also order, force_second_correction\n(P_2 of (SO.9)). A sweep: {swept, rows: [...]} "
                    "(max_pressure null "
                    "without --max-pressure). "
                    f"CSV columns: {', '.join(CSV_COLUMNS)}.",
        epilog="examples:\n"
               "  thinlayer solve --nu 0.3 --tip paraboloid:R=10 --delta0 0.1 --H 0.1 --E 2 --json\n"
               "  thinlayer solve --base frictionless --nu 0.5 --punch 'x_1**2/8 + x_2**2/2' --force 100 --H 0.05 "
               "--mu 1\n"
               "  thinlayer solve --tip flat:a=1 --nu 0.3 --delta0 0.01 --H 0.5 --E 2.6\n"
               "  thinlayer solve --nu 0.3 --tip paraboloid:R=10 --delta0 0.1 --H 0.05 --mu 1 --order 2\n"
               "  thinlayer solve --nu 0.49 --tip paraboloid:R=10 --delta0 0.1 --H 0.5 --mu 1 --verbose\n"
               "  thinlayer solve --nu 0.3 --tip paraboloid:R=10 --delta0 0.01:1:100 --H 0.1 --E 2 "
               "--format csv\n"
               "  thinlayer solve --nu 0.45 --tip paraboloid:R=10 --delta0 0.1 --H 0.05,0.1,0.5,2 --mu 1\n"
               "  thinlayer solve --nu 0.3 --cone 70 --delta0 1 --H 0.1 --E 2\n"
               "  thinlayer solve --nu 0.45 --blunted-cone 0.5 70 --delta0 1 --H 0.1 --E 2 --json\n"
               "  thinlayer solve --nu 0.3 --sphere 10 --delta0 0.3 --H 0.1 --mu 1")
    base_arg(s, "the base under the layer: bonded (default) or frictionless", old="--layer")
    s.add_argument("--nu", required=True, help="Poisson ratio in (-1, 1/2]: a number or an exact fraction")
    s.add_argument("--H", type=_thickness, required=True,
                   help="layer thickness (> 0), or a sweep START:STOP:COUNT or A,B,C; inf: the half-space (Hertz)")
    s.add_argument("--mu", type=_finite, default=None, help="shear modulus (> 0); or give --E")
    s.add_argument("--E", type=_finite, default=None, help="Young's modulus (> 0); or give --mu")
    s.add_argument("--substrate-E", type=_finite, default=None, metavar="E_S",
                   help="Young's modulus of the substrate (units of E): a FLAG when its compliance would change the "
                        "force by more than 1 %% (the laws take the base as rigid)")
    s.add_argument("--substrate-nu", type=_finite, default=0.0, help="the substrate's Poisson ratio (default 0)")
    s.add_argument("--delta0", type=parse_values, help="indentation (> 0), or a sweep START:STOP:COUNT or A,B,C")
    s.add_argument("--force", type=parse_values,
                   help="total force P instead of --delta0 (inverse problem), or a sweep")
    s.add_argument("--model", choices=MODEL_CHOICES, default="auto",
                   help="auto (default): the first model within --tol, then any-thickness, else the direct solver; "
                        "asymptotic: refuse instead of solving directly; or one model")
    s.add_argument("--tol", type=_tolerance, default=0.05,
                   help="largest relative error estimate accepted (default 0.05)")
    s.add_argument("--order", type=_solve_order, default=1,
                   help="order of the compressible model's laws: 1 (default; force (1.8), area (3.25)) or 2 "
                        "(second order: force (SO.9) to O((H/a)^4), area (SO.10) to O((H/a)^3))")
    s.add_argument("--boundary-layer", choices=("exact", "alexandrov"), default="exact",
                   help="boundary layer of the compressible model's composite pressure (default exact)")
    add_punch_args(s, flat=True)
    add_tip_shortcuts(s)
    s.add_argument("--format", choices=("text", "json", "csv"), default=None,
                   help="output format (default text; --json is --format json)")
    s.add_argument("--output", type=Path, metavar="FILE",
                   help="write the result (the --format, default csv for a sweep, json for one value) to FILE "
                        "instead of stdout")
    s.add_argument("--overwrite", action="store_true", help="replace --output FILE if it exists (default: refuse)")
    s.add_argument("--max-pressure", action="store_true",
                   help="a sweep's rows with max_pressure too (about a second per row; one value always has it)")
    s.add_argument("--verbose", action="store_true", help="also say which models were tried first and why each "
                                                          "was rejected")
    s.add_argument("--quiet", action="store_true", help="no 'wrote ...' message (errors still go to stderr)")
    s.add_argument("--json", action="store_true", help="machine-readable JSON output (keys above)")
    from .adhesion_cli import add_adhesion_args

    add_adhesion_args(s, _finite)
    s.add_argument("--latex", action="store_true", help="print the LaTeX of the result (one value only)")
    s.set_defaults(func=cmd_solve)
    return s


def _thickness(text: str) -> float | list[float]:
    """``--H``: :func:`parse_values`, or ``inf`` (the half-space)."""
    return math.inf if text.strip().lower() in ("inf", "+inf", "infinity") else parse_values(text)


def _finite(text: str) -> float:
    return _number(text, "")


def _sweep(args: argparse.Namespace) -> tuple[str | None, list[float]]:
    """The swept option and its values (``(None, [value])`` without a sweep); refuses two swept options."""
    swept = [k for k in SWEPT if isinstance(getattr(args, k), list)]
    if len(swept) > 1:
        raise _bad(f"--{swept[0]} and --{swept[1]} are both sweeps: sweep one option at a time")
    if not swept:
        return None, [getattr(args, "delta0" if args.delta0 is not None else "force")]
    return swept[0], list(getattr(args, swept[0]))


def _bad(msg: str) -> Exception:
    from .cli_args import BadInput

    return BadInput(msg)


def cmd_solve(args: argparse.Namespace) -> int:
    """Run ``thinlayer solve``; returns 0.  Bad input raises ValueError/TypeError (one line, exit 2)."""
    from ..contact.solve import solve
    from .cli_args import print_text, punch_from_args, punch_params, solve_layer

    fmt = "json" if args.json else args.format
    if args.json and args.format not in (None, "json"):
        raise _bad(f"--json and --format {args.format}: choose one")
    if (args.delta0 is None) == (args.force is None):
        raise _bad("give exactly one of --delta0 (indentation) and --force (total force P)")
    if (args.mu is None) == (args.E is None):
        raise _bad("give exactly one of --mu (shear modulus) and --E (Young's modulus)")
    if args.work_of_adhesion is not None:  # JKR adhesion (thinlayer.export.adhesion_cli)
        from .adhesion_cli import cmd_solve_adhesive

        return cmd_solve_adhesive(args, _bad, _punch_text)
    swept, values = _sweep(args)
    if swept is not None and args.latex:
        raise _bad(f"--latex prints one result: give one value of --{swept}, or --format csv|json for the sweep")
    if args.output is not None:
        if fmt in (None, "text"):
            fmt = fmt or ("csv" if swept else "json")
        from ..validation.output import refuse_existing

        refuse_existing([args.output], args.overwrite)  # before the first solve
    layer = solve_layer(args.base, args.nu)
    punch, flat = punch_from_args(args, allow_flat=True)
    opts = {} if args.boundary_layer == "exact" else {"boundary_layer": args.boundary_layer}
    if args.order == 2:  # the compressible model's second-order laws (SO.9), (SO.10)
        if flat:
            raise _bad("--order 2 is the second order of a polynomial punch's thin-layer expansion; the flat punch "
                       "has its own laws: leave out --order")
        opts["order"] = 2
    params = punch_params(args.param)
    # a catalogue --kind whose --param gave every radius is built with its numbers (cli_args.punch_from_args)
    kind_params = {} if getattr(punch, "formula_text", None) is not None else params
    given = "delta0" if args.delta0 is not None else "force"
    answers = []
    for k, value in enumerate(values):
        kw = {"delta0": args.delta0, "force": args.force, "H": args.H}
        if swept is not None:
            kw[swept] = value
        try:
            ans = solve(layer, punch, delta0=kw["delta0"], force=kw["force"], H=kw["H"], mu=args.mu, E=args.E,
                        model=args.model, tol=args.tol, parameters=kind_params, substrate_E=args.substrate_E,
                        substrate_nu=args.substrate_nu, **opts)
            for name in ("force", "contact_area", "delta0"):
                val = getattr(ans, name)
                if not (math.isfinite(val) and val > 0):
                    raise _bad(f"the {name.replace('_', ' ')} came out as {val}: not a finite positive number "
                               "(check --H, --delta0, --mu/--E and --param)")
        except (ValueError, TypeError, ArithmeticError) as exc:
            if swept is None:
                raise
            raise type(exc)(f"--{swept} {value:g} (value {k + 1} of {len(values)}): {exc}") from exc
        answers.append(ans)
    if args.latex:
        print(answers[0].latex())
        return 0
    base = args.base
    if fmt in (None, "text"):
        if swept is None:
            print_text("\n".join(text_lines(answers[0], base, given, args.verbose, _punch_text(punch, params))))
        else:
            a = answers[0]
            head = [_punch_text(punch, params), _layer_text(a, base) if swept != "H" else
                    f"{base} layer, ν = {_g(a.nu, 6)}, μ = {_g(a.mu, 6)} (E = {_g(a.E, 6)})"]
            print_text("\n".join(head + _table(answers, swept)))
        return 0
    rows = [_row(a, base, detail=swept is None, max_pressure=swept is None or args.max_pressure) for a in answers]
    if fmt == "csv":
        text = to_csv(rows)
    else:
        from .cli_args import nonfinite

        obj: Any = rows[0] if swept is None else {"swept": swept, "rows": rows}
        bad = nonfinite(obj)
        if bad:
            raise _bad(f"the result {bad} is not a finite number: the inputs are outside the range this model can "
                       "answer")
        text = json.dumps(obj, indent=2, allow_nan=False) + "\n"
    if args.output is None:
        sys.stdout.write(text)
        return 0
    from ..validation.output import atomic_write, refuse_existing

    refuse_existing([args.output], args.overwrite)
    atomic_write(args.output, text)
    if not args.quiet:
        print(f"wrote {args.output} ({len(rows)} row{'s' if len(rows) > 1 else ''}, {fmt})")
    return 0
