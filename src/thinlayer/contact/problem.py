r"""The question a model answers: layer + tip + material + interaction + loading (issue 29 item 3).

:func:`thinlayer.solve` validates the user's input once and builds a :class:`Problem`; every model of the
registry (:mod:`thinlayer.contact.models`) reads it and nothing else.  Each part has one class today and a
role that another class can fill later without touching the models that do not care:

* material: :class:`Elastic` (``mu``, ``nu``; ``E = 2 mu (1 + nu)``) or :class:`Viscoelastic` (``E(t)`` at a
  constant ``nu``: the viscoelastic rows answer it, :mod:`thinlayer.contact.models.viscoelastic`);
* interaction: :class:`Frictionless` (frictionless, non-adhesive); adhesion is another class;
* loading: :class:`Depth` (the depth ``delta0`` (1.5) is given) or :class:`Force` (the total force (1.8) is given),
  or a :class:`History` of either against time (viscoelastic problems).
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, ClassVar

from .._checks import InputError, InputTypeError, positive

__all__ = ["Adhesive", "Depth", "ELASTIC_HINT", "Elastic", "Force", "Frictionless", "History", "Problem",
           "Viscoelastic"]

ELASTIC_HINT = "give exactly one of mu= (shear modulus) or E= (Young's modulus), with the Poisson ratio nu"


@dataclass(frozen=True)
class Elastic:
    """A linear elastic, isotropic material: shear modulus ``mu`` and Poisson ratio ``nu`` (2.1)."""

    mu: float
    nu: float
    viscoelastic: ClassVar[bool] = False

    @property
    def E(self) -> float:  # noqa: N802 - Young's modulus is E
        """Young's modulus ``E = 2 mu (1 + nu)``."""
        return 2.0 * self.mu * (1.0 + self.nu)

    @classmethod
    def from_moduli(cls, mu: Any = None, E: Any = None, nu: float = 0.5) -> Elastic:  # noqa: N803
        """The material from exactly one of ``mu`` and ``E`` (one-line refusals naming the input)."""
        if (mu is None) == (E is None):
            raise InputTypeError(f"solve(): {ELASTIC_HINT}" + ("" if mu is None else "; both were given"))
        if mu is not None:
            return cls(positive(mu, "mu"), float(nu))
        mm = positive(E, "E") / (2.0 * (1.0 + nu))
        if not (math.isfinite(mm) and mm > 0):
            raise InputError(f"E = {E!r} gives the shear modulus mu = E/(2(1 + nu)) = {mm!r}: out of the double range")
        return cls(mm, float(nu))


@dataclass(frozen=True)
class Viscoelastic:
    """A linear viscoelastic material: Young's relaxation modulus ``E(t)`` (``relaxation``, a
    :class:`~thinlayer.contact.materials.Material`) at a constant Poisson ratio ``nu`` (issue 27 item 1).
    It has no single shear modulus: ``mu`` is NaN (only the viscoelastic rows read this material).
    """

    relaxation: Any
    nu: float
    #: the elastic law at unit modulus the correspondence uses (``"auto"``: the first valid over the history)
    law: str = "auto"
    viscoelastic: ClassVar[bool] = True

    @property
    def mu(self) -> float:
        return math.nan


@dataclass(frozen=True)
class Frictionless:
    """The interaction: frictionless, non-adhesive contact (the paper's (1.5)-(1.7))."""

    adhesive: ClassVar[bool] = False


@dataclass(frozen=True)
class Adhesive:
    """The interaction: frictionless JKR adhesion with work of adhesion ``w`` (J.5); ``branch`` of the JKR curve
    (``"stable"`` or ``"unstable"``) that the answer lies on (:mod:`thinlayer.contact.adhesion`).
    """

    work_of_adhesion: float
    branch: str = "stable"
    adhesive: ClassVar[bool] = True


@dataclass(frozen=True)
class Depth:
    """Loading by a given indentation depth ``delta0`` (1.5)."""

    delta0: float


@dataclass(frozen=True)
class Force:
    """Loading by a given total force (1.8): the depth is found."""

    force: float


@dataclass(frozen=True, eq=False)
class History:
    """Loading by a history against time: ``values`` are depths (``control="depth"``) or forces (``"force"``)."""

    times: Any
    values: Any
    control: str = "depth"


@dataclass(frozen=True, eq=False)
class Problem:
    """One contact problem, validated: what every model of :mod:`thinlayer.contact.models` reads.

    Attributes
    ----------
    layer : LayerKernel
        The layer (numeric; ``IncompressibleLayer()`` for a bonded layer at nu = 1/2).
    tip : Tip
        The numeric tip (a polynomial punch or the flat punch).
    material, interaction, loading
        :class:`Elastic`, :class:`Frictionless`, :class:`Depth` or :class:`Force`.
    H, tol : float
        Thickness and the largest accepted relative error estimate.
    n : int or None
        Modes or cells of the direct solvers.
    options : Mapping
        Model options (``order``, ``terms``, ``boundary_layer`` of the compressible model).
    guess : float or None
        A depth for the direct solver's inverse problem to start from (an earlier model's answer).
    """

    layer: Any
    tip: Any
    material: Elastic | Viscoelastic
    interaction: Frictionless | Adhesive
    loading: Depth | Force | History
    H: float
    tol: float
    n: int | None = None
    options: Mapping = field(default_factory=dict)
    guess: float | None = None

    @property
    def mu(self) -> float:
        return self.material.mu

    @property
    def nu(self) -> float:
        return self.material.nu

    @property
    def delta0(self) -> float | None:
        """The given depth, or None for a given force."""
        return self.loading.delta0 if isinstance(self.loading, Depth) else None

    @property
    def force(self) -> float | None:
        """The given force, or None for a given depth."""
        return self.loading.force if isinstance(self.loading, Force) else None
