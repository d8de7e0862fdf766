"""Which answer each student wrote for each exercise, read the way the grader reads it.

The notebooks of a class folder are found and matched to lessons by
:mod:`autograder.grading.submissions`, and each exercise's answer cell is taken
by :func:`autograder.grading.extract.lesson_program` (by ``grade_id``, else by
the function it defines), so the similarity stage compares exactly what was
graded. A student whose folder cannot be read costs that student only: the
reason is kept in :attr:`ClassAnswers.unread`. An answer is compared on its
first :data:`MAX_ANSWER_CHARACTERS` characters, so a cell of megabytes costs
no more than a long answer.

Examples
--------
>>> answers = read_class(Path("class"), course)               # doctest: +SKIP
>>> answers.by_exercise["rot_z"]["ada"][:14]
'def rot_z(angle'
"""

from __future__ import annotations

import multiprocessing
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from autograder.grading.extract import lesson_program
from autograder.grading.submissions import match_lessons, scan_submissions
from autograder.lessons import cells
from autograder.lessons.course import Course
from autograder.lessons.notebook_files import read_master, read_submission

MAX_ANSWER_CHARACTERS = 20_000  # a long answer is a few thousand


@dataclass
class ClassAnswers:
    """``by_exercise[exercise][author] = answer source``; ``unread[author] = why`` nothing was read."""

    by_exercise: dict = field(default_factory=dict)
    unread: dict = field(default_factory=dict)

    @property
    def authors(self) -> list[str]:
        return sorted({author for answers in self.by_exercise.values() for author in answers} | set(self.unread))


def student_answers(folder: Path, course: Course) -> dict[str, str]:
    """``{exercise: source}`` of one student's folder (lessons matched by content, cells by grade_id)."""
    catalog = course.catalog
    found, parsed = {}, {}

    def read(path):  # each notebook parsed once: matching lessons reads it, and so does taking its cells
        if path not in parsed:
            parsed[path] = read_submission(path, root=folder)
        return parsed[path]

    files = match_lessons(Path(folder), catalog, course.released, read=read)
    for lesson in catalog.graded_lessons:
        path = files.chosen.get(lesson.number)
        if path is None or path in files.unreadable:
            continue
        program = lesson_program(read(path), lesson)
        found.update((name, source[:MAX_ANSWER_CHARACTERS]) for name, source in program.cells)
    return found


def _one_student(folder, course):
    """``(answers, None)``, or ``(None, why)`` when the folder could not be read (that student only)."""
    try:
        return student_answers(folder, course), None
    except Exception as error:
        return None, f"{type(error).__name__}: {error}"


def read_class(path: str | Path, course: Course, prefix: str = "", jobs: int = 1) -> ClassAnswers:
    """Every student's answers under ``path`` (any layout :mod:`~autograder.grading.submissions` reads).

    ``prefix`` is put before each student id (``"past term/"`` for a past class), so authors from
    different folders never share a name. ``jobs``: forked processes reading students' folders.
    """
    answers = ClassAnswers()
    students = scan_submissions(path).files
    tasks = [(folder, course) for _, folder in students]
    if jobs > 1 and len(tasks) > 20 and "fork" in multiprocessing.get_all_start_methods():
        with multiprocessing.get_context("fork").Pool(jobs) as pool:
            read = pool.starmap(_one_student, tasks, chunksize=max(1, len(tasks) // (4 * jobs)))
    else:
        read = [_one_student(*task) for task in tasks]
    for (student_id, _), (found, why) in zip(students, read):
        author = f"{prefix}{student_id}"
        if why is not None:
            answers.unread[author] = why
        for exercise, source in (found or {}).items():
            answers.by_exercise.setdefault(exercise, {})[author] = source
    return answers


@lru_cache(maxsize=None)
def released_stubs(course_dir: Path) -> dict[str, str]:
    """``{exercise: the answer cell as released in course/}``: what every student started from."""
    stubs = {}
    for path in sorted(Path(course_dir).glob("[0-9][0-9]_*.ipynb")):
        for cell in read_master(path).cells:
            if cells.is_answer_cell(cell):
                stubs[cells.grade_id(cell)] = cells.source_text(cell)
    return stubs
