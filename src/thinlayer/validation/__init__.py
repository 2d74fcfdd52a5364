r"""Validation study: the asymptotic results against the direct numerical solvers (issue 4).

For each case -- a punch shape (a sphere, an elliptic paraboloid R1/R2 = 4), a Poisson ratio ``nu``
and a thickness ratio ``H/a`` -- the asymptotic solution (:func:`thinlayer.solve`: force (1.8) with its
first correction, contact area with the exact edge shift h^* (3.25), composite pressure) is compared
with an independent direct solution of (1.5)-(1.8) that uses no thin-layer series, and the observed
order of each remainder is fitted against the claimed one.

Modules, by role:

* :mod:`~thinlayer.validation.cases`: the two shapes, the input checks and one :class:`ValidationRow`
  per case (with the plot data :class:`PressureProfile`, :class:`ContourData`);
* :mod:`~thinlayer.validation.analysis`: :class:`ValidationStudy` -- observed orders (:class:`OrderFit`),
  the edge-shift check (:class:`EdgeShiftCheck`), tables, LaTeX, JSON and files;
* :mod:`~thinlayer.validation.runner`: :func:`validation_study`, :func:`validate_sphere`,
  :func:`validate_elliptic`, with progress lines and a clean stop on Ctrl-C (:class:`StudyEvent`);
* :mod:`~thinlayer.validation.plots`: the figures (matplotlib, the ``plot`` extra);
* :mod:`~thinlayer.validation.speed`: :func:`speed_comparison`, the asymptotic force against the direct
  solvers at equal accuracy;
* :mod:`~thinlayer.validation.comparison`: :func:`compare_sphere_models`, the compressible, incompressible and
  two-term sphere models side by side (with the direct solver);
* :mod:`~thinlayer.validation.cli`: the command ``thinlayer validate`` (:func:`add_cli`, :func:`cli`).
"""
from .._lazy import lazy_exports

#: public names and the module each lives in (imported on first use)
_EXPORTS = {
    **dict.fromkeys(["EdgeShiftCheck", "OrderFit", "ValidationStudy"], "thinlayer.validation.analysis"),
    **dict.fromkeys(["CLAIMED_ORDERS", "H_OVER_A_RANGE", "NUS", "SHAPES", "ContourData", "PressureProfile",
                     "ValidationRow", "check_nu", "check_nus", "check_ratio", "check_ratios", "check_shapes",
                     "elliptic_grid"], "thinlayer.validation.cases"),
    **dict.fromkeys(["add_cli", "cli"], "thinlayer.validation.cli"),
    **dict.fromkeys(["SphereModels", "compare_sphere_models"], "thinlayer.validation.comparison"),
    **dict.fromkeys(["StudyEvent", "validate_elliptic", "validate_sphere", "validation_study"],
                    "thinlayer.validation.runner"),
    **dict.fromkeys(["SpeedComparison", "speed_comparison"], "thinlayer.validation.speed"),
}
__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)

__all__ = [
    "CLAIMED_ORDERS",
    "H_OVER_A_RANGE",
    "NUS",
    "SHAPES",
    "ContourData",
    "EdgeShiftCheck",
    "OrderFit",
    "PressureProfile",
    "SpeedComparison",
    "SphereModels",
    "StudyEvent",
    "ValidationRow",
    "ValidationStudy",
    "add_cli",
    "check_nu",
    "check_nus",
    "check_ratio",
    "check_ratios",
    "check_shapes",
    "cli",
    "compare_sphere_models",
    "elliptic_grid",
    "speed_comparison",
    "validate_elliptic",
    "validate_sphere",
    "validation_study",
]
