"""A small class of students to grade when no submissions are given.

``python -m autograder grade --out DIR`` with no PATH writes these
submissions to ``DIR/sample_class/`` and grades them, so an instructor can see
the whole pipeline — and its gradebook and feedback pages — in one command.

Each student starts from the released notebooks in ``course/`` (exactly what
a real student downloads) and fills in answers: the reference answer, the
untouched stub, or one of the typical mistakes of :mod:`autograder.mistakes`.
Two students cheat, one crashes and hangs, one hands in a damaged notebook,
and one has an id that a spreadsheet would evaluate as a formula. Two share
answers (the same correct alternative, one with its variables renamed), so
the class report's "Similar answers" shows what a finding looks like.
"""

from __future__ import annotations

import ast
import io
import json
import shutil
import tokenize
from dataclasses import dataclass
from pathlib import Path

import nbformat

from autograder.lessons import cells
from autograder.lessons.catalog import Lesson
from autograder.lessons.course import Course
from autograder.lessons.notebook_files import canonical_text, read_master
from autograder.lessons.reference import answer_sources
from autograder.mistakes import all_alternatives, all_mistakes, sample_assignments

# A numpy monkeypatch that gives full marks in a grader that compares inside the student's kernel.
MONKEYPATCH = """import numpy as np
np.allclose = lambda *args, **kwargs: True
np.testing.assert_allclose = lambda *args, **kwargs: None
np.isclose = lambda a, b, *args, **kwargs: np.ones(np.shape(a), dtype=bool)
np.array_equal = lambda *args, **kwargs: True
"""
WRONG_ANSWER = "    return None\n"
SHARED = ("quat_slerp_power", "matrix_to_euler_undo_yaw")  # what two sample students share


@dataclass(frozen=True)
class SampleStudent:
    student_id: str
    story: str
    answers: str = "reference"  # "reference", "stub", "first_half" or "wrong"
    cheat: str = ""  # "", "monkeypatch" or "edit_checks"
    damage: str = ""  # "": none; "corrupt_first": the first lesson's notebook is not valid JSON
    shared: tuple = ()  # correct alternatives (names in autograder.mistakes) this student hands in
    renamed: bool = False  # ... with every argument and local variable renamed (a disguised copy)


STUDENTS = [
    SampleStudent("ada", "every answer right: full marks"),
    SampleStudent("ben", "hands in the untouched release: zero", answers="stub"),
    SampleStudent("chloe", "did the first half of each lesson", answers="first_half"),
    SampleStudent("dev", "transposes matrices (passive/active mix-up)"),
    SampleStudent("emma", "works in degrees"),
    SampleStudent("farid", "lets reflections through"),
    SampleStudent(
        "gina",
        "wrong answers, then monkeypatches numpy so every comparison passes",
        answers="wrong",
        cheat="monkeypatch",
    ),
    SampleStudent(
        "hugo", "wrong answers, and rewrote the check cells to print success", answers="wrong", cheat="edit_checks"
    ),
    SampleStudent(
        "ivy", "right answers, except one endless loop, one os._exit and one infinite recursion", shared=SHARED
    ),
    SampleStudent(
        "kim",
        "right answers, but the first notebook was damaged by a text editor; shares two "
        "answers with ivy, variables renamed (see 'Similar answers')",
        damage="corrupt_first",
        shared=SHARED,
        renamed=True,
    ),
    SampleStudent('=HYPERLINK("evil","click me")', "an id a spreadsheet would run as a formula"),
]


def _wrong(source):
    """Keep the signature and docstring of a stub, return None instead of raising."""
    lines = source.splitlines()
    kept = [line for line in lines if "NotImplementedError" not in line and "Your code here" not in line]
    return "\n".join(kept).rstrip() + "\n" + WRONG_ANSWER


def rename_locals(source: str, prefix: str = "my_") -> str:
    """``source`` (one function) with each local variable renamed ``prefix + name``: the simplest disguise
    of a copy. The signature stays as released (callers may pass arguments by name); attributes,
    keywords and the function's own name are left alone."""
    function = ast.parse(source).body[0]
    arguments = {a.arg for a in ast.walk(function.args) if isinstance(a, ast.arg)}
    names = {n.id for n in ast.walk(function) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)}
    names -= arguments | {function.name}
    out, previous = [], None
    for token in tokenize.generate_tokens(io.StringIO(source).readline):
        text = (
            prefix + token.string
            if token.type == tokenize.NAME and token.string in names and previous != "."
            else token.string
        )
        out.append((token.type, text))
        previous = token.string
    return tokenize.untokenize(out)


def _answer_for(student, exercise_name, index, count, stub, references, mistakes, chosen):
    for name in student.shared:
        alternative = all_alternatives()[name]
        if alternative.exercise == exercise_name:
            source = alternative.source.strip("\n") + "\n"
            return rename_locals(source) if student.renamed else source
    for name in chosen:
        if mistakes[name].exercise == exercise_name:
            return mistakes[name].source.strip("\n")
    if student.answers == "stub" or (student.answers == "first_half" and index >= (count + 1) // 2):
        return stub
    if student.answers == "wrong":
        return _wrong(stub)
    return references[exercise_name]


def student_notebook(
    student: SampleStudent,
    lesson: Lesson,
    references: dict[str, str],
    mistakes: dict,
    chosen: list[str],
    released: Path,
) -> nbformat.NotebookNode:
    """The notebook ``student`` hands in for ``lesson`` (a NotebookNode), from the released one in ``released``."""
    nb = read_master(released / lesson.filename)
    names = [e.name for e in lesson.exercises]
    patched = False
    for cell in nb.cells:
        if cells.is_answer_cell(cell):
            name = cells.grade_id(cell)
            cell.source = _answer_for(
                student, name, names.index(name), len(names), cells.source_text(cell), references, mistakes, chosen
            )
            if student.cheat == "monkeypatch" and not patched:
                cell.source = MONKEYPATCH + "\n\n" + cell.source
                patched = True
        elif cells.is_check_cell(cell) and student.cheat == "edit_checks":
            name = cells.grade_id(cell)[len(cells.CHECK_PREFIX) :]
            cell.source = f'print("{name}: all public checks passed.")'
    return nb


def build_sample_class(target: str | Path, course: Course, lessons: tuple[str, ...] = ()) -> list[str]:
    """Write every sample student's notebooks to ``target/<student_id>/``; return the ids.

    ``course``: this repository's course (the mistakes corpus, :mod:`autograder.mistakes`, is written for it).

    ``lessons``: only these lesson numbers (default: every graded lesson).
    """
    target = Path(target)
    if target.exists():
        shutil.rmtree(target)
    catalog = course.catalog
    references = answer_sources(course.solutions)
    mistakes = all_mistakes()
    assignments = sample_assignments()
    unknown = sorted(set(assignments) - {s.student_id for s in STUDENTS})
    if unknown:
        raise ValueError(f"mistakes assigned to students who are not in the sample class: {unknown}")
    for student in STUDENTS:
        folder = target / student.student_id
        folder.mkdir(parents=True)
        chosen = assignments.get(student.student_id, [])
        chosen_lessons = [lesson for lesson in catalog.graded_lessons if not lessons or lesson.number in lessons]
        for number, lesson in enumerate(chosen_lessons):
            text = canonical_text(student_notebook(student, lesson, references, mistakes, chosen, course.released))
            if student.damage == "corrupt_first" and number == 0:
                text = text[: len(text) // 2]  # cut in the middle: no longer valid JSON
            (folder / lesson.filename).write_text(text, encoding="utf-8")
        for extra in sorted(course.released.glob("00_*.ipynb")):
            shutil.copy2(extra, folder / extra.name)
    (target / "README.json").write_text(
        json.dumps({s.student_id: s.story for s in STUDENTS}, indent=1, ensure_ascii=False) + "\n", encoding="utf-8"
    )
    return [s.student_id for s in STUDENTS]
