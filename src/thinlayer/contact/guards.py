r"""Guards a user can trust (issue 25 item 4): the sign of the depth axis, the half-space, and the regime flags.

* **Sign convention.**  thinlayer's depth ``delta`` is positive into the sample and the force grows with it.  AFM
  software records the *tip position*, negative into the sample (nanite's ``valid_axes_x = ["tip position"]``,
  afmformats' ``"tip position"`` column): passed unflipped, a fit returns nonsense with a tiny standard error
  (issue 25: E = 1.2e-17 +- 2.5e-5 Pa).  :func:`oriented_depths` refuses depths that are all ``<= 0`` or whose force
  falls as the depth grows (a negative correlation of force with depth), in one line naming the convention, and
  flips them only when asked (``depth_sign=-1``, CLI ``--depth-sign -1``).
* **The half-space.**  ``H=None`` or ``H=inf`` means the half-space: :func:`half_space` says so.
* **Regime flags** (:func:`regime_flags`), reported in the result and the CLI output, never silently:

  - ``delta/H > SMALL_STRAIN`` (0.1): the nominal strain under the tip of a thin layer is ``delta/H``; linear
    elasticity is a small-strain theory, and a neo-Hookean solid in uniaxial compression at nominal strain ``e``
    carries ``mu (lambda - lambda^-2) = 3 mu e (1 + e + O(e^2))`` (``lambda = 1 - e``), i.e. a stress ``e``
    above the linear law's: 10 % at ``delta/H = 0.1``.
  - ``delta/R > SPHERE_RATIO`` (0.1) for the paraboloid: the force of the exact sphere (Sneddon 1965, (6.8)-(6.9)
    for the half-space) is ``P_Hertz (1 - delta/(10 R) + O((delta/R)^2))`` (measured by mpmath in
    ``tests/afm/test_guards.py``), so the paraboloid's E differs from the sphere's by 1 % at ``delta/R = 0.1``.
  - a substrate not much stiffer than the layer (:func:`substrate_flags`, when the substrate's modulus is given):
    every law of thinlayer takes the base as rigid.  To first order the layer passes the punch's force P to the
    substrate over about the contact disc (radius a); an elastic half-space of plane-strain modulus ``E*_s`` under a
    load P on that disc sinks by at most the rigid flat punch's ``P/(2 E*_s a)`` (Boussinesq; a load spread over
    the disc sinks less on average, and a thick layer spreads it wider still), while the layer on a rigid base
    takes ``P = 2 E*_l a kappa(a/H) w0`` (F.1).  The substrate's share of the indentation, the relative error of
    the force at a given depth, is therefore at most about ``kappa(a/H) E*_l/E*_s`` (:func:`substrate_estimate`):
    close to it for a thin layer, an overestimate for a thick one.  Flagged beyond :data:`SUBSTRATE_ERROR` (1 %).
    This is a first-order bound from the engine's own flat-punch stiffness, not measured against a direct solver
    (thinlayer has no elastic-base kernel).
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from .._checks import InputError

__all__ = ["SIGN_CONVENTION", "SMALL_STRAIN", "SPHERE_RATIO", "SUBSTRATE_ERROR", "half_space", "oriented_depths",
           "fit_substrate_flags", "regime_flags", "substrate_estimate", "substrate_flags"]

#: the largest depth over thickness taken as small strain (module docstring)
SMALL_STRAIN = 0.1
#: the largest depth over sphere radius where the paraboloid stands for the sphere within 1 % in force
SPHERE_RATIO = 0.1
#: the largest relative error of the force from the substrate's compliance taken without a flag (module docstring)
SUBSTRATE_ERROR = 0.01
#: one sentence: thinlayer's depth axis against the AFM tip position
SIGN_CONVENTION = ("thinlayer's depth is positive into the sample and the force grows with it; an AFM tip position "
                   "(nanite, afmformats) is negative into the sample: flip it with depth_sign=-1 (CLI --depth-sign "
                   "-1)")


def half_space(H: Any) -> bool:
    """Whether ``H`` asks for the half-space: ``None`` or ``+inf``."""
    return H is None or (isinstance(H, (int, float)) and not isinstance(H, bool) and math.isinf(H) and H > 0)


def oriented_depths(d: np.ndarray, f: np.ndarray, depth_sign: Any = 1, who: str = "fit()") -> np.ndarray:
    """``depth_sign * d``, refused in one line when the depths are all ``<= 0`` or the force falls as they grow.

    Raises
    ------
    InputError
        Naming the sign convention (:data:`SIGN_CONVENTION`).
    """
    if isinstance(depth_sign, bool) or depth_sign not in (1, -1):
        raise InputError(f"depth_sign must be 1 (depth positive into the sample) or -1 (a tip position, negative "
                         f"into the sample), got {depth_sign!r}")
    dd = d * float(depth_sign)
    flipped = " after depth_sign=-1" if depth_sign == -1 else ""
    if not np.any(dd > 0):
        raise InputError(f"{who}: no positive depth in the data{flipped}: {SIGN_CONVENTION}")
    if dd.size > 2 and np.ptp(dd) > 0 and np.ptp(f) > 0:
        r = float(np.corrcoef(dd, f)[0, 1])
        if r < 0:
            raise InputError(f"{who}: the force falls as the depth grows{flipped} (correlation {r:.2f}): "
                             f"{SIGN_CONVENTION}")
    return dd


def regime_flags(depth_max: float, H: float, R: float | None) -> tuple[str, ...]:
    """One line per regime limit the data pass: ``delta/H`` beyond :data:`SMALL_STRAIN`, ``delta/R`` beyond
    :data:`SPHERE_RATIO` (``R``: the paraboloid's radius, None for another tip).
    """
    out = []
    if math.isfinite(H) and depth_max / H > SMALL_STRAIN:
        out.append(f"delta/H = {depth_max / H:.3g} > {SMALL_STRAIN:g}: beyond small strain (nominal strain "
                   f"{100 * depth_max / H:.3g} % under the tip; a linear law's stress is off by about as much)")
    if R is not None and math.isfinite(R) and depth_max / R > SPHERE_RATIO:
        out.append(f"delta/R = {depth_max / R:.3g} > {SPHERE_RATIO:g}: the paraboloid departs from a real sphere "
                   f"(force {100 * depth_max / (10 * R):.2g} % higher, Sneddon 1965)")
    return tuple(out)


def substrate_estimate(kappa: float, E_layer: float, nu_layer: float, E_substrate: float,
                       nu_substrate: float = 0.0) -> float:
    """``kappa E*_layer/E*_substrate`` (``E* = E/(1 - nu^2)``): the first-order relative error of the force from a
    substrate taken as rigid (module docstring; ``nu_substrate = 0``, the default, gives the largest value).
    """
    return kappa * (E_layer / (1.0 - nu_layer * nu_layer)) / (E_substrate / (1.0 - nu_substrate * nu_substrate))


def substrate_flags(layer: Any, a_over_H: float, E_layer: float, substrate_E: Any,
                    substrate_nu: Any = 0.0) -> tuple[str, ...]:
    """One line when a substrate of Young's modulus ``substrate_E`` (Poisson ratio ``substrate_nu``) changes the force
    by more than :data:`SUBSTRATE_ERROR` (:func:`substrate_estimate` with ``kappa(a/H)`` of the flat punch (F.1) on
    ``layer``); nothing when ``substrate_E`` is None or the layer is a half-space (``a/H = 0``).

    Raises
    ------
    InputError
        One line: ``substrate_E`` not a positive finite number, ``substrate_nu`` outside ``[-1, 1/2]``.
    """
    if substrate_E is None:
        return ()
    Es, nus = _modulus(substrate_E, "substrate_E"), _modulus(substrate_nu, "substrate_nu", poisson=True)
    if not (math.isfinite(a_over_H) and a_over_H > 0):
        return ()
    from .flat_punch import flat_punch_stiffness

    kappa = float(flat_punch_stiffness(layer, min(float(a_over_H), 200.0), "auto"))
    nu = float(layer.numeric_nu) if layer.numeric_nu is not None else 0.5
    est = substrate_estimate(kappa, float(E_layer), nu, Es, nus)
    if est <= SUBSTRATE_ERROR:
        return ()
    return (f"substrate E = {Es:.3g} vs layer E = {float(E_layer):.3g}: the base's compliance changes the force by "
            f"kappa(a/H = {a_over_H:.3g}) E*_layer/E*_substrate = {est:.2g} > {SUBSTRATE_ERROR:g} (first order); "
            f"the law takes the base as rigid",)


def fit_substrate_flags(base: str, nu: float, R: float, chi_max: float, E: float, substrate_E: Any,
                        substrate_nu: Any = 0.0) -> tuple[str, ...]:
    """:func:`substrate_flags` of a fit (:func:`thinlayer.fit`, :func:`thinlayer.fit_curve`) at its deepest point: the
    layer of its base and nu, ``a/H`` the rigid overlap radius ``sqrt(2 R delta_max)/H = sqrt(2) chi_max`` for the
    paraboloid (``R`` a number), the fit's ``(c/H)_max`` for another tip (``R`` nan).
    """
    from ..layers.kernels import BondedLayer, FrictionlessLayer

    layer = FrictionlessLayer(nu) if base == "frictionless" else BondedLayer(nu)
    a_over_H = chi_max if math.isnan(R) else math.sqrt(2.0) * chi_max
    return substrate_flags(layer, a_over_H if math.isfinite(a_over_H) else 0.0, E, substrate_E, substrate_nu)


def _modulus(value: Any, name: str, poisson: bool = False) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        v = math.nan
    if isinstance(value, bool) or not math.isfinite(v) or (v < -1.0 or v > 0.5 if poisson else v <= 0.0):
        valid = "a number in [-1, 1/2]" if poisson else "a positive finite number (Pa, the units of E)"
        raise InputError(f"{name} must be {valid}, got {str(value)[:60]!r}")
    return v
