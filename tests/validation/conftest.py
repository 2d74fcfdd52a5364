"""Shared fixture of the validation tests: a small sphere study (axisymmetric numerics).

The small study's cases (sphere, nu = 0.3, 0.45, H/a = 0.1 ... 0.0125) are all cases of the default study, which
the README's ``thinlayer validate --out validation --plots`` runs anyway (tests/test_readme.py).  So the small study
is that run's sphere rows, profiles and contours at those nu and H/a (the root conftest's ``validate_cli_run``
runs the command once for both; they share the xdist group ``validation-study``): every case is computed by the
same ``sphere_case(nu, H/a)`` as in a study of its own, and the analyses (fits, h^* checks, tables) are made from
these rows alone.  ``test_small_study_is_a_study_of_its_own`` checks one case against a study run on its own.
"""
from __future__ import annotations

import dataclasses
from types import MappingProxyType

import pytest

from thinlayer.validation import ValidationStudy

SMALL_NUS = (0.3, 0.45)
SMALL_RATIOS = (0.1, 0.05, 0.025, 0.0125)
#: the README's command (tests/test_readme.py runs the README's own line through the same shared run)
DEFAULT_VALIDATE = ("validate", "--out", "validation", "--plots")


def _small(item) -> bool:
    return item.shape == "sphere" and item.nu in SMALL_NUS and round(item.H_over_a, 12) in SMALL_RATIOS


@pytest.fixture(scope="session")
def small_study(validate_cli_run) -> ValidationStudy:
    """Sphere, nu in {0.3, 0.45}, H/a = 0.1 ... 0.0125: the default study's rows of these cases."""
    run = validate_cli_run(DEFAULT_VALIDATE)
    assert run.code == 0 and run.study is not None, run.err[-2000:]
    full = run.study
    settings = dict(full.settings, shapes=["sphere"], nus=list(SMALL_NUS), ratios=list(SMALL_RATIOS),
                    elliptic_nus=[], elliptic_ratios=[])
    return dataclasses.replace(full, rows=tuple(r for r in full.rows if _small(r)),
                               profiles=tuple(p for p in full.profiles if _small(p)),
                               contours=tuple(c for c in full.contours if _small(c)),
                               skipped=tuple(s for s in full.skipped if s[0] == "sphere" and s[1] in SMALL_NUS),
                               settings=MappingProxyType(settings))
