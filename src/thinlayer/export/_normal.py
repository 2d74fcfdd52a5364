r"""The reports' normalisation policy: a re-export of :mod:`thinlayer.normal`, where it now lives.

The policy moved down to :mod:`thinlayer.normal` (rank 0 of the architecture) so that every ``latex()`` and
``print(result)`` of the layers and the stages prints with it, not only the reports.  The report code keeps
importing it from here; a value that is not yet a sympy object goes through :func:`thinlayer.parse.as_expr`
first, as before.

>>> import sympy as sp
>>> from thinlayer import symbols as S
>>> normal_latex((sp.Rational(1, 2) - S.nu) / (1 - S.nu) ** 2)
'\\frac{1 - 2 \\nu}{2 \\left(1 - \\nu\\right)^{2}}'
"""
from __future__ import annotations

from typing import Any

from .. import normal as _policy
from ..normal import (  # noqa: F401 (re-exported for the report code)
    DIGITS,
    NormalLatexPrinter,
    ReportPrinter,
    Term,
    float_latex,
    normal_term,
    ordered_terms,
)
from ..parse import as_expr

__all__ = ["DIGITS", "NormalLatexPrinter", "ReportPrinter", "Term", "float_latex", "normal_latex", "normal_term",
           "normal_terms", "ordered_terms"]


def normal_latex(expr: Any, digits: int = DIGITS) -> str:
    """:func:`thinlayer.normal.normal_latex` of ``as_expr(expr)``."""
    return _policy.normal_latex(as_expr(expr), digits)


def normal_terms(expr: Any) -> list[Term]:
    """:func:`thinlayer.normal.normal_terms` of ``as_expr(expr)``."""
    return _policy.normal_terms(as_expr(expr))
