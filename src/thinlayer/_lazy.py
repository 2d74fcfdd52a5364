"""Package attributes imported on first use (PEP 562): a fast ``import`` and ``thinlayer --help``."""
from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping
from typing import Any


def lazy_exports(namespace: dict, exports: Mapping[str, str]) -> tuple[Callable[[str], Any], Callable[[], list]]:
    """``(__getattr__, __dir__)`` for a package whose names live in submodules, imported on first access.

    Parameters
    ----------
    namespace : dict
        The package's ``globals()``: a loaded name is stored there, so the next access is a plain attribute.
    exports : Mapping[str, str]
        ``{name: module}``, e.g. ``{"validation_study": "thinlayer.validation.runner"}``.
    """
    package = namespace["__name__"]

    def __getattr__(name: str) -> Any:
        module = exports.get(name)
        if module is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(module), name)
        namespace[name] = value
        return value

    def __dir__() -> list[str]:
        return sorted(set(namespace) | set(exports))

    return __getattr__, __dir__
