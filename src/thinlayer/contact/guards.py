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
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from .._checks import InputError

__all__ = ["SIGN_CONVENTION", "SMALL_STRAIN", "SPHERE_RATIO", "half_space", "oriented_depths", "regime_flags"]

#: the largest depth over thickness taken as small strain (module docstring)
SMALL_STRAIN = 0.1
#: the largest depth over sphere radius where the paraboloid stands for the sphere within 1 % in force
SPHERE_RATIO = 0.1
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
