"""Cold start of the daily path (issue 28, item 6): ``thinlayer solve`` and a first ``solve()`` in a fresh process.

Rows, side by side in one run, each the median of five fresh processes against the peer ``python -c "import
numpy"`` measured the same way:

* ``thinlayer solve`` of the sphere (paraboloid R = 10, numeric nu = 0.3) from a fresh process, with the per-nu
  constants on disk (thinlayer._cache, filled by one earlier run): target <= 0.5 s;
* the same with an empty cache (the first run ever of that nu): informational;
* the first ``thinlayer.solve()`` after ``import thinlayer`` (timed inside the process, import excluded):
  target <= 0.3 s; and a second, warm ``solve()`` in the same process.

The cache folder is a temporary one (THINLAYER_CACHE_DIR), so the user's own cache is neither used nor changed.
The processes write and read compiled bytecode in a temporary folder too (PYTHONPYCACHEPREFIX; an environment
that sets PYTHONDONTWRITEBYTECODE, as the development machine does, would otherwise compile every module of every
process from source, about 0.8 s, which an installed package never does), filled by the warm-up runs.
"""
from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time

from _timing import Row, main

SOLVE = ["solve", "--nu", "0.3", "--tip", "paraboloid:R=10", "--delta0", "0.1", "--H", "0.05",
         "--mu", "1"]
FIRST = """
import time, sys
import thinlayer as tl
t0 = time.perf_counter()
tl.solve(tl.BondedLayer(0.3), tl.Punch.paraboloid(10), delta0=0.1, H=0.05, mu=1.0).force
t1 = time.perf_counter()
tl.solve(tl.BondedLayer(0.3), tl.Punch.paraboloid(10), delta0=0.12, H=0.05, mu=1.0).force
t2 = time.perf_counter()
print(t1 - t0, t2 - t1)
"""


def _wall(cmd: list[str], env: dict) -> float:
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL,
                   env=env)
    return time.perf_counter() - t0


def run(runs: int = 5) -> list[Row]:
    cli = [sys.executable, "-m", "thinlayer", *SOLVE]
    with tempfile.TemporaryDirectory(prefix="thinlayer-bench-cache-") as warm_dir, \
            tempfile.TemporaryDirectory(prefix="thinlayer-bench-pyc-") as pyc:
        base = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        base["PYTHONPYCACHEPREFIX"] = pyc
        base.pop("THINLAYER_CACHE", None)
        warm = {**base, "THINLAYER_CACHE_DIR": warm_dir}
        _wall(cli, warm)  # compiles the modules (bytecode) and fills the warm cache
        cold_first = []
        for _ in range(2):  # an empty cache each time: the first run ever of nu = 0.3
            with tempfile.TemporaryDirectory(prefix="thinlayer-bench-cache-") as empty:
                cold_first.append(_wall(cli, {**base, "THINLAYER_CACHE_DIR": empty}))
        numpy_t, solve_t, first_t, warm_t = [], [], [], []
        for _ in range(runs):  # interleaved, so that a busy moment of the machine hits every row alike
            numpy_t.append(_wall([sys.executable, "-c", "import numpy"], warm))
            solve_t.append(_wall(cli, warm))
            out = subprocess.run([sys.executable, "-c", FIRST], check=True, capture_output=True, text=True,
                                 stdin=subprocess.DEVNULL, env=warm).stdout.split()
            first_t.append(float(out[0]))
            warm_t.append(float(out[1]))
    peer = statistics.median(numpy_t)
    return [
        Row('python -c "import numpy" (the peer)', peer, "reference"),
        Row("thinlayer solve, sphere, nu = 0.3, fresh process (constants on disk)", statistics.median(solve_t),
            "<= 0.5 s", 'python -c "import numpy"', peer),
        Row("thinlayer solve, same, first run ever (empty cache)", min(cold_first), "reference",
            'python -c "import numpy"', peer),
        Row("first solve() after import thinlayer (import excluded)", statistics.median(first_t), "<= 0.3 s",
            'python -c "import numpy"', peer),
        Row("warm solve() (same process, second call)", statistics.median(warm_t), "reference"),
    ]


if __name__ == "__main__":
    main(run)
