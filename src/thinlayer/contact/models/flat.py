r"""The flat-ended cylinder's laws (F.1): the thick-layer series (F.18)-(F.19) (preference 40) and the thin-layer
law (F.10)-(F.16) (preference 50), each within ``tol`` of its estimate; the exact Fredholm solution (F.6)-(F.7)
is the flat punch's ``"direct"`` entry (:mod:`thinlayer.contact.models.direct`).

``P = 4 mu a w0 kappa(a/H)/(1 - nu)``: the force is linear in the depth and the contact is the punch's face, so
the force curve is one ``kappa`` (:func:`thinlayer.contact.flat_punch.stiffness_table`).
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...asymptotics.solution import ValidityError
from ..flat_punch import EQUATIONS, flat_punch_fields, stiffness_table
from ..indentation import Indentation
from ..problem import Problem
from .base import ForceCurve, Model, register_model

__all__ = ["FlatPunchModel", "flat_answer", "flat_curve"]

#: the step in log(a/H) of the exact curve's slope in H (a central difference)
SLOPE_STEP = 1e-4


def flat_answer(problem: Problem, choice: str) -> Indentation:
    """The flat punch's answer by one law (``"thick"``, ``"thin"``) or the exact solution (``"direct"``)."""
    tol = problem.tol
    try:
        fields = flat_punch_fields(problem.layer, problem.tip.radius, problem.H, problem.delta0, problem.force,
                                   problem.mu, problem.nu, choice, tol, problem.n)
    except ValueError as exc:
        if "max_error" in str(exc):  # the law's estimate exceeds tol
            raise ValidityError(f"solve(): {exc}".replace("max_error", "tol"), "force", math.inf, tol,
                                "direct") from None
        raise
    fields["punch"] = problem.tip
    return Indentation(**fields)


def flat_curve(name: str, problem: Problem, law: str) -> ForceCurve:
    """``P = 4 a delta kappa/(1 - nu)`` at ``mu = 1`` with the ``kappa`` (and estimate) of one law or the exact one."""
    a, nu = float(problem.tip.radius), problem.nu
    kappa, est, _ = stiffness_table(problem.layer, a / problem.H, law, max_error=1.0) if law == "exact" else \
        (None, None, None)
    if kappa is None:
        from ...asymptotics.flat_punch import thick_flat_punch, thin_flat_punch

        m = (thick_flat_punch if law == "thick" else thin_flat_punch)(problem.layer)
        x = np.asarray([a / problem.H])
        with np.errstate(all="ignore"):
            kappa, est = m(x), m.error_estimate(x)
    k, e = float(np.ravel(kappa)[0]), float(np.ravel(est)[0])

    def f(d: Any):
        return 4.0 * a * d * k / (1.0 - nu), np.full_like(d, math.pi * a * a), np.full_like(d, e)

    slope_H: list[float] = []

    def slopes(d: Any):
        # d log P/d log delta = 1; d log P/d log H = -d log kappa/d log(a/H), a central difference of the exact
        # kappa (step 1e-4 in log(a/H): error ~1e-8, the solver's 1e-10 over the step ~1e-6), computed once
        if not slope_H:
            x = a / problem.H * np.exp([-SLOPE_STEP, SLOPE_STEP])
            kk = stiffness_table(problem.layer, x, "exact", max_error=1.0)[0]
            slope_H.append(-float(np.log(kk[1] / kk[0])) / (2 * SLOPE_STEP))
        d = np.asarray(d, dtype=float)
        return np.ones_like(d), np.full_like(d, slope_H[0])

    return ForceCurve(name, problem.tol, f, radius_law=lambda d: np.full_like(d, a),
                      slopes=slopes if law == "exact" else None)


class FlatPunchModel(Model):
    """One law of the flat punch (subclasses: the thick-layer series, the thin-layer law)."""

    name = "flat"
    preference = 45
    asymptotic = True
    selectable = False  # solve() names them "auto" and "asymptotic": the result says which law answered
    equations = ("F.1", "F.1")
    law = ""
    parameter_keys = ("mu", "nu", "H", "delta0", "a")
    parameter_names = ("shear modulus", "Poisson ratio", "layer thickness", "indentation depth", "punch radius")
    parameter_units = ("Pa", "", "m", "m", "m")

    def refuses(self, problem: Problem) -> str | None:
        return None if problem.tip.fixed_contact else "the flat punch's laws hold for the flat punch only"

    def applies(self, problem: Problem) -> str | None:
        return None

    def run(self, problem: Problem) -> Indentation:
        return flat_answer(problem, self.law)

    def reason(self, answer: Indentation, tried: list[str], tol: float, named: bool) -> str:
        """The law and its estimate (F.16) or (F.19): the smooth-punch models never apply to a flat punch."""
        return answer.reason

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        return None if self.refuses(problem) else flat_curve(self.name, problem, self.law)


class ThickFlatModel(FlatPunchModel):
    """The thick-layer series (F.18) with its estimate (F.19); ``a/H < 0.8``."""

    name = "thick-layer"
    preference = 40
    law = "thick"
    equations = EQUATIONS["thick-layer"]


class ThinFlatModel(FlatPunchModel):
    """The thin-layer law (F.10)-(F.16) with its estimate (F.16)."""

    name = "thin-layer"
    preference = 50
    law = "thin"
    equations = EQUATIONS["thin-layer"]


register_model(ThickFlatModel)
register_model(ThinFlatModel)
