"""Take a student's answers out of their notebook, and nothing else.

For each exercise of a lesson we look for the answer cell by its nbgrader
``grade_id`` (the exercise's name). If the student deleted it and wrote the
function in a new cell, we fall back to the source: the last top-level
``def <name>`` anywhere in the notebook (with the imports of its cell). Check
cells, demonstrations and anything else the student typed are never run, so
editing or deleting a check cell cannot change a grade; it is noted all the
same ("worth a look" in the class report), since nobody does it by accident
in a locked cell.

Examples
--------
>>> program = lesson_program(student_nb, catalog.lesson("01"))   # doctest: +SKIP
>>> [label for label, _ in program.cells]                        # doctest: +SKIP
['rot2d', 'rot_x', ...]
"""

from __future__ import annotations

import ast

import nbformat

from autograder.lessons import cells
from autograder.lessons.catalog import Lesson
from autograder.sandbox.session import LessonProgram


def _defines(tree, name):
    return [
        node for node in tree.body if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.name == name
    ]


def _definitions(code_cells):
    """``{index: names of the top-level functions}`` of the code cells that may hold an answer (each cell
    parsed once, whatever the number of exercises looked for)."""
    found = {}
    for index, cell in code_cells:
        if cells.is_check_cell(cell) or cells.is_setup_cell(cell):
            continue
        source = cells.source_text(cell)
        tree = cells.parse_source(source) if "def" in source else None
        if tree is not None:
            found[index] = {
                node.name for node in tree.body if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))
            }
    return found


def _fallback_source(source, tree, name):
    """The imports of a cell followed by its last definition of ``name``."""
    lines = source.splitlines()
    pieces = [
        ast.get_source_segment(source, node) for node in tree.body if isinstance(node, (ast.Import, ast.ImportFrom))
    ]
    node = _defines(tree, name)[-1]
    start = (node.decorator_list[0].lineno if node.decorator_list else node.lineno) - 1
    pieces.append("\n".join(lines[start : node.end_lineno]))
    return "\n".join(p for p in pieces if p)


def _edited_check_cells(nb, lesson):
    """One note for the check cells that are not as released (edited), one for those removed."""
    found = {cells.grade_id(c): cells.source_text(c).strip() for c in nb.cells if cells.is_check_cell(c)}
    edited, removed = [], []
    for exercise in lesson.exercises:
        source = found.get(f"{cells.CHECK_PREFIX}{exercise.name}")
        if source is None:
            removed.append(exercise.name)
        elif source != f'check("{exercise.name}", {exercise.name})':
            edited.append(exercise.name)
    return [
        f"the check cell was {what} for {', '.join(names)} (check cells are never run by the grader, "
        "so this changes no points)"
        for what, names in (("edited", edited), ("removed", removed))
        if names
    ]


def lesson_program(nb: nbformat.NotebookNode, lesson: Lesson) -> LessonProgram:
    """Build the :class:`LessonProgram` the sandbox runs for one lesson notebook.

    Parameters
    ----------
    nb : nbformat.NotebookNode
        The student's notebook (already read safely).
    lesson : autograder.lessons.catalog.Lesson

    Returns
    -------
    LessonProgram
        ``setup`` is the master's setup cell (never the student's copy);
        ``cells`` are ``(exercise name, source)`` pairs in notebook order;
        ``problems`` lists what was odd (duplicates, fallbacks, missing cells).
    """
    code_cells = [(index, cell) for index, cell in enumerate(nb.cells) if cell.get("cell_type") == "code"]
    defined = None  # index -> names of the functions a cell defines, worked out once, when first needed
    chosen, problems = [], []
    for exercise in lesson.exercises:
        name = exercise.name
        tagged = [(i, c) for i, c in code_cells if cells.grade_id(c) == name and not cells.is_check_cell(c)]
        if len(tagged) > 1:
            problems.append(f"{name}: {len(tagged)} cells carry grade_id {name!r}; the last one was graded")
        if tagged:
            index, cell = tagged[-1]
            chosen.append((index, name, cells.source_text(cell)))
            continue
        if defined is None:
            defined = _definitions(code_cells)
        found = [index for index, names in defined.items() if name in names]
        if found:
            source = cells.source_text(nb.cells[found[-1]])
            problems.append(
                f"{name}: the answer cell was not found by its id; graded the definition "
                f"of {name} found in cell {found[-1] + 1}"
            )
            chosen.append((found[-1], name, _fallback_source(source, cells.parse_source(source), name)))
        else:
            problems.append(f"{name}: no answer cell and no definition of {name} found in the notebook")
    chosen.sort()
    problems += _edited_check_cells(nb, lesson)
    return LessonProgram(
        setup=lesson.setup_source, cells=[(name, source) for _, name, source in chosen], problems=problems
    )
