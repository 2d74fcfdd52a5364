r"""The answer of :func:`thinlayer.solve`: :class:`Indentation` (force, contact size, pressure, the model and its
estimate) and :class:`DirectComparison` (an answer beside the direct solution of the same problem).

An ``Indentation`` is built by keyword only; quantities one model has and others lack go into ``extras`` (the
flat punch's stiffness ``kappa`` (F.1)), so that a new quantity adds no field.  What depends on the model (its
equations, the direct solution to compare with) is asked of the registry entry that gave the answer
(:mod:`thinlayer.contact.models`), not decided here by the model's name.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, ClassVar

import numpy as np

from ..display import RichDisplay
from ..errors import boundary_methods
from ..layers.kernels import LayerKernel

__all__ = ["DirectComparison", "Indentation", "tex_num"]

# =============================================================================================
# the result
# =============================================================================================
@boundary_methods
@dataclass(frozen=True, eq=False, kw_only=True)
class Indentation(RichDisplay):
    r"""The answer of :func:`solve`: force, contact size and pressure, with the model and its error estimate.

    Attributes
    ----------
    layer, punch
        The layer and the (numeric) punch.
    delta0, force : float
        Indentation depth and total force (1.8); one was given, the other computed.
    H, mu, E, nu : float
        Thickness, shear modulus, Young's modulus ``E = 2 mu (1 + nu)`` and Poisson ratio.
    contact_area : float
        Area of the contact region.
    contact_radius : float or None
        Radius of the contact disc (axisymmetric punches; None otherwise).
    semi_axes : tuple of float or None
        Semi-axes of an elliptic contact (elliptic paraboloid punches, where the model gives them).
    model : str
        ``"compressible"``, ``"two-term"``, ``"incompressible"`` or ``"direct"``.
    reason : str
        Why this model: the estimates of the models tried before it.
    error_estimate : dict
        Relative error estimates: ``{"force", "contact_area"}`` and ``"contact_radius"`` where defined.
    tol : float
        The tolerance the estimates were accepted with.
    detail : Any
        The model's own result (``ContactSolution``, ``SphereValues``, ``AxisymmetricContact``, ...).
    extras : Mapping
        Model-specific quantities (a copy of the mapping given), e.g. ``{"kappa": ...}`` for the flat punch (F.1).
    entry : Model or None
        The registry entry that gave the answer (:mod:`thinlayer.contact.models`; None: looked up by ``model``).
    flags : tuple of str
        The regime limits the problem passes (:func:`thinlayer.contact.guards.regime_flags`: ``delta0/H`` beyond
        small strain, ``delta0/R`` where the paraboloid departs from a sphere), one line each.
    """

    equation: ClassVar[str] = "1.8"

    layer: LayerKernel
    punch: Any
    delta0: float
    force: float
    H: float
    mu: float
    nu: float
    contact_area: float
    contact_radius: float | None
    semi_axes: tuple[float, float] | None
    model: str
    reason: str
    error_estimate: dict
    tol: float
    detail: Any = field(repr=False)
    _pressure: Callable = field(repr=False)
    _extent: Any = field(repr=False)
    extras: Mapping[str, Any] = field(default_factory=dict, repr=False)
    entry: Any = field(default=None, repr=False, compare=False)
    flags: tuple = field(default=(), repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "extras", dict(self.extras))  # a copy: the caller's mapping stays the caller's

    @property
    def E(self) -> float:
        """Young's modulus ``E = 2 mu (1 + nu)``."""
        return 2.0 * self.mu * (1.0 + self.nu)

    @property
    def half_width(self) -> float:
        """``a = 2 |omega|/|Gamma|`` for the models with a contour, the radius (or its area equivalent) otherwise."""
        if self.contact_radius is not None:
            return self.contact_radius
        if getattr(self.detail, "half_width", None) is not None:  # a contour's a = 2|omega|/|Gamma| (compressible)
            return float(self.detail.half_width)
        if self.semi_axes is not None:  # an ellipse: |Gamma| = 4 a E(1 - b^2/a^2), a >= b
            import mpmath

            a, b = max(self.semi_axes), min(self.semi_axes)
            return math.pi * a * b / (2.0 * a * float(mpmath.ellipe(1.0 - (b / a) ** 2)))
        return math.sqrt(self.contact_area / math.pi)

    @property
    def H_over_a(self) -> float:
        return self.H / self.half_width

    def pressure(self, x1: Any, x2: Any) -> np.ndarray:
        """Contact pressure ``p(x1, x2)`` (vectorised over numpy arrays; zero outside the contact)."""
        x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
        return np.asarray(self._pressure(x1, x2), dtype=float)

    @cached_property
    def max_pressure(self) -> float:
        """The largest contact pressure: sampled on a 161 x 161 grid over the contact, then polished locally.

        ``inf`` for the flat punch, whose pressure is singular at the edge (F.8).
        """
        from scipy import optimize

        if getattr(self.punch, "singular_edge", False):
            return math.inf
        w = float(getattr(self._extent, "value", self._extent))  # a lazy extent computes its value on first use
        g = np.linspace(-w, w, 161)
        X1, X2 = np.meshgrid(g, g, indexing="ij")
        P = self.pressure(X1, X2)
        k = np.unravel_index(int(np.argmax(P)), P.shape)
        x0 = np.array([X1[k], X2[k]])
        res = optimize.minimize(lambda z: -float(self.pressure(z[0], z[1])), x0, method="Nelder-Mead",
                                options={"xatol": 1e-10 * w, "fatol": 1e-14 * max(P[k], 1e-300)})
        return float(max(P[k], -res.fun))

    def compare_direct(self, **options: Any) -> DirectComparison:
        """Solve the same problem (same ``delta0``) with the direct solver and put both side by side.

        ``options`` go to the direct solver (``n`` modes or cells).  When this result is itself
        ``"direct"``, the comparison is with a refined direct solution (1.4 times the modes or cells).
        """
        from .models.walk import direct_comparison

        return DirectComparison(self, direct_comparison(self, **options))

    # ---- output ----------------------------------------------------------------------------
    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        est = self.error_estimate
        base = f", {self.layer.base_note}" if self.layer.base_note else ""
        lines = [
            f"Indentation ({self.model} model): "
            + getattr(self.punch, "description", f"{self.punch.name} Phi = {getattr(self.punch, 'expr', '')}"),
            f"  layer nu = {self.nu:.6g}{base}, H = {self.H:.6g}, mu = {self.mu:.6g} (E = {self.E:.6g}), "
            f"delta0 = {self.delta0:.8g}, H/a = {self.H_over_a:.3g}",
            f"  force           P = {self.force:.8g}   (+- {100 * est['force']:.2g} %)",
            f"  contact area      = {self.contact_area:.8g}   (+- {100 * est['contact_area']:.2g} %)",
        ]
        if self.contact_radius is not None:
            lines.append(f"  contact radius  c = {self.contact_radius:.8g}   "
                         f"(+- {100 * est.get('contact_radius', math.nan):.2g} %)")
        if self.semi_axes is not None:
            lines.append(f"  semi-axes         = {self.semi_axes[0]:.8g}, {self.semi_axes[1]:.8g}")
        lines.append(f"  model: {self.model} -- {self.reason}")
        lines += [f"  FLAG: {f}" for f in self.flags]
        return lines

    @property
    def equations(self) -> tuple[str, str]:
        """The equations of the force and of the contact size in the model used."""
        from .models.walk import entry_of

        entry = entry_of(self)
        if entry is None:
            return self.equation, self.equation
        return entry.result_equations(self)

    def latex(self) -> str:
        est = self.error_estimate
        tf, ta = self.equations
        rows = [rf"P = {tex_num(self.force)}\ \left(\pm {100 * est['force']:.2g}\,\%\right) \tag{{{tf}}}",
                rf"|\omega| = {tex_num(self.contact_area)}\ \left(\pm {100 * est['contact_area']:.2g}\,\%\right)"
                rf" \tag{{{ta}}}"]
        if self.contact_radius is not None:
            rows.append(rf"c = {tex_num(self.contact_radius)}")
        rows.append(rf"\text{{model: {self.model}}},\quad H/a = {self.H_over_a:.3g},\quad \nu = {self.nu:.6g}")
        return " \\\\\n".join(rows)

    def as_dict(self) -> dict[str, Any]:
        """The numbers as a JSON-ready dictionary."""
        return {"model": self.model, "reason": self.reason, "force": self.force, "delta0": self.delta0,
                "contact_area": self.contact_area, "contact_radius": self.contact_radius,
                "semi_axes": list(self.semi_axes) if self.semi_axes else None,
                "max_pressure": self.max_pressure if math.isfinite(self.max_pressure) else None,
                "H": self.H if math.isfinite(self.H) else None, "mu": self.mu, "E": self.E, "nu": self.nu,
                "H_over_a": self.H_over_a if math.isfinite(self.H_over_a) else None,
                "error_estimate": dict(self.error_estimate), "tol": self.tol, "flags": list(self.flags)}


def tex_num(x: float) -> str:
    m, e = f"{x:.7e}".split("e")
    e = int(e)
    return f"{x:.8g}" if -3 <= e <= 5 else rf"{float(m):.8g} \times 10^{{{e}}}"


@boundary_methods
@dataclass(frozen=True, eq=False)
class DirectComparison(RichDisplay):
    """An :class:`Indentation` beside the direct solution of the same problem (:meth:`Indentation.compare_direct`).

    Attributes
    ----------
    solution, direct : Indentation
        The answer and the direct solution (``direct.model == "direct"``).
    rows : list of tuple
        ``(quantity, solution value, direct value, relative difference, the solution's estimate)``.
    """

    solution: Indentation
    direct: Indentation

    @property
    def rows(self) -> list[tuple[str, float, float, float, float]]:
        out = []
        for key in ("force", "contact_area", "contact_radius"):
            a, b = getattr(self.solution, key), getattr(self.direct, key)
            if a is None or b is None:
                continue
            out.append((key, a, b, abs(a - b) / abs(b), self.solution.error_estimate.get(key, math.nan)))
        return out

    @property
    def within_estimate(self) -> bool:
        """Whether every difference is inside the solution's estimate plus the direct solution's own."""
        return all(d <= e + self.direct.error_estimate.get(k, 0.0) for k, _, _, d, e in self.rows)

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        lines = [f"{self.solution.model} model vs direct solver ({self.direct.reason})",
                 f"  {'quantity':<15}{self.solution.model:>16}{'direct':>16}{'difference':>12}{'estimate':>12}"]
        for k, a, b, d, e in self.rows:
            lines.append(f"  {k:<15}{a:>16.8g}{b:>16.8g}{100 * d:>11.3g}%{100 * e:>11.3g}%")
        return lines

    def latex(self) -> str:
        return " \\\\\n".join(rf"\text{{{k.replace('_', ' ')}}}: {tex_num(a)}\ \text{{vs}}\ {tex_num(b)}"
                              for k, a, b, _, _ in self.rows)

