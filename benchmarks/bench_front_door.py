"""Timings of the front door :func:`thinlayer.solve` with ``model="auto"`` (issue 13).

Targets: under 0.1 s wherever an asymptotic model holds (the layer and punch seen before: the symbolic law
and the edge shift are cached per layer and punch); under 2 s for an axisymmetric direct fallback.
``run()`` returns ``(name, seconds, target)`` rows, best of three calls; each row also names the model used.
"""
from __future__ import annotations

from _timing import best, main


def run() -> list[tuple[str, float, str]]:
    import thinlayer as tl

    sphere, ellipse = tl.Punch.paraboloid(10), tl.Punch.elliptic_paraboloid(40, 10)
    quartic = tl.Punch("x_1**2/2 + x_2**2 + x_1**3/5 + x_1*x_2/10 + x_1**4 + x_2**4")
    cases = [
        ("sphere nu=0.3 H/a=0.05", tl.BondedLayer(0.3), sphere, 0.1, 0.07, 0.1),
        ("ellipse 4:1 nu=0.3 H/a=0.05", tl.BondedLayer(0.3), ellipse, 0.1, 0.14, 0.1),
        ("quartic nu=0.45 H/a=0.05", tl.BondedLayer(0.45), quartic, 0.3, 0.03, 0.1),
        ("sphere frictionless H/a=0.2", tl.FrictionlessLayer(0.3), sphere, 0.1, 0.28, 0.1),
        ("sphere nu=0.499 H/a=0.014", tl.BondedLayer(0.499), sphere, 0.1, 0.02, 0.1),
        ("sphere nu=1/2 H/a=0.005", tl.BondedLayer(0.5), sphere, 0.1, 0.01, 0.1),
        ("sphere nu=0.49 H/a=0.2", tl.BondedLayer(0.49), sphere, 0.1, 0.28, 2.0),
        ("sphere nu=0.3 H/a=0.5", tl.BondedLayer(0.3), sphere, 0.1, 0.7, 2.0),
    ]
    rows = []
    for name, layer, punch, d0, H, target in cases:
        def call(layer=layer, punch=punch, d0=d0, H=H):
            return tl.solve(layer, punch, delta0=d0, H=H, E=1.0)

        model = call().model  # warm: the law, the edge shift and the coefficients are cached per layer
        rows.append((f"solve(auto) {name}: {model}", best(call), f"< {target:g} s"))
    # the inverse problem through the direct solver: secant steps on log P against log delta0
    layer = tl.BondedLayer(0.49)
    P = tl.solve(layer, sphere, delta0=0.1, H=0.28, E=1.0).force
    rows.append(("solve(auto, force=P) sphere nu=0.49 H/a=0.2: direct",
                 best(lambda: tl.solve(layer, sphere, force=P, H=0.28, E=1.0)), "< 2 s"))
    return rows


if __name__ == "__main__":
    main(run)
