"""The reference solutions, run from the masters in the grader's own process.

The hidden suite compares each student's answer with these functions (and
with scipy where it applies). They are the solution cells of ``solutions/``
executed as written, so there is one copy of every solution in the project.
The setup cells import ``coursekit``: call :meth:`~autograder.lessons.course.Course.use_support_package`
first (``Course.reference`` does).

Examples
--------
>>> ref = load_reference(Path("solutions"))
>>> ref.rot_z(0.0)
array([[1., 0., 0.],
       [0., 1., 0.],
       [0., 0., 1.]])
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from types import SimpleNamespace

import nbformat

from autograder.lessons import cells
from autograder.lessons.catalog import load_catalog
from autograder.lessons.notebook_files import read_master


def lesson_namespace(master: nbformat.NotebookNode, label: str) -> dict:
    """Execute a master's setup cell and answer cells; return the namespace dict."""
    namespace = {"__name__": f"reference_{label}"}
    for cell in master.cells:
        if cells.is_setup_cell(cell) or cells.is_answer_cell(cell):
            exec(compile(cells.source_text(cell), f"<reference {label} {cells.grade_id(cell)}>", "exec"), namespace)
    return namespace


class ReferenceSolutions(SimpleNamespace):
    """Every exercise function of the masters as an attribute (``ref.rot_z``), and a ``memo``.

    ``memo`` is a dict the grading stage keeps what it learns about these
    functions in (the hidden tests' transcripts, :mod:`autograder.grading.suite`),
    so it lives and dies with them and never outlives them. It is not an
    attribute of the namespace's contents: ``vars(ref)`` holds the functions only.
    """

    __slots__ = ("memo",)

    def __init__(self, functions: dict):
        super().__init__(**functions)
        self.memo = {}


@lru_cache(maxsize=2)
def load_reference(solutions_dir: Path) -> ReferenceSolutions:
    """A namespace with every exercise function of every lesson, from the masters."""
    catalog = load_catalog(solutions_dir)
    functions = {}
    for lesson in catalog.graded_lessons:
        namespace = lesson_namespace(read_master(Path(solutions_dir) / lesson.filename), lesson.number)
        for exercise in lesson.exercises:
            functions[exercise.name] = namespace[exercise.name]
    return ReferenceSolutions(functions)


def answer_sources(solutions_dir: Path) -> dict[str, str]:
    """``{exercise name: answer-cell source}`` of the masters, solution markers removed."""
    catalog = load_catalog(solutions_dir)
    sources = {}
    for lesson in catalog.graded_lessons:
        for cell in read_master(Path(solutions_dir) / lesson.filename).cells:
            if cells.is_answer_cell(cell):
                text = cells.source_text(cell)
                kept = [
                    line for line in text.splitlines() if line.strip() not in (cells.BEGIN_SOLUTION, cells.END_SOLUTION)
                ]
                sources[cells.grade_id(cell)] = "\n".join(kept)
    return sources
