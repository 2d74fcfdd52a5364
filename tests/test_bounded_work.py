"""Issue 12 item 7: orders, degrees, grid sizes and memory are checked before any work starts.

Each refusal is shown to come before the heavy call: the heavy function is replaced by one that fails the
test if it is reached (no timing).
"""
from __future__ import annotations

import pytest

import thinlayer as tl
from thinlayer._checks import WorkLimitError, check_bounded
from thinlayer.layers import coefficients as coef_mod
from thinlayer.numerics import _spectral, fft2d, obstacle
from thinlayer.symbols import x1, x2


def _forbid(monkeypatch, module, name):
    def boom(*a, **k):
        raise AssertionError(f"{name} was called: the limit must be checked before the work")
    monkeypatch.setattr(module, name, boom)


def test_check_bounded_message():
    assert check_bounded(3, "order", 30, "why") == 3
    with pytest.raises(WorkLimitError, match=r"^order = 31 exceeds the limit 30: because$"):
        check_bounded(31, "order", 30, "because")
    assert issubclass(WorkLimitError, ValueError)


@pytest.mark.parametrize("layer, limit", [(tl.BondedLayer(), 30), (tl.BondedLayer("3/10"), 200),
                                          (tl.BondedLayer(0.3), 500), (tl.FrictionlessLayer(), 200),
                                          (tl.GenericLayer(), 12)])
def test_coefficient_order_refused_before_work(monkeypatch, layer, limit):
    _forbid(monkeypatch, coef_mod, "quotient_field")
    _forbid(monkeypatch, coef_mod, "quotient_fraction_free")
    _forbid(monkeypatch, coef_mod, "reciprocal_recurrence")
    coef_mod.kernel_coefficients.cache_clear()
    with pytest.raises(WorkLimitError, match=rf"order = {limit + 1} exceeds the limit {limit}: .*\d s"):
        tl.kernel_coefficients(layer, limit + 1)
    with pytest.raises(WorkLimitError, match="exceeds the limit"):
        layer.m(100000)  # the issue: m(100) ran over 150 s
    with pytest.raises(WorkLimitError, match="exceeds the limit"):
        layer.moment(2 * limit + 2, 0)


def test_symbolic_m100_refused():
    with pytest.raises(WorkLimitError, match=r"order = 100 exceeds the limit 30: symbolic nu"):
        tl.BondedLayer().m(100)


def test_incompressible_and_inversion_bounded(monkeypatch):
    _forbid(monkeypatch, coef_mod, "quotient_field")
    with pytest.raises(WorkLimitError, match="order = 201 exceeds the limit 200"):
        coef_mod.incompressible_coefficients(201)
    with pytest.raises(WorkLimitError, match="order = 31 exceeds the limit 30"):
        coef_mod.reciprocal_by_inversion(tl.BondedLayer(), 31)


def test_dps_bounded():
    with pytest.raises(WorkLimitError, match="dps = 1001 exceeds the limit 1000"):
        tl.BondedLayer(0.3, dps=1001)
    assert tl.BondedLayer(0.3, dps=1000).dps == 1000


def test_inner_order_refused_before_work(monkeypatch):
    _forbid(monkeypatch, coef_mod, "quotient_fraction_free")
    coef_mod.kernel_coefficients.cache_clear()
    punch = tl.Punch.elliptic_paraboloid()
    with pytest.raises(WorkLimitError, match=r"^order = 100000 exceeds the limit 31: the inner expansion"):
        tl.inner_pressure(tl.BondedLayer(), punch, order=100000)  # the issue: grew to 24 GB
    with pytest.raises(WorkLimitError, match="order = 202 exceeds the limit 201"):
        tl.inner_pressure(tl.BondedLayer("3/10"), punch, order=202)


def test_inner_order_at_limit_allowed_exact():
    ip = tl.inner_pressure(tl.BondedLayer("3/10"), tl.Punch.paraboloid(R=1), order=201)
    assert ip.order == 201 and ip.nonzero_terms == 2


def test_moment_expansion_order_bounded():
    from thinlayer.asymptotics.moment_expansion import moment_expansion
    with pytest.raises(WorkLimitError, match="order = 31 exceeds the limit 30"):
        moment_expansion(tl.BondedLayer(), 31)


def test_punch_degree_bounded():
    # x_1**100000 would make sympy's dense Poly of 100001 entries: refused from the expression tree
    with pytest.raises(tl.PunchError, match="degree 100000 in x_1, x_2, above the limit 40"):
        tl.Punch(x1**100000 + x2**2)
    with pytest.raises(tl.PunchError, match="degree 42 in x_1, x_2, above the limit 40"):
        tl.Punch((x1**2 + x2**2) ** 21)
    with pytest.raises(tl.PunchError, match="degree = 41 exceeds the limit 40"):
        tl.Punch.general(41)
    assert tl.Punch((x1**2 + x2**2) ** 20).degree == 40
    # a bound above the limit that cancels is measured exactly
    assert tl.Punch((x1**2 + x2**2) ** 25 - (x1**2 + x2**2) ** 25 + x1**2 + x2**2).degree == 2


def test_punch_degree_string_bounded():
    with pytest.raises(tl.PunchError, match="above the limit 40"):
        tl.Punch("x_1**1000 + x_2**2")


@pytest.mark.parametrize("delta0, H", [(0.1, 1e-6), (1e6, 0.1)])
def test_axisymmetric_refused_before_work(monkeypatch, delta0, H):
    """The issue: H = 1e-6 tried to allocate 166 GiB; delta0 = 1e6, H = 0.1 ran 300 s."""
    _forbid(monkeypatch, _spectral.Discretisation, "build")
    with pytest.raises(WorkLimitError, match=r"work estimate .* exceeds the limit 2e\+08: .*increase H"):
        tl.solve_axisymmetric(tl.BondedLayer(0.3), tl.Punch.paraboloid(R=10), delta0, H)


def test_contact_for_radius_refused_before_work(monkeypatch):
    from thinlayer.numerics import contact_for_radius
    _forbid(monkeypatch, _spectral.Discretisation, "build")
    with pytest.raises(WorkLimitError, match="layer thicknesses"):
        contact_for_radius(tl.BondedLayer(0.3), tl.Punch.paraboloid(R=10), 1.0, 1e-4)
    with pytest.raises(WorkLimitError, match="600\\^2 modes"):
        contact_for_radius(tl.BondedLayer(0.3), tl.Punch.paraboloid(R=10), 1.0, 0.05, n=600)


def test_axisymmetric_half_space_not_limited():
    res = tl.solve_axisymmetric(tl.HalfSpace(), tl.Punch.paraboloid(R=2), 0.5, nu=0.3, n=40, error_estimate=False)
    assert abs(res.contact_radius - 1.0) < 1e-9


def test_axisymmetric_at_c_over_H_100_allowed():
    # c/H ~ 100 is inside the limit (work 9.9e7 < 2e8)
    res = tl.solve_axisymmetric(tl.BondedLayer(0.3), tl.Punch.paraboloid(R=1), 50.0, 0.1, error_estimate=False)
    assert 95 < res.radius / 0.1 < 101


def test_fft2d_memory_refused_before_work(monkeypatch):
    _forbid(monkeypatch, fft2d, "influence_coefficients")
    _forbid(monkeypatch, fft2d, "_overlap_box")
    assert fft2d.memory_estimate(4096) > fft2d.MAX_BYTES >= fft2d.memory_estimate(2048)
    with pytest.raises(WorkLimitError, match=r"memory estimate for n = 4096 cells per side \(GiB\) = .* exceeds "
                                             r"the limit 2: .*smaller n"):
        tl.numerics.solve_2d(tl.BondedLayer(0.3), tl.Punch.paraboloid(R=1), delta0=0.1, H=0.1, n=4096)


def test_obstacle_nodes_refused_before_work(monkeypatch):
    from thinlayer.asymptotics.incompressible import IncompressibleLayer
    _forbid(monkeypatch, obstacle, "_grid_solve")
    with pytest.raises(WorkLimitError, match="n \\(nodes per side\\) = 641 exceeds the limit 321"):
        obstacle.solve_obstacle_grid(IncompressibleLayer(), tl.Punch.paraboloid(R=1), 0.5, 0.05, n=641)


# ---------------------------------------------------------------------------------------------------------------
# issue 23 item 3: refused by cost, under a hard CPU limit
# ---------------------------------------------------------------------------------------------------------------
#: inputs that ran for minutes before issue 23 (each > 30 s when measured), with what must refuse them
REFUSED_BY_COST = {
    "float literal 1e999999 in a punch": "tl.Punch('x_1**2 + 1e999999*x_2**2')",
    "float literal 1e-999999": "tl.Punch('x_1**2 + 1e-999999*x_2**2')",
    "1e309 as a parameter value": "tl.Punch.paraboloid().subs({'R': '1e309'})",
    "((9**1000)**1000)**30": "tl.Punch('x_1**2*((9**1000)**1000)**30')",
    "a 3001-digit integer": "tl.Punch('x_1**2 + ' + '9' * 3001 + '*x_2**2')",
    "(a+b+c+d)**1000": "tl.Punch('x_1**2*(a+b+c+d)**1000 + x_2**2')",
    "x_2**2*(a+b+c+d+e)**200": "tl.Punch('x_1**2 + x_2**2*(a+b+c+d+e)**200')",
    "(x_1+x_2+a+b+c)**40": "tl.inner_pressure(tl.BondedLayer(0.3), tl.Punch('(x_1+x_2+a+b+c)**40'))",
    "(a+b+c)**-500 in a denominator": "tl.Punch('x_1**2/(a+b+c)**500 + x_2**2')",
    "a punch with 300 parameters": "tl.Punch(' + '.join(f'a{k}*x_1**2' for k in range(300)) + ' + x_2**2')",
    "Punch.general(40): 860 parameters": "tl.Punch.general(40)",
    "a sympy-built (a+b+c+d)**1000": "tl.Punch(x1**2 * (a + b + c + d)**1000 + x2**2)",
    "BondedLayer('1e-99999999')": "tl.BondedLayer('1e-99999999')",
    "FrictionlessLayer('0.' + 5000 digits)": "tl.FrictionlessLayer('0.' + '3' * 5000)",
    "fit() with 10 million points": "tl.fit(np.broadcast_to(0.5, (10**7,)), np.broadcast_to(1.0, (10**7,)), "
                                    "punch=10.0, H=1.0)",
    "fit() with a 10-million-element list": "tl.fit([0.5] * 10**7, [1.0] * 10**7, punch=10.0, H=1.0)",
    "force_arrays with 1e8 depths": "tl.force_arrays(tl.BondedLayer(0.3), tl.Punch.paraboloid(10), "
                                    "np.broadcast_to(0.1, (10**8,)), 0.05)",
    "flat_punch_stiffness with 1e7 ratios": "tl.flat_punch_stiffness(tl.BondedLayer(0.3), "
                                            "np.broadcast_to(30.0, (10**7,)), 'thin')",
    "CLI inner --punch 1e999999": "cli(['inner', '--punch', 'x_1**2 + 1e999999*x_2**2'])",
    "derivation file expr ((9**1000)**1000)**30": "cli(['report', toml('x_1**2*((9**1000)**1000)**30'), '--out', "
                                                   "str(tmp / 'out')])",
}

_CHILD = r'''
import json, resource, sys, time, contextlib, io
from pathlib import Path
import numpy as np
import sympy as sp
import thinlayer as tl
from thinlayer.export.cli import main as cli_main
from thinlayer.symbols import x1, x2
a, b, c, d = sp.symbols("a b c d")
tmp = Path(sys.argv[1])
cases = json.loads(sys.argv[2])
budget = float(sys.argv[3])

def cli(argv):
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        code = cli_main(argv)
    if code != 2:
        raise RuntimeError(f"exit {code}: {err.getvalue()!r}")
    raise ValueError(err.getvalue().strip())

def toml(expr):
    f = tmp / "d.toml"
    f.write_text(f"[derivation]\nname='d'\n[layer]\nnu='3/10'\n[punch]\nexpr='{expr}'\n")
    return str(f)

# the hard stop: what is used so far, plus every case's budget (a runaway is killed by SIGXCPU)
used = resource.getrusage(resource.RUSAGE_SELF).ru_utime + resource.getrusage(resource.RUSAGE_SELF).ru_stime
limit = int(used + budget * len(cases)) + 2
resource.setrlimit(resource.RLIMIT_CPU, (limit, limit + 1))
for name, code in cases.items():
    t0 = time.process_time()
    try:
        eval(code)
        out = {"name": name, "ok": False, "error": "accepted"}
    except (ValueError, TypeError) as exc:
        out = {"name": name, "ok": True, "error": f"{type(exc).__name__}: {exc}"}
    except Exception as exc:
        out = {"name": name, "ok": False, "error": f"{type(exc).__name__}: {exc}"}
    out["cpu"] = time.process_time() - t0
    print(json.dumps(out), flush=True)
'''


def test_refused_inputs_under_a_cpu_limit(tmp_path):
    """Each input of issue 23's unbounded-work list is refused in one line within 2 s of CPU, in a child process
    whose RLIMIT_CPU kills it if any input runs away (before the fix each ran > 30 s)."""
    import json
    import subprocess
    import sys

    budget = 2.0
    proc = subprocess.run([sys.executable, "-c", _CHILD, str(tmp_path), json.dumps(REFUSED_BY_COST), str(budget)],
                          capture_output=True, text=True, timeout=600)
    rows = [json.loads(line) for line in proc.stdout.splitlines() if line.startswith("{")]
    assert proc.returncode == 0, f"the child died (a runaway hit RLIMIT_CPU?): {proc.returncode} {proc.stderr[-500:]}"
    assert [r["name"] for r in rows] == list(REFUSED_BY_COST)
    bad = [r for r in rows if not r["ok"] or r["cpu"] > budget or "\n" in r["error"].strip()]
    assert not bad, "\n".join(f"{r['name']}: {r['cpu']:.2f} s CPU, {r['error'][:200]}" for r in bad)
