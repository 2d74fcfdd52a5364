r"""The thin-layer force law (1.8) of a polyhedral tip (a pyramid), read through its polygonal level set (issue 24).

The engine's law (:mod:`~thinlayer.asymptotics.force_law`) integrates the inner terms (2.26)-(2.27), (4.1) over
``omega0 = {Phi < delta0}`` and adds the boundary layer's force defect (3.15)-(3.25) along ``Gamma0``:

    P = (vartheta/(A H)) V + (vartheta H/A)(M_1 + m_1/2) J + remainder,    V = iint (delta0 - Phi)_+,
    J = oint_{Gamma0} |grad Phi| ds.

Why it still holds for a pyramid (:mod:`thinlayer.punch.pyramid`):

* ``p_0 = vartheta (delta0 - Phi)/(A H)`` is continuous: ``iint p_0 = vartheta V/(A H)``, ``V = |omega0| delta0/3``.
* ``p_1 = (vartheta H/A) M_1 Laplacian Phi`` is a line measure on the ridges (the jump of grad Phi across them);
  its mass over omega0 is, by the divergence theorem in the sense of distributions,
  ``iint Laplacian Phi = oint |grad Phi| ds = cot(alpha) |Gamma0| = J``.
* On each straight edge of the polygon the boundary layer is the one-dimensional problem (3.15) with
  ``g = |grad Phi| = cot(alpha)``: its defect ``(vartheta g/A) H m_1/2`` per length adds ``(vartheta H/A)(m_1/2) J``.

So the coefficient of J is the engine's, derived on a polynomial punch (it depends on the layer only; called, not
copied), and ``P_0 = vartheta N tan(pi/N) tan^2(alpha) delta0^3/(3 A H)``, ``J = 2 N tan(pi/N) delta0``.

Order of the remainder (relative to P_0; ``a`` = the inradius ``delta0 tan(alpha)`` = ``2|omega0|/|Gamma0|``):

* the edges are straight: the boundary layer's curvature term, ``O((H/a)^3)`` for a smooth contour, is absent;
* the apex: Phi is homogeneous of degree 1 like the cone, so the inner expansion fails in the region ``r ~ H``
  where the pressure differs from ``p_0 + p_1`` by ``O(vartheta cot(alpha))``: a force ``O(vartheta cot(alpha)
  H^2)``, against ``P_0 ~ vartheta cot(alpha) a^3/H`` that is ``(H/a)^3``; the ridges' own strips of width H
  carry ``p_2 ~ delta''`` across them, whose force vanishes except at their ends (apex, corners);
* the N corners of the contour: the boundary layer of an edge is not the whole story in an ``H x H`` square at
  each corner (the corner problem of two edges, where the ridges end too); the pressure there is
  ``O(vartheta cot(alpha)/A)``: a force ``O(vartheta cot(alpha) H^2)`` and an area ``O(H^2)`` per corner, i.e.
  ``(H/a)^3`` in the force and ``(H/a)^2`` in the area.

Hence ``P = P_0 + P_1 + O(P_0 (H/a)^3)`` (q = 3), measured against :func:`thinlayer.numerics.solve_2d` in
tests/asymptotics/test_pyramid_law.py.  The contact area is the polygon shrunk by the edge shift (3.25),
``|omega| = N tan(pi/N) (a - h^* H)^2 = |omega0| - h^* H |Gamma0| + O(H^2)`` (its ``H^2`` term is of the order of
the corners' unknown one).
"""
from __future__ import annotations

from typing import Any

import sympy as sp

from .. import symbols as S
from ..errors import InputError, boundary
from ..layers.kernels import LayerKernel
from ..punch import Punch, Tip
from .force_law import force_law
from .tip_law import TipForceLaw

__all__ = ["REMAINDER_ORDER", "polyhedral_force_law"]

#: the order q of the remainder O(P0 (H/a)^q) (module docstring)
REMAINDER_ORDER = 3.0

_SOURCES = ("the apex region r ~ H (Phi homogeneous of degree 1, like the cone) and the corners of the polygonal "
            "contour (an H x H region each: area O(H^2), force O(vartheta cot(alpha) H^2)), both (H/a)^3; the straight "
            "edges add no curvature term")


@boundary
def polyhedral_force_law(layer: LayerKernel, tip: Any) -> TipForceLaw:
    r"""The force law (1.8) of a polyhedral tip (module docstring): ``P0 + P1`` in closed form for a regular pyramid,
    through the numeric polygon (``.evaluate``) for any other ``max`` of planes.

    Examples
    --------
    >>> from thinlayer import BondedLayer, Punch
    >>> law = polyhedral_force_law(BondedLayer(), Punch.pyramid(sides=4))
    >>> law.remainder_order
    3.0
    """
    if not isinstance(layer, LayerKernel) or not layer.has_thickness:
        raise InputError(f"the thin-layer law needs a layer of finite thickness (e.g. BondedLayer(0.3)), got {layer!r}")
    if not isinstance(tip, Tip) or tip.axisymmetric or tip.polynomial is not None or tip.fixed_contact \
            or tip.smoothness != "ridge":
        raise InputError(f"polyhedral_force_law takes a polyhedral tip (Punch.pyramid(35), Punch.berkovich(), "
                         f"Punch.from_expr('max(...)')); tips of revolution: tip_force_law; got {tip!r:.80}")
    # the coefficient of J is the engine's, derived on a polynomial punch: it does not depend on the shape
    coefficient = force_law(layer, Punch.paraboloid()).coefficient
    exprs = getattr(tip, "level_set_expressions", None)
    exprs = exprs() if exprs is not None else None
    P0 = P1 = None
    if exprs is not None:
        P0 = sp.factor(layer.vartheta / (layer.A * S.H) * exprs["volume"])
        P1 = sp.factor(coefficient * exprs["flux"])
    return TipForceLaw(layer, tip, P0, P1, coefficient, REMAINDER_ORDER, _SOURCES)
