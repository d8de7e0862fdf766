"""What an instructor should look at after a run: stages that failed for most of the class, and
students worth a look (attempted tampering, timeouts, crashes).

Both read only the saved :class:`~autograder.grading.results.StudentResult` objects, by the sentences
the sandbox and the stages write (see :mod:`autograder.sandbox.session`):

- *tampering*: a reply that did not match its request (forged output), a value that is not plain
  data (an object that lies about equality), a locked check cell edited or removed;
- *timeout*: a function or cell that did not return in time, a used-up time budget;
- *crash*: a process killed by a signal or a limit, ``sys.exit``/``os._exit``, a grader that could
  not grade the student.

Examples
--------
>>> [w.text for w in stage_warnings(results)]                         # doctest: +SKIP
['the notebook stage failed for 9 of 10 students who had full hidden marks on lesson 03 ...']
>>> worth_a_look(results)[0]                                          # doctest: +SKIP
Concern(student_id='ivy', kind='timeout', count=1, example='rot_z did not return within 5 s ...')
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from autograder.grading.results import COULD_NOT_GRADE, MISSING, StudentResult

KINDS = {
    "tampering": (
        "does not match the request",
        "forged",
        "return numbers, numpy arrays",
        "the check cell was edited",
        "the check cell was removed",
    ),
    "timeout": (
        "did not return within",
        "did not finish within",
        "time budget",
        "took longer than",
        "did not finish in time",
    ),
    "crash": (
        "crashed",
        "was killed",
        "exited with status",
        "segmentation fault",
        "used up its CPU time",
        "kernel had stopped",
        "killed by",
        "ended without a result",
    ),
}
MOST = 0.5  # a stage that failed for more than this share of the students who reached it


@dataclass(frozen=True)
class Concern:
    student_id: str
    kind: str
    count: int
    example: str


@dataclass(frozen=True)
class StageWarning:
    text: str


def _messages(result):
    if result.status == COULD_NOT_GRADE and result.reason:
        yield "crash", f"could not grade: {result.reason}"
    for lesson in result.lessons:
        for exercise in lesson.exercises:
            yield from ((None, f"{exercise.name}: {c.reason}") for c in exercise.checks if not c.passed)
            yield from ((None, f"{exercise.name}: {note}") for note in exercise.notes)
        if lesson.run is not None:
            yield from ((None, f"lesson {lesson.number} notebook: {f}") for f in lesson.run.failures)
    yield from ((None, problem) for problem in result.problems)


def _kind(message):
    lowered = message.lower()
    for kind, needles in KINDS.items():
        if any(needle in lowered for needle in needles):
            return kind
    return None


def worth_a_look(results: list[StudentResult]) -> list[Concern]:
    """Students whose results show tampering, timeouts or crashes: one :class:`Concern` per kind."""
    concerns = []
    for result in sorted(results, key=lambda r: r.student_id):
        if result.status == MISSING:
            continue
        found = {}
        for kind, message in _messages(result):
            kind = kind or _kind(message)
            if kind:
                count, example = found.get(kind, (0, message))
                found[kind] = (count + 1, example)
        for kind in KINDS:
            if kind in found:
                concerns.append(Concern(result.student_id, kind, found[kind][0], found[kind][1][:240]))
    return concerns


def stage_warnings(results: list[StudentResult]) -> list[StageWarning]:
    """Stages that failed for most of the students who reached them: likely the grader, not the class."""
    graded = [r for r in results if r.status != MISSING]
    warnings = []
    failed = [r for r in graded if r.status == COULD_NOT_GRADE]
    if len(graded) >= 2 and len(failed) > MOST * len(graded):
        reasons = Counter(r.reason for r in failed).most_common(1)[0][0]
        warnings.append(
            StageWarning(
                f"{len(failed)} of {len(graded)} students could not be graded at all "
                f"(most often: {reasons}): check the grading machine before trusting this run."
            )
        )
    reached, setup_failed, notebook_failed = Counter(), Counter(), Counter()
    eligible = Counter()
    for result in graded:
        for lesson in result.lessons:
            if lesson.status != "graded":
                continue
            reached[lesson.number] += 1
            if any("setup cell failed" in note for e in lesson.exercises for note in e.notes):
                setup_failed[lesson.number] += 1
            full = all(e.points >= e.max_points for e in lesson.exercises)
            if lesson.run is not None and full:
                eligible[lesson.number] += 1
                if lesson.run.status == "failed":
                    notebook_failed[lesson.number] += 1
    for number in sorted(reached):
        if reached[number] >= 2 and setup_failed[number] > MOST * reached[number]:
            warnings.append(
                StageWarning(
                    f"lesson {number}: the lesson's setup cell failed in the sandbox for {setup_failed[number]} of "
                    f"{reached[number]} students: a grader or environment problem, not the students'."
                )
            )
        if eligible[number] >= 2 and notebook_failed[number] > MOST * eligible[number]:
            warnings.append(
                StageWarning(
                    f"lesson {number}: the notebook stage failed for {notebook_failed[number]} of {eligible[number]} "
                    "students who had full hidden marks: look at their feedback pages before trusting these points."
                )
            )
    return warnings
