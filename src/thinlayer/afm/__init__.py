"""Optional integrations with the AFM tools users already work in (the extra ``thinlayer[afm]``: nanite, afmformats).

Nothing here is imported by ``import thinlayer``; each module imports the integration it serves on first use.

* :mod:`thinlayer.afm.nanite_models`: thinlayer's any-thickness laws as nanite fit models (PyJibe lists them too).
"""
