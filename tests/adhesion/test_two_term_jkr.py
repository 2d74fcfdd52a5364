"""JKR near nu = 1/2 through the two-term model (issue 26 item 1): (J.19)-(J.23) of
:mod:`thinlayer.asymptotics.adhesion_two_term`, and the second-order compressible law (J.24).

Independent sources: the direct JKR solver (J.1)-(J.6) with the exact kernel (``numerics/adhesion.py``); mpmath
quadrature and differentiation of the two-term flat punch's pressure; the limits (J.10)/(J.11) and (J.15) of
:mod:`thinlayer.asymptotics.adhesion`, themselves measured against the direct solver in ``test_adhesion_jkr.py``.

Scaling of the comparisons: ``R = c^2/(2H)`` (the smooth depth is ``O(H)``), ``w`` such that the law's flat part
``d`` is a quarter of its smooth depth (adhesion carries a quarter of the depth whatever ``lambda``).
"""
import math
from functools import lru_cache

import mpmath
import numpy as np
import pytest

from thinlayer import BondedLayer
from thinlayer.asymptotics.adhesion import thin_layer_jkr
from thinlayer.asymptotics.adhesion_two_term import two_term_jkr, two_term_jkr_derivation
from thinlayer.errors import InputError
from thinlayer.numerics.adhesion import adhesive_state

pytestmark = pytest.mark.xdist_group("adhesion-laws")  # shares the laws' sympy builds with the adhesion tests

H = 1.0


def _work(law, c, R):
    """``w`` with ``d = -delta_1/4`` (d grows like sqrt(w))."""
    d1 = float(law.evaluate(c, H, R, 0.0)[0])
    d_one = float(law.evaluate(c, H, R, 1.0)[0]) - d1
    return (0.25 * d1 / d_one) ** 2


@lru_cache(maxsize=None)
def _point(nu, lam):
    """Relative errors ``(delta, P)`` of the two-term law, (J.11) and (J.15), and (true error)/(estimate)."""
    law = two_term_jkr(nu)
    c, R = lam * H, lam * lam * H / 2
    w = _work(law, c, R)
    st = adhesive_state(BondedLayer(nu), lambda r, R=R: r * r / (2 * R), c, H, work_of_adhesion=w, energy_route=False)
    out = {}
    for name, other in (("two-term", law), ("J.11", thin_layer_jkr(nu, 1)), ("J.15", thin_layer_jkr(0.5, 1))):
        with np.errstate(invalid="ignore"):  # (J.11) at nu = 0.499: c + h* H < 0 below c/H = 11.5 (nan)
            d, P = (float(v) for v in other.evaluate(c, H, R, w))
        out[name] = (abs(d / st.delta - 1), abs(P / st.force - 1))
    ed, eP = (float(v) for v in law.error_estimate(c, H, R, w))
    d, P = (float(v) for v in law.evaluate(c, H, R, w))
    out["ratio"] = (abs(d - st.delta) / ed, abs(P - st.force) / eP)
    return out


# --------------------------------------------------------------------------- the derivation
def test_derivation_checks_and_limits():
    """(J.19)-(J.22) derived in sympy; x -> 0 gives (J.15) exactly, x -> oo gives (J.10) to O(H) and the depth
    of (J.11) plus the m_1 H^2/R term of (SO.10) to O(H^2) (Hankel's expansion)."""
    der = two_term_jkr_derivation()
    what = [w for w, _ in der.checks]
    assert what == ["(I.10) solved", "(J.19) S", "(J.20) G", "(J.20) in sigma", "(J.22) G = w",
                    "x -> 0: (J.15) delta", "x -> 0: (J.15) P", "x -> oo: (J.10) G",
                    "x -> oo: (J.11) delta_1 to O(H^2)"]
    assert all(rung in ("==", "expand/cancel", "simplify") for _, rung in der.checks)
    tags = [t for t, _ in der.steps()]
    assert tags == ["J.19", "J.20", "J.22"]
    assert all(r"\tag{" + t + "}" in tex for t, tex in der.steps())


def test_flat_punch_stiffness_and_release_rate_mpmath():
    """(J.19) against mpmath quadrature of p(r) r, (J.20) against mpmath's derivative of S (J.4), nu = 0.49."""
    law = two_term_jkr(0.49)
    vt, m1, A = 1 / 0.51, law.m1, law.A
    k = 1 / math.sqrt(m1)
    for c in (12.0,):
        ae = c + law.h

        def S_quad(ae):  # P/d by quadrature of (vartheta/(A H))(1 - I_0(k r)/I_0(k a_e)) over the disc
            f = lambda r: (1 - mpmath.besseli(0, k * r) / mpmath.besseli(0, k * ae)) * r  # noqa: E731
            return 2 * mpmath.pi * vt / A * mpmath.quad(f, [0, ae])

        assert float(law.stiffness(c, H)) == pytest.approx(float(S_quad(ae)), rel=1e-12)
        dS = mpmath.diff(S_quad, ae)
        d = -0.3
        assert float(law.release_rate(c, d, H)) == pytest.approx(float(d * d * dS / (4 * mpmath.pi * c)), rel=1e-10)


def test_limits_in_numbers():
    """nu = 1/2: the two-term law is (J.15) to rounding; nu = 0.49, c/H = 2000 (lambda^2 = 2.6e5): it differs from
    (J.11) order 1 by the m_1 term of the depth, 2 m_1 (H/c)^2 relative (x -> oo in (J.22)), by O((H/c)^3) in the
    force, and G = w holds at its d (J.20)."""
    a, b = two_term_jkr(0.5), thin_layer_jkr(0.5, 1)
    for c, R, w in ((10.0, 12.5, 0.3), (40.0, 200.0, 2.0)):
        for x, y in zip(a.evaluate(c, H, R, w), b.evaluate(c, H, R, w)):
            assert float(x) == pytest.approx(float(y), rel=1e-12)
    a, b = two_term_jkr(0.49), thin_layer_jkr(0.49, 1)
    c, w = 2000.0, 0.05 / 0.51
    R = c * c / 2
    (da, Pa), (db, Pb) = a.evaluate(c, H, R, w), b.evaluate(c, H, R, w)
    assert 1.8 < (float(da) / float(db) - 1) / (a.m1 * (H / c) ** 2) < 2.5
    assert abs(float(Pa) / float(Pb) - 1) < 0.1 * (H / c) ** 2
    d = float(da) - float(a.evaluate(c, H, R, 0.0)[0])
    assert float(a.release_rate(c, d, H)) == pytest.approx(w, rel=1e-12)


def test_against_direct_in_the_crossover():
    """nu = 0.49, c/H = 10 and 20 (lambda^2 = 6.5, 26): the two-term law is within its estimate and falls faster
    than (H/c)^2, where (J.11) errs by 40 % and (J.15) by 80 % in the force."""
    p10, p20 = _point(0.49, 10.0), _point(0.49, 20.0)
    assert p10["two-term"][0] < 0.02 and p10["two-term"][1] < 0.05
    assert p20["two-term"][0] < 2e-3 and p20["two-term"][1] < 0.01
    assert p10["J.11"][0] > 0.3 and p10["J.15"][1] > 0.5
    assert math.log2(p10["two-term"][0] / p20["two-term"][0]) > 2.5
    assert math.log2(p10["two-term"][1] / p20["two-term"][1]) > 2.0
    assert max(p10["ratio"] + p20["ratio"]) < 1.0


@pytest.mark.slow
def test_table_against_direct():
    """The table (THINLAYER_SLOW=1): nu = 0.45, 0.49, 0.499 x c/H = 5, 10, 20, 40; the estimate holds everywhere,
    the depth's remainder falls with slope >= 2.8 and the force's with slope >= 1.8 between c/H = 20 and 40."""
    lines = []
    for nu in (0.45, 0.49, 0.499):
        for lam in (5.0, 10.0, 20.0, 40.0):
            p = _point(nu, lam)
            assert max(p["ratio"]) < 1.0
            lines.append(f"{nu:6g} {lam:5g} " + " ".join(f"{v:9.2e}" for k in ("two-term", "J.11", "J.15", "ratio")
                                                           for v in p[k]))
        a, b = _point(nu, 20.0)["two-term"], _point(nu, 40.0)["two-term"]
        assert math.log2(a[0] / b[0]) > 2.8 and math.log2(a[1] / b[1]) > 1.8
    print("\n".join(lines))


def test_pull_off_limits():
    """(J.23): at nu = 1/2 the pull-off of (J.15) order 1; at nu = 0.49 it falls from above 2 pi w R in the crossover
    (2.36 at R = 1000 H, lambda^2 = 9.6) to the compressible 2 pi w R of (J.12) (R = 1e8 H, lambda^2 = 6e5)."""
    a, b = two_term_jkr(0.5), thin_layer_jkr(0.5, 1)
    (ca, Pa), (cb, Pb) = a.pull_off(H, 1000.0, 0.1), b.pull_off(H, 1000.0, 0.1)
    assert Pa == pytest.approx(Pb, rel=1e-9) and ca == pytest.approx(cb, rel=1e-6)
    law, w = two_term_jkr(0.49), 0.05
    ratios = [law.pull_off(H, R, w)[1] / (math.pi * w * R) for R in (1e3, 1e8)]
    assert 2.2 < ratios[0] < 2.5 and abs(ratios[1] - 2) < 0.005


@pytest.mark.slow
def test_pull_off_against_direct():
    """(J.23) against the direct JKR curve's load-controlled pull-off (J.6), nu = 0.49, R = 1000 H (c_p = 12 H,
    lambda^2 = 9.6): measured 6.2e-3 relative (1000 H), 5.1e-4 (10^4 H, c_p = 33 H)."""
    import numpy as np

    from thinlayer.numerics.adhesion import jkr_curve

    law, w, R = two_term_jkr(0.49), 0.05, 1000.0
    cp, Pp = law.pull_off(H, R, w)
    cur = jkr_curve(BondedLayer(0.49), lambda r: r * r / (2 * R), np.linspace(0.6 * cp, 1.6 * cp, 6), H,
                    work_of_adhesion=w)
    assert abs(Pp / -cur.pull_off_load.force - 1) < 0.01
    assert abs(cp / cur.pull_off_load.radius - 1) < 0.01


def test_bad_input():
    for bad in (0.25, 0.2, 0.6, "x", None):
        with pytest.raises(InputError, match="nu"):
            two_term_jkr(bad)
    with pytest.raises(InputError):
        two_term_jkr(0.49).evaluate(-1.0, H, 10.0, 0.1)


# --------------------------------------------------------------------------- (J.24) the next order
def _order2(nu, lams, wf=0.05):
    """Depth errors of (J.11) order 1 and (J.24) order 2 against the direct solver; the estimates hold."""
    lay, vt = BondedLayer(nu), 1 / (1 - nu)
    wv = wf * vt * H
    laws = thin_layer_jkr(nu, 1), thin_layer_jkr(nu, 2)
    out = []
    for lam in lams:
        c, R = lam * H, lam * lam * H / 2
        st = adhesive_state(lay, lambda r, R=R: r * r / (2 * R), c, H, work_of_adhesion=wv, energy_route=False)
        row = []
        for law in laws:
            d, P = (float(v) for v in law.evaluate(c, H, R, wv))
            ed, eP = (float(v) for v in law.error_estimate(c, H, R, wv))
            assert abs(d - st.delta) <= ed and abs(P - st.force) <= eP
            row.append(abs(d - st.delta))
        out.append(row)
    return out


def test_second_order_depth():
    """(J.24): nu = 0.3, c/H = 10, 20: the order-2 depth error falls like (H/c)^3 (measured 0.138 (H/c)^3 H),
    order 1's like (H/c)^2; the force is order 1's (already O((H/c)^3)); order 2 is refused at nu = 1/2."""
    (a1, a2), (b1, b2) = _order2(0.3, (10.0, 20.0))
    assert 1.8 < math.log2(a1 / b1) < 2.2
    assert 2.8 < math.log2(a2 / b2) < 3.2
    assert b2 < 0.06 * b1
    assert 0.12 < b2 * 20.0**3 / H < 0.16
    law = thin_layer_jkr(0.3, 2)
    assert law.equation == "J.24" and r"\tag{J.24}" in law.latex()
    assert law.force == thin_layer_jkr(0.3, 1).force
    with pytest.raises(InputError, match="order 2"):
        thin_layer_jkr(0.5, 2)


@pytest.mark.slow
def test_second_order_depth_long():
    """(J.24) from c/H = 5 to 80 at nu = 0.3 (THINLAYER_SLOW=1): slope 3.0 (order 1: 2.0); the estimate holds at
    nu = -0.5, 0, 0.3, 0.45 and w/(vartheta H) = 0.05, 0.5."""
    lams = [5.0, 10.0, 20.0, 40.0, 80.0]
    rows = _order2(0.3, lams)
    s1 = [math.log2(rows[i][0] / rows[i + 1][0]) for i in range(len(lams) - 1)]
    s2 = [math.log2(rows[i][1] / rows[i + 1][1]) for i in range(len(lams) - 1)]
    assert all(1.9 < s < 2.1 for s in s1[1:]) and all(2.9 < s < 3.1 for s in s2)
    for nu in (-0.5, 0.0, 0.45):
        for wf in (0.05, 0.5):
            _order2(nu, [5.0, 10.0, 20.0, 40.0], wf)


# --------------------------------------------------------------------------- the front door
def test_door_uses_the_two_term_law_where_the_regime_says_so():
    """solve(..., work_of_adhesion=w), model "thin-layer-jkr": at nu = 0.49 (lambda^2 = 12, (I.13) says not
    compressible) the answer is the two-term law (J.22) at the contact radius it reports, within its estimate of
    the direct solver's state at that radius; at nu = 0.3 (lambda^2 = 2600) it is (J.11) as before."""
    from thinlayer import Punch, solve

    ans = solve(BondedLayer(0.49), Punch.paraboloid(200.0), delta0=0.3, H=H, mu=1.0, work_of_adhesion=0.05,
                model="thin-layer-jkr", tol=0.3)
    assert ans.model == "thin-layer-jkr" and ans.equations == ("J.22", "J.22")
    c = ans.contact_radius
    d, P = (float(v) for v in two_term_jkr(0.49).evaluate(c, H, 200.0, 0.05))
    assert d == pytest.approx(0.3, rel=1e-9) and abs(P) == pytest.approx(ans.force, rel=1e-9)
    st = adhesive_state(BondedLayer(0.49), lambda r: r * r / 400.0, c, H, work_of_adhesion=0.05, energy_route=False)
    assert abs(st.force / P - 1) < ans.error_estimate["force"] and abs(st.delta / 0.3 - 1) < ans.error_estimate["depth"]
    ans = solve(BondedLayer(0.3), Punch.paraboloid(200.0), delta0=0.3, H=H, mu=1.0, work_of_adhesion=0.05,
                model="thin-layer-jkr")
    assert ans.equations == ("J.11", "J.11")
