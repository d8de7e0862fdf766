"""The lessons and their exercises, read from a course's masters (``solutions/``).

The masters are the single source of truth: an exercise exists because its
answer cell exists, and it is worth what its check cell's ``points`` say.

What kind of thinking an exercise asks for is recorded on its answer cell, as cell metadata
(COURSE_SPEC.md, "Exercise kinds")::

    "exercise": {"kind": "derive", "minutes": 20, "giveaways": ["1 + a·b", "np.cross(a, b)"]}

``kind`` is one of :data:`KINDS`; ``minutes`` is the estimated time a student spends on it;
``giveaways`` (required for the kinds of :data:`THINKING_KINDS`) are the phrases, in LaTeX and in
code, that would hand its result away: they must appear nowhere in the student edition
(``tests/test_answers_off_page.py``), and ``release`` leaves them out of ``course/``.

Examples
--------
>>> catalog = load_catalog(Path("solutions"))
>>> catalog.exercise("rot_z").lesson
'01'
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass
from functools import cached_property, lru_cache
from pathlib import Path

import nbformat

from autograder.lessons import cells
from autograder.lessons.notebook_files import read_master

LESSON_FILE = re.compile(r"^(\d\d)_[a-z0-9_]+\.ipynb$")
EXERCISE_METADATA = "exercise"  # the answer cell's metadata key (see the module docstring)
KINDS = ("transcribe", "assemble", "derive", "design", "diagnose")
THINKING_KINDS = ("derive", "design", "diagnose")  # the page never gives their result
GIVEAWAYS = "giveaways"


@dataclass(frozen=True)
class Exercise:
    name: str
    lesson: str
    points: float
    kind: str = ""  # one of KINDS; "" when the master does not say
    minutes: int = 0  # estimated student time; 0 when the master does not say
    giveaways: tuple[str, ...] = ()
    meaning: str = ""  # the first line of the answer function's docstring

    @property
    def asks_for_thinking(self) -> bool:
        return self.kind in THINKING_KINDS


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


def exercise_metadata(cell: dict, where: str = "answer cell") -> tuple[str, int, tuple[str, ...]]:
    """``(kind, minutes, giveaways)`` of an answer cell's ``"exercise"`` metadata; ``("", 0, ())`` without it.

    Raises :class:`CatalogError` when the metadata is there but malformed.

    Examples
    --------
    >>> exercise_metadata({"metadata": {"exercise": {"kind": "derive", "minutes": 15, "giveaways": ["1 + a·b"]}}})
    ('derive', 15, ('1 + a·b',))
    """
    meta = cell.get("metadata", {}).get(EXERCISE_METADATA)
    if meta is None:
        return "", 0, ()
    if not isinstance(meta, dict):
        raise CatalogError(f"{where}: metadata {EXERCISE_METADATA!r} must be a mapping")
    kind, minutes, giveaways = meta.get("kind"), meta.get("minutes"), meta.get(GIVEAWAYS, [])
    if kind not in KINDS:
        raise CatalogError(f"{where}: exercise kind {kind!r} is not one of {', '.join(KINDS)}")
    if not isinstance(minutes, int) or isinstance(minutes, bool) or minutes <= 0:
        raise CatalogError(f"{where}: exercise minutes must be a positive whole number, not {minutes!r}")
    if not isinstance(giveaways, list) or not all(isinstance(g, str) and g.strip() for g in giveaways):
        raise CatalogError(f"{where}: exercise giveaways must be a list of non-empty strings")
    unknown = sorted(set(meta) - {"kind", "minutes", GIVEAWAYS})
    if unknown:
        raise CatalogError(f"{where}: unknown exercise metadata {unknown}")
    return kind, minutes, tuple(giveaways)


def _meaning(cell: dict, name: str) -> str:
    """The first line of the docstring of the function ``name`` defined in ``cell``."""
    tree = cells.parse_source(cells.source_text(cell))
    for node in tree.body if tree else ():
        if isinstance(node, ast.FunctionDef) and node.name == name:
            doc = (ast.get_docstring(node) or "").strip()
            return doc.splitlines()[0].strip() if doc else ""
    return ""


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
    details = {}
    for cell in nb.cells:
        if cells.is_setup_cell(cell):
            setup_source = cells.source_text(cell)
        elif cells.is_hand_in_cell(cell):
            hand_in_points = cells.points(cell)
        elif cells.is_answer_cell(cell):
            if pending:
                raise CatalogError(f"{path}: answer cell {pending!r} has no check cell after it")
            pending = cells.grade_id(cell)
            kind, minutes, giveaways = exercise_metadata(cell, f"{path}: answer cell {pending!r}")
            details = dict(kind=kind, minutes=minutes, giveaways=giveaways, meaning=_meaning(cell, pending))
        elif cells.is_check_cell(cell):
            name = (cells.grade_id(cell) or "")[len(cells.CHECK_PREFIX) :]
            if name != pending:
                raise CatalogError(f"{path}: check cell {cells.grade_id(cell)!r} does not follow its answer cell")
            exercises.append(Exercise(name=name, lesson=number, points=cells.points(cell), **details))
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
