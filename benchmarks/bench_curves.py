"""Measured curves (issue 25 items 3, 8): thinlayer.fit_curve on the real AFM curves shipped in tests/afm/data.

``python benchmarks/bench_curves.py`` prints, per curve (afmformats' example data: a JPK force curve, four curves of a
QI map, one QI series curve; approach segment, R = 10 um, nu = 1/2, nanite's contact-point weights), the evidence
table of issue 25 item 8:

* nanite's E: ``hertz_para`` fitted by nanite with its own preprocessing and contact-point model;
* thinlayer's thick-limit E (``fit_curve(H=None, weighting="nanite")``: Hertz with the contact point and the
  baseline offset free) and its ratio to nanite's;
* E at a finite H (any-thickness law (T.7), bonded, H given below) with the naive standard error and the block
  bootstrap's (200 refits), the block length and the residuals' lag-1 autocorrelation;
* the time per fit (median of 5; the bootstrap's time per refit);

then the timing rows of ``benchmarks/run.py``.  Rows are empty when the extra thinlayer[afm] is not installed.
"""
from __future__ import annotations

import importlib.util
import time
import warnings
from pathlib import Path

from _timing import Row, main, median

DATA = Path(__file__).resolve().parents[1] / "tests" / "afm" / "data"
CURVES = [("fmt-jpk-fd_spot3-0192.jpk-force", 0)] + [("fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data", i)
                                                      for i in range(4)] + \
         [("fmt-jpk-fd_qi-data-2021.04.13.jpk-qi-series", 0)]
R = 10e-6
#: the finite thickness of the table: a layer several times the largest indentation of these curves
H = 5e-6
BOOT = 200


def _nanite_E(name: str, index: int) -> tuple[float, float]:
    import nanite

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        idnt = nanite.load_group(DATA / name)[index]
        idnt.apply_preprocessing(["compute_tip_position", "correct_force_offset", "correct_tip_offset"])

    def go():
        p = nanite.model.get_init_parms("hertz_para")
        idnt.fit_properties.pop("hash", None)  # nanite skips a fit it has done (same hash): fit again
        idnt.fit_model(model_key="hertz_para", params_initial=p)
        return idnt.fit_properties["params_fitted"]["E"].value

    E = go()
    return E, median(go)


def table() -> list[dict]:
    from thinlayer.afm.curve_fit import fit_curve
    from thinlayer.afm.curves import load_curve

    out = []
    for name, i in CURVES:
        curve = load_curve(DATA / name, index=i)
        E_nan, t_nan = _nanite_E(name, i)
        thick = fit_curve(curve, punch=R, H=None, weighting="nanite")
        t_thick = median(lambda: fit_curve(curve, punch=R, H=None, weighting="nanite"))
        unweighted = fit_curve(curve, punch=R, H=None)
        fin = fit_curve(curve, punch=R, H=H, weighting="nanite")
        t_fin = median(lambda: fit_curve(curve, punch=R, H=H, weighting="nanite"))
        t0 = time.perf_counter()
        boot = fit_curve(curve, punch=R, H=H, weighting="nanite", bootstrap=BOOT)
        t_boot = (time.perf_counter() - t0) / BOOT
        out.append(dict(curve=f"{name[:28]}#{i}", n=curve.n_points, E_nanite=E_nan, E_thick=thick.E,
                        ratio=thick.E / E_nan, E_unw=unweighted.E, E_H=fin.E, se=boot.E_se, se_boot=boot.E_se_boot,
                        b=boot.block_length, phi=boot.phi, chi=fin.chi_max, dH=fin.delta_max / H, valid=fin.valid,
                        flags=len(fin.flags),
                        t_nanite=t_nan, t_thick=t_thick, t_H=t_fin, t_boot=t_boot))
    return out


def print_table(rows: list[dict]) -> None:
    print(f"R = {R * 1e6:g} um, nu = 0.5, approach segment, nanite's contact-point weights (1 um); finite H = "
          f"{H * 1e6:g} um, bonded; {BOOT} block-bootstrap refits; times: median of 5 (uptime "
          f"{Path('/proc/loadavg').read_text().split()[:3] if Path('/proc/loadavg').exists() else '?'})")
    head = (f"{'curve':<32}{'pts':>5}{'E nanite':>12}{'E thick':>12}{'ratio-1':>10}{'E unweighted':>14}"
            f"{'E at H':>11}{'SE naive':>10}{'SE block':>10}{'b':>4}{'phi':>6}{'chi_max':>8}{'d/H':>6}"
            f"{'t nanite':>10}{'t thick':>9}{'t at H':>9}{'t/refit':>9}")
    print(head)
    print("-" * len(head))
    for r in rows:
        print(f"{r['curve']:<32}{r['n']:>5}{r['E_nanite']:>12.5g}{r['E_thick']:>12.5g}{r['ratio'] - 1:>10.1e}"
              f"{r['E_unw']:>14.5g}{r['E_H']:>11.5g}{r['se']:>10.2g}{r['se_boot']:>10.2g}{r['b']:>4}{r['phi']:>6.2f}"
              f"{r['chi']:>8.3f}{r['dH']:>6.3f}{1e3 * r['t_nanite']:>8.1f}ms{1e3 * r['t_thick']:>7.1f}ms"
              f"{1e3 * r['t_H']:>7.1f}ms{1e3 * r['t_boot']:>7.1f}ms" + ("" if r["valid"] else "  NOT VALID")
              + ("  FLAG delta/H > 0.1" if r["flags"] else ""))


def run() -> list[Row]:
    if importlib.util.find_spec("nanite") is None or importlib.util.find_spec("afmformats") is None:
        return []
    from thinlayer.afm.curve_fit import fit_curve
    from thinlayer.afm.curves import load_curve

    name, i = CURVES[0]
    curve = load_curve(DATA / name, index=i)
    fit_curve(curve, punch=R, H=H)  # warm the law
    _, t_nan = _nanite_E(name, i)
    return [Row("fit_curve thick limit (E, z0, b0; nanite weights), JPK curve 2000 pts",
                median(lambda: fit_curve(curve, punch=R, H=None, weighting="nanite")), ">= 0.2x",
                peer="nanite hertz_para", peer_value=t_nan),
            Row("fit_curve at H = 5 um (any-thickness law), JPK curve 2000 pts",
                median(lambda: fit_curve(curve, punch=R, H=H, weighting="nanite")), "< 0.5 s"),
            Row("fit_curve at H = 5 um with 100 block-bootstrap refits",
                median(lambda: fit_curve(curve, punch=R, H=H, bootstrap=100), repeat=3), "< 10 s")]


if __name__ == "__main__":
    if importlib.util.find_spec("nanite") is not None:
        print_table(table())
        print()
    main(run)
