"""The lessons and their exercises, read from a course's masters (``solutions/``).

The masters are the single source of truth: an exercise exists because its
answer cell exists, and it is worth what its check cell's ``points`` say.

Examples
--------
>>> catalog = load_catalog(Path("solutions"))
>>> catalog.exercise("rot_z").lesson
'01'
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cached_property, lru_cache
from pathlib import Path

import nbformat

from autograder.lessons import cells
from autograder.lessons.notebook_files import read_master

LESSON_FILE = re.compile(r"^(\d\d)_[a-z0-9_]+\.ipynb$")


@dataclass(frozen=True)
class Exercise:
    name: str
    lesson: str
    points: float


@dataclass(frozen=True)
class Lesson:
    number: str
    filename: str
    title: str
    exercises: tuple[Exercise, ...]
    setup_source: str
    hand_in_points: float = 0.0  # the notebook point, as the hand-in grade cell records it for nbgrader

    @property
    def points(self) -> float:
        return sum(exercise.points for exercise in self.exercises)


@dataclass(frozen=True)
class Catalog:
    lessons: tuple[Lesson, ...]

    @property
    def exercises(self) -> tuple[Exercise, ...]:
        return tuple(e for lesson in self.lessons for e in lesson.exercises)

    @property
    def graded_lessons(self) -> tuple[Lesson, ...]:
        return tuple(lesson for lesson in self.lessons if lesson.exercises)

    def lesson(self, number: str) -> Lesson:
        for lesson in self.lessons:
            if lesson.number == number:
                return lesson
        raise KeyError(f"no lesson {number!r}")

    @cached_property
    def _exercises_by_name(self):  # the hidden suite looks one up per student call
        return {exercise.name: exercise for exercise in self.exercises}

    def exercise(self, name: str) -> Exercise:
        try:
            return self._exercises_by_name[name]
        except KeyError:
            raise KeyError(f"no exercise {name!r}") from None


class CatalogError(ValueError):
    """A master notebook breaks the conventions of :mod:`autograder.lessons.cells`."""


def lesson_from_notebook(path: Path, nb: nbformat.NotebookNode) -> Lesson:
    """Read one master's lesson number, title, exercises and setup cell."""
    match = LESSON_FILE.match(Path(path).name)
    if not match:
        raise CatalogError(f"{path}: lesson files are named NN_words.ipynb")
    number = match.group(1)
    title = ""
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            first = cells.source_text(cell).strip().splitlines()[0] if cells.source_text(cell).strip() else ""
            if first.startswith("# "):
                title = re.sub(r"^Lesson\s+\d+\s*[—:-]\s*", "", first[2:].strip())
                break
    exercises, setup_source, pending, hand_in_points = [], "", None, 0.0
    for cell in nb.cells:
        if cells.is_setup_cell(cell):
            setup_source = cells.source_text(cell)
        elif cells.is_hand_in_cell(cell):
            hand_in_points = cells.points(cell)
        elif cells.is_answer_cell(cell):
            if pending:
                raise CatalogError(f"{path}: answer cell {pending!r} has no check cell after it")
            pending = cells.grade_id(cell)
        elif cells.is_check_cell(cell):
            name = (cells.grade_id(cell) or "")[len(cells.CHECK_PREFIX) :]
            if name != pending:
                raise CatalogError(f"{path}: check cell {cells.grade_id(cell)!r} does not follow its answer cell")
            exercises.append(Exercise(name=name, lesson=number, points=cells.points(cell)))
            pending = None
    if pending:
        raise CatalogError(f"{path}: answer cell {pending!r} has no check cell after it")
    return Lesson(
        number=number,
        filename=Path(path).name,
        title=title,
        exercises=tuple(exercises),
        setup_source=setup_source,
        hand_in_points=hand_in_points,
    )


@lru_cache(maxsize=4)
def load_catalog(solutions_dir: Path) -> Catalog:
    """Build the catalog from every ``NN_*.ipynb`` master, in lesson order."""
    lessons = []
    for path in sorted(Path(solutions_dir).glob("[0-9][0-9]_*.ipynb")):
        lessons.append(lesson_from_notebook(path, read_master(path)))
    names = [e.name for lesson in lessons for e in lesson.exercises]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise CatalogError(f"exercise names used twice: {duplicates}")
    return Catalog(lessons=tuple(lessons))
