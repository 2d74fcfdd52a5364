"""Direct numerical solvers of the contact problem (1.5)-(1.8), independent of the asymptotics.

* :func:`solve_2d` -- any polynomial punch: FFT influence coefficients of the layer kernel (2.1)
  on an N x N grid and the Polonsky-Keer conjugate-gradient method (:mod:`.fft2d`);
* :func:`solve_axisymmetric` -- an axisymmetric :class:`~thinlayer.punch.Punch`, through the spectral
  solver :func:`thinlayer.numerics.direct.solve_axisymmetric` (:mod:`.axisymmetric`).
"""
from .axisymmetric import AxisymmetricPunchContact, solve_axisymmetric
from .fft2d import (
    CoarseGridWarning,
    Contact2D,
    ContactConvergenceError,
    influence_coefficients,
    layer_correction_kernel,
    solve_2d,
)

__all__ = [
    "AxisymmetricPunchContact",
    "CoarseGridWarning",
    "Contact2D",
    "ContactConvergenceError",
    "influence_coefficients",
    "layer_correction_kernel",
    "solve_2d",
    "solve_axisymmetric",
]
