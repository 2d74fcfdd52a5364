"""Large batches on dask.distributed (issue 25 item 6): the same results as the serial run, bit for bit.

Default: a dask cluster of 2 worker threads in this process (``LocalCluster(processes=False)``, ~1 s to start) runs
thinlayer.afm.distributed.map_batch and fit_map; every number equals the serial run's exactly (``np.array_equal``,
not a tolerance: each item is the same function on the same numbers).  THINLAYER_SLOW=1: a local cluster of 2 worker
processes (``scheduler="local"``, ~6-9 s to start on a loaded machine), for a map and for a sweep of the direct
solver.  Every wait is bounded (``timeout=``): a stuck cluster fails the test, never hangs it.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("afmformats")
distributed = pytest.importorskip("distributed")

from thinlayer.afm.distributed import chunked, map_batch  # noqa: E402
from thinlayer.afm.map_data import write_synthetic_map  # noqa: E402
from thinlayer.afm.maps import fit_curve_basic, fit_map  # noqa: E402
from thinlayer.errors import InputError  # noqa: E402

R = 5e-6
TIMEOUT = 120


@pytest.fixture(scope="module")
def threads_client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=":0",
                                       silence_logs=40)  # ":0": any free port, never a clash with another cluster
    client = distributed.Client(cluster, timeout=TIMEOUT)
    yield client
    client.close()
    cluster.close()


@pytest.fixture(scope="module")
def small_map(tmp_path_factory):
    E = np.array([[3e3, 5e3, 0.0], [7e3, 9e3, 1.1e4]])
    path = tmp_path_factory.mktemp("dask") / "map.h5"
    return write_synthetic_map(path, E, math.inf, R=R, points=200, depth=0.2e-6, noise=2e-12, seed=3)


def _series(x: float, n: int = 200) -> float:
    """A float computation whose last bits depend on the order of its operations."""
    return float(np.sum(np.sin(x * np.arange(1, n + 1)) / np.arange(1, n + 1) ** 1.5))


def _same(a, b) -> None:
    for name in ("E", "E_se", "H", "contact_point", "residual"):
        assert np.array_equal(getattr(a, name), getattr(b, name), equal_nan=True), name
    assert np.array_equal(a.status, b.status) and np.array_equal(a.reasons, b.reasons)
    assert np.array_equal(a.names, b.names)


def test_map_batch_on_threads_equals_serial_bit_for_bit(threads_client):
    items = list(np.linspace(0.1, 3.0, 23))
    serial = map_batch(_series, items)
    for chunk in (1, 5, None):
        got = map_batch(_series, items, scheduler=threads_client, chunk=chunk, timeout=TIMEOUT)
        assert got == serial  # float ==: bit for bit, and in the items' order
    assert map_batch(abs, [], scheduler=threads_client) == []


def test_fit_map_on_threads_equals_serial(small_map, threads_client):
    serial = fit_map(small_map, punch=R, H=None, nu=0.5, fit_one=fit_curve_basic, progress=False)
    dask = fit_map(small_map, punch=R, H=None, nu=0.5, fit_one=fit_curve_basic, progress=False,
                   scheduler=threads_client, timeout=TIMEOUT)
    _same(serial, dask)
    assert serial.counts() == {"ok": 5, "flagged": 0, "failed": 1, "empty": 0}


_CALLS: list = []


def _counted(x: float) -> float:
    _CALLS.append(x)
    return _series(x)


def test_map_batch_packs_warms_and_times_with_the_same_results(threads_client):
    """pack= (each chunk sent as an object that iterates over its items), warm= (one call per worker before the
    chunks) and timings= change nothing in the results; every phase is timed."""
    items = list(np.linspace(0.1, 3.0, 11))
    serial = map_batch(_series, items)
    _CALLS.clear()
    timings: dict = {}
    got = map_batch(_counted, items, scheduler=threads_client, chunk=4, timeout=TIMEOUT, pack=tuple, warm=True,
                    timings=timings)
    assert got == serial
    assert len(_CALLS) == len(items) + 2 and _CALLS.count(items[0]) == 3  # the 2 workers' warm-up calls
    assert timings["chunks"] == 3 and timings["workers"] == 2
    assert all(timings[k] >= 0 for k in ("start", "send", "compute", "close", "task_cpu", "worker_cpu"))


def test_packed_pixels_iterate_to_the_same_curves_after_pickling():
    """A map chunk packed for a worker (maps._PixelBlock): pickled, it gives back every item, in order, with equal
    arrays, names, indices and thicknesses; curves that are not float arrays of one length travel as they are."""
    import pickle

    from thinlayer.afm.map_data import MapCurve
    from thinlayer.afm.maps import _PixelBlock

    rng = np.random.default_rng(5)
    items = [(MapCurve((i, 2 * i), rng.normal(size=7 + i), rng.normal(size=7 + i), f"c{i}", 0.1 * i, (i, -i)),
              None if i == 1 else 1e-6 * (i + 1)) for i in range(4)]
    block = pickle.loads(pickle.dumps(_PixelBlock(items)))
    assert block.items is None and block.z.size == sum(c.force.size for c, _ in items)
    back = list(block)
    assert len(back) == len(block) == len(items)
    for (c, H), (c2, H2) in zip(items, back):
        assert (c2.index, c2.name, c2.spring_constant, c2.position, H2) == (c.index, c.name, c.spring_constant,
                                                                           c.position, H)
        assert np.array_equal(c2.tip_position, c.tip_position) and np.array_equal(c2.force, c.force)
    odd = [(MapCurve((0, 0), np.arange(5), np.ones(5)), None), (MapCurve((0, 1), np.ones(3), np.ones(4)), None)]
    kept = _PixelBlock(odd)
    assert kept.z is None and [c for c, _ in kept] == [c for c, _ in odd]


def test_clusters_started_here_run_without_the_profiler_and_with_glibc_trimming():
    from thinlayer.afm.distributed import _cluster_config, start_method

    config = _cluster_config()
    assert config["distributed.worker.profile.enabled"] is False
    assert config["distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_"] is None
    assert config["distributed.worker.multiprocessing-method"] == start_method()


def test_progress_counter_goes_to_stderr(capsys):
    assert map_batch(abs, [-1, -2, -3], progress=True, label="curves") == [1, 2, 3]
    out, err = capsys.readouterr()
    assert out == "" and "3/3 curves" in err


def test_chunks_keep_the_order():
    assert chunked(list(range(7)), 3) == [[0, 1, 2], [3, 4, 5], [6]]


@pytest.mark.parametrize("scheduler, match", [("nowhere", "scheduler must be"), (3, "scheduler must be"),
                                              ("tcp//host", "scheduler must be")])
def test_bad_scheduler_is_one_line(scheduler, match):
    with pytest.raises((InputError, TypeError), match=match) as exc:
        map_batch(abs, [1], scheduler=scheduler)
    assert "\n" not in str(exc.value)


@pytest.mark.slow
def test_local_cluster_of_two_processes_equals_serial(small_map):
    """scheduler="local" (2 worker processes, pickled work): the map bit for bit equal to the serial run."""
    serial = fit_map(small_map, punch=R, H=None, nu=0.5, fit_one=fit_curve_basic, progress=False)
    dask = fit_map(small_map, punch=R, H=None, nu=0.5, fit_one=fit_curve_basic, progress=False, scheduler="local",
                   workers=2, timeout=TIMEOUT)
    _same(serial, dask)


@pytest.mark.slow
def test_direct_solver_sweep_on_two_processes_equals_serial():
    """A parameter sweep of the direct solver (solve(model="direct")) through the same batch API."""
    import thinlayer as tl
    from thinlayer.afm.distributed import solve_sweep

    cases = [dict(layer=tl.BondedLayer(0.3), punch=tl.Punch.paraboloid(10), delta0=d, H=2.0, E=3.0, model="direct")
             for d in (0.1, 0.2)]
    serial = solve_sweep(cases)
    dask = solve_sweep(cases, scheduler="local", workers=2, timeout=TIMEOUT)
    assert [r.force for r in dask] == [r.force for r in serial]
    assert [r.model for r in dask] == ["direct", "direct"]

