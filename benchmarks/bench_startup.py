"""Start-up: ``import thinlayer`` against sympy + numpy + mpmath alone, and ``thinlayer --help`` (issue 18, item 5).

Each row is the median of five fresh processes.  Targets: ``import thinlayer`` at most 1.3 times the import of
sympy, numpy and mpmath (the package's names are imported on first use), ``thinlayer --help`` under 0.3 s.
"""
from __future__ import annotations

import statistics
import subprocess
import sys
import time

from _timing import main


def _median(cmd: list[str], runs: int = 5) -> float:
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def run() -> list[tuple[str, float, str]]:
    base = _median([sys.executable, "-c", "import sympy, numpy, mpmath"])
    mine = _median([sys.executable, "-c", "import thinlayer"])
    core = _median([sys.executable, "-c", "import thinlayer; thinlayer.BondedLayer(0.3); thinlayer.Punch"])
    helps = _median([sys.executable, "-m", "thinlayer", "--help"])
    return [
        ("python -c 'import sympy, numpy, mpmath' (the peer)", base, "reference"),
        (f"python -c 'import thinlayer' ({mine / base:.2f}x the peer)", mine, f"<= {1.3 * base:.3f} s (1.3x)"),
        ("import thinlayer + first layer and punch (sympy loaded)", core, "reference"),
        ("thinlayer --help", helps, "< 0.3 s"),
    ]


if __name__ == "__main__":
    main(run)
