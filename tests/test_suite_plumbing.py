"""What the README's test command (pytest-xdist, two workers) needs from the package itself."""
from __future__ import annotations

import importlib
import inspect
import pkgutil

import thinlayer


def test_every_class_that_names_thinlayer_as_its_module_is_an_attribute_of_thinlayer():
    """xdist rebuilds a worker's warning as ``getattr(sys.modules[cls.__module__], cls.__name__)``: a warning class
    that says it lives in ``thinlayer`` but is not importable from there ended the whole run with INTERNALERROR
    (ValidityWarning, raised by fit())."""
    names = set()
    for info in pkgutil.walk_packages(thinlayer.__path__, "thinlayer."):
        if info.name.startswith("thinlayer.derivations") or info.name.endswith("__main__"):
            continue
        mod = importlib.import_module(info.name)
        names |= {n for n, obj in vars(mod).items() if inspect.isclass(obj) and obj.__module__ == "thinlayer"}
    assert "ValidityWarning" in names  # the case that broke the run is among those checked
    missing = sorted(n for n in names if not hasattr(thinlayer, n))
    assert not missing, missing
