"""The reference's transcripts, kept on disk so that each grader process records them only once per machine.

Recording (:func:`~autograder.grading.suite.transcripts_for`) runs every hidden
test twice on the reference, and learning
(:func:`~autograder.grading.suite.learn_reference_in_sandbox`) runs them again
in a sandbox: about 25 CPU seconds that every ``grade`` command paid again,
although nothing they depend on had changed. They are saved here as JSON, in
:func:`~autograder.grading.fingerprint.cache_dir` beside the canary's markers, and
loaded by the next process.

The file's name is a digest of everything a transcript depends on: the grader's
code, the reference solutions, coursekit, the hidden suite and the library
versions (:func:`~autograder.grading.fingerprint.content_parts`), the format,
and the machine and BLAS kernel (the reference's values and the tests' own
oracles can differ in the last bits between OpenBLAS kernels). A change to any
of them names another file, so a stale transcript is never read. It is speed
only: a missing or unreadable file means recording again, and a transcript
never decides a verdict by itself (a test passes unrun only on values with which
it ran and passed, see :mod:`autograder.grading.transcripts`). The folder is
trusted as the canary's markers are: it belongs to the instructor, and student
code never runs with write access to it (see SECURITY.md).

Examples
--------
>>> saved = load(course)                           # doctest: +SKIP
>>> save(course, transcripts, learned={"01"})      # doctest: +SKIP
"""

from __future__ import annotations

import hashlib
import json
import os
import platform
from pathlib import Path

from autograder.grading.fingerprint import cache_dir, content_parts, write_private
from autograder.grading.transcripts import Transcript
from autograder.lessons.course import Course

FORMAT = 1  # bump when Transcript's fields or their meaning change


def _cpu_model():
    try:
        for line in Path("/proc/cpuinfo").read_text(encoding="utf-8", errors="replace").splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


def key(course: Course) -> str:
    """A digest of everything the reference's transcripts depend on (see the module's docstring)."""
    parts = dict(
        content_parts(course),
        format=FORMAT,
        machine=platform.machine(),
        cpu=_cpu_model(),
        kernel=os.environ.get("OPENBLAS_CORETYPE", ""),
        l2=os.environ.get("OPENBLAS_L2_SIZE", ""),
    )
    return hashlib.sha256(json.dumps(parts, sort_keys=True).encode()).hexdigest()[:20]


def path(course: Course) -> Path:
    """This machine's, this grader's and this course's transcript file."""
    return cache_dir() / f"transcripts-{key(course)}.json"


def save(course: Course, transcripts: dict[str, Transcript], learned: set[str] | tuple = ()) -> None:
    """Write ``{nodeid: Transcript}`` and the lessons already learned in a sandbox, atomically; never raises."""
    target = path(course)
    document = {
        "format": FORMAT,
        "learned": sorted(learned),
        "transcripts": {nodeid: vars(t) for nodeid, t in transcripts.items()},
    }
    tmp = target.with_name(f".{target.name}.{os.getpid()}.tmp")
    try:
        write_private(target, json.dumps(document))  # 0600 in a 0700 folder: what grades rely on is this user's
    except OSError:
        tmp.unlink(missing_ok=True)


def load(course: Course) -> tuple[dict[str, Transcript], set[str]] | None:
    """``({nodeid: Transcript}, learned lessons)`` from this machine's file, or ``None`` if there is none
    (or it cannot be read: recording again is always safe)."""
    try:
        document = json.loads(path(course).read_text(encoding="utf-8"))
        if document.get("format") != FORMAT:
            return None
        transcripts = {}
        for nodeid, fields in document["transcripts"].items():
            fields["keys"] = [tuple(k) for k in fields["keys"]]
            transcripts[nodeid] = Transcript(**fields)
        return transcripts, set(document["learned"])
    except (OSError, ValueError, KeyError, TypeError):
        return None
