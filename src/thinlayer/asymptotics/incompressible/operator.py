r"""The thin-layer operator (I.2) and the free-boundary problem (I.3)-(I.5), (I.10).

:func:`thin_layer_operator` gives the operator series of the moment expansion (2.22)-(2.23) in
dimensional form (I.2); :func:`obstacle_problem` the free-boundary problem of its leading term
(I.3)-(I.4) at ``nu = 1/2`` and of its first two terms (I.10) for ``1/4 < nu < 1/2``.

The models take the layer first, as :func:`thinlayer.solve` does: ``BondedLayer(nu)`` with
``1/4 < nu < 1/2``, ``IncompressibleLayer()`` (``nu = 1/2``), or ``BondedLayer()`` (symbolic nu).
:func:`model_layer` checks such a layer through the layer interface and turns a bare Poisson ratio
(the form of earlier releases, deprecated) into its layer.
"""
from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ... import symbols as S
from ..._checks import InputError, InputTypeError, check_order, parse_nu
from ...display import RichDisplay, fmt
from ...errors import boundary, boundary_methods
from ...layers.kernels import BondedLayer, IncompressibleLayer, LayerKernel
from ...normal import join_signed, normal_latex
from ...parse import sympy_value
from ...punch import Punch, is_polynomial_tip
from ...results import checked_lambdify, latex_equation
from ...symbols import laplacian

__all__ = [
    "ObstacleProblem",
    "ThinLayerOperator",
    "model_coefficients",
    "model_layer",
    "obstacle_problem",
    "thin_layer_operator",
]

HALF = sp.Rational(1, 2)
QUARTER = sp.Rational(1, 4)
#: the pressure as an unknown function in the free-boundary problems (I.3), (I.10)
p_fun = sp.Function("p")
#: why the models need 1/4 < nu <= 1/2 (appended to the out-of-range message)
RANGE_HINT = ("the incompressible/two-term models need m_1 > 0, so that -m_1 H^2 Delta + 1 is elliptic; "
              "for nu <= 1/4 use the compressible expansion (thinlayer.inner_pressure, thinlayer.solve)")


# =============================================================================================
# (I.2) the operator series
# =============================================================================================
@boundary_methods
@dataclass(frozen=True)
class ThinLayerOperator(RichDisplay):
    """The thin-layer operator (2.22)-(2.23) in dimensional form (I.2)::

        u_3 = (H/vartheta) sum_{n=0}^{order} (-1)^n c_n H^{2n} Delta^n p,   c_n = [s^{2n}] L(s)/s,

    for any layer with a small-s expansion (``c_n = A m_n`` for ``nu < 1/2``, (I.1) at ``nu = 1/2``).

    Attributes
    ----------
    layer : LayerKernel
        The layer kernel.
    order : int
        The highest power of the Laplacian kept.
    c : tuple
        ``(c_0, ..., c_order)``.
    """

    layer: LayerKernel
    order: int
    c: tuple

    equation = "I.2"

    @property
    def vartheta(self) -> sp.Expr:
        """``vartheta = mu/(1 - nu)`` of the layer (2.1)."""
        return self.layer.vartheta

    def weights(self) -> tuple:
        """Weights ``(-1)^n pi^2 c_n`` of ``Lambda^{-2n-2} Delta^n delta`` in the moment expansion (2.22)."""
        return tuple((-1) ** n * sp.pi**2 * cn for n, cn in enumerate(self.c))

    def apply_scaled(self, f: sp.Expr, v1: sp.Symbol = S.xi1, v2: sp.Symbol = S.xi2,
                     Lam: sp.Expr = S.Lambda) -> sp.Expr:
        """The operator series (2.23) on a density ``f(xi)``: ``sum_n w_n Lambda^{-2n-2} Delta^n f``."""
        f, v1, v2, Lam = (sympy_value(f, "f"), sympy_value(v1, "v1", symbol=True),
                         sympy_value(v2, "v2", symbol=True), sympy_value(Lam, "Lam"))
        return sp.Add(*[w * Lam ** (-2 * n - 2) * laplacian(f, v1, v2, n) for n, w in enumerate(self.weights())])

    def pairing(self, phi: sp.Expr, v1: sp.Symbol = S.xi1, v2: sp.Symbol = S.xi2,
                Lam: sp.Expr = S.Lambda) -> sp.Expr:
        """``<k(Lambda xi), phi>`` by (2.16), built from the individual moments ``mu_alpha`` (2.15).

        Comparing it with :meth:`apply_scaled` checks the moments against the Laplacian form (2.22).
        """
        phi, v1, v2, Lam = (sympy_value(phi, "phi"), sympy_value(v1, "v1", symbol=True),
                         sympy_value(v2, "v2", symbol=True), sympy_value(Lam, "Lam"))
        terms = []
        for total in range(2 * self.order + 2):
            for a1 in range(total + 1):
                a2 = total - a1
                mu_a = self.layer.moment(a1, a2)
                if mu_a == 0:
                    continue
                d = sp.diff(phi, v1, a1, v2, a2) if (a1 or a2) else phi
                terms.append(mu_a * d.subs({v1: 0, v2: 0}) / (sp.factorial(a1) * sp.factorial(a2)
                                                                 * Lam ** (total + 2)))
        return sp.Add(*terms)

    def apply(self, p: sp.Expr, v1: sp.Symbol = S.x1, v2: sp.Symbol = S.x2) -> sp.Expr:
        """``u_3`` of (I.2) for a pressure ``p(x1, x2)`` (dimensional)."""
        p, v1, v2 = sympy_value(p, "p"), sympy_value(v1, "v1", symbol=True), sympy_value(v2, "v2", symbol=True)
        return self.vartheta ** -1 * sp.Add(*[(-1) ** n * cn * S.H ** (2 * n + 1) * laplacian(p, v1, v2, n)
                                             for n, cn in enumerate(self.c)])

    def leading(self) -> sp.Expr:
        """The leading non-zero term of (I.2) applied to ``p(x1, x2)`` (``-(H^3/(3 mu)) Delta p`` at nu = 1/2)."""
        for n, cn in enumerate(self.c):
            if cn != 0:
                pf = p_fun(S.x1, S.x2)
                return sp.factor((-1) ** n * cn * S.H ** (2 * n + 1) / self.vartheta) * laplacian(pf, S.x1, S.x2, n)
        raise InputError(f"all coefficients c_0..c_{self.order} vanish; raise the order")

    def latex(self) -> str:
        """The operator (I.2) as a tagged LaTeX line."""
        parts = []
        for n, cn in enumerate(self.c):
            if cn == 0:
                continue
            coef = sp.factor((-1) ** n * cn * S.H ** (2 * n + 1) / self.vartheta)
            op = "p" if n == 0 else (r"\Delta p" if n == 1 else rf"\Delta^{{{n}}} p")
            tex = normal_latex(coef)
            parts.append((rf"\left({tex}\right)" if isinstance(coef, sp.Add) else tex) + rf"\, {op}")
        return r"u_3 = " + join_signed(parts) + r" + \dots \tag{I.2}"

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``: (I.2) with its coefficients."""
        parts = []
        for n, cn in enumerate(self.c):
            if cn != 0:
                coef = sp.factor((-1) ** n * cn * S.H ** (2 * n + 1) / self.vartheta)
                text = fmt(coef)
                op = "p" if n == 0 else ("Δp" if n == 1 else f"Δ^{n} p")
                parts.append((f"({text})" if isinstance(coef, sp.Add) else text) + " " + op)
        return [f"ThinLayerOperator of {self.layer}, through Δ^{self.order}   (I.2)",
                f"  u₃ = {join_signed(parts, latex=False)} + ...",
                f"  c  = ({', '.join(fmt(cn) for cn in self.c)})   (c_n = [s^(2n)] L(s)/s)"]

    def lambdify(self, backend: str = "numpy") -> Callable:
        """Numeric ``(c_0, ..., c_order)`` as a function of the layer's parameter (none at nu = 1/2)."""
        prm = self.layer.parameter
        return checked_lambdify([prm] if prm is not None else [], list(self.c), backend)


@boundary
def thin_layer_operator(layer: LayerKernel, order: int = 1) -> ThinLayerOperator:
    """The operator series (I.2) through ``Delta^order``, from the moment expansion (2.22).

    Parameters
    ----------
    layer : LayerKernel
        :class:`IncompressibleLayer`, or a compressible layer (``BondedLayer(nu)``, symbolic or numeric).
    order : int
        Highest power of the Laplacian (non-negative integer).

    Returns
    -------
    ThinLayerOperator

    Examples
    --------
    >>> thin_layer_operator(IncompressibleLayer()).leading()
    -H**3*(Derivative(p(x_1, x_2), (x_1, 2)) + Derivative(p(x_1, x_2), (x_2, 2)))/(3*mu)
    """
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a thinlayer LayerKernel (IncompressibleLayer(), BondedLayer(nu)), "
                        f"got {layer!r}")
    order = check_order(order, "order")
    return ThinLayerOperator(layer, order, layer.taylor_coefficients(order))


# =============================================================================================
# the layer of a model (and the deprecated bare Poisson ratio)
# =============================================================================================
def layer_from_nu(nu: Any, call: str, stacklevel: int = 3) -> LayerKernel:
    """The layer of a bare Poisson ratio given where the layer goes (deprecated), with a DeprecationWarning.

    Parameters
    ----------
    nu : Symbol, number or str
        Poisson ratio in (1/4, 1/2], or a Symbol.
    call : str
        The new call, with ``{layer}`` where the layer goes (named in the warning).
    stacklevel : int
        Passed to :func:`warnings.warn` (the user's frame).

    Returns
    -------
    LayerKernel
        ``IncompressibleLayer()`` at 1/2, ``BondedLayer(nu)`` below, ``BondedLayer()`` for a Symbol.
    """
    nv = parse_nu(nu, floats="Float", lower=QUARTER, upper_closed=True, example="'49/100', 0.49 or 0.5",
                  range_hint=RANGE_HINT)
    if nv == HALF:
        layer, new = IncompressibleLayer(), "IncompressibleLayer()"
    elif isinstance(nv, sp.Symbol):
        layer, new = BondedLayer(), "BondedLayer()"
    else:
        layer, new = BondedLayer(nv), f"BondedLayer({nu!r})"
    warnings.warn(f"a Poisson ratio where the layer goes is deprecated; call {call.format(layer=new)}",
                  DeprecationWarning, stacklevel=stacklevel)
    return layer


def model_nu(layer: LayerKernel) -> sp.Basic:
    """Poisson's ratio of a model's layer: 1/2, an exact Rational, a 17-digit Float or the Symbol nu.

    Read from ``vartheta = mu/(1 - nu)`` (2.1), the one interface member that carries nu exactly.
    """
    if layer.numeric_nu == 0.5:
        return HALF
    nu = sp.expand(1 - S.mu / layer.vartheta)
    if isinstance(nu, sp.Float):
        return sp.Float(float(nu), 17)
    return nu


def model_layer(layer: Any, call: str, numeric: bool = False) -> tuple[LayerKernel, sp.Basic]:
    """Check the layer of the incompressible/two-term models and return it with its Poisson ratio.

    Parameters
    ----------
    layer : LayerKernel or number (deprecated)
        ``BondedLayer(nu)`` with ``1/4 < nu < 1/2``, ``IncompressibleLayer()`` or ``BondedLayer()``;
        ``None`` is ``IncompressibleLayer()``.  A bare Poisson ratio still works, with a DeprecationWarning.
    call : str
        The call, with ``{layer}`` where the layer goes (for the messages).
    numeric : bool
        Whether a symbolic layer is refused.

    Returns
    -------
    tuple
        ``(layer, nu)`` with ``nu`` as :func:`model_nu` gives it.
    """
    if layer is None:
        layer = IncompressibleLayer()
    elif not isinstance(layer, LayerKernel):
        layer = layer_from_nu(layer, call, stacklevel=4)
    if not layer.has_incompressible_model or layer.symbolic_coefficients or not layer.has_thickness:
        raise InputError(f"the incompressible/two-term models need a layer bonded to a rigid base, "
                         f"{call.format(layer='BondedLayer(nu)')} (1/4 < nu < 1/2) or "
                         f"{call.format(layer='IncompressibleLayer()')}; got {layer!r}")
    nu = model_nu(layer)
    if not isinstance(nu, sp.Symbol) and not nu.is_number:
        raise InputError(f"a symbolic layer of the models must have the parameter nu: BondedLayer(), got {layer!r}")
    if isinstance(nu, sp.Symbol):
        if numeric:
            raise InputTypeError(f"a numeric Poisson ratio in (1/4, 1/2] is needed here "
                            f"(e.g. {call.format(layer='BondedLayer(0.49)')}), got the symbolic {layer!r}")
    else:
        parse_nu(nu, floats="Float", lower=QUARTER, upper_closed=True, range_hint=RANGE_HINT)
    return layer, nu


def model_coefficients(layer: LayerKernel, nu: sp.Basic) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """``(c_0, c_1, vartheta)`` of the two-term operator (I.10): ``c_0 = A``, ``c_1 = A m_1``, (I.1) at 1/2."""
    c0, c1 = layer.taylor_coefficients(1)
    if isinstance(nu, sp.Symbol):
        c1 = sp.factor(c1)
    elif isinstance(nu, sp.Float):
        c0, c1 = sp.Float(c0, 20), sp.Float(c1, 20)
    return c0, c1, S.mu / (1 - nu)


# =============================================================================================
# (I.3), (I.4), (I.10): the free-boundary problem
# =============================================================================================
@boundary_methods
@dataclass(frozen=True)
class ObstacleProblem(RichDisplay):
    """The thin-layer free-boundary problem for one punch, (I.3)-(I.4) at ``nu = 1/2``, (I.10) below::

        -Delta p + k^2 p = f  in omega,   p = dp/dn = 0  on its contour,   p >= 0,
        f = vartheta (delta0 - Phi)/(c_1 H^3),   k^2 = c_0/(c_1 H^2),

    i.e. ``min int (|grad p|^2/2 + k^2 p^2/2 - f p) dx`` over ``p >= 0``.

    Attributes
    ----------
    layer : LayerKernel
        ``IncompressibleLayer()`` or ``BondedLayer(nu)``.
    punch : Punch
        The punch.
    nu : sympy object
        Poisson's ratio (1/2, an exact or float value in (1/4, 1/2), or the Symbol nu).
    c0, c1, vartheta : sympy.Expr
        sympy.Expr
        ``c_0 = A``, ``c_1 = A m_1`` (``2/3`` at nu = 1/2) and ``vartheta = mu/(1 - nu)``.
    source, k2 : sympy.Expr
        sympy.Expr
        ``f(x1, x2)`` and ``k^2`` (zero at nu = 1/2).
    """

    layer: LayerKernel
    punch: Punch
    nu: Any
    c0: sp.Expr
    c1: sp.Expr
    vartheta: sp.Expr
    source: sp.Expr
    k2: sp.Expr

    @property
    def equation(self) -> str:
        """``"I.3"`` at nu = 1/2, ``"I.10"`` below."""
        return "I.3" if self.is_incompressible else "I.10"

    @property
    def is_incompressible(self) -> bool:
        """Whether ``c_0 = A = 0`` (nu = 1/2)."""
        return self.c0 == 0

    def residual(self, p: sp.Expr) -> sp.Expr:
        """``-Delta p + k^2 p - f`` for a candidate pressure ``p(x1, x2)`` (zero inside the contact)."""
        p = sympy_value(p, "p")
        return -laplacian(p, S.x1, S.x2) + self.k2 * p - self.source

    def boundary_values(self, p: sp.Expr, x1: sp.Expr, x2: sp.Expr) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        """``(p, dp/dx1, dp/dx2)`` at a point -- all three vanish on the contour (I.4)."""
        p = sympy_value(p, "p")
        at = {S.x1: sympy_value(x1, "x1"), S.x2: sympy_value(x2, "x2")}
        return p.xreplace(at), sp.diff(p, S.x1).xreplace(at), sp.diff(p, S.x2).xreplace(at)

    @property
    def arguments(self) -> tuple[sp.Symbol, ...]:
        """``(x1, x2, delta0, H, mu)`` and the other free symbols, by name."""
        base = (S.x1, S.x2, S.delta0, S.H, S.mu)
        rest = sorted((self.source.free_symbols | self.k2.free_symbols) - set(base), key=lambda q: q.name)
        return base + tuple(rest)

    def lambdify(self, args=None, backend: str = "numpy") -> Callable:
        """``(f, k^2)`` as one numeric function of :attr:`arguments` (x1, x2, delta0, H, mu, then the rest)."""
        return checked_lambdify(self.arguments if args is None else args, (self.source, self.k2), backend)

    def latex(self) -> str:
        """(I.3) or (I.10), the edge conditions (I.4) and, at nu = 1/2, the volume identity (I.5)."""
        lhs = r"-\Delta p" if self.is_incompressible else rf"-\Delta p + {normal_latex(self.k2)}\, p"
        tag = self.equation
        lines = [
            latex_equation(lhs, normal_latex(sp.factor(self.source)) + r",\quad \mathbf{x} \in \omega", tag),
            (r"p = \frac{\partial p}{\partial n} = 0 \ \text{on}\ \partial\omega,\quad p > 0 \ \text{in}\ \omega"
             r" \tag{I.4}"),
        ]
        if self.is_incompressible:
            lines.append(rf"\iint_\omega \left({normal_latex(S.delta0 - self.punch.expr)}\right) d\mathbf{{x}} = 0"
                         r" \tag{I.5}")
        return " \\\\\n".join(lines)

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``: the problem (I.3)-(I.5) or (I.10)."""
        lhs = "-Δp" if self.is_incompressible else "-Δp + k² p"
        out = [f"ObstacleProblem: {self.punch.name} on {self.layer}   ({self.equation}), (I.4)",
               f"  {lhs} = f in ω,  p = ∂p/∂n = 0 on ∂ω,  p > 0 in ω",
               f"  Φ  = {fmt(self.punch.expr)}",
               f"  f  = {fmt(sp.factor(self.source))}"]
        if not self.is_incompressible:
            out.append(f"  k² = {fmt(self.k2)}")
        else:
            out.append("  ∬_ω (δ₀ - Φ) dx = 0   (I.5)")
        return out


@boundary
def obstacle_problem(layer: LayerKernel, punch: Punch | None = None, nu: Any = None) -> ObstacleProblem:
    """The free-boundary problem (I.3)-(I.4) (``nu = 1/2``) or the two-term problem (I.10) (``1/4 < nu < 1/2``).

    The source ``f = vartheta (delta0 - Phi)/(c_1 H^3)`` and ``k^2 = c_0/(c_1 H^2)`` come from the
    operator (I.2): ``c_1 = 2/3`` from (I.1) at ``nu = 1/2``, ``c_0 = A``, ``c_1 = A m_1`` from
    :func:`thinlayer.kernel_coefficients` otherwise.

    Parameters
    ----------
    layer : LayerKernel
        ``IncompressibleLayer()`` (I.3), ``BondedLayer(nu)`` with ``1/4 < nu < 1/2`` or ``BondedLayer()`` (I.10).
    punch : Punch
        The punch.
    nu : number or Symbol, optional
        Deprecated: the form ``obstacle_problem(punch, nu)`` of earlier releases (a DeprecationWarning).

    Returns
    -------
    ObstacleProblem

    Examples
    --------
    >>> from thinlayer import Punch
    >>> sp.factor(obstacle_problem(IncompressibleLayer(), Punch.paraboloid()).source)
    3*mu*(2*R*delta_0 - x_1**2 - x_2**2)/(2*H**3*R)
    """
    if is_polynomial_tip(layer):  # deprecated: obstacle_problem(punch, nu=1/2)
        old = punch if punch is not None else (HALF if nu is None else nu)
        layer, punch = layer_from_nu(old, "obstacle_problem({layer}, punch)"), layer
    elif nu is not None:
        raise InputTypeError("nu= belongs to the deprecated form obstacle_problem(punch, nu); "
                        "pass the layer only: obstacle_problem(BondedLayer(nu), punch)")
    if not is_polynomial_tip(punch):
        raise InputTypeError(f"punch must be a thinlayer.Punch, got {type(punch).__name__}")
    layer, nv = model_layer(layer, "obstacle_problem({layer}, punch)")
    c0, c1, th = model_coefficients(layer, nv)
    f = th * (S.delta0 - punch.expr) / (c1 * S.H**3)
    k2 = c0 / (c1 * S.H**2)
    return ObstacleProblem(layer, punch, nv, c0, c1, th, f, k2)
