r"""The report's section on the two-term model (I.10), (I.11) of a nearly incompressible layer under a sphere.

It applies to the catalogue's paraboloid of revolution (the trait ``"sphere"``) on a compressible bonded layer
with a symbolic nu or 1/4 < nu < 1/2, where the compressible expansion needs ever thinner layers (I.13).
"""
from __future__ import annotations

from typing import Any

from .base import compressible_bonded, sphere_rows, tagged

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render"]

KEY = None
SCHEMA: dict = {}
ORDER = 40


def parse(table: Any, context: Any) -> None:
    return None


def applies(der: Any) -> bool:
    layer = der.layer
    if der.punch is None or not compressible_bonded(layer):
        return False
    nu = layer.numeric_nu
    return "sphere" in der.punch_traits and (nu is None or 0.25 < nu < 0.5)


def render(doc: Any, der: Any, context: Any) -> None:
    from ...asymptotics.incompressible import two_term_sphere

    doc.section("Nearly incompressible layer: the two-term model").text(
        r"Near $\nu = 1/2$ the compressible expansion needs $\lambda^2 = (a/H)^2/m_1 \gg 1$ (I.13); the two-term "
        r"model (I.10), $-\Delta p + k^2 p = f$ with $f = \vartheta (\delta_0 - \Phi)/(c_1 H^3)$ and "
        r"$k^2 = 1/(m_1 H^2)$, holds in both regimes. For the sphere, in terms of the contact radius $c$:")
    tagged(doc, sphere_rows(two_term_sphere(der.layer)))
