"""Optional integrations with the AFM tools users already work in (the extra ``thinlayer[afm]``: nanite, afmformats).

Nothing here is imported by ``import thinlayer``; each module imports the integration it serves on first use.

* :mod:`thinlayer.afm.nanite_models`: thinlayer's any-thickness laws as nanite fit models (PyJibe lists them too).
* :mod:`thinlayer.afm.maps`: force maps fitted pixel by pixel (``fit_map``, ``thinlayer fit-map``); curves on a grid
  read by :mod:`thinlayer.afm.map_data`; large batches on dask.distributed by :mod:`thinlayer.afm.distributed`.
"""
