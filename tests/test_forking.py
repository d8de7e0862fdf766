"""The per-student forks: a child that dies or hangs is reported, and the rest go on."""

import os
import signal
import time

from autograder.sandbox.forking import fork_each


def _task(item, slot):
    assert slot is None  # no slot pool given
    if item == "killed":
        os.kill(os.getpid(), signal.SIGKILL)
    if item == "raises":
        raise RuntimeError("boom")
    if item == "exits":
        os._exit(3)
    if item == "hangs":
        time.sleep(60)


def test_every_child_ends_with_a_reason():
    outcomes = {}
    started = time.monotonic()
    fork_each(
        _task,
        ["fine", "killed", "raises", "exits", "hangs", "also fine"],
        jobs=2,
        on_done=lambda item, problem: outcomes.__setitem__(item, problem),
        deadline_seconds=2,
    )
    assert time.monotonic() - started < 30
    assert outcomes["fine"] is None and outcomes["also fine"] is None
    assert "SIGKILL" in outcomes["killed"]
    assert "status 1" in outcomes["raises"] and "status 3" in outcomes["exits"]
    assert "longer than 2 s" in outcomes["hangs"]
