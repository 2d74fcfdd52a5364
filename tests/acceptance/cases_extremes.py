"""Issue 23: exceptions at extremes -- thinlayer's own one-line errors, or answers an independent route confirms.

The issue met ``ZeroDivisionError`` (R = 1e-199), ``NotImplementedError`` (order=3), scipy's "function value is
NaN" (delta0 = 1e300), "math domain error" (force = 1e-300), a message about mu's unit at delta0 = 1e-300, and a
flat punch of radius 1e-300 answered with zero area.  Answers at extremes are held against Hertz's closed form
``P = (8/3) mu/(1 - nu) sqrt(R) delta0^(3/2)`` (the half-space: H/a >> 1) and Boussinesq's flat punch
``P = 4 mu a w0/(1 - nu)``; no numpy warning may leak.
"""
from __future__ import annotations

import math
import warnings
from fractions import Fraction
from pathlib import Path

import numpy as np

import thinlayer as tl

from ._common import attempt, classify_call, positive_finite

CATEGORIES = ("exceptions at extremes: solve", "exceptions at extremes: other doors",
              "answers at extremes (against Hertz)")

VALUES = (1e-300, 1e-199, 1e300, math.inf, math.nan, 0, -1.0, 10**400, Fraction(1, 3), np.float64(0.2), True, None,
          np.array([0.1, 0.2]))


def _hertz(R: float, d0: float, mu: float = 1.0, nu: float = 0.3) -> float:
    return 8.0 / 3.0 * mu / (1.0 - nu) * math.sqrt(R) * d0**1.5


def _quiet(fn):
    """``fn()`` with numpy's warnings turned into failures (a leak is a crash)."""
    def call():
        with warnings.catch_warnings():
            warnings.simplefilter("error", RuntimeWarning)
            warnings.simplefilter("ignore", tl.errors.ValidityWarning)
            return fn()
    return call


def _answer_ok(ans) -> tuple[str, str]:
    valid = getattr(ans, "valid", None)
    if isinstance(valid, np.ndarray):  # force_arrays: NaN exactly where flagged invalid, positive finite elsewhere
        f = np.asarray(ans.force, dtype=float)
        ok = np.all(np.isnan(f[~valid])) and np.all(np.isfinite(f[valid]) & (f[valid] > 0))
        return ("clear", "") if ok else ("wrong", f"force {f} where valid {valid}")
    force = getattr(ans, "force", None)
    if force is not None and not positive_finite(float(np.min(force)), float(np.max(force))):
        return "wrong", f"force {force}"
    area = getattr(ans, "contact_area", None)
    if area is not None and not positive_finite(float(np.min(area))):
        return "wrong", f"contact area {area}"
    return "clear", ""


def run(t, tmp: Path) -> None:
    L = tl.BondedLayer(0.3)
    S = tl.Punch.paraboloid(10)

    cat = "exceptions at extremes: solve"
    solve_args = {
        "delta0": lambda v: tl.solve(L, S, delta0=v, H=0.05, mu=1.0),
        "H": lambda v: tl.solve(L, S, delta0=0.1, H=v, mu=1.0),
        "mu": lambda v: tl.solve(L, S, delta0=0.1, H=0.05, mu=v),
        "force": lambda v: tl.solve(L, S, force=v, H=0.05, mu=1.0),
        "R": lambda v: tl.solve(L, tl.Punch.paraboloid(v), delta0=0.1, H=0.05, mu=1.0),
        "a (flat)": lambda v: tl.solve(L, tl.Punch.flat(v), delta0=0.1, H=0.05, mu=1.0),
    }
    for arg, call in solve_args.items():
        for v in VALUES:
            attempt(t, cat, lambda call=call, v=v: classify_call(_quiet(lambda: call(v)), check=_answer_ok),
                    f"solve({arg}={v!r:.20})")
    issue = {
        "R = 1e-199 with tiny delta0 and H": lambda: tl.solve(L, tl.Punch.paraboloid(1e-199), delta0=1e-200,
                                                              H=1e-201, mu=1.0),
        "order=3": lambda: tl.solve(L, S, delta0=0.1, H=0.05, mu=1.0, order=3),
        "delta0 = 1e300": lambda: tl.solve(L, S, delta0=1e300, H=0.05, mu=1.0),
        "delta0 = 1e-300": lambda: tl.solve(L, S, delta0=1e-300, H=0.05, mu=1.0),
        "flat punch a = 1e-300": lambda: tl.solve(L, tl.Punch.flat(1e-300), delta0=0.1, H=0.05, mu=1.0),
        "E = 1e308 (mu overflows)": lambda: tl.solve(L, S, delta0=0.1, H=0.05, E=1.7e308),
    }
    for name, call in issue.items():
        attempt(t, cat, lambda call=call: classify_call(_quiet(call), check=_answer_ok), name)

    cat = "exceptions at extremes: other doors"
    d = np.linspace(0.05, 1.0, 8)
    P = tl.force_any_thickness(d, 10.0, 2.0, E=3.0, nu=0.5)
    others = {
        "fit(H=)": lambda v: tl.fit(d, P, punch=10.0, H=v),
        "fit(punch=)": lambda v: tl.fit(d, P, punch=v, H=2.0),
        "fit(delta[0]=)": lambda v: tl.fit([v, *d[1:]], P, punch=10.0, H=2.0),
        "force_arrays(H=)": lambda v: tl.force_arrays(L, S, [0.1], v),
        "solve_axisymmetric(H=)": lambda v: tl.solve_axisymmetric(L, S, 0.1, v, n=24, error_estimate=False),
        "flat_punch_stiffness(a/H, thin)": lambda v: tl.flat_punch_stiffness(L, v, "thin"),
    }
    for name, call in others.items():
        for v in (1e-300, 1e300, math.inf, math.nan, 0, -1.0, 10**400, None, True):
            attempt(t, cat, lambda call=call, v=v: classify_call(_quiet(lambda: call(v)), check=_answer_ok),
                    f"{name}{v!r:.20}")

    cat = "answers at extremes (against Hertz)"

    def tiny_depth(d0):
        ans = tl.solve(L, S, delta0=d0, H=0.05, mu=1.0)
        chi = math.sqrt(10 * d0) / 0.05  # the thick-layer term is below 1.2 chi: within it of Hertz
        ok = abs(ans.force / _hertz(10, d0) - 1) <= 1.2 * chi + 1e-9
        return ("clear", "") if ok else ("wrong", f"delta0 = {d0}: {ans.force} vs Hertz {_hertz(10, d0)}")

    for d0 in (1e-200, 1e-100, 1e-30, 1e-12):
        attempt(t, cat, lambda d0=d0: tiny_depth(d0), f"delta0 = {d0}")

    def tiny_force(P0):
        ans = tl.solve(L, S, force=P0, H=0.05, mu=1.0)
        d_h = (P0 / (8 / 3 / 0.7 * math.sqrt(10))) ** (2 / 3)
        ok = ans.force == P0 and abs(ans.delta0 / d_h - 1) <= 1.2 * math.sqrt(10 * d_h) / 0.05 + 1e-9
        return ("clear", "") if ok else ("wrong", f"force {P0}: depth {ans.delta0} vs Hertz {d_h}")

    for P0 in (1e-300, 1e-200, 1e-40):
        attempt(t, cat, lambda P0=P0: tiny_force(P0), f"force = {P0}")

    def thick(H):
        ans = tl.solve(L, S, delta0=0.1, H=H, mu=1.0)
        chi = 1.0 / H
        ok = abs(ans.force / _hertz(10, 0.1) - 1) <= 1.2 * chi + 1e-9
        return ("clear", "") if ok else ("wrong", f"H = {H}: {ans.force}")

    for H in (1e4, 1e8, 1e100, 1e300):
        attempt(t, cat, lambda H=H: thick(H), f"H = {H}")

    def flat(a):
        ans = tl.solve(L, tl.Punch.flat(a), delta0=0.1, H=0.05, mu=1.0)
        ok = abs(ans.force / (4 * a * 0.1 / 0.7) - 1) <= 2 * a / 0.05 + 1e-9  # kappa = 1 + O(a/H)
        return ("clear", "") if ok else ("wrong", f"a = {a}: {ans.force}")

    for a in (1e-100, 1e-20, 1e-8):
        attempt(t, cat, lambda a=a: flat(a), f"flat a = {a}")
