r"""Build the any-thickness table of the regular pyramids (``contact/data/any_thickness_pyramids.npz``).

``python -m thinlayer.contact._pyramid_table_build [--out PATH] [--n 256]`` regenerates it.  The pyramid is
self-similar (its profile is homogeneous of degree 1): scaling the plane by ``t = tan(alpha)`` maps the pyramid of
face angle alpha on a layer ``H`` to the pyramid of face angle 45 degrees on the layer ``H/t``, so

    P = P_hs Pi(chi; nu, base, sides),     chi = delta0 tan(alpha)/H,     P_hs = K vartheta t delta0^2   (T.11)

holds for every face angle.  Every entry is ``Pi = P_layer/P_hs`` with both forces from
:func:`thinlayer.numerics.solve_2d` on the SAME grid (pyramid of 45 degrees, ``delta0 = 1``, so the inradius of the
level set is 1; the square ``[-1.25, 1.25]^2`` for 4 sides, ``[-1.8, 1.8] x [-1.3, 2.3]`` for 3): the grid's error at
the contact's edge, the same on both, largely cancels in the ratio.  Stored per curve (one base, one nu):
``y = log Pi`` at the nodes :data:`CHI_NODES` from :data:`CHI_SOLVED` on (below it the thick-layer series (T.12) is
better than the grid and the law takes its values there).  Validation points (chi and nu between nodes, and a finer
grid at some nodes) are solved too and stored: the law's estimate is measured on them.
"""
from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

__all__ = ["CHI_NODES", "CHI_SOLVED", "NU_NODES", "build_pyramid_table", "direct_ratio", "main"]

#: the table's nodes in chi = delta0 tan(alpha)/H: geometric, 17 from 0.05 to 10 (step 0.33 in log chi)
CHI_NODES = tuple(float(v) for v in np.geomspace(0.05, 10.0, 17))
#: from this chi on the nodes are direct solutions; below, the series (T.12) (estimate <= 5e-5 at chi <= 0.1)
CHI_SOLVED = 0.1
#: the bonded layer's nodes in nu (clustered at 1/2: the crossover variable u = log(1 + sqrt(24 (1/2 - nu)) chi) of
#: (I.13) spaced <= 0.55 at chi = 10)
NU_NODES = (0.3, 0.4, 0.45, 0.48, 0.49, 0.495, 0.499, 0.4998, 0.5)
#: the grids: ``n`` cells per side over the extent (Delta = 2.5/256 ~ H/10 at chi = 10 for 4 sides)
N_TABLE = 256
EXTENTS = {4: 1.25, 3: (-1.8, 1.8, -1.3, 2.3)}
#: validation points (sides, base, nu, chi, n): off the nodes in chi and nu, and the finer grid on nodes
VALIDATION = ([(s, "frictionless", 0.3, c, N_TABLE) for s in (3, 4) for c in (0.6, 7.8)]
              + [(s, "bonded", nu, c, N_TABLE) for s in (3, 4)
                 for nu, c in ((0.35, 0.3), (0.465, 4.1), (0.4855, 8.7), (0.497, 2.9), (0.4994, 6.0))]
              + [(4, "bonded", 0.45, CHI_NODES[16], 384), (3, "bonded", 0.3, CHI_NODES[10], 384)])


def _layer(nu: float, base: str):
    from ..layers.kernels import BondedLayer, FrictionlessLayer, IncompressibleLayer

    if base == "frictionless":
        return FrictionlessLayer(nu)
    return IncompressibleLayer() if nu == 0.5 else BondedLayer(float(nu))


def _extent(sides: int, scale: float):
    e = EXTENTS[sides]
    if isinstance(e, tuple):  # scaled about the level set's centre (the origin)
        return tuple(scale * v for v in e)
    return scale * e


def _half_space_force(sides: int, nu: float, n: int, scale: float) -> float:
    """The half-space force; ``vartheta = mu/(1 - nu)`` is its only nu (solved at nu = 0: nu = 1/2 is admissible for
    the incompressible layer only).
    """
    from ..layers.kernels import HalfSpace
    from ..numerics import solve_2d
    from ..punch import Punch

    key = (sides, n, scale)
    if key not in _HS:
        _HS[key] = solve_2d(HalfSpace(), Punch.pyramid(45, sides), delta0=1.0, n=n, extent=_extent(sides, scale),
                            nu=0.0, tol=1e-11, workers=1).force
    return _HS[key] / (1.0 - nu)


_HS: dict = {}
#: the domain grows by these factors when a contact reaches its boundary (a nearly incompressible thin layer piles
#: up around the tip: its contact leaves the level set)
SCALES = (1.0, 1.3, 1.7, 2.2)


def direct_ratio(sides: int, base: str, nu: float, chi: float, n: int = N_TABLE) -> float:
    """``Pi = P_layer/P_hs`` of the direct solver at ``chi`` (layer ``H = 1/chi`` under the 45-degree pyramid at
    depth 1), both on the same grid (the domain enlarged, for both, when the contact reaches its boundary).
    """
    from ..errors import InputError
    from ..numerics import solve_2d
    from ..punch import Punch

    for scale in SCALES:
        try:
            res = solve_2d(_layer(nu, base), Punch.pyramid(45, sides), delta0=1.0, H=1.0 / chi, n=n,
                           extent=_extent(sides, scale), tol=1e-11, workers=1,
                           nu=nu if base == "frictionless" else None)
        except InputError as exc:
            if "boundary of the computational domain" in str(exc) and scale != SCALES[-1]:
                continue
            raise
        return res.force / _half_space_force(sides, nu, n, scale)
    raise AssertionError("unreachable")


def build_pyramid_table(out: Path | None = None, progress: bool = False, validate: bool = True,
                        sides_list: tuple = (4, 3), work: Path | None = None) -> dict[str, np.ndarray]:
    """Solve the grid (and the validation points) and return the arrays; write them to ``out`` if given (``work``:
    a folder keeping each finished curve, so that an interrupted build resumes).
    """
    chi = np.array(CHI_NODES)
    solved = chi >= CHI_SOLVED
    curves = [("frictionless", 0.3)] + [("bonded", nu) for nu in NU_NODES]
    y = np.full((len(sides_list), len(curves), chi.size), np.nan)
    t0 = time.perf_counter()
    for a, sides in enumerate(sides_list):
        for i, (base, nu) in enumerate(curves):
            done = None if work is None else Path(work) / f"curve_{sides}_{base}_{nu!r}.npy"
            if done is not None and done.exists():
                y[a, i] = np.load(done)
                continue
            for j in np.flatnonzero(solved):
                y[a, i, j] = math.log(direct_ratio(sides, base, nu, float(chi[j])))
            if done is not None:
                np.save(done, y[a, i])
            if progress:
                print(f"{sides} sides, {base} nu = {nu}: done ({time.perf_counter() - t0:.0f} s)", file=sys.stderr,
                      flush=True)
    data = dict(sides=np.array(sides_list), chi=chi, nu=np.array(NU_NODES), y=y)
    if out is not None:
        np.savez_compressed(Path(out), **data)
    if validate:
        rows = []
        for sides, base, nu, c, n in VALIDATION:
            if sides in sides_list:
                rows.append((sides, 0 if base == "frictionless" else 1, nu, c, n,
                             math.log(direct_ratio(sides, base, nu, c, n))))
                if progress:
                    print(f"check {rows[-1]} ({time.perf_counter() - t0:.0f} s)", file=sys.stderr, flush=True)
        data["check"] = np.array(rows)
        if out is not None:
            np.savez_compressed(Path(out), **data)
    return data


def main(argv: list[str] | None = None) -> int:
    """Command line: ``python -m thinlayer.contact._pyramid_table_build [--out PATH]``."""
    from .any_thickness_pyramids import PYRAMID_TABLE_PATH

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=PYRAMID_TABLE_PATH, help=f"output .npz (default {PYRAMID_TABLE_PATH})")
    args = ap.parse_args(argv)
    build_pyramid_table(out=args.out, progress=True)
    print(f"wrote {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
