"""A course that asks students to think (issue 42): what each exercise asks for, and no answer on the page.

Every answer cell of a master carries ``exercise`` metadata (``autograder/lessons/catalog.py``): its kind, its
estimated minutes and, for derive, design and diagnose exercises, the *giveaways*, the phrases in LaTeX and in
code that would hand its result away. Here:

- every exercise has a kind and minutes, and the thinking kinds have giveaways;
- each giveaway is real: it appears in the reader's edition or the reference solution (the master);
- none appears in what a student gets, course-wide (a later lesson may not restate an earlier lesson's result,
  it refers back to it or calls the student's function): every notebook in ``course/`` (markdown, code with the
  stubs' docstrings, outputs), every public check module and ``coursekit/hints.py`` (their whole text: hints
  ship with them), the prose of every other shipped ``coursekit`` module (docstrings, comments and string
  literals; a function body's code may compute a result that a later lesson uses, as ``coursekit.lie.Exp``
  computes lesson 03's with scipy, but never writes a thinking exercise's answer out: the large expressions of the
  reference answers are looked for, whatever their variables are called) and the strings of the
  hidden tests (their failure reasons and hints reach the student). Whitespace is ignored on both sides; the
  few matches that are the same symbols meaning something else are listed, with the reason, in
  :data:`UNRELATED`;
- ``docs/EXERCISES.md`` is what ``python -m autograder course-stats --catalog`` prints, and the README's
  course table gives each lesson's exercises by kind;
- the share of derive/design/diagnose points does not fall below a ratchet (:data:`RATCHET`), and the gap to
  the issue's targets is printed.
"""

import ast
import io
import re
import tokenize
from functools import lru_cache

import nbformat
import pytest

from autograder.lessons import cells
from autograder.lessons.catalog import THINKING_KINDS
from autograder.lessons.course_stats import (
    THINKING_TARGET,
    catalog_page,
    course_totals,
    kinds_summary,
    lesson_stats,
    target_gaps,
)
from autograder.lessons.notebook_files import read_master
from autograder.lessons.paths import COURSE, PROJECT_ROOT, SOLUTIONS
from support import THIS_COURSE

CATALOG = THIS_COURSE.catalog
THINKING = [e for e in CATALOG.exercises if e.kind in THINKING_KINDS]
CHECKS = SOLUTIONS / "coursekit" / "checks"
HINTS = SOLUTIONS / "coursekit" / "hints.py"
HIDDEN = PROJECT_ROOT / "autograder" / "hidden"

# (exercise, giveaway, where): a match that is the same symbols with another meaning, and why. Each entry must
# still match (test_unrelated_matches_are_still_there), so a stale one is noticed.
UNRELATED = {
    ("quat_from_two_vectors", "a × b", "course/03_exp_and_log.ipynb"): (
        "the bracket identity [a^, b^] = (a × b)^ of two rotation vectors, not the quaternion's axis"
    ),
    ("quat_from_two_vectors", "np.cross(a, b)", "course/03_exp_and_log.ipynb"): (
        "the same bracket identity, checked in code"
    ),
    ("quat_from_two_vectors", "a × b", "course/06_perturbations_and_jacobians.ipynb"): (
        "the second-order term ½ a×b of the BCH series, a and b two rotation vectors"
    ),
    ("quat_from_two_vectors", "a × b", "autograder/hidden/test_02_groups.py"): (
        "lesson 02's group axioms for the cross product (not associative, anticommutative)"
    ),
    ("quat_from_two_vectors", "a × b", "autograder/hidden/test_03_exp_and_log.py"): (
        "the bracket identity [a^, b^] = (a × b)^ in a test's description"
    ),
    ("exp_se3", "\\frac{1 - \\cos\\theta}{\\theta^2}\\,\\mathbf W", "course/03_exp_and_log.ipynb"): (
        "Rodrigues' formula, whose W² term begins with the same symbols (lesson 03 prints it to transcribe); "
        "exp_se3's V has the coefficient in front of W itself"
    ),
}

# Derive/design/diagnose points per lesson, and exercises in all, that the course may not fall below. Raise a
# figure when a lesson gains such an exercise; never lower one (issue 42's targets are printed by the test).
RATCHET = {"03": 5.0, "04": 9.0, "05": 7.0, "06": 12.0, "07": 13.0, "08": 6.0, "09": 26.0}
RATCHET_EXERCISES = 27


def _squeezed(text: str) -> str:
    """The text without whitespace and without LaTeX's spacing commands (``\\,``, ``\\;``, ``\\!``, ``\\ ``), so
    that ``-\\mathbf R\\,[\\mathbf p]_\\times`` is caught by the giveaway ``-\\mathbf R[\\mathbf p]_\\times``."""
    return re.sub(r"\s+", "", re.sub(r"\\[,;! ]", "", text))


def _notebook_text(nb: nbformat.NotebookNode) -> str:
    parts = []
    for cell in nb.cells:
        parts.append(cells.source_text(cell))
        for output in cell.get("outputs", []):
            text = output.get("text", "")
            parts.append("".join(text) if isinstance(text, list) else str(text))
            for value in output.get("data", {}).values():
                parts.append("".join(value) if isinstance(value, list) else str(value))
            parts.extend(str(line) for line in output.get("traceback", []))
    return "\n".join(parts)


def _lesson_filename(exercise):
    return CATALOG.lesson(exercise.lesson).filename


def _prose(source: str, *, shown_docstrings=None) -> str:
    """The words of a Python module that a reader meets as text: its string literals (docstrings, messages,
    hints) and comments, without the code. With ``shown_docstrings`` (a test of the hidden suite, whose
    module, helpers and comments the student never sees), only the docstrings of the functions it accepts by
    name are kept, their first line only (the feedback's description of the test), and no comments."""
    parts = []
    tree = ast.parse(source)
    skip = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and node.body:
            first = node.body[0]
            shown = shown_docstrings is None or (not isinstance(node, ast.Module) and shown_docstrings(node.name))
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) and not shown:
                skip.add(id(first.value))
    first_lines = {}  # the feedback shows the first line of a test's docstring only
    if shown_docstrings is not None:
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and ast.get_docstring(node):
                first_lines[id(node.body[0].value)] = ast.get_docstring(node).strip().splitlines()[0]
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in skip:
            parts.append(first_lines.get(id(node), node.value))
    if shown_docstrings is None:
        for token in tokenize.generate_tokens(io.StringIO(source).readline):
            if token.type == tokenize.COMMENT:
                parts.append(token.string)
    return "\n".join(parts)


@lru_cache(maxsize=1)
def _course_texts() -> dict[str, str]:
    """Everything a student of any lesson reads, squeezed, by where it is."""
    texts = {
        f"course/{path.name}": _notebook_text(read_master(path)) for path in sorted(COURSE.glob("[0-9][0-9]_*.ipynb"))
    }
    for path in sorted(CHECKS.glob("*.py")):
        texts[f"coursekit/checks/{path.name}"] = path.read_text(encoding="utf-8")
    texts["coursekit/hints.py"] = HINTS.read_text(encoding="utf-8")
    for path in sorted((COURSE / "coursekit").glob("*.py")):
        if path.name != "hints.py":
            texts[f"coursekit/{path.name}"] = _prose(path.read_text(encoding="utf-8"))
    for path in sorted(HIDDEN.glob("*.py")):
        texts[f"autograder/hidden/{path.name}"] = _prose(
            path.read_text(encoding="utf-8"), shown_docstrings=lambda name: name.startswith("test")
        )
    return {where: _squeezed(text) for where, text in texts.items()}


def _leaks(exercise) -> list[tuple[str, str]]:
    return [
        (giveaway, where)
        for where, text in _course_texts().items()
        for giveaway in exercise.giveaways
        if _squeezed(giveaway) in text
    ]


def _student_texts(exercise) -> dict[str, str]:
    """What a student of the exercise's lesson reads: the released notebook, the lesson's public checks (their
    hints, and everything else in the modules, ship to students) and the catalogue of hints."""
    texts = {f"course/{_lesson_filename(exercise)}": _notebook_text(read_master(COURSE / _lesson_filename(exercise)))}
    for path in sorted(CHECKS.glob(f"lesson{exercise.lesson}*.py")):
        texts[f"coursekit/checks/{path.name}"] = path.read_text(encoding="utf-8")
    texts["coursekit/hints.py"] = HINTS.read_text(encoding="utf-8")
    return texts


def test_every_exercise_has_a_kind_and_minutes():
    missing = [f"{e.lesson} {e.name}" for e in CATALOG.exercises if not e.kind or e.minutes <= 0]
    assert not missing, f"answer cells without 'exercise' metadata (kind and minutes): {missing}"


def test_thinking_exercises_name_their_giveaways():
    missing = [e.name for e in THINKING if not e.giveaways]
    assert not missing, f"derive/design/diagnose exercises without giveaways: {missing}"


@pytest.mark.parametrize("exercise", THINKING, ids=lambda e: e.name)
def test_giveaways_are_real(exercise):
    """Each giveaway is written somewhere in the master (the book's cells or the reference solution):
    a string that appears nowhere could never be caught on the student's page."""
    master = _squeezed(_notebook_text(read_master(SOLUTIONS / _lesson_filename(exercise))))
    invented = [g for g in exercise.giveaways if _squeezed(g) not in master]
    assert not invented, (
        f"{exercise.name}: giveaways found nowhere in the master {_lesson_filename(exercise)}: {invented}"
    )


@pytest.mark.parametrize("exercise", THINKING, ids=lambda e: e.name)
def test_the_answer_is_off_the_students_page(exercise):
    found = [
        f"{giveaway!r} in {where}"
        for where, text in _student_texts(exercise).items()
        for giveaway in exercise.giveaways
        if _squeezed(giveaway) in _squeezed(text)
    ]
    assert not found, (
        f"{exercise.name} ({exercise.kind}) gives its result away to students: {found}. Move it to a reader-only "
        "cell or after the check cell, or make the hint name the property that failed instead of the formula."
    )


@pytest.mark.parametrize("exercise", THINKING, ids=lambda e: e.name)
def test_the_answer_is_off_every_page_of_the_course(exercise):
    """No lesson, shipped module or hint gives the result away: a later lesson refers back to it ("the Jacobian
    you derived in lesson 06") or calls the student's function, and a hint names the property that failed."""
    found = [
        f"{giveaway!r} in {where}"
        for giveaway, where in _leaks(exercise)
        if (exercise.name, giveaway, where) not in UNRELATED
    ]
    assert not found, (
        f"{exercise.name} (lesson {exercise.lesson}, {exercise.kind}) is given away elsewhere in the course: "
        f"{found}. Refer back to the lesson (or call the student's function), move the statement into a "
        "reader-only cell, or make the hint name what failed and where."
    )


MIN_CODE_NODES = 25  # an expression this large is a formula, not a common idiom such as np.linalg.norm(a - b)


class _AnonymousNames(ast.NodeTransformer):
    def visit_Name(self, node):
        return ast.Name(id="_", ctx=ast.Load())


def _formulas(source: str) -> dict[str, str]:
    """The large expressions of ``source`` with every variable renamed alike: ``{shape: code}``."""
    import copy

    found = {}
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.expr) and sum(not isinstance(n, ast.expr_context) for n in ast.walk(node)) >= (
            MIN_CODE_NODES
        ):
            found.setdefault(ast.dump(_AnonymousNames().visit(copy.deepcopy(node))), ast.unparse(node))
    return found


def test_no_thinking_answer_is_written_out_in_shipped_code():
    """The code of every shipped ``coursekit`` module (what a curious student opens) holds no large expression of
    a derive, design or diagnose answer, whatever its variables are called: ``R(q)`` written out entry by entry
    in a simulator is lesson 04's ``quat_to_matrix``. Expressions that a transcribe or assemble answer also has
    are tools (``vee``'s three differences), not results."""
    from autograder.lessons.reference import answer_sources

    answers = answer_sources(SOLUTIONS)
    tools = {}
    for exercise in CATALOG.exercises:
        if exercise.kind not in THINKING_KINDS:
            tools.update(_formulas(answers[exercise.name]))
    shipped = {
        str(path.relative_to(COURSE)): _formulas(path.read_text(encoding="utf-8"))
        for path in sorted((COURSE / "coursekit").rglob("*.py"))
    }
    found = [
        f"{exercise.name}: {shipped[where][shape][:100]} in {where}"
        for exercise in THINKING
        for shape in _formulas(answers[exercise.name]).keys() - tools.keys()
        for where in shipped
        if shape in shipped[where]
    ]
    assert not found, "answers written out in shipped code (compute them another way, e.g. with scipy):\n" + (
        "\n".join(found)
    )


def test_unrelated_matches_are_still_there():
    by_name = {e.name: e for e in THINKING}
    stale = [key for key in UNRELATED if key[0] not in by_name or (key[1], key[2]) not in _leaks(by_name[key[0]])]
    assert not stale, f"UNRELATED lists matches that no longer occur; remove them: {stale}"


def test_released_notebooks_carry_no_giveaways_in_metadata():
    leaked = [
        f"{path.name}: {cells.grade_id(cell)}"
        for path in sorted(COURSE.glob("[0-9][0-9]_*.ipynb"))
        for cell in read_master(path).cells
        if "giveaways" in cell.get("metadata", {}).get("exercise", {})
    ]
    assert not leaked, leaked


def test_the_exercise_catalog_is_current():
    path = PROJECT_ROOT / "docs" / "EXERCISES.md"
    assert path.exists() and path.read_text(encoding="utf-8") == catalog_page(CATALOG), (
        "docs/EXERCISES.md is stale: python -m autograder course-stats --catalog > docs/EXERCISES.md"
    )


def test_the_readme_course_table_gives_the_kinds():
    readme = (PROJECT_ROOT / "README.md").read_text(encoding="utf-8")
    wrong = []
    for lesson in CATALOG.graded_lessons:
        row = next((line for line in readme.splitlines() if line.startswith(f"| {lesson.number} |")), "")
        if kinds_summary(lesson) not in row:
            wrong.append(f"lesson {lesson.number}: the row should say {kinds_summary(lesson)!r}")
    assert not wrong, wrong


def test_thinking_points_do_not_fall_below_the_ratchet():
    fallen = []
    for number, floor in RATCHET.items():
        stats = lesson_stats(CATALOG.lesson(number))
        if stats.thinking_points < floor:
            fallen.append(
                f"lesson {number}: {stats.thinking_points:g} derive/design/diagnose points, ratchet {floor:g}"
            )
    total = course_totals(CATALOG).thinking_count
    if total < RATCHET_EXERCISES:
        fallen.append(f"{total} derive/design/diagnose exercises in all, ratchet {RATCHET_EXERCISES}")
    gaps = target_gaps(CATALOG)
    print(f"issue 42's targets (≥ 1/3 of the points from lesson 03 on, ≥ {THINKING_TARGET} exercises):")
    print("\n".join(f"  {gap}" for gap in gaps) or "  all met")
    assert not fallen, fallen


def test_course_stats_prints_the_table_and_the_catalog(capsys):
    from autograder.cli import main

    assert main(["course-stats"]) == 0
    table = capsys.readouterr().out
    assert "derive+design+diagnose" in table and "Targets (issue 42)" in table
    assert main(["course-stats", "--catalog"]) == 0
    assert capsys.readouterr().out == catalog_page(CATALOG)
