r"""The thin-layer law of a polyhedral tip (a pyramid), public name ``"tip-law"`` (preference 16): the force (1.8)
to its first correction through the tip's polygonal level set
(:func:`thinlayer.asymptotics.pyramid_law.polyhedral_force_law`), the contact area of the polygon shrunk by the
edge shift (3.25), ``|omega| = |omega0| (1 - h^* H/a)^2`` (``a = 2|omega0|/|Gamma0|``, the inradius of a regular
pyramid's polygon).

It applies to a polyhedral tip (non-axisymmetric, not a polynomial, with ridges) on a layer with a compressible
expansion (``A != 0``).  The tips of revolution are the other ``"tip-law"`` entry (:mod:`.tip_law`).

Estimate.  The remainder is ``O(P0 (H/a)^3)`` (pyramid_law.py), measured against
:func:`thinlayer.numerics.solve_2d` (4-sided pyramid, face angle 35, and Berkovich; H/a = 0.05 .. 0.3):
``|P - P0 - P1|/P0 / (H/a)^3`` = 0.39-0.51 (bonded nu = 0.3), 0.14-0.22 (frictionless), 12.9-17.7 (bonded
nu = 0.45).  The tips of revolution's estimate (:func:`~thinlayer.contact.models.tip_law.tip_law_estimate`,
``3 (|P1/P0| (H/a) + (P1/P0)^2 + 0.2 (H/a)^3)``) covers each of these points by a factor 1.6 or more; it is used as is
for the force.  The area: ``|A - A_direct|/A`` measured at most ``0.35 (H/a)^2 + 0.45 |P1/P0|`` (the corners' H x H
squares and the edge shift's O(H^2); 4-sided 35 and Berkovich, the three layers, H/a = 0.05 .. 0.3), so
``est_A = 1.5 (H/a)^2 + 0.75 |P1/P0|`` (1.6x or more).
tests/asymptotics/test_pyramid_law.py checks both estimates against solve_2d.
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from ...asymptotics.solution import ValidityError
from ..indentation import Indentation
from ..problem import Problem
from .base import ForceCurve, Model, register_model
from .common import LazyExtent, depth_for_force
from .tip_law import edge_shift, tip_law_estimate

__all__ = ["AREA_FACTORS", "PolyhedralLawModel", "polyhedral_estimate"]

#: the area estimate's constants on (H/a)^2 and on |P1/P0| (module docstring: 1.6x the measured ones or more)
AREA_FACTORS = (1.5, 0.75)


def polyhedral_estimate(P0: float, P1: float, H_over_a: float) -> dict[str, float]:
    """The relative estimates of the force and the contact area (module docstring)."""
    est = tip_law_estimate(P0, P1, H_over_a)
    area = AREA_FACTORS[0] * H_over_a**2 + AREA_FACTORS[1] * abs(P1 / P0)
    return {"force": est["force"], "contact_area": area}


@lru_cache(maxsize=64)
def _law(layer, tip):
    from ...asymptotics.pyramid_law import polyhedral_force_law

    return polyhedral_force_law(layer, tip)


@lru_cache(maxsize=64)
def _level_set_arrays(tip):
    """``delta0 -> (a, |omega0|, V, J)`` on arrays: the tip's closed forms (its ``level_set_expressions``, compiled
    once per tip), else its numeric ``level_set`` depth by depth.
    """
    from ... import symbols as S
    from ...asymptotics.force_law import lambdify_law

    exprs = getattr(tip, "level_set_expressions", None)
    exprs = exprs() if exprs is not None else None
    if exprs is not None:
        keys = ("inradius", "area", "volume", "flux")
        outs = tuple(exprs[k] for k in keys)
        if all(not (o.free_symbols - {S.delta0}) for o in outs):
            fn = lambdify_law((S.delta0,), outs, "numpy")
            return lambda d: tuple(np.broadcast_to(np.asarray(v, dtype=float), d.shape) for v in fn(d))

    def numeric(d):
        sets = [tip.level_set(x) for x in d.ravel()]
        return tuple(np.array([getattr(ls, k) for ls in sets], dtype=float).reshape(d.shape)
                     for k in ("half_width", "area", "volume", "flux"))

    return numeric


class PolyhedralLawModel(Model):
    """The thin-layer law (1.8), (3.25) of a polyhedral tip."""

    name = "tip-law"
    preference = 16
    asymptotic = True
    fits = True
    equations = ("1.8", "3.25")

    def refuses(self, problem: Problem) -> str | None:
        tip = problem.tip
        if tip.fixed_contact or tip.axisymmetric or tip.polynomial is not None or tip.smoothness != "ridge":
            return ("this tip-law entry is the thin-layer law of a polyhedral tip (Punch.pyramid, Punch.berkovich, "
                    "Punch.vickers, Punch.from_expr('max(...)'))")
        return None

    def applies(self, problem: Problem) -> str | None:
        if not problem.layer.has_compressible_expansion:
            return "nu = 1/2 on a bonded base: A = 0 in (2.4), no thin-layer law of order 1"
        return None

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        """The law at ``mu = 1`` on arrays of depths: ``P0 = c0 V``, ``P1 = c1 J`` (1.8) through the tip's level set,
        the area ``|omega0| (1 - h^* H/a)^2`` (3.25), the estimate :func:`polyhedral_estimate` (the larger of force and
        area) and the slopes ``d log P/d log delta0 = delta0 P'/P``, ``d log P/d log H = (P1 - P0)/P``
        (``P0 ~ 1/H``, ``P1 ~ H``; ``delta0 P' = delta0 c0 |omega0| + c1 J`` since ``dV/d delta0 = |omega0|`` and
        ``J`` is linear in ``delta0`` on a planar-faced tip).  None for a tip or layer the model refuses.
        """
        if self.refuses(problem) or self.applies(problem) or not problem.tip.is_numeric:
            return None
        law, H, nu = _law(problem.layer, problem.tip), problem.H, problem.nu
        c0, c1 = law.constants(H, 1.0, nu)
        shift = edge_shift(problem.layer) * H
        level_set = _level_set_arrays(problem.tip)

        def force(d):
            a, area0, V, J = level_set(d)
            P0, P1 = c0 * V, c1 * J
            x = H / a
            r1 = np.abs(P1 / P0)
            est = tip_law_estimate(P0, P1, x)["force"]
            est_A = AREA_FACTORS[0] * x * x + AREA_FACTORS[1] * r1
            shrink = 1.0 - shift / a
            area = np.where(shrink > 0, area0 * shrink * shrink, np.nan)
            return P0 + P1, area, np.maximum(est, est_A)

        def slopes(d):
            a, area0, V, J = level_set(d)
            P0, P1 = c0 * V, c1 * J
            P = P0 + P1
            return (d * c0 * area0 + P1) / P, (P1 - P0) / P

        return ForceCurve(self.name, problem.tol, force, slopes=slopes)

    def _at(self, problem: Problem, delta0: float) -> tuple[float, float, float, float, dict, float]:
        """``(P, P0, P1, a, estimate, area0)`` at a depth."""
        law = _law(problem.layer, problem.tip)
        P0, P1 = law.evaluate(delta0, problem.H, problem.mu, nu=problem.nu)
        ls = problem.tip.level_set(delta0)
        a = ls.half_width
        return P0 + P1, P0, P1, a, polyhedral_estimate(P0, P1, problem.H / a), ls.area

    def run(self, problem: Problem) -> Indentation:
        H, tol, tip = problem.H, problem.tol, problem.tip
        if problem.force is not None:
            delta0 = depth_for_force(lambda d: self._at(problem, d)[0], problem.force, problem.guess or 1.0)
        else:
            delta0 = problem.delta0
        P, P0, P1, a, est, area0 = self._at(problem, delta0)
        shrink = 1.0 - edge_shift(problem.layer) * H / a
        if not (P > 0 and math.isfinite(P) and shrink > 0) or max(est.values()) > tol:
            raise ValidityError(f"solve(): tip-law: estimates force {100 * est['force']:.3g} %, contact area "
                                f"{100 * est['contact_area']:.3g} % exceed tol {100 * tol:.3g} % at H/a = "
                                f"{H / a:.3g}", "force", est["force"], tol, "direct")
        vt_AH = P0 / tip.level_set(delta0).volume  # vartheta/(A H): the leading pressure (2.26)

        def pressure(x1, x2):
            phi = tip.profile(x1, x2)
            return np.where(phi < delta0, vt_AH * (delta0 - phi), 0.0)

        return Indentation(layer=problem.layer, punch=tip, delta0=delta0, force=P, H=H, mu=problem.mu, nu=problem.nu,
                           contact_area=area0 * shrink * shrink, contact_radius=None, semi_axes=None,
                           model=self.name, reason="", error_estimate=est, tol=math.inf,
                           detail=_law(problem.layer, tip), _pressure=pressure, _extent=LazyExtent(tip, delta0),
                           extras={"P0": P0, "P1": P1, "level_set_half_width": a,
                                   "pressure_order": "leading (2.26): vartheta (delta0 - Phi)/(A H)"})


register_model(PolyhedralLawModel)
