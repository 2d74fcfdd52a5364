"""thinlayer: symbolic asymptotics of a rigid punch pressed into a thin elastic layer.

Stages of the paper, each a pure function returning an immutable result with ``latex()``
and ``lambdify()``:

``kernel_coefficients`` (2.20), (4.2) -> ``kernel_moment`` (2.15), (2.21) ->
``moment_expansion`` (2.22) -> ``inner_pressure`` (2.24)-(2.31), (4.1) ->
``contact_contour`` (3.1)-(3.14) -> ``alexandrov_solution`` / ``boundary_layer_exact`` (3.15)-(3.25) ->
``force_law`` (1.8) and ``composite_pressure``; ``solve`` joins them for numeric parameters.
"""
from . import errata, symbols
from .asymptotics.boundary_layer import (
    AlexandrovParameters,
    AlexandrovSolution,
    alexandrov_kernel,
    alexandrov_parameters,
    alexandrov_solution,
    boundary_layer_kernel,
)
from .asymptotics.composite import CompositePressure, composite_pressure
from .asymptotics.contour import (
    ContactContour,
    ContourAccuracy,
    EllipseContour,
    contact_contour,
    ellipse_contour,
)
from .asymptotics.force_law import ForceLaw, ForceValues, boundary_layer_force_defect, force_law
from .asymptotics.incompressible import (
    EllipseValues,
    GridContact,
    IncompressibleCoefficients,
    IncompressibleEllipse,
    IncompressibleLayer,
    IncompressibleRadial,
    ObstacleProblem,
    RadialValues,
    Regime,
    SphereModels,
    SphereValues,
    ThinLayerOperator,
    TwoTermEdgeLayer,
    TwoTermSphere,
    compare_sphere_models,
    incompressible_axisymmetric,
    incompressible_coefficients,
    incompressible_ellipse,
    obstacle_problem,
    regime,
    solve_obstacle_grid,
    thin_layer_operator,
    two_term_edge_layer,
    two_term_edge_shift,
    two_term_sphere,
)
from .asymptotics.inner import InnerPressure, inner_pressure
from .asymptotics.moment_expansion import MomentExpansion, moment_expansion
from .asymptotics.solution import ContactSolution, solve
from .asymptotics.wiener_hopf import (
    WienerHopfSolution,
    boundary_layer_exact,
    edge_shift_alexandrov,
    edge_shift_exact,
    edge_shift_table,
    wiener_hopf_solution,
)
from .layers.coefficients import KernelCoefficients, kernel_coefficients
from .layers.kernels import (
    BondedLayer,
    FrictionlessLayer,
    GenericLayer,
    HalfSpace,
    IncompressibleLayerError,
    LayerKernel,
)
from .layers.moments import kernel_moment
from .numerics.direct import AxisymmetricContact, contact_for_radius, solve_axisymmetric, surface_displacement
from .punch import Punch, PunchError
from .results import MissingArgumentError, checked_lambdify

__all__ = [
    "BondedLayer",
    "FrictionlessLayer",
    "GenericLayer",
    "HalfSpace",
    "IncompressibleLayerError",
    "LayerKernel",
    "KernelCoefficients",
    "kernel_coefficients",
    "kernel_moment",
    "MomentExpansion",
    "moment_expansion",
    "Punch",
    "PunchError",
    "InnerPressure",
    "inner_pressure",
    "MissingArgumentError",
    "checked_lambdify",
    "errata",
    "ContactContour",
    "ContourAccuracy",
    "EllipseContour",
    "contact_contour",
    "ellipse_contour",
    "AxisymmetricContact",
    "solve_axisymmetric",
    "contact_for_radius",
    "surface_displacement",
    "WienerHopfSolution",
    "boundary_layer_exact",
    "edge_shift_alexandrov",
    "edge_shift_exact",
    "edge_shift_table",
    "wiener_hopf_solution",
    "symbols",
    "AlexandrovParameters",
    "AlexandrovSolution",
    "alexandrov_kernel",
    "alexandrov_parameters",
    "alexandrov_solution",
    "boundary_layer_kernel",
    "CompositePressure",
    "composite_pressure",
    "ForceLaw",
    "ForceValues",
    "boundary_layer_force_defect",
    "force_law",
    "ContactSolution",
    "solve",
    "IncompressibleLayer",
    "incompressible_coefficients",
    "IncompressibleCoefficients",
    "thin_layer_operator",
    "ThinLayerOperator",
    "obstacle_problem",
    "ObstacleProblem",
    "incompressible_ellipse",
    "IncompressibleEllipse",
    "EllipseValues",
    "incompressible_axisymmetric",
    "IncompressibleRadial",
    "RadialValues",
    "solve_obstacle_grid",
    "GridContact",
    "two_term_sphere",
    "TwoTermSphere",
    "SphereValues",
    "two_term_edge_shift",
    "two_term_edge_layer",
    "TwoTermEdgeLayer",
    "regime",
    "Regime",
    "compare_sphere_models",
    "SphereModels",
]
