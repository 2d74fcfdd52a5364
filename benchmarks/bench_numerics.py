"""Timings of the direct numerical solvers of :mod:`thinlayer.numerics` (issue 4; issue 18 items 3 and 4).

``run()`` returns rows; nothing runs at import.  Sphere on a thin bonded layer (nu = 0.3, R = 1000 H, contact
radius ~ 10 H).  The 2D FFT solver is measured side by side with ContactMechanics' finite-thickness FFT solver on
the same grid (each solve in a fresh process: medians of three alternating runs at 1024^2, one run at 2048^2),
both compared with the axisymmetric solution for the accuracy (``dP``), and its peak memory (tracemalloc, in a
fresh process) against the bound :func:`thinlayer.numerics.fft2d.memory_estimate` stated in its docstring.
"""
from __future__ import annotations

import json
import statistics
import subprocess
import sys

from _timing import Row, main, median, timed

R, H, DELTA0, NU = 1000.0, 1.0, 0.05, 0.3  # overlap radius sqrt(2 R delta0) = 10 H

_OURS = """
import json, sys, time, tracemalloc
from thinlayer import BondedLayer, Punch
from thinlayer.numerics import solve_2d
n, trace = int(sys.argv[1]), sys.argv[2] == "trace"
layer, punch = BondedLayer({nu}), Punch.paraboloid(R={R})
solve_2d(layer, punch, delta0={d0}, H={H}, n=128)  # imports and caches
if trace:
    tracemalloc.start()
t = time.perf_counter()
res = solve_2d(layer, punch, delta0={d0}, H={H}, n=n)
secs = time.perf_counter() - t
peak = tracemalloc.get_traced_memory()[1] / 2**20 if trace else None
print(json.dumps(dict(secs=secs, force=res.force, peak=peak, it=res.iterations, spacing=res.spacing)))
"""

_PEER = """
import json, sys, time
import numpy as np
from ContactMechanics import PeriodicFFTElasticHalfSpace
from ContactMechanics.Optimization import constrained_conjugate_gradients
n, d = int(sys.argv[1]), float(sys.argv[2])
nu, mu, L = {nu}, 1.0, d * n
x = (np.arange(n) - (n / 2 - 0.5)) * d
X, Y = np.meshgrid(x, x, indexing="ij")
heights = -(X**2 + Y**2) / (2 * {R})
t = time.perf_counter()
sub = PeriodicFFTElasticHalfSpace((n, n), 2 * mu * (1 + nu), physical_sizes=(L, L), thickness={H}, poisson=nu)
res = constrained_conjugate_gradients(sub, heights, offset={d0}, pentol=1e-10 * {d0}, forcetol=1e-12,
                                      thermotol=1e-12, maxiter=5000)
secs = time.perf_counter() - t
print(json.dumps(dict(secs=secs, force=float(np.sum(res.jac)), it=int(res.nit))))
"""


def _python(code: str, *args: object) -> dict:
    src = code.format(nu=NU, R=R, d0=DELTA0, H=H)
    out = subprocess.run([sys.executable, "-c", src, *map(str, args)], capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def _has_contactmechanics() -> bool:
    return subprocess.run([sys.executable, "-c", "import ContactMechanics"], capture_output=True).returncode == 0


def _side_by_side(n: int, rounds: int, ref_force: float) -> list[Row]:
    """solve_2d against ContactMechanics on the same n x n grid (the period of the latter: solve_2d's square).

    Its ``PeriodicFFTElasticHalfSpace(thickness=H, young=E, poisson=nu)`` is this bonded layer (Green's function
    (1/vartheta) L(kH)/k, E = 2 mu (1 + nu)); the margin of solve_2d's square (about 3 H beyond the contact on
    each side) keeps the periodic images small (the layer kernel decays exponentially on the scale H).
    """
    ours, peer = [], []
    have_peer = _has_contactmechanics()
    for _ in range(rounds):  # alternating, each in a fresh process
        ours.append(_python(_OURS, n, "time"))
        if have_peer:
            peer.append(_python(_PEER, n, ours[-1]["spacing"]))
    t_ours = statistics.median(r["secs"] for r in ours)
    dP = ours[0]["force"] / ref_force - 1
    stat = f"median of {rounds}" if rounds > 1 else "1 run"
    if not have_peer:
        return [Row(f"solve_2d {n}^2 (ContactMechanics not installed: no peer), dP {dP:+.0e}", t_ours, ">= 3x")]
    t_peer = statistics.median(r["secs"] for r in peer)
    dP_peer = peer[0]["force"] / ref_force - 1
    return [Row(f"solve_2d {n}^2 ({ours[0]['it']} it, dP {dP:+.0e}) vs CM ({peer[0]['it']} it, dP {dP_peer:+.0e}), "
                f"{stat}", t_ours, ">= 3x", "ContactMechanics", t_peer)]


def _memory_rows() -> list[Row]:
    from thinlayer.numerics.fft2d import memory_estimate

    rows = []
    for n in (1024, 2048):
        peak = _python(_OURS, n, "trace")["peak"]
        bound = memory_estimate(n) / 2**20
        rows.append(Row(f"solve_2d {n}^2 peak memory (tracemalloc; docstring bound)", peak, f"<= {bound:.0f} MiB",
                        unit="MiB"))
    return rows


def run() -> list[Row]:
    """Axisymmetric solver at H/a = 0.1 and 0.0125; 2D FFT solver at 256^2, 1024^2, 2048^2 against ContactMechanics."""
    from thinlayer import BondedLayer, Punch
    from thinlayer.numerics import solve_2d, solve_axisymmetric

    layer, punch = BondedLayer(NU), Punch.paraboloid(R=R)
    rows: list[Row] = []

    secs, ref = timed(lambda: solve_axisymmetric(layer, punch, DELTA0, H), repeat=3)
    if not max(ref.force_error, ref.radius_error / ref.radius) < 1e-6:
        raise RuntimeError(f"axisymmetric solve not converged to 1e-6: {ref.force_error}, {ref.radius_error}")
    rows.append(Row(f"numerics.solve_axisymmetric H/a=0.1 (est. err {ref.force_error:.0e}, best of 3)", secs,
                    "< 1 s"))
    thin = 80.0**2 / (2 * R)  # overlap radius 80 H: H/a = 0.0125
    ref80 = solve_axisymmetric(layer, punch, thin, H)
    if not max(ref80.force_error, ref80.radius_error / ref80.radius) < 1e-6:
        raise RuntimeError(f"axisymmetric H/a=0.0125 not converged to 1e-6: {ref80.force_error}")
    rows.append(Row(f"numerics.solve_axisymmetric H/a=0.0125 (est. err {ref80.force_error:.0e}, median of 5)",
                    median(lambda: solve_axisymmetric(layer, punch, thin, H), 5), "<= 0.3 s"))

    secs, res = timed(lambda: solve_2d(layer, punch, delta0=DELTA0, H=H, n=256), repeat=3)
    rows.append(Row(f"solve_2d sphere a=10H 256^2: dP {res.force / ref.force - 1:+.0e}, "
                    f"dc {res.contact_radius / ref.radius - 1:+.0e} (best of 3)", secs, "< 1 s"))
    rows += _side_by_side(1024, 3, ref.force)
    rows += _side_by_side(2048, 1, ref.force)
    rows += _memory_rows()
    secs1, res1 = timed(lambda: solve_2d(layer, punch, delta0=DELTA0, H=H, n=1024, workers=1))
    rows.append(Row(f"solve_2d sphere a=10H 1024^2, workers=1: dP {res1.force / ref.force - 1:+.0e}", secs1,
                    "< 10 s"))
    rows.append(_cpu_per_wall(layer, punch))
    return rows


def _cpu_per_wall(layer, punch) -> Row:
    """Process CPU time / wall time of the iteration alone with one FFT worker: above 1 when BLAS threads spin."""
    import time

    from thinlayer.numerics import fft2d

    prob = fft2d._setup(layer, punch, DELTA0, H, 1.0, 1024, None, 1e-10, 5000, None, None, 1)
    time.sleep(0.5)  # an OpenBLAS thread woken by the set-up (the J0 table) goes idle
    w0, c0 = time.perf_counter(), time.process_time()
    fft2d._iterate(prob)
    return Row("solve_2d 1024^2 iteration, workers=1: process CPU / wall time", (time.process_time() - c0)
               / (time.perf_counter() - w0), "<= 1.1", unit="")


if __name__ == "__main__":  # pragma: no cover
    main(run)
