r"""The sphere in every thin-layer model, side by side, and against the direct solver.

:func:`compare_sphere_models` runs the compressible expansion (:func:`thinlayer.solve`), the
incompressible model (I.8), the two-term model (I.11) with the edge correction (I.12), the
criterion (I.13) and, optionally, the direct solver
:func:`thinlayer.numerics.solve_axisymmetric`: the one place where the asymptotic stages
and the numerics meet for the nearly incompressible layer.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from .._checks import InputError, positive
from ..asymptotics.force_law import force_law
from ..asymptotics.incompressible import (
    IncompressibleLayer,
    Regime,
    incompressible_ellipse,
    regime,
    two_term_edge_shift,
    two_term_sphere,
)
from ..asymptotics.incompressible.operator import model_layer
from ..asymptotics.solution import ValidityError
from ..asymptotics.solution import compressible_solution as solve
from ..asymptotics.wiener_hopf import edge_shift_exact
from ..layers.kernels import LayerKernel
from ..numerics import solve_axisymmetric
from ..punch import Punch

__all__ = ["SphereModels", "compare_sphere_models"]


# =============================================================================================
# the sphere in every model, side by side
# =============================================================================================
@dataclass(frozen=True)
class SphereModels:
    """Force and contact radius of a sphere ``Phi = r^2/(2R)`` in each thin-layer model (and the direct solver).

    Attributes
    ----------
    compressible : tuple | None
        ``(P, c)`` from :func:`thinlayer.solve` (force with first correction (2.31), area with (3.25));
        ``None`` at nu = 1/2 (``A = 0``).
    incompressible : tuple
        ``(P, c)`` of (I.8) with nu = 1/2 constants, ``c = 2 sqrt(R delta0) - h(1/2) H`` (I.12).
    two_term : tuple
        ``(P, c)`` of (I.11), ``c`` corrected by (I.12).
    direct : tuple | None
        ``(P, c)`` of :func:`thinlayer.numerics.solve_axisymmetric`, or ``None``.
    regime : Regime
        :func:`regime` at ``H/a`` with ``a`` the two-term radius.
    """

    nu: float
    R: float
    delta0: float
    H: float
    mu: float
    compressible: tuple | None
    incompressible: tuple
    two_term: tuple
    direct: tuple | None
    regime: Regime

    def errors(self) -> dict[str, tuple[float, float]]:
        """Relative errors ``(P/P_direct - 1, c/c_direct - 1)`` of each model (needs ``direct``)."""
        if self.direct is None:
            raise InputError("no direct solution: call compare_sphere_models(..., direct=True)")
        out = {}
        for name in ("compressible", "incompressible", "two_term"):
            v = getattr(self, name)
            if v is not None:
                out[name] = (v[0] / self.direct[0] - 1.0, v[1] / self.direct[1] - 1.0)
        return out

    def latex(self) -> str:
        rows = []
        for name in ("compressible", "incompressible", "two_term", "direct"):
            v = getattr(self, name)
            if v is not None:
                rows.append(rf"\text{{{name.replace('_', '-')}}} & {v[0]:.6g} & {v[1]:.6g}")
        return (r"\begin{array}{lrr} \text{model} & P & c \\ " + r" \\ ".join(rows)
                + rf"\end{{array}}\quad \nu = {self.nu:g},\ \lambda^2 = {self.regime.lambda2:.3g}")

    def lambdify(self) -> Callable:
        """``model name -> (P, c)`` as a function (the numbers of this comparison)."""
        table = {n: getattr(self, n) for n in ("compressible", "incompressible", "two_term", "direct")}
        return lambda name: table[name]



def _compressible(layer: LayerKernel, punch: Punch, d0: float, H: float, mu: float) -> tuple[float, float]:
    """Force and contact radius of the compressible law (1.8), (3.25), also where it fails.

    The comparison exists to show where each model fails, so the tolerance check of :func:`solve` is off
    (``tol=inf``); where even that refuses (an unphysical value such as P <= 0), the raw law is evaluated.
    """
    try:
        sol = solve(layer, punch, d0, H, mu, tol=math.inf)
        return float(sol.force), math.sqrt(float(sol.contact_area) / math.pi)
    except ValidityError:
        vals = force_law(layer, punch).evaluate(d0, H, mu, edge_shift=float(edge_shift_exact(layer, dps=15)))
        return float(vals.force), math.sqrt(max(float(vals.area), 0.0) / math.pi)


def compare_sphere_models(layer: LayerKernel, R: float, delta0: float, H: float, mu: float = 1.0,
                          direct: bool = False) -> SphereModels:
    """Sphere in the compressible, incompressible and two-term models, optionally against the direct solver.

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` with a numeric ``1/4 < nu < 1/2``, or ``IncompressibleLayer()``.  A bare
        Poisson ratio still works, with a DeprecationWarning.
    R, delta0, H, mu : float
        float
        Sphere radius, indentation, thickness, shear modulus.
    direct : bool
        Also run :func:`thinlayer.numerics.solve_axisymmetric` with the layer.

    Returns
    -------
    SphereModels
    """
    layer, nu = model_layer(layer, "compare_sphere_models({layer}, R, delta0, H)", numeric=True)
    nv = float(nu)
    RR, d0, HH, mm = (positive(v, n) for v, n in ((R, "R"), (delta0, "delta0"), (H, "H"), (mu, "mu")))
    two = two_term_sphere(layer).evaluate(d0, RR, HH, mm)
    inc = incompressible_ellipse(sp.Symbol("R", positive=True), sp.Symbol("R", positive=True))
    inc_v = inc.evaluate(d0, HH, mm, R1=RR, R2=RR)
    h_half = float(two_term_edge_shift(IncompressibleLayer(), dps=15))
    incompressible = (inc_v.force, inc_v.a - h_half * HH)
    comp = None
    if layer.has_compressible_expansion:
        comp = _compressible(layer, Punch.paraboloid(RR), d0, HH, mm)
    dres = None
    if direct:
        res = solve_axisymmetric(layer, lambda r: r * r / (2 * RR), d0, HH, mm)
        dres = (float(res.force), float(res.radius))
    return SphereModels(nv, RR, d0, HH, mm, comp, incompressible, (two.force, two.radius_corrected), dres,
                        regime(layer, HH / two.radius))
