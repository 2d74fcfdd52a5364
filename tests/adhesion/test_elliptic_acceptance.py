"""Acceptance cells of the elliptic paraboloid (issue 26 item 6): the thin-layer law (J.25)-(J.31) against the 2D
JKR reference (D.12), (D.13), every difference inside (law estimate + reference estimate).

Kinds of cell (R1 = 1, mu = 0.35):
* ``law``: a thin compressible layer (bonded nu = 0.3, frictionless base): the law :func:`elliptic_jkr` at order 1
  (``law1``, what solve() answers) and order 0 (``law0``) against :func:`jkr_limit_2d` at the same depth: force,
  semi-axes a1, a2.  Lambdas: sigma0 above the JKR edge tension on the layer, sqrt(2 vartheta w/(A H)) (D.13).
* ``half-space``: a thick layer (H = 10 R1): the 2D reference on the layer against the 2D reference on the half-space
  (the thick end; the half-space elliptic JKR of Johnson & Greenwood (1997) is not transcribed).
* ``direct``: bonded nu = 0.5, where no law exists (the contour is not a level set, (J.29)): the reference and its
  estimate only.
* ``front door``: intermediate thickness (H/R1 = 0.2 and 1): what ``thinlayer.solve(..., work_of_adhesion=w)``
  answers (the 2D reference, its estimate), and the law, flagged outside its validity, beside it.

Measured (2026-11-26, diff/allowed, force / a1 / a2; every "now" row with the present estimates; "before" is the
previous stop's table, lambda = 2, 3, the step-only extrapolation estimate, the law at order 0):

    cell (R2/R1, H, w, delta; lambdas, n)        before (law0, lambda 2,3)  law1 now          law0 now
    bonded 0.3,   2, 0.04, 0.005, 0.0108; 4,5 256   0.30/0.30/0.15     0.25/0.00/0.02      0.32/0.23/0.23
    frictionless, 2, 0.04, 0.005, 0.0087; 4,5 256   0.17/0.26/0.07     0.19/0.08/0.06      0.32/0.30/0.36
    bonded 0.3,   4, 0.05, 0.005, 0.0246; 4,5 384   0.30/0.37/0.18     0.19/0.13/0.10      0.22/0.14/0.37
    frictionless, 4, 0.05, 0.005, 0.0226; 4,5 384   0.17/0.47/0.10     0.05/0.12/0.06      0.14/0.33/0.30
    bonded 0.3,   2, 0.04, 0.02, -0.0076; 6,7 256   0.03/0.67/0.71     0.15/0.40/0.29      0.21/0.44/0.41
    frictionless, 2, 0.04, 0.02, -0.0113; 6,7 256   0.10/0.37/0.38     0.62/0.70/0.39      0.48/0.59/0.51
    bonded 0.3,   4, 0.05, 0.02, 0.0044;  6,7 384   0.03/0.78/0.90     0.21/0.32/0.04      0.22/0.38/0.22
    frictionless, 4, 0.05, 0.02, 0.0003;  6,7 384   0.08/0.47/0.54     0.22/0.48/0.11      0.23/0.48/0.33
    half-space vs H = 10, 2, w = 0.05, delta = 0.1   0.22/0.27/0.27     0.24/0.27/0.29
    half-space vs H = 10, 4                          0.61/0.03/0.25     0.73/0.04/0.24

Away from pull-off (w = 0.005) order 1 and the reference agree in the semi-axes to 0.02-0.8 % (order 0: 2-3.5 % high),
well inside the law's own estimate.  Near pull-off (w = 0.02) the law (order 1) lies above the reference by 2.5-4.6 % in
a1, 0.3-2.8 % in a2 and pulls 2-3 % harder: the reference's side, its grid (the zone 2.6 cells wide at lambda = 7): on
the sphere of the mean radius at the same depth the reference is 3.2 % (bonded) and 7.7 % (frictionless, n = 240) low
in radius against the JKR direct solver, while the law at order 1 is within 0.1-0.3 % of it there (the law's own
remainder, measured by (J.11) against the axisymmetric solver at the same H/c, tests/adhesion/test_elliptic_law.py).
These cells pass because the reference's estimate (now true: the grid's change, the analog (D.13)) is large, not
because the numbers agree; a grid twice as fine (n = 512-768, about 4 times the CPU) would be needed to tighten them.
Bonded 0.5 (direct only, R2/R1 = 2, H = 0.04, w = 0.005, delta = 0.02): P = 0.5939 +- 0.0020, a1 = 0.272 +- 0.012,
a2 = 0.364 +- 0.014.
Front door (bonded 0.3, R2/R1 = 2, w = 0.05; solve() picks n = 128, lambda = 2, 3 and the square itself):
H = 0.2, delta = 0.05: P = -0.3651 +- 0.0133, a1 = 0.563 +- 0.050, a2 = 0.810 +- 0.051 (the law, flagged at
a1 = 2.8 H: -0.3715, 0.562, 0.800, within 2 % although outside its validity); H = 1, delta = 0.1: P = -0.3026 +-
0.0123, a1 = 0.724 +- 0.022, a2 = 1.058 +- 0.027 (the law, flagged at a1 = 0.6 H: -0.379, 0.606, 0.866, 16-25 % off).

Each cell costs 1-20 min of CPU (grid Maugis-Dugdale at two lambdas on n and a coarser grid): THINLAYER_SLOW=1 only.
Run as a script to print the table (all cells, or the indices given):  python tests/adhesion/test_elliptic_acceptance.py
"""
import os
import sys
from functools import lru_cache

import pytest

import thinlayer
from thinlayer import BondedLayer, FrictionlessLayer, HalfSpace, IncompressibleLayer, Punch
from thinlayer.asymptotics.adhesion_elliptic import elliptic_jkr
from thinlayer.numerics.cohesive_jkr import jkr_limit_2d

SLOW = os.environ.get("THINLAYER_SLOW") == "1"
slow = pytest.mark.skipif(not SLOW, reason="long validation run: THINLAYER_SLOW=1")
MU = 0.35  # vartheta = 1/2 at nu = 0.3
LAYERS = {"bonded 0.3": (BondedLayer(0.3), None), "frictionless": (FrictionlessLayer(), 0.3),
          "bonded 0.5": (IncompressibleLayer(), None)}
#: (kind, layer, R2/R1, H, w, delta0, extent, n, lambdas[, coarse grid fraction])
CELLS = [
    ("law", "bonded 0.3", 2.0, 0.04, 0.005, 0.0108, 0.4, 256, (4.0, 5.0)),
    ("law", "bonded 0.3", 2.0, 0.04, 0.02, -0.0076, 0.4, 256, (6.0, 7.0), 0.75),
    ("law", "frictionless", 2.0, 0.04, 0.005, 0.0087, 0.4, 256, (4.0, 5.0)),
    ("law", "frictionless", 2.0, 0.04, 0.02, -0.0113, 0.4, 256, (6.0, 7.0), 0.75),
    ("law", "bonded 0.3", 4.0, 0.05, 0.005, 0.0246, 0.68, 384, (4.0, 5.0)),
    ("half-space", "bonded 0.3", 2.0, 10.0, 0.05, 0.1, 1.3, 128, (2.0, 3.0)),
    ("law", "frictionless", 4.0, 0.05, 0.005, 0.0226, 0.68, 384, (4.0, 5.0)),
    ("direct", "bonded 0.5", 2.0, 0.04, 0.005, 0.02, 0.5, 256, (2.0, 3.0)),
    ("law", "bonded 0.3", 4.0, 0.05, 0.02, 0.0044, 0.7, 384, (6.0, 7.0), 0.75),
    ("half-space", "bonded 0.3", 4.0, 10.0, 0.05, 0.1, 1.8, 160, (2.0, 3.0)),
    ("law", "frictionless", 4.0, 0.05, 0.02, 0.0003, 0.7, 384, (6.0, 7.0), 0.75),
    ("front door", "bonded 0.3", 2.0, 0.2, 0.05, 0.05, 0.0, 0, (2.0, 3.0)),
    ("front door", "bonded 0.3", 2.0, 1.0, 0.05, 0.1, 0.0, 0, (2.0, 3.0)),
]
KEYS = (("force", "force_error"), ("a1", "a1_error"), ("a2", "a2_error"))


@lru_cache(maxsize=None)
def reference(kind, name, R2, H, w, delta0, extent, n, lambdas=(2.0, 3.0), coarse=0.5):
    """The 2D JKR reference (D.12), (D.13) of a cell (for ``front door`` cells: solve()'s answer)."""
    layer, nu = LAYERS[name]
    punch = Punch.elliptic_paraboloid(R1=1, R2=R2)
    if kind == "front door":
        return thinlayer.solve(layer if nu is None else layer.with_nu(nu), punch, delta0=delta0, H=H, mu=MU,
                               work_of_adhesion=w)
    return jkr_limit_2d(layer, punch, delta0, H, MU, w=w, extent=extent, n=n, nu=nu, lambdas=lambdas,
                        max_iterations=600, coarse=coarse)


def cell_rows(kind, name, R2, H, w, delta0, extent, n, lambdas=(2.0, 3.0), coarse=0.5):
    layer, nu = LAYERS[name]
    ref = reference(kind, name, R2, H, w, delta0, extent, n, lambdas, coarse)
    others = []
    if kind == "law":
        for order in (1, 0):
            st = elliptic_jkr(layer, nu=nu, order=order).state(delta0, H, 1.0, R2, w, MU)
            assert st.valid, st.reason
            others.append((f"law{order}", st))
    elif kind == "half-space":
        punch = Punch.elliptic_paraboloid(R1=1, R2=R2)
        others.append(("half", jkr_limit_2d(HalfSpace(), punch, delta0, None, MU, w=w, extent=extent, n=n, nu=0.3,
                                            lambdas=lambdas)))
    elif kind == "front door":  # the answer solve() gives (the 2D reference), and the law flagged outside validity
        assert ref.model == "direct" and "thin-layer-jkr" in ref.reason, ref.reason
        flagged = elliptic_jkr(layer, nu=nu, order=1).state(delta0, H, 1.0, R2, w, MU)
        assert not flagged.valid and "< 5 H" in flagged.reason
        others.append(("flagged", flagged))
        ref = ref.detail
    label = f"{kind:10s} {name:12s} R2/R1={R2:g} H={H:g} w={w:g} delta={delta0:g} lam={lambdas[0]:g},{lambdas[1]:g}"
    out = []
    for key, err in KEYS:
        base = {"cell": label, "what": key, "direct": getattr(ref, key), "direct_err": getattr(ref, err)}
        if not others:
            out.append(dict(base, by="-"))
        for tag, other in others:
            row = dict(base, by=tag, law=getattr(other, key), diff=getattr(other, key) - getattr(ref, key),
                       allowed=getattr(other, err) + getattr(ref, err))
            if tag == "flagged":  # outside the law's validity: shown, not held to its estimate
                row["flagged"] = True
            out.append(row)
    return out


@slow
@pytest.mark.parametrize("cell", CELLS, ids=lambda c: f"{c[0]}-{c[1]}-{c[2]:g}-{c[3]:g}-{c[4]:g}")
def test_elliptic_cell(cell):
    for row in cell_rows(*cell):
        if "diff" in row and not row.get("flagged"):
            assert abs(row["diff"]) <= row["allowed"], row
        else:  # direct only (or the law flagged): the reference's estimate is not vacuous
            assert row["direct_err"] < 0.2 * abs(row["direct"]), row


def main(which=None) -> None:
    print(f"{'cell':72s} {'what':5s} {'by':7s} {'law/other':>11s} {'direct':>11s} {'direct est':>10s} {'diff':>10s} "
          f"{'allowed':>10s} diff/allowed", flush=True)
    for i, cell in enumerate(CELLS):
        if which and i not in which:
            continue
        for r in cell_rows(*cell):
            if "diff" in r:
                tail = (f"{r['law']:11.6g} {r['direct']:11.6g} {r['direct_err']:10.3g} {r['diff']:10.3g} "
                        f"{r['allowed']:10.3g} {abs(r['diff']) / r['allowed']:.2f}")
            else:
                tail = f"{'-':>11s} {r['direct']:11.6g} {r['direct_err']:10.3g}"
            print(f"{r['cell']:72s} {r['what']:5s} {r['by']:7s} {tail}", flush=True)


if __name__ == "__main__":
    main({int(v) for v in sys.argv[1:]})
    sys.exit(0)
