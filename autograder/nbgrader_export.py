"""Write our grades into an nbgrader gradebook, so the formgrader shows them.

Each lesson is the assignment ``lessonNN`` (as in :mod:`autograder.nbgrader_course`),
its notebook is the lesson's file name without ``.ipynb``, and each exercise's
check cell ``check_<name>`` is a grade cell worth the exercise's points. Our
points for the exercise become that cell's automatic score. The notebook
stage's point has no cell in nbgrader's model and stays in ``grades.csv``.

Examples
--------
>>> export_to_gradebook(results, "sqlite:////path/to/course/gradebook.db")  # doctest: +SKIP
"""

import os
import warnings

from nbgrader.api import Gradebook, MissingEntry

from .catalog import load_catalog
from .nbgrader_course import assignment_name, with_environment_tools
from .results import COULD_NOT_GRADE, MISSING


def _database_url(path_or_url):
    text = str(path_or_url)
    return text if "://" in text else f"sqlite:///{text}"


def _ensure_structure(gradebook, lesson):
    assignment = assignment_name(lesson)
    notebook = lesson.filename[: -len(".ipynb")]
    gradebook.update_or_create_assignment(assignment)
    gradebook.update_or_create_notebook(notebook, assignment)
    for exercise in lesson.exercises:
        gradebook.update_or_create_grade_cell(f"check_{exercise.name}", notebook, assignment,
                                              max_score=exercise.points, cell_type="code")
        gradebook.update_or_create_solution_cell(exercise.name, notebook, assignment)
    return assignment, notebook


def export_to_gradebook(results, database):
    """Create or update assignments, students and automatic scores; return rows written."""
    catalog = load_catalog()
    written = 0
    os.environ.update(with_environment_tools())
    with warnings.catch_warnings(), Gradebook(_database_url(database)) as gradebook:
        warnings.simplefilter("ignore")  # SQLAlchemy's notes about nbgrader's own models
        structure = {lesson.number: _ensure_structure(gradebook, lesson) for lesson in catalog.graded_lessons}
        for result in results:
            if result.status in (MISSING, COULD_NOT_GRADE):
                continue
            gradebook.update_or_create_student(result.student_id)
            for lesson in result.lessons:
                assignment, notebook = structure[lesson.number]
                try:
                    gradebook.find_submission(assignment, result.student_id)
                except MissingEntry:
                    gradebook.add_submission(assignment, result.student_id)
                for exercise in lesson.exercises:
                    grade = gradebook.find_grade(f"check_{exercise.name}", notebook, assignment, result.student_id)
                    grade.auto_score = exercise.points
                    written += 1
            gradebook.db.commit()
    return written
