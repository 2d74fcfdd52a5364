"""``thinlayer fit-map`` (issue 25 item 5): CSV, PNG, failures list and summary written; bad input exit 2, one line.

Run in-process through thinlayer.export.cli.main (capsys), on a 2 x 3 synthetic Hertz map (afmformats HDF5).
"""
from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest

pytest.importorskip("afmformats")

from thinlayer.afm.map_data import write_synthetic_map  # noqa: E402
from thinlayer.export.cli import main  # noqa: E402

E = np.array([[3e3, 5e3, 0.0], [7e3, 9e3, 1.1e4]])


@pytest.fixture(scope="module")
def map_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("cli") / "map.h5"
    return write_synthetic_map(path, E, math.inf, R=5e-6, points=200, depth=0.2e-6, noise=2e-12, seed=5)


def test_fit_map_writes_csv_png_failures_and_summary(map_file, tmp_path, capsys):
    out = tmp_path / "run"
    code = main(["fit-map", str(map_file), "--R", "5e-6", "--nu", "0.5", "--out", str(out)])
    cap = capsys.readouterr()
    assert code == 0, cap.err
    assert "MapResult 2 x 3 pixels" in cap.out and "5 ok" in cap.out
    assert "6/6 curves" in cap.err  # the progress counter (no tqdm) on stderr
    rows = list(csv.DictReader((out / "map.csv").open()))
    assert len(rows) == 6
    got = {(int(r["row"]), int(r["column"])): r for r in rows}
    for (i, j), want in np.ndenumerate(E):
        if want > 0:
            assert float(got[i, j]["E_Pa"]) == pytest.approx(want, rel=5e-3)
            assert got[i, j]["status"] == "ok"
        else:
            assert got[i, j]["E_Pa"] == "nan" and got[i, j]["status"] == "failed" and got[i, j]["reason"]
    failures = (out / "failures.txt").read_text().splitlines()
    assert len(failures) == 1 and failures[0].startswith("0, 2, map.h5[2]: failed: ")
    summary = json.loads((out / "summary.json").read_text())
    assert summary["counts"] == {"ok": 5, "flagged": 0, "failed": 1, "empty": 0} and summary["shape"] == [2, 3]
    assert summary["E_median_Pa"] == pytest.approx(7e3, rel=5e-3)
    assert (out / "E.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_existing_output_is_refused_before_any_fit(map_file, tmp_path, capsys):
    out = tmp_path / "run"
    out.mkdir()
    (out / "E.png").write_text("mine")
    code = main(["fit-map", str(map_file), "--R", "5e-6", "--nu", "0.5", "--out", str(out), "--no-progress"])
    err = capsys.readouterr().err
    assert code == 2 and "E.png exists" in err and "--overwrite" in err and err.count("\n") == 1
    assert (out / "E.png").read_text() == "mine" and not (out / "map.csv").exists()


@pytest.mark.parametrize("args, match", [
    (["--R", "5e-6", "--nu", "0.5"], "no such file"),
    (["--nu", "0.5"], "give exactly one of --R"),
    (["--R", "-1", "--nu", "0.5"], "must be > 0"),
    (["--R", "5e-6", "--nu", "0.7"], "(-1, 1/2]"),
    (["--R", "5e-6", "--nu", "0.5", "--H", "thick"], "not a number"),
    (["--R", "5e-6", "--nu", "0.5", "--height-image", "x.npy"], "--H height"),
    (["--R", "5e-6", "--nu", "0.5", "--scheduler", "mars"], "scheduler must be"),
])
def test_bad_input_exits_2_with_one_line(map_file, tmp_path, capsys, args, match):
    src = str(tmp_path / "missing.h5") if match == "no such file" else str(map_file)
    code = main(["fit-map", src, *args, "--out", str(tmp_path / "o"), "--no-progress"])
    err = capsys.readouterr().err
    assert code == 2 and match in err and err.count("\n") == 1 and "Traceback" not in err
    assert not (tmp_path / "o").exists()
