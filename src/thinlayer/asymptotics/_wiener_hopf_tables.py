"""Boundary-layer tables (3.22) shipped with the package, for the Poisson ratios users and the validation study ask
most often.

A table is the Chebyshev series of ``q̂(τ) - τ`` in ``√τ`` that :func:`thinlayer.asymptotics.wiener_hopf_solution`
builds by de Hoog inversion (seconds per Poisson ratio).  ``data/wiener_hopf_tables.npz`` holds the series for the
arguments in :data:`SHIPPED`, computed by the same code (``python -m thinlayer.asymptotics._wiener_hopf_build``);
any other argument set is computed, then kept in the per-user disk cache (:mod:`thinlayer._cache`).  The tests
check every shipped table against a fresh de Hoog inversion at points between its Chebyshev nodes, and rebuild
them all with ``THINLAYER_SLOW=1``.
"""
from __future__ import annotations

from fractions import Fraction
from functools import lru_cache
from pathlib import Path

import numpy as np

TABLE_PATH = Path(__file__).resolve().parent / "data" / "wiener_hopf_tables.npz"

#: the Poisson ratios shipped: exact ones, and floats as the user types them (a float is its exact binary value)
SHIPPED_NUS = ("0", "1/5", "1/4", "3/10", "1/3", "2/5", "9/20", "49/100", 0.2, 0.3, 0.4, 0.45, 0.49, "frictionless")
#: the arguments ``(kernel, normaliser, dps, n)`` of the shipped tables: those of ``boundary_layer_exact(nu)``
SHIPPED_ARGS = ("exact", "alexandrov", 20, None)


def nu_key(nu) -> str:
    """The text of a Poisson ratio key: ``"p/q"`` of its exact value, or ``"frictionless"``."""
    if isinstance(nu, str) and nu == "frictionless":
        return nu
    f = Fraction(nu) if not isinstance(nu, str) else Fraction(nu)
    return f"{f.numerator}/{f.denominator}"


def table_key(nu, kernel: str, normaliser: str, dps: int, n) -> str:
    """The name of a table in the shipped file."""
    return f"{nu_key(nu)}|{kernel}|{normaliser}|{dps}|{'auto' if n is None else int(n)}"


@lru_cache(maxsize=1)
def _tables() -> dict[str, np.ndarray]:
    try:
        with np.load(TABLE_PATH, allow_pickle=False) as z:
            keys = [str(k) for k in z["keys"]]
            return {k: np.array(z[f"t{i}"], dtype=float) for i, k in enumerate(keys)}
    except (OSError, KeyError, ValueError):  # no file or a damaged one: every table is computed
        return {}


def shipped_table(nu, kernel: str, normaliser: str, dps: int, n) -> np.ndarray | None:
    """The shipped Chebyshev coefficients for these arguments, or None."""
    t = _tables().get(table_key(nu, kernel, normaliser, dps, n))
    return None if t is None else t.copy()


def shipped_keys() -> list[str]:
    """The names of the tables in the shipped file."""
    return list(_tables())
