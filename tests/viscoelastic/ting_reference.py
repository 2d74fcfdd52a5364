"""The half-space reference of the viscoelastic tests: the Hertz sphere on a standard linear solid under a triangular
depth history, Lee-Radok while loading and Ting while unloading, by mpmath quadrature and root finding from the
construction (T4), (T5) of contact/ting.py (30 digits; neither the solver nor ting_force is used).
"""
from __future__ import annotations

from functools import lru_cache

import mpmath

E0, EINF, TAU, V, TM, RT, NU = 3.0, 1.0, 0.2, 0.02, 0.5, 1.0, 0.3


def _ting_condition(t1, t):
    """``g(t1, t) = int_{t1}^t E(t - s) delta'(s) ds`` for ``t1 <= TM < t`` by mpmath quadrature (T4)."""
    return mpmath.quad(lambda s: (EINF + (E0 - EINF) * mpmath.exp(-(t - s) / TAU)) * (V if s <= TM else -V),
                       [t1, TM, t])


@lru_cache(maxsize=None)
def hertz_ting(t: float) -> tuple[float, float]:
    """``(P, a)`` of the Hertz sphere on the SLS half-space, delta = V min(t, 2 TM - t), by mpmath (T4), (T5).

    ``P = int_0^{t1} vartheta(t - s) d/ds P_H(delta(s)) ds``, ``P_H = (8/3) R^(1/2) delta^(3/2)`` at unit vartheta
    (Hertz: ``P = 4/3 E* R^(1/2) delta^(3/2)``, ``E* = 2 vartheta``) by mpmath quadrature; ``t1 = t`` while loading,
    else the root of ``int_{t1}^t E(t - s) delta'(s) ds = 0`` (mpmath's quadrature and root, 25 digits);
    ``a = (R delta(t1))^(1/2)``.  The contact is lost when ``g(0, t) <= 0``.
    """
    mpmath.mp.dps = 25
    tt = mpmath.mpf(t)
    if tt <= TM:
        t1 = tt
    else:
        g = _ting_condition
        if g(mpmath.mpf(0), tt) <= 0:
            return 0.0, 0.0
        t1 = mpmath.findroot(lambda x: g(x, tt), (mpmath.mpf(0), mpmath.mpf(TM)), solver="illinois", tol=1e-40)
    vt = 1 / (2 * (1 - mpmath.mpf(NU) ** 2))
    P = mpmath.quad(lambda s: vt * (EINF + (E0 - EINF) * mpmath.exp(-(tt - s) / TAU)) * 4 * mpmath.sqrt(RT * V * s)
                    * V, [0, t1])
    return float(P), float(mpmath.sqrt(RT * V * t1))


