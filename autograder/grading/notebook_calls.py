"""The notebook stage's transcripts: a lesson's kernel run skipped when the student's calls return the reference's.

The notebook stage (:mod:`autograder.grading.nbval_stage`) runs each lesson's
master in a kernel that holds no student code; every call the master makes to
an exercise function goes to the student's sandbox and only its value comes
back. The kernel is therefore a deterministic function of the values those
calls return, provided the master itself is deterministic. So, once per
lesson and grader version:

1. **Record.** The masters run as the notebook stage runs them, with the
   *reference's* functions in the student's place, twice; each call the kernel
   makes (lesson, function, arguments, time limit, as wire text) is noted with
   the wire text of the value it got back (``child/student_client.py`` when
   ``AUTOGRADER_RECORD_CALLS`` is set). A lesson gets a transcript only when
   its notebook passed both times and both runs made the same calls and got
   the same values: a master that reads randomness, the clock or anything
   else that changes between runs, and feeds it to a call, records two
   different lists and is never skipped. When the master passes one of its
   own functions to a student function (a callback: a demonstration's map for
   ``numerical_jacobian``), each time the student's code called it is noted
   too, with its arguments, the calls that function made to the student's
   functions in turn (``boxplus_right``) and their values, and the answer the
   kernel gave. A lesson whose master gets an exception back is not skipped.
2. **Replay.** For a student, the lesson's calls go, in order, in one batch, to
   a fresh sandbox of the student's functions for that lesson, as the kernel's
   would (the same program, limits and walls as the hidden suite's calls;
   the feeder hands the student's process one call at a time). The batch stops
   at the first call whose value is not the reference's, bit for bit, so no
   call is made with an input computed from a value the student's own
   function did not return. A callback is answered by the feeder from the
   notes, and only when the student's code calls it exactly as the
   reference's did (the same callable, the same arguments, bit for bit, in
   the same order, as often): any other use fails the call, and the kernel
   runs, since only the kernel can compute what the notes do not hold. The
   calls the callable made to the student's functions are made again, at
   that very moment, in the student's process, as the kernel's would be, and
   must return the noted values.
3. **Same values, same notebook.** When every call returned the reference's
   value, the kernel run would have made exactly these calls (by induction:
   each call's inputs come from the master and the values before it, all the
   reference's, and so does every callback's answer) and got exactly these values, so every cell's output is the
   reference run's, which passed: the lesson's run is ``passed`` without a
   kernel. Any other outcome (a different value, an error, a timeout, a batch
   over :data:`REPLAY_BUDGET` seconds, which could have been a cell over its
   time limit) runs the kernel as before. What the student's functions print
   is not compared by the notebook stage, and in-place changes to arguments
   never reach the kernel (values cross as data), so neither can differ.

The transcripts are kept on the reference's memo (``ReferenceSolutions.memo``,
recorded once by the batch before its graders fork) and on disk beside the
hidden suite's (:mod:`autograder.grading.transcript_cache`'s key: the grader,
the masters, coursekit, the hidden suite, the libraries, the BLAS kernel).
``run_notebooks(..., replay=False)`` runs every kernel, as before;
``tests/test_notebook_replay.py`` holds both paths to the same verdicts.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from autograder.grading import transcript_cache
from autograder.grading.fingerprint import cache_dir, write_private
from autograder.lessons.course import Course
from autograder.sandbox.session import StudentSandbox

FORMAT = 2  # 2: the callbacks of each call are noted (``exchanges``)
REPLAY_BUDGET = 20.0  # seconds of student calls in a replay; a nbval cell may take 60 (nbval_runner.py)
CHUNK_CALLS = 4000  # calls per batch (a batch's replies stop at 8 MiB in the feeder)
CHUNK_BYTES = 2 * 1024**2  # of call text per batch
MAX_CALLS = 50_000  # a lesson recording more calls than this is not replayed (a batch this large is not worth it)
LESSON_RECORD_BYTES = 24 * 1024**2  # of calls noted per lesson; a lesson noting more is not replayed
# (each lesson has a file of its own, below the sandbox's 32 MiB limit on a file's size)


@dataclass
class NotebookTranscript:
    """The calls a lesson's master made to the reference's functions, in order, and the values it got."""

    calls: list  # wire text of {"lesson", "name", "args", "kwargs", "timeout"} per call
    results: list  # wire text of the value the reference returned, per call
    timeouts: list  # each call's time limit
    exchanges: list  # per call, the callbacks it made: [handle, args text, kwargs text, answer] each


MEMO_KEY = "notebook calls"


def memo(course: Course) -> dict:
    """``{lesson: NotebookTranscript or None}`` learned so far for ``course`` (on its reference's memo)."""
    holder = getattr(course.reference, "memo", None)
    if not isinstance(holder, dict):
        return {}
    return holder.setdefault(MEMO_KEY, {})


def read_records(scratch_dir: Path) -> list[dict] | None:
    """The calls noted in ``scratch_dir`` by ``student_client`` (reference code only), lesson by lesson.

    A lesson whose file cannot be read or went over :data:`LESSON_RECORD_BYTES` gets one entry without
    ``ok``, so that lesson alone is not replayed. None only when the folder cannot be listed.
    """
    try:
        paths = sorted(Path(scratch_dir).glob(RECORD_PREFIX + "-*.jsonl"))
    except OSError:
        return None
    entries = []
    for path in paths:
        lesson = path.name[len(RECORD_PREFIX) + 1 : -len(".jsonl")]
        try:
            if path.stat().st_size > LESSON_RECORD_BYTES + 64 * 1024:
                raise ValueError("over the budget")
            entries.extend(json.loads(line) for line in path.read_text(encoding="utf-8").splitlines())
        except (OSError, ValueError):
            entries.append({"lesson": lesson, "overflow": True})
    return entries


def transcript_from(runs: list[list[dict] | None]) -> NotebookTranscript | None:
    """The lesson's transcript from its recorded runs, or None when it must not be replayed: a run
    unreadable, runs that differ, a callback that could not be noted, a call that raised, or too many calls."""
    if not runs or any(run is None for run in runs):
        return None
    first = runs[0]
    if any(run != first for run in runs[1:]) or len(first) > MAX_CALLS:
        return None
    calls, results, timeouts, exchanges = [], [], [], []
    for entry in first:
        if not isinstance(entry, dict) or not entry.get("ok"):
            return None
        if not isinstance(entry.get("call"), str) or not isinstance(entry.get("text"), str):
            return None
        noted = entry.get("exchanges", [] if not entry.get("callbacks") else None)
        if not isinstance(noted, list) or not all(_is_exchange(item) for item in noted):
            return None
        try:
            timeout = json.loads(entry["call"])["__dict__"]
            timeout = float(dict(timeout)["timeout"])
        except (ValueError, KeyError, TypeError):
            return None
        calls.append(entry["call"])
        results.append(entry["text"])
        timeouts.append(timeout)
        exchanges.append(noted)
    return NotebookTranscript(calls=calls, results=results, timeouts=timeouts, exchanges=exchanges)


def _is_exchange(item) -> bool:
    """``[handle, args text, kwargs text, {"ok": bool, "text" or "error": str}, [[call text, value text], ...]]``,
    as ``student_client`` notes a callback (the last: the calls to student functions the callable made)."""
    return (
        isinstance(item, list)
        and len(item) == 5
        and type(item[0]) is int
        and isinstance(item[1], str)
        and isinstance(item[2], str)
        and isinstance(item[3], dict)
        and isinstance(item[3].get("ok"), bool)
        and isinstance(item[3].get("text" if item[3]["ok"] else "error"), str)
        and isinstance(item[4], list)
        and all(
            isinstance(pair, list) and len(pair) == 2 and all(isinstance(text, str) for text in pair)
            for pair in item[4]
        )
    )


def replays_as_recorded(box: StudentSandbox, transcript: NotebookTranscript) -> bool:
    """Make the lesson's recorded calls in ``box`` (a fresh sandbox of the student's functions), in order, in
    batches of at most :data:`CHUNK_CALLS` calls or :data:`CHUNK_BYTES` of call text, their callbacks answered from
    the notes; True when every one returned the reference's value, bit for bit, and called back exactly as the
    reference's did (the kernel run can then be skipped)."""
    spent, start = 0.0, 0
    total = len(transcript.calls)
    while start < total:
        end, size = start, 0
        while end < total and end - start < CHUNK_CALLS and (size < CHUNK_BYTES or end == start):
            size += len(transcript.calls[end]) + sum(
                len(args) + len(kwargs) + len(answer.get("text") or "") + sum(map(len, sum(inner, [])))
                for _, args, kwargs, answer, inner in transcript.exchanges[end]
            )
            end += 1
        before = box.time_used
        expected = transcript.results[start:end]
        replies = box.call_batch(
            transcript.calls[start:end],
            transcript.timeouts[start:end],
            budget=REPLAY_BUDGET - spent,
            expect=expected,
            callbacks=transcript.exchanges[start:end],
        )
        spent += box.time_used - before
        if (
            replies is None
            or len(replies) != end - start
            or not all(r.get("ok") and r.get("text") == e for r, e in zip(replies, expected))
            or spent > REPLAY_BUDGET
        ):
            return False
        start = end
    return True


def path(course: Course) -> Path:
    """This machine's, this grader's and this course's file of notebook transcripts."""
    return cache_dir() / f"notebook-calls-{transcript_cache.key(course)}.json"


def save(course: Course, learned: dict) -> None:
    """Write ``{lesson: NotebookTranscript or None}``; never raises (recording again is always safe)."""
    document = {
        "format": FORMAT,
        "lessons": {lesson: (vars(t) if t is not None else None) for lesson, t in learned.items()},
    }
    try:
        write_private(path(course), json.dumps(document))
    except OSError:
        pass


def load(course: Course) -> dict | None:
    """``{lesson: NotebookTranscript or None}`` from this machine's file, or None."""
    try:
        document = json.loads(path(course).read_text(encoding="utf-8"))
        if document.get("format") != FORMAT:
            return None
        return {
            lesson: (NotebookTranscript(**fields) if fields is not None else None)
            for lesson, fields in document["lessons"].items()
        }
    except (OSError, ValueError, KeyError, TypeError):
        return None


RECORD_PREFIX = "notebook-calls"


def environment_flag() -> dict[str, str]:
    """The kernel's environment entries that make ``student_client`` note its calls (recording runs only):
    one file per lesson, ``/tmp/notebook-calls-<lesson>.jsonl``, of at most :data:`LESSON_RECORD_BYTES`."""
    return {
        "AUTOGRADER_RECORD_CALLS": f"/tmp/{RECORD_PREFIX}",
        "AUTOGRADER_RECORD_BYTES": str(LESSON_RECORD_BYTES),
    }
