"""The 2D JKR reference (D.12): Richardson in lambda^-2 of the grid's Maugis-Dugdale states (issue 26 item 6).

Independent route: on the sphere the axisymmetric JKR direct solver (J.1)-(J.5) (no grid, no cohesive zone), on a
thin (H/R = 0.1) and a thick (H/R = 1) bonded layer; the reference must equal it inside its own estimate.  The
grid runs take 10-30 s each: THINLAYER_SLOW=1.  Default: the input checks (cheap, one line each).
"""
import os

import pytest

from thinlayer import BondedLayer, Punch
from thinlayer._checks import InputError
from thinlayer.numerics.adhesion import adhesive_state
from thinlayer.numerics.cohesive_jkr import jkr_limit_2d

SLOW = os.environ.get("THINLAYER_SLOW") == "1"
slow = pytest.mark.skipif(not SLOW, reason="long validation run: THINLAYER_SLOW=1")
LAYER, MU = BondedLayer(0.3), 0.35  # vartheta = 1/2, E* = 1
SPHERE = Punch.paraboloid(R=1)


def test_refuses_bad_lambdas():
    with pytest.raises(InputError, match="lambdas must increase"):
        jkr_limit_2d(LAYER, SPHERE, 0.01, 0.1, MU, w=0.01, extent=0.4, lambdas=(3.0, 2.0))
    with pytest.raises(InputError, match="two positive numbers"):
        jkr_limit_2d(LAYER, SPHERE, 0.01, 0.1, MU, w=0.01, extent=0.4, lambdas=(3.0,))


@slow
@pytest.mark.parametrize("H, w, c, extent", [(0.1, 0.01, 0.3, 0.42), (1.0, 0.05, 0.8, 1.05)])
def test_sphere_reference_equals_the_axisymmetric_jkr_solver(H, w, c, extent):
    """Measured (n = 128/64, lambda = 2, 3, with the analog (D.13)): thin, force 2.3e-4 off (estimate 6.6e-4, 1.2 % of
    the force), radius 6e-4 (estimate 0.020); thick, force 4.9e-3 off (estimate 1.3e-2, 11 % of the force), radius
    2.5e-3 (estimate 0.021)."""
    js = adhesive_state(LAYER, lambda r: r * r / 2, c, H, MU, work_of_adhesion=w, energy_route=False)
    ref = jkr_limit_2d(LAYER, SPHERE, js.delta, H, MU, w=w, extent=extent, n=128)
    assert abs(ref.force - js.force) <= ref.force_error + js.force_error
    assert abs(ref.a1 - c) <= ref.a1_error and abs(ref.a2 - c) <= ref.a2_error
    assert ref.force_error < 0.15 * abs(js.force)  # the estimate is not vacuous
