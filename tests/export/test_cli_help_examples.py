"""Every example of every ``--help`` text runs (issue 28 item 5): collected from the parsers' epilogs.

The examples are read from :func:`thinlayer.export.cli.build_parser` itself (the top-level epilog and each
subcommand's), so a new example is tested without touching this file.  Each runs in this process through
``main(argv)`` in a fresh folder holding a copy of ``derivations/`` and a force-indentation curve
``curve.csv`` made from the any-thickness law with E = 2 at the example's own ``--R``, ``--H``, ``--nu``.
It must exit 0 and print output of its kind: JSON that parses, LaTeX, CSV with one row per sweep value,
Unicode text without sympy's ``**``, or the files it says it wrote.

An example whose comment says it takes minutes (``# ... minutes``) runs only with ``THINLAYER_SLOW=1``:
the default validation study takes 2 CPU minutes, and it already runs in ``tests/test_readme.py`` (the
README's ``thinlayer validate --out validation --plots``).
"""
from __future__ import annotations

import csv
import io
import json
import os
import re
import shlex
import shutil
from pathlib import Path

import numpy as np
import pytest

from thinlayer.export.cli import build_parser, main

ROOT = Path(__file__).resolve().parents[2]
SLOW = os.environ.get("THINLAYER_SLOW") == "1"


def _parsers():
    ap = build_parser()
    sub = ap._subparsers._group_actions[0].choices
    seen, out = set(), [("thinlayer", ap)]
    for name, p in sub.items():
        if id(p) not in seen:  # 'derive' is the same parser as 'report'
            seen.add(id(p))
            out.append((name, p))
    return out


def help_examples() -> list[tuple[str, str, str]]:
    """``(parser name, command line, comment)`` of every example line in every epilog."""
    out = []
    for name, p in _parsers():
        for line in (p.epilog or "").splitlines():
            line = line.strip()
            if line.startswith("thinlayer "):
                cmd, _, comment = line.partition("#")
                out.append((name, cmd.strip(), comment.strip()))
    return out


EXAMPLES = help_examples()


def test_every_subcommand_has_examples():
    names = {n for n, _, _ in EXAMPLES}
    assert names == {n for n, _ in _parsers()}, names
    assert len(EXAMPLES) >= 30


def _curve(argv: list[str], folder: Path) -> None:
    """``curve.csv`` for a ``fit`` example: the any-thickness law at its --R, --H, --nu with E = 2, 1 % noise (for
    another tip, the direct solver)."""
    import thinlayer as tl

    opt = {argv[k]: argv[k + 1] for k in range(len(argv) - 1) if argv[k].startswith("--")}
    H, nu = float(opt["--H"]), float(opt["--nu"])
    if "--R" in opt:
        R = float(opt["--R"])
        delta = np.linspace(0.02, 1.0, 40) * H
        force = tl.force_any_thickness(delta, R=R, H=H, E=2.0, nu=nu)
    else:  # another tip (--cone, --blunted-cone, ...): the direct solver at 5 depths, c/H from about 7 to 15
        from thinlayer.export.cli_args import tip_from_shortcut
        from thinlayer.numerics import solve_axisymmetric

        tip = tip_from_shortcut(build_parser().parse_args(argv))
        a1 = tip.level_set(1.0).radius  # delta0 = 1: c/H = a/H at depth 1, scaled to 10 at the middle depth
        delta = np.linspace(0.7, 1.4, 5) * 10 * H / a1 if tip.kind == "cone" else np.linspace(0.7, 1.4, 5)
        force = np.array([solve_axisymmetric(tl.BondedLayer(nu), tip, d, H=H, mu=2.0 / (2 * (1 + nu)),
                                             error_estimate=False).force for d in delta])
    force = force * (1 + 0.001 * np.random.default_rng(3).standard_normal(delta.size))
    with open(folder / "curve.csv", "w") as fh:
        fh.write("depth,force\n" + "".join(f"{float(d)!r},{float(f)!r}\n" for d, f in zip(delta, force)))


def _map_inputs(argv: list[str], folder: Path) -> None:
    """The map a ``fit-map`` example names: the JPK map of tests/afm/data for a ``.jpk-force-map``, else a 2 x 2
    synthetic map (Hertz/any-thickness curves, E = 1 kPa, afmformats' HDF5 format; a folder holds one such file),
    and its height image (one pixel at the substrate, three 2 um above it)."""
    from thinlayer.afm.map_data import write_synthetic_map

    opt = {argv[k]: argv[k + 1] for k in range(len(argv) - 1) if argv[k].startswith("--")}
    src = folder / argv[1]
    if argv[1].endswith(".jpk-force-map"):
        shutil.copy(ROOT / "tests" / "afm" / "data" / "fmt-jpk-fd_map-data-reference-points.jpk-force-map", src)
        return
    H = float(opt["--H"]) if opt.get("--H", "inf") not in ("height", "inf") else 2e-6 if "--H" in opt else np.inf
    if argv[1].endswith("/"):
        src.mkdir()
        src = src / "map.h5"
    write_synthetic_map(src, np.full((2, 2), 1000.0), H, R=float(opt["--R"]), nu=float(opt["--nu"]), points=200,
                        depth=0.2e-6, noise=2e-12, seed=5)
    if "--height-image" in opt:
        np.save(folder / opt["--height-image"], np.array([[0.0, 2e-6], [2e-6, 2e-6]]))


def _params():
    out = []
    for name, cmd, comment in EXAMPLES:
        marks = []
        if " report " in f" {cmd} ":
            marks.append(pytest.mark.xdist_group("catalogue-reports"))
        elif " validate " in f" {cmd} ":  # with the README's study: its cases are computed once per process
            marks.append(pytest.mark.xdist_group("validation-study"))
        if "minutes" in comment and not SLOW:
            marks.append(pytest.mark.skip(reason="takes minutes (its help says so): THINLAYER_SLOW=1 runs it"))
        out.append(pytest.param(cmd, id=f"{name}: {cmd[10:70]}", marks=marks))
    return out


@pytest.mark.parametrize("cmd", _params())
def test_help_example_runs(cmd, tmp_path, monkeypatch, capsys):
    shutil.copytree(ROOT / "derivations", tmp_path / "derivations")
    monkeypatch.chdir(tmp_path)
    argv = shlex.split(cmd)[1:]
    if "--pdf" in argv and shutil.which("pdflatex") is None:
        argv.remove("--pdf")
    if argv[0] == "fit":
        _curve(argv, tmp_path)
    if argv[0] == "fit-map":
        _map_inputs(argv, tmp_path)
    code = main(argv)
    out, err = capsys.readouterr()
    assert code == 0, f"{cmd!r} exited {code}: {err[-1500:]}"
    assert "Traceback" not in out + err
    written = [p for p in tmp_path.rglob("*") if p.is_file() and "derivations" not in p.parts
               and p.name != "curve.csv"]
    if "--out" in argv or "--output" in argv:
        assert written, f"{cmd!r} wrote no file"
        if "--quiet" not in argv and "--json" not in argv:
            assert "wrote" in out + err
    else:
        assert out.strip(), f"{cmd!r} printed nothing"
    if "--json" in argv and "--out" not in argv:
        data = json.loads(out)
        assert data, cmd
        if argv[0] == "fit":  # the curve was made with E = 2 by the any-thickness law
            assert abs(data["E"] / 2 - 1) < 0.02, data
    elif "--latex" in argv:
        assert "\\" in out, cmd
    elif "--format" in argv and argv[argv.index("--format") + 1] == "csv":
        rows = list(csv.DictReader(io.StringIO(out)))
        sweep = next(a for a in argv if re.fullmatch(r"[0-9.e+-]+:[0-9.e+-]+:\d+", a))
        assert len(rows) == int(sweep.rsplit(":", 1)[1]) and all(float(r["force"]) > 0 for r in rows)
    elif argv[0] in ("solve", "inner", "coefficients", "flat-punch", "fit"):  # text: Unicode maths
        assert "**" not in out and "+-" not in out, out
        assert re.search("[νδμΦκ𝒜ϑ]", out), out
