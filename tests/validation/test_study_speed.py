"""Speed of the asymptotic force at equal accuracy (thinlayer.validation.speed)."""
from __future__ import annotations

from thinlayer.validation import speed_comparison


def test_speed_comparison_reaches_equal_accuracy():
    sc = speed_comparison(0.3, 0.1, repeat=1)
    assert sc.fft2d_n is not None and sc.fft2d_error <= sc.asymptotic_error
    assert sc.axisymmetric_modes is not None and sc.axisymmetric_error <= sc.asymptotic_error
    assert sc.seconds_solve > 0 and sc.seconds_force_law > 0 and sc.ratio_fft2d > 0
