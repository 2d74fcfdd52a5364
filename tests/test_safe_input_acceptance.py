"""Acceptance table of the trust issues (12 and 23): inputs tried per category and what came back.

Every ``tests/acceptance/cases_*.py`` module contributes inputs tried as an attacker or a careless user would,
through the Python API, the command line and derivation files (the contract and the outcomes are in
``tests/acceptance/__init__.py``).  Each input is a hang past 10 s of CPU (60 s wall at most), and each outcome is
classified by an independent check, never by the engine's own word:

* **clear** -- a documented one-line error (a thinlayer ``ValueError``/``TypeError``, exit 2 from the CLI), or,
  for a valid input, a correct answer;
* **crash** -- any other exception, a traceback, a second line of error, a wrong exit code;
* **hang** -- more than 10 s;
* **wrong** -- an answer not positive and finite, outside its stated estimate of an independent route, or a raw
  LaTeX command in the output;
* **loss** -- a file that existed before a refused run changed, or one created outside the output folder;
* **code** -- code ran (a marker file appeared).

``python tests/test_safe_input_acceptance.py`` prints the table; the test asserts at least 257 (the first round)
+ 150 inputs and that the last five columns are all 0.
"""
from __future__ import annotations

import time
from pathlib import Path

import pytest
from acceptance import Tally, case_modules

#: tests/export/test_symlink_safety.py tries the data-loss inputs of tests/acceptance/cases_files.py: one worker
#: runs both, and planting.attack runs each input once
pytestmark = pytest.mark.xdist_group("file-attacks")

#: the first round's inputs (issue 12) plus at least 150 new ones (issue 23)
MIN_TRIED = 257 + 150


def run(tmp: Path) -> Tally:
    t = Tally()
    for mod in case_modules():
        sub = tmp / mod.__name__.rsplit(".", 1)[-1]
        sub.mkdir(parents=True, exist_ok=True)
        t0 = time.monotonic()
        mod.run(t, sub)
        t.notes.append(f"({mod.__name__.rsplit('.', 1)[-1]}: {time.monotonic() - t0:.1f} s)")
    return t


def test_acceptance_table(tmp_path, capsys):
    t = run(tmp_path)
    with capsys.disabled():
        print("\n" + t.table())
    tot = t.totals()
    assert tot["tried"] >= MIN_TRIED, tot
    bad = {k: tot[k] for k in ("crash", "hang", "wrong", "loss", "code") if tot[k]}
    assert not bad, f"{bad}\n" + "\n".join(n for n in t.notes if not n.startswith("("))


if __name__ == "__main__":
    import tempfile

    with tempfile.TemporaryDirectory() as d:
        tally = run(Path(d))
    print(tally.table())
    print("\n".join(tally.notes))
