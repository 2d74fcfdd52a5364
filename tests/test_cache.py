"""The disk cache of per-nu constants (thinlayer._cache, issue 28 item 6): exact, private, and never trusted blindly.

Each test points THINLAYER_CACHE_DIR at its own folder.  Independent checks: values read back are compared with
the values computed with the cache off (THINLAYER_CACHE=0), and with the computation's own result bit for bit.
"""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import textwrap
from fractions import Fraction
from pathlib import Path

import mpmath
import numpy as np
import pytest
import sympy as sp

from thinlayer import _cache
from thinlayer._cache import cache_dir, cached, entry_path

SRC = str(Path(__file__).resolve().parents[1] / "src")


@pytest.fixture()
def folder(tmp_path, monkeypatch):
    monkeypatch.setenv("THINLAYER_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("THINLAYER_CACHE", raising=False)
    return tmp_path / "cache"


class Counter:
    def __init__(self, value):
        self.value, self.calls = value, 0

    def __call__(self):
        self.calls += 1
        return self.value


def _values():
    with mpmath.workdps(40):
        h = mpmath.sqrt(2) / 3
    return (h, 0.1, -math.inf, math.inf, 5e-324, 2**80 + 1, sp.Rational(-7, 3), Fraction(1, 3), "text", None, True,
            np.array([[0.1, -2.5e300], [math.pi, 0.0]]), [1, (2.0, "x")])


def test_values_come_back_exactly_and_compute_runs_once(folder):
    value = _values()
    c = Counter(value)
    first = cached("roundtrip", ("3/10", sp.Rational(3, 10), 0.3, 7), c)
    again = cached("roundtrip", ("3/10", sp.Rational(3, 10), 0.3, 7), c)
    assert c.calls == 1
    assert first is value  # the computed value itself the first time
    h, *rest = again
    assert isinstance(h, mpmath.mpf) and h._mpf_ == value[0]._mpf_  # all 40 digits, whatever mp.dps is now
    assert rest[0] == 0.1 and rest[1] == -math.inf and rest[2] == math.inf and rest[3] == 5e-324
    assert rest[4] == 2**80 + 1 and rest[5] == sp.Rational(-7, 3) and rest[6] == sp.Rational(1, 3)
    assert rest[7:10] == ["text", None, True] or tuple(rest[7:10]) == ("text", None, True)
    assert np.array_equal(rest[10], value[11]) and rest[10].shape == (2, 2)
    assert rest[11] == [1, (2.0, "x")]
    # another key (0.3 as a float differs from 3/10) is another entry
    cached("roundtrip", ("3/10", sp.Rational(3, 10), 0.30000000000000004, 7), c)
    assert c.calls == 2


def test_the_folder_is_private_to_the_user_and_named_by_version(folder):
    cached("x", (1,), lambda: 1.0)
    d = cache_dir()
    assert d.parent == folder and d.is_dir() and (d.stat().st_mode & 0o777) == 0o700
    entries = list(d.iterdir())
    assert len(entries) == 1 and (entries[0].stat().st_mode & 0o777) == 0o600
    assert not [p for p in d.iterdir() if p.name.endswith(".tmp")]


def test_off_switch(folder, monkeypatch):
    monkeypatch.setenv("THINLAYER_CACHE", "0")
    c = Counter(2.5)
    assert cached("off", (1,), c) == 2.5 and cached("off", (1,), c) == 2.5
    assert c.calls == 2 and not folder.exists()


@pytest.mark.parametrize("damage", ["truncated", "garbage", "empty", "not-utf8", "wrong-key", "wrong-tag",
                                    "wrong-code", "huge", "deep", "bad-number", "a-folder"])
def test_a_damaged_entry_is_ignored_and_rebuilt(folder, damage):
    value = (mpmath.mpf(1) / 3, np.linspace(0.0, 1.0, 50))
    c = Counter(value)
    cached("damaged", ("1/4", 20), c)
    path = entry_path("damaged", ("1/4", 20))
    text = path.read_text()
    doc = json.loads(text)
    if damage == "truncated":
        path.write_text(text[: len(text) // 2])
    elif damage == "garbage":
        path.write_bytes(os.urandom(300))
    elif damage == "empty":
        path.write_text("")
    elif damage == "not-utf8":
        path.write_bytes(b"\xff\xfe" + text.encode())
    elif damage == "wrong-key":  # an entry of other arguments moved to this name
        path.write_text(json.dumps({**doc, "key": doc["key"].replace("1/4", "1/5")}))
    elif damage == "wrong-tag":
        path.write_text(json.dumps({**doc, "value": {"pickle": "gASVBgAAAAAAAAB9lC4="}}))
    elif damage == "wrong-code":  # written by other code (another fingerprint)
        path.write_text(json.dumps({**doc, "code": "0" * 32}))
    elif damage == "huge":
        path.write_text(text + " " * (_cache.MAX_ENTRY_BYTES + 1))
    elif damage == "deep":
        deep = 1
        for _ in range(25):
            deep = {"t": [deep]}
        path.write_text(json.dumps({**doc, "value": deep}))
    elif damage == "bad-number":
        path.write_text(json.dumps({**doc, "value": {"t": [{"mpf": ["1", 2]}, {"f": "0x1.0p+99999"}]}}))
    elif damage == "a-folder":
        path.unlink()
        path.mkdir()
    again = cached("damaged", ("1/4", 20), c)
    assert c.calls == 2 and again is value  # computed afresh, not the damaged text
    if damage != "a-folder":  # rewritten: the next process reads it
        third = cached("damaged", ("1/4", 20), c)
        assert c.calls == 2 and third[0] == value[0] and np.array_equal(third[1], value[1])


def test_a_planted_symlink_is_never_followed(folder, tmp_path):
    value = 0.25
    c = Counter(value)
    path = entry_path("linked", ("1/3",))
    # a well-formed entry with a wrong value, reachable only through a link planted at the entry's path
    cached("linked", ("1/3",), lambda: 99.0)
    victim = tmp_path / "victim.json"
    victim.write_text(path.read_text())
    before = victim.read_text()
    path.unlink()
    path.symlink_to(victim)
    assert cached("linked", ("1/3",), c) == 0.25 and c.calls == 1  # the link was not read
    assert victim.read_text() == before  # nor written through
    assert path.is_file() and not path.is_symlink()  # the entry is now a file of its own
    assert cached("linked", ("1/3",), c) == 0.25 and c.calls == 1
    # a link to a folder for the version folder itself: the cache is not used at all
    other = tmp_path / "elsewhere"
    other.mkdir()
    version_folder = cache_dir()
    for p in version_folder.iterdir():
        p.unlink()
    version_folder.rmdir()
    version_folder.symlink_to(other, target_is_directory=True)
    assert cache_dir() is None
    assert cached("linked", ("1/3",), c) == 0.25 and c.calls == 2 and not list(other.iterdir())


_WRITER = textwrap.dedent("""
    import os, sys
    import numpy as np
    sys.path.insert(0, {src!r})
    from thinlayer._cache import cached, entry_path
    expected = np.sin(np.arange(4000.0))  # a ~100 kB entry: writes are not atomic by luck
    path = entry_path("race", ("shared",))
    for i in range(60):
        if i % 3 == 0:
            try:
                os.unlink(path)
            except FileNotFoundError:
                pass
        got = cached("race", ("shared",), lambda: np.sin(np.arange(4000.0)))
        assert np.array_equal(got, expected), i
    print("ok")
""")


def test_two_concurrent_writers(folder):
    code = _WRITER.format(src=SRC)
    env = {**os.environ, "THINLAYER_CACHE_DIR": str(folder)}
    procs = [subprocess.Popen([sys.executable, "-c", code], env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              stdin=subprocess.DEVNULL, text=True) for _ in range(2)]
    outs = [p.communicate(timeout=300) for p in procs]
    assert [p.returncode for p in procs] == [0, 0], [o[1][-2000:] for o in outs]
    assert all(o[0].strip() == "ok" for o in outs)
    d = cache_dir()
    assert [p.name for p in d.iterdir() if p.name.endswith(".tmp")] == []  # no temporary file left behind
    assert np.array_equal(cached("race", ("shared",), lambda: None), np.sin(np.arange(4000.0)))


def test_the_hooked_constants_read_back_equal_the_computation(folder, monkeypatch):
    """h* (3.18), r_3 (SO.4) and the boundary-layer table (3.22) read from disk equal a fresh computation."""
    from thinlayer.asymptotics import wiener_hopf as wh

    def fresh():
        for f in (wh._solution, wh._layer):
            f.cache_clear()
        sol = wh.boundary_layer_exact("1/4", dps=15, n=16)
        return wh.edge_shift_exact("1/4", dps=15), wh.edge_cubic("1/4", dps=15), sol.cheb, sol.sigma

    computed = fresh()  # with the cache empty: computed, and written
    names = sorted(p.name.split("-")[0] for p in cache_dir().iterdir())
    assert {"edge_shift", "edge_cubic", "wiener_hopf_table", "zero_rate", "pole_rate"} <= set(names)
    with monkeypatch.context() as m:
        m.setattr(wh, "_build_table", None)  # a table built again instead of read would fail here
        m.setattr(wh.mpmath, "quad", None)  # and so would h* or r_3 integrated again
        read = fresh()
    for a, b in zip(computed, read):
        assert a == b
    assert computed[0]._mpf_ == read[0]._mpf_ and computed[1]._mpf_ == read[1]._mpf_  # bit for bit
    # an independent route to the same h*: another exact factorisation (normaliser) of the kernel
    assert abs(read[0] - wh.edge_shift_exact("1/4", dps=15, normaliser="sqrt")) < 1e-12


def test_the_force_defect_read_back_is_the_derived_expression(folder, monkeypatch):
    """D = m_1/2 (derived from (3.23)-(3.25)) is kept as its exact polynomial coefficients in m_1."""
    from thinlayer.asymptotics import force_law as fl

    fl.boundary_layer_force_defect.cache_clear()
    derived = fl.boundary_layer_force_defect()  # derived, and written
    fl.boundary_layer_force_defect.cache_clear()
    with monkeypatch.context() as m:
        m.setattr(fl, "_derived_force_defect", None)  # read back, not derived again
        read = fl.boundary_layer_force_defect()
    fl.boundary_layer_force_defect.cache_clear()
    m1 = sp.Symbol("m_1", real=True)
    assert read == derived and sp.expand(read - fl._derived_force_defect()) == 0
    assert read == m1 / 2  # the closed form the boundary layer's Laplace transform gives by hand


def test_the_thick_moments_and_the_two_term_edge_shift_read_back_bit_for_bit(folder, monkeypatch):
    """b_k (T.2) and h(nu) (I.12) from disk equal the computation; b_0 also equals an adaptive quadrature."""
    import thinlayer as tl
    from thinlayer.asymptotics import thick_layer as tk
    from thinlayer.asymptotics.incompressible import two_term as tt

    layer = tl.BondedLayer(0.3)

    def fresh():
        tk._moments_cached.cache_clear()
        tt._edge_shift_cached.cache_clear()
        return tk.thick_moments(layer, 2, dps=15), tt.two_term_edge_shift(tl.BondedLayer(0.45), dps=12)

    computed = fresh()
    with monkeypatch.context() as m:
        m.setattr(tk, "_moments_computed", None)
        m.setattr(tt, "_edge_shift_computed", None)
        read = fresh()
    assert [v._mpf_ for v in computed[0]] == [v._mpf_ for v in read[0]]
    assert computed[1]._mpf_ == read[1]._mpf_
    with mpmath.workdps(20):  # (T.2) b_0 = int_0^oo (1 - L(u)) du by adaptive quadrature, another rule
        b0 = mpmath.quad(lambda u: 1 - layer.L_numeric(u, "mpmath"), [0, 1, 4, 16, mpmath.inf])
    assert abs(b0 - read[0][0]) < 1e-12 * abs(b0)
