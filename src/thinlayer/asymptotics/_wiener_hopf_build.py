"""Build ``data/wiener_hopf_tables.npz`` (see :mod:`thinlayer.asymptotics._wiener_hopf_tables`).

``python -m thinlayer.asymptotics._wiener_hopf_build [PATH]`` computes the boundary-layer table of
:func:`~thinlayer.asymptotics.boundary_layer_exact` for every shipped Poisson ratio, with no shipped file and no
disk cache in the way, and writes them to PATH (default: the package's file).
"""
from __future__ import annotations

import os
import sys
from pathlib import Path

import numpy as np

from . import _wiener_hopf_tables as T


def fresh_table(nu) -> np.ndarray:
    """The table for ``nu`` computed now (no shipped file, no disk cache)."""
    from .wiener_hopf import fresh_table as fresh

    return np.asarray(fresh(nu, *T.SHIPPED_ARGS), dtype=float)


def build(path: Path = T.TABLE_PATH) -> list[str]:
    keys, arrays = [], {}
    for i, nu in enumerate(T.SHIPPED_NUS):
        keys.append(T.table_key(nu, *T.SHIPPED_ARGS))
        arrays[f"t{i}"] = fresh_table(nu)
    tmp = Path(path).with_suffix(".tmp.npz")
    np.savez_compressed(tmp, keys=np.array(keys), **arrays)
    os.replace(tmp, path)
    return keys


if __name__ == "__main__":
    print("\n".join(build(Path(sys.argv[1]) if len(sys.argv) > 1 else T.TABLE_PATH)))
