"""Rigid tips ``x3 = -Phi(x1, x2)`` (1.1): the tip protocol, the tip kinds a user can name, and their modules.

* :mod:`.base` -- :class:`Tip` (what every tip answers), :class:`LevelSet`, the registry :data:`TIPS` of
  :class:`TipKind` rows and :func:`register_tip`;
* :mod:`.polynomial` -- :class:`Punch`, the polynomial punch and its catalogue (paraboloid, elliptic paraboloid,
  fourth-degree paraboloid, general polynomial);
* :mod:`.flat` -- :class:`FlatPunch`, the flat-ended cylinder (F.1);
* :mod:`.cone`, :mod:`.sphere`, :mod:`.blunted_cone`, :mod:`.power_law`, :mod:`.revolution` -- the tips of
  revolution that are not polynomials (issue 24; common part in :mod:`._radial`);
* :mod:`.pyramid` -- :class:`Pyramid` (3 or 4 faces; Berkovich, Vickers) and :class:`Polyhedral` (any ``max`` of
  planes), tips with ridges;
* :mod:`.spec` -- :func:`tip_from_spec`, ``"paraboloid:R=10"`` read by the restricted grammar.

A new tip kind is one module here (a :class:`Tip` subclass and a ``register_tip(TipKind(...))`` line), named in
:data:`thinlayer.punch.base.CATALOGUE` (imported when the registry is first read).
"""
import importlib
from typing import Any

from .base import (
    SMOOTHNESS,
    LevelSet,
    PunchError,
    Tip,
    TipKind,
    TipParameter,
    catalogue,
    is_polynomial_tip,
    register_tip,
    tip_kind,
)
from .flat import FlatPunch
from .polynomial import MAX_DEGREE, MAX_TERMS, MAX_TOTAL_DEGREE, Punch, PunchTooLargeError
from .spec import TipSpecError, tip_from_spec, valid_forms

#: names imported on first use (PEP 562): the tips of revolution build sympy constants at import, and a numeric
#: ``solve()`` of a polynomial punch needs none of them (issue 28 item 6)
_LAZY = {"BluntedCone": "thinlayer.punch.blunted_cone", "Cone": "thinlayer.punch.cone",
         "PowerLaw": "thinlayer.punch.power_law", "Revolution": "thinlayer.punch.revolution",
         "Polyhedral": "thinlayer.punch.pyramid", "Pyramid": "thinlayer.punch.pyramid",
         "Sphere": "thinlayer.punch.sphere", "laplacian": "thinlayer.symbols"}


def __getattr__(name: str) -> Any:
    """``TIPS`` (every kind registered: :func:`~thinlayer.punch.base.catalogue`) and the lazily imported names."""
    if name == "TIPS":
        return catalogue()
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["MAX_DEGREE", "MAX_TERMS", "MAX_TOTAL_DEGREE", "SMOOTHNESS", "TIPS", "BluntedCone", "Cone", "FlatPunch",
           "LevelSet", "Polyhedral", "PowerLaw", "Punch", "PunchError", "PunchTooLargeError", "Pyramid", "Revolution",
           "Sphere", "Tip",
           "TipKind", "TipParameter", "TipSpecError", "is_polynomial_tip", "laplacian", "register_tip", "tip_from_spec",
           "tip_kind", "valid_forms"]
