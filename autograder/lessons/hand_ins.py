"""Notebooks as a student hands them in, written from a course's released lessons.

The canary grades one (every reference answer: it must get full marks), and the
tests build their classes with it.

Examples
--------
>>> folder = write_submission(course, tmp, {"rot_z": "def rot_z(angle):\\n    return None"}, lessons=("01",))  # doctest: +SKIP
>>> sorted(p.name for p in folder.iterdir())                                                            # doctest: +SKIP
['01_frames_and_rotations.ipynb']
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from autograder.lessons import cells
from autograder.lessons.notebook_files import canonical_text, read_master
from autograder.lessons.reference import answer_sources

if TYPE_CHECKING:
    from autograder.lessons.course import Course


def write_submission(
    course: Course, folder: str | Path, answers: dict[str, str], lessons: tuple[str, ...] = ()
) -> Path:
    """Write ``course``'s released notebooks into ``folder`` with ``answers`` in their answer cells;
    return ``folder`` (a :class:`~pathlib.Path`).

    ``answers``: ``{exercise name: answer-cell source}``; an exercise not in it keeps its stub.
    ``lessons``: only these lesson numbers (default: every graded lesson).
    """
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    for lesson in course.catalog.graded_lessons:
        if lessons and lesson.number not in lessons:
            continue
        nb = read_master(course.released / lesson.filename)
        for cell in nb.cells:
            if cells.is_answer_cell(cell) and cells.grade_id(cell) in answers:
                cell.source = answers[cells.grade_id(cell)]
        (folder / lesson.filename).write_text(canonical_text(nb), encoding="utf-8")
    return folder


def write_reference_submission(course: Course, folder: str | Path, lessons: tuple[str, ...] = ()) -> Path:
    """:func:`write_submission` with every reference answer: the canary's submission
    (:mod:`autograder.grading.canary`), which must get full marks."""
    return write_submission(course, folder, answer_sources(course.solutions), lessons)
