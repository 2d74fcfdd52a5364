"""Issue 23 item 1: no user value is ever evaluated, through any door.

:data:`INVENTORY` lists every public callable that takes a user value -- the names of ``thinlayer.__all__`` and the
other public names of ``thinlayer``, of ``thinlayer.numerics``, ``thinlayer.parse`` and ``thinlayer.errors``, the
stages the README presents by module, and the public methods of every class among them or returned by them (found
from the return annotations) -- with one call per argument position that takes a user value, the payload
string in that position.  A payload would create a marker file if it were evaluated as Python.  Every call must
leave no marker and end in a thinlayer ``ValueError``/``TypeError`` (a :class:`thinlayer.errors.ThinlayerError`)
with a one-line message, or return (a string read legitimately, e.g. a label).

:func:`test_inventory_is_complete` walks the same public surface and fails when a callable is neither in
:data:`INVENTORY` nor in :data:`NO_USER_VALUES` (each entry with the reason it takes no user value), so that a
new door without a check fails the suite.
"""
from __future__ import annotations

import importlib
import inspect
import typing
from functools import cache
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import thinlayer as tl
import thinlayer.numerics as N
import thinlayer.parse as PA
from thinlayer.asymptotics import second_order as SO
from thinlayer.asymptotics import solution as SOL
from thinlayer.errors import ThinlayerError

#: one worker builds F() once for the 240 door tests (it costs ~8 s), not once per worker
pytestmark = pytest.mark.xdist_group("doors")

#: strings that run code if anything evaluates them; {m} is the marker file
PAYLOADS = ("__import__('os').system('touch {m}') or 1",
            "x_1**2 + x_2**2 + 0*__import__('os').system('touch {m}')")

AFM_FILE = Path(__file__).resolve().parent / "afm" / "data" / "fmt-jpk-fd_spot3-0192.jpk-force"  # a real curve
_curve = lambda: __import__("thinlayer.afm.curves").afm.curves.curve_from_arrays(np.arange(9.0), [0, 0, 0, 0, 1, 2.8, 5.2, 8, 11.2])  # noqa: E501,E731
#: the stages the README (and the issue) present by their module, beyond the names of thinlayer
PRESENTED = (("thinlayer.asymptotics.second_order", "edge_constants"),
             ("thinlayer.asymptotics.second_order", "second_order_law"),
             ("thinlayer.asymptotics.solution", "numeric_punch"),
             ("thinlayer.asymptotics.solution", "compressible_solution"))


# ---------------------------------------------------------------------------------------------------------------
# the public surface
# ---------------------------------------------------------------------------------------------------------------
def _returned_classes(fn) -> list[type]:
    try:
        hints = typing.get_type_hints(inspect.unwrap(fn))
    except Exception:  # noqa: BLE001 - an annotation that does not resolve names no class
        return []
    r = hints.get("return")
    return [t for t in (r, *typing.get_args(r)) if inspect.isclass(t) and t.__module__.startswith("thinlayer")]


def public_surface() -> dict[str, object]:
    """``{name: callable}``: public functions and classes, and the public methods of those classes."""
    roots: list[tuple[str, object]] = [(f"thinlayer.{n}", getattr(tl, n)) for n in sorted(set(tl.__all__)
                                                                                         | set(tl._PUBLIC))]
    for modname in ("thinlayer.numerics", "thinlayer.parse", "thinlayer.errors"):
        mod = importlib.import_module(modname)
        roots += [(f"{modname}.{n}", getattr(mod, n)) for n in mod.__all__]
    roots += [(f"{m}.{n}", getattr(importlib.import_module(m), n)) for m, n in PRESENTED]
    out: dict[str, object] = {}
    seen: set[int] = set()
    todo = list(roots)
    while todo:
        key, obj = todo.pop(0)
        if inspect.ismodule(obj) or not callable(obj) or id(obj) in seen:
            continue
        if inspect.isclass(obj) and issubclass(obj, BaseException):
            continue
        seen.add(id(obj))
        out[key] = obj
        if inspect.isclass(obj):
            for name, st in inspect.getmembers_static(obj):
                if name.startswith("_") and name != "__call__":
                    continue
                fn = st.__func__ if isinstance(st, (staticmethod, classmethod)) else st
                if inspect.isfunction(fn):
                    out[f"{key}.{name}"] = fn
                    todo += [(f"{c.__module__}.{c.__qualname__}", c) for c in _returned_classes(fn)]
        else:
            todo += [(f"{c.__module__}.{c.__qualname__}", c) for c in _returned_classes(obj)]
    return out


# ---------------------------------------------------------------------------------------------------------------
# objects the calls need (built once, on first use)
# ---------------------------------------------------------------------------------------------------------------
@cache
def F():  # noqa: N802 - a namespace of fixtures
    from thinlayer.asymptotics.second_order import edge_constants, second_order_law
    from thinlayer.asymptotics.solution import compressible_solution
    from thinlayer.contact.any_thickness import any_thickness_law
    from thinlayer.layers.kernels import IncompressibleLayer
    from thinlayer.numerics import solve_obstacle_grid

    class NS:
        pass

    ns = NS()
    ns.L = tl.BondedLayer(0.3)
    ns.LI = IncompressibleLayer()
    ns.P = tl.Punch.paraboloid(10)
    ns.PE = tl.Punch.elliptic_paraboloid(4, 1)
    ns.ind = tl.solve(ns.L, ns.P, delta0=0.1, H=0.05, mu=1.0)
    ns.law = tl.force_law(ns.L, ns.P)
    ns.law_sym = tl.force_law(ns.L, tl.Punch.paraboloid())
    ns.law2 = second_order_law(ns.L, ns.P)
    ns.edge = edge_constants(ns.L)
    ns.sol = compressible_solution(ns.L, ns.P, delta0=0.1, H=0.05)
    ns.comp = ns.sol.composite
    ns.contour = tl.contact_contour("x_1**2 + 2*x_2**2 + x_1**4/10", 0.1)
    ns.ellipse = tl.ellipse_contour()
    ns.inner = tl.inner_pressure(ns.L, ns.P)
    ns.mexp = tl.moment_expansion(ns.L, 2)
    ns.alex = tl.alexandrov_solution(ns.L)
    ns.wh = tl.boundary_layer_exact("3/10")  # the shipped table: no factorisation to compute
    ns.op = tl.thin_layer_operator(ns.LI, 1)
    ns.obst = tl.obstacle_problem(ns.LI, ns.P)
    ns.two = tl.two_term_sphere(tl.BondedLayer(0.45))
    ns.reg = tl.regime(tl.BondedLayer(0.45), 0.1)
    ns.atl = any_thickness_law(0.5)
    d = np.linspace(0.05, 1.0, 8)
    ns.fitres = tl.fit(d, tl.force_any_thickness(d, 10.0, 2.0, E=3.0, nu=0.5), punch=10.0, H=2.0)
    ns.axi = tl.solve_axisymmetric(ns.L, ns.P, 0.1, 0.05)
    ns.c2d = tl.solve_2d(ns.L, ns.P, delta0=0.1, H=1.0, n=32)
    ns.grid = solve_obstacle_grid(ns.LI, ns.P, 0.1, 0.05, n=21)
    return ns


def _layers():
    from thinlayer.layers.kernels import IncompressibleLayer

    return {"BondedLayer": tl.BondedLayer(0.3), "FrictionlessLayer": tl.FrictionlessLayer(0.3),
            "HalfSpace": tl.HalfSpace(), "IncompressibleLayer": IncompressibleLayer(),
            "GenericLayer": tl.GenericLayer(), "LayerKernel": tl.BondedLayer("3/10")}


def _layer_doors() -> dict[str, list]:
    out = {}
    for cls, lay in _layers().items():
        k = f"thinlayer.{cls}"
        out[f"{k}.L"] = [lambda s, lay=lay: lay.L(s)]
        out[f"{k}.L_numeric"] = [lambda s, lay=lay: lay.L_numeric(s), lambda s, lay=lay: lay.L_numeric(0.5, backend=s),
                                 lambda s, lay=lay: lay.L_numeric(0.5, "mpmath", over_u=s)]
        out[f"{k}.M"] = [lambda s, lay=lay: lay.M(s)]
        out[f"{k}.m"] = [lambda s, lay=lay: lay.m(s)]
        out[f"{k}.coefficients"] = [lambda s, lay=lay: lay.coefficients(s)]
        out[f"{k}.taylor_coefficients"] = [lambda s, lay=lay: lay.taylor_coefficients(s)]
        out[f"{k}.moment"] = [lambda s, lay=lay: lay.moment(s, 0), lambda s, lay=lay: lay.moment(0, s)]
        out[f"{k}.poisson_ratio"] = [lambda s, lay=lay: lay.poisson_ratio(s)]
        out[f"{k}.series_parts"] = [lambda s, lay=lay: lay.series_parts(s, None),
                                    lambda s, lay=lay: lay.series_parts(1, s)]
        out[f"{k}.small_u"] = [lambda s, lay=lay: lay.small_u(s), lambda s, lay=lay: lay.small_u(2, s)]
        out[f"{k}.with_nu"] = [lambda s, lay=lay: lay.with_nu(s)]
        out[f"{k}.incompressible_at"] = [lambda s, lay=lay: lay.incompressible_at(s)]
        if hasattr(getattr(tl, cls), "large_u"):
            out[f"{k}.large_u"] = [lambda s, lay=lay: lay.large_u(s)]
    return out


#: every door that takes a user value: ``name -> [call(payload), ...]``, one call per argument position
def _material(name: str):
    return {"Prony": lambda: tl.Prony(1.0, [(1.0, 1.0)]), "KelvinVoigt": lambda: tl.KelvinVoigt(1.0, 1.0),
            "PowerLaw": lambda: tl.PowerLaw(1.0, 1.0, 0.5)}[name]()


INVENTORY: dict[str, list] = {
    **_layer_doors(),
    # viscoelastic materials and the Lee-Radok force history (issue 27)
    "thinlayer.Prony": [lambda s: tl.Prony(s), lambda s: tl.Prony(1.0, s), lambda s: tl.Prony(1.0, [(s, 1.0)]),
                        lambda s: tl.Prony(1.0, [(1.0, s)])],
    "thinlayer.StandardLinearSolid": [lambda s: tl.StandardLinearSolid(s, 1, 1),
                                      lambda s: tl.StandardLinearSolid(2, s, 1),
                                      lambda s: tl.StandardLinearSolid(2, 1, s)],
    "thinlayer.KelvinVoigt": [lambda s: tl.KelvinVoigt(s, 1), lambda s: tl.KelvinVoigt(1, s)],
    "thinlayer.PowerLaw": [lambda s: tl.PowerLaw(s, 1, 0.5), lambda s: tl.PowerLaw(1, s, 0.5),
                           lambda s: tl.PowerLaw(1, 1, s)],
    **{f"thinlayer.{c}.{m}": [lambda s, c=c, m=m: getattr(_material(c), m)(s)]
       for c in ("Prony", "KelvinVoigt", "PowerLaw") for m in ("relaxation", "complex_modulus")},
    "thinlayer.viscoelastic_force": [
        lambda s, k=k: tl.viscoelastic_force(**{**dict(layer=tl.BondedLayer(0.3), punch=tl.Punch.paraboloid(10),
                                                       H=1.0, material=tl.Prony(1.0), times=[0.0, 1.0],
                                                       depths=[0.0, 0.1]), k: s})
        for k in ("layer", "punch", "H", "material", "times", "depths", "nu", "tol", "model")],
    # force control, oscillation, fit (issue 27 item 4: viscodoor)
    "thinlayer.viscoelastic_depth": [lambda s, k=k: tl.viscoelastic_depth(**{**dict(layer=tl.BondedLayer(0.5), punch=tl.Punch.paraboloid(10), H=1.0, material=tl.Prony(1.0), times=[0.0, 1.0], forces=[0.0, 0.1]), k: s}) for k in ("layer", "punch", "H", "material", "times", "forces", "nu", "tol", "model")],  # noqa: E501
    "thinlayer.oscillation": [lambda s, k=k: tl.oscillation(**{**dict(layer=tl.BondedLayer(0.5), punch=tl.Punch.paraboloid(10), H=1.0, material=tl.Prony(1.0), delta0=0.1, omega=[1.0], amplitude=1e-3), k: s}) for k in ("layer", "punch", "H", "material", "delta0", "omega", "amplitude", "nu", "tol", "model")],  # noqa: E501
    "thinlayer.contact_stiffness": [lambda s, k=k: tl.contact_stiffness(**{**dict(layer=tl.BondedLayer(0.5), punch=tl.Punch.paraboloid(10), H=1.0, delta0=0.1), k: s}) for k in ("layer", "punch", "H", "delta0", "nu", "tol", "model")],  # noqa: E501
    "thinlayer.contact.oscillation.ContactStiffness.complex_modulus": [lambda s: tl.contact_stiffness(tl.BondedLayer(0.5), tl.Punch.paraboloid(10), 1.0, 0.1).complex_modulus(s)],  # noqa: E501
    "thinlayer.contact.oscillation.ContactStiffness.half_space_complex_modulus": [lambda s: tl.contact_stiffness(tl.BondedLayer(0.5), tl.Punch.paraboloid(10), 1.0, 0.1).half_space_complex_modulus(s)],  # noqa: E501
    "thinlayer.fit_viscoelastic": [lambda s, k=k: tl.fit_viscoelastic(tl.BondedLayer(0.5), tl.Punch.paraboloid(10), 1.0, **{**dict(curves=[([0.0, 1.0, 2.0], [0.0, 0.1, 0.1], [0.0, 1.0, 0.8])]), k: s}) for k in ("material", "curves", "oscillation", "delta0", "nu", "t0", "guess", "tol", "model", "fit_H", "contact_point")],  # noqa: E501
    # constructors of the layers and the punch
    "thinlayer.BondedLayer": [lambda s: tl.BondedLayer(s), lambda s: tl.BondedLayer(parameter=s),
                              lambda s: tl.BondedLayer(0.3, dps=s)],
    "thinlayer.FrictionlessLayer": [lambda s: tl.FrictionlessLayer(s)],
    "thinlayer.HalfSpace": [lambda s: tl.HalfSpace(s)],
    "thinlayer.IncompressibleLayer": [lambda s: tl.IncompressibleLayer(s)],
    "thinlayer.GenericLayer": [lambda s: tl.GenericLayer(s)],
    "thinlayer.GenericLayer.m_symbol": [lambda s: tl.GenericLayer.m_symbol(s)],
    "thinlayer.Punch": [lambda s: tl.Punch(s), lambda s: tl.Punch("x_1**2 + x_2**2", x1=s),
                        lambda s: tl.Punch("x_1**2 + x_2**2", x2=s),
                        lambda s: tl.Punch("x_1**2/R + x_2**2", scaling={s: 1}),
                        lambda s: tl.Punch("x_1**2/R + x_2**2", scaling={"R": s}),
                        lambda s: tl.Punch("x_1**2 + x_2**2", name=s)],  # a label: stored, never read
    "thinlayer.FlatPunch": [lambda s: tl.FlatPunch(s)],
    "thinlayer.Punch.elliptic_paraboloid": [lambda s: tl.Punch.elliptic_paraboloid(s),
                                            lambda s: tl.Punch.elliptic_paraboloid(1, s)],
    "thinlayer.Punch.paraboloid": [lambda s: tl.Punch.paraboloid(s)],
    "thinlayer.Punch.flat": [lambda s: tl.Punch.flat(s)],
    # the tips of revolution (issue 24): each argument read by the grammar or refused
    "thinlayer.Punch.cone": [lambda s: tl.Punch.cone(s)],
    "thinlayer.Punch.sphere": [lambda s: tl.Punch.sphere(s)],
    "thinlayer.Punch.blunted_cone": [lambda s: tl.Punch.blunted_cone(s, 70), lambda s: tl.Punch.blunted_cone(1, s)],
    "thinlayer.Punch.power_law": [lambda s: tl.Punch.power_law(s, 2), lambda s: tl.Punch.power_law(1, s)],
    "thinlayer.Punch.revolution": [lambda s: tl.Punch.revolution(s)],
    # the polyhedral tips (issue 24)
    "thinlayer.Punch.pyramid": [lambda s: tl.Punch.pyramid(s), lambda s: tl.Punch.pyramid(35, s)],
    "thinlayer.Punch.from_expr": [lambda s: tl.Punch.from_expr(s)],
    "thinlayer.Punch.fourth_degree": [lambda s: tl.Punch.fourth_degree(s), lambda s: tl.Punch.fourth_degree(1, s)],
    "thinlayer.Punch.general": [lambda s: tl.Punch.general(s), lambda s: tl.Punch.general(2, prefix=s)],
    "thinlayer.Punch.lambdify": [lambda s: F().P.lambdify(args=[s]), lambda s: F().P.lambdify(backend=s)],
    "thinlayer.Punch.laplacian": [lambda s: F().P.laplacian(s)],
    "thinlayer.Punch.scaled": [lambda s: tl.Punch.paraboloid().scaled(s), lambda s: F().P.scaled(v1=s),
                               lambda s: F().P.scaled(v2=s)],
    "thinlayer.Punch.subs": [lambda s: tl.Punch.paraboloid().subs({"R": s}),
        lambda s: tl.Punch.paraboloid().subs({s: 1}),
                             lambda s: tl.Punch.paraboloid().subs(s)],
    # the tip protocol (thinlayer.punch.Tip): every tip answers these
    **{f"{k}.{m}": [lambda s, t=t, m=m: getattr(t, m)(s)] for k, t in (
        ("thinlayer.Punch", tl.Punch.paraboloid(10)), ("thinlayer.FlatPunch", tl.FlatPunch(1)),
        ("thinlayer.punch.base.Tip", tl.Punch.paraboloid("3/2")))
        for m in ("level_set", "radial_profile", "radial_slope")},
    **{f"{k}.profile": [lambda s, t=t: t.profile(s, 0.0), lambda s, t=t: t.profile(0.0, s)] for k, t in (
        ("thinlayer.Punch", tl.Punch.paraboloid(10)), ("thinlayer.FlatPunch", tl.FlatPunch(1)),
        ("thinlayer.punch.base.Tip", tl.Punch.paraboloid("3/2")))},
    "thinlayer.FlatPunch.subs": [lambda s: tl.FlatPunch(1).subs({"a": s}), lambda s: tl.FlatPunch(1).subs({s: 1}),
                                 lambda s: tl.FlatPunch(1).subs(s)],
    "thinlayer.punch.base.Tip.subs": [lambda s: tl.Punch.paraboloid().subs({"R": s})],
    # the stages
    "thinlayer.kernel_coefficients": [lambda s: tl.kernel_coefficients(s, 2),
        lambda s: tl.kernel_coefficients(F().L, s),
                                      lambda s: tl.kernel_coefficients(F().L, 2, backend=s)],
    "thinlayer.kernel_moment": [lambda s: tl.kernel_moment(s, 1, 1), lambda s: tl.kernel_moment(F().L, s, 1),
                                lambda s: tl.kernel_moment(F().L, 1, s)],
    "thinlayer.moment_expansion": [lambda s: tl.moment_expansion(s, 2), lambda s: tl.moment_expansion(F().L, s)],
    "thinlayer.inner_pressure": [lambda s: tl.inner_pressure(s, F().P), lambda s: tl.inner_pressure(F().L, s),
                                 lambda s: tl.inner_pressure(F().L, F().P, order=s),
                                 lambda s: tl.inner_pressure(F().L, F().P, method=s)],
    "thinlayer.contact_contour": [lambda s: tl.contact_contour(s, 0.1),
        lambda s: tl.contact_contour("x_1**2 + x_2**2", s),
                                  lambda s: tl.contact_contour("x_1**2 + x_2**2", 0.1, n=s),
                                  lambda s: tl.contact_contour("x_1**2 + x_2**2", 0.1, tol=s)],
    "thinlayer.ellipse_contour": [lambda s: tl.ellipse_contour(s), lambda s: tl.ellipse_contour(1, s),
                                  lambda s: tl.ellipse_contour(1, 2, s)],
    "thinlayer.alexandrov_solution": [lambda s: tl.alexandrov_solution(s)],
    "thinlayer.boundary_layer_exact": [lambda s: tl.boundary_layer_exact(s),
        lambda s: tl.boundary_layer_exact(0.3, dps=s),
                                       lambda s: tl.boundary_layer_exact(0.3, n=s)],
    "thinlayer.edge_shift_exact": [lambda s: tl.edge_shift_exact(s), lambda s: tl.edge_shift_exact(0.3, dps=s),
                                   lambda s: tl.edge_shift_exact(0.3, normaliser=s)],
    "thinlayer.edge_shift_alexandrov": [lambda s: tl.edge_shift_alexandrov(s)],
    "thinlayer.force_law": [lambda s: tl.force_law(s, F().P), lambda s: tl.force_law(F().L, s)],
    "thinlayer.composite_pressure": [lambda s: tl.composite_pressure(s, F().P, 0.1, 0.05),
                                     lambda s: tl.composite_pressure(F().L, s, 0.1, 0.05),
                                     lambda s: tl.composite_pressure(F().L, F().P, s, 0.05),
                                     lambda s: tl.composite_pressure(F().L, F().P, 0.1, s),
                                     lambda s: tl.composite_pressure(F().L, F().P, 0.1, 0.05, mu=s),
                                     lambda s: tl.composite_pressure(F().L, F().P, 0.1, 0.05, terms=s),
                                     lambda s: tl.composite_pressure(F().L, F().P, 0.1, 0.05, boundary_layer=s),
                                     lambda s: tl.composite_pressure(tl.FrictionlessLayer(), F().P, 0.1, 0.05, nu=s)],
    "thinlayer.thin_layer_operator": [lambda s: tl.thin_layer_operator(s), lambda s: tl.thin_layer_operator(F().LI, s)],
    "thinlayer.obstacle_problem": [lambda s: tl.obstacle_problem(s), lambda s: tl.obstacle_problem(F().LI, s),
                                   lambda s: tl.obstacle_problem(tl.BondedLayer(), F().P, nu=s)],
    "thinlayer.two_term_sphere": [lambda s: tl.two_term_sphere(s)],
    "thinlayer.regime": [lambda s: tl.regime(s, 0.1), lambda s: tl.regime(F().L, s),
        lambda s: tl.regime(F().L, 0.1, s)],
    # the user's question
    "thinlayer.solve": [
        lambda s: tl.solve(s, F().P, delta0=0.1, H=0.05, mu=1.0),
        lambda s: tl.solve(F().L, s, delta0=0.1, H=0.05, mu=1.0),
        lambda s: tl.solve(F().L, F().P, delta0=s, H=0.05, mu=1.0),
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=s, mu=1.0),
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=0.05, mu=s),
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=0.05, E=s),
        lambda s: tl.solve(F().L, F().P, force=s, H=0.05, mu=1.0),
        lambda s: tl.solve(tl.FrictionlessLayer(), F().P, delta0=0.1, H=0.05, mu=1.0, nu=s),
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=0.05, mu=1.0, model=s),
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=0.05, mu=1.0, tol=s),
        lambda s: tl.solve(F().L, tl.Punch.paraboloid(), delta0=0.1, H=0.05, mu=1.0, parameters={"R": s}),
        lambda s: tl.solve(F().L, tl.Punch.paraboloid(), delta0=0.1, H=0.05, mu=1.0, parameters={s: 10}),
        lambda s: tl.solve(F().L, tl.Punch.paraboloid(), delta0=0.1, H=0.05, mu=1.0, parameters=s),
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=0.05, mu=1.0, model="direct", n=s),
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=0.05, mu=1.0, order=s),
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=0.05, mu=1.0, terms=s),
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=0.05, mu=1.0, boundary_layer=s),
        lambda s: tl.solve(F().L, tl.Punch.flat(1), delta0=0.1, H=0.05, mu=s),
        # adhesion (issue 26 item 5)
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=0.05, mu=1.0, work_of_adhesion=s),
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=0.05, mu=1.0, work_of_adhesion=0.01, branch=s),
        lambda s: tl.solve(F().L, F().P, delta0=s, H=0.05, mu=1.0, work_of_adhesion=0.01),
        lambda s: tl.solve(F().L, F().P, force=s, H=0.05, mu=1.0, work_of_adhesion=0.01),
        lambda s: tl.solve(F().L, F().P, delta0=0.1, H=0.05, mu=1.0, work_of_adhesion=0.01, model=s),
        # viscoelastic (issue 27 item 4)
        lambda s: tl.solve(F().L, F().P, H=1.0, material=s, history=([0.0, 1.0], [0.0, 0.1])),
        lambda s: tl.solve(F().L, F().P, H=1.0, material=tl.Prony(1.0), history=s),
        lambda s: tl.solve(F().L, F().P, H=1.0, material=tl.Prony(1.0), history=([0.0, 1.0], s)),
        lambda s: tl.solve(F().L, F().P, H=1.0, material=tl.Prony(1.0), history=([0.0, 1.0], [0.0, 0.1]), control=s),
        lambda s: tl.solve(F().L, F().P, H=1.0, material=tl.Prony(1.0), history=([0.0, 1.0], [0.0, 0.1]), model=s),
    ],
    "thinlayer.Indentation": [lambda s: tl.Indentation(*([s] * 17))],
    "thinlayer.Indentation.pressure": [lambda s: F().ind.pressure(s, 0.0), lambda s: F().ind.pressure(0.0, s)],
    "thinlayer.Indentation.compare_direct": [lambda s: F().ind.compare_direct(n=s)],
    "thinlayer.solve_axisymmetric": [
        lambda s: tl.solve_axisymmetric(s, F().P, 0.1, 0.05), lambda s: tl.solve_axisymmetric(F().L, s, 0.1, 0.05),
        lambda s: tl.solve_axisymmetric(F().L, F().P, s, 0.05), lambda s: tl.solve_axisymmetric(F().L, F().P, 0.1, s),
        lambda s: tl.solve_axisymmetric(F().L, F().P, 0.1, 0.05, mu=s),
        lambda s: tl.solve_axisymmetric(F().L, F().P, 0.1, 0.05, n=s),
        lambda s: tl.solve_axisymmetric(tl.FrictionlessLayer(), F().P, 0.1, 0.05, nu=s)],
    "thinlayer.solve_2d": [
        lambda s: tl.solve_2d(s, F().P, delta0=0.1, H=1.0, n=32),
        lambda s: tl.solve_2d(F().L, s, delta0=0.1, H=1.0, n=32),
        lambda s: tl.solve_2d(F().L, F().P, delta0=s, H=1.0, n=32),
        lambda s: tl.solve_2d(F().L, F().P, delta0=0.1, H=s, n=32),
        lambda s: tl.solve_2d(F().L, F().P, delta0=0.1, H=0.1, mu=s, n=32),
        lambda s: tl.solve_2d(F().L, F().P, delta0=0.1, H=0.1, n=s),
        lambda s: tl.solve_2d(F().L, F().P, delta0=0.1, H=1.0, n=32, extent=s),
        lambda s: tl.solve_2d(F().L, F().P, force=s, H=1.0, n=32),
        lambda s: tl.solve_2d(F().L, F().P, delta0=0.1, H=1.0, n=32, extent=2.0, surface_load=s),
        lambda s: tl.solve_2d(tl.FrictionlessLayer(), F().P, delta0=0.1, H=1.0, n=32, nu=s)],
    "thinlayer.force_any_thickness": [
        lambda s: tl.force_any_thickness(s, 10.0, 2.0, mu=1.0), lambda s: tl.force_any_thickness(0.1, s, 2.0, mu=1.0),
        lambda s: tl.force_any_thickness(0.1, 10.0, s, mu=1.0), lambda s: tl.force_any_thickness(0.1, 10.0, 2.0, mu=s),
        lambda s: tl.force_any_thickness(0.1, 10.0, 2.0, E=s),
        lambda s: tl.force_any_thickness(0.1, 10.0, 2.0, 1.0, nu=s),
        lambda s: tl.force_any_thickness(0.1, 10.0, 2.0, 1.0, base=s),
        lambda s: tl.force_any_thickness([0.1, s], 10.0, 2.0, 1.0)],
    "thinlayer.any_thickness_law": [lambda s: tl.any_thickness_law(s), lambda s: tl.any_thickness_law(0.5, s)],
    "thinlayer.load_curve": [lambda s: tl.load_curve(s), lambda s: tl.load_curve(AFM_FILE, segment=s), lambda s: tl.load_curve(AFM_FILE, index=s)],  # noqa: E501
    "thinlayer.fit_curve": [lambda s: tl.fit_curve(s, punch=1.0)] + [lambda s, k=k: tl.fit_curve(_curve(), **{"punch": 1.0, k: s}) for k in ("punch", "H", "nu", "base", "model", "fit_H", "baseline", "contact_point", "weighting", "weight_cp", "fit_range", "range_kind", "bootstrap", "seed", "bootstrap_method")],  # noqa: E501
    "thinlayer.afm.curve_fit.CurveFit.predict": [lambda s: tl.fit_curve(_curve(), punch=1.0).predict(s), lambda s: tl.fit_curve(_curve(), punch=1.0).predict([0.1, s])],  # noqa: E501
    "thinlayer.fit": [
        lambda s: tl.fit(s, [1, 2, 3], punch=1.0, H=1.0), lambda s: tl.fit([0.1, 0.2, 0.3], s, punch=1.0, H=1.0),
        lambda s: tl.fit([0.1, s, 0.3], [1, 2, 3], punch=1.0, H=1.0),
        lambda s: tl.fit([0.1, 0.2, 0.3], [1, 2, 3], punch=s, H=1.0),
        lambda s: tl.fit([0.1, 0.2, 0.3], [1, 2, 3], punch=1.0, H=s),
        lambda s: tl.fit([0.1, 0.2, 0.3], [1, 2, 3], punch=1.0, H=1.0, nu=s),
        lambda s: tl.fit([0.1, 0.2, 0.3], [1, 2, 3], punch=1.0, H=1.0, base=s),
        lambda s: tl.fit([0.1, 0.2, 0.3], [1, 2, 3], punch=1.0, H=1.0, model=s),
        lambda s: tl.fit([0.1, 0.2, 0.3], [1, 2, 3], punch=1.0, H=1.0, E0=s),
        lambda s: tl.fit([0.1, 0.2, 0.3], [1, 2, 3], punch=1.0, H=1.0, sigma=s),
        lambda s: tl.fit([0.1, 0.2, 0.3], [1, 2, 3], punch=1.0, H=1.0, fit_H=s),
        lambda s: tl.fit([0.1, 0.2, 0.3], [1, -2, 3], punch=1.0, H=1.0, work_of_adhesion=s),  # issue 26 item 5
        lambda s: tl.fit(s, [1, -2, 3], punch=1.0, H=1.0, work_of_adhesion="free")],
    "thinlayer.force_arrays": [
        lambda s: tl.force_arrays(s, F().P, [0.1], 0.05), lambda s: tl.force_arrays(F().L, s, [0.1], 0.05),
        lambda s: tl.force_arrays(F().L, F().P, s, 0.05), lambda s: tl.force_arrays(F().L, F().P, [0.1, s], 0.05),
        lambda s: tl.force_arrays(F().L, F().P, [0.1], s), lambda s: tl.force_arrays(F().L, F().P, [0.1], 0.05, mu=s),
        lambda s: tl.force_arrays(tl.FrictionlessLayer(), F().P, [0.1], 0.05, nu=s),
        lambda s: tl.force_arrays(F().L, tl.Punch.paraboloid(), [0.1], 0.05, parameters={"R": s}),
        lambda s: tl.force_arrays(F().L, F().P, [0.1], 0.05, tol=s)],
    "thinlayer.flat_punch_stiffness": [
        lambda s: tl.flat_punch_stiffness(s, 1.0), lambda s: tl.flat_punch_stiffness(F().L, s),
        lambda s: tl.flat_punch_stiffness(F().L, [1.0, s]), lambda s: tl.flat_punch_stiffness(F().L, 1.0, s),
        lambda s: tl.flat_punch_stiffness(F().L, 1.0, "thin", max_error=s)],
    "thinlayer.checked_lambdify": [lambda s: tl.checked_lambdify([s], sp.Symbol("x")),
                                   lambda s: tl.checked_lambdify([sp.Symbol("x")], s),
                                   lambda s: tl.checked_lambdify([sp.Symbol("x")], [s]),
                                   lambda s: tl.checked_lambdify([sp.Symbol("x")], sp.Symbol("x"), backend=s)],
    # thinlayer.parse: the grammar itself
    "thinlayer.parse.parse_expression": [lambda s: PA.parse_expression(s),
                                         lambda s: PA.parse_expression("a + b", names=[s])],
    "thinlayer.parse.parse_number": [lambda s: PA.parse_number(s, "x")],
    "thinlayer.parse.as_expr": [lambda s: PA.as_expr(s)],
    "thinlayer.parse.sympy_value": [lambda s: PA.sympy_value(s, "x"), lambda s: PA.sympy_value(s, "x", symbol=True)],
    "thinlayer.parse.check_cost": [lambda s: PA.check_cost(s)],
    "thinlayer.parse.expression_cost": [lambda s: PA.expression_cost(s)],
    "thinlayer.parse.piecewise_linear_form": [lambda s: PA.piecewise_linear_form(s, (sp.Symbol("r"),)),
                                              lambda s: PA.piecewise_linear_form(sp.Symbol("r"), s)],
    "thinlayer.parse.Cost": [lambda s: PA.Cost(s, s, s)],
    # the direct solvers' other doors
    "thinlayer.numerics.contact_for_radius": [
        lambda s: N.contact_for_radius(s, F().P, 1.0, 0.5),
        lambda s: N.contact_for_radius(F().L, s, 1.0, 0.5),
        lambda s: N.contact_for_radius(F().L, F().P, s, 0.5),
        lambda s: N.contact_for_radius(F().L, F().P, 1.0, s),
        lambda s: N.contact_for_radius(F().L, F().P, 1.0, 0.5, mu=s),
        lambda s: N.contact_for_radius(F().L, F().P, 1.0, 0.5, n=s)],
    "thinlayer.numerics.influence_coefficients": [
        lambda s: N.influence_coefficients(s, 0.1, 0.01, 8),
        lambda s: N.influence_coefficients(F().L, s, 0.01, 8),
        lambda s: N.influence_coefficients(F().L, 0.1, s, 8),
        lambda s: N.influence_coefficients(F().L, 0.1, 0.01, s),
        lambda s: N.influence_coefficients(F().L, 0.1, 0.01, 8, mu=s),
        lambda s: N.influence_coefficients(tl.FrictionlessLayer(), 0.1, 0.01, 8, nu=s)],
    "thinlayer.numerics.layer_correction_kernel": [
        lambda s: N.layer_correction_kernel(s, 0.1, [0.1]),
        lambda s: N.layer_correction_kernel(F().L, s, [0.1]),
        lambda s: N.layer_correction_kernel(F().L, 0.1, s)],
    "thinlayer.numerics.radial_profile": [lambda s: N.radial_profile(s)],
    "thinlayer.numerics.solve_obstacle_grid": [
        lambda s: N.solve_obstacle_grid(s, F().P, 0.1, 0.05, n=21),
        lambda s: N.solve_obstacle_grid(F().LI, s, 0.1, 0.05, n=21),
        lambda s: N.solve_obstacle_grid(F().LI, F().P, s, 0.05, n=21),
        lambda s: N.solve_obstacle_grid(F().LI, F().P, 0.1, s, n=21),
        lambda s: N.solve_obstacle_grid(F().LI, F().P, 0.1, 0.05, mu=s, n=21),
        lambda s: N.solve_obstacle_grid(F().LI, F().P, 0.1, 0.05, n=s),
        lambda s: N.solve_obstacle_grid(F().LI, F().P, 0.1, 0.05, n=21, box=s),
        lambda s: N.solve_obstacle_grid(F().LI, tl.Punch.paraboloid(), 0.1, 0.05, n=21,
                                                  parameters={"R": s})],
    "thinlayer.numerics.surface_displacement": [lambda s: N.surface_displacement(s, [0.1]),
                                                lambda s: N.surface_displacement(F().axi, s)],
    "thinlayer.numerics.AxisymmetricContact.pressure_at": [lambda s: F().axi.pressure_at(s)],
    "thinlayer.numerics.GridContact.pressure_at": [lambda s: F().grid.pressure_at(s, 0.0),
                                                   lambda s: F().grid.pressure_at(0.0, s)],
    # the results' methods that take values
    "thinlayer.asymptotics.force_law.ForceLaw.evaluate": [
        lambda s: F().law.evaluate(s, 0.05), lambda s: F().law.evaluate(0.1, s),
        lambda s: F().law.evaluate(0.1, 0.05, s),
        lambda s: F().law.evaluate(0.1, 0.05, edge_shift=s),
        lambda s: F().law_sym.evaluate(0.1, 0.05, parameters={"R": s}),
        lambda s: F().law_sym.evaluate(0.1, 0.05, parameters={s: 10}), lambda s: F().law.evaluate(0.1, 0.05, nu=s),
        lambda s: F().law.evaluate(0.1, 0.05, contour=s)],
    "thinlayer.asymptotics.force_law.ForceLaw.indentation": [
        lambda s: F().law.indentation(s, 0.05), lambda s: F().law.indentation(1.0, s),
        lambda s: F().law.indentation(1.0, 0.05, s), lambda s: F().law_sym.indentation(1.0, 0.05, parameters={"R": s}),
        lambda s: F().law.indentation(1.0, 0.05, nu=s), lambda s: F().law.indentation(1.0, 0.05, order=s)],
    "thinlayer.asymptotics.force_law.ForceLaw.parameter_values": [lambda s: F().law_sym.parameter_values({"R": s}),
                                                                  lambda s: F().law_sym.parameter_values({s: 1}),
                                                                  lambda s: F().law_sym.parameter_values(s)],
    "thinlayer.asymptotics.force_law.ForceLaw.lambdify": [lambda s: F().law.lambdify(args=[s]),
                                                          lambda s: F().law.lambdify(backend=s)],
    "thinlayer.asymptotics.second_order.SecondOrderLaw.evaluate": [
        lambda s: F().law2.evaluate(s, 0.05), lambda s: F().law2.evaluate(0.1, s),
        lambda s: F().law2.evaluate(0.1, 0.05, s),
        lambda s: F().law2.evaluate(0.1, 0.05, parameters={"R": s}), lambda s: F().law2.evaluate(0.1, 0.05, nu=s)],
    "thinlayer.asymptotics.second_order.SecondOrderLaw.lambdify": [lambda s: F().law2.lambdify(args=[s]),
                                                                   lambda s: F().law2.lambdify(backend=s)],
    "thinlayer.asymptotics.second_order.edge_constants": [lambda s: SO.edge_constants(s),
        lambda s: SO.edge_constants(F().L, dps=s)],
    "thinlayer.asymptotics.second_order.second_order_law": [
        lambda s: SO.second_order_law(s, F().P),
        lambda s: SO.second_order_law(F().L, s)],
    "thinlayer.asymptotics.solution.numeric_punch": [
        lambda s: SOL.numeric_punch(s),
        lambda s: SOL.numeric_punch(
            tl.Punch.paraboloid(), {"R": s})],
    "thinlayer.asymptotics.solution.compressible_solution": [
        lambda s: SOL.compressible_solution(
            F().L, tl.Punch.paraboloid(), delta0=0.1, H=0.05, parameters={"R": s}),
        lambda s: SOL.compressible_solution(
            F().L, F().P, delta0=s, H=0.05),
        lambda s: SOL.compressible_solution(
            F().L, F().P, delta0=0.1, H=0.05, tol=s),
        lambda s: SOL.compressible_solution(
            tl.FrictionlessLayer(), F().P, delta0=0.1, H=0.05, nu=s)],
    "thinlayer.asymptotics.solution.ContactSolution.pressure": [lambda s: F().sol.pressure(s, 0.0)],
    "thinlayer.asymptotics.solution.ContactSolution.contains": [lambda s: F().sol.contains(s, 0.0)],
    "thinlayer.asymptotics.composite.CompositePressure.__call__": [lambda s: F().comp(s, 0.0),
        lambda s: F().comp(0.0, s)],
    "thinlayer.asymptotics.composite.CompositePressure.local": [lambda s: F().comp.local(s, 0.0),
                                                                lambda s: F().comp.local(0.0, s)],
    "thinlayer.asymptotics.contour.ContactContour.b1": [lambda s: F().contour.b1(s)],
    "thinlayer.asymptotics.contour.ContactContour.b2": [lambda s: F().contour.b2(s)],
    "thinlayer.asymptotics.contour.ContactContour.b_star": [lambda s: F().contour.b_star(s, 0.1, 1.0),
                                                            lambda s: F().contour.b_star(0.1, s, 1.0),
                                                            lambda s: F().contour.b_star(0.1, 0.1, s)],
    "thinlayer.asymptotics.contour.ContactContour.boundary_integral": [
        lambda s: F().contour.boundary_integral(s), lambda s: F().contour.boundary_integral(np.cos, of=s),
        lambda s: F().contour.boundary_integral(np.cos, n=s)],
    "thinlayer.asymptotics.contour.ContactContour.contains": [lambda s: F().contour.contains(s, 0.0)],
    "thinlayer.asymptotics.contour.ContactContour.curvature": [lambda s: F().contour.curvature(s)],
    "thinlayer.asymptotics.contour.ContactContour.derivative": [lambda s: F().contour.derivative(s),
                                                                lambda s: F().contour.derivative(0.1, s)],
    "thinlayer.asymptotics.contour.ContactContour.f": [lambda s: F().contour.f(s)],
    "thinlayer.asymptotics.contour.ContactContour.g": [lambda s: F().contour.g(s)],
    "thinlayer.asymptotics.contour.ContactContour.integrate": [
        lambda s: F().contour.integrate(s), lambda s: F().contour.integrate(np.hypot, n_radial=s),
        lambda s: F().contour.integrate(np.hypot, n_angular=s)],
    "thinlayer.asymptotics.contour.ContactContour.local_to_cartesian": [
        lambda s: F().contour.local_to_cartesian(s, 0.0), lambda s: F().contour.local_to_cartesian(0.0, s)],
    "thinlayer.asymptotics.contour.ContactContour.normal": [lambda s: F().contour.normal(s)],
    "thinlayer.asymptotics.contour.ContactContour.phi": [lambda s: F().contour.phi(s, 0.0),
        lambda s: F().contour.phi(0.0, s)],
    "thinlayer.asymptotics.contour.ContactContour.rho": [lambda s: F().contour.rho(s)],
    "thinlayer.asymptotics.contour.ContactContour.tangent": [lambda s: F().contour.tangent(s)],
    "thinlayer.asymptotics.contour.EllipseContour.curvature_radius": [lambda s: F().ellipse.curvature_radius(s, 0),
                                                                      lambda s: F().ellipse.curvature_radius(0, s)],
    "thinlayer.asymptotics.inner.InnerPressure.lambdify": [lambda s: F().inner.lambdify(args=[s]),
                                                           lambda s: F().inner.lambdify(backend=s),
                                                           lambda s: F().inner.lambdify(scaled=s)],
    "thinlayer.asymptotics.moment_expansion.MomentExpansion.apply": [
        lambda s: F().mexp.apply(s), lambda s: F().mexp.apply(sp.Symbol("xi_1") ** 2, v1=s),
        lambda s: F().mexp.apply(sp.Symbol("xi_1") ** 2, v2=s),
        lambda s: F().mexp.apply(sp.Symbol("xi_1") ** 2, Lam=s)],
    "thinlayer.asymptotics.moment_expansion.MomentExpansion.pairing": [
        lambda s: F().mexp.pairing(s), lambda s: F().mexp.pairing(sp.Symbol("xi_1") ** 2, v1=s),
        lambda s: F().mexp.pairing(sp.Symbol("xi_1") ** 2, Lam=s)],
    "thinlayer.asymptotics.moment_expansion.MomentExpansion.lambdify": [lambda s: F().mexp.lambdify(backend=s)],
    "thinlayer.asymptotics.boundary_layer.AlexandrovSolution.dimensional": [lambda s: F().alex.dimensional(s)],
    "thinlayer.asymptotics.boundary_layer.AlexandrovSolution.laplace_transform": [
        lambda s: F().alex.laplace_transform(s)],
    "thinlayer.asymptotics.boundary_layer.AlexandrovSolution.q": [lambda s: F().alex.q(s)],
    "thinlayer.asymptotics.boundary_layer.AlexandrovSolution.q_general": [lambda s: F().alex.q_general(s),
                                                                          lambda s: F().alex.q_general(h=s)],
    "thinlayer.asymptotics.boundary_layer.AlexandrovSolution.q_hat": [lambda s: F().alex.q_hat(s)],
    "thinlayer.asymptotics.boundary_layer.AlexandrovSolution.q_mpmath": [lambda s: F().alex.q_mpmath(s)],
    "thinlayer.asymptotics.boundary_layer.AlexandrovSolution.q_numeric": [lambda s: F().alex.q_numeric(s)],
    "thinlayer.asymptotics.boundary_layer.AlexandrovSolution": [lambda s: type(F().alex)(s, s)],
    "thinlayer.asymptotics.wiener_hopf.WienerHopfSolution.laplace": [lambda s: F().wh.laplace(s),
                                                                     lambda s: F().wh.laplace(1.0, dps=s)],
    "thinlayer.asymptotics.wiener_hopf.WienerHopfSolution.pressure": [lambda s: F().wh.pressure(s),
                                                                      lambda s: F().wh.pressure(1.0, scale=s)],
    "thinlayer.asymptotics.wiener_hopf.WienerHopfSolution.q": [lambda s: F().wh.q(s), lambda s: F().wh.q(1.0, dps=s),
                                                               lambda s: F().wh.q(1.0, method=s)],
    "thinlayer.asymptotics.wiener_hopf.WienerHopfSolution.q_numpy": [lambda s: F().wh.q_numpy(s)],
    "thinlayer.asymptotics.wiener_hopf.WienerHopfSolution.table_check": [lambda s: F().wh.table_check(s)],
    "thinlayer.asymptotics.incompressible.operator.ThinLayerOperator.apply": [
        lambda s: F().op.apply(s), lambda s: F().op.apply(sp.Symbol("x_1") ** 2, v1=s),
        lambda s: F().op.apply(sp.Symbol("x_1") ** 2, v2=s)],
    "thinlayer.asymptotics.incompressible.operator.ThinLayerOperator.apply_scaled": [
        lambda s: F().op.apply_scaled(s), lambda s: F().op.apply_scaled(sp.Symbol("xi_1"), Lam=s)],
    "thinlayer.asymptotics.incompressible.operator.ThinLayerOperator.pairing": [
        lambda s: F().op.pairing(s), lambda s: F().op.pairing(sp.Symbol("xi_1"), v2=s)],
    "thinlayer.asymptotics.incompressible.operator.ThinLayerOperator.lambdify": [lambda s: F().op.lambdify(backend=s)],
    "thinlayer.asymptotics.incompressible.operator.ObstacleProblem.residual": [lambda s: F().obst.residual(s)],
    "thinlayer.asymptotics.incompressible.operator.ObstacleProblem.boundary_values": [
        lambda s: F().obst.boundary_values(s, 0, 0), lambda s: F().obst.boundary_values(sp.Integer(1), s, 0),
        lambda s: F().obst.boundary_values(sp.Integer(1), 0, s)],
    "thinlayer.asymptotics.incompressible.operator.ObstacleProblem.lambdify": [
        lambda s: F().obst.lambdify(args=[s]), lambda s: F().obst.lambdify(backend=s)],
    "thinlayer.asymptotics.incompressible.regime.Regime.lambdify": [lambda s: F().reg.lambdify(backend=s)],
    "thinlayer.asymptotics.incompressible.two_term.TwoTermSphere.evaluate": [
        lambda s: F().two.evaluate(s, 10, 0.05), lambda s: F().two.evaluate(0.1, s, 0.05),
        lambda s: F().two.evaluate(0.1, 10, s), lambda s: F().two.evaluate(0.1, 10, 0.05, s),
        lambda s: F().two.evaluate(0.1, 10, 0.05, edge_correction=s)],
    "thinlayer.asymptotics.incompressible.two_term.TwoTermSphere.lambdify": [
        lambda s: F().two.lambdify(args=[s]), lambda s: F().two.lambdify(backend=s)],
    "thinlayer.contact.any_thickness.AnyThicknessLaw.error_estimate": [lambda s: F().atl.error_estimate(s)],
    "thinlayer.contact.any_thickness.AnyThicknessLaw.log_force_ratio": [lambda s: F().atl.log_force_ratio(s)],
    "thinlayer.contact.any_thickness.AnyThicknessLaw.ratios": [lambda s: F().atl.ratios(s)],
    "thinlayer.contact.any_thickness.AnyThicknessLaw.regime": [lambda s: F().atl.regime(s)],
    "thinlayer.contact.fit.FitResult.predict": [lambda s: F().fitres.predict(s),
        lambda s: F().fitres.predict([0.1, s])],
}

#: public callables that take no user value, each with the reason
NO_USER_VALUES: dict[str, str] = {
    **{f"thinlayer.{c}.{m}": "prints the layer" for c in _layers() for m in ("latex", "text_lines")},
    **{f"thinlayer.{k}.{m}": "prints the object" for k in ("Punch", "FlatPunch", "Indentation") for m in ("latex",
                                                                                                          "text_lines")},
    "thinlayer.Punch.codegen_expressions": "returns the punch's own expressions",
    "thinlayer.Punch.berkovich": "takes no argument: the nominal Berkovich pyramid",
    "thinlayer.Punch.vickers": "takes no argument: the nominal Vickers pyramid",
    **{f"thinlayer.asymptotics.{m}.codegen_constants": "returns the law's layer constants (h*, r_3): no argument"
       for m in ("force_law.ForceLaw", "second_order.SecondOrderLaw")},
    "thinlayer.LayerKernel": "the abstract base of the layers: no constructor (Python refuses to instantiate it)",
    "thinlayer.punch.base.Tip": "the abstract base of the tips: no constructor (Python refuses to instantiate it)",
    "thinlayer.punch.base.LevelSet": "a result class: thinlayer builds it; its constructor stores values and "
                                     "evaluates none",
    "thinlayer.Indentation.as_dict": "returns the numbers it holds",
    "thinlayer.contact.hereditary.ViscoelasticForce.to_json": "returns the numbers it holds, as JSON",
    "thinlayer.oscillation_law": "takes no argument: the sympy derivation",
    "thinlayer.errors.boundary": "a decorator for thinlayer's own functions (its argument is code, not a value)",
    "thinlayer.errors.boundary_methods": "a class decorator for thinlayer's own classes",
    "thinlayer.errors.translate": "turns an exception into thinlayer's; never evaluates its text",
    "thinlayer.asymptotics.solution.ContactSolution.report_rows": "prints the result's numbers; its argument is the "
                                                                  "report's LaTeX of [units], set after them as text",
}
#: result classes: thinlayer builds them; their constructors store what they are given and evaluate nothing
RESULT_CLASSES = (
    "thinlayer.asymptotics.composite.CompositePressure", "thinlayer.asymptotics.contour.ContactContour",
    "thinlayer.asymptotics.contour.EllipseContour", "thinlayer.asymptotics.force_law.ForceLaw",
    "thinlayer.asymptotics.force_law.ForceValues", "thinlayer.asymptotics.incompressible.operator.ObstacleProblem",
    "thinlayer.asymptotics.incompressible.operator.ThinLayerOperator",
    "thinlayer.asymptotics.incompressible.regime.Regime", "thinlayer.asymptotics.incompressible.two_term.SphereValues",
    "thinlayer.asymptotics.incompressible.two_term.TwoTermSphere", "thinlayer.asymptotics.inner.InnerPressure",
    "thinlayer.asymptotics.moment_expansion.MomentExpansion", "thinlayer.asymptotics.second_order.EdgeConstants",
    "thinlayer.asymptotics.second_order.SecondOrderLaw", "thinlayer.asymptotics.second_order.SecondOrderValues",
    "thinlayer.asymptotics.solution.ContactSolution", "thinlayer.asymptotics.solution.ForceArrays",
    "thinlayer.asymptotics.wiener_hopf.WienerHopfSolution", "thinlayer.contact.any_thickness.AnyThicknessLaw",
    "thinlayer.contact.fit.FitResult", "thinlayer.contact.hereditary.ViscoelasticForce",
    "thinlayer.contact.oscillation.ContactStiffness", "thinlayer.contact.oscillation.Oscillation",
    "thinlayer.contact.oscillation.OscillationLaw", "thinlayer.contact.visco_fit.ViscoFitResult",
    "thinlayer.afm.curves.Curve", "thinlayer.afm.curve_fit.CurveFit",
    "thinlayer.contact.indentation.DirectComparison",
    "thinlayer.numerics.AxisymmetricContact",
    "thinlayer.numerics.Contact2D", "thinlayer.numerics.GridContact",
)
for _cls in RESULT_CLASSES:
    NO_USER_VALUES[_cls] = "a result class: thinlayer builds it; its constructor stores values and evaluates none"
#: methods of the result classes that take no argument (they print or return what the result holds)
_NO_ARGUMENT = ("latex", "text_lines", "codegen_expressions", "as_dict", "scaled_semi_axes", "leading", "weights",
                "force_defect", "extent", "moments", "lambdify", "codegen_constants")
del _cls


def _no_argument_methods(surface: dict[str, object]) -> dict[str, str]:
    out = {}
    for key, fn in surface.items():
        if key in INVENTORY or key in NO_USER_VALUES or not inspect.isfunction(fn):
            continue
        params = [p for p in inspect.signature(fn).parameters if p != "self"]
        if key.rsplit(".", 1)[-1] in _NO_ARGUMENT and not params:
            out[key] = "takes no argument"
    return out


# ---------------------------------------------------------------------------------------------------------------
# the tests
# ---------------------------------------------------------------------------------------------------------------
def test_inventory_is_complete():
    """Every public callable is a door with its calls, or is listed with the reason it takes no user value."""
    surface = public_surface()
    exempt = {**NO_USER_VALUES, **_no_argument_methods(surface)}
    missing = sorted(k for k in surface if k not in INVENTORY and k not in exempt)
    assert not missing, "doors without a check (add them to INVENTORY or NO_USER_VALUES):\n" + "\n".join(missing)
    stale = sorted(k for k in INVENTORY if k not in surface)
    assert not stale, "INVENTORY names no longer public:\n" + "\n".join(stale)


def _one_call(call, payload: str, marker: Path) -> str:
    """``"ok"``, or a description of what went wrong."""
    try:
        call(payload)
    except ThinlayerError as exc:
        text = str(exc)
        if not isinstance(exc, (ValueError, TypeError)):
            return f"{type(exc).__name__} is not a ValueError/TypeError: {text[:200]}"
        if "\n" in text.strip() or not text.strip():
            return f"{type(exc).__name__} without a one-line message: {text[:200]!r}"
    except Exception as exc:  # noqa: BLE001 - the point: anything else is a leak
        return f"{type(exc).__name__} (not a thinlayer exception): {str(exc)[:200]}"
    if marker.exists():
        marker.unlink()
        return "CODE RAN"
    return "ok"


@pytest.mark.parametrize("door", sorted(INVENTORY))
def test_door_never_evaluates_a_payload(door, tmp_path):
    F()  # the objects the calls need: built here, so that a failure to build them is not taken for a refusal
    marker = tmp_path / "pwned"
    bad = []
    for k, call in enumerate(INVENTORY[door]):
        for payload in PAYLOADS:
            got = _one_call(call, payload.replace("{m}", str(marker)), marker)
            if got != "ok" or marker.exists():
                bad.append(f"call {k} with {payload[:30]!r}...: {got}")
    assert not bad, f"{door}:\n" + "\n".join(bad)


def test_the_payloads_would_run_code(tmp_path):
    """The check can fail: evaluating the payloads (as sympy's sympify would) creates the marker."""
    marker = tmp_path / "pwned"
    for payload in PAYLOADS:
        eval(payload.replace("{m}", str(marker)).replace("x_1", "1").replace("x_2", "1"))  # noqa: S307
        assert marker.exists()
        marker.unlink()
