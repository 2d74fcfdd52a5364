"""What the direct solvers ask of a layer: a numeric Poisson ratio, and quadrature nodes for ``L(u) - 1``.

Shared by :mod:`thinlayer.numerics.axisymmetric` and :mod:`thinlayer.numerics.fft2d`.  Only the layer
interface is used (``numeric_nu``, ``parameter``, ``symbolic_coefficients``, ``L_numeric``), never the
concrete layer class.
"""
from __future__ import annotations

import math
import numbers
from typing import Any

import numpy as np
import sympy as sp

from .._checks import InputError, InputTypeError
from .._lazy import lazy_module
from ..layers.kernels import LayerKernel

special = lazy_module("scipy.special")  # scipy imported on first use

__all__ = ["GAUSS", "U_MAX", "gauss_panels", "numeric_layer_nu", "panel_count"]

#: ``L(u) - 1 = O(u^2 e^{-2u}) < 1e-16`` beyond this u (2.4)
U_MAX = 22.0
#: Gauss-Legendre points per panel of the composite rules
GAUSS = 16


def numeric_layer_nu(layer: Any, nu: Any) -> float:
    """Check that ``layer`` can be evaluated numerically and return its Poisson ratio as a float.

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` with numeric nu, ``FrictionlessLayer()``, ``HalfSpace()`` or the incompressible
        layer (kernel (2.3) at ``nu = 1/2``).
    nu : float or None
        Poisson ratio; needed only when the layer fixes none (``layer.numeric_nu is None``), and then
        ``-1 < nu < 1/2``; if given for a layer that fixes one, it must agree.

    Returns
    -------
    float
        The Poisson ratio defining ``vartheta = mu/(1 - nu)`` (2.1).

    Raises
    ------
    TypeError
        If ``layer`` is not a layer kernel or ``nu`` not a number.
    ValueError
        For a symbolic layer, a missing, disagreeing or inadmissible nu, or a kernel that cannot be
        evaluated numerically or does not tend to the half-space value ``L = 1`` (2.4).

    Examples
    --------
    >>> from thinlayer import BondedLayer, HalfSpace
    >>> numeric_layer_nu(BondedLayer(0.3), None), numeric_layer_nu(HalfSpace(), 0.25)
    (0.3, 0.25)
    """
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(
            f"layer must be a thinlayer LayerKernel (BondedLayer(nu), FrictionlessLayer(), HalfSpace()), "
            f"got {layer!r} ({type(layer).__name__})")
    layer_nu = layer.numeric_nu
    if layer_nu is None and layer.parameter is not None and not layer.symbolic_coefficients:
        raise InputError("the direct solver needs a numeric Poisson ratio: build e.g. BondedLayer(0.3), "
                         f"not {layer!r}")
    nu_val = layer.poisson_ratio(nu)
    if layer_nu is None and (isinstance(nu_val, bool) or not isinstance(nu_val, (numbers.Real, sp.Number))):
        raise InputTypeError(f"nu must be a real number with -1 < nu < 1/2, got {nu!r}")
    nu_val = float(nu_val)
    # nu = 1/2 is admissible only when the layer itself fixes it (the incompressible bonded layer, kappa = 1)
    if not (-1 < nu_val < 0.5 or (nu_val == 0.5 and layer_nu == 0.5)):
        raise InputError(f"Poisson ratio nu={nu_val} outside the admissible range -1 < nu < 1/2 "
                         "(nu = 1/2 only with the incompressible layer, IncompressibleLayer())")
    try:
        far = float(np.asarray(layer.L_numeric(np.array([2 * U_MAX]), "numpy"))[0])
    except Exception as exc:  # GenericLayer and friends
        raise InputError(f"layer {layer!r} cannot be evaluated numerically: {exc}") from exc
    if abs(far - 1.0) > 1e-12:
        raise InputError(f"layer kernel must tend to the half-space value L = 1 at large u (2.4); "
                         f"L({2 * U_MAX}) = {far}")
    return nu_val


def gauss_panels(T: float, npan: int, points: int = GAUSS) -> tuple[np.ndarray, np.ndarray]:
    """Nodes and weights of the composite Gauss-Legendre rule with ``npan`` equal panels on ``[0, T]``.

    Parameters
    ----------
    T : float
        Right end of the interval.
    npan : int
        Number of panels.
    points : int
        Gauss-Legendre points per panel.

    Returns
    -------
    tuple of numpy.ndarray
        ``(t, w)``, each of length ``npan * points``.
    """
    xg, wg = special.roots_legendre(points)
    edges = np.linspace(0.0, T, npan + 1)
    a, b = edges[:-1, None], edges[1:, None]
    t = (0.5 * (b - a) * xg + 0.5 * (a + b)).ravel()
    w = np.broadcast_to(0.5 * (b - a) * wg, (npan, points)).ravel().copy()
    return t, w


def panel_count(T: float, length: float) -> int:
    """Number of panels of at most ``length`` on ``[0, T]`` (at least 8)."""
    return max(8, math.ceil(T / length))
