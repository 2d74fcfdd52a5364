"""Rigid tips ``x3 = -Phi(x1, x2)`` (1.1): the tip protocol, the tip kinds a user can name, and their modules.

* :mod:`.base` -- :class:`Tip` (what every tip answers), :class:`LevelSet`, the registry :data:`TIPS` of
  :class:`TipKind` rows and :func:`register_tip`;
* :mod:`.polynomial` -- :class:`Punch`, the polynomial punch and its catalogue (paraboloid, elliptic paraboloid,
  fourth-degree paraboloid, general polynomial);
* :mod:`.flat` -- :class:`FlatPunch`, the flat-ended cylinder (F.1);
* :mod:`.spec` -- :func:`tip_from_spec`, ``"paraboloid:R=10"`` read by the restricted grammar.

A new tip kind is one module here (a :class:`Tip` subclass and a ``register_tip(TipKind(...))`` line), imported
below.
"""
from ..symbols import laplacian
from .base import SMOOTHNESS, TIPS, LevelSet, PunchError, Tip, TipKind, TipParameter, is_polynomial_tip, register_tip
from .flat import FlatPunch
from .polynomial import MAX_DEGREE, MAX_TERMS, MAX_TOTAL_DEGREE, Punch, PunchTooLargeError
from .spec import TipSpecError, tip_from_spec, valid_forms

__all__ = ["MAX_DEGREE", "MAX_TERMS", "MAX_TOTAL_DEGREE", "SMOOTHNESS", "TIPS", "FlatPunch", "LevelSet", "Punch",
           "PunchError", "PunchTooLargeError", "Tip", "TipKind", "TipParameter", "TipSpecError", "is_polynomial_tip",
           "laplacian", "register_tip", "tip_from_spec", "valid_forms"]
