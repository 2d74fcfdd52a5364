"""``thinlayer solve --work-of-adhesion W``: one line per quantity with its estimate; bad values exit 2, one line."""
from __future__ import annotations

import json
import math

import pytest

from thinlayer.export.cli import main

BASE = ["solve", "--nu", "0.3", "--H", "0.1", "--mu", "1"]


def test_flat_punch_text_says_tensile_and_pull_off(capsys):
    assert main([*BASE, "--tip", "flat:a=1", "--delta0=-0.01", "--work-of-adhesion", "0.01", "--pull-off"]) == 0
    out = capsys.readouterr().out
    assert "tensile (pulling) force" in out and "(punch above the undeformed surface)" in out
    line = next(ln for ln in out.splitlines() if "pull-off force, load control" in ln)
    # Kendall's thin-film law with its first correction (J.13), by hand: A = 0.2/0.49, h* = 0.1221
    hand = math.pi * (1 + 0.1221 * 0.1) ** 1.5 * math.sqrt(2 * (1 / 0.7) * 0.01 / (0.2 / 0.49 * 0.1))
    assert abs(float(line.split("=")[1].split()[0]) / hand - 1) < 2e-3
    assert "model: direct" in out


def test_law_json_states_branch_and_sign(capsys):
    assert main([*BASE, "--tip", "paraboloid:R=10", "--force=-0.3", "--work-of-adhesion", "0.01", "--json"]) == 0
    obj = json.loads(capsys.readouterr().out)
    assert obj["model"] == "thin-layer-jkr" and obj["tensile"] is True and obj["force"] == 0.3
    assert obj["signed_force"] == -0.3 and obj["branch"] == "stable" and obj["control"] == "load"
    assert max(obj["error_estimate"].values()) <= 0.05


@pytest.mark.parametrize("extra", [["--work-of-adhesion", "-1"], ["--work-of-adhesion", "abc"],
                                   ["--work-of-adhesion", "0.01", "--branch", "up"],
                                   ["--work-of-adhesion", "0.01", "--format", "csv"],
                                   ["--work-of-adhesion", "0.01", "--delta0", "0.01,0.02"]])
def test_bad_values_exit_2_one_line(capsys, extra):
    argv = [*BASE, "--tip", "paraboloid:R=10", *extra]
    if "--delta0" not in extra:
        argv += ["--delta0", "0.01"]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert err and "\n" not in err and "Traceback" not in err


def test_detached_flat_punch_exit_2(capsys):
    assert main([*BASE, "--tip", "flat:a=1", "--delta0=-1", "--work-of-adhesion", "0.01"]) == 2
    assert "come off" in capsys.readouterr().err
