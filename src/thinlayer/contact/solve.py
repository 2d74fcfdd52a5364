r"""The front door: force, contact size and pressure of a rigid punch on a layer, by the model that holds.

:func:`solve` answers a user's question ("sphere R = 10 on a layer H = 0.5, E = 2, nu = 0.45, pressed
d = 0.1: force, contact radius, pressure?") for a layer bonded to a rigid base with
``-1 < nu <= 1/2`` or lying on a frictionless base, any thickness and any smooth polynomial punch.
It tries the thin-layer models in this order and keeps the first whose error estimate is within ``tol``:

``"compressible"``
    the paper's expansion (2.22)-(3.25): force (1.8) with its first correction, contact area with the
    exact edge shift h^* (3.25), composite pressure (:func:`thinlayer.asymptotics.solution.compressible_solution`).
    Estimate: :func:`thinlayer.asymptotics.force_law.error_estimate` (powers of
    ``kappa^2 = |P1/P0| + (1 + h^*^2)(H/a)^2``); it grows like ``m_1 ~ 1/(3(1 - 2 nu))`` near nu = 1/2.
``"two-term"``
    the sphere in the two-term model (I.10)-(I.12), ``1/4 < nu < 1/2`` (bonded base).
``"incompressible"``
    nu = 1/2 (bonded base): the model (I.3)-(I.4) for the sphere (I.11), the elliptic paraboloid (I.6)-(I.8)
    and any axisymmetric polynomial punch (I.9).

Both nearly-incompressible models neglect the edge layer of width ``H`` (I.12): the true contact edge
lies ``h H`` inside the model's (``h`` from :func:`two_term_edge_shift`, 1.459 at nu = 1/2), which
changes the force at relative order ``h H/c``.  Their estimates are ``2 h H/c`` for the force and the
area (the factor 2 covers the unknown order-one constant of that term) and ``2 (h H/c)^2`` for the
corrected radius ``c - h H``; the acceptance tests check them against the direct solver.

Where no thin-layer model holds, ``model="auto"`` tries for an axisymmetric punch ``"any-thickness"``
(:mod:`thinlayer.contact.any_thickness`): the sphere at any ``H/a`` by the law (T.7) (thick-layer series,
a table of direct solutions shipped with the package, thin-layer asymptotics; estimate <= 2.1e-4, the
pressure from the direct solver on first use), another axisymmetric punch by the thick-layer series (T.5)
where its estimate (T.8) is within ``tol``.  Where that does not hold either, it solves the problem
directly (``"direct"``): the axisymmetric
spectral solver (:func:`thinlayer.numerics.solve_axisymmetric`, its estimate from a run with 0.7 times the
modes) for an axisymmetric punch, otherwise the 2D FFT solver (:func:`thinlayer.numerics.solve_2d`, its
estimate the change from a grid of half the cells: an upper bound for a method converging at least
linearly in the cell size).  ``model="asymptotic"`` refuses instead, naming each model and why it fails.
"""
from __future__ import annotations

import dataclasses
import math
import numbers
from typing import Any

from .._checks import InputError, InputTypeError, check_choice, parse_nu, positive
from .._lazy import loaded_types
from ..asymptotics.solution import DEFAULT_TOL, numeric_punch
from ..errors import boundary
from ..layers.kernels import LayerKernel
from ..punch import Tip, is_polynomial_tip
from .guards import half_space, regime_flags, substrate_flags
from .indentation import DirectComparison, Indentation
from .indentation import tex_num as _tex_num  # noqa: F401 - the name tests and older callers import from here
from .models import MODEL_REGISTRY, model_names, walk
from .models.direct import MAX_CELLS_2D  # noqa: F401 - kept importable from here
from .problem import ELASTIC_HINT, Adhesive, Depth, Elastic, Force, Frictionless, History, Problem, Viscoelastic

__all__ = ["Indentation", "DirectComparison", "MODELS", "solve", "ELASTIC_HINT"]

#: the values of ``model`` (the registry's public names when this module was imported; solve() asks it afresh)
MODELS = model_names()


# =============================================================================================
# the front door
# =============================================================================================
@boundary
def solve(layer: LayerKernel, punch: Any, delta0: Any = None, H: Any = None, mu: Any = None, *, E: Any = None,
          force: Any = None, nu: Any = None, model: str = "auto", tol: Any = DEFAULT_TOL,
          parameters: dict | None = None, n: int | None = None, work_of_adhesion: Any = None,
          branch: str = "stable", material: Any = None, history: Any = None, control: str = "depth",
          substrate_E: Any = None, substrate_nu: Any = 0.0, **options: Any) -> Indentation:
    r"""Force, contact size and pressure of a rigid punch pressed into a layer, by the model that holds.

    Parameters
    ----------
    layer : LayerKernel
        ``BondedLayer(nu)`` with ``-1 < nu <= 1/2`` (``BondedLayer(0.5)`` is the incompressible layer) or
        ``FrictionlessLayer(nu)`` (a frictionless base).
    punch : Punch or str
        Any smooth polynomial punch with numeric coefficients (or ``parameters`` giving them).
    delta0, force : Any
        Exactly one: the indentation depth, or the total force (the depth is then found).
    H : Any
        Layer thickness; ``None`` or ``inf``: the half-space (Hertz, the paraboloid:
        :mod:`thinlayer.contact.half_space`).
    mu, E : Any
        Exactly one: the shear modulus, or Young's modulus ``E = 2 mu (1 + nu)``.
    nu : Any
        The Poisson ratio, when the layer was built without one (``FrictionlessLayer()``).
    model : str
        ``"auto"`` (default: the first asymptotic model within ``tol``, then the any-thickness law, else the
        direct solver),
        ``"asymptotic"`` (the same but refuse instead of the direct solver), or one model:
        ``"compressible"``, ``"two-term"``, ``"incompressible"``, ``"any-thickness"``, ``"direct"``.
    tol : Any
        Largest accepted relative error estimate (default 0.05).
    parameters : dict, optional
        Values of the punch's parameters.
    n : int, optional
        Modes (axisymmetric) or cells per side (2D) of the direct solver.
    work_of_adhesion : Any, optional
        ``w >= 0``: JKR adhesion (:mod:`thinlayer.contact.adhesion`); the paraboloid of revolution, the flat
        punch or the elliptic paraboloid (:mod:`thinlayer.contact.models.adhesion_elliptic`); ``delta0`` and ``force``
        may then be negative (force: compressive positive).  The answer is an
        :class:`~thinlayer.contact.adhesion.AdhesiveIndentation` (``force`` a magnitude, ``tensile``, ``branch``,
        ``pull_off``); models ``"thin-layer-jkr"`` (J.11)/(J.15), (J.30)/(J.31) and ``"direct"`` (J.1)-(J.6), (J.13),
        (D.12).
    branch : str
        With adhesion: ``"stable"`` (default) or ``"unstable"`` state of the JKR curve.
    material, history, control
        A viscoelastic layer (issue 27): ``material`` a :class:`~thinlayer.contact.materials.Prony`,
        ``StandardLinearSolid``, ``KelvinVoigt`` or ``PowerLaw`` (Young's ``E(t)``, ``nu`` constant) instead of
        ``mu``/``E``, and ``history=(times, values)`` instead of ``delta0``/``force``: depths (``control="depth"``)
        or forces (``control="force"``).  The answer is a
        :class:`~thinlayer.contact.hereditary.ViscoelasticForce` (force, depth and contact radius against time,
        ``valid`` and ``reason``) from the registry's viscoelastic row (:mod:`thinlayer.contact.models.viscoelastic`);
        ``model`` then names the elastic law at unit modulus (``"auto"``: the first valid over the history).
    substrate_E, substrate_nu : float, optional
        Young's modulus (same units as ``E``) and Poisson ratio (default 0: the largest estimate) of the substrate
        under the layer: every law takes the base as rigid, and the answer carries a flag when the substrate's
        compliance would change the force by more than 1 % (first order, ``kappa(a/H) E*_layer/E*_substrate``:
        :func:`thinlayer.contact.guards.substrate_flags`).
    options
        For the compressible model: ``order``, ``terms``, ``boundary_layer``
        (:func:`thinlayer.asymptotics.solution.compressible_solution`).

    Returns
    -------
    Indentation
        ``force``, ``contact_area``, ``contact_radius`` (axisymmetric), ``semi_axes`` (ellipses),
        ``pressure(x1, x2)``, ``max_pressure``, ``model``, ``reason``, ``error_estimate``,
        ``compare_direct()``, ``flags`` (``delta0/H`` beyond small strain, ``delta0/R`` where the paraboloid departs
        from a sphere: :mod:`thinlayer.contact.guards`).

    Raises
    ------
    ValidityError
        With ``model="asymptotic"`` or a named model whose estimate exceeds ``tol``; the one-line message
        names each model tried and its estimate.

    Examples
    --------
    The sphere on a thin layer: the leading force ``P0 = pi vartheta R delta0^2/(A H)`` (1.8),
    ``A = (1/2 - nu)/(1 - nu)^2``, ``vartheta = mu/(1 - nu)``, ``mu = E/(2(1 + nu))``; its first correction
    ``-2 m_1 H^2/(R delta0)``, ``m_1 = 1/14``; the contact radius ``sqrt(2 R delta0) - h^* H`` (3.25):

    >>> import math
    >>> from thinlayer import BondedLayer, Punch, solve
    >>> ans = solve(BondedLayer(0.3), Punch.paraboloid(10), delta0=0.1, H=0.05, E=2.6)
    >>> P0 = math.pi * (1.0 / 0.7) * 10 * 0.1**2 / (0.2 / 0.49 * 0.05)
    >>> ans.model, round(ans.force / P0 - 1, 6), round(-2 / 14 * 0.05**2 / (10 * 0.1), 6)
    ('compressible', -0.000357, -0.000357)
    >>> round((math.sqrt(2) - ans.contact_radius) / 0.05, 2)     # h*(0.3) = 0.1221 (Wiener-Hopf), + O(H)
    0.12
    >>> ans = solve(BondedLayer(0.49), Punch.paraboloid(10), delta0=0.1, H=0.5, E=2.0)
    >>> ans.model, ans.error_estimate["force"] < 1e-4       # no asymptotic model holds at H/a = 0.35
    ('any-thickness', True)
    >>> ans = solve(BondedLayer(0.49), Punch.paraboloid(10), delta0=0.1, H=0.5, E=2.0, model="direct")
    >>> ans.error_estimate["force"] < 1e-6
    True
    """
    layer, nu_v = _check_model_layer(layer, nu)
    if substrate_E is not None and (material is not None or history is not None or work_of_adhesion is not None):
        raise InputTypeError("solve(): substrate_E is checked for the elastic, non-adhesive answers only; leave it "
                             "out with material=/history= or work_of_adhesion=")
    if material is not None or history is not None:
        given = [k for k, v in (("delta0", delta0), ("force", force), ("mu", mu), ("E", E),
                                ("work_of_adhesion", work_of_adhesion), ("n", n)) if v is not None]
        extra = ", ".join(given + sorted(options) + (["parameters"] if parameters else []))
        if extra:
            raise InputTypeError(f"solve(material=..., history=...) takes the modulus from the material and the "
                                 f"loading from the history: leave out {extra}")
        return walk(_viscoelastic_problem(layer, punch, H, nu_v, material, history, control, model, tol), "auto")
    material = Elastic.from_moduli(mu, E, nu_v)
    adhesive = work_of_adhesion is not None
    choice = check_choice(model, adhesive_model_names() if adhesive else model_names(), "model")
    HH = math.inf if half_space(H) else positive(H, "H")
    if adhesive and math.isinf(HH):
        raise InputError("solve(work_of_adhesion=...) answers for a layer of finite thickness H; the half-space "
                         "JKR law is thinlayer.asymptotics.adhesion.half_space_jkr()")
    tol_v = _tol(tol)
    if (delta0 is None) == (force is None):
        raise InputTypeError("give exactly one of delta0 (indentation) and force (the inverse problem)")
    if adhesive:
        interaction: Any = Adhesive(non_negative(work_of_adhesion, "work_of_adhesion"),
                                    check_choice(branch, ("stable", "unstable"), "branch"))
        loading = Depth(finite(delta0, "delta0")) if delta0 is not None else Force(finite(force, "force"))
    else:
        interaction = Frictionless()
        loading = Depth(positive(delta0, "delta0")) if delta0 is not None else Force(positive(force, "force"))
    if isinstance(punch, Tip) and not is_polynomial_tip(punch):  # flat punch, tips of revolution: no options
        if options:
            raise InputTypeError(f"the {punch.name} takes no model options, got {sorted(options)}")
        if parameters and not punch.parameters:
            raise InputTypeError(f"the {punch.name} takes no parameters (its sizes are numbers), got "
                                 f"{sorted(map(str, parameters))}")
        tip = punch.subs(parameters) if parameters else punch
        if not tip.is_numeric:
            names = ", ".join(q.name for q in tip.parameters)
            raise InputError(f"the {tip.name} has free parameter(s) {names}: give them in parameters={{...}}")
    else:
        tip = numeric_punch(punch, parameters)
    if layer.numeric_nu is None or layer.incompressible_at(nu_v):  # a frictionless base's nu; bonded at nu = 1/2
        layer = layer.with_nu(nu_v)
    if adhesive:  # JKR: the adhesive rows of the registry (the regime flags are for the non-adhesive laws)
        return walk(Problem(layer, tip, material, interaction, loading, HH, tol_v, n, dict(options)), choice)
    if math.isinf(HH):
        from .half_space import half_space_answer

        ans = half_space_answer(layer, tip, getattr(loading, "delta0", None), getattr(loading, "force", None),
                                material.mu, nu_v, tol_v)
    else:
        ans = walk(Problem(layer, tip, material, Frictionless(), loading, HH, tol_v, n, dict(options)), choice)
    flags = regime_flags(ans.delta0, HH, getattr(tip, "sphere_radius", None))
    if substrate_E is not None:  # a: the contact radius, or the equal-area radius of a contact that is not a disc
        a = ans.contact_radius if ans.contact_radius is not None else math.sqrt(ans.contact_area / math.pi)
        flags += substrate_flags(layer, a / HH if math.isfinite(HH) else 0.0, material.E, substrate_E, substrate_nu)
    return dataclasses.replace(ans, flags=flags) if flags else ans


def _viscoelastic_problem(layer: LayerKernel, punch: Any, H: Any, nu: float, material: Any, history: Any,
                          control: Any, model: Any, tol: Any) -> Problem:
    """The viscoelastic problem of ``solve(material=..., history=(times, values), control=...)``."""
    if material is None or history is None:
        raise InputTypeError("solve(): a viscoelastic answer needs both material=Prony(...)|PowerLaw(...)|... and "
                             "history=(times, depths) (or forces with control='force')")
    if isinstance(history, (str, bytes)) or not isinstance(history, (tuple, list)) or len(history) != 2:
        raise InputTypeError(f"history must be a pair (times, values), got {type(history).__name__}")
    kind = check_choice(control, ("depth", "force"), "control")
    if half_space(H):
        raise InputError("solve(material=...) answers for a layer of finite thickness H")
    if not isinstance(model, str):
        raise InputError(f"model must be a string naming the elastic law (or 'auto'), got {model!r}")
    tip = punch if isinstance(punch, Tip) and not is_polynomial_tip(punch) else numeric_punch(punch, {})
    if layer.numeric_nu is None or layer.incompressible_at(nu):
        layer = layer.with_nu(nu)
    return Problem(layer, tip, Viscoelastic(material, nu, law=model), Frictionless(), History(*history, kind),
                   positive(H, "H"), _tol(tol))


def _check_model_layer(layer: Any, nu: Any) -> tuple[LayerKernel, float]:
    if not isinstance(layer, LayerKernel):
        raise InputTypeError(f"layer must be a thinlayer layer, e.g. BondedLayer(0.3) or FrictionlessLayer(0.3); "
                        f"got {layer!r}")
    if not layer.on_rigid_base or not layer.has_thickness or layer.symbolic_coefficients:
        raise InputTypeError(f"solve() answers for a layer on a rigid base: BondedLayer(nu) (-1 < nu <= 1/2) or "
                        f"FrictionlessLayer(nu); got {layer!r}")
    if layer.parameter is not None:
        raise InputError("solve() needs a numeric Poisson ratio: BondedLayer(0.3) or BondedLayer('3/10'), "
                         "not the symbolic BondedLayer()")
    given = layer.poisson_ratio(nu)
    nv = parse_nu(given, floats="float", upper_closed=True, symbols=False, example="0.3, '3/10' or 0.5")
    return layer, float(nv)


def adhesive_model_names() -> tuple[str, ...]:
    """``solve(work_of_adhesion=...)``'s choices of ``model``."""
    return ("auto", "asymptotic", *dict.fromkeys(m.name for m in MODEL_REGISTRY if m.adhesive and m.solves))


def finite(value: Any, name: str) -> float:
    """A finite real number (either sign), as a float; one-line refusal naming the input."""
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, *loaded_types("sympy", "Number"))):
        raise InputError(f"{name} must be a finite real number, got {value!r}")
    v = float(value)
    if not math.isfinite(v):
        raise InputError(f"{name} must be a finite real number, got {value!r}")
    return v


def non_negative(value: Any, name: str) -> float:
    """A finite number ``>= 0``."""
    v = finite(value, name)
    if v < 0:
        raise InputError(f"{name} must be a finite number >= 0, got {value!r}")
    return v


def _tol(tol: Any) -> float:
    if isinstance(tol, bool) or not isinstance(tol, (numbers.Real, *loaded_types("sympy", "Number"))) \
            or not float(tol) > 0:
        raise InputError(f"tol must be a positive number (the largest accepted relative error estimate, "
                         f"e.g. 0.05; math.inf accepts any), got {tol!r}")
    return float(tol)
