r"""Which thin-layer model where (I.13): the compressible expansion, the incompressible or the two-term model."""
from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ... import symbols as S
from ..._checks import InputTypeError, parse_nu, positive
from ...display import RichDisplay
from ...errors import boundary, boundary_methods
from ...layers.kernels import BondedLayer, IncompressibleLayer, LayerKernel
from ...results import checked_lambdify

__all__ = ["Regime", "regime"]


# =============================================================================================
# (I.13): which model where
# =============================================================================================
@boundary_methods
@dataclass(frozen=True)
class Regime(RichDisplay):
    """Where the compressible expansion and the incompressible model hold (I.13).

    Attributes
    ----------
    nu, H_over_a : float
        Poisson ratio and thickness over contact half-width.
    m1 : float
        ``m_1(nu)`` (2.20), ``~ 1/(3 (1 - 2 nu))`` near 1/2 (``inf`` at nu = 1/2).
    lambda2 : float
        ``(a/H)^2/m_1``, the ratio of the two terms of (I.10).
    compressible_correction : float
        ``4 m_1 (H/a)^2 = 4/lambda^2``: size of the first correction of the compressible force law
        (the paraboloid's ``2 m_1 H^2/(R delta0)``); the expansion needs it small.
    incompressible_correction : float
        ``(3/16) lambda^2``: the relative force change of the sphere caused by ``c_0 = A``, neglected by
        the incompressible model (from the series of (I.11) at ``x = 0``).
    model : str
        ``"compressible"``, ``"incompressible"`` or ``"two-term"``: the simplest model whose neglected
        term is below ``tol``.
    """

    nu: float
    H_over_a: float
    tol: float
    m1: float
    lambda2: float
    compressible_correction: float
    incompressible_correction: float
    model: str

    equation = "I.13"

    def latex(self) -> str:
        return (rf"\lambda^2 = \frac{{(a/H)^2}}{{m_1}} = {self.lambda2:.4g},\quad "
                rf"4 m_1 (H/a)^2 = {self.compressible_correction:.3g},\quad "
                rf"\tfrac{{3}}{{16}}\lambda^2 = {self.incompressible_correction:.3g}"
                rf"\ \Rightarrow\ \text{{{self.model}}} \tag{{I.13}}")

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``: the model (I.13) picks and the sizes it compares with ``tol``."""
        return [f"Regime: ν = {self.nu:.6g}, H/a = {self.H_over_a:.6g} -> {self.model} model   (I.13)",
                f"  m₁ = {self.m1:.6g},  λ² = (a/H)²/m₁ = {self.lambda2:.4g}",
                f"  compressible correction 4m₁ (H/a)² = {self.compressible_correction:.3g},  "
                f"incompressible correction (3/16) λ² = {self.incompressible_correction:.3g},  tol = {self.tol:.3g}"]

    def lambdify(self, backend: str = "numpy") -> Callable:
        """``(lambda^2, 4/lambda^2, 3 lambda^2/16)`` as a numeric function of ``(nu, H_over_a)``."""
        m1 = BondedLayer().coefficients(1).m_expr(1)
        ha = sp.Symbol("H_over_a", positive=True)
        lam2 = 1 / (ha**2 * m1)
        return checked_lambdify([S.nu, ha], (lam2, 4 / lam2, sp.Rational(3, 16) * lam2), backend)



def _regime_layer(layer: Any) -> LayerKernel:
    """The layer of :func:`regime`; a bare Poisson ratio (deprecated) becomes its layer, with a warning."""
    if isinstance(layer, LayerKernel):
        return layer
    nv = parse_nu(layer, floats="float", upper_closed=True, symbols=False, example="'49/100', 0.49 or 0.5")
    if nv == 0.5:
        new, out = "IncompressibleLayer()", IncompressibleLayer()
    else:
        new, out = f"BondedLayer({layer!r})", BondedLayer(float(nv))
    warnings.warn(f"a Poisson ratio where the layer goes is deprecated; call regime({new}, H_over_a)",
                  DeprecationWarning, stacklevel=3)
    return out


@boundary
def regime(layer: LayerKernel, H_over_a: float, tol: float = 0.05) -> Regime:
    """Which thin-layer model to use for a layer at ``H/a`` (I.13).

    The compressible expansion (2.26)-(2.31) is a series in ``m_1 (H/a)^2`` and needs
    ``lambda^2 = (a/H)^2/m_1 >> 1``, i.e. ``1 - 2 nu >> (H/a)^2/3`` near 1/2; the incompressible model
    (I.3) needs ``lambda^2 << 1``; the two-term model (I.10) holds for both (``nu > 1/4``).

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` with a numeric ``-1 < nu < 1/2``, or ``IncompressibleLayer()`` (nu = 1/2).
        A bare Poisson ratio still works, with a DeprecationWarning.
    H_over_a : float
        Thickness over contact half-width (> 0).
    tol : float
        Accepted size of the neglected relative force term.

    Returns
    -------
    Regime

    Examples
    --------
    >>> layers = [BondedLayer(nu) for nu in (0.3, 0.45, 0.49, 0.4999)] + [IncompressibleLayer()]
    >>> [regime(layer, 0.05).model for layer in layers]
    ['compressible', 'compressible', 'two-term', 'incompressible', 'incompressible']
    """
    ha = positive(H_over_a, "H_over_a")
    tl = positive(tol, "tol")
    layer = _regime_layer(layer)
    nv = layer.numeric_nu
    if nv is None or not layer.has_two_term_model or not layer.has_thickness:
        raise InputTypeError(f"regime needs a numeric bonded layer, BondedLayer(nu) or IncompressibleLayer(), "
                        f"got {layer!r}")
    c0, c1 = layer.taylor_coefficients(1)
    m1 = math.inf if c0 == 0 else float(c1 / c0)  # m_1 = c_1/c_0 (2.20); A = 0 at nu = 1/2
    if m1 <= 0:
        # nu <= 1/4: m_1 <= 0, the expansion parameter |m_1| (H/a)^2 stays small; no two-term model
        return Regime(nv, ha, tl, m1, math.inf, 4 * abs(m1) * ha**2, math.inf, "compressible")
    lam2 = 0.0 if math.isinf(m1) else 1.0 / (m1 * ha**2)
    comp = math.inf if lam2 == 0 else 4.0 / lam2
    inc = 3.0 * lam2 / 16.0
    model = "compressible" if comp <= tl else "incompressible" if inc <= tl else "two-term"
    return Regime(nv, ha, tl, m1, lam2, comp, inc, model)
