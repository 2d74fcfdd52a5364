"""Child processes of the tests behave the same however pytest was launched (issue 23, item 7).

A shell starts a background job (``pytest &``, ``nohup``, some CI runners) with SIGINT ignored, and an
ignored signal stays ignored across ``exec``: a child Python would then never see the Ctrl-C a test
sends it.  Every child a test signals starts through :data:`CHILD`: SIGINT and SIGTERM back at their
defaults and unblocked, and stdin at ``/dev/null``, so that nothing depends on the terminal either.
"""
from __future__ import annotations

import signal
import subprocess


def default_signals() -> None:
    """``preexec_fn``: SIGINT and SIGTERM at their default dispositions and unblocked, in the child."""
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT, signal.SIGTERM})


#: keyword arguments of ``subprocess.Popen``/``run`` for a child the test may signal
CHILD = {"stdin": subprocess.DEVNULL, "preexec_fn": default_signals}
