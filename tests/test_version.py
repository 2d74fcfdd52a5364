"""``thinlayer.__version__`` (issue 28, item 5): the installed version, or pyproject's when not installed."""
from __future__ import annotations

import importlib.metadata
import sys
from pathlib import Path

import thinlayer

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

PYPROJECT = Path(__file__).resolve().parents[1] / "pyproject.toml"


def test_version_is_the_installed_distributions():
    assert thinlayer.__version__ == importlib.metadata.version("thinlayer")
    assert "__version__" in dir(thinlayer)


def test_version_falls_back_to_pyproject_when_not_installed(monkeypatch):
    def missing(name):
        raise importlib.metadata.PackageNotFoundError(name)

    monkeypatch.setattr(importlib.metadata, "version", missing)
    expected = tomllib.loads(PYPROJECT.read_text())["project"]["version"]
    assert thinlayer._version() == expected
    assert expected == importlib.metadata.distribution("thinlayer").version  # the two sources agree
