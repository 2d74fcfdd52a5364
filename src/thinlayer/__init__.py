"""thinlayer: symbolic asymptotics of a rigid punch on a thin elastic layer."""
from .coefficients import KernelCoefficients, kernel_coefficients
from .kernels import BondedLayer, FrictionlessLayer, HalfSpace, LayerKernel

__all__ = [
    "BondedLayer",
    "FrictionlessLayer",
    "HalfSpace",
    "LayerKernel",
    "KernelCoefficients",
    "kernel_coefficients",
]
