"""Gradescope's ``results.json`` for one student: one test per exercise and one per notebook.

Written by ``grade --out DIR`` to ``DIR/results/<student>.json`` and, in the
Gradescope container, by :mod:`autograder.integrations.gradescope` to
``/autograder/results/results.json``. Each test carries the failed checks with
their reasons and hints; ``visibility`` is ``after_due_date`` by default, so
hidden-test details appear only once the due date has passed, while the
top-level ``output`` (always visible) says which notebooks were read.

Examples
--------
>>> data = results_json(student_result)                        # doctest: +SKIP
>>> data["score"], [test["name"] for test in data["tests"]][:1]  # doctest: +SKIP
(12.0, ['Lesson 01 · rot2d'])
"""

from __future__ import annotations

from autograder.grading.results import StudentResult
from autograder.sandbox.launcher import LIMITS_ONLY_WARNING

DEFAULT_VISIBILITY = "after_due_date"


def _check_output(check):
    mark = "✓" if check.passed else "✗"
    line = f"{mark} {check.description}"
    if not check.passed and check.reason:
        line += f": {check.reason}"
    if not check.passed and check.hint:
        line += f"\n    hint: {check.hint}"
    return line


def results_json(result: StudentResult, visibility: str = DEFAULT_VISIBILITY, seconds: float | None = None) -> dict:
    """Gradescope's results for one :class:`~autograder.grading.results.StudentResult` (a dict)."""
    tests = []
    for lesson in result.lessons:
        for exercise in lesson.exercises:
            lines = [f"{exercise.name}: {exercise.points:g} of {exercise.max_points:g} points"]
            if lesson.status == "missing":
                lines.append(lesson.reason)  # one line, not one per hidden check
            else:
                lines += exercise.notes
                lines += [_check_output(c) for c in exercise.checks]
            tests.append(
                {
                    "name": f"Lesson {lesson.number} · {exercise.name}",
                    "score": exercise.points,
                    "max_score": exercise.max_points,
                    "status": "passed" if exercise.points >= exercise.max_points else "failed",
                    "output": "\n".join(lines),
                    "visibility": visibility,
                }
            )
        if lesson.run is not None:
            run = lesson.run
            tests.append(
                {
                    "name": f"Lesson {lesson.number} · notebook runs top to bottom",
                    "score": run.points,
                    "max_score": run.max_points,
                    "status": "passed" if run.points >= run.max_points else "failed",
                    "output": "\n".join([f"nbval: {run.status}"] + run.failures),
                    "visibility": visibility,
                }
            )
    read = [lesson for lesson in result.lessons if lesson.status == "graded"]
    summary = [
        f"Graded {len(read)} of {len(result.lessons)} notebook(s). "
        "Details of each check appear here after the due date."
    ]
    for lesson in result.lessons:
        if lesson.status != "graded":
            summary.append(f"Lesson {lesson.number}: {lesson.reason}")
        if lesson.late_penalty:
            summary.append(
                f"Lesson {lesson.number} late: {lesson.late_note} ({lesson.raw_points:g} → {lesson.points:g} points)"
            )
    if result.raw_score != result.score:
        summary.append(
            f"Score {result.score:g} of {result.max_score:g} after late penalties ({result.raw_score:g} before)."
        )
    if result.reason:
        summary.append(result.reason)
    if result.isolation == "limits":
        summary.append(LIMITS_ONLY_WARNING)
    data = {
        "score": result.score,
        "output": "\n".join(summary),
        "visibility": "visible",
        "stdout_visibility": "hidden",
        "tests": tests,
    }
    if seconds is not None:
        data["execution_time"] = round(seconds, 1)
    return data


def failure_json(message: str) -> dict:
    """What Gradescope shows when grading itself failed: a message, no score claimed."""
    return {
        "score": 0.0,
        "visibility": "visible",
        "stdout_visibility": "hidden",
        "tests": [],
        "output": "The autograder could not grade this submission: "
        + message
        + "\nThe score of 0 is not a grade: your submission was received and is kept; "
        "ask your instructor to re-run the autograder.",
    }
