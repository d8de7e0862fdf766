"""Works with what instructors already run: stock nbgrader and Gradescope."""

import csv
import json
import os
import subprocess
import sys
import warnings
from pathlib import Path

import pytest

from autograder.integrations.gradescope import build_bundle, unpack_bundle
from autograder.integrations.nbgrader_course import (
    assignment_name,
    build_course,
    run_nbgrader,
    submit,
    with_environment_tools,
)
from autograder.lessons import cells
from autograder.lessons.notebook_files import canonical_text, read_master
from autograder.lessons.paths import COURSE, PROJECT_ROOT
from autograder.lessons.reference import answer_sources
from autograder.sandbox import launcher
from support import STUB, build_submission
from support import THIS_COURSE

LESSONS = THIS_COURSE.catalog.graded_lessons


def _gradebook(root):
    from nbgrader.api import Gradebook

    os.environ.update(with_environment_tools())
    warnings.simplefilter("ignore")
    return Gradebook(f"sqlite:///{root / 'gradebook.db'}")


@pytest.fixture(scope="module")
def nbgrader_course(tmp_path_factory):
    """Every lesson as an nbgrader assignment, generated and autograded by stock nbgrader.

    nbgrader reads an assignment id as a glob, so one ``generate_assignment "*"`` and one
    ``autograde "*"`` do every lesson (one start-up of nbgrader each instead of one per lesson).
    """
    root = build_course(tmp_path_factory.mktemp("nbgrader") / "course", THIS_COURSE.solutions)
    references = answer_sources(THIS_COURSE.solutions)
    run_nbgrader(root, "generate_assignment", "*", "--force")
    for lesson in LESSONS:
        released = root / "release" / assignment_name(lesson) / lesson.filename
        submit(root, "untouched", lesson, released)
        nb = read_master(released)
        for cell in nb.cells:
            if cells.is_answer_cell(cell):
                cell.source = references[cells.grade_id(cell)]
        filled = root / f"filled_{lesson.filename}"
        filled.write_text(canonical_text(nb), encoding="utf-8")
        submit(root, "reference", lesson, filled)
    run_nbgrader(root, "autograde", "*", "--force")
    return root


@pytest.mark.parametrize("lesson", LESSONS, ids=lambda lesson: f"lesson{lesson.number}")
def test_stock_nbgrader_release_matches_ours(nbgrader_course, lesson):
    theirs = read_master(nbgrader_course / "release" / assignment_name(lesson) / lesson.filename)
    ours = read_master(COURSE / lesson.filename)
    assert [cells.source_text(c) for c in theirs.cells] == [cells.source_text(c) for c in ours.cells]
    assert [c.metadata.get("nbgrader") for c in theirs.cells] == [c.metadata.get("nbgrader") for c in ours.cells]


@pytest.mark.parametrize("lesson", LESSONS, ids=lambda lesson: f"lesson{lesson.number}")
def test_stock_nbgrader_grades_reference_full_and_release_zero(nbgrader_course, lesson):
    with _gradebook(nbgrader_course) as gradebook:
        reference = gradebook.find_submission(assignment_name(lesson), "reference")
        untouched = gradebook.find_submission(assignment_name(lesson), "untouched")
        assert reference.max_score == lesson.points + lesson.hand_in_points > lesson.points
        assert reference.score == reference.max_score
        assert untouched.score == 0


def _grade_into(course_root, *extra, nbval=False):
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "autograder",
            "grade",
            str(course_root),
            "--out",
            str(course_root.parent / "out"),
            *([] if nbval else ["--no-nbval"]),
            "--nbgrader-db",
            str(course_root / "gradebook.db"),
            *extra,
        ],
        cwd=PROJECT_ROOT,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert run.returncode == 0, run.stdout[-1500:] + run.stderr[-2000:]
    with open(course_root.parent / "out" / "grades.csv", newline="", encoding="utf-8") as handle:
        return {row["student_id"]: float(row["score"]) for row in csv.DictReader(handle)}


def _scores(root, lesson):
    with _gradebook(root) as gradebook:
        return {s.student.id: s.score for s in gradebook.assignment_submissions(assignment_name(lesson))}


CHEAT = "check = lambda *args, **kwargs: None  # every later check cell passes in nbgrader's kernel\n"


def test_nbgrader_db_lives_alongside_stock_nbgrader(tmp_path):
    """Our export and stock nbgrader share one gradebook: only lessons handed in get submissions,
    generate_assignment still works afterwards, the notebook point lands in the hand-in cell, and
    whichever of autograde and our export ran last owns the automatic scores (the rule in
    autograder/integrations/nbgrader_export.py)."""
    first, second = LESSONS[0], LESSONS[1]
    root = build_course(tmp_path / "course", THIS_COURSE.solutions, lessons=(first.number, second.number))
    run_nbgrader(root, "generate_assignment", assignment_name(first), "--force")
    released = root / "release" / assignment_name(first) / first.filename
    answers = {"ada": "reference", "ben": STUB, "gina": "reference"}
    for student, default in answers.items():
        folder = build_submission(tmp_path / "work" / student, default=default, lessons=(first.number,))
        notebook = folder / first.filename
        if student == "gina":  # wrong answers, and the kernel's check function replaced by one that passes
            nb = read_master(released)
            for cell in nb.cells:
                if cells.is_answer_cell(cell):
                    cell.source = (
                        CHEAT if cells.grade_id(cell) == first.exercises[0].name else ""
                    ) + cells.source_text(cell).replace("raise NotImplementedError", "return None  #")
            notebook.write_text(canonical_text(nb), encoding="utf-8")
        submit(root, student, first, notebook)

    ours = _grade_into(root, nbval=True)
    assert ours == {"ada": first.points + first.hand_in_points, "ben": 0.0, "gina": 0.0}
    assert _scores(root, first) == ours
    with _gradebook(root) as gradebook:
        point = gradebook.find_grade(
            cells.HAND_IN_GRADE_ID, first.filename[: -len(".ipynb")], assignment_name(first), "ada"
        )
        assert point.auto_score == point.max_score == first.hand_in_points == 1.0
    assert _scores(root, second) == {}, "a lesson nobody handed in got submissions"

    run_nbgrader(root, "generate_assignment", assignment_name(second))  # never generated before: works
    run_nbgrader(root, "generate_assignment", assignment_name(first), "--force")  # regenerated: works

    run_nbgrader(root, "autograde", assignment_name(first), "--force")
    theirs = _scores(root, first)
    assert theirs["ada"] == first.points + first.hand_in_points
    assert theirs["gina"] == first.points  # the cheat fooled the check cells, not the hand-in cell
    again = _grade_into(root, nbval=True)  # unchanged students are reused; the export runs again
    assert _scores(root, first) == again == ours


@pytest.fixture(scope="module")
def gradescope_root(tmp_path_factory):
    base = tmp_path_factory.mktemp("gradescope")
    bundle = build_bundle(base / "autograder.zip", THIS_COURSE, lessons=(LESSONS[0].number,))
    root = base / "autograder"
    source = unpack_bundle(bundle, root)
    for name in ("setup.sh", "run_autograder"):
        assert os.access(source / name, os.X_OK), f"{name} is not executable in the bundle"
    return root


NAMESPACES = launcher.isolation()[0] == "namespaces"


def _run_gradescope(root, folder, sandbox=None):
    submission = root / "submission"
    if submission.exists():
        subprocess.run(["rm", "-rf", str(submission), str(root / "results")], check=True)
    subprocess.run(["cp", "-r", str(folder), str(submission)], check=True)
    env = dict(os.environ, AUTOGRADER_ROOT=str(root), AUTOGRADER_PYTHON=sys.executable)
    env.pop("AUTOGRADER_SANDBOX", None)
    if sandbox:
        env["AUTOGRADER_SANDBOX"] = sandbox
    run = subprocess.run(
        [str(root / "source" / "run_autograder")], env=env, capture_output=True, text=True, timeout=600
    )
    assert run.returncode == 0, run.stderr[-2000:]
    return json.loads((root / "results" / "results.json").read_text(encoding="utf-8"))


def _check_schema(data):
    assert {"score", "output", "tests"} <= set(data)
    for test in data["tests"]:
        assert {"name", "score", "max_score", "status", "output", "visibility"} <= set(test)
        assert test["visibility"] == "after_due_date" and test["status"] in ("passed", "failed")


@pytest.mark.parametrize("sandbox", [None, "limits"])
def test_gradescope_reference_full_marks(gradescope_root, tmp_path, sandbox):
    """Full marks, notebook point included, in either isolation mode (Gradescope's containers often
    forbid namespaces); limits mode says so in the output students and staff see."""
    lesson = LESSONS[0]
    data = _run_gradescope(gradescope_root, build_submission(tmp_path / "s", lessons=(lesson.number,)), sandbox)
    _check_schema(data)
    assert data["score"] == sum(t["max_score"] for t in data["tests"]) == lesson.points + 1
    assert all(t["status"] == "passed" for t in data["tests"])
    assert ("resource limits only" in data["output"]) == (sandbox == "limits" or not NAMESPACES)


def test_gradescope_setup_runs_the_canary(gradescope_root):
    setup = (gradescope_root / "source" / "setup.sh").read_text(encoding="utf-8")
    assert setup.rstrip().endswith('-m autograder canary --course "." --lessons ' + LESSONS[0].number)


def test_gradescope_stubs_zero(gradescope_root, tmp_path):
    data = _run_gradescope(
        gradescope_root, build_submission(tmp_path / "s", default=STUB, lessons=(LESSONS[0].number,))
    )
    _check_schema(data)
    assert data["score"] == 0 and "not written yet" in data["tests"][0]["output"]


def test_gradescope_corrupt_notebook(gradescope_root, tmp_path):
    folder = build_submission(tmp_path / "s", lessons=(LESSONS[0].number,))
    notebook = folder / LESSONS[0].filename
    notebook.write_text(notebook.read_text(encoding="utf-8")[:500], encoding="utf-8")
    data = _run_gradescope(gradescope_root, folder)
    assert data["score"] == 0 and "not valid JSON" in data["output"]


def test_grade_writes_gradescope_results(tmp_path):
    build_submission(tmp_path / "class" / "ada", lessons=(LESSONS[0].number,))
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "autograder",
            "grade",
            str(tmp_path / "class"),
            "--out",
            str(tmp_path / "out"),
            "--no-nbval",
            "--lessons",
            LESSONS[0].number,
        ],
        cwd=PROJECT_ROOT,
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr[-2000:]
    data = json.loads(Path(tmp_path / "out" / "results" / "ada.json").read_text(encoding="utf-8"))
    _check_schema(data)
    assert data["score"] == LESSONS[0].points
