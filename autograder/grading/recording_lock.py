"""One grader at a time records a course's reference on this machine; the others wait and start warm.

A cold start (no passing canary for this grader version yet) records the
reference's transcripts, hidden and notebook (:mod:`~autograder.grading.transcript_cache`,
:mod:`~autograder.grading.notebook_calls`), then grades the reference as the canary:
about a minute of both CPUs. Two ``grade`` commands started together on a fresh
machine (two sections of one course, a limits-mode run beside the default one,
a test suite's workers) used to do that work twice, each at half speed. Now the
first takes a lock file in the cache folder, named by the transcripts' key, and the
others wait for it, say so, and then read what it saved.

The lock is ``flock(2)`` on a file: the kernel drops it when its holder ends, however
it ends, so a killed grader never leaves the others waiting. Speed only, like the
caches it guards: when the folder cannot hold a lock file, or the wait passes
``timeout`` seconds, the run goes on and records for itself (as it does with
``AUTOGRADER_RECORDING_LOCK=0``, the benchmarks' way to compare).

Examples
--------
>>> with recording_turn(course, announce=print):              # doctest: +SKIP
...     ensure_reference_passes(course, options, parts)
waiting for another grader on this machine (pid 4242) that is recording this course's reference...
"""

from __future__ import annotations

import errno
import fcntl
import os
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

from autograder.grading import transcript_cache
from autograder.grading.fingerprint import private_cache_dir
from autograder.lessons.course import Course

POLL_SECONDS = 0.25
WAIT_AT_MOST = 1800.0  # seconds: a canary's own limit is 900 s, after the recordings' side-by-side runs


def lock_path(course: Course) -> Path:
    """The lock file of ``course``'s reference recordings on this machine (in the private cache folder)."""
    return private_cache_dir() / f"recording-{transcript_cache.key(course)}.lock"


def _holder(handle) -> str:
    try:
        handle.seek(0)
        pid = handle.read(20).strip()
    except (OSError, ValueError):  # unreadable, or not ASCII: the message goes without the pid
        return ""
    return f" (pid {pid})" if pid.isdigit() else ""


@contextmanager
def recording_turn(
    course: Course,
    announce: Callable[[str], None] | None = None,
    timeout: float = WAIT_AT_MOST,
) -> Iterator[bool]:
    """Hold this machine's lock on recording ``course``'s reference for the ``with`` block.

    Yields ``True`` when the lock is held, ``False`` when the run goes on without it (no lock file could be
    made, or another holder kept it past ``timeout`` seconds; ``announce`` is told). Waiting is announced once.
    """
    if os.environ.get("AUTOGRADER_RECORDING_LOCK") == "0":
        yield False
        return
    try:
        path = lock_path(course)
        fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC, 0o600)
    except OSError:
        yield False
        return
    with os.fdopen(fd, "r+", encoding="ascii") as handle:
        held, waited_since = False, None
        deadline = time.monotonic() + timeout
        while True:
            try:
                fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
                held = True
                break
            except OSError as error:
                if error.errno not in (errno.EAGAIN, errno.EACCES, errno.EWOULDBLOCK):
                    break  # a file system without locks: go on without one
            if waited_since is None:
                waited_since = time.monotonic()
                if announce:
                    announce(
                        f"waiting for another grader on this machine{_holder(handle)} that is recording this "
                        "course's reference (it is saved for every run here, so this one then starts warm)..."
                    )
            if time.monotonic() > deadline:
                if announce:
                    announce(f"still locked after {timeout:g} s: recording the reference in this run too")
                break
            time.sleep(POLL_SECONDS)
        if held:
            try:
                handle.seek(0)
                handle.truncate()
                handle.write(f"{os.getpid()}\n")
                handle.flush()
            except OSError:
                pass  # the pid is only for the message of a run that waits
            if waited_since is not None and announce:
                announce(f"waited {time.monotonic() - waited_since:.1f} s for the other grader's recordings")
        try:
            yield held
        finally:
            if held:
                # an explicit unlock: forks of this process (sandboxes, kernels) share the open file, and closing
                # our descriptor alone would leave the lock held until the last of them ends
                fcntl.flock(handle, fcntl.LOCK_UN)
