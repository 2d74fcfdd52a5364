"""Shared fixture of the validation tests: a small sphere study (axisymmetric numerics, ~8 s)."""
from __future__ import annotations

import pytest

from thinlayer.validation import ValidationStudy, validation_study

SMALL_NUS = (0.3, 0.45)
SMALL_RATIOS = (0.1, 0.05, 0.025, 0.0125)


@pytest.fixture(scope="session")
def small_study() -> ValidationStudy:
    """Sphere, nu in {0.3, 0.45}, H/a = 0.1 ... 0.0125 (axisymmetric numerics, ~8 s)."""
    return validation_study(nus=SMALL_NUS, ratios=SMALL_RATIOS, shapes=("sphere",), progress=False)
