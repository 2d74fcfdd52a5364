"""thinlayer: symbolic asymptotics of a rigid punch pressed into a thin elastic layer.

Stages of the paper, each a pure function returning an immutable result with ``latex()``
and ``lambdify()``:

``kernel_coefficients`` (2.20), (4.2) -> ``kernel_moment`` (2.15), (2.21) ->
``moment_expansion`` (2.22) -> ``inner_pressure`` (2.24)-(2.31), (4.1) ->
``contact_contour`` (3.1)-(3.14) -> ``alexandrov_solution`` / ``boundary_layer_exact`` (3.15)-(3.25) ->
``force_law`` (1.8) and ``composite_pressure``.  ``solve`` answers for numeric parameters with the model
that holds (the compressible expansion, the two-term or incompressible model, or the direct solver).
The direct numerical solvers (``solve_axisymmetric``, ``solve_2d``) are the independent reference.

The folders follow the pipeline: ``layers/`` -> ``punch`` -> ``asymptotics/`` (and, independent of it,
``numerics/``) -> ``validation/`` -> ``export/``.  Names that used to be importable from here and are
no longer in ``__all__`` still are for one release, with a ``DeprecationWarning`` naming their module.
"""
from __future__ import annotations

import importlib
import warnings
from typing import Any

#: where each public name lives; imported on first use (PEP 562), so that ``import thinlayer`` and
#: ``thinlayer --help`` do not pay for scipy, the numerics and the validation studies up front
_PUBLIC = {
    **dict.fromkeys(["BondedLayer", "FrictionlessLayer", "GenericLayer", "HalfSpace", "IncompressibleLayer",
                     "IncompressibleLayerError", "LayerKernel"], "thinlayer.layers.kernels"),
    "kernel_coefficients": "thinlayer.layers.coefficients",
    "kernel_moment": "thinlayer.layers.moments",
    **dict.fromkeys(["FlatPunch", "Punch", "PunchError"], "thinlayer.punch"),
    "flat_punch_stiffness": "thinlayer.contact.flat_punch",
    "moment_expansion": "thinlayer.asymptotics.moment_expansion",
    "inner_pressure": "thinlayer.asymptotics.inner",
    **dict.fromkeys(["contact_contour", "ellipse_contour"], "thinlayer.asymptotics.contour"),
    "alexandrov_solution": "thinlayer.asymptotics.boundary_layer",
    **dict.fromkeys(["boundary_layer_exact", "edge_shift_alexandrov", "edge_shift_exact"],
                    "thinlayer.asymptotics.wiener_hopf"),
    "force_law": "thinlayer.asymptotics.force_law",
    "composite_pressure": "thinlayer.asymptotics.composite",
    **dict.fromkeys(["obstacle_problem", "regime", "thin_layer_operator", "two_term_sphere"],
                    "thinlayer.asymptotics.incompressible"),
    **dict.fromkeys(["Indentation", "solve"], "thinlayer.contact.solve"),
    **dict.fromkeys(["any_thickness_law", "force_any_thickness"], "thinlayer.contact.any_thickness"),
    "fit": "thinlayer.contact.fit",
    "load_curve": "thinlayer.afm.curves", "fit_curve": "thinlayer.afm.curve_fit",  # measured curves (issue 25)
    # viscoelastic materials and the Lee-Radok force history (issue 27, first slice)
    **dict.fromkeys(["viscoelastic_force", "viscoelastic_depth"], "thinlayer.contact.hereditary"),
    **dict.fromkeys(["oscillation", "contact_stiffness", "oscillation_law"], "thinlayer.contact.oscillation"),
    "fit_viscoelastic": "thinlayer.contact.visco_fit",
    **dict.fromkeys(["Prony", "StandardLinearSolid", "KelvinVoigt", "PowerLaw"], "thinlayer.contact.materials"),
    "force_arrays": "thinlayer.asymptotics.solution",
    **dict.fromkeys(["solve_2d", "solve_axisymmetric"], "thinlayer.numerics"),
    **dict.fromkeys(["MissingArgumentError", "checked_lambdify"], "thinlayer.results"),
    **dict.fromkeys(["ThinlayerError", "InputError", "InputTypeError", "WorkLimitError", "NotDerivedError",
                     "ComputationError", "ValidityWarning"], "thinlayer.errors"),
    "ExpressionError": "thinlayer.parse",
    "ValidityError": "thinlayer.asymptotics.solution",
}
#: public submodules
_MODULES = {"errata": "thinlayer.errata", "errors": "thinlayer.errors", "symbols": "thinlayer.symbols"}

__all__ = [
    # layers: the kernel L(u) (2.3)-(2.4)
    "BondedLayer", "FrictionlessLayer", "HalfSpace", "IncompressibleLayer", "GenericLayer", "LayerKernel",
    # the punch (1.1); the flat-ended cylinder (F.1)
    "Punch",
    # the stages, in the paper's order
    "kernel_coefficients", "kernel_moment", "moment_expansion", "inner_pressure",
    "contact_contour", "ellipse_contour", "alexandrov_solution", "boundary_layer_exact",
    "edge_shift_exact", "edge_shift_alexandrov", "force_law", "composite_pressure",
    # nu = 1/2 and near it (I.1)-(I.13)
    "thin_layer_operator", "obstacle_problem", "two_term_sphere", "regime",
    # the user's question: force, contact size and pressure by the model that holds; the direct solvers
    "solve", "Indentation", "solve_axisymmetric", "solve_2d",
    # any thickness (T.1)-(T.8) and fitting measured curves
    "force_any_thickness", "fit",
    # the flat-ended cylinder's stiffness kappa(a/H) (F.1)-(F.19)
    "flat_punch_stiffness",
    # errors and tools (every exception class is in thinlayer.errors, and importable from here)
    "IncompressibleLayerError", "PunchError", "MissingArgumentError", "checked_lambdify",
    # modules
    "errata", "symbols",
]

#: names importable from ``thinlayer`` before the redesign, and the module each lives in now
_MOVED = {
    **dict.fromkeys(["ContactContour", "ContourAccuracy", "EllipseContour"], "thinlayer.asymptotics.contour"),
    **dict.fromkeys(["AlexandrovParameters", "AlexandrovSolution", "alexandrov_kernel", "alexandrov_parameters",
                     "boundary_layer_kernel"], "thinlayer.asymptotics.boundary_layer"),
    "CompositePressure": "thinlayer.asymptotics.composite",
    "KernelCoefficients": "thinlayer.layers.coefficients",
    **dict.fromkeys(["AxisymmetricContact", "contact_for_radius", "surface_displacement"],
                    "thinlayer.numerics.axisymmetric"),
    **dict.fromkeys(["ForceLaw", "ForceValues", "boundary_layer_force_defect"], "thinlayer.asymptotics.force_law"),
    **dict.fromkeys(["incompressible_coefficients", "IncompressibleCoefficients"], "thinlayer.layers.coefficients"),
    **dict.fromkeys(["ThinLayerOperator", "ObstacleProblem", "incompressible_ellipse", "IncompressibleEllipse",
                     "EllipseValues", "incompressible_axisymmetric", "IncompressibleRadial", "RadialValues",
                     "TwoTermSphere", "SphereValues", "two_term_edge_shift", "two_term_edge_layer",
                     "TwoTermEdgeLayer", "Regime"], "thinlayer.asymptotics.incompressible"),
    **dict.fromkeys(["solve_obstacle_grid", "GridContact"], "thinlayer.numerics.obstacle"),
    **dict.fromkeys(["compare_sphere_models", "SphereModels"], "thinlayer.validation.comparison"),
    "InnerPressure": "thinlayer.asymptotics.inner",
    "ContactSolution": "thinlayer.asymptotics.solution",
    "MomentExpansion": "thinlayer.asymptotics.moment_expansion",
    **dict.fromkeys(["WienerHopfSolution", "edge_shift_table", "wiener_hopf_solution"],
                    "thinlayer.asymptotics.wiener_hopf"),
}


def _version() -> str:
    """The installed distribution's version; from ``pyproject.toml`` beside the sources when not installed."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("thinlayer")
    except PackageNotFoundError:
        from pathlib import Path

        pyproject = Path(__file__).resolve().parents[2] / "pyproject.toml"
        try:
            try:
                import tomllib
            except ModuleNotFoundError:  # Python 3.10
                import tomli as tomllib
            return str(tomllib.loads(pyproject.read_text())["project"]["version"])
        except (OSError, KeyError, ValueError, ModuleNotFoundError):
            return "0+unknown"


def __getattr__(name: str) -> Any:
    """A public name, imported on first use; a name moved out of ``__all__``, with a DeprecationWarning.

    ``__version__`` is read on first use too (:func:`importlib.metadata.version`), not at import.
    """
    if name == "__version__":
        value = globals()["__version__"] = _version()
        return value
    if name in _PUBLIC:
        value = getattr(importlib.import_module(_PUBLIC[name]), name)
    elif name in _MODULES:
        value = importlib.import_module(_MODULES[name])
    else:
        module = _MOVED.get(name)
        if module is None:
            raise AttributeError(f"module 'thinlayer' has no attribute {name!r}")
        warnings.warn(f"thinlayer.{name} is deprecated: import it from {module} (thinlayer 0.2 removes this alias)",
                      DeprecationWarning, stacklevel=2)
        return getattr(importlib.import_module(module), name)
    globals()[name] = value  # the next access is a plain attribute
    return value


def __dir__() -> list[str]:
    """The current names only (loaded or not): the deprecated aliases are not advertised."""
    return sorted(set(globals()) | set(__all__) | {"__version__"})
