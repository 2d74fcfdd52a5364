r"""The any-thickness model (preference 60): the sphere at any ``H/a`` by the law (T.7), the cone by its law (T.9)
(:mod:`thinlayer.contact.any_thickness_tips`; bonded ``0.3 <= nu <= 1/2`` or frictionless, ``chi = c_0/H`` up to the
table's end), every tip of revolution (exact sphere, blunted cone, power law) by the equation (F.6) with its load
(F.10)-(F.15) solved at the depth (``c_0/H <= 30``), another axisymmetric punch by the thick-layer series (T.5)
where its estimate (T.8) is within ``tol``
(:mod:`thinlayer.contact.any_thickness`).  ``model="auto"`` tries it for axisymmetric punches after the
thin-layer models and before the direct solver.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ...asymptotics.solution import ValidityError
from ...errors import InputTypeError
from ..any_thickness import (
    ADOPTED_LAWS,
    AnyThicknessLaw,
    NotTabulatedError,
    any_thickness_fields,
    any_thickness_law,
    sphere_radius,
)
from ..indentation import Indentation
from ..problem import Problem
from .base import ForceCurve, Model, register_model
from .common import polynomial_reason
from .tip_tables import tip_table_curve

__all__ = ["AnyThicknessModel", "SphereCurve", "adopt_law", "sphere_curve"]

#: ``R delta`` within these bounds: the contact area of (T.7) is a positive double wherever the force is (the
#: force-only path needs no area to mask the force; outside them :meth:`SphereCurve.force_slopes` computes it)
_RD_SAFE = (1e-250, 1e250)


@dataclass(frozen=True, eq=False)
class SphereCurve(ForceCurve):
    """The sphere's :class:`ForceCurve` of the law (T.7), with a force-only path for fits.

    A fit evaluates the force (and its slopes) many times and the validity once, over the fitted depths:
    :meth:`force_slopes` computes ``P`` from ``log(P/P_Hertz)`` alone (no contact radius, no error estimate), the
    same numbers bit for bit as :meth:`ForceCurve.force` and ``slopes`` (tests/afm/test_maps_fast.py).
    """

    fast: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]] | None = None  # delta > 0 -> (P, d log P/d log chi)
    radius_scale: float = 1.0  # R: the contact area is pi R delta (c/sqrt(R delta))^2

    def force_slopes(self, delta: np.ndarray, slopes: bool = True) -> tuple[np.ndarray, Any, Any]:
        """``(force, d log P/d log delta, d log P/d log H)`` at depths ``delta > 0`` (every one positive), equal bit for
        bit to ``(self.force(delta), *self.slopes(delta))``; the slopes None unless ``slopes``.
        """
        d = np.asarray(delta, dtype=float)
        fast = self.fast is not None and self.tol == math.inf and d.size > 0
        if fast:
            lo, hi = self.radius_scale * float(d.min()), self.radius_scale * float(d.max())
            fast = lo > 0 and _RD_SAFE[0] < lo and hi < _RD_SAFE[1]  # NaN fails
        if not fast:
            P = self.force(d)
            return (P, *self.slopes(d)) if slopes else (P, None, None)
        with np.errstate(all="ignore"):
            P, dlp = self.fast(d)
            ok = P > 0
            ok &= P < math.inf
        if not ok.all():
            P[~ok] = np.nan
        if not slopes:
            return P, None, None
        return P, 1.5 + 0.5 * dlp, -dlp


def adopt_law(law: AnyThicknessLaw) -> None:
    """Use ``law`` for its (nu, base) from now on instead of building it: a worker process of a force map receives
    the law its parent built (:func:`thinlayer.afm.maps.fit_map`), the same numbers, and skips the build (seconds of
    symbolic series per process).
    """
    if not isinstance(law, AnyThicknessLaw):
        raise InputTypeError(f"adopt_law() takes an AnyThicknessLaw, got {type(law).__name__}")
    ADOPTED_LAWS.setdefault((law.nu, law.base), law)


def sphere_curve(name: str, R: float, H: float, nu: float, base: str, tol: float) -> ForceCurve:
    r"""The law (T.7) at ``mu = 1``: ``P = (8/3) R^{1/2} delta^{3/2} Pi(chi)/(1 - nu)``, ``c = sqrt(R delta) C(chi)``,
    ``chi = sqrt(R delta)/H``; the depth for a contact radius by inverting ``c/H = chi C(chi)`` (monotone).
    """
    law = any_thickness_law(nu, base)
    K = 8.0 / 3.0 / (1.0 - nu) * math.sqrt(R)

    def parts(d):
        chi = np.sqrt(R * d) / H
        Pr, cr = law.ratios(chi)
        eP, ec = law.error_estimate(chi)
        return chi, Pr, cr, eP, ec

    def f(d):
        _, Pr, cr, eP, ec = parts(d)
        c = np.sqrt(R * d) * cr
        return K * d**1.5 * Pr, math.pi * c * c, np.maximum(eP, 2 * ec)

    def radius(d):
        _, _, cr, _, _ = parts(d)
        return np.sqrt(R * d) * cr

    def slopes(d):
        _, dlp = law.log_force_ratio(np.log(np.sqrt(R * d) / H))
        return 1.5 + 0.5 * dlp, -dlp

    def fast(d):  # f(d)'s force and slopes' dlp from one lookup of log(P/P_Hertz): the same operations
        lp, dlp = law.log_force_ratio(np.log(np.sqrt(R * d) / H))
        return K * d**1.5 * np.exp(lp), dlp

    grid = np.geomspace(1e-8, 1e8, 4001)

    def inverse(c):
        lg = np.log(grid * law.ratios(grid)[1])  # log(c/H) against log chi: increasing
        t = np.log(np.asarray(c, dtype=float) / H)
        x = np.interp(t, lg, np.log(grid))
        for _ in range(3):  # Newton steps in log chi on log(chi C(chi)) = t, the slope from the grid
            y = x + np.log(law.ratios(np.exp(x))[1])
            s = np.interp(x, np.log(grid), np.gradient(lg, np.log(grid)))
            x = x - (y - t) / s
        return (np.exp(x) * H) ** 2 / R

    return SphereCurve(name, tol, f, radius_law=radius, inverse_radius=inverse, slopes=slopes, fast=fast,
                       radius_scale=float(R))






class AnyThicknessModel(Model):
    """The sphere at any thickness (T.7); other axisymmetric punches on thick layers (T.5)."""

    name = "any-thickness"
    preference = 60
    equations = ("T.7", "T.7")
    fits = True
    declines = (NotTabulatedError, ValidityError)

    def refuses(self, problem: Problem) -> str | None:
        if problem.tip.fixed_contact:
            return "the any-thickness law covers the sphere and axisymmetric smooth punches"
        return None

    def skips(self, problem: Problem) -> bool:
        """``model="auto"`` tries the law for axisymmetric smooth punches only."""
        return self.refuses(problem) is not None or not problem.tip.axisymmetric

    def applies(self, problem: Problem) -> str | None:
        tip = problem.tip
        if tip.polynomial is None and tip.axisymmetric and hasattr(tip, "radial_slope"):
            return None  # a tip of revolution: the cone's law, the thick-layer series (T.9) of the others
        return polynomial_reason(tip)

    def run(self, problem: Problem) -> Indentation:
        tol = problem.tol
        try:
            fields = any_thickness_fields(problem.layer, problem.tip, delta0=problem.delta0, force=problem.force,
                                          H=problem.H, mu=problem.mu, nu=problem.nu, tol=tol)
        except NotTabulatedError:
            raise
        except ValidityError as exc:
            if exc.model == "other units":  # the law holds, its numbers leave the double range: the true reason
                raise ValidityError(f"solve(): {exc}", exc.quantity, exc.estimate, exc.tol, exc.model) from None
            raise
        except ValueError as exc:  # the estimate exceeds tol
            raise ValidityError(f"solve(): {exc}", "force", math.inf, tol, "direct") from None
        return Indentation(**fields)

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        """The law (T.7) for the sphere, the cone's table law (T.9) where it covers the layer
        (:func:`.tip_tables.tip_table_curve`); None for other punches (the equation (F.6) is solved per depth).
        """
        R = sphere_radius(problem.tip)
        if R is None:
            if self.refuses(problem):
                return None
            return tip_table_curve(problem.tip, problem.H, problem.nu, problem.layer.base_label, problem.tol,
                                   self.name)
        return sphere_curve(self.name, R, problem.H, problem.nu, problem.layer.base_label, problem.tol)


register_model(AnyThicknessModel)
