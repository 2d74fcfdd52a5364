r"""Force--indentation law (1.8) and contact area, each with its first correction in H.

Derivation (any polynomial punch with a smooth, simply connected contact area)
------------------------------------------------------------------------------
The uniformly valid pressure is the inner expansion (2.26) plus the boundary layer (3.24) minus
their common part.  Near the contour Gamma_0, with ``n`` the inward distance, ``v = n/H`` and
``g(s) = |grad Phi|`` on Gamma_0, the leading inner term is ``p_0 ~ (vartheta g/A) v`` and the
boundary layer is ``(vartheta g/A) Qhat(v)`` with ``Qhat ~ v`` far from the edge, ``Qhat = 0`` for
``v < h^*``.  Integrating over the plane (``P = iint p``, (1.8)):

    P = iint_{omega_0} p_0 + iint_{omega_0} p_1 + oint_{Gamma_0} (vartheta g/A) H D ds + ...,
    D = int (Qhat(v) - max(v, 0)) dv                       (the boundary layer's force defect).

* ``p_0 = vartheta (delta0 - Phi)/(A H)`` (2.27), ``p_1 = (vartheta H/A) M_1 Laplacian Phi`` (4.1);
  ``iint_{omega_0} Laplacian Phi = oint_{Gamma_0} |grad Phi| ds =: J`` (divergence theorem; on the
  level set the outward normal is ``grad Phi/|grad Phi|``).
* ``D`` follows from the Laplace transform of the boundary layer: ``int_0^oo (Q(h + tau) - tau - h)
  dtau`` is the ``p^0`` coefficient of ``Q~(p) - 1/p^2 - h/p`` and ``D`` is that minus ``h^2/2``.
  :func:`boundary_layer_force_defect` carries this out on Alexandrov's transform and, with the
  condition (3.21) (``1/C - 1/(2B^2) = -m_1``), obtains ``D = m_1/2``.  The identity depends on the
  kernel only through ``m_1`` (the second moment of ``F``); for the exact kernel it is checked by
  quadrature of the Wiener--Hopf solution (tests).

Hence, with ``V = iint_{omega_0} (delta0 - Phi) dx`` and ``M_1 = -m_1`` (4.2),

    P = (vartheta/(A H)) V + (vartheta H/A) (M_1 + m_1/2) J + O((H/a)^3) relative,

the boundary layer cancelling half of the inner correction.  The remainder comes from the
next boundary-layer order (curvature of Gamma_0, ``b_2``, matching ``p_1``): ``O(H/a)`` relative
to the boundary layer's own ``O((H/a)^2)`` contribution.  ``p_2`` is ``O((H/a)^4)``.

The true contact edge lies at the distance ``h^* H`` inside Gamma_0 (3.25), so the contact area is

    |omega| = |omega_0| - h^* H |Gamma_0| + O((H/a)^2) relative.

Error estimate (what :func:`error_estimate` returns, relative)
-------------------------------------------------------------
The expansion parameter is not ``H/a`` alone.  The inner series (2.26) is a series in
``M_k H^{2k} Laplacian^k``: for the paraboloid ``P = P0 [1 - 4 m_1 (H/a)^2 + ...]`` and in general
``e_1 = |P1/P0| ~ |m_1| (H/a)^2`` times a shape factor (``J a^2/V``).  As nu -> 1/2, ``m_1`` grows like
``1/(3 (1 - 2 nu))`` and so do ``M_2 = m_1^2 - m_2 ~ m_1^2`` and the higher ``M_k ~ m_1^k``: the series
is one in ``e_1``, not in ``(H/a)^2``.  The boundary layer has the width ``H`` when ``m_1 = O(1)``,
``sqrt(m_1) H`` near nu = 1/2 (the operator ``1 - m_1 H^2 Laplacian`` of (I.10)), and is displaced by
``h^* H`` (3.25).  All neglected terms are therefore powers of the one ratio

    kappa^2 = e_1 + (1 + h^*^2) (H/a)^2       (boundary-layer width over a, squared; e_1 = |P1/P0|),

and the first neglected force term is ``O(kappa^3)`` (the curvature of Gamma_0 and ``p_1`` seen by
the boundary layer: ``(H/a) x`` the boundary layer's own ``O(kappa^2)``; the inner ``p_2 ~ M_2 H^4`` is
``O(kappa^4) <= O(e_1^2)``, the ``|P1/P0|^2`` of a geometric series).  The estimates are

    force, first correction kept:  E_P  = C_P kappa^3 (1 + kappa),                 C_P = 2,
    force, leading term only:      E_P0 = e_1 + E_P,
    area, first correction kept:   E_A  = C_A (e_1 + (1/4 + h^*^2) (H/a)^2),      C_A = 3/2,
    area, leading term only:       E_A0 = 2 |h^*| H/a + E_A.

In the area, ``e_1`` is the shift of the edge by ``p_1`` (its value at Gamma_0 over ``|grad p_0|``),
``h^*^2 (H/a)^2`` the geometric square of the shift that ``|omega_0| - h^* H |Gamma_0|`` leaves out
(exact for a circle), and ``(H/a)^2/4`` the curvature term of the second-order boundary layer, whose
O(1) constant is not derived: it is bounded by the measured values (0.04 .. 0.15 at nu = 0, where
``m_1 = 0``).  The constants C_P, C_A are safety factors; the estimates were checked against the direct
numerical solution (sphere and ``Phi = r^4/4`` with nu in {-0.5, 0, 0.3, 0.45, 0.49} and a frictionless
base, elliptic paraboloid ``R1/R2 = 4`` with nu in {0, 0.3, 0.45, 0.49}; H/a in {0.05, 0.1, 0.2, 0.35}):
the true relative error is below the estimate in all 64 force cells (ratio estimate/true 1.7 .. 14.6,
refused cells with ``P <= 0`` included) and all 55 area cells (ratio 3.0 .. 17.7)
(``tests/asymptotics/test_validity.py``, ``THINLAYER_SLOW=1``).  The old statement "remainder ~ P0 (H/a)^3" ignored the
growth of ``m_1`` and was 285 times too small at nu = 0.49, H/a = 0.035.

Closed forms are produced for a quadratic punch ``Phi = x^T K x/2 + b^T x + c`` with ``K``
positive definite (the elliptic paraboloid (1.1)): ``omega_0`` is an ellipse with
``|omega_0| = 2 pi D0/sqrt(det K)``, ``V = pi D0^2/sqrt(det K)``, ``J = tr K |omega_0|``,
``D0 = delta0 - min Phi``; and for a radial monomial ``Phi = c r^{2k}``: ``a = (delta0/c)^{1/2k}``,
``|omega_0| = pi a^2``, ``V = pi a^2 delta0 k/(k + 1)``, ``J = 4 pi k delta0``.  Any other punch is
evaluated numerically on the spectral contour (:func:`thinlayer.contact_contour`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import mpmath

from .. import symbols as S
from .._cache import cached
from .._checks import InputError, InputTypeError, check_bounded, parse_nu
from .._checks import positive as _positive
from .._lazy import lazy_function, lazy_module
from ..display import RichDisplay, fmt
from ..errors import boundary, boundary_methods
from ..layers.kernels import LayerKernel
from ..parse import parse_number
from ..punch import Punch, PunchError, is_polynomial_tip
from ..results import checked_lambdify, latex_equation
from .inner import inner_pressure

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it
join_signed = lazy_function("thinlayer.normal", "join_signed")
normal_latex = lazy_function("thinlayer.normal", "normal_latex")  # the printers subclass sympy's

__all__ = [
    "ForceLaw",
    "ForceValues",
    "P",  # noqa: F822 - made on first use (module __getattr__)
    "h_star",  # noqa: F822 - made on first use (module __getattr__)
    "boundary_layer_force_defect",
    "error_estimate",
    "error_estimate_arrays",
    "force_law",
]

@lru_cache(maxsize=1)
def _symbols() -> dict[str, Any]:
    """The symbols of the laws, made on first use (importing this module needs no sympy)."""
    V, J, A0, L0 = sp.symbols(r"V J |\omega_0| |\Gamma_0|", positive=True)
    return {"P": sp.Symbol("P", positive=True), "h_star": sp.Symbol("h^*", real=True), "V": V, "J": J,
            "A0": A0, "L0": L0}


def __getattr__(name: str) -> Any:
    """``P`` (the total force (1.8)) and ``h_star`` (the edge shift (3.25) as a symbol in the contact-area law; its
    value is numeric, per nu): sympy symbols made on first use (PEP 562).
    """
    if name in ("P", "h_star"):
        return _symbols()[name]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


#: order of accuracy of each result, as (exponent of H/a, statement)
ORDERS = {
    "force": (3, "P = P_0 + P_1 + O(P_0 (H/a)^3)"),
    "contact_area": (2, "|omega| = |omega_0| - h^* H |Gamma_0| + O(|omega_0| (H/a)^2)"),
    "pressure_interior": (None, "inner expansion with K terms: O(p_0 (H/a)^(2K)) away from the edge"),
    "pressure_composite": (1, "composite pressure: O(p_max H/a) uniformly (leading-order boundary layer)"),
}


@lru_cache(maxsize=1)
def boundary_layer_force_defect() -> sp.Expr:
    r"""``D = int (Qhat(v) - max(v, 0)) dv = m_1/2``, derived from the boundary layer's Laplace transform.

    With ``Q~(p) = int_0^oo Q(h + tau) e^{-p tau} dtau = sqrt(A) (p + sqrt C)/(p^2 sqrt(p + B))``
    (3.23)-(3.24), ``int_0^oo (Q - tau - h) dtau`` is the ``p^0`` term of ``Q~ - 1/p^2 - h/p``;
    the part ``v < h`` (or ``0 < v < h``) contributes ``-h^2/2``.  Eliminating ``A = B/C`` (3.20)
    and ``C`` by (3.21) leaves a function of ``m_1`` alone.  Returns ``m_1/2`` in the symbol
    ``m_1`` (as an expression in ``thinlayer.layers.kernels`` naming, ``Symbol('m_1')``).
    """
    m1 = sp.Symbol("m_1", real=True)

    def coefficients() -> tuple:
        D = _derived_force_defect()
        if not D.is_polynomial(m1):  # never so far: the expression itself, not kept on disk
            return (D,)
        return ("polynomial", *sp.Poly(D, m1).all_coeffs())

    # the derivation (a series and a simplify, ~1 s) is kept on disk as the exact coefficients in m_1
    # (thinlayer._cache); a value that is not a polynomial with rational coefficients is not kept
    c = cached("boundary_layer_force_defect", (), coefficients)
    return sp.Poly(c[1:], m1).as_expr() if c[0] == "polynomial" else c[0]


def _derived_force_defect() -> sp.Expr:
    """The derivation of :func:`boundary_layer_force_defect`."""
    B, C, p = sp.symbols("B C p", positive=True)
    m1 = sp.Symbol("m_1", real=True)
    A = B / C  # (3.20)
    h = 1 / sp.sqrt(C) - 1 / (2 * B)  # (3.25)
    Qt = sp.sqrt(A) * (p + sp.sqrt(C)) / (p**2 * sp.sqrt(p + B))
    rest = sp.series(Qt - 1 / p**2 - h / p, p, 0, 1).removeO()
    if rest.has(p):
        raise ArithmeticError(f"the Laplace transform has an unexpected singular part at p = 0: {rest}")
    D = sp.expand(rest - h**2 / 2)
    # (3.21): 1/C - 1/(2 B^2) = -m_1
    D = sp.simplify(D.subs(C, 1 / (1 / (2 * B**2) - m1)))
    if D.has(B):
        raise ArithmeticError(f"the force defect does not reduce to a function of m_1: {D}")
    return D


def _force_defect(layer: LayerKernel) -> sp.Expr:
    return boundary_layer_force_defect().subs(sp.Symbol("m_1", real=True), layer.m(1))


# ---------------------------------------------------------------------------------------------
# the shape of the punch: closed-form classes
# ---------------------------------------------------------------------------------------------
#: the largest quadratic punch with a symbolic closed-form law: its eigenvalues and factorisations took 33 s with
#: 20 parameters and 11 s with the 59 terms of x_1**2 (a + b)**58 (2 cores, load 12); 2.5 s at 12 parameters
MAX_QUADRATIC_PARAMETERS = 12
MAX_QUADRATIC_TERMS = 40


def _check_quadratic_size(expr: sp.Expr) -> None:
    """Refuse, before the symbolic work, a quadratic punch whose closed forms would take minutes."""
    why = ("its closed-form force law (eigenvalues, factorisations) took 33 s with 20 parameters and 11 s with the 59 "
           "terms of x_1**2 (a + b)**58; give numbers for some parameters (parameters=, Punch.subs)")
    check_bounded(len(expr.free_symbols - {S.x1, S.x2}), "the number of parameters of a quadratic punch",
                  MAX_QUADRATIC_PARAMETERS, why)
    check_bounded(len(sp.Add.make_args(sp.expand(expr))), "the number of terms of a quadratic punch",
                  MAX_QUADRATIC_TERMS, why)


def _quadratic_data(expr: sp.Expr, poly: sp.Poly | None = None):
    """``(K, b, c)`` if Phi is quadratic with a constant Hessian K, else None (``poly``: Phi's Poly, if known)."""
    poly = sp.Poly(expr, S.x1, S.x2) if poly is None else poly
    if poly.total_degree() != 2:
        return None
    X = sp.Matrix([S.x1, S.x2])
    K = sp.hessian(expr, (S.x1, S.x2))
    b = sp.Matrix([sp.diff(expr, v).subs({S.x1: 0, S.x2: 0}) for v in X])
    c = expr.subs({S.x1: 0, S.x2: 0})
    return K, b, c


def radial_monomial(expr: sp.Expr):
    """``(c, k)`` when ``expr = c r^{2k}`` (``r^2 = x1^2 + x2^2``), else None."""
    return _radial_monomial(expr)


def _radial_monomial(expr: sp.Expr, poly: sp.Poly | None = None):
    """``(c, k)`` if Phi = c (x1^2 + x2^2)^k, else None (``poly``: Phi's Poly, if known)."""
    poly = sp.Poly(expr, S.x1, S.x2) if poly is None else poly
    d = poly.total_degree()
    if d < 2 or d % 2:
        return None
    k = d // 2
    c = poly.coeff_monomial(S.x1**d)
    if c == 0 or sp.expand(expr - c * (S.x1**2 + S.x2**2) ** k) != 0:
        return None
    return c, k


def _eigenvalues(K: sp.Matrix) -> list:
    """The two eigenvalues of the symmetric 2x2 Hessian (closed form when sympy's numeric route fails)."""
    try:
        return list(K.eigenvals(multiple=True))
    except sp.core.evalf.PrecisionExhausted:  # float entries of extreme size (e.g. 1/R with R = 1e-300)
        tr, d = (K[0, 0] + K[1, 1]) / 2, sp.sqrt(((K[0, 0] - K[1, 1]) / 2) ** 2 + K[0, 1] ** 2)
        return [tr + d, tr - d]


def _positive_definite(K: sp.Matrix, name: str) -> None:
    det = sp.simplify(K.det())
    tr = sp.simplify(K.trace())
    for q, what in ((det, "det"), (tr, "trace")):
        if q.is_positive is False or (q.is_number and not q > 0):
            raise PunchError(
                f"the quadratic punch {name} has a Hessian with {what} = {q}: it is not positive definite, "
                "so the contact area {delta0 - Phi > 0} is not bounded (the punch must be convex)"
            )


# ---------------------------------------------------------------------------------------------
# the result objects
# ---------------------------------------------------------------------------------------------
@boundary_methods
@dataclass(frozen=True)
class ForceValues:
    """Numbers of the force law and the area law at one set of parameters.

    ``P0, P1`` leading force and first correction (``force = P0 + P1``); ``area0`` = |omega_0|,
    ``perimeter`` = |Gamma_0|, ``area`` = contact area with its first correction; ``V``, ``J``
    the two integrals of the derivation (module docstring); ``half_width`` = 2|omega_0|/|Gamma_0|
    (the radius for a circle), the ``a`` of the error orders.
    """

    delta0: float
    H: float
    P0: float
    P1: float
    area0: float
    perimeter: float
    edge_shift: float
    V: float
    J: float
    P2: float = 0.0  # the second-order force term (SO.9), 0 at first order
    area2: float = 0.0  # the H^2 terms of the second-order area (SO.10), 0 at first order

    @property
    def force(self) -> float:
        return self.P0 + self.P1 + self.P2

    @property
    def area(self) -> float:
        return self.area0 - self.edge_shift * self.H * self.perimeter + self.area2

    @property
    def half_width(self) -> float:
        return 2 * self.area0 / self.perimeter

    @property
    def H_over_a(self) -> float:
        return self.H / self.half_width


#: safety factors of the error estimates (module docstring, "Error estimate")
ERROR_FACTORS = {"force": 2.0, "contact_area": 1.5}
#: the un-derived O(1) curvature constant of the area remainder, bounded by measurement
_AREA_CURVATURE = 0.25


def error_estimate(values: ForceValues, first_correction: float | None = None, order: int = 1) -> dict[str, float]:
    r"""Relative error estimates ``{"force": E_P, "contact_area": E_A}`` of the force and area laws (1.8), (3.25).

    Parameters
    ----------
    values : ForceValues
        The numbers of the law (:meth:`ForceLaw.evaluate`); ``values.edge_shift`` is ``h^*``.
    first_correction : float | None
        ``P1/P0`` when ``values.P1`` has been dropped (``order=0``); default ``values.P1/values.P0``.
    order : int
        1: the first corrections are kept (estimates of the remainders); 0: the leading terms alone.

    Returns
    -------
    dict
        ``force`` and ``contact_area``: relative sizes (``inf`` when the expansion does not apply at all),
        from ``kappa^2 = |P1/P0| + (1 + h^*^2)(H/a)^2`` as derived in the module docstring.

    Examples
    --------
    >>> v = ForceValues(1.0, 0.1, 100.0, -4.0, 3.0, 6.0, 0.5, 0.0, 0.0)   # H/a = 0.1, P1/P0 = -0.04
    >>> {k: round(e, 6) for k, e in error_estimate(v).items()}    # kappa^2 = 0.04 + 1.25 * 0.01
    {'force': 0.029571, 'contact_area': 0.0675}
    """
    x, h = values.H_over_a, values.edge_shift
    if not values.P0 > 0:
        return {"force": math.inf, "contact_area": math.inf}
    ratio = values.P1 / values.P0 if first_correction is None else first_correction
    if not all(math.isfinite(q) for q in (x, h, ratio)) or x > 1e100:
        return {"force": math.inf, "contact_area": math.inf}
    e1 = abs(ratio)
    x2 = x * x
    k = math.sqrt(e1 + (1.0 + h * h) * x2)
    force = ERROR_FACTORS["force"] * k * k * k * (1.0 + k)
    area = ERROR_FACTORS["contact_area"] * (e1 + (_AREA_CURVATURE + h * h) * x2)
    if order == 0:
        force += e1
        area += 2.0 * abs(h) * x
    return {"force": force, "contact_area": area}


@boundary_methods
@dataclass(frozen=True)
class ForceLaw(RichDisplay):
    r"""``P(delta0)`` and ``|omega|(delta0)`` with their first corrections in H (1.8), (3.25).

    Attributes
    ----------
    layer, punch
        The layer kernel and the punch (symbolic or numeric parameters).
    kind : str
        ``"quadratic"`` (closed form, the elliptic paraboloid (1.1)), ``"radial-monomial"``
        (closed form, ``Phi = c r^{2k}``) or ``"contour"`` (numeric integrals over omega_0).
    P0, P1 : sympy.Expr | None
        Leading force and first correction (sympy), or ``None`` for ``kind == "contour"``.
    area0, perimeter : sympy.Expr | None
        ``|omega_0|`` and ``|Gamma_0|`` (sympy) or ``None``.
    coefficient : sympy.Expr
        ``P1 = coefficient * J`` with ``coefficient = (vartheta H/A)(M_1 + D)``, ``D = m_1/2``.
    V, J : sympy.Expr | None
        ``iint_{omega_0} (delta0 - Phi) dx`` and ``oint_{Gamma_0} |grad Phi| ds`` (closed forms) or None.
    phi_min : sympy.Expr | None
        The lowest value of Phi (closed forms) or None: contact needs ``delta0 > phi_min``.
    """

    layer: LayerKernel
    punch: Punch
    kind: str
    P0: sp.Expr | None
    P1: sp.Expr | None
    area0: sp.Expr | None
    perimeter: sp.Expr | None
    coefficient: sp.Expr
    p1_factor: sp.Expr
    V: sp.Expr | None = None
    J: sp.Expr | None = None
    phi_min: sp.Expr | None = None

    equation = "1.8"

    # ---- symbolic --------------------------------------------------------------------------
    @property
    def force(self) -> sp.Expr | None:
        """``P0 + P1`` (None when the punch has no closed form)."""
        return None if self.P0 is None else self.P0 + self.P1

    @property
    def contact_area(self) -> sp.Expr | None:
        """``|omega_0| - h^* H |Gamma_0|`` in the symbol ``h^*`` (None without a closed form)."""
        return None if self.area0 is None else self.area0 - _symbols()["h_star"] * S.H * self.perimeter

    @property
    def general(self) -> sp.Expr:
        """The law in terms of the integrals ``V``, ``J`` (any punch)."""
        th = self.layer.vartheta
        return th / (self.layer.A * S.H) * _symbols()["V"] + self.coefficient * _symbols()["J"]

    @property
    def arguments(self) -> tuple[sp.Symbol, ...]:
        """``(delta_0, H, mu)`` then the other free symbols (nu, punch parameters, h^*) by name."""
        return law_arguments(self.force, self.contact_area)

    def lambdify(self, args=None, backend: str = "numpy"):
        """``(P, |omega|)`` as one numeric function of :attr:`arguments` (closed forms only)."""
        if self.P0 is None:
            raise InputError(
                f"the force law of {self.punch.name} ({self.punch.expr}) has no closed form; "
                "use .evaluate(delta0, H, mu, ...) (numeric integrals over the contact contour)"
            )
        args = self.arguments if args is None else args
        return lambdify_law(args, (self.force, self.contact_area), backend)

    codegen_name = "force_law"

    def codegen_expressions(self):
        """``(arguments, {name: expression})`` for :mod:`thinlayer.export.codegen` (closed forms only).

        Outputs ``force`` (1.8) and ``contact_area_leading`` (|omega_0|) and, when the perimeter has
        no complete elliptic integral (a circle; none of the target languages has ``E(k)``),
        ``contact_area`` (3.25).  For the elliptic paraboloid multiply ``h^* H`` by the perimeter
        ``4 a E(k)``, ``k = sqrt(1 - b^2/a^2)`` (the modulus; scipy's ``ellipe`` takes ``m = k^2``) yourself.
        """
        if self.P0 is None:
            raise InputError(f"no closed-form force law for {self.punch.name}; code generation needs one")
        outs = {"force": self.force, "contact_area_leading": self.area0}
        if not self.perimeter.has(sp.elliptic_e):
            outs["contact_area"] = self.contact_area
        free = set().union(*(e.free_symbols for e in outs.values()))
        constants = self.codegen_constants() if _symbols()["h_star"] in free else {}
        return tuple(a for a in self.arguments if a in free and a not in constants), outs

    def codegen_constants(self) -> dict:
        """``{h^*: (number, note)}`` when the layer has one edge shift (a numeric nu, the frictionless base), else
        ``{}`` (a symbolic nu: ``h^*`` stays an argument).  Generated code defines it as a named constant.
        """
        try:
            key = self.layer.edge_shift_key
        except ValueError:
            return {}
        from .wiener_hopf import edge_shift

        return {_symbols()["h_star"]: (sp.Float(edge_shift(key, kernel="exact"), 17),
                         f"edge shift h*({layer_label(self.layer)}), exact Wiener-Hopf solution (3.18), (3.25)")}

    def latex(self) -> str:
        th = self.layer.vartheta
        sym = _symbols()
        names = {sym["V"]: r"\iint_{\omega_0}(\delta_0 - \Phi)\,d\mathbf{x}",
                 sym["J"]: r"\oint_{\Gamma_0}|\nabla\Phi|\,ds"}
        rem_P = r" + O\!\left(P_0 \frac{H^3}{a^3}\right)"
        rem_A = r" + O\!\left(|\omega_0| \frac{H^2}{a^2}\right)"
        lead = normal_latex(sp.factor(th / (self.layer.A * S.H)))
        corr = normal_latex(sp.factor(self.coefficient))
        lines = [
            latex_equation("P", join_signed([lead + names[sym["V"]],
                                             corr + names[sym["J"]] if self.coefficient != 0 else ""]) + rem_P, "1.8"),
            latex_equation(r"\int_{-\infty}^{\infty}(\hat Q(v) - \max(v, 0))\,dv",
                           normal_latex(boundary_layer_force_defect()), None),
        ]
        if self.P0 is not None:
            rel = sp.factor(sp.cancel(self.P1 / self.P0))
            bracket = r"\left(" + join_signed(["1", normal_latex(rel)]) + r"\right)" if rel != 0 else ""
            lines.append(latex_equation("P", normal_latex(sp.factor(self.P0)) + bracket + rem_P, "1.8"))
            shift = "- " + normal_latex(sym["h_star"] * S.H * self.perimeter)
            lines.append(latex_equation(r"|\omega|", join_signed([normal_latex(self.area0), shift]) + rem_A, "3.25"))
        else:
            lines.append(latex_equation(r"|\omega|", r"|\omega_0| - h^* H |\Gamma_0|" + rem_A, "3.25"))
        return " \\\\\n".join(lines)

    # ---- numeric -----------------------------------------------------------------------------
    def parameter_values(self, values: dict) -> dict:
        """``{name or symbol: value}`` -> ``{punch parameter symbol: value}`` (matched by name)."""
        return self._numeric_values(values)

    def _numeric_values(self, values: dict) -> dict:
        """``{name or symbol: value}`` -> ``{punch parameter symbol: number}`` (matched by name).

        Each value is a finite number: a string is read by the restricted grammar
        (:func:`thinlayer.parse.parse_number`), never evaluated.
        """
        if not isinstance(values, dict):
            raise InputTypeError(f"parameters must be a dict such as {{'R': 10}}, got {type(values).__name__}")
        by_name = {q.name: q for q in self.punch.parameters}
        out = {}
        for k, v in values.items():
            name = k if isinstance(k, str) else getattr(k, "name", None)
            if name not in by_name:
                raise InputError(f"{k!r} is not a parameter of the punch; its parameters are "
                                 f"{', '.join(by_name) or 'none'}")
            out[by_name[name]] = parse_number(v, f"the value of {name}")
        return out

    def evaluate(self, delta0: Any, H: Any, mu: Any = 1.0, edge_shift: Any = 0.0,
                 parameters: dict | None = None, contour=None, nu: Any = None) -> ForceValues:
        """Numbers of the law at one point (float).

        Parameters
        ----------
        delta0, H, mu : Any
            Indentation, thickness, shear modulus (numbers > 0).
        edge_shift : Any
            ``h^*`` for the area law (e.g. :func:`thinlayer.edge_shift_exact`).
        parameters : dict | None
            Values of the punch parameters (``{symbol or name: number}``) if it has any.
        contour
            A precomputed :class:`thinlayer.ContactContour` for ``kind == "contour"``.
        nu : Any
            Poisson ratio for ``vartheta = mu/(1 - nu)`` when the kernel does not fix it
            (:class:`~thinlayer.FrictionlessLayer`).
        """
        d0, HH, mm = (_positive(x, nm) for x, nm in ((delta0, "delta0"), (H, "H"), (mu, "mu")))
        vals = self._numeric_values(parameters or {})
        nu_free = {S.nu, S.kappa} & (_free(self.coefficient) | _free(self.p1_factor))
        if nu_free:
            raise InputError("evaluate needs a layer with a numeric Poisson ratio, e.g. BondedLayer(0.3)")
        sub = {S.delta0: d0, S.H: HH, S.mu: mm, **vals}
        if nu is not None:
            sub[S.nu] = parse_nu(nu, floats="float", upper_closed=True, symbols=False)
        if _free(self.layer.vartheta) - set(sub):
            raise InputError(f"vartheta = {self.layer.vartheta} needs the Poisson ratio: pass nu= "
                             f"(the {self.layer.name} kernel does not fix it)")
        th = _compiled_number(self.layer.vartheta, sub)
        A = float(self.layer.A)
        P0 = None
        if self.kind != "contour":  # P0 from its closed form: finite even where V alone overflows
            P0, _, area0, per, V, J = self._closed_numbers(sub)
        else:
            from .contour import contact_contour

            Phi = self.punch.expr.xreplace(vals)
            free = Phi.free_symbols - {S.x1, S.x2}
            if free:
                raise InputError(f"the punch parameters {sorted(map(str, free))} need values (parameters=...)")
            c = contour if contour is not None else contact_contour(Phi, d0)
            area0, per = c.area, c.perimeter
            V = c.integrate(lambda a, b: d0 - c.phi(a, b))
            J = c.boundary_integral(c.g, of="s")
        coef = _compiled_number(self.coefficient, sub)
        if P0 is None:
            P0 = th / (A * HH) * V
        return ForceValues(d0, HH, P0, coef * J, float(area0), float(per),
                           float(edge_shift), float(V), float(J))

    def _closed_numbers(self, sub):
        """``P0, P1, |omega_0|, |Gamma_0|, V, J`` at the numbers ``sub``: the closed forms compiled once per set of
        symbols (mpmath at 20 digits: no overflow where only the float result would leave the double range).
        """
        free = (_free(self.P0) | _free(self.area0)) - set(sub)
        if free:
            raise InputError(f"the punch parameters {sorted(map(str, free))} need values (parameters=...)")
        keys = tuple(sorted(sub, key=str))
        f = _compiled_closed_forms(self, keys)
        with mpmath.workdps(20):
            return tuple(float(v) for v in f(*(mpmath.mpf(float(sub[k])) for k in keys)))

    def indentation(self, force: Any, H: Any, mu: Any = 1.0, parameters: dict | None = None,
                    nu: Any = None, order: int = 1) -> float:
        """The inverse problem: ``delta0`` with ``P0(delta0) + P1(delta0) = force`` (numbers).

        ``order=0`` inverts the leading term ``P0`` alone.  For the quadratic punch the truncated law
        is a quadratic in ``D0 = delta0 - min Phi``, solved in closed form (its positive root);
        otherwise a bracketing root search (Brent) on :meth:`evaluate`.
        """
        Pt, HH, mm = (_positive(x, nm) for x, nm in ((force, "force P"), (H, "H"), (mu, "mu")))
        vals = self._numeric_values(parameters or {})
        if self.kind == "quadratic":
            D0 = sp.Symbol("D_0", positive=True)
            sub = {S.H: HH, S.mu: mm, **vals}
            if nu is not None:
                sub[S.nu] = parse_nu(nu, floats="float", upper_closed=True, symbols=False)
            target = self.force if order else self.P0
            law = sp.expand((target - Pt).subs(S.delta0, D0 + self.phi_min).subs(sub))
            a2, a1, a0 = (float(sp.N(law.coeff(D0, k))) for k in (2, 1, 0))
            disc = a1 * a1 - 4 * a2 * a0
            root = (-a1 + math.sqrt(disc)) / (2 * a2) if a1 < 0 else (-2 * a0) / (a1 + math.sqrt(disc))
            return float(sp.N(self.phi_min.subs(sub))) + root
        Phi = self.punch.expr.xreplace(vals)
        from .contour import contact_contour

        lo_c = contact_contour(Phi, 1.0)  # a first look for the minimum of Phi
        phimin = lo_c.min_value

        def resid(d):
            v = self.evaluate(d, HH, mm, parameters=vals, nu=nu)
            return (v.force if order else v.P0) - Pt

        span = max(abs(phimin), 1.0)
        hi = phimin + span
        while resid(hi) < 0:
            span *= 2
            hi = phimin + span
            if span > 1e12:
                raise InputError(f"no indentation gives the force {Pt}")
        lo = phimin + span * 1e-9
        import scipy.optimize as opt

        if resid(lo) > 0:
            lo = phimin + span * 1e-3
        return float(opt.brentq(resid, lo, hi, xtol=1e-14 * span, rtol=1e-13))

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        out = [f"ForceLaw: {self.punch.name} on {self.layer}, {self.kind}   (1.8), (3.25)",
               f"  Φ  = {fmt(self.punch.expr)}"]
        if self.P0 is not None:
            out += ["  P  = P₀ + P₁ + O(P₀ (H/a)³)",
                    f"  P₀ = {fmt(self.P0)}",
                    f"  P₁ = {fmt(self.P1)}",
                    f"  |ω| = {fmt(self.area0)} - h* H {fmt(self.perimeter)} + O(|ω| (H/a)²)"
                    if self.perimeter.is_Atom else
                    f"  |ω| = {fmt(self.area0)} - h* H ({fmt(self.perimeter)}) + O(|ω| (H/a)²)"]
            if self.perimeter.has(sp.elliptic_e):
                out.append("  E(k): complete elliptic integral of the second kind, modulus k (the eccentricity)")
        else:
            out += ["  P  = ϑ/(𝒜 H) ∬_ω₀ (δ₀ - Φ) dx + c ∮_Γ₀ |∇Φ| ds + O(P₀ (H/a)³)",
                    f"  c  = {fmt(self.coefficient)}",
                    "  no closed form: use .evaluate(delta0, H, mu, ...) (integrals over the contact contour)"]
        return out


def layer_label(layer: LayerKernel) -> str:
    """The layer a number belongs to, as a note of generated code says it: ``nu=0.3``, ``frictionless base``.

    >>> from thinlayer import BondedLayer, FrictionlessLayer
    >>> layer_label(BondedLayer("3/10")), layer_label(FrictionlessLayer())
    ('nu=3/10', 'frictionless base')
    """
    text = str(layer)
    if getattr(layer, "base", None) == "frictionless":
        return "frictionless base"
    return text[text.index("(") + 1:-1] if text.startswith("BondedLayer(") and text.endswith(")") else text


def law_arguments(*exprs: sp.Expr | None) -> tuple[sp.Symbol, ...]:
    """``(delta_0, H, mu)`` then the other free symbols of ``exprs`` (None skipped) by name."""
    base = (S.delta0, S.H, S.mu)
    free = set().union(*(e.free_symbols for e in exprs if e is not None))
    return base + tuple(sorted(free - set(base), key=lambda q: q.name))


def lambdify_law(args: tuple, exprs: tuple, backend: str = "numpy"):
    """:func:`~thinlayer.results.checked_lambdify`, with numpy given scipy's complete elliptic integrals
    (``ellipe``, ``ellipk``: the parameter convention of sympy's ``elliptic_e``, ``elliptic_k``).
    """
    if backend == "numpy" and any(e.has(sp.elliptic_e, sp.elliptic_k) for e in exprs):
        from scipy.special import ellipe, ellipk

        checked_lambdify(args, exprs, "sympy")  # names any missing argument
        return sp.lambdify(args, exprs, modules=[{"elliptic_e": ellipe, "elliptic_k": ellipk}, "numpy"], cse=True)
    return checked_lambdify(args, exprs, backend)


# ---------------------------------------------------------------------------------------------
# the stage function
# ---------------------------------------------------------------------------------------------
def error_estimate_arrays(P0: Any, P1: Any, area0: Any, perimeter: Any, H: Any, edge_shift: float
                          ) -> tuple[Any, Any]:
    """:func:`error_estimate` (``order=1``) over numpy arrays: ``(force estimate, area estimate)``.

    inf where the expansion does not apply (``P0 <= 0``, non-finite numbers, ``H/a > 1e100``).
    """
    import numpy as np

    h2 = float(edge_shift) ** 2
    with np.errstate(all="ignore"):
        x2 = np.multiply(perimeter, 0.5 * np.asarray(H, dtype=float))
        x2 /= area0  # H/a, a = 2|omega_0|/|Gamma_0|
        bad = ~np.isfinite(x2)
        bad |= x2 > 1e100
        x2 *= x2
        e1 = np.divide(P1, P0)
        bad |= ~np.isfinite(e1)
        bad |= ~(np.asarray(P0) > 0)
        np.abs(e1, out=e1)
        area = (_AREA_CURVATURE + h2) * x2
        area += e1
        area *= ERROR_FACTORS["contact_area"]
        x2 *= 1.0 + h2
        x2 += e1  # kappa^2
        k = np.sqrt(x2)
        force = k + 1.0
        force *= x2
        force *= k
        force *= ERROR_FACTORS["force"]
        force[bad] = np.inf
        area[bad] = np.inf
    return force, area


@lru_cache(maxsize=1024)
def _free(expr: sp.Expr) -> frozenset:
    """``expr.free_symbols``, kept (sympy walks the tree at every call)."""
    return frozenset(expr.free_symbols)


@lru_cache(maxsize=256)
def _compiled_expr(expr: sp.Expr, keys: tuple) -> Any:
    return sp.lambdify(keys, expr, modules="mpmath")


def _compiled_number(expr: sp.Expr, sub: dict) -> float:
    """``float(expr.subs(sub))`` by a function of the symbols of ``sub`` compiled once (mpmath, 20 digits)."""
    keys = tuple(sorted(sub, key=str))
    with mpmath.workdps(20):
        return float(_compiled_expr(expr, keys)(*(mpmath.mpf(float(sub[k])) for k in keys)))


@lru_cache(maxsize=256)
def _compiled_closed_forms(law: ForceLaw, keys: tuple) -> Any:
    """The closed forms of a quadratic or radial-monomial law as one mpmath function of ``keys`` (cached)."""
    return sp.lambdify(keys, [law.P0, law.P1, law.area0, law.perimeter, law.V, law.J], modules="mpmath")


#: force laws kept for repeated solves (the symbolic law depends on the layer and the punch only)
FORCE_LAW_CACHE = 256


@boundary
def force_law(layer: LayerKernel, punch: Punch) -> ForceLaw:
    r"""Force--indentation law with its first correction in H (1.8), and the contact-area law (3.25).

    Built from the inner terms ``p_0, p_1`` of :func:`thinlayer.inner_pressure` and the boundary
    layer's force defect :func:`boundary_layer_force_defect` (module docstring).

    Examples
    --------
    >>> from thinlayer import BondedLayer, Punch
    >>> law = force_law(BondedLayer(), Punch.paraboloid())
    >>> law.kind
    'quadratic'
    >>> import sympy as sp
    >>> sp.factor(sp.simplify(law.force / law.P0 - 1))     # = -2 m_1 H^2/(R delta0)
    -2*H**2*nu*(4*nu - 1)/(3*R*delta_0*(nu - 1)*(2*nu - 1))
    """
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a thinlayer layer kernel (e.g. BondedLayer(0.3)), got {layer!r}")
    if not is_polynomial_tip(punch):
        punch = Punch(punch)
    if not layer.has_thickness:
        raise InputError("the half-space kernel (L = 1) has no thin-layer expansion; use a layer of finite H")
    try:
        return _force_law_cached(layer, punch)
    except TypeError:  # an unhashable layer or punch: derive it afresh
        return _force_law(layer, punch)


@lru_cache(maxsize=FORCE_LAW_CACHE)
def _force_law_cached(layer: LayerKernel, punch: Punch) -> ForceLaw:
    return _force_law(layer, punch)


def _force_law(layer: LayerKernel, punch: Punch) -> ForceLaw:
    """The derivation of :func:`force_law` (module docstring)."""
    inner = inner_pressure(layer, punch, order=2)
    lap = punch.laplacian()
    p1 = inner.terms[1]
    th = layer.vartheta
    # p_1 = (vartheta H / A) M_1 Laplacian(Phi) (4.1): read the factor off the derived term
    p1_factor = sp.cancel(p1 / lap) if lap != 0 else th * S.H * layer.M(1) / layer.A
    if p1_factor.has(S.x1) or p1_factor.has(S.x2):
        raise ArithmeticError(f"p_1 = {p1} is not proportional to Laplacian(Phi) = {lap}")
    coefficient = sp.factor(p1_factor + th * S.H * _force_defect(layer) / layer.A)
    expr = punch.expr
    quad = _quadratic_data(expr, punch.polynomial)
    if quad is not None:
        _check_quadratic_size(expr)
        K, b, c = quad
        _positive_definite(K, str(expr))
        detK = sp.factor(K.det())
        phimin = sp.simplify(c - (b.T * K.inv() * b)[0, 0] / 2)
        D0 = S.delta0 - phimin
        area0 = 2 * sp.pi * D0 / sp.sqrt(detK)
        V = sp.pi * D0**2 / sp.sqrt(detK)
        J = sp.factor(K.trace()) * area0
        lam = _eigenvalues(K)
        a1, a2 = (sp.sqrt(2 * D0 / q) for q in lam)
        perimeter = 4 * a1 * sp.elliptic_e(sp.simplify(1 - a2**2 / a1**2))
        if (lam[0] - lam[1]).is_zero:
            perimeter = 2 * sp.pi * a1
        kind = "quadratic"
    else:
        rm = _radial_monomial(expr, punch.polynomial)
        if rm is not None:
            cc, k = rm
            if cc.is_number and not cc > 0:
                raise PunchError(f"the punch {expr} opens downwards (coefficient {cc} <= 0): no bounded contact")
            a = (S.delta0 / cc) ** sp.Rational(1, 2 * k)
            area0 = sp.pi * a**2
            V = sp.pi * a**2 * S.delta0 * sp.Rational(k, k + 1)
            J = 4 * sp.pi * k * S.delta0
            perimeter = 2 * sp.pi * a
            kind = "radial-monomial"
            phimin = sp.Integer(0)
        else:
            return ForceLaw(layer, punch, "contour", None, None, None, None, coefficient, p1_factor)
    P0 = th / (layer.A * S.H) * V
    P1 = coefficient * J
    return ForceLaw(layer, punch, kind, P0, P1, area0, perimeter, coefficient, p1_factor, V, J, phimin)
