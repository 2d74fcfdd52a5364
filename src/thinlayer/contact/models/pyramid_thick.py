r"""The regular pyramid on a thick layer (preference 61), public name ``"any-thickness"``: the series (T.12) of
:mod:`thinlayer.asymptotics.pyramid_thick`, exact through ``chi^5`` (``chi = delta0 tan(alpha)/H``) in the three
half-space numbers of the pyramid (T.13).  The any-thickness entry of the tips of revolution
(:mod:`.any_thickness`) skips non-axisymmetric tips; this row answers the pyramids (3 or 4 sides, Berkovich,
Vickers) where its estimate is within ``tol`` and declines otherwise, so ``model="auto"`` goes on to the direct
solver (solve_2d).

Estimate (:meth:`~thinlayer.asymptotics.pyramid_thick.PyramidThickLaw.estimate`): the force's last two terms (T.8)
plus the half-space constant's uncertainty (T.13); the contact area (the level set of the shifted depth
``delta_e``) ``chi^3`` plus the area constant's uncertainty.  Checked against solve_2d in
tests/asymptotics/test_pyramid_thick.py.
"""
from __future__ import annotations

import math

import numpy as np

from ...asymptotics.solution import ValidityError
from ...errors import InputError
from ..indentation import Indentation
from ..problem import Problem
from .base import ForceCurve, Model, register_model
from .tip_tables import tip_table_curve

__all__ = ["PyramidThickModel"]


class PyramidThickModel(Model):
    """The thick-layer law (T.12) of a regular pyramid."""

    name = "any-thickness"
    preference = 61
    equations = ("T.12", "T.12")
    declines = (ValidityError,)
    fits = True

    def refuses(self, problem: Problem) -> str | None:
        if getattr(problem.tip, "kind", None) != "pyramid":
            return "this any-thickness entry is the thick-layer law (T.12) of a regular pyramid (3 or 4 sides)"
        return None

    def applies(self, problem: Problem) -> str | None:
        layer = problem.layer
        if not layer.has_thickness or layer.symbolic_coefficients or layer.parameter is not None:
            return "the thick-layer law needs a layer of finite thickness with a numeric kernel"
        if not problem.tip.is_numeric:
            return "the pyramid's face angle needs a value"
        return None

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        """The pyramid's any-thickness table law (T.11)-(T.13) (:func:`.tip_tables.tip_table_curve`, ``chi <= 10``)
        where it covers the layer, for fit(); None elsewhere.
        """
        if self.refuses(problem) or self.applies(problem):
            return None
        return tip_table_curve(problem.tip, problem.H, problem.nu, problem.layer.base_label, problem.tol, self.name)

    def run(self, problem: Problem) -> Indentation:
        from ...asymptotics.pyramid_thick import pyramid_thick_law

        layer, nu, tol, H = problem.layer, problem.nu, problem.tol, problem.H
        if layer.numeric_nu is None and not layer.kernel_depends_on_nu:
            layer = layer.with_nu(nu)
        if layer.incompressible_at(nu):
            layer = layer.with_nu(nu)
        law = pyramid_thick_law(layer, problem.tip)
        vt = problem.mu / (1.0 - nu)
        try:
            v = law.at_depth(problem.delta0, H, vt) if problem.force is None else law.at_force(problem.force, H, vt)
        except InputError as exc:
            raise ValidityError(f"solve(): any-thickness: {exc}", "force", math.inf, tol, "direct") from None
        est = {"force": v.force_error, "contact_area": v.area_error}
        # the estimate first: beyond the series' range (a negative or infinite force) the law does not hold, and
        # model='auto' goes on to the direct solver; only a law that holds reports numbers outside the double range
        if not max(est.values()) <= tol:
            raise ValidityError(f"solve(): any-thickness: the pyramid's thick-layer series (T.12) estimates force "
                                f"{v.force_error:.3g}, contact area {v.area_error:.3g} at chi = delta0 tan(alpha)/H = "
                                f"{v.chi:.3g}, above tol = {tol:.3g}", "force", v.force_error, tol, "direct")
        if not (0 < v.force < math.inf and 0 < v.contact_area < math.inf):  # the law holds; its numbers do not
            raise ValidityError(f"solve(): any-thickness: the pyramid's force {v.force:.3g} or contact area "
                                f"{v.contact_area:.3g} leaves the double range at chi = {v.chi:.3g}; express the "
                                "lengths and the moduli in other units", "force", v.force_error, tol, "other units")
        tip, d0 = problem.tip, v.delta0
        force = v.force if problem.force is None else problem.force
        scale = force / v.contact_area  # the mean pressure; the law gives no pressure field beyond it

        def pressure(x1, x2):
            return np.where(tip.profile(x1, x2) < d0, scale, 0.0)

        return Indentation(layer=problem.layer, punch=tip, delta0=d0, force=force, H=H, mu=problem.mu, nu=nu,
                           contact_area=v.contact_area, contact_radius=None, semi_axes=None, model=self.name,
                           reason=f"thick-layer series of the pyramid (T.12) through chi^{v.order} at chi = "
                                  f"delta0 tan(alpha)/H = {v.chi:.4g} (estimates force {v.force_error:.2g}, area "
                                  f"{v.area_error:.2g})",
                           error_estimate=est, tol=tol, detail=law, _pressure=pressure,
                           _extent=1.2 * float(np.abs(tip.polygon(d0)).max()),
                           extras={"chi": v.chi, "pressure_order": "mean pressure only (T.12 gives the force)"})


register_model(PyramidThickModel)
