"""Timings of the direct numerical solvers of :mod:`thinlayer.numerics` (issue 4).

``run()`` returns ``(name, seconds, target)`` rows; nothing runs at import.  The names carry the
accuracy reached (against the independent axisymmetric solver of :mod:`thinlayer.direct`).
"""
from __future__ import annotations

import time


def _timed(fn, repeat: int = 1):
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def run() -> list[tuple[str, float, str]]:
    """Sphere on a thin bonded layer (nu = 0.3, contact radius ~ 10 H): 2D FFT solver and axisymmetric solver."""
    from thinlayer import BondedLayer, Punch
    from thinlayer.numerics import solve_2d, solve_axisymmetric

    layer, R, H, delta0 = BondedLayer(0.3), 1000.0, 1.0, 0.05  # overlap radius sqrt(2 R delta0) = 10 H
    punch = Punch.paraboloid(R=R)
    rows: list[tuple[str, float, str]] = []

    secs, ref = _timed(lambda: solve_axisymmetric(layer, punch, delta0, H), repeat=3)
    if not max(ref.force_error, ref.radius_error / ref.radius) < 1e-6:
        raise RuntimeError(f"axisymmetric solve not converged to 1e-6: {ref.force_error}, {ref.radius_error}")
    rows.append((f"numerics.solve_axisymmetric H/a=0.1 (est. err {ref.force_error:.0e})", secs, "< 1 s"))

    for n, repeat, target in ((256, 3, "< 1 s"), (1024, 1, "< 10 s")):
        secs, res = _timed(lambda n=n: solve_2d(layer, punch, delta0=delta0, H=H, n=n), repeat=repeat)
        name = (f"solve_2d sphere a=10H {n}^2: dP {res.force / ref.force - 1:+.0e}, "
                f"dc {res.contact_radius / ref.radius - 1:+.0e}")
        rows.append((name, secs, target))
    return rows


if __name__ == "__main__":
    for name, sec, target in run():
        print(f"{name:62s} {sec:8.3f} s   (target {target})")
