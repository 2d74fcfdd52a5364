"""Force maps (issue 25 item 5): a 64 x 64 map of 2,000-point curves fitted, target <= 15 s on 2 cores.

The map is synthetic (thinlayer.afm.map_data.write_synthetic_map, afmformats' HDF5 format, written once into a
temporary folder and not timed): E from 3 to 12 kPa over the map, contact heights over 0.3 um, a sphere R = 5 um,
0.15 um deep (half of each curve off contact), noise 2 pN.  Timed: ``fit_map`` from the file to the MapResult
(reading through afmformats included), on a dask LocalCluster of 2 worker processes (``scheduler="local"``,
cluster start-up included) and serially.  Rows for the half-space (Hertz, closed form) and a layer H = 2 um (the
any-thickness law (T.7)), each by the fast fitter ``fit_curve_basic`` (thinlayer.fit with the contact point free,
after a baseline and contact estimate) and the default ``fit_curve_full`` (thinlayer.afm.curve_fit.fit_curve:
contact point and baseline fitted, its robust start).  ``THINLAYER_BENCH_MAP=N`` sets the side (default 64); the
machine's load average is printed beside the rows (``uptime``): the 2 cores are shared.
"""
from __future__ import annotations

import importlib.util
import math
import os
import sys
import tempfile
from pathlib import Path

from _timing import Row, main, once

SIDE = int(os.environ.get("THINLAYER_BENCH_MAP", "64"))
POINTS = 2000


def _load() -> str:
    try:
        return "load average " + ", ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:  # pragma: no cover
        return "load average n/a"


def run() -> list[Row]:
    if importlib.util.find_spec("afmformats") is None or importlib.util.find_spec("distributed") is None:
        return []
    import numpy as np

    from thinlayer.afm.map_data import write_synthetic_map
    from thinlayer.afm.maps import fit_curve_basic, fit_curve_full, fit_map

    n = SIDE
    yy, xx = np.mgrid[0:n, 0:n]
    E = 3e3 + 9e3 * (xx + yy) / max(1, 2 * (n - 1))
    contact = 0.3e-6 * np.sin(xx / 7.0) * np.cos(yy / 9.0)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        maps = {}
        for H in (math.inf, 2e-6):
            p = Path(tmp) / f"map_{'hertz' if math.isinf(H) else 'layer'}.h5"
            write_synthetic_map(p, E, H, R=5e-6, nu=0.5, points=POINTS, depth=0.15e-6, contact=contact, noise=2e-12,
                                pixel=1e-6)
            maps[H] = p
        # warm the any-thickness law in this process (the workers build theirs inside the timed run)
        from thinlayer.contact.any_thickness import any_thickness_law

        any_thickness_law(0.5, "bonded")
        print(f"# bench_maps: {n} x {n} curves of {POINTS} points; {_load()} before the runs", file=sys.stderr)
        for H, fitter, target in ((math.inf, fit_curve_basic, "<= 15 s"), (2e-6, fit_curve_basic, "<= 15 s"),
                                  (math.inf, fit_curve_full, ""), (2e-6, fit_curve_full, "")):
            where = "half-space (Hertz)" if math.isinf(H) else "layer H = 2 um (T.7)"
            Hs = None if math.isinf(H) else H

            def go(fitter=fitter, H=H, Hs=Hs):
                r = fit_map(maps[H], punch=5e-6, H=Hs, nu=0.5, fit_one=fitter, progress=False, scheduler="local",
                            workers=2, timeout=3600)
                ok = np.isfinite(r.E)
                err = float(np.max(np.abs(r.E[ok] / E[ok] - 1))) if ok.any() else math.nan
                print(f"#   {fitter.__name__}, {where}: {int(ok.sum())}/{n * n} pixels fitted, largest |E/E_true - 1|"
                      f" = {err:.2g}; {_load()}", file=sys.stderr)

            rows.append(Row(f"fit_map {n}x{n} x {POINTS} pts, {fitter.__name__}, {where}, local cluster 2 procs",
                            once(go), target))
        serial = once(lambda: fit_map(maps[2e-6], punch=5e-6, H=2e-6, nu=0.5, fit_one=fit_curve_basic,
                                      progress=False))
        rows.append(Row(f"fit_map {n}x{n} x {POINTS} pts, fit_curve_basic, layer H = 2 um, serial (1 process)",
                        serial, ""))
    return rows


if __name__ == "__main__":
    main(run)
