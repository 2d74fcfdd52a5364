"""Derivation files and the LaTeX report (the ``report``/``derive`` subcommand: test_cli.py)."""
import shutil
from pathlib import Path

import pytest

from thinlayer.export.derivation import DerivationFileError, load_derivation, report_latex, write_report

ROOT = Path(__file__).resolve().parents[2]


def test_default_derivation_report(tmp_path):
    der = load_derivation(ROOT / "derivations" / "quartic_punch.toml")
    tex = write_report(der, tmp_path)
    text = tex.read_text()
    for tag in ("2.3", "2.20", "4.2", "2.21", "2.22", "2.27", "4.1", "2.26"):
        assert rf"\tag{{{tag}}}" in text
    from thinlayer import errata

    # issue 28: its own errata, not the registry: the eight entries of the seed paper that concern the quartic
    # punch's equations (test_report_quality.EXPECTED_ERRATA spells them out), none of the other publications
    assert "Errata" in text and text.count(r"\paragraph{(") == 8 < len(errata.ENTRIES)
    assert text.count(r"\paragraph{") == 8


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="needs pdflatex (installed by .ci/run)")
@pytest.mark.parametrize("path", sorted((ROOT / "derivations").glob("*.toml")), ids=lambda p: p.stem)
def test_every_shipped_derivation_compiles_without_overfull_lines(catalogue_report, path):
    from thinlayer.export.report import overfull_boxes

    der = load_derivation(path)
    tex = catalogue_report(path.stem)  # write_report(der, <a folder>, pdf=True), shared with test_report_quality
    assert tex.with_suffix(".pdf").stat().st_size > 10_000
    log = tex.with_suffix(".log").read_text()
    assert overfull_boxes(log) == [], f"{path.name}: lines run off the page"
    if der.validation is not None:  # the validation plots are included in the report
        figs = sorted(p.name for p in (tex.parent / f"{der.name}-figures").glob("*.pdf"))
        assert figs and all(f"{der.name}-figures/{f}" in tex.read_text() for f in figs)


def test_overfull_detector():
    from thinlayer.export.report import overfull_boxes

    log = "Overfull \\hbox (24.3pt too wide) detected at line 46\nOverfull \\hbox (0.2pt too wide) in paragraph"
    assert overfull_boxes(log) == ["Overfull \\hbox (24.3pt too wide) detected at line 46"]


def test_failed_latex_leaves_no_files(tmp_path, monkeypatch):
    import thinlayer.asymptotics.inner as I

    der = load_derivation(ROOT / "derivations" / "quartic_punch.toml")

    def broken(*_args, **_kw):
        raise RuntimeError("stage failed")

    monkeypatch.setattr(I, "inner_pressure", broken)  # the report imports the stage when it needs it
    with pytest.raises(RuntimeError, match="stage failed"):
        write_report(der, tmp_path / "out")
    assert not list(tmp_path.rglob("*.tex")) and not list(tmp_path.rglob("*.tmp"))


@pytest.mark.parametrize("content, message", [
    ("[derivation]\nname='x'\n", "[layer]"),
    ("[derivation]\nname='x'\n[layer]\nnu=0.7\n[punch]\nkind='elliptic_paraboloid'\n", "-1 < nu < 1/2"),
    ("[derivation]\nname='x'\n[layer]\nmodel='rubber'\n[punch]\nkind='paraboloid'\n", "valid models"),
    ("[derivation]\nname='x'\n[layer]\n[punch]\nexpr='exp(x_1)'\n", "not a polynomial"),
    ("[derivation]\nname='x'\n[layer]\n[punch]\nkind='cone'\n", "valid kinds"),
    ("[derivation]\nname='x'\n[layer]\n[punch]\nkind='paraboloid'\n[inner]\norder=0\n", "positive integer"),
    ("[derivation]\nname='x'\n[layer]\n[punch]\nkind='paraboloid'\n[extra]\n", "unknown table"),
    ("[derivation\n", "not valid TOML"),
    ("[derivation]\nname='x'\n[layer]\n[punch]\nkind='paraboloid'\n[validation]\nH_over_a=[0.5]\n",
     "[validation] H_over_a"),
    ("[derivation]\nname='x'\n[layer]\n[punch]\nkind='paraboloid'\n[validation]\nshapes=['cube']\n",
     "[validation] shapes"),
    ("[derivation]\nname='x'\n[layer]\n[punch]\nkind='paraboloid'\n[contact]\ndelta0=0.1\nH=0.1\n"
     "parameters={R=1}\n", "because [layer] nu is symbolic"),
    ("[derivation]\nname='x'\n[layer]\nnu=0.3\n[punch]\nkind='paraboloid'\n[contact]\ndelta0=0.1\n"
     "parameters={R=1}\n", "missing the key 'H'"),
    ("[derivation]\nname='x'\n[layer]\nnu=0.3\n[punch]\nkind='paraboloid'\n[contact]\ndelta0=0.1\nH=-1\n"
     "parameters={R=1}\n", "H = -1 is invalid"),
    ("[derivation]\nname='x'\n[layer]\nnu=0.3\n[punch]\nkind='paraboloid'\n[contact]\ndelta0=0.1\nH=1\n"
     "parameters={R_1=1}\n", "not parameters of the punch"),
    ("[derivation]\nname='x'\n[layer]\nnu=0.3\n[punch]\nkind='paraboloid'\n[contact]\ndelta0=0.1\nH=1\n",
     "values missing for ['R']"),
    ("[derivation]\nname='x'\n[layer]\nnu=0.3\n[punch]\nkind='paraboloid'\n[contact]\nH=1\n"
     "parameters={R=1}\n", "exactly one of 'delta0'"),
    ("[derivation]\nname='x'\n[layer]\nnu=0.3\n[punch]\nkind='paraboloid'\n[contact]\nH=1\ndelta0=1\n"
     "parameters={R=1}\nsize=3\n", "unknown key(s) ['size']"),
])
def test_malformed_derivation_files(tmp_path, content, message):
    f = tmp_path / "bad.toml"
    f.write_text(content)
    with pytest.raises(DerivationFileError) as exc:
        load_derivation(f)
    assert message in str(exc.value)


def test_report_contains_edge_shift_table():
    der = load_derivation(ROOT / "derivations" / "elliptic_paraboloid.toml")
    text = report_latex(der)
    assert "Wiener" in text and r"\tag{3.1}" in text


def test_report_contains_boundary_layer_force_law_and_solution():
    der = load_derivation(ROOT / "derivations" / "elliptic_paraboloid.toml")
    text = report_latex(der)
    for tag in ("3.19", "3.20--3.21", "3.23", "3.24", "3.25", "1.8"):
        assert rf"\tag{{{tag}}}" in text
    assert "Contact solution for numeric parameters" in text
    # the numeric solution's force agrees with thinlayer.solve called directly
    from thinlayer import BondedLayer, Punch, solve
    from thinlayer.export._normal import float_latex

    sol = solve(BondedLayer(0.3), Punch.elliptic_paraboloid(4, 1), delta0=0.5, H=0.05, mu=1.0)
    assert f"= {float_latex(sol.force)}" in text and f"{sol.force:.6g}" in text


def test_report_contains_validation_table(sphere_latex):
    der = load_derivation(ROOT / "derivations" / "sphere.toml")
    assert der.validation == {"nu": [0.3], "H_over_a": [0.1, 0.05, 0.025], "shapes": ["sphere"]}
    text = sphere_latex  # report_latex(der), shared with test_derivation_models
    assert "Validation against the direct numerical solution" in text and "tabular" in text
