"""Test configuration: long validation runs are marked ``slow`` and run only with THINLAYER_SLOW=1.

The README's command runs the suite on two pytest-xdist workers with ``--dist loadgroup``.  A test that uses a
module- or session-scoped fixture of this suite is put into an ``xdist_group`` named after that fixture (tests
that share any such fixture or explicit group end up in one group), so that all the tests sharing it run in one
worker and the fixture is built once, not once per worker.
"""
import os
import shutil
import tempfile

# One BLAS/OpenMP thread per process, set before numpy loads in the xdist workers and in every process a test starts
# (they inherit the environment): the suite runs two workers on two cores, and OpenBLAS's own threads on top of
# them spin against each other.  Measured on tests/numerics/test_axisymmetric.py at load 8: 33.2 s user CPU and
# 69 s wall with the default threads, 6.5 s and 17 s with one (the Galerkin matrix G^T diag(v) G at c/H = 80:
# 0.27 s -> 0.01 s CPU).  A value the caller set is kept.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")
# sympy's expression cache (read when sympy is first imported, after this file in every worker): 100,000 entries
# instead of its default 1,000, which the suite's derivations overflow (entries evicted and recomputed).  Measured on
# tests/asymptotics/test_thick_layer.py + test_second_order.py: 36.5 -> 32.8 s user CPU, +28 MB.  Values are the same
# either way (a cache); a value the caller set is kept.
os.environ.setdefault("SYMPY_CACHE_SIZE", "100000")

import gc  # noqa: E402
import linecache  # noqa: E402

import mpmath  # noqa: E402 - after the thread settings
import pytest  # noqa: E402

_checkcache = linecache.checkcache


def _tolerant_checkcache(filename=None):
    """``linecache.checkcache`` that survives an entry removed while it iterates (Python 3.11).

    sympy's ``lambdify`` registers its generated source in ``linecache.cache`` and removes it by a
    ``weakref.finalize`` when the function is collected; a garbage collection inside ``checkcache``'s loop (doctest
    calls it through pdb before every example) then raises ``KeyError: '<lambdifygenerated-N>'`` (CI, 7aca840, in
    the doctest of ``Punch``).  The check is retried; it only discards stale cache entries.
    """
    for _ in range(5):
        try:
            return _checkcache(filename)
        except KeyError:
            continue
    return None


linecache.checkcache = _tolerant_checkcache

# Python's cyclic garbage collector is paused while the suite is collected and resumed when collection ends: a
# collection imports every test module and the package (for the doctests) and rewrites 3,500 asserts, and each full
# collection of the growing heap walks everything imported so far.  Measured on this suite's collection (one
# process, 4,095 items): 29.9 s wall with the collector on, 17.6 s with it paused, per xdist worker.  Nothing is
# skipped: the tests run with the collector on, as a user's code does.
gc.disable()


def pytest_collection_finish(session):
    gc.enable()


def pytest_sessionfinish(session):
    """The session's garbage collected once, then what is left frozen: pytest's unraisable-exception check
    collects five times more at exit (``gc_collect_harder``), each a walk of every object the worker still holds
    (measured: 1.5 s after the last test for 0.3 M objects, 3.1 s for 0.9 M; 0.2 s with this).  Garbage cycles
    are still collected, here, so a finaliser's unraisable exception is still reported."""
    gc.collect()
    gc.freeze()


TESTS = os.path.dirname(os.path.abspath(__file__))
_CACHE_ENV = "THINLAYER_CACHE_DIR"


def pytest_configure(config):
    """One disk cache of per-nu constants (thinlayer._cache) for the whole run, shared by the xdist workers and
    the CLI processes the tests start: each h*, r_3 and boundary-layer table is computed once per run.  The folder
    is new for each run (a run measures a cold start) and removed at the end; the user's own cache is not touched.
    """
    if hasattr(config, "workerinput"):  # an xdist worker: inherits the controller's folder through the environment
        return
    folder = tempfile.mkdtemp(prefix="thinlayer-test-cache-")
    config._thinlayer_cache = (folder, os.environ.get(_CACHE_ENV))
    os.environ[_CACHE_ENV] = folder


def pytest_unconfigure(config):
    state = getattr(config, "_thinlayer_cache", None)
    if state is None:
        return
    folder, before = state
    if before is None:
        os.environ.pop(_CACHE_ENV, None)
    else:
        os.environ[_CACHE_ENV] = before
    shutil.rmtree(folder, ignore_errors=True)
#: shared fixtures that join a named group: tests that build the same things without the fixture join it too
FIXTURE_GROUPS = {"catalogue_report": "catalogue-reports", "sphere_latex": "catalogue-reports",
                  "validate_cli_run": "validation-study", "small_study": "validation-study"}


def _shared_fixtures(item) -> set[str]:
    """The module-, package- and session-scoped fixtures of this suite that ``item`` uses."""
    info = getattr(item, "_fixtureinfo", None)
    out = set()
    for name, defs in (info.name2fixturedefs.items() if info is not None else ()):  # doctests have none
        fd = defs[-1]
        code = getattr(fd.func, "__code__", None)
        where = os.path.abspath(code.co_filename) if code is not None else ""
        if fd.scope in ("module", "package", "session") and where.startswith(TESTS + os.sep):
            out.add(f"{os.path.relpath(where, TESTS)}::{name}")
    return out


def _explicit_groups(item) -> set[str]:
    return {str(m.args[0] if m.args else m.kwargs.get("name", "default")) for m in item.iter_markers("xdist_group")}


@pytest.hookimpl(tryfirst=True)  # before pytest-xdist turns the xdist_group marks into node ids
def pytest_collection_modifyitems(config, items):
    # one group per connected set of shared fixtures and explicit groups (a test using fixtures A and B joins
    # every test of A and of B): pytest-xdist would make a test marked A and B a group "A_B" of its own
    parent: dict[str, str] = {}

    def find(x: str) -> str:
        while parent.setdefault(x, x) != x:
            x = parent[x]
        return x

    nodes = {}
    for item in items:
        fixtures = _shared_fixtures(item)
        ns = {f"g:{g}" for g in _explicit_groups(item)} | {f"f:{f}" for f in fixtures}
        ns |= {f"g:{FIXTURE_GROUPS[f.split('::')[1]]}" for f in fixtures if f.split("::")[1] in FIXTURE_GROUPS}
        nodes[item] = ns
        for a, b in zip(sorted(ns), sorted(ns)[1:]):
            parent[find(b)] = find(a)
    members: dict[str, set[str]] = {}
    for ns in nodes.values():
        for n in ns:
            members.setdefault(find(n), set()).add(n)
    name = {}
    for root, ms in members.items():  # an explicit group's name if the set has one, else its first fixture's
        explicit = sorted(m for m in ms if m.startswith("g:"))
        name[root] = explicit[0][2:] if explicit else min(ms)[2:]
    for item, ns in nodes.items():
        if ns:
            group = name[find(next(iter(ns)))]
            if group not in _explicit_groups(item):
                item.add_marker(pytest.mark.xdist_group(group))
    if os.environ.get("THINLAYER_SLOW") == "1" or "slow" in (config.getoption("-m") or ""):
        return
    skip = pytest.mark.skip(reason="long validation run: set THINLAYER_SLOW=1 to run it")
    for item in items:
        if "slow" in item.keywords:
            item.add_marker(skip)


@pytest.fixture(scope="session")
def validate_cli_run(tmp_path_factory):
    """``thinlayer validate <args>`` run once per argument list and shared (xdist group ``validation-study``).

    Returns a function ``run(argv) -> SimpleNamespace(code, out, err, folder, study)``: the command runs in this
    process through ``thinlayer.export.cli.main(argv)`` in a fresh folder (``folder``), stdout and stderr
    captured; ``study`` is the :class:`~thinlayer.validation.ValidationStudy` the command computed, caught on its
    way out of ``validation_study`` (the command itself runs unchanged).  The README's
    ``thinlayer validate --out validation --plots`` (tests/test_readme.py) and the ``small_study`` fixture of
    tests/validation (its sphere cases at nu = 0.3, 0.45) are one run of the default study.
    """
    import contextlib
    import io
    from types import SimpleNamespace

    from thinlayer.export.cli import main
    from thinlayer.validation import runner

    runs = {}

    def run(argv):
        key = tuple(argv)
        if key not in runs:
            folder = tmp_path_factory.mktemp("validate")
            studies = []
            real = runner.validation_study

            def spy(*args, **kwargs):
                studies.append(real(*args, **kwargs))
                return studies[-1]

            out, err, old = io.StringIO(), io.StringIO(), os.getcwd()
            with pytest.MonkeyPatch.context() as mp:
                mp.setattr(runner, "validation_study", spy)
                os.chdir(folder)
                try:
                    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                        code = main(list(argv))
                finally:
                    os.chdir(old)
            runs[key] = SimpleNamespace(code=code, out=out.getvalue(), err=err.getvalue(), folder=folder,
                                        study=studies[0] if len(studies) == 1 else None)
        return runs[key]

    return run


@pytest.fixture(autouse=True)
def _mpmath_precision_restored():
    """A test that sets mpmath's global precision must not change what later tests compute."""
    dps = mpmath.mp.dps
    yield
    mpmath.mp.dps = dps
