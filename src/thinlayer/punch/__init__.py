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

A new tip kind is one module here (a :class:`Tip` subclass and a ``register_tip(TipKind(...))`` line), imported
below.
"""
from ..symbols import laplacian
from .base import SMOOTHNESS, TIPS, LevelSet, PunchError, Tip, TipKind, TipParameter, is_polynomial_tip, register_tip
from .blunted_cone import BluntedCone
from .cone import Cone
from .flat import FlatPunch
from .polynomial import MAX_DEGREE, MAX_TERMS, MAX_TOTAL_DEGREE, Punch, PunchTooLargeError
from .power_law import PowerLaw
from .pyramid import Polyhedral, Pyramid
from .revolution import Revolution
from .spec import TipSpecError, tip_from_spec, valid_forms
from .sphere import Sphere

__all__ = ["MAX_DEGREE", "MAX_TERMS", "MAX_TOTAL_DEGREE", "SMOOTHNESS", "TIPS", "BluntedCone", "Cone", "FlatPunch",
           "LevelSet", "Polyhedral", "PowerLaw", "Punch", "PunchError", "PunchTooLargeError", "Pyramid", "Revolution",
           "Sphere", "Tip",
           "TipKind", "TipParameter", "TipSpecError", "is_polynomial_tip", "laplacian", "register_tip", "tip_from_spec",
           "valid_forms"]
