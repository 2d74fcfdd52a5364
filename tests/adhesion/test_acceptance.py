"""Acceptance of adhesion (issue 26 item 6): {sphere; flat punch} x {bonded nu = 0.3, 0.5; frictionless base} x
H/R from thick to thin x two works of adhesion, against the direct solver (J.1)-(J.6), (J.13).

* Sphere: the any-thickness JKR law (J.16) at two contact radii (either side of the pull-off radius) against the
  direct JKR states: every difference inside the law's estimate (J.18) plus the direct solver's own; the pull-off
  force (load control) against the direct curve's minimum (jkr_curve).
* Flat punch (Kendall): the detachment force of the flat part's laws (J.17) (thick series, thin forms, exact
  table, the model each a/H picks) against the direct detachment (flat_punch_detachment: its own exact solves and
  the compliance route (J.4)), inside the stated estimates; the half-space limit is Kendall (1971) as printed.
* The thin-layer laws' remainders fall at their derived orders: (J.11) order 1 for the sphere (slope 2 in H/c),
  (J.13) order 1 for the flat punch (slope 2 in H/a).

Default: one slice (bonded 0.3, H/R = 0.1, one w); THINLAYER_SLOW=1: the whole grid (the elliptic paraboloid in
solve_2d is the cohesive helper's).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from thinlayer import BondedLayer, FrictionlessLayer, IncompressibleLayer
from thinlayer.asymptotics.adhesion import thin_flat_detachment, thin_layer_jkr
from thinlayer.contact.adhesion_sphere import any_thickness_jkr, flat_release_factor
from thinlayer.numerics.adhesion import adhesive_state, flat_punch_detachment, jkr_curve

pytestmark = pytest.mark.xdist_group("adhesion-laws")

R, MU = 1.0, 1.0
LAYERS = {"bonded 0.3": (BondedLayer(0.3), None, 0.3), "bonded 0.5": (IncompressibleLayer(), None, 0.5),
          "frictionless": (FrictionlessLayer(), 0.3, 0.3)}
H_OVER_R = (3.0, 1.0, 0.3, 0.1, 0.03, 0.01)
WORKS = (0.02, 0.2)  # w/(mu R)


def _paraboloid(r):
    return r * r / (2 * R)


def sphere_rows(name: str, hr: float, w: float) -> list[dict]:
    """The law against the direct states at 0.6 and 1.5 times the law's pull-off radius."""
    layer, nu, _ = LAYERS[name]
    law = any_thickness_jkr(layer, nu)
    c_off, _, _ = law.pull_off(hr * R, R, w, MU)
    rows = []
    for f in (0.6, 1.5):
        c = f * c_off
        st = law.states(c, hr * R, R, w, MU)
        ds = adhesive_state(layer, _paraboloid, c, hr * R, MU, work_of_adhesion=w, nu=nu, energy_route=False)
        rows.append({"c": c, "dP": abs(st.force[0] - ds.force), "eP": st.force_error[0] + ds.force_error,
                     "dd": abs(st.delta[0] - ds.delta), "ed": st.delta_error[0] + ds.delta_error,
                     "scale": max(abs(ds.force), math.pi * w * R)})
    return rows


def flat_row(name: str, a_over_H: float, w: float) -> dict:
    """The detachment force of a flat punch of radius R by (J.17) against the direct one (J.13)."""
    layer, nu, nu_val = LAYERS[name]
    H = R / a_over_H
    vt = MU / (1 - nu_val)
    kappa, g, ek, eg, models = flat_release_factor(layer, a_over_H)
    law = 4 * vt * R * kappa[0] * math.sqrt(math.pi * R * w / (vt * g[0]))
    det = flat_punch_detachment(layer, R, H, MU, work_of_adhesion=w, nu=nu)
    return {"law": law, "direct": det.force, "est": (ek[0] + 0.5 * eg[0]) * law + det.error * det.force,
            "model": models[0], "kendall": math.sqrt(8 * math.pi * R**3 * 2 * vt * w)}


def check_sphere(name: str, hr: float, w: float) -> None:
    for row in sphere_rows(name, hr, w):
        assert row["dP"] <= row["eP"], (name, hr, w, row)
        assert row["dd"] <= row["ed"], (name, hr, w, row)
        assert row["dP"] < 1e-3 * row["scale"], (name, hr, w, row)


def check_flat(name: str, a_over_H: float, w: float) -> None:
    row = flat_row(name, a_over_H, w)
    assert abs(row["law"] - row["direct"]) <= row["est"], (name, a_over_H, w, row)


# --------------------------------------------------------------------------- the default slice
def test_slice_sphere_and_flat_punch_against_direct():
    """Bonded nu = 0.3, H/R = 0.1, w = 0.02: the sphere at two radii and the flat punch at a/H = 10 and 0.02."""
    check_sphere("bonded 0.3", 0.1, 0.02)
    check_flat("bonded 0.3", 10.0, 0.02)
    thick = flat_row("bonded 0.3", 0.02, 0.02)  # a/H = 0.02: the half-space, Kendall (1971) as printed
    assert thick["model"] == "thick" and abs(thick["direct"] / thick["kendall"] - 1) < 0.03
    assert abs(thick["law"] - thick["direct"]) <= thick["est"]


# --------------------------------------------------------------------------- the grid (THINLAYER_SLOW=1)
@pytest.mark.slow
@pytest.mark.parametrize("w", WORKS)
@pytest.mark.parametrize("name", list(LAYERS))
def test_grid_sphere_states(name, w):
    for hr in H_OVER_R:
        check_sphere(name, hr, w)


@pytest.mark.slow
@pytest.mark.parametrize("w", WORKS)
@pytest.mark.parametrize("name", list(LAYERS))
def test_grid_flat_punch_detachment(name, w):
    for hr in H_OVER_R:
        check_flat(name, 1.0 / hr, w)


@pytest.mark.slow
@pytest.mark.parametrize("name", list(LAYERS))
def test_grid_pull_off_against_direct_curve(name):
    """The law's load-controlled pull-off force against the direct jkr_curve's, H/R from 3 to 0.01."""
    layer, nu, _ = LAYERS[name]
    law = any_thickness_jkr(layer, nu)
    w = WORKS[0]
    for hr in H_OVER_R:
        c, P_off, err = law.pull_off(hr * R, R, w, MU)
        cur = jkr_curve(layer, _paraboloid, c * np.array([0.5, 0.8, 0.95, 1.1, 1.4]), hr * R, MU,
                        work_of_adhesion=w, nu=nu)
        direct = -cur.pull_off_load.force
        assert abs(P_off - direct) <= err + cur.pull_off_load.force_error, (name, hr, P_off, direct, err)
        assert abs(P_off / direct - 1) < 1e-3


@pytest.mark.slow
@pytest.mark.parametrize("nu, layer", [(0.3, BondedLayer(0.3)), (0.5, IncompressibleLayer())])
def test_thin_layer_laws_remainders_at_their_order(nu, layer):
    """(J.11)/(J.15) order 1 at a fixed contact radius c = R/2 and (J.13)/(J.14) order 1 for the flat punch of
    radius R, H/R = 0.1, 0.05, 0.025: the remainder against the direct solver falls like (H/c)^2 (slope >= 1.8)."""
    w = 0.02
    sph = thin_layer_jkr(nu, 1)
    flat = thin_flat_detachment(nu, 1)
    errs_s, errs_f = [], []
    for hr in (0.1, 0.05, 0.025):
        H, c = hr * R, 0.5 * R
        ds = adhesive_state(layer, _paraboloid, c, H, MU, work_of_adhesion=w, energy_route=False)
        d, _ = sph.evaluate(c, H, R, w, MU)
        errs_s.append(abs(float(d) - ds.delta) / (c * c / R))
        det = flat_punch_detachment(layer, R, H, MU, work_of_adhesion=w)
        errs_f.append(abs(float(flat(R, H, w, MU)) / det.force - 1))
    for errs in (errs_s, errs_f):
        slopes = [math.log(errs[i] / errs[i + 1]) / math.log(2) for i in range(2)]
        assert min(slopes) >= 1.8, (nu, errs, slopes)
