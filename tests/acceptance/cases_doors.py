"""Issue 23: code execution through every door -- parameters=, Punch.subs, the layer constructors, fit, CSV cells.

The first round drove the formula doors (the punch, ``--punch``, ``--param``, ``expr``); the hole it missed was a
value: ``parameters={'R': "__import__('os').system(...) or 10"}`` reached sympy's ``subs`` and ran.  Here every
door that takes a value is driven with payloads that would create a marker file if evaluated, in the Python API,
the command line, derivation files and the CSV read by ``thinlayer fit``.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import sympy as sp

import thinlayer as tl

from ._common import api, attempt, cli, cli_refused

CATEGORIES = ("code execution: parameter values", "code execution: layers and fit",
              "code execution: expression arguments", "code execution: CSV and files")

#: value payloads (the issue's is the first); {m} is the marker file
VALUE_PAYLOADS = (
    "__import__('os').system('touch {m}') or 10",
    "10 + 0*__import__('os').system('touch {m}')",
    "(lambda: __import__('os').system('touch {m}'))() or 10",
    "[c for c in ().__class__.__base__.__subclasses__()][0] or 10",
    "eval(\"__import__('os').system('touch {m}')\") or 10",
)


def run(t, tmp: Path) -> None:
    m = tmp / "pwned"
    L = tl.BondedLayer(0.3)
    sym = tl.Punch.paraboloid()
    from thinlayer.asymptotics import second_order as so
    from thinlayer.asymptotics import solution as sol
    from thinlayer.numerics import solve_obstacle_grid

    law = tl.force_law(L, sym)
    law2 = so.second_order_law(L, sym)
    payloads = [p.replace("{m}", str(m)) for p in VALUE_PAYLOADS]

    cat = "code execution: parameter values"
    doors = {
        "solve parameters= value": lambda s: tl.solve(L, sym, delta0=0.1, H=0.05, E=2.6, parameters={"R": s}),
        "solve parameters= key": lambda s: tl.solve(L, sym, delta0=0.1, H=0.05, E=2.6, parameters={s: 10}),
        "Punch.subs value": lambda s: sym.subs({"R": s}),
        "Punch.subs symbol key": lambda s: sym.subs({sp.Symbol("R", positive=True): s}),
        "force_arrays parameters=": lambda s: tl.force_arrays(L, sym, [0.1], 0.05, parameters={"R": s}),
        "compressible_solution parameters=": lambda s: sol.compressible_solution(L, sym, delta0=0.1, H=0.05,
                                                                                  parameters={"R": s}),
        "numeric_punch": lambda s: sol.numeric_punch(sym, {"R": s}),
        "ForceLaw.evaluate parameters=": lambda s: law.evaluate(0.1, 0.05, parameters={"R": s}),
        "ForceLaw.indentation parameters=": lambda s: law.indentation(1.0, 0.05, parameters={"R": s}),
        "ForceLaw.parameter_values": lambda s: law.parameter_values({"R": s}),
        "SecondOrderLaw.evaluate parameters=": lambda s: law2.evaluate(0.1, 0.05, parameters={"R": s}),
        "solve_obstacle_grid parameters=": lambda s: solve_obstacle_grid(tl.IncompressibleLayer(), sym, 0.1, 0.05,
                                                                         n=21, parameters={"R": s}),
        "Punch scaling value": lambda s: tl.Punch("x_1**2/R + x_2**2", scaling={"R": s}),
        "Punch.paraboloid(R=)": lambda s: tl.Punch.paraboloid(s),
        "Punch.elliptic_paraboloid(R2=)": lambda s: tl.Punch.elliptic_paraboloid(1, s),
        "Punch.fourth_degree(K=)": lambda s: tl.Punch.fourth_degree(1, s),
        "Punch.flat(a)": lambda s: tl.Punch.flat(s),
    }
    for name, door in doors.items():
        for s in payloads[:3]:
            api(t, cat, m, lambda door=door, s=s: door(s), name)
    # the knock-on: '1/0' said "the punch is constant"
    api(t, cat, m, lambda: tl.solve(L, sym, delta0=0.1, H=0.05, E=2.6, parameters={"R": "1/0"}),
        "R = '1/0'", check=lambda out: ("wrong", "answered for R = 1/0"))

    def legit():  # a value the grammar reads: '10' and 10 give the same answer
        a = tl.solve(L, sym, delta0=0.1, H=0.05, E=2.6, parameters={"R": "10"}).force
        b = tl.solve(L, sym, delta0=0.1, H=0.05, E=2.6, parameters={"R": 10}).force
        return ("clear", "") if a == b else ("wrong", f"'10' gave {a}, 10 gave {b}")

    attempt(t, cat, legit, "R = '10'")

    cat = "code execution: layers and fit"
    d = np.linspace(0.05, 1.0, 8)
    P = tl.force_any_thickness(d, 10.0, 2.0, E=3.0, nu=0.5)
    doors = {
        "BondedLayer(nu)": lambda s: tl.BondedLayer(s),
        "FrictionlessLayer(nu)": lambda s: tl.FrictionlessLayer(s),
        "BondedLayer(parameter=)": lambda s: tl.BondedLayer(parameter=s),
        "solve(nu=)": lambda s: tl.solve(tl.FrictionlessLayer(), tl.Punch.paraboloid(10), delta0=0.1, H=0.05,
                                         mu=1.0, nu=s),
        "fit(delta=[..., s])": lambda s: tl.fit([*d[:-1], s], P, punch=10.0, H=2.0),
        "fit(force=[..., s])": lambda s: tl.fit(d, [*P[:-1], s], punch=10.0, H=2.0),
        "fit(punch=)": lambda s: tl.fit(d, P, punch=s, H=2.0),
        "fit(H=)": lambda s: tl.fit(d, P, punch=10.0, H=s),
        "fit(nu=)": lambda s: tl.fit(d, P, punch=10.0, H=2.0, nu=s),
        "fit(sigma=)": lambda s: tl.fit(d, P, punch=10.0, H=2.0, sigma=s),
        "force_any_thickness(R=)": lambda s: tl.force_any_thickness(0.1, s, 2.0, mu=1.0),
        "edge_shift_exact(nu)": lambda s: tl.edge_shift_exact(s),
        "boundary_layer_exact(nu)": lambda s: tl.boundary_layer_exact(s),
        "edge_constants(nu)": lambda s: so.edge_constants(s),
    }
    for name, door in doors.items():
        for s in payloads[:2]:
            api(t, cat, m, lambda door=door, s=s: door(s), name)

    cat = "code execution: expression arguments"  # sympy's functions sympify a string: each is read first
    op = tl.thin_layer_operator(tl.IncompressibleLayer(), 1)
    obst = tl.obstacle_problem(tl.IncompressibleLayer(), tl.Punch.paraboloid(10))
    mexp = tl.moment_expansion(L, 2)
    alex = tl.alexandrov_solution(L)
    doors = {
        "layer.L(u)": lambda s: L.L(s),
        "layer.small_u(order, u)": lambda s: L.small_u(2, s),
        "ThinLayerOperator.apply(p)": lambda s: op.apply(s),
        "ThinLayerOperator.apply_scaled(f)": lambda s: op.apply_scaled(s),
        "ThinLayerOperator.pairing(phi)": lambda s: op.pairing(s),
        "ObstacleProblem.residual(p)": lambda s: obst.residual(s),
        "ObstacleProblem.boundary_values(x1=)": lambda s: obst.boundary_values(sp.Integer(1), s, 0),
        "MomentExpansion.apply(v1=)": lambda s: mexp.apply(sp.Symbol("xi_1") ** 2, v1=s),
        "MomentExpansion.pairing(v1=)": lambda s: mexp.pairing(sp.Symbol("xi_1") ** 2, v1=s),
        "AlexandrovSolution.q(v)": lambda s: alex.q(s),
        "Punch.scaled(Hs)": lambda s: tl.Punch.paraboloid().scaled(s),
        "checked_lambdify(exprs)": lambda s: tl.checked_lambdify([sp.Symbol("x")], s),
        "ellipse_contour(R1)": lambda s: tl.ellipse_contour(s),
        # issue 24: max/min of linear forms (polyhedral tips) -- each argument read by the grammar, never evaluated
        "Punch.from_expr(max(x1, s))": lambda s: tl.Punch.from_expr(f"max(x1, -x1, x2, {s})"),
        "Punch.from_expr(min(s, x2))": lambda s: tl.Punch.from_expr(f"max(x1, -x1, min({s}, x2), -x2)"),
        "Punch.pyramid(angle)": lambda s: tl.Punch.pyramid(s),
        "Punch.pyramid(sides=)": lambda s: tl.Punch.pyramid(35, s),
        "tip_from_spec(polyhedral)": lambda s: tl.punch.tip_from_spec(f"polyhedral:expr=max(x_1,-x_1,x_2,{s})"),
    }
    for name, door in doors.items():
        for s in (payloads[0], "x_1**2 + " + payloads[1]):
            api(t, cat, m, lambda door=door, s=s: door(s), name)

    cat = "code execution: CSV and files"
    for k, s in enumerate(payloads):
        # in a data row: refused (exit 2) naming the row and column
        f = tmp / f"curve{k}.csv"
        f.write_text(f"depth,force\n0.1,1\n0.2,{s}\n0.3,3\n0.4,4\n")
        cli_refused(t, cat, ["fit", str(f), "--R", "10", "--H", "2", "--nu", "0.5"], tmp, m)
        # in the first row: a header (names, read as text and never evaluated), the data fit as usual
        for first in (f"0.1,{s}\n", f"{s},1\n"):
            g = tmp / f"header{k}_{len(first)}.csv"
            g.write_text(first + "0.2,2\n0.3,3\n0.4,4.5\n")

            def header(g=g):
                code, out, err = cli(["fit", str(g), "--R", "10", "--H", "2", "--nu", "0.5", "--json"], tmp)
                if m.exists():
                    m.unlink()
                    return "code", "a header cell ran"
                return ("clear", "") if code == 0 and '"E"' in out else ("crash", f"exit {code}: {err[:150]!r}")

            attempt(t, cat, header, f"header {first[:30]!r}")
    f = tmp / "curve_ok.csv"
    f.write_text("depth,force\n" + "".join(f"{a},{b}\n" for a, b in zip(d, P)))
    cli_refused(t, cat, ["fit", str(f), "--R", payloads[0], "--H", "2", "--nu", "0.5"], tmp, m)
    cli_refused(t, cat, ["fit", str(f), "--R", "10", "--H", "2", "--nu", "0.5", "--columns", payloads[0]], tmp, m)
    for s in payloads[:3]:
        body = (f"[derivation]\nname='c'\n[layer]\nnu='3/10'\n[punch]\nkind='paraboloid'\n[contact]\ndelta0=0.1\n"
                f"H=0.05\nmu=1.0\nparameters={{R=\"{s}\"}}\n")
        g = tmp / "params.toml"
        g.write_text(body)
        cli_refused(t, cat, ["report", str(g), "--out", str(tmp / "o")], tmp, m)
        cli_refused(t, cat, ["solve", "--kind", "paraboloid", "--param", f"R={s}", "--mu", "1", "--nu", "0.3",
                             "--delta0", "0.1", "--H", "0.05"], tmp, m)

    def env_not_read():  # the package reads no environment variable: a payload there is inert
        import os

        old = {k: os.environ.get(k) for k in ("THINLAYER_SLOW", "THINLAYER_CACHE", "SYMPY_USE_CACHE")}
        os.environ.update({k: payloads[0] for k in old})
        try:
            code, out, _ = cli(["coefficients", "--nu", "3/10", "--order", "1"], tmp)
        finally:
            for k, v in old.items():
                if v is None:
                    os.environ.pop(k, None)
                else:
                    os.environ[k] = v
        if m.exists():
            m.unlink()
            return "code", "an environment variable ran"
        return ("clear", "") if code == 0 else ("crash", f"exit {code}")

    attempt(t, cat, env_not_read, "environment")
