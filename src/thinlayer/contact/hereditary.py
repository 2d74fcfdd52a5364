r"""Lee-Radok hereditary force law on the layer (issue 27 item 2, first slice): monotonically growing contact.

For a linear viscoelastic material with a **constant Poisson ratio** ``nu`` the shear relaxation modulus is
``G(t) = E(t)/(2 (1 + nu))`` and, while the contact size does not decrease (Lee & Radok 1960), the force is

.. math::  P(t) = \int_0^t G(t - s)\, \frac{d}{ds} F\big(\delta(s)\big)\, ds
           = \frac{1}{2 (1 + \nu)} \int_0^t E(t - s)\, \frac{d}{ds} F\big(\delta(s)\big)\, ds,

with ``F(delta)`` the layer's elastic force at unit **shear** modulus ``mu = 1`` (the model's
:class:`~thinlayer.contact.models.base.ForceCurve`).  The history before ``times[0]`` is at rest; a nonzero
``depths[0]`` is a step at ``times[0]``.  The contact radius follows the elastic law at the current depth.

The evaluators (:func:`hereditary_integral`) take ``F`` at the time nodes and interpolate it **linearly in time**;
for such ``F`` they are exact (to rounding):

* Prony series: each branch's internal variable ``q_i(t_n) = exp(-h_n/tau_i) q_i(t_{n-1}) + r_n tau_i
  (1 - exp(-h_n/tau_i))``, ``r_n`` the slope of ``F`` on step ``n``; evaluated in blocks of ``30 tau_i`` by
  cumulative sums (O(N) per history, vectorised);
* power law: product integration, ``int E(t_n - s) ds`` over each step in closed form; by FFT convolution on a
  uniform grid, else O(N^2) (refused beyond :data:`MAX_NONUNIFORM_POWER` steps before any work);
* Kelvin-Voigt: ``E F(t_n) + eta r_n`` (the impulse ``eta delta(t)`` as the rate over the step ending at ``t_n``:
  the left derivative of the piecewise-linear ``F``; for a smooth history, first order in the step).

Where the contact shrinks, Lee-Radok does not hold (Ting's method is needed: :func:`thinlayer.contact.ting.ting_force`,
which ``solve(material=Prony(...), history=...)`` uses for a depth history rising to one maximum): those times are
flagged and their force is NaN, as is every time after the first shrink.
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._checks import check_array_size, check_bounded, check_history, parse_nu, positive
from ..asymptotics.solution import DEFAULT_TOL, numeric_punch
from ..errors import InputError, InputTypeError, WorkLimitError, boundary
from ..layers.kernels import LayerKernel
from ..punch import Tip, is_polynomial_tip
from .materials import KelvinVoigt, Material, PowerLaw, Prony
from .models.base import MODEL_REGISTRY, ForceCurve
from .problem import Depth, Elastic, Frictionless, Problem

__all__ = ["MAX_NONUNIFORM_POWER", "MAX_STEPS", "ViscoelasticForce", "check_setting", "force_curve_for",
           "hereditary_integral", "inverse_hereditary", "viscoelastic_depth", "viscoelastic_force"]

#: the most time nodes of a history (measured: 1e6 nodes of a ramp-hold, sphere, 3-term Prony series, in 0.9 s
#: and 0.12 GB more memory at load 10.9 on 2 cores)
MAX_STEPS = 2_000_000
#: the most time nodes of a power-law history on a non-uniform grid (O(N^2): 5,000 nodes took 4 s at load 9.5)
MAX_NONUNIFORM_POWER = 5_000
_BLOCK = 30.0  # exp(30) ~ 1e13: the cumulative sums of a block stay far inside the double range


def _prony_branch(t: np.ndarray, b: np.ndarray, tau: float) -> np.ndarray:
    """``q_n = sum_{k <= n} exp(-(t_n - t_k)/tau) b_k``, exact, in blocks of ``30 tau`` (no overflow)."""
    x = (t - t[0]) / tau
    q = np.empty_like(b)
    s, carry, n = 0, 0.0, len(t)
    while s < n:
        e = max(int(np.searchsorted(x, x[s] + _BLOCK, side="right")), s + 1)
        dx = x[s:e] - x[s]
        acc = np.cumsum(np.exp(dx) * b[s:e]) + carry
        q[s:e] = np.exp(-dx) * acc
        if e < n:
            carry = q[e - 1] * math.exp(-(x[e] - x[e - 1]))
        s = e
    return q


def _power_weights(t: np.ndarray, alpha: float) -> np.ndarray | None:
    """Uniform grid: ``w_j = (j + 1)^beta - j^beta``, ``beta = 1 - alpha`` (stable for large j); else None."""
    h = np.diff(t)
    if h.size == 0 or np.ptp(h) > 1e-10 * h.mean():  # linspace rounding: ~1e-12
        return None
    beta = 1.0 - alpha
    j = np.arange(len(h), dtype=float)
    w = np.empty_like(j)
    w[0] = 1.0
    w[1:] = np.exp(beta * np.log(j[1:])) * np.expm1(beta * np.log1p(1.0 / j[1:]))
    return w


def _power_law(t: np.ndarray, F: np.ndarray, m: PowerLaw) -> np.ndarray:
    beta = 1.0 - m.alpha
    c = m.E0 * m.t0**m.alpha / beta
    r = np.diff(F) / np.diff(t)
    out = np.zeros_like(F)
    with np.errstate(all="ignore"):
        out += F[0] * m.relaxation(t - t[0])  # the step at t[0] (inf at t[0] itself when F[0] > 0)
    out[0] = np.inf if F[0] > 0 else 0.0
    if len(t) < 2:
        return out
    w = _power_weights(t, m.alpha)
    if w is not None:
        h = (t[-1] - t[0]) / (len(t) - 1)
        from scipy.signal import fftconvolve

        conv = fftconvolve(r, w)[: len(r)] if len(r) > 64 else np.convolve(r, w)[: len(r)]
        out[1:] += c * h**beta * conv
        # before the first change of F the integral is exactly F[0] E(t - t0): the FFT's round-off (~1e-17 of the
        # largest force, of either sign) is not left there, so pre-contact forces are 0, never -1e-17
        first = int(np.argmax(r != 0)) if (r != 0).any() else len(r)
        out[1:first + 1] = F[0] * m.relaxation(t[1:first + 1] - t[0]) if F[0] > 0 else 0.0
        return out
    if len(t) > MAX_NONUNIFORM_POWER:
        raise WorkLimitError(f"a power-law history on a non-uniform time grid costs O(N^2): at most "
                             f"{MAX_NONUNIFORM_POWER} nodes, got {len(t)}; use a uniform grid (FFT, any N)")
    for n0 in range(1, len(t), 512):  # rows n0..n1 of the lower triangle, 512 at a time
        n1 = min(n0 + 512, len(t))
        tn = t[n0:n1, None]
        A = np.maximum(tn - t[None, :-1], 0.0)
        B = np.maximum(tn - t[None, 1:], 0.0)
        with np.errstate(all="ignore"):
            W = np.where(B > 0, np.exp(beta * np.log(A)) * -np.expm1(beta * np.log(B / A)),
                         np.exp(beta * np.log(A)))
        W = np.where(A > 0, W, 0.0)
        out[n0:n1] += c * (W @ r)
    return out


def hereditary_integral(material: Material, times: Any, F: Any) -> np.ndarray:
    r"""``int_0^t E(t - s) d/ds F(s) ds`` at each time node, ``F`` linear in time between nodes (exact for it).

    ``F[0]`` is a step at ``times[0]`` (the history before is at rest).  Divide by ``2 (1 + nu)`` for the force
    at the shear relaxation modulus.  A step under a material whose ``E(0+)`` is infinite (power law,
    Kelvin-Voigt) gives ``inf`` at ``times[0]``.

    Examples
    --------
    A ramp ``F = t`` under ``E(t) = 1 + exp(-t)``: ``t + 1 - exp(-t)``.

    >>> import numpy as np
    >>> t = np.linspace(0, 2, 5)
    >>> bool(np.allclose(hereditary_integral(Prony(1.0, [(1.0, 1.0)]), t, t), t + 1 - np.exp(-t), atol=1e-15))
    True
    """
    t = np.asarray(times, dtype=float)
    f = np.asarray(F, dtype=float)
    if t.ndim != 1 or f.shape != t.shape or t.size == 0:
        raise InputError(f"times and F must be 1-d arrays of one length, got shapes {t.shape} and {f.shape}")
    if not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
        raise InputError("times must be finite and strictly increasing")
    evaluate = _EVALUATORS.get(type(material))
    if evaluate is None:
        raise InputTypeError(f"material must be Prony, StandardLinearSolid, KelvinVoigt or PowerLaw, got {material!r}")
    return evaluate(t, f, material)


def _kelvin_voigt(t: np.ndarray, f: np.ndarray, m: KelvinVoigt) -> np.ndarray:
    rate = np.concatenate([[np.inf if f[0] > 0 else 0.0], np.diff(f) / np.diff(t)])
    return m.E * f + m.eta * rate


def _prony(t: np.ndarray, f: np.ndarray, m: Prony) -> np.ndarray:
    out = m.E_inf * f
    h = np.diff(t)
    r = np.diff(f) / h
    for e, tau in m.terms:
        b = np.concatenate([[f[0]], r * tau * -np.expm1(-h / tau)])
        out = out + e * _prony_branch(t, b, tau)
    return out


#: each material's evaluator (a new material adds a row)
_EVALUATORS = {Prony: _prony, KelvinVoigt: _kelvin_voigt, PowerLaw: _power_law}


# =============================================================================================
# force control: the hereditary integral inverted by time stepping
# =============================================================================================
def _prony_inverse(t: np.ndarray, g: np.ndarray, m: Prony) -> np.ndarray:
    """``F`` with ``E_inf F_n + sum_i E_i q_i(t_n) = g_n`` (the recursion of :func:`_prony`, solved for ``F_n``)."""
    E = np.array([e for e, _ in m.terms])
    tau = np.array([x for _, x in m.terms])
    F = np.empty_like(g)
    F[0] = g[0] / m.instantaneous
    q = E * 0.0 + F[0]  # q_i(t_0) = F_0 (the step)
    h = np.diff(t)
    for n in range(1, len(t)):
        a = np.exp(-h[n - 1] / tau)
        gi = tau * -np.expm1(-h[n - 1] / tau) / h[n - 1]  # q_i gains r_n h gi
        qa = a * q
        # g_n = E_inf F_n + sum E_i (qa_i + (F_n - F_{n-1}) gi)
        F[n] = (g[n] - E @ qa + F[n - 1] * (E @ gi)) / (m.E_inf + E @ gi)
        q = qa + (F[n] - F[n - 1]) * gi
    return F


def _kelvin_voigt_inverse(t: np.ndarray, g: np.ndarray, m: KelvinVoigt) -> np.ndarray:
    """``E F_n + eta (F_n - F_{n-1})/h_n = g_n`` (``F_0 = 0``: the impulse takes a step in force without depth)."""
    F = np.zeros_like(g)
    h = np.diff(t)
    for n in range(1, len(t)):
        F[n] = (g[n] + m.eta * F[n - 1] / h[n - 1]) / (m.E + m.eta / h[n - 1])
    return F


def _power_inverse(t: np.ndarray, g: np.ndarray, m: PowerLaw) -> np.ndarray:
    """Product integration of :func:`_power_law` solved step by step for the slopes (``F_0 = 0``: E(0+) = inf)."""
    if len(t) > MAX_NONUNIFORM_POWER:
        raise WorkLimitError(f"a power-law force history is inverted in O(N^2): at most {MAX_NONUNIFORM_POWER} "
                             f"nodes, got {len(t)}; subsample the history")
    beta = 1.0 - m.alpha
    c = m.E0 * m.t0**m.alpha / beta
    r = np.zeros(len(t) - 1)
    F = np.zeros_like(g)
    for n in range(1, len(t)):
        A = t[n] - t[:n]  # t_n - t_{k-1}, k = 1..n
        B = t[n] - t[1:n + 1]  # t_n - t_k
        W = c * (A**beta - B**beta)
        r[n - 1] = (g[n] - W[:-1] @ r[: n - 1]) / W[-1]
        F[n] = F[n - 1] + r[n - 1] * (t[n] - t[n - 1])
    return F


_INVERSES = {Prony: _prony_inverse, KelvinVoigt: _kelvin_voigt_inverse, PowerLaw: _power_inverse}


def inverse_hereditary(material: Material, times: Any, G: Any) -> np.ndarray:
    r"""``F`` (linear in time between nodes) with ``int_0^t E(t - s) dF(s) = G(t)`` at every node: the exact inverse
    of :func:`hereditary_integral` on the same grid (time stepping; Prony O(N), power law O(N^2)).

    Under a material with infinite ``E(0+)`` (power law, Kelvin-Voigt) ``F[0] = 0``: a step in force needs no step
    in ``F``.

    >>> import numpy as np
    >>> m = Prony(1.0, [(2.0, 0.5)])
    >>> t = np.linspace(0.0, 2.0, 41)
    >>> F = inverse_hereditary(m, t, np.ones_like(t))        # creep under a unit step
    >>> bool(np.allclose(hereditary_integral(m, t, F), 1.0, rtol=1e-13))
    True
    """
    t = np.asarray(times, dtype=float)
    g = np.asarray(G, dtype=float)
    if t.ndim != 1 or g.shape != t.shape or t.size == 0:
        raise InputError(f"times and G must be 1-d arrays of one length, got shapes {t.shape} and {g.shape}")
    if not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0) or not np.all(np.isfinite(g)):
        raise InputError("times must be finite and strictly increasing, G finite")
    invert = _INVERSES.get(type(material))
    if invert is None:
        raise InputTypeError(f"material must be Prony, StandardLinearSolid, KelvinVoigt or PowerLaw, got {material!r}")
    return invert(t, g, material)


def _depths_for(curve: ForceCurve, F: np.ndarray, scale: float) -> np.ndarray:
    """The depths at which the unit-modulus law gives the forces ``F >= 0`` (NaN beyond the law's valid range)."""
    out = np.zeros_like(F)
    pos = F > 0
    if not pos.any():
        return out
    top = float(F[pos].max())
    hi = scale
    for _ in range(200):  # bracket the largest force (the law is increasing in the depth)
        fh = float(curve.force(np.array([hi]))[0])
        if not np.isfinite(fh) or fh >= top:
            break
        hi *= 2.0
    grid = np.geomspace(hi * 1e-9, hi, 4001)
    fg = curve.force(grid)
    ok = np.isfinite(fg) & (fg > 0)
    if ok.sum() < 2:
        out[pos] = np.nan
        return out
    lg, lf = np.log(grid[ok]), np.log(fg[ok])
    x = np.interp(np.log(F[pos]), lf, lg, left=np.nan, right=np.nan)
    for _ in range(3):  # Newton steps in log depth on log F(delta) = log F, the slope from the grid
        y = np.log(curve.force(np.exp(x)))
        slope = np.interp(x, lg, np.gradient(lf, lg))
        x = x - (y - np.log(F[pos])) / slope
    out[pos] = np.exp(x)
    return out


@boundary
def viscoelastic_depth(layer: LayerKernel, punch: Any, H: Any, material: Material, times: Any, forces: Any, *,
                       nu: Any = None, tol: float = DEFAULT_TOL, model: str = "auto") -> ViscoelasticForce:
    r"""The depth and contact radius against time for a **force** history (Lee-Radok inverted; contact must grow).

    ``2 (1 + nu) P(t) = int E(t - s) d/ds F(delta(s)) ds`` is solved for ``F`` by time stepping
    (:func:`inverse_hereditary`, exact for ``F`` linear in time between nodes), then ``delta = F^{-1}``.  Where
    ``F`` decreases the contact shrinks and Lee-Radok does not hold: flagged, NaN from there on.

    >>> import numpy as np
    >>> from thinlayer import BondedLayer, Punch, StandardLinearSolid
    >>> t = np.linspace(0, 1, 201)
    >>> out = viscoelastic_depth(BondedLayer(0.5), Punch.paraboloid(10.0), 1.0, StandardLinearSolid(3.0, 1.0, 0.2),
    ...                          t, np.full_like(t, 5.0))          # creep under a step force
    >>> bool(out.valid.all()), bool(np.all(np.diff(out.depths) > 0))
    (True, True)
    """
    layer, tip, nu_v, HH = check_setting(layer, punch, H, material, nu, tol, model)
    for name, v in (("times", times), ("forces", forces)):
        check_array_size(v, name, MAX_STEPS, "1e6 nodes take ~1 s and 0.12 GB; subsample the history")
    t, P = check_history(times, forces, "forces")
    if np.any(P < 0):
        raise InputError("forces must be >= 0 (compressive positive; a punch cannot pull without adhesion)")
    F = inverse_hereditary(material, t, 2.0 * (1.0 + nu_v) * P)
    scale = float(getattr(tip, "sphere_radius", None) or HH) * 1e-3
    probe = force_curve_for(layer, tip, HH, nu_v, float(tol), np.array([scale]), model)
    d = _depths_for(probe, np.maximum(F, 0.0), scale)
    c = probe.contact_radius(np.where(np.isfinite(d), d, 0.0))
    shrink = np.concatenate([[False], np.diff(F) < -1e-12 * np.maximum(np.abs(F[1:]), 1e-300)])
    after = np.logical_or.accumulate(shrink)
    bad_law = np.logical_or.accumulate(~np.isfinite(d) | ~np.isfinite(c))
    valid = ~(after | bad_law)
    reasons = []
    if after.any():
        reasons.append(f"the contact shrinks from t = {t[np.argmax(after)]:.6g} on (F(delta) decreases): Lee-Radok "
                       "holds only for a growing contact; Ting's method is needed (not for a force history in this "
                       "release)")
    if bad_law.any():
        reasons.append(f"the {probe.model} law has no depth within tol = {tol:.3g} for the force at t = "
                       f"{t[np.argmax(bad_law)]:.6g}; from there the history is unknown")
    depth = np.where(valid, d, np.nan)
    radius = np.where(valid, c, np.nan)
    for a in (t, P, depth, radius, valid):
        a.setflags(write=False)
    return ViscoelasticForce(t, depth, P, radius, valid, "; ".join(reasons) or "Lee-Radok: the contact grows",
                             probe.model, material, nu_v, HH, control="force", tol=float(tol))


# =============================================================================================
# the front door
# =============================================================================================
@dataclass(frozen=True, eq=False)
class ViscoelasticForce:
    r"""A Lee-Radok force history: ``force`` and ``contact_radius`` against ``times`` (arrays, read-only).

    ``valid[n]`` is False where Lee-Radok does not hold or the elastic law has no answer (the force is NaN
    there); ``reason`` says why, in one line.
    """

    times: np.ndarray
    depths: np.ndarray
    force: np.ndarray
    contact_radius: np.ndarray
    valid: np.ndarray
    reason: str
    model: str
    material: Material
    nu: float
    H: float
    #: ``"depth"`` (the depths were given, the force computed) or ``"force"`` (the reverse)
    control: str = "depth"
    tol: float = DEFAULT_TOL
    entry: Any = field(default=None, repr=False, compare=False)

    def latex(self) -> str:
        return (r"P(t) = \frac{1}{2(1+\nu)}\int_0^t E(t-s)\,\frac{d}{ds}F\big(\delta(s)\big)\,ds,\quad "
                + self.material.latex() + rf",\ \nu = {self.nu:.4g}\ \text{{({self.model})}}")

    def as_dict(self) -> dict:
        """Plain lists and numbers for JSON (NaN where not valid becomes None)."""
        def col(a: np.ndarray) -> list:
            return [float(x) if np.isfinite(x) else None for x in a]

        return {"control": self.control, "model": self.model, "nu": self.nu, "H": self.H,
                "material": self.material.latex(), "reason": self.reason, "times": col(self.times),
                "depths": col(self.depths), "force": col(self.force), "contact_radius": col(self.contact_radius),
                "valid": [bool(v) for v in self.valid]}

    def to_json(self) -> str:
        """The history as JSON (strict: no NaN)."""
        import json

        return json.dumps(self.as_dict(), allow_nan=False)

    def __repr__(self) -> str:
        n_bad = int((~self.valid).sum())
        return (f"<ViscoelasticForce: {self.model} law, {len(self.times)} times"
                + (f", {n_bad} NOT VALID>" if n_bad else ">"))

    def __str__(self) -> str:
        n_bad = int((~self.valid).sum())
        top = (f"force up to {np.nanmax(self.force, initial=0.0):.6g}" if self.control == "depth" else
               f"depth up to {np.nanmax(np.where(self.valid, self.depths, np.nan), initial=0.0):.6g} (force given)")
        return (f"ViscoelasticForce ({self.model} law, {len(self.times)} times, nu = {self.nu:.4g}, H = {self.H:.6g}): "
                + top
                + (f"; {n_bad} times NOT VALID: {self.reason}" if n_bad else ""))


def force_curve_for(layer: LayerKernel, tip: Any, H: float, nu: float, tol: float, depths: np.ndarray,
                    model: str = "auto") -> ForceCurve:
    """The unit-modulus force curve of the registry's first model that gives one for this layer and tip.

    ``model="auto"``: by preference, the first curve valid at 64 of the history's depths (quantiles, with the least
    and the largest; else the one valid at most of them); a model name: that model's curve.  The caller flags
    every depth where the chosen curve is not valid.
    """
    problem = Problem(layer, tip, Elastic(1.0, nu), Frictionless(), Depth(1.0), H, tol)
    pos = np.unique(depths[depths > 0])
    if pos.size > 64:  # the choice is made on 64 depths (quantiles, the least and the largest among them)
        pos = pos[np.unique(np.linspace(0, pos.size - 1, 64).round().astype(int))]
    best, best_ok = None, -1
    for entry in MODEL_REGISTRY:
        if model != "auto" and entry.name != model:
            continue
        if entry.refuses(problem) is not None or entry.applies(problem) is not None:
            continue
        try:
            curve = entry.force_curve(problem)
        except (ValueError, ArithmeticError):
            continue
        if curve is None:
            continue
        ok = int(curve.valid(pos).sum())
        if ok == pos.size:
            return curve
        if ok > best_ok:
            best, best_ok = curve, ok
    if best is None:
        raise InputError(f"no model gives a unit-modulus force curve for this layer and tip (model={model!r}); "
                         "viscoelastic_force() covers the tips with a vectorised elastic law (sphere, flat punch, "
                         "polynomial punches on thin layers)")
    return best


def check_setting(layer: Any, punch: Any, H: Any, material: Any, nu: Any, tol: Any,
                  model: Any) -> tuple[LayerKernel, Any, float, float]:
    """``(layer, tip, nu, H)`` checked for a viscoelastic answer (one-line refusals naming the input)."""
    if not isinstance(layer, LayerKernel) or not layer.on_rigid_base or not layer.has_thickness:
        raise InputTypeError(f"layer must be BondedLayer(nu) or FrictionlessLayer(nu), got {layer!r}")
    if not isinstance(material, Material):
        raise InputTypeError(f"material must be Prony(...), StandardLinearSolid(...), KelvinVoigt(...) or "
                             f"PowerLaw(...), got {material!r}")
    nu_v = float(parse_nu(layer.poisson_ratio(nu), floats="float", upper_closed=True, symbols=False,
                          example="0.3, '3/10' or 0.5"))
    HH = positive(H, "H")
    if isinstance(tol, bool) or not isinstance(tol, numbers.Real) or not tol > 0:
        raise InputError(f"tol must be a positive number (the elastic law's largest relative error), got {tol!r}")
    names = ("auto", *dict.fromkeys(m.name for m in MODEL_REGISTRY if m.solves and not m.adhesive
                                    and not getattr(m, "viscoelastic", False)))
    if not isinstance(model, str) or model not in names:
        raise InputError(f"model must be one of {', '.join(names)}; got {model!r}")
    if isinstance(punch, Tip) and not is_polynomial_tip(punch):
        tip = punch
    else:
        tip = numeric_punch(punch, {})
    if layer.numeric_nu is None or layer.incompressible_at(nu_v):
        layer = layer.with_nu(nu_v)
    return layer, tip, nu_v, HH


@boundary
def viscoelastic_force(layer: LayerKernel, punch: Any, H: Any, material: Material, times: Any, depths: Any, *,
                       nu: Any = None, tol: float = DEFAULT_TOL, model: str = "auto") -> ViscoelasticForce:
    r"""The force and contact radius against time for a depth history (Lee-Radok; contact must not shrink).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` or ``FrictionlessLayer(nu)`` on its rigid base.
    punch : Tip
        ``Punch.paraboloid(R)``, ``Punch.flat(a)`` or another tip with a vectorised elastic law.
    H : float
        Layer thickness.
    material : Prony, StandardLinearSolid, KelvinVoigt or PowerLaw
        Young's relaxation modulus ``E(t)``; ``nu`` is constant in time.
    times, depths : array_like
        The depth history at strictly increasing times (linear in time between nodes; at rest before
        ``times[0]``).
    nu, tol, model
        The constant Poisson ratio; the elastic law's tolerance and model (``"auto"``: the registry's first force
        curve valid over the history).

    Examples
    --------
    A sphere ramped into a thin bonded layer of a standard linear solid:

    >>> import numpy as np
    >>> from thinlayer import BondedLayer, Punch, StandardLinearSolid, viscoelastic_force
    >>> t = np.linspace(0, 1, 1001)
    >>> out = viscoelastic_force(BondedLayer(0.5), Punch.paraboloid(10.0), 1.0, StandardLinearSolid(3.0, 1.0, 0.2),
    ...                          t, 0.05 * t)
    >>> bool(out.valid.all()), out.model
    (True, 'any-thickness')
    """
    layer, tip, nu_v, HH = check_setting(layer, punch, H, material, nu, tol, model)
    for name, v in (("times", times), ("depths", depths)):
        check_array_size(v, name, MAX_STEPS, "1e6 nodes take ~1 s and 0.12 GB; subsample the history")
        if not isinstance(v, (list, tuple, np.ndarray)) and hasattr(v, "__len__"):  # a range: counted too
            check_bounded(len(v), f"the number of values of {name}", MAX_STEPS,
                          "1e6 nodes take ~1 s and 0.12 GB; subsample the history")
    t, d = check_history(times, depths, "depths")  # copies: the result's arrays are made read-only
    curve = force_curve_for(layer, tip, HH, nu_v, float(tol), d, model)
    u, inv = np.unique(d, return_inverse=True)  # each depth once (a hold repeats one depth)
    F = curve.force(u)[inv]
    c = curve.contact_radius(u)[inv]
    bad_law = ~np.isfinite(F)
    P = hereditary_integral(material, t, np.where(bad_law, 0.0, F)) / (2.0 * (1.0 + nu_v))
    # Lee-Radok holds while the contact grows: from the first shrink on, Ting's method is needed
    cmax = np.maximum.accumulate(np.where(np.isfinite(c), c, 0.0))
    shrink = np.isfinite(c) & (c < cmax * (1.0 - 1e-12))
    after = np.logical_or.accumulate(shrink)
    tension = P < 0  # a fixed-size contact (flat punch) pulling: the punch lifts off
    infinite = ~np.isfinite(P)
    invalid_law = np.logical_or.accumulate(bad_law)
    valid = ~(after | tension | infinite | invalid_law)
    reasons = []
    if after.any():
        reasons.append(f"the contact shrinks from t = {t[np.argmax(after)]:.6g} on: Lee-Radok holds only for a "
                       "growing contact; Ting's method is needed (solve(material=Prony(...), history=(t, depths)) uses "
                       "it for a depth rising to one maximum; not for a power law or Kelvin-Voigt in this release)")
    if tension.any():
        reasons.append(f"the force would be negative (the punch lifts off) from t = {t[np.argmax(tension)]:.6g}")
    if infinite.any():
        reasons.append(f"a step in depth at t = {t[np.argmax(infinite)]:.6g} under a material with infinite E(0+) "
                       "gives an infinite force; start the history at rest (depths[0] = 0)")
    if invalid_law.any():
        reasons.append(f"the {curve.model} law's estimate exceeds tol = {tol:.3g} (or it has no answer) at depth "
                       f"{d[np.argmax(bad_law)]:.6g} (t = {t[np.argmax(bad_law)]:.6g}); from there the history is "
                       "unknown")
    force = np.where(valid, P, np.nan)
    radius = np.where(valid, c, np.nan)
    for a in (t, d, force, radius, valid):
        a.setflags(write=False)
    return ViscoelasticForce(t, d, force, radius, valid, "; ".join(reasons) or "Lee-Radok: the contact grows",
                             curve.model, material, nu_v, HH, tol=float(tol))
