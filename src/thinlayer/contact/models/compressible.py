r"""The compressible thin-layer model: the paper's expansion (2.22)-(3.25) (preference 10).

Force (1.8) with its first correction, contact area with the exact edge shift h^* (3.25), composite pressure
(:func:`thinlayer.asymptotics.solution.compressible_solution`); estimate
:func:`thinlayer.asymptotics.force_law.error_estimate`.  Its force curve is
:func:`thinlayer.asymptotics.solution.force_arrays` (punches with a closed-form law).
"""
from __future__ import annotations

import math

import numpy as np

from ...asymptotics.force_law import force_law
from ...asymptotics.solution import compressible_solution, force_arrays
from ..indentation import Indentation
from ..problem import Problem
from .base import ForceCurve, Model, register_model
from .common import LazyExtent

__all__ = ["CompressibleModel", "SMOOTH_ONLY"]

#: the refusal of the smooth-punch models for a tip whose contact does not move (the flat punch)
SMOOTH_ONLY = ("model={name!r} is a model of smooth punches; for the flat punch the thin-layer law (F.10)-(F.16) "
               "covers every nu: use model='auto', 'asymptotic', 'any-thickness' or 'direct'")


class CompressibleModel(Model):
    """The compressible thin-layer expansion (1.8), (3.25)."""

    name = "compressible"
    preference = 10
    asymptotic = True
    equations = ("1.8", "3.25")
    takes_options = True

    def refuses(self, problem: Problem) -> str | None:
        return SMOOTH_ONLY.format(name=self.name) if problem.tip.fixed_contact else None

    def applies(self, problem: Problem) -> str | None:
        if not problem.layer.has_compressible_expansion:
            return "nu = 1/2 on a bonded base: A = 0 in (2.4), no compressible expansion"
        return None

    def run(self, problem: Problem) -> Indentation:
        layer, punch, H = problem.layer, problem.tip, problem.H
        sol = compressible_solution(layer, punch, delta0=problem.delta0, H=H, mu=problem.mu, force=problem.force,
                                    nu=problem.nu, tol=math.inf, **problem.options)
        est = dict(sol.error_estimate)
        radius = None
        if punch.axisymmetric:
            radius = math.sqrt(sol.contact_area / math.pi)
            est["contact_radius"] = est["contact_area"] / 2
        axes = None
        if punch.quadric is not None and not punch.axisymmetric:
            semi = [math.sqrt(2 * sol.delta0 / k) for k in punch.quadric[:2]]
            if sol.order == 2:  # (SO.5): h = h* + m1 H (kappa/2 + Phi_nn/(2g)); at the end of axis i kappa = a_i/a_j^2
                m1 = float(layer.m(1))
                axes = tuple(a - H * (sol.edge_shift + m1 * H * (a / b**2 + 1 / a) / 2)
                             for a, b in (semi, semi[::-1]))
            else:  # the contour moves inward by h* H along its normal (3.25)
                axes = tuple(a - sol.edge_shift * H for a in semi)
        return Indentation(layer=layer, punch=punch, delta0=sol.delta0, force=sol.force, H=H, mu=problem.mu,
                           nu=problem.nu, contact_area=sol.contact_area, contact_radius=radius, semi_axes=axes,
                           model=self.name, reason="", error_estimate=est, tol=math.inf, detail=sol,
                           _pressure=sol.pressure, _extent=LazyExtent(punch, sol.delta0))  # extent: max_pressure

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        """``force_arrays`` at ``mu = 1``: the punches with a closed-form law (quadric, radial monomial)."""
        if problem.tip.fixed_contact or not problem.layer.has_compressible_expansion:
            return None
        closed_form = force_law(problem.layer, problem.tip)
        if closed_form.kind == "contour":  # the law needs its contour at every depth
            return None
        layer, punch, H, nu, tol = problem.layer, problem.tip, problem.H, problem.nu, problem.tol

        def law(d):
            out = force_arrays(layer, punch, d, H, 1.0, nu=nu, tol=math.inf)
            est = np.maximum(out.error_estimate["force"], out.error_estimate["contact_area"])
            return out.force, out.contact_area, est

        return ForceCurve(self.name, tol, law)


register_model(CompressibleModel)
