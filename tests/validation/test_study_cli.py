"""The command ``thinlayer validate`` (thinlayer.validation.cli)."""
from __future__ import annotations

import argparse
import json

import pytest

from thinlayer.validation import add_cli


def _parser():
    ap = argparse.ArgumentParser(prog="thinlayer")
    sub = ap.add_subparsers(dest="cmd", required=True)
    add_cli(sub, argparse.RawDescriptionHelpFormatter)
    return ap


def test_cli_writes_files_and_json(tmp_path, capsys):
    args = _parser().parse_args(["validate", "--shapes", "sphere", "--nu", "0.3", "--ratios", "0.1,0.05,0.025",
                                 "--out", str(tmp_path), "--json", "--quiet"])
    assert args.func(args) == 0
    out = json.loads(capsys.readouterr().out)
    assert [r["H_over_a"] for r in out["rows"]] == pytest.approx([0.1, 0.05, 0.025])
    assert {p.name for p in tmp_path.iterdir()} == {"validation.txt", "validation.tex", "validation.json"}


def test_cli_bad_input():
    ap = _parser()
    for argv, msg in ((["validate", "--plots"], "--plots needs --out"),
                      (["validate", "--nu", "0.3,x"], "'x' is not a number"),
                      (["validate", "--ratios", "0.9", "--quiet"], "validated range")):
        args = ap.parse_args(argv)
        with pytest.raises(ValueError, match=msg):
            args.func(args)
