r"""Build the any-thickness table (``contact/data/any_thickness.npz``) from the direct solver.

``python -m thinlayer.contact._table_build [--small] [--out PATH]`` regenerates it; the tests re-run
:func:`build_table` at a coarse size.  The table is data, not a fit: every entry is a direct solution
(:func:`thinlayer.numerics.solve_axisymmetric`, spectral, ~1e-10) of the sphere ``Phi = r^2/(2R)`` on a layer,
at ``chi = sqrt(R delta0)/H`` on a geometric grid from :data:`CHI_LO` to :data:`CHI_HI`, and stored normalised
by the anchor of :func:`thinlayer.contact.any_thickness.anchor` (Hertz plus the thin-layer law), so that what
is interpolated is smooth and tends to 0 at both ends:

    y = log(P / (P_Hertz (1 + w))),     z = log(c / (a (1 + w g)/(1 + w))),    a = sqrt(R delta0).

Three sets: the frictionless base (one curve: its kernel does not depend on nu); the bonded layer with
``-1 < nu < 0.3`` at Chebyshev-Gauss nodes in nu (anchor: the compressible leading force (1.8)); the bonded
layer with ``0.3 <= nu <= 1/2``, anchor the two-term model (I.11), whose crossover variable
``lambda = 24 (1/2 - nu) chi^2 ~ (k c)^2`` (I.13) sets the nodes: at each chi, Chebyshev-Lobatto nodes in
``u = log(1 + sqrt(lambda))`` from ``u = 0`` (nu = 1/2) to the u of nu = 0.3.  (Measured while choosing: 13 nodes
in u interpolate to ~1e-5; in ``sqrt(lambda)/(1 + sqrt(lambda))`` the compressible end was crowded, 5e-3.)
Validation points (chi half-way between nodes, nu between nodes) are solved too and stored with the table.
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
from ..numerics import solve_axisymmetric
from ..punch import Punch
from .any_thickness import (
    CHI_HI,
    CHI_LO,
    NU_SPLIT,
    TABLE_PATH,
    anchor,
    build_law,
    high_nu_of_u,
    high_u_max,
    low_nu_nodes,
)

__all__ = ["build_table", "direct_ratios", "main"]

#: table sizes: (chi nodes, low-nu nodes, high u nodes); ``small`` is the coarse size the tests re-run
FULL = (45, 14, 13)
SMALL = (4, 3, 3)


def _layer(nu: float, base: str) -> LayerKernel:
    if base == "frictionless":
        return FrictionlessLayer(nu)
    return IncompressibleLayer() if nu == 0.5 else BondedLayer(float(nu))


def direct_ratios(nu: float, base: str, chi: float) -> tuple[float, float, float, float]:
    """``(P/P_Hertz, c/sqrt(R delta0), force estimate, radius estimate)`` of the direct solver (R = H = mu = 1)."""
    res = solve_axisymmetric(_layer(nu, base), Punch.paraboloid(1), chi * chi, H=1.0, mu=1.0,
                             nu=nu if base == "frictionless" else None)
    vt = 1.0 / (1.0 - nu)
    PH = 8.0 / 3.0 * vt * chi**3
    return res.force / PH, res.radius / chi, res.force_error, res.radius_error / res.radius


def _normalised(nu: float, base: str, chi: float, two_term: bool) -> tuple[float, float, float, float]:
    P, c, ef, ec = direct_ratios(nu, base, chi)
    w, g = anchor(np.array([chi]), nu, base, two_term)
    y = math.log(P / (1.0 + w[0]))
    z = math.log(c / ((1.0 + w[0] * g[0]) / (1.0 + w[0])))
    return y, z, ef, ec


def build_table(size: tuple[int, int, int] = FULL, out: Path | None = None, progress: bool = False,
                validate: bool = True, chi_range: tuple[float, float] = (CHI_LO, CHI_HI)) -> dict[str, np.ndarray]:
    """Solve the grid (and the validation points) and return the arrays; write them to ``out`` if given.

    Parameters
    ----------
    size : tuple of int
        ``(chi nodes, low-nu nodes, high-u nodes)``; :data:`FULL` is the shipped table, :data:`SMALL` the tests'.
    out : Path, optional
        ``.npz`` file to write (refused if it exists and is not the package's own table).
    progress : bool
        Print a line per chi node.
    validate : bool
        Also solve the validation points.
    chi_range : tuple of float
        First and last chi node (the shipped table: ``(CHI_LO, CHI_HI)``; a coarse test may stop earlier).
    """
    n_chi, n_low, n_high = size
    if min(size) < 2:
        raise InputError(f"size needs at least 2 nodes in each direction, got {size}")
    chi = np.geomspace(chi_range[0], chi_range[1], n_chi)
    low_nu = low_nu_nodes(n_low)
    uf = 0.5 * (1.0 - np.cos(np.pi * np.arange(n_high) / (n_high - 1)))  # Chebyshev-Lobatto on [0, 1]
    shape_low, shape_high = (n_chi, n_low), (n_chi, n_high)
    data = {k: np.zeros(s) for k, s in [("low_y", shape_low), ("low_z", shape_low), ("low_err", shape_low),
                                         ("high_y", shape_high), ("high_z", shape_high), ("high_err", shape_high),
                                         ("high_nu", shape_high)]}
    for k in ("fric_y", "fric_z", "fric_err"):
        data[k] = np.zeros(n_chi)
    t0 = time.perf_counter()
    for i, x in enumerate(chi):
        y, z, ef, ec = _normalised(0.3, "frictionless", x, False)
        data["fric_y"][i], data["fric_z"][i], data["fric_err"][i] = y, z, max(ef, ec)
        for j, nu in enumerate(low_nu):
            y, z, ef, ec = _normalised(nu, "bonded", x, False)
            data["low_y"][i, j], data["low_z"][i, j], data["low_err"][i, j] = y, z, max(ef, ec)
        umax = high_u_max(x)
        for j, f in enumerate(uf):
            nu = high_nu_of_u(f * umax, x)
            y, z, ef, ec = _normalised(nu, "bonded", x, True)
            data["high_nu"][i, j] = nu
            data["high_y"][i, j], data["high_z"][i, j], data["high_err"][i, j] = y, z, max(ef, ec)
        if progress:
            print(f"chi = {x:.4g} done ({time.perf_counter() - t0:.0f} s)", file=sys.stderr, flush=True)
    data.update(chi=chi, low_nu=low_nu, high_uf=uf, size=np.array(size))
    if validate:
        data.update(_validation_points(chi, n_low))
        data["check_err"] = check_errors(data)
    if out is not None:
        out = Path(out)
        if out.exists() and out.resolve() != TABLE_PATH.resolve():
            raise FileExistsError(f"{out} exists; remove it first or write elsewhere")
        np.savez_compressed(out, **data)
    return data


def _validation_points(chi: np.ndarray, n_low: int) -> dict[str, np.ndarray]:
    """Direct solutions off the grid: chi half-way between nodes; nu between the nodes of each set."""
    rng = np.random.default_rng(12345)
    xm = np.sqrt(chi[:-1] * chi[1:])
    rows = []
    for x in xm:
        rows.append(("frictionless", 0.3, float(x)))
        rows.append(("bonded", float(rng.uniform(-0.99, NU_SPLIT)), float(x)))
        rows.append(("bonded", float(rng.uniform(NU_SPLIT, 0.5)), float(x)))
        rows.append(("bonded", float(0.5 - (0.5 - NU_SPLIT) * rng.uniform() ** 6), float(x)))
    for x in chi[:: max(1, len(chi) // 10)]:
        rows.append(("bonded", float(rng.uniform(-0.99, NU_SPLIT)), float(x)))
        rows.append(("bonded", float(0.5 - (0.5 - NU_SPLIT) * rng.uniform() ** 3), float(x)))
    out = np.array([(0 if b == "frictionless" else 1, nu, x, *direct_ratios(nu, b, x)) for b, nu, x in rows])
    return {"check": out}


def check_errors(data: dict[str, np.ndarray]) -> np.ndarray:
    """Rows ``(set, chi, force error, radius error)`` of the law built from ``data`` against its validation
    points (set 0 frictionless, 1 bonded nu < NU_SPLIT, 2 bonded nu >= NU_SPLIT).
    """
    rows = []
    for kind, nu, x, P, c, _, _ in data["check"]:
        base = "frictionless" if kind == 0 else "bonded"
        law = build_law(data, float(nu), base)
        Pl, cl = law.ratios(np.array([x]))
        which = 0 if kind == 0 else 1 if nu < NU_SPLIT else 2
        rows.append((which, x, abs(Pl[0] / P - 1), abs(cl[0] / c - 1)))
    return np.array(rows)


def main(argv: list[str] | None = None) -> int:
    """Command line: ``python -m thinlayer.contact._table_build [--small] [--out PATH]``."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--small", action="store_true", help="the coarse size of the tests")
    ap.add_argument("--out", type=Path, default=TABLE_PATH, help=f"output .npz (default {TABLE_PATH})")
    args = ap.parse_args(argv)
    build_table(SMALL if args.small else FULL, args.out, progress=True)
    print(f"wrote {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
