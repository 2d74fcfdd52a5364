r"""The report's table of the edge shift h^* (3.25) from ``[edge_shift]``: Alexandrov's constants B, C (3.20)-(3.21),
the exact edge shift (Wiener--Hopf) and Alexandrov's approximation, for each Poisson ratio of the table.
"""
from __future__ import annotations

from typing import Any

from .base import DerivationFileError, num, short

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render"]

KEY = "edge_shift"
SCHEMA = {"nu": ((list,), "a list of numbers in (-1, 1/2)")}
ORDER = 60


def parse(table: Any, context: Any) -> tuple:
    """``[edge_shift] nu``: at most 50 numbers in (-1, 1/2), the rows of the table (none: no table)."""
    es = (table or {}).get("nu", [])
    if not all(isinstance(v, (int, float)) and not isinstance(v, bool) and -1 < v < 0.5 for v in es) or len(es) > 50:
        raise DerivationFileError(f"[edge_shift] nu = {short(es)}: a list of at most 50 numbers in (-1, 1/2)")
    return tuple(es)


def applies(der: Any) -> bool:
    return bool(der.sections.get(KEY))


def render(doc: Any, der: Any, context: Any) -> None:
    from ...asymptotics.boundary_layer import alexandrov_parameters
    from ...asymptotics.wiener_hopf import edge_shift_alexandrov, edge_shift_exact
    from ...layers.kernels import BondedLayer

    rows = []
    for v in der.sections[KEY]:
        B, C = alexandrov_parameters(BondedLayer(v)).numeric()
        rows.append([f"${num(v)}$", f"${num(B)}$", f"${num(C)}$", f"${num(edge_shift_exact(v))}$",
                     f"${num(edge_shift_alexandrov(v))}$"])
    doc.section("Edge shift of the contact area").text(
        r"The contour of the contact area lies the distance $h^* H$ inside $\Gamma_0$ (Table~\ref{tab:edge}).")
    doc.table(r"Alexandrov's constants $B$, $C$, (3.20)--(3.21), and the edge shift $h^*$: exact "
              r"(Wiener--Hopf) and Alexandrov's approximation (3.25)~\cite{alexandrov}.", "rrrrr",
              [r"$\nu$", "$B$", "$C$", r"$h^*$ exact", r"$h^*$ (3.25)"], rows, label="tab:edge")
