r"""The cases of the validation study: the two punch shapes, the input checks and one row per case.

For each case -- a punch shape, a Poisson ratio ``nu`` and a thickness ratio ``H/a`` -- the
asymptotic solution (:func:`thinlayer.solve`: force (1.8) with its first correction, contact area
with the exact edge shift h^* (3.25), composite pressure) is compared with an independent direct
solution of (1.5)-(1.8) that uses no thin-layer series:

* ``"sphere"``: the paraboloid of revolution ``Phi = r^2/(2R)``, R = 1, delta0 = 1/2, so the leading
  contact radius is ``a_0 = 1`` and ``H = (H/a) a_0``.  Numerics: the spectral axisymmetric solver
  (:func:`thinlayer.numerics.solve_axisymmetric`; its force is converged to ~1e-12, far below every
  asymptotic error measured here).
* ``"elliptic"``: the elliptic paraboloid (1.1) with ``R1/R2 = 4`` (R1 = 4, R2 = 1, delta0 = 1/2:
  semi-axes ``a_1 = 2``, ``a_2 = 1`` of Gamma_0), ``a = 2|omega_0|/|Gamma_0|`` the half-width of
  :class:`~thinlayer.ContactSolution`.  Numerics: the FFT/Polonsky--Keer solver
  :func:`thinlayer.numerics.solve_2d` on a grid of ``cells_per_H`` cells per layer thickness, and a
  second, coarser grid (Delta = H/5, the solver's limit) for an error estimate: the 2D force error is
  ``~ c (Delta/a)^2`` (c = 0.08-0.19 measured against the axisymmetric solver on the sphere) and the
  coarse grid's error is the larger, so ``|P_fine - P_coarse|/P`` estimates the fine grid's error from
  above (on the sphere at H/a = 0.1 and 0.05, with the same grids: 1.1 and 1.4 times the true error).
  Likewise for the area, the semi-axes and the pressure.

Errors are relative, ``asymptotic/numeric - 1``, for the force ``P = P_0 + P_1`` and the leading
``P_0``; for the contact area ``|omega_0| - h^* H |Gamma_0|``, the leading ``|omega_0|`` and the
area with Alexandrov's h^*.  The pressure error is ``max |p_c - p_num| / max p_num`` (sphere: on a
radial line through the whole contact, edge included; elliptic: on the cells at least three cells
inside the numerical contact edge, where the piecewise-constant numerical pressure is accurate --
nearer the edge its own error, ~5e-3 p_max at Delta = H/8, is as large as the asymptotic one).
Next to them, the second-order force ``P_0 + P_1 + P_2`` (SO.9) and area (SO.10) of
:mod:`thinlayer.asymptotics.second_order`, with the same numerical reference.
"""
from __future__ import annotations

import math
import numbers
import time
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field
from fractions import Fraction
from types import MappingProxyType
from typing import Any

import numpy as np

from .._checks import InputError, InputTypeError, check_list, parse_nu

__all__ = [
    "CLAIMED_ORDERS",
    "H_OVER_A_RANGE",
    "NUS",
    "SHAPES",
    "ContourData",
    "PressureProfile",
    "ValidationRow",
    "check_nu",
    "check_nus",
    "check_ratio",
    "check_ratios",
    "check_shapes",
    "elliptic_grid",
]

#: the punch shapes of the study
SHAPES = ("sphere", "elliptic")
#: Poisson ratios of the study (issue 4)
NUS = (0.0, 0.2, 0.3, 0.4, 0.45)
#: admissible thickness ratios H/a (issue 4); beyond, the asymptotics or the numerics are out of their range
H_OVER_A_RANGE = (0.0125, 0.2)
#: default ratios: a factor 2 apart
QUICK_RATIOS = (0.2, 0.1, 0.05, 0.025, 0.0125)
#: ratios of the full study: a factor sqrt(2) apart
FULL_RATIOS = tuple(round(0.2 * 2.0 ** (-k / 2.0), 12) for k in range(9))
#: the elliptic cases of the quick study (the 2D solver is the expensive part)
QUICK_ELLIPTIC = {"nus": (0.3,), "ratios": (0.2, 0.1)}
#: ``{quantity: (order, kind)}``: claimed order of the relative remainder in H/a; kind "equal" (the
#: remainder is of exactly this order) or "bound" (at most of this order)
CLAIMED_ORDERS = MappingProxyType({
    "force": (3, "equal"),
    "contact_area": (2, "equal"),
    "pressure": (1, "bound"),
})
#: the leading terms alone, for contrast (kind "contrast": shown, not judged): the first corrections matter
CONTRAST_ORDERS = MappingProxyType({
    "force_leading": (2, "contrast"),
    "contact_area_leading": (1, "contrast"),
})
#: the second-order laws (SO.9), (SO.10) of :mod:`thinlayer.asymptotics.second_order`: remainders O((H/a)^4) and
#: O((H/a)^3); kind "reported": the observed slope is shown next to the claim, not judged (over the study's range
#: the small second-order remainders are partly pre-asymptotic and change sign where two of their terms compete;
#: their asymptotic orders are checked against the direct solver on ranges chosen for it, with the asymptotics)
SECOND_ORDERS = MappingProxyType({
    "force_second": (4, "reported"),
    "contact_area_second": (3, "reported"),
})
#: every quantity with an order: the claimed ones, the second order and the contrast
ORDERS = MappingProxyType({**CLAIMED_ORDERS, **SECOND_ORDERS, **CONTRAST_ORDERS})
#: an observed order matches a claim when within this distance (or above claim - this, for a bound)
ORDER_TOLERANCE = 0.4
#: a numerical result resolves an asymptotic error when its error estimate is below error/RESOLUTION
RESOLUTION = 3.0

# the geometry of the two shapes
SPHERE_R, DELTA0 = 1.0, 0.5  # a_0 = sqrt(2 R delta0) = 1
_ELLIPSE_R = (4.0, 1.0)  # a_1 = 2, a_2 = 1
_PRESSURE_BAND_CELLS = 3  # 2D pressure error: cells at least this far inside the numerical edge
_COARSE_CELLS_PER_H = 5.0  # the 2D solver's limit; the coarse grid of the error estimate


# ---------------------------------------------------------------------------------------------
# result objects
# ---------------------------------------------------------------------------------------------
def readonly(a: Any) -> np.ndarray:
    """A read-only float copy of ``a`` (the arrays of the frozen results)."""
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


def jsonable(obj: Any) -> Any:
    """``obj`` with tuples as lists, numpy scalars as Python numbers and non-finite floats as None."""
    if isinstance(obj, dict):
        return {str(k): jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [jsonable(v) for v in obj]
    if isinstance(obj, (bool, np.bool_)):
        return bool(obj)
    if isinstance(obj, (numbers.Integral,)):
        return int(obj)
    if isinstance(obj, (numbers.Real, np.floating)):
        v = float(obj)
        return v if math.isfinite(v) else None
    return obj


@dataclass(frozen=True)
class ValidationRow:
    """One case of the study: asymptotic against numerical results.

    Attributes
    ----------
    shape, nu, H_over_a
        The case: ``"sphere"`` or ``"elliptic"``, Poisson ratio, thickness ratio ``H/a``.
    H, delta0, half_width : float
        Thickness, indentation and ``a = 2|omega_0|/|Gamma_0|``.
    force_numeric, force_asymptotic, force_leading : float
        ``P`` numerical, ``P_0 + P_1`` (1.8) and ``P_0``.
    force_numeric_error : float
        Estimated relative error of ``force_numeric``.
    area_numeric, area_asymptotic, area_leading, area_alexandrov : float
        Contact area: numerical, ``|omega_0| - h^* H |Gamma_0|`` (3.25), ``|omega_0|``, and with
        Alexandrov's h^*.
    area_numeric_error : float
        Estimated relative error of ``area_numeric``.
    semi_axes_numeric, semi_axes_asymptotic, semi_axes_leading : tuple[float, float]
        Contact semi-axes (x1, x2): numerical, ``a_i - h^* H`` and ``a_i`` (the radius twice for the sphere).
    edge_shift_numeric, edge_shift_numeric_error : float
        ``(a_i - s_i)/H`` from the numerics (mean over the two axes) and its estimated error.
    edge_shift_exact, edge_shift_alexandrov : float
        h^* (3.25): exact (Wiener--Hopf) and Alexandrov's.
    pressure_error : float
        ``max |p_c - p_num| / max p_num`` (see the module docstring for the region).
    pressure_band : float
        Width of the band inside the numerical contact edge left out of ``pressure_error`` (0 for the sphere).
    pressure_numeric_error : float
        Estimated error of the numerical pressure in the same norm.
    solver : str
        The numerical method and its resolution.
    seconds_numeric, seconds_asymptotic : float
        Wall time of the numerical solution(s) and of :func:`thinlayer.solve` with the pressure evaluation
        (and the second-order laws).
    force_second, area_second : float
        The second-order force ``P_0 + P_1 + P_2`` (SO.9) and contact area (SO.10)
        (:func:`thinlayer.asymptotics.second_order.second_order_law`); NaN where not computed.
    """

    shape: str
    nu: float
    H_over_a: float
    H: float
    delta0: float
    half_width: float
    force_numeric: float
    force_asymptotic: float
    force_leading: float
    force_numeric_error: float
    area_numeric: float
    area_asymptotic: float
    area_leading: float
    area_alexandrov: float
    area_numeric_error: float
    semi_axes_numeric: tuple[float, float]
    semi_axes_asymptotic: tuple[float, float]
    semi_axes_leading: tuple[float, float]
    edge_shift_numeric: float
    edge_shift_numeric_error: float
    edge_shift_exact: float
    edge_shift_alexandrov: float
    pressure_error: float
    pressure_band: float
    pressure_numeric_error: float
    solver: str
    seconds_numeric: float
    seconds_asymptotic: float
    force_second: float = math.nan
    area_second: float = math.nan

    # ---- relative errors of the asymptotic results -----------------------------------------
    def _relative(self, value: float, reference: float) -> float:
        return value / reference - 1.0

    @property
    def force_error(self) -> float:
        """``(P_0 + P_1)/P_num - 1``: claimed O((H/a)^3)."""
        return self._relative(self.force_asymptotic, self.force_numeric)

    @property
    def force_leading_error(self) -> float:
        """``P_0/P_num - 1``."""
        return self._relative(self.force_leading, self.force_numeric)

    @property
    def area_error(self) -> float:
        """``(|omega_0| - h^* H |Gamma_0|)/|omega_num| - 1``: claimed O((H/a)^2)."""
        return self._relative(self.area_asymptotic, self.area_numeric)

    @property
    def area_leading_error(self) -> float:
        """``|omega_0|/|omega_num| - 1``."""
        return self._relative(self.area_leading, self.area_numeric)

    @property
    def area_alexandrov_error(self) -> float:
        """The area with Alexandrov's h* (3.25), relative to the numerical one."""
        return self._relative(self.area_alexandrov, self.area_numeric)

    @property
    def force_second_error(self) -> float:
        """``(P_0 + P_1 + P_2)/P_num - 1`` (SO.9): O((H/a)^4)."""
        return self._relative(self.force_second, self.force_numeric)

    @property
    def area_second_error(self) -> float:
        """The second-order area (SO.10) relative to the numerical one: O((H/a)^3)."""
        return self._relative(self.area_second, self.area_numeric)

    def errors(self) -> dict[str, float]:
        """``{quantity: relative error}``: the claimed quantities, the second order, the leading terms and
        Alexandrov's area.
        """
        return {"force": self.force_error, "contact_area": self.area_error, "pressure": self.pressure_error,
                "force_second": self.force_second_error, "contact_area_second": self.area_second_error,
                "force_leading": self.force_leading_error, "contact_area_leading": self.area_leading_error,
                "contact_area_alexandrov": self.area_alexandrov_error}

    def numeric_error(self, quantity: str) -> float:
        """Estimated error of the numerical value entering ``quantity``'s error."""
        if quantity.startswith("force"):
            return self.force_numeric_error
        if quantity.startswith("contact_area"):
            return self.area_numeric_error
        if quantity == "pressure":
            return self.pressure_numeric_error
        raise InputError(f"unknown quantity {quantity!r}; known: {', '.join(self.errors())}")

    def resolved(self, quantity: str) -> bool:
        """True when the numerical error estimate is below ``|asymptotic error| / RESOLUTION``."""
        err = abs(self.errors()[quantity])
        num = self.numeric_error(quantity)
        return bool(math.isfinite(num) and num * RESOLUTION < err)

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d.update({f"{q}_error": e for q, e in self.errors().items() if q != "pressure"})
        d["resolved"] = {q: self.resolved(q) for q in self.errors()}
        return jsonable(d)


@dataclass(frozen=True, eq=False)
class PressureProfile:
    """Pressure along a line: numerical against composite asymptotic, for the plots.

    ``x`` is the coordinate along ``axis`` (``"r"``, ``"x1"`` or ``"x2"``), the other coordinate
    being ``offset``; ``edge`` the numerical contact edge on that line.
    """

    shape: str
    nu: float
    H_over_a: float
    axis: str
    offset: float
    x: np.ndarray = field(repr=False)
    numeric: np.ndarray = field(repr=False)
    asymptotic: np.ndarray = field(repr=False)
    half_width: float = 1.0
    edge: float = float("nan")


@dataclass(frozen=True, eq=False)
class ContourData:
    """Contact contours for the plots: numerical polygon(s), Gamma_0 moved in by ``h^* H`` (exact h^*),
    ``Gamma_0`` itself and Gamma_0 moved in by Alexandrov's h^*.
    """

    shape: str
    nu: float
    H_over_a: float
    numeric: tuple = field(repr=False)
    asymptotic: np.ndarray = field(repr=False)
    leading: np.ndarray = field(repr=False)
    alexandrov: np.ndarray = field(repr=False)



# ---------------------------------------------------------------------------------------------
# input checks (the rules themselves live in thinlayer._checks; these word them for the study)
# ---------------------------------------------------------------------------------------------
def check_nu(nu: Any) -> float:
    """A Poisson ratio of the study: a real number with ``-1 < nu < 1/2``, as a float.

    Parameters
    ----------
    nu : real number
        The Poisson ratio of the bonded (compressible) layer.

    Returns
    -------
    float

    Raises
    ------
    TypeError
        ``nu`` is not a real number (a string or a bool included).
    ValueError
        ``nu`` is outside the admissible range.

    Examples
    --------
    >>> check_nu(3 / 10)
    0.3
    """
    if isinstance(nu, bool) or not isinstance(nu, numbers.Real):
        raise InputTypeError(f"nu must be a real number in (-1, 1/2), got {nu!r} ({type(nu).__name__})")
    return float(parse_nu(nu, floats="float", symbols=False,
                          range_hint="the validation study covers the compressible layer"))


def check_ratio(eps: Any) -> float:
    """A thickness ratio ``H/a`` in the validated range :data:`H_OVER_A_RANGE` = [0.0125, 0.2], as a float.

    Parameters
    ----------
    eps : real number
        The thickness ratio ``H/a``; the ends of the range are admitted to within a relative 1e-9.

    Returns
    -------
    float

    Raises
    ------
    TypeError
        ``eps`` is not a real number.
    ValueError
        ``eps`` is outside the validated range.

    Examples
    --------
    >>> check_ratio(0.1)
    0.1
    """
    if isinstance(eps, bool) or not isinstance(eps, numbers.Real):
        raise InputTypeError(f"H/a must be a real number in [{H_OVER_A_RANGE[0]}, {H_OVER_A_RANGE[1]}], got {eps!r}")
    v = float(eps)
    lo, hi = H_OVER_A_RANGE
    if not (lo * (1 - 1e-9) <= v <= hi * (1 + 1e-9)):
        raise InputError(f"H/a = {eps!r} is outside the validated range [{lo}, {hi}]: above, the remainders "
                         f"are no longer small; below, the direct numerics become too expensive")
    return v


def check_nus(values: Any, name: str = "nus") -> tuple[float, ...]:
    """A non-empty sequence (or one value) of Poisson ratios, each by :func:`check_nu`, duplicates dropped.

    Parameters
    ----------
    values : real number or sequence of real numbers
        The Poisson ratios.
    name : str
        The argument's name in the error messages.

    Returns
    -------
    tuple of float
    """
    return check_list(values, check_nu, name)


def check_ratios(values: Any, name: str = "ratios") -> tuple[float, ...]:
    """As :func:`check_nus`, for thickness ratios ``H/a`` (each by :func:`check_ratio`)."""
    return check_list(values, check_ratio, name)


def _check_shape(shape: Any) -> str:
    if shape not in SHAPES:
        raise InputError(f"unknown shape {shape!r}: choose from {', '.join(SHAPES)}")
    return shape


def check_shapes(shapes: Any) -> tuple[str, ...]:
    """Shapes of the study: a name of :data:`SHAPES` or a non-empty sequence of them, duplicates dropped.

    Parameters
    ----------
    shapes : str or sequence of str
        ``"sphere"`` and/or ``"elliptic"``.

    Returns
    -------
    tuple of str

    Examples
    --------
    >>> check_shapes(["elliptic", "sphere", "elliptic"])
    ('elliptic', 'sphere')
    """
    return check_list(shapes, _check_shape, "shapes")


def bonded_layer(nu: float):
    """The bonded layer of the study at ``nu`` (an exact rational close to the float)."""
    from ..layers.kernels import BondedLayer

    return BondedLayer(Fraction(float(nu)).limit_denominator(10**6))  # exact, no text round trip


def _second_order(layer: Any, punch: Any, H: float) -> Any:
    """The second-order force (SO.9) and area (SO.10) at the study's indentation (their numbers, ~1 ms;
    the layer's constants h^*, m_1, r_3 once per nu, ~0.2 s).
    """
    from ..asymptotics.second_order import second_order_law

    return second_order_law(layer, punch).evaluate(DELTA0, H)


# ---------------------------------------------------------------------------------------------
# the sphere
# ---------------------------------------------------------------------------------------------
def _same_ratio(got: float, want: float) -> None:
    if abs(got / want - 1.0) > 1e-9:  # pragma: no cover - the geometry above fixes a
        raise RuntimeError(f"internal: the solution has H/a = {got}, the case asked for {want}")


def _sphere_radii(c: float, ra: float, H: float) -> np.ndarray:
    """Radii of the sphere's pressure comparison: the whole contact, and densely between the two edges.

    The largest error sits between the numerical edge ``c`` and the composite pressure's edge ``ra``
    (O(H^2/a) apart).
    """
    lo, hi = min(c, ra), max(c, ra)
    near = H * np.geomspace(1e-7, 4.0, 300)
    r = np.unique(np.concatenate([np.linspace(0.0, hi + 2.0 * H, 1201), np.linspace(lo, hi, 201),
                                  c - near, c + near, ra - near, ra + near]))
    return r[r >= 0.0]


def _circles(nu: float, eps: float, c: float, a0: float, H: float, h_ex: float, h_alex: float) -> ContourData:
    th = np.linspace(0.0, 2.0 * math.pi, 361)
    circ = np.column_stack([np.cos(th), np.sin(th)])
    return ContourData("sphere", nu, eps, (readonly(c * circ),), readonly((a0 - h_ex * H) * circ),
                       readonly(a0 * circ), readonly((a0 - h_alex * H) * circ))


def sphere_case(nu: float, eps: float) -> tuple[ValidationRow, list[PressureProfile], list[ContourData]]:
    """The sphere at ``nu`` and ``H/a = eps`` against the axisymmetric numerics: the row and the plot data."""
    from ..asymptotics.solution import compressible_solution as solve
    from ..numerics import contact_for_radius, radial_profile, solve_axisymmetric
    from ..punch import Punch

    layer, punch = bonded_layer(nu), Punch.paraboloid(R=SPHERE_R)
    a0 = math.sqrt(2.0 * SPHERE_R * DELTA0)
    H = eps * a0
    t0 = time.perf_counter()
    sol = solve(layer, punch, delta0=DELTA0, H=H, tol=math.inf)  # the study measures the error itself
    _same_ratio(sol.H_over_a, eps)
    t1 = time.perf_counter()
    res = solve_axisymmetric(layer, punch, DELTA0, H)
    c = res.contact_radius
    # a coarser run at the same radius: its pressure differs from the fine one by more than the fine error
    coarse = contact_for_radius(layer, radial_profile(punch), c, H, n=max(4, round(0.7 * res.modes)),
                                error_estimate=False)
    t2 = time.perf_counter()
    h_ex = sol.edge_shift
    r = _sphere_radii(c, a0 - h_ex * H, H)  # a0 - h_ex H: the edge of the composite pressure
    pn = res.pressure_at(r)
    t3 = time.perf_counter()
    pc = np.asarray(sol.pressure(r, np.zeros_like(r)), dtype=float)
    second = _second_order(layer, punch, H)
    t4 = time.perf_counter()
    pmax = float(pn.max())
    row = ValidationRow(
        shape="sphere", nu=nu, H_over_a=eps, H=H, delta0=DELTA0, half_width=sol.half_width,
        force_numeric=res.force, force_asymptotic=sol.force, force_leading=sol.force_leading,
        force_numeric_error=float(res.force_error),
        area_numeric=res.contact_area, area_asymptotic=sol.contact_area, area_leading=sol.contact_area_leading,
        area_alexandrov=sol.contact_area_alexandrov, area_numeric_error=2.0 * float(res.radius_error) / c,
        semi_axes_numeric=(c, c), semi_axes_asymptotic=(a0 - h_ex * H,) * 2, semi_axes_leading=(a0, a0),
        edge_shift_numeric=(a0 - c) / H, edge_shift_numeric_error=float(res.radius_error) / H,
        edge_shift_exact=h_ex, edge_shift_alexandrov=sol.edge_shift_alexandrov,
        pressure_error=float(np.abs(pc - pn).max() / pmax), pressure_band=0.0,
        pressure_numeric_error=float(np.abs(coarse.pressure_at(r) - pn).max() / pmax),
        solver=f"axisymmetric spectral, {res.modes} modes",
        seconds_numeric=(t2 - t1) + (t3 - t2), seconds_asymptotic=(t1 - t0) + (t4 - t3),
        force_second=second.force, area_second=second.area)
    prof = PressureProfile("sphere", nu, row.H_over_a, "r", 0.0, readonly(r), readonly(pn), readonly(pc), a0, c)
    return row, [prof], [_circles(nu, row.H_over_a, c, a0, H, h_ex, sol.edge_shift_alexandrov)]


# ---------------------------------------------------------------------------------------------
# the elliptic paraboloid
# ---------------------------------------------------------------------------------------------
def _ellipse_geometry() -> tuple[float, float, float, float, float]:
    """Semi-axes a1, a2 of Gamma_0, |omega_0|, |Gamma_0| and a = 2|omega_0|/|Gamma_0|."""
    from scipy.special import ellipe

    R1, R2 = _ELLIPSE_R
    a1, a2 = math.sqrt(2 * R1 * DELTA0), math.sqrt(2 * R2 * DELTA0)
    area = math.pi * a1 * a2
    perim = 4.0 * a1 * float(ellipe(1.0 - (a2 / a1) ** 2))
    return a1, a2, area, perim, 2.0 * area / perim


def elliptic_grid(H_over_a: float, cells_per_H: float = 8.0) -> tuple[int, int, float]:
    """``(n, n_coarse, half_width)`` of the 2D grids of the elliptic case at ``H/a``.

    The square ``|x_i| < 1.01 a_1 + 2H`` (the contact stays inside for -0.6 < h^* and more than
    two cells from the boundary); ``n`` gives ``cells_per_H`` cells per H, the coarse grid H/5
    cells; both rounded up to multiples of 16.

    Parameters
    ----------
    H_over_a : float
        The thickness ratio, in [0.0125, 0.2].
    cells_per_H : float
        Cells of the fine grid per layer thickness, at least 6.

    Returns
    -------
    tuple of (int, int, float)
        The cells per side of the fine and of the coarse grid, and the half-width of the square.

    Examples
    --------
    >>> n, n_coarse, W = elliptic_grid(0.1)
    >>> n, n_coarse, round(W, 4)
    (288, 176, 2.2794)
    """
    eps = check_ratio(H_over_a)
    if not (isinstance(cells_per_H, numbers.Real) and cells_per_H >= 6.0):
        raise InputError(f"cells_per_H must be a number >= 6 (the coarse grid of the error estimate has "
                         f"{_COARSE_CELLS_PER_H:g}, the 2D solver's limit), got {cells_per_H!r}")
    a1, _, _, _, a = _ellipse_geometry()
    H = eps * a
    W = 1.01 * a1 + 2.0 * H

    def cells(k: float) -> int:
        return 16 * math.ceil(2.0 * W * k / H / 16.0 - 1e-9)

    return cells(float(cells_per_H)), cells(_COARSE_CELLS_PER_H), W


def _axis_crossing(polys: Sequence[np.ndarray], axis: int) -> float:
    """Mean |coordinate| where the contour polygons cross the other axis (the semi-axis along ``axis``)."""
    other = 1 - axis
    hits = []
    for pts in polys:
        a, b = pts[:-1], pts[1:]
        s = (a[:, other] <= 0) != (b[:, other] <= 0)
        for p, q in zip(a[s], b[s]):
            t = p[other] / (p[other] - q[other])
            hits.append(abs(p[axis] + t * (q[axis] - p[axis])))
    if len(hits) < 2:
        raise RuntimeError(f"the numerical contact contour does not cross the x{other + 1} = 0 axis twice")
    hits.sort()
    return float(np.mean(hits[-2:]))


def _grid_pressure_errors(fine: Any, coarse: Any, pc: np.ndarray) -> tuple[float, float]:
    """``max |p_c - p_num| / p_max`` on the fine cells well inside the contact, and the numerical error there.

    The error estimate compares the coarse cells (well inside) with the fine pressure interpolated there.
    """
    from scipy import ndimage
    from scipy.interpolate import RegularGridInterpolator

    pn = np.asarray(fine.pressure)
    pmax = float(pn.max())
    inner = ndimage.binary_erosion(pn > 0, iterations=_PRESSURE_BAND_CELLS)
    perr = float(np.abs(pc - pn)[inner].max() / pmax)
    interp = RegularGridInterpolator((fine.x1, fine.x2), pn)
    inner_c = ndimage.binary_erosion(np.asarray(coarse.pressure) > 0, iterations=_PRESSURE_BAND_CELLS)
    Y1, Y2 = np.meshgrid(coarse.x1, coarse.x2, indexing="ij")
    pnum = float(np.abs(np.asarray(coarse.pressure)[inner_c]
                        - interp(np.column_stack([Y1[inner_c], Y2[inner_c]]))).max() / pmax)
    return perr, pnum


def _elliptic_plot_data(row: ValidationRow, fine: Any, pc: np.ndarray, semi_axes: tuple[float, float],
                        leading: tuple[float, float]) -> tuple[list[PressureProfile], list[ContourData]]:
    """Pressure on the grid lines next to the axes, and the contours (numerical, moved in by h^* H, Gamma_0)."""
    nu, eps, H = row.nu, row.H_over_a, row.H
    a1, a2 = leading
    pn = np.asarray(fine.pressure)
    j = i = fine.n // 2  # x2 = Delta/2 and x1 = Delta/2: the lines next to the axes
    profs = [
        PressureProfile("elliptic", nu, eps, "x1", float(fine.x2[j]), readonly(fine.x1), readonly(pn[:, j]),
                        readonly(pc[:, j]), a1, semi_axes[0]),
        PressureProfile("elliptic", nu, eps, "x2", float(fine.x1[i]), readonly(fine.x2), readonly(pn[i, :]),
                        readonly(pc[i, :]), a2, semi_axes[1]),
    ]
    th = np.linspace(0.0, 2.0 * math.pi, 721)
    g0 = np.column_stack([a1 * np.cos(th), a2 * np.sin(th)])
    nrm = np.column_stack([g0[:, 0] / a1**2, g0[:, 1] / a2**2])
    nrm /= np.hypot(nrm[:, 0], nrm[:, 1])[:, None]
    cont = ContourData("elliptic", nu, eps, tuple(readonly(p) for p in fine.contour),
                       readonly(g0 - row.edge_shift_exact * H * nrm), readonly(g0),
                       readonly(g0 - row.edge_shift_alexandrov * H * nrm))
    return profs, [cont]


def elliptic_case(nu: float, eps: float, cells_per_H: float, workers: int | None
                  ) -> tuple[ValidationRow, list[PressureProfile], list[ContourData]]:
    """The elliptic paraboloid at ``nu`` and ``H/a = eps`` against the 2D numerics on two grids."""
    from ..asymptotics.solution import compressible_solution as solve
    from ..numerics import solve_2d
    from ..punch import Punch

    layer, punch = bonded_layer(nu), Punch.elliptic_paraboloid(R1=_ELLIPSE_R[0], R2=_ELLIPSE_R[1])
    a1, a2, _, _, a = _ellipse_geometry()
    H = eps * a
    n, nc, W = elliptic_grid(eps, cells_per_H)
    t0 = time.perf_counter()
    sol = solve(layer, punch, delta0=DELTA0, H=H, tol=math.inf)  # the study measures the error itself
    _same_ratio(sol.H_over_a, eps)
    t1 = time.perf_counter()
    fine = solve_2d(layer, punch, delta0=DELTA0, H=H, n=n, extent=W, workers=workers)
    coarse = solve_2d(layer, punch, delta0=DELTA0, H=H, n=nc, extent=W, workers=workers)
    t2 = time.perf_counter()
    X1, X2 = np.meshgrid(fine.x1, fine.x2, indexing="ij")
    pc = np.asarray(sol.pressure(X1, X2), dtype=float)
    second = _second_order(layer, punch, H)
    t3 = time.perf_counter()
    perr, pnum = _grid_pressure_errors(fine, coarse, pc)
    s_f = (_axis_crossing(fine.contour, 0), _axis_crossing(fine.contour, 1))
    s_c = (_axis_crossing(coarse.contour, 0), _axis_crossing(coarse.contour, 1))
    h_ex = sol.edge_shift
    row = ValidationRow(
        shape="elliptic", nu=nu, H_over_a=eps, H=H, delta0=DELTA0, half_width=sol.half_width,
        force_numeric=fine.force, force_asymptotic=sol.force, force_leading=sol.force_leading,
        force_numeric_error=abs(fine.force - coarse.force) / fine.force,
        area_numeric=fine.contact_area, area_asymptotic=sol.contact_area, area_leading=sol.contact_area_leading,
        area_alexandrov=sol.contact_area_alexandrov,
        area_numeric_error=abs(fine.contact_area - coarse.contact_area) / fine.contact_area,
        semi_axes_numeric=s_f, semi_axes_asymptotic=(a1 - h_ex * H, a2 - h_ex * H), semi_axes_leading=(a1, a2),
        edge_shift_numeric=0.5 * ((a1 - s_f[0]) + (a2 - s_f[1])) / H,
        edge_shift_numeric_error=max(abs(s_f[0] - s_c[0]), abs(s_f[1] - s_c[1])) / H,
        edge_shift_exact=h_ex, edge_shift_alexandrov=sol.edge_shift_alexandrov,
        pressure_error=perr, pressure_band=_PRESSURE_BAND_CELLS * fine.spacing, pressure_numeric_error=pnum,
        solver=f"fft2d n={n} (Delta=H/{H / fine.spacing:.1f}; error est. n={nc})",
        seconds_numeric=t2 - t1, seconds_asymptotic=(t1 - t0) + (t3 - t2),
        force_second=second.force, area_second=second.area)
    profs, conts = _elliptic_plot_data(row, fine, pc, s_f, (a1, a2))
    return row, profs, conts
