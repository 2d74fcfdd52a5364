r"""The viscoelastic row of the model registry (issue 27 item 4): ``solve(..., material=Prony(...), history=...)``.

``"lee-radok"`` (preference 70, viscoelastic): the hereditary force law of :mod:`thinlayer.contact.hereditary` on
the layer's elastic law at unit modulus (the registry's first force curve valid over the history, or the one named
by ``model=``): the force against time for a depth history (:func:`~thinlayer.contact.hereditary.viscoelastic_force`)
or the depth against time for a force history (:func:`~thinlayer.contact.hereditary.viscoelastic_depth`, the
hereditary integral inverted by time stepping).  Lee-Radok holds while the contact grows; from the first shrink on
the answer is flagged ``valid = False`` with NaN.

``"ting"`` (preference 65, viscoelastic): Ting's method (T3)-(T5) (:func:`thinlayer.contact.ting.ting_force`) for a
depth history that rises to one maximum and then falls, under a Prony-series material: exact on the layer under
(C1)-(C3) (the Ting module's statement, measured against the direct solver); the cone through its any-thickness
law (T.9); the flat punch (T7): Lee-Radok on its face while the force is compressive, then lift-off (force 0).
Other histories go to Lee-Radok.

A ``viscoelastic`` entry: the walk offers it only problems with a viscoelastic material, and offers those problems
no other entry (:mod:`thinlayer.contact.models.walk`).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..problem import Problem
from .base import Model, register_model

if TYPE_CHECKING:
    from ..hereditary import ViscoelasticForce

__all__ = ["LeeRadokModel", "TingModel"]


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


class TingModel(LeeRadokModel):
    """Ting's method (T3)-(T5) for a depth history whose contact grows to one maximum and then shrinks."""

    name = "ting"
    preference = 65
    equations = ("T5", "T5")

    def applies(self, problem: Problem) -> str | None:
        from ..materials import Prony

        ld = problem.loading
        if ld.control != "depth":
            return "Ting's method here takes a depth history"
        if not isinstance(problem.material.relaxation, Prony):
            return "Ting's method here needs a Prony series (or a standard linear solid)"
        try:
            d = np.asarray(ld.values, dtype=float)
        except (TypeError, ValueError):
            return None  # the Lee-Radok row refuses it with its own message
        if d.ndim != 1 or d.size < 2 or not np.all(np.isfinite(d)):
            return None if d.ndim != 1 or d.size < 2 else "the depths are not finite"
        m = int(np.argmax(d))
        if not np.any(d[m:] < d[m]):
            return "the depth does not fall after its maximum: Lee-Radok answers"
        return None

    def run(self, problem: Problem) -> ViscoelasticForce:
        from ..hereditary import ViscoelasticForce
        from ..ting import ting_force

        m, ld = problem.material, problem.loading
        out = ting_force(problem.layer, problem.tip, problem.H, m.relaxation, ld.times, ld.values, nu=m.nu,
                         tol=problem.tol, model=m.law)
        why = out.reason if out.surface_depth is not None else \
            "Ting (T3)-(T5), exact on the layer under (C1)-(C3): " + out.reason  # the flat punch says (T7) itself
        return ViscoelasticForce(out.times, out.depths, out.force, out.contact_radius, out.valid, why, out.model,
                                 out.material, out.nu, out.H, control="depth", tol=problem.tol)


register_model(LeeRadokModel)
register_model(TingModel)
