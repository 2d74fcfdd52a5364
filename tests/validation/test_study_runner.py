"""Running a validation study (thinlayer.validation.runner): progress, interruption, skipped cases, the full study.

The full study (every nu, nine H/a, the 2D elliptic case everywhere) is ``slow``.
"""
from __future__ import annotations

import json
import sys

import pytest

from thinlayer.validation import StudyEvent, validate_elliptic, validate_sphere, validation_study


def test_progress_lines_on_stderr(capsys):
    validate_sphere(0.3, (0.1, 0.05), progress=True)
    err = capsys.readouterr().err
    assert "validate: [1/2] sphere nu=0.3 H/a=0.1" in err and "[2/2]" in err


def test_progress_bar_with_tqdm_on_a_terminal(monkeypatch):
    import io
    import types

    from thinlayer.validation.runner import Progress

    calls = []

    class FakeTqdm:
        def __init__(self, total, file, unit, desc):
            calls.append(("init", total))

        def set_postfix_str(self, s):
            calls.append(("label", s))

        def update(self, k):
            calls.append(("update", k))

        def close(self):
            calls.append(("close",))

    class Tty(io.StringIO):
        def isatty(self):
            return True

    monkeypatch.setitem(sys.modules, "tqdm", types.SimpleNamespace(tqdm=FakeTqdm))
    stream = Tty()
    prog = Progress(True, 2, stream)
    prog.start(0, "sphere nu=0.3 H/a=0.1", False)
    prog.done(0, "sphere nu=0.3 H/a=0.1", 0.1)
    prog.close(False, 1)
    assert calls == [("init", 2), ("label", "sphere nu=0.3 H/a=0.1"), ("update", 1), ("close",)]
    assert stream.getvalue() == ""  # the bar replaces the lines
    # not a terminal: plain lines, no bar
    plain = io.StringIO()
    prog = Progress(True, 2, plain)
    prog.done(0, "x", 0.1)
    assert prog.bar is None and plain.getvalue().startswith("validate: [1/2] x")


@pytest.mark.parametrize("stage, at, done", [("start", 2, 2), ("done", 0, 1)])
def test_keyboard_interrupt_keeps_rows(stage, at, done, tmp_path):
    events: list[StudyEvent] = []

    def hook(ev: StudyEvent):
        events.append(ev)
        if ev.stage == stage and ev.index == at:
            raise KeyboardInterrupt

    study = validate_sphere(0.3, (0.2, 0.1, 0.05), callback=hook)
    assert study.interrupted
    assert len(study.rows) == done
    assert [r.H_over_a for r in study.rows] == pytest.approx([0.2, 0.1][:done])
    assert [p[2] for p in study.pending] == pytest.approx([0.2, 0.1, 0.05][done:])
    assert events[0].stage == "start" and events[0].total == 3
    assert "INTERRUPTED" in study.table()
    files = study.write(tmp_path)  # the rows done are saved
    d = json.loads(files[-1].read_text())
    assert d["interrupted"] is True and len(d["rows"]) == done


def test_other_callback_errors_propagate():
    def hook(ev):
        raise RuntimeError("boom")

    with pytest.raises(RuntimeError, match="boom"):
        validate_sphere(0.3, (0.1,), callback=hook)


def test_grid_too_large_is_skipped_with_reason():
    study = validate_elliptic(0.3, (0.0125,), max_n=512)
    assert not study.rows
    ((shape, nu, eps, why),) = study.skipped
    assert (shape, nu, eps) == ("elliptic", 0.3, 0.0125) and "max_n = 512" in why
    assert "skipped" in study.table()


# ---------------------------------------------------------------------------------------------
# the full study
# ---------------------------------------------------------------------------------------------
@pytest.mark.slow
def test_full_study():
    study = validation_study(full=True, progress=True)
    assert not study.interrupted
    assert len({r.nu for r in study.rows}) == 5
    fits = [f for f in study.observed_orders(("force", "contact_area", "pressure")) if f.observed is not None]
    assert fits and all(f.matches for f in fits), [f for f in fits if not f.matches]
    checks = study.edge_shift_checks()
    assert len(checks) == 5 and all(c.status == "ok" for c in checks)
    assert {r.shape for r in study.rows} == {"sphere", "elliptic"}
