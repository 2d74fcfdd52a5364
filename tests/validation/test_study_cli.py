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


def test_cli_refuses_existing_outputs_before_the_study(tmp_path):
    from thinlayer.validation.output import OutputExistsError

    (tmp_path / "validation.tex").write_text("my edited table\n")
    args = _parser().parse_args(["validate", "--shapes", "sphere", "--nu", "0.3", "--out", str(tmp_path), "--quiet"])
    with pytest.raises(OutputExistsError, match="validation.tex exists; pass --overwrite"):
        args.func(args)
    assert (tmp_path / "validation.tex").read_text() == "my edited table\n"
    assert "--overwrite" in _parser()._subparsers._group_actions[0].choices["validate"].format_help()


def test_cli_plots_written_atomically_and_kept_without_force(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    from planting import quick_validation

    # the files are what is checked here (written through atomic_write, refused, replaced with --force): figures are
    # saved as a few bytes of their format (tests/planting.py), not drawn; drawing them (3 s of CPU per figure set,
    # 12 s for this test) is checked by tests/validation/test_study_plots.py and the README's validate --plots
    with quick_validation():
        _plots_written_atomically_and_kept_without_force(tmp_path)


def _plots_written_atomically_and_kept_without_force(tmp_path):
    from thinlayer.validation.output import OutputExistsError

    argv = ["validate", "--shapes", "sphere", "--nu", "0.3", "--ratios", "0.05", "--out", str(tmp_path),
            "--plots", "--quiet"]
    args = _parser().parse_args(argv)
    assert args.func(args) in (0, 1)  # one H/a: no observed order to fit, the files are what is checked
    names = {p.name for p in tmp_path.iterdir()}
    assert {"validation_errors.png", "validation_errors.pdf", "validation.json"} <= names
    assert not [n for n in names if n.endswith(".tmp") or n.endswith(".lock")]
    png = tmp_path / "validation_errors.png"
    png.write_bytes(b"my figure")
    for suffix in (".txt", ".tex", ".json"):
        (tmp_path / f"validation{suffix}").unlink()
    args = _parser().parse_args(argv)
    with pytest.raises(OutputExistsError, match="validation_errors.png exists"):
        args.func(args)
    assert png.read_bytes() == b"my figure" and not (tmp_path / "validation.json").exists()
    args = _parser().parse_args([*argv, "--force"])
    assert args.func(args) in (0, 1) and png.read_bytes()[:4] == b"\x89PNG"


def test_default_shapes_are_every_shape():
    # the parser spells the default out so that building it imports no solver
    from thinlayer.validation.cases import SHAPES
    from thinlayer.validation.cli import DEFAULT_SHAPES

    assert DEFAULT_SHAPES == ",".join(SHAPES)
