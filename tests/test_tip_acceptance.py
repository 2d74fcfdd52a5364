"""Acceptance grid of the tips (issue 24, item 7): :func:`thinlayer.solve` with every tip against the direct solver.

The grid is {exact sphere R = 10, cone 70 deg, blunted cone R = 1 / 70 deg, 4-sided pyramid 35 deg} x {bonded nu =
0.3, 0.45, 0.5; frictionless base nu = 0.3} x chi = a/H in {0.1, 0.3, 1, 3, 10, 20} (``a`` the radius of the rigid
overlap ``{Phi < delta0}``; chi = 20 is the thin-layer regime: at nu = 1/2 the contact radius is then about 27 H, near
the direct reference's work limit). ``solve(model="auto")`` answers each cell with the model that holds (the thin-
layer tip law (1.8) read through the level set, an any-thickness law, or the axisymmetric direct solver);
:meth:`Indentation.compare_direct` solves the same problem with the axisymmetric spectral solver, or the 2D FFT solver
for the pyramid (1.4 times the modes or cells when the answer is itself direct). Every relative difference of the
force, the contact area and the contact radius must lie inside the estimate ``solve()`` states plus the reference's
own estimate.

The default run takes the cells of :data:`DEFAULT_CELLS` (each tip, each base, both ends of chi and the thin-law
boundary); ``THINLAYER_SLOW=1`` runs all 96. ``python tests/test_tip_acceptance.py`` prints the whole table (model,
differences and estimates per cell) for the closing note.
"""
from __future__ import annotations

import math
import sys

import pytest

import thinlayer as tl

LAYERS = {
    "bonded nu=0.3": lambda: tl.BondedLayer(0.3),
    "bonded nu=0.45": lambda: tl.BondedLayer(0.45),
    "bonded nu=0.5": lambda: tl.BondedLayer(0.5),
    "frictionless nu=0.3": lambda: tl.FrictionlessLayer(0.3),
}
DELTA0 = 0.5
#: tip factory and the radius a of its rigid overlap {Phi < delta0} at delta0 = 0.5 (closed forms, not the engine's)
TIPS = {
    "sphere": (lambda: tl.Punch.sphere(10), math.sqrt(2 * 10 * DELTA0 - DELTA0**2)),
    "cone70": (lambda: tl.Punch.cone(70), DELTA0 * math.tan(math.radians(70))),
    # blunted cone R = 1, 70 deg: sphere cap up to r_t = R cos(alpha), then the tangent cone
    "blunted": (lambda: tl.Punch.blunted_cone(1, 70), None),
    # 4-sided pyramid, face angle 35 deg: the overlap is a square of inradius delta0 tan(35 deg), its half-width
    # a = 2|omega_0|/|Gamma_0| = the inradius; the reference is the 2D FFT solver
    "pyramid35": (lambda: tl.Punch.pyramid(35, 4), DELTA0 * math.tan(math.radians(35))),
}
CHI = (0.1, 0.3, 1.0, 3.0, 10.0, 20.0)
DEFAULT_CELLS = {  # one cell per tip and base kind, mostly where a law answers (one direct reference each)
    ("sphere", "frictionless nu=0.3", 3.0), ("cone70", "bonded nu=0.3", 20.0),
    ("blunted", "bonded nu=0.45", 20.0), ("pyramid35", "bonded nu=0.3", 20.0),
}


def _blunted_radius(R: float, alpha_deg: float, delta0: float) -> float:
    """The overlap radius of the blunted cone by its geometry: the cap R - sqrt(R^2 - r^2), tangent to the cone."""
    a = math.radians(alpha_deg)
    r_t = R * math.cos(a)
    z_t = R - math.sqrt(R * R - r_t * r_t)
    if delta0 <= z_t:
        return math.sqrt(2 * R * delta0 - delta0**2)
    return r_t + (delta0 - z_t) * math.tan(a)


def overlap_radius(tip: str) -> float:
    a = TIPS[tip][1]
    return _blunted_radius(1.0, 70.0, DELTA0) if a is None else a


def cell(tip: str, layer: str, chi: float) -> dict:
    """Solve one cell with ``model="auto"`` and compare with the direct solver; the row of the table."""
    H = overlap_radius(tip) / chi
    ans = tl.solve(LAYERS[layer](), TIPS[tip][0](), delta0=DELTA0, H=H, mu=1.0)
    cmp = ans.compare_direct()
    rows = {key: (diff, est + cmp.direct.error_estimate.get(key, 0.0)) for key, _v, _d, diff, est in cmp.rows}
    return {"model": ans.model, "force": ans.force, "estimate": dict(ans.error_estimate), "rows": rows,
            "direct_model": cmp.direct.model}


def _params():
    slow = pytest.mark.slow
    return [pytest.param(t, lay, chi, id=f"{t}-{lay.replace(' ', '_')}-chi{chi:g}",
                         marks=[] if (t, lay, chi) in DEFAULT_CELLS else [slow])
            for t in TIPS for lay in LAYERS for chi in CHI]


@pytest.mark.parametrize(("tip", "layer", "chi"), _params())
def test_every_tip_agrees_with_the_direct_solver_inside_its_estimate(tip, layer, chi):
    out = cell(tip, layer, chi)
    assert math.isfinite(out["force"]) and out["force"] > 0
    assert out["direct_model"] == "direct"
    assert set(out["rows"]) >= ({"force", "contact_area"} if tip == "pyramid35" else
                                {"force", "contact_area", "contact_radius"})
    for key, (diff, allowed) in out["rows"].items():
        assert diff <= allowed, f"{tip} {layer} chi={chi} ({out['model']}): {key} differs by {diff:.3g} > {allowed:.3g}"


def test_the_overlap_radii_are_the_tips_level_sets():
    # the grid's chi uses closed-form radii; they must be the tips' own level sets (independent: geometry vs engine)
    for tip in TIPS:
        assert TIPS[tip][0]().level_set(DELTA0).half_width == pytest.approx(overlap_radius(tip), rel=1e-12)


if __name__ == "__main__":  # the table for the closing note
    print(f"{'tip':8} {'layer':20} {'chi':>5} {'model':14} {'force diff':>11} {'allowed':>9} {'area diff':>10} "
          f"{'allowed':>9} {'radius diff':>11} {'allowed':>9}  ok")
    bad = 0
    for t in TIPS:
        for lay in LAYERS:
            for chi in CHI:
                out = cell(t, lay, chi)
                r = out["rows"]
                ok = all(d <= a for d, a in r.values())
                bad += not ok
                print(f"{t:8} {lay:20} {chi:5g} {out['model']:14} "
                      + " ".join(f"{r[k][0]:11.2e} {r[k][1]:9.2e}" if k in r else f"{'-':>11} {'-':>9}"
                                 for k in ("force", "contact_area", "contact_radius"))
                      + f"  {'yes' if ok else 'NO'}", flush=True)
    print(f"{bad} cell(s) outside the estimate")
    sys.exit(1 if bad else 0)
