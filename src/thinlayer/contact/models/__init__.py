"""The model registry of :func:`thinlayer.solve` (issue 29 item 1): one module per model, each registering itself.

``MODEL_REGISTRY`` holds the entries in increasing preference; :func:`register_model` checks a new entry's
contract (:mod:`thinlayer.contact.models.base`); :func:`walk` answers a :class:`~thinlayer.contact.problem.Problem`
by the first entry that holds.  A new model is one module here with one ``register_model`` line, imported below.
"""
from __future__ import annotations

from . import (  # noqa: F401,E501 - they register
    adhesion,
    adhesion_elliptic,
    any_thickness,
    compressible,
    direct,
    flat,
    incompressible,
    published,
    pyramid_law,
    pyramid_thick,
    tip_law,
    two_term,
    viscoelastic,
)
from .base import (
    MODEL_REGISTRY,
    ForceCurve,
    Model,
    entries_named,
    fit_entry,
    fit_names,
    model_names,
    register_model,
    unregister_model,
)
from .walk import direct_comparison, entry_of, walk

__all__ = ["ForceCurve", "MODEL_REGISTRY", "Model", "direct_comparison", "entries_named", "entry_of", "fit_entry",
           "fit_names", "model_names",
           "register_model", "unregister_model", "walk"]
