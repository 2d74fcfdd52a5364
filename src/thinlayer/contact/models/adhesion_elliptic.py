r"""The adhesive (JKR) rows of the elliptic paraboloid (issue 26 item 6): ``solve(Punch.elliptic_paraboloid(R1, R2),
..., work_of_adhesion=w)``.

* ``"thin-layer-jkr"`` (preference 13, asymptotic): the thin-layer law of
  :mod:`thinlayer.asymptotics.adhesion_elliptic` at order 1 ((J.25)-(J.28) with the edge's curvature correction
  (J.30)) on a compressible layer (bonded ``-1 < nu < 1/2``, or lying on the base without friction), at a given depth
  or force (both branches under load control), with its estimate (J.31);
  refused where the smaller semi-axis is below ``5 H`` (the law's validity flag) and, for a bonded layer with
  ``1/4 < nu < 1/2``, where the regime variable (I.13) at the smaller semi-axis does not say ``"compressible"``.
* ``"direct"`` (preference 96, adhesive): the 2D JKR reference (D.12), (D.13) of
  :mod:`thinlayer.numerics.cohesive_jkr` (Richardson in ``lambda^-2`` of the grid's Maugis-Dugdale states, with the
  grid's and the axisymmetric analog's estimates), at a given depth only (at a given force it would need a root of
  expensive 2D states: refused, one line).  The square holds the cohesive zone at lambda = 2 (its outer radius on the
  axisymmetric analog, stretched to the long axis); ``n`` (default: cells no wider than ``H/5``, 128 at least) above
  512 is refused before the grid solves start.  It costs 0.5-3 min of CPU at n = 128-256 (four grid solves of n and
  n/2 cells).

The sphere (``R1 = R2``) is the rows of :mod:`thinlayer.contact.models.adhesion`; both kinds of row refuse the other's
punch, so ``model="thin-layer-jkr"`` or ``"direct"`` names the right one.
"""
from __future__ import annotations

import math
from typing import Any

from ..._lazy import lazy_function
from ...asymptotics.solution import ValidityError
from ...errors import InputError
from ...layers.kernels import BondedLayer
from ..adhesion import AdhesiveIndentation, PullOff, relative_estimates
from ..problem import Problem
from .base import Model, register_model

elliptic_jkr = lazy_function("thinlayer.asymptotics.adhesion_elliptic", "elliptic_jkr")
regime = lazy_function("thinlayer.asymptotics.incompressible", "regime")
jkr_limit_2d = lazy_function("thinlayer.numerics.cohesive_jkr", "jkr_limit_2d")
axisymmetric_analog = lazy_function("thinlayer.numerics.cohesive_jkr", "axisymmetric_analog")

__all__ = ["EllipticDirectJKRModel", "EllipticJKRModel"]

#: cells per side of the 2D JKR reference at most (four Maugis-Dugdale grid solves; n = 512 takes ~20 min of CPU)
MAX_CELLS_JKR_2D = 512


def _radii(problem: Problem) -> tuple[float, float] | None:
    """``(R1, R2)`` (``R1 < R2``) of an elliptic paraboloid (a numeric quadric with unequal curvatures), else None."""
    tip = problem.tip
    q = None if tip.fixed_contact else tip.quadric
    if q is None or q[0] == q[1]:
        return None
    return 1.0 / q[1], 1.0 / q[0]


def _elliptic_reason(problem: Problem) -> str | None:
    if _radii(problem) is None:
        return "the elliptic JKR rows are for the elliptic paraboloid x1^2/(2 R1) + x2^2/(2 R2) with R1 != R2"
    return None


def _nu_arg(problem: Problem) -> float | None:
    return None if problem.layer.numeric_nu is not None else problem.nu


def _answer(problem: Problem, model: str, state: Any, est: dict, branch: str, equations: tuple, detail: Any,
            pull_off: Any) -> AdhesiveIndentation:
    P = problem.force if problem.force is not None else state.force
    delta = problem.delta0 if problem.delta0 is not None else state.delta
    return AdhesiveIndentation(layer=problem.layer, punch=problem.tip, H=problem.H, mu=problem.mu, nu=problem.nu,
                               work_of_adhesion=problem.interaction.work_of_adhesion, delta0=float(delta),
                               force=abs(float(P)), tensile=bool(P < 0),
                               contact_radius=math.sqrt(state.a1 * state.a2), branch=branch,
                               control="displacement" if problem.delta0 is not None else "load", model=model,
                               reason="", error_estimate=est, tol=problem.tol, equations=equations, detail=detail,
                               _pull_off=pull_off)


class _EllipticAdhesive(Model):
    adhesive = True
    takes_options = None
    parameter_keys = ("mu", "nu", "H", "delta0", "w")
    parameter_names = ("shear modulus", "Poisson ratio", "layer thickness", "indentation depth", "work of adhesion")
    parameter_units = ("Pa", "", "m", "m", "J/m^2")

    def refuses(self, problem: Problem) -> str | None:
        return _elliptic_reason(problem)

    def reason(self, answer: Any, tried: list[str], tol: float, named: bool) -> str:
        est = ", ".join(f"{k.replace('_', ' ')} {100 * v:.3g} %" for k, v in answer.error_estimate.items())
        return "; ".join(tried + [f"{self.name}: estimates {est}" + (f" within tol {100 * tol:.3g} %"
                                                                      if self.asymptotic else "")])


def _estimates(s: Any, wv: float, R: float, dP_dd: float, dc_dd: float, load: bool) -> dict:
    """Relative estimates ``{"force", "depth", "contact_radius"}`` of a law state (J.29), under either control."""
    c = math.sqrt(s.a1 * s.a2)
    ec = 0.5 * c * (s.a1_error / s.a1 + s.a2_error / s.a2)  # the equal-area radius sqrt(a1 a2)
    if load:  # the force is given: its error moves the depth by eP/|dP/d delta|, and the contact with it
        ed = s.force_error / abs(dP_dd) if dP_dd != 0 else math.inf
        return relative_estimates(0.0, ed, ec + abs(dc_dd) * ed, s.force, s.delta, c, math.pi * wv * R, c * c / R)
    return relative_estimates(s.force_error, 0.0, ec, s.force, s.delta, c, math.pi * wv * R, c * c / R)


class EllipticJKRModel(_EllipticAdhesive):
    """The elliptic paraboloid's thin-layer JKR law at order 1 (J.30), (J.31) on a compressible layer."""

    name = "thin-layer-jkr"
    preference = 13
    asymptotic = True
    equations = ("J.31", "J.30")

    def applies(self, problem: Problem) -> str | None:
        layer = problem.layer
        if not layer.has_thickness or not layer.on_rigid_base or layer.A is None or not float(layer.A) > 0:
            return "the elliptic thin-layer JKR law (J.25)-(J.29) is derived for compressible layers (A > 0)"
        return None

    def run(self, problem: Problem) -> AdhesiveIndentation:
        R1, R2 = _radii(problem)
        H, mu, wv = problem.H, problem.mu, problem.interaction.work_of_adhesion
        law = elliptic_jkr(problem.layer, nu=_nu_arg(problem), order=1)
        branch = problem.interaction.branch
        try:
            if problem.delta0 is not None:
                if branch != "stable":
                    raise ValidityError("solve(): thin-layer-jkr: under displacement control the law's contact grows "
                                        "with the depth (J.28): it has no unstable branch", "force", math.inf,
                                        problem.tol, "direct")
                s = law.state(problem.delta0, H, R1, R2, wv, mu)
            else:
                s = law.state_at_force(problem.force, H, R1, R2, wv, mu, branch)
        except InputError as exc:  # no contact in the law (near or beyond its pull-off): the direct solver decides
            raise ValidityError(f"solve(): thin-layer-jkr: {exc}", "force", math.inf, problem.tol, "direct") from None
        if not s.valid:
            raise ValidityError(f"solve(): thin-layer-jkr: {s.reason}", "force", math.inf, problem.tol, "direct")
        nu = problem.nu
        if problem.layer.has_incompressible_model and 0.25 < nu < 0.5 \
                and regime(BondedLayer(nu), H / min(s.a1, s.a2)).model != "compressible":
            raise ValidityError(f"solve(): thin-layer-jkr: nearly incompressible (nu = {nu:g}): the regime variable "
                                f"(I.13) at the smaller semi-axis is not 'compressible'", "force", math.inf,
                                problem.tol, "direct")
        R = math.sqrt(R1 * R2)
        step = 1e-6 * max(abs(s.delta), s.level)
        try:
            hi, lo = (law.state(s.delta + sg * step, H, R1, R2, wv, mu) for sg in (1, -1))
            dP_dd = (hi.force - lo.force) / (2 * step)
            dc_dd = (math.sqrt(hi.a1 * hi.a2) - math.sqrt(lo.a1 * lo.a2)) / (2 * step)
        except InputError:
            dP_dd, dc_dd = 0.0, 0.0  # at the edge of the law's range: the depth at a given force is not determined
        est = _estimates(s, wv, R, dP_dd, dc_dd, problem.force is not None)

        def pull_off() -> PullOff:
            try:
                off = law.pull_off(H, R1, R2, wv, mu)
                touch = law.state(0.0, H, R1, R2, wv, mu)
                zero = law.state_at_force(0.0, H, R1, R2, wv, mu)
            except InputError as exc:
                raise ValidityError(f"solve(): the elliptic thin-layer law: {exc}", "force", math.inf, problem.tol,
                                    "direct") from None
            if not off.valid:
                raise ValidityError(f"solve(): the elliptic thin-layer law does not hold at its pull-off here: "
                                    f"{off.reason}", "force", math.inf, problem.tol, "direct")
            return PullOff(-off.force, math.sqrt(off.a1 * off.a2), None, None, None,
                           math.sqrt(touch.a1 * touch.a2), math.sqrt(zero.a1 * zero.a2),
                           source="elliptic thin-layer JKR law at order 1 (J.31); equal-area radii sqrt(a1 a2)")
        return _answer(problem, self.name, s, est, branch, self.equations, s, pull_off)


def _check_cells(n: int, tol: float) -> None:
    """Refuse (one line, before the grid solves) more than ``MAX_CELLS_JKR_2D`` cells per side."""
    if n > MAX_CELLS_JKR_2D:
        raise ValidityError(f"solve(): the 2D JKR reference with n = {n} cells per side would take hours (four "
                            f"Maugis-Dugdale grid solves); at most n = {MAX_CELLS_JKR_2D}", "force", math.inf, tol,
                            "direct")


class EllipticDirectJKRModel(_EllipticAdhesive):
    """The 2D JKR reference (D.12), (D.13) for the elliptic paraboloid, at a given depth."""

    name = "direct"
    preference = 96
    equations = ("D.12", "D.12")
    declines = (ValidityError,)

    def applies(self, problem: Problem) -> str | None:
        return None

    def run(self, problem: Problem) -> AdhesiveIndentation:
        if problem.delta0 is None:
            raise ValidityError("solve(): the 2D JKR reference (D.12) answers at a given depth (delta0=) only: at a "
                                "given force it would need a root of 2D states of minutes each", "force", math.inf,
                                problem.tol, "direct")
        if problem.interaction.branch != "stable":
            raise ValidityError("solve(): the 2D JKR reference (D.12) gives the state at a given depth (displacement "
                                "control, stable)", "force", math.inf, problem.tol, "direct")
        if problem.n is not None:
            _check_cells(problem.n, problem.tol)
        R1, R2 = _radii(problem)
        R = math.sqrt(R1 * R2)
        H = problem.H if problem.layer.has_thickness else None
        wv, mu, nu = problem.interaction.work_of_adhesion, problem.mu, _nu_arg(problem)
        lambdas = (2.0, 3.0)
        # the square must hold the cohesive zone at the smaller lambda: its outer radius on the mean-curvature
        # paraboloid (the analog, D.13), stretched to the long axis by (R2/R)^(2/3) (>= the thin layer's sqrt(R2/R))
        try:
            from ...numerics.cohesive import maugis_dugdale, maugis_lambda  # rank 4, on use (scipy)
            from ...punch import Punch

            vt = mu / (1.0 - problem.nu)
            st = maugis_dugdale(problem.layer, Punch.paraboloid(R=R), H, mu, w=wv,
                                h0=maugis_lambda(R, 2 * vt, wv, 1.0) / lambdas[0], delta0=problem.delta0, nu=nu,
                                error_estimate=False)
            extent = 1.25 * st.zone_radius * (R2 / R) ** (2.0 / 3.0)
            # cells no wider than H/5 (the grid solver's own limit), 128 at least
            n = problem.n or max(128, 2 * math.ceil(5.0 * extent / H) if H is not None else 0)
            _check_cells(n, problem.tol)
            ref = jkr_limit_2d(problem.layer, problem.tip, problem.delta0, H, mu, w=wv, extent=extent, n=n, nu=nu,
                               lambdas=lambdas)
        except InputError as exc:
            raise ValidityError(f"solve(): direct (2D JKR reference): {exc}", "force", math.inf, problem.tol,
                                "direct") from None
        c = math.sqrt(ref.a1 * ref.a2)
        ec = 0.5 * c * (ref.a1_error / ref.a1 + ref.a2_error / ref.a2)
        est = relative_estimates(ref.force_error, 0.0, ec, ref.force, problem.delta0, c, math.pi * wv * R, c * c / R)

        def pull_off() -> PullOff:
            raise ValidityError("solve(): the 2D JKR reference gives no pull-off (a minimum over 2D states of "
                                "minutes each); the thin-layer law's (J.28) holds on thin compressible layers",
                                "force", math.inf, problem.tol, "direct")
        return _answer(problem, self.name, ref, est, "stable", self.equations, ref, pull_off)


register_model(EllipticJKRModel)
register_model(EllipticDirectJKRModel)
