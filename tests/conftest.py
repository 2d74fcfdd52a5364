"""Test configuration: long validation runs are marked ``slow`` and run only with THINLAYER_SLOW=1."""
import os

import mpmath
import pytest


def pytest_collection_modifyitems(config, items):
    if os.environ.get("THINLAYER_SLOW") == "1" or "slow" in (config.getoption("-m") or ""):
        return
    skip = pytest.mark.skip(reason="long validation run: set THINLAYER_SLOW=1 to run it")
    for item in items:
        if "slow" in item.keywords:
            item.add_marker(skip)


@pytest.fixture(autouse=True)
def _mpmath_precision_restored():
    """A test that sets mpmath's global precision must not change what later tests compute."""
    dps = mpmath.mp.dps
    yield
    mpmath.mp.dps = dps
