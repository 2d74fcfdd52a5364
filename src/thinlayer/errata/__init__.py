"""Errata registry: every place where thinlayer's derivation differs from the printed paper.

Each :class:`Erratum` names the equation, what is printed, what is derived, the evidence,
and carries a ``check()`` that re-derives the result *by an independent route* and returns
True only when (a) the engine agrees with the independent route and (b) the printed form
disagrees with it.  ``tests/test_errata.py`` runs every check.

>>> from thinlayer import errata
>>> sorted({e.equation for e in errata.ENTRIES})[:3]
['2.1', '2.10', '2.17']
"""
from __future__ import annotations

from collections.abc import Iterable

import sympy as sp

from .. import symbols as S
from ..parse import as_expr
from .entry import LAYERS, PUNCHES, Concern, Erratum
from .published import HAYES_1972_TABLES, PUBLISHED_ENTRIES

__all__ = ["LAYERS", "PUNCHES", "Concern", "Erratum", "ENTRIES", "HAYES_1972_TABLES", "get", "equations",
           "latex_table", "select"]


# --------------------------------------------------------------------------- checks
def _series_F(nu, order: int) -> sp.Expr:
    """Independent route: sympy's own ``series`` of L(s)/s (2.3) at low order (not the engine's method)."""
    k = 3 - 4 * as_expr(nu)
    s = S.s
    L = (2 * k * sp.sinh(2 * s) - 4 * s) / (2 * k * sp.cosh(2 * s) + 1 + k**2 + 4 * s**2)
    return sp.series(L / s, s, 0, 2 * order + 1).removeO()


def _check_2_21() -> bool:
    from ..layers.kernels import BondedLayer

    nu = sp.Rational(3, 10)
    layer = BondedLayer(nu)
    F = _series_F(nu, 2)
    s1, s2 = sp.symbols("s_1 s_2")
    F2 = F.subs(S.s, sp.sqrt(s1**2 + s2**2))
    ok_engine, print_differs = True, False
    for n in range(3):
        for k in range(n + 1):
            # (2.19): mu_{2k,2n-2k} = (-1)^n pi^2 d^{2k}_{s1} d^{2n-2k}_{s2} F(0)
            d = sp.expand(F2)
            d = sp.diff(d, s1, 2 * k) if k else d
            d = sp.diff(d, s2, 2 * n - 2 * k) if n - k else d
            independent = (-1) ** n * sp.pi**2 * d.subs({s1: 0, s2: 0})
            engine = layer.moment(2 * k, 2 * n - 2 * k)
            printed = (-1) ** n * sp.pi**2 * layer.A * layer.m(n) * sp.binomial(n, k) * 2**n \
                * sp.factorial(k) * sp.factorial(n - k)
            ok_engine &= sp.simplify(engine - independent) == 0
            print_differs |= sp.simplify(printed - independent) != 0
    return ok_engine and print_differs


def _inner_generic_p1():
    from ..asymptotics.inner import inner_pressure
    from ..layers.kernels import GenericLayer
    from ..punch import Punch

    ip = inner_pressure(GenericLayer(), Punch.elliptic_paraboloid())
    return ip


def _printed_p1() -> sp.Expr:
    A, m1 = sp.Symbol(r"\mathcal{A}", positive=True), sp.Symbol("m_1")
    R1s, R2s = sp.Symbol("R_1^*", positive=True), sp.Symbol("R_2^*", positive=True)
    return S.vartheta * m1 * S.H_s / A * (1 / R1s + 1 / R2s)


def _residual_order4(p0: sp.Expr, p1: sp.Expr) -> sp.Expr:
    """Coefficient of Lambda^{-4} in  [sum_n (-1)^n pi^2 A m_n Lambda^{-2n-2} Delta^n](p0 + Lambda^{-2} p1) - Lambda^{-2} phi^*  (2.24)."""  # noqa: E501 (one formula or one table row)
    from ..asymptotics.moment_expansion import moment_expansion
    from ..layers.kernels import GenericLayer

    me = moment_expansion(GenericLayer(), 2)
    lhs = me.apply(p0 + S.Lambda**-2 * p1)
    return sp.expand(lhs * S.Lambda**4).coeff(S.Lambda, 0)


def _check_2_30() -> bool:
    ip = _inner_generic_p1()
    p0, p1 = ip.scaled_terms[0], ip.scaled_terms[1]
    # independent route: substitute back into (2.24): the Lambda^{-4} residual must vanish
    engine_ok = sp.expand(_residual_order4(p0, p1)) == 0
    printed_bad = sp.expand(_residual_order4(p0, _printed_p1())) != 0
    return engine_ok and printed_bad


def _check_2_31() -> bool:
    ip = _inner_generic_p1()
    A, m1 = sp.Symbol(r"\mathcal{A}", positive=True), sp.Symbol("m_1")
    R1s, R2s = sp.Symbol("R_1^*", positive=True), sp.Symbol("R_2^*", positive=True)
    Rs = 2 / (1 / R1s + 1 / R2s)
    base = S.delta0_s - S.H_s**2 * (S.xi1**2 / (2 * R1s) + S.xi2**2 / (2 * R2s))
    printed = S.vartheta / (A * S.H_s) * (base + 2 * m1 * S.H_s**2 / (S.Lambda**2 * Rs))
    derived = S.vartheta / (A * S.H_s) * (base - 2 * m1 * S.H_s**2 / (S.Lambda**2 * Rs))
    engine = ip.scaled_pressure
    return sp.expand(engine - derived) == 0 and sp.expand(engine - printed) != 0 and _check_2_30()


def _check_3_1() -> bool:
    from ..punch import Punch

    R1, R1s = sp.Symbol("R_1", positive=True), sp.Symbol("R_1^*", positive=True)
    phis = Punch.elliptic_paraboloid().scaled()
    roots = sp.solve(sp.Eq(phis.subs(S.xi2, 0), S.delta0_s), S.xi1)
    a = max(roots, key=lambda r: r.subs({S.delta0_s: 1, S.H_s: 1, R1s: 1}))
    derived = sp.sqrt(2 * S.delta0_s * R1s) / S.H_s
    printed = sp.sqrt(2 * S.delta0_s * R1) / S.H_s  # R_1 = Lambda R_1^* (1.2)
    printed_in_star = printed.subs(R1, S.Lambda * R1s)
    return sp.simplify(a - derived) == 0 and sp.simplify(a - printed_in_star) != 0


def _check_3_21_m1() -> bool:
    """Literal reading lim L''(s)/s gives 3 m_1; the reading (L(s)/s)'' at 0 gives m_1."""
    from ..layers.kernels import BondedLayer

    nu = sp.Rational(3, 10)
    k = 3 - 4 * nu
    L = (2 * k * sp.sinh(2 * S.s) - 4 * S.s) / (2 * k * sp.cosh(2 * S.s) + 1 + k**2 + 4 * S.s**2)
    lim_literal = sp.limit(sp.diff(L, S.s, 2) / S.s, S.s, 0)  # independent of the engine
    lim_quotient = sp.limit(sp.diff(L / S.s, S.s, 2), S.s, 0)
    layer = BondedLayer(nu)
    literal_is_3m1 = lim_literal / (2 * layer.A) == 3 * layer.m(1)
    return literal_is_3m1 and lim_quotient / (2 * layer.A) == layer.m(1) and lim_literal / (6 * layer.A) == layer.m(1)


def _check_2_1() -> bool:
    """Sign of (2.1): for L = 1 a positive pressure must push the surface into the layer (u_3 > 0).

    Uniform unit pressure on a disc of radius a: in Hankel form (axisymmetric (2.1)),
    u_3(0) = +-(1/vartheta) int_0^oo pbar(alpha) L dalpha with pbar = a J_1(alpha a)/alpha,
    and the integral is a > 0 (mpmath quadrature).  (1.5) needs u_3 >= delta_0 - Phi > 0 in contact,
    and (2.6) with its positive right-hand side follows from (2.1) only with the + sign.
    """
    import mpmath as mp

    a = mp.mpf(1)
    integral = mp.quadosc(lambda al: a * mp.besselj(1, al * a) / al, [0, mp.inf], period=2 * mp.pi)
    printed_u3 = -integral  # with vartheta = 1
    derived_u3 = +integral
    return abs(integral - a) < 1e-10 and derived_u3 > 0 and printed_u3 < 0


def _check_3_21_alexandrov() -> bool:
    """Series of Alexandrov's L~(s)/s = sqrt(s^2+B^2)/(s^2+C) with B = A C (3.19), (3.20)."""
    A, C, s = sp.symbols("A C s", positive=True)
    B = A * C
    ser = sp.series(sp.sqrt(s**2 + B**2) / (s**2 + C), s, 0, 4).removeO()
    a0, a2 = ser.coeff(s, 0), ser.coeff(s, 2)
    m1_tilde = sp.simplify(a2 / a0)  # the m_1 of the approximation (2.20)
    derived_ok = sp.simplify(1 / C - 1 / (2 * B**2) + m1_tilde) == 0  # 1/C - 1/(2B^2) = -m_1
    printed_bad = sp.simplify(1 / C - 1 / (2 * B**2) + 2 * m1_tilde) != 0  # printed: = -2 m_1
    return sp.simplify(a0 - A) == 0 and derived_ok and printed_bad


def _check_2_10() -> bool:
    """Substitute (1.2), (2.8) into the right side of (2.6) and divide by the Jacobian H_*^2."""
    from ..punch import Punch

    p = Punch.elliptic_paraboloid()
    eps = 1 / S.Lambda
    rhs = sp.pi**2 * (eps * S.H_s) * S.vartheta * (eps * S.delta0_s - p.expr)
    rhs = rhs.xreplace({S.x1: S.H_s * S.xi1, S.x2: S.H_s * S.xi2}).xreplace(dict(p.scaling)) / S.H_s**2
    derived = sp.pi**2 * S.vartheta / (S.Lambda**2 * S.H_s) * (S.delta0_s - p.scaled())
    eta1, eta2 = sp.symbols("eta_1 eta_2", real=True)
    printed = derived.subs({S.xi1: eta1, S.xi2: eta2})
    return sp.expand(rhs - derived) == 0 and sp.expand(rhs - printed) != 0


def _check_2_17() -> bool:
    """With xi_j^{2j} every moment would equal mu_{2,4}; (2.15) needs xi_j^{alpha_j}."""
    from ..layers.kernels import BondedLayer

    layer = BondedLayer(sp.Rational(3, 10))
    return layer.moment(2, 0) != layer.moment(2, 4) and layer.moment(0, 0) != layer.moment(2, 4)


def _check_4_1() -> bool:
    """(4.1) holds with phi^* of (2.25) in the place of the undefined f^*: closed form == recursion (2.28)."""
    from ..asymptotics.inner import inner_pressure
    from ..layers.kernels import GenericLayer
    from ..punch import Punch

    p = Punch(S.x1**4 + S.x1 * S.x2**3 + S.x2**2)
    a = inner_pressure(GenericLayer(), p, method="closed")
    b = inner_pressure(GenericLayer(), p, method="recursion")
    return all(sp.expand(x - y) == 0 for x, y in zip(a.scaled_terms, b.scaled_terms))




ENTRIES: tuple[Erratum, ...] = (
    Erratum(
        "2.1", "sign of the surface displacement",
        r"u_3 = -\frac{1}{4\pi^2\vartheta}\iint \hat p_\varepsilon \frac{\mathcal{L}(\alpha H)}{\alpha} e^{-i\alpha\cdot x}\,d\alpha",  # noqa: E501 (one formula or one table row)
        r"u_3 = +\frac{1}{4\pi^2\vartheta}\iint \hat p_\varepsilon \frac{\mathcal{L}(\alpha H)}{\alpha} e^{-i\alpha\cdot x}\,d\alpha",  # noqa: E501 (one formula or one table row)
        r"With $x_3$ into the layer and $p = -\sigma_{33} > 0$, (1.5) needs $u_3 > 0$ in contact; for "
        r"$\mathcal{L} = 1$ the plus sign gives Boussinesq's $u_3 = \frac{1 - \nu}{2\pi\mu}\iint "
        r"\frac{p}{|x - y|}\,dy$ and (2.6) with its positive right side. The direct numerical solver "
        r"(thinlayer.numerics), built on the plus sign, satisfies (1.5) to $10^{-13}$.",
        _check_2_1, concerns=Concern(("2.1", "2.3")), where="(2.1)", cites=("boussinesq1885",),
    ),
    Erratum(
        "2.10", "argument of the punch on the right-hand side",
        r"\Phi^*(\boldsymbol\eta)", r"\Phi^*(\boldsymbol\xi)",
        r"Substituting (1.2), (2.8) into the right side of (2.6) gives a function of $x = H_* \xi$, the "
        r"observation point; $\eta$ is the integration variable.",
        _check_2_10,
        "notation", concerns=Concern(("2.10",), ("smooth",), ("compressible",)), where="(2.10)",
    ),
    Erratum(
        "2.17", "exponent in the moment integral",
        r"\xi_j^{2j}", r"\xi_j^{\alpha_j}",
        r"Definition (2.15): the moment of order $\alpha$ has the weight $\xi_1^{\alpha_1} \xi_2^{\alpha_2}$; "
        r"with $\xi_j^{2j}$ every moment would be $\mu_{2,4}$.",
        _check_2_17,
        "notation", concerns=Concern(("2.17", "2.19", "2.21"), layers=("compressible",)), where="(2.17)",
    ),
    Erratum(
        "2.21", "even kernel moments",
        r"(-1)^n \pi^2 \mathcal{A} m_n C_n^k 2^n k! (n-k)!",
        r"(-1)^n \pi^2 \mathcal{A} m_n C_n^k (2k)! (2n-2k)!",
        r"The coefficient of $s_1^{2k} s_2^{2n-2k}$ in $(s_1^2 + s_2^2)^n$ is $C_n^k$, and its derivative "
        r"$\partial^{2k}_{s_1} \partial^{2n-2k}_{s_2}$ at 0 is $(2k)!\,(2n-2k)!$. Checked against (2.19) "
        r"evaluated with sympy's own series of $\mathcal{L}(s)/s$, and numerically by quadrature of $k(\xi)$. "
        r"Only the derived form gives $\mu_\alpha/\alpha! = (-1)^n \pi^2 \mathcal{A} m_n C_n^k$, the weight "
        r"printed in (2.22). The two agree for $n \le 1$ and for $n = 2$, $k = 1$, so the misprint is visible "
        r"first in $\mu_{4,0}$.",
        _check_2_21, concerns=Concern(("2.21",), layers=("compressible",)), where="(2.21)",
    ),
    Erratum(
        "2.30", r"sign of the first correction $p_1^*$",
        r"p_1^* = \frac{\vartheta m_1 H_*}{\mathcal{A}}\left(\frac{1}{R_1^*}+\frac{1}{R_2^*}\right)",
        r"p_1^* = -\frac{\vartheta m_1 H_*}{\mathcal{A}}\left(\frac{1}{R_1^*}+\frac{1}{R_2^*}\right)",
        r"(2.28) with $k = 1$ gives $p_1^* = m_1 \Delta p_0^*$ and $\Delta p_0^* = -\vartheta H_* "
        r"(1/R_1^* + 1/R_2^*)/\mathcal{A}$. Substituting $p_0^* + \Lambda^{-2} p_1^*$ back into (2.24) leaves no "
        r"residual of order $\Lambda^{-4}$ with the derived sign and a non-zero one with the printed sign; the "
        r"moment expansion itself is checked numerically, and the sign of the resulting force correction "
        r"against a direct numerical solution of the contact problem.",
        _check_2_30, concerns=Concern(("2.26", "2.30", "4.1"), ("smooth",), ("compressible",)), where="(2.30)",
    ),
    Erratum(
        "2.31", "sign of the correction term of the inner pressure",
        r"+\frac{2 m_1 H_*^2}{\Lambda^2 R^*}", r"-\frac{2 m_1 H_*^2}{\Lambda^2 R^*}",
        r"Follows from the corrected (2.30): $p^* = p_0^* + \Lambda^{-2} p_1^*$.",
        _check_2_31, concerns=Concern(("2.26", "2.31"), ("elliptic paraboloid", "sphere"), ("compressible",)),
        where="(2.31)",
    ),
    Erratum(
        "3.1", "semi-axis of the leading contact ellipse in scaled variables",
        r"\alpha^* = \frac{1}{H^*}\sqrt{2\delta_0^* R_1}", r"\alpha^* = \frac{1}{H_*}\sqrt{2\delta_0^* R_1^*}",
        r"Solving $\Phi^*(\xi_1, 0) = \delta_0^*$ with (2.13); with $R_1 = R_1^*/\varepsilon$ (1.2) the printed "
        r"form is off by $\varepsilon^{-1/2}$. (The dimensional semi-axis is $\sqrt{2 \delta_0 R_1}$.)",
        _check_3_1, concerns=Concern(("3.1",), ("elliptic paraboloid",)), where="(3.1)",
    ),
    Erratum(
        "3.21", r"$m_1$ through the second derivative of $\mathcal{L}$",
        r"m_1 = \frac{1}{2\mathcal{A}} \lim_{s\to 0} \frac{\mathcal{L}''(s)}{s}",
        r"m_1 = \frac{1}{6\mathcal{A}} \lim_{s\to 0} \frac{\mathcal{L}''(s)}{s}",
        r"Ambiguous: read literally, $\lim \mathcal{L}''(s)/s = 6 \mathcal{A} m_1$ (as $\mathcal{L}(s) = "
        r"\mathcal{A} s + \mathcal{A} m_1 s^3 + \dots$), so the printed factor $1/(2\mathcal{A})$ would give "
        r"$3 m_1$; read as the second derivative of $\mathcal{L}(s)/s$ at 0 it is right. thinlayer uses (2.20) "
        r"directly. Both readings checked with sympy's limit at $\nu = 3/10$.",
        _check_3_21_m1,
        "ambiguous", concerns=Concern(("3.21",), layers=("compressible",)), where="(3.21)", cites=("alexandrov",),
    ),
    Erratum(
        "3.21", r"Alexandrov's second condition on $B$ and $C$",
        r"\frac{1}{C} - \frac{1}{2B^2} = -2 m_1", r"\frac{1}{C} - \frac{1}{2B^2} = -m_1",
        r"With $B = \mathcal{A} C$ (3.20), $\sqrt{s^2 + B^2}/(s^2 + C) = \mathcal{A}\left(1 + "
        r"\left(\frac{1}{2B^2} - \frac{1}{C}\right) s^2 + \dots\right)$, so matching the $s^2$ term of (2.20) "
        r"gives $\frac{1}{2B^2} - \frac{1}{C} = m_1$.",
        _check_3_21_alexandrov, concerns=Concern(("3.21",), layers=("compressible",)), where="(3.21)",
        cites=("alexandrov",),
    ),
    Erratum(  # noqa: E501 (one formula or one table row)
        "4.1", r"undefined symbol $f^*$",
        r"p_k^* = \frac{(-1)^k}{\pi^2\mathcal{A}} M_k \Delta^k f^*", r"p_k^* = \frac{(-1)^k}{\pi^2\mathcal{A}} M_k \Delta^k \varphi^*",  # noqa: E501 (one formula or one table row)
        r"$f^*$ is not defined; with $\varphi^*$ of (2.25) the closed form equals the recursion (2.27)--(2.28) "
        r"term by term (symbolic check on a non-symmetric quartic punch).",
        _check_4_1,
        "notation", concerns=Concern(("4.1",), layers=("compressible",)), where="(4.1)",
    ),
) + PUBLISHED_ENTRIES


def get(equation: str) -> tuple[Erratum, ...]:
    """All entries for an equation number such as ``"2.21"`` (empty tuple if the print is right)."""
    eq = equation.strip("() ")
    return tuple(e for e in ENTRIES if e.equation == eq)


def equations() -> tuple[str, ...]:
    """Equation numbers with at least one erratum, in paper order."""
    seen: list[str] = []
    for e in ENTRIES:
        if e.equation not in seen:
            seen.append(e.equation)
    return tuple(seen)


def latex_table() -> str:
    """The registry as a LaTeX ``longtable`` body for the report."""
    rows = [rf"({e.equation}) & {e.kind}: {e.quantity} & ${e.printed}$ & ${e.derived}$ \\" for e in ENTRIES]
    return "\n".join(rows)


def select(equations: Iterable[str], punches: Iterable[str], layers: Iterable[str]) -> tuple[Erratum, ...]:
    """The entries a report carries that uses ``equations`` for ``punches`` on ``layers`` (:meth:`Concern.selects`).

    >>> [e.equation for e in select(["3.1"], ["smooth", "elliptic paraboloid"], ["compressible"])]
    ['3.1']
    >>> select(["2.21"], ["flat"], ["incompressible"])
    ()
    """
    eqs, pun, lay = tuple(equations), tuple(punches), tuple(layers)
    return tuple(e for e in ENTRIES if e.concerns.selects(eqs, pun, lay))

