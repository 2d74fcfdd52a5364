r"""The incompressible model, nu = 1/2 on a bonded base (I.3)-(I.4) (preference 30): the sphere (I.11), the
elliptic paraboloid (I.6)-(I.8), any axisymmetric polynomial punch (I.9) and any tip of revolution (cone, exact sphere,
blunted cone, power law: (I.9a)-(I.9c), :mod:`thinlayer.asymptotics.incompressible.tips`); the edge layer (I.12) as in
:mod:`thinlayer.contact.models.two_term`.
"""
from __future__ import annotations

from ..indentation import Indentation
from ..problem import Problem
from .base import ForceCurve, Model, register_model
from .common import polynomial_reason
from .compressible import SMOOTH_ONLY
from .two_term import base_nu_reason, nearly_incompressible, nearly_incompressible_curve

__all__ = ["IncompressibleModel"]


class IncompressibleModel(Model):
    """The incompressible thin layer (I.3)-(I.12)."""

    name = "incompressible"
    preference = 30
    asymptotic = True
    equations = ("I.8", "I.7")

    def refuses(self, problem: Problem) -> str | None:
        return SMOOTH_ONLY.format(name=self.name) if problem.tip.fixed_contact else None

    def applies(self, problem: Problem) -> str | None:
        tip = problem.tip
        why = base_nu_reason(problem, self.name, incompressible=True)
        if why is None and not (tip.axisymmetric and tip.polynomial is None):  # tips of revolution: (I.9a)-(I.9c)
            why = polynomial_reason(tip)
        if why is None and not (problem.tip.axisymmetric or problem.tip.quadric is not None):
            return ("the incompressible model is closed-form for axisymmetric punches and the elliptic paraboloid; "
                    "this punch needs the direct solver")
        return why

    def run(self, problem: Problem) -> Indentation:
        return nearly_incompressible(problem, self.name)

    def result_equations(self, answer: Indentation) -> tuple[str, str]:
        """The sphere (I.11)-(I.12), another axisymmetric punch (I.9), the elliptic paraboloid (I.7)-(I.8)."""
        if answer.semi_axes is not None or answer.contact_radius is None:
            return self.equations
        return ("I.11", "I.12") if answer.punch.sphere_radius is not None else ("I.9", "I.12")

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        return None if self.refuses(problem) or self.applies(problem) else nearly_incompressible_curve(problem,
                                                                                                        self.name)


register_model(IncompressibleModel)
