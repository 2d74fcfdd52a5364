r"""Linear viscoelastic materials (issue 27 item 1): Young's relaxation modulus ``E(t)`` at a constant Poisson ratio.

Every material here is isotropic and linear with a **constant Poisson ratio** ``nu`` (given separately, to
:func:`thinlayer.contact.hereditary.viscoelastic_force`): the shear relaxation modulus is then
``G(t) = E(t) / (2 (1 + nu))`` and the layer's elastic law, which depends on ``nu``, keeps its shape in time
(the correspondence principle needs nothing more).  At ``nu = 1/2`` (incompressible) the correspondence is exact
for any ``E(t)``, since ``nu`` cannot relax.

* :class:`Prony`: ``E(t) = E_inf + sum_i E_i exp(-t/tau_i)``,
  ``E*(w) = E_inf + sum_i E_i i w tau_i/(1 + i w tau_i)``;
* :func:`StandardLinearSolid`: ``E(t) = E_inf + (E0 - E_inf) exp(-t/tau)``, a one-term Prony series;
* :class:`KelvinVoigt`: ``E(t) = E + eta delta(t)`` (Dirac delta), ``E*(w) = E + i w eta``;
* :class:`PowerLaw`: ``E(t) = E0 (t/t0)^(-alpha)``, ``0 < alpha < 1``, ``E*(w) = E0 Gamma(1 - alpha) (i w t0)^alpha``.

The complex modulus is ``E*(w) = i w int_0^inf E(t) exp(-i w t) dt`` (the Prony constant ``E_inf`` as the limit).
The Kelvin-Voigt impulse ``eta delta(t)`` is not a function: :meth:`KelvinVoigt.relaxation` returns its regular
part ``E`` only, and the hereditary integral adds the impulse as ``eta d/dt f(delta(t))`` (the rate over each time
step; infinite at a step in depth, which is flagged, never returned as a number).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._checks import positive
from ..errors import InputError, InputTypeError

__all__ = ["KelvinVoigt", "Material", "PowerLaw", "Prony", "StandardLinearSolid"]


def _nonneg(value: Any, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise InputTypeError(f"{name} must be a real number >= 0, got {value!r} ({type(value).__name__})")
    v = float(value)
    if not (math.isfinite(v) and v >= 0):
        raise InputError(f"{name} must be a finite number >= 0, got {value!r}")
    return v


def _times(t: Any) -> np.ndarray:
    try:
        a = np.asarray(t, dtype=float)
    except (TypeError, ValueError):
        raise InputTypeError(f"t must be a number or an array of numbers, got {t!r}") from None
    if np.any(np.isnan(a)) or np.any(a < 0):
        raise InputError("t must be >= 0 (the time since the start of the history), with no nan")
    return a


class Material:
    """A linear viscoelastic material: ``relaxation(t)`` (Young's modulus), ``complex_modulus(omega)``, ``latex()``."""

    #: the modulus at t = 0+ (inf for the power law) and its impulse (the Kelvin-Voigt eta; 0 for the others)
    instantaneous: float
    impulse: float = 0.0

    def relaxation(self, t: Any) -> np.ndarray:  # pragma: no cover - every subclass defines it
        raise NotImplementedError

    def complex_modulus(self, omega: Any) -> np.ndarray:  # pragma: no cover
        raise NotImplementedError

    def latex(self) -> str:  # pragma: no cover
        raise NotImplementedError


@dataclass(frozen=True)
class Prony(Material):
    r"""Generalised Maxwell solid: ``E(t) = E_inf + sum_i E_i exp(-t/tau_i)``.

    Parameters
    ----------
    E_inf : float
        The long-time (equilibrium) modulus, ``>= 0``.
    terms : sequence of (E_i, tau_i)
        Maxwell branches: modulus ``E_i > 0`` and relaxation time ``tau_i > 0``.

    Examples
    --------
    >>> m = Prony(1.0, [(2.0, 0.5)])
    >>> float(m.relaxation(0.0))
    3.0
    >>> complex(m.complex_modulus(1e12)).real
    3.0
    """

    E_inf: float
    terms: tuple[tuple[float, float], ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "E_inf", _nonneg(self.E_inf, "Prony: E_inf"))
        if isinstance(self.terms, (str, bytes)) or not hasattr(self.terms, "__iter__"):
            raise InputTypeError(f"Prony: terms must be a sequence of (E_i, tau_i) pairs, got {self.terms!r}")
        out = []
        for k, pair in enumerate(self.terms):
            if isinstance(pair, (str, bytes)) or not hasattr(pair, "__len__") or len(pair) != 2:
                raise InputTypeError(f"Prony: terms[{k}] must be a pair (E_i, tau_i), got {pair!r}")
            out.append((positive(pair[0], f"Prony: terms[{k}] modulus E_i"),
                        positive(pair[1], f"Prony: terms[{k}] relaxation time tau_i")))
        object.__setattr__(self, "terms", tuple(out))
        if not self.E_inf + sum(e for e, _ in out) > 0:
            raise InputError("Prony: the moduli are all zero; give E_inf > 0 or a term (E_i, tau_i)")
        if not math.isfinite(self.E_inf + sum(e for e, _ in out)):
            raise InputError("Prony: the instantaneous modulus E_inf + sum E_i is beyond the double range")

    @property
    def instantaneous(self) -> float:  # type: ignore[override]
        """``E(0+) = E_inf + sum E_i``."""
        return self.E_inf + sum(e for e, _ in self.terms)

    def relaxation(self, t: Any) -> np.ndarray:
        """``E(t)``, vectorised over ``t >= 0``."""
        a = _times(t)
        out = np.full(a.shape, self.E_inf)
        for e, tau in self.terms:
            out = out + e * np.exp(-a / tau)
        return out

    def complex_modulus(self, omega: Any) -> np.ndarray:
        """``E*(w) = E_inf + sum_i E_i i w tau_i / (1 + i w tau_i)`` (``w >= 0``)."""
        w = _times(omega)
        out = np.full(w.shape, complex(self.E_inf))
        for e, tau in self.terms:
            x = w * tau
            # i x/(1 + i x) = (x^2 + i x)/(1 + x^2), written without overflow at x = 1e300 or inf
            with np.errstate(all="ignore"):
                inv = np.where(x > 1.0, 1.0 / np.where(x > 1.0, x, 1.0), 0.0)
                re = np.where(x > 1.0, 1.0 / (1.0 + inv * inv), x * x / (1.0 + x * x))
                im = np.where(x > 1.0, inv / (1.0 + inv * inv), x / (1.0 + x * x))
            out = out + e * (re + 1j * im)
        return out

    def latex(self) -> str:
        body = " + ".join([f"{self.E_inf:.6g}"] + [rf"{e:.6g}\,e^{{-t/{tau:.6g}}}" for e, tau in self.terms])
        return rf"E(t) = {body}"


def StandardLinearSolid(E0: Any, E_inf: Any, tau: Any) -> Prony:  # noqa: N802, N803 - a class-like constructor
    r"""The standard linear solid (Zener): ``E(t) = E_inf + (E0 - E_inf) exp(-t/tau)``, a one-term :class:`Prony`.

    ``E0`` is the instantaneous modulus, ``E_inf <= E0`` the relaxed one (``E0 = E_inf``: elastic).

    >>> StandardLinearSolid(3.0, 1.0, 0.5)
    Prony(E_inf=1.0, terms=((2.0, 0.5),))
    """
    e0, einf, t = positive(E0, "StandardLinearSolid: E0"), _nonneg(E_inf, "StandardLinearSolid: E_inf"), \
        positive(tau, "StandardLinearSolid: tau")
    if einf > e0:
        raise InputError(f"StandardLinearSolid: the relaxed modulus E_inf = {E_inf!r} must not exceed the "
                         f"instantaneous one E0 = {E0!r}")
    return Prony(einf, [(e0 - einf, t)] if e0 > einf else [])


@dataclass(frozen=True)
class KelvinVoigt(Material):
    r"""Kelvin-Voigt solid: ``E(t) = E + eta delta(t)`` (a spring and a dashpot in parallel).

    :meth:`relaxation` gives the regular part ``E`` (for ``t > 0``); the impulse ``eta delta(t)`` enters the
    hereditary integral as ``eta d/dt f(delta(t))``.

    >>> complex(KelvinVoigt(2.0, 0.5).complex_modulus(4.0))
    (2+2j)
    """

    E: float
    eta: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "E", _nonneg(self.E, "KelvinVoigt: E"))
        object.__setattr__(self, "eta", positive(self.eta, "KelvinVoigt: eta (the viscosity)"))

    @property
    def instantaneous(self) -> float:  # type: ignore[override]
        return math.inf

    @property
    def impulse(self) -> float:  # type: ignore[override]
        return self.eta

    def relaxation(self, t: Any) -> np.ndarray:
        """The regular part ``E`` of ``E(t)`` (the impulse ``eta delta(t)`` is not a function)."""
        return np.full(_times(t).shape, self.E)

    def complex_modulus(self, omega: Any) -> np.ndarray:
        """``E*(w) = E + i w eta``."""
        w = _times(omega)
        return self.E + 1j * self.eta * w

    def latex(self) -> str:
        return rf"E(t) = {self.E:.6g} + {self.eta:.6g}\,\delta(t)"


@dataclass(frozen=True)
class PowerLaw(Material):
    r"""Power-law rheology: ``E(t) = E0 (t/t0)^(-alpha)``, ``0 < alpha < 1`` (``E(0+)`` infinite).

    >>> z = complex(PowerLaw(1.0, 1.0, 0.5).complex_modulus(1.0))    # Gamma(1/2) i^(1/2)
    >>> abs(z - math.sqrt(math.pi) * (1 + 1j) / math.sqrt(2)) < 1e-15
    True
    """

    E0: float
    t0: float
    alpha: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "E0", positive(self.E0, "PowerLaw: E0"))
        object.__setattr__(self, "t0", positive(self.t0, "PowerLaw: t0 (the reference time)"))
        a = positive(self.alpha, "PowerLaw: alpha")
        if not a < 1:
            raise InputError(f"PowerLaw: alpha must lie in 0 < alpha < 1, got {self.alpha!r}")
        object.__setattr__(self, "alpha", a)

    @property
    def instantaneous(self) -> float:  # type: ignore[override]
        return math.inf

    def relaxation(self, t: Any) -> np.ndarray:
        """``E0 (t/t0)^(-alpha)`` (inf at ``t = 0``)."""
        a = _times(t)
        with np.errstate(divide="ignore"):
            return self.E0 * np.exp(-self.alpha * np.log(a / self.t0))

    def complex_modulus(self, omega: Any) -> np.ndarray:
        """``E*(w) = E0 Gamma(1 - alpha) (w t0)^alpha exp(i pi alpha / 2)``."""
        w = _times(omega)
        mag = self.E0 * math.gamma(1.0 - self.alpha) * np.exp(self.alpha * np.log(w * self.t0))
        return mag * complex(math.cos(math.pi * self.alpha / 2), math.sin(math.pi * self.alpha / 2))

    def latex(self) -> str:
        return rf"E(t) = {self.E0:.6g}\,(t/{self.t0:.6g})^{{-{self.alpha:.6g}}}"
