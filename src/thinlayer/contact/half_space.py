r"""The half-space (``H = None`` or ``inf`` in :func:`thinlayer.solve`): Hertz's answer for the paraboloid.

For the paraboloid ``r^2/(2R)`` pressed ``delta0`` into the half-space (Hertz 1882; Johnson 1985, (3.39)-(3.41);
the chi -> 0 limit of the any-thickness law (T.7), which is how it is checked in ``tests/afm/test_guards.py``)::

    a = sqrt(R delta0),   P = (4/3) E* R^{1/2} delta0^{3/2},   p(r) = (2 E*/(pi R)) sqrt(a^2 - r^2),
    E* = E/(1 - nu^2) = 2 mu/(1 - nu).

Other tips on the half-space (Sneddon's cone, flat punch, ...) are not answered by ``solve()`` in this version:
one line says so (thinlayer.fit and the nanite models give the cone and the flat punch their half-space forms).
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from .._checks import InputError
from .indentation import Indentation

__all__ = ["HERTZ", "half_space_answer"]


class _HertzEntry:
    """What the answer says of its model (``Indentation.equations``): Hertz's law, not an equation of the paper."""

    name = "half-space"

    def result_equations(self, ans: Indentation) -> tuple[str, str]:
        return "Hertz", "Hertz"


#: the half-space's answers carry this entry (it is not a row of the model registry: solve() takes H = inf to it)
HERTZ = _HertzEntry()


def half_space_answer(layer: Any, tip: Any, delta0: float | None, force: float | None, mu: float, nu: float,
                      tol: float) -> Indentation:
    """The Hertz answer on the half-space (module docstring) as an :class:`Indentation` (model ``"half-space"``)."""
    R = getattr(tip, "sphere_radius", None)
    if R is None:
        raise InputError(f"solve(H=inf): the half-space is answered for the paraboloid (Hertz) in this version, not "
                         f"the {tip.name}; give a finite H")
    R = float(R)
    Es = 2.0 * mu / (1.0 - nu)
    if delta0 is None:
        delta0 = (3.0 * force / (4.0 * Es * math.sqrt(R))) ** (2.0 / 3.0)
    P = 4.0 / 3.0 * Es * math.sqrt(R) * delta0 ** 1.5 if force is None else force
    a = math.sqrt(R * delta0)

    def pressure(x1, x2):
        return 2.0 * Es / (math.pi * R) * np.sqrt(np.maximum(a * a - x1 * x1 - x2 * x2, 0.0))

    return Indentation(layer=layer, punch=tip, delta0=float(delta0), force=float(P), H=math.inf, mu=mu, nu=nu,
                       contact_area=math.pi * a * a, contact_radius=a, semi_axes=None, model="half-space",
                       reason="half-space: H = inf, Hertz's law (exact for the paraboloid)",
                       error_estimate={"force": 0.0, "contact_area": 0.0, "contact_radius": 0.0}, tol=tol,
                       detail=None, _pressure=pressure, _extent=a, entry=HERTZ)
