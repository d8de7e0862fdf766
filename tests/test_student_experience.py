"""What a student sees in a real kernel: one friendly line where a check stops, and a hand-in summary.

Run in Jupyter's kernel (nbclient), lesson 01 as released (stubs) and as solved:
- every check cell that fails ends in an error (nbgrader counts it as failed) shown as ONE red line
  that names the exercise, not a traceback into coursekit;
- the lesson's last cell, "Ready to hand in?", lists every unwritten exercise for the stubs and
  ends in one red line naming them (the error that scores the notebook point 0 in nbgrader);
  it says "ready to hand in" for the reference and raises nothing (and shows no value under it);
- every other cell that reaches a stub (a worked example, a figure) also ends in one line naming the
  exercise to write, while a NotImplementedError raised inside a library keeps its traceback.
"""

import shutil

import nbformat
import pytest
from nbclient import NotebookClient

from autograder.grading.pipeline import GradingOptions
from autograder.lessons import cells
from autograder.lessons.paths import COURSE, SOLUTIONS
from support import THIS_COURSE

LESSON = "01_frames_and_rotations.ipynb"
EXERCISES = [e.name for e in THIS_COURSE.catalog.lesson("01").exercises]


def _execute(folder):
    nb = nbformat.read(str(folder / LESSON), as_version=4)
    NotebookClient(
        nb, timeout=120, allow_errors=True, kernel_name="python3", resources={"metadata": {"path": str(folder)}}
    ).execute()
    return nb


@pytest.fixture(scope="module")
def released():
    return _execute(COURSE)


@pytest.fixture(scope="module")
def solved():
    return _execute(SOLUTIONS)


def _errors(cell):
    return [o for o in cell.get("outputs", []) if o.get("output_type") == "error"]


def _hand_in(nb):
    """``(printed text, errors)`` of the hand-in cell."""
    cell = next(c for c in nb.cells if c.get("id") == "ready-to-hand-in")
    return "".join(o.get("text", "") for o in cell.outputs), _errors(cell)


def test_a_failing_check_is_one_line_that_names_the_exercise(released):
    checks = [c for c in released.cells if cells.is_check_cell(c)]
    assert checks
    for cell in checks:
        name = cells.grade_id(cell)[len(cells.CHECK_PREFIX) :]
        (error,) = _errors(cell)
        assert error["ename"] == "NotWrittenYet" and len(error["traceback"]) == 1, error["traceback"][:3]
        assert f"write {name} next" in error["traceback"][0]


def test_the_hand_in_cell_lists_what_is_left(released, solved):
    left, errors = _hand_in(released)
    assert f"0 of {len(EXERCISES)} exercises pass" in left and f"Still to do: {', '.join(EXERCISES)}." in left
    (error,) = errors
    assert error["ename"] == "NotReadyYet" and len(error["traceback"]) == 1, error["traceback"][:3]
    assert f"still to do in lesson 01: {', '.join(EXERCISES)}" in error["traceback"][0]
    done, errors = _hand_in(solved)
    assert f"All {len(EXERCISES)} exercises pass their public checks: ready to hand in" in done and "✗" not in done
    assert not errors
    cell = next(c for c in solved.cells if c.get("id") == "ready-to-hand-in")
    assert not [o for o in cell.outputs if o.get("output_type") == "execute_result"], "a value under the cell"


def test_every_cell_that_reaches_a_stub_says_so_in_one_line(released):
    reached = [
        c for c in released.cells if _errors(c) and not cells.is_check_cell(c) and c.get("id") != "ready-to-hand-in"
    ]
    assert reached, "no worked example or figure of lesson 01 calls an exercise: the test would hold nothing"
    for cell in reached:
        (error,) = _errors(cell)
        assert error["ename"] == "NotImplementedError" and len(error["traceback"]) == 1, error["traceback"][:3]
        named = [name for name in EXERCISES if f"{name} is not written yet: write {name}" in error["traceback"][0]]
        assert named and named[0] in cell.source, (cell.source[:200], error["traceback"][0])


def test_only_a_stub_gets_the_one_line(tmp_path):
    """A NotImplementedError from a library, or raised where no stub is, keeps IPython's traceback."""
    shutil.copytree(SOLUTIONS / "coursekit", tmp_path / "coursekit")
    nb = nbformat.v4.new_notebook(
        cells=[
            nbformat.v4.new_code_cell("import coursekit\nimport numpy as np"),
            nbformat.v4.new_code_cell("def rot_x(angle):\n    raise NotImplementedError('not written yet')"),
            nbformat.v4.new_code_cell("[rot_x(a) for a in np.linspace(0, 1, 3)]"),
            nbformat.v4.new_code_cell("import numbers\nnumbers.Complex.real.fget(1j)"),  # raised in numbers.py
            nbformat.v4.new_code_cell("raise NotImplementedError('typed at the top level')"),
        ]
    )
    NotebookClient(
        nb, timeout=60, allow_errors=True, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    ).execute()
    (stub,) = _errors(nb.cells[2])
    assert len(stub["traceback"]) == 1 and "rot_x is not written yet: write rot_x" in stub["traceback"][0]
    for cell in nb.cells[3:]:
        (error,) = _errors(cell)
        assert error["ename"] == "NotImplementedError", error
        assert "not written yet: write" not in "".join(error["traceback"]), error["traceback"]
        assert len(error["traceback"]) > 1, error["traceback"]


def test_every_lesson_ends_with_its_hand_in_cell():
    for lesson in THIS_COURSE.catalog.graded_lessons:
        nb = nbformat.read(str(SOLUTIONS / lesson.filename), as_version=4)
        ids = [c.get("id") for c in nb.cells]
        assert "ready-to-hand-in" in ids, lesson.filename
        cell = nb.cells[ids.index("ready-to-hand-in")]
        assert f'ready_to_hand_in("{lesson.number}")' in cells.source_text(cell)
        assert cells.is_hand_in_cell(cell) and cell.metadata.get("editable") is False, lesson.filename
        assert lesson.hand_in_points == GradingOptions().notebook_points, (
            f"{lesson.filename}: the hand-in cell (the notebook point in nbgrader) is not worth the notebook point"
        )
        later = [c for c in nb.cells[ids.index("ready-to-hand-in") + 1 :] if c.cell_type == "code"]
        assert not later, f"{lesson.filename}: code after the hand-in cell"
