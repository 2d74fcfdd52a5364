r"""Force curves of the sphere that :func:`thinlayer.contact.fit.fit` offers besides the any-thickness law (T.7):
Hertz's half-space law and two published thick-layer series (preference 200 and up; never walked by ``solve()``).

``P = (4/3) E/(1 - nu^2) R^{1/2} delta^{3/2} S(chi)``, ``chi = sqrt(R delta)/H``, with ``S = 1`` (Hertz) or the
printed coefficients of :data:`thinlayer.asymptotics.thick_layer.PUBLISHED_SERIES` (secondary sources, printed for
nu = 1/2).  Their ranges are measured against the any-thickness law by ``fit()`` (``model_error``): the curves
carry no estimate of their own.
"""
from __future__ import annotations

import math

import numpy as np

from ...errors import InputError
from ..indentation import Indentation
from ..problem import Problem
from .base import ForceCurve, Model, register_model

__all__ = ["DimitriadisModel", "GarciaModel", "HertzModel", "series_coefficients"]


def series_coefficients(model: str, base: str) -> tuple[float, ...]:
    """``(1, b_1, b_2, ...)`` of ``S(chi)`` for ``"hertz"``, ``"dimitriadis2002"`` or ``"garcia2018"``."""
    if model == "hertz":
        return (1.0,)
    from ...asymptotics.thick_layer import PUBLISHED_SERIES

    key = {"dimitriadis2002": f"dimitriadis2002-{'bonded' if base == 'bonded' else 'nonbonded'}",
           "garcia2018": "garcia2018-sphere"}[model]
    if model == "garcia2018" and base != "bonded":
        raise InputError("the Garcia & Garcia (2018) series is for a bonded layer; use base='bonded' or another model")
    return (1.0, *PUBLISHED_SERIES[key]["coefficients"])


class _PublishedSphere(Model):
    asymptotic = False
    selectable = False
    solves = False
    fits = True

    def refuses(self, problem: Problem) -> str | None:
        return None if problem.tip.sphere_radius is not None else f"the {self.name} law is for the sphere"

    def applies(self, problem: Problem) -> str | None:
        return self.refuses(problem)

    def run(self, problem: Problem) -> Indentation:
        raise InputError(f"the {self.name} law is a force curve for fit(), not a model of solve()")

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        """``mu * 2(1 + nu) * (4/3)/(1 - nu^2) R^{1/2} delta^{3/2} S(chi)`` at ``mu = 1``; estimate 0 (unmeasured)."""
        R, H, nu = problem.tip.sphere_radius, problem.H, problem.nu
        if R is None:
            return None
        coef = np.array(series_coefficients(self.name, problem.layer.base_label))
        dcoef = coef[1:] * np.arange(1, coef.size)
        K = 2.0 * (1.0 + nu) * 4.0 / 3.0 / (1.0 - nu * nu) * math.sqrt(R)

        def parts(d):
            chi = np.sqrt(R * d) / H
            S = np.polynomial.polynomial.polyval(chi, coef)
            dS = chi * np.polynomial.polynomial.polyval(chi, dcoef) if dcoef.size else np.zeros_like(chi)
            return S, dS

        def law(d):
            S, _ = parts(d)
            return K * d**1.5 * S, math.pi * R * d, np.zeros_like(d)

        def slopes(d):
            S, dS = parts(d)
            with np.errstate(divide="ignore", invalid="ignore"):
                dl = np.where(S > 0, dS / S, 0.0)
            return 1.5 + 0.5 * dl, -dl

        return ForceCurve(self.name, math.inf, law, slopes=slopes)


class HertzModel(_PublishedSphere):
    """Hertz's half-space law (what a thickness-blind fit does)."""

    name = "hertz"
    preference = 200
    equations = ("Hertz (1882)", "Hertz (1882)")

    def applies(self, problem: Problem) -> str | None:
        return self.refuses(problem)


class DimitriadisModel(_PublishedSphere):
    """Dimitriadis et al. (2002): Hertz times a thick-layer series in chi (printed for nu = 1/2)."""

    name = "dimitriadis2002"
    preference = 210
    equations = ("Dimitriadis et al. (2002)", "Dimitriadis et al. (2002)")

    def applies(self, problem: Problem) -> str | None:
        return self.refuses(problem)


class GarciaModel(_PublishedSphere):
    """Garcia & Garcia (2018): Hertz times a thick-layer series in chi (bonded layer, nu = 1/2)."""

    name = "garcia2018"
    preference = 220
    equations = ("Garcia & Garcia (2018)", "Garcia & Garcia (2018)")

    def applies(self, problem: Problem) -> str | None:
        return self.refuses(problem)


register_model(HertzModel)
register_model(DimitriadisModel)
register_model(GarciaModel)
