"""The notebook stage runs each lesson's master without the cells that only run public checks (their claims are the
hidden suite's, graded before nbval runs) and keeps every other cell, each answer cell bound to the student."""

from autograder.grading.nbval_stage import merged_notebook
from autograder.lessons import cells
from autograder.lessons.notebook_files import read_master
from autograder.lessons.paths import SOLUTIONS


def test_check_cells_are_left_out_and_every_other_cell_kept():
    for path in sorted(SOLUTIONS.glob("0[1-9]_*.ipynb")):
        master = read_master(path)
        lesson = path.name[:2]
        before = [c.source for c in master.cells]
        merged = merged_notebook(read_master(path), lesson)
        after = [c.source for c in merged.cells]
        dropped = len(before) - len(after)
        checks = sum(s.strip().startswith(("check(", "from coursekit import ready_to_hand_in")) for s in before)
        assert dropped == checks > 0, (path.name, dropped, checks)
        assert not any(s.strip().startswith("check(") for s in after), path.name
        answers = [c for c in master.cells if cells.is_answer_cell(c)]
        assert sum("student_function(" in s for s in after) == len(answers), path.name
