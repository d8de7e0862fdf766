"""Run each task in its own fork of this (pre-warmed) process, a few at a time.

Unlike ``multiprocessing.Pool``, a child that dies — killed by a signal, out of
memory, past its deadline — never leaves the parent waiting: the parent
learns how it ended and moves on. Tasks report their results through files
(the child saves its student's result atomically), so the only thing that
crosses back is the exit status.

Examples
--------
>>> outcomes = []
>>> fork_each(lambda item, slot: print(item), ["a", "b"], jobs=2,
...           on_done=lambda item, how: outcomes.append((item, how)))  # doctest: +SKIP
"""

from __future__ import annotations

import os
import signal
import time
import traceback
from typing import Callable, TypeVar

from autograder.sandbox import cpus
from autograder.sandbox.warm import SlotPool, WarmSlot

T = TypeVar("T")  # one task: what fork_each hands to ``function`` and to ``on_done``


def describe_exit(status: int) -> str | None:
    """A sentence for how a child ended, or ``None`` when it exited normally (status 0)."""
    if os.WIFEXITED(status):
        code = os.WEXITSTATUS(status)
        return None if code == 0 else f"the grading process exited with status {code}"
    if os.WIFSIGNALED(status):
        number = os.WTERMSIG(status)
        try:
            name = signal.Signals(number).name
        except ValueError:
            name = f"signal {number}"
        return f"the grading process was killed by {name}"
    return "the grading process ended abnormally"


def _run_child(function, item, slots, slot, jobs):
    code = 0
    try:
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        cpus.pin(cpus.cpu_of_slot(slot, jobs, batch=os.getppid()))  # with its slot's zygote: one CPU per grader
        function(item, slots.enter(slot) if slots is not None else None)
    except BaseException:  # report on stderr, end with a non-zero status
        traceback.print_exc()
        code = 1
    finally:
        os._exit(code)


def _release(slots, slot, free):
    if slots is not None:
        slots.repair(slot)
    free.append(slot)


def fork_each(
    function: Callable[[T, WarmSlot | None], None],
    items: list[T],
    jobs: int,
    on_done: Callable[[T, str | None], None],
    deadline_seconds: float | None = None,
    poll: float = 0.05,
    slots: SlotPool | None = None,
) -> None:
    """Call ``function(item, slot)`` in a new fork per item, at most ``jobs`` at a time.

    ``on_done(item, problem)`` runs in the parent as each child ends:
    ``problem`` is ``None`` for a normal exit, else a sentence (killed by a
    signal, non-zero status, or past ``deadline_seconds`` and killed).
    ``slots`` (a :class:`~autograder.sandbox.warm.SlotPool` of ``jobs``
    slots, or None): each child gets a slot no running child has
    (``slots.enter(index)``, passed to ``function`` as ``slot``; None without
    slots); the parent calls ``slots.repair(index)`` after the child ends.
    """
    pending = list(items)
    running = {}  # pid -> (item, started, slot)
    free = list(range(jobs))
    try:
        while pending or running:
            while pending and len(running) < jobs:
                item, slot = pending.pop(0), free.pop(0)
                pid = os.fork()
                if pid == 0:
                    _run_child(function, item, slots, slot, jobs)
                running[pid] = (item, time.monotonic(), slot)
            pid, status = os.waitpid(-1, os.WNOHANG)
            if pid == 0:
                if deadline_seconds is not None:
                    now = time.monotonic()
                    for child, (item, started, slot) in list(running.items()):
                        if now - started > deadline_seconds:
                            os.kill(child, signal.SIGKILL)
                            os.waitpid(child, 0)
                            del running[child]
                            _release(slots, slot, free)
                            on_done(item, f"grading took longer than {deadline_seconds:g} s and was stopped")
                time.sleep(poll)
                continue
            if pid in running:
                item, _, slot = running.pop(pid)
                _release(slots, slot, free)
                on_done(item, describe_exit(status))
    except BaseException:
        for child in running:
            try:
                os.kill(child, signal.SIGKILL)
            except ProcessLookupError:
                pass
        for child in running:
            try:
                os.waitpid(child, 0)
            except ChildProcessError:
                pass
        raise
