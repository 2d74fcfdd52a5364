r"""The force curves of the tips' any-thickness tables (issue 25 item 1): the cone (T.9) and the regular pyramids
(T.11)-(T.13) at every ``chi`` their tables cover, as unit-modulus :class:`~.base.ForceCurve` objects for
:func:`thinlayer.fit` (``model="any-thickness"``) and every reader of the registry's curves.

Both tips are self-similar: at ``mu = 1`` (``vartheta = 1/(1 - nu)``)

* the cone (half-angle ``alpha``, ``t = tan(alpha)``): ``P = (4/pi) t delta^2 Pi(chi)/(1 - nu)``,
  ``c = (2/pi) t delta Gamma(chi)``, ``chi = c_0/H = (2/pi) t delta/H``
  (:func:`thinlayer.contact.any_thickness_tips.cone_law`: bonded ``0.3 <= nu <= 1/2`` or frictionless,
  ``chi <= 29``);
* the regular pyramid (3 or 4 sides, face angle ``alpha``): ``P = K t delta^2 Pi(chi)/(1 - nu)`` (K of (T.13)),
  ``chi = delta t/H`` (:func:`thinlayer.contact.any_thickness_pyramids.pyramid_law`: the same layers, ``chi <= 10``;
  the contact area is the level set's, ``2 n tan(pi/n) (delta t)^2/2`` for ``n`` sides, to the table's accuracy the
  force's own area being unknown there: the curve gives the level set's, flagged by no estimate of its own).

The estimate of a point is the law's own (the table's, measured against the direct solvers).  Slopes for a fit's
Jacobian: ``d log P/d log delta = 2 + L``, ``d log P/d log H = -L``, ``L = d log Pi/d log chi`` by a central
difference of ``log Pi`` in ``log chi`` (step 1e-5: error ~1e-10, far below any fit's noise).  Beyond the table's
``chi`` (the thin layer) the curve continues ``Pi`` as the power law of its last slope with an infinite estimate, so
a fit that wanders there (a free ``H``) keeps going and its result is marked not valid; ``solve()``'s walk and every
reader with a finite ``tol`` see NaN there (:class:`~.base.ForceCurve`).
"""
from __future__ import annotations

import math
from functools import lru_cache
from typing import Any

import numpy as np

from .base import ForceCurve

__all__ = ["cone_curve", "pyramid_curve", "tip_table_curve"]

#: the step in log chi of the slope's central difference
STEP = 1e-5


def _extended(ratios: Any, estimate: Any, chi_max: float):
    """``(Pi(chi), est(chi), L(chi))`` on arrays, continued beyond ``chi_max`` as a power law with est = inf."""

    def slope_at(chi: np.ndarray) -> np.ndarray:
        hi = np.minimum(chi * math.exp(STEP), chi_max)
        lo = chi * math.exp(-STEP)
        return (np.log(ratios(hi)) - np.log(ratios(lo))) / np.log(hi / lo)

    top = np.array([chi_max])
    L_top = float(slope_at(top)[0])
    Pi_top = float(ratios(top)[0])

    def parts(chi: np.ndarray, slopes: bool = False):
        chi = np.asarray(chi, dtype=float)
        inside = chi <= chi_max
        cin = np.where(inside, chi, chi_max)
        Pi = np.asarray(ratios(cin), dtype=float)
        est = np.asarray(estimate(cin), dtype=float)
        if not inside.all():
            Pi = np.where(inside, Pi, Pi_top * (chi / chi_max) ** L_top)
            est = np.where(inside, est, math.inf)
        if not slopes:
            return Pi, est, None
        return Pi, est, np.where(inside, slope_at(cin), L_top)

    return parts


@lru_cache(maxsize=256)
def cone_curve(tan_a: float, H: float, nu: float, base: str, tol: float, name: str = "any-thickness") -> ForceCurve:
    """The cone's unit-modulus force curve from its any-thickness law (module docstring; cached per setting)."""
    from ..any_thickness_tips import cone_law

    law = cone_law(nu, base)
    parts = _extended(lambda c: law.ratios(c)[0], lambda c: law.error_estimate(c)[0], law.chi_max)
    gamma = _extended(lambda c: law.ratios(c)[1], lambda c: law.error_estimate(c)[1], law.chi_max)
    K = 4.0 / math.pi * tan_a / (1.0 - nu)
    k = 2.0 / math.pi * tan_a

    def force(d):
        chi = k * d / H
        Pi, eP, _ = parts(chi)
        G, ec, _ = gamma(chi)
        c = k * d * G
        return K * d * d * Pi, math.pi * c * c, np.maximum(eP, 2.0 * ec)

    def radius(d):
        return k * d * gamma(k * d / H)[0]

    def slopes(d):
        L = parts(k * d / H, slopes=True)[2]
        return 2.0 + L, -L

    return ForceCurve(name, tol, force, radius_law=radius, slopes=slopes)


@lru_cache(maxsize=256)
def pyramid_curve(sides: int, tan_a: float, H: float, nu: float, base: str, tol: float,
                  name: str = "any-thickness") -> ForceCurve:
    """The regular pyramid's unit-modulus force curve from its any-thickness law (module docstring)."""
    from ..any_thickness_pyramids import pyramid_law

    law = pyramid_law(sides, nu, base)
    parts = _extended(law.ratios, law.error_estimate, law.chi_max)
    K = law.K * tan_a / (1.0 - nu)
    area = sides * math.tan(math.pi / sides) * tan_a * tan_a  # the level set: n r^2 tan(pi/n), r = delta t

    def force(d):
        Pi, est, _ = parts(tan_a * d / H)
        return K * d * d * Pi, area * d * d, est

    def slopes(d):
        L = parts(tan_a * d / H, slopes=True)[2]
        return 2.0 + L, -L

    return ForceCurve(name, tol, force, slopes=slopes)


def tip_table_curve(tip: Any, H: float, nu: float, base: str, tol: float,
                    name: str = "any-thickness") -> ForceCurve | None:
    """The table curve of a cone or a regular pyramid with numbers where its table covers ``(nu, base)``; else None."""
    from ..any_thickness_pyramids import NU_MIN as PYR_NU_MIN
    from ..any_thickness_tips import NU_MIN, cone_tangent

    if not (0 < H < math.inf) or not getattr(tip, "is_numeric", False):
        return None
    if getattr(tip, "kind", None) == "pyramid":
        if base == "bonded" and not PYR_NU_MIN <= nu <= 0.5:
            return None
        return pyramid_curve(int(tip.sides), math.tan(float(tip.alpha)), float(H), float(nu), base, float(tol), name)
    if base == "bonded" and not NU_MIN <= nu <= 0.5:
        return None
    tan_a = cone_tangent(tip)
    if tan_a is None:
        return None
    return cone_curve(tan_a, float(H), float(nu), base, float(tol), name)
