r"""Fitting indentation curves: Young's modulus (optionally the thickness and the contact point) by least squares.

:func:`fit` fits ``force = P(delta - d_c; E, H)`` to a measured curve of a sphere (paraboloid of radius ``R``)
on a layer, by :func:`scipy.optimize.least_squares` with the analytic Jacobian.  The model ``P`` is

* ``"any-thickness"`` (default): :func:`thinlayer.contact.any_thickness.force_any_thickness`, valid for every
  ``a/H`` (its estimate <= 1e-3 against the direct solver);
* ``"hertz"``: the half-space, ``P = (4/3) E/(1 - nu^2) R^{1/2} delta^{3/2}`` (what a thickness-blind fit does);
* ``"dimitriadis2002"`` or ``"garcia2018"``: Hertz times a published thick-layer series in
  ``chi = sqrt(R delta)/H`` (printed coefficients, :data:`thinlayer.asymptotics.thick_layer.PUBLISHED_SERIES`).

Validity.  Hertz's law holds for the half-space and the published series are expansions for small ``chi``
printed for ``nu = 1/2`` (Dimitriadis 2002 also fits ``alpha_0(nu)``, ``beta_0(nu)``, not used here); neither
publication bounds ``chi`` in a form thinlayer could check, so the range is measured: every fit compares its
model with the any-thickness law (itself within 2e-4 of the direct solver) at the data's ``nu``, base and
``0 < chi <= chi_max`` and reports the largest relative difference of the force as ``model_error``.  Above
:data:`MODEL_TOL` (5 %, the default tolerance of :func:`thinlayer.solve`) the result is returned marked
``valid=False`` with the reason (``validity``) and a :class:`~thinlayer.errors.ValidityWarning` naming the range
and the model that holds (``"any-thickness"``): a fit is often run to compare models on the same curve (Hertz's
overestimate of E is the point of such a comparison), so the numbers come back, never unflagged.  At
``nu = 1/2`` on a bonded layer the measured ranges are ``chi <= 0.044`` (Hertz), ``chi <= 0.40`` (Dimitriadis
2002, bonded; 0.34 non-bonded) and ``chi <= 0.75`` (Garcia 2018).  A real sphere is a paraboloid to
``delta/(4R)`` in the profile at the contact edge: ``R`` here is the paraboloid's radius of curvature.

The parameters are ``log E`` (and ``log H``: both stay positive) and the contact point ``d_c`` (the depth is
``delta - d_c``; points before contact carry zero force).  Standard errors come from the Jacobian at the
solution, ``cov = s^2 (J^T J)^{-1}`` with ``s^2 = sum r^2/(n - p)`` (residuals in force units), mapped to
``E`` and ``H`` by the chain rule.
"""
from __future__ import annotations

import dataclasses
import math
import numbers
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._checks import InputError, InputTypeError, check_array_size, check_choice, positive
from ..display import RichDisplay
from ..errors import ComputationError, ValidityWarning, boundary, boundary_methods
from .any_thickness import BASES, any_thickness_law
from .guards import fit_substrate_flags, half_space, oriented_depths, regime_flags
from .models import MODEL_REGISTRY, fit_names
from .models.published import series_coefficients

__all__ = ["FIT_MODELS", "FitLaw", "FitResult", "MODEL_TOL", "curve_entries", "fit", "fit_law", "model_error"]

#: fit()'s models: the registry's entries with a force curve for fitting (:mod:`thinlayer.contact.models`)
FIT_MODELS = fit_names()
#: the largest relative difference in force from the any-thickness law over the data for a valid fit
MODEL_TOL = 0.05
#: a condition number of the scaled Jacobian above this means the data cannot separate the parameters
MAX_CONDITION = 1e10
#: more points than this are refused before any work or allocation: 1e6 points fit in 1.2 s and 0.27 GB on 2
#: cores (1e7 took 34 s and 1.9 GB); subsample a longer curve
MAX_POINTS = 1_000_000


@boundary_methods
@dataclass(frozen=True, eq=False)
class FitResult(RichDisplay):
    """The result of :func:`fit`: estimates, standard errors, the residual and the model.

    Attributes
    ----------
    E, E_se : float
        Young's modulus and its standard error.
    H, H_se : float
        Thickness (fitted, or as given with ``H_se = 0``).
    offset, offset_se : float
        Contact point ``d_c`` (fitted, or 0 with ``offset_se = 0``).
    residual_rms : float
        Root-mean-square force residual.
    residuals : numpy.ndarray
        ``model - force`` at each point.
    model, base : str
        The force model and the base.
    nu, R : float
        Poisson ratio and sphere radius.
    n_points : int
    fitted : tuple of str
        The fitted parameters (``"E"``, ``"H"``, ``"offset"``).
    covariance : numpy.ndarray
        Covariance of the fitted parameters in ``(log E, log H, offset)`` order (those fitted).
    condition : float
        Condition number of the column-scaled Jacobian.
    chi_max : float
        The largest ``sqrt(R delta)/H`` of the data (the thickness regime it probes).
    valid : bool
        Whether the model holds over the data: ``model_error <= MODEL_TOL`` (module docstring).
    model_error : float
        The largest relative difference of the model's force from the any-thickness law over ``0 < chi <=
        chi_max`` (for ``"any-thickness"``: the law's own estimate against the direct solver).
    validity : str
        Why the result is (not) valid, one line.
    flags : tuple of str
        The regime limits the data pass (:func:`thinlayer.contact.guards.regime_flags`: ``delta/H`` beyond small
        strain, ``delta/R`` where the paraboloid departs from a sphere), one line each; empty when none.
    depth_sign : int
        ``1``, or ``-1`` when the depths were given as a tip position (negative into the sample) and flipped.
    """

    E: float
    E_se: float
    H: float
    H_se: float
    offset: float
    offset_se: float
    residual_rms: float
    residuals: np.ndarray = field(repr=False)
    model: str = "any-thickness"
    base: str = "bonded"
    nu: float = 0.5
    R: float = 1.0
    n_points: int = 0
    fitted: tuple = ()
    covariance: np.ndarray = field(default=None, repr=False)
    condition: float = math.nan
    chi_max: float = math.nan
    valid: bool = True
    model_error: float = 0.0
    validity: str = ""
    tip: Any = field(default=None, repr=False)
    flags: tuple = ()
    depth_sign: int = 1
    equation = "T.7"

    @property
    def tip_words(self) -> str:
        """The tip in a few words: ``"sphere R = 10"`` (the paraboloid), ``"cone half_angle = 70"``."""
        if self.paraboloid:
            return f"sphere R = {self.R:.6g}"
        values = getattr(self.tip, "values", None)
        if isinstance(values, tuple) and all(isinstance(v, tuple) and len(v) == 2 and _is_number(v[1])
                                             for v in values):
            return f"{self.tip.name} " + ", ".join(f"{k} = {float(v):.6g}" for k, v in values)
        return getattr(self.tip, "description", None) or self.tip.name  # a pyramid: its planes are expressions

    @property
    def paraboloid(self) -> bool:
        """Whether the tip is the paraboloid of radius ``R`` (then ``chi_max = sqrt(R delta)/H``; for another tip
        ``chi_max`` is the largest contact radius over H, ``c/H``).
        """
        return self.tip is None or self.tip.sphere_radius is not None

    @property
    def mu(self) -> float:
        """Shear modulus ``E/(2(1 + nu))``."""
        return self.E / (2 * (1 + self.nu))

    def predict(self, delta: Any) -> np.ndarray:
        """The fitted model's force at the depths ``delta`` (raw, uncorrected: times ``depth_sign`` as given)."""
        tip = self.tip if self.tip is not None else _paraboloid(self.R)
        shape = (_half_space_shape(self.R, self.nu) if math.isinf(self.H)
                 else _shape_function(self.model, tip, self.nu, self.base))
        P, _, _ = shape(self.depth_sign * np.asarray(delta, dtype=float) - self.offset, self.H)
        return self.E * P

    def as_dict(self) -> dict[str, Any]:
        """The numbers as a JSON-ready dictionary."""
        return {"model": self.model, "base": self.base, "nu": self.nu, "R": self.R if self.paraboloid else None,
                "E": self.E, "E_se": self.E_se,
                "H": self.H if math.isfinite(self.H) else None, "H_se": self.H_se, "offset": self.offset,
                "offset_se": self.offset_se,
                "residual_rms": self.residual_rms, "n_points": self.n_points, "fitted": list(self.fitted),
                "condition": self.condition, "chi_max": self.chi_max, "valid": self.valid,
                "model_error": self.model_error, "validity": self.validity,
                "tip": None if self.paraboloid else self.tip_words, "flags": list(self.flags),
                "depth_sign": self.depth_sign}

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        what = f"R = {self.R:.6g}" if self.paraboloid else self.tip_words
        size = "chi_max" if self.paraboloid else "(c/H)_max"
        lines = [f"FitResult ({self.model} model, {self.base} base, nu = {self.nu:.6g}, {what}), "
                 f"{self.n_points} points, {size} = {self.chi_max:.3g}"]
        if not self.valid:
            lines.append(f"  NOT VALID: {self.validity}")
        lines.append(f"  E      = {self.E:.8g} +- {self.E_se:.2g}")
        if "H" in self.fitted:
            lines.append(f"  H      = {self.H:.8g} +- {self.H_se:.2g}")
        elif math.isinf(self.H):
            lines.append("  H      = inf (the half-space)")
        else:
            lines.append(f"  H      = {self.H:.8g} (given)")
        if "offset" in self.fitted:
            lines.append(f"  offset = {self.offset:.8g} +- {self.offset_se:.2g}")
        lines.append(f"  residual rms = {self.residual_rms:.4g}")
        lines += [f"  FLAG: {f}" for f in self.flags]
        if self.model == "any-thickness" or not self.paraboloid:
            lines.append(f"  model error  = {100 * self.model_error:.2g} % (the law's own estimate, against the direct "
                         "solver)")
        else:
            lines.append(f"  model error  = {100 * self.model_error:.2g} % against the any-thickness law"
                         + ("" if self.valid else f" (a valid fit needs <= {100 * MODEL_TOL:.3g} %)"))
        return lines

    def latex(self) -> str:
        return (rf"E = {self.E:.6g} \pm {self.E_se:.2g},\quad H = {self.H:.6g},\quad "
                rf"\text{{{self.model}}},\ \nu = {self.nu:.4g}")


def _paraboloid(R: float):
    from ..punch import Punch

    return Punch.paraboloid(R)


def _is_number(v: Any) -> bool:
    """A real number (a Python or numpy number, or a sympy number), not an expression or a tuple."""
    if isinstance(v, bool):
        return False
    if isinstance(v, numbers.Real):
        return True
    return bool(getattr(v, "is_number", False)) and bool(getattr(v, "is_real", False))


def _problem(tip: Any, nu: float, base: str, H: float):
    from ..layers.kernels import BondedLayer, FrictionlessLayer
    from .problem import Depth, Elastic, Frictionless, Problem

    layer = FrictionlessLayer(nu) if base == "frictionless" else BondedLayer(nu)
    return Problem(layer, tip, Elastic(1.0, nu), Frictionless(), Depth(1.0), H, math.inf)


def curve_entries(tip: Any, nu: float, base: str) -> list[str]:
    """The models of :func:`fit` with a force curve for this tip, layer and ``nu`` (by preference)."""
    out = []
    for m in MODEL_REGISTRY:
        if m.fits and m.name not in out:
            try:
                if m.force_curve(_problem(tip, nu, base, 1.0)) is not None:
                    out.append(m.name)
            except (ValueError, TypeError):  # the model refuses this problem (one line, e.g. nu)
                continue
    return out


def _entry(model: str, tip: Any, nu: float, base: str):
    """The first entry named ``model`` with a force curve for the tip (refusals raised as they come)."""
    for m in MODEL_REGISTRY:
        if m.fits and m.name == model and m.force_curve(_problem(tip, nu, base, 1.0)) is not None:
            return m
    holds = curve_entries(tip, nu, base)
    if not holds:
        raise InputError(f"fit() has no force curve for the {tip.name} (nu = {nu:g}, {base} base): it takes a sphere "
                         "(the radius R, Punch.paraboloid(R), Punch.sphere(R)) or another tip of revolution "
                         "(Punch.cone(70), Punch.blunted_cone(R, 70), Punch.power_law(C, n))")
    raise InputError(f"fit(model={model!r}) has no force curve for the {tip.name} on this layer (nu = {nu:g}, "
                     f"{base} base); the models that fit it: {', '.join(holds)}")


def _shape_function(model: str, tip: Any, nu: float, base: str):
    """``g(delta, H, slopes) -> (P/E, d log P/d log delta, d log P/d log H)`` of one model (zero force for
    delta <= 0; the slopes only when ``slopes``, else zeros).

    The model's unit-modulus :class:`~thinlayer.contact.models.ForceCurve` from the registry (no tolerance: the
    validity is measured by :func:`model_error` or the curve's own estimate), divided by ``E/mu = 2(1 + nu)``.
    """
    entry = _entry(model, tip, nu, base)
    scale = 1.0 / (2.0 * (1.0 + nu))
    curves: dict[float, Any] = {}

    def g(delta: np.ndarray, H: float, slopes: bool = True):
        curve = curves.get(H)
        if curve is None:
            if len(curves) > 64:
                curves.clear()
            curve = curves[H] = entry.force_curve(_problem(tip, nu, base, H))
        pos = delta > 0
        d = np.where(pos, delta, 1.0)
        P = np.where(pos, curve.force(d) * scale, 0.0)
        if not slopes:
            return P, None, None
        gd, gH = curve.slopes(d)
        return P, np.where(pos, gd, 0.0), np.where(pos, gH, 0.0)

    g.curve = lambda H: curves.get(H) or entry.force_curve(_problem(tip, nu, base, H))
    return g


_NAMES = {"hertz": "Hertz's half-space law", "dimitriadis2002": "the Dimitriadis et al. (2002) series",
          "garcia2018": "the Garcia & Garcia (2018) series", "any-thickness": "the any-thickness law"}


def model_error(model: str, R: float, nu: float, base: str, H: float, chi_max: float) -> tuple[float, float]:
    """``(largest |P_model/P_any-thickness - 1| over 0 < chi <= chi_max, the chi where it is reached)``.

    The any-thickness law (T.7) is the independent reference (within 2e-4 of the direct solver); for the law
    itself, its own estimate at ``chi_max``.
    """
    law = any_thickness_law(nu, base)
    if not chi_max > 0:
        return 0.0, 0.0
    if model == "any-thickness":
        return float(law.error_estimate(np.array([chi_max]))[0][0]), chi_max
    chi = np.geomspace(min(1e-4, chi_max), chi_max, 400)
    ratio, _ = law.ratios(chi)
    coef = np.array(series_coefficients(model, base))
    dev = np.abs(np.polynomial.polynomial.polyval(chi, coef) / ratio - 1.0)
    k = int(np.argmax(dev))
    return float(dev[k]), float(chi[k])


def _validity(model: str, R: float, nu: float, base: str, H: float, chi_max: float) -> tuple[bool, float, str]:
    err, at = model_error(model, R, nu, base, H, chi_max)
    if model == "any-thickness" or err <= MODEL_TOL:
        return True, err, (f"{_NAMES[model]} is within {100 * err:.2g} % of the any-thickness law up to chi_max = "
                           f"{chi_max:.3g}")
    printed = "" if model == "hertz" or nu == 0.5 else f", and it is printed for nu = 1/2 (here nu = {nu:.4g})"
    return False, err, (f"{_NAMES[model]} differs from the any-thickness law by {100 * err:.3g} % at chi = "
                        f"sqrt(R delta)/H = {at:.3g} (the data reach chi_max = {chi_max:.3g}; a valid fit needs "
                        f"<= {100 * MODEL_TOL:.3g} %){printed}: outside its range; model='any-thickness' holds at "
                        "every chi")


def _points(delta: Any, force: Any) -> tuple[np.ndarray, np.ndarray]:
    for name, v in (("delta", delta), ("force", force)):
        check_array_size(v, name, MAX_POINTS, "1e6 points fit in 1.2 s and 0.27 GB; subsample the curve")
    try:
        d = np.asarray(delta, dtype=float).ravel()
        f = np.asarray(force, dtype=float).ravel()
    except (TypeError, ValueError, OverflowError):
        raise InputError("delta and force must be sequences of numbers") from None
    if d.size != f.size:
        raise InputError(f"delta and force must have the same length, got {d.size} and {f.size}")
    if not (np.all(np.isfinite(d)) and np.all(np.isfinite(f))):
        raise InputError("delta and force must be finite (no nan or inf); drop the bad rows first")
    return d, f


def _tip(punch: Any) -> tuple[Any, float]:
    """``(tip, R)``: a number is the paraboloid's radius; a tip with numbers (``R`` NaN unless a paraboloid)."""
    if isinstance(punch, numbers.Real) and not isinstance(punch, bool):
        R = positive(punch, "punch (the sphere radius R)")
        return _paraboloid(R), R
    from ..punch import Tip

    if not isinstance(punch, Tip):
        raise InputTypeError(f"punch must be the sphere radius R (a number) or a tip (Punch.paraboloid(R), "
                             f"Punch.cone(70), Punch.sphere(R), ...), got {punch!r:.80}")
    if not punch.is_numeric:
        raise InputError(f"fit() needs a tip with numbers for its parameters "
                         f"({', '.join(q.name for q in punch.parameters)}): use .subs({{...}})")
    R = punch.sphere_radius
    return punch, (math.nan if R is None else R)


@boundary
def fit(delta: Any, force: Any, punch: Any = None, H: Any = None, nu: Any = 0.5, base: str = "bonded", *,
        fit_H: bool = False, fit_offset: bool = False, model: str | None = None, E0: float | None = None,
        sigma: Any = None, depth_sign: int = 1, work_of_adhesion: Any = None, substrate_E: Any = None,
        substrate_nu: Any = 0.0) -> FitResult:
    r"""Estimate Young's modulus (and optionally H and the contact point) from a force-indentation curve.

    Parameters
    ----------
    delta, force : array_like
        Indentation depths and forces (same length, consistent units).
    punch : float or Tip
        The sphere radius ``R`` or ``Punch.paraboloid(R)``, or any tip with a force curve (``Punch.cone(70)``,
        ``Punch.sphere(R)``, ``Punch.blunted_cone(R, alpha)``, ``Punch.power_law(C, n)``, ...: the models
        ``"tip-law"`` and ``"direct"``, and any other model whose force curve takes the tip).
    H : float or None
        Layer thickness (the starting value when ``fit_H``); ``None`` or ``inf``: the half-space (Hertz's law,
        the paraboloid only in this version).
    nu : float
        Poisson ratio, ``-1 < nu <= 1/2``.
    base : str
        ``"bonded"`` or ``"frictionless"``.
    fit_H, fit_offset : bool
        Also fit the thickness, the contact point ``d_c`` (force at depth ``delta - d_c``).
    model : str, optional
        ``"any-thickness"``, ``"hertz"``, ``"dimitriadis2002"``, ``"garcia2018"`` (paraboloid), ``"tip-law"``
        (thin-layer law of a tip of revolution), ``"direct"`` (the axisymmetric solver, tabulated).  Default:
        ``"any-thickness"`` when it has a curve for the tip, else the first of :func:`curve_entries`.  For a tip
        other than the paraboloid, ``model_error`` is the curve's own estimate (against the direct solver) at the
        data's largest depth and over the data, and a fit is valid when it is within 5 %.
    E0 : float, optional
        Starting value of E (default: from the points by the model with the given H).
    sigma : array_like, optional
        Standard deviation of each force (weights ``1/sigma``); default equal weights.
    depth_sign : int
        ``1`` (default): ``delta`` is the depth, positive into the sample, the force growing with it; ``-1``:
        ``delta`` is a tip position (nanite, afmformats: negative into the sample), flipped.  Depths that are all
        ``<= 0`` or whose force falls as they grow are refused (:mod:`thinlayer.contact.guards`).
    work_of_adhesion : str, optional
        ``"free"``: an adhesive (JKR) unloading curve, signed forces (tensile negative): E and the work of adhesion
        w are fitted together (:func:`thinlayer.contact.adhesion_fit.fit_free_adhesion`; the any-thickness JKR
        law (J.16) on a layer, the direct solver on the half-space); the answer is an
        :class:`~thinlayer.contact.adhesion_fit.AdhesiveFit` (``E``, ``E_error``, ``work_of_adhesion``,
        ``work_of_adhesion_error``).  The paraboloid only; ``fit_H``, ``fit_offset`` and ``sigma`` are not taken.
    substrate_E, substrate_nu : float, optional
        Young's modulus (units of E) and Poisson ratio (default 0: the largest estimate) of the substrate under the
        layer: the laws take the base as rigid, and the result carries a flag when the substrate's compliance would
        change the force by more than 1 % at the deepest point (first order, ``kappa(a/H) E*_layer/E*_substrate``
        with the rigid overlap radius ``a``: :func:`thinlayer.contact.guards.substrate_flags`).

    Returns
    -------
    FitResult

    Raises
    ------
    ValueError
        One line naming what is missing: fewer points than parameters plus one, no positive force, no point in
        contact, depths of the wrong sign (the convention in one sentence), or data that cannot separate the
        parameters (singular Jacobian).

    Examples
    --------
    >>> import numpy as np
    >>> from thinlayer.contact.any_thickness import force_any_thickness
    >>> d = np.linspace(0.01, 1.0, 50)
    >>> P = force_any_thickness(d, R=10.0, H=2.0, E=3.0, nu=0.5)
    >>> r = fit(d, P, punch=10.0, H=2.0, nu=0.5)
    >>> round(r.E, 8), bool(r.E_se < 1e-8)
    (3.0, True)
    """
    if work_of_adhesion is not None:  # an adhesive curve (issue 26 item 5): E and w together
        from .adhesion_fit import fit_free_adhesion

        if substrate_E is not None:
            raise InputTypeError("fit(): substrate_E is checked for the non-adhesive fits only; leave it out with "
                                 "work_of_adhesion=")

        check_choice(base, BASES, "base")
        extras = tuple(n for n, v in (("fit_H", fit_H), ("fit_offset", fit_offset), ("sigma", sigma is not None)) if v)
        return fit_free_adhesion(delta, force, _tip(punch)[0] if punch is not None else None, H, _nu(nu), base,
                                 E0=E0, work_of_adhesion=work_of_adhesion, model=model, depth_sign=depth_sign,
                                 extras=extras)
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):  # checked below
        res = _fit(delta, force, punch, H, nu, base, fit_H, fit_offset, model, E0, sigma, depth_sign)
        if model is None and res.valid is False and not math.isfinite(res.model_error):
            res = _beyond_the_table(res, delta, force, punch, H, nu, base, fit_H, fit_offset, E0, sigma, depth_sign)
    if not all(math.isfinite(v) for v in (res.E, res.E_se, res.H_se, res.offset, res.residual_rms)) \
            or math.isnan(res.H):
        raise ComputationError(f"fit(): the fitted numbers are not finite (E = {res.E!r}, E_se = {res.E_se!r}): the "
                               "data's numbers leave the double range; express depths and forces in other units")
    if substrate_E is not None:
        extra = fit_substrate_flags(res.base, res.nu, res.R, res.chi_max, res.E, substrate_E, substrate_nu)
        if extra:
            res = dataclasses.replace(res, flags=res.flags + extra)
    if res.valid is False:
        warnings.warn(f"fit(): E = {res.E:.4g} is NOT VALID: {res.validity}", ValidityWarning, stacklevel=3)
    return res


def _beyond_the_table(res: FitResult, *args: Any) -> FitResult:
    """The default model's data reach beyond its table (no estimate there: ``model_error`` infinite): the next
    model with a law (not the direct solver, whose fit takes minutes) that holds over the data answers instead;
    none: the first answer, NOT VALID.
    """
    delta, force, punch, H, nu, base, fit_H, fit_offset, E0, sigma, depth_sign = args
    for alt in curve_entries(_tip(punch)[0], _nu(nu), base):
        if alt in (res.model, "direct"):
            continue
        try:
            other = _fit(delta, force, punch, H, nu, base, fit_H, fit_offset, alt, E0, sigma, depth_sign)
        except (ValueError, ArithmeticError):
            continue
        if other.valid:
            return other
    return res


def _nu(nu: Any) -> float:
    if isinstance(nu, bool) or not isinstance(nu, numbers.Real) or not -1 < float(nu) <= 0.5:
        raise InputError(f"nu must be a number in (-1, 1/2], got {nu!r}")
    return float(nu)


def _fit(delta, force, punch, H, nu, base, fit_H, fit_offset, model, E0, sigma, depth_sign) -> FitResult:
    d, f = _points(delta, force)
    if sigma is not None:  # refused before any law is built (bounded work)
        check_array_size(sigma, "sigma", MAX_POINTS, "one standard deviation per point")
    d = oriented_depths(d, f, depth_sign)
    if punch is None:
        raise InputTypeError("fit() needs punch= (the sphere radius R, Punch.paraboloid(R) or another tip)")
    tip, R = _tip(punch)
    halfspace = half_space(H)
    if halfspace and fit_H:
        raise InputTypeError("fit(fit_H=True) needs H= (the starting value of the thickness); H=None or inf is the "
                             "half-space")
    if halfspace and math.isnan(R):
        raise InputError(f"fit(H=inf): the half-space is fitted for the paraboloid (Hertz) in this version, not the "
                         f"{tip.name}; give a finite H")
    H0 = math.inf if halfspace else positive(H, "H")
    check_separable(tip, fit_H)
    check_choice(base, BASES, "base")
    if model is not None:
        check_choice(model, fit_names(), "model")
    if isinstance(nu, bool) or not isinstance(nu, numbers.Real) or not -1 < float(nu) <= 0.5:
        raise InputError(f"nu must be a number in (-1, 1/2], got {nu!r}")
    nu = float(nu)
    if halfspace:  # every paraboloid model is Hertz's law at chi = 0
        model = "hertz"
    elif model is None:
        holds = curve_entries(tip, nu, base)
        model = "any-thickness" if "any-thickness" in holds or not holds else holds[0]
    names = ["E"] + (["H"] if fit_H else []) + (["offset"] if fit_offset else [])
    p = len(names)
    if d.size < p + 1:
        raise InputError(f"{d.size} points cannot determine {p} parameter(s) ({', '.join(names)}) with an error "
                         f"estimate: give at least {p + 1} points")
    if not np.any(f > 0):
        raise InputError("no positive force in the data: the curve carries no information on E (is the force "
                         "column right, and in contact?)")
    if sigma is None:
        w = np.ones_like(f)
    else:
        try:
            s = np.broadcast_to(np.asarray(sigma, dtype=float), f.shape)
        except (TypeError, ValueError, OverflowError):
            raise InputError(f"sigma must be one positive number or one per point ({f.size}), got "
                             f"{np.size(sigma)} values") from None
        if not (np.all(np.isfinite(s)) and np.all(s > 0)):
            raise InputError("sigma must be positive and finite")
        w = 1.0 / s
    shape = _half_space_shape(R, nu) if halfspace else _shape_function(model, tip, nu, base)
    P1, _, _ = shape(d, H0, slopes=False)
    if not np.any(P1 > 0):
        raise InputError("no point is in contact with the starting contact point: check the depth column")
    if E0 is None:
        sel = (P1 > 0) & (f > 0)
        E0 = float(np.median(f[sel] / P1[sel])) if sel.any() else 1.0
    else:
        E0 = positive(E0, "E0")
    fscale = float(np.max(np.abs(f * w)))

    def unpack(x):
        E = math.exp(x[0])
        HH = math.exp(x[1]) if fit_H else H0
        dc = x[-1] * dscale if fit_offset else 0.0
        return E, HH, dc

    dscale = float(np.max(np.abs(d))) or 1.0

    def resid(x):
        E, HH, dc = unpack(x)
        P, _, _ = shape(d - dc, HH, slopes=False)
        return (E * P - f) * w / fscale

    def jac(x):
        E, HH, dc = unpack(x)
        dd = d - dc
        P, gd, gH = shape(dd, HH, slopes=fit_H or fit_offset)
        EP = E * P * w / fscale
        cols = [EP]
        if fit_H:
            cols.append(EP * gH)
        if fit_offset:
            with np.errstate(divide="ignore", invalid="ignore"):
                cols.append(np.where(dd > 0, -EP * gd / np.where(dd > 0, dd, 1.0), 0.0) * dscale)
        return np.column_stack(cols)

    from scipy import optimize

    x0 = [math.log(E0)] + ([math.log(H0)] if fit_H else []) + ([0.0] if fit_offset else [])
    sol = optimize.least_squares(resid, x0, jac=jac, method="lm", xtol=1e-14,
                                 ftol=1e-14, gtol=1e-14, max_nfev=2000)
    E, HH, dc = unpack(sol.x)
    J = jac(sol.x)
    r = sol.fun
    colnorm = np.linalg.norm(J, axis=0)
    if np.any(colnorm == 0):
        bad = names[int(np.argmin(colnorm))]
        raise InputError(f"the data do not determine {bad}: the model does not depend on it at these points")
    sv = np.linalg.svd(J / colnorm, compute_uv=False)
    cond = float(sv[0] / sv[-1]) if sv[-1] > 0 else math.inf
    if cond > MAX_CONDITION:
        raise InputError(f"the data cannot separate {', '.join(names)} (singular Jacobian, condition {cond:.2g}): "
                         "fit fewer parameters (e.g. give H) or measure deeper indentations")
    dof = d.size - p
    s2 = float(r @ r) / dof
    cov_scaled = np.linalg.inv(J.T @ J) * s2
    # back to physical units: residuals were divided by fscale (w included), the offset scaled by dscale
    scale = np.array([1.0] + ([1.0] if fit_H else []) + ([dscale] if fit_offset else []))
    cov = cov_scaled * np.outer(scale, scale)
    se = np.sqrt(np.diag(cov))
    E_se = E * se[0]
    H_se = HH * se[1] if fit_H else 0.0
    off_se = se[-1] if fit_offset else 0.0
    resid_force = (r * fscale / w)
    dmax = max(float(np.max(d - dc)), 0.0)
    if halfspace:
        chi_max, valid, err, why = 0.0, True, 0.0, "the half-space (H = inf): Hertz's law, the paraboloid's force"
    elif math.isnan(R):
        chi_max, (valid, err, why) = _tip_validity(shape.curve(HH), d - dc, HH, model)
    else:
        chi_max = float(math.sqrt(R * dmax) / HH)
        valid, err, why = _validity(model, R, nu, base, HH, chi_max)
    return FitResult(E, E_se, HH, H_se, dc, off_se, float(np.sqrt(np.mean(resid_force**2))), resid_force, model,
                     base, nu, R, int(d.size), tuple(names), cov, cond, chi_max, valid, err, why, tip,
                     regime_flags(dmax, HH, None if math.isnan(R) else R), depth_sign)


def _half_space_shape(R: float, nu: float):
    """The half-space's ``g(delta, H, slopes)`` of :func:`_shape_function`: Hertz, ``(4/3) R^{1/2} delta^{3/2}/(1 -
    nu^2)`` per unit E (H is ignored; the slope in H is zero).
    """
    K = 4.0 / 3.0 * math.sqrt(R) / (1.0 - nu * nu)

    def g(delta: np.ndarray, H: float, slopes: bool = True):
        pos = delta > 0
        P = np.where(pos, K * np.where(pos, delta, 0.0) ** 1.5, 0.0)
        if not slopes:
            return P, None, None
        return P, np.where(pos, 1.5, 0.0), np.zeros_like(P)

    return g


def _tip_validity(curve: Any, depths: np.ndarray, H: float, model: str) -> tuple[float, tuple[bool, float, str]]:
    """``((c/H)_max, (valid, model error, why))`` of a fit with a tip other than the paraboloid: the curve's own
    estimate, largest over the points in contact.
    """
    dd = depths[depths > 0]
    est = curve.estimate(dd)
    err = float(np.max(est)) if dd.size and np.all(np.isfinite(est)) else math.inf
    c = curve.contact_radius(np.array([float(dd.max())])) if dd.size else np.array([0.0])
    size = float(c[0]) / H if np.isfinite(c[0]) else math.nan
    if err <= MODEL_TOL:
        return size, (True, err, f"the {model} model's own estimate is within {100 * err:.2g} % over the data "
                                 f"(c/H up to {size:.3g})")
    return size, (False, err, f"the {model} model's own estimate reaches {100 * err:.3g} % over the data (c/H up to "
                              f"{size:.3g}; a valid fit needs <= {100 * MODEL_TOL:.3g} %): outside its range; "
                              "model='direct' holds at every thickness")


@dataclass(frozen=True)
class FitLaw:
    """The force law :func:`fit` fits, for a caller that adds parameters of its own (a baseline, a contact point on a
    measured axis: :func:`thinlayer.afm.curves.fit_curve`).  Built by :func:`fit_law`.

    ``shape(delta, H, slopes)`` returns ``(P/E, d log P/d log delta, d log P/d log H)`` (zero force for ``delta <=
    0``; the slopes only when ``slopes``); :meth:`validity` is fit()'s own check of the model over the data.
    """

    tip: Any
    R: float
    model: str
    nu: float
    base: str
    half_space: bool
    shape: Any = field(repr=False)

    def validity(self, depths: np.ndarray, H: float) -> tuple[float, bool, float, str, tuple]:
        """``(chi_max (or (c/H)_max), valid, model_error, why, regime flags)`` of the law over ``depths`` (those
        ``> 0`` are in contact), as :func:`fit` reports them.
        """
        d = np.asarray(depths, dtype=float)
        dmax = max(float(np.max(d)) if d.size else 0.0, 0.0)
        if self.half_space:
            chi_max, valid, err, why = 0.0, True, 0.0, "the half-space (H = inf): Hertz's law, the paraboloid's force"
        elif math.isnan(self.R):
            chi_max, (valid, err, why) = _tip_validity(self.shape.curve(H), d, H, self.model)
        else:
            chi_max = float(math.sqrt(self.R * dmax) / H)
            valid, err, why = _validity(self.model, self.R, self.nu, self.base, H, chi_max)
        return chi_max, valid, err, why, regime_flags(dmax, H, None if math.isnan(self.R) else self.R)


def check_separable(tip: Any, fit_H: bool) -> None:
    """A flat punch's force is ``E kappa(a/H)`` times the depth: one stiffness, so E and H cannot both be fitted."""
    if fit_H and tip.fixed_contact:
        raise InputError("fit(fit_H=True): a flat punch's force is linear in the depth, P = 4 mu a kappa(a/H) "
                         "delta/(1 - nu) (F.1): its curve gives one stiffness, not E and H apart; give H")


def fit_law(punch: Any, H: Any, nu: Any = 0.5, base: str = "bonded", model: str | None = None) -> FitLaw:
    """The law :func:`fit` would fit for these arguments (the same checks, the same model choice), as a
    :class:`FitLaw`; ``H`` None or inf: Hertz's half-space law (the paraboloid).
    """
    if punch is None:
        raise InputTypeError("fit() needs punch= (the sphere radius R, Punch.paraboloid(R) or another tip)")
    tip, R = _tip(punch)
    halfspace = half_space(H)
    if halfspace and math.isnan(R):
        raise InputError(f"fit(H=inf): the half-space is fitted for the paraboloid (Hertz) in this version, not the "
                         f"{tip.name}; give a finite H")
    if not halfspace:
        positive(H, "H")
    check_choice(base, BASES, "base")
    if model is not None:
        check_choice(model, fit_names(), "model")
    if isinstance(nu, bool) or not isinstance(nu, numbers.Real) or not -1 < float(nu) <= 0.5:
        raise InputError(f"nu must be a number in (-1, 1/2], got {nu!r}")
    nu = float(nu)
    if halfspace:
        model = "hertz"
    elif model is None:
        holds = curve_entries(tip, nu, base)
        model = "any-thickness" if "any-thickness" in holds or not holds else holds[0]
    shape = _half_space_shape(R, nu) if halfspace else _shape_function(model, tip, nu, base)
    return FitLaw(tip, R, model, nu, base, halfspace, shape)
