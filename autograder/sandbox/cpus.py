"""One CPU per grading slot: a grader, its sandboxes and its notebook kernels stay on the slot's CPU.

A grader and its sandbox take turns (the grader waits while the student's code
runs, the feeder while the runner does), and the notebook stage's kernel and
the student's runner hand over once per call, thousands of times a lesson. A
round trip through a pipe between two processes on one CPU took 6 µs on a
2-core machine, across the two CPUs 47 µs; a call into a sandbox, 192 µs kept
on one CPU against 295 µs left to the scheduler (2026-11-28,
``benchmarks/sandbox_round_trip.py`` prints both). So when a batch grades
with several slots at once, slot ``k``'s whole process tree (its zygote, its
graders and whatever they start) is kept on the ``k``-th CPU this process may
use. One grader alone is never pinned: two separate runs on one machine would
then share one CPU.

Examples
--------
>>> cpu_of_slot(1, jobs=2)                        # doctest: +SKIP
1
>>> with pinned(cpu_of_slot(0, jobs=2)):          # doctest: +SKIP
...     spawn_something()                         # its processes stay on CPU 0
"""

from __future__ import annotations

import os
from contextlib import contextmanager
from typing import Iterator


def cpu_of_slot(slot: int, jobs: int, batch: int | None = None) -> int | None:
    """The CPU slot ``slot`` of ``jobs`` concurrent graders keeps to, or None (one grader, or one CPU).

    ``batch``: the process id of the batch that owns the slots (default: this process). The slots of one batch
    get distinct CPUs, counted from one that the batch's id picks, so that two batches running at once on one
    machine do not both put their first slot on the first CPU.
    """
    try:
        allowed = sorted(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return None
    if jobs < 2 or len(allowed) < 2:
        return None
    return allowed[(slot + (os.getpid() if batch is None else batch)) % len(allowed)]


def pin(cpu: int | None) -> None:
    """Keep this process (and what it starts from now on) on ``cpu``; None or a refusal changes nothing."""
    if cpu is None:
        return
    try:
        os.sched_setaffinity(0, {cpu})
    except (AttributeError, OSError):
        pass


@contextmanager
def pinned(cpu: int | None) -> Iterator[None]:
    """Within the block, this process (and what it starts there) keeps to ``cpu``; afterwards, as before."""
    if cpu is None:
        yield
        return
    try:
        before = os.sched_getaffinity(0)
    except (AttributeError, OSError):
        yield
        return
    pin(cpu)
    try:
        yield
    finally:
        try:
            os.sched_setaffinity(0, before)
        except OSError:
            pass
