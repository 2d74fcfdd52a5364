"""Package attributes imported on first use (PEP 562): a fast ``import`` and ``thinlayer --help``."""
from __future__ import annotations

import importlib
import sys
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

    __slots__ = ("_name", "_module")

    def __init__(self, name: str):
        self._name = name
        self._module = None

    def __getattr__(self, attr: str) -> Any:
        module = self._module
        if module is None:
            module = importlib.import_module(self._name)
            self._module = module
        return getattr(module, attr)

    def __repr__(self) -> str:
        return f"<module {self._name!r}, imported on first use>"


def lazy_module(name: str) -> Any:
    """``name`` (e.g. ``"scipy.special"``) imported on first use: a module-level name that costs nothing at import.

    The direct solvers keep scipy this way, so that a path which never calls them (``thinlayer solve`` with the
    asymptotic model) does not pay scipy's import; the symbolic modules keep sympy so (``sp = lazy_module("sympy")``),
    so that a numeric ``solve()`` whose constants are on disk never imports it (issue 28 item 6).
    """
    return _LazyModule(name)


def lazy_function(module: str, name: str) -> Callable[..., Any]:
    """``module.name`` imported on its first call: ``normal_latex = lazy_function("thinlayer.normal", "normal_latex")``.

    The printers of :mod:`thinlayer.normal` subclass sympy's; a module that prints only in ``latex()`` keeps them off
    its import this way.
    """
    def call(*args: Any, **kwargs: Any) -> Any:
        return getattr(importlib.import_module(module), name)(*args, **kwargs)

    call.__name__ = call.__qualname__ = name
    call.__doc__ = f"``{module}.{name}``, imported on first call."
    return call


def loaded_types(module: str, *names: str) -> tuple[type, ...]:
    """The classes ``module.<name>`` if ``module`` is imported already, else ``()``: for ``isinstance`` checks.

    An object of a class of a module that was never imported cannot exist, so ``isinstance(x, (float,
    *loaded_types("sympy", "Number")))`` is the full check and imports nothing.
    """
    mod = sys.modules.get(module)
    return tuple(getattr(mod, n) for n in names) if mod is not None else ()


def is_loaded(module: str) -> bool:
    """Whether ``module`` is imported already (e.g. ``"sympy"``: then a value may be a sympy object)."""
    return module in sys.modules
