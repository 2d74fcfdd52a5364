r"""The incompressible bonded layer (nu = 1/2) and nearly incompressible layers.

At ``nu = 1/2`` the bonded-layer kernel (2.3) has ``kappa = 1`` and ``A = 0`` (2.4): the leading
term of the inner problem (2.27) is no longer algebraic.  This module derives the thin-layer
model from the same moment expansion (2.14)-(2.23), solves it, and joins it to the compressible
expansion of the paper.  Equations that the paper does not have carry tags ``I.n``.

Kernel and operator (I.1), (I.2)
--------------------------------
With ``kappa = 1`` the Maclaurin data of ``L(s)/s`` (power-series arithmetic on sinh, cosh, as in
:mod:`thinlayer.layers.coefficients`) start one order later::

    L(s)/s = c_1 s^2 + c_2 s^4 + ...,   c_0 = A = 0,   c_1 = 2/3,   c_2 = -6/5, ...      (I.1)

The moment expansion (2.22) with weights ``(-1)^n pi^2 c_n`` (in the compressible case
``c_n = A m_n``) acts on a smooth density as the operator series (2.23); written in dimensional
variables (``Lambda^{-2} Delta_xi = H^2 Delta_x``) the surface displacement is::

    u_3 = (H/vartheta) sum_n (-1)^n c_n H^{2n} Delta^n p,   vartheta = mu/(1 - nu).       (I.2)

At ``nu = 1/2`` (``vartheta = 2 mu``) the leading term is ``u_3 = -(H^3/(3 mu)) Delta p``: the
classical thin incompressible layer (Jaffar; Barber), here obtained from the kernel.

The free-boundary problem (I.3), (I.4)
--------------------------------------
The unilateral conditions (1.5) with the leading operator become: ``p >= 0``,
``-(c_1 H^3/vartheta) Delta p >= delta0 - Phi``, with equality where ``p > 0``.  Dividing by
``c_1 H^3/vartheta``::

    -Delta p = f  in omega,   f = (vartheta/(c_1 H^3)) (delta0 - Phi) = (3 mu/H^3)(delta0 - Phi),   (I.3)
    p = 0,  dp/dn = 0  on the contour of omega.                                               (I.4)

Two conditions on the unknown contour: extended by zero, ``p`` has the distributional Laplacian
``Delta p 1_omega - (dp/dn) delta_Gamma``; a non-zero normal derivative would put a line load of
*displacement* on the contour, which is not a function, so ``dp/dn = 0``.  Equivalently (I.3)-(I.4)
is the obstacle problem ``min int (|grad p|^2/2 - f p) dx`` over ``p >= 0``, whose solution is
``C^{1,1}``.  Integrating ``-Delta p = f`` against any harmonic ``v`` (Green's formula, both
boundary terms vanish by (I.4)) gives the *quadrature-domain identities*::

    int_omega f v dx = 0   (v harmonic),   in particular   int_omega (delta0 - Phi) dx = 0,   (I.5)

(the penetrated volume is pushed up inside the contact: incompressibility), and, with ``v = |x|^2``
(``Delta v = 4``), the force ``P = -(1/4) int_omega f |x|^2 dx``.

Elliptic paraboloid (I.6)-(I.8)
-------------------------------
``p = C (1 - x1^2/a^2 - x2^2/b^2)^2`` satisfies (I.4) identically and (I.3) when three polynomial
coefficients match.  Eliminating ``C`` and ``a`` leaves, for the aspect ratio ``t = a^2/b^2`` and
``r = R1/R2``::

    3 t^2 + (1 - r) t - 3 r = 0,   t = (r - 1 + sqrt(r^2 + 34 r + 1))/6                       (I.6)

(the product of the roots is ``-r < 0``: exactly one positive root).  ``t = 1`` for ``r = 1``,
``t ~ r/3`` for ``r -> oo`` and ``t ~ 3r`` for ``r -> 0``: the incompressible contact ellipse is
rounder than the compressible one, ``b^2/a^2 = R2/R1`` (3.1).  Then::

    a^2 = 2 R1 delta0 (3 + t)/(1 + t),  b^2 = 2 R2 delta0 (3 t + 1)/(1 + t),
    C = 3 mu R1 delta0^2 (3 + t)/(2 H^3 (1 + t)^2),                                          (I.7)
    P = pi a b C/3 = pi mu R1^2 delta0^3 (3 + t)^2 / (H^3 (1 + t)^3 sqrt(t)),                (I.8)

and for the sphere ``a^2 = 4 R delta0``, ``P = 2 pi mu R^2 delta0^3/H^3``.  The relation (I.6)
also follows, independently of the ansatz, from the harmonic moments (I.5) with ``v = 1`` and
``v = x1^2 - x2^2`` (tested).

Axisymmetric punches (I.9)
--------------------------
For ``Phi = Phi(r)`` the radial form of (I.3) integrates twice: ``p'(r) = -(1/r) int_0^r f s ds``,
so (I.4) gives the radius from ``int_0^c (delta0 - Phi) r dr = 0`` and
``p(r) = int_r^c (1/rho) int_0^rho f s ds d rho``.

Nearly incompressible layers: the two-term model (I.10)-(I.13)
--------------------------------------------------------------
The compressible expansion (2.26)-(2.31) is a series in ``m_1 (H/a)^2``, and
``m_1 = nu (4 nu - 1)/(3 (1 - 2 nu)(1 - nu)) ~ 1/(3 (1 - 2 nu))`` blows up as ``nu -> 1/2``
(the inner correction (2.30) of the sphere's force, ``-2 m_1 H^2/(R delta0)``, exceeds 1 at
``nu = 0.499``, ``a/H = 20``).  Keeping *both* ``c_0 = A`` and ``c_1 = A m_1`` in (I.2)::

    (H/vartheta)(A p - A m_1 H^2 Delta p) = delta0 - Phi  in omega,  p = dp/dn = 0  on its contour,   (I.10)

i.e. ``-Delta p + k^2 p = f`` with ``k^2 = 1/(m_1 H^2)`` and ``f = vartheta (delta0 - Phi)/(A m_1 H^3)``,
an obstacle problem again (``m_1 > 0`` needs ``1/4 < nu <= 1/2``).  Both limits are contained:
for ``k a >> 1`` its inner solution is ``(vartheta/(A H))(delta0 - Phi - m_1 H^2 Delta Phi)`` (2.26), (4.1)
and its edge layer, ``q = g (v + l e^{-(v + l)/l})`` with ``l = sqrt(m_1)``, has the force defect
``l^2/2 = m_1/2`` -- the same as the Wiener--Hopf boundary layer (see :mod:`thinlayer.asymptotics.force_law`), so
the force is right to first order; for ``k a << 1`` it is (I.3).  The ratio of the two terms is

    lambda^2 = (a/H)^2 / m_1  ~  3 (1 - 2 nu) (a/H)^2:                                      (I.13)

the compressible expansion holds for ``lambda^2 >> 1`` (``1 - 2 nu >> (H/a)^2/3``), the
incompressible model for ``lambda^2 << 1`` (its force is off by ``-(3/16) lambda^2`` for the sphere),
the two-term model everywhere (``nu > 1/4``).  See :func:`regime`.

For the sphere, ``p = (f0 - f2 r^2)/k^2 - 4 f2/k^4 + B I_0(k r)`` and (I.4) give, with ``x = k c``::

    delta0 = c^2 (1 - 2 psi(x))/(2 R),   P = 2 pi f2 c^6 chi(x),                             (I.11)
    psi(x) = (x I_0(x)/I_1(x) - 2)/x^2,   chi(x) = (1/4 - psi(x))/x^2,   f2 = vartheta/(2 R A m_1 H^3),

smooth at ``x = 0`` (``psi = 1/4 - x^2/96 + ...``, ``chi = 1/96 - ...``): one formula from the
compressible to the incompressible limit, evaluated without cancellation.

Edge correction (I.12).  The local models put the contact edge where the outer solution ends;
the true edge lies ``h(nu) H`` inside it, with the Wiener--Hopf factor ``K = F/(c_0 + c_1 s^2)``
(``F = L(s)/s``; ``K -> 1`` at ``s = 0``)::

    h(nu) = -(1/pi) int_0^oo log(F(t)/(c_0 + c_1 t^2)) t^{-2} dt,      h(1/2) = 1.4591...

With ``K = K_+ K_-`` and ``K_+(s) = 1 + K_1 s + ...``, the half-line problems of the true kernel and of
the model, driven by the same outer solution, have edges ``-i K_1`` apart (the argument of (3.25),
now relative to the model; the outer forcing -- linear in the compressible, constant in the
incompressible case -- does not enter).  For ``nu < 1/2``, ``h = h^*(nu) + sqrt(m_1)``: the paper's
edge shift plus the model's outward shift ``sqrt(m_1)`` (tested against
:func:`thinlayer.asymptotics.wiener_hopf.edge_shift_exact`).

Accuracy, measured against the direct solver (sphere, tests): at ``nu = 1/2`` the force of (I.8) is
low by ``~21 (H/a)^2`` (rate 1.93 between ``a/H = 20`` and 40) and ``(a - c)/H -> h(1/2)`` at rate ``H/a``;
the two-term force is within 2.5 % at ``a/H = 20`` for every ``0.45 <= nu <= 1/2`` (0.1 % at 0.45,
0.4 % at 0.49, 1.5 % at 0.499, 2.45 % at 1/2 where it is (I.8)) and its corrected radius within
0.5 %, where the compressible law fails by 249 % (nu = 0.499) and the
incompressible one by a factor 37 (nu = 0.45).

Numerics: :func:`thinlayer.numerics.obstacle.solve_obstacle_grid` solves (I.3)/(I.10) for any punch
on a grid (5-point Laplacian, primal-dual active-set iteration with sparse LU); the direct solver
:func:`thinlayer.numerics.solve_axisymmetric` accepts :class:`IncompressibleLayer` at ``nu = 1/2``;
:func:`thinlayer.validation.comparison.compare_sphere_models` sets the models side by side.

Modules
-------
* :mod:`.operator` -- (I.2) :func:`thin_layer_operator`; (I.3)-(I.5), (I.10) :func:`obstacle_problem`;
* :mod:`.leading` -- (I.6)-(I.8) :func:`incompressible_ellipse`, (I.9) :func:`incompressible_axisymmetric`;
* :mod:`.tips` -- (I.9a)-(I.9c) :func:`incompressible_tip` for tips of revolution (cone, exact sphere, ...);
* :mod:`.two_term` -- (I.10)-(I.12) :func:`two_term_sphere`, :func:`two_term_edge_shift`,
  :func:`two_term_edge_layer`;
* :mod:`.regime` -- (I.13) :func:`regime`.

The kernel :class:`IncompressibleLayer` and its coefficients (I.1) live in :mod:`thinlayer.layers`
and are re-exported here.  Every model takes the layer first (``BondedLayer(nu)``,
``IncompressibleLayer()``), as :func:`thinlayer.solve` does; a bare Poisson ratio still works for
one release, with a DeprecationWarning.
"""
from ...layers.coefficients import IncompressibleCoefficients, incompressible_coefficients
from ...layers.kernels import IncompressibleLayer
from .leading import (
    EllipseValues,
    IncompressibleEllipse,
    IncompressibleRadial,
    RadialValues,
    c_sym,
    incompressible_axisymmetric,
    incompressible_ellipse,
    r_sym,
    rho,
    t_sym,
)
from .operator import ObstacleProblem, ThinLayerOperator, obstacle_problem, p_fun, thin_layer_operator
from .regime import Regime, regime
from .tips import IncompressibleTip, TipValues, incompressible_tip
from .two_term import (
    SphereValues,
    TwoTermEdgeLayer,
    TwoTermSphere,
    k_sym,
    two_term_edge_layer,
    two_term_edge_shift,
    two_term_sphere,
)

__all__ = [
    "EllipseValues",
    "IncompressibleCoefficients",
    "IncompressibleEllipse",
    "IncompressibleLayer",
    "IncompressibleRadial",
    "IncompressibleTip",
    "ObstacleProblem",
    "RadialValues",
    "Regime",
    "SphereValues",
    "ThinLayerOperator",
    "TipValues",
    "TwoTermEdgeLayer",
    "TwoTermSphere",
    "c_sym",
    "incompressible_axisymmetric",
    "incompressible_coefficients",
    "incompressible_ellipse",
    "incompressible_tip",
    "k_sym",
    "obstacle_problem",
    "p_fun",
    "r_sym",
    "regime",
    "rho",
    "t_sym",
    "thin_layer_operator",
    "two_term_edge_layer",
    "two_term_edge_shift",
    "two_term_sphere",
]
