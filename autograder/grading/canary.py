"""The canary: before a batch, the reference solutions are graded through the whole pipeline.

The reference must get full marks on every exercise and every notebook
stage. If it does not, some stage is broken on this machine (a sandbox that
cannot import ``coursekit``, a kernel that does not start, a changed
library...) and every student would be graded wrongly: the batch stops
before anything is written, with a message naming the lesson and the stage.

A passing canary is remembered per grader fingerprint
(:mod:`autograder.grading.fingerprint`) in a small cache folder, so it costs one
student's grading once, not once per run.

Examples
--------
>>> ensure_reference_passes(course, GradingOptions(), parts)   # doctest: +SKIP
CanaryResult(cached=True, seconds=0.0, ...)
"""

from __future__ import annotations

import json
import time
from dataclasses import dataclass
from pathlib import Path

from autograder.grading.fingerprint import cache_dir, fingerprint
from autograder.grading.options import GradingOptions
from autograder.grading.results import StudentResult
from autograder.lessons.course import Course
from autograder.sandbox import cleanup
from autograder.sandbox.forking import fork_each


class CanaryFailed(Exception):
    """The reference solutions did not get full marks: grading on this machine cannot be trusted."""


@dataclass
class CanaryResult:
    cached: bool
    seconds: float
    score: float = 0.0
    max_score: float = 0.0


def describe_canary(canary: CanaryResult) -> str:
    """One line for the run's output."""
    if canary.cached:
        return "canary: the reference solutions got full marks with this grader before (cached)"
    return (
        f"canary: the reference solutions got full marks ({canary.score:g}/{canary.max_score:g}) "
        f"in {canary.seconds:.1f} s"
    )


def _marker(parts):
    return cache_dir() / f"canary-{fingerprint(parts)}.json"


def shortfalls(result: StudentResult) -> list[str]:
    """One line per lesson stage where ``result`` is below full marks (empty when it has full marks)."""
    lines = []
    if result.reason:
        lines.append(f"{result.status}: {result.reason}")
    for lesson in result.lessons:
        if lesson.status != "graded":
            lines.append(f"lesson {lesson.number}, reading the notebook: {lesson.reason}")
            continue
        for exercise in lesson.exercises:
            if exercise.points < exercise.max_points:
                failed = next((c for c in exercise.checks if not c.passed), None)
                why = f"{failed.description}: {failed.reason}" if failed else "; ".join(exercise.notes)
                lines.append(
                    f"lesson {lesson.number}, hidden suite, {exercise.name} "
                    f"({exercise.points:g}/{exercise.max_points:g}): {why}"
                )
        run = lesson.run
        if run is not None and run.points < run.max_points:
            lines.append(
                f"lesson {lesson.number}, notebook stage (nbval): " + ("; ".join(run.failures[:2]) or run.status)
            )
    return lines


def _grade_reference(course, options, folder, target, slot=None):
    """Runs in a fork, like a student's grading: grade the reference and write its result to ``target``."""
    from autograder.grading.context import GradingContext
    from autograder.grading.pipeline import grade_student
    from autograder.sandbox import process_tree

    process_tree.become_subreaper()
    try:
        result = grade_student("reference solutions (canary)", folder, GradingContext(course, options), slot=slot)
    finally:
        process_tree.kill_descendants()
    Path(target).write_text(result.to_json(), encoding="utf-8")


def ensure_reference_passes(
    course: Course, options: GradingOptions, parts: dict[str, str], timeout: float = 900
) -> CanaryResult:
    """Grade ``course``'s reference through the full pipeline unless a passing canary is cached; raise
    :class:`CanaryFailed` naming each failing lesson and stage."""
    marker = _marker(parts)
    if marker.exists():
        return CanaryResult(cached=True, seconds=0.0)
    from autograder.lessons.hand_ins import write_reference_submission

    started = time.monotonic()
    with cleanup.private_folder_for("canary") as base:
        folder = write_reference_submission(course, Path(base) / "reference", lessons=options.lessons)
        target = Path(base) / "result.json"
        deaths = []
        fork_each(
            lambda _, slot: _grade_reference(course, options, folder, target, slot),
            [None],
            jobs=1,
            on_done=lambda _, problem: deaths.append(problem),
            deadline_seconds=timeout,
        )
        if deaths[0] or not target.exists():
            raise CanaryFailed(
                f"grading the reference solutions failed: {deaths[0] or 'no result was written'}; "
                "no student was graded (nothing was written or overwritten)"
            )
        result = StudentResult.from_json(target.read_text(encoding="utf-8"))
    problems = shortfalls(result)
    if problems or result.max_score <= 0:
        raise CanaryFailed(
            f"the reference solutions scored {result.score:g}/{result.max_score:g} on this machine, so a "
            "stage of the grader is broken here and no student was graded (nothing was written or "
            "overwritten). Where the reference lost points:\n  " + "\n  ".join(problems or ["no points at all"])
        )
    seconds = time.monotonic() - started
    try:
        marker.parent.mkdir(parents=True, exist_ok=True)
        marker.write_text(
            json.dumps({"parts": parts, "score": result.score, "seconds": round(seconds, 1)}, indent=1),
            encoding="utf-8",
        )
    except OSError:
        pass  # a read-only home: the canary simply runs again next time
    return CanaryResult(cached=False, seconds=seconds, score=result.score, max_score=result.max_score)
