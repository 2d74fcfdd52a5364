r"""Build the any-thickness tables of the self-similar tips (``contact/data/any_thickness_tips.npz``).

``python -m thinlayer.contact._tips_table_build [--small] [--out PATH]`` regenerates it; a test re-solves a few
nodes and compares them with the shipped values.  Every entry is a direct solution
(:func:`thinlayer.numerics.contact_for_radius`: prescribed contact radius ``c``, the depth and force follow;
spectral, graded for the apex, with its own error estimate) of the power-law tip ``C r^n`` (the cone:
``n = 1``) on a layer of thickness ``H = 1``, at contact radii ``c/H`` on a geometric grid.  Stored per curve
(one layer, one nu):

    chi = c_0/H,   y = log(P/P_0),   z = log(c/c_0),

``c_0 = (delta0/(C k_n))^{1/n}`` and ``P_0 = 4 vartheta C k_n c_0^{n+1} n/(n + 1)`` the half-space (Sneddon)
radius and force at the same depth (T.9).  ``C`` scales out (``delta0`` and ``P`` are linear in C at fixed c), so
one curve per (n, layer, nu) holds for every C, i.e. every cone angle.

Curves: the frictionless base (its kernel does not depend on nu; ``P/P_0`` neither), and the bonded layer at
:data:`NU_NODES` in ``[0.3, 1/2]``, clustered at 1/2 where the incompressible/compressible crossover
(``lambda = 24 (1/2 - nu) chi^2``, (I.13)) sharpens as chi grows.  Validation points (chi between nodes, nu
between nodes) are solved too and stored with the table: the law's estimate is measured on them.
"""
from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

from .._checks import InputError
from ..layers.kernels import BondedLayer, FrictionlessLayer, IncompressibleLayer, LayerKernel
from ..numerics import contact_for_radius
from ..punch import Punch

__all__ = ["NU_NODES", "S_NODES", "build_tips_table", "direct_point", "main"]

#: bonded-layer nodes in nu: v = sqrt(1/2 - nu) geometric (ratio ~1.2-1.5) from 0.005 to 0.45, and nu = 1/2, so
#: that ``u = log(1 + sqrt(24) v chi)`` is spaced ~0.15-0.25 up to chi ~ 20 (measured while choosing: 12 nodes left
#: 1.4e-3 at nu = 0.499, chi = 17.5, where y falls from 9.2 to 4.0 across the u range; 20 nodes 4.5e-5)
NU_NODES = (0.5, 0.499975, 0.49995, 0.4999, 0.49985, 0.499776, 0.499665, 0.4995, 0.499293, 0.499, 0.498586, 0.498,
            0.49759, 0.49684, 0.4960, 0.495, 0.49293, 0.49, 0.48586, 0.48, 0.47172, 0.46, 0.4471, 0.43, 0.39,
            0.345, 0.3)
#: contact radii c/H of the table's nodes (geometric)
S_NODES = (0.04, 48.0, 31)
#: validation points: (base, nu, c/H); the bonded ones half-way (geometric mean in v) between consecutive nu nodes,
#: at radii cycling through the table's range, plus the brief's nu = 0.45 across chi
_CYCLE = (0.11, 0.5, 1.3, 3.3, 7.7, 14.0, 22.0, 30.0, 40.0, 46.0)
VALIDATION = [("frictionless", 0.3, s) for s in (0.13, 0.9, 5.5, 17.0, 33.0)] + \
    [("bonded", 0.5 - math.sqrt(0.5 - a) * math.sqrt(0.5 - b), _CYCLE[(3 * i) % len(_CYCLE)])
     for i, (a, b) in enumerate(zip(NU_NODES[1:-1], NU_NODES[2:]))] + \
    [("bonded", 0.5 - 0.25 * (0.5 - NU_NODES[1]), s) for s in (3.3, 30.0)] + \
    [("bonded", 0.45, s) for s in (0.11, 1.3, 7.7, 29.0)]


def _layer(nu: float, base: str) -> LayerKernel:
    if base == "frictionless":
        return FrictionlessLayer(nu)
    return IncompressibleLayer() if nu == 0.5 else BondedLayer(float(nu))


def direct_point(n: int, base: str, nu: float, s: float) -> tuple[float, float, float, float]:
    """``(chi, P/P_0, c/c_0, estimate)`` of the direct solver for ``r^n`` at contact radius ``s = c/H`` (H = 1)."""
    from ..asymptotics.thick_layer import power_law_half_space

    k = float(power_law_half_space(n))
    tip = Punch.cone(45) if n == 1 else Punch.power_law(1, n)  # C = cot 45 deg = 1
    res = contact_for_radius(_layer(nu, base), tip, s, H=1.0, mu=1.0, nu=nu if base == "frictionless" else None)
    c0 = (res.delta0 / k) ** (1.0 / n)
    P0 = 4.0 / (1.0 - nu) * k * c0 ** (n + 1) * n / (n + 1)
    est = res.force_error + res.delta0_error / res.delta0 * (n + 1) / n  # P_0 ~ delta0^{(n+1)/n}
    return c0, res.force / P0, s / c0, est


def build_tips_table(n: int = 1, s_nodes: tuple = S_NODES, nu_nodes: tuple = NU_NODES, out: Path | None = None,
                     progress: bool = False, validate: bool = True) -> dict[str, np.ndarray]:
    """Solve the grid (and the validation points) and return the arrays; write them to ``out`` if given."""
    lo, hi, m = s_nodes
    if m < 4 or len(nu_nodes) < 2:
        raise InputError(f"the table needs at least 4 radii and 2 nu nodes, got {m} and {len(nu_nodes)}")
    s = np.geomspace(lo, hi, m)
    curves = [("frictionless", 0.3)] + [("bonded", nu) for nu in nu_nodes]
    chi, y, z, err = (np.zeros((len(curves), m)) for _ in range(4))
    t0 = time.perf_counter()
    for i, (base, nu) in enumerate(curves):
        for j, sv in enumerate(s):
            c0, Pr, cr, e = direct_point(n, base, nu, float(sv))
            chi[i, j], y[i, j], z[i, j], err[i, j] = c0, math.log(Pr), math.log(cr), e
        if progress:
            print(f"{base} nu = {nu}: done ({time.perf_counter() - t0:.0f} s)", file=sys.stderr, flush=True)
    data = dict(n=np.array(n), s=s, nu=np.array(nu_nodes), chi=chi, y=y, z=z, err=err)
    if validate:
        rows = []
        for base, nu, sv in VALIDATION:
            if sv < lo or sv > hi:
                continue
            c0, Pr, cr, e = direct_point(n, base, nu, sv)
            rows.append((0 if base == "frictionless" else 1, nu, c0, Pr, cr, e))
        data["check"] = np.array(rows)
        if progress:
            print(f"validation: done ({time.perf_counter() - t0:.0f} s)", file=sys.stderr, flush=True)
    if out is not None:
        out = Path(out)
        np.savez_compressed(out, **data)
    return data


def main(argv: list[str] | None = None) -> int:
    """Command line: ``python -m thinlayer.contact._tips_table_build [--out PATH]``."""
    from .any_thickness_tips import TIPS_TABLE_PATH

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=TIPS_TABLE_PATH, help=f"output .npz (default {TIPS_TABLE_PATH})")
    args = ap.parse_args(argv)
    build_tips_table(1, out=args.out, progress=True)
    print(f"wrote {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
