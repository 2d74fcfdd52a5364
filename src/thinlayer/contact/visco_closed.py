r"""A closed form of the Lee-Radok force on the thin layer: the sphere under a ramp, standard linear solid (V.11).

With a constant Poisson ratio the shear relaxation modulus is ``E(t)/(2(1 + nu))`` and Lee-Radok's hereditary
integral over a growing contact (:mod:`thinlayer.contact.hereditary`) is

    P(t) = (1/(2(1 + nu))) int_0^t E(t - s) d/ds F(delta(s)) ds,

``F`` the layer's elastic force law at unit shear modulus.  On the thin compressible layer ``F`` is the engine's
force law of the paraboloid (1.8), (3.25) (:func:`thinlayer.force_law`, ``P = mu (a2 delta^2 + a1 delta)``, the
edge shift in ``a1``); for the ramp ``delta = v t`` and the standard linear solid
``E(t) = E_inf + (E0 - E_inf) exp(-t/tau)`` sympy integrates it in closed form (V.11).  Checks, each raising if
it fails: the limits ``tau -> oo`` (``E0`` throughout) and ``tau -> 0`` (``E_inf``) are the elastic law times
``E/(2(1 + nu))``, and the closed form satisfies the standard linear solid's differential form
``tau P' + P = (E_inf F + tau E0 dF/dt)/(2(1 + nu))`` (cancel of the difference).  Valid while the contact grows
(the ramp) and where the thin-layer law holds (``c >> H``; its estimate is the force law's).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import sympy as sp

from .. import symbols as S
from ..asymptotics.force_law import force_law
from ..display import RichDisplay
from ..punch import Punch
from ..results import checked_lambdify

__all__ = ["RampSLSForce", "sls_ramp_force"]

t, v, tau = sp.symbols("t v tau", positive=True)
E0, E_inf = sp.symbols("E_0 E_infty", positive=True)
_s = sp.Symbol("s", positive=True)


@dataclass(frozen=True)
class RampSLSForce(RichDisplay):
    """The Lee-Radok force of the sphere on the thin layer under ``delta = v t``, standard linear solid (V.11).

    Attributes
    ----------
    elastic : sympy.Expr
        ``F(delta)``: the thin-layer force law (1.8) at unit shear modulus.
    force : sympy.Expr
        ``P(t)`` in ``t, v, E_0, E_infty, tau, R, H`` (and ``h^*`` for a symbolic Poisson ratio).
    nu : sympy.Expr
        The layer's Poisson ratio.
    """

    elastic: sp.Expr
    force: sp.Expr
    nu: sp.Expr
    relaxing: sp.Expr = sp.S.Zero

    def latex_display(self, printer: Any = sp.latex) -> str:
        """(V.11) as ``P = [E_inf F(vt) + (E0 - E_inf)(A(t) + B exp(-t/tau))]/(2(1 + nu))``, no nested fraction;
        ``printer`` turns each part into LaTeX (the report passes its normal form).
        """
        decay = sp.exp(-t / tau)
        A, B = sp.factor(self.relaxing.subs(decay, 0)), sp.factor(self.relaxing.coeff(decay))
        Ft = sp.factor(self.elastic.subs(S.delta0, v * t))
        k = sp.latex(1 / (2 * (1 + self.nu)))
        return (rf"P(t) = {k}\Big[E_\infty \left({printer(Ft)}\right) + (E_0 - E_\infty)\Big("
                rf"{printer(A)} + {printer(B)}\,\exp(-t/\tau)\Big)\Big]")

    @property
    def arguments(self) -> tuple:
        return tuple(sorted(self.force.free_symbols, key=lambda x: x.name))

    def lambdify(self) -> Any:
        """A numpy function of :attr:`arguments` (in that order)."""
        return checked_lambdify(self.arguments, self.force)

    def latex(self) -> str:
        return (rf"P(t) = {sp.latex(self.force)},\quad F(\delta) = {sp.latex(self.elastic)},\quad "
                rf"\delta = v t \tag{{V.11}}")

    def text_lines(self) -> list[str]:
        return [f"RampSLSForce: sphere on the thin layer, nu = {self.nu}, delta = v t, standard linear solid   (V.11)",
                f"  F(delta) = {self.elastic}", f"  P(t) = {self.force}"]


@lru_cache(maxsize=16)
def _derive(layer: Any) -> RampSLSForce:
    law = force_law(layer, Punch.paraboloid())
    F = sp.expand(law.force.subs(S.mu, 1))
    nu = layer.nu
    k = 1 / (2 * (1 + nu))
    dF = sp.diff(F.subs(S.delta0, v * _s), _s)
    Ft = F.subs(S.delta0, v * t)
    # the relaxing part int_0^t exp(-(t - s)/tau) dF(s), written with exp(-t/tau) only (<= 1: no overflow)
    decay = sp.exp(-t / tau)
    relax = sp.expand(sp.powsimp(sp.expand(sp.integrate(sp.expand(sp.exp(-(t - _s) / tau) * dF), (_s, 0, t)))))
    relax = sp.collect(relax, decay, sp.factor)
    if sp.expand(relax.subs(decay, 0) + relax.coeff(decay) * decay - relax) != 0:
        raise ArithmeticError(f"(V.11): the relaxing part is not A(t) + B exp(-t/tau): {relax}")
    P = k * (E_inf * Ft + (E0 - E_inf) * relax)
    # the standard linear solid's differential form (cancel of the difference): tau P' + P = k (E_inf F + tau E0 F')
    ode = tau * sp.diff(P, t) + P - k * (E_inf * Ft + tau * E0 * sp.diff(Ft, t))
    if sp.cancel(sp.expand(ode)) != 0:
        raise ArithmeticError(f"(V.11) does not satisfy the standard linear solid's equation: {ode}")
    for lim, E in ((sp.oo, E0), (0, E_inf)):  # no relaxation / instant relaxation: the elastic law
        diff = sp.limit(P, tau, lim) - k * E * Ft
        if sp.cancel(sp.expand(diff)) != 0:
            raise ArithmeticError(f"(V.11) at tau -> {lim} is not the elastic law: {diff}")
    return RampSLSForce(F, P, nu, relax)


def sls_ramp_force(layer: Any) -> RampSLSForce:
    """The closed form (V.11) for the paraboloid on the thin compressible ``layer`` (``BondedLayer(nu)``,
    numeric nu), from the engine's force law (1.8), (3.25) (module docstring).

    Examples
    --------
    >>> import sympy as sp
    >>> from thinlayer import BondedLayer
    >>> res = sls_ramp_force(BondedLayer(sp.Rational(3, 10)))
    >>> res.elastic
    -pi*H*delta_0/2 + 7*pi*R*delta_0**2/(2*H)
    """
    return _derive(layer)
