"""Write our grades into an nbgrader gradebook, so the formgrader shows them.

Each lesson is the assignment ``lessonNN`` (as in :mod:`autograder.integrations.nbgrader_course`),
its notebook is the lesson's file name without ``.ipynb``, and each exercise's
check cell ``check_<name>`` is a grade cell worth the exercise's points.

What nbgrader can live with:

- **Structure exactly as nbgrader makes it.** An assignment's cells are recorded
  by nbgrader's own ``SaveCells`` preprocessor on the released notebook, the
  same step ``nbgrader generate_assignment`` runs, so regenerating an
  assignment later finds the cells it expects (it refuses to add or remove
  cells once submissions exist).
- **Only lessons that were handed in** get a submission; a student who handed
  in two lessons has two submissions, not eight.
- **Who owns which score.** We write the *automatic* score (``auto_score``) of
  the ``check_<name>`` grade cells, nothing else: manual scores, comments and
  extra credit stay the instructor's. ``nbgrader autograde`` writes the same
  automatic scores from the visible check cells, so **whichever ran last
  owns them**: after an ``nbgrader autograde``, re-run
  ``python -m autograder grade ... --nbgrader-db PATH`` (unchanged students are
  reused, the export runs again) to put the thorough grades back.
- **The notebook point** goes to the lesson's hand-in cell (``grade_id``
  ``ready-to-hand-in``, a grade cell worth the point), when the notebook stage
  ran; with ``--no-nbval`` that cell is left as it is.

Examples
--------
>>> export_to_gradebook(results, "nbgrader-course/gradebook.db", course)  # doctest: +SKIP
"""

from __future__ import annotations

import os
import warnings

from nbgrader.api import Gradebook, MissingEntry

from autograder.grading.results import COULD_NOT_GRADE, MISSING, StudentResult
from autograder.integrations.nbgrader_course import assignment_name, with_environment_tools
from autograder.lessons import cells
from autograder.lessons.course import Course
from autograder.lessons.notebook_files import read_master


def _database_url(path_or_url):
    text = str(path_or_url)
    return text if "://" in text else f"sqlite:///{text}"


def _ensure_structure(url, lesson, released):
    """Record the lesson's cells as ``nbgrader generate_assignment`` would (its own SaveCells step)."""
    from nbgrader.preprocessors import SaveCells

    assignment = assignment_name(lesson)
    notebook = lesson.filename[: -len(".ipynb")]
    with Gradebook(url) as gradebook:
        gradebook.update_or_create_assignment(assignment)
        try:
            existing = gradebook.find_notebook(notebook, assignment)
            recorded = bool(existing.grade_cells)
        except MissingEntry:
            recorded = False
    if not recorded:  # already there (from nbgrader itself or an earlier export): leave it as it is
        resources = {"nbgrader": {"db_url": url, "assignment": assignment, "notebook": notebook}}
        SaveCells().preprocess(read_master(released / lesson.filename), resources)
    return assignment, notebook


def export_to_gradebook(results: list[StudentResult], database: str | os.PathLike, course: Course) -> int:
    """Create ``course``'s assignments (as nbgrader would), students, and automatic scores for the lessons
    handed in; return the number of grade cells written."""
    catalog = course.catalog
    url = _database_url(database)
    written = 0
    os.environ.update(with_environment_tools())
    handed_in = {
        lesson.number
        for result in results
        if result.status not in (MISSING, COULD_NOT_GRADE)
        for lesson in result.lessons
        if lesson.status != "missing"
    }
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # SQLAlchemy's notes about nbgrader's own models
        structure = {
            lesson.number: _ensure_structure(url, lesson, course.released)
            for lesson in catalog.graded_lessons
            if lesson.number in handed_in
        }
        gradebook = Gradebook(url)
    with warnings.catch_warnings(), gradebook:
        warnings.simplefilter("ignore")
        for result in results:
            if result.status in (MISSING, COULD_NOT_GRADE):
                continue
            gradebook.update_or_create_student(result.student_id)
            for lesson in result.lessons:
                if lesson.status == "missing":
                    continue
                assignment, notebook = structure[lesson.number]
                try:
                    gradebook.find_submission(assignment, result.student_id)
                except MissingEntry:
                    gradebook.add_submission(assignment, result.student_id)
                scores = {f"{cells.CHECK_PREFIX}{exercise.name}": exercise.points for exercise in lesson.exercises}
                if lesson.run is not None:
                    scores[cells.HAND_IN_GRADE_ID] = lesson.run.points
                for cell_id, points in scores.items():
                    gradebook.find_grade(cell_id, notebook, assignment, result.student_id).auto_score = points
                    written += 1
            gradebook.db.commit()
    return written
