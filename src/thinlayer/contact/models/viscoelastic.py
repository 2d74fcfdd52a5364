r"""The viscoelastic row of the model registry (issue 27 item 4): ``solve(..., material=Prony(...), history=...)``.

``"lee-radok"`` (preference 70, viscoelastic): the hereditary force law of :mod:`thinlayer.contact.hereditary` on
the layer's elastic law at unit modulus (the registry's first force curve valid over the history, or the one named
by ``model=``): the force against time for a depth history (:func:`~thinlayer.contact.hereditary.viscoelastic_force`)
or the depth against time for a force history (:func:`~thinlayer.contact.hereditary.viscoelastic_depth`, the
hereditary integral inverted by time stepping).  Lee-Radok holds while the contact grows; from the first shrink on
the answer is flagged ``valid = False`` with NaN (Ting's method is not wired in this release).

A ``viscoelastic`` entry: the walk offers it only problems with a viscoelastic material, and offers those problems
no other entry (:mod:`thinlayer.contact.models.walk`).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ..problem import Problem
from .base import Model, register_model

if TYPE_CHECKING:
    from ..hereditary import ViscoelasticForce

__all__ = ["LeeRadokModel"]


class LeeRadokModel(Model):
    """Lee-Radok's hereditary integral over the layer's elastic law (growing contact)."""

    name = "lee-radok"
    preference = 70
    viscoelastic = True
    selectable = False  # solve(material=...) walks the viscoelastic rows; model= names the elastic law
    equations = ("Lee-Radok", "Lee-Radok")
    parameter_keys = ("E(t)", "nu", "H", "history")
    parameter_names = ("relaxation modulus", "Poisson ratio", "layer thickness", "depth or force against time")
    parameter_units = ("Pa", "", "m", "s, m or N")

    def refuses(self, problem: Problem) -> str | None:
        if not problem.material.viscoelastic:
            return "the Lee-Radok row answers a viscoelastic material (solve(material=..., history=...))"
        return None

    def applies(self, problem: Problem) -> str | None:
        return None

    def run(self, problem: Problem) -> ViscoelasticForce:
        from ..hereditary import viscoelastic_depth, viscoelastic_force  # it imports the registry: at call time

        m, ld = problem.material, problem.loading
        answer = viscoelastic_force if ld.control == "depth" else viscoelastic_depth
        return answer(problem.layer, problem.tip, problem.H, m.relaxation, ld.times, ld.values, nu=m.nu,
                      tol=problem.tol, model=m.law)

    def reason(self, answer: Any, tried: list[str], tol: float, named: bool) -> str:
        return f"{self.name} over the {answer.model} law: {answer.reason}"


register_model(LeeRadokModel)
