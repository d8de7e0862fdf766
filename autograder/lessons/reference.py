"""The reference solutions, run from the masters in the grader's own process.

The hidden suite compares each student's answer with these functions (and
with scipy where it applies). They are the solution cells of ``solutions/``
executed as written, so there is one copy of every solution in the project.

Examples
--------
>>> ref = load_reference()
>>> ref.rot_z(0.0)
array([[1., 0., 0.],
       [0., 1., 0.],
       [0., 0., 1.]])
"""

from functools import lru_cache
from types import SimpleNamespace

from autograder.lessons import cells
from autograder.lessons.catalog import load_catalog
from autograder.lessons.notebook_files import read_master
from autograder.lessons.paths import SOLUTIONS


def lesson_namespace(master, label):
    """Execute a master's setup cell and answer cells; return the namespace dict."""
    namespace = {"__name__": f"reference_{label}"}
    for cell in master.cells:
        if cells.is_setup_cell(cell) or cells.is_answer_cell(cell):
            exec(compile(cells.source_text(cell), f"<reference {label} {cells.grade_id(cell)}>", "exec"),
                 namespace)
    return namespace


@lru_cache(maxsize=2)
def load_reference(solutions_dir=SOLUTIONS):
    """A namespace with every exercise function of every lesson, from the masters."""
    catalog = load_catalog(solutions_dir)
    functions = {}
    for lesson in catalog.graded_lessons:
        namespace = lesson_namespace(read_master(solutions_dir / lesson.filename), lesson.number)
        for exercise in lesson.exercises:
            functions[exercise.name] = namespace[exercise.name]
    return SimpleNamespace(**functions)


def answer_sources(solutions_dir=SOLUTIONS):
    """``{exercise name: answer-cell source}`` of the masters, solution markers removed."""
    catalog = load_catalog(solutions_dir)
    sources = {}
    for lesson in catalog.graded_lessons:
        for cell in read_master(solutions_dir / lesson.filename).cells:
            if cells.is_answer_cell(cell):
                text = cells.source_text(cell)
                kept = [line for line in text.splitlines()
                        if line.strip() not in (cells.BEGIN_SOLUTION, cells.END_SOLUTION)]
                sources[cells.grade_id(cell)] = "\n".join(kept)
    return sources
