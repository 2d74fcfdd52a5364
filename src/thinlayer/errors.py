"""The exceptions a user of thinlayer can meet: each a ``ValueError`` or a ``TypeError`` with a one-line message.

=======================  =================================  =================================================
class                    base                               raised when
=======================  =================================  =================================================
``ThinlayerError``       ``Exception``                      base of all below: ``except ThinlayerError``
``InputError``           ``ThinlayerError``, ``ValueError`` a value out of range, malformed, or leading
                                                            outside the double range
``InputTypeError``       ``ThinlayerError``, ``TypeError``  an argument of the wrong type, or missing
``WorkLimitError``       ``InputError``                     the work or memory would exceed a documented limit
``NotDerivedError``      ``InputError``,                    a case thinlayer has not derived (e.g. ``order=3``)
                         ``NotImplementedError``
``ComputationError``     ``InputError``                     a numerical step failed at these numbers
``ValidityWarning``      ``UserWarning``                    a result returned marked ``valid=False`` (a fit
                                                            by a published series outside its range)
=======================  =================================  =================================================

Each stage adds its own subclasses of :class:`InputError` (``ExpressionError``, ``PunchError``,
``ValidityError``, ...).  :func:`boundary` decorates the public entry points: whatever else escapes them (a
library's ``ValueError``, ``ZeroDivisionError``, ``NotImplementedError``, ``math domain error``) is translated
into one of these.  Imports nothing (the bottom of the import table, with ``thinlayer.symbols``).
"""
from __future__ import annotations

import functools
import inspect
import linecache
import os
import re
from collections.abc import Callable

__all__ = ["ComputationError", "InputError", "InputTypeError", "NotDerivedError", "ThinlayerError", "ValidityWarning",
           "WorkLimitError", "boundary", "boundary_methods", "translate"]


# =============================================================================================
# the exceptions a user can meet: each a ValueError or a TypeError, with a one-line message
# =============================================================================================
class ThinlayerError(Exception):
    """Base of every exception thinlayer raises for what a user gave it (each is also a ValueError or a TypeError).

    ``except thinlayer.ThinlayerError`` catches all of them and nothing else.
    """


class InputError(ThinlayerError, ValueError):
    """A value thinlayer does not accept: out of its range, malformed, or leading outside the double range."""


class InputTypeError(ThinlayerError, TypeError):
    """An argument of the wrong type, or a required argument missing (the message names it and what is valid)."""


class WorkLimitError(InputError):
    """A request whose work or memory would exceed a documented limit; raised before any work starts."""


class NotDerivedError(InputError, NotImplementedError):
    """A case thinlayer has not derived (an order beyond the derived ones, a kernel without the expansion).

    Also a ``NotImplementedError``, as it was before thinlayer's own classes.
    """


class ComputationError(InputError):
    """A numerical step failed at these inputs (numbers beyond the double range, a solver that did not converge).

    Raised by :func:`boundary` in place of a library's own error (``ZeroDivisionError``, scipy's messages, ``math
    domain error``), with the function, the reason in thinlayer's words and the library's text.
    """


class ValidityWarning(UserWarning):
    """A result returned outside its model's validity, marked so (``valid=False`` and the reason), e.g. a fit by a
    published series on data beyond its range.  ``warnings.simplefilter("error", ValidityWarning)`` refuses instead.
    """


for _cls in (ThinlayerError, InputError, InputTypeError, WorkLimitError, NotDerivedError, ComputationError,
             ValidityWarning):
    _cls.__module__ = "thinlayer"  # what a traceback shows: the name users import
del _cls

_PACKAGE = os.path.dirname(os.path.abspath(__file__))
_FOREIGN = (
    (ZeroDivisionError, "a division by zero: the numbers leave the double range"),
    (OverflowError, "a number beyond the double range (about 1.8e308)"),
    (FloatingPointError, "a floating-point failure: the numbers leave the double range"),
    (ArithmeticError, "an arithmetic failure at these numbers"),
    (NotImplementedError, "a case thinlayer has not derived"),
    (RecursionError, "the input nests too deeply"),
    (RuntimeError, "a numerical step did not converge at these numbers"),
    (ValueError, "a numerical step failed at these numbers (they may leave the double range)"),
    (TypeError, "an argument of a type the computation cannot use"),
    (AttributeError, "an argument of the wrong type (it lacks what the computation needs)"),
    (LookupError, "an argument out of the range the computation indexes"),
    (AssertionError, "an internal check failed at these numbers"),
)


def _raised_by_thinlayer(exc: BaseException) -> bool:
    """Whether a ``raise`` statement of thinlayer's own code raised ``exc`` (its message is in thinlayer's words).

    The innermost frame of the traceback is thinlayer's and its line is a ``raise``: an error raised inside a
    library (scipy, sympy) or by a builtin called from thinlayer (``math.sqrt``, ``float``) is not.
    """
    tb = exc.__traceback__
    if tb is None:
        return False
    while tb.tb_next is not None:
        tb = tb.tb_next
    path = os.path.abspath(tb.tb_frame.f_code.co_filename)
    if not path.startswith(_PACKAGE + os.sep):
        return False
    return linecache.getline(path, tb.tb_lineno).lstrip().startswith("raise")


def _one_line(text: str, limit: int = 300) -> str:
    text = re.sub(r"\s*\n\s*", "; ", str(text).strip())
    return text if len(text) <= limit else text[: limit - 5] + " ..."


def translate(exc: BaseException, where: str) -> ThinlayerError:
    """A thinlayer exception standing for ``exc`` (raised in ``where``): the same text if thinlayer wrote it.

    A ``ValueError``/``TypeError`` raised by thinlayer's own code keeps its message (an :class:`InputError` or
    :class:`InputTypeError`); an error from a library (scipy, numpy, mpmath, sympy, ``math``) or an arithmetic
    error becomes a :class:`ComputationError` (a :class:`WorkLimitError` for recursion and memory) whose message
    names ``where`` and the reason in thinlayer's words, with the library's own text in parentheses.
    """
    if isinstance(exc, MemoryError):
        return WorkLimitError(f"{where}: out of memory at these inputs; ask for less (fewer points, modes or terms)")
    own = _raised_by_thinlayer(exc)
    if isinstance(exc, NotImplementedError):
        return NotDerivedError(_one_line(exc) if own else f"{where}: not derived for these inputs "
                               f"({type(exc).__name__}: {_one_line(exc, 160)})")
    if own and isinstance(exc, TypeError):  # thinlayer's own words, kept whole
        return InputTypeError(_one_line(exc, 10**6))
    if own and isinstance(exc, ValueError):
        return InputError(_one_line(exc, 10**6))
    detail = f"{type(exc).__name__}: {_one_line(exc, 160) or '-'}"
    text = str(exc)
    if isinstance(exc, RecursionError):
        return WorkLimitError(f"{where}: the input nests too deeply ({detail}); give a smaller one")
    if isinstance(exc, TypeError) and _SIGNATURE.search(text):
        return InputTypeError(f"{where}: the arguments do not match its signature ({detail}); see help()")
    if isinstance(exc, (TypeError, AttributeError, LookupError)) or (isinstance(exc, ValueError)
                                                                     and _NOT_A_NUMBER.search(text)):
        return InputTypeError(f"{where}: an argument of a type or form it cannot use ({detail}); see its "
                              "docstring for what each argument takes")
    reason = next(text for cls, text in _FOREIGN if isinstance(exc, cls))
    return ComputationError(f"{where}: no answer at these inputs: {reason} ({detail}); give values of moderate "
                            "size (rescale the units) or another model")


_SIGNATURE = re.compile(r"positional argument|keyword argument|required (positional|keyword)")
_NOT_A_NUMBER = re.compile(r"could not convert|invalid literal|must be (a )?real|string|not a number|dtype", re.I)


#: what :func:`boundary` translates (everything else, e.g. KeyboardInterrupt, passes through)
_TRANSLATED = (ValueError, TypeError, ArithmeticError, RuntimeError, AssertionError, MemoryError, AttributeError,
               LookupError)


def boundary(fn: Callable, where: str | None = None) -> Callable:
    """Decorate a public entry point: every error it lets out is a :class:`ThinlayerError` with one line.

    thinlayer's own errors pass unchanged; anything else that escapes (a library's ``ValueError``, a
    ``ZeroDivisionError``, ``NotImplementedError``, ``math domain error``) is translated by :func:`translate`.
    ``where`` names the entry point in the message (default ``fn.__name__ + "()"``).
    """
    where = where or f"{fn.__name__}()"

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        try:
            return fn(*args, **kwargs)
        except ThinlayerError:
            raise
        except _TRANSLATED as exc:
            raise translate(exc, where) from exc

    for attr in ("cache_clear", "cache_info"):  # an lru_cache underneath keeps its controls
        if hasattr(fn, attr):
            setattr(wrapper, attr, getattr(fn, attr))
    wrapper.__thinlayer_boundary__ = True
    return wrapper


def boundary_methods(cls: type) -> type:
    """Apply :func:`boundary` to the public methods ``cls`` defines (and ``__init__``, ``__new__``, ``__call__``).

    Properties are left alone (they take no argument).  Returns ``cls``: a class decorator.
    """
    for name, attr in list(vars(cls).items()):
        if name.startswith("_") and name not in ("__init__", "__new__", "__call__"):
            continue
        if isinstance(attr, (staticmethod, classmethod)):
            fn = attr.__func__
            if not getattr(fn, "__thinlayer_boundary__", False):
                setattr(cls, name, type(attr)(boundary(fn, f"{cls.__name__}.{fn.__name__}()")))
        elif inspect.isfunction(attr) and not getattr(attr, "__thinlayer_boundary__", False):
            shown = cls.__name__ if name in ("__init__", "__new__") else f"{cls.__name__}.{name}"
            setattr(cls, name, boundary(attr, f"{shown}()"))
    return cls
