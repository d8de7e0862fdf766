"""course/ is generated from solutions/, in sync, and gives nothing away."""

import ast
import shutil
from pathlib import Path

from autograder.authoring.release import stale_files
from autograder.lessons import cells
from autograder.lessons.notebook_files import read_master
from autograder.lessons.paths import COURSE, HIDDEN_SUITE, SOLUTIONS
from support import THIS_COURSE


def _course_line_pairs(folder=COURSE):
    """Consecutive pairs of stripped code lines in every file under ``folder`` (notebook cells split)."""
    pairs = set()
    for path in sorted(Path(folder).rglob("*")):
        if not path.is_file() or "__pycache__" in path.parts:
            continue
        if path.suffix == ".ipynb":
            chunks = [cells.source_text(c) for c in read_master(path).cells]
        elif path.suffix == ".py":
            chunks = [path.read_text(encoding="utf-8")]
        else:
            continue
        for chunk in chunks:
            lines = [line.strip() for line in chunk.splitlines() if line.strip()]
            pairs.update(zip(lines, lines[1:]))
    return pairs


def _distinctive(line):
    """Long enough to be someone's solution rather than a common idiom (``for j in range(3):``)."""
    return len(line) >= 20 and not line.startswith(("#", "import ", "from ", '"""', "return None"))


def _blocks(text, only_between_markers=False):
    """Runs of consecutive distinctive lines (stripped) of ``text``."""
    blocks, current, inside = [], [], not only_between_markers
    for raw in text.splitlines():
        line = raw.strip()
        if cells.BEGIN_SOLUTION in line:
            inside, current = True, []
            continue
        if cells.END_SOLUTION in line:
            inside = False
            blocks.append(current)
            current = []
            continue
        if inside and line:
            current.append(line)
    blocks.append(current)
    return blocks


def _leaks(blocks, pairs, run=2, public=frozenset()):
    """Runs of ``run`` consecutive distinctive lines of ``blocks`` that also stand together in course/.

    Runs whose pairs all occur in ``public`` (code students get anyway) are not leaks.
    """
    found = []
    for block in blocks:
        for start in range(len(block) - run + 1):
            lines = block[start : start + run]
            steps = list(zip(lines, lines[1:]))
            if (
                all(_distinctive(line) for line in lines)
                and all(step in pairs for step in steps)
                and not all(step in public for step in steps)
            ):
                found.append(" / ".join(lines))
    return found


def test_course_is_in_sync_with_solutions():
    assert stale_files(THIS_COURSE.solutions, THIS_COURSE.released) == [], "run: python -m autograder release"


def test_no_solution_code_in_course():
    pairs = _course_line_pairs()
    found = []
    for master in sorted(SOLUTIONS.glob("[0-9][0-9]_*.ipynb")):
        for cell in read_master(master).cells:
            if cells.is_answer_cell(cell):
                for leak in _leaks(_blocks(cells.source_text(cell), only_between_markers=True), pairs):
                    found.append(f"{master.name} {cells.grade_id(cell)}: {leak}")
    assert not found, "solution lines in course/:\n" + "\n".join(found)


def test_no_hidden_test_code_in_course():
    """No run of three distinctive lines of a hidden test appears in course/ (beyond public coursekit code)."""
    pairs, public = _course_line_pairs(), _course_line_pairs(COURSE / "coursekit")
    found = [
        f"{path.name}: {leak}"
        for path in sorted(HIDDEN_SUITE.glob("test_*.py"))
        for leak in _leaks(_blocks(path.read_text(encoding="utf-8")), pairs, run=3, public=public)
    ]
    assert not found, "hidden test lines in course/:\n" + "\n".join(found)


def test_the_leak_detector_finds_a_leak():
    solution = "    c, s = np.cos(theta), np.sin(theta)\n    return np.array([[c, -s], [s, c]])"
    pairs = {("c, s = np.cos(theta), np.sin(theta)", "return np.array([[c, -s], [s, c]])")}
    assert _leaks(_blocks(solution), pairs)
    assert not _leaks(_blocks(solution), pairs, public=frozenset(pairs))


def test_released_answers_are_stubs_and_checks_are_locked():
    for path in sorted(COURSE.glob("[0-9][0-9]_*.ipynb")):
        nb = read_master(path)
        for cell in nb.cells:
            if cell.cell_type == "code":
                assert cell.outputs == [] and cell.execution_count is None, f"{path.name}: outputs left"
            if cells.is_answer_cell(cell):
                source = cells.source_text(cell)
                assert "raise NotImplementedError" in source and cells.BEGIN_SOLUTION not in source, path.name
                function = [n for n in ast.parse(source).body if isinstance(n, ast.FunctionDef)]
                assert function and ast.get_docstring(function[0]), f"{path.name}: stub lost its docstring"
            if cells.is_check_cell(cell):
                assert cell.metadata.get("editable") is False and cell.metadata.get("deletable") is False
                assert cell.metadata["nbgrader"]["points"] > 0 and "checksum" in cell.metadata["nbgrader"]


def test_release_check_notices_an_edited_master(tmp_path):
    solutions, course = tmp_path / "solutions", tmp_path / "course"
    shutil.copytree(SOLUTIONS, solutions, ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copytree(COURSE, course, ignore=shutil.ignore_patterns("__pycache__"))
    assert stale_files(solutions, course) == []
    master = sorted(solutions.glob("01_*.ipynb"))[0]
    master.write_text(master.read_text(encoding="utf-8").replace("Lesson 01", "Lesson 1", 1), encoding="utf-8")
    (course / "stray.ipynb").write_text("{}", encoding="utf-8")
    reasons = dict(stale_files(solutions, course))
    assert any("differs" in r for r in reasons.values()), reasons
    assert str(course / "stray.ipynb") in reasons


def test_release_command_exits_nonzero_when_stale(tmp_path, monkeypatch):
    import autograder.authoring.release as release_module
    from autograder.cli import main

    monkeypatch.setattr(release_module, "stale_files", lambda *a, **k: [("course/x.ipynb", "missing")])
    assert main(["release", "--check"]) == 1
