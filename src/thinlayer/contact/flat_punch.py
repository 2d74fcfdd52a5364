r"""Flat-ended cylindrical punch: the stiffness ``kappa(a/H)`` by the model that holds (F.1).

``P = 4 mu a w0 kappa(a/H)/(1 - nu)`` (F.1).  Three models, each with its own error estimate:

``"exact"``
    the Fredholm equation of the second kind (F.6)-(F.7) (:func:`thinlayer.numerics.flat_punch.flat_punch_kappa`),
    any ``0 < a/H <= 200``, about 1e-10 (estimate: the change against 0.7 times the nodes); a few ms up to
    ``a/H = 20``, 0.12 s at 200.
``"thin"``
    the thin-layer asymptotics (F.10)-(F.15) in their effective-radius form
    (:func:`thinlayer.asymptotics.flat_punch.thin_flat_punch`), estimate (F.16); microseconds per value.
``"thick"``
    the thick-layer series (F.18) through ``(a/H)^12`` (:func:`thinlayer.asymptotics.flat_punch.thick_flat_punch`),
    estimate (F.19); ``a/H < 0.8`` only.

``"auto"`` takes the cheapest whose estimate is within ``max_error`` (thick, then thin), else the exact solver.
"""
from __future__ import annotations

import functools
import math
import sys
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._checks import InputError, InputTypeError, array_size, check_bounded, check_choice, parse_nu, positive
from .._lazy import lazy_function, lazy_module
from ..display import RichDisplay
from ..errors import boundary
from ..layers.kernels import LayerKernel

# the model and solver modules load sympy and scipy: imported on first use, so that importing the model registry
# (thinlayer.contact.models) stays cheap for a numeric solve() of a smooth punch (issue 28 item 6)
thick_flat_punch = lazy_function("thinlayer.asymptotics.flat_punch", "thick_flat_punch")
thin_flat_punch = lazy_function("thinlayer.asymptotics.flat_punch", "thin_flat_punch")
check_numeric_layer = lazy_function("thinlayer.numerics.flat_punch", "check_numeric_layer")
flat_punch_kappa = lazy_function("thinlayer.numerics.flat_punch", "flat_punch_kappa")
solve_flat_punch = lazy_function("thinlayer.numerics.flat_punch", "solve_flat_punch")
numerics_flat_punch = lazy_module("thinlayer.numerics.flat_punch")

__all__ = ["FLAT_PUNCH_MODELS", "FlatPunchResult", "flat_punch_contact", "flat_punch_fields", "flat_punch_stiffness",
           "stiffness_table"]

#: the values of ``model``
FLAT_PUNCH_MODELS = ("exact", "thin", "thick", "auto")
#: most values of a/H in one call of the exact model (each is one solve: 0.12 s at a/H = 200)
MAX_EXACT_POINTS = 2000
#: most values of a/H in one call of the asymptotic models (each is a formula)
MAX_POINTS = 1_000_000


def _check_max_error(max_error: Any) -> float:
    v = positive(max_error, "max_error")
    if v > 1.0:
        raise InputError(f"max_error is a relative error in (0, 1], got {max_error!r}")
    return v


def _as_ratios(a_over_H: Any, limit: int) -> tuple[np.ndarray, bool]:
    """``a/H`` as a float array (and whether it was a scalar): finite, positive, at most ``limit`` values."""
    if isinstance(a_over_H, bool):
        raise InputTypeError("a_over_H must be a positive number or an array of them, got a bool")
    check_bounded(array_size(a_over_H), "the number of a/H values", limit, "each value is one solve of the exact "
                  "model (0.12 s at a/H = 200); the thin model takes 1.1 s for 1e6 values (21 s for 1e7)")
    if isinstance(a_over_H, (str, bytes)) or np.asarray(a_over_H).dtype.kind in "USOb":
        raise InputTypeError(f"a_over_H must be a positive number or an array of numbers, got {a_over_H!r}")
    try:
        x = np.asarray(a_over_H, dtype=float)
    except (TypeError, ValueError):
        raise InputTypeError(f"a_over_H must be a positive number or an array of them, got {a_over_H!r}") from None
    check_bounded(x.size, "the number of a/H values", limit, "each value is one solve of the exact model "
                                                             "(0.12 s at a/H = 200); the asymptotic models take any "
                                                             "array")
    if x.size == 0:
        raise InputError("a_over_H is empty: give at least one value")
    bad = ~np.isfinite(x) | (x <= 0)
    if np.any(bad):
        raise InputError(f"a_over_H must be finite and positive, got {float(x[bad].flat[0])!r}")
    return x, x.ndim == 0


def _refuse(what: str, x: np.ndarray, est: np.ndarray, max_error: float, hint: str) -> None:
    bad = est > max_error
    if np.any(bad):
        i = int(np.argmax(np.where(bad, est, -np.inf)))
        raise InputError(f"the {what} at a/H = {x.flat[i]:.6g} has an estimated relative error "
                         f"{est.flat[i]:.1e} > max_error = {max_error:g}: {hint}")


def _thin(layer: LayerKernel, x: np.ndarray, max_error: float) -> tuple[np.ndarray, np.ndarray]:
    model = thin_flat_punch(layer)
    est = model.error_estimate(x)
    _refuse("thin-layer model (F.12)-(F.16)", x, est, max_error,
            "the layer is not thin enough; use model='exact' (or 'auto')")
    return model(x), est


def _thick(layer: LayerKernel, x: np.ndarray, max_error: float) -> tuple[np.ndarray, np.ndarray]:
    model = thick_flat_punch(layer)
    est = model.error_estimate(x)
    _refuse("thick-layer series (F.18)", x, est, max_error,
            "it converges only for a/H < 0.8; use model='exact' (or 'auto')")
    return model(x), est


def _exact(layer: LayerKernel, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    if np.any(x > numerics_flat_punch.MAX_A_OVER_H):
        i = int(np.argmax(x))
        raise InputError(f"the exact model is limited to a/H <= {numerics_flat_punch.MAX_A_OVER_H:g} (0.12 s at 200), "
                         f"got a/H = "
                         f"{x.flat[i]:.6g}: use model='thin' (error below 5e-5 there) or 'auto'")
    res = [flat_punch_kappa(layer, float(v)) for v in x.ravel()]
    return (np.array([r.kappa for r in res]).reshape(x.shape),
            np.array([r.error for r in res]).reshape(x.shape))


def _models(layer: LayerKernel, x: np.ndarray, model: str,
            max_error: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(kappa, estimate, model index)`` for every a/H (index into FLAT_PUNCH_MODELS)."""
    if model == "exact":
        k, e = _exact(layer, x)
        return k, e, np.zeros(x.shape, dtype=int)
    if model == "thin":
        k, e = _thin(layer, x, max_error)
        return k, e, np.ones(x.shape, dtype=int)
    if model == "thick":
        k, e = _thick(layer, x, max_error)
        return k, e, np.full(x.shape, 2)
    # auto: thick, then thin, then exact, per value
    kappa = np.full(x.shape, np.nan)
    est = np.full(x.shape, np.inf)
    which = np.zeros(x.shape, dtype=int)
    if layer.has_thickness:
        tk = thick_flat_punch(layer)
        e = tk.error_estimate(x)  # inf beyond a/H = 0.8
        use = e <= max_error
        kappa[use], est[use], which[use] = tk(x[use]), e[use], 2
        th = thin_flat_punch(layer)
        e = th.error_estimate(x)
        use = ~np.isfinite(kappa) & (e <= max_error)
        kappa[use], est[use], which[use] = th(x[use]), e[use], 1
    rest = ~np.isfinite(kappa)
    if np.any(rest):
        check_bounded(int(np.count_nonzero(rest)), "the number of a/H values for the exact model",
                      MAX_EXACT_POINTS, "each is one solve (0.12 s at a/H = 200)")
        k, e = _exact(layer, x[rest])
        kappa[rest], est[rest], which[rest] = k, e, 0
    return kappa, est, which


def stiffness_table(layer: LayerKernel, a_over_H: Any, model: str = "auto", *,
                    max_error: float = 1e-2) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """``(kappa, estimate, model used)`` for every value of ``a_over_H`` (arrays; see :func:`flat_punch_stiffness`)."""
    layer = check_numeric_layer(layer)
    model = check_choice(model, FLAT_PUNCH_MODELS, "model")
    tol = _check_max_error(max_error)
    x, _ = _as_ratios(a_over_H, MAX_EXACT_POINTS if model in ("exact", "auto") else MAX_POINTS)
    x = np.atleast_1d(x)
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):  # refused below
        kappa, est, which = _models(layer, x, model, tol)
    _check_kappa(x, kappa)
    return kappa, est, [FLAT_PUNCH_MODELS[int(w)] for w in which.ravel()]


@boundary
def flat_punch_stiffness(layer: LayerKernel, a_over_H: Any, model: str = "exact", *,
                         max_error: float = 1e-2) -> Any:
    """The stiffness ``kappa(a/H)`` of a flat-ended cylindrical punch, ``P = 4 mu a w0 kappa/(1 - nu)`` (F.1).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` (numeric nu), ``IncompressibleLayer()``, ``FrictionlessLayer()`` or ``HalfSpace()``
        (kappa = 1; exact model only).
    a_over_H : float or array_like
        Punch radius over layer thickness (> 0); an array gives an array (the exact model solves each value).
    model : str
        ``"exact"`` (default), ``"thin"``, ``"thick"`` or ``"auto"`` (the module docstring).
    max_error : float
        Largest accepted estimated relative error of the asymptotic models (``"thin"``, ``"thick"`` refuse
        beyond it; ``"auto"`` falls back to the exact solver).

    Returns
    -------
    float or numpy.ndarray
        ``kappa`` (1 for the half-space, ``-> 1`` as ``a/H -> 0``).

    Raises
    ------
    ValueError
        One line: an estimated error above ``max_error`` (naming a/H and the estimate), ``a/H > 200`` for the
        exact model, a layer the model does not cover.

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> layer = BondedLayer(0.3)
    >>> round(flat_punch_stiffness(layer, 1.0), 6)
    2.483525
    >>> round(float(flat_punch_stiffness(layer, 30.0, "thin")), 4)
    58.1975
    """
    model = check_choice(model, FLAT_PUNCH_MODELS, "model")
    x, scalar = _as_ratios(a_over_H, MAX_EXACT_POINTS if model == "exact" else MAX_POINTS)  # sizes first
    layer = check_numeric_layer(layer)
    tol = _check_max_error(max_error)
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):  # refused below
        kappa, _, _ = _models(layer, x, model, tol)
    _check_kappa(x, kappa)
    return float(kappa) if scalar else kappa


def _check_kappa(x: np.ndarray, kappa: np.ndarray) -> None:
    """Every kappa a positive double: at a/H = 1e300 the thin-layer law's (a/H)^3 is beyond the double range."""
    bad = ~(np.isfinite(kappa) & (kappa > 0))
    if np.any(bad):
        i = int(np.argmax(bad))
        raise InputError(f"kappa at a/H = {np.ravel(x)[i]:.3g} is {np.ravel(kappa)[i]!r}, beyond the double range: "
                         "express the lengths in other units")


@dataclass(frozen=True)
class FlatPunchResult(RichDisplay):
    """Force and depth of a flat-ended cylindrical punch on a layer, by one model (F.1).

    Attributes
    ----------
    layer : LayerKernel
        The layer.
    model : str
        ``"exact"``, ``"thin"`` or ``"thick"`` (the one used).
    radius, H, mu, nu : float
        float
        Punch radius ``a``, thickness, shear modulus, Poisson ratio.
    w0, force : float
        float
        Indentation depth and total force, ``P = 4 mu a w0 kappa/(1 - nu)``.
    kappa, error : float
        float
        The stiffness factor and its estimated relative error.
    """

    layer: LayerKernel
    model: str
    radius: float
    H: float
    mu: float
    nu: float
    w0: float
    force: float
    kappa: float
    error: float

    equation = "F.1"

    @property
    def stiffness(self) -> float:
        """``dP/dw0 = 4 mu a kappa/(1 - nu)``."""
        return 4.0 * self.mu * self.radius * self.kappa / (1.0 - self.nu)

    def latex(self) -> str:
        return (rf"P = \frac{{4\mu a w_0 \kappa}}{{1 - \nu}} = {self.force:.10g},\quad w_0 = {self.w0:.10g},\quad "
                rf"\kappa({self.radius / self.H:.6g}) = {self.kappa:.10g}\ (\text{{{self.model}}}) \tag{{F.1}}")

    def text_lines(self) -> list[str]:
        return [f"FlatPunchResult: flat-ended cylinder on {self.layer}, {self.model} model   (F.1)",
                f"  a = {self.radius:.6g}, H = {self.H:.6g}, mu = {self.mu:.6g}, nu = {self.nu:.6g}",
                f"  w0 = {self.w0:.10g}, P = {self.force:.10g}",
                f"  kappa(a/H = {self.radius / self.H:.6g}) = {self.kappa:.12g}  (+- {self.error:.1e} relative)"]


def flat_punch_contact(layer: LayerKernel, radius: float, H: float, *, w0: float | None = None,
                       force: float | None = None, mu: float = 1.0, nu: float | None = None,
                       model: str = "auto", max_error: float = 1e-2) -> FlatPunchResult:
    """Force for a given depth, or depth for a given force, of a flat-ended cylinder on a layer (F.1).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)``, ``IncompressibleLayer()``, ``FrictionlessLayer(nu)`` or ``HalfSpace()``.
    radius, H : float
        float
        Punch radius ``a`` and layer thickness (both > 0).
    w0, force : float, optional
        float
        Indentation depth or total force (> 0): exactly one of them.
    mu : float
        Shear modulus.
    nu : float, optional
        Poisson ratio, for layers that do not fix one (``FrictionlessLayer()``, ``HalfSpace()``).
    model, max_error
        As in :func:`flat_punch_stiffness` (default ``"auto"``).

    Returns
    -------
    FlatPunchResult

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> res = flat_punch_contact(BondedLayer(0.3), radius=2.0, H=1.0, w0=0.01)
    >>> res.model, round(res.force, 8)
    ('exact', 0.49751363)
    >>> back = flat_punch_contact(BondedLayer(0.3), radius=2.0, H=1.0, force=res.force)
    >>> round(back.w0, 12)
    0.01
    """
    layer = check_numeric_layer(layer)
    a = positive(radius, "radius")
    Hv = positive(H, "H")
    mu_v = positive(mu, "mu")
    nu_v = parse_nu(layer.poisson_ratio(nu), floats="float", upper_closed=True, symbols=False)
    nu_v = float(nu_v)
    if (w0 is None) == (force is None):
        raise InputError("give exactly one of w0 (indentation depth) and force (total force)")
    check_choice(model, FLAT_PUNCH_MODELS, "model")
    tol = _check_max_error(max_error)
    x = np.asarray(a / Hv)
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):  # refused below
        kappa, est, which = _models(layer, x, model, tol)
    _check_kappa(x, kappa)
    k = float(kappa)
    factor = 4.0 * mu_v * a / (1.0 - nu_v)  # P = factor w0 kappa (F.1)
    if w0 is not None:
        w = positive(w0, "w0")
        P = factor * w * k
    else:
        P = positive(force, "force")
        w = P / (factor * k)
    return FlatPunchResult(layer, FLAT_PUNCH_MODELS[int(which)], a, Hv, mu_v, nu_v, w, P, k, float(est))


# =============================================================================================
# the flat punch at the front door: thinlayer.solve(layer, Punch.flat(a), ...)
# =============================================================================================
#: the name of each flat-punch model in an Indentation, and its equations (force, contact size)
SOLVE_NAMES = {"exact": "direct", "thin": "thin-layer", "thick": "thick-layer"}
EQUATIONS = {"direct": ("F.1, F.6-F.7", "F.1"), "thin-layer": ("F.1, F.10-F.16", "F.1"),
             "thick-layer": ("F.1, F.18-F.19", "F.1")}


class _FlatPressure:
    """The contact pressure (F.8) from the exact solution, computed on first use (the laws give kappa only)."""

    def __init__(self, layer, a: float, H: float, w0: float, mu: float, nu: float, n: int | None = None):
        self.args = (layer, a, H, w0, mu, nu, n)
        self.contact = None

    def __call__(self, x1: np.ndarray, x2: np.ndarray) -> np.ndarray:
        layer, a, H, w0, mu, nu, n = self.args
        if self.contact is None:
            self.contact = solve_flat_punch(layer, a, H, w0=w0, mu=mu, nu=nu if layer.numeric_nu is None else None,
                                            n=n)
        return self.contact.pressure_at(np.hypot(x1, x2))


def flat_punch_fields(layer: LayerKernel, radius: float, H: float, w0: float | None, force: float | None,
                      mu: float, nu: float, choice: str, tol: float, n: int | None = None) -> dict[str, Any]:
    """The flat punch's answer as the fields of :class:`~thinlayer.contact.solve.Indentation` (F.1).

    ``choice`` is ``solve()``'s model: ``"auto"`` (the thick series, then the thin-layer law, within ``tol``,
    else the exact solution), ``"asymptotic"`` (the same, refusing instead of the exact solution),
    ``"thick"`` or ``"thin"`` (that law only, refusing beyond ``tol``: the registry's flat-punch entries), or
    ``"direct"``/``"any-thickness"`` (the exact Fredholm solution (F.6)-(F.7), any ``a/H <= 200``).  The contact is
    the disc (its area and radius are exact); the pressure comes from the exact solution on first use.
    """
    nv = float(nu)
    if layer.numeric_nu is None and not layer.kernel_depends_on_nu:  # a frictionless base: nu from the caller
        layer = layer.with_nu(nv)
    if choice in ("compressible", "two-term", "incompressible"):
        raise InputError(f"model={choice!r} is a model of smooth punches; for the flat punch the thin-layer law "
                         "(F.10)-(F.16) covers every nu: use model='auto', 'asymptotic', 'any-thickness' or 'direct'")
    x = np.asarray(math.exp(math.log(radius) - math.log(H)))  # a/H of 1e-300/0.05 without underflow
    if not 0 < float(x) < math.inf:
        raise InputError(f"a/H = {radius:.3g}/{H:.3g} is beyond the double range: express the lengths in other units")
    lo, hi = math.log(sys.float_info.min), math.log(sys.float_info.max)
    log_area = math.log(math.pi) + 2 * math.log(radius)
    if not lo <= log_area <= hi:  # before any model: the disc's area alone leaves the double range
        exp10 = log_area / math.log(10)
        shown = f"{10 ** (exp10 - math.floor(exp10)):.2g}e{math.floor(exp10):+d}"  # 3.1e-600: not a double
        raise InputError(f"the flat punch's contact area pi a^2 is {shown}, "
                         f"{'below' if log_area < 0 else 'beyond'} the double range (a = {radius:.3g}): express the "
                         "lengths in other units")
    with np.errstate(over="ignore", under="ignore", divide="ignore"):  # an estimate of inf just declines a model
        if choice == "asymptotic":
            try:
                kappa, est, which = _models(layer, x, "thick", tol)
            except ValueError:
                kappa, est, which = _models(layer, x, "thin", tol)  # refuses in one line beyond tol
        elif choice in ("auto", "thick", "thin"):
            kappa, est, which = _models(layer, x, choice, tol)
        elif n is not None:
            st = flat_punch_kappa(layer, float(x), n)
            kappa, est, which = np.asarray(st.kappa), np.asarray(st.error), np.asarray(0)
        else:
            kappa, est, which = _models(layer, x, "exact", tol)
    _check_kappa(x, kappa)
    model = SOLVE_NAMES[FLAT_PUNCH_MODELS[int(which)]]
    k, e = float(kappa), max(float(est), 1e-16)
    # P = 4 mu a w0 kappa/(1 - nu) (F.1), in logarithms: mu a can underflow where P does not
    log_factor = math.log(4.0) + math.log(mu) + math.log(radius) - math.log1p(-nv) + math.log(k)
    log_w = math.log(w0) if w0 is not None else math.log(force) - log_factor
    log_P = log_factor + log_w
    for what, lv in (("force", log_P), ("depth", log_w)):
        if not lo <= lv <= hi:
            raise InputError(f"the flat punch's {what} is 1e{lv / math.log(10):.1f}, {'below' if lv < 0 else 'beyond'}"
                             f" the double range (a = {radius:.3g}, a/H = {float(x):.3g}): express the lengths, mu "
                             "and the force in other units")
    w, P = (w0, math.exp(log_P)) if w0 is not None else (math.exp(log_w), force)
    why = {"direct": f"exact kappa(a/H = {float(x):.4g}) = {k:.10g} from the Fredholm equation (F.6)-(F.7)",
           "thin-layer": f"thin-layer law (F.10)-(F.16) at a/H = {float(x):.4g}, estimate (F.16) {e:.2g}",
           "thick-layer": f"thick-layer series (F.18) at a/H = {float(x):.4g}, estimate (F.19) {e:.2g}"}[model]
    area = math.exp(log_area)
    return dict(layer=layer, punch=None, delta0=w, force=P, H=H, mu=mu, nu=nv, contact_area=area,
                contact_radius=radius, semi_axes=None, model=model, reason=why,
                error_estimate={"force": e, "contact_area": 0.0, "contact_radius": 0.0}, tol=tol,
                detail=FlatPunchResult(layer, FLAT_PUNCH_MODELS[int(which)], radius, H, mu, nv, w, P, k, e),
                _pressure=_FlatPressure(layer, radius, H, w, mu, nv, n), _extent=1.2 * radius, extras={"kappa": k})


# =============================================================================================
# standalone code: kappa(a/H) of one layer at any thickness, as a numpy module or a C file
# =============================================================================================
#: points of the generated table in log(a/H), from SOURCE_RANGE[0] to SOURCE_RANGE[1]
SOURCE_POINTS = 161
SOURCE_RANGE = (1e-3, 200.0)


@functools.lru_cache(maxsize=16)
def _log_kappa_table(layer: LayerKernel) -> tuple[np.ndarray, np.ndarray]:
    """``(log(a/H), log kappa)`` on the :data:`SOURCE_POINTS` nodes of :func:`flat_punch_source`: the exact solution
    (F.6)-(F.7) at each node, computed once per layer and process (both languages are generated from it), read-only.
    """
    xs = np.linspace(np.log(SOURCE_RANGE[0]), np.log(SOURCE_RANGE[1]), SOURCE_POINTS)
    F = np.log([flat_punch_kappa(layer, float(np.exp(x)), error_estimate=False).kappa for x in xs])
    for a in (xs, F):
        a.setflags(write=False)
    return xs, F


def flat_punch_source(layer: LayerKernel, language: str = "python") -> str:
    r"""Source of a standalone ``kappa(a_over_H)`` of one layer for every thickness: numpy module or C99.

    ``log kappa`` of the exact solution (F.6)-(F.7) is tabulated on :data:`SOURCE_POINTS` points uniform in
    ``log(a/H)`` over :data:`SOURCE_RANGE` and interpolated by cubic Hermite polynomials (slopes from the cubic
    spline through the table; agreement with the exact solution measured in the tests: below 2e-7); below the
    table the thick series (F.18) through ``(a/H)^3``; beyond ``a/H = 200`` NaN (there the thin-layer law
    holds: ``thinlayer codegen flat-punch --law thin``).  About 2 s to build (161 exact solutions).

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> "double thinlayer_flat_punch_kappa(double a_over_H)" in flat_punch_source(BondedLayer(0.3), "c")
    True
    """
    from scipy.interpolate import CubicSpline

    layer = check_numeric_layer(layer)
    check_choice(language, ("python", "c"), "language")
    xs, F = _log_kappa_table(layer)
    dF = CubicSpline(xs, F)(xs, 1)
    c = thick_flat_punch(layer, 3).coefficients
    h = float(xs[1] - xs[0])
    doc = (f"thinlayer: stiffness kappa(a/H) of a flat-ended cylinder on {layer} (generated; do not edit).\n"
           f"P = 4 mu a w0 kappa/(1 - nu) (F.1); exact Fredholm solution (F.6)-(F.7) tabulated for "
           f"{SOURCE_RANGE[0]:g} <= a/H <= {SOURCE_RANGE[1]:g}, thick series (F.18) below, NaN above.")

    def fmt(a):
        return ",\n".join(", ".join(f"{v:.17g}" for v in a[i:i + 4]) for i in range(0, a.size, 4))

    x0, xmax = float(xs[0]), float(xs[-1])
    if language == "python":
        return f'''"""{doc}"""
import numpy as np

X0, X_MAX, H_STEP, N = {x0!r}, {xmax!r}, {h!r}, {SOURCE_POINTS}
_F = np.array([
{fmt(F)}])
_DF = np.array([
{fmt(dF)}])


def kappa(a_over_H):
    """kappa for a/H > 0 (vectorised); NaN beyond a/H = {SOURCE_RANGE[1]:g} and for a/H <= 0."""
    lam = np.asarray(a_over_H, dtype=float)
    ok = lam > 0
    x = np.log(np.where(ok, lam, 1.0))
    t = np.clip((x - X0) / H_STEP, 0.0, N - 1.000000001)
    i = t.astype(np.intp)
    s = t - i
    s2, s3 = s * s, s * s * s
    F = ((2 * s3 - 3 * s2 + 1) * _F[i] + (s3 - 2 * s2 + s) * H_STEP * _DF[i]
         + (-2 * s3 + 3 * s2) * _F[i + 1] + (s3 - s2) * H_STEP * _DF[i + 1])
    small = 1.0 + lam * ({c[1]!r} + lam * ({c[2]!r} + lam * {c[3]!r}))
    out = np.where(x < X0, small, np.exp(F))
    return np.where(ok & (x <= X_MAX * (1 + 1e-15)), out, np.nan)
'''
    return f'''/* {doc} */
#include <math.h>

#define TL_X0 {x0!r}
#define TL_XMAX {xmax!r}
#define TL_H {h!r}
#define TL_N {SOURCE_POINTS}
static const double TL_F[TL_N] = {{
{fmt(F)}}};
static const double TL_DF[TL_N] = {{
{fmt(dF)}}};

/* kappa(a/H) of P = 4 mu a w0 kappa/(1 - nu); NaN beyond a/H = {SOURCE_RANGE[1]:g} and for a/H <= 0 */
double thinlayer_flat_punch_kappa(double a_over_H) {{
    if (!(a_over_H > 0.0)) return NAN;
    double x = log(a_over_H);
    if (x > TL_XMAX * (1 + 1e-15)) return NAN;
    if (x < TL_X0)
        return 1.0 + a_over_H * ({c[1]!r} + a_over_H * ({c[2]!r} + a_over_H * {c[3]!r}));
    double t = (x - TL_X0) / TL_H;
    if (t > TL_N - 1.000000001) t = TL_N - 1.000000001;
    int i = (int)t;
    double s = t - i, s2 = s * s, s3 = s2 * s;
    return exp((2 * s3 - 3 * s2 + 1) * TL_F[i] + (s3 - 2 * s2 + s) * TL_H * TL_DF[i]
               + (-2 * s3 + 3 * s2) * TL_F[i + 1] + (s3 - s2) * TL_H * TL_DF[i + 1]);
}}
'''
