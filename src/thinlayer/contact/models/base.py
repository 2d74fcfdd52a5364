r"""The model interface and its registry (issue 29 item 1): one entry per way of answering a contact problem.

A model is a :class:`Model` subclass in its own module with one :func:`register_model` line, like nanite's
``register_model`` (the contract is checked when the model registers, not when a user first meets it):

* ``name`` -- the public model name users pass (``solve(model="compressible")``); several entries may share one
  (``"direct"``: the flat punch's exact solution, the axisymmetric spectral solver, the 2D FFT solver), each with
  its own :meth:`Model.applies`;
* ``preference`` -- an int: ``model="auto"`` walks the entries in increasing preference;
* ``asymptotic`` -- whether ``model="asymptotic"`` tries it, and whether the walk checks its estimate against
  ``tol`` (the other entries check their own or have none to check);
* ``equations`` -- the equations of the force and of the contact size (a pair of strings);
* ``parameter_keys``, ``parameter_names``, ``parameter_units`` -- what the model's answer depends on (nanite's
  names), of equal length;
* :meth:`Model.applies` -- None, or the reason the model does not apply to this problem (one phrase);
* :meth:`Model.run` -- the :class:`~thinlayer.contact.indentation.Indentation` with its estimate, or a
  :class:`~thinlayer.asymptotics.solution.ValidityError`;
* :meth:`Model.force_curve` -- the unit-modulus :class:`ForceCurve`, vectorised over depths, or None.

The walk itself is :func:`thinlayer.contact.models.walk.walk`.
"""
from __future__ import annotations

import math
import numbers
from abc import ABC, abstractmethod
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from ...errors import InputError, InputTypeError

if TYPE_CHECKING:
    from ..indentation import Indentation
    from ..problem import Problem

__all__ = ["ForceCurve", "MODEL_REGISTRY", "Model", "entries_named", "estimate_ok", "fit_entry", "fit_names", "fmt_est",
           "model_names",
           "register_model", "unregister_model"]


# =============================================================================================
# the unit-modulus force curve
# =============================================================================================
@dataclass(frozen=True, eq=False)
class ForceCurve:
    r"""A model's force and contact size against the depth at unit modulus (``mu = 1``), vectorised.

    Linear elasticity: the force at shear modulus ``mu`` is ``mu * force(delta)``; the contact size does not
    depend on ``mu``.  Depths ``<= 0`` give zero force and zero contact (no contact).  Where the model's estimate
    exceeds ``tol`` (or a number leaves the double range) ``valid`` is False and the values are NaN: never an
    unflagged force.  Hereditary integrals (issue 27) and adhesion (issue 26) read only this.

    Attributes
    ----------
    model : str
        The model's public name.
    tol : float
        The tolerance ``valid`` is measured against.
    """

    model: str
    tol: float
    law: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]] = None  # delta > 0 -> (P, area, est)
    radius_law: Callable[[np.ndarray], np.ndarray] | None = None  # delta > 0 -> c (axisymmetric contacts)
    inverse_radius: Callable[[np.ndarray], np.ndarray] | None = None  # c > 0 -> delta
    slopes: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]] | None = None  # (dlogP/dlog delta, dlogP/dlog H)

    def _eval(self, delta: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``(P, A, est, valid)``, fresh arrays of the depths' shape.  No copy or ``np.where`` pass where nothing
        needs masking (every depth positive and valid: the common case of a fit, benchmarks/bench_tips.py).
        """
        d = np.asarray(delta, dtype=float)
        pos = d > 0
        every = bool(pos.all())
        arg = d if every else np.where(pos, d, 1.0)
        with np.errstate(all="ignore"):
            out = [_fresh(v, d.shape, (d, arg)) for v in self.law(arg)]
            P, A, est = out
            if A is P or est is P or est is A:
                P, A, est = P, A.copy(), est.copy()
            ok = est <= self.tol  # P > 0 & P < inf: finite and positive (NaN fails both)
            ok &= P > 0
            ok &= P < math.inf
            ok &= A > 0
            ok &= A < math.inf
        if every:
            if not ok.all():
                P[~ok] = np.nan
                A[~ok] = np.nan
            return P, A, est, ok
        bad = ~ok & pos
        P[bad] = np.nan
        A[bad] = np.nan
        out_ = ~pos
        P[out_] = 0.0
        A[out_] = 0.0
        est[out_] = 0.0
        return P, A, est, ok | out_

    def force(self, delta: Any) -> np.ndarray:
        """The force at ``mu = 1`` (zero for ``delta <= 0``; NaN where not valid)."""
        return self._eval(delta)[0]

    def contact_area(self, delta: Any) -> np.ndarray:
        """The contact area (zero for ``delta <= 0``; NaN where not valid)."""
        return self._eval(delta)[1]

    def contact_radius(self, delta: Any) -> np.ndarray:
        """The contact radius (the radius of the disc of equal area where the model gives no radius)."""
        d = np.asarray(delta, dtype=float)
        if self.radius_law is None:
            return np.sqrt(self.contact_area(d) / math.pi)
        _, _, _, ok = self._eval(d)
        with np.errstate(all="ignore"):
            c = np.broadcast_to(np.asarray(self.radius_law(np.where(d > 0, d, 1.0)), dtype=float), d.shape)
        return np.where(d > 0, np.where(ok, c, np.nan), 0.0)

    def estimate(self, delta: Any) -> np.ndarray:
        """The model's relative error estimate at each depth (the largest over force and contact size)."""
        return self._eval(delta)[2]

    def valid(self, delta: Any) -> np.ndarray:
        """Where the estimate is within ``tol`` and the numbers are positive and finite."""
        return self._eval(delta)[3]

    def depth_for_radius(self, c: Any) -> np.ndarray:
        """The depth at which the contact radius is ``c`` (where the model can invert it)."""
        if self.inverse_radius is None:
            raise InputError(f"the {self.model} model's force curve gives no depth for a contact radius")
        return np.asarray(self.inverse_radius(np.asarray(c, dtype=float)), dtype=float)

    def force_for_radius(self, c: Any) -> np.ndarray:
        """The force at ``mu = 1`` at which the contact radius is ``c``."""
        return self.force(self.depth_for_radius(c))


def _fresh(v: Any, shape: tuple, inputs: tuple) -> np.ndarray:
    """``v`` as a float array of ``shape`` that the caller may write into (a copy unless the law made it)."""
    a = np.asarray(v, dtype=float)
    if a.shape != shape:
        return np.array(np.broadcast_to(a, shape))
    if not (a.flags.owndata and a.flags.writeable) or any(a is x for x in inputs):
        return a.copy()
    return a


# =============================================================================================
# the model interface
# =============================================================================================
class Model(ABC):
    """One way of answering a contact problem (module docstring: the contract checked at registration)."""

    name: ClassVar[str]
    preference: ClassVar[int]
    asymptotic: ClassVar[bool] = False
    equations: ClassVar[tuple[str, str]]
    parameter_keys: ClassVar[tuple[str, ...]] = ("mu", "nu", "H", "delta0")
    parameter_names: ClassVar[tuple[str, ...]] = ("shear modulus", "Poisson ratio", "layer thickness",
                                                  "indentation depth")
    parameter_units: ClassVar[tuple[str, ...]] = ("Pa", "", "m", "m")
    #: among solve()'s choices of ``model`` (False: an entry that answers under another public name only)
    selectable: ClassVar[bool] = True
    #: False: a force-curve model for fit() only, never walked by solve()
    solves: ClassVar[bool] = True
    #: further public names this entry answers to (the flat punch's exact solution answers "any-thickness")
    aliases: ClassVar[tuple[str, ...]] = ()
    #: the model options: True takes them, False refuses them (one line), None ignores them
    takes_options: ClassVar[bool | None] = False
    #: whether fit() offers this model's force curve (``fit(model=name)``)
    fits: ClassVar[bool] = False
    #: exceptions after which ``model="auto"`` goes on to the next entry (non-asymptotic entries)
    declines: ClassVar[tuple[type[BaseException], ...]] = ()
    #: True: an adhesive (JKR) entry, offered only problems with a work of adhesion (and those only such entries)
    adhesive: ClassVar[bool] = False
    #: True: a viscoelastic entry, offered only problems with a viscoelastic material (and those only such entries)
    viscoelastic: ClassVar[bool] = False

    def refuses(self, problem: Problem) -> str | None:
        """None, or why this model is not one for this kind of problem at all (an InputError when named)."""
        return None

    def skips(self, problem: Problem) -> bool:
        """Whether ``model="auto"`` passes over this entry without naming it among the models tried."""
        return self.refuses(problem) is not None

    @abstractmethod
    def applies(self, problem: Problem) -> str | None:
        """None, or the reason the model does not apply to this problem."""

    @abstractmethod
    def run(self, problem: Problem) -> Indentation:
        """The answer with its estimate (raises ValidityError where the model has none)."""

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        """The unit-modulus force curve of this problem's layer and tip (None: not vectorised)."""
        return None

    def result_equations(self, answer: Indentation) -> tuple[str, str]:
        """The equations of the force and of the contact size of one answer (default :attr:`equations`)."""
        return self.equations

    def reason(self, answer: Indentation, tried: list[str], tol: float, named: bool) -> str:
        """Why this answer: the models tried before it, then this one (``named``: the user chose it)."""
        if self.asymptotic:
            return "; ".join(tried + [f"{self.name}: estimates {fmt_est(answer.error_estimate)} within tol "
                                      f"{100 * tol:.3g} %"])
        return answer.reason if named else "; ".join(tried + [f"{self.name}: {answer.reason}"])

    def refined(self, answer: Indentation, problem: Problem, **options: Any) -> Indentation:
        """The same problem solved again for a comparison (direct entries; ``options`` go to the solver)."""
        raise InputError(f"the {self.name} model gives no direct solution to compare with")

    def __repr__(self) -> str:
        return f"<model {self.name!r} ({type(self).__name__}, preference {self.preference})>"


# =============================================================================================
# the registry
# =============================================================================================
#: the registered entries, in increasing preference
MODEL_REGISTRY: list[Model] = []


def _check_contract(entry: Model) -> None:
    cls = type(entry)
    where = f"register_model({cls.__name__})"
    name = getattr(entry, "name", None)
    if not isinstance(name, str) or not name or name in ("auto", "asymptotic"):
        raise InputTypeError(f"{where}: name must be a non-empty string other than 'auto' and 'asymptotic', "
                             f"got {name!r}")
    pref = getattr(entry, "preference", None)
    if isinstance(pref, bool) or not isinstance(pref, numbers.Integral):
        raise InputTypeError(f"{where}: preference must be an int, got {pref!r}")
    eq = getattr(entry, "equations", None)
    if not (isinstance(eq, tuple) and len(eq) == 2 and all(isinstance(e, str) and e for e in eq)):
        raise InputTypeError(f"{where}: equations must be a pair of strings (force, contact size), got {eq!r}")
    keys, names, units = entry.parameter_keys, entry.parameter_names, entry.parameter_units
    if not all(isinstance(t, tuple) and all(isinstance(s, str) for s in t) for t in (keys, names, units)) \
            or not len(keys) == len(names) == len(units):
        raise InputTypeError(f"{where}: parameter_keys, parameter_names and parameter_units must be tuples of "
                             f"strings of equal length, got {len(keys)}, {len(names)}, {len(units)}")
    for hook in ("applies", "run", "force_curve"):
        if not callable(getattr(entry, hook, None)):
            raise InputTypeError(f"{where}: {hook} must be callable")
    for other in MODEL_REGISTRY:
        if other.name == name and type(other).applies is cls.applies:
            raise InputError(f"{where}: an entry named {name!r} with the same applies() is registered already "
                             f"({type(other).__name__})")


def register_model(entry: Model | type[Model]) -> Model:
    """Check the model's contract and add it to :data:`MODEL_REGISTRY` in its order of preference.

    Returns the registered entry (an instance: a class is instantiated without arguments).
    """
    if isinstance(entry, type):
        if not issubclass(entry, Model):
            raise InputTypeError(f"register_model: {entry.__name__} is not a Model subclass")
        entry = entry()
    if not isinstance(entry, Model):
        raise InputTypeError(f"register_model: a Model subclass or instance is needed, got {entry!r}")
    _check_contract(entry)
    MODEL_REGISTRY.append(entry)
    MODEL_REGISTRY.sort(key=lambda m: m.preference)  # stable: equal preferences keep their registration order
    return entry


def unregister_model(entry: Model) -> None:
    """Remove an entry (tests that register a toy model remove it afterwards)."""
    MODEL_REGISTRY.remove(entry)


def model_names() -> tuple[str, ...]:
    """``solve()``'s choices of ``model``: ``"auto"``, ``"asymptotic"``, then the public names by preference."""
    out = ["auto", "asymptotic"]
    for m in MODEL_REGISTRY:
        if m.solves and m.selectable and m.name not in out and not m.adhesive and not m.viscoelastic:
            out.append(m.name)
    return tuple(out)


def fit_names() -> tuple[str, ...]:
    """``fit()``'s choices of ``model``: the entries with a force curve for fitting, by preference."""
    return tuple(dict.fromkeys(m.name for m in MODEL_REGISTRY if m.fits))


def fit_entry(name: str) -> Model:
    """The entry ``fit(model=name)`` uses."""
    return next(m for m in MODEL_REGISTRY if m.fits and m.name == name)


def entries_named(name: str, adhesive: bool = False) -> list[Model]:
    """The entries that answer to the public name ``name`` (their own name or an alias), by preference; the
    adhesive ones (``adhesive=True``) or the others.
    """
    return [m for m in MODEL_REGISTRY if m.solves and (m.name == name or name in m.aliases) and m.adhesive == adhesive]


def estimate_ok(est: dict, tol: float) -> bool:
    """Whether every relative estimate is within ``tol``."""
    return all(v <= tol for v in est.values())


def fmt_est(est: dict) -> str:
    """``"force 0.1 %, contact area 0.2 %"``."""
    return ", ".join(f"{k.replace('_', ' ')} {100 * v:.3g} %" for k, v in est.items())
