"""A second course, graded end to end with no change to the grader: docs/AUTHORING.md, "Write your own course",
followed step by step through the CLI.

The course is the starter course ``python -m autograder new-course`` writes ("Turning the plane": two lessons,
four exercises, 2 points each, and a notebook point per lesson: 10 points), in a temporary folder.

Oracles: the reference answers score every point (canary, local grading, a Dask cluster, the Gradescope
bundle run as Gradescope runs it); untouched stubs score no exercise point; a typical mistake (``rot2``
transposed) loses that exercise's points and nothing else; the local and the Dask gradebooks are equal.
Edge cases: a folder that is not a course is refused with the reason (exit status 2); the second course's
exercise names appear nowhere in the grader but the template that writes it.
"""

import csv
import json
import os
import subprocess
import sys
import zipfile
from pathlib import Path

import nbformat
import pytest

from autograder.integrations.gradescope import unpack_bundle
from autograder.lessons import cells
from autograder.lessons.course import Course
from autograder.lessons.hand_ins import write_submission
from autograder.lessons.paths import PACKAGE, PROJECT_ROOT
from autograder.lessons.reference import answer_sources

FULL = 10.0  # 4 exercises × 2 points, and one notebook point per lesson
TRANSPOSED = ("[[c, -s], [s, c]]", "[[c, s], [-s, c]]")  # rot2's reference, and the typical mistake


def autograder(*args, timeout=600, env=None):
    """``python -m autograder ARGS`` from the project root; the finished process (text output)."""
    return subprocess.run(
        [sys.executable, "-m", "autograder", *map(str, args)],
        cwd=PROJECT_ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=timeout,
    )


def ok(run):
    assert run.returncode == 0, (run.stdout[-2000:], run.stderr[-2000:])
    return run.stdout


@pytest.fixture(scope="module")
def course_dir(tmp_path_factory):
    """Steps 1 and 3 of the walkthrough: the starter course, written and released."""
    folder = tmp_path_factory.mktemp("second") / "plane"
    ok(autograder("new-course", folder))
    ok(autograder("release", "--course", folder))
    return folder


@pytest.fixture(scope="module")
def course(course_dir):
    return Course.at(course_dir)


@pytest.fixture(scope="module")
def klass(course, tmp_path_factory):
    """Three students: every reference answer, untouched stubs, and rot2 transposed (the rest right)."""
    root = tmp_path_factory.mktemp("second-class")
    answers = answer_sources(course.solutions)
    assert TRANSPOSED[0] in answers["rot2"]
    write_submission(course, root / "ada", answers)
    write_submission(course, root / "bob", {})
    write_submission(course, root / "cy", dict(answers, rot2=answers["rot2"].replace(*TRANSPOSED)))
    return root


def _grades(out):
    with open(Path(out) / "grades.csv", encoding="utf-8") as handle:
        return {row["student_id"]: row for row in csv.DictReader(handle)}


def _points(row, exercise):
    return float(row[exercise])


def test_the_walkthrough_writes_a_course_the_grader_reads(course):
    assert course.title == "Turning the plane" and course.handout == "turning-the-plane"
    assert [(e.lesson, e.name, e.points) for e in course.catalog.exercises] == [
        ("01", "rot2", 2.0),
        ("01", "rotate2", 2.0),
        ("02", "angle_of", 2.0),
        ("02", "angle_difference", 2.0),
    ]
    assert ok(autograder("release", "--check", "--course", course.root)).strip().endswith("in sync.")
    assert "0 master(s) changed" in ok(autograder("record", "--course", course.root))


def test_the_canary_gives_the_reference_full_marks(course):
    assert f"full marks ({FULL:g}/{FULL:g})" in ok(autograder("canary", "--course", course.root))


def test_a_class_is_graded_against_the_second_course(course, klass, tmp_path):
    out = tmp_path / "out"
    ok(autograder("grade", klass, "--course", course.root, "--out", out, "--jobs", "2"))
    grades = _grades(out)
    assert float(grades["ada"]["score"]) == FULL
    assert all(_points(grades["bob"], e.name) == 0 for e in course.catalog.exercises)
    assert _points(grades["cy"], "rot2") < 2.0
    assert [_points(grades["cy"], name) for name in ("rotate2", "angle_of", "angle_difference")] == [2.0] * 3
    feedback = (out / "feedback" / "cy.html").read_text(encoding="utf-8")
    assert "rot2" in feedback and "✗" in feedback


def test_dask_workers_grade_the_course_they_are_given(course, klass, tmp_path):
    local, cluster = tmp_path / "local", tmp_path / "cluster"
    ok(autograder("grade", klass, "--course", course.root, "--out", local, "--jobs", "2", "--no-nbval"))
    run = ok(
        autograder("grade", klass, "--course", course.root, "--out", cluster, "--cluster", "local:1", "--no-nbval")
    )
    assert "cluster: 1 worker(s) ready" in run
    keep = ("student_id", "score", "max_score", "status", "rot2", "rotate2", "angle_of", "angle_difference")
    assert {s: {k: row[k] for k in keep} for s, row in _grades(cluster).items()} == {
        s: {k: row[k] for k in keep} for s, row in _grades(local).items()
    }


def test_the_book_shows_the_second_course(course, tmp_path):
    ok(autograder("book", "--course", course.root, "--out", tmp_path / "book"))
    pages = {path.name for path in (tmp_path / "book").glob("*.html")}
    assert {"index.html", "01_rotation_matrices.html", "02_reading_angles.html"} <= pages
    assert "Turning the plane" in (tmp_path / "book" / "01_rotation_matrices.html").read_text(encoding="utf-8")


def test_the_handout_holds_the_second_course_and_no_answer(course, tmp_path):
    ok(autograder("handout", "--course", course.root, "--out", tmp_path / "plane.zip"))
    with zipfile.ZipFile(tmp_path / "plane.zip") as archive:
        names = archive.namelist()
        texts = {name: archive.read(name).decode("utf-8") for name in names}
    assert {
        "turning-the-plane/01_rotation_matrices.ipynb",
        "turning-the-plane/coursekit/watching.py",
        "turning-the-plane/README.md",
    } <= set(names)
    assert texts["turning-the-plane/README.md"].startswith("# Turning the plane")
    assert "A short Jupyter course on rotations in the plane" in texts["turning-the-plane/README.md"]
    answers = {
        name: [line.strip() for line in source.splitlines() if line.strip().startswith("return ")]
        for name, source in answer_sources(course.solutions).items()
    }
    assert sorted(answers) == ["angle_difference", "angle_of", "rot2", "rotate2"] and all(answers.values())
    handed_out = [
        cell
        for name, text in texts.items()
        if name.endswith(".ipynb")
        for cell in nbformat.reads(text, as_version=4).cells
        if cells.is_answer_cell(cell)
    ]
    assert sorted(cells.grade_id(cell) for cell in handed_out) == sorted(answers)
    assert not [
        cells.grade_id(cell)
        for cell in handed_out
        if any(line in cell.source for line in answers[cells.grade_id(cell)] + ["BEGIN SOLUTION"])
    ]


def test_the_gradescope_bundle_carries_the_course_it_grades(course, klass, tmp_path):
    ok(autograder("gradescope", "--course", course.root, "--out", tmp_path / "autograder.zip"))
    root = tmp_path / "autograder"
    source = unpack_bundle(tmp_path / "autograder.zip", root)
    assert (source / "graded_course" / "hidden" / "test_01_rotation_matrices.py").is_file()
    assert '--course "graded_course"' in (source / "setup.sh").read_text(encoding="utf-8")
    subprocess.run(["cp", "-r", str(klass / "ada"), str(root / "submission")], check=True)
    env = dict(os.environ, AUTOGRADER_ROOT=str(root), AUTOGRADER_PYTHON=sys.executable)
    run = subprocess.run([str(source / "run_autograder")], env=env, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]
    results = json.loads((root / "results" / "results.json").read_text(encoding="utf-8"))
    assert results["score"] == FULL, results.get("output")


def test_the_nbgrader_course_has_the_second_course_lessons(course, tmp_path):
    ok(autograder("nbgrader-course", "--course", course.root, "--out", tmp_path / "nb"))
    assert (tmp_path / "nb" / "source" / "lesson01" / "01_rotation_matrices.ipynb").is_file()
    assert (tmp_path / "nb" / "source" / "lesson02" / "coursekit" / "checks" / "lesson02.py").is_file()


def test_a_folder_that_is_not_a_course_is_refused(tmp_path):
    run = autograder("canary", "--course", tmp_path)
    assert run.returncode == 2 and "is not a course folder" in run.stderr, run.stderr


def test_the_grader_does_not_know_the_second_course():
    """Nothing in autograder/ names the second course's exercises but the template that writes it."""
    writer = {PACKAGE / "authoring" / "new_course.py"}
    template = PACKAGE / "authoring" / "course_template"
    found = [
        str(path.relative_to(PACKAGE))
        for path in PACKAGE.rglob("*.py")
        if path not in writer
        and template not in path.parents
        and any(name in path.read_text(encoding="utf-8") for name in ("rotate2", "angle_difference"))
    ]
    assert not found
