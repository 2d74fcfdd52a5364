"""Derivation files against their schema (issue 12, item 5): unknown keys, types, contradictions, bad files."""
from __future__ import annotations

from pathlib import Path

import pytest

from thinlayer.export.derivation import SCHEMA, DerivationFileError, check_schema, load_derivation

try:
    import tomllib
except ModuleNotFoundError:  # pragma: no cover
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[2]
BASE = {"derivation": "name='x'\n", "layer": "nu='3/10'\n", "punch": "kind='paraboloid'\n"}
OPTIONAL = {"coefficients": "order=2\n", "inner": "order=2\n", "edge_shift": "nu=[0.3]\n",
            "contact": "delta0=0.1\nH=0.01\nparameters={R=1}\n", "validation": "nu=[0.3]\n", "units": "length='mm'\n",
            "flat_punch": "a_over_H=[1]\n", "second_order": "nu=['3/10']\n", "tip": "H=1.0\n",
            "adhesion": "work_of_adhesion=0.1\n",
            "viscoelastic": "E0=3.0\nE_inf=1.0\ntau=0.2\nspeed=0.05\nduration=2.0\n"}


def _file(tmp_path, tables: dict) -> Path:
    f = tmp_path / "d.toml"
    f.write_text("".join(f"[{t}]\n{body}" for t, body in tables.items()))
    return f


@pytest.mark.parametrize("table", sorted(SCHEMA))
def test_unknown_key_in_every_table(tmp_path, table):
    tables = dict(BASE)
    if table in OPTIONAL:
        tables[table] = OPTIONAL[table]
    tables[table] = tables[table] + "nuu = '0.3'\n"
    f = _file(tmp_path, tables)
    with pytest.raises(DerivationFileError) as exc:
        load_derivation(f)
    msg = str(exc.value)
    assert str(f) in msg and f"[{table}]" in msg and "'nuu'" in msg and "valid keys" in msg
    assert all(k in msg for k in SCHEMA[table])  # every valid key is named
    assert "\n" not in msg


@pytest.mark.parametrize("table, line, expected", [
    ("derivation", "title = 5", "title = 5 is invalid: expected a string"),
    ("punch", "kind = ['paraboloid']", "kind = ['paraboloid'] is invalid"),
    ("coefficients", "order = 3.5", "order = 3.5 is invalid"),
    ("coefficients", "order = '3'", "order = '3' is invalid"),
    ("inner", "order = true", "order = True is invalid"),
    ("edge_shift", "nu = 0.3", "nu = 0.3 is invalid: expected a list"),
    ("layer", "model = 1", "model = 1 is invalid"),
    ("contact", "delta0 = 0.1\nH = 0.01\nparameters = 3", "parameters = 3 is invalid: expected a table"),
    ("contact", "delta0 = '0.1'\nH = 0.01\nparameters = {R = 1}", "delta0 = '0.1' is invalid"),
    ("contact", "delta0 = 0.1\nH = 0.01\nparameters = {R = 'big'}", "parameters.R = 'big' is invalid"),
    ("validation", "shapes = 'sphere'", "shapes = 'sphere' is invalid: expected a list"),
])
def test_types_checked(tmp_path, table, line, expected):
    tables = dict(BASE)
    tables[table] = {"derivation": "name='x'\n", "punch": ""}.get(table, tables.get(table, "")) + line + "\n"
    with pytest.raises(DerivationFileError) as exc:
        load_derivation(_file(tmp_path, tables))
    assert expected in str(exc.value), str(exc.value)


def test_table_that_is_not_a_table(tmp_path):
    f = tmp_path / "d.toml"
    f.write_text("coefficients = 3\n[derivation]\nname='x'\n[layer]\n[punch]\nkind='paraboloid'\n")
    with pytest.raises(DerivationFileError, match=r"\[coefficients\] must be a table"):
        load_derivation(f)


@pytest.mark.parametrize("tables, expected", [
    ({"layer": "nu='3/10'\n", "contact": "nu=0.4\ndelta0=0.1\nH=0.01\nparameters={R=1}\n"},
     "[contact] nu = 0.4 contradicts [layer] nu = '3/10'"),
    ({"layer": "nu=0.3\n", "contact": "nu=0.3\ndelta0=0.1\nH=0.01\nparameters={R=1}\n"}, "contradicts"),
    ({"layer": "model='frictionless'\nnu=0.3\n"}, "contradicts model = 'frictionless'"),
])
def test_contradictions_between_tables(tmp_path, tables, expected):
    all_tables = {**BASE, **tables}
    with pytest.raises(DerivationFileError) as exc:
        load_derivation(_file(tmp_path, all_tables))
    assert expected in str(exc.value)


@pytest.mark.parametrize("line, expected", [
    ("H = 1e300", "from 1e-30 to 1e+30"), ("H = inf", "H = inf is invalid"), ("H = nan", "H = nan is invalid"),
    ("H = -1", "H = -1 is invalid"),
])
def test_contact_numbers_in_range(tmp_path, line, expected):
    tables = {**BASE, "contact": f"delta0=0.1\n{line}\nparameters={{R=1}}\n"}
    with pytest.raises(DerivationFileError) as exc:
        load_derivation(_file(tmp_path, tables))
    assert expected in str(exc.value)


def test_tiny_parameter_is_an_error(tmp_path):
    tables = {**BASE, "contact": "delta0=0.1\nH=0.01\nparameters={R=1e-300}\n"}
    with pytest.raises(DerivationFileError, match=r"parameters\] R = 1e-300 is invalid"):
        load_derivation(_file(tmp_path, tables))


def test_binary_nonutf8_folder_and_missing_file(tmp_path):
    binary = tmp_path / "b.toml"
    binary.write_bytes(b"\x00\x01\x02[derivation]\n")
    latin = tmp_path / "l.toml"
    latin.write_bytes("[derivation]\nname='x'\ntitle='caf\xe9'\n".encode("latin-1"))
    for path, expected in ((binary, "binary file"), (latin, "not a UTF-8 text file"), (tmp_path, "is a folder"),
                           (tmp_path / "none.toml", "does not exist")):
        with pytest.raises(DerivationFileError) as exc:
            load_derivation(path)
        assert str(path) in str(exc.value) and expected in str(exc.value)
        assert "\n" not in str(exc.value)


def test_bad_names_and_titles(tmp_path):
    for name, expected in (("-x", "name = '-x'"), ("caf\u00e9", "ASCII")):
        with pytest.raises(DerivationFileError, match=expected):
            load_derivation(_file(tmp_path, {**BASE, "derivation": f"name='{name}'\n"}))
    for title, expected in (("a\\u0007b", "U+0007"), ("\\U0001F600", "U+1F600"), ("\u4e2d", "U+4E2D")):
        with pytest.raises(DerivationFileError) as exc:
            load_derivation(_file(tmp_path, {**BASE, "derivation": f"name='x'\ntitle=\"{title}\"\n"}))
        assert expected in str(exc.value) and "cannot be set by LaTeX" in str(exc.value)


@pytest.mark.parametrize("path", sorted((ROOT / "derivations").glob("*.toml")), ids=lambda p: p.stem)
def test_shipped_files_follow_the_schema(path):
    check_schema(tomllib.loads(path.read_text()))  # raises on an unknown key or a wrong type


@pytest.mark.parametrize("line, expected", [
    ("nu = 0.3", "nu = 0.3 is invalid: expected a list"),
    ("nu = []", "a list of 1 to 12 Poisson ratios"),
    ("nu = [0.1, 0.2, 0.3, 0.4, 0.1, 0.2, 0.3, 0.4, 0.1, 0.2, 0.3, 0.4, 0.1]", "a list of 1 to 12 Poisson ratios"),
    ("nu = ['1/2']", "'1/2' is outside (-1, 1/2)"),
    ("nu = [0.5]", "0.5 is outside (-1, 1/2)"),
    ("nu = [-1]", "-1 is outside (-1, 1/2)"),
    ("nu = ['__import__(\"os\")']", "is invalid"),
    ("nu = ['3/10 + 1']", "is invalid"),
    ("nu = [true]", "True is invalid"),
    ("nu = ['bonded']", "'bonded' is invalid"),
])
def test_second_order_table_is_validated(tmp_path, line, expected):
    tables = {**BASE, "second_order": line + "\n"}
    with pytest.raises(DerivationFileError) as exc:
        load_derivation(_file(tmp_path, tables))
    assert "[second_order]" in str(exc.value) and expected in str(exc.value), str(exc.value)
    assert "\n" not in str(exc.value)


def test_second_order_table_accepts_numbers_fractions_and_the_frictionless_base(tmp_path):
    from fractions import Fraction

    tables = {**BASE, "second_order": "nu = ['0', '3/10', 0.45, -0.5, 'frictionless']\n"}
    der = load_derivation(_file(tmp_path, tables))
    assert der.second_order == {"nu": [Fraction(0), Fraction(3, 10), 0.45, -0.5, "frictionless"]}
    default = load_derivation(_file(tmp_path, {**BASE, "second_order": ""}))
    assert len(default.second_order["nu"]) == 6 and "frictionless" in default.second_order["nu"]
    assert load_derivation(_file(tmp_path, BASE)).second_order is None


@pytest.mark.parametrize("tables", [
    {"layer": "nu='1/2'\n"},
    {"punch": "kind='flat'\n", "flat_punch": "a_over_H=[1]\n"},
])
def test_second_order_needs_the_compressible_expansion_of_a_polynomial_punch(tmp_path, tables):
    with pytest.raises(DerivationFileError, match=r"\[second_order\] is for the compressible expansion"):
        load_derivation(_file(tmp_path, {**BASE, **tables, "second_order": "nu=[0.3]\n"}))
