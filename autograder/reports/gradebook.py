"""The gradebook: one CSV row per student, safe to open in a spreadsheet.

Columns: ``student_id, score, max_score, status``; one total per lesson
(``lesson_01``…: its exercises and notebook point, after any late penalty;
each lesson is often its own assignment); one column per exercise (points
earned); one per lesson for the notebook stage (``notebook_01``…, when it
ran); ``late`` (which lessons were late and by how much); then nbgrader's
export columns that apply: ``raw_score`` (before late penalties) and
``timestamp`` (when the newest notebook was handed in); ``graded_at`` and
``problems``.

Every text cell is one line, bounded, with control characters escaped, and a
cell that a spreadsheet could read as a formula (starting with ``=``, ``+``,
``-``, ``@``) is prefixed with an apostrophe, so a student named
``=HYPERLINK(...)`` stays a name (:func:`~autograder.lessons.untrusted_text.csv_cell`).
"""

from __future__ import annotations

import csv
import io

from autograder.grading.results import StudentResult
from autograder.lessons.catalog import Catalog
from autograder.lessons.untrusted_text import csv_cell, spreadsheet_safe  # noqa: F401 (spreadsheet_safe: API)

MAX_ID_CHARACTERS = 1100  # an id from a folder name (255 bytes) with every byte escaped fits


def _number(value):
    return f"{value:g}"


def columns(catalog: Catalog, with_notebooks: bool) -> list[str]:
    names = ["student_id", "score", "max_score", "status"]
    names += [f"lesson_{lesson.number}" for lesson in catalog.graded_lessons]
    names += [exercise.name for exercise in catalog.exercises]
    if with_notebooks:
        names += [f"notebook_{lesson.number}" for lesson in catalog.graded_lessons]
    return names + ["late", "raw_score", "timestamp", "graded_at", "problems"]


def row(result: StudentResult, catalog: Catalog, with_notebooks: bool, graded_at: str = "") -> list[str]:
    earned = {e.name: e.points for e in result.exercises}
    lessons = {lesson.number: lesson for lesson in result.lessons}
    values = [
        csv_cell(result.student_id, MAX_ID_CHARACTERS),
        _number(result.score),
        _number(result.max_score),
        csv_cell(result.status),
    ]
    values += [
        _number(lessons[lesson.number].points) if lesson.number in lessons else "" for lesson in catalog.graded_lessons
    ]
    values += [_number(earned[e.name]) if e.name in earned else "" for e in catalog.exercises]
    if with_notebooks:
        values += [
            _number(lessons[lesson.number].run.points)
            if lesson.number in lessons and lessons[lesson.number].run
            else ""
            for lesson in catalog.graded_lessons
        ]
    late = "; ".join(
        f"{lesson.number}: −{100 * lesson.late_penalty:g}%" for lesson in result.lessons if lesson.late_penalty
    )
    problems = "; ".join(([result.reason] if result.reason else []) + list(result.problems))
    values += [
        late,
        _number(result.raw_score),
        csv_cell(result.submitted_at),
        csv_cell(graded_at),
        csv_cell(problems, 2000),
    ]
    return values


def gradebook_csv(results: list[StudentResult], catalog: Catalog, graded_at: dict[str, str] | None = None) -> str:
    """The gradebook text for a list of :class:`~autograder.grading.results.StudentResult`.

    ``graded_at``: ``{student_id: when the result was computed}``.
    """
    graded_at = graded_at or {}
    with_notebooks = any(lesson.run is not None for r in results for lesson in r.lessons)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(columns(catalog, with_notebooks))
    for result in sorted(results, key=lambda r: r.student_id):
        writer.writerow(row(result, catalog, with_notebooks, graded_at.get(result.student_id, "")))
    return buffer.getvalue()
