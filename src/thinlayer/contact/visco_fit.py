r"""Fitting viscoelastic data on a layer (issue 27 item 4): the material's parameters with their uncertainties.

:func:`fit_viscoelastic` fits a standard linear solid (``E0``, ``E_inf``, ``tau``) or a power law (``E0``,
``alpha`` at a given ``t0``) for a given thickness ``H`` to

* **force curves** against time -- ramp-hold, approach-retract, at one or several speeds: each a triple
  ``(times, depths, forces)``.  The model is Lee-Radok's force (:mod:`thinlayer.contact.hereditary`) over the layer's
  elastic law at unit modulus, ``P = 1/(2(1 + nu)) int E(t - s) dF(delta(s))``; ``F(delta(t))`` is evaluated once per
  curve (it does not depend on the material), and each evaluation of the model is one O(N) hereditary integral.
  Lee-Radok holds while the contact grows.  For a standard linear solid and a depth that rises to one maximum and
  then falls (approach-retract), the retraction is fitted by Ting's method (T3)-(T5)
  (:func:`thinlayer.contact.ting.ting_force`, one call per evaluation of the model, ~25 ms per 1,000 points);
  otherwise (power law; other histories) the points from the first shrink on are **left out** of the fit and counted
  (``n_excluded``).
* **an oscillation** -- the dynamic stiffness ``K*(w) = (Delta P/Delta delta)(w)`` measured around a depth
  ``delta0`` (:mod:`thinlayer.contact.oscillation`): ``E*(w) = 2(1 + nu) K*/S(delta0)`` with the layer's ``S``,
  fitted by the model's complex modulus (real and imaginary parts).

**H free and the contact point** (``fit_H=True``, ``contact_point=True``).  ``H`` joins the parameters (``log H``,
kept within a factor :data:`H_RANGE` of its start); with ``contact_point`` each curve's second column is the tip
position ``z`` (negative into the sample, nanite's axis), the depth ``delta = z0 - z`` (no contact, ``F = 0``, before
``z0`` on the approach; on the retraction the tip may rise above the undeformed surface while Ting's contact holds),
and each curve has its own contact point ``z0`` and baseline force ``b0``: ``force = b0 + P(t)``.  The start: ``b0``
the median of the farthest fifth of the approach, ``z0`` the last approach point within ``max(5 sigma, 1 %)`` of the
force range from it; Lee-Radok on the approach fits first (cheap), Ting's retraction after.  The law at unit modulus is
re-evaluated for each ``(H, z0)`` (the registry's model chosen once, then named: ~0.5 ms a law).
Whether the data separate ``H`` from the modulus is reported, not assumed: the result carries the correlation matrix
and the reason the correlations of ``H`` with the moduli; a flag (one line) says so when ``|corr| >``
:data:`MAX_H_CORRELATION` or the relative error of ``H`` exceeds :data:`MAX_H_RELATIVE_ERROR`.  Measured on approach
curves (sphere R = 10, bonded nu = 1/2, H = 1, delta to 0.1, SLS 3/1/0.3, 0.3 % noise,
tests/viscoelastic/test_visco_fit_H.py, seed 1): one speed, 200 points: ``H = 1.20 +- 0.37`` (31 %, flagged; time and
depth are tied, ``delta = v t``, and relaxation mimics the base's stiffening), ``tau = 0.59 +- 1.2``; two speeds a
decade apart, 100 points each: ``H = 1.054 +- 0.039``, ``tau = 0.282 +- 0.044``; over 40 seeds (two speeds, 200 points
each) 288 of 320 parameter values lie within two standard errors (90 %, nominal 95 %: the delta method is a
linearisation); ``corr(H, E0)`` is 0.99 even then (a thinner layer and a softer material trade
off), so the correlation alone does not decide.  At ``delta/H = 1e-3`` (the half-space) ``H`` is flagged.

Least squares by :func:`scipy.optimize.least_squares` in unconstrained variables (``log E_inf``,
``log(E0 - E_inf)``, ``log tau``; ``log E0``, ``logit alpha``); the standard errors from the Jacobian at the
solution, ``cov = s^2 (J^T J)^{-1}``, ``s^2 = sum r^2/(n - p)``, carried to the parameters by the chain rule (the
delta method: a linearisation, fair while the errors are small against the values).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._checks import InputError, InputTypeError, check_choice, positive
from ..asymptotics.solution import DEFAULT_TOL
from ..display import RichDisplay
from ..errors import ComputationError, boundary
from .hereditary import check_setting, hereditary_integral, viscoelastic_force
from .materials import Material, PowerLaw, Prony, StandardLinearSolid
from .oscillation import contact_stiffness

__all__ = ["MATERIALS", "ViscoFitResult", "fit_viscoelastic"]

#: the materials fit_viscoelastic() fits, and their parameters
MATERIALS = {"sls": ("E0", "E_inf", "tau"), "power-law": ("E0", "alpha")}
#: more points than this (over all curves) are refused before any work
MAX_POINTS = 1_000_000


@dataclass(frozen=True, eq=False)
class ViscoFitResult(RichDisplay):
    r"""The result of :func:`fit_viscoelastic`.

    Attributes
    ----------
    material : Material
        The fitted material (``StandardLinearSolid`` as a one-term :class:`Prony`, or :class:`PowerLaw`).
    values, errors : dict
        The parameters by name and their standard errors.
    covariance : numpy.ndarray
        Covariance of the parameters in the order of ``values``.
    kind : str
        ``"curves"`` or ``"oscillation"``.
    model : str
        The elastic law at unit modulus the model used.
    residual_rms : float
        Root-mean-square residual (force units; modulus units for an oscillation).
    n_points, n_excluded : int
        Points fitted, and points left out (shrinking contact: Lee-Radok does not hold there).
    H, nu : float
    reason : str
        What was fitted and what was left out, one line.
    """

    material: Material
    values: dict
    errors: dict
    covariance: np.ndarray = field(repr=False)
    kind: str
    model: str
    residual_rms: float
    n_points: int
    n_excluded: int
    H: float
    nu: float
    reason: str
    #: the correlation matrix of the parameters (order of ``values``)
    correlation: np.ndarray = field(default=None, repr=False)
    #: warnings a reader must see (e.g. H not separated from the modulus), one line each
    flags: tuple = ()

    equation = "Lee-Radok (fitted)"

    def latex(self) -> str:
        body = r",\ ".join(rf"{_tex(k)} = {v:.6g} \pm {self.errors[k]:.2g}" for k, v in self.values.items())
        return body + r",\quad " + self.material.latex()

    def text_lines(self) -> list[str]:
        out = [f"ViscoFitResult ({self.kind}, {self.model} law, H = {self.H:.6g}, nu = {self.nu:.4g}): "
               f"{self.n_points} points" + (f", {self.n_excluded} left out" if self.n_excluded else "")]
        out += [f"  {k:<6} = {v:.8g} ± {self.errors[k]:.3g}" for k, v in self.values.items()]
        out.append(f"  residual rms {self.residual_rms:.3g}; {self.reason}")
        out += [f"  FLAG: {f}" for f in self.flags]
        return out

    def __str__(self) -> str:
        return "\n".join(self.text_lines())

    def as_dict(self) -> dict:
        """Plain numbers for JSON."""
        return {"kind": self.kind, "model": self.model, "H": self.H, "nu": self.nu, "values": dict(self.values),
                "errors": dict(self.errors), "residual_rms": self.residual_rms, "n_points": self.n_points,
                "n_excluded": self.n_excluded, "reason": self.reason, "flags": list(self.flags),
                "correlation": None if self.correlation is None else [[float(v) for v in row]
                                                                      for row in self.correlation]}


def _tex(name: str) -> str:
    base, _, k = name.partition("_") if name[:2] in ("z0", "b0") else (name, "", "")
    tex = {"E0": "E_0", "E_inf": r"E_\infty", "tau": r"\tau", "alpha": r"\alpha", "H": "H", "z0": "z_0",
           "b0": "b_0"}[base]
    return tex if not k else f"{tex[0]}_{{0,{k}}}"


# =============================================================================================
# the parametrisations: unconstrained x -> material, and the Jacobian d(values)/dx
# =============================================================================================
def _sls(x: np.ndarray) -> tuple[Material, np.ndarray, np.ndarray]:
    einf, de, tau = math.exp(x[0]), math.exp(x[1]), math.exp(x[2])
    vals = np.array([einf + de, einf, tau])
    jac = np.array([[einf, de, 0.0], [einf, 0.0, 0.0], [0.0, 0.0, tau]])
    return StandardLinearSolid(einf + de, einf, tau), vals, jac


def _power(x: np.ndarray, t0: float) -> tuple[Material, np.ndarray, np.ndarray]:
    e0 = math.exp(x[0])
    a = 1.0 / (1.0 + math.exp(-x[1]))
    a = min(max(a, 1e-12), 1.0 - 1e-12)
    vals = np.array([e0, a])
    jac = np.array([[e0, 0.0], [0.0, a * (1.0 - a)]])
    return PowerLaw(e0, t0, a), vals, jac


def _start(kind: str, scale: float, span: float, guess: dict | None) -> np.ndarray:
    g = dict(guess or {})
    if kind == "sls":
        e0 = float(g.get("E0", 2.0 * scale))
        einf = float(g.get("E_inf", scale))
        tau = float(g.get("tau", span / 5.0))
        if not (e0 > einf > 0 and tau > 0):
            raise InputError(f"guess must have E0 > E_inf > 0 and tau > 0, got {guess!r}")
        return np.log([einf, e0 - einf, tau])
    e0 = float(g.get("E0", scale))
    a = float(g.get("alpha", 0.2))
    if not (e0 > 0 and 0 < a < 1):
        raise InputError(f"guess must have E0 > 0 and 0 < alpha < 1, got {guess!r}")
    return np.array([math.log(e0), math.log(a / (1.0 - a))])


def _bool(value: Any, name: str) -> bool:
    if not isinstance(value, (bool, np.bool_)):
        raise InputTypeError(f"{name} must be True or False, got {value!r}")
    return bool(value)


def _curves(curves: Any) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    if isinstance(curves, (str, bytes)) or not isinstance(curves, (list, tuple)) or not curves:
        raise InputTypeError("curves must be a non-empty list of (times, depths, forces) triples")
    if len(curves) == 3 and all(isinstance(c, np.ndarray) and c.ndim == 1 for c in curves):
        curves = [curves]  # one curve given bare
    out, total = [], 0
    for k, c in enumerate(curves):
        if isinstance(c, (str, bytes)) or not isinstance(c, (list, tuple)) or len(c) != 3:
            raise InputTypeError(f"curves[{k}] must be a triple (times, depths, forces)")
        try:
            t, d, p = (np.array(a, dtype=float) for a in c)
        except (TypeError, ValueError):
            raise InputTypeError(f"curves[{k}]: times, depths and forces must be sequences of numbers") from None
        if t.ndim != 1 or d.shape != t.shape or p.shape != t.shape or t.size < 2:
            raise InputError(f"curves[{k}]: times, depths and forces must be 1-d, of one length >= 2")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(d)) and np.all(np.isfinite(p))):
            raise InputError(f"curves[{k}]: times, depths and forces must be finite (no nan or inf)")
        if np.any(np.diff(t) <= 0):
            raise InputError(f"curves[{k}]: times must be strictly increasing")
        total += t.size
        if total > MAX_POINTS:
            raise InputError(f"at most {MAX_POINTS} points over all curves; subsample them")
        out.append((t, d, p))
    return out


def _one_maximum(d: np.ndarray) -> bool:
    """The depth rises (or holds) to its maximum, then falls somewhere: Ting's history (one maximum of the radius)."""
    m = int(np.argmax(d))
    return bool(np.all(np.diff(d[: m + 1]) >= 0) and np.any(d[m:] < d[m]))


def _lee_radok_model(t: np.ndarray, F: np.ndarray, valid: np.ndarray, c2: float) -> Any:
    def predict(m: Material) -> np.ndarray:
        return hereditary_integral(m, t, F)[valid] / c2
    return predict


def _ting_model(layer: Any, tip: Any, H: float, t: np.ndarray, d: np.ndarray, nu: float, tol: float, model: str,
                ok: np.ndarray) -> Any:
    from .ting import ting_force

    def predict(m: Material) -> np.ndarray:
        f = ting_force(layer, tip, H, m, t, d, nu=nu, tol=tol, model=model).force[ok]
        return np.where(np.isfinite(f), f, 0.0)  # a point Ting leaves at another material: no force
    return predict


@boundary
def fit_viscoelastic(layer: Any, punch: Any, H: Any, *, material: str = "sls", curves: Any = None,
                     oscillation: Any = None, delta0: Any = None, nu: Any = None, t0: Any = 1.0,
                     guess: dict | None = None, tol: float = DEFAULT_TOL, model: str = "auto", fit_H: Any = False,
                     contact_point: Any = False) -> ViscoFitResult:
    r"""Fit a viscoelastic material to force curves or to an oscillation on a layer of given thickness.

    Parameters
    ----------
    layer, punch, H, nu, tol, model
        As :func:`thinlayer.contact.hereditary.viscoelastic_force` (``model`` names the elastic law).
    material : str
        ``"sls"`` (``E0``, ``E_inf``, ``tau``) or ``"power-law"`` (``E0``, ``alpha``; ``t0`` given).
    curves : list of (times, depths, forces)
        Ramp-hold or approach-retract curves (one or several speeds), depth positive into the sample.
    oscillation : (omega, dynamic_stiffness)
        Angular frequencies and the complex ``K* = (Delta P/Delta delta)(w)`` around ``delta0``.
    delta0 : float
        The held depth of the oscillation.
    t0 : float
        The power law's reference time.
    guess : dict, optional
        Starting values by parameter name (``"H"`` too with ``fit_H``).
    fit_H : bool
        Fit the thickness too (``H`` is then the starting value); its standard error and its correlation with the
        moduli are in the result, and a flag says so when the data do not separate ``H`` from the modulus.
    contact_point : bool
        The second column of each curve is the **tip position** ``z`` (negative into the sample, as nanite's):
        ``delta = z0 - z``, with the contact point ``z0`` and a baseline force ``b0`` fitted per curve
        (``F = b0 + P(delta)``, ``P = 0`` before contact).  Named ``z0``, ``b0`` (one curve) or ``z0_1``, ``b0_1``,
        ``z0_2``, ... (several).

    Examples
    --------
    >>> import numpy as np
    >>> from thinlayer import BondedLayer, Punch, StandardLinearSolid, viscoelastic_force
    >>> t = np.linspace(0, 2, 401)
    >>> d = 0.1 * np.minimum(t / 0.5, 1.0)
    >>> L, tip = BondedLayer(0.5), Punch.paraboloid(10.0)
    >>> P = viscoelastic_force(L, tip, 1.0, StandardLinearSolid(3.0, 1.0, 0.3), t, d).force
    >>> res = fit_viscoelastic(L, tip, 1.0, curves=[(t, d, P)])
    >>> [round(res.values[k], 6) for k in ("E0", "E_inf", "tau")]
    [3.0, 1.0, 0.3]
    """
    kind = check_choice(material, tuple(MATERIALS), "material")
    layer, tip, nu_v, HH = check_setting(layer, punch, H, Prony(1.0), nu, tol, model)
    t0v = positive(t0, "t0")
    if (curves is None) == (oscillation is None):
        raise InputTypeError("give exactly one of curves=[(times, depths, forces), ...] and "
                             "oscillation=(omega, dynamic_stiffness) (with delta0)")
    free_H, cp = _bool(fit_H, "fit_H"), _bool(contact_point, "contact_point")
    keys = MATERIALS[kind] + (("H",) if free_H else ())
    if guess is not None and (not isinstance(guess, dict) or not set(guess) <= set(keys)
                              or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in
                                         guess.values())):
        raise InputTypeError(f"guess must be a dict of numbers with keys among {', '.join(keys)}")
    build = _sls if kind == "sls" else (lambda x: _power(x, t0v))
    c2 = 2.0 * (1.0 + nu_v)
    if free_H or cp:
        if oscillation is not None or curves is None:
            raise InputError("fit_H and contact_point need force curves (curves=[...]): an oscillation around one "
                             "depth cannot separate H from the modulus (K* = E*(w) S(delta0; H)/(2(1 + nu)))")
        if delta0 is not None:
            raise InputTypeError("delta0 belongs to an oscillation; leave it out with curves=")
        return _fit_free(layer, tip, HH, kind, build, _curves(curves), nu_v, float(tol), model, free_H, cp, guess)
    if curves is not None:
        if delta0 is not None:
            raise InputTypeError("delta0 belongs to an oscillation; leave it out with curves=")
        data = _curves(curves)
        prepared, excluded, law, n_ting, loading = [], 0, "", 0, []
        for t, d, p in data:
            el = viscoelastic_force(layer, tip, HH, Prony(1.0), t, d, nu=nu_v, tol=tol, model=model)
            F = np.where(el.valid, el.force * c2, 0.0)  # the unit-modulus law F(delta(t)) (E = 1)
            law = el.model
            loading.append((_lee_radok_model(t, F, el.valid, c2), el.valid, p))
            if kind == "sls" and _one_maximum(d) and not el.valid.all():
                from .ting import ting_force

                ok = ting_force(layer, tip, HH, Prony(1.0), t, d, nu=nu_v, tol=tol, model=model).valid
                if ok.sum() > el.valid.sum():  # Ting (T3)-(T5) answers the retraction too
                    n_ting += 1
                    prepared.append((_ting_model(layer, tip, HH, t, d, nu_v, tol, model, ok), ok, p))
                    excluded += int((~ok).sum())
                    continue
            prepared.append((_lee_radok_model(t, F, el.valid, c2), el.valid, p))
            excluded += int((~el.valid).sum())
        y = np.concatenate([p[v] for _, v, p in prepared])
        if y.size < len(MATERIALS[kind]) + 1:
            raise InputError(f"{y.size} valid points (growing contact) cannot fix {len(MATERIALS[kind])} parameters")

        def residual(x: np.ndarray) -> np.ndarray:
            m = build(x)[0]
            return np.concatenate([predict(m) for predict, _, _ in prepared]) - y

        y_load = np.concatenate([p[v] for _, v, p in loading])

        def first_residual(x: np.ndarray) -> np.ndarray:  # Lee-Radok on the loading: Ting's fit starts there
            m = build(x)[0]
            return np.concatenate([predict(m) for predict, _, _ in loading]) - y_load

        unit = [predict(Prony(1.0)) for predict, _, _ in prepared]  # the force at E = 1
        span = float(max(t[-1] - t[0] for t, *_ in data))
        scale = float(np.max(np.abs(y)) / max(max(float(np.max(u)) for u in unit), 1e-300))
        what = f"{len(data)} curve(s)" + (f" ({n_ting} with its retraction by Ting's method (T3)-(T5))" if n_ting
                                           else "")
    else:
        if not isinstance(oscillation, (tuple, list)) or len(oscillation) != 2:
            raise InputTypeError("oscillation must be a pair (omega, dynamic_stiffness)")
        if delta0 is None:
            raise InputTypeError("an oscillation needs delta0, the depth it oscillates around")
        try:
            w = np.array(oscillation[0], dtype=float).ravel()
            k = np.array(oscillation[1], dtype=complex).ravel()
        except (TypeError, ValueError):
            raise InputTypeError("oscillation: omega must be numbers, dynamic_stiffness (complex) numbers") from None
        if w.shape != k.shape or w.size < 2 or not (np.all(np.isfinite(w)) and np.all(np.isfinite(k))) \
                or np.any(w <= 0):
            raise InputError("oscillation: omega > 0 and dynamic_stiffness finite, of one length >= 2")
        st = contact_stiffness(layer, tip, HH, delta0, nu=nu_v, tol=tol, model=model)
        target = st.complex_modulus(k)
        y = np.concatenate([target.real, target.imag])

        def residual(x: np.ndarray) -> np.ndarray:
            e = build(x)[0].complex_modulus(w)
            return np.concatenate([e.real, e.imag]) - y

        excluded, law = 0, st.model
        span = float(2 * math.pi / np.median(w))
        scale = float(np.median(np.abs(target)))
        what = f"an oscillation at {w.size} frequencies around delta0 = {st.delta0:.6g} (layer S = " \
               f"{st.stiffness:.6g} mu)"
    from scipy.optimize import least_squares

    x0 = _start(kind, scale, span, guess)
    if curves is not None and n_ting and y_load.size > x0.size:  # ~10 cheap evaluations save as many Ting ones
        first = least_squares(first_residual, x0, method="lm", x_scale="jac", max_nfev=2000)
        if np.all(np.isfinite(first.x)):
            x0 = first.x
    sol = least_squares(residual, x0, method="lm", x_scale="jac", max_nfev=2000)
    if not np.all(np.isfinite(sol.x)) or not np.all(np.isfinite(sol.fun)):
        raise ComputationError("fit_viscoelastic(): the least-squares fit did not converge to finite values")
    mat, vals, jac = build(sol.x)
    n, p = y.size, sol.x.size
    dof = max(n - p, 1)
    s2 = float(sol.fun @ sol.fun) / dof
    try:
        cov_x = s2 * np.linalg.inv(sol.jac.T @ sol.jac)
    except np.linalg.LinAlgError:
        raise ComputationError("fit_viscoelastic(): the data cannot separate the parameters (singular Jacobian)") \
            from None
    cov = jac @ cov_x @ jac.T
    names = MATERIALS[kind]
    errs = np.sqrt(np.maximum(np.diag(cov), 0.0))
    cov.setflags(write=False)
    corr = correlation(cov)
    reason = f"{kind} fitted to {what} for H = {HH:.6g} (least squares, delta-method errors)"
    if excluded:
        reason += (f"; {excluded} points left out where the contact shrinks (Lee-Radok holds for a growing contact; "
                   "Ting's method is fitted for a standard linear solid only)")
    return ViscoFitResult(mat, dict(zip(names, map(float, vals))), dict(zip(names, map(float, errs))), cov,
                          "curves" if curves is not None else "oscillation", law,
                          float(math.sqrt(float(sol.fun @ sol.fun) / n)), int(n if curves is not None else n // 2),
                          excluded, HH, nu_v, reason, corr)


def correlation(cov: np.ndarray) -> np.ndarray:
    """The correlation matrix of a covariance (read-only; 0 where a variance is 0)."""
    sd = np.sqrt(np.maximum(np.diag(cov), 0.0))
    with np.errstate(all="ignore"):
        c = cov / np.outer(sd, sd)
    c = np.where(np.isfinite(c), c, 0.0)
    np.fill_diagonal(c, 1.0)
    c.setflags(write=False)
    return c



# =============================================================================================
# H and the contact point free (issue 27 item 4)
# =============================================================================================
#: |correlation| of H with a modulus above which H is flagged as not separated from it
MAX_H_CORRELATION = 0.9999
#: relative standard error of H above which H is flagged as not determined
MAX_H_RELATIVE_ERROR = 0.25
_STEP = 1.4901161193847656e-08  # sqrt(machine epsilon): the forward-difference step, relative to max(1, |x|)
#: a fitted H stays within this factor of its start (a bound: beyond it the data do not see the base, or the layer)
H_RANGE = 1e3


@dataclass(frozen=True)
class _Curve:
    t: np.ndarray
    a: np.ndarray  # depth, or tip position with the contact point
    p: np.ndarray
    m: int  # the deepest point
    start: int  # the first fitted point
    stop: int  # one past the last fitted point
    ting: bool  # the retraction fitted by Ting's method


def _prepare(data: list, kind: str, cp: bool) -> list[_Curve]:
    out = []
    for k, (t, a, p) in enumerate(data):
        depth_like = -a if cp else a
        m = int(np.argmax(depth_like))
        if cp and (m == 0 or not np.corrcoef(depth_like[: m + 1], p[: m + 1])[0, 1] > 0):
            raise InputError(f"curves[{k}]: with contact_point=True the second column is the tip position z, negative "
                             "into the sample (depth = z0 - z), and the force must rise as z falls; it does not here "
                             "(a depth axis? give -depth)")
        rising = bool(np.all(np.diff(depth_like[: m + 1]) >= 0))
        falls = bool(np.any(depth_like[m:] < depth_like[m]))
        if kind == "sls" and rising and falls:
            out.append(_Curve(t, a, p, m, 0, t.size, True))
            continue
        shrink = np.nonzero(depth_like < np.maximum.accumulate(depth_like))[0]
        stop = int(shrink[0]) if shrink.size else t.size
        start = 1 if (kind == "power-law" and not cp and a[0] > 0) else 0  # E(0+) = inf: a step's force is infinite
        out.append(_Curve(t, a, p, m, start, stop, False))
    return out


def _contact_start(c: _Curve) -> tuple[float, float, float]:
    """A robust start on the approach: baseline ``b0`` (median of the farthest fifth), noise, contact point ``z0``
    (the last approach point within ``max(5 sigma, 1 %)`` of the force range from the baseline).
    """
    z, p = c.a[: c.m + 1], c.p[: c.m + 1]
    far = p[: max(3, z.size // 5)]
    b0 = float(np.median(far))
    sigma = 1.4826 * float(np.median(np.abs(far - b0)))
    thr = b0 + max(5.0 * sigma, 0.01 * (float(p.max()) - b0))
    below = np.nonzero(p <= thr)[0]
    z0 = float(z[below[-1]]) if below.size else float(z[0])
    return b0, sigma, z0


def _fit_free(layer: Any, tip: Any, H0: float, kind: str, build: Any, data: list, nu: float, tol: float, model: str,
              fit_H: bool, cp: bool, guess: dict | None) -> ViscoFitResult:
    """:func:`fit_viscoelastic` with ``H`` and/or the contact point and baseline among the parameters."""
    from scipy.optimize import least_squares

    from .hereditary import force_curve_for
    from .ting import ting_force

    c2 = 2.0 * (1.0 + nu)
    cvs = _prepare(data, kind, cp)
    nmat, K = len(MATERIALS[kind]), len(cvs)
    law = [model]
    cache: dict = {}

    def unit_curve(H: float, d: np.ndarray) -> Any:
        c = cache.get(H)
        if c is None:
            c = force_curve_for(layer, tip, H, nu, tol, d, law[0])
            law[0] = c.model  # resolved once: every later call names it (a registry walk costs ~15 ms)
            if len(cache) > 16:
                cache.clear()
            cache[H] = c
        return c

    starts = [_contact_start(c) for c in cvs] if cp else []
    zs = [max(float(np.ptp(c.a[: c.m + 1])), 1e-300) for c in cvs]
    fs = max(float(np.ptp(np.concatenate([c.p for c in cvs]))), 1e-300)
    zc = [s[2] for s in starts]
    bc = [s[0] for s in starts]

    def unpack(x: np.ndarray) -> tuple[Material, float, list, list]:
        mat = build(x[:nmat])[0]
        j = nmat
        H = H0
        if fit_H:
            H = math.exp(x[j])
            j += 1
        if not cp:
            return mat, H, [None] * K, [0.0] * K
        return mat, H, [zc[k] + zs[k] * x[j + 2 * k] for k in range(K)], \
            [bc[k] + fs * x[j + 2 * k + 1] for k in range(K)]

    def depth(c: _Curve, z0: float | None) -> np.ndarray:
        return c.a if z0 is None else z0 - c.a

    def predict(x: np.ndarray, full: bool) -> list[np.ndarray]:
        mat, H, z0s, b0s = unpack(x)
        out = []
        for c, z0, b0 in zip(cvs, z0s, b0s):
            d = depth(c, z0)
            if c.ting and full:
                dd = np.where(np.arange(d.size) <= c.m, np.maximum(d, 0.0), d)  # no contact before z0
                unit_curve(H, dd)
                f = ting_force(layer, tip, H, mat, c.t, dd, nu=nu, tol=tol, model=law[0]).force
                out.append(np.where(np.isfinite(f), f, 0.0) + b0)
                continue
            n = c.m + 1 if c.ting else c.stop
            dd = np.maximum(d[:n], 0.0)
            F = unit_curve(H, dd).force(dd)
            P = hereditary_integral(mat, c.t[:n], np.where(np.isfinite(F), F, 0.0)) / c2
            out.append(P[c.start:] + b0)
        return out

    y_full = np.concatenate([c.p[c.start:(c.t.size if c.ting else c.stop)] for c in cvs])
    y_load = np.concatenate([c.p[c.start:(c.m + 1 if c.ting else c.stop)] for c in cvs])
    n_par = nmat + int(fit_H) + 2 * K * int(cp)
    if y_full.size < n_par + 1:
        raise InputError(f"{y_full.size} fitted points cannot fix {n_par} parameters")
    g = dict(guess or {})
    H_start = float(g.pop("H", H0))
    if not H_start > 0:
        raise InputError(f"guess H must be > 0, got {H_start!r}")
    tail = ([math.log(H_start)] if fit_H else []) + [0.0] * (2 * K * int(cp))
    unit_mat = Prony(1.0)
    x_unit = np.concatenate([np.zeros(nmat), tail])
    mat0, Hs, z0s, _ = unpack(x_unit)
    unit = [hereditary_integral(unit_mat, c.t[: c.m + 1], unit_curve(Hs, np.maximum(depth(c, z0)[: c.m + 1], 0.0))
                                .force(np.maximum(depth(c, z0)[: c.m + 1], 0.0))) / c2 for c, z0 in zip(cvs, z0s)]
    top = max(float(np.nanmax(u)) for u in unit)
    rise = max(float(np.max(c.p) - (bc[k] if cp else 0.0)) for k, c in enumerate(cvs))
    scale = rise / max(top, 1e-300)
    span = float(max(c.t[-1] - c.t[0] for c in cvs))
    x0 = np.concatenate([_start(kind, scale, span, g), tail])

    last: dict = {}

    def model_at(x: np.ndarray, full: bool) -> list[np.ndarray]:
        key = (full, x.tobytes())
        if key not in last:
            last.clear()  # the last point only: least_squares asks the Jacobian where it just asked the residual
            last[key] = predict(x, full)
        return last[key]

    def res_load(x: np.ndarray) -> np.ndarray:
        return np.concatenate(model_at(x, False)) - y_load

    def res_full(x: np.ndarray) -> np.ndarray:
        return np.concatenate(model_at(x, True)) - y_full

    # columns known without evaluating the model: the baselines' (1 on their curve's rows), and one modulus's: the force
    # is homogeneous of degree 1 in the moduli (Lee-Radok, and Ting's t1 depends on E(t)'s shape only), so with
    # x0 = log E_inf, x1 = log(E0 - E_inf): dP/dx0 + dP/dx1 = P; for the power law dP/d(log E0) = P
    analytic = {1 if kind == "sls" else 0} | ({nmat + int(fit_H) + 2 * k + 1 for k in range(K)} if cp else set())

    def jacobian(full: bool) -> Any:
        def jac(x: np.ndarray) -> np.ndarray:
            parts = model_at(x, full)
            f0 = np.concatenate(parts)
            b0s = unpack(x)[3]
            rows = np.concatenate([np.full(q.size, k) for k, q in enumerate(parts)])
            P = f0 - np.asarray(b0s, dtype=float)[rows]
            J = np.empty((f0.size, x.size))
            for i in range(x.size):
                if i in analytic:
                    continue
                h = _STEP * max(1.0, abs(float(x[i])))
                xh = x.copy()
                xh[i] += h
                J[:, i] = (np.concatenate(predict(xh, full)) - f0) / h
            if kind == "sls":
                J[:, 1] = P - J[:, 0]
            else:
                J[:, 0] = P
            for k in range(K if cp else 0):
                J[:, nmat + int(fit_H) + 2 * k + 1] = np.where(rows == k, fs, 0.0)
            return J
        return jac

    n_ting = sum(c.ting for c in cvs)
    opts: dict = dict(method="lm", x_scale="jac", max_nfev=4000, jac=jacobian(True))
    if fit_H:  # log H within H_RANGE of its start: data that do not see the base stop there (and are flagged)
        lo, hi = np.full(x0.size, -np.inf), np.full(x0.size, np.inf)
        lo[nmat], hi[nmat] = math.log(H_start / H_RANGE), math.log(H_start * H_RANGE)
        opts.update(method="trf", bounds=(lo, hi))
    sol = None
    if n_ting:  # Levenberg-Marquardt on the whole from the start (measured: 10 Jacobians on the benchmark's curve; from
        # a Lee-Radok fit of the approach alone, which one speed leaves loose, 35) while H stays in its range
        lm = least_squares(res_full, x0, method="lm", x_scale="jac", max_nfev=50 * (x0.size + 1), jac=jacobian(True))
        if lm.status > 0 and np.all(np.isfinite(lm.x)) and (not fit_H or lo[nmat] <= lm.x[nmat] <= hi[nmat]):
            sol = lm
        elif y_load.size > x0.size:  # else Lee-Radok on the loading first, then the bounded method
            first = least_squares(res_load, x0, **{**opts, "jac": jacobian(False)})
            if np.all(np.isfinite(first.x)):
                x0 = first.x
    if sol is None:
        sol = least_squares(res_full, x0, **opts)
    if not np.all(np.isfinite(sol.x)) or not np.all(np.isfinite(sol.fun)):
        raise ComputationError("fit_viscoelastic(): the least-squares fit did not converge to finite values")
    mat, vals_m, jac_m = build(sol.x[:nmat])
    _, H, z0s, b0s = unpack(sol.x)
    names = list(MATERIALS[kind])
    vals = list(vals_m)
    T = np.zeros((n_par, n_par))
    T[:nmat, :nmat] = jac_m
    j = nmat
    if fit_H:
        names.append("H")
        vals.append(H)
        T[j, j] = H
        j += 1
    for k in range(K if cp else 0):
        sfx = "" if K == 1 else f"_{k + 1}"
        names += [f"z0{sfx}", f"b0{sfx}"]
        vals += [z0s[k], b0s[k]]
        T[j, j], T[j + 1, j + 1] = zs[k], fs
        j += 2
    n = y_full.size
    s2 = float(sol.fun @ sol.fun) / max(n - n_par, 1)
    try:
        cov_x = s2 * np.linalg.inv(sol.jac.T @ sol.jac)
    except np.linalg.LinAlgError:
        raise ComputationError("fit_viscoelastic(): the data cannot separate the parameters (singular Jacobian)"
                               + ("; fix H (fit_H=False)" if fit_H else "")) from None
    cov = T @ cov_x @ T.T
    errs = np.sqrt(np.maximum(np.diag(cov), 0.0))
    cov.setflags(write=False)
    corr = correlation(cov)
    flags = []
    if fit_H:
        iH = names.index("H")
        mods = [names.index(m) for m in ("E0", "E_inf") if m in names]
        worst = max(mods, key=lambda i: abs(corr[iH, i]))
        rel = errs[iH] / H
        if abs(corr[iH, worst]) > MAX_H_CORRELATION or not rel < MAX_H_RELATIVE_ERROR:
            flags.append(f"H is not separated from the modulus by these data: corr(H, {names[worst]}) = "
                         f"{corr[iH, worst]:.5f}, H = {H:.4g} +- {errs[iH]:.2g} ("
                         + (f"{100 * rel:.0f} %" if rel < 10 else "> 1000 %") + "); fix H "
                         "(fit_H=False) or add curves at other speeds and depths")
    what = f"{K} curve(s)" + (f" ({n_ting} with its retraction by Ting's method (T3)-(T5))" if n_ting else "")
    excluded = sum(c.start + (0 if c.ting else c.t.size - c.stop) for c in cvs)
    reason = (f"{kind} fitted to {what}, H {'fitted' if fit_H else f'= {H:.6g} given'}"
              + (", the contact point and baseline of each curve fitted (depth = z0 - z)" if cp else "")
              + " (least squares, delta-method errors)")
    if fit_H:
        iH = names.index("H")
        reason += "; " + ", ".join(f"corr(H, {m}) = {corr[iH, names.index(m)]:.3f}" for m in ("E0", "E_inf")
                                   if m in names)
    if excluded:
        reason += (f"; {excluded} points left out where the contact shrinks (Lee-Radok holds for a growing contact; "
                   "Ting's method is fitted for a standard linear solid only)")
    return ViscoFitResult(mat, dict(zip(names, map(float, vals))), dict(zip(names, map(float, errs))), cov, "curves",
                          law[0], float(math.sqrt(float(sol.fun @ sol.fun) / n)), n, excluded, float(H), nu, reason,
                          corr, tuple(flags))
