r"""One call for users: the contact solution for numeric parameters.

:func:`compressible_solution` joins the stages of the paper for a layer of thickness ``H``, shear modulus ``mu``
and Poisson ratio ``nu`` indented by ``delta0`` (or pressed by a force ``P``):

* the leading contact area omega_0 = {delta0 - Phi > 0} and its contour Gamma_0 (3.1)-(3.14)
  (:func:`thinlayer.contact_contour`, closed form for the elliptic paraboloid);
* the edge shift h^* (3.25), exact (Wiener--Hopf with the kernel (2.3)) and Alexandrov's;
* the force (1.8) and the contact area with their first corrections (:mod:`thinlayer.asymptotics.force_law`);
* the composite pressure (:mod:`thinlayer.asymptotics.composite`), built on first use.

Orders of accuracy, in the contact half-width ``a = 2|omega_0|/|Gamma_0|`` (the radius for a
circle): force ``O((H/a)^3)`` relative, contact area ``O((H/a)^2)``, composite pressure ``O(H/a)``
uniformly (inner terms alone: ``O((H/a)^{2K})`` away from the edge).  The constants of these orders
grow like ``m_1 ~ 1/(3 (1 - 2 nu))`` as nu -> 1/2, so every solution carries an error estimate
(:attr:`ContactSolution.error_estimate`, from
:func:`thinlayer.asymptotics.force_law.error_estimate`, whose docstring derives its form from the
structure of the expansion: powers of ``kappa^2 = |P1/P0| + (1 + h^*^2)(H/a)^2``, checked against the
direct solver).

Validity: :func:`compressible_solution` refuses, with a one-line :class:`ValidityError` naming the quantity, its
estimate, the tolerance and the model that would hold, when an estimate exceeds ``tol`` (default 5 %)
or a result would be unphysical (``P <= 0``, area ``<= 0``, a non-finite force, area or pressure).  The
force is computed per unit ``mu`` and scaled at the end, so it overflows only when the true force
exceeds the double range (then the error says so).
"""
from __future__ import annotations

import dataclasses
import math
import numbers
import sys
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cached_property, lru_cache
from typing import Any, ClassVar

import mpmath
import numpy as np

from .. import symbols as S
from .._cache import cached
from .._checks import InputError, InputTypeError, NotDerivedError, check_array_size, check_bounded, parse_nu
from .._checks import positive as _positive
from .._lazy import lazy_function, lazy_module, loaded_types
from ..display import RichDisplay
from ..errors import boundary, boundary_methods
from ..layers.kernels import LayerKernel
from ..punch import Punch, PunchError, is_polynomial_tip
from .composite import BOUNDARY_LAYERS, CompositePressure, composite_pressure
from .force_law import ORDERS, ForceLaw, ForceValues, error_estimate, error_estimate_arrays, force_law

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it
float_latex = lazy_function("thinlayer.normal", "float_latex")
normal_latex = lazy_function("thinlayer.normal", "normal_latex")  # the printers subclass sympy's

__all__ = ["ContactSolution", "ForceArrays", "ValidityError", "compressible_solution", "force_arrays", "numeric_punch",
           "MAX_FORCE_ORDER", "DEFAULT_TOL"]

#: default tolerance of :func:`compressible_solution` on the relative error estimates
DEFAULT_TOL = 0.05
#: most values :func:`force_arrays` computes in one call (refused before any allocation)
MAX_ARRAY_VALUES = 5_000_000
_ARRAY_REASON = "5e6 values take 1.4 s and 0.42 GB (about 85 bytes each); split the arrays"


class ValidityError(InputError):
    """An asymptotic result outside the model's validity (or unphysical); the message is one line.

    Attributes
    ----------
    quantity : str
        ``"force"``, ``"contact_area"`` or ``"pressure"``.
    estimate : float
        The relative error estimate of that quantity (``inf`` when not available).
    tol : float
        The tolerance it was compared with.
    model : str
        The model or solver that would hold there.
    value : float
        The asymptotic value that was refused (``nan`` when there is none).
    """

    def __init__(self, message: str, quantity: str = "", estimate: float = math.inf, tol: float = math.nan,
                 model: str = "", value: float = math.nan):
        super().__init__(message)
        self.quantity, self.estimate, self.tol, self.model, self.value = quantity, estimate, tol, model, value

#: the force and area laws are derived to their first correction in H
MAX_FORCE_ORDER = 2


@lru_cache(maxsize=128)
def _edge_shifts(nu: sp.Rational | str) -> tuple[float, float]:
    from .wiener_hopf import edge_shift_alexandrov, edge_shift_exact

    with mpmath.workdps(20):
        return float(edge_shift_exact(nu, dps=12)), float(edge_shift_alexandrov(nu))


def _check_layer(layer: Any, nu: Any) -> tuple[LayerKernel, float]:
    """The layer and its numeric Poisson ratio (given by the layer, or by ``nu`` for a nu-free kernel)."""
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a thinlayer layer, e.g. BondedLayer(0.3); got {layer!r}")
    if not layer.has_edge_shift or not layer.has_compressible_expansion or layer.symbolic_coefficients:
        raise NotDerivedError(
            f"solve() supports BondedLayer and FrictionlessLayer, got {type(layer).__name__}; "
            "the boundary layer and edge shift are derived for those kernels"
        )
    if layer.parameter is not None:
        raise InputError("solve() needs a numeric Poisson ratio: BondedLayer(0.3) or BondedLayer('3/10'), "
                         "not the symbolic BondedLayer()")
    given = layer.poisson_ratio(nu)  # the layer's own nu, or nu for a kernel that fixes none (frictionless base)
    if layer.numeric_nu is None:
        return layer, parse_nu(given, floats="float", example="0.3, '3/10'")
    return layer, given


@boundary
def numeric_punch(punch: Any, parameters: dict | None = None) -> Punch:
    """The punch as a :class:`~thinlayer.Punch` with every parameter given a number (one clear error if not)."""
    if not is_polynomial_tip(punch):
        punch = Punch(punch)
    if parameters:
        punch = punch.subs(parameters)
    free = punch.parameters
    if free:
        raise PunchError(
            f"the punch {punch.expr} has parameters {', '.join(map(str, free))} without values; "
            f"pass parameters={{{', '.join(repr(str(q)) + ': ...' for q in free)}}} or Punch.subs(...)"
        )
    return punch


@boundary_methods
@dataclass(frozen=True, eq=False)
class ContactSolution(RichDisplay):
    r"""Contact solution for numeric parameters; made by :func:`compressible_solution`.

    Attributes
    ----------
    layer, punch
        The layer and the punch (numeric coefficients).
    delta0, H, mu, nu : float
        Indentation, thickness, shear modulus and Poisson ratio.
    law : ForceLaw
        The symbolic :class:`~thinlayer.asymptotics.force_law.ForceLaw` (derived on first access when the numbers
        came from the numeric route of a quadric punch) and ``values`` its numbers here.
    edge_shift, edge_shift_alexandrov : float
        h^* (3.25) from the exact kernel and from Alexandrov's approximation.
    terms : int
        Number of inner terms in the composite pressure.
    boundary_layer : str
        ``"exact"`` or ``"alexandrov"``: which boundary layer :attr:`pressure` uses.
    error_estimate : dict
        ``{"force": E_P, "contact_area": E_A}``: relative error estimates of :attr:`force` and
        :attr:`contact_area` (:func:`thinlayer.asymptotics.force_law.error_estimate`).
    tol : float
        The tolerance the estimates were accepted with.
    """

    #: the paper's equation this result reproduces
    equation: ClassVar[str] = "1.8"

    layer: LayerKernel
    punch: Punch
    delta0: float
    H: float
    mu: float
    nu: float
    _law: ForceLaw | None
    values: ForceValues
    edge_shift: float
    edge_shift_alexandrov: float
    terms: int = 2
    boundary_layer: str = "exact"
    _contour: Any = field(default=None, repr=False)
    error_estimate: dict = field(default_factory=dict)
    tol: float = DEFAULT_TOL
    order: int = 1  # 2: values carry P_2 and the H^2 area terms of (SO.9), (SO.10)

    # ---- the numbers -------------------------------------------------------------------------
    @property
    def law(self) -> ForceLaw:
        """The symbolic force law (1.8), (3.25) of this layer and punch (derived on first access if need be)."""
        return self._law if self._law is not None else force_law(self.layer, self.punch)

    @property
    def force(self) -> float:
        """Total force ``P`` with its first correction (1.8); remainder ``O(P (H/a)^3)``."""
        return self.values.force

    @property
    def force_leading(self) -> float:
        return self.values.P0

    @property
    def contact_area(self) -> float:
        """``|omega_0| - h^* H |Gamma_0|`` (exact h^*); remainder ``O(|omega| (H/a)^2)``."""
        return self.values.area

    @property
    def contact_area_leading(self) -> float:
        return self.values.area0

    @property
    def contact_area_alexandrov(self) -> float:
        """The contact area with Alexandrov's h^* (3.25) instead of the exact one."""
        return self.values.area0 - self.edge_shift_alexandrov * self.H * self.values.perimeter

    @property
    def half_width(self) -> float:
        """``a = 2 |omega_0|/|Gamma_0|`` (the radius for a circle): the length in the error orders."""
        return self.values.half_width

    @property
    def H_over_a(self) -> float:
        return self.H / self.half_width

    @property
    def order_of_accuracy(self) -> dict[str, tuple[str, float | None]]:
        """``{result: (statement, (H/a)^order)}``: the size of the neglected remainder, relative."""
        eps = self.H_over_a
        out = {}
        orders = dict(ORDERS)
        if self.order == 2:
            from .second_order import ORDERS as ORDERS_2

            orders.update(ORDERS_2)
        for key, (k, text) in orders.items():
            if key == "pressure_interior":
                k = 2 * self.terms
                text = text.replace("2K", str(2 * self.terms)).replace("K", str(self.terms))
            out[key] = (text, eps**k)
        return out

    # ---- geometry and pressure -------------------------------------------------------------
    @cached_property
    def contour(self):
        """The leading contour Gamma_0 (:class:`~thinlayer.ContactContour`)."""
        if self._contour is not None:
            return self._contour
        from .contour import contact_contour

        return contact_contour(self.punch.expr, self.delta0)

    def contains(self, x1: Any, x2: Any):
        """Membership of the contact area (composite pressure > 0)."""
        return self.pressure(x1, x2) > 0

    @cached_property
    def composite(self) -> CompositePressure:
        """The composite pressure object (built on first use; the exact table once per nu)."""
        self.contour  # noqa: B018 - raises early for a non-smooth or multiply connected contour
        if self.order == 2:
            from .second_order import composite_pressure_second_order

            return composite_pressure_second_order(self.layer, self.punch, self.delta0, self.H, self.mu, nu=self.nu)
        return composite_pressure(self.layer, self.punch, self.delta0, self.H, self.mu, self.terms,
                                  self.boundary_layer, nu=self.nu)

    def pressure(self, x1: Any, x2: Any):
        """Composite contact pressure ``p_c(x1, x2)`` (vectorised numpy); :class:`ValidityError` if not finite."""
        with np.errstate(over="ignore", invalid="ignore"):
            p = self.composite(x1, x2)
        bad = ~np.isfinite(np.asarray(p, dtype=float))
        if np.any(bad):
            raise ValidityError(
                f"compressible: the composite pressure is not finite at {int(bad.sum())} of {bad.size} points "
                f"(mu = {self.mu:.3g}, H/a = {self.H_over_a:.3g}: beyond the double range); "
                f"express mu in a larger unit of stress (smaller numbers) or use {_reference_model(self.punch)}",
                "pressure")
        return p

    def lambdify(self):
        """The vectorised pressure function ``(x1, x2) -> p_c``."""
        return self.composite

    # ---- output ------------------------------------------------------------------------------
    @property
    def P2(self) -> float:
        """The second-order force term (SO.9) (0 unless ``order == 2``)."""
        return self.values.P2

    def latex(self) -> str:
        v = self.values
        P0, P1, P2 = v.P0, v.P1, v.P2
        second = self.order == 2
        nu = getattr(self.layer, "nu", None)
        nu = normal_latex(sp.Rational(Fraction(mpmath.nstr(mpmath.mpf(self.nu), 15)))
                      if nu is None or isinstance(nu, mpmath.mpf) else nu)
        if self.layer.base_note:
            nu += rf"\ (\text{{{self.layer.base_note}}})"
        rows = [
            rf"\Phi = {normal_latex(self.punch.expr)},\quad \nu = {nu},\quad \delta_0 = {self.delta0:.6g},"
            rf"\quad H = {self.H:.6g},\quad \mu = {self.mu:.6g},\quad H/a = {self.H_over_a:.4g}",
            rf"P = {P0:.8g} {'-' if P1 < 0 else '+'} {abs(P1):.8g}"
            + (rf" {'-' if P2 < 0 else '+'} {abs(P2):.8g}" if second else "")
            + rf" = {v.force:.8g}\ \left(\pm {self._abs_estimate('force'):.2g}\right) \tag{{{self._tags()[0]}}}",
            rf"|\omega| = {v.area0:.8g} - {self.edge_shift:.8g} \cdot {self.H:.6g} \cdot {v.perimeter:.8g}"
            + (rf" {'-' if v.area2 < 0 else '+'} {abs(v.area2):.8g}" if second else "")
            + rf" = {v.area:.8g}\ \left(\pm {self._abs_estimate('contact_area'):.2g}\right) \tag{{{self._tags()[1]}}}",
            rf"h^* = {self.edge_shift:.10g}\ (\text{{exact}}),\quad \tilde h^* = {self.edge_shift_alexandrov:.10g}"
            r"\ (\text{Alexandrov}) \tag{3.25}",
        ]
        return " \\\\\n".join(rows)

    def report_rows(self, units: dict | None = None) -> tuple[str, list[str]]:
        r"""What a report shows of this solution beside the table every model fills: a sentence and tagged lines.

        The force (1.8) and the contact area (3.25) as leading term and first correction (and the second-order
        terms (SO.9), (SO.10) when ``order == 2``), the numbers to six significant digits.  The hook of the
        report's contact section (:mod:`thinlayer.export.sections.contact`), which asks a result for it instead
        of naming its model.

        Parameters
        ----------
        units : dict, optional
            The LaTeX set after a force (key ``"force"``, e.g. ``r"\,\mathrm{N}"``) and after an area (``"area"``);
            none by default.

        Returns
        -------
        tuple of str and list of str
            The sentence (LaTeX text) and the displayed lines, each ending in its ``\tag``.
        """
        u = units or {}
        force_unit, area_unit = u.get("force", ""), u.get("area", "")
        v, second = self.values, self.order == 2
        tags = self._tags()

        def term(x: float) -> str:  # " + 0.1" or " - 0.1"; nothing for 0
            return "" if x == 0 else f" {'-' if x < 0 else '+'} {float_latex(abs(x), 6)}"

        lead = (r"The force (1.8) and the contact area (3.25) as leading term and first correction:" if not second
                else r"The force (SO.9) and the contact area (SO.10) as leading term, first and second correction:")
        sign = "-" if v.edge_shift >= 0 else "+"
        force = f"P = {float_latex(v.P0, 6)}{term(v.P1)}{term(v.P2) if second else ''}"
        area = (rf"|\omega| = {float_latex(v.area0, 6)} {sign} {float_latex(abs(v.edge_shift), 6)} \cdot "
                rf"{float_latex(self.H, 6)} \cdot {float_latex(v.perimeter, 6)}{term(v.area2) if second else ''}")
        return lead, [rf"{force} = {float_latex(v.force, 6)}{force_unit} \tag{{{tags[0]}}}",
                      rf"{area} = {float_latex(v.area, 6)}{area_unit} \tag{{{tags[1]}}}"]

    def _tags(self) -> tuple[str, str]:
        return ("SO.9", "SO.10") if self.order == 2 else ("1.8", "3.25")

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return str(self).splitlines()

    def __str__(self) -> str:
        v = self.values
        second = self.order == 2
        corr = f"correction {v.P1:+.6g}" + (f", second order {v.P2:+.6g}" if second else "")
        return (
            f"ContactSolution({self.punch.name}: delta0={self.delta0:.6g}, H={self.H:.6g}, mu={self.mu:.6g}, "
            f"nu={self.nu:.6g}{', ' + self.layer.base_note if self.layer.base_note else ''}; "
            f"H/a={self.H_over_a:.3g}{'; second order' if second else ''})\n"
            f"  force        P = {v.force:.8g}  (leading {v.P0:.8g}, {corr}; "
            f"error estimate {self._pct('force')})\n"
            f"  contact area   = {v.area:.8g}  (leading {v.area0:.8g}; error estimate {self._pct('contact_area')})\n"
            f"  edge shift h*  = {self.edge_shift:.10g} exact, {self.edge_shift_alexandrov:.10g} Alexandrov"
        )

    def _abs_estimate(self, key: str) -> float:
        value = self.force if key == "force" else self.contact_area
        return self.error_estimate.get(key, math.nan) * value

    def _pct(self, key: str) -> str:
        e = self.error_estimate.get(key, math.nan)
        return f"{100 * e:.2g} % = +-{self._abs_estimate(key):.2g}"

    def _repr_latex_(self) -> str:
        from ..display import display_math

        return display_math(self.latex())


@boundary
def compressible_solution(layer: LayerKernel, punch: Any, delta0: Any = None, H: Any = None, mu: Any = 1.0, *,
          force: Any = None, parameters: dict | None = None, order: int = 1, terms: int = 2,
          boundary_layer: str = "exact", nu: Any = None, tol: Any = DEFAULT_TOL) -> ContactSolution:
    r"""The compressible thin-layer model: contact solution of a thin layer under a rigid polynomial punch.

    This is one model of the front door :func:`thinlayer.solve` (``model="compressible"``), which also
    chooses the nearly-incompressible models or the direct solver where this one does not hold.

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` with a numeric Poisson ratio in (-1, 1/2), or ``FrictionlessLayer()``
        (a layer on a frictionless base; give ``nu``).
    punch : Any
        A :class:`~thinlayer.Punch` (or a polynomial in ``x_1, x_2``) with numeric coefficients,
        or with ``parameters`` giving them.
    delta0 : Any
        Indentation depth (> 0, above the punch's lowest point).  Give either ``delta0`` or
        ``force``.
    H, mu : Any
        Layer thickness and shear modulus (> 0).
    force : Any
        The inverse problem: the total force P (1.8); ``delta0`` is then found from the force
        law with its first correction.
    order : int
        Corrections in the force and area laws: 0 (leading terms) or 1 (first correction in H,
        the default); higher orders are not derived.
    terms : int
        Inner terms ``p_0 ... p_{terms-1}`` (2.26) in the composite pressure.
    boundary_layer : str
        ``"exact"`` (default) or ``"alexandrov"`` boundary layer in the composite pressure.
    nu : Any
        Poisson ratio for ``vartheta = mu/(1 - nu)`` when the kernel does not fix it
        (``FrictionlessLayer``; its ``m_1 = 0``, so the force has no correction of relative order
        ``(H/a)^2`` and the remainder is ``O((H/a)^3)``).
    tol : Any
        Largest accepted relative error estimate of the force and of the contact area (default 0.05;
        ``math.inf`` accepts any estimate but still refuses unphysical results).

    Returns
    -------
    ContactSolution
        With ``error_estimate = {"force": ..., "contact_area": ...}`` (relative).

    Raises
    ------
    ValidityError
        (a ``ValueError``) when an error estimate exceeds ``tol`` or a result would be unphysical
        (``P <= 0``, area ``<= 0``, non-finite or beyond the double range); the one-line message names
        the quantity, the estimate, ``tol`` and the model that would hold.

    Examples
    --------
    >>> from thinlayer import BondedLayer, Punch
    >>> sol = compressible_solution(BondedLayer("3/10"), Punch.paraboloid(1), delta0=0.01, H=0.01)
    >>> round(sol.edge_shift, 6), round(sol.edge_shift_alexandrov, 6)
    (0.122071, 0.145193)
    >>> round(sol.force / sol.force_leading - 1, 6)      # -2 m1 H^2/(R delta0), m1 = 1/14
    -0.001429
    >>> sol.error_estimate["force"] < 2e-3      # 2 kappa^3 (1 + kappa), kappa^2 = |P1/P0| + (1 + h*^2)(H/a)^2
    True
    >>> compressible_solution(BondedLayer(0.49), Punch.paraboloid(10), delta0=0.1, H=0.5)   # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    thinlayer.asymptotics.solution.ValidityError: compressible: the force error estimate ... exceeds tol = 5 % ...
    """
    layer, nu_value = _check_layer(layer, nu)
    if boundary_layer not in BOUNDARY_LAYERS:
        raise InputError(f"boundary_layer must be one of {BOUNDARY_LAYERS}, got {boundary_layer!r}")
    if isinstance(order, bool) or not isinstance(order, int) or order < 0:
        raise InputError(f"order must be 0, 1 or 2 (corrections in the force law), got {order!r}")
    if order > MAX_FORCE_ORDER:
        raise NotDerivedError(
            f"order={order}: the force and contact-area laws are derived to their second correction in H "
            f"(order <= {MAX_FORCE_ORDER}, (SO.9)-(SO.10)); the next terms need the third-order boundary layer"
        )
    if order == 2 and boundary_layer != "exact":
        raise InputError("order=2 uses the exact boundary layer (SO.7); boundary_layer='alexandrov' is first order")
    if isinstance(terms, bool) or not isinstance(terms, int) or terms < 1:
        raise InputError(f"terms must be an integer >= 1 (inner terms p_0 .. p_(terms-1)), got {terms!r}")
    if H is None:
        raise InputTypeError("solve() needs the layer thickness H")
    HH = _positive(H, "H")
    mm = _positive(mu, "mu")
    tol_v = _check_tol(tol)
    pn = numeric_punch(punch, parameters)
    if (delta0 is None) == (force is None):
        raise InputTypeError("give exactly one of delta0 (indentation) and force (the inverse problem)")
    fast = _quadric_solution(layer, pn, delta0, force, HH, mm, nu_value, order, terms, boundary_layer, tol_v)
    if fast is not None:
        return fast
    law = force_law(layer, pn)
    if force is not None:
        Pt = _positive(force, "force")
        per_mu = Pt / mm  # the law is linear in mu: solve it per unit mu
        if not (math.isfinite(per_mu) and per_mu > 0):
            raise ValidityError(f"compressible: force/mu = {Pt:.3g}/{mm:.3g} is beyond the double range; "
                                "express force and mu in other units", "force")
        try:
            d0 = law.indentation(per_mu, HH, 1.0, nu=nu_value, order=min(order, 1))
            if order == 2:
                d0 = _second_order_indentation(layer, pn, per_mu, HH, nu_value, d0)
        except (OverflowError, ZeroDivisionError) as exc:
            raise ValidityError(f"compressible: the indentation for force = {Pt:.3g} is beyond the double range "
                                f"({exc}); express the lengths in other units", "force") from None
    else:
        d0 = _positive(delta0, "delta0")
    contour = None
    if law.kind == "contour":
        from .contour import contact_contour

        contour = contact_contour(pn.expr, d0)
    else:
        _check_contact(law, d0)
    h_ex, h_al = _edge_shifts(layer.edge_shift_key)
    try:  # per unit mu (P is linear in mu): no overflow where the true force is finite
        vals = law.evaluate(d0, HH, 1.0, edge_shift=h_ex, contour=contour, nu=nu_value)
        if not (vals.area0 > 0 and vals.perimeter > 0 and math.isfinite(vals.half_width)):
            raise ZeroDivisionError(f"|omega_0| = {vals.area0:.3g}, |Gamma_0| = {vals.perimeter:.3g}")
        est = error_estimate(vals, order=order)
    except (OverflowError, ZeroDivisionError) as exc:
        raise ValidityError(f"compressible: the contact geometry is beyond the double range at delta0 = {d0:.3g}, "
                            f"H = {HH:.3g} ({exc}); express the lengths in other units", "force") from None
    if order == 2:
        from .second_order import second_order_error_estimate, second_order_law

        try:
            v2 = second_order_law(layer, pn).evaluate(d0, HH, 1.0, nu=nu_value)
            est = second_order_error_estimate(v2)
        except (OverflowError, ZeroDivisionError) as exc:
            raise ValidityError(f"compressible: the second-order terms are beyond the double range at "
                                f"delta0 = {d0:.3g}, H = {HH:.3g} ({exc}); express the lengths in other units",
                                "force") from None
        vals = dataclasses.replace(vals, P2=v2.P2, area2=v2.area2)
    _check_overflow(vals, mm, est["force"])
    vals = _scaled(vals, mm, min(order, 1))
    _check_validity(layer, pn, nu_value, vals, est, tol_v, mm)
    return ContactSolution(layer, pn, d0, HH, mm, nu_value, law, vals, h_ex, h_al, terms, boundary_layer, contour,
                           est, tol_v, order)


# ---------------------------------------------------------------------------------------------
# the numeric route of a quadric punch (issue 28 item 6): the same law from per-nu numbers kept on disk
# ---------------------------------------------------------------------------------------------
#: whether :func:`compressible_solution` answers a numeric quadric punch by the numeric route (the tests turn it off
#: to hold that route against the symbolic one, tests/asymptotics/test_cold_start.py)
NUMERIC_QUADRIC = True
_CONSTANTS: dict[tuple, tuple[float, ...]] = {}
#: the names of :func:`compressible_constants`' numbers, in the order the disk cache keeps them
CONSTANT_NAMES = ("A", "m1", "c1", "h_exact", "h_alexandrov")


def compressible_constants(layer: LayerKernel) -> dict[str, float]:
    r"""The per-nu numbers of the compressible model, from the disk cache (:mod:`thinlayer._cache`).

    ``A`` (2.4), ``m1`` (2.20), ``c1`` with ``P_1 = vartheta H c_1 J`` (1.8) (``c_1 = (M_1 + D)/A``, ``D = m_1/2``:
    read off the derived :func:`~thinlayer.asymptotics.force_law.force_law`, not written here), and the edge shifts
    h^* (3.25), exact (Wiener--Hopf) and Alexandrov's.  On a cache miss the symbolic route derives them (seconds,
    once per nu and version); a hit needs neither sympy nor scipy.

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> k = compressible_constants(BondedLayer("3/10"))
    >>> round(k["m1"] * 14, 12), round(k["h_exact"], 6)     # m_1 = 1/14 at nu = 3/10
    (1.0, 0.122071)
    """
    key = layer.constants_key
    if key is None:
        raise InputError(f"the compressible model's numbers need a numeric layer on a rigid base, got {layer!r}")
    if key not in _CONSTANTS:
        _CONSTANTS[key] = tuple(cached("compressible_constants", key, lambda: _derived_constants(layer)))
    return dict(zip(CONSTANT_NAMES, _CONSTANTS[key]))


def _derived_constants(layer: LayerKernel) -> tuple[float, ...]:
    """The numbers of :func:`compressible_constants`, derived by the symbolic route."""
    law = force_law(layer, Punch.paraboloid(1))
    c1 = sp.cancel(law.coefficient / (layer.vartheta * S.H))  # (M_1 + D)/A: a number (nu enters vartheta only)
    if not c1.is_number:
        raise ArithmeticError(f"the first correction of (1.8) is not vartheta H times a number: {law.coefficient}")
    h_ex, h_al = _edge_shifts(layer.edge_shift_key)
    return float(layer.A), float(layer.m(1)), float(c1), h_ex, h_al


#: the numeric route keeps to numbers far from the ends of the double range; the symbolic route (mpmath at 20
#: digits) answers, and words its refusals, beyond
_SAFE = (1e-280, 1e280)
#: the curvatures, depth, thickness and modulus the numeric route takes (their products stay inside _SAFE)
_MODERATE = (1e-60, 1e60)


def _quadric_solution(layer: LayerKernel, punch: Punch, delta0: Any, force: Any, H: float, mu: float, nu: float,
                      order: int, terms: int, boundary_layer: str, tol: float) -> ContactSolution | None:
    """:func:`compressible_solution` of a numeric quadric ``Phi = x.Kx/2`` from :func:`compressible_constants`
    and the level set of the punch (:meth:`~thinlayer.punch.Punch.level_set`: ``|omega_0| = 2 pi delta0/sqrt(det K)``,
    ``V = pi delta0^2/sqrt(det K)``, ``J = tr K |omega_0|``, ``|Gamma_0|`` by ``E(k)``), in floats; None where
    the symbolic route answers (other punches, order 2, numbers near the ends of the double range).
    """
    if not NUMERIC_QUADRIC or order not in (0, 1) or layer.constants_key is None:
        return None
    q = punch.quadric
    if q is None or not all(_MODERATE[0] < v < _MODERATE[1] for v in (q[0], q[1], H, mu)):
        return None
    k = compressible_constants(layer)
    th = 1.0 / (1.0 - nu)  # vartheta per unit mu (2.1)
    root_det = math.sqrt(q[0] * q[1])
    if force is not None:  # P0 + P1 = a2 d^2 + a1 d = force/mu, solved as the symbolic route does
        per_mu = _positive(force, "force") / mu
        a2 = th / (k["A"] * H) * math.pi / root_det
        a1 = th * H * k["c1"] * (q[0] + q[1]) * 2 * math.pi / root_det if order else 0.0
        a0 = -per_mu
        if not all(_SAFE[0] < abs(v) < _SAFE[1] for v in (a2, a0)) or not math.isfinite(a1):
            return None
        disc = a1 * a1 - 4 * a2 * a0
        d0 = (-a1 + math.sqrt(disc)) / (2 * a2) if a1 < 0 else (-2 * a0) / (a1 + math.sqrt(disc))
    else:
        d0 = _positive(delta0, "delta0")
    if not _MODERATE[0] < d0 < _MODERATE[1]:
        return None
    ls = punch.level_set(d0)
    vals = ForceValues(d0, H, th / (k["A"] * H) * ls.volume, th * H * k["c1"] * ls.flux, ls.area, ls.perimeter,
                       k["h_exact"], ls.volume, ls.flux)
    numbers = (vals.P0, vals.area0, vals.perimeter, vals.V, vals.J, vals.P0 * mu, vals.half_width, H / vals.half_width)
    if not all(_SAFE[0] < abs(v) < _SAFE[1] for v in numbers) or not math.isfinite(vals.P1 * mu):
        return None
    est = error_estimate(vals, order=order)
    vals = _scaled(vals, mu, order)
    _check_validity(layer, punch, nu, vals, est, tol, mu, k["m1"])
    return ContactSolution(layer, punch, d0, H, mu, nu, None, vals, k["h_exact"], k["h_alexandrov"], terms,
                           boundary_layer, None, est, tol, order)


def _second_order_indentation(layer, punch, per_mu, H, nu, guess):
    """``delta0`` with ``P0 + P1 + P2 = per_mu`` (per unit mu): Brent's method around the first-order depth."""
    from scipy.optimize import brentq

    from .second_order import second_order_law

    law = second_order_law(layer, punch)

    def resid(d):
        return law.evaluate(d, H, 1.0, nu=nu).force - per_mu

    lo, hi = guess, guess
    for _ in range(60):
        lo, hi = lo * 0.9, hi * 1.1
        try:
            if resid(lo) < 0 < resid(hi):
                return brentq(resid, lo, hi, xtol=1e-15 * guess, rtol=1e-14)
        except (ValueError, PunchError):
            continue
    raise ValidityError(f"compressible: no depth gives the second-order force {per_mu:.6g} mu near the first-order "
                        f"depth {guess:.6g}; use order=1 or model='direct'", "force")


@boundary_methods
@dataclass(frozen=True)
class ForceArrays:
    """The compressible model's force (1.8) and contact area (3.25) over arrays of depths (:func:`force_arrays`).

    Attributes
    ----------
    delta0 : numpy.ndarray
        The depths (broadcast with ``H``).
    force, contact_area : numpy.ndarray
        ``P0 + P1`` and ``|omega_0| - h^* H |Gamma_0|``; NaN wherever ``valid`` is False.
    force_leading : numpy.ndarray
        ``P0`` (NaN where not valid).
    error_estimate : dict
        ``{"force": array, "contact_area": array}`` (relative; inf where the expansion does not apply).
    valid : numpy.ndarray
        Where both estimates are within ``tol`` and force and area are positive and finite.
    """

    delta0: Any
    force: Any
    force_leading: Any
    contact_area: Any
    error_estimate: dict
    valid: Any
    tol: float


@lru_cache(maxsize=128)
def _array_law(law: Any, keys: tuple) -> Any:
    per = law.perimeter  # E(k) of an ellipse (k = e): its eccentricity does not depend on the depth, a number here
    per = per.xreplace({e: e.evalf(20) for e in per.atoms(sp.elliptic_e) if e.args[0].is_number})
    return sp.lambdify(keys, [law.P0, law.P1, law.area0, per], modules="numpy")


@boundary
def force_arrays(layer: LayerKernel, punch: Any, delta0: Any, H: Any, mu: Any = 1.0, *, nu: Any = None,
                 parameters: dict | None = None, tol: Any = DEFAULT_TOL) -> ForceArrays:
    r"""The force law (1.8) with its first correction and the area law (3.25) over numpy arrays of ``delta0``.

    For the punches with closed forms (quadratic, radial monomial): the symbolic law is derived once per
    (layer, punch) and compiled once; ``delta0`` and ``H`` broadcast (``mu`` scalar).  Where the estimate of
    :func:`thinlayer.asymptotics.force_law.error_estimate` exceeds ``tol``, or force or area are not positive and
    finite (no contact, overflow), the values are NaN and ``valid`` is False: never an unflagged negative or
    infinite force.  Equal to :func:`compressible_solution` point by point (to rounding).

    Examples
    --------
    >>> import numpy as np
    >>> from thinlayer import BondedLayer, Punch
    >>> out = force_arrays(BondedLayer(0.3), Punch.paraboloid(10), np.array([1e-4, 0.1, 1.0]), H=0.02)
    >>> out.valid.tolist(), bool(np.isnan(out.force[0]))        # 1e-4: contact too small for H = 0.02
    ([False, True, True], True)
    """
    for name, v in (("delta0", delta0), ("H", H)):  # before any other work
        check_array_size(v, name, MAX_ARRAY_VALUES, _ARRAY_REASON)
    layer, nu_value = _check_layer(layer, nu)
    tol_v = _check_tol(tol)
    mm = _positive(mu, "mu")
    pn = numeric_punch(punch, parameters)
    law = force_law(layer, pn)
    if law.kind == "contour":
        raise InputError("force_arrays needs a punch with a closed-form law (quadratic or (x1^2 + x2^2)^k); "
                         "this one needs its contour at every depth: use compressible_solution per depth")
    try:
        d0 = np.asarray(delta0, dtype=float)
        HH = np.asarray(H, dtype=float)
    except (TypeError, ValueError):
        raise InputTypeError("force_arrays: delta0 and H must be numbers or arrays of numbers") from None
    check_bounded(d0.size * max(HH.size, 1), "the number of depth x thickness values", MAX_ARRAY_VALUES,
                  _ARRAY_REASON)
    keys = [S.delta0, S.H, S.mu] + ([S.nu] if S.nu in (law.P0.free_symbols | law.P1.free_symbols) else [])
    args = [d0, HH, mm] + ([nu_value] if len(keys) == 4 else [])
    with np.errstate(all="ignore"):
        P0, P1, area0, per = (np.asarray(v, dtype=float) for v in _array_law(law, tuple(keys))(*args))
        h_ex, _ = _edge_shifts(layer.edge_shift_key)
        est_f, est_a = error_estimate_arrays(P0, P1, area0, per, HH, h_ex)
        force = P0 + P1
        area = per * (-h_ex * HH)
        area += area0
        valid = est_f <= tol_v  # inf (and so False) wherever P0 <= 0 or a number is not finite
        valid &= est_a <= tol_v
        valid &= force > 0
        valid &= area > 0
        valid &= np.isfinite(force)
        valid &= np.isfinite(area)
        invalid = ~valid
        force[invalid] = np.nan
        area[invalid] = np.nan
        P0 = np.where(valid, P0, np.nan)
    return ForceArrays(np.broadcast_to(d0, valid.shape), force, P0, area, {"force": est_f, "contact_area": est_a},
                       valid, tol_v)


def _check_tol(tol: Any) -> float:
    if isinstance(tol, bool) or not isinstance(tol, (numbers.Real, *loaded_types("sympy", "Number"))) \
            or not float(tol) > 0:
        raise InputError(f"tol must be a positive number (the largest accepted relative error estimate, "
                         f"e.g. 0.05; math.inf accepts any), got {tol!r}")
    return float(tol)


def _scaled(vals: ForceValues, mu: float, order: int) -> ForceValues:
    """The values per unit mu times mu (the leading terms alone for ``order == 0``)."""
    P0 = vals.P0 * mu
    P1 = vals.P1 * mu if order else 0.0
    return ForceValues(vals.delta0, vals.H, P0, P1, vals.area0, vals.perimeter,
                       vals.edge_shift if order else 0.0, vals.V, vals.J, vals.P2 * mu, vals.area2)


def _reference_model(punch: Punch) -> str:
    if punch.axisymmetric:
        return "the direct numerical solver thinlayer.numerics.solve_axisymmetric"
    return "the direct numerical solver thinlayer.numerics.solve_2d"


def _validity_model(layer: LayerKernel, punch: Punch, vals: ForceValues, m1: float | None = None) -> str:
    """The model that would hold: the direct solver, and the two-term model where m_1 (nu -> 1/2) dominates
    (``m1``: the layer's m_1 if known, else derived).
    """
    model = _reference_model(punch)
    x = vals.H_over_a
    e1 = abs(vals.P1 / vals.P0) if vals.P0 else 0.0
    if not layer.has_two_term_model:
        m1 = 0.0
    elif m1 is None:
        m1 = float(layer.m(1))
    if m1 > 0 and e1 > (1.0 + vals.edge_shift**2) * x * x:
        lam2 = 1.0 / (m1 * x * x) if x > 0 else math.inf
        where = ("thinlayer.asymptotics.incompressible.two_term_sphere" if punch.axisymmetric and punch.is_numeric
                 and punch.degree == 2
                 else "thinlayer.asymptotics.incompressible (regime(), solve_obstacle_grid)")
        model += (f", or for nu near 1/2 the two-term/incompressible model {where} "
                  f"(lambda^2 = (a/H)^2/m1 = {lam2:.3g})")
    return model


def _check_overflow(unit: ForceValues, mu: float, estimate: float = math.nan) -> None:
    """The force per unit mu is finite and positive, but times mu beyond the double range.

    ``estimate`` (the force's relative error estimate) goes with the error: :func:`thinlayer.solve` takes "other
    units" for the true reason only where the model holds (the estimate within its tolerance).
    """
    P = unit.force
    if math.isfinite(P) and P > 0 and 0 < P * mu < sys.float_info.min:
        raise ValidityError(f"compressible: the force P = {P * mu:.3g} underflows double precision (below "
                            f"{sys.float_info.min:.3g}) at mu = {mu:.3g}; express mu (and P) in a smaller unit "
                            "of stress", "force", estimate, math.nan, "other units")
    if math.isfinite(unit.P0) and unit.P0 > 0 and P > 0 and not math.isfinite(unit.P0 * mu):
        mag = math.log10(P) + math.log10(mu)
        raise ValidityError(f"compressible: the force P = 1e{mag:.2f} overflows double precision (max 1.8e308) at "
                            f"mu = {mu:.3g}; express mu (and P) in a larger unit of stress", "force",
                            estimate, math.nan, "other units")


def _check_validity(layer: LayerKernel, punch: Punch, nu: float, vals: ForceValues, est: dict, tol: float,
                    mu: float, m1: float | None = None) -> None:
    """Raise :class:`ValidityError` for a non-finite or unphysical result or an estimate above ``tol``."""
    x = vals.H_over_a
    where = f"nu = {nu:.4g}, H/a = {x:.3g}"
    for name, q in (("force", vals.force), ("contact_area", vals.area), ("perimeter", vals.perimeter)):
        if not math.isfinite(q) and math.isfinite(x) and x < 0.1:  # the expansion holds: a number beyond range
            raise ValidityError(f"compressible: the {name.replace('_', ' ')} is beyond the double range (about "
                                f"1.8e308) at {where}, where the thin-layer expansion holds; express the lengths and "
                                "the moduli in other units", name, x * x, tol, "other units")
        if not math.isfinite(q):
            raise ValidityError(f"compressible: the {name.replace('_', ' ')} is not finite ({q}) at {where}; "
                                f"use {_reference_model(punch)} or other units",
                                name, est.get(name, math.inf), tol, _reference_model(punch))
    model = _validity_model(layer, punch, vals, m1)
    for key in ("force", "contact_area"):
        e = est[key]
        if not e <= tol:
            value = vals.force if key == "force" else vals.area
            sign = f"; the asymptotic value {value:.4g} is unphysical" if value <= 0 else ""
            raise ValidityError(
                f"compressible: the {key.replace('_', ' ')} error estimate {_percent(e)} exceeds tol = {_percent(tol)} "
                f"({where}, |P1/P0| = {abs(vals.P1 / vals.P0) if vals.P0 else math.inf:.3g}: outside the "
                f"thin-layer expansion{sign}); use {model}", key, e, tol, model, value)
    if vals.force <= 0 and vals.P0 > 0 and mu > 0:
        raise ValidityError(f"compressible: the asymptotic force P = {vals.force:.4g} <= 0 is unphysical ({where}; "
                            f"estimate {_percent(est['force'])}); use {model}", "force", est["force"], tol, model,
                            vals.force)
    if vals.force <= 0:
        raise ValidityError(f"compressible: the force P = {vals.force:.4g} underflows or is not positive at mu = "
                            f"{mu:.3g}; express mu (and P) in a smaller unit of stress", "force",
                            est["force"], tol, "other units")
    if vals.area <= 0:
        raise ValidityError(f"compressible: the asymptotic contact area {vals.area:.4g} <= 0 is unphysical ({where}; "
                            f"estimate {_percent(est['contact_area'])}); use {model}", "contact_area",
                            est["contact_area"], tol, model, vals.area)


def _percent(e: float) -> str:
    return "inf" if math.isinf(e) else f"{100 * e:.3g} %"


def _check_contact(law: ForceLaw, d0: float) -> None:
    """For a closed-form punch: delta0 must exceed the lowest point of Phi."""
    phimin = float(law.phi_min)
    if d0 <= phimin:
        raise InputError(f"no contact: delta0 = {d0:g} does not exceed the lowest point of the punch, "
                         f"min Phi = {phimin:g}; take delta0 > {phimin:g}")
