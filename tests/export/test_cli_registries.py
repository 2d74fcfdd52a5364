"""The command line's choices are the registries' keys (issue 29 item 5, the parts without the tip and model
registries): codegen languages, solve and fit models, and one name for the base option."""
from __future__ import annotations

import json

from thinlayer.export.cli import build_parser, main


def _sub(name):
    return build_parser()._subparsers._group_actions[0].choices[name]


def _choices(parser, option):
    (action,) = [a for a in parser._actions if option in a.option_strings]
    return tuple(action.choices)


def test_codegen_languages_are_the_codegen_registry(capsys):
    from thinlayer.export import cli
    from thinlayer.export.codegen import LANGUAGES

    assert cli.LANGUAGES == LANGUAGES
    assert main(["codegen", "coefficients", "--order", "1", "--lang", "all", "--json"]) == 0
    assert tuple(c["language"] for c in json.loads(capsys.readouterr().out)) == LANGUAGES
    assert main(["codegen", "coefficients", "--order", "1", "--lang", "cobol"]) == 2
    assert ", ".join(LANGUAGES) in capsys.readouterr().err


def test_tabulated_languages_are_what_the_tabulated_laws_write():
    from thinlayer.contact.any_thickness import any_thickness_source
    from thinlayer.export.cli import TABULATED_LANGUAGES

    for lang in TABULATED_LANGUAGES:
        assert any_thickness_source(0.3, "bonded", lang)


def test_model_choices_are_the_models_of_solve_and_fit():
    from thinlayer.contact.fit import FIT_MODELS
    from thinlayer.contact.solve import MODELS

    assert _choices(_sub("solve"), "--model") == MODELS
    assert _choices(_sub("fit"), "--model") == FIT_MODELS


def test_one_name_for_the_base():
    for cmd in ("solve", "coefficients", "inner", "codegen", "fit", "flat-punch"):
        p = _sub(cmd)
        assert _choices(p, "--base") == ("bonded", "frictionless"), cmd
        text = p.format_help()
        assert "--base" in text and "--layer" not in text, cmd


def test_solve_models_and_tips_are_the_registries(capsys):
    from thinlayer.contact.models import fit_names, model_names
    from thinlayer.punch import TIPS

    assert _choices(_sub("solve"), "--model") == model_names()
    assert _choices(_sub("fit"), "--model") == fit_names()
    # --tip takes every kind of the tip registry (its value is parsed by tip_from_spec)
    assert "thinlayer.punch.TIPS" in _sub("solve").format_help()
    argv = ["solve", "--nu", "0.3", "--delta0", "0.01", "--H", "0.5", "--mu", "1", "--json"]
    assert main([*argv, "--tip", "flat:a=1"]) == 0
    a = json.loads(capsys.readouterr().out)
    assert main([*argv, "--flat", "1"]) == 0
    assert json.loads(capsys.readouterr().out)["force"] == a["force"]
    assert main([*argv, "--tip", "nosuchtip:a=1"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "cone" in err, err
    assert "flat" in TIPS and "cone" in TIPS
