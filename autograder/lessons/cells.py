"""The roles a cell plays in a lesson notebook, read from its metadata.

A lesson master (``solutions/NN_*.ipynb``) is an nbgrader source notebook:

- an **answer cell** holds one exercise: ``nbgrader.solution`` is true and its
  ``grade_id`` is the exercise's function name (``rot_z``); the solution sits
  between ``### BEGIN SOLUTION`` and ``### END SOLUTION``;
- a **check cell** follows it: ``nbgrader.grade`` is true, ``grade_id`` is
  ``check_<name>``, ``points`` is what the exercise is worth, and its source
  is ``check("<name>", <name>)``;
- the **setup cell** (tag ``setup``) holds the imports the answers need; the
  grader runs it before a student's answer cells;
- **demonstration cells** tagged ``nbval-check-output`` print results that
  nbval compares with the reference outputs;
- the **hand-in cell** ends the lesson: ``ready_to_hand_in("NN")`` runs every
  public check at once. It is a locked grade cell (``grade_id``
  ``ready-to-hand-in``) worth the notebook point, so the point has a home in
  nbgrader's gradebook: stock ``nbgrader autograde`` gives it when the cell
  runs clean (every public check passes), our grader when the notebook
  reproduces the reference and the hidden suite gives full marks.

The constructors below build such cells for authors; the predicates read them.
"""

from __future__ import annotations

import ast

import nbformat

NBGRADER_SCHEMA = 3
SETUP_TAG = "setup"
CHECK_OUTPUT_TAG = "nbval-check-output"
# The lab and the book come from one master: the book drops student-only cells (hand-in, grading, check
# cells), the students' copy drops reader-only cells (the book's own wording where one is needed).
STUDENT_ONLY_TAG = "student-only"
READER_ONLY_TAG = "reader-only"
CHECK_PREFIX = "check_"
HAND_IN_GRADE_ID = "ready-to-hand-in"  # also its cell id
BEGIN_SOLUTION = "### BEGIN SOLUTION"
END_SOLUTION = "### END SOLUTION"


def _nbgrader(cell):
    meta = cell.get("metadata", {}).get("nbgrader")
    return meta if isinstance(meta, dict) else {}


def tags(cell: dict) -> list[str]:
    value = cell.get("metadata", {}).get("tags", [])
    return [t for t in value if isinstance(t, str)] if isinstance(value, list) else []


def grade_id(cell: dict) -> str | None:
    value = _nbgrader(cell).get("grade_id")
    return value if isinstance(value, str) else None


def is_answer_cell(cell: dict) -> bool:
    meta = _nbgrader(cell)
    return cell.get("cell_type") == "code" and bool(meta.get("solution")) and not meta.get("grade")


def is_grade_cell(cell: dict) -> bool:
    """Any cell nbgrader scores: a check cell or the hand-in cell."""
    meta = _nbgrader(cell)
    return cell.get("cell_type") == "code" and bool(meta.get("grade")) and not meta.get("solution")


def is_check_cell(cell: dict) -> bool:
    return is_grade_cell(cell) and not is_hand_in_cell(cell)


def is_hand_in_cell(cell: dict) -> bool:
    return is_grade_cell(cell) and grade_id(cell) == HAND_IN_GRADE_ID


def is_setup_cell(cell: dict) -> bool:
    return cell.get("cell_type") == "code" and SETUP_TAG in tags(cell)


def is_student_only(cell: dict) -> bool:
    return STUDENT_ONLY_TAG in tags(cell)


def is_reader_only(cell: dict) -> bool:
    return READER_ONLY_TAG in tags(cell)


def drop_giveaways(cell: dict) -> None:
    """Leave out the ``giveaways`` of an answer cell's ``exercise`` metadata (they are the answer:
    ``lessons/catalog.py``); its ``kind`` and ``minutes`` stay. Every edition a student gets goes through it.
    The cell gets a new mapping, so a notebook sharing the old one (the master) keeps its giveaways."""
    metadata = cell.get("metadata", {})
    exercise = metadata.get("exercise")
    if isinstance(exercise, dict) and "giveaways" in exercise:
        metadata["exercise"] = type(exercise)({k: v for k, v in exercise.items() if k != "giveaways"})


def checks_output(cell: dict) -> bool:
    return cell.get("cell_type") == "code" and CHECK_OUTPUT_TAG in tags(cell)


def points(cell: dict) -> float:
    value = _nbgrader(cell).get("points", 0)
    return float(value) if isinstance(value, (int, float)) else 0.0


def source_text(cell: dict) -> str:
    source = cell.get("source", "")
    return "".join(source) if isinstance(source, list) else str(source)


MAX_PARSED_SOURCE = 200_000  # characters; an answer cell has a few hundred


def parse_source(source: str) -> ast.Module | None:
    """The ``ast.Module`` of a cell's source, or ``None`` when it is not Python the grader can read.

    A student's cell may be anything: a syntax error, an expression nested 100,000 levels deep (the
    parser then raises ``RecursionError`` or ``MemoryError``), or megabytes long (its tree could take
    gigabytes). Each of these gives ``None``, for that cell only; longer sources than
    :data:`MAX_PARSED_SOURCE` are not parsed at all. Student code is never run here.

    Examples
    --------
    >>> [node.name for node in parse_source("def rot_z(a):\n    return a").body]
    ['rot_z']
    >>> parse_source("-" * 100_000 + "1") is None
    True
    """
    if len(source) > MAX_PARSED_SOURCE:
        return None
    try:
        return ast.parse(source)
    except Exception:  # SyntaxError, ValueError, RecursionError, MemoryError: all the same to us
        return None


# ---------------------------------------------------------------- constructors for authors
def _meta(grade, solution, locked, cell_id, points_value=None):
    meta = {
        "grade": grade,
        "grade_id": cell_id,
        "locked": locked,
        "schema_version": NBGRADER_SCHEMA,
        "solution": solution,
        "task": False,
    }
    if points_value is not None:
        meta["points"] = points_value
    return {"nbgrader": meta}


def markdown(text: str) -> nbformat.NotebookNode:
    """A narrative cell."""
    return nbformat.v4.new_markdown_cell(text.strip("\n"))


def code(source: str, check_output: bool = False) -> nbformat.NotebookNode:
    """A demonstration cell; ``check_output`` makes nbval compare its printed output."""
    cell = nbformat.v4.new_code_cell(source.strip("\n"))
    if check_output:
        cell.metadata["tags"] = [CHECK_OUTPUT_TAG]
    return cell


def setup(source: str) -> nbformat.NotebookNode:
    """The lesson's imports, run by the grader before the student's answers."""
    cell = nbformat.v4.new_code_cell(source.strip("\n"))
    cell.metadata["tags"] = [SETUP_TAG]
    cell.metadata.update(_meta(False, False, True, "setup"))
    cell.metadata["editable"] = False
    cell.metadata["deletable"] = False
    cell.id = "setup"
    return cell


def answer(name: str, source: str) -> nbformat.NotebookNode:
    """The answer cell of exercise ``name``; ``source`` contains the solution markers."""
    if BEGIN_SOLUTION not in source or END_SOLUTION not in source:
        raise ValueError(f"answer cell {name!r} has no solution markers")
    cell = nbformat.v4.new_code_cell(source.strip("\n"))
    cell.metadata.update(_meta(False, True, False, name))
    cell.id = name
    return cell


def hand_in(lesson_number: str, points_value: float = 1) -> nbformat.NotebookNode:
    """The locked last cell of a lesson, worth the notebook point (see the module docstring)."""
    cell = nbformat.v4.new_code_cell(f'from coursekit import ready_to_hand_in\n\nready_to_hand_in("{lesson_number}")')
    cell.metadata.update(_meta(True, False, True, HAND_IN_GRADE_ID, points_value))
    cell.metadata["editable"] = False
    cell.metadata["deletable"] = False
    cell.metadata["tags"] = [STUDENT_ONLY_TAG]
    cell.id = HAND_IN_GRADE_ID
    return cell


def check(name: str, points_value: float) -> nbformat.NotebookNode:
    """The locked check cell that follows exercise ``name``."""
    cell = nbformat.v4.new_code_cell(f'check("{name}", {name})')
    cell.metadata.update(_meta(True, False, True, CHECK_PREFIX + name, points_value))
    cell.metadata["editable"] = False
    cell.metadata["deletable"] = False
    cell.metadata["tags"] = [STUDENT_ONLY_TAG]
    cell.id = CHECK_PREFIX + name
    return cell
