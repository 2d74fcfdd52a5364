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


class _LazyModule:
    """A module imported on first attribute access: ``special = lazy_module("scipy.special")``."""

    def __init__(self, name: str):
        self._name = name

    def __getattr__(self, attr: str) -> Any:
        module = importlib.import_module(self._name)
        return getattr(module, attr)

    def __repr__(self) -> str:
        return f"<module {self._name!r}, imported on first use>"


def lazy_module(name: str) -> Any:
    """``name`` (e.g. ``"scipy.special"``) imported on first use: a module-level name that costs nothing at import.

    The direct solvers keep scipy this way, so that a path which never calls them (``thinlayer solve`` with the
    asymptotic model) does not pay scipy's import.
    """
    return _LazyModule(name)
