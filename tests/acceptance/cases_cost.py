"""Issue 23: bounded work, enforced by cost and not by shape -- short inputs that ran for minutes, and their cousins.

Every input here must be refused in one line well before the 10 s alarm (the issue's ran 57 s to minutes), or,
for the inputs at the limits, answer.  The refusals are timed: a refusal slower than 2 s counts as a hang too,
because the point is that the work is estimated before it starts.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import sympy as sp

import thinlayer as tl

from ._common import attempt, classify_call, cli_refused, cpu_seconds

CATEGORIES = ("bounded work: formulas", "bounded work: parameters and nu", "bounded work: arrays and files",
              "bounded work: inside the limits")

REFUSE_WITHIN = 2.0


def _refused_fast(fn):
    t0 = cpu_seconds()  # CPU, not wall: the refusal's own work, whatever the machine's load
    outcome, note = classify_call(fn, check=lambda out: ("crash", "accepted a runaway input"))
    took = cpu_seconds() - t0
    if outcome == "clear" and took > REFUSE_WITHIN:
        return "hang", f"refused only after {took:.1f} s of CPU"
    return outcome, note


def run(t, tmp: Path) -> None:
    # the modules first: their import (scipy, seconds on a loaded machine) is not the refusal being timed
    import thinlayer.asymptotics.solution  # noqa: F401
    import thinlayer.contact.any_thickness  # noqa: F401
    import thinlayer.contact.fit  # noqa: F401
    import thinlayer.contact.flat_punch  # noqa: F401

    a, b, c, d, e = sp.symbols("a b c d e")
    x1, x2 = tl.symbols.x1, tl.symbols.x2
    L = tl.BondedLayer(0.3)

    cat = "bounded work: formulas"
    formulas = [
        "x_1**2 + 1e999999*x_2**2", "x_1**2 + 1e-999999*x_2**2", "x_1**2 + 1e309*x_2**2", "x_1**2 + 1e-320*x_2**2",
        "x_1**2 + 1.0e99999999999999999999*x_2**2", "x_1**2*((9**1000)**1000)**30", "x_1**2*(9**1000)**1000",
        "x_1**2 + " + "9" * 3001 + "*x_2**2", "x_1**2 + 2**1000*2**1000*2**1000*2**1000*2**1000*2**1000*2**1000"
        "*2**1000*2**1000*2**1000*2**1000*x_2**2", "x_1**2*(a+b+c+d)**1000 + x_2**2",
        "x_1**2 + x_2**2*(a+b+c+d+e)**200", "(x_1+x_2+a+b+c)**40", "x_1**2/(a+b+c)**500 + x_2**2",
        "x_1**2*((a+b)**30)**30 + x_2**2", "x_1**2*(a+b+c+d+e+f)**9 + x_2**2", "x_1**2*a**999*b + x_2**2",
        "(x_1**2 + x_2**2)*(a+b+c+d+e+f+g+h+i+j)**3",
        " + ".join(f"a{k}*x_1**2" for k in range(300)) + " + x_2**2",
        "x_1**2 + x_2**2 + " + " + ".join(f"p{k}" for k in range(251)),
    ]
    for f in formulas:
        attempt(t, cat, lambda f=f: _refused_fast(lambda: tl.Punch(f)), f[:50])
    # issue 24: max/min of linear forms -- many arguments, deep nesting, huge or tiny numbers, powers of a max
    polyhedral = [
        "max(" + ", ".join(["x1"] * 65) + ")", "max(" + ", ".join(f"{k}*x1 - x2" for k in range(5000)) + ")",
        "max(" * 120 + "x1" + ", -x1)" * 120, "max(x1, -x1, x2, -x2)*1e999999", "max(x1, -x1, x2, -x2)*1e-999999",
        "max(x1, -x1, x2, -x2)*(9**1000)**1000", "max(x1, -x1, x2, -x2)**1000", "max(x1**1000, x2)",
        "max(x1*(a+b+c+d)**1000, -x1, x2, -x2)", "max(x1, -x1, x2, -x2)/0", "min(x1, -x1, x2, -x2)",
        "max(" + "9" * 3001 + "*x1, -x1, x2, -x2)",
        "max(x1, -x1, x2, -x2) + " + " + ".join(f"p{k}" for k in range(251)),
        "max(1e308*x1, -1e308*x1, 1e308*x2, -1e308*x2)*1e308",
    ]
    for f in polyhedral:
        attempt(t, cat, lambda f=f: _refused_fast(lambda: tl.Punch.from_expr(f)), f"from_expr {f[:40]}")
        attempt(t, cat, lambda f=f: _refused_fast(lambda: tl.Punch(f)), f"Punch {f[:45]}")
    for f in formulas[:6]:
        cli_refused(t, cat, ["inner", "--punch", f], tmp)
        g = tmp / "cost.toml"
        g.write_text(f"[derivation]\nname='c'\n[layer]\nnu='3/10'\n[punch]\nexpr='{f}'\n")
        cli_refused(t, cat, ["report", str(g), "--out", str(tmp / "o")], tmp)
    sympy_built = [x1**2 * (a + b + c + d) ** 1000 + x2**2, (x1 + x2 + a + b + c) ** 40,
                   x1**2 * (a + b + c + d + e) ** 8 + x2**2, x1**2 * sp.Integer(9) ** 4000 + x2**2]
    for expr in sympy_built:
        attempt(t, cat, lambda expr=expr: _refused_fast(lambda: tl.Punch(expr)), str(expr)[:50])
    for phi in ((x1 + x2 + 1) ** 1000 + x1**2, x1**100 + x2**2, "(x_1 + x_2 + 1)**1000 + x_1**2"):
        attempt(t, cat, lambda phi=phi: _refused_fast(lambda: tl.contact_contour(phi, 0.1)), f"contour {phi}"[:50])
    attempt(t, cat, lambda: _refused_fast(lambda: tl.force_law(L, tl.Punch(" + ".join(f"a{k}*x_1**2" for k in range(
        13)) + " + x_2**2"))), "quadratic punch with 13 parameters")
    attempt(t, cat, lambda: _refused_fast(lambda: tl.force_law(L, tl.Punch("x_1**2*(a+b)**58 + x_2**2"))),
            "quadratic punch with 60 terms")

    cat = "bounded work: parameters and nu"
    for g in (21, 30, 40):
        attempt(t, cat, lambda g=g: _refused_fast(lambda: tl.Punch.general(g)), f"Punch.general({g})")
    for nu in ("1e-99999999", "1e99999999", "0." + "3" * 5000, "0.1234567", "1234567/10000000", "1e-7",
               "3/" + "7" * 40, "-" + "9" * 200):
        attempt(t, cat, lambda nu=nu: _refused_fast(lambda: tl.BondedLayer(nu)), f"BondedLayer({nu[:20]!r})")
        attempt(t, cat, lambda nu=nu: _refused_fast(lambda: tl.FrictionlessLayer(nu)), f"Frictionless({nu[:20]!r})")
    for v in ("1e999999", "9" * 5000, "(2**1000)**1000"):
        attempt(t, cat, lambda v=v: _refused_fast(lambda: tl.Punch.paraboloid().subs({"R": v})), f"subs R={v[:20]}")
        attempt(t, cat, lambda v=v: _refused_fast(lambda: tl.solve(L, tl.Punch.paraboloid(), delta0=0.1, H=0.05,
                                                                   mu=1.0, parameters={"R": v})), f"R={v[:20]}")
    cli_refused(t, cat, ["solve", "--kind", "paraboloid", "--param", "R=1e999999", "--mu", "1", "--nu", "0.3",
                         "--delta0", "0.1", "--H", "0.05"], tmp)
    cli_refused(t, cat, ["coefficients", "--nu", "1e-99999999/1", "--order", "2"], tmp)

    cat = "bounded work: arrays and files"
    big = np.broadcast_to(0.5, (10**7,))  # a view: no memory, 10 million values
    arrays = {
        "fit 1e7 points (array)": lambda: tl.fit(big, big, punch=10.0, H=1.0),
        "fit 1e6 + 1 points": lambda: tl.fit(np.broadcast_to(0.5, (10**6 + 1,)), np.broadcast_to(1.0, (10**6 + 1,)),
                                             punch=10.0, H=1.0),
        "fit 1e7 sigma": lambda: tl.fit([0.1, 0.2, 0.3], [1.0, 2.0, 3.0], punch=10.0, H=1.0, sigma=big),
        "force_arrays 1e8 depths": lambda: tl.force_arrays(L, tl.Punch.paraboloid(10), np.broadcast_to(0.1, (10**8,)),
                                                           0.05),
        "force_arrays 1e4 x 1e4 grid": lambda: tl.force_arrays(L, tl.Punch.paraboloid(10),
                                                               np.broadcast_to(0.1, (10**4, 1)),
                                                               np.broadcast_to(0.05, (1, 10**4))),
        "flat_punch_stiffness 1e7 (thin)": lambda: tl.flat_punch_stiffness(L, np.broadcast_to(30.0, (10**7,)), "thin"),
        "flat_punch_stiffness 1e4 (exact)": lambda: tl.flat_punch_stiffness(L, np.broadcast_to(1.0, (10**4,))),
        "force_any_thickness 1e9 depths": lambda: tl.force_any_thickness(np.broadcast_to(0.1, (10**9,)), 10.0, 1.0,
                                                                        mu=1.0),
    }
    for name, call in arrays.items():
        attempt(t, cat, lambda call=call: _refused_fast(call), name)
    f = tmp / "huge.csv"
    f.write_text("0.1,1\n" * (10**6 + 2000))
    cli_refused(t, cat, ["fit", str(f), "--R", "10", "--H", "1", "--nu", "0.5"], tmp)

    cat = "bounded work: inside the limits"  # the largest accepted inputs answer, quickly
    ok_inputs = {
        "Punch.general(20)": lambda: tl.Punch.general(20).degree == 20,
        "(a+b)**10 in a punch": lambda: tl.Punch("x_1**2*(a+b)**10 + x_2**2").degree == 2,
        "x_1**40 + x_2**2": lambda: tl.Punch("x_1**40 + x_2**2").degree == 40,
        "nu = '0.499999'": lambda: tl.BondedLayer("0.499999").nu == sp.Rational(499999, 1000000),
        "1e308 and 2.3e-308 literals": lambda: tl.Punch("1e308*x_1**2 + 2.3e-308*x_2**2").degree == 2,
        "a 3000-digit integer": lambda: tl.Punch("x_1**2 + " + "9" * 3000 + "*x_2**2").degree == 2,
        "quadratic punch, 12 parameters": lambda: tl.force_law(L, tl.Punch(" + ".join(
            f"a{k}*x_1**2" for k in range(11)) + " + b*x_2**2")).kind == "quadratic",
    }
    for name, call in ok_inputs.items():
        attempt(t, cat, lambda call=call, name=name: ("clear", "") if call() else ("wrong", name), name)

    def fit_at_limit():
        dd = np.linspace(0.01, 1.0, 10**6)
        P = tl.force_any_thickness(dd, 10.0, 2.0, E=3.0, nu=0.5)
        r = tl.fit(dd, P, punch=10.0, H=2.0)
        return ("clear", "") if abs(r.E / 3.0 - 1) < 1e-9 else ("wrong", f"E = {r.E}")

    attempt(t, cat, fit_at_limit, "fit of 1e6 points")
