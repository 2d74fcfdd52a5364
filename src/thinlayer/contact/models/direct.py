r"""The direct solutions, public name ``"direct"`` (preference 90 and up): three entries, one per kind of tip.

* the flat punch: the exact Fredholm solution (F.6)-(F.7) (:func:`thinlayer.numerics.flat_punch.flat_punch_kappa`);
  it also answers ``model="any-thickness"`` for the flat punch (any ``a/H <= 200``);
* an axisymmetric punch: the spectral solver (:func:`thinlayer.numerics.solve_axisymmetric`, its estimate from a run
  with 0.7 times the modes);
* any other punch: the 2D FFT solver (:func:`thinlayer.numerics.solve_2d`, its estimate the change from a grid of
  0.7 times the cells: an upper bound for a method converging at least linearly in the cell size).
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...asymptotics.solution import DEFAULT_TOL, ValidityError
from ..flat_punch import EQUATIONS
from ..indentation import Indentation
from ..problem import Problem
from .base import ForceCurve, Model, register_model
from .common import depth_for_force, extent_of, fast_size
from .flat import FlatPunchModel, flat_answer, flat_curve

__all__ = ["AxisymmetricDirect", "FFTDirect", "FlatExact", "MAX_CELLS_2D", "direct_solution"]

#: cells per side of the 2D direct solver at most (memory about 1 GB at 1024, see numerics.fft2d.memory_estimate)
MAX_CELLS_2D = 1024


def direct_solution(layer, punch, axisymmetric: bool, delta0, H, mu, nu, refine=False, previous=None, force=None,
                    tol=DEFAULT_TOL, n=None, estimate=True) -> Indentation:
    """The direct numerical solution (axisymmetric spectral or 2D FFT), with its estimate from a coarser run."""
    from ...numerics import solve_2d, solve_axisymmetric
    from ...numerics.fft2d import memory_estimate

    free_nu = nu if layer.numeric_nu is None else None
    if force is not None:
        guess = delta0 if delta0 is not None else 1.0
        delta0 = depth_for_force(lambda d: direct_solution(layer, punch, axisymmetric, d, H, mu, nu, n=n,
                                                           estimate=False).force, force, guess)
    common = dict(layer=layer, punch=punch, delta0=delta0, H=H, mu=mu, nu=nu, model="direct", tol=tol)
    if axisymmetric:
        modes = n
        if refine and previous is not None:
            modes = int(1.4 * previous.modes) + 1
        res = solve_axisymmetric(layer, punch, delta0, H, mu, n=modes, nu=free_nu, error_estimate=estimate)
        c = res.radius
        floor = 1e-9  # the spectral estimate can read zero; the solver's own tolerances are ~1e-12
        est = {"force": max(res.force_error, floor), "contact_radius": max(res.radius_error / c, floor),
               "contact_area": max(2 * res.radius_error / c, floor)}
        why = f"axisymmetric spectral solver, {res.modes} modes (estimate: change from ~0.7x the modes)"
        return Indentation(**common, force=res.force, contact_area=res.contact_area, contact_radius=c,
                           semi_axes=None, reason=why, error_estimate=est, detail=res,
                           _pressure=lambda x1, x2: res.pressure_at(np.hypot(x1, x2)), _extent=1.2 * c)
    # 2D: a square around the overlap {Phi < delta0} (wider near nu = 1/2, where the contact outgrows it), cells
    # resolving H (Delta <= H/7.2, so that the check run at 0.7 times the cells still has Delta <= H/5) and the
    # contact (>= 128 across); widened when the contact reaches the boundary
    half = extent_of(punch, delta0) * (1.15 if nu < 0.4 or not layer.has_incompressible_model else 1.6) + 1.5 * H
    for _ in range(4):
        cells = n
        if cells is None:
            cells = fast_size(max(14.4 * half / H, 128))
            if refine and previous is not None:
                cells = fast_size(1.4 * previous.n)
            if cells > MAX_CELLS_2D and not refine:
                raise ValidityError(
                    f"solve(): the direct 2D solution needs {cells} x {cells} cells to resolve H = {H:.3g} over the "
                    f"contact (half-width {half:.3g}; about {memory_estimate(cells) / 2**30:.1f} GiB) -- more than "
                    f"the {MAX_CELLS_2D} x {MAX_CELLS_2D} allowed; give n= explicitly, or a larger tol for an "
                    "asymptotic model", "force", math.inf, tol, "direct")
        try:
            res = solve_2d(layer, punch, delta0=delta0, H=H, mu=mu, n=cells, extent=half, nu=free_nu)
            if not estimate:
                coarse = res
                break
            coarse = solve_2d(layer, punch, delta0=delta0, H=H, mu=mu, n=fast_size(0.7 * cells), extent=half,
                              nu=free_nu)
            break
        except ValueError as exc:
            if "reaches the boundary" not in str(exc):
                raise
            half *= 1.4
    else:
        raise ValidityError("solve(): the direct 2D solution's contact keeps reaching the domain boundary",
                            "force", math.inf, tol, "direct")
    # error ~ C Delta^p with p >= 1: the fine grid's error is |P_n - P_0.7n|/(0.7^-p - 1) <= 2.34 |P_n - P_0.7n|
    n, nc = cells, coarse.n
    est = {"force": max(2.5 * abs(res.force - coarse.force) / res.force, 1e-9),
           "contact_area": max(2.5 * abs(res.contact_area - coarse.contact_area) / res.contact_area, 1e-9)}
    why = f"2D FFT solver, {n} x {n} cells (estimate: 2.5 x the change from {nc} x {nc})"
    x1, x2 = res.x1, res.x2

    def p(a, b):
        i = np.clip(np.rint((a - x1[0]) / res.spacing).astype(int), 0, x1.size - 1)
        j = np.clip(np.rint((b - x2[0]) / res.spacing).astype(int), 0, x2.size - 1)
        inside = (a >= x1[0] - res.spacing / 2) & (a <= x1[-1] + res.spacing / 2) & \
                 (b >= x2[0] - res.spacing / 2) & (b <= x2[-1] + res.spacing / 2)
        return np.where(inside, res.pressure[i, j], 0.0)

    return Indentation(**common, force=res.force, contact_area=res.contact_area, contact_radius=None,
                       semi_axes=None, reason=why, error_estimate=est, detail=res, _pressure=p, _extent=half)


class FlatExact(FlatPunchModel):
    """The flat punch's exact solution (F.6)-(F.7), any ``a/H <= 200`` (about 1e-10)."""

    name = "direct"
    preference = 90
    asymptotic = False
    selectable = True
    aliases = ("any-thickness",)
    takes_options = None
    law = "direct"
    equations = EQUATIONS["direct"]

    def refined(self, answer: Indentation, problem: Problem, **options: Any) -> Indentation:
        """The exact solution, with 1.4 times the nodes when ``answer`` is itself exact (or ``n`` given)."""
        import dataclasses

        n = options.get("n")
        if n is None and answer.model == "direct":
            from ...numerics.flat_punch import flat_punch_kappa

            n = min(int(1.4 * flat_punch_kappa(answer.layer, answer.H_over_a ** -1, error_estimate=False).nodes),
                    400)
        return flat_answer(dataclasses.replace(problem, tol=math.inf, n=n), "direct")

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        return None if self.refuses(problem) else flat_curve(self.name, problem, "exact")


class _SmoothDirect(Model):
    name = "direct"
    asymptotic = False
    equations = ("1.5-1.8", "1.5-1.8")
    takes_options = None
    axisymmetric = True

    def refuses(self, problem: Problem) -> str | None:
        return "the flat punch's direct solution is its own entry" if problem.tip.fixed_contact else None

    def skips(self, problem: Problem) -> bool:
        """A shape the other direct entry answers: passed over in silence."""
        return self.refuses(problem) is not None or self.applies(problem) is not None

    def shape_reason(self, problem: Problem) -> str | None:
        """None when the punch's symmetry is this solver's, else why not."""
        if problem.tip.axisymmetric != self.axisymmetric:
            return "the punch is not axisymmetric" if self.axisymmetric else "the punch is axisymmetric"
        return None

    def run(self, problem: Problem) -> Indentation:
        return direct_solution(problem.layer, problem.tip, self.axisymmetric, problem.delta0 if problem.force is None
                               else problem.guess, problem.H, problem.mu, problem.nu, force=problem.force,
                               tol=problem.tol, n=problem.n)

    def refined(self, answer: Indentation, problem: Problem, **options: Any) -> Indentation:
        """The direct solution at the answer's depth; refined (1.4 times the modes or cells) if it is direct."""
        refine = answer.model == "direct"
        return direct_solution(answer.layer, answer.punch, self.axisymmetric, answer.delta0, answer.H, answer.mu,
                               answer.nu, refine=refine, previous=answer.detail if refine else None, **options)


class AxisymmetricDirect(_SmoothDirect):
    """The axisymmetric spectral solver."""

    preference = 91
    axisymmetric = True

    def applies(self, problem: Problem) -> str | None:
        return self.shape_reason(problem)


class FFTDirect(_SmoothDirect):
    """The 2D FFT solver (any punch)."""

    preference = 92
    axisymmetric = False

    def applies(self, problem: Problem) -> str | None:
        return self.shape_reason(problem)


register_model(FlatExact)
register_model(AxisymmetricDirect)
register_model(FFTDirect)
