"""The exercises and their signatures match the contract in COURSE_SPEC.md."""

import ast
import re

import pytest

from autograder.lessons import cells
from autograder.lessons.notebook_files import read_master
from autograder.lessons.paths import PROJECT_ROOT, SOLUTIONS
from support import THIS_COURSE

SPEC = PROJECT_ROOT.parent / "shared" / "COURSE_SPEC.md"
SIGNATURE = re.compile(r"`([a-z_0-9]+)\(([^`]*)\)`")


def _normal(args):
    """Arguments in one canonical spelling: ``tol=1e-9`` and ``tol=1e-09`` agree."""
    return ast.unparse(ast.parse(f"def f({args}): pass").body[0].args)


def _spec_signatures():
    if not SPEC.exists():
        pytest.skip("../shared/COURSE_SPEC.md is not beside the project")
    text = SPEC.read_text(encoding="utf-8")
    signatures = {}
    for line in text.splitlines():
        match = re.match(r"^\| (\d\d) \|", line)
        if match:
            last_column = line.rstrip(" |").split(" | ")[-1]
            for name, args in SIGNATURE.findall(last_column):
                signatures[name] = (match.group(1), _normal(args))
    # "Exact meanings" may spell a signature out with its defaults: the more specific one wins
    for name, args in SIGNATURE.findall(text):
        if name in signatures and args.count("=") > signatures[name][1].count("="):
            try:
                signatures[name] = (signatures[name][0], _normal(args))
            except SyntaxError:
                pass
    return signatures


def _master_signatures():
    found = {}
    for path in sorted(SOLUTIONS.glob("[0-9][0-9]_*.ipynb")):
        for cell in read_master(path).cells:
            if cells.is_answer_cell(cell):
                tree = ast.parse(cells.source_text(cell))
                for node in tree.body:
                    if isinstance(node, ast.FunctionDef) and node.name == cells.grade_id(cell):
                        found[node.name] = (path.name[:2], _normal(ast.unparse(node.args)))
    return found


def test_signatures_match_the_spec():
    spec, masters = _spec_signatures(), _master_signatures()
    written = {name: spec[name] for name in spec if name in masters}
    assert written, "no lesson of the spec is written yet"
    for name, (lesson, args) in written.items():
        assert masters[name][0] == lesson, f"{name} belongs to lesson {lesson}"
        assert masters[name][1] == args, f"{name}({masters[name][1]}) differs from the spec's {name}({args})"


def test_every_lesson_written_has_all_its_spec_exercises():
    spec, masters = _spec_signatures(), _master_signatures()
    lessons_written = {lesson for lesson, _ in masters.values()}
    missing = [name for name, (lesson, _) in spec.items() if lesson in lessons_written and name not in masters]
    assert not missing, missing


def test_catalog_points_match_exercise_headings():
    catalog = THIS_COURSE.catalog
    for lesson in catalog.graded_lessons:
        text = "\n".join(
            cells.source_text(c) for c in read_master(SOLUTIONS / lesson.filename).cells if c.cell_type == "markdown"
        )
        for exercise in lesson.exercises:
            points = f"{exercise.points:g} point" + ("" if exercise.points == 1 else "s")
            pattern = rf"`{re.escape(exercise.name)}`[^\n]*\({re.escape(points)}"
            assert re.search(pattern, text), f"{lesson.filename}: no heading announcing {exercise.name} ({points})"
