"""fit() with the tips' any-thickness tables (issue 25 item 1): the cone (T.9), the regular pyramids (T.11)-(T.13)
and the flat punch (F.1) at finite thickness through the registry's force curves, on data from independent routes.

The data are never the tables themselves: the cone's forces come from the any-thickness equation (F.6) with the
tip's load (:func:`thinlayer.numerics.revolution.revolution_contact`, ~1e-12 against the direct solver) and from the
direct solutions stored with the table as its validation points (off the table's nodes); the pyramid's from the
thick-layer series (T.12) where the table is solve_2d's; the flat punch's from the thick-layer series (F.18).
"""
import math
import warnings
from functools import lru_cache

import numpy as np
import pytest

from thinlayer.contact.fit import curve_entries, fit
from thinlayer.errors import ValidityWarning
from thinlayer.punch import Punch

pytestmark = pytest.mark.xdist_group("afm-laws")  # shares the cone and pyramid laws with the nanite tests
TAN70 = math.tan(math.radians(70))


@lru_cache(maxsize=1)
def _cone_on_incompressible():
    """(depths, forces at mu = 1) of the 70-degree cone on a bonded nu = 1/2 layer of H = 1 by (F.6)."""
    from thinlayer.layers.kernels import IncompressibleLayer
    from thinlayer.numerics.revolution import revolution_contact

    d = np.array([0.15, 0.5, 1.0])  # chi = c_0/H = 0.26, 0.87, 1.75
    P = np.array([revolution_contact(IncompressibleLayer(), Punch.cone(70), x, 1.0, mu=1.0).force for x in d])
    return d, P


def test_the_tables_are_fit_models_where_they_cover_the_layer():
    """The reproduction of the brief: the bonded incompressible cone had only 'direct' (the layers without a
    thin-layer tip law here: curve_entries builds every entry's curve, and the tip law's is a symbolic derivation)."""
    from thinlayer.contact.fit import fit_law
    from thinlayer.contact.models import fit_entry
    from thinlayer.contact.models.tip_tables import tip_table_curve

    assert curve_entries(Punch.cone(70), 0.5, "bonded") == ["any-thickness", "direct"]
    assert curve_entries(Punch.pyramid(35, 4), 0.5, "bonded") == ["any-thickness"]
    assert curve_entries(Punch.flat(1.0), 0.5, "bonded") == ["direct"]
    assert fit_law(Punch.cone(70), 1.0, 0.5, "bonded").model == "any-thickness"
    assert fit_entry("any-thickness") is not None
    assert tip_table_curve(Punch.cone(70), 1.0, 0.3, "frictionless", math.inf) is not None
    assert tip_table_curve(Punch.berkovich(), 1.0, 0.3, "bonded", math.inf) is not None
    assert tip_table_curve(Punch.cone(70), 1.0, 0.2, "bonded", math.inf) is None  # below the table's nu = 0.3
    assert tip_table_curve(Punch.blunted_cone(1.0, 70), 1.0, 0.5, "bonded", math.inf) is None  # no table


def test_cone_on_a_bonded_incompressible_layer_recovers_E_and_H():
    """E (H given) within the law's own estimate; E and H (free, started 30 % off) within a few estimates."""
    d, P = _cone_on_incompressible()
    E = 1234.0
    F = E / 3.0 * P  # mu = 1 is E = 3 at nu = 1/2
    r = fit(d, F, Punch.cone(70), H=1.0, nu=0.5)
    assert r.model == "any-thickness" and r.valid
    assert 0 < r.model_error < 1e-3
    assert abs(r.E / E - 1) <= r.model_error
    f = fit(d, F, Punch.cone(70), H=1.3, nu=0.5, fit_H=True)
    assert abs(f.E / E - 1) <= 3 * f.model_error and abs(f.H - 1.0) <= 3 * f.model_error


def test_cone_on_a_frictionless_base_from_the_stored_direct_solutions():
    """The table's frictionless validation points (direct solutions off the nodes): P/P_0 at chi, so the force at
    depth delta = chi H pi/(2 tan(alpha)) is (4/pi) vartheta tan(alpha) delta^2 P/P_0."""
    from thinlayer.contact.any_thickness_tips import TIPS_TABLE_PATH

    with np.load(TIPS_TABLE_PATH) as f:
        check = f["check"]
    rows = check[(check[:, 0] == 0) & (check[:, 2] <= 25)]
    assert rows.shape[0] >= 4
    H, nu, E = 2.0, 0.5, 50.0
    chi, ratio = rows[:, 2], rows[:, 3]
    d = chi * H * math.pi / (2 * TAN70)
    F = 4 / math.pi * (E / (2 * (1 + nu)) / (1 - nu)) * TAN70 * d * d * ratio
    r = fit(d, F, Punch.cone(70), H=H, nu=nu, base="frictionless", model="any-thickness")
    assert r.model == "any-thickness" and r.valid
    assert abs(r.E / E - 1) <= r.model_error


def test_pyramid_on_a_bonded_incompressible_layer_against_the_thick_series():
    """The 4-sided pyramid's table (solve_2d above chi = 0.1) against the thick-layer series (T.12) at chi = 0.1 ..
    0.25 (solve(model='any-thickness') is the series): E within both estimates."""
    from thinlayer import solve
    from thinlayer.layers.kernels import IncompressibleLayer

    tip = Punch.pyramid(35, 4)
    d = np.array([0.12, 0.18, 0.25]) / math.tan(math.radians(35))  # chi = delta tan(alpha)/H
    ans = [solve(IncompressibleLayer(), tip, H=1.0, delta0=x, mu=1.0, nu=0.5, model="any-thickness") for x in d]
    P = np.array([a.force for a in ans])
    series_est = max(a.error_estimate["force"] for a in ans)
    r = fit(d, 7.0 * P, tip, H=1.0, nu=0.5)
    assert r.model == "any-thickness" and r.valid
    assert abs(r.E / 21.0 - 1) <= r.model_error + series_est
    f = fit(d, 7.0 * P, tip, H=1.2, nu=0.5, fit_H=True)
    assert abs(f.H - 1.0) < 0.05 and abs(f.E / 21.0 - 1) < 0.01


def test_flat_punch_E_at_finite_thickness_and_H_refused():
    """kappa of the thick-layer series (F.18) at a/H = 0.25 (its estimate (F.19) below 1e-4): E within it; the flat
    punch's curve gives one stiffness, so fitting H too is refused with one line."""
    from thinlayer.asymptotics.flat_punch import thick_flat_punch
    from thinlayer.layers.kernels import BondedLayer

    law = thick_flat_punch(BondedLayer(0.3))
    x = np.array([0.25])
    kappa, est = float(law(x)[0]), float(law.error_estimate(x)[0])
    assert est < 1e-4
    a, H, nu, E = 1.0, 4.0, 0.3, 10.0
    d = np.linspace(0.01, 0.2, 8)
    F = 2 * E * a / (1 - nu * nu) * kappa * d  # P = 4 mu a kappa delta/(1 - nu)
    r = fit(d, F, Punch.flat(a), H=H, nu=nu)
    assert r.model == "direct" and r.valid
    assert abs(r.E / E - 1) <= est + 1e-9
    with pytest.raises(ValueError, match="one stiffness"):
        fit(d, F, Punch.flat(a), H=H, nu=nu, fit_H=True)


def test_beyond_the_cone_table_the_fit_is_flagged_not_valid():
    """chi = c_0/H beyond the table's end (about 29): the numbers come back marked NOT VALID, never unflagged."""
    d, P = _cone_on_incompressible()
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = fit(d, P, Punch.cone(70), H=0.03, nu=0.5)  # chi up to 58
    assert not r.valid and "NOT VALID" in str(r)
    assert any(issubclass(x.category, ValidityWarning) for x in w)
