r"""The thin-layer law of a tip of revolution (preference 15), ``model="tip-law"``: the force (1.8) to its first
correction through the tip's level set (:func:`thinlayer.asymptotics.tip_law.tip_force_law`), the contact radius
``c = a - h^* H`` (3.25) (``a`` the level-set radius, ``h^*`` the exact edge shift of the layer).

It applies to an axisymmetric tip with a radial profile that is not a polynomial (cone, blunted cone, power law,
exact sphere, any ``Phi(r)``) whose inner expansion reaches order 1, on a layer with a compressible expansion
(``A != 0``: bonded ``nu < 1/2`` or a frictionless base).  Polynomial punches go to the compressible model.

Estimate.  The remainder is ``O(P0 (H/a)^q)``, ``q = 3`` for every tip here (tip_law.py).  Its constant is the layer's:
it grows like the first correction's ``|P1/P0| = O((H/a)^2)`` as ``nu -> 1/2`` (``m_1 ~ 1/(3(1 - 2 nu))``), and the
first correction vanishes on a frictionless base while the remainder does not.  So the force estimate is

    est_P = 3 (|P1/P0| (H/a) + (P1/P0)^2 + 0.2 (H/a)^3),

the three terms the next order's size with the layer's scale, its square (where ``|P1/P0|`` is no longer small), and
the base's own ``(H/a)^3``.  Measured against the direct solver (cone 70, blunted cone, power law 3/2; bonded nu = 0.3,
0.45, frictionless; a/H = 5 .. 30): ``|P - P_direct|/P`` is at most 1.7x ``|P1/P0| (H/a) + (P1/P0)^2`` on the bonded
layers and 0.13 ``(H/a)^3`` on the frictionless base, so the factor 3 covers every point with a margin of 1.8x or more.
The radius: ``|c - c_direct|/c`` measured at most 0.21 ``|P1/P0|`` (bonded) and 0.01 ``(H/a)^3`` (frictionless):
``est_c = 0.5 |P1/P0| + 0.05 (H/a)^3``, the area twice that.  tests/contact/test_tip_law_model.py checks the grid.
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

__all__ = ["TipLawModel", "edge_shift", "tip_law_estimate"]

#: the factor on the next-order size (module docstring: 1.8x the largest measured constant or more)
FACTOR = 3.0
#: the frictionless base's own (H/a)^3 constant of the force (measured 0.13 at most) and of the radius (0.01)
BASE_FORCE, BASE_RADIUS = 0.2, 0.05
#: the radius's constant on |P1/P0| (measured 0.21 at most)
RADIUS_FACTOR = 0.5
#: depths per block of the vectorised force curve (its working arrays stay in the cache)
BLOCK = 1 << 15


def tip_law_estimate(P0: float, P1: float, H_over_a: float) -> dict[str, float]:
    """The relative estimates of the force, contact radius and area (module docstring)."""
    r1 = abs(P1 / P0)
    x = H_over_a
    x3 = x * x * x
    force = FACTOR * (r1 * (x + r1) + BASE_FORCE * x3)
    radius = RADIUS_FACTOR * r1 + BASE_RADIUS * x3
    return {"force": force, "contact_radius": radius, "contact_area": 2.0 * radius}


def _scratch(v: np.ndarray, d: np.ndarray) -> np.ndarray | None:
    """``v`` as an output buffer when it is a writable array of its own that does not share the depths' memory
    (else None: numpy allocates).
    """
    ok = (isinstance(v, np.ndarray) and v.flags.writeable and v.flags.owndata and v.shape == np.shape(d)
          and not np.may_share_memory(v, d))
    return v if ok else None


@lru_cache(maxsize=64)
def _law(layer, tip):
    from ...asymptotics.tip_law import tip_force_law

    return tip_force_law(layer, tip)


@lru_cache(maxsize=64)
def edge_shift(layer) -> float:
    """h* of the layer (3.18), (3.25) in floats, cached per layer (the tip laws' edge shift)."""
    from ...asymptotics.wiener_hopf import edge_shift_exact

    return float(edge_shift_exact(layer.edge_shift_key, dps=12))


class TipLawModel(Model):
    """The thin-layer law (1.8), (3.25) of a tip of revolution that is not a polynomial."""

    name = "tip-law"
    preference = 15
    asymptotic = True
    fits = True
    equations = ("1.8", "3.25")

    def refuses(self, problem: Problem) -> str | None:
        tip = problem.tip
        if tip.fixed_contact or not tip.axisymmetric or tip.polynomial is not None:
            return ("the tip-law model is the thin-layer law of a tip of revolution that is not a polynomial (cone, "
                    "sphere, blunted cone, power law); polynomial punches: model='compressible'")
        return None

    def applies(self, problem: Problem) -> str | None:
        tip, layer = problem.tip, problem.layer
        if not layer.has_compressible_expansion:
            return "nu = 1/2 on a bonded base: A = 0 in (2.4), no thin-layer law of order 1"
        order = tip.max_inner_order
        if order is not None and order < 1:
            return f"the inner expansion of the {tip.name} stops before order 1 (no first correction)"
        return None

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        """The law at ``mu = 1`` on arrays of depths (:meth:`~thinlayer.asymptotics.tip_law.TipForceLaw.arrays`),
        its estimate :func:`tip_law_estimate` (the largest of force and area), the radius ``c = a - h^* H`` (3.25) and
        the slopes ``d log P/d log delta0 = delta0 P'/P``, ``d log P/d log H = (P1 - P0)/P`` (``P0 ~ 1/H``,
        ``P1 ~ H``).  None for a tip or layer the model refuses.
        """
        if self.refuses(problem) or self.applies(problem) or not problem.tip.is_numeric:
            return None
        law, H, nu = _law(problem.layer, problem.tip), problem.H, problem.nu
        shift = edge_shift(problem.layer) * H

        def force(d):
            # in blocks of BLOCK depths: some 20 passes over arrays that stay in the cache (on 1e6 depths the whole
            # arrays go through memory each pass: 2x slower, benchmarks/bench_tips.py); elementwise, the same numbers
            d = np.asarray(d, dtype=float)
            if d.ndim != 1 or d.size <= BLOCK:
                return block(d)
            P, A, est = np.empty_like(d), np.empty_like(d), np.empty_like(d)
            for i in range(0, d.size, BLOCK):
                P[i:i + BLOCK], A[i:i + BLOCK], est[i:i + BLOCK] = block(d[i:i + BLOCK])
            return P, A, est

        def block(d):
            # tip_law_estimate's formula with few fresh arrays (each costs page faults: benchmarks/bench_tips.py):
            # est = FACTOR (r1 (x + r1) + BASE_FORCE x^3), area 2 (RADIUS_FACTOR r1 + BASE_RADIUS x^3), the larger;
            # the law's own arrays are reused once read (never the depths' memory)
            out = law.arrays(d, H, 1.0, nu, derivative=False)
            P0, P1, a = out["P0"], out["P1"], out["radius"]
            A = np.subtract(a, shift)  # c = a - h* H (3.25), then pi c^2
            np.multiply(A, A, out=A)
            A *= np.pi
            x = np.divide(H, a, out=_scratch(a, d))
            r1 = np.divide(P1, P0)
            np.abs(r1, out=r1)
            P = np.add(P0, P1, out=_scratch(P0, d))
            est = np.add(x, r1)
            est *= r1
            x3 = np.multiply(x, x, out=_scratch(P1, d))
            x3 *= x
            r1 *= RADIUS_FACTOR  # r1 becomes the area's estimate
            np.multiply(x3, BASE_RADIUS, out=x)
            r1 += x
            r1 *= 2.0
            x3 *= BASE_FORCE
            est += x3
            est *= FACTOR
            np.maximum(est, r1, out=est)
            return P, A, est

        def slopes(d):
            out = law.arrays(d, H, 1.0, nu)
            P = out["P0"] + out["P1"]
            return d * out["dP"] / P, (out["P1"] - out["P0"]) / P

        def radius(d):
            return law.arrays(d, H, 1.0, nu, derivative=False)["radius"] - shift

        return ForceCurve(self.name, problem.tol, force, radius_law=radius, slopes=slopes)

    def _at(self, problem: Problem, delta0: float) -> tuple[float, float, float, float, dict]:
        """``(P, P0, P1, a, estimate)`` at a depth."""
        law = _law(problem.layer, problem.tip)
        P0, P1 = law.evaluate(delta0, problem.H, problem.mu, nu=problem.nu)
        a = problem.tip.level_set(delta0).radius
        return P0 + P1, P0, P1, a, tip_law_estimate(P0, P1, problem.H / a)

    def run(self, problem: Problem) -> Indentation:
        H, tol = problem.H, problem.tol
        tip = problem.tip
        rim = tip.support_radius
        if problem.force is not None:
            def force_of(d):
                if math.isfinite(rim) and not d < tip.rim_depth:
                    return math.inf
                return self._at(problem, d)[0]

            guess = problem.guess or 1.0
            if math.isfinite(rim):
                guess = min(guess, 0.5 * float(tip.radial_profile(np.array([0.5 * rim]))[0]))
            delta0 = depth_for_force(force_of, problem.force, guess)
        else:
            delta0 = problem.delta0
        P, P0, P1, a, est = self._at(problem, delta0)
        c = a - edge_shift(problem.layer) * H
        if not (P > 0 and math.isfinite(P) and c > 0) or max(est.values()) > tol:
            raise ValidityError(f"solve(): tip-law: estimates force {100 * est['force']:.3g} %, contact radius "
                                f"{100 * est['contact_radius']:.3g} % exceed tol {100 * tol:.3g} % at H/a = "
                                f"{H / a:.3g}", "force", est["force"], tol, "direct")
        vt_AH = P0 / tip.level_set(delta0).volume  # vartheta/(A H): the leading pressure (2.26)

        def pressure(x1, x2):
            phi = tip.profile(x1, x2)
            return np.where(phi < delta0, vt_AH * (delta0 - phi), 0.0)

        return Indentation(layer=problem.layer, punch=tip, delta0=delta0, force=P, H=H, mu=problem.mu, nu=problem.nu,
                           contact_area=math.pi * c * c, contact_radius=c, semi_axes=None, model=self.name, reason="",
                           error_estimate=est, tol=math.inf, detail=_law(problem.layer, tip), _pressure=pressure,
                           _extent=LazyExtent(tip, delta0),
                           extras={"P0": P0, "P1": P1, "level_set_radius": a,
                                   "pressure_order": "leading (2.26): vartheta (delta0 - Phi)/(A H)"})


register_model(TipLawModel)
