"""fit(..., work_of_adhesion="free") and ``thinlayer fit --work-of-adhesion free`` (issue 26 item 5).

Independent reference: curves made by the direct JKR solver (J.1)-(J.5) (its own smooth-edge Galerkin solution and
flat-punch solves) on a bonded layer at contact radii that are not the fit table's nodes; the fit's model is the
any-thickness JKR law (J.16).
"""
from __future__ import annotations

import json
import math
from functools import lru_cache

import numpy as np
import pytest

from thinlayer import BondedLayer, fit
from thinlayer.contact.adhesion_fit import AdhesiveFit
from thinlayer.errors import InputError
from thinlayer.export.cli import main
from thinlayer.numerics.adhesion import adhesive_state

pytestmark = pytest.mark.xdist_group("adhesion-laws")

R, NU, E, W, H = 1.0, 0.3, 2.6, 0.05, 0.2


@lru_cache(maxsize=1)
def _curve() -> tuple[np.ndarray, np.ndarray]:
    """The stable (unloading) branch of the direct JKR curve at 8 radii (about 0.5 s)."""
    mu = E / (2 * (1 + NU))
    st = [adhesive_state(BondedLayer(NU), lambda r: r * r / (2 * R), c, H, mu, work_of_adhesion=W, energy_route=False)
          for c in np.linspace(0.31, 0.87, 8)]
    return np.array([s.delta for s in st]), np.array([s.force for s in st])


def test_fit_recovers_E_and_w_of_direct_solver_data():
    d, P = _curve()
    assert np.all(np.diff(d) > 0) and P.min() < 0  # stable branch under displacement control, with pulls
    f = fit(d, P, punch=R, H=H, nu=NU, work_of_adhesion="free")
    assert isinstance(f, AdhesiveFit) and f.model == "any-thickness"
    # no noise: the law (J.16) and the direct solver agree to ~1e-6 (tests/adhesion/test_door_sphere.py)
    assert abs(f.E / E - 1) < 1e-5 and abs(f.work_of_adhesion / W - 1) < 1e-5
    noisy = P + 0.004 * np.random.default_rng(5).standard_normal(P.size)
    g = fit(d, noisy, punch=R, H=H, nu=NU, work_of_adhesion="free")
    assert abs(g.E - E) < 3 * g.E_se and abs(g.work_of_adhesion - W) < 3 * g.work_of_adhesion_error
    assert 0 < g.E_se < 0.02 * E and 0 < g.work_of_adhesion_error < 0.05 * W
    assert g.as_dict()["work_of_adhesion_se"] == g.work_of_adhesion_error


@pytest.mark.parametrize("kw, match", [({"work_of_adhesion": 0.05}, "'free'"), ({"fit_H": True}, "fit_H"),
                                       ({"punch": None}, "paraboloid"), ({"nu": 0.7}, "nu")])
def test_bad_input_one_line(kw, match):
    d, P = _curve()
    args = {"punch": R, "H": H, "nu": NU, "work_of_adhesion": "free", **kw}
    with pytest.raises(InputError, match=match) as exc:
        fit(d, P, **args)
    assert "\n" not in str(exc.value)


def test_cli_fit_work_of_adhesion_free(tmp_path, capsys):
    d, P = _curve()
    csv = tmp_path / "curve.csv"
    csv.write_text("depth,force\n" + "\n".join(f"{float(a)!r},{float(b)!r}" for a, b in zip(d, P)) + "\n")
    assert main(["fit", str(csv), "--R", "1", "--H", "0.2", "--nu", "0.3", "--work-of-adhesion", "free",
                 "--json"]) == 0
    obj = json.loads(capsys.readouterr().out)
    assert obj["model"] == "any-thickness" and abs(obj["E"] / E - 1) < 1e-5
    assert abs(obj["work_of_adhesion"] / W - 1) < 1e-5 and obj["work_of_adhesion_se"] > 0
    assert main(["fit", str(csv), "--R", "1", "--H", "0.2", "--nu", "0.3", "--work-of-adhesion", "free",
                 "--fit-offset"]) == 2
    err = capsys.readouterr().err.strip()
    assert "fit_offset" in err and "\n" not in err and "Traceback" not in err
    assert math.isfinite(obj["residual_rms"])
