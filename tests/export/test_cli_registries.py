"""The command line's choices are the registries' keys (issue 29 item 5, the parts without the tip and model
registries): codegen languages, solve and fit models, and one name for the base option."""
from __future__ import annotations

import json

import pytest

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


# ---- the tip registry (issue 29 item 5): --tip everywhere a punch is taken, --kind/--flat deprecated ----------
SOLVE_SPHERE = ["solve", "--nu", "0.3", "--delta0", "0.1", "--H", "0.1", "--E", "2", "--json"]
SOLVE_FLAT = ["solve", "--nu", "0.3", "--delta0", "0.01", "--H", "0.5", "--mu", "1", "--json"]


def _listed_kinds(text: str) -> set[str]:
    """The kinds a --help text lists after 'KIND one of' (argparse wraps the line: whitespace is joined)."""
    text = " ".join(text.split())
    listed = text.split("KIND one of ", 1)[1].split(";", 1)[0]
    return {k.strip() for k in listed.split(",")}


def test_tip_kinds_in_help_and_errors_are_the_tip_registry(capsys):
    from thinlayer.export.cli_args import TIP_KINDS
    from thinlayer.punch import TIPS

    assert sorted(TIP_KINDS) == sorted(TIPS)
    for cmd in ("solve", "inner", "codegen"):
        text = _sub(cmd).format_help()
        assert _listed_kinds(text) == set(TIPS), cmd
        assert "--kind" not in text and "--flat " not in text, cmd  # the deprecated spellings are hidden
    assert main([*SOLVE_SPHERE, "--tip", "nosuchtip"]) == 2
    err = capsys.readouterr().err
    forms = err.split("valid forms: ", 1)[1].strip()
    assert {f.split(":", 1)[0].strip() for f in forms.split(", ") if "=" in f} == set(TIPS), err


def _run(capsys, argv):
    code = main(argv)
    out = capsys.readouterr()
    return code, out.out, out.err


def test_kind_is_a_deprecated_alias_with_a_one_line_note(capsys):
    code, out, err = _run(capsys, [*SOLVE_SPHERE, "--kind", "paraboloid", "--param", "R=10"])
    assert code == 0
    assert err.splitlines() == ["thinlayer: note: --kind paraboloid is deprecated; use --tip paraboloid:R=10"]
    code, tip_out, tip_err = _run(capsys, [*SOLVE_SPHERE, "--tip", "paraboloid:R=10"])  # the note's own advice
    assert (code, tip_err) == (0, "")
    old, new = json.loads(out), json.loads(tip_out)
    # --param R=10 substitutes the float 10.0, the spec the exact 10: the answer is the same to the bit, the
    # estimates (ratios of small differences) to rounding
    assert {k: old[k] for k in ("model", "force", "contact_area", "contact_radius", "delta0")} == {
        k: new[k] for k in ("model", "force", "contact_area", "contact_radius", "delta0")}
    assert old["error_estimate"] == pytest.approx(new["error_estimate"], rel=1e-12)
    # a --param name that is an alias of the kind's key is written as the key (R_1 -> R1)
    code, out, err = _run(capsys, ["inner", "--kind", "elliptic_paraboloid", "--param", "R_1=4", "--param", "R_2=1",
                                   "--json"])
    assert code == 0 and err.splitlines() == [
        "thinlayer: note: --kind elliptic_paraboloid is deprecated; use --tip elliptic_paraboloid:R1=4,R2=1"]
    code, new, err = _run(capsys, ["inner", "--tip", "elliptic_paraboloid:R1=4,R2=1", "--json"])
    assert (code, err) == (0, "")  # the spec's exact 4 and 1: x_1^2/(2*4) + x_2^2/(2*1), exact where --param is float
    assert json.loads(new)["punch"] == "x_1**2/8 + x_2**2/2"
    assert len(json.loads(new)["terms"]) == len(json.loads(out)["terms"])
    # an error given with --kind stays one line: the note is printed only after a command that succeeded
    code, out, err = _run(capsys, [*SOLVE_SPHERE[:-3], "0", "--E", "2", "--kind", "paraboloid", "--param", "R=10"])
    assert code == 2 and len(err.strip().splitlines()) == 1 and "note" not in err, err


def test_flat_is_a_deprecated_alias_with_a_one_line_note(capsys):
    code, out, err = _run(capsys, [*SOLVE_FLAT, "--flat", "1"])
    assert code == 0
    assert err.splitlines() == ["thinlayer: note: --flat 1 is deprecated; use --tip flat:a=1"]
    assert _run(capsys, [*SOLVE_FLAT, "--tip", "flat:a=1"]) == (0, out, "")
    code, out, err = _run(capsys, [*SOLVE_FLAT, "--flat", "-1"])
    assert code == 2 and len(err.strip().splitlines()) == 1 and "note" not in err, err


def test_tip_on_inner_and_codegen(capsys):
    """``--tip paraboloid`` (no R) is the catalogue paraboloid with its symbol R, as ``--kind paraboloid`` was."""
    for argv in (["inner", "--nu", "3/10", "--json"],
                 ["codegen", "force", "--lang", "python"],
                 ["codegen", "incompressible", "--lang", "c"],
                 ["codegen", "two-term", "--nu", "0.45", "--lang", "julia"]):
        code, old, note = _run(capsys, [*argv, "--kind", "paraboloid"])
        assert code == 0 and "deprecated" in note, argv
        assert _run(capsys, [*argv, "--tip", "paraboloid"]) == (0, old, ""), argv
    code, old, _ = _run(capsys, ["codegen", "composite", "--kind", "paraboloid", "--param", "R=2", "--nu", "0.3",
                                 "--delta0", "0.25", "--H", "0.02", "--lang", "python"])
    assert code == 0
    # R=2.0: the float that --param R=2 substitutes (R=2 would be the exact 2, and the code differs in the last bits)
    assert _run(capsys, ["codegen", "composite", "--tip", "paraboloid:R=2.0", "--nu", "0.3", "--delta0", "0.25",
                         "--H", "0.02", "--lang", "python"]) == (0, old, "")
    code, old, _ = _run(capsys, ["codegen", "incompressible", "--kind", "elliptic_paraboloid", "--param", "R_1=4",
                                 "--param", "R_2=1", "--lang", "python"])
    assert code == 0 and "IncompressibleEllipse" in old
    assert _run(capsys, ["codegen", "incompressible", "--tip", "elliptic_paraboloid:R1=4.0,R2=1.0", "--lang",
                         "python"]) == (0, old, "")


def test_tip_refusals_are_one_line(capsys):
    cases = [(["inner", "--tip", "cone:half_angle=70"], "not a polynomial"),
             (["codegen", "inner", "--tip", "sphere:R=2", "--lang", "c"], "not a polynomial"),
             ([*SOLVE_SPHERE, "--tip", "paraboloid"], "write --tip paraboloid:R=VALUE"),
             ([*SOLVE_SPHERE, "--tip", "elliptic_paraboloid:R1=4"], "write --tip elliptic_paraboloid:R1=4,R2=VALUE"),
             (["codegen", "composite", "--tip", "paraboloid", "--nu", "0.3", "--delta0", "0.25", "--H", "0.02"],
              "write --tip paraboloid:R=VALUE"),
             ([*SOLVE_SPHERE, "--tip", "paraboloid:R=10", "--param", "R=1"], "leave out --param"),
             ([*SOLVE_SPHERE, "--tip", "paraboloid:R=10", "--kind", "paraboloid"], "exactly one of")]
    for argv, words in cases:
        code, out, err = _run(capsys, argv)
        assert code == 2 and out == "", argv
        assert len(err.strip().splitlines()) == 1 and words in err, (argv, err)


def test_solve_passes_the_tip_itself_to_solve(capsys, monkeypatch):
    """``--tip cone:half_angle=70`` reaches thinlayer.solve() as the registry's Cone (not a formula of it): the
    "must be a number, a string formula or a sympy expression, got Cone" refusal comes from the library's models,
    and the CLI works unchanged once solve() takes the tip."""
    import thinlayer.contact.solve as solve_module
    from thinlayer.punch import tip_from_spec

    seen = []

    def fake_solve(layer, punch, **kw):
        seen.append((punch, kw))
        raise ValueError("stop here")

    monkeypatch.setattr(solve_module, "solve", fake_solve)
    assert main([*SOLVE_SPHERE, "--tip", "cone:half_angle=70"]) == 2
    assert "stop here" in capsys.readouterr().err
    ((punch, kw),) = seen
    want = tip_from_spec("cone:half_angle=70")
    assert type(punch) is type(want) and punch.description == want.description
    assert punch.radial_profile(0.5) == want.radial_profile(0.5)
    assert kw["delta0"] == 0.1 and kw["H"] == 0.1 and kw["parameters"] == {}
