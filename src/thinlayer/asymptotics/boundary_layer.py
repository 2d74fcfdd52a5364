r"""Stage (3.15)-(3.25): the boundary-layer equation and Alexandrov's approximate solution.

Boundary-layer equation
-----------------------
Near the contour, in the fast normal variable ``v`` (3.7), the pressure ``q(v)`` solves (3.15)::

    int_h^oo q(v') N(v' - v) dv' = pi^2 vartheta H_* b_1 v,      v > h,     q(h) = 0  (3.18)

*Kernel (3.16) -> (3.17), own derivation.*  Write (2.12) as the full Fourier integral
``k(xi) = (1/4) iint_{R^2} F(|s|) e^{i s.xi} ds`` with ``F(s) = L(s)/s`` even (3.10).  Integrating
over the tangential variable, ``int e^{i s_1 sigma} d sigma = 2 pi delta(s_1)`` (2.18), hence::

    N(t) = int k(sigma, t) d sigma = (pi/2) int_R F(|s_2|) e^{i s_2 t} ds_2
         = pi int_0^oo (L(s)/s) cos(s t) ds                                            (3.17)

and ``int N(t) e^{i w t} dt = pi^2 L(w)/w``; at ``w = 0``: ``int N dt = pi^2 A = mu_00`` (2.21).
Since ``F(s) = 1/s + O(s e^{-2s})``, N has the logarithmic singularity ``-pi log|t|`` at 0.

*Numerics of N.*  The cosine transforms ``int_0^oo cos(st) (s^2+1)^{-1/2} ds = K_0(t)`` and
``int_0^oo cos(st) (s^2+1)^{-3/2} ds = t K_1(t)`` are subtracted (``method="bessel2"``: the
remainder ``F - (s^2+1)^{-1/2} - (s^2+1)^{-3/2}/2 = O(s^{-5})``; ``method="bessel1"``: only K_0,
remainder ``O(s^{-3})``) and the remainder is integrated by :func:`mpmath.quadosc`.

Alexandrov's kernel (3.19)-(3.21)
---------------------------------
``L~(s)/s = sqrt(s^2 + B^2)/(s^2 + C) = (B/C) (1 + (1/(2B^2) - 1/C) s^2 + O(s^4))``; matching (2.20):

* ``s -> 0``: ``B/C = A`` (3.20);
* ``s^2``:   ``1/C - 1/(2B^2) = -m_1`` (3.21; the paper prints ``-2 m_1``, a misprint), where
  ``m_1 = lim_{s->0} L''(s)/(6 A s)`` (the paper prints ``1/(2A)``: ``L = A(s + m_1 s^3 + ...)``
  gives ``L'' = 6 A m_1 s + ...``).

With ``C = B/A`` the second condition reads ``2 m_1 B^2 + 2 A B - 1 = 0``.  Its roots multiply to
``-1/(2 m_1)``; the one continuous through ``m_1 = 0`` (nu = 0 and nu = 1/4, where ``B = 1/(2A)``) is::

    B = 1/(A + sqrt(A^2 + 2 m_1)),     C = B/A.

The other root, ``-(A + sqrt(A^2 + 2 m_1))/(2 m_1)``, is negative for ``m_1 > 0`` and tends to
``+oo`` as ``m_1 -> 0^-`` (``0 < nu < 1/4``), so it is discarded.  For the bonded layer
``A^2 + 2 m_1 = -(32nu^5 - 104nu^4 + 144nu^3 - 92nu^2 + 26nu - 3)/(12 (1-nu)^4 (1-2nu))``, whose
numerator's only real zero is nu = 0.7165...: the square root is real on all of (-1, 1/2) and
B, C > 0 there.  Moreover ``A B < 1`` always, i.e. ``C > B^2``.

*Alexandrov kernel.*  ``N~(t) = pi int_0^oo sqrt(s^2+B^2)/(s^2+C) cos(st) ds``.  Writing
``sqrt(s^2+B^2)/(s^2+C) = (1 + (B^2 - C)/(s^2+C))/sqrt(s^2+B^2)`` and turning the contour of the
second part onto the positive imaginary axis ``s = i y`` (the branch cut starts at ``y = B``; the pole
``y = sqrt(C) > B`` lies on the cut and contributes only an imaginary half-residue)::

    N~(t) = pi [ K_0(B|t|) + (C - B^2) PV int_B^oo e^{-y|t|} dy / ((y^2 - C) sqrt(y^2 - B^2)) ]

(``method="laplace"``; ``method="fourier"`` subtracts ``K_0(|t|)`` and uses ``quadosc``).

Wiener--Hopf solution (3.22)-(3.25), own derivation
---------------------------------------------------
Put ``q = (c/(pi^2 A)) Q`` with ``c = pi^2 vartheta H_* b_1`` (3.22), i.e. pull the factor
``vartheta H_* b_1 / A`` out, so that ``Q ~ v`` at infinity (matching the inner pressure (2.29),
linear in the distance from the contour).  For ``tau = v - h > 0``::

    int_0^oo Q(tau') N~(tau' - tau) dtau' = pi^2 A (h + tau).

Fourier transform (``Q+(w) = int_0^oo Q e^{i w tau} dtau``); ``N~^(w) = pi^2 K+(w) K-(w)`` with
``K+(w) = sqrt(w + iB)/(w + i sqrt C)``, ``K-(w) = sqrt(w - iB)/(w - i sqrt C)``.  Dividing by ``K-`` and
keeping the pole part at ``w = 0`` (Liouville: both sides vanish at infinity) gives, with ``w = i p``,
the Laplace transform::

    Q~(p) = sqrt(A) (p + sqrt C)/sqrt(p + B) [1/p^2 + (h - h_0)/p],   h_0 = 1/sqrt(C) - 1/(2B).

Inverting (``L^{-1}[(p+B)^{-1/2}] = e^{-B tau}/sqrt(pi tau)``, ``L^{-1}[1/(p sqrt(p+B))] =
erf(sqrt(B tau))/sqrt(B)``) with ``sqrt(A C/B) = 1``::

    Q(tau) = (tau + h) erf sqrt(B tau) + sqrt(tau/(pi B)) e^{-B tau}
             + (h - h_0) sqrt(A/(pi tau)) e^{-B tau}                                  (3.23)

which is the printed (3.23) times ``A``.  The edge condition (3.18) kills the ``tau^{-1/2}`` term:
``h = h_0 = 1/sqrt(C) - 1/(2B) = sqrt(A/B) - 1/(2B)`` (3.25), and then (3.24)::

    Q(v) = v erf sqrt(B (v - h)) + sqrt((v - h)/(pi B)) e^{-B (v - h)},   v > h,
    int_0^oo Q(h + tau) e^{-p tau} dtau = sqrt(A) (p + sqrt C)/(p^2 sqrt(p + B)).

``dQ/dtau = erf sqrt(B tau) + e^{-B tau} (B/sqrt C)/sqrt(pi B tau) > 0``, so ``Q > 0`` for ``v > h``.
Force defect: ``int_{-oo}^{oo} (Qhat(v) - max(v, 0)) dv = 1/(4B^2) - 1/(2C) = m_1/2``, with
``Qhat = Q`` for ``v > h`` and 0 otherwise; for ``h >= 0`` it is ``int_0^oo (Qhat - v) dv``.
(h < 0 for nu > 0.38...: the corrected edge lies outside the leading contour.)
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any, ClassVar

import mpmath
import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import InputError, InputTypeError
from ..display import RichDisplay, fmt
from ..errors import boundary, boundary_methods
from ..layers.kernels import LayerKernel
from ..normal import normal_latex
from ..parse import as_expr, sympy_value
from ..results import latex_equation

#: fast normal variable (3.7), distance from the edge (3.22), Laplace variable, kernel argument
v = sp.Symbol("v", real=True)
tau = sp.Symbol("tau", nonnegative=True)
p = sp.Symbol("p", positive=True)
t = sp.Symbol("t", real=True)
b1 = sp.Symbol("b_1^*", real=True)

__all__ = [
    "AlexandrovParameters",
    "AlexandrovSolution",
    "alexandrov_fit",
    "alexandrov_kernel",
    "alexandrov_kernel_numpy",
    "alexandrov_parameters",
    "alexandrov_solution",
    "boundary_layer_kernel",
]


# ---------------------------------------------------------------------------------------------
# helpers
# ---------------------------------------------------------------------------------------------
def _check_layer(layer: Any) -> LayerKernel:
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a thinlayer LayerKernel (e.g. BondedLayer(0.3)), "
                             f"got {type(layer).__name__}")
    return layer


def _is_mp(x: Any) -> bool:
    return isinstance(x, (mpmath.mpf, mpmath.mpc))


def _to_mpf(x: Any) -> mpmath.mpf:
    """A real number (sympy, mpmath, float) as an mpf at the current precision."""
    if _is_mp(x):
        return mpmath.mpf(x)
    x = as_expr(x)
    if not x.is_number:
        raise InputError(f"a numeric value is needed, got the expression {x}; build the layer with a numeric nu")
    return mpmath.mpf(str(sp.N(x, mpmath.mp.dps + 10)))


def _to_sympy(x: Any, dps: int) -> sp.Expr:
    return sp.Float(mpmath.nstr(x, dps + 5, strip_zeros=False), dps) if _is_mp(x) else as_expr(x)


def _check_t(t_: Any) -> mpmath.mpf:
    if isinstance(t_, bool):
        raise InputTypeError("t must be a real number, got a bool")
    try:
        tt = _to_mpf(t_)
    except (TypeError, ValueError, sp.SympifyError) as exc:
        raise InputTypeError(f"t must be a real number, got {t_!r}") from exc
    if tt == 0:
        raise InputError("t = 0: the kernel N(t) ~ -pi log|t| is singular there; give t != 0")
    if not mpmath.isfinite(tt):
        raise InputError(f"t must be finite, got {t_!r}")
    return abs(tt)


def _cosine_integral(f: Any, tt: Any, s0: int = 32) -> Any:
    """``int_0^oo f(s) ds`` for ``f`` oscillating like ``cos(s t)`` with an algebraically small tail.

    ``[0, s0]`` (where the non-oscillatory structure of the kernel lives) is cut into panels no
    longer than half a period; ``[s0, oo)`` goes to :func:`mpmath.quadosc`.  A single quadosc from
    0 is inaccurate for small t, where one period covers the whole structure.
    """
    n = max(8, int(mpmath.ceil(s0 * tt / mpmath.pi)) + 1)
    head = mpmath.quad(f, mpmath.linspace(0, s0, n + 1))
    # quadosc's ``omega`` places the zeros at n pi/omega counted from 0, not from the lower
    # limit: for a lower limit s0 > pi/omega it would integrate [pi/omega, s0] twice.  Give the
    # half-period points from s0 explicitly.
    half = mpmath.pi / tt
    return head + mpmath.quadosc(f, [s0, mpmath.inf], zeros=lambda k: s0 + k * half)


# ---------------------------------------------------------------------------------------------
# the exact kernel (3.17)
# ---------------------------------------------------------------------------------------------
def boundary_layer_kernel(layer: LayerKernel, t: Any, method: str = "bessel2") -> mpmath.mpf:
    """Kernel of the boundary-layer equation, ``N(t) = pi int_0^oo (L(s)/s) cos(st) ds`` (3.17).

    Derived from (3.16) and (2.12) in the module docstring.  Evaluated in mpmath at the current
    ``mpmath.mp.dps``: closed-form Bessel pieces with the same large-s behaviour are subtracted
    and the remainder is integrated with :func:`mpmath.quadosc`.

    Parameters
    ----------
    layer : LayerKernel
        A layer with numeric nu (e.g. ``BondedLayer(0.3)`` or ``BondedLayer("3/10")``).
    t : Any
        Real, ``t != 0`` (logarithmic singularity at 0); N is even.
    method : str
        ``"bessel2"`` (subtract ``K_0(t) + t K_1(t)/2``, remainder ``O(s^-5)``) or ``"bessel1"``
        (subtract ``K_0(t)``, remainder ``O(s^-3)``): two independent quadrature routes.

    Returns
    -------
    mpmath.mpf
    """
    layer = _check_layer(layer)
    if layer.parameter is not None:
        raise InputError("boundary_layer_kernel needs a numeric nu; build e.g. BondedLayer(0.3)")
    if method not in ("bessel2", "bessel1"):
        raise InputError(f"method must be 'bessel2' or 'bessel1', got {method!r}")
    tt = _check_t(t)
    with mpmath.extradps(5):
        F = lambda s: layer.L_numeric(s, backend="mpmath", over_u=True)
        if method == "bessel2":
            def rem(s):
                r = 1 / mpmath.sqrt(s * s + 1)
                return (F(s) - r - r**3 / 2) * mpmath.cos(s * tt)

            closed = mpmath.besselk(0, tt) + tt * mpmath.besselk(1, tt) / 2
        else:
            def rem(s):
                return (F(s) - 1 / mpmath.sqrt(s * s + 1)) * mpmath.cos(s * tt)

            closed = mpmath.besselk(0, tt)
        val = mpmath.pi * (closed + _cosine_integral(rem, tt))
    return +val


# ---------------------------------------------------------------------------------------------
# Alexandrov's parameters (3.20), (3.21)
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class AlexandrovParameters(RichDisplay):
    """Constants B, C of Alexandrov's approximation ``L~(s) = s sqrt(s^2+B^2)/(s^2+C)`` (3.19).

    ``B = 1/(A + sqrt(A^2 + 2 m_1))`` and ``C = B/A`` solve (3.20) ``B/C = A`` and the corrected
    (3.21) ``1/C - 1/(2B^2) = -m_1``.  Attributes are sympy expressions of nu for a symbolic
    layer, exact sympy numbers for an exact nu, mpmath numbers for a float nu.
    """

    #: the paper's equation this result reproduces
    equation: ClassVar[str] = "3.19"

    A: Any
    m1: Any
    B: Any
    C: Any
    dps: int = 30

    @property
    def discriminant(self) -> Any:
        """``A^2 + 2 m_1``: must be positive for real B."""
        return self.A**2 + 2 * self.m1

    def symbol(self, s: sp.Expr = S.s) -> sp.Expr:
        """``L~(s)/s = sqrt(s^2 + B^2)/(s^2 + C)`` (3.19) as a sympy expression."""
        B, C = _to_sympy(self.B, self.dps), _to_sympy(self.C, self.dps)
        return sp.sqrt(s**2 + B**2) / (s**2 + C)

    def numeric(self) -> tuple[mpmath.mpf, mpmath.mpf]:
        """``(B, C)`` as mpmath numbers at the current precision (needs a numeric nu)."""
        return _to_mpf(self.B), _to_mpf(self.C)

    def latex(self) -> str:
        d = self.dps
        B, C = _to_sympy(self.B, d), _to_sympy(self.C, d)
        return " \\\\\n".join(
            [
                latex_equation(r"\tilde{\mathcal{L}}(s)", normal_latex(S.s * self.symbol()), "3.19"),
                latex_equation(r"\frac{B}{C} = \mathcal{A}, \quad B", normal_latex(B), "3.20"),
                latex_equation(r"\frac{1}{C} - \frac{1}{2B^2} = -m_1, \quad C", normal_latex(C), "3.21"),
            ]
        )

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return [
            "AlexandrovParameters: L̃(s)/s = √(s² + B²)/(s² + C)   (3.19)-(3.21)",
            f"  𝒜   = {fmt(self.A)}",
            f"  m₁  = {fmt(self.m1)}",
            f"  B   = {fmt(self.B)}",
            f"  C   = {fmt(self.C)}",
        ]


def alexandrov_fit(A: Any, m1: Any, dps: int = 30) -> AlexandrovParameters:
    """Alexandrov's B, C from ``A`` and ``m_1`` of (2.20), conditions (3.20)-(3.21).

    Parameters
    ----------
    A, m1 : Any
        ``L(s)/s = A (1 + m_1 s^2 + ...)``: sympy expressions, exact numbers or mpmath floats.
    dps : int
        precision carried for mpmath inputs.

    Raises
    ------
    ValueError
        if ``A <= 0`` or ``A^2 + 2 m_1 <= 0`` (B would be complex); the bonded layer never does
        this for -1 < nu < 1/2.
    """
    if _is_mp(A) or _is_mp(m1) or isinstance(A, float) or isinstance(m1, float):
        with mpmath.workdps(dps + 10):
            A_, m_ = mpmath.mpf(A), mpmath.mpf(m1)
            if A_ <= 0:
                raise InputError(f"A = {A_} must be positive for Alexandrov's approximation (3.20)")
            disc = A_**2 + 2 * m_
            if disc <= 0:
                raise InputError(
                    f"A^2 + 2 m_1 = {mpmath.nstr(disc, 8)} <= 0: Alexandrov's B = 1/(A + sqrt(A^2 + 2 m_1)) "
                    "is complex, so (3.20)-(3.21) have no real solution"
                )
            B = 1 / (A_ + mpmath.sqrt(disc))
            C = B / A_
        with mpmath.workdps(dps):
            return AlexandrovParameters(+A_, +m_, +B, +C, dps)
    A_, m_ = as_expr(A), as_expr(m1)
    disc = sp.factor(sp.together(A_**2 + 2 * m_))
    if disc.is_number:
        if not A_.is_positive:
            raise InputError(f"A = {A_} must be positive for Alexandrov's approximation (3.20)")
        if not disc.is_positive:
            raise InputError(
                f"A^2 + 2 m_1 = {disc} <= 0: Alexandrov's B = 1/(A + sqrt(A^2 + 2 m_1)) is complex, "
                "so (3.20)-(3.21) have no real solution"
            )
    if disc.is_number:
        B = 1 / (A_ + sp.sqrt(disc))
        C = B / A_
    else:  # sqrt(disc) = sqrt(R)/out:  B = out/(A out + sqrt(R)),  C = B/A
        sqrt_r, out = _sqrt_pulled(disc)
        den = sp.factor(sp.cancel(A_ * out)) + sqrt_r
        B = out / den
        C = sp.factor(sp.cancel(out / A_)) / den
    return AlexandrovParameters(A_, m_, B, C, dps)


def _h_symbolic(par: AlexandrovParameters) -> sp.Expr:
    """(3.25) ``h = sqrt(A/B) - 1/(2B)`` written with ``1/B = den/out`` as built above."""
    if par.B.is_number:
        return 1 / sp.sqrt(par.C) - 1 / (2 * par.B)
    out, den = sp.fraction(par.B)  # B = out/den
    r, o = _sqrt_pulled(sp.cancel(par.A / out), extra=den)
    return r / o - den / (2 * out)


_ONE = sp.Integer(1)


def _sqrt_pulled(expr: sp.Expr, extra: sp.Expr = _ONE) -> tuple[sp.Expr, sp.Expr]:
    """``sqrt(expr) = sqrt(R)/out`` with fourth powers of real factors of the denominator pulled out.

    ``sqrt(f^4) = f^2`` for real f, so this is exact for a real parameter.
    """
    n, d = sp.fraction(sp.factor(expr))
    c, facs = sp.factor_list(d)
    out, rest = sp.Integer(1), sp.Integer(c)
    for f, k in facs:
        j = k // 4
        out *= f ** (2 * j)
        rest *= f ** (k - 4 * j)
    if rest.could_extract_minus_sign():
        n, rest = -n, -rest
    return sp.sqrt(sp.factor(n) * extra / sp.factor(rest), evaluate=False), out


def alexandrov_parameters(layer: LayerKernel) -> AlexandrovParameters:
    """B and C of Alexandrov's approximation (3.19) for a layer: conditions (3.20), (3.21).

    Parameters
    ----------
    layer : LayerKernel
        Any layer with a thin-layer expansion (2.20), e.g. ``BondedLayer()`` (symbolic nu: B, C
        are sympy expressions of nu), ``BondedLayer("3/10")`` (exact) or ``BondedLayer(0.3)``.

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> par = alexandrov_parameters(BondedLayer(0))
    >>> par.B, par.C
    (1, 2)
    """
    layer = _check_layer(layer)
    # BondedLayer(0) == BondedLayer(0.0) as dataclasses: key the cache on the type of nu too
    nu_ = getattr(layer, "nu", None)
    return _parameters_cached(layer, type(nu_).__name__, repr(nu_), getattr(layer, "dps", 30))


@lru_cache(maxsize=64)
def _parameters_cached(layer: LayerKernel, _kind: str, _nu: str, dps: int) -> AlexandrovParameters:
    return alexandrov_fit(layer.A, layer.m(1), dps=dps)


def _params(obj: Any) -> AlexandrovParameters:
    if isinstance(obj, AlexandrovParameters):
        return obj
    if isinstance(obj, AlexandrovSolution):
        return obj.params
    return alexandrov_parameters(obj)


# ---------------------------------------------------------------------------------------------
# Alexandrov's kernel N~
# ---------------------------------------------------------------------------------------------
def _pv_cut(tt: Any, B: Any, C: Any) -> Any:
    """``PV int_B^oo e^{-y t} / ((y^2 - C) sqrt(y^2 - B^2)) dy`` for ``sqrt(C) > B``, in mpmath.

    With ``y = B cosh u``: ``PV int_0^oo e^{-B t cosh u} du/(B^2 cosh^2 u - C)``, pole at
    ``cosh u_0 = sqrt(C)/B``, folded about ``u_0`` (see :func:`alexandrov_kernel_numpy`).
    """
    u0 = mpmath.acosh(mpmath.sqrt(C) / B)
    ch0 = mpmath.cosh(u0)

    def phi(x):
        return mpmath.exp(-B * tt * mpmath.cosh(u0 + x)) / (
            2 * B * B * mpmath.sinh(u0 + x / 2) * (mpmath.cosh(u0 + x) + ch0)
        )

    fold = mpmath.quad(lambda x: (phi(x) - phi(-x)) / mpmath.sinh(x / 2), [0, u0])
    big = (mpmath.mp.dps + 5) * mpmath.log(10)  # e^{-big} is below the working precision
    U = mpmath.acosh(max(big / (B * tt), mpmath.cosh(2 * u0)))
    tail = mpmath.quad(lambda u: mpmath.exp(-B * tt * mpmath.cosh(u)) / (B * B * mpmath.cosh(u) ** 2 - C),
                       [2 * u0, (2 * u0 + U) / 2, U]) if U > 2 * u0 else 0
    return fold + tail


def alexandrov_kernel(layer: Any, t: Any, method: str = "laplace") -> mpmath.mpf:
    """Alexandrov's kernel ``N~(t) = pi int_0^oo sqrt(s^2+B^2)/(s^2+C) cos(st) ds`` ((3.22), (3.19)).

    Parameters
    ----------
    layer : Any
        A numeric layer, or :class:`AlexandrovParameters` / :class:`AlexandrovSolution`.
    t : Any
        Real, ``t != 0``; the kernel is even with a ``-pi log|t|`` singularity at 0.
    method : str
        ``"laplace"`` (default): ``pi [K_0(B t) + (C - B^2) PV int_B^oo e^{-yt} dy /((y^2-C)
        sqrt(y^2-B^2))]`` (contour turned onto the imaginary axis, see module docstring);
        ``"fourier"``: ``pi [K_0(t) + quadosc(remainder)]``.

    Returns
    -------
    mpmath.mpf at the current ``mpmath.mp.dps``.
    """
    if method not in ("laplace", "fourier"):
        raise InputError(f"method must be 'laplace' or 'fourier', got {method!r}")
    par = _params(layer)
    tt = _check_t(t)
    with mpmath.extradps(10):
        B, C = par.numeric()
        if method == "laplace":
            if not C > B * B:  # A B < 1 always (module docstring); guard anyway
                raise InputError(f"the 'laplace' route needs C > B^2, got B={B}, C={C}; use method='fourier'")
            val = mpmath.besselk(0, B * tt) + (C - B * B) * _pv_cut(tt, B, C)
        else:
            def rem(s):
                return (mpmath.sqrt(s * s + B * B) / (s * s + C) - 1 / mpmath.sqrt(s * s + 1)) * mpmath.cos(s * tt)

            val = mpmath.besselk(0, tt) + _cosine_integral(rem, tt)
        val = mpmath.pi * val
    return +val


@lru_cache(maxsize=8)
def _leggauss(n: int) -> tuple[np.ndarray, np.ndarray]:
    if n < 8:
        raise InputError(f"nodes must be an integer >= 8, got {n}")
    return np.polynomial.legendre.leggauss(n)


def alexandrov_kernel_numpy(layer: Any, t: Any, nodes: int = 80) -> np.ndarray:
    """Vectorised ``N~(t)`` in double precision: the ``"laplace"`` route of :func:`alexandrov_kernel`.

    With ``y = B cosh u`` the principal value becomes
    ``PV int_0^oo e^{-B t cosh u} du / (B^2 cosh^2 u - C)`` with a simple pole at
    ``cosh u_0 = sqrt(C)/B``; folding ``[0, 2 u_0]`` about ``u_0`` and writing
    ``cosh u - cosh u_0 = 2 sinh((u+u_0)/2) sinh((u-u_0)/2)`` gives a smooth integrand, done by a
    fixed Gauss--Legendre rule (``nodes`` points on the fold and on the tail).

    Parameters
    ----------
    layer : Any
        numeric layer, :class:`AlexandrovParameters` or :class:`AlexandrovSolution`.
    t : Any
        array of reals, all ``!= 0``.
    """
    from scipy.special import k0

    par = _params(layer)
    B, C = (float(x) for x in par.numeric())
    tt = np.abs(np.asarray(t, dtype=float))
    if np.any(tt == 0) or not np.all(np.isfinite(tt)):
        raise InputError("t must be finite and != 0 (N~ ~ -pi log|t| at t = 0)")
    u0 = float(np.arccosh(np.sqrt(C) / B))
    ch0 = np.cosh(u0)
    xg, wg = _leggauss(int(nodes))
    tb = tt[..., None]
    # fold: x in (0, u0)
    x = 0.5 * u0 * (xg + 1)
    wx = 0.5 * u0 * wg

    def phi(xx):
        return np.exp(-B * tb * np.cosh(u0 + xx)) / (
            2 * B * B * np.sinh(u0 + xx / 2) * (np.cosh(u0 + xx) + ch0)
        )

    fold = np.sum(wx * (phi(x) - phi(-x)) / np.sinh(x / 2), axis=-1)
    # tail: u in (2 u0, U), U where B t cosh U = 40
    U = np.maximum(np.arccosh(np.maximum(40.0 / (B * tt), 1.0)), 2 * u0)[..., None]
    u = 2 * u0 + 0.5 * (U - 2 * u0) * (xg + 1)
    wu = 0.5 * (U - 2 * u0) * wg
    tail = np.sum(wu * np.exp(-B * tb * np.cosh(u)) / (B * B * np.cosh(u) ** 2 - C), axis=-1)
    out = np.pi * (k0(B * tt) + (C - B * B) * (fold + tail))
    return out[()] if out.ndim == 0 else out


# ---------------------------------------------------------------------------------------------
# the boundary-layer solution (3.23)-(3.25)
# ---------------------------------------------------------------------------------------------
@boundary_methods
@dataclass(frozen=True)
class AlexandrovSolution(RichDisplay):
    """Boundary layer with Alexandrov's kernel, normalised: ``q** = (vartheta H_* b_1^*/A) Q(v)``.

    ``Q(v) ~ v`` as ``v -> oo`` (matching the inner pressure (2.29), linear in the distance from
    the contour), ``Q(h) = 0`` (3.18), ``h`` from (3.25).
    """

    #: the paper's equation this result reproduces
    equation: ClassVar[str] = "3.23"

    params: AlexandrovParameters
    h: Any

    # ---- symbolic ----------------------------------------------------------------------------
    def _BCh(self) -> tuple[sp.Expr, sp.Expr, sp.Expr, sp.Expr]:
        d = self.params.dps
        return (
            _to_sympy(self.params.A, d),
            _to_sympy(self.params.B, d),
            _to_sympy(self.params.C, d),
            _to_sympy(self.h, d),
        )

    def q(self, v_: sp.Expr = v) -> sp.Expr:
        """Normalised boundary layer (3.24), valid for ``v >= h``::

        Q(v) = v erf(sqrt(B (v - h))) + sqrt((v - h)/(pi B)) exp(-B (v - h)).
        """
        v_ = sympy_value(v_, "v")
        _, B, _, h = self._BCh()
        x = v_ - h
        return v_ * sp.erf(sp.sqrt(B * x)) + sp.sqrt(x / (sp.pi * B)) * sp.exp(-B * x)

    def q_hat(self, v_: sp.Expr = v) -> sp.Piecewise:
        """``Q`` extended by 0 outside the contact area: ``Piecewise((Q(v), v >= h), (0, True))``."""
        v_ = sympy_value(v_, "v")
        _, _, _, h = self._BCh()
        return sp.Piecewise((self.q(v_), v_ >= h), (0, True))

    def q_general(self, tau_: sp.Expr = tau, h: sp.Expr | None = None) -> sp.Expr:
        """General solution (3.23) of (3.22) for a given edge position ``h`` (normalised by ``A``)::

        Q = (tau + h) erf sqrt(B tau) + sqrt(tau/(pi B)) e^{-B tau}
            + (h - h_0) sqrt(A/(pi tau)) e^{-B tau},     h_0 = 1/sqrt(C) - 1/(2B).
        """
        tau_ = sympy_value(tau_, "tau")
        A, B, C, _ = self._BCh()
        hh = sp.Symbol("h", real=True) if h is None else as_expr(h)
        e = sp.exp(-B * tau_)
        return (
            (tau_ + hh) * sp.erf(sp.sqrt(B * tau_))
            + sp.sqrt(tau_ / (sp.pi * B)) * e
            + (hh - (1 / sp.sqrt(C) - 1 / (2 * B))) * sp.sqrt(A / (sp.pi * tau_)) * e
        )

    def laplace_transform(self, p_: sp.Expr = p) -> sp.Expr:
        """``int_0^oo Q(h + tau) e^{-p tau} dtau = sqrt(A) (p + sqrt C)/(p^2 sqrt(p + B))``."""
        p_ = sympy_value(p_, "p")
        A, B, C, _ = self._BCh()
        return sp.sqrt(A) * (p_ + sp.sqrt(C)) / (p_**2 * sp.sqrt(p_ + B))

    def dimensional(self, v_: sp.Expr = v) -> sp.Expr:
        """The physical boundary layer ``q**(s, v) = vartheta H_* b_1^*(s) A^{-1} Q(v)`` (3.24)."""
        v_ = sympy_value(v_, "v")
        A = _to_sympy(self.params.A, self.params.dps)
        return S.vartheta * S.H_s * b1 / A * self.q(v_)

    # ---- numeric -----------------------------------------------------------------------------
    def q_numeric(self, v_: Any) -> Any:
        """Vectorised ``Q(v)`` (numpy, scipy.special.erf); 0 for ``v <= h``.  Needs a numeric nu."""
        from scipy.special import erf

        try:
            B, h = float(_to_mpf(self.params.B)), float(_to_mpf(self.h))
        except ValueError as exc:
            raise InputError("q_numeric needs a numeric nu; build the layer with e.g. nu=0.3") from exc
        vv = np.asarray(v_, dtype=float)
        x = np.maximum(vv - h, 0.0)
        out = vv * erf(np.sqrt(B * x)) + np.sqrt(x / (np.pi * B)) * np.exp(-B * x)
        out = np.where(vv > h, out, 0.0)
        return out[()] if out.ndim == 0 else out

    def q_mpmath(self, v_: Any) -> mpmath.mpf:
        """``Qhat(v)`` in mpmath at the current precision (0 for ``v <= h``)."""
        B, h = _to_mpf(self.params.B), _to_mpf(self.h)
        vv = _to_mpf(v_)
        if vv <= h:
            return mpmath.mpf(0)
        x = vv - h
        return vv * mpmath.erf(mpmath.sqrt(B * x)) + mpmath.sqrt(x / (mpmath.pi * B)) * mpmath.exp(-B * x)

    def latex(self) -> str:
        _, B, C, h = self._BCh()
        hs = sp.Symbol("h", real=True)
        return " \\\\\n".join(
            [
                latex_equation(r"\frac{\mathcal{A}\,\tilde q^{**}(s, h + \tau)}{\vartheta H_* b_1^*(s)}",
                               self.q_general(tau, hs), "3.23"),
                latex_equation(r"\frac{\mathcal{A}\,\tilde q^{**}(s, v)}{\vartheta H_* b_1^*(s)}", self.q(v), "3.24"),
                latex_equation(r"h^*(s)", normal_latex(1 / sp.sqrt(C) - 1 / (2 * B)) + " = " + normal_latex(h), "3.25"),
            ]
        )

    def text_lines(self) -> list[str]:
        """The lines of ``str(self)``."""
        return [
            ("AlexandrovSolution: Q(v) = v erf(√(B (v - h))) + √((v - h)/(π B)) exp(-B (v - h)), v > h"
            "   (3.23)-(3.25)"),
            f"  B  = {fmt(self.params.B)}",
            f"  C  = {fmt(self.params.C)}",
            f"  h* = {fmt(self.h)}",
        ]


@boundary
def alexandrov_solution(layer: Any) -> AlexandrovSolution:
    """Boundary layer with Alexandrov's kernel (3.22)-(3.25), by Wiener--Hopf (module docstring).

    Parameters
    ----------
    layer : Any
        A layer (symbolic or numeric nu) or :class:`AlexandrovParameters`.

    Returns
    -------
    AlexandrovSolution
        ``.h = 1/sqrt(C) - 1/(2B) = sqrt(A/B) - 1/(2B)`` (3.25); ``.q(v)`` (3.24) normalised so
        that ``Q ~ v`` at infinity (the factor ``vartheta H_* b_1^*/A`` pulled out).

    Examples
    --------
    >>> from thinlayer import BondedLayer
    >>> alexandrov_solution(BondedLayer(0)).h
    -1/2 + sqrt(2)/2
    """
    par = _params(layer)
    if _is_mp(par.B):
        with mpmath.workdps(par.dps):
            h = 1 / mpmath.sqrt(par.C) - 1 / (2 * par.B)
    else:
        h = _h_symbolic(par)  # (3.25)
    return AlexandrovSolution(par, h)
