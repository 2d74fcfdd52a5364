r"""The nearly-incompressible models of a bonded layer: two-term (I.10)-(I.12) (preference 20) and the code they
share with the incompressible model (:mod:`thinlayer.contact.models.incompressible`).

Both neglect the edge layer of width ``H`` (I.12): the true contact edge lies ``h H`` inside the model's (``h``
from :func:`thinlayer.asymptotics.incompressible.two_term_edge_shift`, 1.459 at nu = 1/2), which changes the force
at relative order ``h H/c``.  Their estimates are ``2 h H/c`` for the force and the area (the factor 2 covers the
unknown order-one constant of that term) and ``2 (h H/c)^2`` for the corrected radius ``c - h H``.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from functools import lru_cache

import numpy as np

from ... import symbols as S
from ..._lazy import lazy_function, lazy_module
from ...asymptotics.solution import ValidityError
from ...layers.kernels import LayerKernel
from ...punch import is_polynomial_tip
from ..indentation import Indentation
from ..problem import Problem
from .base import ForceCurve, Model, register_model
from .common import depth_for_force, polynomial_reason
from .compressible import SMOOTH_ONLY

sp = lazy_module("sympy")  # imported on first use: a numeric solve() never needs it
# the nearly-incompressible models build sympy objects at import: loaded when this model first runs
incompressible_axisymmetric, incompressible_ellipse, incompressible_tip, two_term_edge_shift, two_term_sphere = (
    lazy_function("thinlayer.asymptotics.incompressible", name)
    for name in ("incompressible_axisymmetric", "incompressible_ellipse", "incompressible_tip", "two_term_edge_shift",
                 "two_term_sphere"))

__all__ = ["TwoTermModel", "base_nu_reason", "edge_h", "incompressible_ellipse_cached", "nearly_incompressible",
           "nearly_incompressible_curve", "two_term_pressure"]


def two_term_pressure(model, c: float, H: float, mu: float, R: float) -> Callable:
    """``p(r)`` of the sphere in the two-term model (I.10)-(I.11), stable for every ``k c``.

    ``-Delta p + k^2 p = F (delta0 - r^2/(2R))``, ``F = vartheta/(c_1 H^3)``, ``p(c) = p'(c) = 0``:
    ``p = alpha_0 + alpha_1 r^2 + B I_0(k r)`` with ``alpha_1 = -F/(2 R k^2)``, ``B = -2 alpha_1 c/(k I_1(k c))``
    and ``alpha_0 = -alpha_1 c^2 - B I_0(k c)``; the Bessel ratios are taken scaled (``ive``) so that nothing
    overflows.  At ``k = 0`` (nu = 1/2): ``p = F (c^2 - r^2)^2/(32 R)``.
    """
    from scipy import special

    c0, c1, th = float(model.c0), float(model.c1), float(model.vartheta.subs(S.mu, mu))
    F = th / (c1 * H**3)
    k = math.sqrt(c0 / c1) / H if c0 else 0.0

    def p(r):
        r = np.abs(np.asarray(r, dtype=float))
        rr = np.minimum(r, c)
        if k * c < 1e-3:  # the incompressible limit (relative error (k c)^2 / 10 below 1e-7)
            val = F * (c * c - rr * rr) ** 2 / (32 * R)
        else:
            a1 = -F / (2 * R * k * k)
            b_over = -2 * a1 * c / k  # B I_1(k c)
            ratio_r = special.ive(0, k * rr) / special.ive(1, k * c) * np.exp(k * (rr - c))
            ratio_c = special.ive(0, k * c) / special.ive(1, k * c)
            val = a1 * (rr * rr - c * c) + b_over * (ratio_r - ratio_c)
        return np.where(r < c, np.maximum(val, 0.0), 0.0)

    return p


@lru_cache(maxsize=64)
def incompressible_ellipse_cached(R1: float, R2: float):  # noqa: N803
    """:func:`~thinlayer.asymptotics.incompressible.incompressible_ellipse` at numeric radii (cached)."""
    return incompressible_ellipse(sp.Float(R1, 17), sp.Float(R2, 17))


@lru_cache(maxsize=64)
def edge_h(layer: LayerKernel) -> float:
    """``h(nu)`` of (I.12) as a float (cached per layer)."""
    return float(two_term_edge_shift(layer, dps=15))


def base_nu_reason(problem: Problem, name: str, incompressible: bool) -> str | None:
    """Why a nearly-incompressible model does not apply to this base and nu (None: it does)."""
    nu = problem.nu
    if not (problem.layer.has_incompressible_model if incompressible else problem.layer.has_two_term_model):
        return f"the {name} model is derived for a bonded base"
    if incompressible and nu != 0.5:
        return f"nu = {nu:.6g} < 1/2 (the incompressible model is nu = 1/2)"
    if not incompressible and not 0.25 < nu < 0.5:
        return f"the two-term model needs 1/4 < nu < 1/2, got nu = {nu:.6g}"
    return None


def nearly_incompressible(problem: Problem, name: str) -> Indentation:
    """The two-term (sphere) or incompressible (sphere, elliptic paraboloid, axisymmetric) answer (I.3)-(I.12)."""
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):  # refused below if not finite
        ans = _nearly_incompressible(problem, name)
    if not (math.isfinite(ans.force) and ans.force > 0):
        raise ValidityError(f"solve(): the {name} model's force {ans.force:.4g} is not a positive finite number",
                            "force", math.inf, problem.tol, "direct")
    return ans


def _nearly_incompressible(problem: Problem, name: str) -> Indentation:
    layer, punch = problem.layer, problem.tip
    H, mu, nu, tol, force, delta0 = problem.H, problem.mu, problem.nu, problem.tol, problem.force, problem.delta0
    h = edge_h(layer)
    common = dict(layer=layer, punch=punch, H=H, mu=mu, nu=nu, model=name, reason="", tol=tol)
    if punch.sphere_radius is not None:
        R = punch.sphere_radius
        model = two_term_sphere(layer)

        def at(d0):
            return model.evaluate(d0, R, H, mu)

        d0 = depth_for_force(lambda d: at(d).force, force, math.sqrt(force / mu) if force else 1.0) \
            if force is not None else delta0
        v = at(d0)
        c = v.radius
        hc = h * H / c
        radius = v.radius_corrected
        if not radius > 0:
            raise ValidityError(f"solve(): the {name} model's corrected radius c - h H = {radius:.3g} <= 0 "
                                f"(H/c = {H / c:.3g}): far outside the thin-layer range", "contact_radius",
                                math.inf, tol, "direct")
        est = {"force": 2 * hc, "contact_area": 2 * hc, "contact_radius": 2 * hc * hc}
        p_r = two_term_pressure(model, c, H, mu, R)
        return Indentation(**common, delta0=d0, force=v.force, contact_area=math.pi * radius**2,
                           contact_radius=radius, semi_axes=None, error_estimate=est, detail=v,
                           _pressure=lambda x1, x2: p_r(np.hypot(x1, x2)), _extent=1.2 * c)
    if punch.quadric is not None:  # elliptic paraboloid at nu = 1/2 (I.6)-(I.8)
        k1, k2, ang = punch.quadric
        model = incompressible_ellipse_cached(1 / k1, 1 / k2)

        def at(d0):
            return model.evaluate(d0, H, mu)

        d0 = depth_for_force(lambda d: at(d).force, force, 1.0) if force is not None else delta0
        v = at(d0)
        a, b, C = v.a, v.b, v.C
        hc = h * H / math.sqrt(a * b)
        est = {"force": 2 * hc, "contact_area": 2 * hc}
        cs, sn = math.cos(ang), math.sin(ang)

        def p(x1, x2):
            y1, y2 = cs * x1 + sn * x2, -sn * x1 + cs * x2
            q = 1 - (y1 / a) ** 2 - (y2 / b) ** 2
            return np.where(q > 0, C * np.maximum(q, 0.0) ** 2, 0.0)

        axes = (max(a - h * H, 0.0), max(b - h * H, 0.0))
        return Indentation(**common, delta0=d0, force=v.force, contact_area=math.pi * axes[0] * axes[1],
                           contact_radius=None, semi_axes=axes, error_estimate=est, detail=v, _pressure=p,
                           _extent=1.2 * max(a, b))
    # any axisymmetric polynomial punch (I.9); a tip of revolution (cone, exact sphere, ...) (I.9a)-(I.9c)
    model = incompressible_axisymmetric(punch) if is_polynomial_tip(punch) else incompressible_tip(punch)

    def at(d0):
        return model.evaluate(d0, H, mu)

    d0 = depth_for_force(lambda d: at(d).force, force, 1.0) if force is not None else delta0
    v = at(d0)
    c = v.radius
    hc = h * H / c
    radius = c - h * H
    est = {"force": 2 * hc, "contact_area": 2 * hc, "contact_radius": 2 * hc * hc}
    return Indentation(**common, delta0=d0, force=v.force, contact_area=math.pi * max(radius, 0.0) ** 2,
                       contact_radius=radius, semi_axes=None, error_estimate=est, detail=v,
                       _pressure=lambda x1, x2: v.pressure(np.hypot(x1, x2)), _extent=1.2 * c)


def nearly_incompressible_curve(problem: Problem, name: str) -> ForceCurve:
    """The unit-modulus force curve of the two-term/incompressible answer (one model evaluation per depth)."""
    import dataclasses

    from ..problem import Depth, Elastic

    def law(d):
        d = np.asarray(d, dtype=float)
        out = np.full((3,) + d.shape, np.nan)
        for i, dv in np.ndenumerate(d):
            try:
                q = dataclasses.replace(problem, loading=Depth(float(dv)), material=Elastic(1.0, problem.nu))
                ans = nearly_incompressible(q, name)
            except (ValidityError, ArithmeticError, ValueError):
                continue
            out[(slice(None),) + i] = (ans.force, ans.contact_area, max(ans.error_estimate.values()))
        return out[0], out[1], np.where(np.isnan(out[2]), np.inf, out[2])

    return ForceCurve(name, problem.tol, law)


class TwoTermModel(Model):
    """The sphere on a nearly-incompressible bonded layer, ``1/4 < nu < 1/2`` (I.10)-(I.12)."""

    name = "two-term"
    preference = 20
    asymptotic = True
    equations = ("I.11", "I.12")

    def refuses(self, problem: Problem) -> str | None:
        return SMOOTH_ONLY.format(name=self.name) if problem.tip.fixed_contact else None

    def applies(self, problem: Problem) -> str | None:
        why = base_nu_reason(problem, self.name, incompressible=False) or polynomial_reason(problem.tip)
        if why is None and not problem.tip.sphere_radius is not None:
            return "the two-term model is derived for the sphere (paraboloid) only"
        return why

    def run(self, problem: Problem) -> Indentation:
        return nearly_incompressible(problem, self.name)

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        return None if self.refuses(problem) or self.applies(problem) else nearly_incompressible_curve(problem,
                                                                                                        self.name)


register_model(TwoTermModel)
