"""Timings of the direct numerical solvers of :mod:`thinlayer.numerics` (issue 4).

``run()`` returns ``(name, seconds, target)`` rows; nothing runs at import.  The names carry the
accuracy reached (against the independent axisymmetric solver of :mod:`thinlayer.numerics.axisymmetric`).
"""
from __future__ import annotations

from _timing import main, timed


def run() -> list[tuple[str, float, str]]:
    """Sphere on a thin bonded layer (nu = 0.3, contact radius ~ 10 H): 2D FFT solver and axisymmetric solver."""
    from thinlayer import BondedLayer, Punch
    from thinlayer.numerics import solve_2d, solve_axisymmetric

    layer, R, H, delta0 = BondedLayer(0.3), 1000.0, 1.0, 0.05  # overlap radius sqrt(2 R delta0) = 10 H
    punch = Punch.paraboloid(R=R)
    rows: list[tuple[str, float, str]] = []

    secs, ref = timed(lambda: solve_axisymmetric(layer, punch, delta0, H), repeat=3)
    if not max(ref.force_error, ref.radius_error / ref.radius) < 1e-6:
        raise RuntimeError(f"axisymmetric solve not converged to 1e-6: {ref.force_error}, {ref.radius_error}")
    rows.append((f"numerics.solve_axisymmetric H/a=0.1 (est. err {ref.force_error:.0e})", secs, "< 1 s"))
    thin = 80.0**2 / (2 * R)  # overlap radius 80 H: H/a = 0.0125
    secs80, ref80 = timed(lambda: solve_axisymmetric(layer, punch, thin, H), repeat=1)
    if not max(ref80.force_error, ref80.radius_error / ref80.radius) < 1e-6:
        raise RuntimeError(f"axisymmetric H/a=0.0125 not converged to 1e-6: {ref80.force_error}")
    rows.append((f"numerics.solve_axisymmetric H/a=0.0125 (est. err {ref80.force_error:.0e})", secs80, "< 30 s"))

    results = {}
    for n, repeat, target in ((256, 3, "< 1 s"), (1024, 1, "< 10 s")):
        secs, res = timed(lambda n=n: solve_2d(layer, punch, delta0=delta0, H=H, n=n), repeat=repeat)
        results[n] = (secs, res)
        name = (f"solve_2d sphere a=10H {n}^2: dP {res.force / ref.force - 1:+.0e}, "
                f"dc {res.contact_radius / ref.radius - 1:+.0e}")
        rows.append((name, secs, target))
    rows += _contactmechanics_rows(layer, punch, R, delta0, H, ref, *results[1024])
    return rows


def _contactmechanics_rows(layer, punch, R, delta0, H, ref, secs_ours, ours) -> list[tuple[str, float, str]]:
    """Side by side at 1024^2: contactmechanics' finite-thickness FFT solver on the same problem and grid.

    Its ``PeriodicFFTElasticHalfSpace(thickness=H, young=E, poisson=nu)`` is this bonded layer (its Green's
    function is (1/vartheta) L(kH)/k, E = 2 mu (1 + nu)); the period is solve_2d's square, whose margin
    (6 H beyond the contact on each side) makes the periodic images negligible: the layer kernel decays
    exponentially on the scale H.  Also solve_2d with one FFT thread, as contactmechanics runs serially.
    """
    import math

    import numpy as np

    from thinlayer.numerics import solve_2d

    nu, mu = float(layer.nu), 1.0
    n, L = ours.n, ours.spacing * ours.n
    rows = []
    secs1, res1 = timed(lambda: solve_2d(layer, punch, delta0=delta0, H=H, n=n, workers=1))
    rows.append((f"solve_2d sphere a=10H {n}^2, workers=1: dP {res1.force / ref.force - 1:+.0e}", secs1,
                 "< 10 s"))
    try:
        from ContactMechanics import PeriodicFFTElasticHalfSpace
        from ContactMechanics.Optimization import constrained_conjugate_gradients
    except ImportError:
        rows.append(("contactmechanics not installed: comparison skipped", math.nan, "-"))
        return rows
    x = (np.arange(n) - (n / 2 - 0.5)) * ours.spacing
    X, Y = np.meshgrid(x, x, indexing="ij")
    heights = -(X**2 + Y**2) / (2 * R)

    def cm():
        sub = PeriodicFFTElasticHalfSpace((n, n), 2 * mu * (1 + nu), physical_sizes=(L, L), thickness=H, poisson=nu)
        return constrained_conjugate_gradients(sub, heights, offset=delta0, pentol=1e-10 * delta0,
                                               forcetol=1e-12, thermotol=1e-12, maxiter=5000)

    secs_cm, res = timed(cm)
    P = float(np.sum(res.jac))
    rows.append((f"contactmechanics thickness=H {n}^2: dP {P / ref.force - 1:+.0e}, {res.nit} it", secs_cm,
                 f">= solve_2d ({secs_ours:.1f} s)"))
    rows.append((f"  solve_2d / contactmechanics time: {secs_ours / secs_cm:.2f} (1 thread {secs1 / secs_cm:.2f})",
                 secs_ours / secs_cm, "<= 1"))
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
