"""The gradebook: one CSV row per student, safe to open in a spreadsheet.

Columns: ``student_id, score, max_score, status``, then one column per
exercise (points earned), one per lesson for the notebook stage
(``notebook_01``…, when it ran), then nbgrader's export columns that apply
(``raw_score``, ``timestamp``) and ``problems``.

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
    names += [exercise.name for exercise in catalog.exercises]
    if with_notebooks:
        names += [f"notebook_{lesson.number}" for lesson in catalog.graded_lessons]
    return names + ["raw_score", "timestamp", "problems"]


def row(result, catalog, with_notebooks, timestamp=""):
    earned = {e.name: e.points for e in result.exercises}
    runs = {lesson.number: lesson.run for lesson in result.lessons}
    values = [spreadsheet_safe(result.student_id), _number(result.score), _number(result.max_score),
              spreadsheet_safe(result.status)]
    values += [_number(earned[e.name]) if e.name in earned else "" for e in catalog.exercises]
    if with_notebooks:
        values += [_number(runs[l.number].points) if runs.get(l.number) else "" for l in catalog.graded_lessons]
    problems = "; ".join(([result.reason] if result.reason else []) + list(result.problems))
    values += [_number(result.score), spreadsheet_safe(timestamp), spreadsheet_safe(problems[:2000])]
    return values


def gradebook_csv(results, catalog, timestamps=None):
    """The gradebook text for a list of :class:`~autograder.results.StudentResult`."""
    timestamps = timestamps or {}
    with_notebooks = any(lesson.run is not None for r in results for lesson in r.lessons)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(columns(catalog, with_notebooks))
    for result in sorted(results, key=lambda r: r.student_id):
        writer.writerow(row(result, catalog, with_notebooks, timestamps.get(result.student_id, "")))
    return buffer.getvalue()
