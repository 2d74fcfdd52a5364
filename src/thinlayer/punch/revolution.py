r"""A tip of revolution given by its profile ``Phi(r)``, read by the restricted grammar (issue 24).

``Punch.revolution("R - sqrt(R**2 - r**2)")`` or ``tip_from_spec("revolution:expr=2*r**1.5")``: the formula is read by
:func:`thinlayer.parse.parse_expression` with ``radial=True`` (the radius ``r``, parameter names, ``+ - * / **``,
rational exponents, ``sqrt(...)``, ``abs(...)``, ``max(...)``/``min(...)`` of linear forms in r; never evaluated as
code).

``max``/``min`` of linear forms (a cone that steepens, ``max(r/2, 2*r - 3)``, or flattens, ``min(2*r, r/2 + 3/2)``):
with numbers, the profile becomes a Piecewise of its pieces between the radii where two forms cross
(:attr:`Revolution.radial_breakpoints`, where Phi' jumps: the solvers and quadratures split there); with parameters it
stays a Max/Min until ``.subs`` gives numbers.  A flat-ended profile (``max(0, 2*r - 1)``) is refused like any profile
that is not increasing.  A numeric profile must vanish at
``r = 0`` and increase (checked on a sample).  Its inner order and smoothness are read off the apex
(:func:`~thinlayer.punch._radial.apex_inner_order`); its level set is found by root finding and quadrature.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from .._lazy import lazy_module
from ..errors import WorkLimitError, boundary_methods
from ..parse import RADIUS, ExpressionError, check_cost, parse_expression
from ._radial import RadialTip, check_profile
from .base import PunchError, TipKind, TipParameter, register_tip

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it


def _profile_expr(expr: Any) -> sp.Expr:
    if isinstance(expr, str):
        try:
            return parse_expression(expr, radial=True, what="radial profile Phi(r)")
        except ExpressionError as exc:
            raise (type(exc) if isinstance(exc, WorkLimitError) else PunchError)(f"the profile: {exc}") from None
    if not isinstance(expr, sp.Expr) or isinstance(expr, sp.Piecewise):
        raise PunchError(f"the profile of a tip of revolution must be a formula in r (a string such as "
                         f"'R - sqrt(R**2 - r**2)'), got {expr!r:.60}")
    # a sympy expression: its plain-named r becomes the radius; it must be built from what the grammar builds
    expr = expr.xreplace({q: RADIUS for q in expr.free_symbols if q.name == "r"})
    allowed = (sp.Add, sp.Mul, sp.Pow, sp.Abs, sp.Symbol, sp.Number, sp.Max, sp.Min)
    bad = [a for a in sp.preorder_traversal(expr) if not isinstance(a, allowed)]
    if bad:
        raise PunchError(f"the profile may hold only + - * / **, sqrt, abs, max and min of r and parameters; {bad[0]} "
                         "is not")
    from ..parse import piecewise_linear_form

    for m in (a for a in sp.preorder_traversal(expr) if isinstance(a, (sp.Max, sp.Min))):
        if not all(piecewise_linear_form(v, (RADIUS,)) for v in m.args):
            raise PunchError(f"the profile's {m} is not a max/min of linear forms in r")
    try:
        return check_cost(expr, "radial profile Phi(r)")
    except WorkLimitError as exc:
        raise type(exc)(str(exc)) from None


def _leaves(e: sp.Expr) -> list[sp.Expr]:
    """The linear forms inside the max/min calls of ``e``."""
    out = []
    for m in (a for a in sp.preorder_traversal(e) if isinstance(a, (sp.Max, sp.Min))):
        out.extend(v for v in m.args if not v.has(sp.Max, sp.Min))
    return out


def _active(e: sp.Expr, at: sp.Rational) -> sp.Expr:
    """``e`` with each max/min replaced by its argument that is largest/smallest at ``r = at`` (exact arithmetic)."""
    if isinstance(e, (sp.Max, sp.Min)):
        args = [_active(v, at) for v in e.args]
        vals = [v.xreplace({RADIUS: at}) for v in args]
        pick = max if isinstance(e, sp.Max) else min
        return args[vals.index(pick(vals))]
    if e.args and e.has(sp.Max, sp.Min):
        return e.func(*(_active(v, at) for v in e.args))
    return e


def _pieces(e: sp.Expr) -> tuple[sp.Expr, tuple[float, ...]]:
    """A numeric profile with max/min of linear forms as ``Piecewise`` of its pieces, and the radii between them: the
    crossings ``r > 0`` of every two forms (exact), each interval's piece chosen at its midpoint; equal neighbours
    merged.
    """
    forms = list(dict.fromkeys(sp.expand(v) for v in _leaves(e)))
    cuts = set()
    for i, f in enumerate(forms):
        for g in forms[i + 1:]:
            a = sp.expand(f - g).coeff(RADIUS, 1)
            if a != 0:
                x = -sp.expand(f - g).subs(RADIUS, 0) / a
                if x.is_positive:
                    cuts.add(x)
    cuts = sorted(cuts)
    edges = [sp.Integer(0), *cuts]
    mids = [(lo + hi) / 2 for lo, hi in zip(edges, edges[1:])] + [edges[-1] + 1]
    pieces = [sp.expand(_active(e, m)) for m in mids]
    kept: list[tuple[sp.Expr, sp.Expr]] = []
    for piece, hi in zip(pieces, [*cuts, None]):
        if kept and sp.expand(kept[-1][0] - piece) == 0:
            kept[-1] = (piece, hi)
        else:
            kept.append((piece, hi))
    if len(kept) == 1:
        return kept[0][0], ()
    args = [(p, RADIUS <= hi) for p, hi in kept[:-1]] + [(kept[-1][0], True)]
    return sp.Piecewise(*args), tuple(float(hi) for _, hi in kept[:-1])


@boundary_methods
@dataclass(frozen=True, init=False)
class Revolution(RadialTip):
    """A tip of revolution ``Phi(r)`` from a formula (module docstring).

    Examples
    --------
    >>> from thinlayer import Punch
    >>> tip = Punch.revolution("r**2/2 + r**3")
    >>> tip.smoothness, tip.max_inner_order
    ('apex', 2)
    """

    values: tuple
    name: ClassVar[str] = "tip of revolution"

    def __init__(self, expr: Any) -> None:
        e = _profile_expr(expr)
        if RADIUS not in e.free_symbols:
            raise PunchError(f"the profile Phi(r) = {e} does not depend on r")
        breaks: tuple = ()
        if e.has(sp.Max, sp.Min) and not (e.free_symbols - {RADIUS}):
            e, breaks = _pieces(e)
        object.__setattr__(self, "values", (("expr", e),))
        object.__setattr__(self, "_breaks", breaks)
        check_profile(self)

    @property
    def radial_breakpoints(self) -> tuple[float, ...]:
        """The radii where two linear forms of a numeric ``max``/``min`` cross (Phi' jumps there); ``()`` else."""
        return self._breaks

    def _rebuild(self, values: dict) -> Revolution:  # pragma: no cover - subs is overridden
        return Revolution(values["expr"])

    def subs(self, values) -> Revolution:
        """A new tip with parameters replaced (strings read by the restricted grammar, never evaluated)."""
        from collections.abc import Mapping

        from ..parse import parse_number

        if not isinstance(values, Mapping):
            raise PunchError(f"the tip's parameter values must be a dict, got {type(values).__name__}")
        by_name = {q.name: q for q in self.parameters}
        out = {}
        for k, v in values.items():
            key = k.name if isinstance(k, sp.Symbol) else k
            if key not in by_name:
                raise PunchError(f"{k!r} is not a parameter of the tip of revolution; its parameters are "
                                 f"{', '.join(by_name) or 'none'}")
            try:
                out[by_name[key]] = parse_number(v, f"the value of {key}")
            except (TypeError, ValueError) as exc:
                raise PunchError(str(exc)) from None
        return Revolution(self.radial_expr.xreplace(out))

    @property
    def kind(self) -> str:
        """``"revolution"``."""
        return "revolution"

    @property
    def radial_expr(self) -> sp.Expr:
        """The profile as read."""
        return self.values[0][1]


register_tip(TipKind("revolution", Revolution, (
    TipParameter("expr", "profile", "radial profile Phi(r)", ("Phi", "profile"), required=True),),
    "any tip of revolution Phi(r), read by the restricted grammar (r, sqrt, abs, rational powers) (issue 24)"))
