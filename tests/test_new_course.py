"""``write_course`` (``python -m autograder new-course DIR``) writes a small course the grader can read.

Oracles: the course-folder layout of docs/AUTHORING.md ("Write your own course") as
:meth:`autograder.lessons.course.Course.at` reads it; the master conventions as
:func:`~autograder.lessons.catalog.load_catalog` enforces them; this repository's
``solutions/coursekit``, byte for byte, for the generic modules; the written
course's own public checks and hidden tests, run in a child Python (this process
already imports this repository's coursekit): the reference passes every one of
them and the stubs none. No grading, no sandbox; the recording test starts one
kernel per lesson (a few seconds).
"""

import ast
import json
import os
import subprocess
import sys
import textwrap

import pytest

from autograder.authoring.new_course import GENERIC_MODULES, TEMPLATE_SUFFIX, write_course
from autograder.lessons import cells
from autograder.lessons.catalog import load_catalog
from autograder.lessons.course import LAYOUT_FILE, Course
from autograder.lessons.notebook_files import read_master
from autograder.lessons.paths import PROJECT_ROOT, this_course
from autograder.lessons.reference import answer_sources

SUPPORT = this_course().support  # what `new-course` copies the generic modules from
LESSONS = {"01": ("rot2", "rotate2"), "02": ("angle_of", "angle_difference")}


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    return write_course(tmp_path_factory.mktemp("new") / "plane", SUPPORT, record=False)


def _child_env():
    """A child Python that finds the grader but not this repository's coursekit."""
    env = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    env["PYTHONPATH"] = str(PROJECT_ROOT)
    return env


def test_the_folder_has_the_course_layout(course):
    files = sorted(p.relative_to(course).as_posix() for p in course.rglob("*") if p.is_file())
    assert LAYOUT_FILE in files and not (course / "course").exists()  # course/ is written by release
    assert {
        "solutions/00_start_here.ipynb",
        "solutions/01_rotation_matrices.ipynb",
        "solutions/02_reading_angles.ipynb",
    } <= set(files)
    assert {"hidden/test_01_rotation_matrices.py", "hidden/test_02_reading_angles.py"} == {
        f for f in files if f.startswith("hidden/")
    }
    for name in ("__init__.py", "contracts.py", "checks/lesson01.py", "checks/lesson02.py", *GENERIC_MODULES):
        assert f"solutions/coursekit/{name}" in files, name
    assert not [f for f in files if f.endswith(TEMPLATE_SUFFIX) or "__pycache__" in f], files
    found = Course.at(course)
    assert (found.title, found.solutions, found.hidden_suite) == (
        "Turning the plane",
        course / "solutions",
        course / "hidden",
    )


def test_the_masters_follow_the_conventions(course):
    catalog = load_catalog(course / "solutions")
    assert {lesson.number: tuple(e.name for e in lesson.exercises) for lesson in catalog.graded_lessons} == LESSONS
    assert all(exercise.points > 0 for exercise in catalog.exercises)
    for lesson in catalog.graded_lessons:
        nb = read_master(course / "solutions" / lesson.filename)
        assert cells.source_text(nb.cells[0]).startswith(f"# Lesson {lesson.number} — {lesson.title}\n")
        assert lesson.setup_source == "import numpy as np\nfrom coursekit import check, show"
        assert lesson.hand_in_points == 1
        code = [cell for cell in nb.cells if cell.cell_type == "code"]
        assert cells.is_hand_in_cell(code[-1]), f"{lesson.filename}: the hand-in cell is not the last code cell"
        for cell in nb.cells:
            if cells.is_answer_cell(cell):
                function = ast.parse(cells.source_text(cell)).body[0]
                docstring = ast.get_docstring(function)
                assert function.name == cells.grade_id(cell) and "Parameters" in docstring and "Returns" in docstring
        headings = [cells.source_text(c) for c in nb.cells if cells.source_text(c).startswith("### Exercise")]
        assert [h.splitlines()[0] for h in headings] == [
            f"### Exercise {k}: `{e.name}` ({e.points:g} points)" for k, e in enumerate(lesson.exercises, 1)
        ]


def test_the_generic_modules_are_this_repositorys_byte_for_byte(course):
    for name in GENERIC_MODULES:
        assert (course / "solutions" / "coursekit" / name).read_bytes() == (SUPPORT / name).read_bytes(), name


def test_the_hidden_tests_import_only_the_hidden_api_numpy_and_coursekit(course):
    for path in sorted((course / "hidden").glob("test_*.py")):
        imported = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                imported.update(alias.name for alias in node.names)
            elif isinstance(node, ast.ImportFrom):
                imported.add(node.module)
        assert imported <= {"numpy", "autograder.grading.hidden_api", "coursekit", "coursekit.diagnose"}, (
            path.name,
            imported,
        )


def test_a_folder_with_files_is_refused(tmp_path):
    (tmp_path / "notes.txt").write_text("mine", encoding="utf-8")
    with pytest.raises(ValueError, match="not empty"):
        write_course(tmp_path, SUPPORT, record=False)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes.txt"]
    with pytest.raises(ValueError, match="is a file"):
        write_course(tmp_path / "notes.txt", SUPPORT, record=False)
    with pytest.raises(ValueError, match="support package"):
        write_course(tmp_path / "new", tmp_path, record=False)
    (tmp_path / "empty").mkdir()
    write_course(tmp_path / "empty", SUPPORT, record=False)  # an empty folder is fine
    assert (tmp_path / "empty" / LAYOUT_FILE).is_file()


def test_the_written_course_passes_ruff(course):
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "ruff",
            "check",
            "--no-cache",
            "--config",
            str(PROJECT_ROOT / "pyproject.toml"),
            str(course),
        ],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stdout + run.stderr


PUBLIC_CHECKS = textwrap.dedent("""
    import json, sys
    import numpy as np
    from coursekit.checking import checks_of_lesson, run_quietly

    answers = json.load(sys.stdin)
    stub = "def {0}(*args):\\n    raise NotImplementedError('this exercise is not written yet')"
    report = {"lessons": {n: checks_of_lesson(n) for n in ("01", "02")}, "reference": {}, "stub": {}}
    for name, source in answers.items():
        for kind, text in (("reference", source), ("stub", stub.format(name))):
            namespace = {"np": np}
            exec(text, namespace)
            report[kind][name] = run_quietly(name, namespace[name])
    print(json.dumps(report))
""")


def test_the_public_checks_pass_for_the_reference_and_fail_for_the_stubs(course):
    run = subprocess.run(
        [sys.executable, "-c", PUBLIC_CHECKS],
        input=json.dumps(answer_sources(course / "solutions")),
        cwd=course / "solutions",
        env=_child_env(),
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stderr
    report = json.loads(run.stdout)
    assert {n: tuple(names) for n, names in report["lessons"].items()} == LESSONS
    for name, (passed, total, problem) in report["reference"].items():
        assert total >= 2 and passed == total and not problem, (name, problem)
    for name, (passed, total, problem) in report["stub"].items():
        assert passed == 0 and problem == "not written yet", (name, problem)


HIDDEN_FIXTURES = textwrap.dedent("""
    import os
    import sys

    import pytest

    sys.modules.setdefault("rfc3987_syntax", None)  # as autograder/cli.py: nbformat's jsonschema builds it slowly
    sys.path.insert(0, os.environ["COURSE_SOLUTIONS"])
    from pathlib import Path
    from types import SimpleNamespace

    from autograder.lessons.reference import load_reference

    def _stub(*args):
        raise NotImplementedError("this exercise is not written yet")


    STUB = SimpleNamespace(**{name: _stub for name in ("rot2", "rotate2", "angle_of", "angle_difference")})


    def pytest_configure(config):
        config.addinivalue_line("markers", "exercise(name, weight): the exercise a hidden test grades")


    @pytest.fixture
    def ref():
        return load_reference(Path(os.environ["COURSE_SOLUTIONS"]))


    @pytest.fixture
    def student(ref):
        return STUB if os.environ["STUDENT"] == "stub" else ref
""")


@pytest.mark.parametrize("student", ["reference", "stub"])
def test_the_hidden_tests_pass_for_the_reference_and_fail_for_the_stubs(course, tmp_path, student):
    """Plain pytest with ``student`` and ``ref`` given by a plugin outside the course, as the grader gives them."""
    (tmp_path / "course_fixtures.py").write_text(HIDDEN_FIXTURES, encoding="utf-8")
    env = _child_env() | {
        "COURSE_SOLUTIONS": str(course / "solutions"),
        "STUDENT": student,
        "PYTEST_DISABLE_PLUGIN_AUTOLOAD": "1",
        "PYTHONPATH": f"{tmp_path}{os.pathsep}{PROJECT_ROOT}",
    }
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            "-q",
            "-p",
            "no:cacheprovider",
            "-p",
            "course_fixtures",
            "--noconftest",
            "-c",
            os.devnull,
            "--rootdir",
            str(course / "hidden"),
            "-o",
            "addopts=",
            str(course / "hidden"),
        ],
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )
    summary = run.stdout.strip().splitlines()[-1]
    assert summary.startswith("9 passed" if student == "reference" else "9 failed"), run.stdout[-3000:]


def test_the_masters_run_top_to_bottom_and_record_their_demonstrations(tmp_path):
    course = write_course(tmp_path / "plane", SUPPORT)  # record_outputs raises if a cell raises
    for filename in ("01_rotation_matrices.ipynb", "02_reading_angles.ipynb"):
        shown = [
            cell.outputs for cell in read_master(course / "solutions" / filename).cells if cells.checks_output(cell)
        ]
        assert shown and all(shown), f"{filename}: a demonstration cell has no recorded output"
