"""Stage (2.24)-(2.31), (4.1): the inner asymptotic expansion of the contact pressure.

Substituting the moment expansion (2.22) into the integral equation (2.10) gives (2.24)

    sum_n (-1)^n pi^2 A m_n Lambda^{-2n-2} Delta^n p^*(xi) ~ Lambda^{-2} phi^*(xi),
    phi^*(xi) = pi^2 vartheta / H_* (delta_0^* - Phi^*(xi))                       (2.25)

and with ``p^* ~ sum_k Lambda^{-2k} p_k^*`` (2.26), order by order in Lambda^{-2}:

    p_0^* = phi^* / (pi^2 A)                                                      (2.27)
    p_k^* = - sum_{j<k} (-1)^{k-j} m_{k-j} Delta^{k-j} p_j^*                       (2.28)
          = (-1)^k M_k Delta^k phi^* / (pi^2 A)                                    (4.1)

(4.1) follows from (2.28) by induction with the M_k of (4.2).  For a polynomial punch of
degree d, ``Delta^k Phi = 0`` for 2k > d, so the series terminates: p_k^* = 0 for k > d // 2.

Dimensional form (x = H_* xi, H = H_*/Lambda, delta_0 = delta_0^*/Lambda, Phi = Phi^*/Lambda):

    p(x) = (vartheta / (A H)) sum_k (-1)^k M_k H^{2k} Delta_x^k (delta_0 - Phi(x)),
    vartheta = mu / (1 - nu).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .. import symbols as S
from .._checks import InputError, InputTypeError, check_bounded
from .._checks import check_order as _check_order
from .._lazy import lazy_function, lazy_module
from ..display import RichDisplay, fmt
from ..errors import boundary, boundary_methods
from ..layers.coefficients import order_limit
from ..layers.kernels import LayerKernel
from ..parse import as_expr
from ..punch import Punch, is_polynomial_tip
from ..results import checked_lambdify

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it
normal_latex = lazy_function("thinlayer.normal", "normal_latex")  # the printers subclass sympy's

METHODS = ("closed", "recursion")


@boundary_methods
@dataclass(frozen=True)
class InnerPressure(RichDisplay):
    """The inner expansion of the contact pressure for one layer and punch.

    Attributes
    ----------
    terms : tuple
        Dimensional terms ``p_k(x1, x2) = Lambda^{-2k} p_k^*`` written in x, delta_0, H, mu, nu and
        the punch parameters; ``pressure`` is their sum.
    scaled_terms : tuple
        ``p_k^*(xi1, xi2)`` of (2.27)-(2.28)/(4.1) in the scaled variables (1.2), (2.8):
        H_*, delta_0^*, vartheta, the starred punch parameters.
    order : int
        Number of terms kept (p_0 .. p_{order-1}).
    method : str
        ``"closed"`` (4.1) or ``"recursion"`` (2.28).
    """

    layer: LayerKernel
    punch: Punch
    order: int
    method: str
    terms: tuple
    scaled_terms: tuple

    equation = "2.26"

    @property
    def pressure(self) -> sp.Expr:
        """Dimensional inner pressure ``p(x1, x2) = sum_k p_k`` (2.26) in dimensional form."""
        return sp.Add(*self.terms)

    @property
    def scaled_pressure(self) -> sp.Expr:
        """``p^*(xi) ~ sum_k Lambda^{-2k} p_k^*(xi)`` (2.26)."""
        return sp.Add(*[S.Lambda ** (-2 * k) * t for k, t in enumerate(self.scaled_terms)])

    @property
    def nonzero_terms(self) -> int:
        """How many p_k are not identically zero (``degree // 2 + 1`` at most)."""
        return sum(1 for t in self.terms if t != 0)

    @property
    def arguments(self) -> tuple[sp.Symbol, ...]:
        """Default argument order of :meth:`lambdify`:
        ``(x1, x2, delta_0, H, mu)`` then every other free symbol sorted by name (nu, punch parameters).
        """
        base = (S.x1, S.x2, S.delta0, S.H, S.mu)
        rest = sorted(self.pressure.free_symbols - set(base), key=lambda q: q.name)
        return base + tuple(rest)

    def codegen_expressions(self) -> tuple[tuple[sp.Symbol, ...], dict[str, sp.Expr]]:
        """Arguments in call order and the one output ``p`` (2.26), for :func:`thinlayer.export.codegen.generate`."""
        return self.arguments, {"p": self.pressure}

    @property
    def scaled_arguments(self) -> tuple[sp.Symbol, ...]:
        """Default arguments of the scaled form: ``(xi1, xi2, delta_0^*, H_*, Lambda, vartheta)`` + the rest by name."""
        base = (S.xi1, S.xi2, S.delta0_s, S.H_s, S.Lambda, S.vartheta)
        rest = sorted(self.scaled_pressure.free_symbols - set(base), key=lambda q: q.name)
        return base + tuple(rest)

    def lambdify(self, args=None, backend: str = "numpy", scaled: bool = False):
        """Numeric pressure function.

        Parameters
        ----------
        args
            Argument symbols in call order; default :attr:`arguments` (or :attr:`scaled_arguments`).
            A free symbol of the pressure that is missing raises ``MissingArgumentError`` naming it.
        backend : str
            ``"numpy"`` (vectorised) or ``"mpmath"``.
        scaled : bool
            Lambdify the scaled ``p^*(xi)`` instead of the dimensional ``p(x)``.
        """
        expr = self.scaled_pressure if scaled else self.pressure
        if args is None:
            args = self.scaled_arguments if scaled else self.arguments
        return checked_lambdify(args, expr, backend)

    def latex(self) -> str:
        """The terms p_k^* ((2.27), (4.1)) and the dimensional pressure, one tagged line each."""
        lines = []
        for k, t in enumerate(self.scaled_terms):
            tag = "2.27" if k == 0 else "4.1"
            lines.append(rf"p_{{{k}}}^*(\boldsymbol{{\xi}}) = {normal_latex(t)} \tag{{{tag}}}")
        lines.append(rf"p(x_1, x_2) \sim {normal_latex(self.pressure)} \tag{{2.26}}")
        return " \\\\\n".join(lines)

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        how = "closed form (4.1)" if self.method == "closed" else "recursion (2.28)"
        out = [(f"InnerPressure: {self.punch.name} on {self.layer}, {self.order} term{'s' if self.order != 1 else ''} "
               f"({how})   (2.26)"), f"  Φ   = {fmt(self.punch.expr)}"]
        sub = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
        out += [f"  p{str(k).translate(sub)}  = {fmt(t)}" for k, t in enumerate(self.terms)]
        out += [f"  p{str(k).translate(sub)}* = {fmt(t)}   (scaled, ξ = x/H*, {'2.27' if k == 0 else '4.1'})"
                for k, t in enumerate(self.scaled_terms)]
        out.append(f"  arguments of lambdify(): ({', '.join(a.name for a in self.arguments)})")
        return out


Mono = tuple[int, int]


def _laplacian_dict(d: dict[Mono, Any]) -> dict[Mono, Any]:
    """Laplacian of a polynomial given as ``{(i, j): coefficient}`` (coefficients untouched)."""
    out: dict[Mono, Any] = {}
    for (i, j), c in d.items():
        if i >= 2:
            out[(i - 2, j)] = out.get((i - 2, j), 0) + i * (i - 1) * c
        if j >= 2:
            out[(i, j - 2)] = out.get((i, j - 2), 0) + j * (j - 1) * c
    return {k: v for k, v in out.items() if v != 0}


def _dict_expr(d: dict[Mono, Any], v1: sp.Symbol, v2: sp.Symbol) -> sp.Expr:
    return sp.Add(*[c * v1**i * v2**j for (i, j), c in sorted(d.items())])


def _combine(parts: list[tuple[Any, dict[Mono, Any]]]) -> dict[Mono, Any]:
    """``sum_w w * d`` over (weight, dict) pairs, coefficients as unexpanded sums."""
    acc: dict[Mono, list] = {}
    for w, d in parts:
        for k, c in d.items():
            acc.setdefault(k, []).append(w * c)
    return {k: sp.Add(*v) for k, v in acc.items()}


def _gap_dicts(punch: Punch) -> tuple[dict[Mono, Any], dict[Mono, Any]]:
    """``delta_0 - Phi(x)`` and ``delta_0^* - Phi^*(xi)`` (2.25) as coefficient dictionaries."""
    phi = punch.polynomial.as_dict()
    sc = dict(punch.scaling)
    gap = {k: -c for k, c in phi.items()}
    gap[(0, 0)] = S.delta0 + gap.get((0, 0), 0)
    gap_s = {(i, j): -S.Lambda * as_expr(c).xreplace(sc) * S.H_s ** (i + j) for (i, j), c in phi.items()}
    gap_s[(0, 0)] = S.delta0_s + gap_s.get((0, 0), 0)
    return gap, gap_s


@boundary
def inner_pressure(layer: LayerKernel, punch: Punch, order: int | None = None,
                   method: str = "closed") -> InnerPressure:
    """The inner expansion (2.26) of the contact pressure, terms (2.27)-(2.28) or (4.1).

    Parameters
    ----------
    layer : LayerKernel
        A layer with a small-s expansion (BondedLayer, FrictionlessLayer, GenericLayer).
    punch : Punch
        Any polynomial :class:`~thinlayer.punch.Punch`.
    order : int | None
        Number of terms p_0..p_{order-1} to keep (an integer >= 1).  Default: all the
        terms that can be non-zero, ``punch.degree // 2 + 1``; beyond them the series
        terminates (every further p_k is identically zero).  At most the layer's coefficient order
        limit + 1 (:data:`thinlayer.layers.coefficients.ORDER_LIMITS`): 31 for a symbolic nu, 201 for an
        exact nu, 501 for a float nu, 13 for a GenericLayer; checked before any work.  Measured: the default
        order of a degree-40 punch (21 terms) takes 3.0 s with a symbolic nu and 0.55 s with nu = 3/10.
    method : str
        ``"closed"`` -- the closed form (4.1) with the M_k of (4.2); ``"recursion"`` -- (2.28).

    Examples
    --------
    >>> from thinlayer import BondedLayer, Punch, inner_pressure
    >>> ip = inner_pressure(BondedLayer("3/10"), Punch.paraboloid(R=1))
    >>> ip.terms[1]
    -H*mu/2
    """
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a LayerKernel (e.g. BondedLayer()), got {type(layer).__name__}")
    if not is_polynomial_tip(punch):
        raise InputTypeError(f"punch must be a thinlayer.Punch, got {type(punch).__name__}")
    if method not in METHODS:
        raise InputError(f"method must be one of {METHODS}, got {method!r}")
    if order is None:
        order = punch.degree // 2 + 1
    else:
        if isinstance(order, bool) or not isinstance(order, int):
            raise InputTypeError(f"order must be a positive integer (number of terms), got {order!r}")
        if order < 1:
            raise InputError(
                f"order must be a positive integer (the number of terms p_0..p_(order-1)), got {order}; "
                f"order=1 keeps p_0 only, the default keeps all {punch.degree // 2 + 1} non-zero terms"
            )
    _check_order(order, "order")
    limit, reason = order_limit(layer)
    check_bounded(order, "order", limit + 1, f"the inner expansion needs M_1..M_(order-1) (4.2), and {reason}")
    coef = layer.coefficients(order - 1)
    A = coef.A_expr
    theta = layer.vartheta
    gap, gap_s = _gap_dicts(punch)
    pref = theta / (A * S.H)  # dimensional p_0 = pref (delta_0 - Phi)
    pref_s = S.vartheta / (A * S.H_s)  # phi^*/(pi^2 A) = pref_s (delta_0^* - Phi^*), (2.25), (2.27)

    if method == "closed":
        # (4.1); dimensionally Lambda^{-2} Delta_xi = H^2 Delta_x
        lap, lap_s = [gap], [gap_s]
        for _ in range(1, order):
            lap.append(_laplacian_dict(lap[-1]))
            lap_s.append(_laplacian_dict(lap_s[-1]))
        dims = tuple(pref * (-1) ** k * coef.M_expr(k) * S.H ** (2 * k) * _dict_expr(lap[k], S.x1, S.x2)
                     for k in range(order))
        scaled = tuple(pref_s * (-1) ** k * coef.M_expr(k) * _dict_expr(lap_s[k], S.xi1, S.xi2)
                       for k in range(order))
    else:
        # (2.27), (2.28): p_k = - sum_{j<k} (-1)^{k-j} m_{k-j} Delta^{k-j} p_j, each p_j a coefficient dict
        pd = [{k: pref * c for k, c in gap.items()}]
        ps = [{k: pref_s * c for k, c in gap_s.items()}]
        for k in range(1, order):
            parts_d, parts_s = [], []
            for j in range(k):
                w = -((-1) ** (k - j)) * coef.m_expr(k - j)
                dd, ds = pd[j], ps[j]
                for _ in range(k - j):
                    dd, ds = _laplacian_dict(dd), _laplacian_dict(ds)
                parts_d.append((w * S.H ** (2 * (k - j)), dd))
                parts_s.append((w, ds))
            pd.append(_combine(parts_d))
            ps.append(_combine(parts_s))
        dims = tuple(_dict_expr(d, S.x1, S.x2) for d in pd)
        scaled = tuple(_dict_expr(d, S.xi1, S.xi2) for d in ps)
    return InnerPressure(layer, punch, order, method, dims, scaled)
