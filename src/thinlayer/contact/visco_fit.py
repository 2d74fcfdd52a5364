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

    equation = "Lee-Radok (fitted)"

    def latex(self) -> str:
        body = r",\ ".join(rf"{_tex(k)} = {v:.6g} \pm {self.errors[k]:.2g}" for k, v in self.values.items())
        return body + r",\quad " + self.material.latex()

    def text_lines(self) -> list[str]:
        out = [f"ViscoFitResult ({self.kind}, {self.model} law, H = {self.H:.6g}, nu = {self.nu:.4g}): "
               f"{self.n_points} points" + (f", {self.n_excluded} left out" if self.n_excluded else "")]
        out += [f"  {k:<6} = {v:.8g} ± {self.errors[k]:.3g}" for k, v in self.values.items()]
        out.append(f"  residual rms {self.residual_rms:.3g}; {self.reason}")
        return out

    def __str__(self) -> str:
        return "\n".join(self.text_lines())

    def as_dict(self) -> dict:
        """Plain numbers for JSON."""
        return {"kind": self.kind, "model": self.model, "H": self.H, "nu": self.nu, "values": dict(self.values),
                "errors": dict(self.errors), "residual_rms": self.residual_rms, "n_points": self.n_points,
                "n_excluded": self.n_excluded, "reason": self.reason}


def _tex(name: str) -> str:
    return {"E0": "E_0", "E_inf": r"E_\infty", "tau": r"\tau", "alpha": r"\alpha"}[name]


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
                     guess: dict | None = None, tol: float = DEFAULT_TOL, model: str = "auto") -> ViscoFitResult:
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
        Starting values by parameter name.

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
    if guess is not None and (not isinstance(guess, dict) or not set(guess) <= set(MATERIALS[kind])
                              or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in
                                         guess.values())):
        raise InputTypeError(f"guess must be a dict of numbers with keys among {', '.join(MATERIALS[kind])}")
    build = _sls if kind == "sls" else (lambda x: _power(x, t0v))
    c2 = 2.0 * (1.0 + nu_v)
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
    reason = f"{kind} fitted to {what} for H = {HH:.6g} (least squares, delta-method errors)"
    if excluded:
        reason += (f"; {excluded} points left out where the contact shrinks (Lee-Radok holds for a growing contact; "
                   "Ting's method is fitted for a standard linear solid only)")
    return ViscoFitResult(mat, dict(zip(names, map(float, vals))), dict(zip(names, map(float, errs))), cov,
                          "curves" if curves is not None else "oscillation", law,
                          float(math.sqrt(float(sol.fun @ sol.fun) / n)), int(n if curves is not None else n // 2),
                          excluded, HH, nu_v, reason)
