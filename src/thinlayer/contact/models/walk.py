r"""The walk over the model registry: which model answers, and why (``solve(model=...)``).

``model="auto"`` walks every entry in increasing preference and keeps the first answer whose estimate is within
``tol``; ``"asymptotic"`` walks the asymptotic entries only and refuses instead of the direct solver; a public
name runs the first entry of that name that applies.  The answer's ``reason`` names each model tried and why it
was passed over (the estimates, or why it does not apply).
"""
from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from ...asymptotics.solution import DEFAULT_TOL, ValidityError
from ...errors import InputError, InputTypeError, ThinlayerError
from ..problem import Depth, Elastic, Frictionless, Problem
from .base import MODEL_REGISTRY, Model, entries_named, estimate_ok, fmt_est

__all__ = ["direct_comparison", "entry_of", "problem_of", "walk"]


def _with_reason(ans: Any, why: str, tol: float, entry: Model) -> Any:
    return dataclasses.replace(ans, reason=why, tol=tol, entry=entry)


def _option_owner() -> str:
    return " or ".join(dict.fromkeys(m.name for m in MODEL_REGISTRY if m.takes_options)) or "no"


def _options_for(entry: Model, problem: Problem, named: bool) -> Problem:
    """The problem with the options this entry gets: all of them if it takes them or was named, else none."""
    if entry.takes_options is None:
        return dataclasses.replace(problem, options={})
    opts = problem.options if entry.takes_options or named else {}
    if opts and not entry.takes_options:
        raise InputTypeError(f"the options {sorted(opts)} belong to the {_option_owner()} model, not {entry.name}")
    return dataclasses.replace(problem, options=opts)


def _try_asymptotic(entry: Model, problem: Problem, tried: list[str], named: bool) -> tuple[Any, float | None]:
    """``(answer within tol or None, the depth of an answer beyond tol or None)``; the tried list grows."""
    name, tol = entry.name, problem.tol
    problem = _options_for(entry, problem, named)
    why = entry.applies(problem)
    if why is not None:
        tried.append(f"{name}: {why}")
        if named:
            raise ValidityError(f"solve(): the {name} model does not apply: {why}", "force", math.inf, tol, "direct")
        return None, None
    try:
        ans = entry.run(problem)
    except ValidityError as exc:
        # beyond the double range where the model holds: no other model would do better (where it does not
        # hold, e.g. delta0 = 1e-300 with H/a = 1e148, the next model answers or gives the true reason)
        if exc.model == "other units" and exc.estimate <= tol:
            raise
        tried.append(f"{name}: " + str(exc).replace("solve(): ", "").removeprefix(f"{name}: "))
        if named:
            raise
        return None, None
    except (ArithmeticError, ValueError) as exc:
        if isinstance(exc, ThinlayerError):
            raise
        # the model's own numbers left the double range (e.g. R = 1e-199: R delta0 underflows): the next model
        tried.append(f"{name}: no answer at these numbers ({type(exc).__name__}: {exc})")
        if named:
            raise ValidityError(f"solve(): the {name} model has no answer at these numbers ({type(exc).__name__}: "
                                f"{exc}); use model='auto' or other units", "force") from None
        return None, None
    if estimate_ok(ans.error_estimate, tol):
        return _with_reason(ans, entry.reason(ans, tried, tol, named), tol, entry), None
    tried.append(f"{name}: estimates {fmt_est(ans.error_estimate)} exceed tol {100 * tol:.3g} %")
    if named:
        raise ValidityError(f"solve(): the {name} model's {tried[-1].split(': ', 1)[1]} (H/a = "
                            f"{ans.H_over_a:.3g}); use model='auto' or model='direct'", "force",
                            max(ans.error_estimate.values()), tol, "direct")
    return None, ans.delta0


def _named(problem: Problem, choice: str) -> Any:
    candidates = entries_named(choice, problem.interaction.adhesive)
    if not candidates:
        raise InputError(f"no model named {choice!r} is registered")
    live = [m for m in candidates if m.refuses(problem) is None]
    if not live:
        raise InputError(candidates[0].refuses(problem))
    entry = next((m for m in live if m.applies(problem) is None), live[0])
    if entry.asymptotic:
        ans, _ = _try_asymptotic(entry, problem, [], named=True)
        return ans
    problem = _options_for(entry, problem, named=True)
    why = entry.applies(problem)
    if why is not None:
        raise ValidityError(f"solve(): the {entry.name} model does not apply: {why}", "force", math.inf,
                            problem.tol, "direct")
    ans = entry.run(problem)
    return _with_reason(ans, entry.reason(ans, [], problem.tol, True), problem.tol, entry)


def walk(problem: Problem, choice: str) -> Any:
    """The answer of the first entry that holds (``choice``: ``"auto"``, ``"asymptotic"`` or a public name)."""
    if choice not in ("auto", "asymptotic"):
        return _named(problem, choice)
    tol = problem.tol
    tried: list[str] = []
    guess = None
    for entry in list(MODEL_REGISTRY):
        if not entry.solves or entry.adhesive != problem.interaction.adhesive \
                or entry.viscoelastic != problem.material.viscoelastic or entry.skips(problem) \
                or (choice == "asymptotic" and not entry.asymptotic):
            continue
        if entry.asymptotic:
            ans, depth = _try_asymptotic(entry, problem, tried, named=False)
            if ans is not None:
                return ans
            guess = guess or depth  # a depth for the direct solver's inverse problem to start from
            continue
        if entry.applies(problem) is not None:
            continue
        try:
            with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):
                ans = entry.run(dataclasses.replace(problem, options={}, guess=guess))
        except entry.declines as exc:
            if getattr(exc, "model", "") == "other units":  # the model holds here: no other model does better
                raise
            tried.append(f"{entry.name}: " + str(exc).replace("solve(): ", ""))
            continue
        return _with_reason(ans, entry.reason(ans, tried, tol, False), tol, entry)
    raise ValidityError("solve(): no asymptotic model holds to tol = " + f"{100 * tol:.3g} % -- "
                        + "; ".join(tried) + "; use model='auto' or 'direct'", "force", math.inf, tol, "direct")


# =============================================================================================
# an answer's own problem and entry (Indentation.equations, Indentation.compare_direct)
# =============================================================================================
def problem_of(ans: Any, tol: float = DEFAULT_TOL, n: int | None = None) -> Problem:
    """The problem an answer solved (at its depth)."""
    return Problem(ans.layer, ans.punch, Elastic(ans.mu, ans.nu), Frictionless(), Depth(ans.delta0), ans.H, tol, n)


def _first_applying(name: str, problem: Problem) -> Model | None:
    for m in entries_named(name):
        if m.refuses(problem) is None and m.applies(problem) is None:
            return m
    return None


def entry_of(ans: Any) -> Model | None:
    """The registry entry that gave an answer (the one it carries, else the first of its name that applies)."""
    if getattr(ans, "entry", None) is not None:
        return ans.entry
    problem = problem_of(ans)
    m = _first_applying(ans.model, problem)
    if m is None:
        m = next((e for e in entries_named(ans.model) if e.refuses(problem) is None), None)
    return m


def direct_comparison(ans: Any, **options: Any) -> Any:
    """The direct solution of an answer's problem (refined when the answer is itself direct)."""
    problem = problem_of(ans)
    entry = _first_applying("direct", problem)
    if entry is None:
        raise InputError(f"no direct solver answers {ans.punch!r}")
    return entry.refined(ans, problem, **options)
