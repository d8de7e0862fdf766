"""The gradebook: one CSV row per student, safe to open in a spreadsheet.

Columns: ``student_id, score, max_score, status``; one total per lesson
(``lesson_01``…: its exercises and notebook point, after any late penalty;
each lesson is often its own assignment); one column per exercise (points
earned); one per lesson for the notebook stage (``notebook_01``…, when it
ran); ``late`` (which lessons were late and by how much); then nbgrader's
export columns that apply: ``raw_score`` (before late penalties) and
``timestamp`` (when the newest notebook was handed in); ``graded_at`` and
``problems``.

Every text cell that a spreadsheet could read as a formula (starting with
``=``, ``+``, ``-``, ``@``, a tab or a carriage return) is prefixed with an
apostrophe, so a student named ``=HYPERLINK(...)`` stays a name.
"""

import csv
import io

FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")


def spreadsheet_safe(text):
    """``text`` with a leading apostrophe if a spreadsheet would evaluate it.

    Examples
    --------
    >>> spreadsheet_safe("=1+1"), spreadsheet_safe("ada")
    ("'=1+1", 'ada')
    """
    text = str(text)
    return "'" + text if text.startswith(FORMULA_STARTS) else text


def _number(value):
    return f"{value:g}"


def columns(catalog, with_notebooks):
    names = ["student_id", "score", "max_score", "status"]
    names += [f"lesson_{lesson.number}" for lesson in catalog.graded_lessons]
    names += [exercise.name for exercise in catalog.exercises]
    if with_notebooks:
        names += [f"notebook_{lesson.number}" for lesson in catalog.graded_lessons]
    return names + ["late", "raw_score", "timestamp", "graded_at", "problems"]


def row(result, catalog, with_notebooks, graded_at=""):
    earned = {e.name: e.points for e in result.exercises}
    lessons = {lesson.number: lesson for lesson in result.lessons}
    values = [spreadsheet_safe(result.student_id), _number(result.score), _number(result.max_score),
              spreadsheet_safe(result.status)]
    values += [_number(lessons[l.number].points) if l.number in lessons else "" for l in catalog.graded_lessons]
    values += [_number(earned[e.name]) if e.name in earned else "" for e in catalog.exercises]
    if with_notebooks:
        values += [_number(lessons[l.number].run.points) if l.number in lessons and lessons[l.number].run else ""
                   for l in catalog.graded_lessons]
    late = "; ".join(f"{lesson.number}: −{100 * lesson.late_penalty:g}%" for lesson in result.lessons
                     if lesson.late_penalty)
    problems = "; ".join(([result.reason] if result.reason else []) + list(result.problems))
    values += [late, _number(result.raw_score), spreadsheet_safe(result.submitted_at), spreadsheet_safe(graded_at),
               spreadsheet_safe(problems[:2000])]
    return values


def gradebook_csv(results, catalog, graded_at=None):
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
