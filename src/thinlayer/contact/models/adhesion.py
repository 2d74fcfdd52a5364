r"""The adhesive (JKR) rows of the model registry (issue 26 item 5): ``solve(..., work_of_adhesion=w)``.

* ``"thin-layer-jkr"`` (preference 12, asymptotic): the paraboloid on a bonded layer by the thin-layer JKR law
  (J.11) (``-1 < nu < 1/2``) or (J.15) (``nu = 1/2``) at order 1, with its measured estimate
  :meth:`~thinlayer.asymptotics.adhesion.ThinLayerJKR.error_estimate`; refused below ``c = 5 H``.  For
  ``1/4 < nu < 1/2`` the regime variable (I.13) at the contact radius decides, as in the non-adhesive walk: where it
  says ``"compressible"`` (J.11), else (nearly incompressible, ``lambda^2 = (c/H)^2/m_1`` not large) the two-term
  law (J.22) of :mod:`thinlayer.asymptotics.adhesion_two_term` with its estimate.
* ``"any-thickness"`` (preference 60): the sphere at any thickness, bonded or frictionless base, by the law
  (J.16)-(J.18) of :mod:`thinlayer.contact.adhesion_sphere` (the any-thickness sphere law (T.7) plus the flat punch's
  compliance), where its estimate is within ``tol`` (else the walk goes on to the direct solver).
* ``"direct"`` (preference 95, adhesive): the direct JKR solver (J.1)-(J.6) for the paraboloid and (J.13) for the
  flat-ended cylinder, any thickness, bonded or frictionless base.

Both are ``adhesive`` entries: the walk offers them only problems with a work of adhesion, and offers those
problems no other entry (:mod:`thinlayer.contact.models.walk`).
"""
from __future__ import annotations

import math
from typing import Any

from ..._lazy import lazy_function
from ...asymptotics.solution import ValidityError
from ...layers.kernels import BondedLayer
from ..adhesion import AdhesiveIndentation, NoContactError, PullOff, jkr_radius, relative_estimates, slope
from ..problem import Problem
from .base import Model, register_model

# sympy (the law) and scipy (the direct solver) load when an adhesive problem is solved, not at import: a numeric
# solve() of a paraboloid imports neither (issue 28 item 6, tests/contact/test_cold_start.py)
thin_layer_jkr = lazy_function("thinlayer.asymptotics.adhesion", "thin_layer_jkr")
two_term_jkr = lazy_function("thinlayer.asymptotics.adhesion_two_term", "two_term_jkr")
regime = lazy_function("thinlayer.asymptotics.incompressible", "regime")
adhesive_state = lazy_function("thinlayer.numerics.adhesion", "adhesive_state")
flat_punch_detachment = lazy_function("thinlayer.numerics.adhesion", "flat_punch_detachment")
jkr_curve = lazy_function("thinlayer.numerics.adhesion", "jkr_curve")
any_thickness_jkr = lazy_function("thinlayer.contact.adhesion_sphere", "any_thickness_jkr")

__all__ = ["AnyThicknessJKRModel", "DirectJKRModel", "ThinLayerJKRModel"]

#: the thin-layer law is measured for c >= 5 H only (ThinLayerJKR.error_estimate)
MIN_C_OVER_H = 5.0


def _paraboloid_reason(problem: Problem) -> str | None:
    if problem.tip.fixed_contact or problem.tip.sphere_radius is None:
        return "the JKR law is derived for the paraboloid of revolution r^2/(2R)"
    return None


def _target(problem: Problem) -> tuple[str, float]:
    return ("delta", problem.delta0) if problem.delta0 is not None else ("force", problem.force)


def _pull_off_direct(problem: Problem, c_ref: float):
    """A callable computing the direct JKR curve's pull-off and jump-in around the radius scale ``c_ref``."""
    def compute() -> PullOff:
        w, R, vt = problem.interaction.work_of_adhesion, problem.tip.sphere_radius, problem.mu / (1 - problem.nu)
        a0 = (9 * math.pi * w * R * R / (4 * vt)) ** (1 / 3)  # half-space JKR zero-load radius, E* = 2 vartheta
        top = 2.0 * max(c_ref, a0)
        radii = [top * x for x in (0.01, 0.02, 0.04, 0.07, 0.1, 0.15, 0.22, 0.3, 0.4, 0.55, 0.75, 1.0)]
        cur = jkr_curve(problem.layer, problem.tip, radii, problem.H, problem.mu, work_of_adhesion=w,
                        nu=_nu_arg(problem), n=problem.n)
        lo, dp = cur.pull_off_load, cur.pull_off_displacement
        if lo is None:
            raise ValidityError(f"the load-controlled pull-off lies outside the sampled radii "
                                f"[{radii[0]:.4g}, {radii[-1]:.4g}]", "force")
        ji_d, ji_l = cur.jump_in_displacement, cur.jump_in_load
        return PullOff(-lo.force, lo.radius, None if dp is None else -dp.force, None if dp is None else dp.radius,
                       None if dp is None else dp.delta, None if ji_d is None else ji_d.radius,
                       None if ji_l is None else ji_l.radius, cur)
    return compute


def _nu_arg(problem: Problem) -> float | None:
    return None if problem.layer.numeric_nu is not None else problem.nu


def _answer(problem: Problem, model: str, P: float, delta: float, c: float, est: dict, branch: str,
            equations: tuple, detail: Any, pull_off: Any) -> AdhesiveIndentation:
    if problem.force is not None:  # the given value itself (the root meets it to the solver's tolerance)
        P = problem.force
    else:
        delta = problem.delta0
    return AdhesiveIndentation(layer=problem.layer, punch=problem.tip, H=problem.H, mu=problem.mu, nu=problem.nu,
                               work_of_adhesion=problem.interaction.work_of_adhesion, delta0=float(delta),
                               force=abs(float(P)), tensile=bool(P < 0), contact_radius=float(c), branch=branch,
                               control="displacement" if problem.delta0 is not None else "load", model=model,
                               reason="", error_estimate=est, tol=problem.tol, equations=equations, detail=detail,
                               _pull_off=pull_off)


class _AdhesiveModel(Model):
    adhesive = True
    takes_options = None  # the branch travels in options, read by the adhesive rows only
    parameter_keys = ("mu", "nu", "H", "delta0", "w")
    parameter_names = ("shear modulus", "Poisson ratio", "layer thickness", "indentation depth", "work of adhesion")
    parameter_units = ("Pa", "", "m", "m", "J/m^2")

    def reason(self, answer: Any, tried: list[str], tol: float, named: bool) -> str:
        est = ", ".join(f"{k.replace('_', ' ')} {100 * v:.3g} %" for k, v in answer.error_estimate.items())
        return "; ".join(tried + [f"{self.name}: estimates {est}" + (f" within tol {100 * tol:.3g} %"
                                                                      if self.asymptotic else "")])


def _solve_law(problem: Problem, law: Any) -> tuple[Any, float]:
    """``(law, c)``: the contact radius at which the thin-layer law meets the prescribed depth or force."""
    R, H, mu = problem.tip.sphere_radius, problem.H, problem.mu
    w = problem.interaction.work_of_adhesion
    kind, target = _target(problem)
    idx = 0 if kind == "delta" else 1
    guess = max(MIN_C_OVER_H * H, math.sqrt(2 * R * abs(target)) if kind == "delta" else 10 * H)
    try:
        c = jkr_radius(lambda x: float(law.evaluate(x, H, R, w, mu)[idx]), target, guess, problem.interaction.branch,
                       "depth" if kind == "delta" else "force")
    except NoContactError as exc:  # near the law's pull-off: the direct solver decides
        raise ValidityError(f"solve(): thin-layer-jkr: {exc}", "force", math.inf, problem.tol, "direct") from None
    return law, c


class ThinLayerJKRModel(_AdhesiveModel):
    """The thin-layer JKR law (J.11), (J.15) at order 1 for the paraboloid on a bonded layer; near nu = 1/2 the
    two-term law (J.22) where the regime variable (I.13) says the layer is not compressible.
    """

    name = "thin-layer-jkr"
    preference = 12
    asymptotic = True
    equations = ("J.11", "J.11")

    def refuses(self, problem: Problem) -> str | None:
        return _paraboloid_reason(problem)

    def applies(self, problem: Problem) -> str | None:
        if not problem.layer.has_incompressible_model:
            return "the thin-layer JKR law is derived for a bonded base"
        return None

    def run(self, problem: Problem) -> AdhesiveIndentation:
        nu = problem.nu
        if 0.25 < nu < 0.5:  # the two-term law first; (I.13) at its radius picks (J.11) where compressible
            law, c = _solve_law(problem, two_term_jkr(nu))
            if regime(BondedLayer(nu), problem.H / c).model == "compressible":
                law, c = _solve_law(problem, thin_layer_jkr(nu, 1))
        else:
            law, c = _solve_law(problem, thin_layer_jkr(nu, 1))
        R, H, mu = problem.tip.sphere_radius, problem.H, problem.mu
        w = problem.interaction.work_of_adhesion

        def dP(c: float) -> tuple[float, float]:
            d, P = law.evaluate(c, H, R, w, mu)
            return float(d), float(P)

        kind, _ = _target(problem)
        branch = problem.interaction.branch
        d, P = dP(c)
        tag = law.equation
        if c < MIN_C_OVER_H * H:
            raise ValidityError(f"solve(): thin-layer-jkr: c/H = {c / H:.3g} < {MIN_C_OVER_H:g} (the law's estimate "
                                "is measured for c >= 5 H)", "force", math.inf, problem.tol, "direct")
        ed, eP = (float(x) for x in law.error_estimate(c, H, R, w, mu))
        sd, sP = slope(lambda x: dP(x), c)
        if kind == "delta":
            ec = ed / abs(sd)
            eP = eP + abs(sP) * ec
        else:
            ec = eP / abs(sP)
            ed = ed + abs(sd) * ec
        est = relative_estimates(eP, ed, ec, P, d, c, math.pi * w * R, c * c / R)
        return _answer(problem, self.name, P, d, c, est, branch, (tag, tag), law, _pull_off_direct(problem, c))


def _pull_off_law(law, problem: Problem):
    """A callable computing pull-off and jump-in from the any-thickness JKR law (J.16), (J.6)."""
    def compute() -> PullOff:
        R, H, mu, w = problem.tip.sphere_radius, problem.H, problem.mu, problem.interaction.work_of_adhesion
        c_l, P_l, _ = law.pull_off(H, R, w, mu)
        c_d, P_d, d_d, _ = law.pull_off_displacement(H, R, w, mu)

        def fn(idx: int):
            return lambda x: float(law.evaluate(x, H, R, w, mu)[idx])

        ji = [jkr_radius(fn(k), 0.0, 2.0 * c, "stable", "depth" if k == 0 else "force") for k, c in ((0, c_d),
                                                                                                  (1, c_l))]
        return PullOff(P_l, c_l, P_d, c_d, d_d, ji[0], ji[1], source="any-thickness JKR law (J.16)")
    return compute


class AnyThicknessJKRModel(_AdhesiveModel):
    """The sphere's JKR law at any thickness (J.16)-(J.18): bonded or frictionless base, any ``H/R``."""

    name = "any-thickness"
    preference = 60
    equations = ("J.16", "J.16")
    declines = (ValidityError,)

    def refuses(self, problem: Problem) -> str | None:
        return _paraboloid_reason(problem)

    def applies(self, problem: Problem) -> str | None:
        if not problem.layer.on_rigid_base or not problem.layer.has_thickness:
            return "the any-thickness JKR law is built for a layer on a rigid base"
        return None

    def run(self, problem: Problem) -> AdhesiveIndentation:
        law = any_thickness_jkr(problem.layer, _nu_arg(problem))
        R, H, mu = problem.tip.sphere_radius, problem.H, problem.mu
        w = problem.interaction.work_of_adhesion
        branch = problem.interaction.branch

        def state(c: float):
            return law.states(c, H, R, w, mu)

        kind, target = _target(problem)
        attr = "delta" if kind == "delta" else "force"
        guess = max(0.5 * H, math.sqrt(2 * R * abs(target)) if kind == "delta" else H)
        c = jkr_radius(lambda x: float(getattr(state(x), attr)[0]), target, guess, branch,
                       "depth" if kind == "delta" else "force", xtol=1e-11)
        st = state(c)
        sd, sP = slope(lambda x: (lambda s: (s.delta[0], s.force[0]))(state(x)), c)
        e_d, e_P = float(st.delta_error[0]), float(st.force_error[0])
        if kind == "delta":
            ec = e_d / abs(sd) + 1e-11 * c
            e_P = e_P + abs(sP) * ec
        else:
            ec = e_P / abs(sP) + 1e-11 * c
            e_d = e_d + abs(sd) * ec
        est = relative_estimates(e_P, e_d, ec, st.force[0], st.delta[0], c, math.pi * w * R, c * c / R)
        if max(est.values()) > problem.tol:
            words = ", ".join(f"{k.replace('_', ' ')} {100 * v:.3g} %" for k, v in est.items())
            raise ValidityError(f"solve(): any-thickness: estimates {words} exceed tol {100 * problem.tol:.3g} %",
                                "force", max(est.values()), problem.tol, "direct")
        return _answer(problem, self.name, st.force[0], st.delta[0], c, est, branch, ("J.16", "J.16"), st,
                       _pull_off_law(law, problem))


class DirectJKRModel(_AdhesiveModel):
    """The direct JKR solver (J.1)-(J.6) for the paraboloid, (J.13) for the flat punch; any thickness."""

    name = "direct"
    preference = 95
    equations = ("J.5", "J.5")
    selectable = True

    def refuses(self, problem: Problem) -> str | None:
        if problem.tip.fixed_contact:
            return None
        return _paraboloid_reason(problem)

    def applies(self, problem: Problem) -> str | None:
        return None

    def run(self, problem: Problem) -> AdhesiveIndentation:
        if problem.tip.fixed_contact:
            return self._flat(problem)
        R, H, mu, nu = problem.tip.sphere_radius, problem.H, problem.mu, _nu_arg(problem)
        w = problem.interaction.work_of_adhesion
        branch = problem.interaction.branch

        def state(c: float, energy: bool = False):
            return adhesive_state(problem.layer, problem.tip, c, H, mu, work_of_adhesion=w, nu=nu, n=problem.n,
                                  energy_route=energy)

        kind, target = _target(problem)
        attr = "delta" if kind == "delta" else "force"
        guess = max(0.5 * H, math.sqrt(2 * R * abs(target)) if kind == "delta" else H)
        c = jkr_radius(lambda x: getattr(state(x), attr), target, guess, branch, "depth" if kind == "delta" else
                       "force", xtol=1e-10)
        st = state(c, energy=True)
        sd, sP = slope(lambda x: (lambda s: (s.delta, s.force))(state(x)), c)
        if kind == "delta":
            ec = st.delta_error / abs(sd) + 1e-10 * c
            eP, ed = st.force_error + abs(sP) * ec, st.delta_error
        else:
            ec = st.force_error / abs(sP) + 1e-10 * c
            eP, ed = st.force_error, st.delta_error + abs(sd) * ec
        est = relative_estimates(eP, ed, ec, st.force, st.delta, c, math.pi * w * R, c * c / R)
        return _answer(problem, self.name, st.force, st.delta, c, est, branch, ("J.5", "J.5"), st,
                       _pull_off_direct(problem, c))

    def _flat(self, problem: Problem) -> AdhesiveIndentation:
        """(J.13): the contact is the face until the load reaches the detachment force (unstable beyond)."""
        a = float(problem.tip.radius)
        det = flat_punch_detachment(problem.layer, a, problem.H, problem.mu,
                                    work_of_adhesion=problem.interaction.work_of_adhesion, nu=_nu_arg(problem))
        S = 4.0 * det.vartheta * a * det.kappa
        if problem.delta0 is not None:
            d, P = problem.delta0, S * problem.delta0
            if d < det.depth:
                raise ValidityError(f"solve(): the flat punch has come off: depth {d:.6g} below the detachment "
                                    f"depth {det.depth:.6g} (J.13)", "force", math.inf, problem.tol, "direct")
        else:
            P, d = problem.force, problem.force / S
            if P < -det.force:
                raise ValidityError(f"solve(): the flat punch has come off: a pull of {-P:.6g} exceeds the "
                                    f"detachment force {det.force:.6g} (J.13)", "force", math.inf, problem.tol,
                                    "direct")
        est = {"force": det.error, "depth": det.error, "contact_radius": 0.0}
        po = PullOff(det.force, a, det.force, a, det.depth, None, None, source="flat punch (J.13)")
        return _answer(problem, self.name, P, d, a, est, "stable", ("J.13", "F.1"), det, lambda: po)


register_model(ThinLayerJKRModel)
register_model(AnyThicknessJKRModel)
register_model(DirectJKRModel)
