"""Shared machinery of the acceptance tables of the trust issues (issues 12 and 23).

Each module ``tests/acceptance/cases_<topic>.py`` contributes inputs tried as an attacker or a careless user
would.  It exposes

* ``CATEGORIES``: the category names it fills (a tuple of str, each a row of the table), and
* ``run(t: Tally, tmp: pathlib.Path) -> None``: tries its inputs and records one outcome per input with
  ``t.add(category, outcome, note)``.

The outcome of an input is decided by an independent check, never by the engine's own word:

``"clear"``   a documented one-line error (a thinlayer ``ValueError``/``TypeError`` subclass, exit 2 from
              the CLI), or, for a valid input, a correct answer;
``"crash"``   any other exception, a traceback, a second line of error, a wrong exit code;
``"hang"``    more than 10 s of CPU (the input's work, not the machine's load; 60 s wall at most) or the case's
              CPU limit;
``"wrong"``   an answer that is not positive and finite, or outside its stated estimate of an independent
              reference, or a raw LaTeX command in the output;
``"loss"``    a file that existed before the run changed, or a file was created outside the output folder;
``"code"``    code ran (a marker file appeared).

``tests/test_safe_input_acceptance.py`` collects every ``cases_*`` module, prints the table and asserts that
the last five columns are zero.
"""
from __future__ import annotations

import importlib
from collections import defaultdict
from pathlib import Path

OUTCOMES = ("clear", "crash", "hang", "wrong", "loss", "code")
HEADERS = {"clear": "clear error / correct", "crash": "crashes", "hang": "hangs (> 10 s)",
           "wrong": "silently wrong", "loss": "data loss", "code": "code executed"}


class Tally:
    """Counts per category and outcome, with a note for every input that did not come out ``"clear"``."""

    def __init__(self) -> None:
        self.rows: dict[str, dict[str, int]] = defaultdict(lambda: dict.fromkeys(("tried", *OUTCOMES), 0))
        self.notes: list[str] = []
        self.order: list[str] = []

    def add(self, category: str, outcome: str, note: str = "") -> None:
        if outcome not in OUTCOMES:
            raise ValueError(f"unknown outcome {outcome!r}; one of {OUTCOMES}")
        if category not in self.rows:
            self.order.append(category)
        row = self.rows[category]
        row["tried"] += 1
        row[outcome] += 1
        if outcome != "clear":
            self.notes.append(f"{category}: {outcome}: {note}")

    def totals(self) -> dict[str, int]:
        return {k: sum(r[k] for r in self.rows.values()) for k in ("tried", *OUTCOMES)}

    def table(self) -> str:
        cols = ("tried", *OUTCOMES)
        head = "| category | " + " | ".join("tried" if c == "tried" else HEADERS[c] for c in cols) + " |"
        lines = [head, "|---|" + "---:|" * len(cols)]
        for cat in self.order:
            r = self.rows[cat]
            lines.append(f"| {cat} | " + " | ".join(str(r[c]) for c in cols) + " |")
        tot = self.totals()
        lines.append("| **total** | " + " | ".join(f"**{tot[c]}**" for c in cols) + " |")
        return "\n".join(lines)


def case_modules() -> list:
    """The ``cases_*`` modules of this folder, sorted by name."""
    here = Path(__file__).resolve().parent
    return [importlib.import_module(f"{__name__}.{p.stem}") for p in sorted(here.glob("cases_*.py"))]
