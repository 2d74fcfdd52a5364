r"""The report's section on the punch (1.1) and the inner expansion (2.24)-(2.31), (4.1), from ``[inner]``.

``[inner] order`` is the number of inner terms (default: that of
:func:`thinlayer.asymptotics.inner.inner_pressure`); for the catalogue's elliptic paraboloid (its trait in
:attr:`thinlayer.export.derivation.Derivation.punch_traits`) the leading contact ellipse (3.1) follows.
"""
from __future__ import annotations

from typing import Any

from .base import DerivationFileError, incompressible_bonded, nl, polynomial_only

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render"]

KEY = "inner"
SCHEMA = {"order": ((int,), "a positive integer (number of terms)")}
ORDER = 20


def parse(table: Any, context: Any) -> int | None:
    """``[inner] order``: the number of inner terms, 1 to 30, or None (the stage's default)."""
    order = (table or {}).get("order")
    if order is not None and not 1 <= order <= 30:
        raise DerivationFileError(f"[inner] order = {order!r}: a positive integer (number of terms) up to 30")
    polynomial_only(KEY, table, context)
    return order


def applies(der: Any) -> bool:
    return der.punch is not None and not incompressible_bonded(der.layer)


def render(doc: Any, der: Any, context: Any) -> None:
    from ...asymptotics.inner import inner_pressure

    layer, punch = der.layer, der.punch
    ip = inner_pressure(layer, punch, der.sections.get(KEY))
    doc.section("Punch and inner expansion").text(r"The punch, (1.1):")
    doc.math(rf"\Phi(x_1, x_2) = {nl(punch.expr)} \tag{{1.1}}")
    doc.text(r"Inserting the moment expansion (2.22) into the integral equation (2.10) gives the inner terms "
             r"$p_k^*$ in the scaled variables (1.2), (2.8): $p_0^*$ by (2.27), the others by the closed form (4.1) "
             r"(equal to the recursion (2.28)):")
    doc.math(rf"p_0^*(\boldsymbol{{\xi}}) = {nl(ip.scaled_terms[0])} \tag{{2.27}}")
    rest = [rf"p_{{{k}}}^*(\boldsymbol{{\xi}}) = {nl(t)}" for k, t in enumerate(ip.scaled_terms) if k]
    if rest:
        doc.group(rest, "4.1")
    doc.text(r"In the dimensional variables the inner pressure, (2.26), is")
    doc.math(rf"p(x_1, x_2) \sim {nl(ip.pressure)} \tag{{2.26}}")
    if "elliptic paraboloid" in der.punch_traits:  # the catalogue punch, in its symbols R_1, R_2
        from ...asymptotics.contour import ellipse_contour

        e = ellipse_contour()
        doc.text(r"Its leading contact area is bounded by the ellipse $\Phi = \delta_0$, (3.1), with semi-axes")
        doc.math(rf"a = {nl(e.a)},\quad b = {nl(e.b)},\quad e^2 = {nl(1 - e.b**2 / e.a**2)} \tag{{3.1}}")
