"""The restricted grammar (parse.py): user formulas are read, never run."""
from __future__ import annotations

import pathlib
import re

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from thinlayer import symbols as S
from thinlayer.parse import MAX_EXPONENT, ExpressionError, parse_expression, parse_number

SRC = pathlib.Path(__file__).resolve().parents[1] / "src" / "thinlayer"

ATTACKS = [
    "x_1**2 + 0*__import__('os').system('touch pwned')",
    "__import__('os')",
    "x_1.__class__",
    "exec('1')",
    "eval('1')",
    "lambda: 1",
    "[x_1]",
    "x_1; import os",
    "x_1 if 1 else 2",
    "'x_1'",
    "x_1 = 2",
    "x_1 @ x_2",
    "x_1 ^ 2",
    "x_1**x_2",
    "sqrt(x_1)",
    "Symbol('x')",
    "9**9**9",
    "x_1**100000",
    "(" * 500 + "x_1" + ")" * 500,
    "-" * 5000 + "x_1",
    "x_1 " * 3000,
    "",
    "1/0",
    "x_1 +",
]


@pytest.mark.parametrize("text", ATTACKS)
def test_anything_outside_the_grammar_is_a_clear_error(text, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ExpressionError) as info:
        parse_expression(text)
    message = str(info.value)
    assert "\n" not in message and len(message) < 300
    assert not (tmp_path / "pwned").exists()


def test_the_error_names_the_token_and_its_position():
    with pytest.raises(ExpressionError, match=r"'__import__' at position 11"):
        parse_expression("x_1**2 + 0*__import__('os')")
    with pytest.raises(ExpressionError, match=r"'\^' at position 4 .*x\*\*2"):
        parse_expression("x_1 ^ 2")


def test_polynomials_read_as_sympy_would():
    R1, R2 = sp.symbols("R_1 R_2")
    assert parse_expression("x_1**2/(2*R_1) + x_2**2/(2*R_2)") == S.x1**2 / (2 * R1) + S.x2**2 / (2 * R2)
    assert parse_expression("-x_1**2") == -(S.x1**2)  # a sign binds looser than a power, as in Python
    assert parse_expression("2**-1*x1") == S.x1 / 2
    assert parse_expression("2**3**2") == 2**9  # right-associative
    assert parse_expression("1e-71*x_1**2*x_2**2 + 0.3") == sp.Float("1e-71") * S.x1**2 * S.x2**2 + sp.Float("0.3")


@pytest.mark.parametrize("name", ["E", "I", "S", "N", "Q", "beta", "gamma", "lambda", "pi", "oo", "zoo", "nan"])
def test_sympy_constant_and_function_names_are_plain_symbols(name):
    e = parse_expression(f"x_1**2/2 + {name}*x_2**2")
    assert sp.Symbol(name) in e.free_symbols
    assert e.coeff(S.x2**2) == sp.Symbol(name)


def test_declared_names_only():
    assert parse_expression("x_1**2/R", names=["R"]) == S.x1**2 / sp.Symbol("R")
    with pytest.raises(ExpressionError, match="unknown name 'K'.*valid names are R"):
        parse_expression("x_1**2/K", names=["R"])


def test_numbers_exact_where_the_input_is():
    assert parse_number("3/10", "nu") == sp.Rational(3, 10)
    assert parse_number(3, "n") == 3
    assert parse_number("0.3", "nu") == sp.Float("0.3")
    for bad in ("x_1", "R", "1/0", "2**2000/2**1999 + R"):
        with pytest.raises(ExpressionError):
            parse_number(bad, "nu")


def test_exponent_limit():
    assert parse_expression(f"x_1**{MAX_EXPONENT}") == S.x1**MAX_EXPONENT
    with pytest.raises(ExpressionError, match="exponent"):
        parse_expression(f"x_1**{MAX_EXPONENT + 1}")


@settings(max_examples=200, deadline=None)
@given(st.text(alphabet="x_12Rab+-*/() .e^'[]=:;,", max_size=60))
def test_random_text_never_crashes(text):
    try:
        out = parse_expression(text)
    except ExpressionError:
        return
    assert isinstance(out, sp.Basic)


def test_no_sympify_eval_or_nsimplify_in_the_source():
    """The restricted parser is the only door for user strings: the source calls none of the evaluators."""
    pattern = re.compile(r"\b(sympify|nsimplify|parse_expr|eval|exec)\s*\(|sp\.S\(|\bS\(\s*['\"]")
    bad = []
    for path in sorted(SRC.rglob("*.py")):
        for k, line in enumerate(path.read_text().splitlines(), 1):
            code = line.split("#")[0]
            if re.match(r"\s*def eval\(cls", code):  # sympy's Function.eval protocol, not an evaluator
                continue
            if pattern.search(code) and not re.search(r"['\"].*\b(sympify|eval)\b.*['\"]", code):
                bad.append(f"{path.relative_to(SRC)}:{k}: {line.strip()}")
    assert not bad, "\n".join(bad)
