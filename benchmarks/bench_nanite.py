"""Timings of thinlayer's nanite models on a real AFM curve (issue 25), beside nanite's own Hertz model.

One nanite fit (E and contact point, nanite's defaults: R = 10 um, nu = 1/2, contact-point weighting) of afmformats'
example JPK curve (tests/afm/data, 4,000 points; the approach segment is fitted): ``hertz_para`` (the peer),
``thinlayer_para_bonded`` at H = 5 um (the any-thickness law (T.7), cached after the first call) and the module
written by ``thinlayer codegen nanite``.  Target: a thin-layer fit within 5x of nanite's Hertz fit.  Rows are
empty when the extra thinlayer[afm] (nanite, afmformats) is not installed.
"""
from __future__ import annotations

import importlib.util
import tempfile
import warnings
from pathlib import Path

from _timing import Row, main, median

CURVE = Path(__file__).resolve().parents[1] / "tests" / "afm" / "data" / "fmt-jpk-fd_spot3-0192.jpk-force"


def run() -> list[Row]:
    if importlib.util.find_spec("nanite") is None:
        return []
    import nanite

    from thinlayer.afm.nanite_models import register
    from thinlayer.export.cli import main as cli

    register(["thinlayer_para_bonded"])
    with tempfile.TemporaryDirectory() as tmp:
        cli(["codegen", "nanite", "--tip", "sphere", "--base", "bonded", "--nu", "0.5", "--out", tmp, "--quiet"])
        (path,) = Path(tmp).glob("model_*.py")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            gen = nanite.model.load_model_from_file(path, register=True).model_key
    idnt = nanite.load_group(CURVE)[0]
    idnt.apply_preprocessing(["compute_tip_position", "correct_force_offset", "correct_tip_offset"])

    def fit(key, **values):
        def go():
            p = nanite.model.get_init_parms(key)
            for k, v in values.items():
                p[k].value = v
            idnt.fit_properties.pop("hash", None)  # nanite skips a fit it has done (same hash): fit again
            idnt.fit_model(model_key=key, params_initial=p)
            assert idnt.fit_properties["success"]
        return go

    fit("thinlayer_para_bonded", H=5e-6)()  # warm the law
    hertz = median(fit("hertz_para"))
    return [Row("nanite fit, thinlayer_para_bonded at H = 5 um (plugin)", median(fit("thinlayer_para_bonded", H=5e-6)),
                ">= 0.2x", peer="nanite hertz_para", peer_value=hertz),
            Row("nanite fit, generated model (codegen nanite) at H = 5 um", median(fit(gen, H=5e-6)), ">= 0.2x",
                peer="nanite hertz_para", peer_value=hertz)]


if __name__ == "__main__":
    main(run)
