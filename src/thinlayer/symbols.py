"""Canonical sympy symbols of thinlayer, named as in the paper.

Every stage function uses these symbols, so results from different stages can be
combined and substituted into each other without renaming.

===============  =====================================================  ==========
symbol           meaning                                                paper
===============  =====================================================  ==========
``x1, x2``       dimensional surface coordinates                        (1.1)
``xi1, xi2``     scaled coordinates, ``x_j = H_* xi_j``                 (2.8)
``nu``           Poisson ratio                                          (1.3)
``kappa``        ``3 - 4 nu``                                           (2.3)
``mu``           shear modulus                                          (1.3)
``vartheta``     ``mu / (1 - nu)``                                      (2.1)
``H``            layer thickness                                        (1.2)
``delta0``       indentation depth                                      (1.2)
``epsilon``      small parameter                                        (1.2)
``Lambda``       large parameter ``1/epsilon``                          (2.9)
``H_s``          scaled thickness ``H_*`` (``H = epsilon H_*``)          (1.2)
``delta0_s``     scaled indentation ``delta_0^*``                       (1.2)
``s, u``         Fourier variable of the kernel                         (2.3)
===============  =====================================================  ==========
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import sympy as sp

#: the module's symbols, made (with sympy) on the first access of any of them (PEP 562)
_NAMES = ("x1", "x2", "xi1", "xi2", "nu", "kappa", "mu", "vartheta", "H", "delta0", "epsilon", "Lambda", "H_s",
          "delta0_s", "s", "u", "z", "VARTHETA")


def _make() -> dict[str, Any]:
    import sympy as sp  # here, not at import: a numeric solve() never needs sympy (issue 28 item 6)

    x1, x2 = sp.symbols("x_1 x_2", real=True)
    xi1, xi2 = sp.symbols("xi_1 xi_2", real=True)
    nu = sp.Symbol("nu", real=True)
    mu = sp.Symbol("mu", positive=True)
    return {
        "x1": x1, "x2": x2, "xi1": xi1, "xi2": xi2, "nu": nu,
        "kappa": sp.Symbol("kappa", positive=True),
        "mu": mu,
        "vartheta": sp.Symbol("vartheta", positive=True),
        "H": sp.Symbol("H", positive=True),
        "delta0": sp.Symbol("delta_0", positive=True),
        "epsilon": sp.Symbol("epsilon", positive=True),
        "Lambda": sp.Symbol("Lambda", positive=True),
        "H_s": sp.Symbol("H_*", positive=True),
        "delta0_s": sp.Symbol("delta_0^*", positive=True),
        "s": sp.Symbol("s", nonnegative=True),
        "u": sp.Symbol("u", nonnegative=True),
        "z": sp.Symbol("z"),  # z = s**2, the variable of the series (2.20)
        #: vartheta in terms of the material constants, (2.1)
        "VARTHETA": mu / (1 - nu),
    }


def __getattr__(name: str) -> Any:
    """The symbols ``x1, x2, ..., VARTHETA``, made on first use (sympy is imported then, not with the package)."""
    if name in _NAMES:
        values = _make()
        globals().update(values)
        return values[name]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_NAMES))


def starred(sym: sp.Symbol) -> sp.Symbol:
    """The scaled ("starred") counterpart of a punch parameter, as in (1.2): ``R_1 -> R_1^*``."""
    import sympy as sp

    return sp.Symbol(sym.name + "^*", **sym.assumptions0)


def laplacian(f: sp.Expr, v1: sp.Symbol, v2: sp.Symbol, power: int = 1) -> sp.Expr:
    """``Delta^power f`` in the variables (v1, v2): a sympy expression (a string would be sympified, i.e. run)."""
    import sympy as sp

    if not isinstance(f, sp.Basic) or not isinstance(v1, sp.Symbol) or not isinstance(v2, sp.Symbol):
        raise TypeError(f"laplacian needs a sympy expression and two Symbols, got {type(f).__name__}, "
                        f"{type(v1).__name__}, {type(v2).__name__} (read a formula with thinlayer.parse)")
    for _ in range(power):
        f = sp.diff(f, v1, 2) + sp.diff(f, v2, 2)
    return f
