"""Direct numerical solvers of the contact problem (1.5)-(1.8), independent of the asymptotics.

* :func:`solve_2d` -- any polynomial punch: FFT influence coefficients of the layer kernel (2.1)
  on an N x N grid and the Polonsky-Keer conjugate-gradient method (:mod:`.fft2d`);
* :func:`solve_axisymmetric` -- an axisymmetric :class:`~thinlayer.punch.Punch` or a radial profile
  ``Phi(r)``: spectral Galerkin method in Hankel space (:mod:`.axisymmetric`), with
  :func:`contact_for_radius` (prescribed contact radius) and :func:`surface_displacement` (check route);
* :func:`solve_obstacle_grid` -- the incompressible thin-layer obstacle problem on a grid (:mod:`.obstacle`).
"""
from .axisymmetric import (
    AxisymmetricContact,
    AxisymmetricPunchContact,
    contact_for_radius,
    radial_profile,
    solve_axisymmetric,
    surface_displacement,
)
from .fft2d import (
    CoarseGridWarning,
    Contact2D,
    ContactConvergenceError,
    influence_coefficients,
    layer_correction_kernel,
    solve_2d,
)
from .obstacle import GridContact, solve_obstacle_grid

__all__ = [
    "AxisymmetricContact",
    "AxisymmetricPunchContact",
    "CoarseGridWarning",
    "Contact2D",
    "ContactConvergenceError",
    "GridContact",
    "contact_for_radius",
    "influence_coefficients",
    "layer_correction_kernel",
    "radial_profile",
    "solve_2d",
    "solve_axisymmetric",
    "solve_obstacle_grid",
    "surface_displacement",
]
