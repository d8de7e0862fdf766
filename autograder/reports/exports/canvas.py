"""Canvas (exporter ``"canvas"``, ``export --to canvas``): the CSV that Canvas's Gradebook → Import accepts.

Columns ``Student, ID, SIS User ID, SIS Login ID, Section``, then one column
per lesson (each lesson is its own Canvas assignment, named
``Lesson 01: Frames and rotations``; Canvas offers to create assignments it
does not know). The second row, ``Points Possible``, gives each lesson's
maximum. Scores are the lesson totals after late penalties, as in
``grades.csv``. A lesson not handed in is 0 (``missing="blank"`` leaves
its cell empty instead); a student who could not be graded keeps empty cells
(their grade is unknown). Students are matched in Canvas by ``SIS User ID``: the
roster's ``sis_id`` when given, else the grader's student id; ``ID`` is the
roster's ``canvas_id`` (Canvas's own number) when known.

Examples
--------
>>> text = write(results, course.catalog, read_roster("roster.csv"))     # doctest: +SKIP
>>> text.splitlines()[0]                                                   # doctest: +SKIP
'Student,ID,SIS User ID,SIS Login ID,Section,Lesson 01: Frames and rotations,...'
"""

from __future__ import annotations

import csv
import io

from autograder.grading.results import StudentResult
from autograder.lessons.catalog import Catalog, Lesson
from autograder.lessons.untrusted_text import csv_cell
from autograder.reports.exports.missing import MISSING_CHOICES, not_handed_in
from autograder.reports.plugins import register

FIXED = ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"]


def assignment_name(lesson: Lesson) -> str:
    return f"Lesson {lesson.number}: {lesson.title}" if lesson.title else f"Lesson {lesson.number}"


@register("exporter", "canvas")
def write(results: list[StudentResult], catalog: Catalog, roster: tuple | list = (), missing: str = "zero") -> str:
    """The import file's text for ``results`` (StudentResult), with names and sections from ``roster``; a lesson
    not handed in is 0, or an empty cell with ``missing="blank"``."""
    if missing not in MISSING_CHOICES:
        raise ValueError(f"missing must be one of {MISSING_CHOICES}, not {missing!r}")
    people = {entry.student_id: entry for entry in roster}
    lessons = catalog.graded_lessons
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(FIXED + [assignment_name(lesson) for lesson in lessons])
    possible = {lesson.number: lesson.points for lesson in lessons}
    for result in results:  # the graded maximum includes the notebook point when the stage ran
        for lesson in result.lessons:
            possible[lesson.number] = max(possible[lesson.number], lesson.max_points)
    writer.writerow(["Points Possible", "", "", "", ""] + [f"{possible[lesson.number]:g}" for lesson in lessons])
    for result in sorted(results, key=lambda r: r.student_id):
        person = people.get(result.student_id)
        earned = {lesson.number: lesson.points for lesson in result.lessons if lesson.status != "missing"}
        if missing == "zero":
            earned.update({number: 0.0 for number in not_handed_in(result, lessons)})
        writer.writerow(
            [
                csv_cell(value, None)
                for value in (
                    (person.name if person and person.name else result.student_id),
                    person.canvas_id if person else "",
                    (person.sis_id if person and person.sis_id else result.student_id),
                    result.student_id,
                    person.section if person else "",
                )
            ]
            + [f"{earned[lesson.number]:g}" if lesson.number in earned else "" for lesson in lessons]
        )
    return buffer.getvalue()
