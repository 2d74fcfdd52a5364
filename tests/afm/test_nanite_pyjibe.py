"""PyJibe lists thinlayer's models (issue 25 item 1): PyJibe's fit tab fills its model box from nanite's registry
(pyjibe/fd/tab_fit.py: ``nmodel.models_available``), and its Preferences load model files as extensions
(pyjibe/extensions.py: ``nanite.model.load_model_from_file(path, register=True)``).  Run headless
(QT_QPA_PLATFORM=offscreen).  Skipped where PyJibe (and PyQt6) is not installed: it is no dependency of thinlayer
(``pip install pyjibe``; tested with pyjibe 0.16.4, PyQt6 6.11).
"""
import os

import pytest

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
pytest.importorskip("nanite", reason="the extra thinlayer[afm] is not installed (pip install -e .[afm])")
pytest.importorskip("PyQt6.QtWidgets", reason="PyJibe's GUI toolkit PyQt6 is not installed (pip install pyjibe)")
pytest.importorskip("pyjibe", reason="PyJibe is not installed (pip install pyjibe)")

from thinlayer.afm.nanite_models import model_keys, register  # noqa: E402
from thinlayer.export.cli import main  # noqa: E402

pytestmark = pytest.mark.xdist_group("afm-laws")


@pytest.fixture(scope="module")
def app():
    from PyQt6 import QtWidgets

    return QtWidgets.QApplication.instance() or QtWidgets.QApplication([])


def _listed(app):
    """The model keys in PyJibe's fit tab, as a user sees them (the combo box's items)."""
    from pyjibe.fd.tab_fit import TabFit

    tab = TabFit()
    return [tab.cb_model.itemData(i) for i in range(tab.cb_model.count())]


def test_pyjibe_lists_the_registered_plugin_models(app):
    """After ``register()`` (in the process that starts PyJibe) every thinlayer model is in the fit tab's box."""
    register()
    listed = _listed(app)
    assert set(model_keys()) <= set(listed) and "hertz_para" in listed


def test_pyjibe_loads_a_generated_model_file_as_an_extension(app, tmp_path):
    """A ``thinlayer codegen nanite`` file imported through PyJibe's ExtensionManager (what Preferences > Extensions
    does) is loaded, registered and listed."""
    from pyjibe.extensions import ExtensionManager

    gen = tmp_path / "gen"
    assert main(["codegen", "nanite", "--tip", "sphere", "--base", "frictionless", "--nu", "0.5", "--out", str(gen),
                 "--quiet"]) == 0
    (path,) = gen.glob("model_*.py")
    manager = ExtensionManager(tmp_path / "store")
    ext = manager.import_extension_from_path(path)
    assert ext.loaded and ext.title.startswith("sphere, frictionless layer")
    assert "thinlayer_sphere_frictionless_nu0p5" in _listed(app)
    manager.extension_remove(ext)
    assert "thinlayer_sphere_frictionless_nu0p5" not in _listed(app)
