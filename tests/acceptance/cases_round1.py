"""The first round of the safe-input issue (issue 12): 257 inputs in eight categories, every input and check kept.

Moved here from ``tests/test_safe_input_acceptance.py`` (issue 23 item 8).  Two things changed: each input runs
under the 10 s alarm of :func:`tests.acceptance._common.attempt` (past it: ``"hang"``), and a marker file is now
counted as ``"code"`` (code executed) rather than ``"wrong"``; a Python error must be thinlayer's own class.
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

import thinlayer as tl

from ._common import PAYLOADS, api, attempt, cli, cli_refused, one_line, unlimited

CATEGORIES = ("code execution", "LaTeX injection", "validity of answers", "data loss (refused overwrites)",
              "derivation-file schema", "command-line bad input", "bounded work", "numerics at extremes")


def code_execution(t, tmp: Path) -> None:
    cat = "code execution"
    m = tmp / "pwned"
    doors = [
        lambda s: tl.Punch(s),
        lambda s: tl.solve(tl.BondedLayer(0.3), s, delta0=0.1, H=0.05, mu=1.0),
        lambda s: tl.Punch.paraboloid(R=s),
        lambda s: tl.contact_contour(s, 0.1),
        lambda s: tl.solve_2d(tl.BondedLayer(0.3), s, delta0=0.1, H=0.1, n=32),
        lambda s: tl.BondedLayer(s),
        lambda s: tl.Punch("x_1**2/R + x_2**2", ).subs({s: 1}),
        lambda s: tl.inner_pressure(tl.BondedLayer(0.3), s),
    ]
    for door in doors:
        for p in PAYLOADS:
            s = p.replace("{m}", str(m))
            api(t, cat, m, lambda door=door, s=s: door(s), s[:40])
    for p in PAYLOADS[:6]:
        s = p.replace("{m}", str(m))
        cli_refused(t, cat, ["inner", "--punch", s], tmp, m)
        cli_refused(t, cat, ["solve", "--mu", "1", "--nu", s, "--kind", "paraboloid", "--param", "R=1",
                             "--delta0", "0.1", "--H", "0.05"], tmp, m)
        cli_refused(t, cat, ["solve", "--mu", "1", "--nu", "0.3", "--kind", "paraboloid", "--param", f"R={s}",
                             "--delta0", "0.1", "--H", "0.05"], tmp, m)
        f = tmp / "attack.toml"
        f.write_text(f"[derivation]\nname='a'\n[layer]\nnu='3/10'\n[punch]\nexpr=\"{s}\"\n")
        cli_refused(t, cat, ["report", str(f), "--out", str(tmp / "out")], tmp, m)


def latex_injection(t, tmp: Path) -> None:
    cat = "LaTeX injection"
    attacks = [r"\input{/etc/hostname}", r"\immediate\write18{touch pwned}", r"\openin5=/etc/passwd",
               r"$\input{/etc/hostname}$", r"\catcode`\^=12 ^^5cinput{/etc/hostname}",
               r"\def\x{\input}\x{/etc/hostname}"]
    k = 0
    for a in attacks:
        for where in ("title", "param"):
            k += 1
            out = tmp / f"tex_{k}"
            if where == "title":
                body = f"[derivation]\nname='t'\ntitle='''{a}'''\n[layer]\nnu='3/10'\n[punch]\nkind='paraboloid'\n"
            else:
                body = ("[derivation]\nname='t'\n[layer]\nnu='3/10'\n[punch]\n"
                        f"expr='''x_1**2/{a} + x_2**2'''\n")

            def one(body=body, out=out, a=a, where=where):
                f = tmp / "inj.toml"
                f.write_text(body)
                code, _, err = cli(["report", str(f), "--out", str(out), "--quiet"], tmp)
                tex = out / "t.tex"
                if code == 2 and len(err.strip().splitlines()) == 1:
                    return "clear", ""
                if code == 0 and tex.exists():
                    text = tex.read_text()
                    raw = any(k in text for k in (r"\input{/etc", r"\write18", r"\openin5", r"^^5c", r"\def\x"))
                    return ("wrong", f"{where} {a!r} reached the .tex raw") if raw else ("clear", "")
                return "crash", f"{where} {a!r}: exit {code} {err[:150]!r}"

            attempt(t, cat, one, f"{where} {a}")


def _hertz(nu: float, mu: float, R: float, d0: float) -> float:
    return 8.0 / 3.0 * mu / (1.0 - nu) * math.sqrt(R) * d0**1.5


def validity(t, tmp: Path) -> None:
    """solve() across nu and H/a: every answer positive, finite, and inside its estimate of an independent route."""
    cat = "validity of answers"
    sphere = tl.Punch.paraboloid(10)
    cases = [(nu, H) for nu in (0.0, 0.3, 0.49, 0.5) for H in (0.02, 0.1, 0.5, 2.0)]

    def grid_case(nu, H):
        layer = tl.BondedLayer(nu)
        try:
            ans = tl.solve(layer, sphere, delta0=0.1, H=H, mu=1.0)
        except (ValueError, TypeError) as exc:
            return ("clear", "") if one_line(exc) else ("crash", repr(exc)[:200])
        if not (math.isfinite(ans.force) and ans.force > 0 and ans.contact_area > 0):
            return "wrong", f"nu={nu} H={H}: force {ans.force}"
        # the independent route: the axisymmetric direct solver, its own estimate added (not the input: untimed)
        with unlimited():
            ref = tl.solve(layer, sphere, delta0=0.1, H=H, mu=1.0, model="direct")
        diff = abs(ans.force / ref.force - 1)
        allowed = ans.error_estimate["force"] + ref.error_estimate["force"]
        return ("clear", "") if diff <= allowed else ("wrong", f"nu={nu} H={H} {ans.model}: {diff:.3g} > {allowed:.3g}")

    for nu, H in cases:
        attempt(t, cat, lambda nu=nu, H=H: grid_case(nu, H), f"nu={nu} H={H}")

    # the extremes of the issue: a half-space (Hertz, closed form), huge moduli, tiny radii
    def half_space(H):
        ans = tl.solve(tl.BondedLayer(0.3), sphere, delta0=0.1, H=H, mu=1.0)
        ok = math.isfinite(ans.force) and abs(ans.force / _hertz(0.3, 1.0, 10, 0.1) - 1) < 1e-6
        return ("clear", "") if ok else ("wrong", f"H={H}: {ans.force} vs Hertz")

    for H in (1e6, 1e300):
        attempt(t, cat, lambda H=H: half_space(H), f"H={H}")

    def extreme(call, what):
        try:
            ans = call()
        except (ValueError, TypeError) as exc:
            return ("clear", "") if one_line(exc) else ("crash", repr(exc)[:200])
        ok = math.isfinite(ans.force) and ans.force > 0
        return ("clear", "") if ok else ("wrong", f"{what}: force {ans.force}")

    for kw in ({"mu": 1e308}, {"mu": 1e-308}, {"E": 1e300}):
        attempt(t, cat, lambda kw=kw: extreme(lambda: tl.solve(tl.BondedLayer(0.3), sphere, delta0=0.1, H=0.05,
                                                                **kw), kw), str(kw))
    for R in (1e-300, 1e300):
        attempt(t, cat, lambda R=R: extreme(lambda: tl.solve(tl.BondedLayer(0.3), tl.Punch.paraboloid(R),
                                                             delta0=0.1, H=0.05, mu=1.0), f"R={R}"), f"R={R}")


def data_loss(t, tmp: Path) -> None:
    cat = "data loss (refused overwrites)"
    good = tmp / "good.toml"
    good.write_text("[derivation]\nname='g'\n[layer]\nnu='3/10'\n[punch]\nkind='paraboloid'\n")
    runs = [
        (["report", str(good), "--out", "{d}"], ["g.tex"]),
        (["report", str(good), "--out", "{d}", "--pdf"], ["g.pdf"]),
        (["report", str(good), "--out", "{d}", "--pdf"], ["g.log"]),
        (["codegen", "force", "--kind", "paraboloid", "--lang", "c", "--out", "{d}"], None),
        (["codegen", "any-thickness", "--nu", "0.3", "--lang", "python", "--out", "{d}"],
         ["thinlayer_any_thickness.py"]),
        (["validate", "--out", "{d}", "--quiet"], ["validation.txt"]),
        (["validate", "--out", "{d}", "--quiet"], ["validation.json"]),
    ]
    for k, (argv, names) in enumerate(runs):
        d = tmp / f"loss{k}"
        d.mkdir()

        def one(argv=argv, names=names, d=d):
            if names is None:  # the files a first run writes, then a second run must not replace them
                cli([a.replace("{d}", str(d)) for a in argv], tmp)
                names = sorted(p.name for p in d.iterdir() if not p.name.startswith("."))
            for n in names:
                (d / n).write_text("the user's own work\n")
            before = {n: (d / n).read_bytes() for n in names}
            code, _, err = cli([a.replace("{d}", str(d)) for a in argv], tmp)
            after = {n: (d / n).read_bytes() if (d / n).exists() else None for n in names}
            if after != before:
                return "loss", f"{argv[:2]} replaced {names}"
            if code == 2 and "--overwrite" in err:
                return "clear", ""
            return "crash", f"{argv[:2]}: exit {code} {err[:150]!r}"

        attempt(t, cat, one, str(argv[:2]))

    # a .tex edited by hand after thinlayer wrote it is the user's too
    def edited():
        d = tmp / "edited"
        cli(["report", str(good), "--out", str(d), "--quiet"], tmp)
        tex = d / "g.tex"
        tex.write_text(tex.read_text() + "% my notes\n")
        before = tex.read_bytes()
        code, _, err = cli(["report", str(good), "--out", str(d)], tmp)
        return ("clear", "") if tex.read_bytes() == before and code == 2 else ("loss", "edited .tex")

    attempt(t, cat, edited, "edited .tex")


def schema(t, tmp: Path) -> None:
    from thinlayer.export.derivation import SCHEMA

    cat = "derivation-file schema"
    base = {"derivation": "name='x'\n", "layer": "nu='3/10'\n", "punch": "kind='paraboloid'\n"}
    extra = {"contact": "delta0=0.1\nH=0.01\nparameters={R=1}\n"}
    for table in sorted(SCHEMA):
        tables = dict(base)
        tables.setdefault(table, extra.get(table, ""))
        tables[table] += "nuu = '0.3'\n"
        f = tmp / f"s_{table}.toml"
        f.write_text("".join(f"[{k}]\n{v}" for k, v in tables.items()))
        cli_refused(t, cat, ["report", str(f), "--out", str(tmp / "s_out")], tmp)
    contradictions = [
        "[derivation]\nname='x'\n[layer]\nnu='3/10'\n[punch]\nkind='paraboloid'\n[contact]\nnu=0.4\ndelta0=0.1\n"
        "H=0.01\nparameters={R=1}\n",
        "[derivation]\nname='x'\n[layer]\nnu='3/10'\n[punch]\nkind='paraboloid'\nexpr='x_1**2'\n",
        "[derivation]\nname='x'\ntitle=5\n[layer]\n[punch]\nkind='paraboloid'\n",
        "[derivation]\nname='x'\n[layer]\nnu='3/10'\n[punch]\nkind=['paraboloid']\n",
    ]
    for k, body in enumerate(contradictions):
        f = tmp / f"c{k}.toml"
        f.write_text(body)
        cli_refused(t, cat, ["report", str(f), "--out", str(tmp / "c_out")], tmp)


def cli_bad_input(t, tmp: Path) -> None:
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "export"))
    try:
        from test_cli_errors import CASES
    finally:
        sys.path.pop(0)
    cat = "command-line bad input"
    for k, (name, content, argv) in enumerate(CASES):
        d = tmp / f"cli{k}"
        d.mkdir()
        (d / "afile").write_text("a regular file\n")
        (d / "texdir" / "x.tex").mkdir(parents=True)
        (d / "done").mkdir()
        (d / "done" / "validation.txt").write_text("earlier results\n")
        f = d / "d.toml"
        if content is not None:
            f.write_bytes(content if isinstance(content, bytes) else content.encode())
        cli_refused(t, cat, [a.replace("{file}", str(f)).replace("{tmp}", str(d)) for a in argv], d, d / "pwned")
        if (d / "done" / "validation.txt").read_text() != "earlier results\n":
            t.add("data loss (refused overwrites)", "loss", name)


def bounded_work(t, tmp: Path) -> None:
    from thinlayer.layers.coefficients import kernel_coefficients

    cat = "bounded work"
    calls = [
        lambda: kernel_coefficients(tl.BondedLayer(), 100000),
        lambda: tl.inner_pressure(tl.BondedLayer(0.3), tl.Punch.paraboloid(1), order=100000),
        lambda: tl.solve_axisymmetric(tl.BondedLayer(0.3), tl.Punch.paraboloid(R=10), 0.1, 1e-6),
        lambda: tl.solve_axisymmetric(tl.BondedLayer(0.3), tl.Punch.paraboloid(R=10), 1e6, 0.1),
        lambda: tl.solve_2d(tl.BondedLayer(0.3), tl.Punch.paraboloid(R=1), delta0=0.1, H=0.1, n=100000),
        lambda: tl.Punch("x_1**100000 + x_2**2"),
        lambda: tl.solve(tl.BondedLayer(0.3), tl.Punch.elliptic_paraboloid(4, 1), delta0=0.1, H=1e-5, mu=1.0,
                         model="direct"),
    ]

    def refused(call):  # refused before the work, in one line (the runaway cases ran for minutes or GiB)
        try:
            call()
        except (ValueError, TypeError) as exc:
            return ("clear", "") if one_line(exc) else ("crash", repr(exc)[:200])
        return "crash", "accepted a runaway request"

    for k, call in enumerate(calls):
        attempt(t, cat, lambda call=call: refused(call), f"runaway {k}")


def numerics_extremes(t, tmp: Path) -> None:
    import mpmath

    cat = "numerics at extremes"
    for layer in (tl.BondedLayer(0.3), tl.BondedLayer(0.499), tl.FrictionlessLayer(0.3), tl.IncompressibleLayer()):
        for u in (0.0, 1e-300, 1e154, 1e300, math.inf):
            def kernel(layer=layer, u=u):
                v = float(layer.L_numeric(np.array([u]), "numpy")[0])
                w = float(layer.L_numeric(mpmath.mpf(u), "mpmath"))
                ok = math.isfinite(v) and math.isfinite(w) and abs(v - w) <= 1e-15 * max(abs(w), 1e-300) + 1e-300
                return ("clear", "") if ok else ("wrong", f"{layer} L({u}) = {v}, {w}")

            attempt(t, cat, kernel, f"{layer} L({u})")
        for backend, val in (("numpy", np.array([math.nan])), ("mpmath", mpmath.mpf("nan"))):
            def nan(layer=layer, backend=backend, val=val):
                try:
                    layer.L_numeric(val, backend)
                except ValueError:
                    return "clear", ""
                return "wrong", f"{layer} {backend} accepted nan"

            attempt(t, cat, nan, f"{layer} {backend} nan")
    # the contour of a punch whose coefficients span 1e-70 to 1e30 (a scale-free formulation)
    for a, b in ((1e-70, 1.0), (1.0, 1e30), (1e-70, 1e30)):
        def contour(a=a, b=b):
            c = tl.contact_contour(tl.Punch.elliptic_paraboloid(1 / (2 * a), 1 / (2 * b)).expr, 1.0)
            area = math.pi / math.sqrt(a * b)  # ellipse a x^2 + b y^2 < 1
            return ("clear", "") if abs(c.area / area - 1) < 1e-12 else ("wrong", f"contour a={a} b={b}: {c.area}")

        attempt(t, cat, contour, f"contour {a} {b}")


def run(t, tmp: Path) -> None:
    for part in (code_execution, latex_injection, validity, data_loss, schema, cli_bad_input, bounded_work,
                 numerics_extremes):
        sub = tmp / part.__name__
        sub.mkdir(exist_ok=True)
        part(t, sub)
